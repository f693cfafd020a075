//! Closed-form answers for the scenes that have one, written from the SPEC §4 definition
//! independently of either engine: the oracle both engines are measured against.

use super::{Scene, ScenePose};
use contact_core::{Contact, Geometry, Isometry3, Point3, Vector3};
use std::f64::consts::PI;

/// A sphere (I) against an unbounded plane (J). With `d` the height of the centre above the
/// plane: δ = r − d, normal = the plane's +z, the points are the sphere's lowest point and the
/// foot of the centre on the plane, and the area is the cap's base disc π(r² − d²) (0 when the
/// sphere is below the plane's surface entirely, where the cap is the whole sphere).
pub fn sphere_plane(scene: &Scene, pose: &ScenePose) -> Vec<Contact> {
    let (r, x_wi) = sphere_of(scene, true, pose);
    let x_wj = pose.pose_world_j * scene.j[0].pose_part_geometry;
    let n = x_wj.rotation * Vector3::z();
    let c = x_wi.translation.vector;
    let d = n.dot(&(c - x_wj.translation.vector));
    if d >= r {
        return Vec::new();
    }
    vec![Contact {
        point_i_w: Point3::from(c - r * n),
        point_j_w: Point3::from(c - d * n),
        normal_w: n,
        penetration: r - d,
        area: PI * (r * r - d * d).max(0.0),
        geometry_i: 0,
        geometry_j: 0,
    }]
}

/// Two spheres: δ = r_i + r_j − D (D the centre distance), normal from J's centre to I's, the
/// points are each sphere's point on the line of centres, and the area is the lens's circle
/// π·a², a the radius of the circle where the two surfaces meet.
pub fn sphere_sphere(scene: &Scene, pose: &ScenePose) -> Vec<Contact> {
    let (ri, x_wi) = sphere_of(scene, true, pose);
    let (rj, x_wj) = sphere_of(scene, false, pose);
    let (ci, cj) = (x_wi.translation.vector, x_wj.translation.vector);
    let dist = (ci - cj).norm();
    if dist >= ri + rj {
        return Vec::new();
    }
    let n = (ci - cj) / dist;
    // Distance from J's centre to the plane of the meeting circle.
    let xj = (dist * dist + rj * rj - ri * ri) / (2.0 * dist);
    vec![Contact {
        point_i_w: Point3::from(ci - ri * n),
        point_j_w: Point3::from(cj + rj * n),
        normal_w: n,
        penetration: ri + rj - dist,
        area: PI * (rj * rj - xj * xj).max(0.0),
        geometry_i: 0,
        geometry_j: 0,
    }]
}

/// A cylinder (I) lying on an unbounded plane (J), axis parallel to the plane, its axis at
/// height `d < r`: the intersection is a prism over a circular segment whose centroid lies
/// straight below the axis' midpoint, so along the normal through it (SPEC §4) the points are
/// the cylinder's bottom line point and its foot on the plane, δ = r − d, and the area is the
/// footprint L·2·sqrt(r² − d²); wholly under the plane (d ≤ −r) the centroid is the centre,
/// δ = r − d still, and the area is a quarter of the surface.
pub fn cylinder_plane_side(scene: &Scene, pose: &ScenePose) -> Vec<Contact> {
    let Geometry::Cylinder(cyl) = &*scene.i[0].geometry else {
        return Vec::new();
    };
    let x_wi = pose.pose_world_i * scene.i[0].pose_part_geometry;
    let x_wj = pose.pose_world_j * scene.j[0].pose_part_geometry;
    let n = x_wj.rotation * Vector3::z();
    let axis = x_wi.rotation * Vector3::z();
    let mid = x_wi.translation.vector + axis * (0.5 * cyl.length());
    let d = n.dot(&(mid - x_wj.translation.vector));
    let r = cyl.radius();
    if d >= r {
        return Vec::new();
    }
    let immersed = d <= -r;
    let chord = (r * r - d * d).max(0.0).sqrt();
    vec![Contact {
        point_i_w: Point3::from(mid - r * n),
        point_j_w: Point3::from(mid - d * n),
        normal_w: n,
        penetration: r - d,
        area: if immersed {
            0.5 * PI * r * (r + cyl.length())
        } else {
            cyl.length() * 2.0 * chord
        },
        geometry_i: 0,
        geometry_j: 0,
    }]
}

/// Two circles in one plane: as [`sphere_sphere`], with the area the length of the common chord
/// 2·a (the 2-D contact's "area" is the length of its contact segment).
pub fn circle_circle(scene: &Scene, pose: &ScenePose) -> Vec<Contact> {
    let (Geometry::Circle(ci), Geometry::Circle(cj)) =
        (&*scene.i[0].geometry, &*scene.j[0].geometry)
    else {
        return Vec::new();
    };
    let x_wi = pose.pose_world_i * scene.i[0].pose_part_geometry;
    let x_wj = pose.pose_world_j * scene.j[0].pose_part_geometry;
    let (ri, rj) = (ci.radius(), cj.radius());
    let (pi, pj) = (x_wi.translation.vector, x_wj.translation.vector);
    let dist = (pi - pj).norm();
    if dist >= ri + rj {
        return Vec::new();
    }
    let n = (pi - pj) / dist;
    let xj = (dist * dist + rj * rj - ri * ri) / (2.0 * dist);
    vec![Contact {
        point_i_w: Point3::from(pi - ri * n),
        point_j_w: Point3::from(pj + rj * n),
        normal_w: n,
        penetration: ri + rj - dist,
        area: 2.0 * (rj * rj - xj * xj).max(0.0).sqrt(),
        geometry_i: 0,
        geometry_j: 0,
    }]
}

fn sphere_of(scene: &Scene, side_i: bool, pose: &ScenePose) -> (f64, Isometry3) {
    let (instance, part) = if side_i {
        (&scene.i[0], pose.pose_world_i)
    } else {
        (&scene.j[0], pose.pose_world_j)
    };
    let radius = match &*instance.geometry {
        Geometry::Ellipsoid(e) => e.sphere_radius().unwrap_or(f64::NAN),
        _ => f64::NAN,
    };
    (radius, part * instance.pose_part_geometry)
}
