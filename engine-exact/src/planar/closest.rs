//! The closest point of a [`Chain`] to a point, and whether the point lies in the chain's
//! material.
//!
//! Each piece is sampled at [`SAMPLES`] + 1 parameters, then Newton on
//! `g(s) = (P(s) − q)·P′(s)` runs from the nearest sample, kept inside the piece, until a step
//! moves the point by less than `1e-15` of the chain's size; the nearest answer wins.

use super::boundary::{Chain, Piece};
use contact_core::{Vector2, WorkCounters};

/// Samples per piece for the starting guess.
pub const SAMPLES: usize = 16;
/// Newton steps per piece.
pub const MAX_NEWTON_STEPS: usize = 40;

/// The closest point of a chain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Foot {
    /// Forward parameter.
    pub tau: f64,
    /// The point.
    pub point: Vector2,
    /// The forward tangent there (not normalised).
    pub tangent: Vector2,
}

/// The closest point of `piece` on `[s0, s1]` to `q`: `(s, point, squared distance)`.
pub(crate) fn on_piece(
    piece: &Piece,
    s0: f64,
    s1: f64,
    q: &Vector2,
    size: f64,
    work: &mut WorkCounters,
) -> (f64, Vector2, f64) {
    let mut best = (s0, f64::INFINITY);
    for k in 0..=SAMPLES {
        let s = s0 + (s1 - s0) * k as f64 / SAMPLES as f64;
        let d = (piece.point(s) - q).norm_squared();
        if d < best.1 {
            best = (s, d);
        }
    }
    let mut s = best.0;
    for _ in 0..MAX_NEWTON_STEPS {
        work.iterations += 1;
        let c = piece.point(s) - q;
        let d1 = piece.derivative(s);
        let g = c.dot(&d1);
        let dg = d1.norm_squared() + c.dot(&piece.second_derivative(s));
        if dg.is_nan() || dg <= 0.0 {
            break;
        }
        let next = (s - g / dg).clamp(s0, s1);
        let moved = (next - s).abs() * d1.norm();
        s = next;
        if moved <= 1e-15 * size {
            break;
        }
    }
    let p = piece.point(s);
    let d = (p - q).norm_squared();
    if d <= best.1 {
        (s, p, d)
    } else {
        (best.0, piece.point(best.0), best.1)
    }
}

/// The closest point of `chain` to `q`.
pub(crate) fn foot(chain: &Chain, q: &Vector2, size: f64, work: &mut WorkCounters) -> Foot {
    let mut best = (
        f64::INFINITY,
        Foot {
            tau: 0.0,
            point: chain.point(0.0),
            tangent: Vector2::zeros(),
        },
    );
    for (k, piece) in chain.pieces.iter().enumerate() {
        let (s, point, d) = on_piece(piece, 0.0, 1.0, q, size, work);
        if d < best.0 {
            let mut tangent = piece.derivative(s);
            if tangent.norm() == 0.0 {
                tangent = piece.second_derivative(s);
            }
            best = (
                d,
                Foot {
                    tau: k as f64 + s,
                    point,
                    tangent,
                },
            );
        }
    }
    best.1
}

/// True when `q` lies strictly inside `chain`'s material (on the left of its closest point,
/// and not beyond an end of an open chain by more than `1e-9` of `size`).
pub(crate) fn inside(chain: &Chain, q: &Vector2, size: f64, work: &mut WorkCounters) -> bool {
    let f = foot(chain, q, size, work);
    let t_norm = f.tangent.norm();
    if t_norm.is_nan() || t_norm <= 0.0 {
        return false;
    }
    let t = f.tangent / t_norm;
    let offset = q - f.point;
    let at_end = !chain.closed && (f.tau <= 0.0 || f.tau >= chain.count());
    if at_end && offset.dot(&t).abs() > 1e-9 * size {
        return false;
    }
    // Outward normal: the right-hand normal of the forward tangent.
    offset.dot(&Vector2::new(t.y, -t.x)) < -1e-12 * size
}
