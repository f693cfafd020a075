//! The analytic contact partials against an independent oracle: a central difference of the
//! element's loads, perturbing each part's `(r, θ, u, ω)` one coordinate at a time.
//!
//! Where the frozen geometry leaves a term out (the module docs name them), the test either
//! adds that term in closed form and asks for agreement to the difference's own accuracy, or
//! bounds it by its argued size.

use super::*;
use crate::contact_force::SharedContact;
use crate::mbs::{Load, PartId, PartState};
use contact_core::geometry::{Cuboid, Plane};
use contact_core::{
    ContactArgs, FrictionSwitch, Geometry, GeometryEngine, GeometryInstance, Units,
};
use nalgebra::{Isometry3, Translation3, UnitQuaternion};
use std::sync::Arc;

const RADIUS: f64 = 0.1;

/// Coulomb friction (μs 0.3, μd 0.2, vs 0.1, vd 1) when `friction`, off otherwise.
fn friction_args(friction: bool) -> ContactArgs {
    ContactArgs {
        coulomb_friction: friction.then_some(FrictionSwitch::On),
        mu_static: Some(0.3),
        mu_dynamic: Some(0.2),
        stiction_transition_velocity: Some(0.1),
        friction_transition_velocity: Some(1.0),
        ..ContactArgs::default()
    }
}

/// IMPACT, k 1e6, e 1.5, c 50, DMAX 1e-3 (the damping ramp is active at δ = 4e-4).
fn impact(friction: bool) -> ContactArgs {
    ContactArgs {
        impact: true,
        stiffness: Some(1e6),
        exponent: Some(1.5),
        damping: Some(50.0),
        dmax: Some(1e-3),
        ..friction_args(friction)
    }
}

/// POISSON, p 1e6, ε 0.6, transition velocity 0.1.
fn poisson(friction: bool, augmented: bool) -> ContactArgs {
    ContactArgs {
        poisson: true,
        penalty: Some(1e6),
        restitution_coefficient: Some(0.6),
        poisson_transition_velocity: Some(0.1),
        augmented_lagrangian: augmented,
        ..friction_args(friction)
    }
}

fn contact(
    i: GeometryInstance,
    j: GeometryInstance,
    parts: [usize; 2],
    args: ContactArgs,
) -> ContactForce {
    let pair = engine_exact::ExactEngine.prepare(&[i], &[j]).unwrap();
    let (params, _) = args.validate(&Units::MKS).unwrap();
    ContactForce::new(
        "CONTACT/1",
        PartId(parts[0]),
        PartId(parts[1]),
        pair,
        params,
        Analysis::Dynamics,
    )
    .unwrap()
}

fn part(position: [f64; 3], rotation: UnitQuaternion<f64>, u: [f64; 3], w: [f64; 3]) -> PartState {
    PartState {
        pose_w: Isometry3::from_parts(
            Translation3::new(position[0], position[1], position[2]),
            rotation,
        ),
        velocity_w: Vector3::from(u),
        angular_velocity_w: Vector3::from(w),
    }
}

