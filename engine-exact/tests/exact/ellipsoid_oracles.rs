//! Oracles for the general ellipsoid pairs, written independently of the engine (which
//! slices the intersection into planar sections):
//!
//! - [`lens_moments`] + [`mapped`]: two spheres' lens in closed form (volume, centroid, the
//!   disc area vector) carried by an affine map to two ellipsoids of one shape and
//!   orientation (`V·|det M|`, `M·g`, `cof(M)·S`);
//! - [`ellipsoid_cap`]: an ellipsoid cut by one plane, the affine image of a spherical cap;
//! - [`surface_moments`]: any pair by the divergence theorem over the boundary of the
//!   intersection (`V = ⅓∮x·n dA`, `∫x_i dV = ½∮x_i² n_i dA`, `S = ∫n dA` over I's part),
//!   each surface parametrised on its own (the ellipsoid by the unit sphere's angles, faces
//!   and caps by their coordinates, a cylinder's side by height and angle), the inner
//!   integral split where a sampled inside-margin changes sign (bisected), the outer one by
//!   adaptive Gauss–Kronrod (7/15);
//! - [`contact_from`]: SPEC §4's contact from moments, with the ray exits below.

use crate::common::Expected;
use contact_core::{Point3, Vector3};
use nalgebra::Matrix3;
use std::f64::consts::{PI, TAU};

/// The moments of an intersection.
#[derive(Debug, Clone, Copy)]
pub struct Moments {
    pub volume: f64,
    pub centroid: Point3,
    /// `∫ n dA` over I's surface inside J (outward of I).
    pub area_vector_i: Vector3,
}

/// Cap of the unit ball beyond the height `1 − h` along a direction: (volume, centroid
/// distance from the centre).
fn ball_cap(h: f64) -> (f64, f64) {
    (
        PI * h * h * (3.0 - h) / 3.0,
        3.0 * (2.0 - h) * (2.0 - h) / (4.0 * (3.0 - h)),
    )
}

/// The lens of the sphere (`r1`, `c1`) (I) and the sphere (`r2`, `c2`); `None` apart.
pub fn lens_moments(r1: f64, c1: &Vector3, r2: f64, c2: &Vector3) -> Option<Moments> {
    let axis = c2 - c1;
    let d = axis.norm();
    if d >= r1 + r2 {
        return None;
    }
    if d <= (r1 - r2).abs() {
        // The smaller sphere whole; I's surface inside J is all of I or none.
        let (r, c) = if r1 <= r2 { (r1, c1) } else { (r2, c2) };
        return Some(Moments {
            volume: 4.0 / 3.0 * PI * r * r * r,
            centroid: Point3::from(*c),
            area_vector_i: Vector3::zeros(),
        });
    }
    let u = axis / d;
    // The plane of the crossing circle at distance a from c1 along u.
    let a = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
    let (v1, g1) = ball_cap((r1 - a) / r1);
    let (v2, g2) = ball_cap((r2 - (d - a)) / r2);
    let (v1, v2) = (v1 * r1.powi(3), v2 * r2.powi(3));
    let p1 = c1 + u * (g1 * r1);
    let p2 = c2 - u * (g2 * r2);
    let volume = v1 + v2;
    Some(Moments {
        volume,
        centroid: Point3::from((p1 * v1 + p2 * v2) / volume),
        area_vector_i: u * (PI * (r1 * r1 - a * a)),
    })
}

/// The moments carried by `x ↦ map·x + shift`.
pub fn mapped(m: &Moments, map: &Matrix3<f64>, shift: &Vector3) -> Moments {
    let det = map.determinant();
    let cofactor = map.try_inverse().unwrap().transpose() * det;
    Moments {
        volume: m.volume * det.abs(),
        centroid: Point3::from(map * m.centroid.coords + shift),
        area_vector_i: cofactor * m.area_vector_i,
    }
}

/// The ellipsoid `{c + L u : |u| ≤ 1}` (I) cut by the half-space `normal·x ≤ offset` (J).
pub fn ellipsoid_cap(c: &Vector3, l: &Matrix3<f64>, normal: &Vector3, offset: f64) -> Moments {
    let m = l.transpose() * normal;
    let sigma = (offset - normal.dot(c)) / m.norm();
    let m_hat = m / m.norm();
    // The part m̂·u ≤ σ of the unit ball: a cap of height 1 + σ on the −m̂ side.
    let (v, g) = ball_cap(1.0 + sigma);
    let unit = Moments {
        volume: v,
        centroid: Point3::from(-m_hat * g),
        // The curved part's area vector is minus the flat disc's (outward +m̂).
        area_vector_i: -m_hat * (PI * (1.0 - sigma * sigma)),
    };
    mapped(&unit, l, c)
}

