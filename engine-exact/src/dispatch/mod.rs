//! The one exhaustive `match` over geometry pairs.
//!
//! A pair is computed in the canonical order of [`GeometryKind`](contact_core::GeometryKind) (`a.kind() <= b.kind()`);
//! the reverse order is the same computation with the result [`swapped`](contact_core::Contact::swapped).
//! There is no wildcard arm: a new geometry kind in `contact-core` is a compile error here.
//!
//! ## What is built (the model check's table)
//!
//! One row per pair: its method in a few words, the kernel module (under `pairs`, or
//! `planar`) whose doc gives the formulas and ranges, and which side may be flipped. The
//! methods in full, with their measured agreement, are in `docs/exact-engine.md`.
//!
//! | pair                                      | method                                           | module                      | flips                 |
//! | ----------------------------------------- | ------------------------------------------------ | --------------------------- | --------------------- |
//! | sphere–plane                              | closed form                                      | sphere_plane                | plane                 |
//! | sphere–plane (bounded)                    | closed form, or sphere–box on the plane's prism  | sphere_bounded_plane        | plane                 |
//! | sphere–box, –cylinder, –frustum, –torus   | closed form on one face; else ellipsoid slicing  | sphere_solid                | none                  |
//! | sphere–mesh                               | signed distance to the mesh                      | sphere_mesh                 | none                  |
//! | sphere–sphere                             | closed form                                      | sphere_sphere               | one sphere (a cavity) |
//! | ellipsoid–plane                           | closed form (affine cap)                         | ellipsoid_plane             | plane                 |
//! | ellipsoid–plane (bounded)                 | closed form, or ellipsoid–box on the prism       | ellipsoid_bounded_plane     | plane                 |
//! | ellipsoid–ellipsoid                       | slicing along the line of centres                | ellipsoid_ellipsoid         | none                  |
//! | ellipsoid–box                             | slicing along the box's z                        | ellipsoid_box               | none                  |
//! | ellipsoid–cylinder                        | slicing along the axis                           | ellipsoid_cylinder          | none                  |
//! | ellipsoid–frustum                         | slicing across the axis                          | ellipsoid_frustum           | none                  |
//! | ellipsoid–torus                           | slicing across the axis, per region              | ellipsoid_torus             | none                  |
//! | ellipsoid in a cylinder, frustum, ellipsoid or torus cavity | slicing along the cavity's axis, lunes per region | ellipsoid_cavity | the cavity |
//! | ellipsoid–mesh                            | the mesh mapped to the unit sphere, sliced       | ellipsoid_mesh              | none                  |
//! | cylinder–plane                            | quadrature of closed-form chords                 | cylinder_plane              | plane                 |
//! | cylinder–cylinder, –box, –plane (bounded) | divergence theorem or slicing                    | cylinder_sliced             | plane                 |
//! | cylinder/frustum–frustum                  | divergence theorem or polar slicing              | revolved_pair               | none                  |
//! | cylinder/frustum–torus                    | polar slicing across the torus' axis, per region | revolved_torus              | none                  |
//! | torus–torus                               | `a`'s meridians in polar coordinates, per region | torus_torus                 | none                  |
//! | frustum/torus–plane                       | quadrature over the azimuth                      | revolved_plane              | plane                 |
//! | frustum/torus–plane (bounded)             | closed form, or box–solid on the prism           | revolved_bounded_plane      | plane                 |
//! | cylinder/frustum/torus–mesh               | slicing across the axis, per region              | revolved_mesh               | none                  |
//! | box–plane (bounded or not)                | convex clipping; half-space in closed form       | box_plane                   | plane                 |
//! | box–box                                   | convex clipping; a cavity as box–mesh            | box_box                     | one box               |
//! | box–frustum, box–torus                    | slicing across the axis, per region              | box_revolved                | none                  |
//! | box–mesh                                  | polyhedral intersection, per region              | box_mesh                    | mesh (a cavity)       |
//! | mesh–mesh                                 | the faceted method on the meshes, per region     | mesh_mesh                   | none                  |
//! | mesh–plane                                | clipping, per region                             | mesh_plane                  | plane                 |
//! | mesh–plane (bounded)                      | clipping, or box–mesh on the prism               | mesh_bounded_plane          | plane                 |
//! | point–line, circle–line                   | closed form                                      | planar::point_line          | line                  |
//! | circle–line (bounded)                     | the disc cut by the half-strip                   | planar::circle_bounded_line | line                  |
//! | point–circle, circle–circle               | closed form                                      | planar::circles             | circle (a hole)       |
//! | point–arc, circle–arc                     | closed form                                      | planar::arc                 | arc                   |
//! | point–curve, circle–curve                 | closest point (Newton)                           | planar::point_curve         | curve                 |
//! | arc/curve/line overlaps                   | crossings + Green's theorem per region           | planar::overlap             | all                   |
//!
//! The general ellipsoid pairs' degenerate branches (each tested): one solid inside the
//! other (the area vector vanishes: the normal is the line of centres, or the nearest face's
//! or side's outward normal of the containing box, cylinder or frustum, or against the ellipsoid's
//! level surface through the centroid when it contains the other; the area a quarter of the
//! surface), identical coincident ellipsoids (`b`'s `+z`), grazing (the pencil's extent
//! shrinks to the touching point; touching alone is no contact).
//!
//! Everything else answers [`Unsupported`] with the reason: point–point, plane–plane and
//! line–line are not contacts; 2-D against 3-D is refused (SPEC §3).

