//! Force laws against closed forms and published values, derivatives against central
//! differences, continuity at every branch point.

use super::*;
use crate::Vector3;

/// Central difference of `f` at `x` with a step relative to the scale of `x`.
fn central(f: impl Fn(f64) -> f64, x: f64, scale: f64) -> f64 {
    let h = 1e-6 * scale;
    (f(x + h) - f(x - h)) / (2.0 * h)
}

/// |a − b| ≤ 1e-6 · max(|a|, |b|, floor).
fn assert_rel(a: f64, b: f64, floor: f64, what: &str) {
    let tol = 1e-6 * a.abs().max(b.abs()).max(floor);
    assert!(
        (a - b).abs() <= tol,
        "{what}: analytic {a:e} vs difference {b:e}"
    );
}

#[test]
fn step_matches_the_adams_worked_example() {
    // Adams View: STEP((2,3,3.5,4,5),3,0,4,1) = 0,0,0.5,1,1.
    let got: Vec<f64> = [2.0, 3.0, 3.5, 4.0, 5.0]
        .iter()
        .map(|&x| step(x, 3.0, 0.0, 4.0, 1.0).unwrap().value)
        .collect();
    assert_eq!(got, vec![0.0, 0.0, 0.5, 1.0, 1.0]);
}

#[test]
fn step_and_step5_match_their_polynomials_written_independently() {
    // STEP: h0 + a·(3D² − 2D³); STEP5: h0 + a·(10D³ − 15D⁴ + 6D⁵), here from −1 to 3 over [2, 6].
    for k in 1..40 {
        let x = 2.0 + 4.0 * k as f64 / 40.0;
        let d = (x - 2.0) / 4.0;
        let cubic = -1.0 + 4.0 * (3.0 * d.powi(2) - 2.0 * d.powi(3));
        let quintic = -1.0 + 4.0 * (10.0 * d.powi(3) - 15.0 * d.powi(4) + 6.0 * d.powi(5));
        assert!((step(x, 2.0, -1.0, 6.0, 3.0).unwrap().value - cubic).abs() < 1e-14);
        assert!((step5(x, 2.0, -1.0, 6.0, 3.0).unwrap().value - quintic).abs() < 1e-14);
    }
    // STEP5 at the Adams midpoint is exactly the mean.
    assert_eq!(step5(3.5, 3.0, 0.0, 4.0, 1.0).unwrap().value, 0.5);
}

#[test]
fn step_slopes_agree_with_central_differences_and_vanish_at_the_ends() {
    let s = Step::new(-0.5, 2.0, 1.5, -3.0).unwrap();
    for k in 1..50 {
        let x = -0.5 + 2.0 * k as f64 / 50.0;
        assert_rel(
            s.cubic(x).slope,
            central(|x| s.cubic(x).value, x, 1.0),
            1e-6,
            "STEP'",
        );
        assert_rel(
            s.quintic(x).slope,
            central(|x| s.quintic(x).value, x, 1.0),
            1e-6,
            "STEP5'",
        );
    }
    for x in [-0.5, 1.5, -7.0, 9.0] {
        assert_eq!(s.cubic(x).slope, 0.0);
        assert_eq!(s.quintic(x).slope, 0.0);
    }
}

#[test]
fn step_rejects_an_empty_interval() {
    let e = step(0.0, 1.0, 0.0, 1.0, 1.0).unwrap_err();
    assert_eq!(
        e.to_string(),
        "x1 = 1.0 is out of range: must be > x0 = 1.0"
    );
    assert!(step(0.0, f64::NAN, 0.0, 1.0, 1.0).is_err());
}

fn impact() -> ImpactLaw {
    ImpactLaw::from_params(ImpactParams {
        stiffness: 1e5,
        exponent: 2.2,
        damping: 10.0,
        max_penetration: 0.1,
    })
    .unwrap()
}

