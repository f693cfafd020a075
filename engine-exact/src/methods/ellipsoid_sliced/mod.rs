//! The shared machinery of the general ellipsoid pairs (ellipsoid–ellipsoid, –box,
//! –cylinder, –frustum, –torus): the intersection's moments by slicing into parallel planar sections, each
//! overlap in closed form ([`disc_overlap`]), integrated across the slices by
//! [`crate::quadrature::Adaptive`].
//!
//! Everything is expressed in a *slicing frame* (slices `z = t`), lengths divided by a power
//! of two near the pair's size ([`super::clipped::unit_for`]).
//!
//! - An ellipsoid `{c + L u : |u| ≤ 1}` meets the plane `z = t` for `|τ| < 1`,
//!   `τ = (t − c_z)/h`, `h = |Lᵀ e_z|`, in the ellipse `c(t) + s(t)·M·u(φ)`: centre
//!   `c(t) = c + (t − c_z)·L Lᵀe_z/h²` (moving linearly), `s(t) = √(1 − τ²)`, and a fixed
//!   2×2 `M` (all parallel sections are similar).
//! - Each slice maps the ellipsoid's section to the unit disc and overlaps it with the other
//!   solid's section mapped alike: the area and first moments give the volume and centroid.
//! - The area vector of the ellipsoid's surface inside the other solid, `S = ∫ n dA`, by the
//!   moving section: a boundary piece with in-plane outward normal `ν` moving at normal speed
//!   `v = ν·(c′ + s′/s·(p − c))` sweeps `(ν − v e_z) dl dt`. Over an arc, `∫ν dl` is the chord
//!   turned by −90° and `∫(p − c)·ν dl` twice the sector's area: closed forms.
//! - The unsigned area of the intersection's surface (for the containment test and area of
//!   [`super::volume_contact`]): `∫√(1 + v²) dl` along the curved arcs by a 12-node rule per
//!   arc, plus the flat and straight pieces in closed form. It is an estimate (held to 1e-9
//!   of itself, not to round-off).

pub(crate) mod disc_less;
pub(crate) mod disc_overlap;
pub(crate) mod disc_solid;
pub(crate) mod distance;
pub(crate) mod extent;

use crate::quadrature::{self, Adaptive};
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use disc_overlap::DiscOverlap;
use nalgebra::{Matrix2, Matrix3, Vector2};

/// The quadrature across the slices: Gauss–Kronrod pieces halved until their error estimate
/// is within 1e-13 (the rule then sits at round-off on the smooth stretches; the kinks where
/// the sections' crossings appear or vanish are cuts, see [`shape_events`]), at most 20
/// times.
pub(crate) const ADAPTIVE: Adaptive = Adaptive {
    tolerance: 1e-13,
    max_depth: 20,
    pair: crate::quadrature::Pair::Kronrod21,
};

/// The integrand's components: area, `t`·area, the in-plane first moments (2), the area
/// vector (3), the unsigned surface of `a` inside `b` and of `b` inside `a`.
pub(crate) const COMPONENTS: usize = 9;

/// An ellipsoid `{c + L u : |u| ≤ 1}` in the slicing frame, ready to be sliced by `z = t`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SlicedEllipsoid {
    center: Vector3,
    /// `h = |Lᵀ e_z|`: the ellipsoid spans `c_z ± h`.
    height: f64,
    /// `dc/dt` in the plane.
    center_rate: Vector2<f64>,
    /// The section's shape `M` (det > 0), for `s = 1`.
    basis: Matrix2<f64>,
    /// `L⁻¹`, for the quadratic `|L⁻¹(x − c)|²`.
    inverse: Matrix3<f64>,
}

/// One ellipse section `center + matrix·u(φ)` and how it moves with `t`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Section {
    /// Centre.
    pub center: Vector2<f64>,
    /// Shape (already scaled by `s(t)`), det > 0.
    pub matrix: Matrix2<f64>,
    /// `dc/dt`.
    pub center_rate: Vector2<f64>,
    /// `s′/s`.
    pub scale_rate: f64,
}

