//! The step-by-step API: stop times, dense output, roll-back and retry (contact prediction),
//! the limits HMAX/KMAX/HMIN, and failures with their diagnosis.

use crate::bdf::reference::{Linear, Robertson};
use crate::bdf::{Bdf, FailureCause, IntegratorError, IntegratorSettings};
use crate::{DaeSystem, EvaluationError, VariableKind};
use nalgebra::{DMatrix, DVector};

fn decay(settings: IntegratorSettings) -> (Linear, Bdf) {
    let system = Linear { lambda: -1.0 };
    let one = DVector::from_element(1, 1.0);
    let bdf = Bdf::new(&system, 0.0, one.clone(), -one, settings).unwrap();
    (system, bdf)
}

#[test]
fn steps_land_exactly_on_stop_times_and_dense_output_is_accurate() {
    let settings = IntegratorSettings {
        error: 1e-8,
        ..IntegratorSettings::default()
    };
    let (mut system, mut bdf) = decay(settings);
    let (mut worst_dense, mut worst_dense_yp, mut worst_step) = (0.0_f64, 0.0_f64, 0.0_f64);
    for output in 1..=10 {
        let stop = 0.3 * output as f64;
        bdf.set_stop_time(Some(stop)).unwrap();
        while bdf.t() < stop {
            bdf.step(&mut system).unwrap();
            worst_step = worst_step.max((bdf.y()[0] - (-bdf.t()).exp()).abs());
            for f in [0.1, 0.5, 0.9] {
                let t = bdf.t_previous() + f * (bdf.t() - bdf.t_previous());
                let (y, yp) = bdf.interpolate(t).unwrap();
                worst_dense = worst_dense.max((y[0] - (-t).exp()).abs());
                worst_dense_yp = worst_dense_yp.max((yp[0] + (-t).exp()).abs());
            }
        }
        assert_eq!(bdf.t(), stop);
    }
    eprintln!(
        "dense output: y {worst_dense:.2e} (steps {worst_step:.2e}), y' {worst_dense_yp:.2e}"
    );
    // The global error stays within 30× ERROR, and the interpolant between steps is as
    // accurate as the steps themselves.
    assert!(worst_step < 30.0 * 1e-8, "{worst_step:e}");
    assert!(
        worst_dense < 1.5 * worst_step,
        "{worst_dense:e} vs {worst_step:e}"
    );
    // The derivative of the interpolant carries the Newton error divided by the step, about
    // ERROR/h with h ≥ 1e-3 here.
    assert!(worst_dense_yp < 1e-5, "{worst_dense_yp:e}");
    assert!(matches!(
        bdf.interpolate(bdf.t() + 1.0),
        Err(IntegratorError::OutsideLastStep { .. })
    ));
    assert!(matches!(
        bdf.set_stop_time(Some(bdf.t() - 1.0)),
        Err(IntegratorError::InvalidTarget {
            argument: "stop time",
            ..
        })
    ));
}

#[test]
fn hmax_and_kmax_are_honoured() {
    let settings = IntegratorSettings {
        error: 1e-6,
        hmax: Some(0.05),
        kmax: 2,
        ..IntegratorSettings::default()
    };
    let (mut system, mut bdf) = decay(settings);
    bdf.set_stop_time(Some(3.0)).unwrap();
    while bdf.t() < 3.0 {
        bdf.step(&mut system).unwrap();
        assert!(bdf.t() - bdf.t_previous() <= 0.05 * (1.0 + 1e-12));
        assert!(bdf.last_order() <= 2);
    }
    // A stop just beyond HMAX is reached in two steps, never one longer than HMAX.
    bdf.set_stop_time(Some(3.0 + 0.0502)).unwrap();
    while bdf.t() < 3.0502 {
        bdf.step(&mut system).unwrap();
        assert!(bdf.t() - bdf.t_previous() <= 0.05 * (1.0 + 1e-12));
    }
    assert!(
        bdf.restart(-1.0)
            .unwrap_err()
            .to_string()
            .contains("restart step = -1.0")
    );
    let stats = bdf.stats();
    assert_eq!(stats.steps_by_order[3..].iter().sum::<u64>(), 0);
    assert!(stats.steps_by_order[2] > 0);
    assert_eq!(stats.steps_by_order.iter().sum::<u64>(), stats.steps);
}

/// A ball of unit mass dropped from height 1 onto a floor spring: `z′ = v`,
/// `v′ = −g + k·max(0, −z)`.
struct Ball {
    stiffness: f64,
}
const G: f64 = 9.81;

