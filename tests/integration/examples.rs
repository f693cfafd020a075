//! The example datasets in `examples/`, read, lowered and run, each asserting its physics.

use crate::ball_drop::{RADIUS, reference_apexes};
use contact::dataset;
use contact::run::lower::lower;
use contact::session::{ResultFiles, RunOptions, run_model};
use contact::solver::bdf::IntegratorSettings;
use contact::solver::contact_force::Analysis;
use contact::solver::simulate::{DynamicsSettings, simulate};
use std::path::Path;

fn example(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name)
}

/// The model lowered onto the solver with the exact engine (the examples have no meshes).
fn lowered(model: &contact::model::Model) -> contact::run::lower::LoweredModel {
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in this model".to_string());
    lower(
        model,
        &engine_exact::ExactEngine,
        Analysis::Dynamics,
        &no_meshes,
    )
    .unwrap()
}

/// Dynamics from 0 to `end`, a frame every `output_step`, at integrator ERROR `error`.
fn span(end: f64, output_step: f64, error: f64) -> DynamicsSettings {
    DynamicsSettings {
        start: 0.0,
        end,
        output_step,
        integrator: IntegratorSettings {
            error,
            ..IntegratorSettings::default()
        },
    }
}

#[test]
fn the_ball_example_bounces_as_the_one_dof_reference() {
    let loaded = dataset::read(&example("ball/ball.adm"), Some(&example("ball/ball.acf"))).unwrap();
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let mut lowered = lowered(&loaded.model);
    let settings = span(1.6, 1e-3, loaded.model.integrator.error);
    let ball = lowered.parts[0].0;
    let mut apexes = Vec::new();
    let mut was_rising = false;
    simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            let s = frame.parts[ball.0];
            let (z, v) = (s.pose_w.translation.z, s.velocity_w.z);
            if was_rising && v <= 0.0 && frame.contacts[0].is_empty() {
                apexes.push(z + v * v / (2.0 * 9.81));
            }
            was_rising = v > 0.0 && frame.contacts[0].is_empty();
            Ok(())
        },
    )
    .unwrap();
    let reference = reference_apexes(2);
    assert!(apexes.len() >= 2, "{apexes:?}");
    for (got, want) in apexes.iter().zip(&reference) {
        let relative = ((got - RADIUS) - (want - RADIUS)).abs() / (want - RADIUS);
        assert!(relative < 1e-3, "rebound {got} vs {want}");
    }
}

/// Runs an example with the exact engine and returns the frames' `(t, CM position, CM velocity)`
/// of its first moving part.
fn run_example(
    name: &str,
    end: f64,
    output_step: f64,
) -> Vec<(f64, nalgebra::Vector3<f64>, nalgebra::Vector3<f64>)> {
    let adm = example(&format!("{name}/{name}.adm"));
    let loaded = dataset::read(&adm, None).unwrap();
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let mut lowered = lowered(&loaded.model);
    let settings = DynamicsSettings {
        start: 0.0,
        end,
        output_step,
        integrator: IntegratorSettings {
            error: loaded.model.integrator.error,
            ..IntegratorSettings::default()
        },
    };
    let part = lowered.parts[0].0;
    let mut out = Vec::new();
    simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            let s = frame.parts[part.0];
            out.push((frame.t, s.pose_w.translation.vector, s.velocity_w));
            Ok(())
        },
    )
    .unwrap();
    out
}

#[test]
fn the_block_slides_down_the_incline_the_analytic_distance() {
    let frames = run_example("incline", 1.0, 0.01);
    let (t, end, _) = frames.last().copied().unwrap();
    let theta = 30f64.to_radians();
    let a = 9.81 * (theta.sin() - 0.25 * theta.cos());
    let analytic = 0.5 * a * t * t;
    let slid = end.x - frames[0].1.x;
    assert!(
        (slid - analytic).abs() < 0.01 * analytic,
        "slid {slid} m, analytic {analytic} m"
    );
    // It slides on its face: no lift-off, no tipping into the plane.
    assert!(
        (end.z - frames[0].1.z).abs() < 1e-3,
        "height changed by {}",
        end.z - frames[0].1.z
    );
}

