//! Bodies that are exactly one of the exact engine's primitives: a sphere, a torus, a
//! cylinder, a frustum or a box, recognised from their faces, edges and vertices.
//!
//! | shape | faces | edges |
//! |---|---|---|
//! | sphere | one spherical face without loops | none |
//! | ring torus | one toroidal face without loops (major radius > minor) | none |
//! | cylinder, frustum | a cylindrical or conical face between two planar caps | two full circles without vertices, centred on the axis, in planes normal to it, of the side's radius where they lie |
//! | box | six planar faces of three mutually orthogonal normals, four line edges each | twelve lines, eight vertices at the corners of the box |
//!
//! Geometry agrees within [`RESOLUTION`] (Parasolid's linear resolution, in the file's metres)
//! and directions within `RESOLUTION` radians; anything else is not a primitive and stays a mesh.

use crate::brep::{Body, Face};
use crate::geom::{Curve, Surface};
use contact_core::nalgebra::{Rotation3, Translation3};
use contact_core::{Isometry3, Point3, UnitQuaternion, Vector3};

/// Parasolid's linear resolution (m): lengths that differ by less are equal.
pub const RESOLUTION: f64 = 1e-8;

/// A primitive's dimensions (metres), in the frame of [`Primitive::frame`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// A sphere centred on the frame's origin.
    Sphere {
        /// Radius.
        radius: f64,
    },
    /// A ring torus centred on the origin, about z.
    Torus {
        /// Radius of the centre circle.
        major: f64,
        /// Radius of the tube.
        minor: f64,
    },
    /// A frustum (a cylinder when the radii are equal): radius `bottom` at z = 0, `top` at
    /// z = `length`.
    Frustum {
        /// Radius at z = 0.
        bottom: f64,
        /// Radius at z = `length`.
        top: f64,
        /// Length along +z.
        length: f64,
    },
    /// A box centred on the origin with these half extents along x, y, z.
    Box {
        /// Half extents.
        half: [f64; 3],
    },
}

/// A body recognised as a primitive: its shape and where its frame lies in the body's
/// coordinates (metres).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Primitive {
    /// The shape.
    pub shape: Shape,
    /// The shape's frame in the body's coordinates.
    pub frame: Isometry3,
}

/// The primitive `body` is exactly, if any.
pub fn recognise(body: &Body) -> Option<Primitive> {
    match body.faces.len() {
        1 => closed_face(body),
        3 => revolved(body),
        6 => cuboid(body),
        _ => None,
    }
}

fn parallel(a: &Vector3, b: &Vector3) -> bool {
    a.cross(b).norm() <= RESOLUTION
}

/// A frame at `origin` whose z axis is `z` (unit) and x axis `x` (unit, normal to z).
fn frame(origin: Point3, x: Vector3, z: Vector3) -> Isometry3 {
    let y = z.cross(&x);
    let r = Rotation3::from_basis_unchecked(&[x, y, z]);
    Isometry3::from_parts(
        Translation3::from(origin.coords),
        UnitQuaternion::from_rotation_matrix(&r),
    )
}

/// A sphere or a ring torus: one face, no loops, no edges.
fn closed_face(body: &Body) -> Option<Primitive> {
    let face = &body.faces[0];
    if !face.loops.is_empty() || !body.edges.is_empty() {
        return None;
    }
    match face.surface {
        Surface::Sphere { c, r, .. } => Some(Primitive {
            shape: Shape::Sphere { radius: r },
            frame: Isometry3::translation(c.x, c.y, c.z),
        }),
        Surface::Torus {
            c,
            a,
            x,
            big,
            small,
            ..
        } if big > small + RESOLUTION => Some(Primitive {
            shape: Shape::Torus {
                major: big,
                minor: small,
            },
            frame: frame(c, x, a),
        }),
        _ => None,
    }
}

/// The circle of the single ring edge of a one-fin loop: centre, unit normal, radius.
fn ring(body: &Body, fins: &[crate::brep::FinUse]) -> Option<(Point3, Vector3, f64)> {
    let [fin] = fins else { return None };
    let edge = &body.edges[fin.edge];
    if edge.start.is_some() || edge.end.is_some() {
        return None;
    }
    match edge.curve {
        Curve::Ellipse { c, x, y, a, b } if (a - b).abs() <= RESOLUTION => {
            Some((c, x.cross(&y).normalize(), a))
        }
        _ => None,
    }
}