/// The contact of SPEC §4 from moments: normal `−S/|S|`, points where the line through the
/// centroid leaves I (along `−n`) and J (along `+n`).
pub fn contact_from(
    m: &Moments,
    exit_i: impl Fn(&Point3, &Vector3) -> Point3,
    exit_j: impl Fn(&Point3, &Vector3) -> Point3,
) -> Expected {
    let normal = -m.area_vector_i.normalize();
    let point_i = exit_i(&m.centroid, &-normal);
    let point_j = exit_j(&m.centroid, &normal);
    Expected {
        point_i,
        point_j,
        normal,
        depth: (point_j - point_i).norm(),
    }
}

/// Where the ray from `g` (inside) along `d` leaves `{c + L u : |u| ≤ 1}`.
pub fn ellipsoid_exit(c: &Vector3, l: &Matrix3<f64>, g: &Point3, d: &Vector3) -> Point3 {
    let inv = l.try_inverse().unwrap();
    let (p, v) = (inv * (g.coords - c), inv * d);
    let (vv, pv, pp) = (v.norm_squared(), p.dot(&v), p.norm_squared());
    let s = (-pv + (pv * pv - vv * (pp - 1.0)).max(0.0).sqrt()) / vv;
    g + d * s.max(0.0)
}

/// Where the ray from `g` (inside) along `d` leaves the box `|x_k| ≤ half_k` (slabs).
pub fn box_exit(half: &Vector3, g: &Point3, d: &Vector3) -> Point3 {
    let s = (0..3)
        .filter(|&k| d[k] != 0.0)
        .map(|k| ((half[k] * d[k].signum() - g[k]) / d[k]).max(0.0))
        .fold(f64::INFINITY, f64::min);
    g + d * s
}

/// Where the ray from `g` (inside) along `d` leaves the cylinder `x² + y² ≤ r²`, `0 ≤ z ≤ len`.
pub fn cylinder_exit(r: f64, len: f64, g: &Point3, d: &Vector3) -> Point3 {
    let mut s = f64::INFINITY;
    if d.z > 0.0 {
        s = s.min((len - g.z) / d.z);
    } else if d.z < 0.0 {
        s = s.min(-g.z / d.z);
    }
    let a = d.x * d.x + d.y * d.y;
    if a > 0.0 {
        let b = g.x * d.x + g.y * d.y;
        let c = g.x * g.x + g.y * g.y - r * r;
        s = s.min((-b + (b * b - a * c).max(0.0).sqrt()) / a);
    }
    g + d * s.max(0.0)
}

// ---- The divergence-theorem oracle.

/// A piece of boundary: parameters `(s, v)` with `s` in `s_range`, `v` in `v_range(s)`
/// (periodic when the flag is set); `point` gives the point and the area vector per unit
/// `ds dv`.
pub trait Patch {
    fn s_range(&self) -> (f64, f64);
    fn v_range(&self, s: f64) -> (f64, f64, bool);
    fn point(&self, s: f64, v: f64) -> (Vector3, Vector3);
}

/// An ellipsoid `{c + L u}` by the unit sphere's polar angle `s` and azimuth `v`.
pub struct EllipsoidPatch {
    c: Vector3,
    l: Matrix3<f64>,
    /// `cof(L) = det(L)·L⁻ᵀ`, which carries the unit sphere's area vectors.
    cofactor: Matrix3<f64>,
}

impl EllipsoidPatch {
    pub fn new(c: Vector3, l: Matrix3<f64>) -> Self {
        let cofactor = l.try_inverse().unwrap().transpose() * l.determinant();
        Self { c, l, cofactor }
    }
}

impl Patch for EllipsoidPatch {
    fn s_range(&self) -> (f64, f64) {
        (0.0, PI)
    }
    fn v_range(&self, _: f64) -> (f64, f64, bool) {
        (0.0, TAU, true)
    }
    fn point(&self, s: f64, v: f64) -> (Vector3, Vector3) {
        let u = Vector3::new(s.sin() * v.cos(), s.sin() * v.sin(), s.cos());
        (self.c + self.l * u, self.cofactor * u * s.sin())
    }
}

