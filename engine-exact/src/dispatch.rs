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
//! | ellipsoid–mesh                            | the mesh mapped to the unit sphere, sliced       | ellipsoid_mesh              | none                  |
//! | cylinder–plane                            | quadrature of closed-form chords                 | cylinder_plane              | plane                 |
//! | cylinder–cylinder, –box, –plane (bounded) | divergence theorem or slicing                    | cylinder_sliced             | plane                 |
//! | cylinder/frustum–frustum                  | divergence theorem or polar slicing              | revolved_pair               | none                  |
//! | cylinder/frustum–torus                    | polar slicing across the torus' axis, per region | revolved_torus              | none                  |
//! | frustum/torus–plane                       | quadrature over the azimuth                      | revolved_plane              | plane                 |
//! | frustum/torus–plane (bounded)             | closed form, or box–solid on the prism           | revolved_bounded_plane      | plane                 |
//! | cylinder/frustum/torus–mesh               | slicing across the axis, per region              | revolved_mesh               | none                  |
//! | box–plane (bounded or not)                | convex clipping; half-space in closed form       | box_plane                   | plane                 |
//! | box–box                                   | convex clipping; a cavity as box–mesh            | box_box                     | one box               |
//! | box–frustum, box–torus                    | slicing across the axis, per region              | box_revolved                | none                  |
//! | box–mesh                                  | polyhedral intersection, per region              | box_mesh                    | mesh (a cavity)       |
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
//! Everything else answers [`Unsupported`] with the reason: torus–torus; mesh–mesh (the intersection of two meshes is not built); point–point,
//! plane–plane and line–line are not contacts; 2-D against 3-D is refused (SPEC §3).

use crate::ExactEngine;
use crate::kernel::Kernel;
use crate::pairs::box_mesh::box_mesh;
use crate::pairs::cylinder_sliced::SlicedSolid;
use crate::pairs::mesh_plane::PreparedMesh;
use crate::pairs::sphere_solid::Solid;
use crate::planar::boundary::Chain;
use crate::planar::curve_eval::PlanarCurve;
use contact_core::geometry::{Ellipsoid, Plane};
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
const FLIP_NOT_BUILT: &str = "a flipped (inside-out) geometry is built only for planes, lines, one sphere of a sphere pair, a box or a mesh as a cavity around a box, cylinder, frustum, torus or ellipsoid (sphere included), one circle of a circle pair, and arcs and curves against arcs, curves and lines";

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

