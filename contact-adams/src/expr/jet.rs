//! Time derivatives of a time function by forward-mode differentiation: each node of the tree
//! carries its value and its first and second derivatives with respect to TIME (a second-order
//! jet), so a MOTION's velocity and acceleration are those of its FUNCTION to round-off, not
//! difference quotients.
//!
//! Rules: sums and products by Leibniz' rule; a quotient `q = a/b` by `q′ = (a′ − q b′)/b`,
//! `q″ = (a″ − 2q′b′ − q b″)/b`; a function of one argument `f(g)` by the chain rule
//! `(f(g))′ = f′(g) g′`, `(f(g))″ = f″(g) g′² + f′(g) g″`; `ATAN2(y, x)` by
//! `θ′ = (x y′ − y x′)/r²`. Piecewise functions (ABS, SIGN, DIM, MIN, MAX, MOD, AINT, ANINT,
//! STEP, STEP5) take the derivatives of the piece the value lies on (one-sided at a kink).
//! STEP and STEP5 whose ends depend on TIME, IMPACT, BISTOP and anything but TIME and numbers
//! have no jet: the caller differences them instead.

use super::ast::{BinOp, Expr, MathFn};
use super::eval::TimeOnly;

/// A value and its first and second time derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jet {
    /// The value.
    pub value: f64,
    /// d/dt.
    pub first: f64,
    /// d²/dt².
    pub second: f64,
}

impl Jet {
    fn constant(value: f64) -> Self {
        Self {
            value,
            first: 0.0,
            second: 0.0,
        }
    }

    /// `f(self)` given `f`, `f′` and `f″` at the value.
    fn chain(self, f: f64, df: f64, d2f: f64) -> Self {
        Self {
            value: f,
            first: df * self.first,
            second: d2f * self.first * self.first + df * self.second,
        }
    }

    fn is_constant(&self) -> bool {
        self.first == 0.0 && self.second == 0.0
    }

    fn add(self, o: Self) -> Self {
        Self {
            value: self.value + o.value,
            first: self.first + o.first,
            second: self.second + o.second,
        }
    }

    fn sub(self, o: Self) -> Self {
        self.add(o.neg())
    }

    fn neg(self) -> Self {
        Self {
            value: -self.value,
            first: -self.first,
            second: -self.second,
        }
    }

    fn mul(self, o: Self) -> Self {
        Self {
            value: self.value * o.value,
            first: self.first * o.value + self.value * o.first,
            second: self.second * o.value + 2.0 * self.first * o.first + self.value * o.second,
        }
    }

    fn div(self, o: Self) -> Self {
        let q = self.value / o.value;
        let q1 = (self.first - q * o.first) / o.value;
        let q2 = (self.second - 2.0 * q1 * o.first - q * o.second) / o.value;
        Self {
            value: q,
            first: q1,
            second: q2,
        }
    }

    fn pow(self, o: Self) -> Self {
        let (x, y) = (self.value, o.value);
        let value = x.powf(y);
        if o.is_constant() {
            // d/dx x^y = y x^(y−1), d²/dx² = y (y − 1) x^(y−2), written without dividing by x.
            let df = if y == 0.0 { 0.0 } else { y * x.powf(y - 1.0) };
            let d2f = if y == 0.0 || y == 1.0 {
                0.0
            } else {
                y * (y - 1.0) * x.powf(y - 2.0)
            };
            return self.chain(value, df, d2f);
        }
        // x^y = exp(y ln x), x > 0.
        let ln = self.chain(x.ln(), 1.0 / x, -1.0 / (x * x));
        let e = o.mul(ln);
        let mut out = e.chain(value, value, value);
        out.value = value;
        out
    }
}

impl Expr {
    /// The value and first and second TIME derivatives of a time function at `t`, or `None`
    /// where this module has no rule (see the module docs) or a value is not finite.
    pub fn time_jet(&self, t: f64) -> Option<Jet> {
        let jet = self.jet(t)?;
        (jet.value.is_finite() && jet.first.is_finite() && jet.second.is_finite()).then_some(jet)
    }

