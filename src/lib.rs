//! # contact: compliant contact between rigid parts, as the Adams CONTACT statement
//!
//! The application crate of the workspace: it composes [`contact_core`] (the shared vocabulary:
//! geometry, the engine trait, force laws) with the exact and faceted geometry engines.
//!
//! - [`dataset`] — the `.adm`/`.acf` reader (lexer, parser, lowering) with located diagnostics;
//! - [`expr`] — Adams function expressions (MOTION, SFORCE, VARIABLE);
//! - [`model`] — the validated model;
//! - [`geneva`] — the Geneva example's meshes, generated;
//! - [`scenes`] — the reference scenes that tests, benches and the CLI share;
//! - [`tradeoff`] — the accuracy-against-speed measurement and engine selection;
//! - [`solver`] — the DAE interface ([`solver::dae`]), the multibody equations ([`solver::mbs`])
//!   and the BDF integrator;
//! - [`output`] — plots;
//! - [`engine_choice`] — PREFERENCES (or an override) to one `Box<dyn GeometryEngine>`;
//! - [`run`] — a model lowered onto the solver, and its results written;
//! - [`user_routines`] — NORMAL_ROUTINE / FRICTION_ROUTINE laws, registered in code or loaded
//!   from shared libraries;
//! - [`cli`] — the `contact` command-line subcommands.
//!
//! ```
//! use contact::dataset::read_str;
//! use contact::expr::TimeOnly;
//! use contact::scenes;
//!
//! // A dataset: a MOTION function evaluated at t = 1.
//! let adm = "pendulum\nUNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
//!            PART/1, GROUND\nMARKER/1, PART = 1\nPART/2, MASS = 1, CM = 2, IP = 1, 1, 1\n\
//!            MARKER/2, PART = 2\nJOINT/1, REVOLUTE, I = 2, J = 1\n\
//!            MOTION/1, JOINT = 1, FUNCTION = 30D * TIME\nEND\n";
//! let loaded = read_str(adm, "pendulum.adm", None);
//! assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
//! let angle = loaded.model.motions[0].function.eval(&TimeOnly(1.0)).unwrap();
//! assert!((angle - 30f64.to_radians()).abs() < 1e-15);
//!
//! // A reference scene: a sphere 0.01 deep on a plane; the closed form says δ = r − d.
//! let scene = scenes::scene("sphere_plane").expect("a suite scene");
//! let pose = scene.poses.iter().find(|p| p.nominal_depth > 0.005).expect("a contact pose");
//! let oracle = scene.closed_form.expect("sphere_plane has a closed form");
//! assert!((oracle(&scene, pose)[0].penetration - pose.nominal_depth).abs() < 1e-12);
//! ```
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod cli;
pub mod dataset;
pub mod engine_choice;
pub mod expr;
pub mod geneva;
pub mod model;
pub mod output;
pub mod run;
pub mod scenes;
pub mod solver;
pub mod tradeoff;
pub mod user_routines;

/// The README's code blocks, compiled and run as doctests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