#[test]
fn below_the_friction_angle_the_block_creeps_only_at_the_continuous_laws_speed() {
    // At 10°, tan θ = 0.176 < MU_STATIC: the continuous law (no true stiction) lets the block
    // creep at the speed where |μ(v)| = tan θ, and no faster.
    let adm = example("incline/incline.adm");
    let mut loaded = dataset::read(&adm, None).unwrap();
    let theta = 10f64.to_radians();
    loaded.model.gravity = nalgebra::Vector3::new(9.81 * theta.sin(), 0.0, -9.81 * theta.cos());
    let mut lowered = lowered(&loaded.model);
    let settings = span(1.0, 0.05, 1e-6);
    let part = lowered.parts[0].0;
    let mut last = nalgebra::Vector3::zeros();
    simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            last = frame.parts[part.0].velocity_w;
            Ok(())
        },
    )
    .unwrap();
    let friction =
        contact_core::laws::CoulombFriction::from_params(contact_core::laws::CoulombParams {
            mu_static: 0.3,
            mu_dynamic: 0.25,
            stiction_velocity: 0.01,
            friction_velocity: 0.02,
        })
        .unwrap();
    let (mut lo, mut hi) = (0.0, 0.01);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if -friction.mu(mid).value < theta.tan() {
            lo = mid
        } else {
            hi = mid
        }
    }
    let creep = 0.5 * (lo + hi);
    assert!(
        (last.x - creep).abs() < 0.02 * creep,
        "creeping at {} m/s, the law permits {creep} m/s",
        last.x
    );
}

#[test]
fn the_spinning_disk_stops_in_the_flat_pivot_time() {
    let adm = example("spinning_disk/spinning_disk.adm");
    let loaded = dataset::read(&adm, None).unwrap();
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let mut lowered = lowered(&loaded.model);
    let settings = span(0.6, 1e-3, 1e-6);
    let part = lowered.parts[0].0;
    let (m, r, mu, g, omega0) = (2.0, 0.1, 0.2, 9.81, 10.0);
    // "Stopped": the rim slips slower than FRICTION_TRANSITION_VELOCITY, where μ leaves μd.
    let stopped_below = 2e-3 / r;
    let mut stop_time = None;
    simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            let w = frame.parts[part.0].angular_velocity_w.z;
            if stop_time.is_none() && w < stopped_below {
                stop_time = Some(frame.t);
            }
            Ok(())
        },
    )
    .unwrap();
    let inertia = 0.5 * m * r * r;
    let analytic = (omega0 - stopped_below) * inertia / ((2.0 / 3.0) * r * mu * m * g);
    let t = stop_time.expect("the disk stops within the run");
    assert!(
        (t - analytic).abs() < 0.02 * analytic,
        "stopped at {t} s, analytic {analytic} s"
    );
}

/// The complete elliptic integral of the first kind K(k), by the arithmetic–geometric mean.
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    while (a - b).abs() > 1e-16 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

#[test]
fn the_pendulum_keeps_the_large_amplitude_period_and_its_energy() {
    let frames = run_example("pendulum", 5.0, 1e-3);
    let (m, l, g, i_cm): (f64, f64, f64, f64) = (1.0, 1.0, 9.81, 1e-3);
    let i_pivot = i_cm + m * l * l;
    let period = 4.0 * (i_pivot / (m * g * l)).sqrt() * elliptic_k(30f64.to_radians().sin());
    // Downward crossings of x = 0 (the bob passing under the pivot moving −x), interpolated.
    let crossings: Vec<f64> = frames
        .windows(2)
        .filter(|w| w[0].1.x > 0.0 && w[1].1.x <= 0.0)
        .map(|w| w[0].0 + (w[1].0 - w[0].0) * w[0].1.x / (w[0].1.x - w[1].1.x))
        .collect();
    assert!(crossings.len() >= 2, "{crossings:?}");
    let measured = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    assert!(
        (measured - period).abs() < 1e-4 * period,
        "period {measured} s, exact {period} s"
    );
    // Energy: the bob's speed is ω·L and the spin ω, so E = ½·I_O·ω² + m·g·z with ω = |v|/L.
    let energy =
        |v: nalgebra::Vector3<f64>, z: f64| 0.5 * i_pivot * (v.norm() / l).powi(2) + m * g * z;
    let e0 = energy(frames[0].2, frames[0].1.z);
    let drift = frames
        .iter()
        .map(|(_, p, v)| (energy(*v, p.z) - e0).abs())
        .fold(0.0, f64::max);
    assert!(drift < 1e-4 * m * g * l, "energy drift {drift} J");
}

