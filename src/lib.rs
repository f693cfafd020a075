//! # contact: compliant contact between rigid parts
//!
//! The application package: it composes `contact-core` with the exact and faceted geometry
//! engines. So far it holds the command-line tools ([`cli`]).
//!
//! ```
//! use contact::cli::query::{parse_geometry, parse_poses};
//!
//! let (sphere, warnings) = parse_geometry("sphere:r=1.5", false)?;
//! assert!(warnings.is_empty());
//! assert_eq!(sphere.characteristic_length(), Some(3.0 * 3f64.sqrt()));
//! let poses = parse_poses("0 0 1  1 0 0 0\n# a comment\n0.5,0,0,0,0,0,1\n").unwrap();
//! assert_eq!(poses.len(), 2);
//! # Ok::<(), contact::cli::query::QueryCliError>(())
//! ```
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

/// The `contact` command's subcommands, one module each.
pub mod cli {
    pub mod query;
}
