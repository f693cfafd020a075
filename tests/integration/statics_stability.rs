//! EQUILIBRIUM/STABILITY: the fraction of the mass and damping matrices added to the stiffness
//! matrix of the static Jacobian. It makes a neutral equilibrium solvable by Newton and does
//! not move the equilibrium.

use crate::statics::lowered;
use contact::solver::frame::compute_frame;
use contact::solver::statics::newton::{self, imbalance, static_jacobian, static_residual};
use contact::solver::statics::{StaticsMethod, StaticsSettings, solve_statics};
use nalgebra::{DMatrix, DVector};

/// A sphere (radius 0.1, mass 1, inertia 0.004; kg, m) with its CM at `(0.01, −0.02, 0.0995)`,
/// pressed 0.5 mm into a ground plane through an IMPACT contact (k = 1e6, e = 1.5, c = 50,
/// dmax = 1e-4), gravity 9.81. The contact holds it vertically; sideways and in every rotation
/// nothing does: a neutral equilibrium in five directions.
const PRESSED_SPHERE: &str = "sphere pressed into a plane\n\
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
PART/1, GROUND\nMARKER/10, PART = 1\n\
PART/2, MASS = 1, CM = 20, IP = 0.004, 0.004, 0.004\n\
MARKER/20, PART = 2, QP = 0.01, -0.02, 0.0995, REULER = 10D, 20D, 30D\n\
GRAPHICS/1, ELLIPSOID, CM = 20, XSCALE = 0.2, YSCALE = 0.2, ZSCALE = 0.2\n\
GRAPHICS/2, PLANE, RM = 10\n\
CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT, STIFFNESS = 1E6, EXPONENT = 1.5, DAMPING = 50, DMAX = 1E-4\n\
ACCGRAV/ KGRAV = -9.81\nEND\n";

/// The resting penetration: k·δ^e = m·g.
fn resting_penetration() -> f64 {
    (9.81 / 1e6_f64).powf(1.0 / 1.5)
}

fn settings(stability: f64) -> StaticsSettings {
    StaticsSettings {
        error: 1e-10,
        imbalance: 1e-9,
        stability,
        ..StaticsSettings::default()
    }
}

#[test]
fn stability_adds_the_mass_and_the_contact_damping_to_the_static_jacobian() {
    let mut model = lowered("stability_jacobian.adm", PRESSED_SPHERE);
    let y = model.system.given_state().clone();
    let without = static_jacobian(&mut model.system, 0.0, &y, 0.0).unwrap();
    // The damping matrix of the contact, by hand: past dmax (δ = 0.5 mm > 0.1 mm) the IMPACT
    // damping is the full c = 50 on the normal rate −u_z; the force acts through the CM (the
    // contact point is straight below it), so no other velocity enters and no torque results.
    let (mass, inertia, c) = (1.0, 0.004, 50.0);
    let mut expected = DMatrix::<f64>::zeros(6, 6);
    for i in 0..3 {
        expected[(i, i)] = mass;
        expected[(i + 3, i + 3)] = inertia;
    }
    expected[(2, 2)] += c;
    for stability in [1e-3, 0.1, 2.0] {
        let with = static_jacobian(&mut model.system, 0.0, &y, stability).unwrap();
        let added = (&with - &without) / stability;
        let error = (added.view((0, 0), (6, 6)) - &expected).amax();
        assert!(
            error < 1e-6 * c,
            "STABILITY {stability}: added {added} vs {expected}"
        );
        // Nothing is added outside the position columns of the dynamic rows.
        assert_eq!(added.nrows(), 6);
    }
}

#[test]
fn a_neutral_equilibrium_needs_stability_and_every_stability_finds_the_same_equilibrium() {
    let mut model = lowered("stability_neutral.adm", PRESSED_SPHERE);
    let start = model.system.given_state().clone();
    // Without STABILITY the static Jacobian is singular in the five free directions.
    let mut y = start.clone();
    let failure = newton::solve(&mut model.system, 0.0, &mut y, &settings(0.0), true).unwrap_err();
    assert!(failure.cause.contains("singular"), "{failure}");
    // The quasi-dynamic method settles the sphere but its closing Newton is singular too: a
    // neutral equilibrium needs STABILITY.
    let error = solve_statics(&mut model.system, 0.0, &start, &settings(0.0)).unwrap_err();
    let message = error.to_string();
    assert!(
        message.contains("quasi-dynamic") && message.matches("singular").count() == 2,
        "{message}"
    );
    let expected = resting_penetration();
    let mut iterations = Vec::new();
    let mut states: Vec<DVector<f64>> = Vec::new();
    for stability in [1e-5, 1e-2, 1.0, 10.0] {
        let found = solve_statics(&mut model.system, 0.0, &start, &settings(stability)).unwrap();
        assert_eq!(found.method, StaticsMethod::Newton, "STABILITY {stability}");
        // The residual Newton drove to zero is the static residual without STABILITY.
        let r = static_residual(&mut model.system, 0.0, &found.y).unwrap();
        assert!(
            imbalance(&model.system, &r) <= 1e-9,
            "STABILITY {stability}"
        );
        let frame = compute_frame(&model.system, &model.contacts, 0.0, &found.y).unwrap();
        let sphere = frame.parts[1].pose_w;
        let penetration = frame.contacts[0][0].contact.penetration;
        assert!(
            (penetration - expected).abs() < 1e-9 * expected,
            "STABILITY {stability}: δ = {penetration} vs {expected}"
        );
        assert!(((0.1 - sphere.translation.z) - expected).abs() < 1e-9 * expected);
        // Sideways and in rotation it stays where it was put.
        assert!((sphere.translation.x - 0.01).abs() < 1e-12);
        assert!((sphere.translation.y + 0.02).abs() < 1e-12);
        let given = model.system.given_state();
        assert!((found.y.fixed_rows::<4>(3) - given.fixed_rows::<4>(3)).amax() < 1e-12);
        iterations.push(found.iterations);
        states.push(found.y.rows(0, 7).into_owned());
    }
    for (k, state) in states.iter().enumerate() {
        let spread = (state - &states[0]).amax();
        assert!(spread < 1e-9 * expected, "STABILITY case {k}: {spread:e}");
    }
    // STABILITY acts on the iteration: a large fraction of M + C slows Newton down.
    assert!(iterations[3] > iterations[0], "{iterations:?}");
    // EQUILIBRIUM/DYNAMIC reaches the same equilibrium by damped dynamics and Newton.
    let dynamic = StaticsSettings {
        dynamic: true,
        ..settings(1e-5)
    };
    let settled = solve_statics(&mut model.system, 0.0, &start, &dynamic).unwrap();
    let spread = (settled.y.rows(0, 3) - states[0].rows(0, 3)).amax();
    assert!(spread < 1e-9 * expected, "{spread:e}");
}
