//! The first-hour path with both engines: a sphere on a box, queried from two threads, forces
//! from IMPACT and Coulomb friction through the kinematics helper; a mesh read from a file.

use super::*;
use contact_core::geometry::{Cuboid, Plane};
use contact_core::laws::{CoulombParams, ImpactParams};
use contact_core::{Geometry, GeometryInstance, Isometry3, PreparedPair, WorkCounters};

const LIBRARIES: [GeometryLibrary; 2] = [GeometryLibrary::Exact, GeometryLibrary::Faceted];

fn fine() -> FacetingTolerance {
    FacetingTolerance::new(3000.0).unwrap()
}

fn impact() -> ImpactLaw {
    ImpactLaw::from_params(ImpactParams {
        stiffness: 1e7,
        exponent: 1.5,
        damping: 1e3,
        max_penetration: 1e-3,
    })
    .unwrap()
}

fn coulomb() -> CoulombFriction {
    CoulombFriction::from_params(CoulombParams {
        mu_static: 0.3,
        mu_dynamic: 0.2,
        stiction_velocity: 0.01,
        friction_velocity: 0.1,
    })
    .unwrap()
}

/// A ball of radius 0.5 (I) over a 2 × 2 × 2 box centred at the origin (J).
fn sphere_on_box(library: GeometryLibrary) -> Box<dyn PreparedPair> {
    let ball = GeometryInstance::new(Geometry::sphere(0.5).unwrap());
    let block = GeometryInstance::new(Geometry::Cuboid(Cuboid::centered(1.0, 1.0, 1.0).unwrap()));
    engine(library, fine()).prepare(&[ball], &[block]).unwrap()
}

/// The ball's motion at step `k`: sinking 1 mm per step from 1 mm above the box, sliding along
/// x and spinning about z; the box at rest.
fn ball_at(k: usize) -> BodyMotion {
    BodyMotion {
        pose_w: Isometry3::new(
            Vector3::new(0.1 + 0.001 * k as f64, -0.2, 1.501 - 0.001 * k as f64),
            Vector3::z() * 0.05 * k as f64,
        ),
        velocity_w: Vector3::new(0.3, 0.0, -0.5),
        angular_velocity_w: Vector3::new(0.0, 0.0, 4.0),
    }
}

fn loads(pair: &dyn PreparedPair, k: usize) -> Vec<ContactLoad> {
    let ground = BodyMotion::at_rest(Isometry3::identity());
    let ball = ball_at(k);
    let mut contacts = Vec::new();
    pair.query(
        &ball.pose_w,
        &ground.pose_w,
        &mut contacts,
        &mut WorkCounters::default(),
    )
    .unwrap();
    let (impact, friction) = (impact(), coulomb());
    contacts
        .iter()
        .map(|c| contact_load(c, &ball, &ground, &impact, Some(&friction)))
        .collect()
}

#[test]
fn engines_are_chosen_by_their_adams_names() {
    for (name, expected) in [
        ("PARASOLID", "exact"),
        ("exact", "exact"),
        ("DEFAULT_LIBRARY", "faceted"),
        ("RAPID", "faceted"),
        ("faceted", "faceted"),
    ] {
        let library: GeometryLibrary = name.parse().unwrap();
        assert_eq!(engine(library, fine()).name(), expected, "{name}");
    }
    assert!("ACIS".parse::<GeometryLibrary>().is_err());
}

