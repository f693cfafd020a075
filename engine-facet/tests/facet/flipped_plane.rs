//! A flipped PLANE (IFLIP_NORMAL / JFLIP_NORMAL: the material above it) against the solids,
//! bounded and not, held to the exact engine, which answers the other side of a plane in its
//! own closed forms (a side sign in each plane kernel), written apart from the faceted
//! engine's half-turn of the plane's frame.

use crate::common::{Rng, angle_deg, centred, engine, instance_contacts as contacts};
use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid, Plane, Torus};
use contact_core::{FacetingTolerance, Geometry, GeometryInstance, Isometry3, Side};
use engine_exact::ExactEngine;

/// The solids, each with a lower bound on its support in any direction from its centre (the
/// radius of a ball it holds; a torus' tube radius).
fn solids() -> Vec<(&'static str, Geometry, f64)> {
    vec![
        ("sphere", Geometry::sphere(0.5).unwrap(), 0.5),
        (
            "ellipsoid",
            Geometry::Ellipsoid(Ellipsoid::new(0.6, 0.4, 0.3).unwrap()),
            0.3,
        ),
        (
            "box",
            Geometry::Cuboid(Cuboid::centered(0.4, 0.3, 0.2).unwrap()),
            0.2,
        ),
        (
            "cylinder",
            Geometry::Cylinder(Cylinder::new(0.3, 0.8).unwrap()),
            0.3,
        ),
        ("torus", Geometry::Torus(Torus::new(0.6, 0.2).unwrap()), 0.2),
    ]
}

/// Each solid dug into the flipped plane from above (seeded orientations, the solid's centre
/// a little above the plane's top), either order and bounded or not: the faceted contact
/// (FT 3000) has the exact one's count, depth within the solid's chord deviation, normal
/// within a few degrees and points within the deviation plus the depth's share of a tilt.
#[test]
fn a_flipped_plane_is_the_half_space_above_it_as_the_exact_engine_says() {
    let ft = 3000.0;
    let faceted = engine(ft);
    let exact = ExactEngine;
    let planes = [
        ("unbounded", Plane::unbounded()),
        ("bounded", Plane::bounded(-2.0, 3.0, 0.5, 4.0).unwrap()),
    ];
    let mut rng = Rng(0x5eed_f11b);
    let mut compared = 0;
    for (name, solid, support) in solids() {
        let deviation = FacetingTolerance::new(ft)
            .unwrap()
            .chord_deviation(solid.characteristic_length().unwrap());
        for (plane_name, plane) in planes {
            for _ in 0..4 {
                let rotation = rng.rotation();
                // The material is above z = 0: the solid's centre below it, so that it
                // reaches at least 0.4 of its smallest support into the material.
                let h = -0.6 * support;
                // Over the bounded plane, well inside its y range (which is not symmetric:
                // a flip that kept the range unmirrored would put the rectangle elsewhere),
                // and clear of its edges, where the faceted engine keeps the plane's normal.
                let y = if plane.is_unbounded() {
                    rng.range(-0.3, 0.3)
                } else {
                    2.2 + rng.range(-0.3, 0.3)
                };
                let pose_solid = Isometry3::from_parts(
                    nalgebra::Translation3::new(rng.range(-0.3, 0.3), y, h),
                    rotation,
                );
                let pose_plane = Isometry3::identity();
                // The part frame at the solid's middle (a cylinder's frame is at its base).
                let s = centred(solid.clone());
                let p = GeometryInstance::new(Geometry::Plane(plane)).flipped();
                for side in [Side::I, Side::J] {
                    let (i, j, pi, pj) = match side {
                        Side::I => (&p, &s, &pose_plane, &pose_solid),
                        Side::J => (&s, &p, &pose_solid, &pose_plane),
                    };
                    let want = contacts(&exact, i, j, pi, pj);
                    let got = contacts(&faceted, i, j, pi, pj);
                    let what = format!("{name} against the {plane_name} plane flipped on {side:?}");
                    assert!(!want.is_empty(), "{what}: no exact contact");
                    assert_eq!(got.len(), want.len(), "{what}: {got:?} vs {want:?}");
                    let (w, g) = (&want[0], &got[0]);
                    assert!(
                        (g.penetration - w.penetration).abs() <= deviation,
                        "{what}: depth {} vs {} (deviation {deviation})",
                        g.penetration,
                        w.penetration
                    );
                    assert!(
                        angle_deg(&g.normal_w, &w.normal_w) < 3.0,
                        "{what}: normal {:?} vs {:?}",
                        g.normal_w,
                        w.normal_w
                    );
                    // The material is above: the normal from J into I points down when the
                    // plane is J, up when it is I.
                    let sign = if side == Side::J { -1.0 } else { 1.0 };
                    assert!(sign * w.normal_w.z > 0.5, "{what}: {:?}", w.normal_w);
                    assert!(sign * g.normal_w.z > 0.5, "{what}: {:?}", g.normal_w);
                    compared += 1;
                }
            }
        }
    }
    assert_eq!(compared, 5 * 2 * 4 * 2);
}

/// The flip is the plane's other side: a sphere dipping into an unflipped plane from above
/// touches it, one clear above it does not; flipped, the same from below.
#[test]
fn flipping_a_plane_swaps_which_side_touches() {
    let faceted = engine(300.0028);
    let ball = GeometryInstance::new(Geometry::sphere(0.5).unwrap());
    let plane = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
    let flipped = plane.clone().flipped();
    let at = |z: f64| Isometry3::translation(0.0, 0.0, z);
    let id = Isometry3::identity();
    let above = contacts(&faceted, &ball, &plane, &at(0.4), &id);
    assert_eq!(above.len(), 1);
    assert!(above[0].normal_w.z > 0.99, "{above:?}");
    assert!(contacts(&faceted, &ball, &plane, &at(0.6), &id).is_empty());
    assert!(contacts(&faceted, &ball, &flipped, &at(-0.6), &id).is_empty());
    // Sunk wholly into the other side, the ball is one deep contact.
    assert_eq!(contacts(&faceted, &ball, &flipped, &at(0.6), &id).len(), 1);
    let below = contacts(&faceted, &ball, &flipped, &at(-0.4), &id);
    assert_eq!(below.len(), 1);
    assert!(below[0].normal_w.z < -0.99, "{below:?}");
    assert!((below[0].penetration - 0.1).abs() < 1e-9, "{below:?}");
    // The exact engine agrees on both sides, and with the plane as I.
    let exact = ExactEngine;
    let exact_below = contacts(&exact, &ball, &flipped, &at(-0.4), &id);
    assert!(
        (exact_below[0].penetration - 0.1).abs() < 1e-12,
        "{exact_below:?}"
    );
    let plane_as_i = contacts(&exact, &flipped, &ball, &id, &at(-0.4));
    assert_eq!(plane_as_i.len(), 1, "{plane_as_i:?}");
}
