//! Closed forms for the characterization, written separately from the engine: each derives
//! its answer another way (slicing, axis-aligned overlap, vertex averages) from a
//! configuration placed in a canonical frame, so a shared mistake is unlikely.

use crate::common::Expected;
use contact_core::{Isometry3, Matrix3, Point3, UnitQuaternion, Vector3};

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
    // SPEC §4 along the normal: where the line from the centroid along −z leaves the box.
    let local = r.transpose() * (centroid - centre);
    let foot = centre + r * box_exit(h, &local, &(r.transpose() * -Vector3::z()));
    Some((
        centre,
        Expected {
            point_i: foot,
            point_j: Point3::new(centroid.x, centroid.y, 0.0),
            normal: Vector3::z(),
            depth: (foot - Point3::new(centroid.x, centroid.y, 0.0)).norm(),
        },
    ))
}

/// Two axis-aligned boxes (centres, half extents) that overlap: the intersection is the box
/// of per-axis overlaps, its centroid the box's centre; the points are where the line through
/// the centroid along the normal leaves each box (SPEC §4); the normal is the area vector of `b`'s faces lying strictly inside
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
    let point_i = ca + box_exit(ha, &(c - ca), &-n);
    let point_j = cb + box_exit(hb, &(c - cb), &n);
    Some(Expected {
        point_i,
        point_j,
        normal: n,
        depth: (point_i - point_j).norm(),
    })
}

/// A cylinder (radius `r`, length `len`, axis tilted by `alpha` about y, base-centre height
/// `z0`) against the plane z = 0, by slicing *across* the axis: the slice at axial height z is
/// a circular segment with chord offset `s(z) = (h − b z)/a` (area `R² acos(−s/R) + s√(R²−s²)`,
/// first moment `−(2/3)(R² − s²)^{3/2}`). With `s = −R cos θ` the partial part is smooth in
/// θ and integrated by composite Simpson (4,000 panels: error ~1e-13); the full-disc part is
/// exact. The points are the centroid's foot on the plane and where the line from the
/// centroid along −z leaves the cylinder ([`cylinder_exit`]). Needs `a = |sin α|` and `b = cos α` both away from zero.
pub fn cylinder_plane_tilted(r: f64, len: f64, alpha: f64, z0: f64) -> Expected {
    let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), alpha);
    let n = q.inverse_transform_vector(&Vector3::z());
    let (a, b) = (n.xy().norm(), n.z);
    let e = n.xy() / a;
    let h = -z0;
    let z_of = |theta: f64| (h + a * r * theta.cos()) / b;
    let area = |theta: f64| r * r * (theta - theta.sin() * theta.cos());
    let moment = |theta: f64| -2.0 / 3.0 * r.powi(3) * theta.sin().powi(3);
    let jac = |theta: f64| a * r * theta.sin() / b.abs();
    let theta_at = |z: f64| ((b * z - h) / (a * r)).clamp(-1.0, 1.0).acos();
    let (t0, t1) = {
        let (x, y) = (theta_at(0.0), theta_at(len));
        (x.min(y), x.max(y))
    };
    let panels = 4000;
    let step = (t1 - t0) / panels as f64;
    let (mut v, mut mu, mut mz) = (0.0, 0.0, 0.0);
    for k in 0..=panels {
        let t = t0 + k as f64 * step;
        let w = if k == 0 || k == panels {
            1.0
        } else if k % 2 == 1 {
            4.0
        } else {
            2.0
        } * step
            / 3.0;
        let j = jac(t);
        v += w * area(t) * j;
        mu += w * moment(t) * j;
        mz += w * z_of(t) * area(t) * j;
    }
    // Full discs: b z ≤ h − a R.
    let bound = (h - a * r) / b;
    let (lo, hi) = if b > 0.0 {
        (0.0, bound.min(len))
    } else {
        (bound.max(0.0), len)
    };
    if hi > lo {
        let disc = std::f64::consts::PI * r * r;
        v += disc * (hi - lo);
        mz += disc * (hi * hi - lo * lo) / 2.0;
    }
    let u_bar = mu / v;
    let centroid_c = Vector3::new(e.x * u_bar, e.y * u_bar, mz / v);
    // SPEC §4 along the normal: where the line from the centroid along −z leaves the
    // cylinder, and the centroid's foot on the plane.
    let foot_c = cylinder_exit(r, len, &centroid_c, &-n);
    let pose = Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, z0), q);
    let centroid = pose * Point3::from(centroid_c);
    let point_i = pose * Point3::from(foot_c);
    let point_j = Point3::new(centroid.x, centroid.y, 0.0);
    Expected {
        point_i,
        point_j,
        normal: Vector3::z(),
        depth: (point_i - point_j).norm(),
    }
}