/// Both engines: the ball 0.009 deep at step 10 is pushed up by the spring and the damping
/// (approaching at 0.5 m/s, past DMAX), and friction opposes its slip (0.3 m/s along x plus
/// the spin's contribution at the contact point, which lies on the spin axis: none), sharing
/// the Coulomb budget with the spin.
#[test]
fn a_sliding_ball_on_a_box_gets_impact_and_friction_from_both_engines() {
    for library in LIBRARIES {
        let pair = sphere_on_box(library);
        assert!(
            loads(pair.as_ref(), 0).is_empty(),
            "{library}: apart at step 0"
        );
        let at = loads(pair.as_ref(), 10);
        assert_eq!(at.len(), 1, "{library}: {at:?}");
        let load = at[0];
        let k = load.kinematics;
        assert!((k.penetration_rate - 0.5).abs() < 1e-3, "{library}: {k:?}");
        assert!(
            (k.slip_velocity_w - Vector3::new(0.3, 0.0, 0.0)).norm() < 2e-3,
            "{library}: {k:?}"
        );
        assert!((k.spin - 4.0).abs() < 1e-2, "{library}: {k:?}");
        let expected = 1e7 * 0.009_f64.powf(1.5) + 1e3 * 0.5;
        assert!(
            (load.normal_force - expected).abs() < 0.05 * expected,
            "{library}: {load:?} against {expected}"
        );
        // Sliding well past the friction transition velocity: μd = 0.2, against the slip, its
        // budget shared with the spin over the cap of radius R, R² = 2rδ − δ²:
        // |F_t| = μd·Fn·v/sqrt(v² + (ω·R)²).
        let friction = load.force_w - load.force_w.dot(&Vector3::z()) * Vector3::z();
        let rim = 4.0 * (2.0 * 0.5 * 0.009 - 0.009_f64.powi(2)).sqrt();
        let share = 0.3 / 0.3_f64.hypot(rim);
        assert!(
            (friction.x + 0.2 * share * load.normal_force).abs() < 0.05 * load.normal_force * share,
            "{library}: {load:?}"
        );
        assert!(load.force_w.z > 0.0, "{library}: {load:?}");
    }
}

/// A prepared pair is shared by reference between threads (queries take `&self`); two threads
/// taking every other step give the serial answers bit for bit, with both engines.
#[test]
fn two_threads_give_the_serial_bits() {
    for library in LIBRARIES {
        let pair = sphere_on_box(library);
        let steps: Vec<usize> = (0..16).collect();
        let threaded: Vec<(usize, Vec<ContactLoad>)> = std::thread::scope(|scope| {
            let handles: Vec<_> = (0..2)
                .map(|thread| {
                    let (pair, steps) = (pair.as_ref(), &steps);
                    scope.spawn(move || {
                        steps
                            .iter()
                            .skip(thread)
                            .step_by(2)
                            .map(|&k| (k, loads(pair, k)))
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            handles
                .into_iter()
                .flat_map(|h| h.join().unwrap())
                .collect()
        });
        assert_eq!(threaded.len(), steps.len());
        let bits = |l: &ContactLoad| {
            [
                l.normal_force,
                l.force_w.x,
                l.force_w.y,
                l.force_w.z,
                l.torque_w.z,
            ]
            .map(f64::to_bits)
        };
        for (k, answer) in &threaded {
            let serial = loads(pair.as_ref(), *k);
            assert_eq!(answer.len(), serial.len(), "{library} step {k}");
            for (a, s) in answer.iter().zip(&serial) {
                assert_eq!(bits(a), bits(s), "{library} step {k}");
            }
        }
        assert!(threaded.iter().any(|(_, l)| !l.is_empty()), "{library}");
    }
}

/// A mesh read from an OBJ file stands on the ground with either engine: a unit tetrahedron
/// with its base face 0.01 into the ground plane gives depth 0.01 and the normal +z.
#[test]
fn a_mesh_from_a_file_answers_with_both_engines() {
    let path = std::env::temp_dir().join(format!("contact-embedder-{}.obj", std::process::id()));
    std::fs::write(
        &path,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    )
    .unwrap();
    let tetra = contact_core::mesh_file::read_mesh_geometry(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    let ground = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
    for library in LIBRARIES {
        let pair = engine(library, fine())
            .prepare(
                &[GeometryInstance::new(tetra.clone())],
                std::slice::from_ref(&ground),
            )
            .unwrap();
        let mut contacts = Vec::new();
        pair.query(
            &Isometry3::translation(0.0, 0.0, -0.01),
            &Isometry3::identity(),
            &mut contacts,
            &mut WorkCounters::default(),
        )
        .unwrap();
        assert_eq!(contacts.len(), 1, "{library}: {contacts:?}");
        let c = contacts[0];
        assert!((c.penetration - 0.01).abs() < 1e-9, "{library}: {c:?}");
        assert!(
            (c.normal_w - Vector3::z()).norm() < 1e-9,
            "{library}: {c:?}"
        );
    }
}
