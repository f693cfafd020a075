//! B-spline curves and surfaces (rational or not) as Parasolid stores them: distinct knots
//! with multiplicities, control vertices of dimension 2–4 (the last coordinate the weight
//! when rational; the others are stored multiplied by it).

/// A B-spline in one parameter with vector values of dimension `dim` (weights divided out).
#[derive(Debug, Clone, PartialEq)]
pub struct Nurbs {
    /// Degree p ≥ 1.
    pub degree: usize,
    /// Full knot vector (multiplicities expanded), length n + p + 1.
    pub knots: Vec<f64>,
    /// Control vertices, `dim` coordinates each, homogeneous (weight last) when rational.
    pub vertices: Vec<f64>,
    /// Coordinates per stored vertex (including the weight when rational).
    pub stride: usize,
    /// Whether the last coordinate is a weight.
    pub rational: bool,
}

/// Expands distinct knots and multiplicities into a full knot vector.
pub fn expand_knots(knots: &[f64], mult: &[i64]) -> Option<Vec<f64>> {
    if knots.len() != mult.len() {
        return None;
    }
    let mut out = Vec::new();
    for (k, &m) in knots.iter().zip(mult) {
        if !(0..=64).contains(&m) {
            return None;
        }
        out.extend(std::iter::repeat_n(*k, m as usize));
    }
    Some(out)
}

/// A periodic B-spline stored by one period — n vertices and n + 1 knots t₀ … tₙ (period
/// T = tₙ − t₀) — as the equivalent open one: p knots before (t_{n−p} … t_{n−1}, less T) and p
/// after (t₁ … t_p, plus T), for vertices extended by their first p ([`wrap_vertices`]).
/// `None` unless the knots number n + 1 with n ≥ p.
pub fn unwrap_periodic_knots(knots: &[f64], p: usize) -> Option<Vec<f64>> {
    let n = knots.len().checked_sub(1)?;
    if n < p || p == 0 {
        return None;
    }
    let period = knots[n] - knots[0];
    let mut out: Vec<f64> = knots[n - p..n].iter().map(|t| t - period).collect();
    out.extend_from_slice(knots);
    out.extend(knots[1..=p].iter().map(|t| t + period));
    Some(out)
}

/// Vertices of `count` groups of `group` values each, extended by their first `p` groups.
pub fn wrap_vertices(vertices: &[f64], group: usize, p: usize) -> Vec<f64> {
    let mut out = vertices.to_vec();
    out.extend_from_slice(&vertices[..(p * group).min(vertices.len())]);
    out
}

impl Nurbs {
    /// Checks the sizes: n vertices, n + p + 1 non-decreasing knots.
    pub fn new(
        degree: usize,
        knots: Vec<f64>,
        vertices: Vec<f64>,
        stride: usize,
        rational: bool,
    ) -> Option<Self> {
        if degree == 0 || stride == 0 || !vertices.len().is_multiple_of(stride) {
            return None;
        }
        let n = vertices.len() / stride;
        if n <= degree || knots.len() != n + degree + 1 {
            return None;
        }
        if knots.windows(2).any(|w| w[1] < w[0])
            || knots.iter().any(|k| !k.is_finite())
            || vertices.iter().any(|x| !x.is_finite())
        {
            return None;
        }
        Some(Self {
            degree,
            knots,
            vertices,
            stride,
            rational,
        })
    }

    /// Number of control vertices.
    pub fn count(&self) -> usize {
        self.vertices.len() / self.stride
    }

    /// The parameter range `[t_p, t_n]`.
    pub fn range(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.count()])
    }

    /// Distinct interior knots within the range (span boundaries), including both ends.
    pub fn breaks(&self) -> Vec<f64> {
        let (a, b) = self.range();
        let mut out: Vec<f64> = self.knots[self.degree..=self.count()].to_vec();
        out.dedup();
        out.retain(|k| (a..=b).contains(k));
        out
    }

    /// The value at `t` (clamped into the range), `dim = stride − rational` coordinates.
    pub fn eval(&self, t: f64, out: &mut [f64]) {
        let p = self.degree;
        let n = self.count();
        let (a, b) = self.range();
        let t = t.clamp(a, b);
        // Span k with knots[k] <= t < knots[k+1], k in p..n-1.
        let mut k = self.knots[..n + 1]
            .partition_point(|&x| x <= t)
            .saturating_sub(1);
        k = k.clamp(p, n - 1);
        let s = self.stride;
        let mut d = [[0.0f64; 4]; 16];
        let m = p.min(15);
        for (j, dj) in d.iter_mut().enumerate().take(m + 1) {
            let v = &self.vertices[(k - p + j) * s..(k - p + j + 1) * s];
            dj[..s].copy_from_slice(v);
        }
        for r in 1..=m {
            for j in (r..=m).rev() {
                let i = k - p + j;
                let den = self.knots[i + p + 1 - r] - self.knots[i];
                let alpha = if den > 0.0 {
                    (t - self.knots[i]) / den
                } else {
                    0.0
                };
                let prev = d[j - 1];
                for (x, y) in d[j].iter_mut().zip(prev).take(s) {
                    *x = (1.0 - alpha) * y + alpha * *x;
                }
            }
        }
        let r = &d[m];
        if self.rational {
            let w = r[s - 1];
            for c in 0..s - 1 {
                out[c] = r[c] / w;
            }
        } else {
            out[..s].copy_from_slice(&r[..s]);
        }
    }
}

