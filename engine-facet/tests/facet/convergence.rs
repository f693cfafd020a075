//! The characterisation table: depth, normal and point errors against closed forms at
//! FT = 100, 300.0028, 1000, 3000, each the worst over several seeded mesh orientations.
//! Printed with `--nocapture`; asserted: the default-FT accuracy of sphere–plane and
//! sphere–sphere (depth within 2 %, normal within 2°), and that every error shrinks from FT = 100
//! to FT = 3000.

use crate::common::*;
use contact_core::geometry::{Cuboid, Cylinder, Plane, Torus};
use contact_core::{Contact, Geometry, Isometry3, Point3, UnitQuaternion, Vector3};

/// A scene with its closed-form answer.
struct Case {
    name: &'static str,
    i: Geometry,
    j: Geometry,
    /// Pose of I for a spin `rot` of I about its own centre (the faceting then lands
    /// differently while the exact answer does not change).
    pose_i: fn(&UnitQuaternion) -> Isometry3,
    pose_j: Isometry3,
    depth: f64,
    normal: Vector3,
    /// Exact contact point on I (the deepest point of I into J).
    point_i: Point3,
}

fn spin_about_z(rot: &UnitQuaternion) -> UnitQuaternion {
    // Keep the axis of a revolved shape where the case needs it: spin about its own axis only.
    let (_, _, yaw) = rot.euler_angles();
    UnitQuaternion::from_euler_angles(0.0, 0.0, yaw)
}

fn cases() -> Vec<Case> {
    let plane = Geometry::Plane(Plane::unbounded());
    vec![
        Case {
            name: "sphere-plane",
            i: Geometry::sphere(1.0).unwrap(),
            j: plane.clone(),
            pose_i: |r| Isometry3::from_parts(Vector3::new(0.3, -0.2, 0.8).into(), *r),
            pose_j: Isometry3::identity(),
            depth: 0.2,
            normal: Vector3::z(),
            point_i: Point3::new(0.3, -0.2, -0.2),
        },
        Case {
            name: "sphere-sphere",
            i: Geometry::sphere(1.0).unwrap(),
            j: Geometry::sphere(0.5).unwrap(),
            // Centres 1.3 apart along (1, 2, 2)/3: depth 1.5 − 1.3.
            pose_i: |r| {
                Isometry3::from_parts(Vector3::new(1.3 / 3.0, 2.6 / 3.0, 2.6 / 3.0).into(), *r)
            },
            pose_j: Isometry3::identity(),
            depth: 0.2,
            normal: Vector3::new(1.0, 2.0, 2.0) / 3.0,
            point_i: Point3::from(Vector3::new(1.0, 2.0, 2.0) / 3.0 * 0.3),
        },
        Case {
            name: "cylinder-plane",
            // Lying on its side: axis along x after a quarter turn about y, centre at z = 0.45.
            i: Geometry::Cylinder(Cylinder::new(0.5, 2.0).unwrap()),
            j: plane.clone(),
            pose_i: |r| {
                let (_, _, spin) = r.euler_angles();
                let lie = UnitQuaternion::from_euler_angles(0.0, std::f64::consts::FRAC_PI_2, 0.0);
                // Spin about the cylinder's own axis (z of G) before lying it down.
                let q = lie * UnitQuaternion::from_euler_angles(0.0, 0.0, spin);
                Isometry3::from_parts(Vector3::new(-1.0, 0.0, 0.45).into(), q)
            },
            pose_j: Isometry3::identity(),
            depth: 0.05,
            normal: Vector3::z(),
            point_i: Point3::new(0.0, 0.0, -0.05),
        },
        Case {
            name: "box-box",
            i: Geometry::Cuboid(Cuboid::centered(0.5, 0.5, 0.5).unwrap()),
            j: Geometry::Cuboid(Cuboid::centered(2.0, 2.0, 0.5).unwrap()),
            pose_i: |r| Isometry3::from_parts(Vector3::new(0.2, 0.1, 0.9).into(), spin_about_z(r)),
            pose_j: Isometry3::identity(),
            depth: 0.1,
            normal: Vector3::z(),
            point_i: Point3::new(0.2, 0.1, 0.4),
        },
        Case {
            name: "torus-plane",
            // Standing like a wheel (axis along y), lowest point 0.1 below the plane.
            i: Geometry::Torus(Torus::new(2.0, 0.5).unwrap()),
            j: plane,
            pose_i: |r| {
                let (_, _, spin) = r.euler_angles();
                let stand =
                    UnitQuaternion::from_euler_angles(std::f64::consts::FRAC_PI_2, 0.0, 0.0);
                let q = stand * UnitQuaternion::from_euler_angles(0.0, 0.0, spin);
                Isometry3::from_parts(Vector3::new(0.0, 0.0, 2.4).into(), q)
            },
            pose_j: Isometry3::identity(),
            depth: 0.1,
            normal: Vector3::z(),
            point_i: Point3::new(0.0, 0.0, -0.1),
        },
    ]
}

const TOLERANCES: [f64; 4] = [100.0, 300.0028, 1000.0, 3000.0];

/// Worst (relative depth error, normal error in degrees, point error / depth) over orientations.
fn errors(case: &Case, ft: f64) -> (f64, f64, f64) {
    let pair = prepare(&engine(ft), case.i.clone(), case.j.clone());
    let mut rng = Rng(0xC0FFEE);
    let (mut depth, mut angle, mut point) = (0.0_f64, 0.0_f64, 0.0_f64);
    for _ in 0..4 {
        let rot = rng.rotation();
        let (contacts, _) = query_pair(pair.as_ref(), (case.pose_i)(&rot), case.pose_j);
        assert_eq!(contacts.len(), 1, "{} at FT {ft}: {contacts:?}", case.name);
        let c: &Contact = &contacts[0];
        depth = depth.max((c.penetration - case.depth).abs() / case.depth);
        angle = angle.max(angle_deg(&c.normal_w, &case.normal));
        point = point.max((c.point_i_w - case.point_i).norm() / case.depth);
    }
    (depth, angle, point)
}

#[test]
fn errors_shrink_as_the_faceting_tolerance_rises() {
    println!("| pair | FT | depth error (rel.) | normal error (°) | point_i error (/depth) |");
    println!("|---|---|---|---|---|");
    for case in cases() {
        let table: Vec<(f64, (f64, f64, f64))> = TOLERANCES
            .iter()
            .map(|&ft| (ft, errors(&case, ft)))
            .collect();
        for (ft, (d, a, p)) in &table {
            println!("| {} | {ft} | {d:.2e} | {a:.2e} | {p:.2e} |", case.name);
        }
        let (first, last) = (table[0].1, table[3].1);
        // Observed order of the depth error between FT = 100 and 3000.
        let order = (first.0 / last.0.max(1e-300)).ln() / 30f64.ln();
        println!("| {} | order | {order:.2} | | |", case.name);
        let default = table[1].1;
        if case.name.starts_with("sphere") {
            assert!(
                default.0 < 0.02,
                "{}: depth error {} at default FT",
                case.name,
                default.0
            );
            assert!(
                default.1 < 2.0,
                "{}: normal error {}° at default FT",
                case.name,
                default.1
            );
        }
        // Exact primitives (box–box) have nothing to converge: errors at round-off.
        if case.name == "box-box" {
            assert!(
                first.0 < 1e-9 && last.0 < 1e-9 && last.1 < 1e-6,
                "{table:?}"
            );
        } else {
            assert!(
                last.0 < first.0 && last.2 < first.2,
                "{}: {table:?}",
                case.name
            );
        }
    }
}
