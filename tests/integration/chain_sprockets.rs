//! The chain drive (`src/chain.rs`, `examples/chain_sprockets/`): a closed chain of 24
//! REVOLUTE-jointed links over two 12-tooth sprockets, sprocket A turned by a constant torque,
//! B only through the chain. Oracles written apart from the solver, from the part states and
//! the contact reports of its output frames and the generator's masses and dimensions:
//!
//! - energy bookkeeping: the torque's work `∫ τ·ω_A dt` equals the parts' kinetic energy, the
//!   contacts' spring energy `Σ k·δ²/2` and the energy the IMPACT damping took out
//!   (`∫ Σ (Fn − k·δ)·δ̇ dt`), both integrals by the trapezoidal rule over the frames;
//! - no contact deeper than the torque's static load and a roller's impact at the chain's
//!   speed make it, nor than the work put in could;
//! - the chain's kinematics: the equal sprockets turn through equal angles, apart by at most
//!   the play of a roller in a tooth gap on each sprocket and each contact's depth.
//!
//! The dataset's span is 1 s; the tests run its first 0.2 s (A turns through about 0.4 rad,
//! most of a tooth pitch, and rollers enter and leave both wraps), which in a debug build
//! takes seconds where the whole span would take minutes.

use contact::chain::{
    ChainDrive, LINK_MASS, SPROCKET_MASS, STIFFNESS, TORQUE, pitch_radius, seat_play, tooth_arm,
};
use contact::run::lower::{LoweredModel, lower};
use contact::solver::bdf::IntegratorSettings;
use contact::solver::contact_force::Analysis;
use contact::solver::mbs::PartId;
use contact::solver::simulate::{DynamicsSettings, Frame, RunSummary, simulate};
use nalgebra::{Matrix3, Vector3};

fn lowered(chain: &ChainDrive) -> LoweredModel {
    let loaded = crate::inline("chain.adm", &chain.dataset());
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in the chain".to_string());
    lower(
        &loaded.model,
        &engine_exact::ExactEngine,
        Analysis::Dynamics,
        &no_meshes,
    )
    .unwrap()
}

/// What the oracles read from one output frame.
#[derive(Debug, Clone, Copy)]
struct Sample {
    t: f64,
    /// Sprocket A's and B's angles about z (rad), as turned since the start.
    angles: [f64; 2],
    /// Sprocket A's angular velocity about z (rad/s).
    omega: f64,
    /// The parts' kinetic energy (J).
    kinetic: f64,
    /// The contacts' spring energy `Σ k·δ²/2` (J).
    spring: f64,
    /// The damping's power `Σ (Fn − k·δ)·δ̇` (W): what the contacts take out of the motion.
    damping_power: f64,
    /// The deepest contact (m).
    deepest: f64,
}

/// A part's mass and principal moments (in its CM marker's axes) by Adams PART id.
fn inertia(adams_id: u32) -> (f64, [f64; 3]) {
    if adams_id == 2 || adams_id == 3 {
        (SPROCKET_MASS, ChainDrive::sprocket_inertia())
    } else {
        (LINK_MASS, ChainDrive::link_inertia())
    }
}

fn sample(frame: &Frame, parts: &[(PartId, u32)], previous: Option<&Sample>) -> Sample {
    let mut kinetic = 0.0;
    let mut omega = 0.0;
    let mut angles = [0.0; 2];
    for (id, adams) in parts {
        let state = frame.parts[id.0];
        let (mass, [a, b, c]) = inertia(*adams);
        let r = state.pose_w.rotation.to_rotation_matrix();
        let world =
            r.matrix() * Matrix3::from_diagonal(&Vector3::new(a, b, c)) * r.matrix().transpose();
        let w = state.angular_velocity_w;
        kinetic += 0.5 * mass * state.velocity_w.norm_squared() + 0.5 * w.dot(&(world * w));
        if *adams == 2 || *adams == 3 {
            let q = state.pose_w.rotation;
            angles[*adams as usize - 2] = 2.0 * q.k.atan2(q.w);
            if *adams == 2 {
                omega = w.z;
            }
        }
    }
    // Unwrapped against the previous frame (a frame step turns a sprocket far less than π).
    if let Some(p) = previous {
        for (angle, before) in angles.iter_mut().zip(p.angles) {
            let turn = std::f64::consts::TAU;
            *angle += ((before - *angle) / turn).round() * turn;
        }
    }
    let (mut spring, mut damping_power, mut deepest) = (0.0, 0.0, 0.0_f64);
    for report in frame.contacts.iter().flatten() {
        let delta = report.contact.penetration;
        spring += 0.5 * STIFFNESS * delta * delta;
        damping_power += (report.normal_force - STIFFNESS * delta) * report.penetration_rate;
        deepest = deepest.max(delta);
    }
    Sample {
        t: frame.t,
        angles,
        omega,
        kinetic,
        spring,
        damping_power,
        deepest,
    }
}

/// Runs the 24-link chain to `end` at ERROR `error`, sampling every `output_step`.
fn run(end: f64, output_step: f64, error: f64) -> (Vec<Sample>, RunSummary) {
    let chain = ChainDrive::new(24).unwrap();
    let mut model = lowered(&chain);
    let settings = DynamicsSettings {
        start: 0.0,
        end,
        output_step,
        integrator: IntegratorSettings {
            error,
            ..IntegratorSettings::default()
        },
    };
    let mut samples: Vec<Sample> = Vec::new();
    let parts = model.parts.clone();
    let summary = simulate(
        &mut model.system,
        &model.contacts,
        &settings,
        &mut |frame| {
            let s = sample(frame, &parts, samples.last());
            samples.push(s);
            Ok(())
        },
    )
    .unwrap();
    (samples, summary)
}

