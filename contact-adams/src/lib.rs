//! # contact-adams: the Adams layer of `contact`
//!
//! What turns an Adams dataset into a run of the solver ([`contact_solver`]), in the order the
//! data flows:
//!
//! - [`dataset`] — the `.adm`/`.acf` reader (lexer, parser, lowering) with located diagnostics;
//! - [`expr`] — Adams function expressions (MOTION, SFORCE, VARIABLE);
//! - [`model`] — the validated model;
//! - [`engine_choice`] — PREFERENCES (or an override) to one `Box<dyn GeometryEngine>`;
//! - [`user_routines`] — NORMAL_ROUTINE / FRICTION_ROUTINE laws, registered in code or loaded
//!   from shared libraries;
//! - [`run`] — a model lowered onto the solver, and its results written;
//! - [`session`] — the entry point that runs a dataset's analyses and streams their results
//!   to a sink the caller implements (the file writer of `contact run` is one);
//! - [`svg_plot`] — the SVG line plots a run (and the trade report) writes.
//!
//! ```
//! use contact_adams::dataset::read_str;
//! use contact_adams::expr::TimeOnly;
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
//! ```
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod dataset;
pub mod engine_choice;
pub mod expr;
pub mod model;
pub mod parasolid_bodies;
pub mod run;
pub mod session;
pub mod svg_plot;
pub mod user_routines;
