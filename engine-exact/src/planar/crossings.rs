//! Where two chains cross: recursive subdivision on bounding boxes, then Newton.
//!
//! Every pair of pieces whose boxes overlap is split (the larger half first) until both are
//! smaller than [`LEAF_SIZE`] of the pair's length `L` (or [`MAX_DEPTH`] splits deep); from
//! each leaf, Newton on the 2×2 system `P_a(s) = P_b(t)` runs on the *whole* pieces to
//! round-off (a step below `1e-15·L`, at most [`MAX_NEWTON_STEPS`] steps), and the answer is
//! kept when it closes to `1e-14·L` (a few units of round-off). Answers closer than
//! `1e-9·L` are one crossing.
//!
//! Grazing contacts (tangent chains) make Newton singular: such leaves give no answer, and a
//! crossing whose tangents make an angle below [`MIN_SINE`] is dropped — a touching pair
//! encloses no area, so this is also where the contact it would give vanishes. Two shallow
//! crossings (a nearly tangent pair) can fall in one leaf: a leaf whose crossing has a sine
//! below [`SHALLOW_SINE`] is searched again by Newton from its four corners, which finds the
//! twin. Should a crossing still be missed, the region walk fails to close and the region is
//! dropped rather than answered wrongly.

use super::boundary::{Chain, Piece};
use contact_core::{Vector2, WorkCounters};

/// Leaf size of the subdivision, relative to the pair's length.
pub const LEAF_SIZE: f64 = 1e-3;
/// Deepest subdivision.
pub const MAX_DEPTH: usize = 48;
/// Newton steps per leaf.
pub const MAX_NEWTON_STEPS: usize = 40;
/// Smallest sine of the angle between the chains at a kept crossing.
pub const MIN_SINE: f64 = 1e-9;
/// Below this sine of the crossing angle, a leaf is searched again from its corners.
pub const SHALLOW_SINE: f64 = 1e-2;
/// Most leaves examined per chain pair (bounds the work on coincident chains).
pub const MAX_LEAVES: usize = 20_000;

/// A transversal crossing of chain `a` and chain `b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Crossing {
    /// Forward parameter on `a`.
    pub tau_a: f64,
    /// Forward parameter on `b`.
    pub tau_b: f64,
    /// The point.
    pub point: Vector2,
    /// Sine of the angle from `b`'s forward tangent to `a`'s, `t_a × t_b`: negative where `a`
    /// enters `b`'s material.
    pub sine: f64,
}

/// All transversal crossings of `a` and `b`, in no particular order.
pub(crate) fn find(a: &Chain, b: &Chain, length: f64, work: &mut WorkCounters) -> Vec<Crossing> {
    let mut out: Vec<Crossing> = Vec::new();
    let mut search = Search {
        leaf: LEAF_SIZE * length,
        length,
        leaves: 0,
        work,
    };
    for (i, pa) in a.pieces.iter().enumerate() {
        for (j, pb) in b.pieces.iter().enumerate() {
            search.descend(
                pa,
                [0.0, 1.0],
                pb,
                [0.0, 1.0],
                0,
                &mut |s, t, point, sine| {
                    let c = Crossing {
                        tau_a: i as f64 + s,
                        tau_b: j as f64 + t,
                        point,
                        sine,
                    };
                    if !out
                        .iter()
                        .any(|o| (o.point - c.point).norm() <= 1e-9 * length)
                    {
                        out.push(c);
                    }
                },
            );
        }
    }
    out
}

struct Search<'w> {
    leaf: f64,
    length: f64,
    leaves: usize,
    work: &'w mut WorkCounters,
}

