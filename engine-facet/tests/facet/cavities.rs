//! Flipped solids: a body inside a cavity (IFLIP_NORMAL / JFLIP_NORMAL on a 3-D solid or a
//! closed mesh, the space outside it), the cavity's tessellation turned inside out.
//!
//! Oracles written apart from the faceted engine: the exact engine's cavity pairs (a sphere in
//! a spherical socket; a sphere, box, cylinder, frustum or torus in a box-shaped cavity, by
//! closed forms and slicing against the cavity's walls; a sphere or an ellipsoid in a bore, a
//! conical or an ellipsoid cavity, by slicing along its axis), and a closed form for a ball pressed
//! into the wall of a long cylindrical bore (the centroid of the part of the ball in the wall
//! lies on the line from the axis through the ball's centre, so the ray rule gives the depth
//! `e + r − R` along that line).

use crate::common::{Rng, angle_deg, centred, contacts_with_j_at_origin as contacts, engine};
use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid, Frustum, Torus, TriangleMesh};
use contact_core::{
    Contact, FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, Isometry3, Point3,
    PrepareError, Vector3,
};
use engine_exact::ExactEngine;

/// Bodies in a 1.0 × 0.8 × 0.6 box cavity, a sphere socket of radius 0.6, a bore of radius
/// 0.5, a conical cavity (radii 0.6 and 0.35, both 1.2 long) and an ellipsoid cavity
/// (semi-axes 0.6, 0.5, 0.4), pushed from
/// the middle toward a wall by seeded offsets so that they dig into it, against the exact
/// engine: the same number of contacts, and at FT 3000 each depth within the chord deviation
/// of the two surfaces, each normal within 1°.
#[test]
fn bodies_in_cavities_agree_with_the_exact_engine() {
    let ft = 3000.0;
    let faceted = engine(ft);
    let deviation = |g: &Geometry| {
        g.characteristic_length().map_or(0.0, |l| {
            FacetingTolerance::new(ft).unwrap().chord_deviation(l)
        })
    };
    let box_cavity = centred(Geometry::Cuboid(Cuboid::centered(0.5, 0.4, 0.3).unwrap())).flipped();
    let socket = GeometryInstance::new(Geometry::sphere(0.6).unwrap()).flipped();
    let bore = centred(Geometry::Cylinder(Cylinder::new(0.5, 1.2).unwrap())).flipped();
    let cone = centred(Geometry::Frustum(Frustum::new(0.6, 0.35, 1.2).unwrap())).flipped();
    let cases: Vec<(&str, GeometryInstance, GeometryInstance)> = vec![
        (
            "sphere in a socket",
            GeometryInstance::new(Geometry::sphere(0.4).unwrap()),
            socket,
        ),
        (
            "sphere in a box",
            GeometryInstance::new(Geometry::sphere(0.25).unwrap()),
            box_cavity.clone(),
        ),
        (
            "box in a box",
            centred(Geometry::Cuboid(Cuboid::centered(0.2, 0.15, 0.1).unwrap())),
            box_cavity.clone(),
        ),
        (
            "cylinder in a box",
            centred(Geometry::Cylinder(Cylinder::new(0.12, 0.3).unwrap())),
            box_cavity.clone(),
        ),
        (
            "frustum in a box",
            centred(Geometry::Frustum(Frustum::new(0.15, 0.08, 0.3).unwrap())),
            box_cavity.clone(),
        ),
        (
            "torus in a box",
            centred(Geometry::Torus(Torus::new(0.18, 0.06).unwrap())),
            box_cavity,
        ),
        (
            "sphere in a bore",
            GeometryInstance::new(Geometry::sphere(0.25).unwrap()),
            bore.clone(),
        ),
        (
            "ellipsoid in a bore",
            GeometryInstance::new(Geometry::Ellipsoid(Ellipsoid::new(0.3, 0.2, 0.15).unwrap())),
            bore,
        ),
        (
            "ellipsoid in a cone",
            GeometryInstance::new(Geometry::Ellipsoid(Ellipsoid::new(0.3, 0.2, 0.15).unwrap())),
            cone,
        ),
        (
            "ellipsoid in an ellipsoid",
            GeometryInstance::new(Geometry::Ellipsoid(Ellipsoid::new(0.3, 0.2, 0.15).unwrap())),
            GeometryInstance::new(Geometry::Ellipsoid(Ellipsoid::new(0.6, 0.5, 0.4).unwrap()))
                .flipped(),
        ),
    ];
    let mut rng = Rng(0x0ca5_17e5);
    let (mut compared, mut worst_depth, mut worst_normal) = (0, 0.0_f64, 0.0_f64);
    for (name, body, cavity) in &cases {
        let band = deviation(&body.geometry) + deviation(&cavity.geometry);
        for _ in 0..6 {
            let rotation = rng.rotation();
            let direction = rng.unit_vector();
            // From the middle toward a wall, until the exact engine finds the body in it.
            let mut found = None;
            for step in 1..=60 {
                let pose =
                    Isometry3::from_parts((direction * (0.01 * step as f64)).into(), rotation);
                let want = contacts(&ExactEngine, body, cavity, &pose);
                if want.iter().any(|c| c.penetration > 0.02) {
                    found = Some((pose, want));
                    break;
                }
            }
            let Some((pose, want)) = found else {
                panic!("{name}: the body never reached a wall along {direction:?}");
            };
            let got = contacts(&faceted, body, cavity, &pose);
            assert_eq!(
                got.len(),
                want.len(),
                "{name} at {pose:?}: {got:?} vs {want:?}"
            );
            // Pair each exact contact with the faceted one nearest to it.
            for w in &want {
                let g = got
                    .iter()
                    .min_by(|a, b| {
                        let d = |c: &Contact| (c.point_i_w - w.point_i_w).norm();
                        d(a).total_cmp(&d(b))
                    })
                    .unwrap();
                let depth = (g.penetration - w.penetration).abs();
                let normal = angle_deg(&g.normal_w, &w.normal_w);
                assert!(
                    depth <= band,
                    "{name}: depth {} vs {} (band {band})",
                    g.penetration,
                    w.penetration
                );
                assert!(
                    normal < 1.0,
                    "{name}: normal {:?} vs {:?}",
                    g.normal_w,
                    w.normal_w
                );
                worst_depth = worst_depth.max(depth / band);
                worst_normal = worst_normal.max(normal);
            }
            compared += 1;
        }
    }
    println!(
        "cavities: {compared} poses, worst depth error {worst_depth:.3} of the band, normal {worst_normal:.3}°"
    );
    assert_eq!(compared, 6 * cases.len());
}

