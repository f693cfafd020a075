//! Regressions, each named after what went wrong, with its reproducer.

use crate::common::{Rng, instance, one};
use contact_core::geometry::{Curve, CurvePoints, Cylinder, Plane};
use contact_core::{Geometry, Isometry3, Point2, UnitQuaternion, Vector3};
use std::f64::consts::PI;
use std::sync::Arc;

/// At the end of a knot span the knot lookup switched to the next span, so Newton on a
/// polyline's segment used the following segment's derivative and stopped at the vertex:
/// the point below got the next segment (δ 0.0674) instead of the nearer one (δ 0.0226).
#[test]
fn closest_point_near_a_polyline_vertex_stays_on_its_own_segment() {
    let vertices = [
        Point2::new(0.11798821407379095, 0.2453913394360172),
        Point2::new(1.1447745151079238, -0.4757140072853828),
        Point2::new(1.8858855138364574, 0.20525468898165689),
        Point2::new(2.794934687374525, -0.47464601886924374),
        Point2::new(3.826850426665854, 0.08941970121990506),
        Point2::new(5.152794193831549, -0.015085629599315697),
    ];
    let curve = Curve::new(&vertices, 2, false, CurvePoints::Control).unwrap();
    let p = Point2::new(1.1053695161787735, -0.4204078626044989);
    // Independent answer: projection on the first segment.
    let (a, b) = (vertices[0], vertices[1]);
    let d = b - a;
    let t = (p - a).dot(&d) / d.norm_squared();
    let q = a + t * d;
    let n = nalgebra::Vector2::new(d.y, -d.x).normalize();
    let expected_depth = -(p - q).dot(&n);
    let c = one(
        &instance(Geometry::Point),
        &instance(Geometry::Curve(Arc::new(curve))),
        &Isometry3::translation(p.x, p.y, 0.0),
        &Isometry3::identity(),
    );
    assert!(
        (c.penetration - expected_depth).abs() < 1e-14,
        "{c:?} vs {expected_depth}"
    );
    assert!((c.point_j_w.x - q.x).abs() < 1e-14 && (c.point_j_w.y - q.y).abs() < 1e-14);
}

/// A cylinder lying on a plane at a grazing depth (1e-12 of its radius), its axis parallel to
/// the plane up to the round-off of composing the poses (a tilt of about 1e-16): the line
/// contact's centroid slid along the axis by up to 1e-3 of the length, because a tilt that
/// small over the length is comparable to the depth itself. The axis is now taken as parallel
/// when its tilt is below round-off, so the contact sits at the middle of the axis, as the
/// closed form of the parallel pose says; a tilt well above round-off is still followed.
#[test]
fn a_grazing_line_contact_does_not_amplify_round_off_along_its_axis() {
    let (radius, length) = (0.5, 2.0);
    let cylinder = instance(Geometry::Cylinder(Cylinder::new(radius, length).unwrap()));
    let plane = instance(Geometry::Plane(Plane::unbounded()));
    let mut rng = Rng::new(7);
    for k in 0..200 {
        let depth = radius * [1e-12, 1e-9, 1e-6][k % 3];
        // The plane at a random world pose; the cylinder lying on it, axis along a random
        // direction in the plane, its middle above the plane's point (x, y).
        let world_plane = rng.pose(5.0);
        let spin = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, 6.3));
        let lying = spin * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.5 * PI);
        let (x, y) = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        let middle = Vector3::new(x, y, radius - depth);
        let base = middle - lying * Vector3::new(0.0, 0.0, 0.5 * length);
        let plane_cylinder = Isometry3::from_parts(base.into(), lying);
        let c = one(
            &cylinder,
            &plane,
            &(world_plane * plane_cylinder),
            &world_plane,
        );
        // Independent answer for the parallel pose: the segment of depth `depth` under the
        // whole length, its centroid below the middle; the points on the line through it.
        let on_plane = world_plane * nalgebra::Point3::new(x, y, 0.0);
        let along = (c.point_j_w - on_plane).norm();
        assert!(
            along <= 1e-12 * length,
            "pose {k}, depth {depth:e}: the plane point is {along:e} from below the middle"
        );
        assert!((c.penetration - depth).abs() <= 1e-12 * radius, "{c:?}");
    }
    // A tilt τ = 1e-9 rad at a depth h = 1e-6 of the radius is resolved, not snapped: the
    // sections' areas grow as (h + τs)^(3/2) along the axis, so the centroid moves off the
    // middle by τL²/(8h) to first order in τL/h (4e-3 here).
    let tau = 1e-9;
    let tilt = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tau);
    let lying = tilt * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.5 * PI);
    let depth = 1e-6 * radius;
    let middle = Vector3::new(0.0, 0.0, radius - depth);
    let base = middle - lying * Vector3::new(0.0, 0.0, 0.5 * length);
    let c = one(
        &cylinder,
        &plane,
        &Isometry3::from_parts(base.into(), lying),
        &Isometry3::identity(),
    );
    let slide = tau * length * length / (8.0 * depth);
    let got = c.point_j_w.y.abs();
    assert!(
        (got - slide).abs() <= 1e-2 * slide,
        "{got:e} vs {slide:e}: {c:?}"
    );
}