/// The kernel for `a` (flipped when `flip_a`) against `b`, in the caller's order.
pub(crate) fn select(
    a: &Geometry,
    flip_a: bool,
    b: &Geometry,
    flip_b: bool,
) -> Result<Selected, Unsupported> {
    use Geometry as G;
    let no = |reason: &'static str| Unsupported {
        engine: ExactEngine::NAME,
        i: a.kind(),
        j: b.kind(),
        reason,
    };
    let side = |flip: bool| if flip { -1.0 } else { 1.0 };
    let no_flip = |flip: bool, kernel: Kernel| {
        if flip {
            Err(no(FLIP_NOT_BUILT))
        } else {
            Ok(canonical(kernel))
        }
    };
    match (a, b) {
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
        ) => Err(no(MIXED)),

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
            reversed(select(b, flip_b, a, flip_a))
        }

        // ---- 3-D, canonical order.
        (G::Ellipsoid(ea), G::Ellipsoid(eb)) => {
            match (ea.sphere_radius(), eb.sphere_radius(), flip_a, flip_b) {
                (Some(radius_a), Some(radius_b), false, false) => {
                    Ok(canonical(Kernel::SphereSphere { radius_a, radius_b }))
                }
                (Some(radius_a), Some(radius_b), false, true) => {
                    Ok(canonical(Kernel::SphereInCavity { radius_a, radius_b }))
                }
                (Some(radius_a), Some(radius_b), true, false) => Ok(Selected {
                    kernel: Kernel::SphereInCavity {
                        radius_a: radius_b,
                        radius_b: radius_a,
                    },
                    swap: true,
                }),
                (Some(_), Some(_), true, true) => Err(no(NOT_A_CONTACT)),
                (_, _, false, false) => Ok(canonical(Kernel::EllipsoidEllipsoid {
                    semi_a: ea.semi_axes(),
                    semi_b: eb.semi_axes(),
                })),
                _ => Err(no(FLIP_NOT_BUILT)),
            }
        }
        (G::Ellipsoid(e), G::Plane(p)) => {
            ellipsoid_plane(e, flip_a, p, flip_b).ok_or_else(|| no(FLIP_NOT_BUILT))
        }
        (G::Cylinder(cylinder), G::Plane(p)) => {
            if p.is_unbounded() {
                no_flip(
                    flip_a,
                    Kernel::CylinderPlane {
                        cylinder: *cylinder,
                        side: side(flip_b),
                    },
                )
            } else {
                no_flip(
                    flip_a,
                    Kernel::CylinderSliced {
                        cylinder: *cylinder,
                        other: SlicedSolid::Plane {
                            plane: *p,
                            side: side(flip_b),
                        },
                    },
                )
            }
        }
        (G::Frustum(_) | G::Torus(_), G::Plane(p)) => {
            let solid = solid_of(a).ok_or_else(|| no(NOT_BUILT))?;
            if p.is_unbounded() {
                no_flip(
                    flip_a,
                    Kernel::RevolvedPlane {
                        solid,
                        side: side(flip_b),
                    },
                )
            } else {
                no_flip(
                    flip_a,
                    Kernel::RevolvedBoundedPlane {
                        solid,
                        plane: *p,
                        side: side(flip_b),
                    },
                )
            }
        }
        (G::Cuboid(a_box), G::Cuboid(b_box)) => match (flip_a, flip_b) {
            (false, false) => Ok(canonical(Kernel::BoxBox {
                a: *a_box,
                b: *b_box,
            })),
            // A box in a box-shaped cavity: the box against the cavity's walls, a mesh
            // turned inside out.
            (false, true) | (true, false) => {
                let (inner, cavity) = if flip_b {
                    (a_box, b_box)
                } else {
                    (b_box, a_box)
                };
                let walls = box_mesh(cavity).ok_or_else(|| no(MESH_OPEN))?.inverted();
                Ok(Selected {
                    kernel: Kernel::BoxMesh {
                        cuboid: *inner,
                        mesh: std::sync::Arc::new(walls),
                    },
                    swap: flip_a,
                })
            }
            (true, true) => Err(no(NOT_A_CONTACT)),
        },
        (G::Cuboid(cuboid), G::Plane(plane)) => no_flip(
            flip_a,
            Kernel::BoxPlane {
                cuboid: *cuboid,
                plane: *plane,
                side: side(flip_b),
            },
        ),
        (G::Ellipsoid(e), G::Cuboid(cavity)) if flip_b && !flip_a => {
            // An ellipsoid (or sphere) in a box-shaped cavity.
            let mesh = box_cavity(cavity).ok_or_else(|| no(MESH_OPEN))?;
            Ok(canonical(Kernel::EllipsoidMesh {
                semi_axes: e.semi_axes(),
                mesh,
            }))
        }
        (G::Ellipsoid(e), G::Cylinder(_) | G::Cuboid(_) | G::Frustum(_) | G::Torus(_)) => {
            let solid = solid_of(b).ok_or_else(|| no(NOT_BUILT))?;
            match e.sphere_radius() {
                Some(radius) if !flip_b => no_flip(flip_a, Kernel::SphereSolid { radius, solid }),
                Some(_) => Err(no(FLIP_NOT_BUILT)),
                None => general_ellipsoid_solid(e, &solid, flip_a || flip_b).map_err(no),
            }
        }
        (G::Ellipsoid(e), G::Mesh(mesh)) => match e.sphere_radius() {
            Some(radius) if !flip_b => {
                let mesh = prepared_mesh(mesh, false).ok_or_else(|| no(MESH_OPEN))?;
                no_flip(flip_a, Kernel::SphereMesh { radius, mesh })
            }
            // A sphere in a meshed cavity: the general ellipsoid slicing, which finds every
            // wall it meets as its own region.
            Some(_) | None => {
                let prepared = prepared_mesh(mesh, flip_b).ok_or_else(|| no(MESH_OPEN))?;
                no_flip(
                    flip_a,
                    Kernel::EllipsoidMesh {
                        semi_axes: e.semi_axes(),
                        mesh: prepared,
                    },
                )
            }
        },
        (G::Cylinder(_), G::Cuboid(cavity)) if flip_b && !flip_a => {
            // A cylinder in a box-shaped cavity.
            let solid = solid_of(a).ok_or_else(|| no(NOT_BUILT))?;
            let mesh = box_cavity(cavity).ok_or_else(|| no(MESH_OPEN))?;
            Ok(canonical(Kernel::RevolvedMesh { solid, mesh }))
        }
        (G::Cylinder(cylinder), G::Cylinder(_) | G::Cuboid(_)) => {
            let other = match b {
                G::Cuboid(c) => SlicedSolid::Box(*c),
                G::Cylinder(c) => SlicedSolid::Cylinder(*c),
                // Only cylinders and boxes reach here (the arm's patterns).
                G::Ellipsoid(_)
                | G::Frustum(_)
                | G::Torus(_)
                | G::Mesh(_)
                | G::Plane(_)
                | G::Point
                | G::Line(_)
                | G::Circle(_)
                | G::Arc(_)
                | G::Curve(_) => return Err(no(NOT_BUILT)),
            };
            no_flip(
                flip_a || flip_b,
                Kernel::CylinderSliced {
                    cylinder: *cylinder,
                    other,
                },
            )
        }
        (G::Cuboid(cavity), G::Frustum(_) | G::Torus(_)) if flip_a && !flip_b => {
            // A frustum or torus in a box-shaped cavity: the kernel's first geometry is J.
            let solid = solid_of(b).ok_or_else(|| no(NOT_BUILT))?;
            let mesh = box_cavity(cavity).ok_or_else(|| no(MESH_OPEN))?;
            Ok(Selected {
                kernel: Kernel::RevolvedMesh { solid, mesh },
                swap: true,
            })
        }
        (G::Cuboid(cuboid), G::Frustum(_) | G::Torus(_)) => {
            let solid = solid_of(b).ok_or_else(|| no(NOT_BUILT))?;
            no_flip(
                flip_a || flip_b,
                Kernel::BoxRevolved {
                    cuboid: *cuboid,
                    solid,
                },
            )
        }
        (G::Cuboid(cuboid), G::Mesh(mesh)) => {
            let prepared = prepared_mesh(mesh, flip_b).ok_or_else(|| no(MESH_OPEN))?;
            no_flip(
                flip_a,
                Kernel::BoxMesh {
                    cuboid: *cuboid,
                    mesh: prepared,
                },
            )
        }
        (G::Cylinder(_) | G::Frustum(_) | G::Torus(_), G::Mesh(mesh)) => {
            let solid = solid_of(a).ok_or_else(|| no(NOT_BUILT))?;
            let prepared = prepared_mesh(mesh, flip_b).ok_or_else(|| no(MESH_OPEN))?;
            no_flip(
                flip_a,
                Kernel::RevolvedMesh {
                    solid,
                    mesh: prepared,
                },
            )
        }
        (G::Cylinder(_) | G::Frustum(_), G::Frustum(_)) => {
            let solid_a = solid_of(a).ok_or_else(|| no(NOT_BUILT))?;
            let solid_b = solid_of(b).ok_or_else(|| no(NOT_BUILT))?;
            no_flip(
                flip_a || flip_b,
                Kernel::RevolvedPair {
                    a: solid_a,
                    b: solid_b,
                },
            )
        }
        (G::Cylinder(_) | G::Frustum(_), G::Torus(torus)) => {
            let solid = solid_of(a).ok_or_else(|| no(NOT_BUILT))?;
            no_flip(
                flip_a || flip_b,
                Kernel::RevolvedTorus {
                    solid,
                    torus: *torus,
                },
            )
        }
        (G::Torus(_), G::Torus(_)) | (G::Mesh(_), G::Mesh(_)) => Err(no(NOT_BUILT)),
        (G::Mesh(mesh), G::Plane(p)) => {
            let mesh = prepared_mesh(mesh, false).ok_or_else(|| no(MESH_OPEN))?;
            let side = side(flip_b);
            no_flip(
                flip_a,
                if p.is_unbounded() {
                    Kernel::MeshPlane { mesh, side }
                } else {
                    Kernel::MeshBoundedPlane {
                        mesh,
                        plane: *p,
                        side,
                    }
                },
            )
        }
        (G::Plane(_), G::Plane(_)) => Err(no(NOT_A_CONTACT)),

        // ---- 2-D, canonical order.
        (G::Point, G::Point) => Err(no(NOT_A_CONTACT)),
        (G::Point, G::Circle(c)) => no_flip(
            flip_a,
            Kernel::PointCircle {
                radius: c.radius(),
                hole: flip_b,
            },
        ),
        (G::Point, G::Line(line)) => no_flip(
            flip_a,
            Kernel::PointLine {
                line: *line,
                side: side(flip_b),
            },
        ),
        (G::Circle(ca), G::Circle(cb)) => {
            let (radius_a, radius_b) = (ca.radius(), cb.radius());
            match (flip_a, flip_b) {
                (false, false) => Ok(canonical(Kernel::CircleCircle { radius_a, radius_b })),
                (false, true) => Ok(canonical(Kernel::CircleInHole { radius_a, radius_b })),
                (true, false) => Ok(Selected {
                    kernel: Kernel::CircleInHole {
                        radius_a: radius_b,
                        radius_b: radius_a,
                    },
                    swap: true,
                }),
                (true, true) => Err(no(NOT_A_CONTACT)),
            }
        }
        (G::Circle(c), G::Line(line)) => {
            let x_range = line.x_range();
            let kernel = if x_range.iter().any(|x| x.is_finite()) {
                Kernel::CircleBoundedLine {
                    radius: c.radius(),
                    x_range,
                    side: side(flip_b),
                }
            } else {
                Kernel::CircleLine {
                    radius: c.radius(),
                    side: side(flip_b),
                }
            };
            // A flipped circle (a hole) against a line's material is an unbounded region.
            no_flip(flip_a, kernel)
        }
        (G::Point, G::Curve(curve)) => {
            let curve = planar_curve(curve);
            no_flip(
                flip_a,
                Kernel::PointCurve {
                    curve,
                    side: side(flip_b),
                },
            )
        }
        (G::Circle(circle), G::Curve(curve)) => {
            let curve = planar_curve(curve);
            no_flip(
                flip_a,
                Kernel::CircleCurve {
                    radius: circle.radius(),
                    curve,
                    side: side(flip_b),
                },
            )
        }
        (G::Point, G::Arc(arc)) => no_flip(
            flip_a,
            Kernel::PointArc {
                radius: arc.radius(),
                range: arc.range_angle(),
                side: side(flip_b),
            },
        ),
        (G::Circle(circle), G::Arc(arc)) => no_flip(
            flip_a,
            Kernel::CircleArc {
                radius_a: circle.radius(),
                radius: arc.radius(),
                range: arc.range_angle(),
                side: side(flip_b),
            },
        ),
        (G::Arc(_), G::Arc(_) | G::Curve(_) | G::Line(_))
        | (G::Curve(_), G::Curve(_) | G::Line(_)) => {
            let chain = |g: &Geometry, flip: bool| -> Result<Chain, Unsupported> {
                match g {
                    G::Arc(arc) => Ok(Chain::from_arc(arc.radius(), arc.range_angle(), side(flip))),
                    G::Curve(curve) => {
                        let curve = PlanarCurve::new(curve);
                        Ok(Chain::from_curve(&curve, side(flip)))
                    }
                    // Only arcs and curves reach here (the arm's patterns).
                    G::Ellipsoid(_)
                    | G::Cylinder(_)
                    | G::Cuboid(_)
                    | G::Frustum(_)
                    | G::Torus(_)
                    | G::Mesh(_)
                    | G::Plane(_)
                    | G::Point
                    | G::Circle(_)
                    | G::Line(_) => Err(no(NOT_BUILT)),
                }
            };
            let a_chain = std::sync::Arc::new(chain(a, flip_a)?);
            Ok(canonical(match b {
                G::Line(line) => Kernel::OverlapLine {
                    a: a_chain,
                    x_range: line.x_range(),
                    side: side(flip_b),
                },
                G::Ellipsoid(_)
                | G::Cylinder(_)
                | G::Cuboid(_)
                | G::Frustum(_)
                | G::Torus(_)
                | G::Mesh(_)
                | G::Plane(_)
                | G::Point
                | G::Circle(_)
                | G::Arc(_)
                | G::Curve(_) => Kernel::Overlap {
                    a: a_chain,
                    b: std::sync::Arc::new(chain(b, flip_b)?),
                },
            }))
        }
        (G::Line(_), G::Line(_)) => Err(no(NOT_A_CONTACT)),
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