/// A ball of radius r pressed a distance e off the axis of a long bore of radius R < e + r:
/// one contact, depth → e + r − R as FT rises, normal toward the axis. Either order: the
/// bore as J (JFLIP_NORMAL) or as I.
#[test]
fn a_ball_pressed_into_a_bore_wall_converges_to_the_closed_form() {
    let (r, big_r, e) = (0.2, 0.3, 0.15);
    let bore = centred(Geometry::Cylinder(Cylinder::new(big_r, 3.0).unwrap())).flipped();
    let ball = GeometryInstance::new(Geometry::sphere(r).unwrap());
    let u = Vector3::new(0.6, 0.8, 0.0);
    let pose = Isometry3::translation(e * u.x, e * u.y, 0.1);
    let exact_depth = e + r - big_r;
    let mut errors = Vec::new();
    for ft in [300.0, 3000.0, 30000.0] {
        let c = contacts(&engine(ft), &ball, &bore, &pose);
        assert_eq!(c.len(), 1, "FT {ft}: {c:?}");
        assert!(
            angle_deg(&c[0].normal_w, &-u) < 2.0,
            "FT {ft}: {:?}",
            c[0].normal_w
        );
        // The bore as I: the same contact seen from the other side.
        let swapped = contacts(&engine(ft), &bore, &ball, &pose.inverse());
        assert_eq!(swapped.len(), 1, "FT {ft}: {swapped:?}");
        assert!((swapped[0].penetration - c[0].penetration).abs() < 1e-9 * r);
        errors.push((c[0].penetration - exact_depth).abs() / exact_depth);
    }
    println!("ball in a bore: relative depth errors {errors:?}");
    assert!(errors[2] < errors[0] && errors[2] < 2e-3, "{errors:?}");
}

