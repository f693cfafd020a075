//! The Geneva examples (`examples/geneva/`: STL meshes; `examples/geneva_primitives/`: a
//! cylinder and boxes) against the ideal kinematics of a 4-slot external Geneva drive, and the
//! committed meshes against their generator.
//!
//! The oracle, written here apart from the model: with centre distance `a`, crank radius
//! `r = a·sin(π/4)` and the crank angle `θ` measured from the line of centres, the pin is in a
//! slot while `|θ| ≤ π/4`, and the slot then points at the pin: `tan β = r sin θ / (a − r cos θ)`.
//! The wheel turns clockwise by `β + π/4` during engagement `m` (its `m` earlier steps of
//! `π/2` before), and rests at a multiple of `π/2` between engagements.
//!
//! The bound. The pin's centre may sit anywhere across the slot's play, `c/2` either side of the
//! centre line (`c` the clearance), and sinks `δ` into the wall it presses (the contact's
//! penetration at that instant, reported by the run); its polygon lies within `s` of the
//! circle (plus the STL's single-precision rounding). The crank angle is the run's own (the
//! MOTION is met to the integrator's ERROR, about 4e-4 rad here). Seen from the wheel's axis at distance `ρ` from the pin, the slot can be off the pin by
//! `asin((c/2 + δ + s)/ρ)`, and no more, while the pin lies wholly between the walls (in the
//! last pin radius before the mouth it overhangs the walls' ends and may slip round them).

use contact::dataset;
use contact::geneva::GenevaDimensions;
use contact::run::lower::lower;
use contact::solver::bdf::IntegratorSettings;
use contact::solver::contact_force::Analysis;
use contact::solver::simulate::{DynamicsSettings, simulate};
use contact_core::{FacetingTolerance, GeometryEngine, GeometryInstance};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};
use std::path::{Path, PathBuf};

const CENTRE_DISTANCE: f64 = 0.1;
const CLEARANCE: f64 = 0.001;
const PIN_RADIUS: f64 = 0.006;
const PIN_SIDES: f64 = 96.0;
/// The crank's angle at t = 0 (0.3 rad before the first engagement), and its speed (MOTION/1).
const CRANK_START: f64 = -FRAC_PI_4 - 0.3;
const CRANK_SPEED: f64 = TAU;

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name)
}

/// The ideal wheel angle (about +z, from its starting pose) at crank angle `theta`, and the
/// distance from the wheel's axis to the pin while engaged.
fn ideal_wheel_angle(theta: f64) -> (f64, Option<f64>) {
    let (a, r) = (CENTRE_DISTANCE, CENTRE_DISTANCE * FRAC_PI_4.sin());
    let turn = (theta / TAU).round();
    let local = theta - turn * TAU;
    let done = -turn * FRAC_PI_2;
    if local < -FRAC_PI_4 {
        (done, None)
    } else if local > FRAC_PI_4 {
        (done - FRAC_PI_2, None)
    } else {
        let (y, x) = (r * local.sin(), a - r * local.cos());
        (done - (y.atan2(x) + FRAC_PI_4), Some(x.hypot(y)))
    }
}

/// One frame of a run: time, crank and wheel angles about +z (unwrapped), deepest penetration.
struct Sample {
    t: f64,
    crank: f64,
    wheel: f64,
    penetration: f64,
}

/// `about_z` unwrapped to within π of `previous`.
fn unwrap(previous: Option<f64>, about_z: f64) -> f64 {
    previous.map_or(about_z, |last| {
        last + (about_z - last + PI).rem_euclid(TAU) - PI
    })
}