mod planar;
mod solid;

use crate::ExactEngine;
use crate::kernel::Kernel;
use crate::pairs::box_mesh::box_mesh;
use crate::pairs::mesh_plane::PreparedMesh;
use crate::pairs::sphere_solid::Solid;
use Geometry as G;
use contact_core::{Geometry, Unsupported};

/// A pair's kernel and whether it runs with I and J exchanged (`swap`: the kernel's first
/// geometry is J).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Selected {
    /// The computation.
    pub kernel: Kernel,
    /// True when the kernel's first geometry is the caller's second.
    pub swap: bool,
}

/// The reasons given for pairs not built yet, shared so messages stay consistent.
const NOT_BUILT: &str = "this pair is not built in the exact engine yet; use the faceted engine (PREFERENCES/CONTACT_GEOMETRY_LIBRARY = DEFAULT_LIBRARY)";
const NOT_A_CONTACT: &str = "these two geometries have no volume (or area) to overlap";
const MIXED: &str = "2-D geometry cannot contact 3-D geometry (SPEC §3)";
const MESH_OPEN: &str = "the mesh is not a closed 2-manifold (an edge without exactly one neighbour); close it before using it in a contact";
const FLIP_NOT_BUILT: &str = "a flipped (inside-out) geometry is built only for planes, lines, one sphere of a sphere pair, a box or a mesh as a cavity around a box, cylinder, frustum, torus or ellipsoid (sphere included), a cylinder, frustum, ellipsoid or torus as a cavity around an ellipsoid (sphere included), one circle of a circle pair, and arcs and curves against arcs, curves and lines";

/// The convex solids the sphere, box–revolved and revolved–plane kernels take, `None` for
/// every other kind (an exhaustive match: a new kind must say whether it is one).
fn solid_of(g: &Geometry) -> Option<Solid> {
    match g {
        Geometry::Cylinder(c) => Some(Solid::Cylinder(*c)),
        Geometry::Cuboid(c) => Some(Solid::Box(*c)),
        Geometry::Frustum(f) => Some(Solid::Frustum(*f)),
        Geometry::Torus(t) => Some(Solid::Torus(*t)),
        Geometry::Ellipsoid(_)
        | Geometry::Mesh(_)
        | Geometry::Plane(_)
        | Geometry::Point
        | Geometry::Line(_)
        | Geometry::Circle(_)
        | Geometry::Arc(_)
        | Geometry::Curve(_) => None,
    }
}

/// A closed mesh prepared for the exact pairs, turned inside out when flipped (a cavity's
/// walls); `None` unless it is a closed 2-manifold.
fn prepared_mesh(
    mesh: &contact_core::geometry::TriangleMesh,
    flip: bool,
) -> Option<std::sync::Arc<PreparedMesh>> {
    let prepared = PreparedMesh::new(mesh)?;
    Some(std::sync::Arc::new(if flip {
        prepared.inverted()
    } else {
        prepared
    }))
}

/// The walls of a box-shaped cavity (a flipped box): the box's surface as a mesh turned
/// inside out, for the pairs that take a mesh.
fn box_cavity(cuboid: &contact_core::geometry::Cuboid) -> Option<std::sync::Arc<PreparedMesh>> {
    box_mesh(cuboid).map(|m| std::sync::Arc::new(m.inverted()))
}

/// The pair being selected, in the caller's order: the two geometries and whether each is
/// flipped (inside out). The per-pair helpers in [`solid`] and [`planar`] are its methods.
#[derive(Clone, Copy)]
struct Pair<'g> {
    /// The caller's first geometry (I).
    a: &'g Geometry,
    /// True when `a` is inside out.
    flip_a: bool,
    /// The caller's second geometry (J).
    b: &'g Geometry,
    /// True when `b` is inside out.
    flip_b: bool,
}

