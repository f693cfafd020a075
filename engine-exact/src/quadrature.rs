//! Gauss–Legendre quadrature, the nodes computed once (Newton on the Legendre polynomial,
//! to round-off) and kept in a static: no allocation at query time.
//!
//! An `n`-node rule integrates polynomials of degree `2n − 1` exactly; for an analytic
//! integrand on an interval of length `h` its error falls like `(h/2)^(2n)/(2n)!` times a
//! derivative bound — for the trigonometric polynomials the pair kernels integrate, 12 nodes
//! on an interval of at most π are exact to round-off. [`Adaptive`] is for the integrands
//! that are not: the pair kernels whose integrands have corners and square-root ends share
//! it (a Gauss–Kronrod pair, halved until its error estimate meets the tolerance).

use contact_core::WorkCounters;
use std::f64::consts::FRAC_PI_2;
use std::sync::OnceLock;

/// Nodes per rule.
pub const NODES: usize = 12;

/// The `N`-node Gauss–Legendre `(nodes, weights)` on [−1, 1]: Newton on `P_N` from a
/// Chebyshev-like first guess, to round-off.
fn legendre_rule<const N: usize>() -> ([f64; N], [f64; N]) {
    let mut x = [0.0; N];
    let mut w = [0.0; N];
    let n = N as f64;
    for i in 0..N {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n + 0.5)).cos();
        let mut derivative = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=N {
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
}

/// `(nodes, weights)` on [−1, 1].
fn rule() -> &'static ([f64; NODES], [f64; NODES]) {
    static RULE: OnceLock<([f64; NODES], [f64; NODES])> = OnceLock::new();
    RULE.get_or_init(legendre_rule::<NODES>)
}

/// Calls `f(t, weight)` at the nodes of `rule` mapped onto `[a, b]`, weights scaled to it.
fn map_nodes<const N: usize>(
    (x, w): &([f64; N], [f64; N]),
    a: f64,
    b: f64,
    mut f: impl FnMut(f64, f64),
) {
    let half = 0.5 * (b - a);
    let mid = 0.5 * (a + b);
    for k in 0..N {
        f(mid + half * x[k], half * w[k]);
    }
}

/// Calls `f(t, weight)` at the rule's nodes mapped onto `[a, b]`, weights scaled to it.
pub fn for_each_node(a: f64, b: f64, f: impl FnMut(f64, f64)) {
    map_nodes(rule(), a, b, f);
}

/// Calls `f(t, weight)` at the 8-node Gauss–Legendre rule's nodes mapped onto `[a, b]`,
/// weights scaled to it: exact for polynomials of degree 15, and for a function analytic
/// inside the ellipse with foci `a`, `b` and semi-axes' sum `ρ` half-lengths its error falls
/// like `ρ^−16`. For integrands analytic well beyond their interval, where 8 nodes already
/// reach round-off and the 12 of [`for_each_node`] would be paid for nothing.
pub fn for_each_node_8(a: f64, b: f64, f: impl FnMut(f64, f64)) {
    static RULE_8: OnceLock<([f64; 8], [f64; 8])> = OnceLock::new();
    map_nodes(RULE_8.get_or_init(legendre_rule::<8>), a, b, f);
}

/// [`for_each_node_8`] with 4 nodes (exact to degree 7), for integrands analytic farther
/// still beyond their interval.
pub fn for_each_node_4(a: f64, b: f64, f: impl FnMut(f64, f64)) {
    static RULE_4: OnceLock<([f64; 4], [f64; 4])> = OnceLock::new();
    map_nodes(RULE_4.get_or_init(legendre_rule::<4>), a, b, f);
}

/// Most pieces [`Adaptive::integrate_pieces`] takes (cuts − 1).
pub const MAX_PIECES: usize = 32;
/// Most halvings [`Adaptive`] allows per piece, whatever it is asked.
pub const DEPTH_LIMIT: u32 = 40;

/// A Gauss–Kronrod pair on [−1, 1]: the `2n + 1`-node Kronrod rule and the `n`-node Gauss
/// rule whose nodes are every other one of it, so one set of values gives both and their
/// difference estimates the Gauss rule's error (QUADPACK's tables, Piessens et al. 1983).
struct KronrodPair {
    /// The non-negative nodes, decreasing, the last one 0.
    nodes: &'static [f64],
    /// The Kronrod weight of each (the negative nodes mirror them).
    kronrod: &'static [f64],
    /// The Gauss weights of the nodes at odd positions (1, 3, …) of `nodes`.
    gauss: &'static [f64],
}

