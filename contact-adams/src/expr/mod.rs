//! Adams function expressions (MOTION, SFORCE, VARIABLE, REQUEST): a Pratt parser to an
//! [`Expr`] tree and an evaluator over a [`Context`] that supplies the model state.
//!
//! ```
//! use contact_adams::expr::{parse_expr, TimeOnly};
//! // The adamspy dataset's MOTION: 30 degrees per second.
//! let motion = parse_expr("30.0d * time").unwrap();
//! let angle = motion.eval(&TimeOnly(2.0)).unwrap();
//! assert!((angle - 60f64.to_radians()).abs() < 1e-15);
//! ```
//!
//! Unsupported functions are parse errors naming the function, so a model check reports them
//! before any run.

mod ast;
mod eval;
mod jet;
mod parse;

pub use ast::{BinOp, Callee, ElementKind, Expr, FUNCTIONS, ForceMeasure, MathFn, Measure};
pub use eval::{Context, EvalError, TimeOnly};
pub use jet::Jet;
pub use parse::{ExprError, ExprErrorKind, MAX_DEPTH, parse_expr};

#[cfg(test)]
mod tests {
    use super::*;

    fn at(text: &str, t: f64) -> f64 {
        parse_expr(text).unwrap().eval(&TimeOnly(t)).unwrap()
    }

    #[test]
    fn precedence_and_powers() {
        assert_eq!(at("1 + 2 * 3", 0.0), 7.0);
        assert_eq!(at("-2**2", 0.0), -4.0);
        assert_eq!(at("2**3**2", 0.0), 512.0);
        assert_eq!(at("2^-1", 0.0), 0.5);
        assert_eq!(at("(1+2)*3 - 4/2", 0.0), 7.0);
        assert_eq!(at("1.0E+002 + .5", 0.0), 100.5);
        assert_eq!(at("8 - 3 - 2", 0.0), 3.0);
    }

    #[test]
    fn degrees_time_and_constants() {
        assert_eq!(at("90D", 0.0), std::f64::consts::FRAC_PI_2);
        assert_eq!(at("TIME * 2", 1.5), 3.0);
        assert_eq!(at("180 * DTOR", 0.0), std::f64::consts::PI);
        assert!((at("PI * RTOD", 0.0) - 180.0).abs() < 1e-12);
    }

    #[test]
    fn errors_name_what_and_where() {
        let e = parse_expr("1 + FOO(2)").unwrap_err();
        assert_eq!(e.offset, 4);
        assert_eq!(e.to_string(), "unsupported function FOO");
        let e = parse_expr("STEP(time, 1, 0)").unwrap_err();
        assert_eq!(e.to_string(), "STEP takes 5..=5 arguments, 3 given");
        let e = parse_expr("DX(1.5)").unwrap_err();
        assert!(e.to_string().contains("must be an integer id"), "{e}");
        assert_eq!(parse_expr("(1 + 2").unwrap_err().offset, 6);
        assert_eq!(parse_expr("1 # 2").unwrap_err().offset, 2);
        assert!(parse_expr("1.0d3").is_err());
        assert!(parse_expr("").is_err());
    }

    #[test]
    fn depth_is_bounded_for_chains_and_nesting() {
        let chain = vec!["1"; MAX_DEPTH / 2].join(" + ");
        assert_eq!(at(&chain, 0.0), (MAX_DEPTH / 2) as f64);
        let long = vec!["1"; 4 * MAX_DEPTH].join(" + ");
        assert_eq!(parse_expr(&long).unwrap_err().kind, ExprErrorKind::TooDeep);
        let nested = format!(
            "{}1{}",
            "(".repeat(4 * MAX_DEPTH),
            ")".repeat(4 * MAX_DEPTH)
        );
        assert_eq!(
            parse_expr(&nested).unwrap_err().kind,
            ExprErrorKind::TooDeep
        );
    }

    #[test]
    fn state_functions_ask_the_context() {
        let e = parse_expr("DX(2, 3) + VARVAL(1)").unwrap();
        assert_eq!(e.marker_ids(), [2, 3]);
        assert_eq!(e.variable_ids(), [1]);
        assert!(!e.is_time_only());
        assert_eq!(e.eval(&TimeOnly(0.0)), Err(EvalError::NeedsState("DX")));
    }
}