/// A tensor-product B-spline surface: rows of u-curves, `v` varying slowest.
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsSurface {
    /// Degree in u.
    pub u_degree: usize,
    /// Degree in v.
    pub v_degree: usize,
    /// Full u knots.
    pub u_knots: Vec<f64>,
    /// Full v knots.
    pub v_knots: Vec<f64>,
    /// Vertices, v varying fastest (`n_v` per u-index), `stride` coordinates each.
    pub vertices: Vec<f64>,
    /// Vertices in u.
    pub n_u: usize,
    /// Vertices in v.
    pub n_v: usize,
    /// Coordinates per vertex.
    pub stride: usize,
    /// Whether the last coordinate is a weight.
    pub rational: bool,
    /// Whether the surface closes on itself in u (its `u = start` and `u = end` boundaries
    /// coincide, as on a periodic B-surface): u is then taken modulo the range.
    pub u_closed: bool,
    /// Whether it closes in v.
    pub v_closed: bool,
}

/// `t` taken into `[lo, hi]` modulo its length where it lies outside.
pub fn wrap(t: f64, (lo, hi): (f64, f64)) -> f64 {
    if (lo..=hi).contains(&t) || hi <= lo {
        t
    } else {
        lo + (t - lo).rem_euclid(hi - lo)
    }
}