/// The point of a curve closest to `p`, by dense sampling (64 per span) then bisection on the
/// sign change of `(C(u) − p)·C′(u)` around the nearest sample (to 1e-15 of the span) — a
/// different method from the engine's Newton, on `contact-core`'s own evaluator. Returns (signed distance along the
/// outward normal, closest point, outward normal).
pub fn curve_closest(
    curve: &contact_core::geometry::Curve,
    p: &contact_core::Point2,
) -> (f64, contact_core::Point2, contact_core::Vector2) {
    let dist = |u: f64| (curve.point(u) - p).norm_squared();
    let spans = curve.breakpoints();
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for w in spans.windows(2) {
        let step = (w[1] - w[0]) / 64.0;
        for k in 0..=64 {
            let u = w[0] + k as f64 * step;
            let d = dist(u);
            if d < best.0 {
                best = (d, u, step);
            }
        }
    }
    let [u0, u1] = curve.domain();
    let slope = |u: f64| (curve.point(u) - p).dot(&curve.derivative(u));
    let (mut a, mut b) = ((best.1 - best.2).max(u0), (best.1 + best.2).min(u1));
    // A minimum strictly inside has slope < 0 before and > 0 after; at an end it stays put.
    let u = if slope(a) < 0.0 && slope(b) > 0.0 {
        while b - a > 1e-15 * (u1 - u0) {
            let m = 0.5 * (a + b);
            if slope(m) < 0.0 { a = m } else { b = m }
        }
        0.5 * (a + b)
    } else {
        best.1
    };
    let q = curve.point(u);
    let n = curve.normal(u).unwrap();
    ((p - q).dot(&n), q, n)
}

/// A sphere of radius `r` near a box of half extents `h` centred at the origin: its centre
/// at `face + d·(outward direction)` where the closest feature is a face, an edge or a
/// corner, chosen by `feature` (1, 2 or 3 axes outside). The closest point of the box is the
/// centre clamped to the box; the normal runs from it to the centre.
pub fn sphere_box(
    r: f64,
    h: &Vector3,
    inside_point: &Vector3,
    outward: &Vector3,
    d: f64,
) -> (Point3, Expected) {
    // `inside_point` lies on the box's surface feature; `outward` is a unit vector in the
    // feature's normal cone.
    let centre = Point3::from(inside_point + d * outward);
    let q = Point3::new(
        centre.x.clamp(-h.x, h.x),
        centre.y.clamp(-h.y, h.y),
        centre.z.clamp(-h.z, h.z),
    );
    let n = (centre - q).normalize();
    (
        centre,
        Expected {
            point_i: centre - r * n,
            point_j: q,
            normal: n,
            depth: r - (centre - q).norm(),
        },
    )
}

/// A sphere of radius `r` with its centre at (ρ, 0, z) in a torus' frame (major `big`, minor
/// `small`): the nearest tube centre is (big, 0, 0).
pub fn sphere_torus(r: f64, big: f64, small: f64, rho: f64, z: f64) -> Expected {
    let c = Vector3::new(rho, 0.0, z);
    let tube = Vector3::new(big, 0.0, 0.0);
    let n = (c - tube).normalize();
    Expected {
        point_i: Point3::from(c - r * n),
        point_j: Point3::from(tube + small * n),
        normal: n,
        depth: r - ((c - tube).norm() - small),
    }
}

/// Where the line from `p` along the unit `d` leaves a solid given by its inside test, found
/// by bisection on that test alone (independent of any intersection formula): `reach` is a
/// length past which the line is surely outside; for a non-convex solid `step` marches to the
/// first outside point before bisecting (0 for a convex one).
pub fn exit_by_bisection(
    inside: impl Fn(&Vector3) -> bool,
    p: &Vector3,
    d: &Vector3,
    reach: f64,
    step: f64,
) -> Vector3 {
    let (mut lo, mut hi) = (0.0, reach);
    if step > 0.0 {
        let mut t = step;
        while t < reach && inside(&(p + t * d)) {
            lo = t;
            t += step;
        }
        hi = t.min(reach);
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if inside(&(p + mid * d)) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    p + 0.5 * (lo + hi) * d
}

/// The exit of the line from `p` along `d` from the box centred at the origin with half
/// extents `h` (box frame).
pub fn box_exit(h: &Vector3, p: &Vector3, d: &Vector3) -> Vector3 {
    let inside = |x: &Vector3| (0..3).all(|k| x[k].abs() <= h[k]);
    exit_by_bisection(inside, p, d, 4.0 * h.norm() + p.norm(), 0.0)
}

/// The exit of the line from `p` along `d` from the cylinder of radius `r` on the z axis from
/// 0 to `len` (cylinder frame).
pub fn cylinder_exit(r: f64, len: f64, p: &Vector3, d: &Vector3) -> Vector3 {
    let inside = |x: &Vector3| x.xy().norm() <= r && x.z >= 0.0 && x.z <= len;
    exit_by_bisection(inside, p, d, 4.0 * (r + len) + p.norm(), 0.0)
}