/// Runs a Geneva dataset to `end` with `engine`; `None` when the engine refuses the model (the
/// error message is returned).
fn run(
    name: &str,
    engine: &dyn GeometryEngine,
    end: f64,
) -> Result<(Vec<Sample>, contact::solver::simulate::RunSummary), String> {
    let loaded = dataset::read(&example(&format!("{name}/{name}.adm")), None).unwrap();
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let meshes = |file: &contact::model::MeshFile| -> Result<GeometryInstance, String> {
        let stl =
            contact_core::mesh_file::stl::read_stl(&file.path, false).map_err(|e| e.to_string())?;
        Ok(
            GeometryInstance::new(contact_core::Geometry::Mesh(std::sync::Arc::new(stl.mesh)))
                .at(file.pose_part_geometry)
                .labeled(file.label.clone()),
        )
    };
    let mut lowered =
        lower(&loaded.model, engine, Analysis::Dynamics, &meshes).map_err(|e| e.to_string())?;
    let (driver, wheel) = (lowered.parts[0].0, lowered.parts[1].0);
    let settings = DynamicsSettings {
        start: 0.0,
        end,
        output_step: 2e-3,
        integrator: IntegratorSettings {
            error: loaded.model.integrator.error,
            ..IntegratorSettings::default()
        },
    };
    let mut samples: Vec<Sample> = Vec::new();
    let summary = simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            let about_z = |part: contact::solver::mbs::PartId| {
                let q = frame.parts[part.0].pose_w.rotation;
                2.0 * q.k.atan2(q.w)
            };
            let last = samples.last();
            let crank = unwrap(
                last.map(|s| s.crank).or(Some(CRANK_SPEED * frame.t)),
                about_z(driver),
            );
            let wheel = unwrap(last.map(|s| s.wheel), about_z(wheel));
            let penetration = frame.contacts[0]
                .iter()
                .map(|c| c.contact.penetration)
                .fold(0.0, f64::max);
            samples.push(Sample {
                t: frame.t,
                crank,
                wheel,
                penetration,
            });
            Ok(())
        },
    )
    .map_err(|e| e.to_string())?;
    Ok((samples, summary))
}

/// Asserts the run against the ideal kinematics; returns the worst engaged error relative to
/// its bound.
/// `sag` is how far the pin's facets lie inside its circle.
fn assert_follows_the_ideal_drive(samples: &[Sample], sag: f64) -> f64 {
    let half_width = PIN_RADIUS + 0.5 * CLEARANCE;
    let mouth = (0.5 * CENTRE_DISTANCE * CENTRE_DISTANCE - half_width * half_width).sqrt();
    let mut worst_ratio: f64 = 0.0;
    let mut engaged = 0;
    for s in samples {
        // The crank's angle as the run has it (the MOTION is met to the integrator's ERROR).
        let theta = CRANK_START + s.crank;
        let (ideal, rho) = ideal_wheel_angle(theta);
        let error = s.wheel - ideal;
        if let Some(rho) = rho.filter(|&rho| rho <= mouth - PIN_RADIUS) {
            engaged += 1;
            // The penetration stays the compliance of a few newtons on a 1e6 stiffness.
            assert!(
                s.penetration < 1e-3,
                "t = {}: penetration {}",
                s.t,
                s.penetration
            );
            // At first touch the wheel sits exactly the play behind the ideal drive, so the
            // bound is attained there; the two sides come from different formulas and may
            // differ in their last bits (1e-15 relative, seen with the exact engine).
            let bound = ((0.5 * CLEARANCE + s.penetration + sag) / rho).asin() * (1.0 + 1e-12);
            assert!(
                error.abs() <= bound,
                "t = {}: wheel {} rad, ideal {ideal} rad, off by {error} > {bound}",
                s.t,
                s.wheel
            );
            worst_ratio = worst_ratio.max(error.abs() / bound);
        }
    }
    assert!(engaged > 50, "only {engaged} engaged frames");
    // The step ends at 90°: once the detent has settled the wheel (0.4 s after the pin left),
    // it rests within 0.1° of its indexed position until the next engagement.
    for s in samples {
        let theta = CRANK_START + s.crank;
        let local = theta - (theta / TAU).round() * TAU;
        if local < -FRAC_PI_4 && s.t > 0.7 {
            let (ideal, _) = ideal_wheel_angle(theta);
            assert!(
                (s.wheel - ideal).abs() < 0.1f64.to_radians(),
                "t = {}: resting at {} rad, indexed {ideal} rad",
                s.t,
                s.wheel
            );
        }
    }
    worst_ratio
}

