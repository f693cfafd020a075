//! # engine-facet: the faceted geometry engine of `contact`
//!
//! One of the two geometry engines behind [`contact_core::GeometryEngine`] (the crate doc of
//! [`contact_core`] tells the whole); the other is the exact engine, `engine-exact`.
//!
//! This crate is the faceted engine, in the part RAPID plays in Adams: every geometry of a
//! CONTACT becomes a triangle mesh (native primitives are tessellated at a faceting tolerance
//! FT, meshes read from STL or OBJ keep their facets, 3-D planes stay exact half-spaces), meshes are
//! indexed by OBB trees, and a query returns one Adams-style
//! [`Contact`](contact_core::Contact) per intersection region — point on each body, normal,
//! penetration, area — whose error shrinks as FT rises.
//!
//! Pipeline and modules:
//! - [`tessellate`]: primitives → closed meshes (FT → segment counts documented there);
//!   2-D shapes → polylines. Mesh files (STL, OBJ) are read and checked by
//!   [`contact_core::mesh_file`], re-exported here as [`mesh_file`], [`stl`] and [`obj`].
//! - [`obb`], [`obb_tree`]: boxes, the 15-axis separating-axis test, trees and their descent.
//! - [`triangle_pair`]: the triangle–triangle test with its crossing segment.
//! - [`contact_region`]: crossings → regions → contacts (the method and its error bound);
//!   the flood into the triangles inside the other solid in `inside_flood`; half-spaces in
//!   `plane_contact` (a convex mesh's coplanar triangles taken as one face, `flat_faces`).
//! - [`FacetEngine`]: the [`GeometryEngine`](contact_core::GeometryEngine) tying it together.
//! - [`planar`]: the 2-D pairs (a point or a circle against a line, circle, arc or curve; an
//!   arc or curve against an arc, curve or line, one contact per overlap region) on polylines,
//!   with the polyline's true-normal field (exact normals for circles and arcs) and the
//!   chords lifted onto Hermite arcs through the true tangents.
//!
//! ## Accuracy (the characterisation table, `tests/facet/convergence.rs`)
//! Worst case over four mesh orientations; depth error relative to the exact depth, normal error in
//! degrees, `point_i` error relative to the depth. Exact depths: 0.2 (sphere r = 1 on a plane;
//! spheres r = 1 and 0.5), 0.05 (cylinder r = 0.5 lying on a plane), 0.1 (box on box; torus
//! R = 2, r = 0.5 standing on a plane). Order: the observed order of the depth error from FT = 100
//! to 3000.
//!
//! | pair | FT = 100 | 300.0028 (default) | 1000 | 3000 | order |
//! |---|---|---|---|---|---|
//! | sphere–plane depth / normal | 5.3e-3 / 0° | 1.2e-3 / 0° | 6.3e-4 / 0° | 1.7e-4 / 0° | 1.0 |
//! | sphere–sphere depth / normal | 5.0e-3 / 1.08° | 1.5e-3 / 0.22° | 1.7e-4 / 0.07° | 7.1e-5 / 0.02° | 1.25 |
//! | cylinder–plane depth | 3.2e-2 | 3.4e-3 | 3.5e-4 | 4.5e-4 | 1.25 |
//! | box–box depth | 3e-16 | 3e-16 | 3e-16 | 3e-16 | exact |
//! | torus–plane depth | 4.2e-3 | 8.9e-3 | 2.6e-3 | 8.7e-4 | 0.46 |
//! | sphere–plane `point_i` | 9.2e-2 | 6.6e-2 | 4.5e-2 | 2.3e-2 | 0.4 |
//!
//! Depths are far better than the chord deviation `L/FT` because the closest points are lifted onto
//! curved PN triangles through the exact corner normals (see [`contact_region`]); the contact point
//! follows the faceted intersection volume's centroid and converges more slowly (about
//! `O(FT^-0.4)`).
//!
//! ## Example: a sphere resting 0.1 deep on a plane
//! ```
//! use contact_core::{Geometry, GeometryEngine, GeometryInstance, Isometry3, WorkCounters};
//! use contact_core::geometry::Plane;
//! use engine_facet::FacetEngine;
//!
//! let engine = FacetEngine::default(); // FT = 300.0028
//! let ball = GeometryInstance::new(Geometry::sphere(1.0)?);
//! let ground = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
//! let pair = engine.prepare(&[ball], &[ground])?;
//! let (mut contacts, mut work) = (Vec::new(), WorkCounters::default());
//! let pose_ball = Isometry3::translation(0.0, 0.0, 0.9);
//! pair.query(&pose_ball, &Isometry3::identity(), &mut contacts, &mut work)?;
//! assert_eq!(contacts.len(), 1);
//! let c = &contacts[0];
//! assert!((c.penetration - 0.1).abs() < 0.02, "{}", c.penetration);
//! assert!((c.normal_w.z - 1.0).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod contact_region;
mod crossings;
mod engine;
pub mod facet_mesh;
mod flat_faces;
mod inside_flood;
mod mesh_build;
pub mod obb;
pub mod obb_tree;
pub mod patches;
pub mod piece_boundary;
pub mod planar;
mod plane_contact;
mod plane_support;
mod prepared;
mod region_volumes;
mod scratch;
mod smooth_patch;
mod solid_on_face;
pub mod surface_sums;
pub mod tessellate;
pub mod triangle_pair;
pub mod triangle_pieces;

pub use contact_core::mesh_file::{self, obj, stl};
pub use engine::FacetEngine;
pub use prepared::{PreparedFacetPair, PreparedGeometry, Shape};
