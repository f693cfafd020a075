//! Tests of [`super`]: the plan of command files.

use super::*;
use crate::dataset::read_str;
use std::path::Path;

fn plan(acf: &str, overrides: PlanOverrides) -> (Vec<AnalysisStep>, Vec<String>) {
    plan_with_dof(acf, overrides, None)
}

/// The plan of `acf`, the model having `dof` degrees of freedom (`None`: asking is an
/// error, the plan must not need them).
fn plan_with_dof(
    acf: &str,
    overrides: PlanOverrides,
    dof: Option<usize>,
) -> (Vec<AnalysisStep>, Vec<String>) {
    let loaded = read_str(
        "plan\nPART/1, GROUND\nEND\n",
        "plan.adm",
        Some((acf, Path::new("plan.acf"))),
    );
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let mut asked = |_: f64| Ok(dof.expect("the plan must not ask for the degrees of freedom"));
    plan_analyses(&loaded.model, overrides, &mut asked).unwrap()
}

#[test]
fn simulate_commands_become_analyses_in_order_with_the_settings_in_force() {
    let (steps, notes) = plan(
        "plan.adm\nplan\nSIMULATE/DYNAMICS, END = 1, DTOUT = 0.1\n\
         SIMULATE/DYNAMICS, DURATION = 1, DTOUT = 0.5\nEQUILIBRIUM/ MAXIT = 7, DYNAMIC\nSIMULATE/STATICS\n\
         SIMULATE/KINEMATICS, DURATION = 0.5, STEPS = 5\nSIMULATE/INITIAL_CONDITIONS\nSTOP\n",
        PlanOverrides::default(),
    );
    assert_eq!(steps.len(), 5, "{steps:?}");
    // Each SIMULATE/DYNAMICS keeps its own END and DTOUT.
    let spans: Vec<(f64, f64, f64)> = steps[..2]
        .iter()
        .map(|s| match *s {
            AnalysisStep::Dynamics {
                start,
                end,
                output_step,
                ..
            } => (start, end, output_step),
            ref other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(spans, [(0.0, 1.0, 0.1), (1.0, 2.0, 0.5)]);
    let AnalysisStep::Statics { t, settings } = steps[2] else {
        panic!("{:?}", steps[2]);
    };
    assert_eq!((t, settings.maxit, settings.dynamic), (2.0, 7, true));
    assert_eq!(
        steps[3],
        AnalysisStep::Kinematics {
            start: 2.0,
            end: 2.5,
            output_step: 0.1,
            transient: None,
        }
    );
    assert_eq!(steps[4], AnalysisStep::InitialConditions { t: 2.5 });
    assert!(!notes.iter().any(|n| n.contains("one span")), "{notes:?}");
}

/// Three SIMULATEs with output steps 0.01, 1e-6 and 1e-3 keep theirs.
#[test]
fn each_simulate_keeps_its_own_output_step() {
    let (steps, _) = plan(
        "plan.adm\nplan\nSIMULATE/DYNAMICS, END = 1, DTOUT = 0.01\n\
         SIMULATE/DYNAMICS, END = 1.00001, DTOUT = 1E-6\nSIMULATE/DYNAMICS, DURATION = 1, STEPS = 1000\nSTOP\n",
        PlanOverrides::default(),
    );
    let outputs: Vec<f64> = steps
        .iter()
        .map(|s| match *s {
            AnalysisStep::Dynamics { output_step, .. } => output_step,
            ref other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(outputs.len(), 3);
    assert_eq!(outputs[0], 0.01);
    assert_eq!(outputs[1], 1e-6);
    assert!((outputs[2] - 1e-3).abs() < 1e-15, "{outputs:?}");
}

#[test]
fn linear_runs_at_the_state_reached_so_far_and_ends_a_span() {
    let (steps, _) = plan(
        "plan.adm\nplan\nLINEAR/EIGENSOL\nSIMULATE/DYNAMICS, END = 1, DTOUT = 0.1\n\
         LIN/EIGEN, NODAMP\nSIMULATE/DYNAMICS, END = 2, DTOUT = 0.1\nSIMULATE/STATICS\nLINEAR/EIGENSOL\nSTOP\n",
        PlanOverrides::default(),
    );
    let names: Vec<&str> = steps.iter().map(AnalysisStep::name).collect();
    assert_eq!(
        names,
        [
            "LINEAR", "DYNAMICS", "LINEAR", "DYNAMICS", "STATICS", "LINEAR"
        ]
    );
    let undamped = LinearSettings { damping: false };
    assert_eq!(
        steps[0],
        AnalysisStep::Linear {
            t: 0.0,
            settings: LinearSettings::default()
        }
    );
    assert_eq!(
        steps[2],
        AnalysisStep::Linear {
            t: 1.0,
            settings: undamped
        }
    );
    assert!(matches!(steps[5], AnalysisStep::Linear { t: 2.0, .. }));
}

#[test]
fn end_overrides_the_last_timed_analysis_and_is_noted_when_unused() {
    let overrides = PlanOverrides {
        end: Some(3.0),
        ..PlanOverrides::default()
    };
    let (steps, _) = plan(
        "plan.adm\nplan\nSIMULATE/STATICS\nSIMULATE/DYNAMICS, END = 1, STEPS = 10\nSTOP\n",
        overrides,
    );
    let AnalysisStep::Dynamics {
        end, output_step, ..
    } = steps[1]
    else {
        panic!("{:?}", steps[1]);
    };
    assert_eq!((end, output_step), (3.0, 0.3));
    let (steps, notes) = plan("plan.adm\nplan\nSIMULATE/STATICS\nSTOP\n", overrides);
    assert_eq!(steps.len(), 1);
    assert!(
        notes.iter().any(|n| n.contains("--end is not used")),
        "{notes:?}"
    );
}

#[test]
fn transient_runs_kinematics_without_degrees_of_freedom_and_dynamics_with_them() {
    let acf = "plan.adm\nplan\nSIMULATE/TRANSIENT, END = 1, DTOUT = 0.1\nSTOP\n";
    let (steps, notes) = plan_with_dof(acf, PlanOverrides::default(), Some(0));
    let choice = TransientChoice {
        degrees_of_freedom: 0,
    };
    assert_eq!(
        steps,
        vec![AnalysisStep::Kinematics {
            start: 0.0,
            end: 1.0,
            output_step: 0.1,
            transient: Some(choice),
        }]
    );
    assert!(
        notes.iter().any(|n| n.contains("ran as KINEMATICS")),
        "{notes:?}"
    );
    let (steps, notes) = plan_with_dof(acf, PlanOverrides::default(), Some(2));
    assert_eq!(steps.len(), 1);
    assert_eq!(steps[0].name(), "DYNAMICS");
    assert_eq!(steps[0].transient().map(|c| c.degrees_of_freedom), Some(2));
    assert!(
        notes
            .iter()
            .any(|n| n.contains("ran as DYNAMICS: the model has 2 degrees of freedom")),
        "{notes:?}"
    );
    // A DYNAMICS followed by a TRANSIENT that chooses dynamics: two spans, the second
    // from where the first ends.
    let (steps, _) = plan_with_dof(
        "plan.adm\nplan\nSIMULATE/DYNAMICS, END = 1, DTOUT = 0.1\nSIMULATE/TRANSIENT, END = 2, DTOUT = 0.1\nSTOP\n",
        PlanOverrides::default(),
        Some(1),
    );
    assert_eq!(steps.len(), 2);
    assert!(matches!(
        steps[1],
        AnalysisStep::Dynamics {
            start: 1.0,
            end: 2.0,
            ..
        }
    ));
}
