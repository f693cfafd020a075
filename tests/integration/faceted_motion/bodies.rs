//! Bodies other than spheres in motion: a block rocking back onto its base, a torus bouncing
//! and an ellipsoid dropped and settled, each engine against the oracle or the exact run.

use super::*;

/// A block 2b × 2b × 2h (b = 0.1, h = 0.2, 1 kg) tilted by `tilt` about its bottom edge at
/// x = b, resting on that edge on a frictionless ground plane.
fn tilted_block(tilt: f64) -> String {
    let (b, h) = (0.1_f64, 0.2_f64);
    let (c, s) = (tilt.cos(), tilt.sin());
    // Body vectors turned about +y by `tilt` (the side at x = −b rises).
    let turn = |x: f64, z: f64| (x * c + z * s, -x * s + z * c);
    let (cx, cz) = turn(-b, h);
    let (kx, kz) = turn(-2.0 * b, 0.0);
    let (ixx, izz) = ((4.0 * b * b + 4.0 * h * h) / 12.0, 8.0 * b * b / 12.0);
    format!(
        "rocking block
         UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND
         PART/1, GROUND
MARKER/10, PART = 1
         PART/2, MASS = 1, CM = 20, IP = {ixx}, {ixx}, {izz}
         MARKER/20, PART = 2, QP = {x}, 0, {z}, REULER = 90D, {deg}D, -90D
         MARKER/21, PART = 2, QP = {kx}, {y}, {kz}, REULER = 90D, {deg}D, -90D
         GRAPHICS/1, BOX, CORNER = 21, X = {w}, Y = {w}, Z = {t}
         GRAPHICS/2, PLANE, RM = 10
         CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT, STIFFNESS = 1E9, EXPONENT = 1.5
         , DAMPING = 1E3, DMAX = 1E-5
         ACCGRAV/ KGRAV = -9.81
END
",
        x = b + cx,
        z = cz,
        kx = b + kx,
        kz = kz,
        y = -b,
        deg = tilt.to_degrees(),
        w = 2.0 * b,
        t = 2.0 * h,
    )
}

#[test]
fn a_frictionless_rocking_block_lands_at_the_oracle_time() {
    // A block released on its bottom edge, frictionless: no horizontal force, so its CM falls
    // straight down while the edge slides, z = ρ·cos(α − θ), ρ = √(b² + h²), α = atan(b/h).
    // Lagrange: J(θ)·θ̈ + ½·J′(θ)·θ̇² + m·g·ρ·sin(α − θ) = 0 with J = I_cm + m·ρ²·sin²(α − θ),
    // I_cm = m·ρ²/3, from rest at θ0 until θ = 0 (RK4 here).
    let (b, h, tilt) = (0.1_f64, 0.2_f64, 0.15_f64);
    let rho = b.hypot(h);
    let alpha = (b / h).atan();
    let accel = |theta: f64, omega: f64| {
        let (s, c) = (alpha - theta).sin_cos();
        let j = rho * rho / 3.0 + rho * rho * s * s;
        let dj = -2.0 * rho * rho * s * c;
        -(0.5 * dj * omega * omega + G * rho * s) / j
    };
    let (mut theta, mut omega, mut t, dt) = (tilt, 0.0_f64, 0.0_f64, 1e-6);
    while theta > 0.0 {
        let k1 = (omega, accel(theta, omega));
        let k2 = (
            omega + 0.5 * dt * k1.1,
            accel(theta + 0.5 * dt * k1.0, omega + 0.5 * dt * k1.1),
        );
        let k3 = (
            omega + 0.5 * dt * k2.1,
            accel(theta + 0.5 * dt * k2.0, omega + 0.5 * dt * k2.1),
        );
        let k4 = (
            omega + dt * k3.1,
            accel(theta + dt * k3.0, omega + dt * k3.1),
        );
        theta += dt / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
        omega += dt / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
        t += dt;
    }
    let text = tilted_block(tilt);
    let mut exact_time = None;
    for (name, engine) in engines() {
        let (samples, summary) = run(&text, engine.as_ref(), 1.2 * t, 1e-4, 1e-5);
        // Landing: the contact's area jumps from the edge's to the base's.
        let landed = samples
            .iter()
            .find(|s| {
                s.contacts
                    .iter()
                    .any(|c| c.contact.area > 0.5 * (2.0 * b) * (2.0 * b))
            })
            .map(|s| s.t)
            .unwrap_or_else(|| panic!("{name}: never landed"));
        println!(
            "rocking block, {name}: lands at {landed:.5} (oracle {t:.5}), {} steps",
            summary.integrator.steps
        );
        match exact_time {
            None => {
                assert!((landed - t).abs() < 0.01 * t, "{name}");
                exact_time = Some(landed);
            }
            Some(e) => assert!((landed - e).abs() < 0.01 * e, "{name}"),
        }
    }
}

