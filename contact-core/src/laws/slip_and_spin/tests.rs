//! The shared budget against its two pure limits, its partials against central differences,
//! and the force against uniform-pressure Coulomb friction integrated over the disk patch.

use super::super::{CoulombFriction, CoulombParams};
use crate::Vector3;

fn coulomb(stiction_velocity: f64, friction_velocity: f64) -> CoulombFriction {
    CoulombFriction::from_params(CoulombParams {
        mu_static: 0.3,
        mu_dynamic: 0.2,
        stiction_velocity,
        friction_velocity,
    })
    .unwrap()
}

/// The force and torque on I of Coulomb friction with the law's μ(local slip speed) under
/// uniform pressure over a disk of radius `radius` slipping at `(slip, 0, 0)` and spinning
/// at `spin` about z: a midpoint rule on a polar grid, written apart from the law.
fn patch_integral(c: &CoulombFriction, slip: f64, spin: f64, fn_: f64, radius: f64) -> (f64, f64) {
    let (rings, sectors) = (600, 1200);
    let pressure = fn_ / (std::f64::consts::PI * radius * radius);
    let (dr, dt) = (
        radius / rings as f64,
        std::f64::consts::TAU / sectors as f64,
    );
    let (mut force_x, mut torque) = (0.0, 0.0);
    for i in 0..rings {
        let r = (i as f64 + 0.5) * dr;
        for k in 0..sectors {
            let theta = (k as f64 + 0.5) * dt;
            let (x, y) = (r * theta.cos(), r * theta.sin());
            // Local slip v + ω ẑ × (x, y) = (v − ω y, ω x).
            let (sx, sy) = (slip - spin * y, spin * x);
            let speed = sx.hypot(sy);
            let per_speed = c.mu(speed).value / speed;
            let d_force = pressure * r * dr * dt * per_speed;
            force_x += d_force * sx;
            torque += d_force * (x * sy - y * sx);
        }
    }
    (force_x, torque)
}

#[test]
fn without_spin_it_is_the_force_law_and_without_slip_the_torque_law() {
    let c = coulomb(0.1, 1.0);
    let area = std::f64::consts::PI * 0.04;
    for slip in [Vector3::new(0.03, -0.02, 0.0), Vector3::new(-2.0, 0.5, 0.0)] {
        let both = c.slip_and_spin(&slip, 0.0, 15.0, area);
        let alone = c.force(&slip, 15.0);
        // The same force to the bit (the runs of non-spinning contacts are unchanged); its
        // partials to round-off.
        assert_eq!(both.force.force, alone.force);
        assert!((both.force.d_slip - alone.d_slip).norm() <= 1e-14 * alone.d_slip.norm());
        assert_eq!(both.torque.torque, 0.0);
        // A point (no area) spinning: the force law, no torque.
        let point = c.slip_and_spin(&slip, 7.0, 15.0, 0.0);
        assert_eq!(point.force.force, alone.force);
        assert_eq!(point.torque.torque, 0.0);
    }
    for spin in [0.3, -4.0, 50.0] {
        let both = c.slip_and_spin(&Vector3::zeros(), spin, 15.0, area);
        let alone = c.torque(spin, 15.0, area);
        assert_eq!(both.force.force, Vector3::zeros());
        for (a, b) in [
            (both.torque.torque, alone.torque),
            (both.torque.d_spin, alone.d_spin),
            (both.torque.d_normal_force, alone.d_normal_force),
            (both.torque.d_area, alone.d_area),
        ] {
            assert!((a - b).abs() <= 1e-14 * b.abs(), "{a} against {b}");
        }
    }
}