/// The named parameters build the same law as the positional ones, give it back, and are
/// validated the same way: the error names the argument and its value.
#[test]
fn named_parameters_are_the_positional_ones_by_name() {
    let law = impact();
    assert_eq!(law, ImpactLaw::new(1e5, 2.2, 10.0, 0.1).unwrap());
    assert_eq!(ImpactLaw::from_params(law.params()).unwrap(), law);
    let e = ImpactLaw::from_params(ImpactParams {
        max_penetration: -0.1,
        ..law.params()
    })
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "DMAX = -0.1 is out of range: must be finite and > 0"
    );
    let p = poisson(0.5);
    assert_eq!(p, PoissonLaw::new(1e6, 0.5, 1.0).unwrap());
    assert_eq!(PoissonLaw::from_params(p.params()).unwrap(), p);
    let c = coulomb();
    assert_eq!(c, CoulombFriction::new(0.3, 0.1, 0.1, 1.0).unwrap());
    assert_eq!(CoulombFriction::from_params(c.params()).unwrap(), c);
    // The two velocities exchanged: refused, naming the one out of order.
    let e = CoulombFriction::from_params(CoulombParams {
        stiction_velocity: 1.0,
        friction_velocity: 0.1,
        ..c.params()
    })
    .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("FRICTION_TRANSITION_VELOCITY = 0.1 is out of range"),
        "{e}"
    );
}

#[test]
fn impact_is_zero_without_penetration_and_the_spring_at_rest() {
    let law = impact();
    assert_eq!(law.force(0.0, 5.0), NormalForce::ZERO);
    assert_eq!(law.force(-1.0, 5.0), NormalForce::ZERO);
    let f = law.force(0.02, 0.0);
    assert!((f.force - 1e5 * 0.02_f64.powf(2.2)).abs() < 1e-12 * f.force);
}

#[test]
fn impact_damping_ramps_from_zero_to_full_at_dmax() {
    let law = impact();
    let rate = 7.0;
    for (delta, fraction) in [(0.025, 0.15625), (0.05, 0.5), (0.1, 1.0), (0.3, 1.0)] {
        // STEP(δ, 0, 0, 0.1, 10) = 10·(3D² − 2D³) with D = δ/0.1: 0.15625 of c at D = 0.25.
        let f = law.force(delta, rate);
        let spring = 1e5 * f64::powf(delta, 2.2);
        assert!(
            (f.force - (spring + fraction * 10.0 * rate)).abs() < 1e-10 * f.force,
            "δ = {delta}"
        );
        assert!((f.d_rate - fraction * 10.0).abs() < 1e-12);
    }
}

#[test]
fn impact_clamps_at_zero_while_separating_fast() {
    let law = impact();
    // Spring 1e5·0.1^2.2 ≈ 631; full damping 10 · (−100) = −1000: clamped.
    let f = law.force(0.1, -100.0);
    assert_eq!(f, NormalForce::ZERO);
    // Just before the clamp the force is small and positive, and continuous into it.
    let spring = 1e5 * 0.1_f64.powf(2.2);
    let at = -spring / 10.0;
    assert!(law.force(0.1, at + 1e-9).force < 1e-7);
    assert_eq!(law.force(0.1, at - 1e-9).force, 0.0);
}

#[test]
fn impact_partials_agree_with_central_differences() {
    let law = impact();
    for &(delta, rate) in &[
        (0.01, 3.0),
        (0.05, -2.0),
        (0.08, 40.0),
        (0.2, 1.0),
        (0.15, -50.0),
    ] {
        let f = law.force(delta, rate);
        assert!(f.force > 0.0);
        assert_rel(
            f.d_penetration,
            central(|d| law.force(d, rate).force, delta, delta),
            1.0,
            "∂F/∂δ",
        );
        assert_rel(
            f.d_rate,
            central(|v| law.force(delta, v).force, rate, 1.0),
            1e-3,
            "∂F/∂δ̇",
        );
    }
}

fn poisson(e: f64) -> PoissonLaw {
    PoissonLaw::from_params(PoissonParams {
        penalty: 1e6,
        restitution: e,
        transition_velocity: 1.0,
    })
    .unwrap()
}

#[test]
fn poisson_is_stiff_in_compression_and_softer_by_eps_squared_in_restitution() {
    let law = poisson(0.6);
    assert!((law.force(1e-3, 10.0).force - 1e3).abs() < 1e-9);
    assert!((law.force(1e-3, -10.0).force - 0.36e3).abs() < 1e-9);
    // At zero rate the blend is exactly halfway.
    assert!((law.force(1e-3, 0.0).force - 1e3 * (0.36 + 0.64 * 0.5)).abs() < 1e-9);
    assert_eq!(law.force(0.0, 10.0), NormalForce::ZERO);
    // ε = 1 is a conservative spring: no dependence on the rate.
    let elastic = poisson(1.0);
    assert_eq!(
        elastic.force(2e-3, 5.0).force,
        elastic.force(2e-3, -5.0).force
    );
    assert_eq!(elastic.force(2e-3, 0.3).d_rate, 0.0);
}