    fn jet(&self, t: f64) -> Option<Jet> {
        Some(match self {
            Self::Number(v) => Jet::constant(*v),
            Self::Time => Jet {
                value: t,
                first: 1.0,
                second: 0.0,
            },
            Self::Neg(a) => a.jet(t)?.neg(),
            Self::Binary(op, a, b) => {
                let (a, b) = (a.jet(t)?, b.jet(t)?);
                match op {
                    BinOp::Add => a.add(b),
                    BinOp::Sub => a.sub(b),
                    BinOp::Mul => a.mul(b),
                    BinOp::Div => a.div(b),
                    BinOp::Pow => a.pow(b),
                }
            }
            // The chosen branch's jet, as the evaluator takes only that branch.
            Self::Math(MathFn::If, args) => {
                let condition = args[0].eval(&TimeOnly(t)).ok()?;
                args[super::eval::if_branch(condition)].jet(t)?
            }
            Self::Math(f, args) => {
                let args = args.iter().map(|a| a.jet(t)).collect::<Option<Vec<_>>>()?;
                let value = self.eval(&TimeOnly(t)).ok()?;
                let mut jet = math_jet(*f, &args)?;
                // The value as the evaluator computes it, to the bit.
                jet.value = value;
                jet
            }
            Self::Measure(..)
            | Self::VarVal(_)
            | Self::Element(..)
            | Self::ForceMeasure(..)
            | Self::Orient(_)
            | Self::User(_) => return None,
        })
    }
}

/// The jet of a mathematical function of jets.
/// The jet of an elementary function (trigonometric, hyperbolic, exponential, logarithmic,
/// square root) of `a[0]`, or ATAN2 of `a[0]`, `a[1]`; `None` for every other function.
fn elementary_jet(f: MathFn, a: &[Jet]) -> Option<Jet> {
    let x = a[0].value;
    let g = a[0];
    Some(match f {
        MathFn::Sin => g.chain(x.sin(), x.cos(), -x.sin()),
        MathFn::Cos => g.chain(x.cos(), -x.sin(), -x.cos()),
        MathFn::Tan => {
            let (tan, sec2) = (x.tan(), 1.0 + x.tan() * x.tan());
            g.chain(tan, sec2, 2.0 * tan * sec2)
        }
        MathFn::Asin | MathFn::Acos => {
            let s = 1.0 - x * x;
            let (df, d2f) = (1.0 / s.sqrt(), x / (s * s.sqrt()));
            if f == MathFn::Asin {
                g.chain(x.asin(), df, d2f)
            } else {
                g.chain(x.acos(), -df, -d2f)
            }
        }
        MathFn::Atan => {
            let s = 1.0 + x * x;
            g.chain(x.atan(), 1.0 / s, -2.0 * x / (s * s))
        }
        MathFn::Atan2 => {
            let (y, xx) = (a[0], a[1]);
            let r2 = y.value * y.value + xx.value * xx.value;
            let n = xx.value * y.first - y.value * xx.first;
            let n1 = xx.value * y.second - y.value * xx.second;
            let r21 = 2.0 * (xx.value * xx.first + y.value * y.first);
            Jet {
                value: y.value.atan2(xx.value),
                first: n / r2,
                second: (n1 * r2 - n * r21) / (r2 * r2),
            }
        }
        MathFn::Sinh => g.chain(x.sinh(), x.cosh(), x.sinh()),
        MathFn::Cosh => g.chain(x.cosh(), x.sinh(), x.cosh()),
        MathFn::Tanh => {
            let th = x.tanh();
            let d = 1.0 - th * th;
            g.chain(th, d, -2.0 * th * d)
        }
        MathFn::Exp => g.chain(x.exp(), x.exp(), x.exp()),
        MathFn::Log => g.chain(x.ln(), 1.0 / x, -1.0 / (x * x)),
        MathFn::Log10 => {
            let l = std::f64::consts::LN_10;
            g.chain(x.log10(), 1.0 / (x * l), -1.0 / (x * x * l))
        }
        MathFn::Sqrt => {
            let s = x.sqrt();
            g.chain(s, 0.5 / s, -0.25 / (s * x))
        }
        _ => return None,
    })
}

