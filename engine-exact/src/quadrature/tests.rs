//! The rules against closed forms: the fixed Gauss–Legendre rules' and the Kronrod tables'
//! degrees of exactness, and [`Adaptive`](super::Adaptive) on smooth, square-root-ended and
//! kinked integrands.

use super::kronrod::{
    GAUSS_KRONROD_10_21, GAUSS_KRONROD_20_41, KronrodPair, for_each_kronrod_node,
};
use super::*;
use contact_core::WorkCounters;

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
