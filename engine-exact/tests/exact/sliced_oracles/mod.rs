//! Oracles for the cylinder–cylinder and cylinder–box pairs, written apart from the engine's
//! slicing: closed forms where they exist (two parallel cylinders: a circle–circle lens times
//! the axial overlap; a box face cutting the side or the cap: a circular segment times the
//! length), and elsewhere quadratures along another direction:
//!
//! - cylinder–box, any pose: slices perpendicular to the cylinder's axis, each a disc meeting
//!   the box's convex section, whose area and moments are closed form by Green's theorem
//!   (edges clipped to the disc, arcs inside the polygon);
//! - crossed cylinders: slices perpendicular to both axes, each section's area and moments
//!   integrated exactly across `u` as a piecewise-linear length (no polygon clipping);
//!
//! both integrated by an adaptive 7-point Gauss–Legendre rule that halves in the plain
//! variable, with the square-root ends mapped away by `t = m + h·sin θ`. The area vector
//! `S_a` of the cylinder's surface inside the other solid is, for the box, the same rule
//! around the cylinder's side (the length of each of its lines inside the box) plus the caps'
//! parts inside the box's sections; for crossed cylinders, the negative gradient of the
//! oracle's volume with respect to translating the other solid (`−∂V/∂x_b`: moving `b` by `δ`
//! changes the volume by `S_b·δ`, and `S_b = −S_a` over the closed surface), by central
//! differences extrapolated twice (Richardson). The contact points are where the line through
//! the centroid along the normal leaves each solid, by the test's own ray casts.

use crate::common::Expected;
use contact_core::{Matrix3, Point3, Vector2, Vector3};

mod crossed;
pub use crossed::{crossed_cylinders_volume, minus_gradient};

/// 7-point Gauss–Legendre nodes and weights on [−1, 1].
const GL7: [(f64, f64); 7] = [
    (0.0, 0.417_959_183_673_469_4),
    (0.405_845_151_377_397_2, 0.381_830_050_505_118_9),
    (-0.405_845_151_377_397_2, 0.381_830_050_505_118_9),
    (0.741_531_185_599_394_4, 0.279_705_391_489_276_7),
    (-0.741_531_185_599_394_4, 0.279_705_391_489_276_7),
    (0.949_107_912_342_758_5, 0.129_484_966_168_869_7),
    (-0.949_107_912_342_758_5, 0.129_484_966_168_869_7),
];

fn gauss<const N: usize>(a: f64, b: f64, f: &mut impl FnMut(f64) -> [f64; N]) -> [f64; N] {
    let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
    let mut out = [0.0; N];
    for (x, w) in GL7 {
        let v = f(m + h * x);
        for k in 0..N {
            out[k] += w * h * v[k];
        }
    }
    out
}

fn adapt<const N: usize>(
    a: f64,
    b: f64,
    whole: [f64; N],
    f: &mut impl FnMut(f64) -> [f64; N],
    tol: f64,
    depth: u32,
) -> [f64; N] {
    let m = 0.5 * (a + b);
    let (l, r) = (gauss(a, m, f), gauss(m, b, f));
    let mut sum = [0.0; N];
    for k in 0..N {
        sum[k] = l[k] + r[k];
    }
    if depth == 0 || (0..N).all(|k| (sum[k] - whole[k]).abs() <= tol) {
        return sum;
    }
    let (l, r) = (
        adapt(a, m, l, f, 0.5 * tol, depth - 1),
        adapt(m, b, r, f, 0.5 * tol, depth - 1),
    );
    let mut out = [0.0; N];
    for k in 0..N {
        out[k] = l[k] + r[k];
    }
    out
}

/// `∫ f dt` over `[lo, hi]` split at `breaks`, each piece mapped by `t = m + h sin θ`
/// (square-root ends become smooth), adaptive to absolute `tol` per component.
pub fn integrate<const N: usize>(
    lo: f64,
    hi: f64,
    breaks: &[f64],
    tol: f64,
    f: &mut impl FnMut(f64) -> [f64; N],
) -> [f64; N] {
    let mut cuts: Vec<f64> = vec![lo, hi];
    cuts.extend(breaks.iter().copied().filter(|&b| b > lo && b < hi));
    cuts.sort_by(f64::total_cmp);
    let mut total = [0.0; N];
    for p in cuts.windows(2) {
        let (m, h) = (0.5 * (p[0] + p[1]), 0.5 * (p[1] - p[0]));
        let half = std::f64::consts::FRAC_PI_2;
        let mut g = |theta: f64| {
            let v = f(m + h * theta.sin());
            let jac = h * theta.cos();
            v.map(|x| x * jac)
        };
        let whole = gauss(-half, half, &mut g);
        let part = adapt(-half, half, whole, &mut g, tol, 40);
        for k in 0..N {
            total[k] += part[k];
        }
    }
    total
}

