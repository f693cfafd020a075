//! Gauss–Legendre quadrature, the nodes computed once (Newton on the Legendre polynomial,
//! to round-off) and kept in a static: no allocation at query time.
//!
//! An `n`-node rule integrates polynomials of degree `2n − 1` exactly; for an analytic
//! integrand on an interval of length `h` its error falls like `(h/2)^(2n)/(2n)!` times a
//! derivative bound — for the trigonometric polynomials the pair kernels integrate, 12 nodes
//! on an interval of at most π are exact to round-off. [`Adaptive`] is for the integrands
//! that are not: the pair kernels whose integrands have corners and square-root ends share
//! it (a Gauss–Kronrod pair, halved until its error estimate meets the tolerance).
//!
//! This file holds the fixed Gauss–Legendre rules; [`Adaptive`] and its [`Integrand`]s are in
//! `adaptive`, the Gauss–Kronrod tables it integrates with ([`Pair`]) in `kronrod`.

mod adaptive;
mod kronrod;
#[cfg(test)]
mod tests;

pub use adaptive::{Adaptive, Integrand, MAX_RULE_NODES};
pub use kronrod::Pair;
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