/// The central difference of `element`'s loads in the partials layout (ground rows and
/// columns zero):
/// steps `h·ℓ` in position, `h` rad, `h·v` in velocity and `h` rad/s.
fn central_difference(
    element: &dyn ForceElement,
    states: &[PartState],
    length: f64,
) -> DMatrix<f64> {
    let parts = element.parts();
    let mut out = DMatrix::zeros(6 * parts.len(), 12 * parts.len());
    let h = 1e-6;
    let mut plus = vec![Load::default(); parts.len()];
    let mut minus = vec![Load::default(); parts.len()];
    for (slot, &id) in parts.iter().enumerate() {
        if id.is_ground() {
            continue;
        }
        for column in 0..12 {
            let (block, axis) = (column / 3, column % 3);
            let step = match block {
                0 => h * length,
                2 => h * states[id.0].velocity_w.norm().max(1.0),
                _ => h,
            };
            let mut loads = [&mut plus, &mut minus];
            for (sign, out_loads) in [1.0, -1.0].iter().zip(loads.iter_mut()) {
                let mut s = states.to_vec();
                let x = &mut s[id.0];
                let delta = sign * step;
                match block {
                    0 => x.pose_w.translation.vector[axis] += delta,
                    1 => {
                        x.pose_w.rotation =
                            UnitQuaternion::from_scaled_axis(Vector3::ith(axis, delta))
                                * x.pose_w.rotation;
                    }
                    2 => x.velocity_w[axis] += delta,
                    _ => x.angular_velocity_w[axis] += delta,
                }
                element
                    .evaluate(0.0, &StateView::new(&s), out_loads)
                    .unwrap();
            }
            for row in 0..parts.len() {
                let df = (plus[row].force_w - minus[row].force_w) / (2.0 * step);
                let dt = (plus[row].torque_w - minus[row].torque_w) / (2.0 * step);
                for i in 0..3 {
                    out[(6 * row + i, 12 * slot + column)] = df[i];
                    out[(6 * row + 3 + i, 12 * slot + column)] = dt[i];
                }
            }
        }
    }
    for (slot, id) in parts.iter().enumerate() {
        if id.is_ground() {
            out.rows_mut(6 * slot, 6).fill(0.0);
        }
    }
    out
}

/// `partials` without the ground's rows and columns, which the system does not use (the
/// ground's torque about the world origin has lever-arm terms the frozen geometry leaves out).
fn without_ground(element: &ContactForce, mut partials: DMatrix<f64>) -> DMatrix<f64> {
    for (slot, id) in element.parts().iter().enumerate() {
        if id.is_ground() {
            partials.columns_mut(12 * slot, 12).fill(0.0);
            partials.rows_mut(6 * slot, 6).fill(0.0);
        }
    }
    partials
}

/// The analytic partials without the ground's rows and columns.
fn analytic(element: &ContactForce, states: &[PartState], terms: GeometryTerms) -> DMatrix<f64> {
    let a = compute_contact_partials_with(element, 0.0, &StateView::new(states), terms)
        .expect("analytic partials")
        .unwrap();
    without_ground(element, a)
}

/// The largest error of `a` against `reference` per column block (3 columns), relative to the
/// reference's norm over that block's 3 columns and every row, floored at 1e-9 of the whole
/// reference (a block that vanishes in exact arithmetic, such as a sphere turning about its
/// centre, is then held to round-off).
fn worst_relative_error(a: &DMatrix<f64>, reference: &DMatrix<f64>) -> (f64, usize) {
    let floor = 1e-9 * reference.norm();
    let mut worst = (0.0, 0);
    for block in 0..reference.ncols() / 3 {
        let r = reference.columns(3 * block, 3);
        let scale = r.norm().max(floor);
        let e = (a.columns(3 * block, 3) - r).norm() / scale;
        if e > worst.0 {
            worst = (e, block);
        }
    }
    worst
}

fn sphere() -> GeometryInstance {
    GeometryInstance::new(Geometry::sphere(RADIUS).unwrap())
}

fn ground_plane() -> GeometryInstance {
    GeometryInstance::new(Geometry::Plane(Plane::unbounded()))
}

/// Ground (index 0) and the ball (index 1) at penetration `delta` of a ground plane.
fn ball_states(delta: f64, u: [f64; 3], w: [f64; 3]) -> Vec<PartState> {
    vec![
        PartState::GROUND,
        part(
            [0.01, -0.02, RADIUS - delta],
            UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5),
            u,
            w,
        ),
    ]
}

