//! A block and a plate sliding down a 30° incline (gravity tilted, the plane level): the
//! distance slid against the closed form `½·g·(sin θ − μd·cos θ)·t²`, each faceted run against
//! the exact one, and the steps each takes.
//!
//! A box's tessellation is the box at every FT, so its faceted run answers as the exact one to
//! round-off; the plate is a flat cylinder, whose faceted face is a polygon inscribed in its
//! circle: its contact point is the polygon's centroid (the circle's centre), its normal the
//! plane's, and its force the same, so it slides as the exact plate does.

use super::{G, engines, run};

const THETA_DEG: f64 = 30.0;
const MU_DYNAMIC: f64 = 0.25;
/// IMPACT stiffness and exponent: the bodies start at their static penetration.
const STIFFNESS: f64 = 1e7;
const EXPONENT: f64 = 1.5;
const SLIDE_TIME: f64 = 1.0;

/// A 1 kg body (`geometry`, a GRAPHICS statement on marker 21 at its bottom face's centre,
/// `thickness` thick, inertia `ip`) resting flat on the ground plane at its static penetration,
/// with gravity tilted by `THETA_DEG` along +x.
fn on_incline(geometry: &str, thickness: f64, ip: [f64; 3]) -> String {
    let theta = THETA_DEG.to_radians();
    let penetration = (G * theta.cos() / STIFFNESS).powf(1.0 / EXPONENT);
    format!(
        "body on a {THETA_DEG} degree incline\n\
         UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
         PART/1, GROUND\nMARKER/10, PART = 1\n\
         PART/2, MASS = 1, CM = 20, IP = {}, {}, {}\n\
         MARKER/20, PART = 2, QP = 0, 0, {}\n\
         MARKER/21, PART = 2, QP = 0, 0, {}\n\
         MARKER/22, PART = 2, QP = -0.1, -0.1, {}\n\
         {geometry}\n\
         GRAPHICS/2, PLANE, RM = 10\n\
         CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT\n\
         , STIFFNESS = {STIFFNESS}, EXPONENT = {EXPONENT}, DAMPING = 1E3, DMAX = 1E-4\n\
         , COULOMB_FRICTION = ON, MU_STATIC = 0.3, MU_DYNAMIC = {MU_DYNAMIC}\n\
         , STICTION_TRANSITION_VELOCITY = 0.01, FRICTION_TRANSITION_VELOCITY = 0.02\n\
         ACCGRAV/ IGRAV = {}, KGRAV = {}\nEND\n",
        ip[0],
        ip[1],
        ip[2],
        0.5 * thickness - penetration,
        -penetration,
        -penetration,
        G * theta.sin(),
        -G * theta.cos()
    )
}

#[test]
fn a_block_and_a_plate_slide_down_an_incline_as_the_closed_form() {
    let theta = THETA_DEG.to_radians();
    let closed = 0.5 * G * (theta.sin() - MU_DYNAMIC * theta.cos()) * SLIDE_TIME * SLIDE_TIME;
    let (r, plate) = (0.1, 0.01);
    let bodies = [
        (
            "block",
            on_incline(
                "GRAPHICS/1, BOX, CORNER = 22, X = 0.2, Y = 0.2, Z = 0.2",
                0.2,
                [0.2 * 0.2 / 6.0; 3],
            ),
        ),
        (
            "plate",
            on_incline(
                &format!("GRAPHICS/1, CYLINDER, CM = 21, RADIUS = {r}, LENGTH = {plate}"),
                plate,
                [
                    (3.0 * r * r + plate * plate) / 12.0,
                    (3.0 * r * r + plate * plate) / 12.0,
                    0.5 * r * r,
                ],
            ),
        ),
    ];
    for (body, text) in bodies {
        let mut exact: Option<(f64, u64)> = None;
        for (name, engine) in engines() {
            let (samples, summary) = run(&text, engine.as_ref(), SLIDE_TIME, 0.01, 1e-6);
            let (first, last) = (&samples[0], &samples[samples.len() - 1]);
            let slid = last.part.pose_w.translation.x - first.part.pose_w.translation.x;
            let steps = summary.integrator.steps;
            println!(
                "{body} on the incline, {name}: slid {slid:.6} in {SLIDE_TIME} s \
                 (closed form {closed:.6}), {steps} steps"
            );
            // The stiction band holds the body for the first few ms: within 1% of the
            // closed form, which starts sliding at once.
            assert!(
                (slid - closed).abs() < 0.01 * closed,
                "{body}, {name}: slid {slid}"
            );
            match exact {
                None => exact = Some((slid, steps)),
                Some((exact_slid, exact_steps)) => {
                    // The faceted face's contact is the exact face's (see the module's docs):
                    // the runs agree to the integrator's error.
                    assert!(
                        (slid - exact_slid).abs() < 1e-5,
                        "{body}, {name}: {slid} against {exact_slid}"
                    );
                    assert!(
                        2 * steps <= 3 * exact_steps,
                        "{body}, {name}: {steps} steps against {exact_steps}"
                    );
                }
            }
        }
    }
}
