//! Embedding `contact` in your own simulator: pick an engine by name, read a mesh, prepare one
//! CONTACT's pair once, then query it from your time loop — here from four threads at once —
//! and turn each contact into forces with the bodies' velocities: contact-core's kinematics
//! helper gives the penetration rate, slip and spin, and its laws IMPACT and Coulomb friction
//! give the forces, as the solver computes them.
//!
//! Run: `cargo run --example embedding [exact|faceted|PARASOLID|DEFAULT_LIBRARY|RAPID]`.

use contact::engine_choice::engine_by_name;
use contact_core::geometry::Plane;
use contact_core::laws::{CoulombFriction, CoulombParams, ImpactLaw, ImpactParams};
use contact_core::{
    BodyMotion, ContactKinematics, FacetingTolerance, Geometry, GeometryInstance, Isometry3,
    PreparedPair, UnitQuaternion, Vector3, WorkCounters, mesh_file,
};
use std::path::Path;
use std::process::ExitCode;

/// The time step of the loop (s) and its number of steps.
const DT: f64 = 1e-3;
const STEPS: usize = 40;

/// The wheel's motion at step `k`: tilted 0.05 rad about x, spinning at 2 rad/s about the world
/// z axis, its frame origin (the centre of its bottom face) sliding at 0.05 m/s along x and
/// sinking at 0.1 m/s from 1 mm above first touch. The pose is the motion integrated exactly,
/// so the velocities are the pose's own.
fn wheel_at(k: usize) -> BodyMotion {
    let t = k as f64 * DT;
    let (tilt, spin) = (0.05, 2.0);
    let velocity_w = Vector3::new(0.05, 0.0, -0.1);
    let angular_velocity_w = Vector3::new(0.0, 0.0, spin);
    // The rim's lowest point is 0.0707·sin(tilt) below the origin.
    let start = Vector3::new(0.0, 0.0, 0.0707 * f64::sin(tilt) + 0.001);
    let rotation = UnitQuaternion::from_scaled_axis(angular_velocity_w * t)
        * UnitQuaternion::from_scaled_axis(Vector3::x() * tilt);
    BodyMotion {
        pose_w: Isometry3::from_parts((start + velocity_w * t).into(), rotation),
        velocity_w,
        angular_velocity_w,
    }
}

/// One step's answer: the deepest penetration, the total normal force, the total friction
/// force's magnitude and the penetration rate of the deepest contact.
#[derive(Debug, Clone, Copy, PartialEq)]
struct StepAnswer {
    contacts: usize,
    depth: f64,
    rate: f64,
    normal_force: f64,
    friction_force: f64,
}

fn step(
    pair: &dyn PreparedPair,
    k: usize,
    impact: &ImpactLaw,
    friction: &CoulombFriction,
) -> StepAnswer {
    let (wheel, ground) = (wheel_at(k), BodyMotion::at_rest(Isometry3::identity()));
    let mut contacts = Vec::new();
    let mut work = WorkCounters::default();
    pair.query(&wheel.pose_w, &ground.pose_w, &mut contacts, &mut work)
        .expect("finite poses");
    let mut answer = StepAnswer {
        contacts: contacts.len(),
        depth: 0.0,
        rate: 0.0,
        normal_force: 0.0,
        friction_force: 0.0,
    };
    let mut friction_w = Vector3::zeros();
    for c in &contacts {
        // δ̇, the slip and the spin at the contact's midpoint, from both bodies' velocities.
        let k = ContactKinematics::compute(c, &wheel, &ground);
        let normal = impact.force(c.penetration, k.penetration_rate).force;
        friction_w += friction
            .slip_and_spin(&k.slip_velocity_w, k.spin, normal, c.area)
            .force
            .force;
        answer.normal_force += normal;
        if c.penetration > answer.depth {
            answer.depth = c.penetration;
            answer.rate = k.penetration_rate;
        }
    }
    answer.friction_force = friction_w.norm();
    answer
}

fn main() -> ExitCode {
    let name = std::env::args().nth(1).unwrap_or_else(|| "exact".into());
    // The one place that picks an engine: a trait object from here on.
    let engine = match engine_by_name(&name, FacetingTolerance::DEFAULT) {
        Ok(engine) => engine,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };

    // The Geneva wheel (I, an STL mesh in metres) over the ground plane (J).
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/geneva/geneva_wheel.stl");
    let wheel = match mesh_file::read_mesh_geometry(&path) {
        Ok(mesh) => GeometryInstance::new(mesh),
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let ground = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
    let pair = match engine.prepare(&[wheel], &[ground]) {
        Ok(pair) => pair,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    // The laws by named parameters (N, m, s): no two numbers can trade places silently.
    let impact = ImpactLaw::from_params(ImpactParams {
        stiffness: 1e6,
        exponent: 1.5,
        damping: 100.0,
        max_penetration: 1e-4,
    })
    .expect("valid IMPACT parameters");
    let friction = CoulombFriction::from_params(CoulombParams {
        mu_static: 0.3,
        mu_dynamic: 0.2,
        stiction_velocity: 1e-3,
        friction_velocity: 1e-2,
    })
    .expect("valid friction parameters");

    // Your time loop: four threads each take every fourth step; the prepared pair is shared by
    // reference (queries take &self, no locks).
    let steps: Vec<usize> = (0..STEPS).collect();
    let mut answers: Vec<(usize, StepAnswer)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..4)
            .map(|thread| {
                let (pair, steps) = (pair.as_ref(), &steps);
                let (impact, friction) = (&impact, &friction);
                scope.spawn(move || {
                    steps
                        .iter()
                        .skip(thread)
                        .step_by(4)
                        .map(|&k| (k, step(pair, k, impact, friction)))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("a query thread panicked"))
            .collect()
    });
    answers.sort_by_key(|a| a.0);
    println!(
        "engine: {} ({} triangles prepared)",
        engine.name(),
        pair.stats().triangles
    );
    println!("step  contacts  depth (m)     rate (m/s)  normal (N)  friction (N)");
    for (k, a) in answers.iter().step_by(5) {
        println!(
            "{k:>4}  {:>8}  {:<12.6e}  {:>10.4}  {:>10.3}  {:>12.3}",
            a.contacts, a.depth, a.rate, a.normal_force, a.friction_force
        );
    }
    if !answers.iter().any(|(_, a)| a.normal_force > 0.0) {
        eprintln!("error: the wheel never touched the ground");
        return ExitCode::FAILURE;
    }
    // The same steps from one thread give the same bits.
    for (k, threaded) in &answers {
        let serial = step(pair.as_ref(), *k, &impact, &friction);
        let bits =
            |a: &StepAnswer| [a.depth, a.rate, a.normal_force, a.friction_force].map(f64::to_bits);
        if bits(threaded) != bits(&serial) || threaded.contacts != serial.contacts {
            eprintln!("error: step {k}: threaded {threaded:?} differs from serial {serial:?}");
            return ExitCode::FAILURE;
        }
    }
    println!("threaded answers equal the serial ones bit for bit");
    ExitCode::SUCCESS
}