/// Volume and centroid of an intersection.
#[derive(Debug, Clone, Copy)]
pub struct VolumeCentroid {
    pub volume: f64,
    pub centroid: Point3,
}

/// Where the line from `p` (inside) along unit `d` leaves the cylinder of radius `r` on the
/// z axis from `z0` to `z1`.
pub fn cylinder_ray(r: f64, z0: f64, z1: f64, p: &Point3, d: &Vector3) -> Point3 {
    let mut best = f64::INFINITY;
    let a = d.x * d.x + d.y * d.y;
    if a > 0.0 {
        let b = p.x * d.x + p.y * d.y;
        let c = p.x * p.x + p.y * p.y - r * r;
        best = (-b + (b * b - a * c).max(0.0).sqrt()) / a;
    }
    if d.z > 0.0 {
        best = best.min((z1 - p.z) / d.z);
    } else if d.z < 0.0 {
        best = best.min((z0 - p.z) / d.z);
    }
    p + best.max(0.0) * d
}

/// Where the line from `p` (inside) along `d` leaves the box `|x_k − c_k| ≤ h_k`.
pub fn box_ray(c: &Vector3, h: &Vector3, p: &Point3, d: &Vector3) -> Point3 {
    let mut best = f64::INFINITY;
    for k in 0..3 {
        if d[k] > 0.0 {
            best = best.min((c[k] + h[k] - p[k]) / d[k]);
        } else if d[k] < 0.0 {
            best = best.min((c[k] - h[k] - p[k]) / d[k]);
        }
    }
    p + best.max(0.0) * d
}

/// Half-angle, area and centroid distance of the part `x ≥ c` of a disc of radius `r`.
pub fn segment(r: f64, c: f64) -> (f64, f64, f64) {
    let alpha = (c / r).clamp(-1.0, 1.0).acos();
    let area = r * r * (alpha - alpha.sin() * alpha.cos());
    let dist = 4.0 * r * alpha.sin().powi(3) / (3.0 * (2.0 * alpha - (2.0 * alpha).sin()));
    (alpha, area, dist)
}

/// Two parallel cylinders, both axes +z: `a` (radius `ra`, from z = 0 to `la`) at the origin,
/// `b` (radius `rb`, from `zb` to `zb + lb`) with its axis through `(d, 0)`, `|ra − rb| < d <
/// ra + rb`. Expected contact in `a`'s frame.
pub fn parallel_cylinders(ra: f64, la: f64, rb: f64, zb: f64, lb: f64, d: f64) -> Expected {
    let xc = (d * d + ra * ra - rb * rb) / (2.0 * d);
    let (alpha_a, area_a, dist_a) = segment(ra, xc);
    let (_, area_b, dist_b) = segment(rb, d - xc);
    let lens = area_a + area_b;
    let x_bar = (area_a * dist_a + area_b * (d - dist_b)) / lens;
    let (z_lo, z_hi) = (zb.max(0.0), (zb + lb).min(la));
    let h = z_hi - z_lo;
    let mut s = Vector3::new(2.0 * ra * alpha_a.sin() * h, 0.0, 0.0);
    if zb + lb > la {
        s.z += lens;
    }
    if zb < 0.0 {
        s.z -= lens;
    }
    let n = -s / s.norm();
    let g = Point3::new(x_bar, 0.0, 0.5 * (z_lo + z_hi));
    let point_i = cylinder_ray(ra, 0.0, la, &g, &-n);
    let shifted = g - Vector3::new(d, 0.0, 0.0);
    let point_j = cylinder_ray(rb, zb, zb + lb, &shifted, &n) + Vector3::new(d, 0.0, 0.0);
    Expected {
        point_i,
        point_j,
        normal: n,
        depth: (point_j - point_i).norm(),
    }
}

