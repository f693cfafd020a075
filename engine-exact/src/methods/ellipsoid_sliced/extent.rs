//! The `z` extent of the intersection of two quadric solids `(x − c)ᵀQ(x − c) ≤ 1` (an
//! ellipsoid, or an infinite cylinder with a singular `Q`), by Lagrangian duality over the
//! pencil.
//!
//! Every point of both solids satisfies `λ q_a + (1 − λ) q_b ≤ 1` for `λ ∈ [0, 1]`: a single
//! ellipsoid `E_λ` whose lowest and highest `z` are closed forms (`z₀ ∓ √(r·(Q_λ⁻¹)_zz)`, with
//! `z₀` its centre's height and `r = 1 − p_λ(x₀)`). Strong duality (both solids convex with
//! interior) makes `min z` over the intersection equal to `max_λ` of `E_λ`'s lowest `z`, and
//! `max z` the `min_λ` of its highest; the dual is quasi-concave in `λ` (a ray's reach into a
//! convex set), so a golden-section search finds it. An empty `E_λ` (`r < 0`) proves the
//! solids apart.

//!
//! The same holds in any dimension `D` (the last coordinate playing `z`): the ellipsoid–torus
//! pair takes it in a meridian plane, an ellipse against the tube's disc.

use nalgebra::{SMatrix, SVector};

/// A solid `(x − c)ᵀQ(x − c) ≤ 1` in `D` dimensions with `Q` symmetric positive
/// semi-definite.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Quadric<const D: usize = 3> {
    /// Centre `c`.
    pub center: SVector<f64, D>,
    /// `Q`.
    pub q: SMatrix<f64, D, D>,
}

impl<const D: usize> Quadric<D> {
    fn value(&self, x: &SVector<f64, D>) -> f64 {
        let d = x - self.center;
        d.dot(&(self.q * d))
    }
}

/// What the pencil ellipsoid at one `λ` says.
enum Pencil {
    /// Lowest and highest `z` (±∞ when `Q_λ` is singular).
    Span(f64, f64),
    /// `E_λ` is empty: the solids do not meet.
    Empty,
}

fn pencil<const D: usize>(a: &Quadric<D>, b: &Quadric<D>, lambda: f64) -> Pencil {
    let q = a.q * lambda + b.q * (1.0 - lambda);
    let Some(chol) = q.cholesky() else {
        return Pencil::Span(f64::NEG_INFINITY, f64::INFINITY);
    };
    let rhs = a.q * a.center * lambda + b.q * b.center * (1.0 - lambda);
    let x0 = chol.solve(&rhs);
    let r = 1.0 - (lambda * a.value(&x0) + (1.0 - lambda) * b.value(&x0));
    if r.is_nan() {
        return Pencil::Span(f64::NEG_INFINITY, f64::INFINITY);
    }
    if r < 0.0 {
        return Pencil::Empty;
    }
    let mut e_z = SVector::<f64, D>::zeros();
    e_z[D - 1] = 1.0;
    let y = chol.solve(&e_z);
    let half = (r * y[D - 1]).max(0.0).sqrt();
    Pencil::Span(x0[D - 1] - half, x0[D - 1] + half)
}

/// Golden-section search over `λ ∈ [0, 1]` for the largest of `pick(span)`; `None` when an
/// empty pencil ellipsoid shows the solids apart.
fn search<const D: usize>(
    a: &Quadric<D>,
    b: &Quadric<D>,
    pick: impl Fn(f64, f64) -> f64,
) -> Option<f64> {
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    let eval = |lambda: f64| match pencil(a, b, lambda) {
        Pencil::Span(lo, hi) => Some(pick(lo, hi)),
        Pencil::Empty => None,
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    let mut x1 = hi - ratio * (hi - lo);
    let mut x2 = lo + ratio * (hi - lo);
    let (mut f1, mut f2) = (eval(x1)?, eval(x2)?);
    for _ in 0..80 {
        if f1 < f2 {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + ratio * (hi - lo);
            f2 = eval(x2)?;
        } else {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - ratio * (hi - lo);
            f1 = eval(x1)?;
        }
    }
    let ends = [eval(0.0)?, eval(1.0)?];
    Some(f1.max(f2).max(ends[0]).max(ends[1]))
}

/// The highest `z` (the last coordinate) over the intersection of `a` and `b` when `upper`,
/// else the lowest; `None` when an empty pencil ellipsoid shows them apart.
pub(crate) fn z_bound<const D: usize>(a: &Quadric<D>, b: &Quadric<D>, upper: bool) -> Option<f64> {
    if upper {
        search(a, b, |_, hi| -hi).map(|v| -v)
    } else {
        search(a, b, |lo, _| lo)
    }
}

/// `(min z, max z)` over the intersection of `a` and `b` (`z` the last coordinate), or `None`
/// when they do not meet (or only touch).
pub(crate) fn z_extent<const D: usize>(a: &Quadric<D>, b: &Quadric<D>) -> Option<(f64, f64)> {
    let lowest = search(a, b, |lo, _| lo)?;
    let highest = -search(a, b, |_, hi| -hi)?;
    (lowest < highest).then_some((lowest, highest))
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::Vector3;
    use nalgebra::Matrix3;

    #[test]
    fn two_spheres_span_their_lens() {
        // Unit spheres at z = 0 and z = 1: the lens spans z ∈ [0, 1]; side by side at
        // x = ±0.5 it spans z = ±√0.75.
        let unit = |c: Vector3| Quadric {
            center: c,
            q: Matrix3::identity(),
        };
        let (lo, hi) = z_extent(&unit(Vector3::zeros()), &unit(Vector3::z())).unwrap();
        assert!(lo.abs() < 1e-15 && (hi - 1.0).abs() < 1e-15, "{lo} {hi}");
        let (lo, hi) = z_extent(&unit(Vector3::x() * 0.5), &unit(-Vector3::x() * 0.5)).unwrap();
        assert!((hi - 0.75f64.sqrt()).abs() < 1e-14 && (lo + hi).abs() < 1e-14);
        assert!(z_extent(&unit(Vector3::zeros()), &unit(Vector3::x() * 2.5)).is_none());
    }
}