/// The ball in its socket as a separately integrated model: its centre in polar coordinates
/// `(ρ, θ)` about the socket's centre, on the contact's radial spring `F = k·(ρ − L)^e` where
/// `ρ > L` (the penetration of a sphere in a spherical socket is exactly `ρ + r − R`; the
/// example's damping, 1e-3 N·s/m, moves the force by under 1e-7 N and is left out), RK4 at
/// 1 µs from rest at `θ₀`. Returns the times the centre crosses `x = 0` moving −x.
fn socket_reference_crossings(end: f64) -> Vec<f64> {
    let (m, g, l, k, e): (f64, f64, f64, f64, f64) = (1.0, 9.81, 0.4, 1e7, 1.5);
    let accel = |s: [f64; 4]| {
        let [rho, rho_dot, theta, theta_dot] = s;
        let f = if rho > l { k * (rho - l).powf(e) } else { 0.0 };
        let rho_dd = rho * theta_dot * theta_dot + g * theta.cos() - f / m;
        let theta_dd = (-g * theta.sin() - 2.0 * rho_dot * theta_dot) / rho;
        [rho_dot, rho_dd, theta_dot, theta_dd]
    };
    let h = 1e-6;
    let mut s = [l, 0.0, 15f64.to_radians(), 0.0];
    let mut t = 0.0;
    let mut crossings = Vec::new();
    while t < end {
        let add = |a: [f64; 4], b: [f64; 4], w: f64| std::array::from_fn(|i| a[i] + w * b[i]);
        let k1 = accel(s);
        let k2 = accel(add(s, k1, 0.5 * h));
        let k3 = accel(add(s, k2, 0.5 * h));
        let k4 = accel(add(s, k3, h));
        let next: [f64; 4] =
            std::array::from_fn(|i| s[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        let (x0, x1) = (s[0] * s[2].sin(), next[0] * next[2].sin());
        if x0 > 0.0 && x1 <= 0.0 {
            crossings.push(t + h * x0 / (x0 - x1));
        }
        s = next;
        t += h;
    }
    crossings
}

/// The ball sliding in its socket (a flipped sphere) is a pendulum of length `L = R − r`: its
/// period is the elliptic-integral one lengthened by the contact's compliance, by about
/// `δ/(2L)` with `δ` the penetration (between `(m·g·cos θ₀/k)^(1/e)` and the bottom's
/// `(m·g·(3 − 2·cos θ₀)/k)^(1/e)`), and its swing crosses the bottom when the separately
/// integrated model on the contact's spring says; it keeps its energy.
#[test]
fn the_ball_in_its_socket_swings_with_the_pendulum_period() {
    let frames = run_example("ball_socket", 4.0, 1e-3);
    let (m, g, l, k, e): (f64, f64, f64, f64, f64) = (1.0, 9.81, 0.4, 1e7, 1.5);
    let theta = 15f64.to_radians();
    let period = 4.0 * (l / g).sqrt() * elliptic_k((0.5 * theta).sin());
    let delta_max = (m * g * (3.0 - 2.0 * theta.cos()) / k).powf(1.0 / e);
    let crossings: Vec<f64> = frames
        .windows(2)
        .filter(|w| w[0].1.x > 0.0 && w[1].1.x <= 0.0)
        .map(|w| w[0].0 + (w[1].0 - w[0].0) * w[0].1.x / (w[0].1.x - w[1].1.x))
        .collect();
    assert!(crossings.len() >= 3, "{crossings:?}");
    let measured = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    let lengthened = (measured - period) / period;
    assert!(
        lengthened > 0.0 && lengthened < delta_max / l,
        "period {measured} s, rigid {period} s: lengthened by {lengthened:e}"
    );
    let reference = socket_reference_crossings(4.0);
    assert_eq!(
        reference.len(),
        crossings.len(),
        "{reference:?} {crossings:?}"
    );
    for (got, want) in crossings.iter().zip(&reference) {
        assert!(
            (got - want).abs() < 1e-5 * period,
            "crossing at {got} s, reference {want} s"
        );
    }
    // Energy, the contact's spring energy k·δ^(e+1)/(e+1) included (δ = |c| − L, the socket's
    // centre at the origin): the damping takes under 1e-6 J.
    let energy = |v: nalgebra::Vector3<f64>, p: nalgebra::Vector3<f64>| {
        let delta = (p.norm() - l).max(0.0);
        0.5 * m * v.norm_squared() + m * g * p.z + k * delta.powf(e + 1.0) / (e + 1.0)
    };
    let e0 = energy(frames[0].2, frames[0].1);
    let drift = frames
        .iter()
        .map(|(_, p, v)| (energy(*v, *p) - e0).abs())
        .fold(0.0, f64::max);
    assert!(
        drift < 1e-4 * m * g * l * (1.0 - theta.cos()),
        "energy drift {drift} J"
    );
}

/// Runs the POISSON ball with restitution `eps` (`augmented` adds the augmented Lagrangian) for
/// `end` seconds; returns the apex heights of the ball's lowest point after each bounce and
/// the largest penetration seen.
fn poisson_ball(eps: f64, augmented: bool, end: f64) -> (Vec<f64>, f64) {
    let adm = example("ball_poisson/ball_poisson.adm");
    let mut loaded = dataset::read(&adm, None).unwrap();
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let args = contact_core::ContactArgs {
        poisson: true,
        penalty: Some(1e6),
        restitution_coefficient: Some(eps),
        augmented_lagrangian: augmented,
        ..Default::default()
    };
    loaded.model.contacts[0].params = args.validate(&loaded.model.units).unwrap().0;
    let mut lowered = lowered(&loaded.model);
    let settings = DynamicsSettings {
        start: 0.0,
        end,
        output_step: 1e-3,
        integrator: IntegratorSettings {
            error: loaded.model.integrator.error,
            ..IntegratorSettings::default()
        },
    };
    let ball = lowered.parts[0].0;
    let (mut apexes, mut deepest, mut was_rising) = (Vec::new(), 0.0_f64, false);
    simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            let s = frame.parts[ball.0];
            let (z, v) = (s.pose_w.translation.z, s.velocity_w.z);
            let free = frame.contacts[0].is_empty();
            if was_rising && v <= 0.0 && free {
                apexes.push(z + v * v / (2.0 * 9.81) - 0.1);
            }
            was_rising = v > 0.0 && free;
            deepest = frame.contacts[0]
                .iter()
                .map(|r| r.contact.penetration)
                .fold(deepest, f64::max);
            Ok(())
        },
    )
    .unwrap();
    (apexes, deepest)
}

