//! Evaluating expressions against a [`Context`] that supplies time and model state.

use super::ast::{BinOp, ElementKind, Expr, ForceMeasure, MathFn, Measure};
use contact_core::laws::Step;
use thiserror::Error;

/// What an expression may read from the model: the solver implements this; [`TimeOnly`] serves
/// time functions (MOTION) and tests.
pub trait Context {
    /// The simulation time.
    fn time(&self) -> f64;
    /// A measure between markers (`markers` as written; 0 = omitted).
    fn measure(&self, measure: Measure, markers: &[u32]) -> Result<f64, EvalError>;
    /// `VARVAL(id)`.
    fn variable(&self, id: u32) -> Result<f64, EvalError>;
    /// A force element's force component: `NAME(id, jflag, comp, rm)`.
    fn element_force(&self, kind: ElementKind, args: [u32; 4]) -> Result<f64, EvalError>;
    /// The net force or torque at a marker, `FX(i, j, k)` …; by default
    /// [`EvalError::NeedsState`] (only request output, which has the reactions, evaluates it).
    fn force_measure(&self, measure: ForceMeasure, _markers: &[u32]) -> Result<f64, EvalError> {
        Err(EvalError::NeedsState(measure.name()))
    }
    /// `ORIENT(type, component, i, j)`; by default [`EvalError::NeedsState`] (only request
    /// output evaluates it).
    fn orient(&self, _args: [u32; 4]) -> Result<f64, EvalError> {
        Err(EvalError::NeedsState("ORIENT"))
    }
}

/// A context that knows only the time: measures, variables and forces are
/// [`EvalError::NeedsState`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeOnly(pub f64);

impl Context for TimeOnly {
    fn time(&self) -> f64 {
        self.0
    }
    fn measure(&self, measure: Measure, _markers: &[u32]) -> Result<f64, EvalError> {
        Err(EvalError::NeedsState(measure.name()))
    }
    fn variable(&self, _id: u32) -> Result<f64, EvalError> {
        Err(EvalError::NeedsState("VARVAL"))
    }
    fn element_force(&self, kind: ElementKind, _args: [u32; 4]) -> Result<f64, EvalError> {
        Err(EvalError::NeedsState(kind.name()))
    }
}

/// Why an expression has no value.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum EvalError {
    /// An argument outside a function's domain.
    #[error("{function}: argument {value:?} is out of range: must be {allowed}")]
    Domain {
        /// The function.
        function: &'static str,
        /// The argument.
        value: f64,
        /// The allowed range.
        allowed: &'static str,
    },
    /// STEP/STEP5/IMPACT/BISTOP parameters out of range.
    #[error("{function}: {source}")]
    Parameters {
        /// The function.
        function: &'static str,
        /// What was wrong.
        source: contact_core::InvalidArgument,
    },
    /// The context cannot supply a value (a measure without a model state).
    #[error("{0} needs the model state, which this context does not have")]
    NeedsState(&'static str),
    /// VARVAL nested deeper than any chain of distinct VARIABLEs: they read each other in a
    /// cycle (`contact check` reports the cycle).
    #[error(
        "VARVAL({id}): VARIABLE/{id} reads itself through a cycle of VARVALs, so it has no value"
    )]
    VariableCycle {
        /// The VARIABLE read when the nesting bound was hit.
        id: u32,
    },
    /// USER(…) names constants for a user routine; it has no value of its own.
    #[error("USER(…) cannot be evaluated: it passes constants to a user routine")]
    User,
    /// The result is NaN or infinite (overflow, division by zero).
    #[error("the expression's value is not finite ({0:?})")]
    NotFinite(f64),
}

fn domain(function: &'static str, value: f64, allowed: &'static str) -> EvalError {
    EvalError::Domain {
        function,
        value,
        allowed,
    }
}

fn step_of(function: &'static str, x0: f64, h0: f64, x1: f64, h1: f64) -> Result<Step, EvalError> {
    Step::new(x0, h0, x1, h1).map_err(|source| EvalError::Parameters { function, source })
}

/// `IMPACT(x, ẋ, x1, k, e, cmax, d) = max(0, k·(x1 − x)^e − STEP(x, x1 − d, cmax, x1, 0)·ẋ)` for
/// x < x1, else 0 (reference §1.3). Needs d > 0 and e > 0.
fn impact(a: &[f64]) -> Result<f64, EvalError> {
    let [x, xdot, x1, k, e, cmax, d] = [a[0], a[1], a[2], a[3], a[4], a[5], a[6]];
    if e.is_nan() || e <= 0.0 {
        return Err(domain("IMPACT", e, "exponent e > 0"));
    }
    if x >= x1 {
        return Ok(0.0);
    }
    let damping = step_of("IMPACT", x1 - d, cmax, x1, 0.0)?.cubic(x).value;
    Ok((k * (x1 - x).powf(e) - damping * xdot).max(0.0))
}