/// The 10-node Gauss rule (exact to degree 19) in the 21-node Kronrod rule (to degree 31).
#[allow(
    clippy::excessive_precision,
    reason = "the tables as published; f64 rounds them"
)]
const GAUSS_KRONROD_10_21: KronrodPair = KronrodPair {
    nodes: &[
        0.995657163025808080735527280689003,
        0.973906528517171720077964012084452,
        0.930157491355708226001207180059508,
        0.865063366688984510732096688423493,
        0.780817726586416897063717578345042,
        0.679409568299024406234327365114874,
        0.562757134668604683339000099272694,
        0.433395394129247190799265943165784,
        0.294392862701460198131126603103866,
        0.148874338981631210884826001129720,
        0.0,
    ],
    kronrod: &[
        0.011694638867371874278064396062192,
        0.032558162307964727478818972459390,
        0.054755896574351996031381300244580,
        0.075039674810919952767043140916190,
        0.093125454583697605535065465083366,
        0.109387158802297641899210590325805,
        0.123491976262065851077958109831074,
        0.134709217311473325928054001771707,
        0.142775938577060080797094273138717,
        0.147739104901338491374841515972068,
        0.149445554002916905664936468389821,
    ],
    gauss: &[
        0.066671344308688137593568809893332,
        0.149451349150580593145776339657697,
        0.219086362515982043995534934228163,
        0.269266719309996355091226921569469,
        0.295524224714752870173892994651338,
    ],
};

/// The 20-node Gauss rule (exact to degree 39) in the 41-node Kronrod rule (to degree 61).
#[allow(
    clippy::excessive_precision,
    reason = "the tables as published; f64 rounds them"
)]
const GAUSS_KRONROD_20_41: KronrodPair = KronrodPair {
    nodes: &[
        0.998859031588277663838315576545863,
        0.993128599185094924786122388471320,
        0.981507877450250259193342994720217,
        0.963971927277913791267666131197277,
        0.940822633831754753519982722212443,
        0.912234428251325905867752441203298,
        0.878276811252281976077442995113078,
        0.839116971822218823394529061701521,
        0.795041428837551198350638833272788,
        0.746331906460150792614305070355642,
        0.693237656334751384805490711845932,
        0.636053680726515025452836696226286,
        0.575140446819710315342946036586425,
        0.510867001950827098004364050955251,
        0.443593175238725103199992213492640,
        0.373706088715419560672548177024927,
        0.301627868114913004320555356858592,
        0.227785851141645078080496195368575,
        0.152605465240922675505220241022678,
        0.076526521133497333754640409398838,
        0.0,
    ],
    kronrod: &[
        0.003073583718520531501218293246031,
        0.008600269855642942198661787950102,
        0.014626169256971252983787960308868,
        0.020388373461266523598010231432755,
        0.025882133604951158834505067096153,
        0.031287306777032798958543119323801,
        0.036600169758200798030557240707211,
        0.041668873327973686263788305936895,
        0.046434821867497674720231880926108,
        0.050944573923728691932707670050345,
        0.055195105348285994744832372419777,
        0.059111400880639572374967220648594,
        0.062653237554781168025870122174255,
        0.065834597133618422111563556969398,
        0.068648672928521619345623411885368,
        0.071054423553444068305790361723210,
        0.073030690332786667495189417658913,
        0.074582875400499188986581418362488,
        0.075704497684556674659542775376617,
        0.076377867672080736705502835038061,
        0.076600711917999656445049901530102,
    ],
    gauss: &[
        0.017614007139152118311861962351853,
        0.040601429800386941331039952274932,
        0.062672048334109063569506535187042,
        0.083276741576704748724758143222046,
        0.101930119817240435036750135480350,
        0.118194531961518417312377377711382,
        0.131688638449176626898494499748163,
        0.142096109318382051329298325067165,
        0.149172986472603746787828737001969,
        0.152753387130725850698084331955098,
    ],
};

/// The Gauss–Kronrod pair an [`Adaptive`] rule integrates each interval with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pair {
    /// 10 Gauss nodes in 21 Kronrod nodes: the cheaper look at an interval, for integrands
    /// whose pieces may hide a kink (each halving then costs 42 evaluations, not 82).
    Kronrod21,
    /// 20 Gauss nodes in 41 Kronrod nodes: for analytic pieces whose nearest singularity
    /// (off the real line) is too close for the 21-node rule to meet 1e-13 in one look, and
    /// for which 41 evaluations replace a few levels of halving.
    Kronrod41,
}