/// A pin tilted in its bore presses the wall at both ends, on opposite sides: two contacts
/// whose normals point back toward the axis, opposite each other across it, and whose depths
/// are equal by the symmetry of the pose. Centred and upright, it touches nothing.
#[test]
fn a_pin_tilted_in_its_bore_touches_at_both_ends_on_opposite_sides() {
    let faceted = engine(3000.0);
    let bore = centred(Geometry::Cylinder(Cylinder::new(0.21, 2.0).unwrap())).flipped();
    let pin = centred(Geometry::Cylinder(Cylinder::new(0.2, 1.0).unwrap()));
    assert!(contacts(&faceted, &pin, &bore, &Isometry3::identity()).is_empty());
    let tilted = Isometry3::rotation(Vector3::x() * 0.08);
    let c = contacts(&faceted, &pin, &bore, &tilted);
    assert_eq!(c.len(), 2, "{c:?}");
    let (a, b) = (&c[0], &c[1]);
    assert!(a.normal_w.dot(&b.normal_w) < -0.9, "{c:?}");
    for k in &c {
        // Toward the axis: opposite to where the contact sits.
        let radial = Vector3::new(k.point_i_w.x, k.point_i_w.y, 0.0);
        assert!(k.normal_w.dot(&radial) < 0.0, "{k:?}");
        assert!(k.penetration > 0.0, "{k:?}");
    }
    assert!(
        (a.penetration - b.penetration).abs() < 0.05 * a.penetration,
        "{c:?}"
    );
}

/// A body wholly outside its cavity is wholly in the material: one deep contact pushing it
/// back toward the cavity; wholly inside, none.
#[test]
fn a_body_clear_of_its_cavity_is_buried_in_the_material() {
    let faceted = engine(300.0028);
    let socket = GeometryInstance::new(Geometry::sphere(1.0).unwrap()).flipped();
    let ball = GeometryInstance::new(Geometry::sphere(0.2).unwrap());
    assert!(
        contacts(
            &faceted,
            &ball,
            &socket,
            &Isometry3::translation(0.3, 0.0, 0.0)
        )
        .is_empty()
    );
    let out = contacts(
        &faceted,
        &ball,
        &socket,
        &Isometry3::translation(3.0, 0.0, 0.0),
    );
    assert_eq!(out.len(), 1, "{out:?}");
    assert!(out[0].normal_w.x < -0.99, "{out:?}");
    assert!(out[0].penetration > 0.3, "{out:?}");
}

/// A cavity against a PLANE or another cavity has no bounded intersection: refused when the
/// pair is prepared and when it is checked, naming the reason; a flipped open mesh is refused
/// naming the flip argument.
#[test]
fn unbounded_cavity_pairs_and_open_cavities_are_refused() {
    let faceted = engine(300.0028);
    let cavity = GeometryInstance::new(Geometry::sphere(1.0).unwrap()).flipped();
    let plane = GeometryInstance::new(Geometry::Plane(contact_core::geometry::Plane::unbounded()));
    for (i, j) in [(&cavity, &plane), (&plane, &cavity), (&cavity, &cavity)] {
        let Err(err) = faceted.prepare(std::slice::from_ref(i), std::slice::from_ref(j)) else {
            panic!("an unbounded pair was prepared");
        };
        assert!(matches!(err, PrepareError::Unsupported(_)), "{err}");
        assert!(err.to_string().contains("no bounded intersection"), "{err}");
        assert!(faceted.supports_instances(i, j).is_err());
    }
    // A box missing a face.
    let closed = TriangleMesh::boxes(&[(Point3::origin(), Vector3::repeat(0.5))]).unwrap();
    let open = TriangleMesh::new_open(closed.vertices().to_vec(), closed.triangles()[2..].to_vec())
        .unwrap();
    let open = GeometryInstance::new(Geometry::Mesh(std::sync::Arc::new(open))).flipped();
    let ball = GeometryInstance::new(Geometry::sphere(0.2).unwrap());
    let Err(err) = faceted.prepare(&[ball], &[open]) else {
        panic!("a flipped open mesh was prepared");
    };
    assert!(err.to_string().contains("JFLIP_NORMAL"), "{err}");
}