/// Two turned ellipsoids touching at their support points, pressed together by 1e-12 of
/// their size: the true lens is about 1e-6 across and 1e-12 thick, a volume far below the
/// round-off of the slicing quadrature. Its computed centroid was then noise, and the line
/// through it along the normal crossed the surfaces 1e-3 of the size apart: a penetration
/// 1e9 times the true one. The answer must be a contact at most a few times deeper than the
/// overlap, or none.
#[test]
fn a_grazing_ellipsoid_lens_is_not_deeper_than_its_overlap() {
    use contact_core::geometry::Ellipsoid;
    let a = Ellipsoid::new(1.0, 0.6, 0.4).unwrap();
    let b = Ellipsoid::new(0.8, 0.8, 0.5).unwrap();
    let (gi, gj) = (
        instance(Geometry::Ellipsoid(a)),
        instance(Geometry::Ellipsoid(b)),
    );
    // The support point of an ellipsoid with semi-axes `s`, turned by `r`, along `u`.
    let support = |s: Vector3, r: &UnitQuaternion, u: &Vector3| {
        let local = r.inverse() * u;
        let scaled = s.component_mul(&local);
        r * (s.component_mul(&scaled) / scaled.norm())
    };
    let mut rng = Rng::new(11);
    for k in 0..40 {
        let depth = [1e-12, 1e-10, 1e-8, 1e-6][k % 4] * 0.4;
        let (ri, rj) = (rng.rotation(), rng.rotation());
        let u = rng.unit_vector();
        let on_j = support(b.semi_axes(), &rj, &u);
        let on_i = support(a.semi_axes(), &ri, &-u);
        let pose_j = Isometry3::from_parts(Vector3::zeros().into(), rj);
        let pose_i = Isometry3::from_parts((on_j - on_i - u * depth).into(), ri);
        let world = rng.pose(5.0);
        let out = crate::common::query(&gi, &gj, &(world * pose_i), &(world * pose_j));
        assert!(out.len() <= 1, "{out:?}");
        for c in &out {
            assert!(
                c.penetration <= 4.0 * depth + 1e-12,
                "pose {k}, overlap {depth:e}: {c:?}"
            );
        }
        if depth >= 1e-6 * 0.4 {
            assert_eq!(out.len(), 1, "pose {k}, overlap {depth:e}");
            assert!(
                (out[0].penetration - depth).abs() <= 0.05 * depth,
                "{:?}",
                out[0]
            );
        }
    }
}

/// The regions of a solid against a mesh were joined across a cut by the chords' indices in
/// slices just off the cut, which may hold a round-off chord more than the piece's middle
/// (the cut a few ulps from its event): a tilted frustum through a box mesh's top face, where
/// the face's diagonal pierces the frustum's side 1.4e-7 above where the face first touches
/// it, came out as two contacts (depths 0.89 and 13.3) instead of one. The same box as a box
/// is the oracle.
#[test]
fn a_chord_of_round_off_length_does_not_split_a_mesh_region() {
    use contact_core::geometry::{Cuboid, Frustum};
    use nalgebra::{Quaternion, Translation3};
    let h = 10.21013006913768;
    let frustum = Frustum::new(1.27626625864221, 1.0532439000904752, 1.1444786565947003).unwrap();
    let pose_i = Isometry3::from_parts(
        Translation3::new(-1.809003494924881, 0.40255571174116433, -0.9268775037399369),
        UnitQuaternion::from_quaternion(Quaternion::new(
            -0.9741240407888629,
            0.15604607161994802,
            -0.10238576717297311,
            0.1274720807453974,
        )),
    );
    let pose_j = Isometry3::from_parts(
        Translation3::new(-2.7885562509904114, -6.454173172169375, -7.345033912417039),
        UnitQuaternion::from_quaternion(Quaternion::new(
            0.8448560972313947,
            -0.3334021746768694,
            0.19233259348444393,
            0.37157682701591893,
        )),
    );
    let mesh = crate::common::boxes_mesh(&[(contact_core::Point3::origin(), Vector3::repeat(h))]);
    let i = instance(Geometry::Frustum(frustum));
    let got = one(
        &i,
        &instance(Geometry::Mesh(Arc::new(mesh))),
        &pose_i,
        &pose_j,
    );
    let want = one(
        &i,
        &instance(Geometry::Cuboid(Cuboid::centered(h, h, h).unwrap())),
        &pose_i,
        &pose_j,
    );
    crate::common::assert_close(&got, &want, 1.3, 1.3 * 1.3, 1e-9, "frustum on a box mesh");
}
