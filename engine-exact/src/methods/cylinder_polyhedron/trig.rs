//! Products of up to three functions `a + b cos φ + c sin φ` integrated over an arc, for the
//! side integrals of [`super`], without cancellation on short arcs.
//!
//! About the arc's middle `m` (`φ = m + θ`, `|θ| ≤ α`) each factor is
//! `L(m) − g κ + g′ σ` with `κ = 1 − cos θ`, `σ = sin θ`, `g = b cos m + c sin m` and
//! `g′ = −b sin m + c cos m`: its value at the middle, its slope, and a curvature term of
//! order `θ²`. A factor small over a short arc (a shallow region's height above a lower bound,
//! its distance from a tangent plane) has small coefficients in this basis, where in
//! `cos kφ, sin kφ` it has large ones that cancel. The products are polynomials in `κ, σ`;
//! odd powers of `σ` integrate to zero, `σ² = 2κ − κ²`, and `∫κⁿ dθ` is the series of
//! `(1 − cos θ)ⁿ` term by term for `α < ½` (the closed forms cancel there) and the closed
//! forms above.

/// A factor `a + b cos φ + c sin φ` at an arc's middle: `(L(m), −g, g′)`, the coefficients
/// of `1, κ, σ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Local([f64; 3]);

/// A polynomial of total degree at most three in `κ, σ`: `p[i][j]` multiplies `κⁱ σʲ`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Poly([[f64; 4]; 4]);

/// An arc `[m − α, m + α]`: `(cos m, sin m)` and the integrals `∫κⁿ dθ`, `n ≤ 3`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Arc {
    cos: f64,
    sin: f64,
    kappa: [f64; 4],
}

/// Terms of the series of `(1 − cos θ)ⁿ` in `θ²` kept below `α = ½`: the twelfth is below
/// `10⁻¹⁷` of the first.
const TERMS: usize = 12;

/// `SERIES[n − 1][k]`: the coefficient of `θ^{2k}` in `(1 − cos θ)ⁿ`.
const SERIES: [[f64; TERMS + 3]; 3] = series();

const fn series() -> [[f64; TERMS + 3]; 3] {
    let mut out = [[0.0; TERMS + 3]; 3];
    // 1 − cos θ = Σ_{k ≥ 1} (−1)^{k+1} θ^{2k} / (2k)!.
    let mut factorial = 1.0;
    let mut k = 1;
    while k < TERMS + 3 {
        factorial *= ((2 * k - 1) * (2 * k)) as f64;
        out[0][k] = if k % 2 == 1 { 1.0 } else { -1.0 } / factorial;
        k += 1;
    }
    let mut n = 1;
    while n < 3 {
        let mut i = 0;
        while i < TERMS + 3 {
            let mut j = 0;
            while i + j < TERMS + 3 {
                out[n][i + j] += out[n - 1][i] * out[0][j];
                j += 1;
            }
            i += 1;
        }
        n += 1;
    }
    out
}

impl Arc {
    /// The arc about `middle` of half-angle `half`.
    pub fn new(middle: f64, half: f64) -> Self {
        let (sin, cos) = middle.sin_cos();
        let mut kappa = [2.0 * half, 0.0, 0.0, 0.0];
        if half < 0.5 {
            let x2 = half * half;
            for (n, row) in SERIES.iter().enumerate() {
                // ∫_{−α}^{α} θ^{2k} = 2α^{2k+1}/(2k+1), from k = n + 1 on.
                let mut power = 2.0 * half * x2.powi(n as i32 + 1);
                let mut sum = 0.0;
                for (k, c) in row.iter().enumerate().skip(n + 1) {
                    sum += c * power / (2 * k + 1) as f64;
                    power *= x2;
                }
                kappa[n + 1] = sum;
            }
        } else {
            let (s, c) = half.sin_cos();
            kappa[1] = 2.0 * (half - s);
            kappa[2] = 3.0 * half - 4.0 * s + s * c;
            kappa[3] = 5.0 * half - 8.0 * s + 3.0 * s * c + 2.0 / 3.0 * s * s * s;
        }
        Self { cos, sin, kappa }
    }

    /// `a + b cos φ + c sin φ` about the arc's middle.
    pub fn local(&self, a: f64, b: f64, c: f64) -> Local {
        let g = b * self.cos + c * self.sin;
        let slope = c * self.cos - b * self.sin;
        Local([a + g, -g, slope])
    }

    /// `∫ p dφ` over the arc.
    pub fn integral(&self, p: &Poly) -> f64 {
        let k = &self.kappa;
        // σ² = 2κ − κ²: κⁱσ² integrates to 2K_{i+1} − K_{i+2}.
        let p = &p.0;
        p[0][0] * k[0]
            + p[1][0] * k[1]
            + p[2][0] * k[2]
            + p[3][0] * k[3]
            + p[0][2] * (2.0 * k[1] - k[2])
            + p[1][2] * (2.0 * k[2] - k[3])
    }
}

impl Local {
    /// As a polynomial.
    pub fn poly(&self) -> Poly {
        let mut p = Poly::default();
        p.0[0][0] = self.0[0];
        p.0[1][0] = self.0[1];
        p.0[0][1] = self.0[2];
        p
    }
}

impl Poly {
    /// The product with a factor; the degree must stay at most three.
    pub fn times(&self, f: &Local) -> Self {
        let mut out = Self::default();
        for i in 0..4 {
            for j in 0..4 - i {
                let v = self.0[i][j];
                if v == 0.0 {
                    continue;
                }
                out.0[i][j] += v * f.0[0];
                if i + j < 3 {
                    out.0[i + 1][j] += v * f.0[1];
                    out.0[i][j + 1] += v * f.0[2];
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Products of three factors integrated over short and long arcs against the midpoint
    /// rule on the functions themselves.
    #[test]
    fn products_match_sampling() {
        let lin = |a: f64, b: f64, c: f64, phi: f64| a + b * phi.cos() + c * phi.sin();
        let factors = [(0.3, -1.2, 0.7), (-0.5, 0.4, 2.0), (1.1, 0.0, -0.6)];
        for (middle, half) in [
            (0.3, 1e-3),
            (0.3, 0.2),
            (2.5, 0.49),
            (-2.0, 0.51),
            (-2.0, 1.4),
            (1.0, std::f64::consts::PI),
        ] {
            let arc = Arc::new(middle, half);
            let [f, g, h] = factors.map(|(a, b, c)| arc.local(a, b, c));
            let p = f.poly().times(&g).times(&h);
            let n = 100_000;
            let step = 2.0 * half / n as f64;
            let sum: f64 = (0..n)
                .map(|i| {
                    let phi = middle - half + (i as f64 + 0.5) * step;
                    factors
                        .iter()
                        .map(|&(a, b, c)| lin(a, b, c, phi))
                        .product::<f64>()
                        * step
                })
                .sum();
            let got = arc.integral(&p);
            // The midpoint rule's error: step²/24 of the second derivative's integral.
            assert!(
                (got - sum).abs() <= 1e-9 * (1.0 + sum.abs()),
                "{middle} {half}: {got} {sum}"
            );
        }
    }

    /// The series and the closed forms meet at α = ½.
    #[test]
    fn series_and_closed_forms_meet() {
        let below = Arc::new(0.0, 0.5 - 1e-15);
        let above = Arc::new(0.0, 0.5);
        for n in 1..4 {
            let (a, b) = (below.kappa[n], above.kappa[n]);
            assert!((a - b).abs() <= 1e-12 * b.abs(), "{n}: {a} {b}");
        }
    }
}
