//! A ball dropped into a spherical socket (a flipped ELLIPSOID on ground, JFLIP_GEOMETRY), a
//! horizontal pipe (a flipped CYLINDER) and a toroidal groove (a flipped TORUS), run with each
//! engine: the exact engine's sphere-in-socket kernel and the faceted engine's
//! inside-out tessellation. Both runs complete, the ball comes to rest at the socket's bottom
//! where the contact carries its weight (`k·δ^e = m·g`: centre at `−(R − r + δ)`, on the
//! axis), the exact one to the integrator's error and the faceted one within the two
//! spheres' chord deviations.

use contact::session::{RunLayout, RunOptions, RunSink, run_model};
use contact::solver::simulate::Frame;
use contact_core::{FacetingTolerance, GeometryLibrary};

const SOCKET: &str = "ball in a spherical socket\n\
    UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
    PART/1, GROUND\n\
    MARKER/10, PART = 1\n\
    PART/2, MASS = 1, CM = 20, IP = 0.004, 0.004, 0.004\n\
    MARKER/20, PART = 2, QP = 0, 0, -0.1\n\
    GRAPHICS/1, ELLIPSOID, CM = 20, XSCALE = 0.2, YSCALE = 0.2, ZSCALE = 0.2\n\
    GRAPHICS/2, ELLIPSOID, CM = 10, XSCALE = 1, YSCALE = 1, ZSCALE = 1\n\
    CONTACT/1, IGEOM = 1, JGEOM = 2, JFLIP_GEOMETRY = 2, IMPACT, STIFFNESS = 1E6\
    , EXPONENT = 1.5, DAMPING = 1000, DMAX = 1E-4\n\
    ACCGRAV/ KGRAV = -9.81\n\
    INTEGRATOR/ ERROR = 1E-6\n\
    END\n";

/// Keeps the ball's (PART/2) position at every frame.
#[derive(Default)]
struct Last {
    ball: usize,
    track: Vec<nalgebra::Vector3<f64>>,
}

impl RunSink for Last {
    fn start(&mut self, layout: &RunLayout<'_>) -> std::io::Result<()> {
        let (id, _) = layout.parts.iter().find(|(_, adams)| *adams == 2).unwrap();
        self.ball = id.0;
        Ok(())
    }

    fn frame(&mut self, frame: &Frame) -> std::io::Result<()> {
        self.track
            .push(frame.parts[self.ball].pose_w.translation.vector);
        Ok(())
    }
}

/// The ball's track in `dataset` over `end` seconds (100 frames a second).
fn track(dataset: &str, engine: GeometryLibrary, ft: f64, end: f64) -> Vec<nalgebra::Vector3<f64>> {
    let loaded = crate::inline("socket.adm", dataset);
    assert!(!loaded.has_errors(), "{:#?}", crate::printed(&loaded));
    let options = RunOptions {
        engine: Some(engine),
        faceting_tolerance: Some(FacetingTolerance::new(ft).unwrap()),
        end: Some(end),
        steps: Some((100.0 * end) as u32),
        ..RunOptions::default()
    };
    let mut last = Last::default();
    let report = run_model(
        &loaded.model,
        &crate::data_dir().join("socket.adm"),
        &options,
        &mut last,
    )
    .unwrap();
    assert!(report.completed());
    last.track
}

fn rest(engine: GeometryLibrary, ft: f64) -> nalgebra::Vector3<f64> {
    *track(SOCKET, engine, ft, 1.5).last().unwrap()
}

#[test]
fn a_ball_dropped_into_a_socket_rests_at_its_bottom_with_either_engine() {
    let (big_r, r, k, e, m, g): (f64, f64, f64, f64, f64, f64) = (0.5, 0.1, 1e6, 1.5, 1.0, 9.81);
    let delta = (m * g / k).powf(1.0 / e);
    let bottom = -(big_r - r + delta);
    let exact = rest(GeometryLibrary::Exact, 300.0028);
    assert!(exact.xy().norm() < 1e-12, "{exact:?}");
    assert!(
        (exact.z - bottom).abs() < 1e-3 * delta,
        "{exact:?} vs {bottom}"
    );
    let ft = 3000.0;
    let deviation = |l: f64| FacetingTolerance::new(ft).unwrap().chord_deviation(l);
    let band = deviation(3f64.sqrt() * 2.0 * big_r) + deviation(3f64.sqrt() * 2.0 * r);
    let faceted = rest(GeometryLibrary::Faceted, ft);
    assert!(faceted.xy().norm() < band, "{faceted:?}");
    assert!(
        (faceted.z - bottom).abs() < band,
        "{faceted:?} vs {bottom} (band {band})"
    );
}