#[test]
fn poisson_restitutes_eps_on_a_one_dof_impact() {
    // Independent check of the law's design claim: a unit mass hitting at 1000 (units/s) with
    // v_t = 1 leaves at ε·1000 to within the blend's O(v_t/v) effect. Semi-implicit Euler with a
    // step far below the contact period (2π·sqrt(m/p) ≈ 6.3e-3).
    for &eps in &[0.1, 0.3, 0.6, 0.9, 1.0] {
        let law = poisson(eps);
        let (mut x, mut v) = (0.0_f64, 1000.0_f64); // x = penetration, v = its rate
        let dt = 1e-7;
        let mut steps = 0;
        while x >= 0.0 && steps < 10_000_000 {
            let f = law.force(x, v).force;
            v -= f * dt;
            x += v * dt;
            steps += 1;
        }
        let ratio = -v / 1000.0;
        assert!(
            (ratio - eps).abs() < 0.01 * eps.max(0.1),
            "ε = {eps}: ratio {ratio}"
        );
    }
}

#[test]
fn poisson_partials_agree_with_central_differences() {
    let law = poisson(0.5);
    for &(delta, rate) in &[(1e-3, 0.3), (2e-3, -0.7), (5e-4, 3.0), (1e-3, 0.0)] {
        let f = law.force(delta, rate);
        assert_rel(
            f.d_penetration,
            central(|d| law.force(d, rate).force, delta, delta),
            1.0,
            "∂F/∂δ",
        );
        assert_rel(
            f.d_rate,
            central(|v| law.force(delta, v).force, rate, 1.0),
            1e-3,
            "∂F/∂δ̇",
        );
    }
}

#[test]
fn augmented_lagrangian_accumulates_and_never_pulls() {
    let al = AugmentedLagrangian::new(1e4).unwrap();
    assert_eq!(al.update(0.0, 1e-3), (10.0, 1e4));
    assert_eq!(al.update(10.0, 2e-3), (30.0, 1e4));
    assert_eq!(al.update(5.0, -1e-3), (0.0, 0.0));
    let law = poisson(1.0);
    let f = al.force(30.0, law.force(1e-6, 0.0));
    assert!((f.force - (30.0 + 1.0)).abs() < 1e-12);
    assert_eq!(al.force(0.0, NormalForce::ZERO), NormalForce::ZERO);
}

fn coulomb() -> CoulombFriction {
    CoulombFriction::from_params(CoulombParams {
        mu_static: 0.3,
        mu_dynamic: 0.1,
        stiction_velocity: 0.1,
        friction_velocity: 1.0,
    })
    .unwrap()
}

#[test]
fn mu_takes_the_documented_values() {
    let c = coulomb();
    let cases = [
        (0.0, 0.0),
        (0.1, -0.3),
        (-0.1, 0.3),
        (1.0, -0.1),
        (-1.0, 0.1),
        (5.0, -0.1),
        (-5.0, 0.1),
    ];
    for (v, mu) in cases {
        assert!(
            (c.mu(v).value - mu).abs() < 1e-15,
            "μ({v}) = {} ≠ {mu}",
            c.mu(v).value
        );
    }
    // Halfway between vs and vd the STEP is halfway between μs and μd.
    assert!((c.mu(0.55).value + 0.2).abs() < 1e-15);
    // Inside ±vs it equals STEP(v, −vs, μs, vs, −μs) computed by the generic STEP.
    for k in -9..10 {
        let v = 0.01 * k as f64;
        let generic = step(v, -0.1, 0.3, 0.1, -0.3).unwrap().value;
        assert!((c.mu(v).value - generic).abs() < 1e-15, "v = {v}");
    }
}

#[test]
fn mu_is_continuous_with_a_continuous_slope_at_every_branch_point() {
    let c = coulomb();
    for x in [-1.0, -0.1, 0.0, 0.1, 1.0] {
        let (below, above) = (c.mu(x - 1e-12), c.mu(x + 1e-12));
        assert!(
            (below.value - above.value).abs() < 1e-10,
            "value jumps at {x}"
        );
        assert!(
            (below.slope - above.slope).abs() < 1e-9,
            "slope jumps at {x}"
        );
    }
    for k in -60..60 {
        let v = 0.0237 * k as f64 + 0.003;
        assert_rel(
            c.mu(v).slope,
            central(|v| c.mu(v).value, v, 0.1),
            1e-4,
            "dμ/dv",
        );
    }
}

