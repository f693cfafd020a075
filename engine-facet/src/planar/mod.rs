//! 2-D contacts on polylines: the exact engine's 2-D pairs answered on the tessellated shapes.
//!
//! Circles, arcs and curves are tessellated to polylines at the faceting tolerance (chord
//! deviation `L/FT`, [`crate::tessellate`]); the 2-D line (PLANE) and the point stay exact.
//! Each polyline keeps the true outward normal at its points.
//!
//! ## The pairs and their answers (the exact engine's definitions, on the polylines)
//! In every pair one side is the **mover** — a point, or a solid circle as a polygon — and the
//! other the **surface** — a line, a circle's polygon (solid, or a hole when flipped), an arc
//! or a curve. For two solid circles the J circle is the surface. With `c` the mover's centre
//! in the surface's plane, `q` the nearest point of the surface's polyline, `s` the signed
//! distance (negative in the material) and `n` the outward normal at `q`, interpolated along
//! the chord between the true normals at its ends (so it turns smoothly as `c` moves, where
//! the chords' own normals would jump):
//! - **point:** contact iff `s < 0`; δ = `−s`, points `c` and `q`, normal `n`; length 0.
//! - **circle polygon:** with `h` the polygon's support along `−n` from `c`, contact iff
//!   `h − s > 0`; δ = `h − s`, points `c − h·n` and
//!   `q`; length `2√(h² − s²)` while `c` is outside the material, `2h` once inside.
//! - **line:** the exact half-plane: `s` is `c`'s height, `q` its foot; a point beyond a
//!   bounded line's ends has no contact (circles need an unbounded line here; the exact
//!   engine also builds a circle on a bounded one).
//! - **ends of open polylines:** when `q` is an open end and `c` lies beyond it along the
//!   tangent, no contact (no material there), as in the exact engine.
//!
//! The surface's foot and the mover's support are lifted from the chords onto cubic Hermite
//! arcs through the chord ends with the true tangents there (the 2-D counterpart of the
//! PN triangles of the 3-D meshes): a chord of angle θ on a circle of radius R departs from it
//! by `R·θ²/8`, the Hermite arc by `O(R·θ⁴)`.
//!
//! Error bound: every polyline lies within `d = L/FT` of its shape; after the lift the depth
//! error is second order, `O(d²/ρ)` with ρ the smallest radius of curvature involved
//! (measured on two circles 0.4 and 1: 6e-5 at the default FT, 5e-6 at 1000, against
//! chord deviations of 1.3e-2 and 4e-3); the normal is exact on circles and arcs (their
//! points carry radial normals, so the normal field's foot lies on the ray from the centre)
//! and within `O(d/ρ)` rad on curves (1.8° at the default FT on the test blob, 0.5° at 1000).
//!
//! The two geometries must share a plane, as in the exact engine: their z axes within
//! [`PLANE_ANGLE_TOLERANCE`] rad (either orientation) and the mover's origin within
//! `PLANE_OFFSET_TOLERANCE · L` of the surface's plane; otherwise the query fails with
//! [`QueryError::OutOfPlane`](contact_core::QueryError::OutOfPlane).

mod boundary;
mod chain;
mod crossings;
mod orient;
mod overlap;

pub use boundary::{Boundary, Nearest};

use contact_core::geometry::{Line, plane_departure};
use contact_core::{GeometryKind, Isometry3, Point2, Point3, Vector2, Vector3, WorkCounters};

pub use contact_core::geometry::{PLANE_ANGLE_TOLERANCE, PLANE_OFFSET_TOLERANCE};

/// A prepared 2-D geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct Planar {
    /// Its kind (for messages).
    pub kind: GeometryKind,
    /// Its characteristic length, `None` for a point or an unbounded line.
    pub length: Option<f64>,
    /// What it became.
    pub shape: PlanarShape,
}

/// What a 2-D geometry becomes in the faceted engine.
#[derive(Debug, Clone, PartialEq)]
pub enum PlanarShape {
    /// A point (exact).
    Point,
    /// A circle's polygon; `hole` when flipped (the material outside it).
    Disc {
        /// The polygon, outward normals reversed for a hole.
        polygon: Boundary,
        /// True for a flipped circle.
        hole: bool,
    },
    /// An arc or a curve.
    Boundary(Boundary),
    /// The 2-D line (exact): material at `side·y ≤ 0`.
    Line {
        /// Its extent along x.
        line: Line,
        /// +1, or −1 when flipped.
        side: f64,
    },
}

/// One 2-D contact in the world, J into I.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarContact {
    /// Point on I.
    pub point_i: Point3,
    /// Point on J.
    pub point_j: Point3,
    /// Unit normal from J into I.
    pub normal: Vector3,
    /// Penetration.
    pub depth: f64,
    /// Length of the contact (the 2-D "area").
    pub length: f64,
}

