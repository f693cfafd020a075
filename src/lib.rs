//! # contact: compliant contact between rigid parts
//!
//! The application package of the workspace: it composes [`contact_core`] (the shared
//! vocabulary: geometry, the engine trait, force laws) with the exact and faceted geometry
//! engines, and holds the reference [`scenes`] that tests, benches and the CLI share.
//!
//! ```
//! use contact::scenes;
//!
//! // A sphere of radius 1 resting 0.01 deep on a plane: the closed form says δ = r − d.
//! let scene = scenes::scene("sphere_plane").expect("a suite scene");
//! let pose = scene.poses.iter().find(|p| p.nominal_depth > 0.005).expect("a contact pose");
//! let oracle = scene.closed_form.expect("sphere_plane has a closed form");
//! let contacts = oracle(&scene, pose);
//! assert!((contacts[0].penetration - pose.nominal_depth).abs() < 1e-12);
//! ```
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod cli;
pub mod output;
pub mod scenes;
pub mod tradeoff;

/// The README's code blocks, compiled and run as doctests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
