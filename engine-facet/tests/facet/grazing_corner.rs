//! A turned box's corner grazing the middle of another box's face, where that face's two
//! triangles meet: the crossings there are round-off, and a region whose loop enclosed no area
//! once took the centroid of round-off volume sums, far from the contact (a penetration of
//! 0.18 for a true one of 5e-13). The corner's crossings fall on both of the face's triangles,
//! and no single triangle of the corner crosses both; they are still one region (the loop goes
//! on across the edges its segments end on), so one contact, not two identical ones.

use crate::common::{Rng, engine, prepare, query_pair};
use contact_core::geometry::Cuboid;
use contact_core::{Geometry, Isometry3, Vector3};

#[test]
fn a_corner_grazing_a_face_gives_a_penetration_at_the_grazing_depth() {
    let (a, b) = (
        Cuboid::centered(1.0, 0.7, 0.5).unwrap(),
        Cuboid::centered(0.6, 0.6, 0.9).unwrap(),
    );
    let pair = prepare(&engine(300.0028), Geometry::Cuboid(a), Geometry::Cuboid(b));
    let mut rng = Rng(0x5eed);
    for depth in [1e-12, 1e-9, 1e-6] {
        for k in 0..50 {
            // I's deepest corner along −z placed `depth` below the middle of J's top face.
            let rotation = rng.rotation();
            let local_down = rotation.inverse() * -Vector3::z();
            let corner = a.half_extents().component_mul(&local_down.map(f64::signum));
            let top = Vector3::new(0.0, 0.0, 0.9 - depth);
            let pose_i = Isometry3::from_parts((top - rotation * corner).into(), rotation);
            let (contacts, _) = query_pair(pair.as_ref(), pose_i, Isometry3::identity());
            assert!(
                contacts.len() <= 1,
                "depth {depth:e}, pose {k}: {contacts:?}"
            );
            for c in &contacts {
                assert!(
                    c.penetration <= 2.0 * depth + 1e-12,
                    "depth {depth:e}, pose {k}: {c:?}"
                );
            }
            if depth >= 1e-6 {
                assert!(!contacts.is_empty(), "depth {depth:e}, pose {k}");
            }
        }
    }
}
