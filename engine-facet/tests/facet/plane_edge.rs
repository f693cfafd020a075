//! A solid over the edge of a bounded PLANE: the plane stands for the prism under its
//! rectangle, so the intersection is closed by the prism's side faces too and its normal
//! tilts off the plane's (SPEC §4). Held to the exact engine's bounded-plane kernels, written
//! apart (closed forms and slicing on the primitives), with the error falling as the faceting
//! tolerance rises.

use crate::common::{Rng, angle_deg, centred, contacts_with_j_at_origin as contacts, engine};
use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid, Plane, Torus};
use contact_core::{Geometry, GeometryInstance, Isometry3};
use engine_exact::ExactEngine;

/// Each solid, its part frame at its middle, with its smallest support from there.
fn solids() -> Vec<(&'static str, GeometryInstance, f64)> {
    vec![
        ("sphere", centred(Geometry::sphere(0.5).unwrap()), 0.5),
        (
            "ellipsoid",
            centred(Geometry::Ellipsoid(Ellipsoid::new(0.6, 0.4, 0.3).unwrap())),
            0.3,
        ),
        (
            "box",
            centred(Geometry::Cuboid(Cuboid::centered(0.4, 0.3, 0.2).unwrap())),
            0.2,
        ),
        (
            "cylinder",
            centred(Geometry::Cylinder(Cylinder::new(0.3, 0.8).unwrap())),
            0.3,
        ),
        (
            "torus",
            centred(Geometry::Torus(Torus::new(0.6, 0.2).unwrap())),
            0.2,
        ),
    ]
}

/// The worst depth error (relative to the solid's smallest support) and normal error over
/// seeded poses of every solid dug 0.4 of its smallest support into a bounded plane, its
/// centre within 0.3 inside the rectangle's x edge, y edge or corner, at tolerance `ft`, and
/// how many of those reach over an edge.
fn worst_errors(ft: f64) -> (f64, f64, usize) {
    let faceted = engine(ft);
    let plane = Plane::bounded(-1.0, 2.0, -0.5, 1.5).unwrap();
    let plane = GeometryInstance::new(Geometry::Plane(plane));
    let mut rng = Rng(0xed6e_5eed);
    let (mut depth, mut normal, mut over) = (0.0_f64, 0.0_f64, 0);
    for (name, solid, support) in solids() {
        for k in 0..6 {
            let (x, y) = match k % 3 {
                0 => (2.0 - rng.range(0.0, 0.3), rng.range(0.0, 1.0)),
                1 => (rng.range(0.0, 1.0), -0.5 + rng.range(0.0, 0.3)),
                _ => (-1.0 + rng.range(0.0, 0.3), 1.5 - rng.range(0.0, 0.3)),
            };
            let pose = Isometry3::from_parts(
                nalgebra::Translation3::new(x, y, 0.6 * support),
                rng.rotation(),
            );
            let want = contacts(&ExactEngine, &solid, &plane, &pose);
            let got = contacts(&faceted, &solid, &plane, &pose);
            assert_eq!(
                got.len(),
                want.len(),
                "{name} at {pose:?}: {got:?} {want:?}"
            );
            if want.is_empty() {
                // A tilted solid whose lowest part lies beyond the edge: nothing to compare.
                continue;
            }
            assert_eq!(want.len(), 1, "{name} at {pose:?}: {want:?}");
            let (w, g) = (&want[0], &got[0]);
            depth = depth.max((g.penetration - w.penetration).abs() / support);
            normal = normal.max(angle_deg(&g.normal_w, &w.normal_w));
            if w.normal_w.z < 0.999 {
                over += 1;
            }
        }
    }
    (depth, normal, over)
}

#[test]
fn a_solid_over_a_bounded_planes_edge_converges_to_the_exact_contact() {
    let coarse = worst_errors(300.0);
    let fine = worst_errors(3000.0);
    let finest = worst_errors(30000.0);
    println!(
        "depth error, normal error °, poses over an edge: FT 300 {coarse:?}, 3000 {fine:?}, 30000 {finest:?}"
    );
    // Most poses reach over an edge (the exact normal tilts).
    assert!(fine.2 >= 20, "{fine:?}");
    // Before the prism's sides were clipped the depth error grew with FT (to 5% of the
    // support) and the normal stayed the plane's (up to 45° off).
    assert!(fine.0 < 2e-3 && fine.1 < 1.0, "FT 3000: {fine:?}");
    assert!(
        finest.0 < coarse.0 && finest.1 < coarse.1,
        "{coarse:?} {finest:?}"
    );
    assert!(finest.0 < 5e-4 && finest.1 < 0.2, "FT 30000: {finest:?}");
}
