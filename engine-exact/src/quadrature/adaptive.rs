//! Adaptive sine-mapped Gauss–Kronrod quadrature ([`Adaptive`]) of vector-valued
//! [`Integrand`]s on pieces with square-root ends.

use super::kronrod::{MAX_NODES, Pair, node_offsets};
use super::{DEPTH_LIMIT, MAX_PIECES};
use contact_core::WorkCounters;
use std::f64::consts::FRAC_PI_2;

/// A vector-valued integrand of [`Adaptive`]: any `FnMut(f64) -> [f64; N]`, or a type that
/// evaluates a whole rule's nodes at once ([`Integrand::at_each`]).
pub trait Integrand<const N: usize> {
    /// The value at `x`.
    fn at(&mut self, x: f64) -> [f64; N];

    /// The values at each of `xs`, into `out` (as long): one at a time unless overridden. An
    /// integrand whose evaluation is one long chain of dependent steps (a root, a division, a
    /// product of their results) overrides it to take each step for all the points before the
    /// next, so that the points' chains run side by side instead of one after another.
    fn at_each(&mut self, xs: &[f64], out: &mut [[f64; N]]) {
        for (x, value) in xs.iter().zip(out) {
            *value = self.at(*x);
        }
    }
}

impl<const N: usize, F: FnMut(f64) -> [f64; N]> Integrand<N> for F {
    fn at(&mut self, x: f64) -> [f64; N] {
        self(x)
    }
}

/// The most nodes of one rule (both signs and the middle): 41.
pub const MAX_RULE_NODES: usize = 2 * MAX_NODES - 1;

/// Adaptive sine-mapped Gauss–Kronrod quadrature of vector-valued integrands on pieces
/// `[lo, hi]` whose ends may be square-root-type (a width `√(hi − x)` vanishing there).
///
/// Each piece is mapped by `x = m + w·sin t`, `t ∈ [−π/2, π/2]`, which turns a square-root
/// end into a smooth one (and `dx = w cos t dt` vanishes at both ends), then integrated by
/// the 21-node Kronrod rule, whose 10 Gauss nodes among them give a second, less exact
/// value from the same evaluations: an interval is accepted when, for every component, the
/// Kronrod value's estimated error (from the two values' difference, see `converged`) is
/// within `tolerance·|kronrod| + floor`, and halved in `t` otherwise. A kink inside a piece
/// (a corner the caller did not split at) is found by the halving; each level costs two
/// rules. A piece accepted whole costs 21 evaluations.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Adaptive {
    /// Relative agreement at which an interval's integral is accepted.
    pub tolerance: f64,
    /// Halvings allowed per piece (capped at [`DEPTH_LIMIT`]).
    pub max_depth: u32,
    /// The Gauss–Kronrod pair of each look at an interval.
    pub pair: Pair,
}

/// An interval's two estimates: `(kronrod, gauss)`.
type Estimates<const N: usize> = ([f64; N], [f64; N]);

impl Adaptive {
    /// The pair's two values of `∫ f` over the part `[t0, t1]` of `t ∈ [−π/2, π/2]`, with
    /// `x = m + w sin t` mapping `t` onto `[lo, hi]`.
    fn rule<const N: usize>(
        &self,
        (lo, hi): (f64, f64),
        (t0, t1, depth): (f64, f64, u32),
        f: &mut impl Integrand<N>,
        work: &mut WorkCounters,
    ) -> Estimates<N> {
        let mut kronrod = [0.0; N];
        let mut gauss = [0.0; N];
        let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        // The interval is `[−π/2, π/2]` halved `depth` times: its half-width is `π/2^(depth+1)`
        // and the nodes' offsets from its middle `tm` have their sines and cosines in a table,
        // so `sin t` and `cos t` at a node come by the angle-addition formulas from the one
        // `sin tm`, `cos tm` (to an ulp or two, as `sin_cos` itself is).
        let tm = 0.5 * (t0 + t1);
        let (sm, cm) = tm.sin_cos();
        let table = self.pair.table();
        let offsets = &node_offsets(self.pair)[depth.min(DEPTH_LIMIT) as usize];
        let width = FRAC_PI_2 / 2f64.powi(depth.min(DEPTH_LIMIT) as i32);
        let last = table.nodes.len() - 1;
        // The nodes in the order their values are summed (each offset's pair, then the
        // middle), evaluated all at once.
        let mut xs = [0.0; MAX_RULE_NODES];
        let mut weights = [(0.0, 0.0, 0.0); MAX_RULE_NODES];
        let mut count = 0;
        let mut node = |sin: f64, cos: f64, wk: f64, wg: f64| {
            xs[count] = mid + half * sin;
            weights[count] = (half * cos, wk, wg);
            count += 1;
        };
        for (k, (&(so, co), &w)) in offsets.iter().zip(table.kronrod).enumerate() {
            let wk = width * w;
            let wg = if k % 2 == 1 {
                width * table.gauss[k / 2]
            } else {
                0.0
            };
            if k == last {
                node(sm, cm, wk, wg);
            } else {
                node(sm * co - cm * so, cm * co + sm * so, wk, wg);
                node(sm * co + cm * so, cm * co - sm * so, wk, wg);
            }
        }
        let mut values = [[0.0; N]; MAX_RULE_NODES];
        f.at_each(&xs[..count], &mut values[..count]);
        for (value, &(jacobian, wk, wg)) in values[..count].iter().zip(&weights[..count]) {
            for k in 0..N {
                let v = jacobian * value[k];
                kronrod[k] += wk * v;
                gauss[k] += wg * v;
            }
        }
        work.iterations += 2 * table.nodes.len() as u64 - 1;
        (kronrod, gauss)
    }