/// The geometric terms a sphere on a ground plane has and the frozen geometry leaves out, in
/// closed form (friction only): the lever arm `s = −(r − δ/2)·n` shortens by `½·n·δr`
/// (torque `−½·(n × F_t)·nᵀ`), and the area `A = π·(r² − (r − δ)²)` grows by `2π(r − δ)` per
/// unit δ (torque `∂T/∂A·2π(r − δ)·n·(−nᵀ)`; force `∂F_t/∂A·2π(r − δ)·(−nᵀ)` at the lever
/// arm `s`, where the patch spins as it slips).
fn sphere_plane_geometric_terms(element: &ContactForce, states: &[PartState]) -> DMatrix<f64> {
    let mut out = DMatrix::zeros(12, 24);
    let report = element.reports(0.0, &StateView::new(states)).unwrap()[0];
    let n = report.contact.normal_w;
    let (params, _) = element.laws();
    let FrictionModel::On(law) = &params.friction else {
        return out;
    };
    let s = &states[1];
    let spin = s.angular_velocity_w.dot(&n);
    let p = report.contact.midpoint_w().coords;
    let v = s.point_velocity_w(&p);
    let slip = v - n * n.dot(&v);
    let both = law.slip_and_spin(&slip, spin, report.normal_force, report.contact.area);
    let d = RADIUS - report.contact.penetration;
    let d_area = -2.0 * std::f64::consts::PI * d;
    let lever = -0.5 * n.cross(&report.friction_force_w) * n.transpose();
    let area = n * (both.torque.d_area * d_area) * n.transpose();
    let force = both.force_d_area * d_area * n.transpose();
    let arm = skew(&(p - s.pose_w.translation.vector));
    out.fixed_view_mut::<3, 3>(0, 0).copy_from(&force);
    out.fixed_view_mut::<3, 3>(3, 0)
        .copy_from(&(lever + area + arm * force));
    out
}

#[test]
fn a_sphere_on_a_plane_is_exact_without_friction_impact_and_poisson() {
    for args in [impact(false), poisson(false, false)] {
        let element = contact(sphere(), ground_plane(), [1, 0], args);
        // Approaching (IMPACT inside DMAX: the damping ramp's slope counts), and separating
        // within POISSON's blend.
        for (u, w) in [
            ([0.3, -0.2, -0.05], [2.0, -1.0, 3.0]),
            ([0.0, 0.1, 0.02], [0.0, 0.0, 1.0]),
        ] {
            let states = ball_states(4e-4, u, w);
            let a = analytic(&element, &states, GeometryTerms::ContactFrame);
            let fd = central_difference(&element, &states, RADIUS);
            let (e, block) = worst_relative_error(&a, &fd);
            assert!(e < 1e-6, "{e:e} in block {block}\n{a:.4e}\n{fd:.4e}");
        }
    }
}

#[test]
fn a_sphere_on_a_plane_sliding_and_spinning_is_exact_up_to_the_named_terms() {
    // Sliding (slip 0.05 in the stiction ramp, 0.4 in the falling branch) and spinning about
    // the normal (ω·R ≈ 0.03 inside vs): the force partials are exact; the torque about the
    // CM misses the lever-arm and area terms of `sphere_plane_geometric_terms`.
    for args in [impact(true), poisson(true, false)] {
        let element = contact(sphere(), ground_plane(), [1, 0], args);
        for u in [[0.05, 0.0, -0.05], [0.3, -0.25, -0.01]] {
            let states = ball_states(4e-4, u, [0.0, 0.0, 3.0]);
            let a = analytic(&element, &states, GeometryTerms::ContactFrame);
            let fd = central_difference(&element, &states, RADIUS);
            let named = sphere_plane_geometric_terms(&element, &states);
            let (e, block) = worst_relative_error(&(&a + &named), &fd);
            assert!(e < 1e-6, "{e:e} in block {block}\n{a:.4e}\n{fd:.4e}");
            // The named terms are small against the contact's own: lever ½·|F_t| against
            // ∂Fn/∂δ·μ·r, about δ/(2·e·r); the area term ∂T/∂A·2πr against ∂F_t/∂δ·r, of the
            // order R/r. Measured 4e-4 to 7e-4 of the position columns.
            let (without, _) = worst_relative_error(&a, &fd);
            assert!(without < 1e-2, "{without:e}");
        }
    }
}