/// Released on the socket's wall, 0.25 off the axis, the ball slides down and across (no
/// friction): the faceted runs follow the exact one, closer at the finer tolerance.
#[test]
fn a_ball_sliding_in_a_socket_follows_the_exact_run_closer_as_ft_rises() {
    let sliding = SOCKET
        .replace("QP = 0, 0, -0.1", "QP = 0.25, 0, -0.2")
        .replace("DAMPING = 1000", "DAMPING = 100");
    let end = 0.6;
    let exact = track(&sliding, GeometryLibrary::Exact, 300.0028, end);
    let apart = |ft: f64| {
        let faceted = track(&sliding, GeometryLibrary::Faceted, ft, end);
        assert_eq!(faceted.len(), exact.len());
        faceted
            .iter()
            .zip(&exact)
            .map(|(f, e)| (f - e).norm())
            .fold(0.0, f64::max)
    };
    let (coarse, fine) = (apart(300.0028), apart(3000.0));
    // The socket's chord deviation at FT 3000 is 5.8e-4.
    assert!(
        fine < coarse && fine < 5e-3,
        "FT 300: {coarse:e}, FT 3000: {fine:e}"
    );
}

/// The ball of [`SOCKET`] in a horizontal pipe (a flipped CYLINDER of radius 0.5 along `x`)
/// and in a toroidal groove (a flipped TORUS R = 1, ρ = 0.3 about `z`), each dropped 0.1 from
/// the wall's lowest line: with either engine the ball comes to rest on that line where the
/// contact carries its weight, `(ρ − r + δ)` below the bore's axis or the tube's core circle,
/// the exact engine to the integrator's error and the faceted one within the two bodies'
/// chord deviations in height (across, within half a facet).
#[test]
fn a_ball_dropped_into_a_pipe_or_a_groove_rests_on_its_lowest_line_with_either_engine() {
    let (r, k, e, m, g): (f64, f64, f64, f64, f64) = (0.1, 1e6, 1.5, 1.0, 9.81);
    let delta = (m * g / k).powf(1.0 / e);
    let pipe = SOCKET
        .replace(
            "MARKER/10, PART = 1\n",
            "MARKER/10, PART = 1\nMARKER/11, PART = 1, QP = -1, 0, 0, REULER = 90D, 90D, 0D\n",
        )
        .replace(
            "GRAPHICS/2, ELLIPSOID, CM = 10, XSCALE = 1, YSCALE = 1, ZSCALE = 1",
            "GRAPHICS/2, CYLINDER, CM = 11, RADIUS = 0.5, LENGTH = 2",
        )
        .replace("QP = 0, 0, -0.1", "QP = 0, 0, -0.3");
    let groove = SOCKET
        .replace(
            "GRAPHICS/2, ELLIPSOID, CM = 10, XSCALE = 1, YSCALE = 1, ZSCALE = 1",
            "GRAPHICS/2, TORUS, CM = 10, MAJOR_RADIUS = 1, MINOR_RADIUS = 0.3",
        )
        .replace("QP = 0, 0, -0.1", "QP = 1, 0, -0.1");
    let ft = 3000.0;
    let deviation = |l: f64| FacetingTolerance::new(ft).unwrap().chord_deviation(l);
    // The groove's wall curves about `z` as well as round the tube: the part of the ball in
    // the wall is not symmetric about the lowest circle, its area vector tilts off the
    // vertical there, and the ball rests where the tilt vanishes, a fraction of δ off that
    // circle (measured: 0.05 δ inward). The pipe's region is symmetric.
    for (name, dataset, small, line, size, radial) in [
        (
            "pipe",
            &pipe,
            0.5,
            [0.0, 0.0],
            (2.0f64 * 2.0 + 1.0).sqrt(),
            1e-12,
        ),
        ("groove", &groove, 0.3, [1.0, 0.0], 2.0 * 1.3, delta),
    ] {
        let bottom = -(small - r + delta);
        let band = deviation(size) + deviation(3f64.sqrt() * 2.0 * r);
        // On a flat facet nothing holds the ball across it: it may rest anywhere on the
        // bottom facet, within half a facet's chord `√(2ρ·deviation)` of the lowest line.
        let half_facet = (2.0 * small * deviation(size)).sqrt();
        for (engine, ft, tolerance, across) in [
            (GeometryLibrary::Exact, 300.0028, 1e-3 * delta, radial),
            (GeometryLibrary::Faceted, ft, band, half_facet.max(radial)),
        ] {
            let at = *track(dataset, engine, ft, 1.5).last().unwrap();
            assert!(
                at.y.abs() < 1e-12 || engine == GeometryLibrary::Faceted,
                "{name}: {at:?}"
            );
            let off = (at.x - line[0]).abs().max((at.y - line[1]).abs());
            assert!(off < across, "{name} {engine:?}: {at:?}");
            assert!(
                (at.z - bottom).abs() < tolerance,
                "{name} {engine:?}: {at:?} vs {bottom} (tolerance {tolerance:e})"
            );
        }
    }
}