fn math_jet(f: MathFn, a: &[Jet]) -> Option<Jet> {
    let x = a[0].value;
    let g = a[0];
    Some(match f {
        MathFn::Sin
        | MathFn::Cos
        | MathFn::Tan
        | MathFn::Asin
        | MathFn::Acos
        | MathFn::Atan
        | MathFn::Atan2
        | MathFn::Sinh
        | MathFn::Cosh
        | MathFn::Tanh
        | MathFn::Exp
        | MathFn::Log
        | MathFn::Log10
        | MathFn::Sqrt => return elementary_jet(f, a),
        MathFn::Abs => {
            if x < 0.0 {
                g.neg()
            } else {
                g
            }
        }
        MathFn::Sign => {
            // |a|·sgn(b): a's jet, or its negative.
            let positive = (x >= 0.0) == (a[1].value >= 0.0);
            if positive { g } else { g.neg() }
        }
        MathFn::Mod => {
            let k = (x / a[1].value).trunc();
            g.sub(a[1].mul(Jet::constant(k)))
        }
        MathFn::Dim => {
            if x > a[1].value {
                g.sub(a[1])
            } else {
                Jet::constant(0.0)
            }
        }
        MathFn::Min => {
            if x <= a[1].value {
                g
            } else {
                a[1]
            }
        }
        MathFn::Max => {
            if x >= a[1].value {
                g
            } else {
                a[1]
            }
        }
        MathFn::Aint | MathFn::Anint => Jet::constant(0.0),
        MathFn::Step | MathFn::Step5 => step_jet(f == MathFn::Step5, a)?,
        MathFn::Shf => {
            // a·sin(ω(x − x0) − φ) + b.
            let phase = a[3].mul(g.sub(a[1])).sub(a[4]);
            let u = phase.value;
            a[2].mul(phase.chain(u.sin(), u.cos(), -u.sin())).add(a[5])
        }
        // Reached only through `Expr::jet`'s own arm, which takes the chosen branch alone.
        MathFn::If => a[super::eval::if_branch(x)],
        MathFn::Impact | MathFn::Bistop => return None,
    })
}

/// STEP (cubic) or STEP5 (quintic) of `x` from `(x0, h0)` to `(x1, h1)`, the four ends
/// constant: `h0 + (h1 − h0)·s(D)`, `D = (x − x0)/(x1 − x0)`, derivatives `s′(D)/Δ` and
/// `s″(D)/Δ²` inside, zero outside.
fn step_jet(quintic: bool, a: &[Jet]) -> Option<Jet> {
    if a[1..].iter().any(|j| !j.is_constant()) {
        return None;
    }
    let (x, x0, h0, x1, h1) = (a[0].value, a[1].value, a[2].value, a[3].value, a[4].value);
    if x <= x0 || x >= x1 || x1 <= x0 {
        return Some(Jet::constant(if x <= x0 { h0 } else { h1 }));
    }
    let width = x1 - x0;
    let d = (x - x0) / width;
    let (ds, d2s) = if quintic {
        (
            30.0 * d * d * (1.0 - d) * (1.0 - d),
            60.0 * d * (1.0 - d) * (1.0 - 2.0 * d),
        )
    } else {
        (6.0 * d * (1.0 - d), 6.0 * (1.0 - 2.0 * d))
    };
    let rise = h1 - h0;
    Some(a[0].chain(f64::NAN, rise * ds / width, rise * d2s / (width * width)))
}

#[cfg(test)]
mod tests {
    use crate::expr::{TimeOnly, parse_expr};

