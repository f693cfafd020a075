//! Signed distance, closest surface point and outward normal for the solids with a short
//! closed form: box, cylinder, frustum (or cone) and ring torus, in the solid's geometry
//! frame.
//!
//! - Outside: the true closest point (a box clamps; a solid of revolution takes the nearest
//!   edge of its half-section in the (ρ, z) half-plane through the point, which is exact
//!   because the surface is swept by that section).
//! - Inside (`s < 0`): the foot on the nearest face (box: the first of +x, −x, +y, −y, +z,
//!   −z on ties; cylinder or frustum: the nearest of side, bottom and top, the first of
//!   bottom, side, top on ties; torus: the tube's surface along the ray from the nearest
//!   point of its centre circle). For a convex solid this is the closest surface point.
//! - Ties: faces whose distances differ by less than `TIE` times the solid's size count
//!   as equally near and the first in the order above wins, so a symmetric pose (a wheel's
//!   centroid midway between its caps) gives the same point whatever the round-off of the
//!   frame it is seen in.
//! - On the axis of a solid of revolution (no radial direction): the radial direction is the
//!   solid's +x axis.

use contact_core::geometry::{Cuboid, Cylinder, Frustum, Torus};
use contact_core::{Vector2, Vector3};

/// Relative difference of distances below which two faces tie.
pub(crate) const TIE: f64 = 1e-12;

/// A solid that answers signed distance queries, in its geometry frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Solid {
    /// A box.
    Box(Cuboid),
    /// A cylinder.
    Cylinder(Cylinder),
    /// A frustum or cone.
    Frustum(Frustum),
    /// A ring torus.
    Torus(Torus),
}

/// `(s, q, n)`: signed distance, closest surface point and outward normal, in the solid's
/// frame, for the point `p` of that frame.
pub(crate) fn signed_distance(solid: &Solid, p: &Vector3) -> (f64, Vector3, Vector3) {
    match solid {
        Solid::Box(b) => box_distance(
            &(p - b.center().coords),
            &b.half_extents(),
            &b.center().coords,
        ),
        Solid::Cylinder(c) => {
            let profile = [
                Vector2::new(0.0, 0.0),
                Vector2::new(c.radius(), 0.0),
                Vector2::new(c.radius(), c.length()),
                Vector2::new(0.0, c.length()),
            ];
            revolved_distance(&profile, p)
        }
        Solid::Frustum(f) => {
            let profile = [
                Vector2::new(0.0, 0.0),
                Vector2::new(f.bottom_radius(), 0.0),
                Vector2::new(f.top_radius(), f.length()),
                Vector2::new(0.0, f.length()),
            ];
            revolved_distance(&profile, p)
        }
        Solid::Torus(t) => {
            let (radial, rho) = radial_of(p);
            // Within round-off of the axis the radial direction is noise: take +x.
            let radial = if rho <= TIE * t.major_radius() {
                Vector2::x()
            } else {
                radial
            };
            let tube_centre = t.major_radius() * Vector3::new(radial.x, radial.y, 0.0);
            let v = p - tube_centre;
            let d = v.norm();
            let n = if d > 0.0 {
                v / d
            } else {
                Vector3::new(radial.x, radial.y, 0.0)
            };
            (d - t.minor_radius(), tube_centre + t.minor_radius() * n, n)
        }
    }
}

/// The unit radial direction of `p` in the x-y plane (+x on the axis) and the radius.
fn radial_of(p: &Vector3) -> (Vector2, f64) {
    let rho = p.xy().norm();
    if rho > 0.0 {
        (p.xy() / rho, rho)
    } else {
        (Vector2::x(), 0.0)
    }
}

fn box_distance(p: &Vector3, h: &Vector3, center: &Vector3) -> (f64, Vector3, Vector3) {
    let outside = (0..3).any(|k| p[k].abs() > h[k]);
    if outside {
        let q = Vector3::new(
            p.x.clamp(-h.x, h.x),
            p.y.clamp(-h.y, h.y),
            p.z.clamp(-h.z, h.z),
        );
        let d = p - q;
        let s = d.norm();
        return (s, q + center, d / s);
    }
    let mut best = (f64::INFINITY, 0, 1.0);
    let tie = TIE * h.max();
    for k in 0..3 {
        for sign in [1.0, -1.0] {
            let gap = h[k] - sign * p[k];
            if gap < best.0 - tie {
                best = (gap, k, sign);
            }
        }
    }
    let (gap, k, sign) = best;
    let mut q = *p;
    q[k] = sign * h[k];
    (-gap, q + center, Vector3::ith(k, sign))
}

/// Signed distance to the solid of revolution about z whose half-section (ρ ≥ 0) is the
/// convex quadrilateral `profile` = [axis bottom, bottom rim, top rim, axis top]; its surface
/// is the three edges bottom, side, top.
fn revolved_distance(profile: &[Vector2; 4], p: &Vector3) -> (f64, Vector3, Vector3) {
    let (radial, rho) = radial_of(p);
    // Within round-off of the axis the radial direction is noise: take +x, as on the axis.
    let (radial, rho) = if rho <= TIE * profile[2].norm().max(profile[1].norm()) {
        (Vector2::x(), 0.0)
    } else {
        (radial, rho)
    };
    let x = Vector2::new(rho, p.z);
    let edges = [
        (profile[0], profile[1]),
        (profile[1], profile[2]),
        (profile[2], profile[3]),
    ];
    // Outward normals of the edges of a counter-clockwise (ρ, z) polygon: (dz, −dρ).
    let outward = |(a, b): (Vector2, Vector2)| {
        let d = b - a;
        Vector2::new(d.y, -d.x) / d.norm()
    };
    let inside = edges
        .iter()
        .filter(|e| (e.1 - e.0).norm() > 0.0)
        .all(|&e| outward(e).dot(&(x - e.0)) <= 0.0);
    let lift = |v: Vector2| Vector3::new(v.x * radial.x, v.x * radial.y, v.y);
    if inside {
        // Nearest face: the smallest distance to an edge's line (the quadrilateral is convex).
        let mut best = (f64::INFINITY, Vector2::zeros(), Vector2::zeros());
        let tie = TIE * profile[2].norm().max(profile[1].norm());
        for &e in edges.iter().filter(|e| (e.1 - e.0).norm() > 0.0) {
            let n = outward(e);
            let gap = -n.dot(&(x - e.0));
            if gap < best.0 - tie {
                best = (gap, x + gap * n, n);
            }
        }
        return (-best.0, lift(best.1), lift(best.2));
    }
    let mut best = (f64::INFINITY, Vector2::zeros());
    for &(a, b) in &edges {
        let d = b - a;
        let len2 = d.norm_squared();
        let t = if len2 > 0.0 {
            ((x - a).dot(&d) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let q = a + t * d;
        let dist = (x - q).norm();
        if dist < best.0 {
            best = (dist, q);
        }
    }
    let (s, q) = best;
    (s, lift(q), lift((x - q) / s))
}