/// Cylinder `a` (radius `r`, z from 0 to `l`) against the axis-aligned box `x ≥ c`, `|y| <
/// big`, `z0 ≤ z ≤ z1` (the box wider than the cylinder except across `x = c`): a circular
/// segment times the axial overlap. Returns the expected contact and the box's (centre, half
/// extents) in `a`'s frame.
pub fn cylinder_box_segment(
    r: f64,
    l: f64,
    c: f64,
    z0: f64,
    z1: f64,
) -> (Expected, Vector3, Vector3) {
    let big = 3.0 * r;
    let centre = Vector3::new(c + big, 0.0, 0.5 * (z0 + z1));
    let half = Vector3::new(big, big, 0.5 * (z1 - z0));
    let (alpha, area, dist) = segment(r, c);
    let (z_lo, z_hi) = (z0.max(0.0), z1.min(l));
    let h = z_hi - z_lo;
    let mut s = Vector3::new(2.0 * r * alpha.sin() * h, 0.0, 0.0);
    if z1 > l {
        s.z += area;
    }
    if z0 < 0.0 {
        s.z -= area;
    }
    let n = -s / s.norm();
    let g = Point3::new(dist, 0.0, 0.5 * (z_lo + z_hi));
    let expected = Expected {
        point_i: cylinder_ray(r, 0.0, l, &g, &-n),
        point_j: box_ray(&centre, &half, &g, &n),
        normal: n,
        depth: 0.0,
    };
    let depth = (expected.point_j - expected.point_i).norm();
    (Expected { depth, ..expected }, centre, half)
}

/// `[A, ∫x, ∫y]` of the part of the convex polygon `poly` (counter-clockwise) inside the disc
/// of radius `r` about the origin, by Green's theorem: `A = ½∮(x dy − y dx)`, `∫x = ½∮x² dy`,
/// `∫y = −½∮y² dx`, over the polygon's edges clipped to the disc and the disc's arcs inside
/// the polygon.
pub fn disc_polygon(r: f64, poly: &[Vector2]) -> [f64; 3] {
    let mut out = [0.0; 3];
    let mut crossings: Vec<f64> = Vec::new();
    let n = poly.len();
    for k in 0..n {
        let (p, q) = (poly[k], poly[(k + 1) % n]);
        let d = q - p;
        // |p + s d|² = r²: a s² + 2 b s + c.
        let (a, b, c) = (d.norm_squared(), p.dot(&d), p.norm_squared() - r * r);
        let disc = b * b - a * c;
        if a == 0.0 || disc <= 0.0 {
            continue;
        }
        let root = disc.sqrt();
        let (s0, s1) = ((-b - root) / a, (-b + root) / a);
        let (lo, hi) = (s0.max(0.0), s1.min(1.0));
        if lo >= hi {
            continue;
        }
        for (s, keep) in [(s0, s0 > 0.0 && s0 < 1.0), (s1, s1 > 0.0 && s1 < 1.0)] {
            if keep {
                let x = p + s * d;
                crossings.push(x.y.atan2(x.x));
            }
        }
        let (u, v) = (p + lo * d, p + hi * d);
        // Straight segment u → v: exact for the quadratic integrands.
        out[0] += 0.5 * (u.x * v.y - v.x * u.y);
        out[1] += 0.5 * (v.y - u.y) * (u.x * u.x + u.x * v.x + v.x * v.x) / 3.0;
        out[2] -= 0.5 * (v.x - u.x) * (u.y * u.y + u.y * v.y + v.y * v.y) / 3.0;
    }
    let inside = |x: Vector2| {
        (0..n).all(|k| {
            let (p, q) = (poly[k], poly[(k + 1) % n]);
            (q - p).perp(&(x - p)) >= 0.0
        })
    };
    let mut arc = |t0: f64, t1: f64| {
        // x = r cos θ, y = r sin θ.
        let r2 = r * r;
        out[0] += 0.5 * r2 * (t1 - t0);
        // ½∫ r² cos² θ · r cos θ dθ = ½ r³ ∫cos³ = ½ r³ [sin − sin³/3].
        let f = |t: f64| t.sin() - t.sin().powi(3) / 3.0;
        out[1] += 0.5 * r2 * r * (f(t1) - f(t0));
        // −½∫ r² sin² θ · (−r sin θ) dθ = ½ r³ ∫ sin³ = ½ r³ [−cos + cos³/3].
        let g = |t: f64| -t.cos() + t.cos().powi(3) / 3.0;
        out[2] += 0.5 * r2 * r * (g(t1) - g(t0));
    };
    if crossings.is_empty() {
        if inside(Vector2::new(r, 0.0)) {
            arc(0.0, std::f64::consts::TAU);
        }
        return out;
    }
    crossings.sort_by(f64::total_cmp);
    let m = crossings.len();
    for k in 0..m {
        let t0 = crossings[k];
        let t1 = if k + 1 < m {
            crossings[k + 1]
        } else {
            crossings[0] + std::f64::consts::TAU
        };
        let mid = 0.5 * (t0 + t1);
        if inside(Vector2::new(r * mid.cos(), r * mid.sin())) {
            arc(t0, t1);
        }
    }
    out
}