#[test]
fn poisson_rebounds_at_the_restitution_coefficient() {
    let (apexes, _) = poisson_ball(0.6, false, 1.6);
    // Exit over entry speed = sqrt(rebound height / drop height).
    let ratio = apexes[0].sqrt();
    assert!((ratio - 0.6).abs() < 0.02 * 0.6, "rebound ratio {ratio}");
}

#[test]
fn elastic_poisson_conserves_energy_over_ten_bounces() {
    let (apexes, _) = poisson_ball(1.0, false, 9.2);
    assert!(apexes.len() >= 10, "{apexes:?}");
    let drift = apexes.iter().map(|h| (h - 1.0).abs()).fold(0.0, f64::max);
    assert!(drift < 1e-3, "apexes drift {drift} (relative energy)");
}

#[test]
fn one_and_two_threads_give_identical_runs() {
    // Three balls on the plane, each its own CONTACT, so contacts are evaluated in parallel.
    let text = std::fs::read_to_string(example("ball/ball.adm")).unwrap();
    let more = text.replace(
        "ACCGRAV/",
        "PART/3, MASS = 1, CM = 30, IP = 0.004, 0.004, 0.004, VX = 0.3\n\
         MARKER/30, PART = 3, QP = 0.5, 0, 0.7\n\
         GRAPHICS/3, ELLIPSOID, CM = 30, XSCALE = 0.2, YSCALE = 0.2, ZSCALE = 0.2\n\
         CONTACT/2, IGEOM = 3, JGEOM = 2, IMPACT, STIFFNESS = 1E6, EXPONENT = 1.5, DAMPING = 50, DMAX = 1E-4\n\
         , COULOMB_FRICTION = ON, MU_STATIC = 0.3, MU_DYNAMIC = 0.2\n\
         , STICTION_TRANSITION_VELOCITY = 0.01, FRICTION_TRANSITION_VELOCITY = 0.02\n\
         PART/4, MASS = 2, CM = 40, IP = 0.008, 0.008, 0.008, WY = 3\n\
         MARKER/40, PART = 4, QP = -0.5, 0, 0.5\n\
         GRAPHICS/4, ELLIPSOID, CM = 40, XSCALE = 0.2, YSCALE = 0.2, ZSCALE = 0.2\n\
         CONTACT/3, IGEOM = 4, JGEOM = 2, IMPACT, STIFFNESS = 1E6, EXPONENT = 1.5, DAMPING = 50, DMAX = 1E-4\n\
         ACCGRAV/",
    );
    let loaded = dataset::read_str(&more, example("ball/three_balls.adm"), None);
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    // A run with 1 and with 2 threads writes identical result files.
    let dir = std::env::temp_dir().join(format!("contact-threads-{}", std::process::id()));
    let files = |threads: usize| {
        let out = dir.join(format!("out{threads}"));
        let options = RunOptions {
            end: Some(0.8),
            dtout: Some(0.01),
            threads: Some(threads),
            ..RunOptions::default()
        };
        let model = example("ball/three_balls.adm");
        run_model(&loaded.model, &model, &options, &mut ResultFiles::new(&out)).unwrap();
        ["parts.csv", "contacts.csv", "frames.jsonl"].map(|f| std::fs::read(out.join(f)).unwrap())
    };
    assert_eq!(
        files(1),
        files(2),
        "result files differ between 1 and 2 threads"
    );
    std::fs::remove_dir_all(&dir).ok();
    let run = |threads: usize| {
        let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in this model".to_string());
        let mut lowered = lower(
            &loaded.model,
            &engine_exact::ExactEngine,
            Analysis::Dynamics,
            &no_meshes,
        )
        .unwrap();
        lowered.system.set_parallelism(
            contact::solver::parallel::Parallelism::with_threads(threads).unwrap(),
        );
        let settings = span(0.8, 0.01, 1e-5);
        let mut bits = Vec::new();
        simulate(
            &mut lowered.system,
            &lowered.contacts,
            &settings,
            &mut |frame| {
                for s in &frame.parts {
                    bits.extend(
                        s.pose_w
                            .translation
                            .vector
                            .iter()
                            .chain(s.velocity_w.iter())
                            .map(|x| x.to_bits()),
                    );
                }
                for r in frame.contacts.iter().flatten() {
                    bits.push(r.normal_force.to_bits());
                    bits.extend(r.friction_force_w.iter().map(|x| x.to_bits()));
                }
                Ok(())
            },
        )
        .unwrap();
        bits
    };
    let (one, two) = (run(1), run(2));
    assert!(one.len() > 1000, "{}", one.len());
    assert_eq!(one, two, "1 and 2 threads differ");
}

