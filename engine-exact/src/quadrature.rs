//! Gauss–Legendre quadrature, the nodes computed once (Newton on the Legendre polynomial,
//! to round-off) and kept in a static: no allocation at query time.
//!
//! An `n`-node rule integrates polynomials of degree `2n − 1` exactly; for an analytic
//! integrand on an interval of length `h` its error falls like `(h/2)^(2n)/(2n)!` times a
//! derivative bound — for the trigonometric polynomials the pair kernels integrate, 12 nodes
//! on an interval of at most π are exact to round-off. [`Adaptive`] halves it where they are
//! not: the pair kernels whose integrands have corners and square-root ends share it.

use contact_core::WorkCounters;
use std::f64::consts::FRAC_PI_2;
use std::sync::OnceLock;

/// Nodes per rule.
pub const NODES: usize = 12;

/// `(nodes, weights)` on [−1, 1].
fn rule() -> &'static ([f64; NODES], [f64; NODES]) {
    static RULE: OnceLock<([f64; NODES], [f64; NODES])> = OnceLock::new();
    RULE.get_or_init(|| {
        let mut x = [0.0; NODES];
        let mut w = [0.0; NODES];
        let n = NODES as f64;
        for i in 0..NODES {
            // Chebyshev-like first guess, then Newton on P_n.
            let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n + 0.5)).cos();
            let mut derivative = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, z);
                for k in 2..=NODES {
                    let k = k as f64;
                    let p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                derivative = n * (z * p1 - p0) / (z * z - 1.0);
                let step = p1 / derivative;
                z -= step;
                if step.abs() <= 1e-16 {
                    break;
                }
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * derivative * derivative);
        }
        (x, w)
    })
}

/// Calls `f(t, weight)` at the rule's nodes mapped onto `[a, b]`, weights scaled to it.
pub fn for_each_node(a: f64, b: f64, mut f: impl FnMut(f64, f64)) {
    let (x, w) = rule();
    let half = 0.5 * (b - a);
    let mid = 0.5 * (a + b);
    for k in 0..NODES {
        f(mid + half * x[k], half * w[k]);
    }
}

/// Most pieces [`Adaptive::integrate_pieces`] takes (cuts − 1).
pub const MAX_PIECES: usize = 32;
/// Most halvings [`Adaptive`] allows per piece, whatever it is asked.
pub const DEPTH_LIMIT: u32 = 40;

/// Adaptive sine-mapped Gauss–Legendre quadrature of vector-valued integrands on pieces
/// `[lo, hi]` whose ends may be square-root-type (a width `√(hi − x)` vanishing there).
///
/// Each piece is mapped by `x = m + w·sin t`, `t ∈ [−π/2, π/2]`, which turns a square-root
/// end into a smooth one (and `dx = w cos t dt` vanishes at both ends), then integrated by
/// the 12-node rule and halved in `t` until, for every component, the two halves agree with
/// the whole within `tolerance·|halves| + floor`. A kink inside a piece (a corner the caller
/// did not split at) is found by the halving; each level costs two rules.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Adaptive {
    /// Relative agreement at which a piece's integral is accepted.
    pub tolerance: f64,
    /// Halvings allowed per piece (capped at [`DEPTH_LIMIT`]).
    pub max_depth: u32,
}

impl Adaptive {
    /// The 12-node rule for `∫ f` over the part `[t0, t1]` of `t ∈ [−π/2, π/2]`, with
    /// `x = m + w sin t` mapping `t` onto `[lo, hi]`.
    fn rule<const N: usize>(
        (lo, hi): (f64, f64),
        (t0, t1): (f64, f64),
        f: &mut impl FnMut(f64) -> [f64; N],
        work: &mut WorkCounters,
    ) -> [f64; N] {
        let mut sum = [0.0; N];
        let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        for_each_node(t0, t1, |t, weight| {
            let (sin, cos) = t.sin_cos();
            let value = f(mid + half * sin);
            for k in 0..N {
                sum[k] += weight * half * cos * value[k];
            }
        });
        work.iterations += NODES as u64;
        sum
    }