/// The section `z = const` of the box (centre `c`, unit axes the columns of `axes`, half
/// extents `h`), counter-clockwise, by clipping a large square.
fn box_section(c: &Vector3, axes: &Matrix3, h: &Vector3, z: f64, reach: f64) -> Vec<Vector2> {
    let mut poly = vec![
        Vector2::new(-reach, -reach),
        Vector2::new(reach, -reach),
        Vector2::new(reach, reach),
        Vector2::new(-reach, reach),
    ];
    for k in 0..3 {
        let m = axes.column(k).into_owned();
        for sign in [1.0, -1.0] {
            // sign·m·(x − c) ≤ h: (m.x, m.y)·p ≤ h/sign-adjusted …
            let g = sign * Vector2::new(m.x, m.y);
            let d = h[k] + sign * m.dot(c) - sign * m.z * z;
            let mut next = Vec::new();
            for i in 0..poly.len() {
                let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
                let (dp, dq) = (g.dot(&p) - d, g.dot(&q) - d);
                if dp <= 0.0 {
                    next.push(p);
                }
                if (dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0) {
                    next.push(p + (q - p) * (dp / (dp - dq)));
                }
            }
            poly = next;
            if poly.len() < 3 {
                return Vec::new();
            }
        }
    }
    poly
}

/// Volume and centroid of cylinder (radius `r`, z from 0 to `l`) ∩ box, by slices
/// perpendicular to the cylinder's axis, each the disc meeting the box's section.
/// Volume and centroid of cylinder (radius `r`, z from 0 to `l`) ∩ box, by slices
/// perpendicular to the cylinder's axis, each the disc meeting the box's section, to the
/// absolute tolerance `tol` per piece and component.
pub fn cylinder_box_volume(
    r: f64,
    l: f64,
    c: &Vector3,
    axes: &Matrix3,
    h: &Vector3,
    tol: f64,
) -> Option<VolumeCentroid> {
    let mut breaks = Vec::new();
    for v in 0..8 {
        let s = |bit: usize| if v & (1 << bit) != 0 { 1.0 } else { -1.0 };
        breaks.push((c + axes * Vector3::new(s(0) * h.x, s(1) * h.y, s(2) * h.z)).z);
    }
    // Kinks: the box's edges through the side; square-root ends: where a face is tangent to
    // the slices' circle (the z-extremes of the ellipse it cuts from the side).
    for k in 0..3 {
        let dir = axes.column(k).into_owned();
        for v in 0..8 {
            if v & (1 << k) != 0 {
                continue;
            }
            let s = |bit: usize| if v & (1 << bit) != 0 { 1.0 } else { -1.0 };
            let p = c + axes * Vector3::new(s(0) * h.x, s(1) * h.y, s(2) * h.z);
            let (qa, qb, qc) = (
                dir.x * dir.x + dir.y * dir.y,
                p.x * dir.x + p.y * dir.y,
                p.x * p.x + p.y * p.y - r * r,
            );
            let disc = qb * qb - qa * qc;
            if qa > 0.0 && disc >= 0.0 {
                for root in [(-qb - disc.sqrt()) / qa, (-qb + disc.sqrt()) / qa] {
                    if (0.0..=2.0 * h[k]).contains(&root) {
                        breaks.push((p + root * dir).z);
                    }
                }
            }
        }
        for sign in [1.0, -1.0] {
            let m = sign * dir;
            let o = m.dot(c) + h[k];
            if m.z != 0.0 {
                let radial = m.x.hypot(m.y);
                breaks.push((o - r * radial) / m.z);
                breaks.push((o + r * radial) / m.z);
            }
        }
    }
    let reach = 4.0 * (r + h.norm() + c.norm());
    let s = integrate(0.0, l, &breaks, tol, &mut |z| {
        let poly = box_section(c, axes, h, z, reach);
        if poly.is_empty() {
            return [0.0; 4];
        }
        let [a, mx, my] = disc_polygon(r, &poly);
        [a, mx, my, z * a]
    });
    (s[0] > 0.0).then(|| VolumeCentroid {
        volume: s[0],
        centroid: Point3::new(s[1], s[2], s[3]) / s[0],
    })
}