/// The torque's work `∫ τ·ω_A dt` and the damping's energy `∫ Σ (Fn − k·δ)·δ̇ dt` up to
/// each sample, by the trapezoidal rule, with the residual of the energy balance
/// `work − kinetic − spring − dissipated` (the spring energy of the start taken as given).
fn balance(samples: &[Sample]) -> Vec<(f64, f64)> {
    let (mut work, mut dissipated) = (0.0, 0.0);
    let start = samples[0].kinetic + samples[0].spring;
    let mut out = vec![(0.0, 0.0)];
    for pair in samples.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        let h = b.t - a.t;
        work += 0.5 * TORQUE * (a.omega + b.omega) * h;
        dissipated += 0.5 * (a.damping_power + b.damping_power) * h;
        out.push((work, work + start - b.kinetic - b.spring - dissipated));
    }
    out
}

/// The span the tests run (s): a fifth of the dataset's.
const SPAN: f64 = 0.2;
/// The output step of the tests (s): the trapezoidal sums' step.
const STEP: f64 = 1e-4;

#[test]
fn the_torque_s_work_is_the_kinetic_spring_and_damping_energy() {
    let (samples, summary) = run(SPAN, STEP, contact::chain::ERROR);
    let sums = balance(&samples);
    let work = sums.last().unwrap().0;
    // Every part turns or moves: A by the torque, B and the links through the chain.
    assert!(work > 0.0 && summary.integrator.steps > 0);
    // The quadrature's own error, estimated by the same sums over every other sample.
    let halved: Vec<Sample> = samples.iter().step_by(2).copied().collect();
    let coarse = balance(&halved).last().unwrap().1;
    let quadrature = (coarse - sums.last().unwrap().1).abs();
    // The integrator's: the local error test is a weighted RMS over every differential state
    // (about 350 here), so one part's velocities may carry a relative error of
    // `sqrt(350)·ERROR ≈ 2e-3` per step; over the run we hold the books to 1 % of the work.
    let worst = sums.iter().map(|(_, r)| r.abs()).fold(0.0, f64::max);
    assert!(
        worst <= 1e-2 * work + 4.0 * quadrature,
        "residual {worst:e} J of {work:e} J (quadrature {quadrature:e})"
    );
    // And the books close as the integration tightens: a force or rate reported apart from
    // what moves the parts would leave a residual that does not shrink.
    let (tight, _) = run(SPAN, STEP, 1e-2 * contact::chain::ERROR);
    let tight_worst = balance(&tight)
        .iter()
        .map(|(_, r)| r.abs())
        .fold(0.0, f64::max);
    assert!(
        tight_worst <= 0.25 * worst,
        "{tight_worst:e} against {worst:e}"
    );
}

#[test]
fn the_chain_turns_the_second_sprocket_with_the_first() {
    let (samples, _) = run(SPAN, 10.0 * STEP, contact::chain::ERROR);
    let deepest = samples.iter().map(|s| s.deepest).fold(0.0, f64::max);
    // Each sprocket can turn against its rollers by the play of a roller in its gap, and by
    // the depth of the tooth contact over its arm; the rigid links carry the rest.
    let bound = 2.0 * (seat_play() + deepest / tooth_arm());
    for s in &samples {
        let [a, b] = s.angles;
        assert!(
            (a - b).abs() <= bound,
            "t = {}: A {a}, B {b}, bound {bound}",
            s.t
        );
    }
    // A has turned through many times that bound, so B was driven (not left behind).
    let [a, _] = samples.last().unwrap().angles;
    assert!(a >= 4.0 * bound, "A turned {a} rad, the bound is {bound}");
}

#[test]
fn no_contact_is_deeper_than_the_load_and_the_roller_s_impact_make_it() {
    let (samples, _) = run(SPAN, 10.0 * STEP, contact::chain::ERROR);
    // Statically the torque τ is all that loads the chain: every tooth force on A is at most
    // τ over the tooth's arm (the other contacts' moments about A's axis are of one sign or
    // zero, and A's inertia only takes some away), the tight span's tension too, and B, the
    // hubs and the links carry the tension or less: a spring deflection of at most
    // `τ/(k·arm)`, twice that when the load comes on at once.
    let statics = 2.0 * TORQUE / (STIFFNESS * tooth_arm());
    // Dynamically a roller entering a wrap meets the seat at most at the chain's speed `ω_A·R`
    // relative to it (for T ≥ 6) with its link's mass: an undamped spring stores that kinetic
    // energy at `v·sqrt(m/k)`; the IMPACT damping only takes from it.
    let mut speed = 0.0_f64;
    // And no contact stores more than the energy put in: k·δ²/2 ≤ work (+ the start's).
    let mut work = samples[0].spring;
    for pair in samples.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        work += 0.5 * TORQUE * (a.omega + b.omega) * (b.t - a.t);
        speed = speed.max(b.omega.abs() * pitch_radius());
        let impact = statics + speed * (LINK_MASS / STIFFNESS).sqrt();
        let energy = (2.0 * work / STIFFNESS).sqrt();
        assert!(
            b.deepest <= energy,
            "t = {}: {} deep, energy bound {energy}",
            b.t,
            b.deepest
        );
        assert!(
            b.deepest <= impact,
            "t = {}: {} deep, impact bound {impact}",
            b.t,
            b.deepest
        );
    }
}
