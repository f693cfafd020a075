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
    fn arithmetic_if_takes_the_branch_of_its_conditions_sign() {
        // Fortran's arithmetic IF, as Adams writes it: IF(c: negative, zero, positive).
        for (t, expected) in [(0.5, 10.0), (1.0, 20.0), (2.0, 30.0)] {
            assert_eq!(at("IF(TIME - 1: 10, 20, 30)", t), expected);
        }
        // Nested, with degrees and line breaks as a dataset continues them.
        let text = "IF( MOD(TIME,PI/2) -89D:\n STEP( MOD(TIME,PI/2), 0, 21, 89D, 28.57), 28.57,\n STEP( MOD(TIME,PI/2), 89D, 28.57, 90D, 21) )";
        let text = text.replace("\\n", "\n");
        let cubic = |d: f64, h0: f64, h1: f64| h0 + (h1 - h0) * d * d * (3.0 - 2.0 * d);
        let below = at(&text, 45f64.to_radians());
        assert!(
            (below - cubic(45.0 / 89.0, 21.0, 28.57)).abs() < 1e-12,
            "{below}"
        );
        let above = at(&text, 89.5f64.to_radians());
        assert!((above - cubic(0.5, 28.57, 21.0)).abs() < 1e-12, "{above}");
        assert_eq!(at("IF(1: 1, 2, IF(TIME: 3, 4, 5))", 0.0), 4.0);
        // Only the chosen branch is evaluated: the other may be undefined there.
        assert_eq!(at("IF(TIME: 0, 1, SQRT(TIME))", -4.0), 0.0);
        assert_eq!(
            parse_expr("IF(TIME: SQRT(TIME), 0, 1)")
                .unwrap()
                .eval(&TimeOnly(-4.0)),
            Err(EvalError::Domain {
                function: "SQRT",
                value: -4.0,
                allowed: ">= 0"
            })
        );
    }

    #[test]
    fn arithmetic_if_needs_its_colon_and_four_parts() {
        let e = parse_expr("IF(TIME, 1, 2, 3)").unwrap_err();
        assert_eq!(e.to_string(), "expected ':', found ','");
        assert_eq!(e.offset, 7);
        let e = parse_expr("IF(TIME: 1, 2)").unwrap_err();
        assert_eq!(e.to_string(), "IF takes 4..=4 arguments, 3 given");
        let e = parse_expr("MAX(TIME: 1)").unwrap_err();
        assert_eq!(e.to_string(), "expected ',' or ')', found ':'");
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