/// Total energy `½m·v² + ½ωᵀ(R·I·Rᵀ)ω + m·g·z` of a 1 kg part with principal moments
/// `inertia` at each frame free of contact.
fn flight_energies(samples: &[Sample], inertia: nalgebra::Vector3<f64>) -> Vec<f64> {
    let inertia = nalgebra::Matrix3::from_diagonal(&inertia);
    samples
        .iter()
        .filter(|s| s.contacts.is_empty())
        .map(|s| {
            let r = s.part.pose_w.rotation.to_rotation_matrix().into_inner();
            let w = s.part.angular_velocity_w;
            0.5 * s.part.velocity_w.norm_squared()
                + 0.5 * w.dot(&(r * inertia * r.transpose() * w))
                + G * s.part.pose_w.translation.z
        })
        .collect()
}

/// The torus' flight energies for radii R = 0.06, r = 0.04 and mass 1
/// (`I = m·(R²/2 + 5r²/8, R²/2 + 5r²/8, R² + 3r²/4)`).
fn torus_energies(samples: &[Sample]) -> Vec<f64> {
    let (major, minor) = (0.06f64, 0.04f64);
    let diameter = major * major / 2.0 + 5.0 * minor * minor / 8.0;
    let axis = major * major + 3.0 * minor * minor / 4.0;
    flight_energies(samples, nalgebra::Vector3::new(diameter, diameter, axis))
}

#[test]
fn a_faceted_torus_injects_less_than_its_weight_times_the_chord_deviation_per_impact() {
    // A torus (no sphere, no ellipsoid: the facets' own contact answers) dropped at a generic
    // orientation, undamped, frictionless. Energy changes in flight only by the integrator's
    // error; at an impact the facets can give or take energy (the force field of a surface
    // that steps from facet to facet is not a gradient), by at most the work of the weight over
    // the surface's displacement: m·g·d per impact, d = L/FT.
    let text = ball(0.1, "", 1e10, 2.2, 1e-9, "")
        .replace(
            "ELLIPSOID, CM = 20, XSCALE = 0.2, YSCALE = 0.2, ZSCALE = 0.2",
            "TORUS, CM = 20, MAJOR_RADIUS = 0.06, MINOR_RADIUS = 0.04",
        )
        .replace("IP = 0.004, 0.004, 0.004", "IP = 0.0028, 0.0028, 0.0048");
    let change = |engine: &dyn GeometryEngine| {
        let (samples, _) = run(&text, engine, 2.0, 1e-3, 1e-5);
        let impacts = samples
            .windows(2)
            .filter(|w| w[0].contacts.is_empty() && !w[1].contacts.is_empty())
            .count();
        let energies = torus_energies(&samples);
        (energies.last().unwrap() - energies[0], impacts)
    };
    let (exact, impacts) = change(&engine_exact::ExactEngine);
    assert!(impacts >= 5, "{impacts} impacts");
    let torus = contact_core::geometry::Torus::new(0.06, 0.04).unwrap();
    let length = contact_core::Geometry::Torus(torus)
        .characteristic_length()
        .unwrap();
    for ft in TOLERANCES {
        let (faceted, _) = change(&faceted(ft));
        let deviation = FacetingTolerance::new(ft).unwrap().chord_deviation(length);
        let per_impact = (faceted - exact).abs() / impacts as f64;
        println!(
            "torus, FT {ft}: energy change {faceted:.3e} J against the exact run's \
             {exact:.3e} over {impacts} impacts: {per_impact:.3e} J per impact, m·g·d = {:.3e}",
            G * deviation
        );
        assert!(per_impact < G * deviation, "FT {ft}");
    }
}