impl DaeSystem for Ball {
    fn size(&self) -> usize {
        2
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![VariableKind::Differential; 2]
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        out[0] = yp[0] - y[1];
        out[1] = yp[1] + G - self.stiffness * (-y[0]).max(0.0);
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        out[(0, 0)] = c;
        out[(0, 1)] = -1.0;
        out[(1, 0)] = if y[0] < 0.0 { self.stiffness } else { 0.0 };
        out[(1, 1)] = c;
        Ok(())
    }
}

#[test]
fn contact_onset_is_located_by_rejecting_and_retrying_at_order_1() {
    let mut ball = Ball { stiffness: 1e6 };
    let settings = IntegratorSettings {
        error: 1e-6,
        ..IntegratorSettings::default()
    };
    let y0 = DVector::from_vec(vec![1.0, 0.0]);
    let yp0 = DVector::from_vec(vec![0.0, -G]);
    let mut bdf = Bdf::new(&ball, 0.0, y0, yp0, settings).unwrap();
    bdf.set_stop_time(Some(0.6)).unwrap();
    let onset_exact = (2.0 / G).sqrt();
    let tolerance = 1e-9; // penetration accepted at the onset step
    let (mut in_contact, mut retries, mut onset) = (false, 0, None);
    let mut iterations = 0;
    while bdf.t() < 0.6 {
        iterations += 1;
        assert!(iterations < 10_000, "the predictor loop does not end");
        bdf.step(&mut ball).unwrap();
        let (z, v) = (bdf.y()[0], bdf.y()[1]);
        if !in_contact && z < 0.0 {
            // SPEC §8: t_c = t − δ/δ̇ (δ = −z, δ̇ = −v), retried until the penetration is small;
            // at most 8 retries per contact (the guard against the endless loop of
            // solver-notes §1.2), each a shorter step from the same start point.
            let mut penetration = -z;
            let (mut t_end, mut rate) = (bdf.t(), -v);
            while penetration > tolerance && retries < 8 {
                let t_c = t_end - penetration / rate;
                let target = t_c + 1e-3 * tolerance / rate.max(1e-12) + 4.0 * f64::EPSILON * t_c;
                bdf.reject_last_step_and_retry_to(&mut ball, target)
                    .unwrap();
                retries += 1;
                assert_eq!(bdf.last_order(), 1, "the retry restarts at order 1");
                assert_eq!(bdf.t(), target);
                penetration = -bdf.y()[0];
                (t_end, rate) = (bdf.t(), -bdf.y()[1]);
            }
            in_contact = true;
            bdf.request_newton_matrix();
            onset = Some((bdf.t(), penetration));
        }
    }
    let (t_onset, penetration) = onset.unwrap();
    eprintln!(
        "onset {t_onset} (exact {onset_exact}), penetration {penetration:e}, {retries} retries, {:?}",
        bdf.stats()
    );
    assert!(
        penetration.abs() <= tolerance,
        "penetration {penetration:e}"
    );
    // The located onset is the free-fall time to within the penetration over the speed.
    assert!(
        (t_onset - onset_exact).abs() < 1e-8,
        "onset {t_onset} vs {onset_exact}"
    );
    assert!(retries <= 4, "{retries} retries");
    assert_eq!(bdf.stats().rejected_by_caller, retries);
    // The ball has bounced: moving up at the end.
    assert!(bdf.y()[1] > 0.0);
}

#[test]
fn rejecting_needs_an_accepted_step_and_a_later_target() {
    let (mut system, mut bdf) = decay(IntegratorSettings::default());
    bdf.set_stop_time(Some(1.0)).unwrap();
    assert!(matches!(
        bdf.reject_last_step_and_retry_to(&mut system, 0.5),
        Err(IntegratorError::NothingToReject)
    ));
    bdf.step(&mut system).unwrap();
    let t0 = bdf.t_previous();
    assert!(matches!(
        bdf.reject_last_step_and_retry_to(&mut system, t0),
        Err(IntegratorError::InvalidTarget {
            argument: "retry target",
            ..
        })
    ));
    // Still possible after a refused target.
    let target = t0 + 1e-4;
    assert_eq!(
        bdf.reject_last_step_and_retry_to(&mut system, target)
            .unwrap(),
        target
    );
    assert!((bdf.y()[0] - (-target).exp()).abs() < 1e-6);
}

#[test]
fn a_stop_time_reached_by_a_rolled_back_step_is_kept() {
    let settings = IntegratorSettings {
        hinit: Some(0.01),
        ..IntegratorSettings::default()
    };
    let (mut system, mut bdf) = decay(settings);
    bdf.set_stop_time(Some(0.01)).unwrap();
    assert_eq!(bdf.step(&mut system).unwrap(), 0.01);
    assert_eq!(
        bdf.reject_last_step_and_retry_to(&mut system, 0.004)
            .unwrap(),
        0.004
    );
    // Stepping on lands on 0.01 again.
    while bdf.t() < 0.01 {
        bdf.step(&mut system).unwrap();
    }
    assert_eq!(bdf.t(), 0.01);
}