/// The cam's control points in `cam_follower/cam_follower.adm`: 16 points on a circle of
/// radius 40 mm centred at (10 mm, 0), counter-clockwise from angle 0.
fn cam_control_points() -> Vec<[f64; 2]> {
    (0..16)
        .map(|k| {
            let phi = std::f64::consts::TAU * f64::from(k) / 16.0;
            [0.01 + 0.04 * phi.cos(), 0.04 * phi.sin()]
        })
        .collect()
}

/// Points of the closed uniform cubic B-spline of `control` (the standard periodic basis,
/// `samples` per span), written out here independently of the engine's curve code.
fn periodic_cubic_bspline(control: &[[f64; 2]], samples: usize) -> Vec<[f64; 2]> {
    let n = control.len();
    let mut out = Vec::with_capacity(n * samples);
    for i in 0..n {
        let p = |k: usize| control[(i + k + n - 1) % n];
        for s in 0..samples {
            let u = s as f64 / samples as f64;
            let b = [
                (1.0 - u).powi(3) / 6.0,
                (3.0 * u.powi(3) - 6.0 * u * u + 4.0) / 6.0,
                (-3.0 * u.powi(3) + 3.0 * u * u + 3.0 * u + 1.0) / 6.0,
                u.powi(3) / 6.0,
            ];
            let point = (0..4).fold([0.0, 0.0], |acc, k| {
                [acc[0] + b[k] * p(k)[0], acc[1] + b[k] * p(k)[1]]
            });
            out.push(point);
        }
    }
    out
}