impl Pair {
    fn table(self) -> &'static KronrodPair {
        match self {
            Self::Kronrod21 => &GAUSS_KRONROD_10_21,
            Self::Kronrod41 => &GAUSS_KRONROD_20_41,
        }
    }

    /// The largest relative difference of an interval's two values at which the error
    /// estimate is trusted: [`TRUSTED_DIFFERENCE`] for the 21-node pair, whose pieces may
    /// hide a kink; for the 41-node pair, used on pieces cut at every kink (analytic, with
    /// square-root ends the sine map smooths), the difference `d` is the Gauss rule's error
    /// `≈ ρ⁻⁴⁰` for the integrand's Bernstein ellipse `ρ`, and the Kronrod rule's is then
    /// `≈ ρ⁻⁶² = d^1.55`: 1e-13 at `d` = 4e-9.
    fn trusted(self) -> f64 {
        match self {
            Self::Kronrod21 => TRUSTED_DIFFERENCE,
            Self::Kronrod41 => 4e-9,
        }
    }
}

/// The largest number of non-negative nodes of a pair.
const MAX_NODES: usize = 21;

/// The largest relative difference between an interval's two values [`Adaptive`] accepts,
/// whatever its tolerance: past it the Kronrod value is not trusted to be the better one
/// by the margin the error estimate assumes (a kink between the nodes), so the interval is
/// halved. The accepted value's error is then below this even there.
const TRUSTED_DIFFERENCE: f64 = 1e-10;

/// `(sin, cos)` of a pair's node offsets at one halving depth.
type OffsetRow = [(f64, f64); MAX_NODES];

/// Per halving depth `d` of `[−π/2, π/2]`, `(sin, cos)` of each of the pair's node offsets
/// from an interval's middle, `x_k·π/2^(d+1)` (computed once per pair).
fn node_offsets(pair: Pair) -> &'static [OffsetRow] {
    static TABLES: [OnceLock<Vec<OffsetRow>>; 2] = [OnceLock::new(), OnceLock::new()];
    let slot = match pair {
        Pair::Kronrod21 => 0,
        Pair::Kronrod41 => 1,
    };
    TABLES[slot].get_or_init(|| {
        (0..=DEPTH_LIMIT)
            .map(|d| {
                let width = FRAC_PI_2 / 2f64.powi(d as i32);
                let mut row = [(0.0, 1.0); MAX_NODES];
                for (entry, &x) in row.iter_mut().zip(pair.table().nodes) {
                    *entry = (width * x).sin_cos();
                }
                row
            })
            .collect()
    })
}

