//! The unit disc less an ellipse, component by component: the section of an ellipsoid (seen
//! as the unit disc) outside a cavity's section (the ellipse), for the ellipsoids in a
//! cavity.
//!
//! The disc less a convex region is bounded by the circle's arcs outside the region and the
//! region's boundary inside the circle, run the other way. For an ellipse (two convex curves
//! crossing at most four times, in the same cyclic order along both) each maximal arc of the
//! circle outside the ellipse, from crossing `θ_a` to crossing `θ_b`, closes with the
//! ellipse's arc between the same two points that lies inside the circle, run clockwise: one
//! *lune* per such arc. Without crossings the difference is the whole disc (apart), the disc
//! with an elliptic hole (one component, the circle counter-clockwise and the whole ellipse
//! clockwise), or empty (the circle inside the ellipse, or the same curve).
//!
//! Each lune is a [`DiscOverlap`] of its own boundary pieces, so the slicing integrand reads it
//! as it reads an overlap: area and moments by Green's theorem, the circle's arcs (the
//! ellipsoid's surface in the cavity's material) in `arcs`, `chord` and `angle`, and the
//! ellipse's arc (the cavity's wall inside the ellipsoid) in `other_arcs`, stored from its end
//! to its start.

use super::disc_overlap::{
    CircleCrossings, DiscOverlap, disc_ellipse, ellipse_parameter, on_circle,
};
use nalgebra::{Matrix2, Vector2};
use std::f64::consts::TAU;

/// Most components: a disc less an ellipse has two at most (four crossings leave two arcs
/// outside), a disc less an elliptic annulus one more inside the annulus' hole.
pub(crate) const MAX_LUNES: usize = 3;

/// [`Lunes::curves`] of the whole disc (no cavity curve bounds it).
pub(crate) const WHOLE: u8 = 2;

/// [`Lunes::curves`] of the part inside an annulus' hole.
pub(crate) const INNER: u8 = 1;

/// The components of the unit disc less an ellipse (or an elliptic annulus).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Lunes {
    parts: [DiscOverlap; MAX_LUNES],
    /// Per part, the cavity's curve its `other_arcs` lie on: 0 the ellipse (an annulus'
    /// outer one), 1 an annulus' inner one, 2 none (the whole disc).
    curves: [u8; MAX_LUNES],
    count: usize,
}

impl Lunes {
    /// The components, each with its boundary pieces.
    pub(crate) fn parts(&self) -> &[DiscOverlap] {
        &self.parts[..self.count]
    }

    /// Per component, the cavity's curve its `other_arcs` lie on (see [`Lunes`]).
    pub(crate) fn curves(&self) -> &[u8] {
        &self.curves[..self.count]
    }

    /// The whole unit disc (a section beyond the cavity's ends).
    pub(crate) fn whole_disc() -> Self {
        let mut out = Self::default();
        out.push().add_circle_arc(0.0, TAU);
        out.curves[0] = WHOLE;
        out
    }

    fn push(&mut self) -> &mut DiscOverlap {
        debug_assert!(self.count < MAX_LUNES, "too many lunes");
        let k = self.count.min(MAX_LUNES - 1);
        self.count = k + 1;
        &mut self.parts[k]
    }
}

/// The unit disc less the ellipse `center + matrix·u(φ)` (`det matrix > 0`), one part per
/// component.
pub(crate) fn disc_less_ellipse(center: &Vector2<f64>, matrix: &Matrix2<f64>) -> Lunes {
    let mut out = Lunes::default();
    let (theta, n, inside, inverse) = match CircleCrossings::of(center, matrix) {
        CircleCrossings::Degenerate | CircleCrossings::Apart => return Lunes::whole_disc(),
        CircleCrossings::Same | CircleCrossings::CircleInside => return out,
        CircleCrossings::EllipseInside => {
            holed_disc(&mut out, center, matrix);
            return out;
        }
        CircleCrossings::At {
            theta,
            n,
            inside,
            inverse,
        } => (theta, n, inside, inverse),
    };
    // The circle's intervals between crossings, outside the ellipse or not; a spurious root
    // (a tangency counted twice) only splits an interval, so runs of outside ones are merged.
    let end = |k: usize| {
        if k + 1 < n {
            theta[k + 1]
        } else {
            theta[0] + TAU
        }
    };
    let outside = |k: usize| inside.value(0.5 * (theta[k] + end(k))) >= 0.0;
    let Some(first_inside) = (0..n).find(|&k| !outside(k)) else {
        // The circle is nowhere inside: the ellipse touches it from inside or from outside.
        let mid = center + matrix * on_circle(0.0);
        if mid.norm_squared() < 1.0 {
            holed_disc(&mut out, center, matrix);
        } else {
            return Lunes::whole_disc();
        }
        return out;
    };
    let mut k = first_inside + 1;
    let stop = first_inside + n;
    while k < stop {
        if !outside(k % n) {
            k += 1;
            continue;
        }
        let start = k % n;
        while k + 1 < stop && outside((k + 1) % n) {
            k += 1;
        }
        let (theta_a, mut theta_b) = (theta[start], end(k % n));
        if theta_b < theta_a {
            theta_b += TAU;
        }
        add_lune(out.push(), center, matrix, &inverse, (theta_a, theta_b));
        k += 1;
    }
    out
}

