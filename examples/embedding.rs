//! Embedding `contact` in your own simulator: build geometry in code, prepare one CONTACT's
//! pair once with either engine, then query it from your time loop — here from several threads
//! at once — and turn the kinematics into forces with contact-core's laws.
//!
//! Run: `cargo run --release --example embedding [exact|faceted]`.

use contact_core::geometry::{Cuboid, Plane};
use contact_core::{
    ContactArgs, FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, GeometryLibrary,
    Isometry3, NormalModel, Units, Vector3, WorkCounters,
};
use std::process::ExitCode;

fn main() -> ExitCode {
    let library = match std::env::args()
        .nth(1)
        .as_deref()
        .map(GeometryLibrary::parse)
    {
        None => GeometryLibrary::Exact,
        Some(Ok(library)) => library,
        Some(Err(e)) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    // The one place that picks an engine: a trait object from here on.
    let engine: Box<dyn GeometryEngine> =
        contact::engine_choice::build_engine(library, FacetingTolerance::DEFAULT);

    // A 0.2 m box (I, on a falling part) over the ground plane (J).
    let block = GeometryInstance::new(Geometry::Cuboid(
        Cuboid::centered(0.1, 0.1, 0.1).expect("valid size"),
    ));
    let ground = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
    let pair = match engine.prepare(&[block], &[ground]) {
        Ok(pair) => pair,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let (params, _) = ContactArgs {
        impact: true,
        stiffness: Some(1e7),
        exponent: Some(1.5),
        ..Default::default()
    }
    .validate(&Units::MKS)
    .expect("valid contact arguments");
    let NormalModel::Impact(law) = params.normal else {
        unreachable!("IMPACT was asked for")
    };

    // Your time loop: the box sinks 1 mm per step, tilting slowly. Four threads each take every
    // fourth step; the prepared pair is shared by reference (queries take &self, no locks).
    let steps: Vec<usize> = (0..40).collect();
    let world = Isometry3::identity();
    let answers: Vec<(usize, f64, f64)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..4)
            .map(|thread| {
                let pair = &pair;
                let steps = &steps;
                scope.spawn(move || {
                    let mut contacts = Vec::new();
                    let mut work = WorkCounters::default();
                    let mut out = Vec::new();
                    for &k in steps.iter().skip(thread).step_by(4) {
                        let height = 0.1 + 0.005 - 0.001 * k as f64;
                        let pose = Isometry3::new(
                            Vector3::new(0.0, 0.0, height),
                            Vector3::x() * 0.002 * k as f64,
                        );
                        pair.query(&pose, &world, &mut contacts, &mut work)
                            .expect("finite poses");
                        let force = contacts
                            .iter()
                            .map(|c| law.force(c.penetration, 0.0).force)
                            .sum::<f64>()
                            + 0.0;
                        let depth = contacts.iter().map(|c| c.penetration).fold(0.0, f64::max);
                        out.push((k, depth, force));
                    }
                    out
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("a query thread panicked"))
            .collect()
    });
    let mut answers = answers;
    answers.sort_by_key(|a| a.0);
    println!(
        "engine: {} ({} triangles prepared)",
        engine.name(),
        pair.stats().triangles
    );
    println!("step  depth (m)     force (N)");
    for (k, depth, force) in answers.iter().step_by(5) {
        println!("{k:>4}  {depth:<12.6e}  {force:.3}");
    }
    // The same queries from one thread give the same bits.
    let mut contacts = Vec::new();
    let mut work = WorkCounters::default();
    for (k, depth, _) in &answers {
        let height = 0.1 + 0.005 - 0.001 * *k as f64;
        let pose = Isometry3::new(
            Vector3::new(0.0, 0.0, height),
            Vector3::x() * 0.002 * *k as f64,
        );
        pair.query(&pose, &world, &mut contacts, &mut work)
            .expect("finite poses");
        let again = contacts.iter().map(|c| c.penetration).fold(0.0, f64::max);
        if again.to_bits() != depth.to_bits() {
            eprintln!("error: step {k}: threaded depth {depth:e} differs from serial {again:e}");
            return ExitCode::FAILURE;
        }
    }
    println!("threaded answers equal the serial ones bit for bit");
    ExitCode::SUCCESS
}
