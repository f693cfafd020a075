//! MOTIONs given as a velocity or an acceleration (Adams `MOTION/…, VELOCITY` or
//! `ACCELERATION`): the displacement the constraint imposes is the function integrated from
//! time 0, where the displacement is ICDISP and (for an acceleration) the velocity ICVEL:
//!
//! - VELOCITY `f`: `d(t) = ICDISP + F(t)`, `ḋ = f(t)`, `d̈ = f′(t)`, `F(t) = ∫₀ᵗ f`;
//! - ACCELERATION `f`: `d(t) = ICDISP + ICVEL·t + t·F(t) − G(t)`, `ḋ = ICVEL + F(t)`,
//!   `d̈ = f(t)`, `G(t) = ∫₀ᵗ s·f(s) ds` (Cauchy's formula for the double integral).
//!
//! The integrals come from cumulative sums over panels of width [`PANEL`] (model time units),
//! each integrated by adaptive Gauss–Legendre quadrature (the exact engine's 12-node rule
//! against its two halves, bisected until they agree to 1e-14 of the panel's magnitude), kept as they are first needed:
//! a query costs one partial panel, and every thread sees the same sums, since each panel's
//! value depends only on the panel. The derivative `f′` of a velocity motion is the same
//! central difference as a displacement motion's ([`super::lower`]).

use crate::expr::{Expr, TimeOnly};
use crate::model::MotionLevel;
use contact_solver::mbs::TimeFunction;
use engine_exact::quadrature::for_each_node;
use std::sync::{Arc, Mutex};

/// The width of the cumulative panels, in model time units.
pub const PANEL: f64 = 1.0 / 64.0;

/// `(∫ f, ∫ s·f)` over `[a, b]` by one Gauss–Legendre rule.
fn rule(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let (mut first, mut moment) = (0.0, 0.0);
    for_each_node(a, b, |s, w| {
        let v = f(s);
        first += w * v;
        moment += w * s * v;
    });
    (first, moment)
}

/// `(∫ f, ∫ s·f)` over `[a, b]`, bisected until a rule and its two halves agree.
fn adaptive(f: &dyn Fn(f64) -> f64, a: f64, b: f64, whole: (f64, f64), depth: u32) -> (f64, f64) {
    let m = 0.5 * (a + b);
    let (l, r) = (rule(f, a, m), rule(f, m, b));
    let halves = (l.0 + r.0, l.1 + r.1);
    let scale = halves.0.abs() + halves.1.abs() + f64::MIN_POSITIVE;
    let agree = (halves.0 - whole.0).abs() + (halves.1 - whole.1).abs() <= 1e-14 * scale;
    if agree || depth >= 30 || !(halves.0.is_finite() && halves.1.is_finite()) {
        return halves;
    }
    let left = adaptive(f, a, m, l, depth + 1);
    let right = adaptive(f, m, b, r, depth + 1);
    (left.0 + right.0, left.1 + right.1)
}

/// The integrals `(F, G)` of a function from 0, with cumulative sums at panel ends.
struct Integrals {
    function: Expr,
    /// `(F, G)` at `k·PANEL`, k = 0, 1, …
    cumulative: Mutex<Vec<(f64, f64)>>,
}

impl Integrals {
    fn new(function: Expr) -> Self {
        Self {
            function,
            cumulative: Mutex::new(vec![(0.0, 0.0)]),
        }
    }

    fn value(&self, t: f64) -> f64 {
        self.function.eval(&TimeOnly(t)).unwrap_or(f64::NAN)
    }

    /// The function's TIME derivative: its jet's, else a central difference.
    fn slope(&self, t: f64) -> f64 {
        if let Some(jet) = self.function.time_jet(t) {
            return jet.first;
        }
        let h = 1e-3 * t.abs().max(1.0);
        (self.value(t + h) - self.value(t - h)) / (2.0 * h)
    }

    fn over(&self, a: f64, b: f64) -> (f64, f64) {
        let f = |s: f64| self.value(s);
        let whole = rule(&f, a, b);
        adaptive(&f, a, b, whole, 0)
    }

