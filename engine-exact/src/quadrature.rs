//! Gauss–Legendre quadrature, the nodes computed once (Newton on the Legendre polynomial,
//! to round-off) and kept in a static: no allocation at query time.
//!
//! An `n`-node rule integrates polynomials of degree `2n − 1` exactly; for an analytic
//! integrand on an interval of length `h` its error falls like `(h/2)^(2n)/(2n)!` times a
//! derivative bound — for the trigonometric polynomials the pair kernels integrate, 12 nodes
//! on an interval of at most π are exact to round-off.

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