/// A flat rectangle `o + s e1 + v e2`, `|s| ≤ h1`, `|v| ≤ h2`, outward normal `e1 × e2`.
pub struct RectanglePatch {
    pub o: Vector3,
    pub e1: Vector3,
    pub e2: Vector3,
    pub h1: f64,
    pub h2: f64,
}

impl Patch for RectanglePatch {
    fn s_range(&self) -> (f64, f64) {
        (-self.h1, self.h1)
    }
    fn v_range(&self, _: f64) -> (f64, f64, bool) {
        (-self.h2, self.h2, false)
    }
    fn point(&self, s: f64, v: f64) -> (Vector3, Vector3) {
        (self.o + self.e1 * s + self.e2 * v, self.e1.cross(&self.e2))
    }
}

/// The six faces of the box `|x_k| ≤ half_k`.
pub fn box_faces(half: &Vector3) -> Vec<RectanglePatch> {
    let mut faces = Vec::new();
    for k in 0..3 {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        for sign in [1.0, -1.0] {
            let e1 = Vector3::ith(i, 1.0);
            let e2 = Vector3::ith(j, sign);
            faces.push(RectanglePatch {
                o: Vector3::ith(k, sign * half[k]),
                e1,
                e2,
                h1: half[i],
                h2: half[j],
            });
        }
    }
    faces
}

/// A cylinder's side (`s` = height, `v` = angle).
pub struct SidePatch {
    pub r: f64,
    pub len: f64,
}

impl Patch for SidePatch {
    fn s_range(&self) -> (f64, f64) {
        (0.0, self.len)
    }
    fn v_range(&self, _: f64) -> (f64, f64, bool) {
        (0.0, TAU, true)
    }
    fn point(&self, s: f64, v: f64) -> (Vector3, Vector3) {
        let (sin, cos) = v.sin_cos();
        (
            Vector3::new(self.r * cos, self.r * sin, s),
            Vector3::new(cos, sin, 0.0) * self.r,
        )
    }
}

/// A cylinder's cap at height `z` with outward normal `±z` (`up`), by `x` and `y`.
pub struct CapPatch {
    pub r: f64,
    pub z: f64,
    pub up: bool,
}

impl Patch for CapPatch {
    fn s_range(&self) -> (f64, f64) {
        (-self.r, self.r)
    }
    fn v_range(&self, s: f64) -> (f64, f64, bool) {
        let w = (self.r * self.r - s * s).max(0.0).sqrt();
        (-w, w, false)
    }
    fn point(&self, s: f64, v: f64) -> (Vector3, Vector3) {
        let n = if self.up { 1.0 } else { -1.0 };
        (Vector3::new(s, v, self.z), Vector3::new(0.0, 0.0, n))
    }
}

const XK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
const WK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
const WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

type Sums = [f64; 7];

/// (Kronrod 15, Gauss 7) sums of `f` over `[a, b]`.
fn kronrod(f: &mut dyn FnMut(f64) -> Sums, a: f64, b: f64) -> (Sums, Sums) {
    let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
    let (mut k, mut g) = ([0.0; 7], [0.0; 7]);
    for i in 0..8 {
        let points: &[f64] = if i == 7 { &[0.0] } else { &[-1.0, 1.0] };
        for &side in points {
            let value = f(m + side * h * XK[i]);
            for c in 0..7 {
                k[c] += h * WK[i] * value[c];
                if i % 2 == 1 {
                    g[c] += h * WG[i / 2] * value[c];
                }
            }
        }
    }
    (k, g)
}

/// Adaptive Gauss–Kronrod: bisects until the 7- and 15-point sums agree within `tol`.
fn adaptive(f: &mut dyn FnMut(f64) -> Sums, a: f64, b: f64, tol: f64, depth: u32) -> Sums {
    let (k, g) = kronrod(f, a, b);
    let err = (0..7).map(|c| (k[c] - g[c]).abs()).fold(0.0, f64::max);
    if err <= tol || depth == 0 {
        return k;
    }
    let m = 0.5 * (a + b);
    let left = adaptive(f, a, m, 0.5 * tol, depth - 1);
    let right = adaptive(f, m, b, 0.5 * tol, depth - 1);
    std::array::from_fn(|c| left[c] + right[c])
}