/// The unit disc less the annulus between the ellipses `inner` and `outer` (each a centre and
/// a matrix; `inner` inside `outer`): the disc's overlap with the inner ellipse (the
/// annulus' hole: one convex part, its arcs of the inner ellipse run counter-clockwise), then
/// the lunes outside the outer one.
pub(crate) fn disc_less_annulus(
    inner: (&Vector2<f64>, &Matrix2<f64>),
    outer: (&Vector2<f64>, &Matrix2<f64>),
) -> Lunes {
    let hole = disc_ellipse(inner.0, inner.1);
    let mut out = disc_less_ellipse(outer.0, outer.1);
    if hole.area > 0.0 {
        // The hole's part first: shift the lunes up.
        let count = out.count.min(MAX_LUNES - 1);
        for k in (0..count).rev() {
            out.parts[k + 1] = out.parts[k];
            out.curves[k + 1] = out.curves[k];
        }
        out.parts[0] = hole;
        out.curves[0] = INNER;
        out.count = count + 1;
    }
    out
}

/// The disc with the whole ellipse as its hole.
fn holed_disc(out: &mut Lunes, center: &Vector2<f64>, matrix: &Matrix2<f64>) {
    let part = out.push();
    part.add_circle_arc(0.0, TAU);
    part.add_ellipse_arc(center, matrix, TAU, 0.0);
}

/// The lune of the circle's arc `(θ_a, θ_b)` outside the ellipse: that arc counter-clockwise,
/// then the ellipse's arc between the same points inside the circle, clockwise.
fn add_lune(
    part: &mut DiscOverlap,
    center: &Vector2<f64>,
    matrix: &Matrix2<f64>,
    inverse: &Matrix2<f64>,
    (theta_a, theta_b): (f64, f64),
) {
    part.add_circle_arc(theta_a, theta_b);
    let phi_a = ellipse_parameter(inverse, center, theta_a);
    let mut phi_b = ellipse_parameter(inverse, center, theta_b);
    if phi_b < phi_a {
        phi_b += TAU;
    }
    // The forward arc from φ_a to φ_b is the one inside the circle (both curves meet their
    // crossings in the same cyclic order); its complement is taken only if its middle says so.
    let forward_mid = center + matrix * on_circle(0.5 * (phi_a + phi_b));
    let (from, to) = if forward_mid.norm_squared() <= 1.0 {
        (phi_a, phi_b)
    } else {
        (phi_b, phi_a + TAU)
    };
    part.add_ellipse_arc(center, matrix, to, from);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;
    use std::f64::consts::PI;

    #[test]
    fn lunes_add_up_to_the_disc_less_the_overlap() {
        let mut rng = Rng(11);
        let mut counts = [0usize; 3];
        for _ in 0..4000 {
            let center = Vector2::new(rng.uniform(-1.8, 1.8), rng.uniform(-1.8, 1.8));
            let angle = rng.uniform(0.0, PI);
            let (c, s) = (angle.cos(), angle.sin());
            let axes = Matrix2::new(rng.uniform(0.1, 2.0), 0.0, 0.0, rng.uniform(0.1, 2.0));
            let matrix = Matrix2::new(c, -s, s, c) * axes;
            let lunes = disc_less_ellipse(&center, &matrix);
            let overlap = disc_ellipse(&center, &matrix);
            let area: f64 = lunes.parts().iter().map(|p| p.area).sum();
            let moment: Vector2<f64> = lunes.parts().iter().map(|p| p.moment).sum();
            let angle_out: f64 = lunes.parts().iter().map(|p| p.angle).sum();
            assert!(
                (area - (PI - overlap.area)).abs() < 1e-12,
                "{area} {}",
                overlap.area
            );
            assert!((moment + overlap.moment).norm() < 1e-12);
            if area > 0.0 {
                assert!((angle_out - (TAU - overlap.angle)).abs() < 1e-12);
            }
            for p in lunes.parts() {
                assert!(p.area > -1e-15, "a lune of negative area {}", p.area);
            }
            counts[lunes.parts().len()] += 1;
        }
        // Every count occurs in the sample (two lunes: an ellipse across the disc).
        assert!(counts.iter().all(|&c| c > 50), "{counts:?}");
    }

    /// An ellipse across the disc, symmetric about both axes: two mirror lunes, each the
    /// area in closed form.
    #[test]
    fn an_ellipse_across_the_disc_leaves_two_mirror_lunes() {
        let matrix = Matrix2::new(0.4, 0.0, 0.0, 3.0);
        let lunes = disc_less_ellipse(&Vector2::zeros(), &matrix);
        assert_eq!(lunes.parts().len(), 2);
        let (a, b) = (lunes.parts()[0], lunes.parts()[1]);
        assert!((a.area - b.area).abs() < 1e-14);
        assert!((a.moment.x + b.moment.x).abs() < 1e-14);
        // The right lune: x from 0.4·√(1 − y²/9) to √(1 − y²) for |y| < y₀, where
        // ∫₋ₐᵃ √(1 − y²) dy = a√(1 − a²) + asin a.
        let y0: f64 = ((1.0 - 0.16) / (1.0 - 0.16 / 9.0_f64)).sqrt();
        let half_disc = |a: f64| a * (1.0 - a * a).sqrt() + a.asin();
        let exact = half_disc(y0) - 1.2 * half_disc(y0 / 3.0);
        assert!((a.area - exact).abs() < 1e-14, "{} {exact}", a.area);
    }

    #[test]
    fn an_ellipse_inside_leaves_one_holed_disc() {
        let matrix = Matrix2::new(0.3, 0.1, 0.0, 0.5);
        let lunes = disc_less_ellipse(&Vector2::new(0.1, -0.2), &matrix);
        assert_eq!(lunes.parts().len(), 1);
        let hole = PI * matrix.determinant();
        assert!((lunes.parts()[0].area - (PI - hole)).abs() < 1e-14);
        let apart = disc_less_ellipse(&Vector2::new(3.0, 0.0), &matrix);
        assert!((apart.parts()[0].area - PI).abs() < 1e-15);
        let covering = disc_less_ellipse(&Vector2::zeros(), &Matrix2::identity().scale(1.5));
        assert!(covering.parts().is_empty());
    }
}