/// An ellipsoid (semi-axes 0.1, 0.07, 0.05, 1 kg) dropped 0.1 on a plane at a generic
/// orientation with friction, damped: it bounces, rocks and settles.
fn ellipsoid_drop() -> String {
    ball(
        0.1,
        "",
        1e6,
        1.5,
        50.0,
        ", COULOMB_FRICTION = ON, MU_STATIC = 0.3, MU_DYNAMIC = 0.2\n\
         , STICTION_TRANSITION_VELOCITY = 1E-3, FRICTION_TRANSITION_VELOCITY = 2E-3",
    )
    .replace("YSCALE = 0.2, ZSCALE = 0.2", "YSCALE = 0.14, ZSCALE = 0.1")
    .replace("IP = 0.004, 0.004, 0.004", "IP = 0.00148, 0.0025, 0.00298")
}

/// The ellipsoid's total energy after its first impact, at the first frame free of contact.
fn energy_after_first_impact(samples: &[Sample]) -> f64 {
    // I = m/5·(b² + c², a² + c², a² + b²) for semi-axes (0.1, 0.07, 0.05).
    let inertia = nalgebra::Vector3::new(0.00148, 0.0025, 0.00298);
    let first = samples.iter().position(|s| !s.contacts.is_empty()).unwrap();
    let after = first
        + samples[first..]
            .iter()
            .position(|s| s.contacts.is_empty())
            .unwrap();
    flight_energies(&samples[after..=after], inertia)[0]
}

#[test]
fn a_faceted_ellipsoid_bounces_as_the_exact_one_does_in_as_many_steps() {
    // A tessellated ellipsoid on a plane answers as the ellipsoid it stands for (engine-facet's
    // plane_support): its first impact (friction, damping, spin) leaves the energy the exact
    // run's leaves within m·g·d, and the whole 3 s of bouncing and rocking take about as many
    // steps. (Past the first impacts the rocking is sensitive to every digit, so the two runs
    // are compared there by their cost, not their paths.)
    let text = ellipsoid_drop();
    let (exact, exact_summary) = run(&text, &engine_exact::ExactEngine, 3.0, 1e-3, 1e-5);
    let length = (0.2f64.powi(2) + 0.14f64.powi(2) + 0.1f64.powi(2)).sqrt();
    let exact_energy = energy_after_first_impact(&exact);
    for ft in TOLERANCES {
        let (samples, summary) = run(&text, &faceted(ft), 3.0, 1e-3, 1e-5);
        let deviation = FacetingTolerance::new(ft).unwrap().chord_deviation(length);
        let energy = energy_after_first_impact(&samples);
        let (steps, exact_steps) = (summary.integrator.steps, exact_summary.integrator.steps);
        println!(
            "ellipsoid drop, FT {ft}: {steps} steps against {exact_steps}; energy after the \
             first impact {energy:.6} J against {exact_energy:.6} J (m·g·d = {:.2e})",
            G * deviation
        );
        assert!((energy - exact_energy).abs() < G * deviation, "FT {ft}");
        assert!(steps as f64 <= 1.5 * exact_steps as f64, "FT {ft}");
    }
}

#[test]
fn faceted_ellipsoid_statics_settle_where_the_exact_ones_do() {
    // The dropped ellipsoid's equilibrium by STATICS (static Newton, else the quasi-dynamic
    // method): its weight carried by the contact, and at rest with the faceted engine within
    // the chord deviation of the exact engine's height.
    let text = ellipsoid_drop();
    let length = (0.2f64.powi(2) + 0.14f64.powi(2) + 0.1f64.powi(2)).sqrt();
    let mut heights = Vec::new();
    for (name, engine) in engines() {
        let mut model = lowered(&text, engine.as_ref(), Analysis::Quasistatic);
        let y = model.system.given_state().clone();
        let found = solve_statics(&mut model.system, 0.0, &y, &StaticsSettings::default())
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let frame = compute_frame(&model.system, &model.contacts, 0.0, &found.y).unwrap();
        let force: f64 = frame.contacts[0].iter().map(|c| c.normal_force).sum();
        let height = frame.parts[model.parts[0].0.0].pose_w.translation.z;
        println!(
            "ellipsoid statics, {name}: height {height:.9}, normal force {force:.6}, {:?} in \
             {} iterations",
            found.method, found.iterations
        );
        assert!((force - G).abs() < 1e-3 * G, "{name}: {force}");
        heights.push((name, height));
    }
    let exact = heights[0].1;
    for (name, height) in &heights[1..] {
        let ft = if name.contains("3000") {
            3000.0
        } else {
            300.0028
        };
        let deviation = FacetingTolerance::new(ft).unwrap().chord_deviation(length);
        assert!(
            (height - exact).abs() < deviation,
            "{name}: {height} against {exact}"
        );
    }
}