    /// Whether an interval is accepted: for every component the Kronrod value's estimated
    /// error is within `tolerance·|kronrod| + floor`. The estimate is QUADPACK's: the
    /// difference `d` of the two values bounds the Gauss rule's error, and for a smooth
    /// integrand the Kronrod rule's is far smaller, about `d·(200 d/|kronrod|)^1.5`; it is
    /// trusted only while `d` itself is within the pair's trusted difference of the value
    /// ([`TRUSTED_DIFFERENCE`](super::kronrod::TRUSTED_DIFFERENCE) for the 21-node pair).
    fn converged<const N: usize>(&self, (kronrod, gauss): &Estimates<N>, floor: &[f64; N]) -> bool {
        (0..N).all(|k| {
            let d = (kronrod[k] - gauss[k]).abs();
            let scale = kronrod[k].abs();
            let estimate = if scale > 0.0 {
                // (200 d/|kronrod|)^1.5 as x·√x, capped at 1.
                let x = (200.0 * d / scale).min(1.0);
                d * x * x.sqrt()
            } else {
                d
            };
            estimate <= self.tolerance * scale + floor[k]
                && d <= self.pair.trusted() * scale + floor[k]
        })
    }

    /// Adds `∫ f` over `[lo, hi]` to `total`, starting from the whole interval's estimates
    /// `whole` and halving until, for each component, an interval's two estimates agree within
    /// `tolerance·|kronrod| + floor` (the floor, from the whole integral's size, keeps
    /// round-off in a nearly empty piece from driving the halving to its limit).
    fn integrate<const N: usize>(
        &self,
        (lo, hi): (f64, f64),
        whole: Estimates<N>,
        f: &mut impl Integrand<N>,
        floor: &[f64; N],
        work: &mut WorkCounters,
        total: &mut [f64; N],
    ) {
        let max_depth = self.max_depth.min(DEPTH_LIMIT);
        // Intervals in t ∈ [−π/2, π/2] still to judge, with their estimates (depth first: at
        // most one pending sibling per level).
        let mut stack = [(0.0, 0.0, ([0.0; N], [0.0; N]), 0u32); DEPTH_LIMIT as usize + 2];
        stack[0] = (-FRAC_PI_2, FRAC_PI_2, whole, 0);
        let mut len = 1;
        while len > 0 {
            len -= 1;
            let (t0, t1, estimates, depth) = stack[len];
            if self.converged(&estimates, floor) || depth >= max_depth || len + 2 > stack.len() {
                for (sum, value) in total.iter_mut().zip(&estimates.0) {
                    *sum += value;
                }
                continue;
            }
            let tm = 0.5 * (t0 + t1);
            let left = self.rule((lo, hi), (t0, tm, depth + 1), f, work);
            let right = self.rule((lo, hi), (tm, t1, depth + 1), f, work);
            stack[len] = (t0, tm, left, depth + 1);
            stack[len + 1] = (tm, t1, right, depth + 1);
            len += 2;
        }
    }

    /// Sorts `cuts` (at most [`MAX_PIECES`] + 1) and integrates `f` over each piece between
    /// consecutive cuts, skipping the pieces where `f` vanishes (the cuts must include every
    /// point where it starts or stops vanishing). `floor(&estimate)` turns a first estimate
    /// of the whole integral into the absolute error each piece may keep.
    pub fn integrate_pieces<const N: usize>(
        &self,
        cuts: &mut [f64],
        f: &mut impl Integrand<N>,
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
        let mut wholes = [([0.0; N], [0.0; N]); MAX_PIECES];
        let mut taken = [false; MAX_PIECES];
        let mut estimate = [0.0; N];
        for ((piece, whole), taken) in cuts.windows(2).zip(wholes.iter_mut()).zip(&mut taken) {
            if piece[1] <= piece[0] || f.at(0.5 * (piece[0] + piece[1])).iter().all(|&v| v == 0.0) {
                continue;
            }
            *whole = self.rule((piece[0], piece[1]), (-FRAC_PI_2, FRAC_PI_2, 0), f, work);
            *taken = true;
            for (sum, value) in estimate.iter_mut().zip(&whole.0) {
                *sum += value;
            }
        }
        let floor = floor(&estimate);
        let mut total = [0.0; N];
        for ((piece, whole), taken) in cuts.windows(2).zip(wholes.iter()).zip(&taken) {
            if !taken || whole.0.iter().all(|&v| v == 0.0) {
                continue;
            }
            self.integrate((piece[0], piece[1]), *whole, f, &floor, work, &mut total);
        }
        total
    }
}