#[test]
fn a_rolling_sphere_misses_only_the_contact_points_roll() {
    // With ω tangential the contact point's velocity `ω × s` changes as s shortens with δ:
    // `∂v_t/∂r = −½·(ω × n)·nᵀ`, left out; bounded by `½·|∂F_t/∂v_t|·|ω × n|` per unit
    // length in the force rows (and r times it in the torques).
    let element = contact(sphere(), ground_plane(), [1, 0], impact(true));
    let w = [4.0, -2.0, 0.0];
    let states = ball_states(4e-4, [0.2, 0.3, -0.02], w);
    let a = analytic(&element, &states, GeometryTerms::ContactFrame);
    let fd = central_difference(&element, &states, RADIUS);
    let named = sphere_plane_geometric_terms(&element, &states);
    let diff = &fd - (&a + &named);
    let report = element.reports(0.0, &StateView::new(&states)).unwrap()[0];
    let (params, _) = element.laws();
    let FrictionModel::On(law) = &params.friction else {
        unreachable!()
    };
    let v = states[1].point_velocity_w(&report.contact.midpoint_w().coords);
    let slip = v - report.contact.normal_w * report.contact.normal_w.dot(&v);
    let d_slip = law.force(&slip, report.normal_force).d_slip.norm();
    let bound = 0.5 * d_slip * Vector3::from(w).cross(&report.contact.normal_w).norm();
    let force_rows = diff.view((0, 0), (3, 3)).norm();
    assert!(force_rows <= 1.01 * bound, "{force_rows:e} vs {bound:e}");
    assert!(diff.columns(3, 9).norm() < 1e-6 * fd.columns(3, 9).norm());
}

/// Two balls, I (part 1) and J (part 2), with centres offset along `direction`.
fn two_balls(delta: f64, velocity: bool) -> (Vec<PartState>, Vector3<f64>, f64) {
    let n = Vector3::new(0.3, -0.4, 0.866).normalize();
    let r_j = 0.7 * RADIUS;
    let distance = RADIUS + r_j - delta;
    let c_j = Vector3::new(0.2, 0.1, -0.3);
    let c_i = c_j + n * distance;
    let rotation = UnitQuaternion::from_euler_angles(0.1, 0.2, 0.3);
    let (u_i, w_i, u_j, w_j) = if velocity {
        (
            [0.2, -0.1, 0.05],
            [1.0, 2.0, -3.0],
            [-0.1, 0.05, 0.2],
            [0.5, -1.0, 2.0],
        )
    } else {
        let approach = -0.05 * n;
        (
            [approach.x, approach.y, approach.z],
            [0.0; 3],
            [0.0; 3],
            [0.0; 3],
        )
    };
    let states = vec![
        PartState::GROUND,
        part([c_i.x, c_i.y, c_i.z], rotation, u_i, w_i),
        part([c_j.x, c_j.y, c_j.z], rotation.inverse(), u_j, w_j),
    ];
    (states, n, distance)
}

#[test]
fn two_spheres_miss_exactly_the_turning_normal() {
    // Moving along the normal without spin or friction, the one left-out term is the normal
    // turning with the centres: `∂F_I/∂c_I = ... + Fn·(I − n nᵀ)/D` (and minus it for c_J,
    // and for the force on J), the geometric stiffness.
    let j = GeometryInstance::new(Geometry::sphere(0.7 * RADIUS).unwrap());
    for args in [impact(false), poisson(false, false)] {
        let element = contact(sphere(), j.clone(), [1, 2], args);
        let (states, n, distance) = two_balls(4e-4, false);
        let a = analytic(&element, &states, GeometryTerms::ContactFrame);
        let fd = central_difference(&element, &states, RADIUS);
        let report = element.reports(0.0, &StateView::new(&states)).unwrap()[0];
        let geometric =
            (Matrix3::identity() - n * n.transpose()) * (report.normal_force / distance);
        let mut named = DMatrix::zeros(12, 24);
        named.fixed_view_mut::<3, 3>(0, 0).copy_from(&geometric);
        named.fixed_view_mut::<3, 3>(0, 12).copy_from(&(-geometric));
        named.fixed_view_mut::<3, 3>(6, 0).copy_from(&(-geometric));
        named.fixed_view_mut::<3, 3>(6, 12).copy_from(&geometric);
        let (e, block) = worst_relative_error(&(&a + &named), &fd);
        assert!(e < 1e-6, "{e:e} in block {block}");
        // Its size against the contact stiffness: Fn/D against ∂Fn/∂δ ≈ e·Fn/δ, δ/(e·D).
        let (without, _) = worst_relative_error(&a, &fd);
        assert!(without < 2.0 * 4e-4 / distance, "{without:e}");
    }
}