impl Pair<'_> {
    /// The refusal of this pair with `reason`, naming the caller's I and J.
    fn no(&self, reason: &'static str) -> Unsupported {
        Unsupported {
            engine: ExactEngine::NAME,
            i: self.a.kind(),
            j: self.b.kind(),
            reason,
        }
    }

    /// `kernel` in canonical order, or refused when `flip` (a flip the kernel does not take).
    fn no_flip(&self, flip: bool, kernel: Kernel) -> Result<Selected, Unsupported> {
        if flip {
            Err(self.no(FLIP_NOT_BUILT))
        } else {
            Ok(canonical(kernel))
        }
    }

    /// `g` as one of the convex solids of [`solid_of`], refused as not built otherwise.
    fn solid(&self, g: &Geometry) -> Result<Solid, Unsupported> {
        solid_of(g).ok_or_else(|| self.no(NOT_BUILT))
    }

    /// `mesh` prepared (inside out when `flip`), refused unless it is a closed 2-manifold.
    fn mesh(
        &self,
        mesh: &contact_core::geometry::TriangleMesh,
        flip: bool,
    ) -> Result<std::sync::Arc<PreparedMesh>, Unsupported> {
        prepared_mesh(mesh, flip).ok_or_else(|| self.no(MESH_OPEN))
    }

    /// The walls of the box-shaped cavity `cuboid` (see [`box_cavity`]), refused when its
    /// mesh is not closed.
    fn cavity(
        &self,
        cuboid: &contact_core::geometry::Cuboid,
    ) -> Result<std::sync::Arc<PreparedMesh>, Unsupported> {
        box_cavity(cuboid).ok_or_else(|| self.no(MESH_OPEN))
    }
}

/// The side of a flippable geometry's material: `-1` when `flip` (inside out), else `+1`.
fn side(flip: bool) -> f64 {
    if flip { -1.0 } else { 1.0 }
}

/// The kernel for `a` (flipped when `flip_a`) against `b`, in the caller's order.
pub(crate) fn select(
    a: &Geometry,
    flip_a: bool,
    b: &Geometry,
    flip_b: bool,
) -> Result<Selected, Unsupported> {
    Pair {
        a,
        flip_a,
        b,
        flip_b,
    }
    .select()
}

