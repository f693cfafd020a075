//! The index-3 pendulum in Cartesian coordinates with a Lagrange multiplier (Adams' I3 form):
//! constraint satisfaction, energy drift, and the period against the exact large-amplitude
//! period `4·sqrt(l/g)·K(sin(θ0/2))`.

use crate::bdf::reference::{Pendulum, pendulum_period};
use crate::bdf::{Bdf, Corrector, IntegratorSettings};
use nalgebra::DVector;

const THETA0: f64 = 2.0; // rad: a large swing, period 1.35× the small-angle one.

/// Runs `periods` periods and returns the upward zero crossings of x (dense output +
/// bisection), the worst constraint residual |x² + y² − l²|/l² at accepted steps, the worst
/// relative energy change, and the integrator.
fn swing(error: f64, corrector: Corrector, periods: f64) -> (Vec<f64>, f64, f64, Bdf) {
    let mut pendulum = Pendulum {
        mass: 2.0,
        length: 1.5,
        gravity: 9.81,
    };
    let exact = pendulum_period(pendulum.length, pendulum.gravity, THETA0);
    let (y0, yp0) = pendulum.at_rest(THETA0);
    let e0 = pendulum.energy(&y0);
    let scale = pendulum.mass * pendulum.gravity * pendulum.length;
    let settings = IntegratorSettings {
        error,
        corrector,
        ..IntegratorSettings::default()
    };
    let mut bdf = Bdf::new(&pendulum, 0.0, y0, yp0, settings).unwrap();
    let end = periods * exact;
    bdf.set_stop_time(Some(end)).unwrap();
    let (mut crossings, mut worst_constraint, mut worst_energy) = (Vec::new(), 0.0_f64, 0.0_f64);
    let l2 = pendulum.length * pendulum.length;
    while bdf.t() < end {
        let x_before = bdf.y()[0];
        bdf.step(&mut pendulum).unwrap();
        let y = bdf.y();
        worst_constraint = worst_constraint.max((y[0] * y[0] + y[1] * y[1] - l2).abs() / l2);
        worst_energy = worst_energy.max((pendulum.energy(y) - e0).abs() / scale);
        if x_before < 0.0 && y[0] >= 0.0 {
            let (mut a, mut b) = (bdf.t_previous(), bdf.t());
            for _ in 0..60 {
                let mid = 0.5 * (a + b);
                if bdf.interpolate(mid).unwrap().0[0] < 0.0 {
                    a = mid
                } else {
                    b = mid
                }
            }
            crossings.push(0.5 * (a + b));
        }
    }
    (crossings, worst_constraint, worst_energy, bdf)
}

#[test]
fn period_constraint_and_energy_of_the_index3_pendulum() {
    let exact = pendulum_period(1.5, 9.81, THETA0);
    for corrector in [Corrector::Modified, Corrector::Full] {
        let (crossings, constraint, energy, bdf) = swing(1e-8, corrector, 3.0);
        let measured: Vec<f64> = crossings.windows(2).map(|w| w[1] - w[0]).collect();
        eprintln!(
            "pendulum {corrector:?}: periods {measured:?} (exact {exact}), constraint {constraint:.1e}, \
             energy {energy:.1e}, {:?}",
            bdf.stats()
        );
        assert!(measured.len() >= 2, "{crossings:?}");
        // ERROR = 1e-8 on displacements; the period (a time) comes out to a few 1e-5.
        for period in &measured {
            assert!(
                (period - exact).abs() < 5e-5 * exact,
                "period {period} vs {exact}"
            );
        }
        // Positions are on the circle to Newton precision at every step (index 3: no drift).
        assert!(constraint < 1e-7, "constraint {constraint:e}");
        // Velocities are not error-tested in I3, so energy is only as good as they are: within
        // 1e-4 of m·g·l over 3 periods.
        assert!(energy < 1e-4, "energy drift {energy:e}");
    }
}

#[test]
fn energy_drift_shrinks_with_the_tolerance() {
    let (_, _, loose, _) = swing(1e-4, Corrector::Modified, 2.0);
    let (_, _, tight, _) = swing(1e-7, Corrector::Modified, 2.0);
    eprintln!("pendulum energy drift: {loose:.2e} at 1e-4, {tight:.2e} at 1e-7");
    assert!(tight < loose / 10.0, "{loose:e} {tight:e}");
}

#[test]
fn dense_output_follows_the_circle_between_steps() {
    let mut pendulum = Pendulum {
        mass: 1.0,
        length: 1.0,
        gravity: 9.81,
    };
    let (y0, yp0) = pendulum.at_rest(1.0);
    let settings = IntegratorSettings {
        error: 1e-6,
        ..IntegratorSettings::default()
    };
    let mut bdf = Bdf::new(&pendulum, 0.0, y0, yp0, settings).unwrap();
    bdf.set_stop_time(Some(1.0)).unwrap();
    let mut worst = 0.0_f64;
    while bdf.t() < 1.0 {
        bdf.step(&mut pendulum).unwrap();
        for f in [0.25, 0.5, 0.75] {
            let t = bdf.t_previous() + f * (bdf.t() - bdf.t_previous());
            let y: DVector<f64> = bdf.interpolate(t).unwrap().0;
            worst = worst.max((y[0] * y[0] + y[1] * y[1] - 1.0).abs());
        }
    }
    // Between steps the interpolant is off the circle by the local error only.
    assert!(worst < 1e-4, "worst {worst:e}");
}
