//! # contact-core: the shared vocabulary of `contact`
//!
//! `contact` computes compliant contact between rigid parts, as the Adams Solver CONTACT
//! statement does: a contact's two sides are lists of geometries on two parts, a geometry
//! engine answers where, how deep and which way they touch, and force laws turn that into
//! forces. Two engines answer behind one trait: the *exact* engine (analytic, the reference)
//! and the *faceted* engine (triangle meshes in OBB trees, whose error shrinks as the faceting
//! tolerance rises while its cost grows: the trade `contact tradeoff` measures and
//! `contact select` settles for a model). A CONTACT is prepared once; the prepared pair is then
//! queried at any poses from any number of threads (`&self`, no locks).
//!
//! This crate holds what both engines share and what an embedder needs besides one engine:
//!
//! - [`Geometry`]: every shape of SPEC §2, validated at construction;
//!   [`GeometryInstance`] places one on a part.
//! - [`GeometryEngine`] / [`PreparedPair`]: prepare a CONTACT once, query it at poses from any
//!   number of threads; [`Unsupported`] is an error found when the model is checked.
//! - [`Contact`]: points on each body, the normal from J into I, penetration, area.
//! - [`laws`]: STEP/STEP5, IMPACT, POISSON, the augmented-Lagrangian update, Coulomb μ(v), friction
//!   force and torque, each with its partial derivatives.
//! - [`ContactKinematics`]: penetration rate, slip and spin of a contact from the two bodies'
//!   velocities ([`BodyMotion`]), as the solver computes them.
//! - [`ContactArgs`] → [`ContactParams`]: every CONTACT argument with its range and default;
//!   the laws' named parameters ([`laws::ImpactParams`], [`laws::CoulombParams`], …);
//!   [`Preferences`] ([`GeometryLibrary::parse`] reads an engine's name); [`Units`];
//!   [`estimate_small_part`].
//! - [`mesh_file`]: STL and OBJ files read, welded and checked into mesh geometry — the one
//!   input this crate reads.
//! - [`nalgebra`]: the math library of every type here, re-exported.
//!
//! ## Notation
//! Names say the frame (after Drake's monogram notation): `pose_world_part` or `X_WP` is frame
//! `P` measured in `W`; a `_w` suffix means a vector or point expressed in the world frame `W`
//! (`point_i_w`, `normal_w`). Frames: `W` world, `P` a part, `G` a geometry. Costly work is a
//! verb (`prepare`, `compute_*`), cheap access a noun.
//!
//! ## Example: a force from contact kinematics
//! ```
//! use contact_core::{ContactArgs, NormalModel, Units};
//!
//! // CONTACT/1, IMPACT, STIFFNESS = 1e5, DAMPING = 10, DMAX = 0.1, EXPONENT = 2.2 (N-mm-s).
//! let args = ContactArgs {
//!     impact: true,
//!     stiffness: Some(1e5),
//!     damping: Some(10.0),
//!     dmax: Some(0.1),
//!     exponent: Some(2.2),
//!     ..ContactArgs::default()
//! };
//! let (params, warnings) = args.validate(&Units::MMKS)?;
//! assert!(warnings.is_empty());
//! let NormalModel::Impact(law) = params.normal else { unreachable!() };
//! // 0.05 mm deep, approaching at 10 mm/s: spring plus half the damping (the STEP at DMAX/2).
//! let f = law.force(0.05, 10.0);
//! let expected = 1e5 * 0.05_f64.powf(2.2) + 0.5 * 10.0 * 10.0;
//! assert!((f.force - expected).abs() < 1e-9 * expected);
//! # Ok::<(), contact_core::ParamError>(())
//! ```
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

mod contact;
mod engine;
mod error;
mod estimate;
pub mod geometry;
mod instance;
mod kinematics;
pub mod laws;
pub mod mesh_file;
mod params;
mod preferences;
mod units;

pub use contact::Contact;
pub use engine::{
    GeometryEngine, PrepareError, PreparedPair, PreparedStats, QueryError, Side, Unsupported,
    WorkCounters, check_lists, format_pose,
};
pub use error::{InvalidArgument, LENGTH_RANGE, MAX_ASPECT_RATIO};
pub use estimate::{SmallPartEstimate, estimate_small_part};
pub use geometry::{Geometry, GeometryKind};
pub use instance::GeometryInstance;
pub use kinematics::{BodyMotion, ContactKinematics};
pub use params::{
    ContactArgs, ContactParams, ContactType, FrictionModel, FrictionSwitch, NormalModel,
    ParamError, ParamWarning, UserRoutine,
};
pub use preferences::{FacetingTolerance, GeometryLibrary, Preferences};
pub use units::{Dimension, Units, scale_stiffness};

/// The nalgebra every type of this crate is built on (0.34), re-exported so an embedder names
/// the same version without a dependency of its own: [`Isometry3`], [`Vector3`], … are its
/// types. If you also use parry, nalgebra 0.34 pairs with parry3d-f64 0.25 (the last parry
/// whose math types are nalgebra's; parry 0.26 moved to glam).
pub use nalgebra;

/// A 3-D point (f64).
pub type Point3 = nalgebra::Point3<f64>;
/// A 3-D vector (f64).
pub type Vector3 = nalgebra::Vector3<f64>;
/// A 2-D point (f64).
pub type Point2 = nalgebra::Point2<f64>;
/// A 2-D vector (f64).
pub type Vector2 = nalgebra::Vector2<f64>;
/// A 3×3 matrix (f64).
pub type Matrix3 = nalgebra::Matrix3<f64>;
/// A rigid pose (rotation + translation, f64).
pub type Isometry3 = nalgebra::Isometry3<f64>;
/// A unit quaternion (f64).
pub type UnitQuaternion = nalgebra::UnitQuaternion<f64>;