    /// `(F(t), G(t))`.
    fn at(&self, t: f64) -> (f64, f64) {
        if !t.is_finite() {
            return (f64::NAN, f64::NAN);
        }
        if t < 0.0 {
            // Before the start: rare (a retry never goes below 0), integrated directly.
            let (f, g) = self.over(t, 0.0);
            return (-f, -g);
        }
        let panel = (t / PANEL).floor() as usize;
        let base = {
            // A poisoned lock means another thread panicked mid-push; the sums it held are
            // still those computed before, each complete.
            let mut sums = self
                .cumulative
                .lock()
                .unwrap_or_else(|poisoned| poisoned.into_inner());
            while sums.len() <= panel {
                let k = sums.len() - 1;
                let (f0, g0) = sums[k];
                let (df, dg) = self.over(k as f64 * PANEL, (k + 1) as f64 * PANEL);
                sums.push((f0 + df, g0 + dg));
            }
            sums[panel]
        };
        let start = panel as f64 * PANEL;
        if t == start {
            return base;
        }
        let (df, dg) = self.over(start, t);
        (base.0 + df, base.1 + dg)
    }
}

/// The displacement function of a MOTION given at `level` (with ICDISP and ICVEL, 0 when not
/// given), or `None` for a displacement MOTION, whose function is used as it is.
pub fn integrated_motion(
    function: Expr,
    level: MotionLevel,
    ic_displacement: f64,
    ic_velocity: f64,
) -> Option<TimeFunction> {
    if level == MotionLevel::Displacement {
        return None;
    }
    let integrals = Arc::new(Integrals::new(function));
    match level {
        MotionLevel::Displacement => None,
        MotionLevel::Velocity => Some(Arc::new(move |t: f64| {
            let (f, _) = integrals.at(t);
            let slope = integrals.slope(t);
            (ic_displacement + f, integrals.value(t), slope)
        })),
        MotionLevel::Acceleration => Some(Arc::new(move |t: f64| {
            let (f, g) = integrals.at(t);
            (
                ic_displacement + ic_velocity * t + t * f - g,
                ic_velocity + f,
                integrals.value(t),
            )
        })),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_expr;

    #[test]
    fn velocity_and_acceleration_motions_integrate_to_the_closed_forms() {
        // VELOCITY cos(3t) from ICDISP 0.2: d = 0.2 + sin(3t)/3.
        let v = integrated_motion(
            parse_expr("COS(3*TIME)").unwrap(),
            MotionLevel::Velocity,
            0.2,
            0.0,
        )
        .unwrap();
        // ACCELERATION −9 sin(3t) from ICVEL 3: d = sin(3t) + 0.5.
        let a = integrated_motion(
            parse_expr("-9*SIN(3*TIME)").unwrap(),
            MotionLevel::Acceleration,
            0.5,
            3.0,
        )
        .unwrap();
        for &t in &[
            0.0,
            1e-9,
            0.3,
            PANEL,
            2.0 * PANEL + 1e-12,
            1.7,
            12.25,
            40.0,
            -0.4,
        ] {
            let (d, dv, dd) = v(t);
            let (s, c) = (3.0 * t).sin_cos();
            assert!((d - (0.2 + s / 3.0)).abs() < 1e-13, "t {t}: {d}");
            assert!((dv - c).abs() < 1e-15, "t {t}: {dv}");
            // The central difference's truncation h²·|f‴|/6 with f‴ = 27·sin, plus round-off.
            let h: f64 = 1e-3 * t.abs().max(1.0);
            assert!((dd + 3.0 * s).abs() < 4.5 * h * h + 1e-12, "t {t}: {dd}");
            let (d, dv, dd) = a(t);
            assert!((d - (s + 0.5)).abs() < 1e-12 * (1.0 + t), "t {t}: {d}");
            assert!((dv - 3.0 * c).abs() < 1e-13, "t {t}: {dv}");
            assert!((dd + 9.0 * s).abs() < 1e-14, "t {t}: {dd}");
        }
        assert!(
            integrated_motion(
                parse_expr("1").unwrap(),
                MotionLevel::Displacement,
                0.0,
                0.0
            )
            .is_none()
        );
    }
}