/// Roller-follower kinematics by brute force: with the profile turned by `angle` about the
/// origin, the height of the centre of a roller of radius `r` on the line x = 0 resting on
/// the highest profile point under it.
fn roller_lift(profile: &[[f64; 2]], angle: f64, r: f64) -> f64 {
    let (s, c) = angle.sin_cos();
    profile
        .iter()
        .map(|p| (c * p[0] - s * p[1], s * p[0] + c * p[1]))
        .filter(|(x, _)| x.abs() <= r)
        .map(|(x, y)| y + (r * r - x * x).sqrt())
        .fold(f64::NEG_INFINITY, f64::max)
}

#[test]
fn the_cam_follower_lifts_as_the_roller_kinematics_of_its_profile() {
    let dir = example("cam_follower");
    let loaded = dataset::read(
        &dir.join("cam_follower.adm"),
        Some(&dir.join("cam_follower.acf")),
    )
    .unwrap();
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let mut lowered = lowered(&loaded.model);
    let [(cam, _), (follower, _)] = [lowered.parts[0], lowered.parts[1]];
    let settings = span(1.0, 0.005, loaded.model.integrator.error);
    let mut frames = Vec::new();
    simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            let q = frame.parts[cam.0].pose_w.rotation;
            let force: f64 = frame.contacts[0].iter().map(|c| c.normal_force).sum();
            let y = frame.parts[follower.0].pose_w.translation.y;
            frames.push((frame.t, q.angle() * q.axis().map_or(1.0, |a| a.z), y, force));
            Ok(())
        },
    )
    .unwrap();
    assert_eq!(frames.len(), 201);

    let (roller, mass, k, exponent) = (0.015, 0.1, 1e8, 1.5);
    let profile = periodic_cubic_bspline(&cam_control_points(), 400);
    let lift = |angle: f64| roller_lift(&profile, angle, roller);
    // The bound: IMPACT leaves the roller short of the rigid contact by the penetration that
    // carries the load, δ = (F/k)^(1/e), seen along the line of travel through the pressure
    // angle φ. F is at most the spring at the highest lift (10 N + 500 N/m over the 20 mm rise)
    // plus the follower's inertia m·|ÿ|, ÿ ≤ e·ω² for this near-eccentric profile (e = 10 mm,
    // ω = 2π/s); tan φ = (dy/dθ)/y for a follower in line with the axis.
    let (lowest, highest) = (
        lift(-std::f64::consts::FRAC_PI_2),
        lift(std::f64::consts::FRAC_PI_2),
    );
    let omega = std::f64::consts::TAU;
    let force_max = 10.0 + 500.0 * (highest - lowest) + mass * 0.01 * omega * omega;
    let tan_phi_max = (0..360)
        .map(|d| {
            let a = f64::from(d).to_radians();
            ((lift(a + 1e-4) - lift(a - 1e-4)) / 2e-4 / lift(a)).abs()
        })
        .fold(0.0, f64::max);
    let bound = (force_max / k).powf(1.0 / exponent) * (1.0 + tan_phi_max * tan_phi_max).sqrt();
    assert!(
        bound < 5e-5 && highest - lowest > 0.019,
        "{bound} {lowest} {highest}"
    );
    for &(t, angle, y, force) in &frames {
        // The MOTION turns the cam at 1 rev/s (to the integrator's ERROR = 1e-6, within 10×
        // for output interpolated between steps).
        let expected_angle = omega * t;
        let turned = (angle - expected_angle).rem_euclid(std::f64::consts::TAU);
        assert!(
            turned.min(std::f64::consts::TAU - turned) < 1e-5,
            "t = {t}: {angle}"
        );
        let gap = lift(expected_angle) - y;
        assert!(
            (0.0..=bound).contains(&gap),
            "t = {t}: follower at {y}, rigid kinematics {}, short by {gap:e} (bound {bound:e})",
            lift(expected_angle)
        );
        // Never lifts off the cam: the preload exceeds the follower's inertia force.
        assert!(force > 5.0, "t = {t}: contact force {force}");
    }
}
