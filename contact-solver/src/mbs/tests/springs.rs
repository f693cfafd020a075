//! The spring-dampers against closed forms and their partials against central differences.

use super::*;
use nalgebra::DMatrix;

/// Central-difference partials in the force-element layout (an oracle independent of the
/// product's forward-difference fallback).
fn central_partials(element: &dyn ForceElement, states: &[PartState]) -> DMatrix<f64> {
    let parts = element.parts().to_vec();
    let mut out = DMatrix::zeros(6 * parts.len(), 12 * parts.len());
    let h = 1e-6;
    for (slot, part) in parts.iter().enumerate() {
        for column in 0..12 {
            let mut loads = [
                vec![Load::default(); parts.len()],
                vec![Load::default(); parts.len()],
            ];
            for (k, sign) in [1.0, -1.0].into_iter().enumerate() {
                let mut perturbed = states.to_vec();
                let state = &mut perturbed[part.0];
                let axis = Vector3::ith(column % 3, sign * h);
                match column / 3 {
                    0 => state.pose_w.translation.vector += axis,
                    1 => {
                        state.pose_w.rotation =
                            UnitQuaternion::from_scaled_axis(axis) * state.pose_w.rotation
                    }
                    2 => state.velocity_w += axis,
                    _ => state.angular_velocity_w += axis,
                }
                element
                    .evaluate(0.0, &StateView::new(&perturbed), &mut loads[k])
                    .unwrap();
            }
            for row_slot in 0..parts.len() {
                let df = (loads[0][row_slot].force_w - loads[1][row_slot].force_w) / (2.0 * h);
                let dt = (loads[0][row_slot].torque_w - loads[1][row_slot].torque_w) / (2.0 * h);
                for i in 0..3 {
                    out[(6 * row_slot + i, 12 * slot + column)] = df[i];
                    out[(6 * row_slot + 3 + i, 12 * slot + column)] = dt[i];
                }
            }
        }
    }
    out
}

fn random_states(rng: &mut Rng) -> Vec<PartState> {
    let mut states = vec![PartState::GROUND];
    for _ in 0..2 {
        states.push(PartState {
            pose_w: rng.pose(1.0),
            velocity_w: rng.vector(1.0),
            angular_velocity_w: rng.vector(2.0),
        });
    }
    states
}

#[test]
fn translational_spring_force_is_hookes_law_along_the_line() {
    // Point I at (2, 0, 0) on part 1 (at rest at the origin), point J at the world origin:
    // stretched by 2 − 0.5, moving apart at 3 m/s.
    let params = SpringParams {
        stiffness: 100.0,
        damping: 4.0,
        free_length: 0.5,
        preload: 7.0,
    };
    let spring = TranslationalSpringDamper::new(
        "SPRING/1",
        PartId(1),
        Vector3::new(2.0, 0.0, 0.0),
        PartId::GROUND,
        Vector3::zeros(),
        params,
    )
    .unwrap();
    let moving = PartState {
        pose_w: Isometry3::identity(),
        velocity_w: Vector3::new(3.0, 0.0, 0.0),
        angular_velocity_w: Vector3::zeros(),
    };
    let states = [PartState::GROUND, moving];
    let mut loads = [Load::default(); 2];
    spring
        .evaluate(0.0, &StateView::new(&states), &mut loads)
        .unwrap();
    let expected = -(100.0 * 1.5 + 4.0 * 3.0 - 7.0);
    assert!((loads[0].force_w - Vector3::new(expected, 0.0, 0.0)).norm() < 1e-12);
    assert!(
        loads[0].torque_w.norm() < 1e-12,
        "force along the lever arm has no moment"
    );
    assert!((loads[1].force_w + loads[0].force_w).norm() < 1e-12);
}

#[test]
fn translational_spring_partials_match_central_differences() {
    let mut rng = Rng::new(77);
    let params = SpringParams {
        stiffness: 30.0,
        damping: 2.0,
        free_length: 0.3,
        preload: 1.0,
    };
    for _ in 0..3 {
        let spring = TranslationalSpringDamper::new(
            "SPRING/1",
            PartId(1),
            rng.vector(0.5),
            PartId(2),
            rng.vector(0.5),
            params,
        )
        .unwrap();
        let states = random_states(&mut rng);
        let analytic = spring
            .partials(0.0, &StateView::new(&states))
            .unwrap()
            .unwrap();
        let difference = central_partials(&spring, &states);
        let error = (&analytic - &difference).amax() / difference.amax();
        assert!(error < 1e-7, "relative error {error:e}");
    }
}