impl Pair<'_> {
    /// The table: one arm per pair, each naming the helper (in [`solid`] or [`planar`])
    /// that builds its kernel; the reversed orders through [`select`] and [`reversed`].
    fn select(self) -> Result<Selected, Unsupported> {
        match (self.a, self.b) {
            // ---- 3-D × 2-D: not a contact.
            (
                G::Ellipsoid(_)
                | G::Cylinder(_)
                | G::Cuboid(_)
                | G::Frustum(_)
                | G::Torus(_)
                | G::Mesh(_)
                | G::Plane(_),
                G::Point | G::Circle(_) | G::Arc(_) | G::Curve(_) | G::Line(_),
            )
            | (
                G::Point | G::Circle(_) | G::Arc(_) | G::Curve(_) | G::Line(_),
                G::Ellipsoid(_)
                | G::Cylinder(_)
                | G::Cuboid(_)
                | G::Frustum(_)
                | G::Torus(_)
                | G::Mesh(_)
                | G::Plane(_),
            ) => Err(self.no(MIXED)),

            // ---- Non-canonical 3-D orders: the canonical computation, swapped.
            (G::Cylinder(_), G::Ellipsoid(_))
            | (G::Cuboid(_), G::Ellipsoid(_) | G::Cylinder(_))
            | (G::Frustum(_), G::Ellipsoid(_) | G::Cylinder(_) | G::Cuboid(_))
            | (G::Torus(_), G::Ellipsoid(_) | G::Cylinder(_) | G::Cuboid(_) | G::Frustum(_))
            | (
                G::Mesh(_),
                G::Ellipsoid(_) | G::Cylinder(_) | G::Cuboid(_) | G::Frustum(_) | G::Torus(_),
            )
            | (
                G::Plane(_),
                G::Ellipsoid(_)
                | G::Cylinder(_)
                | G::Cuboid(_)
                | G::Frustum(_)
                | G::Torus(_)
                | G::Mesh(_),
            )
            // ---- Non-canonical 2-D orders.
            | (G::Circle(_), G::Point)
            | (G::Arc(_), G::Point | G::Circle(_))
            | (G::Curve(_), G::Point | G::Circle(_) | G::Arc(_))
            | (G::Line(_), G::Point | G::Circle(_) | G::Arc(_) | G::Curve(_)) => {
                reversed(select(self.b, self.flip_b, self.a, self.flip_a))
            }

            // ---- 3-D, canonical order.
            (G::Ellipsoid(ea), G::Ellipsoid(eb)) => self.ellipsoid_ellipsoid(ea, eb),
            (G::Ellipsoid(e), G::Plane(p)) => self.ellipsoid_plane(e, p),
            (G::Cylinder(cylinder), G::Plane(p)) => self.cylinder_plane(cylinder, p),
            (G::Frustum(_) | G::Torus(_), G::Plane(p)) => self.revolved_plane(p),
            (G::Cuboid(a_box), G::Cuboid(b_box)) => self.box_box(a_box, b_box),
            (G::Cuboid(cuboid), G::Plane(plane)) => self.box_plane(cuboid, plane),
            (G::Ellipsoid(e), G::Cuboid(cavity)) if self.flip_b && !self.flip_a => {
                self.ellipsoid_in_box_cavity(e, cavity)
            }
            (G::Ellipsoid(e), G::Cylinder(_) | G::Cuboid(_) | G::Frustum(_) | G::Torus(_)) => {
                self.ellipsoid_solid(e)
            }
            (G::Ellipsoid(e), G::Mesh(mesh)) => self.ellipsoid_mesh(e, mesh),
            (G::Cylinder(_), G::Cuboid(cavity)) if self.flip_b && !self.flip_a => {
                self.cylinder_in_box_cavity(cavity)
            }
            (G::Cylinder(cylinder), G::Cylinder(_) | G::Cuboid(_)) => {
                self.cylinder_sliced(cylinder)
            }
            (G::Cuboid(cavity), G::Frustum(_) | G::Torus(_)) if self.flip_a && !self.flip_b => {
                self.revolved_in_box_cavity(cavity)
            }
            (G::Cuboid(cuboid), G::Frustum(_) | G::Torus(_)) => self.box_revolved(cuboid),
            (G::Cuboid(cuboid), G::Mesh(mesh)) => self.box_mesh(cuboid, mesh),
            (G::Cylinder(_) | G::Frustum(_) | G::Torus(_), G::Mesh(mesh)) => {
                self.revolved_mesh(mesh)
            }
            (G::Cylinder(_) | G::Frustum(_), G::Frustum(_)) => self.revolved_pair(),
            (G::Cylinder(_) | G::Frustum(_), G::Torus(torus)) => self.revolved_torus(torus),
            (G::Torus(a), G::Torus(b)) => self.torus_torus(a, b),
            (G::Mesh(mesh_a), G::Mesh(mesh_b)) => self.mesh_mesh(mesh_a, mesh_b),
            (G::Mesh(mesh), G::Plane(p)) => self.mesh_plane(mesh, p),
            (G::Plane(_), G::Plane(_)) => Err(self.no(NOT_A_CONTACT)),

            // ---- 2-D, canonical order.
            (G::Point, G::Point) => Err(self.no(NOT_A_CONTACT)),
            (G::Point, G::Circle(c)) => self.point_circle(c),
            (G::Point, G::Line(line)) => self.point_line(line),
            (G::Circle(ca), G::Circle(cb)) => self.circle_circle(ca, cb),
            (G::Circle(c), G::Line(line)) => self.circle_line(c, line),
            (G::Point, G::Curve(curve)) => self.point_curve(curve),
            (G::Circle(circle), G::Curve(curve)) => self.circle_curve(circle, curve),
            (G::Point, G::Arc(arc)) => self.point_arc(arc),
            (G::Circle(circle), G::Arc(arc)) => self.circle_arc(circle, arc),
            (G::Arc(_), G::Arc(_) | G::Curve(_) | G::Line(_))
            | (G::Curve(_), G::Curve(_) | G::Line(_)) => self.overlap(),
            (G::Line(_), G::Line(_)) => Err(self.no(NOT_A_CONTACT)),
        }
    }
}

fn canonical(kernel: Kernel) -> Selected {
    Selected {
        kernel,
        swap: false,
    }
}

/// The selection for the reversed order: the same kernel with `swap` toggled, and an error
/// that still names the caller's I and J.
fn reversed(result: Result<Selected, Unsupported>) -> Result<Selected, Unsupported> {
    match result {
        Ok(s) => Ok(Selected { swap: !s.swap, ..s }),
        Err(e) => Err(Unsupported {
            i: e.j,
            j: e.i,
            ..e
        }),
    }
}