#[test]
fn the_committed_meshes_are_what_the_generator_writes() {
    let dir = std::env::temp_dir().join(format!("contact-geneva-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let dimensions = GenevaDimensions::default();
    assert_eq!(dimensions.centre_distance, CENTRE_DISTANCE);
    assert_eq!(dimensions.crank_start_angle, CRANK_START);
    dimensions.write_meshes(&dir).unwrap();
    for name in ["geneva_driver.stl", "geneva_wheel.stl"] {
        let fresh = std::fs::read(dir.join(name)).unwrap();
        let committed = std::fs::read(example("geneva").join(name)).unwrap();
        assert!(
            fresh == committed,
            "{name} differs from the generator's output: run `cargo run --example geneva_meshes`"
        );
        // Closed, as the faceted engine needs for inside tests.
        contact_core::mesh_file::stl::read_stl(&dir.join(name), false).unwrap();
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_meshed_geneva_wheel_indexes_as_the_ideal_drive() {
    let engine = contact::engine_choice::build_engine(
        contact_core::GeometryLibrary::Faceted,
        FacetingTolerance::default(),
    );
    let (samples, _) = run("geneva", engine.as_ref(), 1.04).unwrap();
    // The exact engine answers the two meshes as given too, by the same polyhedral
    // intersection: the same drive, sample by sample.
    let (by_exact, _) = run("geneva", &engine_exact::ExactEngine, 1.04).unwrap();
    assert_eq!(by_exact.len(), samples.len());
    for (e, f) in by_exact.iter().zip(&samples) {
        assert!(
            (e.wheel - f.wheel).abs() <= 1e-12,
            "t = {}: exact {} rad, faceted {} rad",
            e.t,
            e.wheel,
            f.wheel
        );
    }
    // The STL pin is a polygon of PIN_SIDES sides with its corners on the circle; STL stores
    // single precision, 2⁻²⁴ of the coordinates' size (0.1) on each of the two meshes.
    let sag = PIN_RADIUS * (1.0 - (PI / PIN_SIDES).cos()) + 2.0 * 0.1 * 2f64.powi(-24);
    let worst = assert_follows_the_ideal_drive(&samples, sag);
    assert!(worst > 0.0);
    let last = samples.last().unwrap();
    assert!(
        (last.wheel + FRAC_PI_2).abs() < 0.1f64.to_radians(),
        "{}",
        last.wheel
    );
}

#[test]
fn the_primitive_geneva_indexes_as_the_ideal_drive_with_each_engine_that_answers_it() {
    let faceted = contact::engine_choice::build_engine(
        contact_core::GeometryLibrary::Faceted,
        FacetingTolerance::default(),
    );
    let (by_facets, _) = run("geneva_primitives", faceted.as_ref(), 1.04).unwrap();
    // The tessellated pin lies within its chord deviation L/FT of the cylinder (L its bounding
    // box's diagonal, the cylinder's LENGTH being 0.014).
    let length = 0.014_f64;
    let diagonal = (8.0 * PIN_RADIUS * PIN_RADIUS + length * length).sqrt();
    let chord = FacetingTolerance::default().chord_deviation(diagonal);
    assert_follows_the_ideal_drive(&by_facets, chord);
    // The exact engine answers a cylinder against a box: the same drive within the same
    // bound. The two runs stay apart by no more than the chord deviation (and the difference
    // of their penetrations) seen from the wheel's centre, plus the slot's play: past
    // mid-stroke the wheel runs ahead of the pin onto the slot's other flank, and a
    // faceting-sized difference in the force moves that instant, so for a while one run has
    // the wheel on one flank and the other on the other.
    let (exact, _) = run("geneva_primitives", &engine_exact::ExactEngine, 1.04).unwrap();
    assert_follows_the_ideal_drive(&exact, 0.0);
    let half_width = PIN_RADIUS + 0.5 * CLEARANCE;
    let mouth = (0.5 * CENTRE_DISTANCE * CENTRE_DISTANCE - half_width * half_width).sqrt();
    let mut compared = 0;
    for (e, f) in exact.iter().zip(&by_facets) {
        assert!((e.t - f.t).abs() < 1e-12, "frames at the same times");
        let (_, rho) = ideal_wheel_angle(CRANK_START + e.crank);
        if let Some(rho) = rho.filter(|&rho| rho <= mouth - PIN_RADIUS) {
            compared += 1;
            let apart = (e.wheel - f.wheel).abs();
            let faceting = chord + (e.penetration - f.penetration).abs();
            let allowed = ((CLEARANCE + faceting) / rho).asin();
            assert!(
                apart <= allowed,
                "t = {}: exact {} rad, faceted {} rad, apart {apart} > {allowed}",
                e.t,
                e.wheel,
                f.wheel
            );
        }
    }
    assert!(compared > 50, "only {compared} engaged frames compared");
}

/// The drive with its locking disc, the wheel turned past the lock's play in mid-dwell: the
/// disc overlaps a locking arc in a thin crescent whose volume centroid lies outside it, and
/// the penetration must stay the crescent's thickness (the deepest the wheel's arc vertices
/// reach inside the disc), not where the line through that centroid meets the far side.
#[test]
fn a_locking_disc_pressed_into_its_arc_penetrates_by_the_crescents_thickness() {
    use contact_core::{Geometry, Isometry3, Vector3, WorkCounters};
    let d = GenevaDimensions {
        locking_disc: true,
        ..GenevaDimensions::default()
    };
    let mesh = |triangles: Vec<contact::geneva::Triangle>| {
        let corners: Vec<[contact_core::Point3; 3]> = triangles
            .iter()
            .map(|t| t.map(contact_core::Point3::from))
            .collect();
        let (vertices, faces) = contact_core::mesh_file::stl::weld(&corners);
        GeometryInstance::new(Geometry::Mesh(std::sync::Arc::new(
            contact_core::geometry::TriangleMesh::new(vertices, faces).unwrap(),
        )))
    };
    let engine = engine_facet::FacetEngine::default();
    let pair = engine
        .prepare(&[mesh(d.driver_triangles())], &[mesh(d.wheel_triangles())])
        .unwrap();
    // Mid-dwell: the crank points away from the wheel.
    let pose_driver = Isometry3::rotation(Vector3::z() * (PI - d.crank_start_angle));
    let disc = d.locking_disc_radius();
    // The facets' chords: the disc's inward, the arcs' toward the disc.
    let rim = d.rim_radius();
    let spread =
        (rim * d.lock_tip_angle.sin()).atan2(CENTRE_DISTANCE - rim * d.lock_tip_angle.cos());
    let sag = disc * (1.0 - (PI / d.disc_segments as f64).cos())
        + d.lock_arc_radius() * (1.0 - (spread / d.lock_segments as f64).cos());
    let mut checked = 0;
    for turns in [1.5, 2.0, 3.0, 5.0] {
        for sign in [1.0, -1.0] {
            let w = sign * turns * d.lock_clearance / CENTRE_DISTANCE;
            let pose_wheel = Isometry3::from_parts(
                nalgebra::Translation3::new(CENTRE_DISTANCE, 0.0, 0.0),
                nalgebra::UnitQuaternion::from_axis_angle(&Vector3::z_axis(), w),
            );
            // The crescent's thickness: how far the wheel's outline reaches inside the disc.
            let thickness = d
                .wheel_outline()
                .iter()
                .map(|p| {
                    let q = pose_wheel * contact_core::Point3::new(p[0], p[1], 0.0);
                    disc - q.coords.xy().norm()
                })
                .fold(0.0, f64::max);
            let (mut contacts, mut work) = (Vec::new(), WorkCounters::default());
            pair.query(&pose_driver, &pose_wheel, &mut contacts, &mut work)
                .unwrap();
            assert!(!contacts.is_empty(), "turned {w}: no contact");
            for c in &contacts {
                assert!(
                    c.penetration <= 1.5 * (thickness + sag),
                    "turned {w} rad: penetration {} for a crescent {thickness} thick",
                    c.penetration
                );
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 8);
}