/// `BISTOP(x, ẋ, x1, x2, k, e, cmax, d)`: IMPACT-like stops below x1 and above x2, 0 between
/// (reference §1.5). Needs x1 < x2, d > 0, e > 0.
fn bistop(a: &[f64]) -> Result<f64, EvalError> {
    let [x, xdot, x1, x2, k, e, cmax, d] = [a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7]];
    if x1.is_nan() || x2.is_nan() || x1 >= x2 {
        return Err(domain("BISTOP", x2, "x2 > x1"));
    }
    if e.is_nan() || e <= 0.0 {
        return Err(domain("BISTOP", e, "exponent e > 0"));
    }
    if x < x1 {
        let c = step_of("BISTOP", x1 - d, cmax, x1, 0.0)?.cubic(x).value;
        Ok((k * (x1 - x).powf(e) - c * xdot).max(0.0))
    } else if x > x2 {
        let c = step_of("BISTOP", x2, 0.0, x2 + d, cmax)?.cubic(x).value;
        Ok((-k * (x - x2).powf(e) - c * xdot).min(0.0))
    } else {
        Ok(0.0)
    }
}

/// The argument an arithmetic IF takes for condition `c`: 1 below zero, 2 at zero, 3 above
/// (a NaN condition, which no finite model gives, takes the last).
pub(crate) fn if_branch(c: f64) -> usize {
    if c < 0.0 {
        1
    } else if c == 0.0 {
        2
    } else {
        3
    }
}

fn math(f: MathFn, a: &[f64]) -> Result<f64, EvalError> {
    Ok(match f {
        MathFn::Sin => a[0].sin(),
        MathFn::Cos => a[0].cos(),
        MathFn::Tan => a[0].tan(),
        MathFn::Asin if (-1.0..=1.0).contains(&a[0]) => a[0].asin(),
        MathFn::Asin => return Err(domain("ASIN", a[0], "in [-1, 1]")),
        MathFn::Acos if (-1.0..=1.0).contains(&a[0]) => a[0].acos(),
        MathFn::Acos => return Err(domain("ACOS", a[0], "in [-1, 1]")),
        MathFn::Atan => a[0].atan(),
        MathFn::Atan2 => a[0].atan2(a[1]),
        MathFn::Sinh => a[0].sinh(),
        MathFn::Cosh => a[0].cosh(),
        MathFn::Tanh => a[0].tanh(),
        MathFn::Exp => a[0].exp(),
        MathFn::Log if a[0] > 0.0 => a[0].ln(),
        MathFn::Log => return Err(domain("LOG", a[0], "> 0")),
        MathFn::Log10 if a[0] > 0.0 => a[0].log10(),
        MathFn::Log10 => return Err(domain("LOG10", a[0], "> 0")),
        MathFn::Sqrt if a[0] >= 0.0 => a[0].sqrt(),
        MathFn::Sqrt => return Err(domain("SQRT", a[0], ">= 0")),
        MathFn::Abs => a[0].abs(),
        MathFn::Sign => {
            if a[1] >= 0.0 {
                a[0].abs()
            } else {
                -a[0].abs()
            }
        }
        MathFn::Mod if a[1] != 0.0 => a[0] - (a[0] / a[1]).trunc() * a[1],
        MathFn::Mod => return Err(domain("MOD", a[1], "!= 0 (second argument)")),
        MathFn::Dim => (a[0] - a[1]).max(0.0),
        MathFn::Min => a[0].min(a[1]),
        MathFn::Max => a[0].max(a[1]),
        MathFn::Aint => a[0].trunc(),
        MathFn::Anint => a[0].round(),
        MathFn::Step => step_of("STEP", a[1], a[2], a[3], a[4])?.cubic(a[0]).value,
        MathFn::Step5 => {
            step_of("STEP5", a[1], a[2], a[3], a[4])?
                .quintic(a[0])
                .value
        }
        MathFn::Impact => impact(a)?,
        MathFn::Bistop => bistop(a)?,
        MathFn::Shf => a[2] * (a[3] * (a[0] - a[1]) - a[4]).sin() + a[5],
        MathFn::If => a[if_branch(a[0])],
    })
}

impl Expr {
    /// The value in `ctx`. A NaN or infinite result is [`EvalError::NotFinite`].
    pub fn eval(&self, ctx: &dyn Context) -> Result<f64, EvalError> {
        let v = self.eval_inner(ctx)?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(EvalError::NotFinite(v))
        }
    }

    fn eval_inner(&self, ctx: &dyn Context) -> Result<f64, EvalError> {
        Ok(match self {
            Self::Number(v) => *v,
            Self::Time => ctx.time(),
            Self::Neg(a) => -a.eval_inner(ctx)?,
            Self::Binary(op, a, b) => {
                let (x, y) = (a.eval_inner(ctx)?, b.eval_inner(ctx)?);
                match op {
                    BinOp::Add => x + y,
                    BinOp::Sub => x - y,
                    BinOp::Mul => x * y,
                    BinOp::Div => x / y,
                    BinOp::Pow => x.powf(y),
                }
            }
            // Only the chosen branch: another may be undefined there (a SQRT of a negative).
            Self::Math(MathFn::If, args) => {
                args[if_branch(args[0].eval_inner(ctx)?)].eval_inner(ctx)?
            }
            Self::Math(f, args) => {
                let values = args
                    .iter()
                    .map(|a| a.eval_inner(ctx))
                    .collect::<Result<Vec<_>, _>>()?;
                math(*f, &values)?
            }
            Self::Measure(m, markers) => ctx.measure(*m, markers)?,
            Self::VarVal(id) => ctx.variable(*id)?,
            Self::Element(kind, args) => ctx.element_force(*kind, *args)?,
            Self::ForceMeasure(m, markers) => ctx.force_measure(*m, markers)?,
            Self::Orient(args) => ctx.orient(*args)?,
            Self::User(_) => return Err(EvalError::User),
        })
    }
}