#[test]
fn two_spheres_sliding_and_spinning_are_within_the_geometric_bound() {
    // With every velocity and friction the left-out terms are the turning normal (Fn/D), the
    // roll of the contact point (ω·∂s, |∂F/∂v|·|ω|/2 per unit length) and the lever arms' and
    // area's change; each is bounded by the largest of those against the column's norm.
    let j = GeometryInstance::new(Geometry::sphere(0.7 * RADIUS).unwrap());
    for args in [impact(true), poisson(true, false)] {
        let element = contact(sphere(), j.clone(), [1, 2], args);
        let (states, _, _) = two_balls(4e-4, true);
        let a = analytic(&element, &states, GeometryTerms::ContactFrame);
        let fd = central_difference(&element, &states, RADIUS);
        // Velocity columns: exact (the frozen point is where the velocities are taken).
        for block in [2, 3, 6, 7] {
            let (a_b, fd_b) = (a.columns(3 * block, 3), fd.columns(3 * block, 3));
            let e = (a_b - fd_b).norm() / fd_b.norm();
            assert!(e < 1e-6, "block {block}: {e:e}");
        }
        // The turning normal alone is δ/(e·D) ≈ 2e-3 of the position columns; the roll of
        // the contact point adds |∂F/∂v|·|ω|·r/2 (measured 2.6e-3 and 7.6e-3 in all).
        let (e, block) = worst_relative_error(&a, &fd);
        assert!(e < 3e-2, "{e:e} in block {block}");
    }
}

#[test]
fn a_box_corner_on_a_plane_is_within_the_geometric_bound() {
    // A cube standing on one corner at depth h, tilted, sliding and spinning. The engine
    // measures δ along the normal through the intersection volume's centroid: for a corner,
    // by the similarity of its small tetrahedron, `δ = κ·h` with κ ≤ 1 set by the tilt (1
    // untilted). The frozen geometry takes `∂δ/∂h = 1`, so its normal stiffness is too high
    // by exactly `1/κ` (the safe side for a modified Newton), and the friction torque's area
    // (∝ h²) and the lever arms' change are left out. The velocity columns are exact.
    let cube = GeometryInstance::new(Geometry::Cuboid(
        Cuboid::centered(0.05, 0.05, 0.05).unwrap(),
    ));
    let element = contact(cube, ground_plane(), [1, 0], impact(true));
    // Corner (−1, −1, −1)·h lowest: the diagonal onto −z, then tilted (the corner stays
    // lowest below 35°).
    let diagonal = Vector3::new(-1.0, -1.0, -1.0).normalize();
    let depth = 4e-4;
    for tilt in [0.3, 0.02] {
        let rotation = UnitQuaternion::from_euler_angles(tilt, -0.5 * tilt, 0.0)
            * UnitQuaternion::rotation_between(&diagonal, &-Vector3::z()).unwrap();
        let corner: Vector3<f64> = rotation * (0.05 * Vector3::new(-1.0, -1.0, -1.0));
        let states = vec![
            PartState::GROUND,
            part(
                [0.0, 0.0, -corner.z - depth],
                rotation,
                [0.1, -0.05, -0.02],
                [0.3, 0.2, 1.5],
            ),
        ];
        let fd = central_difference(&element, &states, 0.1);
        let report = element.reports(0.0, &StateView::new(&states)).unwrap()[0];
        let kappa = report.contact.penetration / depth;
        assert!(kappa > 0.5 && kappa <= 1.0, "{kappa}");
        for terms in [GeometryTerms::ContactFrame, GeometryTerms::MaterialPoints] {
            let a = analytic(&element, &states, terms);
            for block in [2, 3] {
                let (a_b, fd_b) = (a.columns(3 * block, 3), fd.columns(3 * block, 3));
                let e = (a_b - fd_b).norm() / fd_b.norm();
                assert!(e < 1e-6, "{terms:?} block {block}: {e:e}");
            }
            let normal_stiffness = fd[(2, 2)] / a[(2, 2)];
            assert!(
                (normal_stiffness - kappa).abs() < 1e-4,
                "{terms:?}: {normal_stiffness} vs κ {kappa}"
            );
            let (e, block) = worst_relative_error(&a, &fd);
            assert!(e < 0.5, "{terms:?}: {e:e} in block {block}");
        }
    }
}