impl SlicedEllipsoid {
    /// The ellipsoid with centre `center` and matrix `l` (invertible).
    pub(crate) fn new(center: Vector3, l: &Matrix3<f64>) -> Option<Self> {
        let inverse = l.try_inverse()?;
        let m = l.row(2).transpose();
        let height = m.norm();
        let lm = l * m;
        let m_hat = m / height;
        // An orthonormal pair across m̂, from the axis m̂ is least aligned with.
        let k = m_hat.iamin();
        let e1 = m_hat.cross(&Vector3::ith(k, 1.0)).normalize();
        let e2 = m_hat.cross(&e1);
        let (p, q) = (l * e1, l * e2);
        let mut basis = Matrix2::new(p.x, q.x, p.y, q.y);
        if basis.determinant() < 0.0 {
            basis.set_column(1, &-basis.column(1).into_owned());
        }
        let center_rate = Vector2::new(lm.x, lm.y) / (height * height);
        let ok = height > 0.0 && center_rate.iter().all(|v| v.is_finite());
        ok.then_some(Self {
            center,
            height,
            center_rate,
            basis,
            inverse,
        })
    }

    /// The `t` range the ellipsoid spans.
    pub(crate) fn range(&self) -> (f64, f64) {
        (self.center.z - self.height, self.center.z + self.height)
    }

    /// The centre.
    pub(crate) fn center(&self) -> &Vector3 {
        &self.center
    }

    /// The centre of the section `z = t` (a point at the range's ends; extrapolated
    /// linearly beyond them).
    pub(crate) fn center_at(&self, t: f64) -> Vector2<f64> {
        Vector2::new(self.center.x, self.center.y) + (t - self.center.z) * self.center_rate
    }

    /// `L⁻¹`.
    pub(crate) fn inverse(&self) -> &Matrix3<f64> {
        &self.inverse
    }

    /// The section `z = t`, or `None` outside the ellipsoid's range.
    pub(crate) fn section(&self, t: f64) -> Option<Section> {
        let tau = (t - self.center.z) / self.height;
        let s2 = (1.0 - tau) * (1.0 + tau);
        if s2.is_nan() || s2 <= 0.0 {
            return None;
        }
        let offset = t - self.center.z;
        Some(Section {
            center: Vector2::new(self.center.x, self.center.y) + offset * self.center_rate,
            matrix: self.basis * s2.sqrt(),
            center_rate: self.center_rate,
            scale_rate: -tau / (self.height * s2),
        })
    }

    /// `(α, β, γ)` with the section's support along the unit in-plane `normal` equal to
    /// `α + βτ + γ√(1 − τ²)` (`t = c_z + hτ`).
    pub(crate) fn support_terms(&self, normal: &Vector2<f64>) -> (f64, f64, f64) {
        (
            normal.dot(&Vector2::new(self.center.x, self.center.y)),
            self.height * normal.dot(&self.center_rate),
            (self.basis.transpose() * normal).norm(),
        )
    }

    /// `t` for the ellipsoid's `τ`.
    pub(crate) fn t_of(&self, tau: f64) -> f64 {
        self.center.z + self.height * tau
    }
}

/// `J v`: the vector turned by −90° (outward of a counter-clockwise boundary).
fn turned(v: &Vector2<f64>) -> Vector2<f64> {
    Vector2::new(v.y, -v.x)
}