/// The ends of the parts of `patch`'s line at `s` (`v ∈ [v0, v1]`) where `margin > 0`,
/// sorted: `v0`, the boundary crossings (sign changes between 64 samples, bisected, and the
/// pairs of crossings near a tangency, by golden section), `v1`.
fn boundary_ends(
    patch: &dyn Patch,
    margin: &dyn Fn(&Vector3) -> f64,
    s: f64,
    (v0, v1): (f64, f64),
) -> Vec<f64> {
    const SAMPLES: usize = 64;
    let inside = |v: f64| margin(&patch.point(s, v).0);
    let bisect = |mut lo: f64, mut hi: f64| {
        let lo_inside = inside(lo) > 0.0;
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if (inside(mid) > 0.0) == lo_inside {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let step = (v1 - v0) / SAMPLES as f64;
    let at = |j: usize| v0 + j as f64 * step;
    let values: Vec<f64> = (0..=SAMPLES).map(|j| inside(at(j))).collect();
    let mut ends = vec![v0];
    for j in 1..=SAMPLES {
        if (values[j] > 0.0) != (values[j - 1] > 0.0) {
            ends.push(bisect(at(j - 1), at(j)));
        }
    }
    // A pair of crossings between two samples (near a tangency): a sampled local extremum
    // on the wrong side of zero, refined by golden section.
    for j in 1..SAMPLES {
        let (l, m, r) = (values[j - 1], values[j], values[j + 1]);
        let peak = m >= l && m >= r && l <= 0.0 && m <= 0.0 && r <= 0.0;
        let dip = m <= l && m <= r && l > 0.0 && m > 0.0 && r > 0.0;
        // Only where the extremum can reach zero within the interval (its rise over the
        // neighbours bounds the curvature's).
        let reach = 2.0 * ((m - l).abs() + (m - r).abs());
        if !(peak || dip) || m.abs() > reach {
            continue;
        }
        let sign = if peak { 1.0 } else { -1.0 };
        let (mut lo, mut hi) = (at(j - 1), at(j + 1));
        let ratio = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..80 {
            let x1 = hi - ratio * (hi - lo);
            let x2 = lo + ratio * (hi - lo);
            if sign * inside(x1) > sign * inside(x2) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        let best = 0.5 * (lo + hi);
        if (inside(best) > 0.0) != (m > 0.0) {
            ends.push(bisect(at(j - 1), best));
            ends.push(bisect(best, at(j + 1)));
        }
    }
    ends.sort_by(f64::total_cmp);
    ends.push(v1);
    ends
}

/// The inner integral of [`patch_sums`] at `s` and the number of boundary crossings found
/// there.
fn inner_sums(
    patch: &dyn Patch,
    margin: &dyn Fn(&Vector3) -> f64,
    own: bool,
    s: f64,
) -> (Sums, usize) {
    let (v0, v1, _periodic) = patch.v_range(s);
    let mut total = [0.0; 7];
    if v1 <= v0 {
        return (total, 0);
    }
    let inside = |v: f64| margin(&patch.point(s, v).0);
    let ends = boundary_ends(patch, margin, s, (v0, v1));
    let crossings = ends.len();
    for w in ends.windows(2) {
        if w[1] <= w[0] || inside(0.5 * (w[0] + w[1])) <= 0.0 {
            continue;
        }
        // K15 on pieces of at most π/2 (the integrands are trigonometric polynomials of
        // degree ≤ 3 on the ellipsoid, polynomials on flat pieces: exact to round-off).
        let pieces = ((w[1] - w[0]) / (0.5 * PI)).ceil().max(1.0) as usize;
        let h = (w[1] - w[0]) / pieces as f64;
        for p in 0..pieces {
            let mut g = |v: f64| -> Sums {
                let (x, n) = patch.point(s, v);
                let own_n = if own { n } else { Vector3::zeros() };
                [
                    x.dot(&n) / 3.0,
                    0.5 * x.x * x.x * n.x,
                    0.5 * x.y * x.y * n.y,
                    0.5 * x.z * x.z * n.z,
                    own_n.x,
                    own_n.y,
                    own_n.z,
                ]
            };
            let a = w[0] + p as f64 * h;
            let (k, _) = kronrod(&mut g, a, a + h);
            for c in 0..7 {
                total[c] += k[c];
            }
        }
    }
    (total, crossings)
}

/// The integrals (V, ½x_i² n_i, n if `own`) over the part of `patch` where `margin > 0`.
fn patch_sums(patch: &dyn Patch, margin: &dyn Fn(&Vector3) -> f64, own: bool, tol: f64) -> Sums {
    let inner = |s: f64| inner_sums(patch, margin, own, s);
    // Split the outer range where the number of crossings changes (the outer integrand's
    // kinks), found on 64 samples and bisected.
    let (s0, s1) = patch.s_range();
    let at = |k: usize| s0 + (s1 - s0) * k as f64 / 64.0;
    let mut cuts = vec![s0];
    let mut previous = inner(at(0)).1;
    for k in 1..=64 {
        let here = inner(at(k)).1;
        if here != previous {
            let (mut a, mut b) = (at(k - 1), at(k));
            for _ in 0..55 {
                let mid = 0.5 * (a + b);
                if inner(mid).1 == previous {
                    a = mid;
                } else {
                    b = mid;
                }
            }
            cuts.push(0.5 * (a + b));
        }
        previous = here;
    }
    cuts.push(s1);
    let mut outer = |s: f64| inner(s).0;
    let mut total = [0.0; 7];
    for w in cuts.windows(2) {
        let part = adaptive(&mut outer, w[0], w[1], tol, 40);
        (0..7).for_each(|c| total[c] += part[c]);
    }
    total
}

/// The moments of the intersection bounded by I's `own` patches (inside J: `margin_j > 0`)
/// and J's `other` patches (inside I: `margin_i > 0`), absolute tolerance `tol` per patch.
pub fn surface_moments(
    own: &[&dyn Patch],
    margin_j: &dyn Fn(&Vector3) -> f64,
    other: &[&dyn Patch],
    margin_i: &dyn Fn(&Vector3) -> f64,
    tol: f64,
) -> Option<Moments> {
    let mut total = [0.0; 7];
    for p in own {
        let s = patch_sums(*p, margin_j, true, tol);
        (0..7).for_each(|c| total[c] += s[c]);
    }
    for p in other {
        let s = patch_sums(*p, margin_i, false, tol);
        (0..7).for_each(|c| total[c] += s[c]);
    }
    (total[0] > 0.0).then(|| Moments {
        volume: total[0],
        centroid: Point3::new(total[1], total[2], total[3]) / total[0],
        area_vector_i: Vector3::new(total[4], total[5], total[6]),
    })
}

/// `1 − |L⁻¹(x − c)|²`: positive inside the ellipsoid.
pub fn ellipsoid_margin(c: Vector3, l: Matrix3<f64>) -> impl Fn(&Vector3) -> f64 {
    let inv = l.try_inverse().unwrap();
    move |x| 1.0 - (inv * (x - c)).norm_squared()
}

#[test]
fn the_surface_oracle_reproduces_the_lens_and_the_cap() {
    let (c1, c2) = (Vector3::new(0.1, 0.2, -0.1), Vector3::new(0.9, -0.3, 0.4));
    let lens = lens_moments(1.0, &c1, 0.8, &c2).unwrap();
    let l1 = Matrix3::identity();
    let l2 = Matrix3::identity() * 0.8;
    let got = surface_moments(
        &[&EllipsoidPatch::new(c1, l1)],
        &ellipsoid_margin(c2, l2),
        &[&EllipsoidPatch::new(c2, l2)],
        &ellipsoid_margin(c1, l1),
        1e-11,
    )
    .unwrap();
    assert!((got.volume - lens.volume).abs() < 1e-11, "{got:?} {lens:?}");
    assert!((got.centroid - lens.centroid).norm() < 1e-11);
    assert!((got.area_vector_i - lens.area_vector_i).norm() < 1e-11);
    // A sphere of radius 1 through the box face z = 0.5 (box half extents 2): a cap.
    let half = Vector3::new(2.0, 2.0, 0.5);
    let c = Vector3::new(0.2, -0.1, 1.2);
    let cap = ellipsoid_cap(&c, &l1, &Vector3::z(), 0.5);
    let faces = box_faces(&half);
    let others: Vec<&dyn Patch> = faces.iter().map(|f| f as &dyn Patch).collect();
    let margin_box = move |x: &Vector3| {
        (0..3)
            .map(|k| half[k] - x[k].abs())
            .fold(f64::INFINITY, f64::min)
    };
    let got = surface_moments(
        &[&EllipsoidPatch::new(c, l1)],
        &margin_box,
        &others,
        &ellipsoid_margin(c, l1),
        1e-11,
    )
    .unwrap();
    assert!((got.volume - cap.volume).abs() < 1e-11, "{got:?} {cap:?}");
    assert!((got.centroid - cap.centroid).norm() < 1e-11);
    assert!((got.area_vector_i - cap.area_vector_i).norm() < 1e-11);
}
