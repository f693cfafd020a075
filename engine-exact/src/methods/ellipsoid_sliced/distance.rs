//! The distance from a point to a filled ellipse of the plane, for the slicings whose other
//! solid is a disc about the origin (a frustum's or torus' section) or a disc in a meridian
//! plane (a torus' tube).
//!
//! The ellipse `{c + M u : |u| ≤ 1}` in its principal frame (`M = U Σ Vᵀ`, semi-axes
//! `σ₁, σ₂`): the point `y = Uᵀ(p − c)` outside it has its closest boundary point at
//! `x_i = σ_i² y_i/(σ_i² + λ)` for the one `λ > 0` with
//! `F(λ) = Σ (σ_i y_i/(σ_i² + λ))² − 1 = 0`. `F` is convex and decreasing, so Newton from
//! below (`λ₀ = max_i(σ_i|y_i| − σ_i²) ≤ λ`, from each term being at most 1) climbs to the
//! root without overshooting; the distance `λ·|(y_i/(σ_i² + λ))|` has no cancellation.

use nalgebra::{Matrix2, Vector2};

/// The distance from `p` to the filled ellipse `{center + matrix·u : |u| ≤ 1}` (`0` inside;
/// `matrix` invertible).
pub(crate) fn ellipse_distance(
    p: &Vector2<f64>,
    center: &Vector2<f64>,
    matrix: &Matrix2<f64>,
) -> f64 {
    let d = p - center;
    match matrix.try_inverse() {
        Some(inverse) if (inverse * d).norm_squared() > 1.0 => {}
        Some(_) => return 0.0,
        // A degenerate ellipse: its centre stands for it.
        None => return d.norm(),
    }
    let svd = matrix.svd(true, false);
    let Some(u) = svd.u else {
        return d.norm();
    };
    let y = u.transpose() * d;
    let s = svd.singular_values;
    let term = |lambda: f64, k: usize| s[k] * y[k] / (s[k] * s[k] + lambda);
    let mut lambda = (0..2)
        .map(|k| s[k] * y[k].abs() - s[k] * s[k])
        .fold(0.0, f64::max);
    for _ in 0..64 {
        let (t0, t1) = (term(lambda, 0), term(lambda, 1));
        let value = t0 * t0 + t1 * t1 - 1.0;
        let slope = -2.0 * (t0 * t0 / (s[0] * s[0] + lambda) + t1 * t1 / (s[1] * s[1] + lambda));
        if value <= 0.0 || slope >= 0.0 || !slope.is_finite() {
            break;
        }
        let step = -value / slope;
        let next = lambda + step;
        if next <= lambda {
            break;
        }
        lambda = next;
    }
    lambda * Vector2::new(y[0] / (s[0] * s[0] + lambda), y[1] / (s[1] * s[1] + lambda)).norm()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_to_a_circle_and_an_ellipse() {
        let c = Vector2::new(1.0, -2.0);
        let circle = Matrix2::identity() * 0.5;
        let d = ellipse_distance(&Vector2::new(4.0, 2.0), &c, &circle);
        assert!((d - 4.5).abs() < 1e-15, "{d}");
        assert_eq!(ellipse_distance(&Vector2::new(1.2, -2.1), &c, &circle), 0.0);
        // Axis-aligned 2 × 1 ellipse rotated by 30°: a point on the minor axis.
        let (s, co) = (0.5f64, 0.75f64.sqrt());
        let rot = Matrix2::new(co, -s, s, co);
        let m = rot * Matrix2::new(2.0, 0.0, 0.0, 1.0);
        let p = Vector2::zeros() + rot * Vector2::new(0.0, 3.0);
        let d = ellipse_distance(&p, &Vector2::zeros(), &m);
        assert!((d - 2.0).abs() < 1e-14, "{d}");
        // Brute force along the boundary for an off-axis point.
        let p = Vector2::new(2.5, 1.7);
        let brute = (0..200_000)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / 200_000.0;
                (m * Vector2::new(a.cos(), a.sin()) - p).norm()
            })
            .fold(f64::INFINITY, f64::min);
        let d = ellipse_distance(&p, &Vector2::zeros(), &m);
        assert!(
            (d - brute).abs() < 1e-9 && d <= brute + 1e-15,
            "{d} vs {brute}"
        );
    }
}