#[test]
fn every_partial_agrees_with_central_differences() {
    let c = coulomb(0.1, 1.0);
    let cases = [
        (Vector3::new(0.02, -0.01, 0.0), 0.3, 12.0, 0.5),
        (Vector3::new(0.3, 0.2, 0.0), 2.0, 5.0, 0.2),
        (Vector3::new(-2.0, 0.5, 0.0), -1.0, 30.0, 1.5),
        (Vector3::new(1e-4, 0.0, 0.0), 40.0, 8.0, 0.1),
    ];
    let h = 1e-6;
    let rel = |a: f64, b: f64, what: &str| {
        let tol = 1e-5 * a.abs().max(b.abs()).max(1e-3);
        assert!((a - b).abs() <= tol, "{what}: analytic {a:e} against {b:e}");
    };
    for (slip, spin, fn_, area) in cases {
        let at = |v: Vector3, w: f64, f: f64, a: f64| c.slip_and_spin(&v, w, f, a);
        let both = at(slip, spin, fn_, area);
        // The slip speed the law sees sets the scale of a slip step.
        let speed = slip
            .norm()
            .hypot(spin * (area / std::f64::consts::PI).sqrt());
        for axis in 0..3 {
            let step = h * speed;
            let mut up = slip;
            let mut down = slip;
            up[axis] += step;
            down[axis] -= step;
            let (hi, lo) = (at(up, spin, fn_, area), at(down, spin, fn_, area));
            for row in 0..3 {
                let fd = (hi.force.force[row] - lo.force.force[row]) / (2.0 * step);
                rel(both.force.d_slip[(row, axis)], fd, "∂F/∂v");
            }
            let fd = (hi.torque.torque - lo.torque.torque) / (2.0 * step);
            rel(both.torque_d_slip[axis], fd, "∂T/∂v");
        }
        let step = h * spin.abs();
        let (hi, lo) = (
            at(slip, spin + step, fn_, area),
            at(slip, spin - step, fn_, area),
        );
        for row in 0..3 {
            let fd = (hi.force.force[row] - lo.force.force[row]) / (2.0 * step);
            rel(both.force_d_spin[row], fd, "∂F/∂ω");
        }
        rel(
            both.torque.d_spin,
            (hi.torque.torque - lo.torque.torque) / (2.0 * step),
            "∂T/∂ω",
        );
        let step = h * fn_;
        let (hi, lo) = (
            at(slip, spin, fn_ + step, area),
            at(slip, spin, fn_ - step, area),
        );
        for row in 0..3 {
            let fd = (hi.force.force[row] - lo.force.force[row]) / (2.0 * step);
            rel(both.force.d_normal_force[row], fd, "∂F/∂Fn");
        }
        let fd = (hi.torque.torque - lo.torque.torque) / (2.0 * step);
        rel(both.torque.d_normal_force, fd, "∂T/∂Fn");
        let step = h * area;
        let (hi, lo) = (
            at(slip, spin, fn_, area + step),
            at(slip, spin, fn_, area - step),
        );
        rel(
            both.torque.d_area,
            (hi.torque.torque - lo.torque.torque) / (2.0 * step),
            "∂T/∂A",
        );
    }
}

#[test]
fn a_spinning_patch_resists_a_small_slip_as_the_integrated_patch_does() {
    // Transition velocities far below the rim speed ω·R = 1: μ ≈ μd over almost all of the
    // patch. The integral's small-slip gain is μd·Fn/(ω·R) (the linearised patch); the law
    // before the shared budget gave the stiction gain 1.5·μs·Fn/vs, 22,500 times larger here.
    let c = coulomb(1e-5, 2e-5);
    let (fn_, radius, spin) = (20.0, 0.1, 10.0);
    let area = std::f64::consts::PI * radius * radius;
    for ratio in [1e-3, 1e-2] {
        let slip = ratio * spin * radius;
        let (force, torque) = patch_integral(&c, slip, spin, fn_, radius);
        let both = c.slip_and_spin(&Vector3::new(slip, 0.0, 0.0), spin, fn_, area);
        let law = both.force.force.x;
        assert!(
            (law - force).abs() < 0.01 * force.abs(),
            "slip/(ωR) {ratio}: {law} against {force}"
        );
        assert!((both.torque.torque - torque).abs() < 0.01 * torque.abs());
    }
    // Anywhere between, the force stays within 20 % of the integral (largest at v = ω·R) and
    // the torque within the factor 8/3 of the pure-slip limit.
    for ratio in [0.1, 0.5, 1.0, 2.0, 10.0, 100.0] {
        let slip = ratio * spin * radius;
        let (force, torque) = patch_integral(&c, slip, spin, fn_, radius);
        let both = c.slip_and_spin(&Vector3::new(slip, 0.0, 0.0), spin, fn_, area);
        let (f, t) = (both.force.force.x / force, both.torque.torque / torque);
        assert!(
            (0.8..1.0 + 1e-3).contains(&f),
            "force ratio {f} at slip/(ωR) {ratio}"
        );
        assert!(
            (1.0 - 1e-3..8.0 / 3.0 + 1e-3).contains(&t),
            "torque ratio {t} at {ratio}"
        );
    }
}