impl Search<'_> {
    fn descend(
        &mut self,
        pa: &Piece,
        ra: [f64; 2],
        pb: &Piece,
        rb: [f64; 2],
        depth: usize,
        found: &mut dyn FnMut(f64, f64, Vector2, f64),
    ) {
        self.work.bounding_volume_tests += 1;
        let (sa, sb) = (pa.sub(ra[0], ra[1]), pb.sub(rb[0], rb[1]));
        let (lo_a, hi_a) = sa.bounding_box();
        let (lo_b, hi_b) = sb.bounding_box();
        let slack = 1e-12 * self.length;
        if lo_a.x > hi_b.x + slack
            || lo_b.x > hi_a.x + slack
            || lo_a.y > hi_b.y + slack
            || lo_b.y > hi_a.y + slack
        {
            return;
        }
        let (size_a, size_b) = ((hi_a - lo_a).norm(), (hi_b - lo_b).norm());
        if (size_a <= self.leaf && size_b <= self.leaf) || depth >= MAX_DEPTH {
            if self.leaves < MAX_LEAVES {
                self.leaves += 1;
                let middle = [0.5 * (ra[0] + ra[1]), 0.5 * (rb[0] + rb[1])];
                if let Some((s, t, p, sine)) = self.newton(pa, pb, middle) {
                    found(s, t, p, sine);
                    // A shallow crossing may have its twin in the same leaf: Newton from the
                    // leaf's corners finds it (the twins are then the nearest roots there).
                    if sine.abs() < SHALLOW_SINE {
                        for start in [
                            [ra[0], rb[0]],
                            [ra[0], rb[1]],
                            [ra[1], rb[0]],
                            [ra[1], rb[1]],
                        ] {
                            if let Some((s, t, p, sine)) = self.newton(pa, pb, start) {
                                found(s, t, p, sine);
                            }
                        }
                    }
                }
            }
            return;
        }
        if size_a >= size_b {
            let m = 0.5 * (ra[0] + ra[1]);
            self.descend(pa, [ra[0], m], pb, rb, depth + 1, found);
            self.descend(pa, [m, ra[1]], pb, rb, depth + 1, found);
        } else {
            let m = 0.5 * (rb[0] + rb[1]);
            self.descend(pa, ra, pb, [rb[0], m], depth + 1, found);
            self.descend(pa, ra, pb, [m, rb[1]], depth + 1, found);
        }
    }

    /// Newton on `P_a(s) − P_b(t) = 0` from `start`, kept inside both pieces.
    fn newton(
        &mut self,
        pa: &Piece,
        pb: &Piece,
        start: [f64; 2],
    ) -> Option<(f64, f64, Vector2, f64)> {
        let [mut s, mut t] = start;
        for _ in 0..MAX_NEWTON_STEPS {
            self.work.iterations += 1;
            let r = pa.point(s) - pb.point(t);
            let (da, db) = (pa.derivative(s), pb.derivative(t));
            // [da, −db]·(Δs, Δt) = −r
            let det = -da.x * db.y + da.y * db.x;
            let scale = da.norm() * db.norm();
            if det.is_nan() || det.abs() <= 1e-14 * scale {
                break;
            }
            let ds = (-r.x * -db.y + r.y * -db.x) / det;
            let dt = (da.x * -r.y - da.y * -r.x) / det;
            let (ns, nt) = ((s + ds).clamp(0.0, 1.0), (t + dt).clamp(0.0, 1.0));
            let moved = (ns - s).abs() * da.norm() + (nt - t).abs() * db.norm();
            s = ns;
            t = nt;
            if moved <= 1e-15 * self.length {
                break;
            }
        }
        let (p, q) = (pa.point(s), pb.point(t));
        if (p - q).norm() > 1e-14 * self.length {
            return None;
        }
        let (ta, tb) = (pa.derivative(s), pb.derivative(t));
        let norms = ta.norm() * tb.norm();
        if norms.is_nan() || norms <= 0.0 {
            return None;
        }
        let sine = (ta.x * tb.y - ta.y * tb.x) / norms;
        (sine.abs() >= MIN_SINE).then_some((s, t, 0.5 * (p + q), sine))
    }
}

/// The transversal crossings of two single pieces, handed to `found(s, t, point, sine)`
/// (duplicates possible where a crossing falls on a leaf boundary).
pub(crate) fn between_pieces(
    pa: &Piece,
    pb: &Piece,
    length: f64,
    work: &mut WorkCounters,
    found: &mut dyn FnMut(f64, f64, Vector2, f64),
) {
    let mut search = Search {
        leaf: LEAF_SIZE * length,
        length,
        leaves: 0,
        work,
    };
    search.descend(pa, [0.0, 1.0], pb, [0.0, 1.0], 0, found);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_both_crossings_of_a_circle_a_hair_below_a_line() {
        let depth = 1e-9;
        let circle = Chain::from_arc(1.0, std::f64::consts::TAU, 1.0).mapped(
            &nalgebra::Matrix2::identity(),
            &Vector2::new(0.3, 1.0 - depth),
        );
        let line = Chain::from_line(-3.0, 3.0, [false; 2], 1.0);
        let mut work = WorkCounters::default();
        let found = find(&circle, &line, 6.0, &mut work);
        assert_eq!(found.len(), 2, "{found:?}");
        let half = ((2.0 - depth) * depth).sqrt();
        let mut xs: Vec<f64> = found.iter().map(|c| c.point.x - 0.3).collect();
        xs.sort_by(f64::total_cmp);
        // Conditioning: a residual of round-off moves a crossing by ε/sine ≈ 1e-16/4.5e-5.
        assert!(
            (xs[0] + half).abs() < 1e-11 && (xs[1] - half).abs() < 1e-11,
            "{xs:?}"
        );
    }
}