    /// The jet against central differences of the evaluator at a small step (their error,
    /// `h²/6·f‴` and `h²/12·f⁗`, is far below the tolerance at these smooth points).
    fn agrees(text: &str, t: f64) {
        let e = parse_expr(text).unwrap();
        let jet = e.time_jet(t).unwrap_or_else(|| panic!("{text}: no jet"));
        let f = |s: f64| e.eval(&TimeOnly(s)).unwrap();
        let h = 1e-4;
        let first = (f(t + h) - f(t - h)) / (2.0 * h);
        let h2 = 1e-3;
        let second = (f(t + h2) - 2.0 * f(t) + f(t - h2)) / (h2 * h2);
        let scale = 1.0 + jet.first.abs() + jet.second.abs();
        assert_eq!(jet.value, f(t), "{text}");
        assert!(
            (jet.first - first).abs() <= 1e-6 * scale,
            "{text}: {jet:?} vs {first}"
        );
        assert!(
            (jet.second - second).abs() <= 1e-4 * scale,
            "{text}: {jet:?} vs {second}"
        );
    }

    #[test]
    fn every_rule_agrees_with_differences() {
        for text in [
            "0.1 * SIN(2 * PI * TIME)",
            "COS(3 * TIME) / (2 + TIME**2)",
            "TAN(TIME / 3) - ATAN(TIME) + ASIN(TIME / 4) * ACOS(TIME / 5)",
            "ATAN2(SIN(TIME), COS(2 * TIME) + 2)",
            "SINH(TIME) + COSH(TIME / 2) * TANH(TIME)",
            "EXP(-TIME) * LOG(1 + TIME) + LOG10(2 + TIME) + SQRT(1 + TIME)",
            "ABS(TIME - 3) + SIGN(TIME, -1) + DIM(TIME, 0.2) + MIN(TIME, 5) + MAX(TIME, -1)",
            "MOD(3 * TIME, 1.1) + AINT(TIME) + ANINT(TIME)",
            "STEP(TIME, 0.5, 0, 2, 1) + STEP5(TIME, 0.5, 1, 2, -3)",
            "SHF(TIME, 0.1, 2, 3, 0.4, 1)",
            "TIME ** 3 + 2 ** TIME + (1 + TIME) ** (TIME / 2)",
            "-360D * TIME",
            "IF(TIME - 1: TIME**2, 0, SIN(TIME)) + IF(TIME - 9: 1, 2, SQRT(TIME - 9))",
        ] {
            for t in [0.3, 0.77, 1.3] {
                agrees(text, t);
            }
        }
    }

    #[test]
    fn exact_where_closed_forms_are_known() {
        let e = parse_expr("0.1 * SIN(2 * PI * TIME)").unwrap();
        let w = 2.0 * std::f64::consts::PI;
        let jet = e.time_jet(0.01).unwrap();
        assert!((jet.first - 0.1 * w * (w * 0.01).cos()).abs() < 1e-15);
        assert!((jet.second + 0.1 * w * w * (w * 0.01).sin()).abs() < 1e-14);
        // A STEP's derivatives vanish outside its span and follow the cubic inside.
        let s = parse_expr("STEP(TIME, 1, 0, 3, 2)").unwrap();
        let (before, inside) = (s.time_jet(0.5).unwrap(), s.time_jet(1.5).unwrap());
        assert_eq!((before.first, before.second), (0.0, 0.0));
        // D = 0.25, width 2, rise 2: 2·6D(1 − D)/2 = 1.125 and 2·6(1 − 2D)/2² = 1.5.
        assert!((inside.first - 1.125).abs() < 1e-15 && (inside.second - 1.5).abs() < 1e-15);
    }

    #[test]
    fn no_jet_without_a_rule() {
        for text in [
            "DX(1, 2)",
            "IMPACT(TIME, 0, 1, 1, 1, 1, 0.1)",
            "STEP(TIME, TIME, 0, 3, 1)",
        ] {
            assert!(parse_expr(text).unwrap().time_jet(0.5).is_none(), "{text}");
        }
    }
}
