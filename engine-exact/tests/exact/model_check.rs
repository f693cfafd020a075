//! What the model check sees: `supports` and `prepare` accept the built pairs in either
//! order and refuse the rest with a typed, order-preserving error — never "no contact".

use crate::common::instance;
use contact_core::geometry::{
    Arc, Circle, Cuboid, Curve, CurvePoints, Cylinder, Ellipsoid, Frustum, Line, Plane, Torus,
    TriangleMesh,
};
use contact_core::{
    Geometry, GeometryEngine, GeometryKind, Isometry3, Point2, Point3, PrepareError, WorkCounters,
};
use engine_exact::ExactEngine;
use std::sync::Arc as Shared;

/// One representative geometry of each kind (spheres for the ellipsoid kind, an unbounded
/// plane and line), plus the general ellipsoid, a bounded plane and a bounded line.
fn representatives() -> Vec<Geometry> {
    let tetra = TriangleMesh::new(
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(0.0, 0.0, 1.0),
        ],
        vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    )
    .unwrap();
    let curve = Curve::new(
        &[
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(2.0, 0.0),
            Point2::new(3.0, 1.0),
        ],
        4,
        false,
        CurvePoints::Control,
    )
    .unwrap();
    vec![
        Geometry::sphere(1.0).unwrap(),
        Geometry::Ellipsoid(Ellipsoid::new(1.0, 2.0, 3.0).unwrap()),
        Geometry::Cylinder(Cylinder::new(1.0, 2.0).unwrap()),
        Geometry::Cuboid(Cuboid::centered(1.0, 1.0, 1.0).unwrap()),
        Geometry::Frustum(Frustum::new(1.0, 0.5, 2.0).unwrap()),
        Geometry::Torus(Torus::new(2.0, 0.5).unwrap()),
        Geometry::Mesh(Shared::new(tetra)),
        Geometry::Plane(Plane::unbounded()),
        Geometry::Plane(Plane::bounded(-1.0, 1.0, -1.0, 1.0).unwrap()),
        Geometry::Point,
        Geometry::Circle(Circle::new(1.0).unwrap()),
        Geometry::Arc(Arc::new(1.0, 3.0).unwrap()),
        Geometry::Curve(Shared::new(curve)),
        Geometry::Line(Line::unbounded()),
        Geometry::Line(Line::bounded(-1.0, 1.0).unwrap()),
    ]
}

/// The built pairs, by name, in canonical order (the table in `engine_exact::dispatch`).
const BUILT: [(&str, &str); 59] = [
    ("torus", "torus"),
    ("mesh", "mesh"),
    ("cylinder", "frustum"),
    ("cylinder", "torus"),
    ("frustum", "torus"),
    ("frustum", "frustum"),
    ("ellipsoid", "mesh"),
    ("torus", "mesh"),
    ("cylinder", "mesh"),
    ("frustum", "mesh"),
    ("box", "mesh"),
    ("mesh", "bounded plane"),
    ("box", "frustum"),
    ("box", "torus"),
    ("frustum", "bounded plane"),
    ("torus", "bounded plane"),
    ("ellipsoid", "bounded plane"),
    ("sphere", "bounded plane"),
    ("cylinder", "cylinder"),
    ("cylinder", "box"),
    ("cylinder", "bounded plane"),
    ("sphere", "mesh"),
    ("point", "arc"),
    ("circle", "arc"),
    ("mesh", "plane"),
    ("sphere", "box"),
    ("sphere", "cylinder"),
    ("sphere", "frustum"),
    ("sphere", "torus"),
    ("point", "curve"),
    ("circle", "curve"),
    ("cylinder", "plane"),
    ("frustum", "plane"),
    ("torus", "plane"),
    ("sphere", "sphere"),
    ("sphere", "plane"),
    ("ellipsoid", "plane"),
    ("ellipsoid", "ellipsoid"),
    ("sphere", "ellipsoid"),
    ("ellipsoid", "box"),
    ("ellipsoid", "cylinder"),
    ("ellipsoid", "frustum"),
    ("ellipsoid", "torus"),
    ("box", "box"),
    ("box", "plane"),
    ("box", "bounded plane"),
    ("point", "circle"),
    ("point", "line"),
    ("circle", "circle"),
    ("circle", "line"),
    ("point", "bounded line"),
    ("circle", "bounded line"),
    ("arc", "arc"),
    ("arc", "curve"),
    ("arc", "line"),
    ("curve", "curve"),
    ("curve", "line"),
    ("arc", "bounded line"),
    ("curve", "bounded line"),
];

fn name(g: &Geometry) -> &'static str {
    match g {
        Geometry::Ellipsoid(e) if e.sphere_radius().is_some() => "sphere",
        Geometry::Plane(p) if !p.is_unbounded() => "bounded plane",
        Geometry::Line(l) if l.x_range().iter().any(|x| x.is_finite()) => "bounded line",
        other => match other.kind() {
            GeometryKind::Ellipsoid => "ellipsoid",
            GeometryKind::Cuboid => "box",
            GeometryKind::Cylinder => "cylinder",
            GeometryKind::Curve => "curve",
            GeometryKind::Frustum => "frustum",
            GeometryKind::Torus => "torus",
            GeometryKind::Mesh => "mesh",
            GeometryKind::Arc => "arc",
            GeometryKind::Plane => "plane",
            GeometryKind::Point => "point",
            GeometryKind::Circle => "circle",
            GeometryKind::Line => "line",
        },
    }
}

