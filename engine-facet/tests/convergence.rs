//! Depth, normal and point converge to closed forms as FT rises.

use crate::common::*;
use contact_core::geometry::Plane;
use contact_core::{Geometry, Isometry3, UnitQuaternion, Vector3};

#[test]
fn probe() {
    for ft in [100.0, 300.0028, 1000.0, 3000.0] {
        let e = engine(ft);
        let mut rng = Rng(7);
        for _ in 0..3 {
            let rot = rng.rotation();
            let (c, w) = query(
                &e,
                Geometry::sphere(1.0).unwrap(),
                Geometry::Plane(Plane::unbounded()),
                Isometry3::from_parts(Vector3::new(0.3, -0.2, 0.8).into(), rot),
                Isometry3::identity(),
            );
            println!("ft {ft} plane {:?} {:?}", c, w);
            let (c, w) = query(
                &e,
                Geometry::sphere(1.0).unwrap(),
                Geometry::sphere(0.5).unwrap(),
                Isometry3::from_parts(Vector3::new(0.0, 0.0, 1.3).into(), rot),
                Isometry3::from_parts(Vector3::zeros().into(), UnitQuaternion::identity()),
            );
            println!("ft {ft} sphere {:?} {:?}", c, w);
        }
    }
}