/// `y′ = y²`, `y(0) = 1`: the solution 1/(1 − t) blows up at t = 1.
struct BlowUp;
impl DaeSystem for BlowUp {
    fn size(&self) -> usize {
        1
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![VariableKind::Differential]
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        out[0] = yp[0] - y[0] * y[0];
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        out[(0, 0)] = c - 2.0 * y[0];
        Ok(())
    }
}

#[test]
fn a_blow_up_stops_with_a_diagnosis_near_the_singularity() {
    let mut system = BlowUp;
    let one = DVector::from_element(1, 1.0);
    let settings = IntegratorSettings {
        error: 1e-6,
        ..IntegratorSettings::default()
    };
    let mut bdf = Bdf::new(&system, 0.0, one.clone(), one, settings).unwrap();
    bdf.set_stop_time(Some(2.0)).unwrap();
    let error = loop {
        match bdf.step(&mut system) {
            Ok(_) => assert!(bdf.y()[0].is_finite()),
            Err(e) => break e,
        }
    };
    let message = error.to_string();
    eprintln!("{message}");
    let t = match &error {
        IntegratorError::StepSizeTooSmall { t, .. }
        | IntegratorError::RepeatedFailures { t, .. } => *t,
        other => panic!("unexpected {other:?}"),
    };
    assert!(t > 0.99 && t < 1.0, "stopped at {t}");
    assert!(
        message.contains("y[0]") && message.contains("remedies"),
        "{message}"
    );
    // The last accepted point is kept and finite.
    assert_eq!(bdf.t(), t);
    assert!(bdf.y()[0].is_finite());
}

/// y′ = −y whose evaluation fails from t = 0.5 on, as a contact query might.
struct FailsLate;
impl DaeSystem for FailsLate {
    fn size(&self) -> usize {
        1
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![VariableKind::Differential]
    }
    fn residual(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        if t > 0.5 {
            return Err(EvaluationError {
                element: "CONTACT/3".into(),
                message: "query failed".into(),
                fatal: false,
            });
        }
        out[0] = yp[0] + y[0];
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        _y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        out[(0, 0)] = c + 1.0;
        Ok(())
    }
}

#[test]
fn an_evaluation_error_is_reported_with_its_element() {
    let mut system = FailsLate;
    let one = DVector::from_element(1, 1.0);
    let mut bdf = Bdf::new(
        &system,
        0.0,
        one.clone(),
        -one,
        IntegratorSettings::default(),
    )
    .unwrap();
    bdf.set_stop_time(Some(1.0)).unwrap();
    let error = loop {
        if let Err(e) = bdf.step(&mut system) {
            break e;
        }
    };
    let message = error.to_string();
    assert!(message.contains("CONTACT/3: query failed"), "{message}");
    assert!(matches!(
        error,
        IntegratorError::RepeatedFailures {
            cause: FailureCause::Evaluation(_),
            ..
        } | IntegratorError::StepSizeTooSmall {
            cause: FailureCause::Evaluation(_),
            ..
        }
    ));
    assert!(bdf.t() <= 0.5);
    assert!(bdf.stats().rejected_evaluation >= 1);
}

#[test]
fn hmin_too_large_for_a_stiff_transient_is_an_error() {
    let mut system = Robertson { as_dae: false };
    let y0 = DVector::from_vec(vec![1.0, 0.0, 0.0]);
    let yp0 = DVector::from_vec(vec![-0.04, 0.04, 0.0]);
    let settings = IntegratorSettings {
        error: 1e-6,
        hmin: Some(1e-2),
        ..IntegratorSettings::default()
    };
    let mut bdf = Bdf::new(&system, 0.0, y0, yp0, settings).unwrap();
    bdf.set_stop_time(Some(10.0)).unwrap();
    let error = loop {
        if let Err(e) = bdf.step(&mut system) {
            break e;
        }
    };
    assert!(
        matches!(error, IntegratorError::StepSizeTooSmall { hmin, .. } if hmin == 1e-2),
        "{error}"
    );
    assert!(error.to_string().contains("HMIN = 1.000e-2"), "{error}");
}