/// `∫ √(1 + v²) dl` along the arcs `spans` (parameters of `section`'s `u(φ)`), by a 12-node
/// rule per arc; in closed form for a round section that does not drift ([`round_rate`]).
pub(crate) fn curved_area(section: &Section, spans: &[(f64, f64)]) -> f64 {
    if let Some(rate) = round_rate(section) {
        return rate * spans.iter().map(|(f0, f1)| f1 - f0).sum::<f64>();
    }
    let mut total = 0.0;
    for &(f0, f1) in spans {
        quadrature::for_each_node(f0, f1, |phi, weight| {
            let (s, c) = phi.sin_cos();
            let tangent = section.matrix * Vector2::new(-s, c);
            let offset = section.matrix * Vector2::new(c, s);
            let rate = turned(&tangent).dot(&(section.center_rate + section.scale_rate * offset));
            total += weight * (tangent.norm_squared() + rate * rate).sqrt();
        });
    }
    total
}

/// The surface's rate per unit of `φ` when the section is a circle of radius `ρ` (`M = ρQ`, `Q`
/// a rotation, to 1e-13 of `M`'s size) whose centre does not move with `t` (`|dc/dt|` within
/// 1e-13): a sphere, or a spheroid sliced along its axis. The integrand of [`curved_area`] is
/// then the same at every `φ`, `√(ρ² + (ρ²·s′/s)²)` (for a sphere of radius `r`, `r`: the zone
/// between two slices has area `2πr·dt`); `None` for any other section.
fn round_rate(section: &Section) -> Option<f64> {
    let m = &section.matrix;
    let size = m.abs().max();
    let round = (m[(0, 0)] - m[(1, 1)]).abs() + (m[(0, 1)] + m[(1, 0)]).abs() <= 1e-13 * size;
    let still = section.center_rate.norm() <= 1e-13;
    (round && still).then(|| {
        let rho2 = m.determinant();
        let rate = section.scale_rate * rho2;
        (rho2 + rate * rate).sqrt()
    })
}

/// The integrand at `t` for the ellipsoid section `a` and its overlap `o` with the other
/// solid's section (in `a`'s disc coordinates); `surface_b` is the unsigned area rate of
/// `b`'s surface inside `a` at this slice.
pub(crate) fn integrand(t: f64, a: &Section, o: &DiscOverlap, surface_b: f64) -> [f64; COMPONENTS] {
    let det = a.matrix.determinant();
    let area = det * o.area;
    let moment = det * (a.center * o.area + a.matrix * o.moment);
    let s_plane = turned(&(a.matrix * o.chord));
    let s_normal = -(a.center_rate.dot(&s_plane) + a.scale_rate * det * o.angle);
    [
        area,
        t * area,
        moment.x,
        moment.y,
        s_plane.x,
        s_plane.y,
        s_normal,
        curved_area(a, o.arcs.spans()),
        surface_b,
    ]
}

/// The absolute error each piece may keep, from a first estimate of the integrals: 1e-14 of
/// the volume (times the working unit, for the moments), 1e-14 of the surface for the area
/// vector, 1e-10 of it for the unsigned surface — and never below 1e-15 in working units
/// (lengths about 1), the round-off of the section overlaps, so a grazing sliver (whose
/// overlaps are all round-off) does not halve to the depth limit everywhere.
pub(crate) fn floor(estimate: &[f64; COMPONENTS]) -> [f64; COMPONENTS] {
    let volume = (estimate[0].abs() * 1e-14).max(ROUND_OFF);
    let surface = (estimate[7].abs() + estimate[8].abs())
        + estimate[4..7].iter().map(|v| v.abs()).sum::<f64>();
    let s = (surface * 1e-14).max(ROUND_OFF);
    let u = (surface * 1e-10).max(ROUND_OFF);
    [volume, volume, volume, volume, s, s, s, u, u]
}

/// The absolute floor of [`floor`], in working units.
const ROUND_OFF: f64 = 1e-15;

/// The integrals over the slices, in the slicing frame (working units).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Integrals {
    /// Volume.
    pub volume: f64,
    /// Centroid.
    pub centroid: Vector3,
    /// Area vector of `a`'s surface inside `b`.
    pub area_vector_a: Vector3,
    /// Unsigned area of `a`'s surface inside `b`.
    pub surface_a: f64,
    /// Unsigned area of `b`'s surface inside `a` (flat faces included by the caller).
    pub surface_b: f64,
}

