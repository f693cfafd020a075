//! A mesh far along an unbounded plane from the plane's origin meets it as it does near the
//! origin: the contact is the same up to the translation (translation along the plane is a
//! symmetry of the pair), in both pair orders. The heights come from the mesh's position in the
//! plane's frame, so 0.1 above the plane at 7.8e85 along it is still 0.1 (the `poses` fuzz
//! target's regression, `fuzz/regressions/poses-far-from-the-plane.txt`).

use crate::common::{Rng, engine, prepare, query_pair};
use contact_core::geometry::{Cuboid, Ellipsoid, Plane};
use contact_core::{Contact, Geometry, GeometryEngine, Isometry3, UnitQuaternion, Vector3};

/// The contacts' depth, normal, area and the points' offsets from the mesh's origin.
fn relative(contacts: &[Contact], pose_mesh: &Isometry3) -> Vec<[f64; 10]> {
    contacts
        .iter()
        .map(|c| {
            let t = pose_mesh.translation.vector;
            let (pi, pj) = (c.point_i_w.coords - t, c.point_j_w.coords - t);
            let n = c.normal_w;
            [
                c.penetration,
                c.area,
                n.x,
                n.y,
                n.z,
                pi.y,
                pi.z,
                pj.y,
                pj.z,
                // The x offsets are only known to the translation's ulp (1e70): kept out.
                0.0,
            ]
        })
        .collect()
}

fn compare(mesh: Geometry, size: f64, heights: &[f64]) {
    let plane = || Geometry::Plane(Plane::unbounded());
    for ft in [300.0028, 3000.0] {
        let mesh_first = prepare(&engine(ft), mesh.clone(), plane());
        let plane_first = prepare(&engine(ft), plane(), mesh.clone());
        let mut rng = Rng(0xfa7_0ff);
        for &h in heights {
            let rotation: UnitQuaternion = rng.rotation();
            let near = Isometry3::from_parts(Vector3::new(0.0, -332.0, h).into(), rotation);
            let far = Isometry3::from_parts(Vector3::new(7.8e85, -332.0, h).into(), rotation);
            let (want, _) = query_pair(mesh_first.as_ref(), near, Isometry3::identity());
            assert!(
                !want.is_empty(),
                "FT {ft}, h = {h}: no contact near the origin"
            );
            let (want_swapped, _) = query_pair(plane_first.as_ref(), Isometry3::identity(), near);
            let (got, _) = query_pair(mesh_first.as_ref(), far, Isometry3::identity());
            let (got_swapped, _) = query_pair(plane_first.as_ref(), Isometry3::identity(), far);
            for (found, want) in [(&got, &want), (&got_swapped, &want_swapped)] {
                let (w, g) = (relative(want, &near), relative(found, &far));
                assert_eq!(
                    g.len(),
                    w.len(),
                    "FT {ft}, h = {h}: {found:?} against {want:?}"
                );
                for (g, w) in g.iter().zip(&w) {
                    for (x, y) in g.iter().zip(w) {
                        // Round-off of the size (the near pose's own −332 offset included).
                        assert!(
                            (x - y).abs() <= 1e-12 * (332.0 + size),
                            "FT {ft}, h = {h}: {g:?} against {w:?}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn an_ellipsoid_far_along_the_plane_keeps_its_contact() {
    let ellipsoid = Geometry::Ellipsoid(Ellipsoid::new(1.0, 0.5, 0.3).unwrap());
    // From a small cap (the closed form) to deep (blended with the facets).
    compare(ellipsoid, 1.0, &[0.1, 0.25, 0.0]);
}

#[test]
fn a_box_far_along_the_plane_keeps_its_contact() {
    let cube = Geometry::Cuboid(Cuboid::centered(0.5, 1.0, 0.25).unwrap());
    compare(cube, 2.0, &[0.1, 0.3, -0.2]);
}

#[test]
fn a_mesh_wholly_under_the_plane_however_deep_has_its_depth() {
    // A box and an ellipsoid (the `poses` fuzz target's find: an ellipsoid 2.2e66 under the
    // plane had NaN points and an infinite depth) wholly under the plane: the line through the
    // centroid leaves the body at its bottom and the half-space at the plane, so the depth is
    // the centroid's depth plus the body's reach below it, as the exact engine says.
    let bodies = [
        Geometry::Cuboid(Cuboid::centered(0.5, 1.0, 0.25).unwrap()),
        Geometry::Ellipsoid(Ellipsoid::new(1.0, 0.5, 0.3).unwrap()),
    ];
    let rotation = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
    for body in bodies {
        let exact = engine_exact::ExactEngine
            .prepare(
                &[contact_core::GeometryInstance::new(body.clone())],
                &[contact_core::GeometryInstance::new(Geometry::Plane(
                    Plane::unbounded(),
                ))],
            )
            .unwrap();
        let faceted = prepare(
            &engine(300.0028),
            body.clone(),
            Geometry::Plane(Plane::unbounded()),
        );
        for depth in [10.0, 1e20, 2.2e66] {
            let pose = Isometry3::from_parts(Vector3::new(0.3, -0.9, -depth).into(), rotation);
            let (want, _) = query_pair(exact.as_ref(), pose, Isometry3::identity());
            let (got, _) = query_pair(faceted.as_ref(), pose, Isometry3::identity());
            assert_eq!(
                (got.len(), want.len()),
                (1, 1),
                "{body:?} at {depth:e}: {got:?}"
            );
            let (g, w) = (got[0], want[0]);
            // Within the chord deviation of the body's reach, relative to the depth's ulp.
            assert!(
                (g.penetration - w.penetration).abs() <= 0.05 + 1e-15 * depth,
                "{body:?} at {depth:e}: {g:?} against {w:?}"
            );
            assert!(
                (g.normal_w - w.normal_w).norm() < 1e-12,
                "{g:?} against {w:?}"
            );
        }
    }
}