/// Calls `f(x, kronrod_weight, gauss_weight)` at the pair's nodes mapped onto `[a, b]`
/// (weights scaled to it; 0 for the nodes that are Kronrod nodes only): the tables' check.
#[cfg(test)]
fn for_each_kronrod_node(pair: &KronrodPair, a: f64, b: f64, mut f: impl FnMut(f64, f64, f64)) {
    let half = 0.5 * (b - a);
    let mid = 0.5 * (a + b);
    let last = pair.nodes.len() - 1;
    for (k, (&x, &w)) in pair.nodes.iter().zip(pair.kronrod).enumerate() {
        let g = if k % 2 == 1 { pair.gauss[k / 2] } else { 0.0 };
        if k == last {
            f(mid, half * w, half * g);
        } else {
            f(mid - half * x, half * w, half * g);
            f(mid + half * x, half * w, half * g);
        }
    }
}

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
    /// ([`TRUSTED_DIFFERENCE`] for the 21-node pair).
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

    /// The 8- and 4-node rules are right to round-off: exact to degree 2n − 1 (the
    /// weights sum to the length) and not at degree 2n.
    #[test]
    fn the_small_rules_are_exact_to_degree_2n_minus_1_and_no_further() {
        let (a, b) = (-0.7, 1.3);
        type Rule = fn(f64, f64, &mut dyn FnMut(f64, f64));
        let rules: [(i32, Rule); 2] = [
            (8, |a, b, f| for_each_node_8(a, b, f)),
            (4, |a, b, f| for_each_node_4(a, b, f)),
        ];
        for (nodes, rule) in rules {
            let sum = |p: i32| {
                let mut s = 0.0;
                rule(a, b, &mut |x, w| s += w * x.powi(p));
                let exact = (b.powi(p + 1) - a.powi(p + 1)) / f64::from(p + 1);
                (s, exact)
            };
            for p in 0..2 * nodes {
                let (s, exact) = sum(p);
                assert!(
                    (s - exact).abs() <= 1e-14 * exact.abs().max(1.0),
                    "{nodes} nodes, x^{p}: {s} vs {exact}"
                );
            }
            let (s, exact) = sum(2 * nodes);
            assert!(
                (s - exact).abs() > 1e-6 * exact.abs(),
                "{nodes} nodes, x^{}: {s} vs {exact}",
                2 * nodes
            );
        }
    }

    /// `(kronrod, gauss)` sums of `x^p` over `[a, b]`, against `(b^{p+1} − a^{p+1})/(p + 1)`.
    fn monomial(a: f64, b: f64, p: i32) -> (f64, f64, f64) {
        monomial_by(&GAUSS_KRONROD_10_21, a, b, p)
    }

    /// [`monomial`] by `pair`.
    fn monomial_by(pair: &KronrodPair, a: f64, b: f64, p: i32) -> (f64, f64, f64) {
        let (mut k, mut g) = (0.0, 0.0);
        for_each_kronrod_node(pair, a, b, |x, wk, wg| {
            k += wk * x.powi(p);
            g += wg * x.powi(p);
        });
        (k, g, (b.powi(p + 1) - a.powi(p + 1)) / f64::from(p + 1))
    }

    /// The tables are right to round-off: the Kronrod rule is exact to degree 31 and its
    /// Gauss part to degree 19 (the weights sum to the length), and neither beyond (one degree
    /// more misses by more than the bound the exact ones meet).
    #[test]
    fn the_kronrod_pair_is_exact_to_its_degrees() {
        for p in 0..=31 {
            let (k, g, exact) = monomial(-0.7, 1.3, p);
            assert!(
                (k - exact).abs() <= 4e-15 * exact.abs().max(1.0),
                "K21 x^{p}: {k} vs {exact}"
            );
            if p <= 19 {
                assert!(
                    (g - exact).abs() <= 4e-15 * exact.abs().max(1.0),
                    "G10 x^{p}: {g} vs {exact}"
                );
            }
        }
        let (k, _, exact) = monomial(-0.7, 1.3, 32);
        assert!(
            (k - exact).abs() > 4e-15 * exact,
            "K21 x^32 should not be exact: {k} vs {exact}"
        );
        let (_, g, exact) = monomial(-0.7, 1.3, 20);
        assert!(
            (g - exact).abs() > 4e-15 * exact,
            "G10 x^20 should not be exact"
        );
    }

    /// The 41-node tables likewise: Kronrod exact to degree 61, Gauss to degree 39 and not
    /// beyond (on `[−0.6, 1]`, where the powers themselves keep their digits; the Gauss
    /// rule's miss on `[−1, 1]`).
    #[test]
    fn the_41_node_pair_is_exact_to_its_degrees() {
        let pair = &GAUSS_KRONROD_20_41;
        for p in 0..=61 {
            let (k, g, exact) = monomial_by(pair, -0.6, 1.0, p);
            assert!(
                (k - exact).abs() <= 4e-15 * exact.abs().max(1.0),
                "K41 x^{p}: {k} vs {exact}"
            );
            if p <= 39 {
                assert!(
                    (g - exact).abs() <= 4e-15 * exact.abs().max(1.0),
                    "G20 x^{p}: {g} vs {exact}"
                );
            }
        }
        // The Kronrod rule's first miss (x^62, of order the Gauss miss squared) is far below
        // round-off; the Gauss rule's at x^40 (6e-11 of the value on [−1, 1]) is not.
        let (_, g, exact) = monomial_by(pair, -1.0, 1.0, 40);
        assert!(
            (g - exact).abs() > 4e-15 * exact,
            "G20 x^40 should not be exact"
        );
    }

    /// A smooth piece is taken whole (one rule), to round-off; a square-root end and a kink
    /// the cuts missed are resolved by halving to the tolerance, against their closed forms.
    #[test]
    fn adaptive_takes_smooth_pieces_whole_and_halves_at_a_kink() {
        let rule = Adaptive {
            tolerance: 1e-13,
            max_depth: 30,
            pair: Pair::Kronrod21,
        };
        let floor = |_: &[f64; 1]| [0.0];
        let run = |cuts: &mut [f64], f: &mut dyn FnMut(f64) -> f64| {
            let mut work = WorkCounters::default();
            let v = rule.integrate_pieces(cuts, &mut |x| [f(x)], &floor, &mut work)[0];
            (v, work.iterations)
        };
        let (v, evaluations) = run(&mut [0.0, 1.0], &mut |x: f64| x.exp());
        assert!((v - (1f64.exp() - 1.0)).abs() < 1e-15, "{v}");
        assert_eq!(evaluations, 21);
        // A quarter disc's area by its height √(1 − x²) (square-root end at 1).
        let (v, _) = run(&mut [0.0, 1.0], &mut |x: f64| (1.0 - x * x).max(0.0).sqrt());
        assert!((v - std::f64::consts::FRAC_PI_4).abs() < 1e-14, "{v}");
        // |x − 0.3| on [0, 1] with no cut at the kink: 0.045 + 0.245.
        let (v, evaluations) = run(&mut [0.0, 1.0], &mut |x: f64| (x - 0.3).abs());
        assert!((v - 0.29).abs() < 1e-11, "{v}");
        assert!(evaluations > 21, "the kink must be halved: {evaluations}");
    }
}