/// The two planes of a 2-D pair do not coincide.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutOfPlane {
    /// Angle between the plane normals (either orientation).
    pub angle_rad: f64,
    /// Distance of the mover's origin from the surface's plane.
    pub offset: f64,
}

enum Mover<'a> {
    Point,
    Disc(&'a Boundary),
}

enum Surface<'a> {
    Boundary(&'a Boundary),
    Line(&'a Line, f64),
}

fn as_surface(shape: &PlanarShape) -> Option<Surface<'_>> {
    match shape {
        PlanarShape::Point => None,
        PlanarShape::Disc { polygon, .. } | PlanarShape::Boundary(polygon) => {
            Some(Surface::Boundary(polygon))
        }
        PlanarShape::Line { line, side } => Some(Surface::Line(line, *side)),
    }
}

fn as_mover(shape: &PlanarShape) -> Option<Mover<'_>> {
    match shape {
        PlanarShape::Point => Some(Mover::Point),
        PlanarShape::Disc {
            polygon,
            hole: false,
        } => Some(Mover::Disc(polygon)),
        _ => None,
    }
}

/// True for the two boundaries of an overlap pair: arcs, curves and lines, not two lines.
fn overlap_pair(i: &PlanarShape, j: &PlanarShape) -> bool {
    let boundary = |s: &PlanarShape| matches!(s, PlanarShape::Boundary(_));
    let line = |s: &PlanarShape| matches!(s, PlanarShape::Line { .. });
    (boundary(i) && (boundary(j) || line(j))) || (line(i) && boundary(j))
}

/// Whether the faceted engine answers `i` against `j` (flips included): the pairs of the
/// module doc. Returns the reason when not.
pub fn supported(i: &PlanarShape, j: &PlanarShape) -> Result<(), &'static str> {
    if overlap_pair(i, j) {
        return Ok(());
    }
    let roles = (as_mover(i).is_some() && as_surface(j).is_some())
        || (as_mover(j).is_some() && as_surface(i).is_some());
    if !roles {
        return Err(
            "the faceted engine answers a point or a solid circle against a line, circle, arc or curve (and a solid circle in a flipped one), and arcs and curves against arcs, curves and lines; this pair is none of these",
        );
    }
    let bounded_line_for_disc = |m: &PlanarShape, s: &PlanarShape| {
        matches!(m, PlanarShape::Disc { .. })
            && matches!(s, PlanarShape::Line { line, .. } if line.x_range().iter().any(|x| x.is_finite()))
    };
    if bounded_line_for_disc(i, j) || bounded_line_for_disc(j, i) {
        return Err("a circle against a bounded 2-D PLANE is not built; use an unbounded line");
    }
    Ok(())
}

/// The contacts of 2-D geometry `i` at `pose_wi` (`X_WG`) against `j` at `pose_wj`, passed
/// to `emit` (at most one for a mover pair, one per overlap region for two boundaries);
/// `length` is the pair's length scale.
pub fn contacts(
    i: &PlanarShape,
    pose_wi: &Isometry3,
    j: &PlanarShape,
    pose_wj: &Isometry3,
    length: f64,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PlanarContact),
) -> Result<(), OutOfPlane> {
    if overlap_pair(i, j) {
        return boundaries(i, pose_wi, j, pose_wj, length, work, emit);
    }
    if let Some(c) = contact(i, pose_wi, j, pose_wj, length)? {
        emit(c);
    }
    Ok(())
}

/// The contact of a mover pair (a point or a solid circle against a surface): `i` at
/// `pose_wi` (`X_WG`) against `j` at `pose_wj`; `length` is the pair's length scale. Two
/// boundaries answer `None` here: see [`contacts`].
pub fn contact(
    i: &PlanarShape,
    pose_wi: &Isometry3,
    j: &PlanarShape,
    pose_wj: &Isometry3,
    length: f64,
) -> Result<Option<PlanarContact>, OutOfPlane> {
    // The mover is I unless only J can move against I, or both circles are solid and J
    // is the surface by convention — which is the same choice.
    if let (Some(mover), Some(surface)) = (as_mover(i), as_surface(j)) {
        return mover_surface(&mover, pose_wi, &surface, pose_wj, length);
    }
    match (as_mover(j), as_surface(i)) {
        (Some(mover), Some(surface)) => {
            Ok(mover_surface(&mover, pose_wj, &surface, pose_wi, length)?.map(swap))
        }
        // `prepare` refuses every other pair; two boundaries go through `contacts`.
        _ => Ok(None),
    }
}