#[test]
fn friction_force_opposes_slip_with_magnitude_mu_fn() {
    let c = coulomb();
    let slip = Vector3::new(3.0, -4.0, 0.0); // |v| = 5 > vd: μd
    let f = c.force(&slip, 20.0);
    assert!((f.force - (-slip / 5.0 * 0.1 * 20.0)).norm() < 1e-14);
    assert_eq!(c.force(&Vector3::zeros(), 20.0).force, Vector3::zeros());
    // Continuous through zero slip: tiny slip gives tiny force.
    assert!(c.force(&Vector3::new(1e-12, 0.0, 0.0), 20.0).force.norm() < 1e-9);
}

#[test]
fn friction_force_partials_agree_with_central_differences() {
    let c = coulomb();
    for slip in [
        Vector3::new(0.03, -0.02, 0.01),
        Vector3::new(0.3, 0.2, 0.0),
        Vector3::new(-2.0, 0.5, 1.0),
    ] {
        let fn_ = 15.0;
        let f = c.force(&slip, fn_);
        for axis in 0..3 {
            let column = |s: f64| {
                let mut v = slip;
                v[axis] = s;
                c.force(&v, fn_).force
            };
            for row in 0..3 {
                let fd = central(|s| column(s)[row], slip[axis], 0.1);
                assert_rel(f.d_slip[(row, axis)], fd, 1e-3, "∂F/∂v");
            }
        }
        for row in 0..3 {
            let fd = central(|n| c.force(&slip, n).force[row], fn_, fn_);
            assert_rel(f.d_normal_force[row], fd, 1e-3, "∂F/∂Fn");
        }
    }
    // At zero slip the Jacobian is the limit Fn·μ′(0)·I = −Fn·1.5·μs/vs·I.
    let f0 = c.force(&Vector3::zeros(), 2.0);
    assert!((f0.d_slip[(0, 0)] + 2.0 * 1.5 * 0.3 / 0.1).abs() < 1e-12);
}

#[test]
fn friction_torque_is_the_flat_pivot_formula() {
    let c = coulomb();
    // A = π·R² with R = 0.5; spinning fast (ω·R ≥ vd): |T| = (2/3)·R·μd·Fn.
    let area = std::f64::consts::PI * 0.25;
    let t = c.torque(10.0, 30.0, area);
    assert!((t.torque - (-(2.0 / 3.0) * 0.5 * 0.1 * 30.0)).abs() < 1e-14);
    assert!(c.torque(-10.0, 30.0, area).torque > 0.0);
    assert_eq!(c.torque(10.0, 30.0, 0.0).torque, 0.0);
    assert_eq!(c.torque(0.0, 30.0, area).torque, 0.0);
}

#[test]
fn friction_torque_partials_agree_with_central_differences() {
    let c = coulomb();
    for &(spin, fn_, area) in &[(0.1, 30.0, 0.8), (1.0, 5.0, 0.3), (-0.5, 12.0, 2.0)] {
        let t = c.torque(spin, fn_, area);
        assert_rel(
            t.d_spin,
            central(|w| c.torque(w, fn_, area).torque, spin, 1.0),
            1e-4,
            "∂T/∂ω",
        );
        assert_rel(
            t.d_normal_force,
            central(|n| c.torque(spin, n, area).torque, fn_, fn_),
            1e-4,
            "∂T/∂Fn",
        );
        assert_rel(
            t.d_area,
            central(|a| c.torque(spin, fn_, a).torque, area, area),
            1e-4,
            "∂T/∂A",
        );
    }
}

#[test]
fn every_normal_law_is_continuous_at_its_branch_points() {
    let tiny = 1e-12;
    let impact = impact();
    // δ = 0 (first touch), δ = dmax (end of the damping ramp), in both rates.
    for rate in [-3.0, 0.0, 4.0] {
        assert!(impact.force(tiny, rate).force < 1e-9);
        let (below, above) = (
            impact.force(0.1 - tiny, rate).force,
            impact.force(0.1 + tiny, rate).force,
        );
        assert!(
            (below - above).abs() < 1e-6,
            "IMPACT jumps at DMAX: {below} vs {above}"
        );
    }
    let poisson = poisson(0.4);
    for rate in [-1.0, 1.0, 0.0, -20.0] {
        assert!(poisson.force(tiny, rate).force < 1e-5);
        let (below, above) = (
            poisson.force(1e-3, rate - tiny).force,
            poisson.force(1e-3, rate + tiny).force,
        );
        assert!((below - above).abs() < 1e-6, "POISSON jumps at rate {rate}");
    }
}
