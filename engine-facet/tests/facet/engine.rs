//! The engine as a whole: what is prepared, booleans against closed forms, containment,
//! unsupported pairs and bad input.

use crate::common::*;
use contact_core::geometry::Plane;
use contact_core::{
    FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, Isometry3, PrepareError, Vector3,
};
use engine_facet::tessellate::counts;

#[test]
fn only_the_geometry_a_contact_names_is_faceted_and_shared_geometry_once() {
    let e = engine(300.0028);
    let ball = GeometryInstance::new(Geometry::sphere(1.0).unwrap());
    let twin = ball.clone().at(Isometry3::translation(3.0, 0.0, 0.0)); // same Arc<Geometry>
    let ground = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
    // A model might also hold a torus no contact uses: it is never passed, so never built.
    let pair = e.prepare(&[ball.clone(), twin], &[ground]).unwrap();
    let stats = pair.stats();
    assert_eq!(stats.geometries, 3);
    let per_ball = counts(&ball.geometry, FacetingTolerance::DEFAULT)
        .unwrap()
        .triangles as usize;
    assert_eq!(
        stats.triangles,
        2 * per_ball,
        "the plane is not tessellated"
    );
    let only_one = e
        .prepare(
            std::slice::from_ref(&ball),
            &[GeometryInstance::new(Geometry::sphere(0.5).unwrap())],
        )
        .unwrap();
    assert_eq!(only_one.stats().geometries, 2);
    let c = pair_contacts(pair.as_ref(), Isometry3::translation(0.0, 0.0, 0.9));
    assert_eq!(c.len(), 2, "both balls touch the ground");
    assert_eq!((c[0].geometry_i, c[1].geometry_i), (0, 1));
}

fn pair_contacts(
    pair: &dyn contact_core::PreparedPair,
    pose_i: Isometry3,
) -> Vec<contact_core::Contact> {
    query_pair(pair, pose_i, Isometry3::identity()).0
}

#[test]
fn touching_or_not_agrees_with_the_closed_form_away_from_the_faceting_band() {
    let e = engine(300.0028);
    let (r1, r2) = (1.0, 0.6);
    let pair = prepare(
        &e,
        Geometry::sphere(r1).unwrap(),
        Geometry::sphere(r2).unwrap(),
    );
    let band = 2.0 * (2.0 * 3f64.sqrt() * r1) / 300.0028; // both meshes' deviations
    let mut rng = Rng(77);
    let (mut yes, mut no) = (0, 0);
    for _ in 0..200 {
        let d = rng.range(0.0, 2.0 * (r1 + r2));
        if (d - (r1 + r2)).abs() < band {
            continue;
        }
        let pose = Isometry3::from_parts((rng.unit_vector() * d).into(), rng.rotation());
        let c = pair_contacts(pair.as_ref(), pose);
        let touching = d < r1 + r2;
        assert_eq!(!c.is_empty(), touching, "d = {d}: {c:?}");
        if touching {
            assert_eq!(c.len(), 1, "one region, d = {d}");
            yes += 1;
        } else {
            no += 1;
        }
    }
    assert!(yes > 50 && no > 50);
}

#[test]
fn a_body_wholly_inside_another_is_a_contact() {
    let e = engine(300.0028);
    let pair = prepare(
        &e,
        Geometry::sphere(0.3).unwrap(),
        Geometry::sphere(2.0).unwrap(),
    );
    // I's centre 1.2 from J's along x: the way out is +x, I must move 2.0 − 1.2 + 0.3 = 1.1.
    // The containment normal comes from the closest facet point of the outer mesh: it is good to
    // one facet angle 2π/n of the outer sphere's tessellation (documented in `containment`).
    let facet_angle = |r: f64| {
        let n = counts(&Geometry::sphere(r).unwrap(), FacetingTolerance::DEFAULT)
            .unwrap()
            .segments;
        360.0 / n as f64
    };
    let c = pair_contacts(pair.as_ref(), Isometry3::translation(1.2, 0.0, 0.0));
    assert_eq!(c.len(), 1, "{c:?}");
    assert!(
        angle_deg(&c[0].normal_w, &Vector3::x()) < facet_angle(2.0),
        "{:?}",
        c[0]
    );
    assert!((c[0].penetration - 1.1).abs() < 0.02, "{:?}", c[0]);
    // And the other way round: J inside I; the normal pushes I so that J leaves through -x.
    let pair = prepare(
        &e,
        Geometry::sphere(2.0).unwrap(),
        Geometry::sphere(0.3).unwrap(),
    );
    let c = pair_contacts(pair.as_ref(), Isometry3::translation(1.2, 0.0, 0.0));
    assert_eq!(c.len(), 1, "{c:?}");
    assert!(
        angle_deg(&c[0].normal_w, &Vector3::x()) < facet_angle(2.0),
        "{:?}",
        c[0]
    );
    assert!((c[0].penetration - 1.1).abs() < 0.02, "{:?}", c[0]);
}

#[test]
fn a_torus_on_a_plane_gives_one_region_and_swapping_i_and_j_swaps_the_contact() {
    let e = engine(300.0028);
    let torus = Geometry::Torus(contact_core::geometry::Torus::new(2.0, 0.5).unwrap());
    let ground = Geometry::Plane(Plane::unbounded());
    // Lying flat, 0.1 into the plane: an annulus, one region.
    let (c, _) = query(
        &e,
        torus.clone(),
        ground.clone(),
        Isometry3::translation(0.0, 0.0, 0.4),
        Isometry3::identity(),
    );
    assert_eq!(c.len(), 1, "{c:?}");
    assert!(c[0].normal_w.z > 0.999);
    let (s, _) = query(
        &e,
        ground,
        torus,
        Isometry3::identity(),
        Isometry3::translation(0.0, 0.0, 0.4),
    );
    assert_eq!(s.len(), 1);
    assert!((s[0].normal_w + c[0].normal_w).norm() < 1e-12);
    assert!((s[0].penetration - c[0].penetration).abs() < 1e-12);
}