#[test]
fn the_augmented_lagrangian_force_is_exact_at_the_current_multipliers() {
    let element = contact(sphere(), ground_plane(), [1, 0], poisson(false, true));
    let m = element.multipliers().unwrap();
    // Build memory: a multiplier and some compression work, as a run would.
    m.corrector_converged(&[(4e-4, 1.0)]);
    m.step_accepted(&[(2e-4, 1.0, 150.0)]);
    m.step_accepted(&[(3e-4, 0.5, 380.0)]);
    assert!(m.memory(0).lambda > 0.0 && m.memory(0).compression_work > 0.0);
    // Compression, restitution, the blend, and the blend deeper than before.
    for (delta, rate) in [
        (2.5e-4, 0.5),
        (2.5e-4, -0.5),
        (2.5e-4, 0.02),
        (3.5e-4, -0.03),
    ] {
        let states = ball_states(delta, [0.0, 0.0, -rate], [0.0; 3]);
        let a = analytic(&element, &states, GeometryTerms::ContactFrame);
        let fd = central_difference(&element, &states, RADIUS);
        let (e, block) = worst_relative_error(&a, &fd);
        assert!(e < 1e-6, "δ {delta}, δ̇ {rate}: {e:e} in block {block}");
    }
}

#[test]
fn no_touch_gives_zero_partials_and_shared_contacts_forward_them() {
    let element = Arc::new(contact(sphere(), ground_plane(), [1, 0], impact(true)));
    let states = ball_states(-1e-3, [0.1, 0.0, -1.0], [1.0, 2.0, 3.0]);
    let a = analytic(&element, &states, GeometryTerms::ContactFrame);
    assert_eq!(a.norm(), 0.0);
    let shared = SharedContact(element.clone());
    let states = ball_states(4e-4, [0.1, 0.0, -0.1], [1.0, 2.0, 3.0]);
    let view = StateView::new(&states);
    let forwarded = shared.partials(0.0, &view).unwrap().unwrap();
    let direct = compute_contact_partials(&element, 0.0, &view)
        .unwrap()
        .unwrap();
    assert_eq!(forwarded, direct);
    assert!(direct.norm() > 0.0);
}

#[test]
fn a_face_on_a_plane_is_left_to_the_difference_and_a_ball_is_not() {
    // A box resting on its face: the patch (0.1 × 0.1) has ρ = A/(2π·δ) ≈ 4 m against a lever
    // arm of 0.05 m, so a frozen point would miss its tilt stiffness.
    let cube = GeometryInstance::new(Geometry::Cuboid(
        Cuboid::centered(0.05, 0.05, 0.05).unwrap(),
    ));
    let element = contact(cube, ground_plane(), [1, 0], impact(true));
    let states = vec![
        PartState::GROUND,
        part(
            [0.0, 0.0, 0.05 - 4e-4],
            UnitQuaternion::identity(),
            [0.0; 3],
            [0.0; 3],
        ),
    ];
    let view = StateView::new(&states);
    assert!(compute_contact_partials(&element, 0.0, &view).is_none());
    let ball = contact(sphere(), ground_plane(), [1, 0], impact(true));
    let states = ball_states(4e-4, [0.0; 3], [0.0; 3]);
    let report = ball.reports(0.0, &StateView::new(&states)).unwrap()[0];
    assert!(!is_extended(
        &report.contact,
        &[states[1].pose_w.translation.vector]
    ));
    assert!(compute_contact_partials(&ball, 0.0, &StateView::new(&states)).is_some());
}