fn planar_curve(curve: &contact_core::geometry::Curve) -> std::sync::Arc<PlanarCurve> {
    std::sync::Arc::new(PlanarCurve::new(curve))
}

/// A general ellipsoid against a box, a cylinder, a frustum or a torus (sliced), or the
/// reason it is refused.
fn general_ellipsoid_solid(
    e: &Ellipsoid,
    solid: &Solid,
    flipped: bool,
) -> Result<Selected, &'static str> {
    let semi_axes = e.semi_axes();
    let kernel = match *solid {
        Solid::Box(cuboid) => Kernel::EllipsoidBox { semi_axes, cuboid },
        Solid::Cylinder(cylinder) => Kernel::EllipsoidCylinder {
            semi_axes,
            cylinder,
        },
        Solid::Frustum(frustum) => Kernel::EllipsoidFrustum { semi_axes, frustum },
        Solid::Torus(torus) => Kernel::EllipsoidTorus { semi_axes, torus },
    };
    if flipped {
        Err(FLIP_NOT_BUILT)
    } else {
        Ok(canonical(kernel))
    }
}

/// An ellipsoid (sphere or general) against a plane (bounded or not); `None` when the
/// ellipsoid is flipped.
fn ellipsoid_plane(e: &Ellipsoid, flip_e: bool, p: &Plane, flip_p: bool) -> Option<Selected> {
    if flip_e {
        return None;
    }
    let side = if flip_p { -1.0 } else { 1.0 };
    if !p.is_unbounded() {
        return Some(canonical(match e.sphere_radius() {
            Some(radius) => Kernel::SphereBoundedPlane {
                radius,
                plane: *p,
                side,
            },
            None => Kernel::EllipsoidBoundedPlane {
                semi_axes: e.semi_axes(),
                plane: *p,
                side,
            },
        }));
    }
    Some(canonical(match e.sphere_radius() {
        Some(radius) => Kernel::SpherePlane { radius, side },
        None => Kernel::EllipsoidPlane {
            semi_axes: e.semi_axes(),
            side,
        },
    }))
}