/// A cylinder or frustum: a side on a cone (tan = 0 for a cylinder) with two loops of one
/// ring edge each, and two planar caps each bounded by one of those rings.
fn revolved(body: &Body) -> Option<Primitive> {
    let side = body
        .faces
        .iter()
        .position(|f| matches!(f.surface, Surface::Cone { .. }))?;
    let Surface::Cone {
        o, a, x, r, tan, ..
    } = body.faces[side].surface
    else {
        return None;
    };
    let caps: Vec<&Face> = (0..3)
        .filter(|&k| k != side)
        .map(|k| &body.faces[k])
        .collect();
    if body.faces[side].loops.len() != 2 || body.edges.len() != 2 {
        return None;
    }
    let mut ends = Vec::new();
    for cap in caps {
        let Surface::Plane {
            o: po,
            x: px,
            y: py,
        } = cap.surface
        else {
            return None;
        };
        let [lp] = cap.loops.as_slice() else {
            return None;
        };
        let (c, n, radius) = ring(body, lp)?;
        let v = (c - o).dot(&a);
        let off_axis = (c - o - a * v).norm();
        let on_side = (r + v * tan - radius).abs();
        let in_cap = (c - po).dot(&px.cross(&py)).abs();
        if off_axis > RESOLUTION
            || on_side > RESOLUTION
            || in_cap > RESOLUTION
            || !parallel(&n, &a)
            || !parallel(&px.cross(&py), &a)
        {
            return None;
        }
        ends.push((v, radius));
    }
    ends.sort_by(|p, q| p.0.total_cmp(&q.0));
    let ((v0, bottom), (v1, top)) = (ends[0], ends[1]);
    if v1 - v0 <= RESOLUTION || bottom <= RESOLUTION || top <= RESOLUTION {
        return None;
    }
    Some(Primitive {
        shape: Shape::Frustum {
            bottom,
            top,
            length: v1 - v0,
        },
        frame: frame(o + a * v0, x, a),
    })
}

/// A box: six planar faces of three mutually orthogonal normal directions, bounded by twelve
/// lines, with eight vertices at the corners.
fn cuboid(body: &Body) -> Option<Primitive> {
    if body.edges.len() != 12 || body.vertices.len() != 8 {
        return None;
    }
    let mut normals = Vec::with_capacity(6);
    for f in &body.faces {
        let Surface::Plane { x, y, .. } = f.surface else {
            return None;
        };
        if f.loops.len() != 1 || f.loops[0].len() != 4 {
            return None;
        }
        normals.push(x.cross(&y).normalize());
    }
    if body
        .edges
        .iter()
        .any(|e| !matches!(e.curve, Curve::Line { .. }))
    {
        return None;
    }
    let e1 = normals[0];
    let e2 = *normals.iter().find(|n| n.dot(&e1).abs() <= RESOLUTION)?;
    let e3 = e1.cross(&e2);
    let axes = [e1, e2, e3];
    for n in &normals {
        if !axes.iter().any(|e| parallel(n, e)) {
            return None;
        }
    }
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in &body.vertices {
        for k in 0..3 {
            let s = p.coords.dot(&axes[k]);
            lo[k] = lo[k].min(s);
            hi[k] = hi[k].max(s);
        }
    }
    let mut corners = std::collections::HashSet::new();
    for p in &body.vertices {
        let mut key = 0u8;
        for k in 0..3 {
            let s = p.coords.dot(&axes[k]);
            match (
                (s - lo[k]).abs() <= RESOLUTION,
                (s - hi[k]).abs() <= RESOLUTION,
            ) {
                (true, false) => {}
                (false, true) => key |= 1 << k,
                _ => return None,
            }
        }
        corners.insert(key);
    }
    if corners.len() != 8 {
        return None;
    }
    let half = [0, 1, 2].map(|k| (hi[k] - lo[k]) / 2.0);
    let centre = axes
        .iter()
        .enumerate()
        .fold(Vector3::zeros(), |c, (k, e)| c + e * (lo[k] + hi[k]) / 2.0);
    Some(Primitive {
        shape: Shape::Box { half },
        frame: frame(Point3::from(centre), e1, e3),
    })
}

#[cfg(test)]
mod tests;