#[test]
fn unsupported_pairs_and_bad_input_are_errors() {
    let e = engine(300.0028);
    let circle = Geometry::Circle(contact_core::geometry::Circle::new(1.0).unwrap());
    assert!(e.supports(&circle, &circle).is_ok());
    let arc = Geometry::Arc(contact_core::geometry::Arc::new(1.0, 1.0).unwrap());
    assert!(
        e.supports(&arc, &arc).is_ok(),
        "two arcs overlap as regions"
    );
    let err = e.supports(&Geometry::Point, &Geometry::Point).unwrap_err();
    assert!(err.to_string().contains("point or a circle"), "{err}");
    let ball = Geometry::sphere(1.0).unwrap();
    let err = e.supports(&circle, &ball).unwrap_err();
    assert!(err.to_string().contains("2-D"), "{err}");
    let plane = Geometry::Plane(Plane::unbounded());
    assert!(e.supports(&plane, &plane).is_err());
    let flipped = GeometryInstance::new(Geometry::sphere(1.0).unwrap()).flipped();
    let err = e
        .prepare(&[flipped], &[GeometryInstance::new(plane)])
        .unwrap_err();
    // A cavity against a half-space: unbounded (tests/facet/cavities.rs has the rest).
    assert!(err.to_string().contains("no bounded intersection"), "{err}");
    let tiny_cap = e.clone().with_max_triangles(100).unwrap();
    let err = tiny_cap
        .prepare(
            &[GeometryInstance::new(Geometry::sphere(1.0).unwrap()).labeled("ball")],
            &[GeometryInstance::new(Geometry::sphere(1.0).unwrap())],
        )
        .unwrap_err();
    assert!(
        matches!(err, PrepareError::TooManyTriangles { limit: 100, .. }),
        "{err}"
    );
    assert!(err.to_string().contains("'ball'"));
    let pair = prepare(
        &e,
        Geometry::sphere(1.0).unwrap(),
        Geometry::sphere(1.0).unwrap(),
    );
    let bad = Isometry3::translation(f64::NAN, 0.0, 0.0);
    assert!(
        pair.query(
            &bad,
            &Isometry3::identity(),
            &mut Vec::new(),
            &mut Default::default()
        )
        .is_err()
    );
}

/// The contacts of `pair` with I at `pose_i` and J at the origin, as bits, and the triangles
/// the query tested.
fn contact_bits(pair: &dyn contact_core::PreparedPair, pose_i: &Isometry3) -> (Vec<u64>, u64) {
    let mut out = Vec::new();
    let mut work = contact_core::WorkCounters::default();
    pair.query(pose_i, &Isometry3::identity(), &mut out, &mut work)
        .unwrap();
    let bits = out
        .iter()
        .flat_map(|c| {
            let (pi, pj, n) = (c.point_i_w, c.point_j_w, c.normal_w);
            [
                pi.x,
                pi.y,
                pi.z,
                pj.x,
                pj.y,
                pj.z,
                n.x,
                n.y,
                n.z,
                c.penetration,
                c.area,
            ]
        })
        .map(f64::to_bits)
        .collect();
    (bits, work.primitive_tests)
}

#[test]
fn a_mesh_moved_along_a_plane_answers_as_a_fresh_pair_does() {
    // A tilted cylinder resting on the ground, then moved along the ground (the pair then
    // reuses its last contacts, moved with it), lowered, turned, and moved back: each answer
    // is a fresh pair's to the bit, and the moved one is the first moved along.
    let e = engine(300.0028);
    let cylinder = GeometryInstance::new(Geometry::Cylinder(
        contact_core::geometry::Cylinder::new(0.1, 0.3).unwrap(),
    ));
    let ground = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
    let prepare = || {
        e.prepare(
            std::slice::from_ref(&cylinder),
            std::slice::from_ref(&ground),
        )
        .unwrap()
    };
    let tilt = contact_core::UnitQuaternion::from_euler_angles(0.2, -0.1, 0.3);
    let at = |x: f64, y: f64, z: f64, r| Isometry3::from_parts(Vector3::new(x, y, z).into(), r);
    let poses = [
        at(0.0, 0.0, -0.01, tilt),
        at(0.37, -1.25, -0.01, tilt),
        at(0.37, -1.25, -0.02, tilt),
        at(
            0.37,
            -1.25,
            -0.02,
            contact_core::UnitQuaternion::identity() * tilt * tilt,
        ),
        at(0.0, 0.0, -0.01, tilt),
    ];
    let kept = prepare();
    let answers: Vec<(Vec<u64>, u64)> = poses
        .iter()
        .map(|p| contact_bits(kept.as_ref(), p))
        .collect();
    for (k, pose) in poses.iter().enumerate() {
        let (fresh, tested) = contact_bits(prepare().as_ref(), pose);
        assert!(!fresh.is_empty() && tested > 0, "pose {k} touches");
        assert_eq!(answers[k].0, fresh, "pose {k}");
        // Only the pose moved along the plane is answered without testing a triangle.
        assert_eq!(
            answers[k].1 == 0,
            k == 1,
            "pose {k}: {} tested",
            answers[k].1
        );
    }
    assert_ne!(answers[0].0, answers[1].0, "the moved contacts are moved");
}