#[test]
fn bad_initial_state_and_settings_are_typed_errors() {
    let system = Linear { lambda: -1.0 };
    let two = DVector::from_element(2, 1.0);
    let one = DVector::from_element(1, 1.0);
    let e = Bdf::new(
        &system,
        0.0,
        two,
        one.clone(),
        IntegratorSettings::default(),
    )
    .err()
    .unwrap();
    assert!(e.to_string().contains("y0 has length 2"), "{e}");
    let nan = DVector::from_element(1, f64::NAN);
    let e = Bdf::new(
        &system,
        0.0,
        one.clone(),
        nan,
        IntegratorSettings::default(),
    )
    .err()
    .unwrap();
    assert!(e.to_string().contains("yp0[0] = NaN"), "{e}");
    let bad = IntegratorSettings {
        kmax: 9,
        ..IntegratorSettings::default()
    };
    let e = Bdf::new(&system, 0.0, one.clone(), one.clone(), bad)
        .err()
        .unwrap();
    assert!(e.to_string().contains("KMAX = 9"), "{e}");
    // No time scale at all: no HINIT, HMAX, stop time, and y′0 = 0.
    let mut system = Linear { lambda: 0.0 };
    let mut bdf = Bdf::new(
        &system,
        0.0,
        one,
        DVector::zeros(1),
        IntegratorSettings::default(),
    )
    .unwrap();
    assert!(matches!(
        bdf.step(&mut system),
        Err(IntegratorError::NoInitialStep)
    ));
}

#[test]
fn a_consistent_start_is_computed_for_index_1_systems() {
    // Robertson as a DAE, started with a wrong algebraic y3 and y′ = 0.
    let mut system = Robertson { as_dae: true };
    let y0 = DVector::from_vec(vec![0.9, 0.1, 0.5]);
    let mut bdf = Bdf::new(
        &system,
        0.0,
        y0,
        DVector::zeros(3),
        IntegratorSettings::default(),
    )
    .unwrap();
    bdf.make_consistent(&mut system).unwrap();
    let (y, yp) = (bdf.y().clone(), bdf.yp().clone());
    // Closed form: y3 = 1 − y1 − y2 = 0, then y1′ = −0.04·y1, y2′ = 0.04·y1 − 3e7·y2².
    assert!(y[2].abs() < 1e-12, "y3 = {}", y[2]);
    assert!((yp[0] + 0.04 * 0.9).abs() < 1e-12, "y1' = {}", yp[0]);
    assert!(
        (yp[1] - (0.04 * 0.9 - 3e7 * 0.01)).abs() < 1e-12 * 3e5,
        "y2' = {}",
        yp[1]
    );
    // Twice is an error once stepping has begun.
    bdf.set_stop_time(Some(1.0)).unwrap();
    bdf.step(&mut system).unwrap();
    assert!(matches!(
        bdf.make_consistent(&mut system),
        Err(IntegratorError::InconsistentStart { .. })
    ));
}

#[test]
fn a_consistent_start_is_refused_for_index_3_systems() {
    use crate::bdf::reference::Pendulum;
    let mut pendulum = Pendulum {
        mass: 1.0,
        length: 1.0,
        gravity: 9.81,
    };
    let (y0, yp0) = pendulum.at_rest(0.5);
    let mut bdf = Bdf::new(&pendulum, 0.0, y0, yp0, IntegratorSettings::default()).unwrap();
    let error = bdf.make_consistent(&mut pendulum).unwrap_err();
    assert!(
        error.to_string().contains("y[2] has DAE index > 1"),
        "{error}"
    );
}

/// `y′ = −y` in units where `y` is of size `scale`, with the matching absolute scale.
struct ScaledDecay {
    scale: f64,
}
impl DaeSystem for ScaledDecay {
    fn size(&self) -> usize {
        1
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![VariableKind::Differential]
    }
    fn absolute_scales(&self) -> Vec<f64> {
        vec![self.scale]
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        out[0] = yp[0] + y[0];
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        _y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        out[(0, 0)] = c + 1.0;
        Ok(())
    }
}

#[test]
fn the_same_model_in_other_units_takes_the_same_steps() {
    let run = |scale: f64| {
        let mut system = ScaledDecay { scale };
        let y0 = DVector::from_element(1, scale);
        let settings = IntegratorSettings {
            error: 1e-6,
            ..IntegratorSettings::default()
        };
        let mut bdf = Bdf::new(&system, 0.0, y0.clone(), -y0, settings).unwrap();
        bdf.set_stop_time(Some(5.0)).unwrap();
        while bdf.t() < 5.0 {
            bdf.step(&mut system).unwrap();
        }
        (bdf.stats().steps, bdf.y()[0] / scale)
    };
    let (reference_steps, reference_y) = run(1.0);
    for scale in [1e-6, 1e6] {
        let (steps, y) = run(scale);
        assert_eq!(steps, reference_steps, "scale {scale}");
        assert!(
            (y - reference_y).abs() < 1e-12,
            "scale {scale}: {y} vs {reference_y}"
        );
    }
    let e = Bdf::new(
        &ScaledDecay { scale: 0.0 },
        0.0,
        DVector::zeros(1),
        DVector::zeros(1),
        IntegratorSettings::default(),
    )
    .err()
    .unwrap();
    assert!(e.to_string().contains("absolute_scales()[0] = 0.0"), "{e}");
}
