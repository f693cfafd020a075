//! The ellipsoid in the torus' meridian planes: its regions by azimuth and each region's
//! lowest and highest slice.
//!
//! The plane through the axis at azimuth `φ` (coordinates `y = (u, z)`, `u` along
//! `(cos φ, sin φ, 0)`) cuts the ellipsoid `|L⁻¹(x − c)|² ≤ 1` in the ellipse
//! `(y − y₀)ᵀA(y − y₀) ≤ 1 − κ` (`A = PᵀQP`, `Q = L⁻ᵀL⁻¹`, `P` the plane's basis,
//! `y₀ = A⁻¹PᵀQc`, `κ = cᵀQc − y₀ᵀAy₀`; empty for `κ ≥ 1`), and the torus in the tube's disc
//! of radius `ρ` about `(R, 0)` (the half-plane `u < 0` holds the disc at `φ + π`, which a
//! ring torus keeps apart). Both are convex, so:
//!
//! - [`Meridians::gap`], the distance from the tube's centre to the ellipse less `ρ`, is the
//!   `g(φ)` of [`crate::pairs::box_revolved::azimuth`], which finds the regions as arcs of
//!   azimuth (one region per arc);
//! - [`Meridians::z_span`], the lowest and highest `z` of ellipse ∩ disc, is the 2-D pencil
//!   extent of [`crate::methods::ellipsoid_sliced::extent`] (duality, to round-off), and a
//!   region's slices run from the least `z_lo(φ)` to the greatest `z_hi(φ)` over its arc,
//!   found by [`lowest_and_highest`].

use crate::methods::ellipsoid_sliced::distance::ellipse_distance;
use crate::methods::ellipsoid_sliced::extent::{Quadric, z_bound, z_extent};
use contact_core::Vector3;
use nalgebra::{Matrix2, Matrix3, Vector2};

/// The ellipsoid `(x − c)ᵀQ(x − c) ≤ 1` and the torus (`big`, `small`) in the torus' frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Meridians {
    /// `Q = L⁻ᵀL⁻¹`.
    pub q: Matrix3<f64>,
    /// Centre `c`.
    pub c: Vector3,
    /// Major radius `R`.
    pub big: f64,
    /// Minor radius `ρ`.
    pub small: f64,
    /// Above every distance from the tube's centre to a meridian section: `R + |c| + ` the
    /// ellipsoid's largest semi-axis.
    pub outside: f64,
}

impl Meridians {
    /// The ellipsoid's section by the meridian plane at `phi`: `(y₀, A/(1 − κ))`, or `None`
    /// when the plane misses it.
    fn section(&self, phi: f64) -> Option<(Vector2<f64>, Matrix2<f64>)> {
        let (y0, a, kappa) = self.plane(phi)?;
        let room = 1.0 - kappa;
        (room > 0.0 && room.is_finite()).then(|| (y0, a / room))
    }

    /// `κ`: the meridian plane's squared distance from the centre in the ellipsoid's metric
    /// (`+∞` if degenerate).
    fn kappa(&self, phi: f64) -> f64 {
        self.plane(phi).map_or(f64::INFINITY, |p| p.2)
    }

    /// `(y₀, A, κ)` of the meridian plane at `phi`.
    fn plane(&self, phi: f64) -> Option<(Vector2<f64>, Matrix2<f64>, f64)> {
        let (sin, cos) = phi.sin_cos();
        let e_r = Vector3::new(cos, sin, 0.0);
        let (qr, qz) = (self.q * e_r, self.q.column(2).into_owned());
        let a = Matrix2::new(e_r.dot(&qr), qr.z, qr.z, qz.z);
        let qc = self.q * self.c;
        let b = Vector2::new(e_r.dot(&qc), qc.z);
        let y0 = a.cholesky()?.solve(&b);
        let kappa = self.c.dot(&qc) - b.dot(&y0);
        Some((y0, a, kappa))
    }

    /// `g(φ)`: the distance from the tube's centre `(R, 0)` to the ellipsoid's meridian
    /// section, less `ρ` (negative where they overlap). Where the plane misses the ellipsoid,
    /// `D + κ` with `D` above every distance (`R + |c| + ` the ellipsoid's reach) and `κ > 1`
    /// the plane's distance from the centre in the ellipsoid's metric: it falls toward the
    /// azimuths where the plane meets the ellipsoid, so a narrow dip of `g` (a small
    /// ellipsoid) lies in a basin that sampling sees.
    pub(crate) fn gap(&self, phi: f64) -> f64 {
        let Some((y0, a)) = self.section(phi) else {
            return self.outside + self.kappa(phi);
        };
        // The ellipse as y₀ + M u with M Mᵀ = A⁻¹.
        let shape = a
            .try_inverse()
            .and_then(|inverse| inverse.cholesky())
            .map(|c| c.l());
        match shape {
            Some(m) => ellipse_distance(&Vector2::new(self.big, 0.0), &y0, &m) - self.small,
            None => self.small,
        }
    }

    /// The two quadrics of the meridian plane at `phi`: the ellipsoid's section and the
    /// tube's disc.
    fn quadrics(&self, phi: f64) -> Option<(Quadric<2>, Quadric<2>)> {
        let (y0, a) = self.section(phi)?;
        let disc = Quadric {
            center: Vector2::new(self.big, 0.0),
            q: Matrix2::identity() / (self.small * self.small),
        };
        Some((Quadric { center: y0, q: a }, disc))
    }

    /// `(z_lo, z_hi)` of the ellipsoid's meridian section at `phi` intersected with the
    /// tube's disc; `None` when they do not overlap.
    pub(crate) fn z_span(&self, phi: f64) -> Option<(f64, f64)> {
        let (ellipse, disc) = self.quadrics(phi)?;
        z_extent(&ellipse, &disc)
    }