/// The area vector `S_a = ∫ n dA` of the cylinder's surface (radius `r`, z from 0 to `l`)
/// inside the box, outward of the cylinder: the caps' parts inside the box's sections at
/// `z = 0, l` (`∓A ẑ`), and the side's, `∫ r (cos φ, sin φ, 0) ℓ(φ) dφ` with `ℓ(φ)` the
/// length of the side's line at `φ` inside the box (each of the box's slabs is an interval
/// in `z` along it), integrated around the circle between the angles where two of those
/// intervals' ends meet (where `ℓ` has kinks).
pub fn cylinder_box_area_vector(
    r: f64,
    l: f64,
    c: &Vector3,
    axes: &Matrix3,
    h: &Vector3,
) -> Vector3 {
    let reach = 4.0 * (r + h.norm() + c.norm());
    let scale = r.max(l).max(h.max());
    let cap = |z: f64| {
        let poly = box_section(c, axes, h, z, reach);
        if poly.is_empty() {
            0.0
        } else {
            disc_polygon(r, &poly)[0]
        }
    };
    // Each end of a slab's interval as z(φ) = α + β cos φ + γ sin φ, and for a slab parallel
    // to the axis its sides as α + β cos φ + γ sin φ = 0.
    let mut ends: Vec<[f64; 3]> = vec![[0.0, 0.0, 0.0], [l, 0.0, 0.0]];
    let mut walls: Vec<[f64; 3]> = Vec::new();
    for k in 0..3 {
        let m = axes.column(k).into_owned();
        let across = m.x * c.x + m.y * c.y;
        for sign in [1.0, -1.0] {
            if m.z != 0.0 {
                ends.push([
                    c.z + (sign * h[k] + across) / m.z,
                    -r * m.x / m.z,
                    -r * m.y / m.z,
                ]);
            } else {
                walls.push([-(sign * h[k] + across), r * m.x, r * m.y]);
            }
        }
    }
    let roots = |f: [f64; 3], out: &mut Vec<f64>| {
        let radius = f[1].hypot(f[2]);
        if radius > f[0].abs() {
            let psi = f[2].atan2(f[1]);
            let spread = (-f[0] / radius).acos();
            for phi in [psi - spread, psi + spread] {
                out.push(phi.rem_euclid(2.0 * std::f64::consts::PI));
            }
        }
    };
    let mut breaks = Vec::new();
    for i in 0..ends.len() {
        for j in 0..i {
            roots(
                [
                    ends[i][0] - ends[j][0],
                    ends[i][1] - ends[j][1],
                    ends[i][2] - ends[j][2],
                ],
                &mut breaks,
            );
        }
    }
    for w in &walls {
        roots(*w, &mut breaks);
    }
    let length = |phi: f64| {
        let p = Vector2::new(r * phi.cos(), r * phi.sin());
        let (mut lo, mut hi) = (0.0f64, l);
        for k in 0..3 {
            let m = axes.column(k).into_owned();
            let q = m.x * (p.x - c.x) + m.y * (p.y - c.y);
            if m.z == 0.0 {
                if q.abs() > h[k] {
                    return 0.0;
                }
                continue;
            }
            let (a, b) = (c.z + (-h[k] - q) / m.z, c.z + (h[k] - q) / m.z);
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        }
        (hi - lo).max(0.0)
    };
    let tol = 1e-15 * scale * scale;
    let side = integrate(0.0, 2.0 * std::f64::consts::PI, &breaks, tol, &mut |phi| {
        let len = r * length(phi);
        [len * phi.cos(), len * phi.sin()]
    });
    Vector3::new(side[0], side[1], cap(l) - cap(0.0))
}