#[test]
fn rotational_spring_torque_is_linear_in_the_angle() {
    // Part 1 turned 0.3 rad about world z, spinning at 2 rad/s about z; markers aligned with
    // their parts: T = −k(0.3 − 0.1) − c·2 + T₀ about +z.
    let params = SpringParams {
        stiffness: 10.0,
        damping: 0.5,
        free_length: 0.1,
        preload: 0.25,
    };
    let spring = RotationalSpringDamper::new(
        "SPRING/2",
        PartId(1),
        Isometry3::identity(),
        PartId::GROUND,
        Isometry3::identity(),
        params,
    )
    .unwrap();
    let moving = PartState {
        pose_w: Isometry3::rotation(Vector3::new(0.0, 0.0, 0.3)),
        velocity_w: Vector3::zeros(),
        angular_velocity_w: Vector3::new(0.0, 0.0, 2.0),
    };
    let mut loads = [Load::default(); 2];
    spring
        .evaluate(
            0.0,
            &StateView::new(&[PartState::GROUND, moving]),
            &mut loads,
        )
        .unwrap();
    let expected = -10.0 * 0.2 - 0.5 * 2.0 + 0.25;
    assert!((loads[0].torque_w - Vector3::new(0.0, 0.0, expected)).norm() < 1e-12);
    assert!((loads[1].torque_w + loads[0].torque_w).norm() < 1e-12);
}

#[test]
fn difference_fallback_matches_central_differences() {
    // The rotational spring has no analytic partials: the system's forward difference must
    // agree with the central-difference oracle to about √ε relative.
    let mut rng = Rng::new(91);
    let params = SpringParams {
        stiffness: 10.0,
        damping: 0.5,
        free_length: 0.1,
        preload: 0.25,
    };
    let spring = RotationalSpringDamper::new(
        "SPRING/2",
        PartId(1),
        rng.pose(0.4),
        PartId(2),
        rng.pose(0.4),
        params,
    )
    .unwrap();
    let states = random_states(&mut rng);
    let forward = difference_partials(&spring, 0.0, &states, 1.0).unwrap();
    let central = central_partials(&spring, &states);
    let error = (&forward - &central).amax() / central.amax();
    assert!(error < 1e-6, "relative error {error:e}");
}

/// An element that records the times of accepted steps and where its part was.
struct Recorder {
    parts: [PartId; 1],
    accepted: Arc<std::sync::Mutex<Vec<(f64, f64)>>>,
}

impl ForceElement for Recorder {
    fn name(&self) -> &str {
        "RECORDER/1"
    }
    fn parts(&self) -> &[PartId] {
        &self.parts
    }
    fn evaluate(
        &self,
        _t: f64,
        _state: &StateView<'_>,
        loads: &mut [Load],
    ) -> Result<(), crate::dae::EvaluationError> {
        loads[0] = Load::default();
        Ok(())
    }
    fn step_accepted(&mut self, t: f64, state: &StateView<'_>) {
        let z = state.part(self.parts[0]).pose_w.translation.z;
        self.accepted.lock().unwrap().push((t, z));
    }
}

#[test]
fn accepted_steps_reach_force_elements_with_the_state() {
    use crate::dae::DaeSystem;
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let pose = Isometry3::translation(0.0, 0.0, 3.0);
    let part = builder
        .add_part(PartSpec::at_rest("PART/2", 1.0, Matrix3::identity(), pose))
        .unwrap();
    let accepted = Arc::new(std::sync::Mutex::new(Vec::new()));
    let recorder = Recorder {
        parts: [part],
        accepted: accepted.clone(),
    };
    builder.add_force(Box::new(recorder)).unwrap();
    let mut system = builder.build().unwrap();
    let start = system.compute_initial_state(0.0).unwrap();
    let mut out = DVector::zeros(system.size());
    system.residual(0.1, &start.y, &start.yp, &mut out).unwrap();
    system.step_accepted(0.25, &start.y, &start.yp);
    let mut moved = start.y.clone();
    moved[2] = 4.0;
    system.step_accepted(0.5, &moved, &start.yp);
    assert_eq!(*accepted.lock().unwrap(), vec![(0.25, 3.0), (0.5, 4.0)]);
}