/// Integrates `f` over the pieces between `cuts` (see [`Adaptive::integrate_pieces`]).
pub(crate) fn integrate(
    cuts: &mut [f64],
    f: &mut impl FnMut(f64) -> [f64; COMPONENTS],
    work: &mut WorkCounters,
) -> Integrals {
    let r = ADAPTIVE.integrate_pieces(cuts, f, &floor, work);
    let volume = r[0];
    Integrals {
        volume,
        centroid: Vector3::new(r[2], r[3], r[1]) / volume,
        area_vector_a: Vector3::new(r[4], r[5], r[6]),
        surface_a: r[7],
        surface_b: r[8],
    }
}

/// The world-frame moments of `integrals` computed in `frame` (slicing frame → world) with
/// lengths divided by `unit`.
pub(crate) fn to_world(
    integrals: &Integrals,
    frame: &Isometry3,
    unit: f64,
) -> super::volume_contact::VolumeMoments {
    super::volume_contact::VolumeMoments {
        volume: integrals.volume * unit * unit * unit,
        centroid: frame * Point3::from(integrals.centroid * unit),
        area_vector_a: frame.rotation * integrals.area_vector_a * (unit * unit),
        surface_area: (integrals.surface_a + integrals.surface_b) * (unit * unit),
        length: unit,
    }
}

/// The world point where the line from `g` along `d` leaves the ellipsoid with `semi_axes` at
/// `pose` (`g` itself if it lies outside by round-off).
pub(crate) fn ellipsoid_exit_w(
    semi_axes: &Vector3,
    pose: &Isometry3,
    g: &Point3,
    d: &Vector3,
) -> Point3 {
    let o = pose.inverse_transform_point(g).coords;
    let dl = pose.inverse_transform_vector(d);
    let t = crate::ray_exit::ellipsoid_exit(semi_axes, &o, &dl).unwrap_or(0.0);
    g + t * d
}

/// The fallback normal (from `b` into `a`) when `b` lies inside the ellipsoid `a`: against
/// the gradient of `a`'s quadratic at `g` (the outward normal of the level surface through
/// it), or `b`'s `−z` axis at `a`'s centre.
pub(crate) fn inward_of_ellipsoid(
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    g: &Point3,
    pose_b: &Isometry3,
) -> Vector3 {
    let p = pose_a.inverse_transform_point(g).coords;
    let gradient = p.component_div(&semi_axes.component_mul(semi_axes));
    let n = gradient.norm();
    if n > 0.0 && n.is_finite() {
        -(pose_a.rotation * (gradient / n))
    } else {
        -(pose_b.rotation * Vector3::z())
    }
}

/// The real roots of `a x² + b x + c` (`a ≠ 0`), without cancellation, and how many.
pub(crate) fn quadratic_roots(a: f64, b: f64, c: f64) -> ([f64; 2], usize) {
    let disc = b * b - 4.0 * a * c;
    if disc.is_nan() || disc < 0.0 || a == 0.0 {
        return ([0.0; 2], 0);
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    if q == 0.0 {
        return ([0.0; 2], 1);
    }
    ([q / a, c / q], 2)
}

/// The matrix `R·diag(semi_axes)/unit` and centre `/unit` of an ellipsoid at `pose` seen from
/// `frame`: `{c + L u : |u| ≤ 1}` in working units.
pub(crate) fn ellipsoid_in(
    frame: &Isometry3,
    pose: &Isometry3,
    semi_axes: &Vector3,
    unit: f64,
) -> (Vector3, Matrix3<f64>) {
    let rel = frame.inv_mul(pose);
    let l =
        rel.rotation.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&(semi_axes / unit));
    (rel.translation.vector / unit, l)
}

/// Samples of the overlap's shape class per slicing range in [`shape_events`].
const SHAPE_SAMPLES: usize = 64;