impl NurbsSurface {
    /// Sets [`NurbsSurface::u_closed`] and [`NurbsSurface::v_closed`] from the geometry: a
    /// direction is closed when its two boundary curves coincide within `tol` at nine points.
    pub fn with_closure(mut self, tol: f64) -> Self {
        let ((u0, u1), (v0, v1)) = self.range();
        let apart =
            |a: [f64; 3], b: [f64; 3]| (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt();
        let f = |k: usize| k as f64 / 8.0;
        self.u_closed = u1 > u0
            && (0..=8).all(|k| {
                let v = v0 + (v1 - v0) * f(k);
                apart(self.eval(u0, v), self.eval(u1, v)) <= tol
            });
        self.v_closed = v1 > v0
            && (0..=8).all(|k| {
                let u = u0 + (u1 - u0) * f(k);
                apart(self.eval(u, v0), self.eval(u, v1)) <= tol
            });
        self
    }

    /// The parameter ranges.
    pub fn range(&self) -> ((f64, f64), (f64, f64)) {
        (
            (self.u_knots[self.u_degree], self.u_knots[self.n_u]),
            (self.v_knots[self.v_degree], self.v_knots[self.n_v]),
        )
    }

    /// The point at (u, v): `Σ N_i(u) N_j(v) P_ij` over the (p+1)(q+1) vertices whose basis
    /// functions are non-zero there (homogeneous when rational, the weight divided out after).
    /// On a closed direction the parameter is taken modulo the range; otherwise it is clamped
    /// into it.
    pub fn eval(&self, u: f64, v: f64) -> [f64; 3] {
        let ((u0, u1), (v0, v1)) = self.range();
        let u = if self.u_closed {
            wrap(u, (u0, u1))
        } else {
            u.clamp(u0, u1)
        };
        let v = if self.v_closed {
            wrap(v, (v0, v1))
        } else {
            v.clamp(v0, v1)
        };
        let (ku, nu) = basis(&self.u_knots, self.u_degree, self.n_u, u);
        let (kv, nv) = basis(&self.v_knots, self.v_degree, self.n_v, v);
        let s = self.stride;
        let mut acc = [0.0f64; 4];
        for (i, bu) in nu.iter().enumerate().take(self.u_degree + 1) {
            let row = (ku - self.u_degree + i) * self.n_v;
            for (j, bv) in nv.iter().enumerate().take(self.v_degree + 1) {
                let at = (row + kv - self.v_degree + j) * s;
                let w = bu * bv;
                for (a, x) in acc.iter_mut().zip(&self.vertices[at..at + s]) {
                    *a += w * x;
                }
            }
        }
        if self.rational {
            let w = acc[s - 1];
            [acc[0] / w, acc[1] / w, acc[2] / w]
        } else {
            [acc[0], acc[1], acc[2]]
        }
    }
}

/// The knot span `k` (`knots[k] ≤ t < knots[k+1]`, k in p..n−1) of `t` and the p+1 basis
/// functions of degree p that are non-zero there, `N_{k−p} … N_k` (Cox–de Boor, computed
/// by the triangular scheme; terms over a zero-length span are zero).
fn basis(knots: &[f64], p: usize, n: usize, t: f64) -> (usize, [f64; 16]) {
    let k = knots[..n + 1]
        .partition_point(|&x| x <= t)
        .saturating_sub(1)
        .clamp(p, n - 1);
    let mut out = [0.0; 16];
    let (mut left, mut right) = ([0.0; 16], [0.0; 16]);
    out[0] = 1.0;
    for j in 1..=p.min(15) {
        left[j] = t - knots[k + 1 - j];
        right[j] = knots[k + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let den = right[r + 1] + left[j - r];
            let temp = if den != 0.0 { out[r] / den } else { 0.0 };
            out[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        out[j] = saved;
    }
    (k, out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rational_quadratic_quarter_circle_lies_on_the_circle() {
        // Quarter circle: (1,0), (1,1) weight √2/2, (0,1); homogeneous storage.
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let c = Nurbs::new(
            2,
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            vec![1.0, 0.0, 1.0, w, w, w, 0.0, 1.0, 1.0],
            3,
            true,
        )
        .unwrap();
        let mut p = [0.0; 2];
        for i in 0..=10 {
            c.eval(i as f64 / 10.0, &mut p);
            assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-14, "{p:?}");
        }
    }

    #[test]
    fn sizes_that_do_not_fit_are_refused() {
        assert!(Nurbs::new(3, vec![0.0; 5], vec![0.0; 12], 3, false).is_none());
        assert!(expand_knots(&[0.0, 1.0], &[2]).is_none());
    }

    /// The surface evaluated as its construction reads: each v-column a B-curve evaluated at
    /// v, then the u-curve through those points at u (homogeneous throughout).
    fn by_columns(n: &NurbsSurface, u: f64, v: f64) -> [f64; 3] {
        let s = n.stride;
        let mut row = Vec::new();
        let mut tmp = [0.0; 4];
        for i in 0..n.n_u {
            let c = Nurbs::new(
                n.v_degree,
                n.v_knots.clone(),
                n.vertices[i * n.n_v * s..(i + 1) * n.n_v * s].to_vec(),
                s,
                false,
            )
            .unwrap();
            c.eval(v, &mut tmp);
            row.extend_from_slice(&tmp[..s]);
        }
        let c = Nurbs::new(n.u_degree, n.u_knots.clone(), row, s, n.rational).unwrap();
        let mut out = [0.0; 3];
        c.eval(u, &mut out);
        out
    }

    #[test]
    fn a_rational_surface_evaluates_as_its_columns_do() {
        // Degree 2 × 3, 4 × 5 vertices, non-uniform knots, weights 0.5–2.
        let (nu, nv) = (4, 5);
        let mut vertices = Vec::new();
        for i in 0..nu {
            for j in 0..nv {
                let w = 0.5 + ((i * 7 + j * 3) % 5) as f64 * 0.375;
                let p = [i as f64, j as f64, ((i * j) as f64).sin()];
                vertices.extend([p[0] * w, p[1] * w, p[2] * w, w]);
            }
        }
        let n = NurbsSurface {
            u_degree: 2,
            v_degree: 3,
            u_knots: vec![0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0],
            v_knots: vec![0.0, 0.0, 0.0, 0.0, 0.3, 1.0, 1.0, 1.0, 1.0],
            vertices,
            n_u: nu,
            n_v: nv,
            stride: 4,
            rational: true,
            u_closed: false,
            v_closed: false,
        };
        for a in 0..=10 {
            for b in 0..=10 {
                let (u, v) = (a as f64 / 10.0, b as f64 / 10.0);
                let (p, q) = (n.eval(u, v), by_columns(&n, u, v));
                for k in 0..3 {
                    assert!((p[k] - q[k]).abs() < 1e-12, "({u}, {v}): {p:?} {q:?}");
                }
            }
        }
    }
}
