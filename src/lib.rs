//! # contact: compliant contact between rigid parts, as the Adams CONTACT statement
//!
//! The application crate of the workspace: the `contact` binary, its subcommands, the
//! accuracy-against-speed trade report and the reference scenes. The pipeline lives in the
//! crates below it, each depending only on those before it:
//!
//! 1. [`contact_core`] — the shared vocabulary: geometry, the engine trait, contacts, force laws;
//! 2. `engine_exact` and `engine_facet` — the two geometry engines;
//! 3. [`contact_solver`] — the multibody equations, the integrator, statics, linearization;
//! 4. [`contact_adams`] — the dataset reader, expressions, the model, runs lowered onto the solver.
//!
//! Their modules are re-exported here under the names the commands use ([`solver`],
//! [`dataset`], [`run`], …). This crate adds:
//!
//! - [`geneva`] — the Geneva example's meshes, generated;
//! - [`chain`] — the chain-drive example's datasets, generated;
//! - [`pile`] — the sphere-pile example's datasets, generated;
//! - [`scenes`] — the reference scenes that tests, benches and the CLI share;
//! - [`peer`] — parry beside our engines, for comparison only (every parry call of the workspace);
//! - [`tradeoff`] — the accuracy-against-speed measurement and engine selection;
//! - [`cli`] — the `contact` command-line subcommands.
//!
//! ```
//! use contact::scenes;
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

pub mod chain;
pub mod cli;
mod generated;
pub mod geneva;
pub mod peer;
pub mod pile;
pub mod scenes;
pub mod tradeoff;

pub use contact_adams::{
    dataset, engine_choice, expr, model, run, session, svg_plot, user_routines,
};
pub use contact_solver as solver;

/// The README's code blocks, compiled and run as doctests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