#[test]
fn supports_is_symmetric_and_matches_the_table() {
    let all = representatives();
    let mut accepted = 0;
    for a in &all {
        for b in &all {
            let forward = ExactEngine.supports(a, b);
            let backward = ExactEngine.supports(b, a);
            assert_eq!(forward.is_ok(), backward.is_ok(), "{a:?} / {b:?}");
            let expected =
                BUILT.contains(&(name(a), name(b))) || BUILT.contains(&(name(b), name(a)));
            assert_eq!(
                forward.is_ok(),
                expected,
                "{} / {}: {forward:?}",
                name(a),
                name(b)
            );
            match forward {
                Ok(()) => accepted += 1,
                Err(e) => {
                    assert_eq!(
                        (e.i, e.j),
                        (a.kind(), b.kind()),
                        "the error keeps the caller's order"
                    );
                    assert_eq!(e.engine, "exact");
                    assert!(!e.reason.is_empty());
                }
            }
        }
    }
    // 59 distinct pairs, 49 of them between different representatives (both orders count).
    assert_eq!(accepted, 10 + 2 * 49);
}

#[test]
fn prepare_refuses_what_it_cannot_answer_before_any_query() {
    let cube = || instance(Geometry::Cuboid(Cuboid::centered(1.0, 1.0, 1.0).unwrap()));
    let plane = || instance(Geometry::Plane(Plane::unbounded()));
    let torus = instance(Geometry::Torus(Torus::new(1.0, 0.5).unwrap()));
    let err = ExactEngine
        .prepare(&[torus.clone().flipped()], std::slice::from_ref(&torus))
        .unwrap_err();
    assert!(matches!(err, PrepareError::Unsupported(_)), "{err}");
    // A flipped box is refused at prepare (supports cannot see flips).
    let err = ExactEngine
        .prepare(&[cube().flipped()], &[plane()])
        .unwrap_err();
    assert!(err.to_string().contains("flipped"), "{err}");
    let err = ExactEngine
        .prepare(&[cube()], &[instance(Geometry::Point)])
        .unwrap_err();
    assert!(matches!(err, PrepareError::MixedDimensions { .. }), "{err}");
    assert!(matches!(
        ExactEngine.prepare(&[], &[plane()]).unwrap_err(),
        PrepareError::EmptyList { .. }
    ));
}

#[test]
fn lists_give_one_contact_per_touching_pair_with_their_indices_and_counted_work() {
    let ball = |r| instance(Geometry::sphere(r).unwrap());
    let cube = instance(Geometry::Cuboid(Cuboid::centered(1.0, 1.0, 1.0).unwrap()));
    // I: a ball at the part origin and a cube 10 above; J: the ground and a ceiling at 100
    // (a flipped plane: its material lies above).
    let i = vec![ball(1.0), cube.at(Isometry3::translation(0.0, 0.0, 10.0))];
    let j = vec![
        instance(Geometry::Plane(Plane::unbounded())),
        instance(Geometry::Plane(Plane::unbounded()))
            .flipped()
            .at(Isometry3::translation(0.0, 0.0, 100.0)),
    ];
    let pair = ExactEngine.prepare(&i, &j).unwrap();
    assert_eq!(pair.stats().geometries, 4);
    let mut out = Vec::new();
    let mut work = WorkCounters::default();
    pair.query(
        &Isometry3::translation(0.0, 0.0, 0.5),
        &Isometry3::identity(),
        &mut out,
        &mut work,
    )
    .unwrap();
    assert_eq!(out.len(), 1);
    assert_eq!((out[0].geometry_i, out[0].geometry_j), (0, 0));
    assert_eq!(work.queries, 1);
    assert_eq!(work.geometry_pairs, 4);
    assert_eq!(work.primitive_tests, 4);
    assert_eq!(work.contacts, 1);
    // Lower the part so the cube (10 up) reaches the ground too.
    pair.query(
        &Isometry3::translation(0.0, 0.0, -9.5),
        &Isometry3::identity(),
        &mut out,
        &mut work,
    )
    .unwrap();
    assert_eq!(out.len(), 2);
    assert_eq!((out[1].geometry_i, out[1].geometry_j), (1, 0));
    assert!((out[1].penetration - 0.5).abs() < 1e-13);
}

#[test]
fn flipped_general_ellipsoid_pairs_are_refused() {
    let general = || instance(Geometry::Ellipsoid(Ellipsoid::new(1.0, 2.0, 3.0).unwrap()));
    let others = [
        general(),
        instance(Geometry::sphere(1.0).unwrap()),
        instance(Geometry::Cuboid(Cuboid::centered(1.0, 1.0, 1.0).unwrap())),
        instance(Geometry::Cylinder(Cylinder::new(1.0, 2.0).unwrap())),
    ];
    for other in &others {
        // A flipped box, cylinder or ellipsoid is a cavity the ellipsoid may sit in (built;
        // tested in mesh_revolved and ellipsoid_cavity); a flipped ellipsoid is one around
        // an ellipsoid or a sphere.
        let cavity = matches!(
            *other.geometry,
            Geometry::Cuboid(_) | Geometry::Cylinder(_) | Geometry::Ellipsoid(_)
        );
        let around = matches!(*other.geometry, Geometry::Ellipsoid(_));
        for (i, j, built) in [
            (general().flipped(), other.clone(), around),
            (general(), other.clone().flipped(), cavity),
            (other.clone().flipped(), general(), cavity),
            (general().flipped(), other.clone().flipped(), false),
        ] {
            let result = ExactEngine.prepare(&[i], &[j]);
            if built {
                assert!(result.is_ok(), "{result:?}");
            } else {
                let err = result.unwrap_err();
                assert!(
                    err.to_string().contains("flipped") || err.to_string().contains("no volume"),
                    "{err}"
                );
            }
        }
    }
}