    /// The highest (`upper`) or lowest `z` of that intersection alone.
    pub(crate) fn z_bound(&self, phi: f64, upper: bool) -> Option<f64> {
        let (ellipse, disc) = self.quadrics(phi)?;
        z_bound(&ellipse, &disc, upper)
    }
}

/// Azimuth samples per arc in [`lowest_and_highest`].
const SAMPLES: usize = 48;
/// Sampled local extrema refined in [`lowest_and_highest`] (with the seed).
const REFINED: usize = 2;
/// Golden-section steps of a refinement (a bracket of two samples, about 0.26 rad at most,
/// shrunk below 1e-8 rad: the extreme's value to round-off).
const GOLDEN_STEPS: usize = 40;

/// The lowest and highest `z` of the ellipsoid's meridian overlaps with the tube over the
/// azimuths `[start, end]`, `None` when none overlaps. Sampled (one pencil extent per
/// sample); the best sampled local extrema, and `seed` (an azimuth where the overlap is not
/// empty, for arcs narrower than the sampling), refined by golden section inside a bracket
/// `(a, b, c)` with `b` the best point, which stays inside whatever the stretches where the
/// overlap is empty (counted as `∓∞`).
pub(crate) fn lowest_and_highest(
    meridians: &Meridians,
    start: f64,
    end: f64,
    seed: Option<f64>,
) -> Option<(f64, f64)> {
    let step = (end - start) / SAMPLES as f64;
    let at = |k: usize| start + step * (k as f64 + 0.5);
    let mut spans = [None; SAMPLES];
    for (k, s) in spans.iter_mut().enumerate() {
        *s = meridians.z_span(at(k));
    }
    let extreme = |upper: bool| -> Option<f64> {
        let sign = if upper { 1.0 } else { -1.0 };
        let sampled = |k: usize| {
            spans[k].map_or(f64::NEG_INFINITY, |(lo, hi)| {
                sign * if upper { hi } else { lo }
            })
        };
        let value = |x: f64| {
            meridians
                .z_bound(x, upper)
                .map_or(f64::NEG_INFINITY, |z| sign * z)
        };
        // Local maxima among the samples, best first.
        let mut peaks = [(f64::NEG_INFINITY, 0.0); REFINED + 1];
        for k in 0..SAMPLES {
            let v = sampled(k);
            let left = if k > 0 {
                sampled(k - 1)
            } else {
                f64::NEG_INFINITY
            };
            let right = if k + 1 < SAMPLES {
                sampled(k + 1)
            } else {
                f64::NEG_INFINITY
            };
            if v > f64::NEG_INFINITY && v >= left && v >= right && v > peaks[REFINED - 1].0 {
                peaks[REFINED - 1] = (v, at(k));
                peaks[..REFINED].sort_by(|x, y| y.0.total_cmp(&x.0));
            }
        }
        if let Some(s) = seed {
            peaks[REFINED] = (value(s), s);
        }
        let mut best = f64::NEG_INFINITY;
        for &(v, x) in &peaks {
            if v == f64::NEG_INFINITY {
                continue;
            }
            let (a, c) = ((x - step).max(start), (x + step).min(end));
            best = best.max(bracketed_maximum(a, x, c, v, &value));
        }
        (best > f64::NEG_INFINITY).then_some(sign * best)
    };
    let hi = extreme(true)?;
    let lo = extreme(false)?;
    Some((lo, hi))
}

/// Golden-section search for the maximum of `f` in the bracket `a < b < c` with
/// `f(b) ≥ f(a), f(c)`: each probe goes into the larger side, and the bracket shrinks about
/// whichever of `b` and the probe is higher (`fb` is `f(b)`). The best value seen.
fn bracketed_maximum(
    mut a: f64,
    mut b: f64,
    mut c: f64,
    mut fb: f64,
    f: &impl Fn(f64) -> f64,
) -> f64 {
    let ratio = 0.5 * (3.0 - 5f64.sqrt());
    for _ in 0..GOLDEN_STEPS {
        let right = c - b > b - a;
        let x = if right {
            b + ratio * (c - b)
        } else {
            b - ratio * (b - a)
        };
        if x == b {
            break;
        }
        let fx = f(x);
        if fx > fb {
            if right {
                a = b;
            } else {
                c = b;
            }
            (b, fb) = (x, fx);
        } else if right {
            c = x;
        } else {
            a = x;
        }
    }
    fb
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ball_through_the_tube_spans_its_lens() {
        // A unit ball centred on the tube's centre circle at azimuth 0 of the torus
        // (R = 3, ρ = 1): the meridian at 0 is two unit discs about one point.
        let m = Meridians {
            q: Matrix3::identity(),
            c: Vector3::new(3.0, 0.0, 0.0),
            big: 3.0,
            small: 1.0,
            outside: 7.0,
        };
        assert!((m.gap(0.0) + 1.0).abs() < 1e-15);
        let (lo, hi) = m.z_span(0.0).unwrap();
        assert!(
            (lo + 1.0).abs() < 1e-12 && (hi - 1.0).abs() < 1e-12,
            "{lo} {hi}"
        );
        // At azimuth π the plane holds the ball's far side only: no overlap.
        assert!(m.gap(std::f64::consts::PI) > 0.0);
        assert!(m.z_span(std::f64::consts::PI).is_none());
        // The lowest and highest z over the arc: the ball's bottom and top, at φ = 0.
        let (lo, hi) = lowest_and_highest(&m, -1.0, 1.0, None).unwrap();
        assert!(
            (lo + 1.0).abs() < 1e-12 && (hi - 1.0).abs() < 1e-12,
            "{lo} {hi}"
        );
    }
}
