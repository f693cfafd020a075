//! # contact: compliant contact between rigid parts, as the Adams CONTACT statement
//!
//! The application crate: reads Adams datasets into a validated [`model::Model`], checks its
//! contacts against a geometry engine, and (in later modules) solves and writes results.
//!
//! - [`dataset`]: the `.adm`/`.acf` reader (lexer, parser, lowering) with located diagnostics;
//! - [`expr`]: Adams function expressions (MOTION, SFORCE, VARIABLE);
//! - [`model`]: the validated model;
//! - [`cli`]: the `contact` command-line subcommands.
//!
//! ```
//! use contact::dataset::read_str;
//! use contact::expr::TimeOnly;
//!
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

pub mod cli;
pub mod dataset;
pub mod expr;
pub mod model;