/// Two boundaries (arcs, curves, lines): the overlap regions of [`overlap`], computed in
/// J's plane, or in the line's when I is the line (then swapped back).
fn boundaries(
    i: &PlanarShape,
    pose_wi: &Isometry3,
    j: &PlanarShape,
    pose_wj: &Isometry3,
    length: f64,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PlanarContact),
) -> Result<(), OutOfPlane> {
    let (a, pose_wa, b, pose_wb, swapped) = match i {
        PlanarShape::Line { .. } => (j, pose_wj, i, pose_wi, true),
        _ => (i, pose_wi, j, pose_wj, false),
    };
    let PlanarShape::Boundary(a) = a else {
        return Ok(());
    };
    let relative = pose_wb.inv_mul(pose_wa);
    if let Some((angle_rad, offset)) = plane_departure(&relative, length) {
        return Err(OutOfPlane { angle_rad, offset });
    }
    let x = relative.rotation * Vector3::x();
    let y = relative.rotation * Vector3::y();
    let m = nalgebra::Matrix2::new(x.x, y.x, x.y, y.y);
    let t = relative.translation.vector.xy();
    overlap::with_buffers(|buffers| {
        buffers.a.fill_placed(a, &m, &t);
        match b {
            PlanarShape::Boundary(b) => {
                buffers
                    .b
                    .fill_placed(b, &nalgebra::Matrix2::identity(), &Vector2::zeros());
            }
            PlanarShape::Line { line, side } => {
                // The line cut to where `a` can reach it: `a`'s x extent widened by its size.
                let (lo, hi) = buffers.a.bounding_box();
                let margin = (hi - lo).norm();
                let (cut0, cut1) = (lo.x - margin, hi.x + margin);
                let [x0, x1] = line.x_range();
                let (c0, c1) = (x0.max(cut0), x1.min(cut1));
                if c0.is_nan() || c1.is_nan() || c0 >= c1 {
                    return;
                }
                buffers.b.fill_line(c0, c1, [x0 >= cut0, x1 <= cut1], *side);
            }
            PlanarShape::Point | PlanarShape::Disc { .. } => return,
        }
        let point_w = |p: Vector2| pose_wb * Point3::new(p.x, p.y, 0.0);
        overlap::contacts(buffers, work, &mut |c| {
            let found = PlanarContact {
                point_i: point_w(c.point_a),
                point_j: point_w(c.point_b),
                normal: pose_wb.rotation * Vector3::new(c.normal.x, c.normal.y, 0.0),
                depth: c.depth,
                length: c.length,
            };
            emit(if swapped { swap(found) } else { found });
        });
    });
    Ok(())
}

fn swap(c: PlanarContact) -> PlanarContact {
    PlanarContact {
        point_i: c.point_j,
        point_j: c.point_i,
        normal: -c.normal,
        ..c
    }
}

fn mover_surface(
    mover: &Mover<'_>,
    pose_wm: &Isometry3,
    surface: &Surface<'_>,
    pose_ws: &Isometry3,
    length: f64,
) -> Result<Option<PlanarContact>, OutOfPlane> {
    let relative = pose_ws.inv_mul(pose_wm);
    if let Some((angle_rad, offset)) = plane_departure(&relative, length) {
        return Err(OutOfPlane { angle_rad, offset });
    }
    let t = relative.translation.vector;
    let c = Point2::new(t.x, t.y);
    let (s, q, n) = match surface {
        Surface::Boundary(b) => match b.nearest(&c) {
            Some(near) => (near.signed_distance, near.point, near.normal),
            None => return Ok(None),
        },
        Surface::Line(line, side) => {
            let [x0, x1] = line.x_range();
            if c.x < x0 || c.x > x1 {
                return Ok(None);
            }
            (side * c.y, Point2::new(c.x, 0.0), Vector2::new(0.0, *side))
        }
    };
    // The mover's reach along −n from its centre.
    let h = match mover {
        Mover::Point => 0.0,
        Mover::Disc(polygon) => {
            let back = relative.rotation.inverse() * Vector3::new(-n.x, -n.y, 0.0);
            polygon.support(&back.xy())
        }
    };
    let depth = h - s;
    if depth <= 0.0 {
        return Ok(None);
    }
    let chord = match mover {
        Mover::Point => 0.0,
        Mover::Disc(_) if s > 0.0 => 2.0 * ((h - s) * (h + s)).max(0.0).sqrt(),
        Mover::Disc(_) => 2.0 * h,
    };
    let world = |p: Point2| pose_ws * Point3::new(p.x, p.y, 0.0);
    Ok(Some(PlanarContact {
        point_i: world(c - h * n),
        point_j: world(q),
        normal: pose_ws.rotation * Vector3::new(n.x, n.y, 0.0),
        depth,
        length: chord,
    }))
}
