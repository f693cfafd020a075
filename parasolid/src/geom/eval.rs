//! Evaluation of the curves and surfaces read in `super`: points, derivatives and the inverse
//! `point → parameters` (see the table in `super`'s docs).

use super::{CLOSED, Curve, Surface};
use contact_core::Point3;
use std::f64::consts::TAU;

impl Curve {
    /// The parameter range (`None` for an unbounded line); closed analytic curves give one
    /// period `[0, 2π]`.
    pub fn range(&self) -> Option<(f64, f64)> {
        match self {
            Curve::Line { .. } => None,
            Curve::Ellipse { .. } => Some((0.0, TAU)),
            Curve::Polyline(p) => Some((0.0, (p.len() - 1) as f64)),
            Curve::Nurbs(n) => Some(n.range()),
            Curve::OnSurface { uv, .. } => Some(uv.range()),
            Curve::Trimmed { t0, t1, .. } => Some((t0.min(*t1), t0.max(*t1))),
        }
    }

    /// Whether the parameter is periodic with period 2π (circles and ellipses).
    pub fn is_periodic(&self) -> bool {
        matches!(self, Curve::Ellipse { .. })
    }

    /// The parameter interval over which a closed curve repeats: `[0, 2π]` for circles and
    /// ellipses, the range of any other curve whose two ends lie within [`CLOSED`] (a periodic
    /// or closed B-curve, a closed intersection curve); `None` for an open curve.
    pub fn closed_range(&self) -> Option<(f64, f64)> {
        if self.is_periodic() {
            return Some((0.0, TAU));
        }
        let (lo, hi) = self.range()?;
        ((self.eval(lo) - self.eval(hi)).norm() < CLOSED && hi > lo).then_some((lo, hi))
    }

    /// The point at `t`, taken modulo the range on a closed curve (see
    /// [`Curve::closed_range`]) and clamped into it on an open one.
    pub fn eval_wrapped(&self, t: f64) -> Point3 {
        if self.range().is_none_or(|(lo, hi)| (lo..=hi).contains(&t)) {
            return self.eval(t);
        }
        match self.closed_range() {
            Some(r) => self.eval(crate::nurbs::wrap(t, r)),
            None => self.eval(t),
        }
    }

    /// The point at parameter `t`.
    pub fn eval(&self, t: f64) -> Point3 {
        match self {
            Curve::Line { p, d } => p + d * t,
            Curve::Ellipse { c, x, y, a, b } => c + x * (a * t.cos()) + y * (b * t.sin()),
            Curve::Polyline(p) => {
                let last = p.len() - 1;
                let t = t.clamp(0.0, last as f64);
                let i = (t.floor() as usize).min(last - 1);
                let f = t - i as f64;
                p[i] + (p[i + 1] - p[i]) * f
            }
            Curve::Nurbs(n) => {
                let mut o = [0.0; 3];
                n.eval(t, &mut o);
                Point3::new(o[0], o[1], o[2])
            }
            Curve::OnSurface { surface, uv } => {
                let mut o = [0.0; 2];
                uv.eval(t, &mut o);
                surface.eval(o[0], o[1])
            }
            Curve::Trimmed { basis, .. } => basis.eval(t),
        }
    }

    /// The parameter of the point of the curve nearest `p` (a coarse search refined by
    /// golden sections; exact for lines and circles).
    pub fn closest(&self, p: &Point3) -> f64 {
        match self {
            Curve::Line { p: o, d } => (p - o).dot(d),
            Curve::Ellipse { c, x, y, a, b } if (a - b).abs() <= 1e-12 * a => {
                let v = p - c;
                v.dot(y).atan2(v.dot(x)).rem_euclid(TAU)
            }
            _ => {
                let (lo, hi) = self.range().unwrap_or((0.0, 1.0));
                let n = match self {
                    Curve::Polyline(pts) => pts.len() * 4,
                    _ => 256,
                };
                let f = |t: f64| (self.eval(t) - p).norm_squared();
                let step = (hi - lo) / n as f64;
                let mut best = (f64::INFINITY, lo);
                for i in 0..=n {
                    let t = lo + step * i as f64;
                    let d = f(t);
                    if d < best.0 {
                        best = (d, t);
                    }
                }
                golden(&f, (best.1 - step).max(lo), (best.1 + step).min(hi))
            }
        }
    }
}

/// Minimises `f` on `[a, b]` by golden sections (60 steps: the bracket shrinks by 1e-12).
pub fn golden(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - g * (b - a);
    let mut d = a + g * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..60 {
        if fc < fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    0.5 * (a + b)
}

impl Surface {
    /// The point at (u, v).
    pub fn eval(&self, u: f64, v: f64) -> Point3 {
        match self {
            Surface::Plane { o, x, y } => o + x * u + y * v,
            Surface::Cone { o, a, x, y, r, tan } => {
                o + a * v + (x * u.cos() + y * u.sin()) * (r + v * tan)
            }
            Surface::Sphere { c, a, x, y, r } => {
                c + (x * u.cos() + y * u.sin()) * (r * v.cos()) + a * (r * v.sin())
            }
            Surface::Torus {
                c,
                a,
                x,
                y,
                big,
                small,
            } => c + (x * u.cos() + y * u.sin()) * (big + small * v.cos()) + a * (small * v.sin()),
            Surface::Nurbs(n) => Point3::from(n.eval(u, v)),
            Surface::Swept { section, d } => section.eval_wrapped(u) + d * v,
            Surface::Spun { profile, b, a } => {
                let q = profile.eval_wrapped(u) - b;
                let (s, c) = v.sin_cos();
                b + q * c + a.cross(&q) * s + a * (a.dot(&q) * (1.0 - c))
            }
        }
    }

    /// Periods of u and v (`None` where not periodic): 2π round an axis; a closed section or
    /// profile's range (see [`Curve::closed_range`]); a closed B-surface's range.
    pub fn periods(&self) -> (Option<f64>, Option<f64>) {
        let len = |r: Option<(f64, f64)>| r.map(|(lo, hi)| hi - lo);
        match self {
            Surface::Cone { .. } | Surface::Sphere { .. } => (Some(TAU), None),
            Surface::Torus { .. } => (Some(TAU), Some(TAU)),
            Surface::Spun { profile, .. } => (len(profile.closed_range()), Some(TAU)),
            Surface::Swept { section, .. } => (len(section.closed_range()), None),
            Surface::Nurbs(n) => {
                let ((u0, u1), (v0, v1)) = n.range();
                (n.u_closed.then_some(u1 - u0), n.v_closed.then_some(v1 - v0))
            }
            Surface::Plane { .. } => (None, None),
        }
    }
}
