//! # engine-exact: analytic contact kinematics for `contact`
//!
//! One of the two geometry engines behind [`contact_core::GeometryEngine`] (the crate doc of
//! [`contact_core`] tells the whole); the other is the faceted engine, `engine-facet`.
//!
//! This crate is the exact engine. It plays the part Parasolid plays in Adams: it answers the
//! contact question of SPEC §4 from the geometry itself, in closed form where one exists, and
//! is the reference the faceted engine is judged against. It implements [`GeometryEngine`]
//! from `contact-core`.
//!
//! ## The contact it returns (SPEC §4)
//! For each (I geometry, J geometry) pair whose solids overlap with positive volume (area in
//! 2-D), one [`Contact`](contact_core::Contact) per connected intersection region:
//! - `normal_w` (unit, from J into I) — per pair family, see `pairs` and [`planar`];
//! - the centroid `g` of the intersection volume; `point_i_w` and `point_j_w` are SPEC §4's
//!   "closest points on the two surfaces to the centroid" taken along the normal: where the
//!   line through `g` along `normal_w` leaves I (towards `−n`) and J (towards `+n`), as in the
//!   faceted engine (the `ray_exit` module documents why: the plain closest points jump between
//!   faces where two are equally near — a cube corner in a plane, coincident boxes — and a
//!   force whose size or line of action jumps stalls a Newton corrector; along the normal they
//!   move continuously and coincide with the closest points wherever the surfaces are smooth
//!   near a shallow contact). A centroid outside a non-convex body (a torus' hole) takes that
//!   body's closest surface point;
//! - `penetration` δ = the distance between those two points (for a sphere on a plane, exactly
//!   `r − d`; for two spheres, `r_a + r_b − D`; for a cube corner pushed `d` into a plane, `d`);
//! - `area`: the contact patch projected on the plane normal to `normal_w` (`|S|` with `S`
//!   the vector area of one body's surface inside the other, the faceted engine's rule; a
//!   length in 2-D).
//!
//! Touching (zero intersection volume) is not a contact: δ would be 0 and so would the force.
//!
//! ## Which pairs
//! [`ExactEngine::supports`] is the model-check answer; a pair it refuses is an
//! [`Unsupported`] error before any run, never "no contact". The module [`dispatch`] holds
//! the one exhaustive `match` over geometry pairs and documents the table of what is built.
//!
//! ## Example: a sphere resting 0.1 deep on the ground plane
//! ```
//! use contact_core::{Contact, Geometry, GeometryEngine, GeometryInstance, Isometry3, WorkCounters};
//! use contact_core::geometry::Plane;
//! use engine_exact::ExactEngine;
//!
//! let ball = GeometryInstance::new(Geometry::sphere(1.0)?);
//! let ground = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
//! let pair = ExactEngine.prepare(&[ball], &[ground])?;
//! let mut contacts: Vec<Contact> = Vec::new();
//! let mut work = WorkCounters::default();
//! let pose_ball = Isometry3::translation(0.0, 0.0, 0.9);
//! pair.query(&pose_ball, &Isometry3::identity(), &mut contacts, &mut work)?;
//! assert_eq!(contacts.len(), 1);
//! let c = contacts[0];
//! assert!((c.penetration - 0.1).abs() < 1e-15);
//! assert_eq!(c.normal_w, nalgebra::Vector3::z());
//! // The cap's base disc: π (r² − d²).
//! assert!((c.area - std::f64::consts::PI * (1.0 - 0.81)).abs() < 1e-14);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! ## Modules
//! - [`dispatch`]: geometry pair → kernel, in the canonical order of `GeometryKind`.
//! - `pairs` (private): the 3-D pair kernels, one module per kernel of the dispatch; `methods`
//!   (private): what they share (slicing, sections, clipping); `polyhedron`: exact convex
//!   clipping.
//! - [`planar`]: 2-D pairs, computed in J's plane.
//! - [`quadrature`]: Gauss–Legendre rules for the pairs without a short closed form.
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod dispatch;
mod kernel;
mod methods;
pub(crate) mod pairs;
pub mod planar;
pub(crate) mod polyhedron;
mod prepared;
pub mod quadrature;
mod ray_exit;
mod sin_cos;
#[cfg(test)]
mod test_rng;

use contact_core::{
    Geometry, GeometryEngine, GeometryInstance, PrepareError, PreparedPair, Unsupported,
    check_lists,
};

pub use prepared::PreparedExact;

/// The exact (analytic) geometry engine. Stateless: all data lives in the prepared pairs.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ExactEngine;

impl ExactEngine {
    /// The engine's name in reports and errors.
    pub const NAME: &'static str = "exact";
}

impl GeometryEngine for ExactEngine {
    fn name(&self) -> &'static str {
        Self::NAME
    }

    /// Checks the pair by kind and data (sphere or general ellipsoid, bounded or unbounded
    /// plane). Normal flips are not seen here: a flipped geometry the engine cannot answer
    /// (flipped boxes, flipped general ellipsoids, a flipped point) is refused by
    /// [`GeometryEngine::prepare`], which also runs before any query.
    fn supports(&self, i: &Geometry, j: &Geometry) -> Result<(), Unsupported> {
        dispatch::select(i, false, j, false).map(|_| ())
    }

    /// The pair's kernel selected with the instances' flips (a cavity): the check `prepare`
    /// makes, without preparing the geometry.
    fn supports_instances(
        &self,
        i: &GeometryInstance,
        j: &GeometryInstance,
    ) -> Result<(), PrepareError> {
        Ok(dispatch::select(&i.geometry, i.flip_normal, &j.geometry, j.flip_normal).map(|_| ())?)
    }

    fn prepare(
        &self,
        i: &[GeometryInstance],
        j: &[GeometryInstance],
    ) -> Result<Box<dyn PreparedPair>, PrepareError> {
        check_lists(self, i, j)?;
        Ok(Box::new(PreparedExact::new(i, j)?))
    }
}
