//! Closed forms for the characterization, written separately from the engine: each derives
//! its answer another way (slicing, axis-aligned overlap, vertex averages) from a
//! configuration placed in a canonical frame, so a shared mistake is unlikely.

use crate::common::Expected;
use contact_core::{Matrix3, Point3, UnitQuaternion, Vector3};

/// Sphere of radius `r` with its centre at height `d` above the plane z = 0.
pub fn sphere_plane(r: f64, d: f64) -> Expected {
    Expected {
        point_i: Point3::new(0.0, 0.0, d - r),
        point_j: Point3::origin(),
        normal: Vector3::z(),
        depth: r - d,
    }
}

/// Sphere `a` at `distance·u` from sphere `b` at the origin.
pub fn sphere_sphere(ra: f64, rb: f64, distance: f64, u: &Vector3) -> Expected {
    Expected {
        point_i: Point3::from(u * (distance - ra)),
        point_j: Point3::from(u * rb),
        normal: *u,
        depth: ra + rb - distance,
    }
}

/// Ellipsoid with semi-axes `s`, orientation `q`, centre at height `z0` above the plane z = 0.
/// Centroid by slicing normal to the plane: the section at `n·x = τ` (ellipsoid frame) is an
/// ellipse of area ∝ 1 − τ²/k² centred at τ·S²n/k², `k² = nᵀS²n`; the moments are
/// polynomial integrals over τ ∈ [−k, min(h, k)].
pub fn ellipsoid_plane(s: &Vector3, q: &UnitQuaternion, z0: f64) -> Expected {
    let n = q.inverse_transform_vector(&Vector3::z());
    let s2n = Vector3::new(s.x * s.x * n.x, s.y * s.y * n.y, s.z * s.z * n.z);
    let k2 = n.dot(&s2n);
    let k = k2.sqrt();
    let h = (-z0).min(k);
    let f1 = |t: f64| t - t * t * t / (3.0 * k2);
    let f2 = |t: f64| t * t / 2.0 - t.powi(4) / (4.0 * k2);
    let tau_bar = (f2(h) - f2(-k)) / (f1(h) - f1(-k));
    let centroid_e = s2n * (tau_bar / k2);
    let centroid = Point3::new(0.0, 0.0, z0) + (q * centroid_e);
    // Ray centroid − t·z leaves the ellipsoid: |S⁻¹ Rᵀ(centroid − t z − centre)|² = 1.
    let inv_s = Matrix3::from_diagonal(&s.map(|v| 1.0 / v));
    let p = inv_s * centroid_e;
    let w = inv_s * n;
    let (a2, b1, c0) = (w.dot(&w), -2.0 * p.dot(&w), p.dot(&p) - 1.0);
    let t = (-b1 + (b1 * b1 - 4.0 * a2 * c0).sqrt()) / (2.0 * a2);
    Expected {
        point_i: centroid - t * Vector3::z(),
        point_j: Point3::new(centroid.x, centroid.y, 0.0),
        normal: Vector3::z(),
        depth: t - centroid.z,
    }
}

/// A box with half extents `h` and orientation `q`, lowered so only its lowest corner is
/// below the plane z = 0, by `e`. The intersection is the tetrahedron of that corner and
/// the three edge crossings; its centroid is their mean. Returns the box centre and the
/// answer, or `None` if a second corner would be below the plane.
pub fn box_corner_plane(h: &Vector3, q: &UnitQuaternion, e: f64) -> Option<(Point3, Expected)> {
    let r = q.to_rotation_matrix();
    let mut corners = Vec::new();
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            for sz in [-1.0, 1.0] {
                corners.push((
                    Vector3::new(sx, sy, sz),
                    r * Vector3::new(sx * h.x, sy * h.y, sz * h.z),
                ));
            }
        }
    }
    corners.sort_by(|a, b| a.1.z.total_cmp(&b.1.z));
    let (signs, low) = corners[0];
    if corners[1].1.z - low.z <= e {
        return None;
    }
    let centre = Point3::new(0.0, 0.0, -e - low.z);
    let v0 = centre + low;
    let mut points = vec![v0];
    for k in 0..3 {
        let mut other = signs;
        other[k] = -other[k];
        let v1 = centre + r * Vector3::new(other.x * h.x, other.y * h.y, other.z * h.z);
        let t = -v0.z / (v1.z - v0.z);
        points.push(v0 + t * (v1 - v0));
    }
    let centroid = Point3::from(points.iter().map(|p| p.coords).sum::<Vector3>() / 4.0);
    // Exit downwards through one of the three faces at the corner.
    let mut t_exit = f64::INFINITY;
    for k in 0..3 {
        let outward = r * (Vector3::ith(k, 1.0) * signs[k]);
        let rate = -outward.z;
        if rate > 0.0 {
            t_exit = t_exit.min(outward.dot(&(v0 - centroid)) / rate);
        }
    }
    Some((
        centre,
        Expected {
            point_i: centroid - t_exit * Vector3::z(),
            point_j: Point3::new(centroid.x, centroid.y, 0.0),
            normal: Vector3::z(),
            depth: t_exit - centroid.z,
        },
    ))
}

/// Two axis-aligned boxes (centres, half extents) that overlap: the intersection is the box
/// of per-axis overlaps; the normal is the area vector of `b`'s faces lying strictly inside
/// `a`'s slab along their axis, each contributing the product of the other two overlaps.
/// `None` when that area vector is zero (b's faces inside a cancel, e.g. a crossing 'plus').
pub fn aligned_boxes(ca: &Point3, ha: &Vector3, cb: &Point3, hb: &Vector3) -> Option<Expected> {
    let lo = (ca - ha).sup(&(cb - hb));
    let hi = (ca + ha).inf(&(cb + hb));
    let overlap = hi - lo;
    let c = Point3::from((lo.coords + hi.coords) / 2.0);
    let mut s = Vector3::zeros();
    for k in 0..3 {
        for side in [-1.0, 1.0] {
            let f = cb[k] + side * hb[k];
            if f > ca[k] - ha[k] && f < ca[k] + ha[k] {
                s[k] += side * overlap[(k + 1) % 3] * overlap[(k + 2) % 3];
            }
        }
    }
    if s == Vector3::zeros() {
        return None;
    }
    let n = s.normalize();
    let exit = |centre: &Point3, half: &Vector3, dir: &Vector3| {
        (0..3)
            .filter(|&k| dir[k] != 0.0)
            .map(|k| (centre[k] + dir[k].signum() * half[k] - c[k]) / dir[k])
            .fold(f64::INFINITY, f64::min)
    };
    let tb = exit(cb, hb, &n);
    let ta = exit(ca, ha, &-n);
    Some(Expected {
        point_i: c - ta * n,
        point_j: c + tb * n,
        normal: n,
        depth: ta + tb,
    })
}