/// Extra samples toward each end of the range in [`shape_events`], each halving the distance
/// left (down to 2⁻⁴⁰ of the first sample's offset).
const END_SAMPLES: usize = 40;

/// Sorts the closed-form `cuts[..*n]`, adds [`shape_events`] between each consecutive two
/// (the changes the closed forms do not give: a tangency often follows a rim's piercing within
/// 1e-5 of the range, so each piece is sampled geometrically towards both of its ends), and
/// sorts again.
pub(crate) fn add_shape_events_between(
    cuts: &mut [f64; quadrature::MAX_PIECES + 1],
    n: &mut usize,
    shape: impl Fn(f64) -> usize,
) {
    cuts[..*n].sort_by(f64::total_cmp);
    let known = *n;
    let closed = *cuts;
    for w in closed[..known].windows(2) {
        shape_events(w[0], w[1], &shape, cuts, n);
    }
    cuts[..*n].sort_by(f64::total_cmp);
}

/// The pieces of the extent `[lo, hi]` for the outer rule: its two ends and the sorted `cuts`
/// strictly inside it, a cut closer than `merge_fraction` of the extent to an end or to the
/// last one kept merged away (a piece that thin holds that fraction of the range, and its
/// slices, within round-off of a tangency, cost the inner rule its whole depth for nothing).
/// Returns the boundaries and how many there are.
pub(crate) fn pieces_within(
    cuts: &[f64],
    (lo, hi): (f64, f64),
    merge_fraction: f64,
) -> ([f64; quadrature::MAX_PIECES + 1], usize) {
    let mut inner = [0.0; quadrature::MAX_PIECES + 1];
    inner[0] = lo;
    let mut m = 1;
    let merge = merge_fraction * (hi - lo);
    for &c in cuts {
        if c > lo + merge && c < hi - merge && c > inner[m - 1] + merge {
            inner[m] = c;
            m += 1;
        }
    }
    inner[m] = hi;
    (inner, m + 1)
}

/// Adds to `cuts[..*n]` (up to its capacity) the slices inside `(lo, hi)` where the overlap's
/// shape class `shape(t)` changes (sections becoming tangent, a corner entering): sampled at
/// 64 slices and at slices approaching both ends geometrically, each change bisected to
/// round-off. The quadrature needs these kinks as cuts: a kink close to the end of a piece,
/// with no node beyond it, would otherwise go unseen — and near the range's ends, where the
/// region shrinks to its lowest or highest point, the sections often turn tangent just short
/// of the end (a 1e-8 error in the area vector when such a kink is left inside the last
/// piece).
pub(crate) fn shape_events(
    lo: f64,
    hi: f64,
    shape: impl Fn(f64) -> usize,
    cuts: &mut [f64],
    n: &mut usize,
) {
    let step = (hi - lo) / SHAPE_SAMPLES as f64;
    let near_lo = (1..=END_SAMPLES)
        .rev()
        .map(|k| lo + 0.5 * step * 0.5f64.powi(k as i32));
    let uniform = (0..SHAPE_SAMPLES).map(|k| lo + step * (k as f64 + 0.5));
    let near_hi = (1..=END_SAMPLES).map(|k| hi - 0.5 * step * 0.5f64.powi(k as i32));
    let mut samples = near_lo.chain(uniform).chain(near_hi);
    let Some(first) = samples.next() else {
        return;
    };
    let (mut last_t, mut previous) = (first, shape(first));
    for t in samples {
        let here = shape(t);
        if here != previous && *n < cuts.len() {
            let (mut a, mut b) = (last_t, t);
            for _ in 0..60 {
                let mid = 0.5 * (a + b);
                if mid <= a || mid >= b {
                    break;
                }
                if shape(mid) == previous {
                    a = mid;
                } else {
                    b = mid;
                }
            }
            cuts[*n] = 0.5 * (a + b);
            *n += 1;
        }
        (last_t, previous) = (t, here);
    }
}
