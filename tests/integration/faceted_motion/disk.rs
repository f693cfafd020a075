//! A flat disk spun down on a plane by the friction torque: the stop time against the closed
//! form, and the disk's tilt, which must stay at round-off while it spins and after it stops.
//!
//! A spinning disk resting on its face has one contact point under its centre. Before slip
//! and spin shared one Coulomb budget (`contact_core::laws::SlipAndSpin`), the friction force
//! at that point saw the stiction-band gain μs·Fn/vs against the tiny slip of a tilt, and a
//! faceted disk's round-off tilt grew into a wobble of 5e-5 rad/s that outlived the spin:
//! 312 steps against the exact run's 124.

use super::{engines, run};

const OMEGA0: f64 = 10.0;
const MASS: f64 = 2.0;
const RADIUS: f64 = 0.1;
const INERTIA_AXIAL: f64 = 0.5 * MASS * RADIUS * RADIUS;
const MU_DYNAMIC: f64 = 0.2;

/// The disk of `examples/spinning_disk`: 2 kg, radius 0.1, thickness 0.02, lying on the
/// ground plane at its static penetration, spinning at `OMEGA0` about its axis.
fn flat_disk() -> String {
    format!(
        "flat disk spun down\n\
         UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
         PART/1, GROUND\nMARKER/10, PART = 1\n\
         PART/2, MASS = {MASS}, CM = 20, IP = 0.005066666666666668, 0.005066666666666668, \
         {INERTIA_AXIAL}, WZ = {OMEGA0}\n\
         MARKER/20, PART = 2, QP = 0, 0, 0.00984327702441574\n\
         MARKER/21, PART = 2, QP = 0, 0, -0.0001567229755842607\n\
         GRAPHICS/1, CYLINDER, CM = 21, RADIUS = {RADIUS}, LENGTH = 0.02\n\
         GRAPHICS/2, PLANE, RM = 10\n\
         CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT\n\
         , STIFFNESS = 1E7, EXPONENT = 1.5, DAMPING = 1E3, DMAX = 1E-4\n\
         , COULOMB_FRICTION = ON, MU_STATIC = 0.3, MU_DYNAMIC = {MU_DYNAMIC}\n\
         , STICTION_TRANSITION_VELOCITY = 1E-3, FRICTION_TRANSITION_VELOCITY = 2E-3\n\
         ACCGRAV/ KGRAV = -9.81\nEND\n"
    )
}

#[test]
fn a_flat_disk_stops_at_the_closed_form_time_without_wobbling() {
    // T = (2/3)·R·μd·m·g with R from the whole face: t = ω0·I/T.
    let closed = OMEGA0 * INERTIA_AXIAL / (2.0 / 3.0 * RADIUS * MU_DYNAMIC * MASS * super::G);
    let text = flat_disk();
    let mut exact = None;
    for (name, engine) in engines() {
        let (samples, summary) = run(&text, engine.as_ref(), 0.8, 5e-3, 1e-6);
        let stopped = samples
            .iter()
            .find(|s| s.part.angular_velocity_w.z.abs() < 0.01)
            .map(|s| s.t)
            .unwrap_or_else(|| panic!("{name}: never stopped"));
        let tilt_rate = samples
            .iter()
            .map(|s| s.part.angular_velocity_w.xy().norm())
            .fold(0.0, f64::max);
        let steps = summary.integrator.steps;
        println!(
            "flat disk, {name}: stops at {stopped:.4} (closed form {closed:.4}), \
             largest tilt rate {tilt_rate:.2e} rad/s, {steps} steps"
        );
        // A wobble of 1e-6 rad/s moves the rim by 1e-7 per second: far below anything the
        // step control should follow, and 50 times below the one this test guards against.
        assert!(tilt_rate < 1e-6, "{name}: tilt rate {tilt_rate:e}");
        match exact {
            None => {
                assert!(
                    (stopped - closed).abs() < 0.01 * closed,
                    "{name}: {stopped}"
                );
                exact = Some((stopped, steps));
            }
            Some((t, exact_steps)) => {
                assert!(
                    (stopped - t).abs() < 0.01 * t,
                    "{name}: {stopped} against {t}"
                );
                assert!(
                    2 * steps <= 3 * exact_steps,
                    "{name}: {steps} steps against the exact run's {exact_steps}"
                );
            }
        }
    }
}
