//! The expression language against closed forms written out here: Adams' STEP worked example,
//! STEP5/IMPACT/BISTOP at hand-computed points, precedence, and a context that records what the
//! evaluator asks it for.

use contact::expr::{Context, ElementKind, EvalError, Measure, TimeOnly, parse_expr};
use std::cell::RefCell;

fn at(text: &str, t: f64) -> f64 {
    parse_expr(text).unwrap().eval(&TimeOnly(t)).unwrap()
}

#[test]
fn step_matches_the_adams_worked_example() {
    // [VIEW] solver_assist_step: STEP((2,3,3.5,4,5),3,0,4,1) = 0,0,0.5,1,1.
    for (x, want) in [(2.0, 0.0), (3.0, 0.0), (3.5, 0.5), (4.0, 1.0), (5.0, 1.0)] {
        assert_eq!(at(&format!("STEP({x}, 3, 0, 4, 1)"), 0.0), want);
        assert_eq!(at("step(time, 3, 0, 4, 1)", x), want);
    }
    // STEP5 at D = 1/4: D³(10 − 15D + 6D²) = 0.103515625.
    assert!((at("STEP5(1.25, 1, 0, 2, 1)", 0.0) - 0.103_515_625).abs() < 1e-15);
    // x1 <= x0 is out of range, not a silent value.
    let e = parse_expr("STEP(TIME, 1, 0, 1, 1)")
        .unwrap()
        .eval(&TimeOnly(0.0))
        .unwrap_err();
    assert!(
        matches!(
            e,
            EvalError::Parameters {
                function: "STEP",
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn impact_and_bistop_match_their_published_formulas() {
    // IMPACT(x=0.9, ẋ=−1, x1=1, k=100, e=2, cmax=10, d=0.2): penetration 0.1, damping
    // STEP(0.9, 0.8, 10, 1, 0) = 5 (midpoint) → 100·0.01 − 5·(−1) = 6.
    assert!((at("IMPACT(0.9, -1, 1, 100, 2, 10, 0.2)", 0.0) - 6.0).abs() < 1e-12);
    assert_eq!(at("IMPACT(1.5, -1, 1, 100, 2, 10, 0.2)", 0.0), 0.0);
    // Separating fast: clamped at 0, never adhesive.
    assert_eq!(at("IMPACT(0.9, 100, 1, 100, 2, 10, 0.2)", 0.0), 0.0);
    // BISTOP above x2 = 1 at x = 1.1, ẋ = 1: −100·0.01 − STEP(1.1, 1, 0, 1.2, 10)·1 = −6.
    assert!((at("BISTOP(1.1, 1, 0, 1, 100, 2, 10, 0.2)", 0.0) + 6.0).abs() < 1e-12);
    assert_eq!(at("BISTOP(0.5, 1, 0, 1, 100, 2, 10, 0.2)", 0.0), 0.0);
    assert!((at("BISTOP(-0.1, -1, 0, 1, 100, 2, 10, 0.2)", 0.0) - 6.0).abs() < 1e-12);
}

#[test]
fn arithmetic_functions_and_degrees() {
    assert_eq!(at("-2**2 + 3*4 - 10/4", 0.0), -4.0 + 12.0 - 2.5);
    assert!((at("SIN(30D) + COS(60d)", 0.0) - 1.0).abs() < 1e-15);
    assert_eq!(at("ATAN2(1, 1)", 0.0), std::f64::consts::FRAC_PI_4);
    assert_eq!(at("MOD(-7, 3)", 0.0), -1.0);
    assert_eq!(
        at("SIGN(2, -1) + ABS(-3) + MAX(1, 2) + MIN(1, 2)", 0.0),
        4.0
    );
    assert_eq!(at("AINT(-2.7) + ANINT(2.5)", 0.0), 1.0);
    assert_eq!(at("SHF(TIME, 0, 2, PI, 0, 1)", 0.5), 3.0);
    let e = parse_expr("SQRT(TIME - 1)")
        .unwrap()
        .eval(&TimeOnly(0.0))
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "SQRT: argument -1.0 is out of range: must be >= 0"
    );
    let e = parse_expr("1 / TIME")
        .unwrap()
        .eval(&TimeOnly(0.0))
        .unwrap_err();
    assert!(matches!(e, EvalError::NotFinite(_)), "{e}");
}

/// Answers every measure with a fixed number and records the call.
struct Recorder {
    calls: RefCell<Vec<String>>,
}

impl Context for Recorder {
    fn time(&self) -> f64 {
        2.0
    }
    fn measure(&self, m: Measure, markers: &[u32]) -> Result<f64, EvalError> {
        self.calls
            .borrow_mut()
            .push(format!("{}{markers:?}", m.name()));
        Ok(match m {
            Measure::Dx => 3.0,
            Measure::Vr => -0.5,
            _ => 1.0,
        })
    }
    fn variable(&self, id: u32) -> Result<f64, EvalError> {
        self.calls.borrow_mut().push(format!("VARVAL{id}"));
        Ok(10.0)
    }
    fn element_force(&self, kind: ElementKind, args: [u32; 4]) -> Result<f64, EvalError> {
        self.calls
            .borrow_mut()
            .push(format!("{}{args:?}", kind.name()));
        Ok(0.0)
    }
}

#[test]
fn measures_go_to_the_context_with_their_markers() {
    let e = parse_expr("-100*(DX(0204, 0109, 0109) - 1) - 5*VR(204,109) + VARVAL(3) + WZ(1) + AZ(1,2) + dm(1,2) + JOINT(1,0,2,0) + TIME").unwrap();
    let ctx = Recorder {
        calls: RefCell::new(Vec::new()),
    };
    let v = e.eval(&ctx).unwrap();
    assert_eq!(v, -200.0 + 2.5 + 10.0 + 1.0 + 1.0 + 1.0 + 0.0 + 2.0);
    assert_eq!(
        ctx.calls.into_inner(),
        [
            "DX[204, 109, 109]",
            "VR[204, 109]",
            "VARVAL3",
            "WZ[1]",
            "AZ[1, 2]",
            "DM[1, 2]",
            "JOINT[1, 0, 2, 0]"
        ]
    );
    assert_eq!(e.marker_ids(), [204, 109, 109, 204, 109, 1, 1, 2, 1, 2]);
}

#[test]
fn unsupported_functions_are_errors_naming_them() {
    let e = parse_expr("SENVAL(0201)").unwrap_err();
    assert_eq!(
        (e.offset, e.to_string().as_str()),
        (0, "unsupported function SENVAL")
    );
    let e = parse_expr("2 * CHEBY(TIME, 0, 1)").unwrap_err();
    assert_eq!(
        (e.offset, e.to_string().as_str()),
        (4, "unsupported function CHEBY")
    );
    let e = parse_expr("3 * SPEED").unwrap_err();
    assert_eq!(
        e.to_string(),
        "unknown name SPEED (known: TIME, PI, DTOR, RTOD)"
    );
}

#[test]
fn a_motion_with_an_unsupported_function_fails_the_check_at_its_column() {
    let text = "t\nPART/1, GROUND\nMARKER/1, PART = 1\nPART/2, MASS = 1, CM = 2, IP = 1, 1, 1\nMARKER/2, PART = 2\n\
JOINT/1, REVOLUTE, I = 2, J = 1\nMOTION/1, JOINT = 1\n, FUNCTION = 2 * POLY(TIME, 0, 1)\nEND\n";
    let loaded = crate::inline("motion.adm", text);
    assert_eq!(
        crate::errors(&loaded),
        ["data/motion.adm:8:18: error: MOTION/1: FUNCTION: unsupported function POLY"]
    );
    // Measures are not allowed in MOTION functions (Adams: time only).
    let text = text.replace("2 * POLY(TIME, 0, 1)", "DX(2, 1)");
    let loaded = crate::inline("motion.adm", &text);
    assert_eq!(
        crate::errors(&loaded),
        ["data/motion.adm:8:14: error: MOTION/1: FUNCTION must depend on TIME only"]
    );
}