    /// Adds `∫ f` over `[lo, hi]` to `total`, starting from the whole-interval estimate
    /// `whole` and halving until, for each component, the halves agree with the whole within
    /// `tolerance·|halves| + floor` (the floor, from the whole integral's size, keeps
    /// round-off in a nearly empty piece from driving the halving to its limit).
    pub fn integrate<const N: usize>(
        &self,
        (lo, hi): (f64, f64),
        whole: [f64; N],
        f: &mut impl FnMut(f64) -> [f64; N],
        floor: &[f64; N],
        work: &mut WorkCounters,
        total: &mut [f64; N],
    ) {
        let max_depth = self.max_depth.min(DEPTH_LIMIT);
        // Intervals in t ∈ [−π/2, π/2] still to do, with their whole-interval estimate
        // (depth first: at most one pending sibling per level).
        let mut stack = [(0.0, 0.0, [0.0; N], 0u32); DEPTH_LIMIT as usize + 2];
        stack[0] = (-FRAC_PI_2, FRAC_PI_2, whole, 0);
        let mut len = 1;
        while len > 0 {
            len -= 1;
            let (t0, t1, estimate, depth) = stack[len];
            let tm = 0.5 * (t0 + t1);
            let left = Self::rule((lo, hi), (t0, tm), f, work);
            let right = Self::rule((lo, hi), (tm, t1), f, work);
            let mut halves = [0.0; N];
            for k in 0..N {
                halves[k] = left[k] + right[k];
            }
            let converged = (0..N).all(|k| {
                (halves[k] - estimate[k]).abs() <= self.tolerance * halves[k].abs() + floor[k]
            });
            if converged || depth >= max_depth || len + 2 > stack.len() {
                for k in 0..N {
                    total[k] += halves[k];
                }
            } else {
                stack[len] = (t0, tm, left, depth + 1);
                stack[len + 1] = (tm, t1, right, depth + 1);
                len += 2;
            }
        }
    }

    /// Sorts `cuts` (at most [`MAX_PIECES`] + 1) and integrates `f` over each piece between
    /// consecutive cuts, skipping the pieces where `f` vanishes (the cuts must include every
    /// point where it starts or stops vanishing). `floor(&estimate)` turns a first estimate
    /// of the whole integral into the absolute error each piece may keep.
    pub fn integrate_pieces<const N: usize>(
        &self,
        cuts: &mut [f64],
        f: &mut impl FnMut(f64) -> [f64; N],
        floor: &impl Fn(&[f64; N]) -> [f64; N],
        work: &mut WorkCounters,
    ) -> [f64; N] {
        debug_assert!(
            cuts.len() <= MAX_PIECES + 1,
            "too many cuts: {}",
            cuts.len()
        );
        cuts.sort_by(f64::total_cmp);
        // First pass: one rule per non-empty piece. Between consecutive cuts the region is
        // empty throughout or nowhere (its edges are cuts): one look at the middle tells.
        let mut wholes = [[0.0; N]; MAX_PIECES];
        let mut estimate = [0.0; N];
        for (piece, whole) in cuts.windows(2).zip(wholes.iter_mut()) {
            if piece[1] <= piece[0] || f(0.5 * (piece[0] + piece[1])).iter().all(|&v| v == 0.0) {
                continue;
            }
            *whole = Self::rule((piece[0], piece[1]), (-FRAC_PI_2, FRAC_PI_2), f, work);
            for k in 0..N {
                estimate[k] += whole[k];
            }
        }
        let floor = floor(&estimate);
        let mut total = [0.0; N];
        for (piece, whole) in cuts.windows(2).zip(wholes.iter()) {
            if whole.iter().all(|&v| v == 0.0) {
                continue;
            }
            self.integrate((piece[0], piece[1]), *whole, f, &floor, work, &mut total);
        }
        total
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_polynomials_of_degree_23_and_a_sine_exactly() {
        let mut sum = 0.0;
        for_each_node(-1.0, 2.0, |t, w| sum += w * t.powi(22));
        let exact = (2f64.powi(23) + 1.0) / 23.0;
        assert!((sum - exact).abs() < 1e-13 * exact, "{sum} vs {exact}");
        let mut s = 0.0;
        for_each_node(0.0, std::f64::consts::PI, |t, w| s += w * t.sin());
        assert!((s - 2.0).abs() < 1e-15, "{s}");
    }
}
