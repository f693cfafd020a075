//! The random scene of each pair family the invariants are checked on.

use super::{Scene, scaled_pose};
use crate::common::{Rng, boxes_mesh, instance};
use contact_core::geometry::{
    Arc, Circle, Cuboid, Curve, CurvePoints, Cylinder, Ellipsoid, Frustum, Line, Plane, Torus,
};
use contact_core::{Geometry, GeometryInstance, Isometry3, Point3, Vector3};
use nalgebra::Translation3;

pub(super) fn sphere_plane(rng: &mut Rng, s: f64) -> Scene {
    let r = rng.uniform(0.5, 2.0);
    let d = rng.uniform(-0.5, 0.99) * r;
    let plane_pose = rng.pose(3.0);
    let pose_i = plane_pose * Isometry3::translation(0.0, 0.0, d);
    Scene {
        i: instance(Geometry::sphere(r * s).unwrap()),
        j: instance(Geometry::Plane(Plane::unbounded())),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&plane_pose, s),
        length: r * s,
    }
}

pub(super) fn sphere_sphere(rng: &mut Rng, s: f64) -> Scene {
    let (ra, rb) = (rng.uniform(0.3, 2.0), rng.uniform(0.3, 2.0));
    let d = rng.uniform(0.1, 0.99) * (ra + rb);
    let pose_j = rng.pose(3.0);
    let pose_i = pose_j * Isometry3::translation(d, 0.0, 0.0) * rng.pose(0.0);
    Scene {
        i: instance(Geometry::sphere(ra * s).unwrap()),
        j: instance(Geometry::sphere(rb * s).unwrap()),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: ra.max(rb) * s,
    }
}

pub(super) fn ellipsoid_plane(rng: &mut Rng, s: f64) -> Scene {
    let axes = Vector3::new(
        rng.uniform(0.3, 2.0),
        rng.uniform(0.3, 2.0),
        rng.uniform(0.3, 2.0),
    );
    let q = rng.rotation();
    let k = axes
        .component_mul(&q.inverse_transform_vector(&Vector3::z()))
        .norm();
    let plane_pose = rng.pose(3.0);
    let pose_i = plane_pose
        * Isometry3::from_parts(Translation3::new(0.0, 0.0, k * rng.uniform(-0.8, 0.99)), q);
    let e = Ellipsoid::new(axes.x * s, axes.y * s, axes.z * s).unwrap();
    Scene {
        i: instance(Geometry::Ellipsoid(e)),
        j: instance(Geometry::Plane(Plane::unbounded())),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&plane_pose, s),
        length: axes.max() * s,
    }
}

pub(super) fn cylinder_plane(rng: &mut Rng, s: f64) -> Scene {
    let (r, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.2, 3.0));
    let plane_pose = rng.pose(3.0);
    // Half the scenes lie exactly on the side (axis parallel to the plane).
    let q = if rng.uniform(0.0, 1.0) < 0.5 {
        nalgebra::UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::FRAC_PI_2)
    } else {
        rng.rotation()
    };
    let pose_i = plane_pose
        * Isometry3::from_parts(Translation3::new(0.2, 0.1, rng.uniform(-0.8, 0.8) * r), q);
    Scene {
        i: instance(Geometry::Cylinder(Cylinder::new(r * s, len * s).unwrap())),
        j: instance(Geometry::Plane(Plane::unbounded())),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&plane_pose, s),
        length: r.max(len) * s,
    }
}

pub(super) fn revolved_plane(rng: &mut Rng, s: f64) -> Scene {
    let plane_pose = rng.pose(3.0);
    // A frustum or cone, or a torus; a third lie on a special axis (along the normal, or in
    // the plane's directions).
    let (solid, size, reach) = if rng.uniform(0.0, 1.0) < 0.5 {
        let (r0, r1, len) = (
            rng.uniform(0.0, 1.5),
            rng.uniform(0.3, 1.5),
            rng.uniform(0.3, 2.0),
        );
        let g = Geometry::Frustum(Frustum::new(r0 * s, r1 * s, len * s).unwrap());
        (g, r0.max(r1).max(len), r0.max(r1).max(len))
    } else {
        let big = rng.uniform(0.8, 2.0);
        let small = rng.uniform(0.1, 0.9) * big;
        let g = Geometry::Torus(Torus::new(big * s, small * s).unwrap());
        (g, big + small, big + small)
    };
    let q = match rng.next_u64() % 3 {
        0 => nalgebra::UnitQuaternion::from_axis_angle(
            &Vector3::x_axis(),
            std::f64::consts::FRAC_PI_2,
        ),
        1 => nalgebra::UnitQuaternion::identity(),
        _ => rng.rotation(),
    };
    let pose_i = plane_pose
        * Isometry3::from_parts(
            Translation3::new(0.2, 0.1, rng.uniform(-0.9, 0.9) * reach),
            q,
        );
    Scene {
        i: instance(solid),
        j: instance(Geometry::Plane(Plane::unbounded())),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&plane_pose, s),
        length: size * s,
    }
}

pub(super) fn sphere_solid(rng: &mut Rng, s: f64) -> Scene {
    let r = rng.uniform(0.3, 1.0);
    let (solid, length) = match rng.next_u64() % 5 {
        4 => (
            Geometry::Mesh(std::sync::Arc::new(boxes_mesh(&[(
                Point3::new(0.1 * s, 0.0, 0.2 * s),
                Vector3::new(0.8, 0.6, 1.0) * s,
            )]))),
            2.0,
        ),
        0 => (
            Geometry::Cuboid(Cuboid::from_corner(1.2 * s, -0.8 * s, 1.5 * s).unwrap()),
            2.2,
        ),
        1 => (
            Geometry::Cylinder(Cylinder::new(0.7 * s, 1.5 * s).unwrap()),
            1.5,
        ),
        2 => (
            Geometry::Frustum(Frustum::new(0.9 * s, 0.3 * s, 1.2 * s).unwrap()),
            1.2,
        ),
        _ => (Geometry::Torus(Torus::new(1.2 * s, 0.4 * s).unwrap()), 1.6),
    };
    let pose_j = rng.pose(3.0);
    let pose_i = pose_j * rng.pose(1.8);
    Scene {
        i: instance(Geometry::sphere(r * s).unwrap()),
        j: instance(solid),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: length * s,
    }
}

pub(super) fn mesh_plane(rng: &mut Rng, s: f64) -> Scene {
    let feet = [
        (Point3::new(-s, 0.0, 0.0), Vector3::new(0.5, 0.4, 0.8) * s),
        (
            Point3::new(s, 0.3 * s, 0.2 * s),
            Vector3::new(0.3, 0.6, 1.0) * s,
        ),
    ];
    let plane_pose = rng.pose(3.0);
    let pose_i = plane_pose
        * Isometry3::from_parts(
            Translation3::new(0.0, 0.0, rng.uniform(0.3, 1.0)),
            rng.rotation(),
        );
    Scene {
        i: instance(Geometry::Mesh(std::sync::Arc::new(boxes_mesh(&feet)))),
        j: instance(Geometry::Plane(Plane::unbounded())),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&plane_pose, s),
        length: 2.5 * s,
    }
}

pub(super) fn circle_curve_or_arc(rng: &mut Rng, s: f64) -> Scene {
    let j = if rng.uniform(0.0, 1.0) < 0.5 {
        let points: Vec<contact_core::Point2> = (0..7)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / 7.0;
                let r = rng.uniform(1.8, 2.2) * s;
                contact_core::Point2::new(r * a.cos(), r * a.sin())
            })
            .collect();
        instance(Geometry::Curve(std::sync::Arc::new(
            Curve::new(&points, 4, true, CurvePoints::Interpolated).unwrap(),
        )))
    } else {
        instance(Geometry::Arc(Arc::new(2.0 * s, 5.0).unwrap()))
    };
    let pose_j = rng.pose(3.0);
    let angle = rng.uniform(0.3, 4.7);
    let reach = rng.uniform(1.7, 2.1);
    let pose_i = pose_j * Isometry3::translation(reach * angle.cos(), reach * angle.sin(), 0.0);
    Scene {
        i: instance(Geometry::Circle(Circle::new(0.4 * s).unwrap())),
        j,
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: 2.0 * s,
    }
}

pub(crate) fn random_box(rng: &mut Rng, s: f64) -> (Cuboid, f64) {
    let h = Vector3::new(
        rng.uniform(0.3, 1.5),
        rng.uniform(0.3, 1.5),
        rng.uniform(0.3, 1.5),
    );
    // A CORNER-marker box (centre off the frame origin) exercises the centre offset.
    let b = Cuboid::from_corner(2.0 * h.x * s, -2.0 * h.y * s, 2.0 * h.z * s).unwrap();
    (b, h.norm() * s)
}

pub(super) fn box_plane(rng: &mut Rng, s: f64) -> Scene {
    let (b, length) = random_box(rng, s);
    let plane_pose = rng.pose(3.0);
    let q = rng.rotation();
    let pose_i =
        plane_pose * Isometry3::from_parts(Translation3::new(0.1, -0.2, rng.uniform(-1.5, 0.2)), q);
    let bounded = Plane::bounded(-3.0 * s, 0.5 * s, -2.0 * s, 4.0 * s).unwrap();
    let plane = if rng.uniform(0.0, 1.0) < 0.5 {
        bounded
    } else {
        Plane::unbounded()
    };
    Scene {
        i: instance(Geometry::Cuboid(b)),
        j: instance(Geometry::Plane(plane)),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&plane_pose, s),
        length,
    }
}

pub(super) fn box_box(rng: &mut Rng, s: f64) -> Scene {
    let (a, la) = random_box(rng, s);
    let (b, lb) = random_box(rng, s);
    let pose_j = rng.pose(3.0);
    let pose_i = pose_j * rng.pose(1.2);
    Scene {
        i: instance(Geometry::Cuboid(a)),
        j: instance(Geometry::Cuboid(b)),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: la.max(lb),
    }
}

pub(super) fn cylinder_pair(rng: &mut Rng, s: f64) -> Scene {
    let (ra, la) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 3.0));
    let (rb, lb) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 3.0));
    let pose_j = rng.pose(3.0);
    // A third of the scenes have parallel axes.
    let turn = if rng.uniform(0.0, 1.0) < 0.33 {
        nalgebra::UnitQuaternion::identity()
    } else {
        rng.rotation()
    };
    let reach = 0.6 * (ra + rb + 0.5 * (la + lb));
    let offset = rng.unit_vector() * rng.uniform(0.0, reach);
    let pose_i = pose_j * Isometry3::from_parts(Translation3::from(offset), turn);
    Scene {
        i: instance(Geometry::Cylinder(Cylinder::new(ra * s, la * s).unwrap())),
        j: instance(Geometry::Cylinder(Cylinder::new(rb * s, lb * s).unwrap())),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: ra.max(la).max(rb).max(lb) * s,
    }
}

pub(super) fn cylinder_box(rng: &mut Rng, s: f64) -> Scene {
    let (r, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 3.0));
    let (b, lb) = random_box(rng, s);
    let pose_j = rng.pose(3.0);
    let pose_i = pose_j * rng.pose(0.5 * (r + len) + lb / s);
    Scene {
        i: instance(Geometry::Cylinder(Cylinder::new(r * s, len * s).unwrap())),
        j: instance(Geometry::Cuboid(b)),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: (r.max(len) * s).max(lb),
    }
}

pub(super) fn cylinder_bounded_plane(rng: &mut Rng, s: f64) -> Scene {
    let (r, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 3.0));
    let plane_pose = rng.pose(3.0);
    let pose_i = plane_pose
        * Isometry3::from_parts(
            Translation3::new(rng.uniform(-0.5, 0.5), 0.1, rng.uniform(-0.8, 0.2) * len),
            rng.rotation(),
        );
    let plane = Plane::bounded(-0.3 * s, f64::INFINITY, -2.0 * s, 0.4 * s).unwrap();
    Scene {
        i: instance(Geometry::Cylinder(Cylinder::new(r * s, len * s).unwrap())),
        j: instance(Geometry::Plane(plane)),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&plane_pose, s),
        length: r.max(len) * s,
    }
}

pub(super) fn circle_circle(rng: &mut Rng, s: f64) -> Scene {
    let (ra, rb) = (rng.uniform(0.3, 2.0), rng.uniform(0.3, 2.0));
    let d = rng.uniform(0.1, 0.99) * (ra + rb);
    let angle = rng.uniform(0.0, std::f64::consts::TAU);
    let pose_j = rng.pose(3.0);
    let pose_i = pose_j * Isometry3::translation(d * angle.cos(), d * angle.sin(), 0.0);
    Scene {
        i: instance(Geometry::Circle(Circle::new(ra * s).unwrap())),
        j: instance(Geometry::Circle(Circle::new(rb * s).unwrap())),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: ra.max(rb) * s,
    }
}

pub(super) fn circle_line(rng: &mut Rng, s: f64) -> Scene {
    let r = rng.uniform(0.3, 2.0);
    let pose_j = rng.pose(3.0);
    let pose_i =
        pose_j * Isometry3::translation(rng.uniform(-2.0, 2.0), rng.uniform(-0.5, 0.99) * r, 0.0);
    Scene {
        i: instance(Geometry::Circle(Circle::new(r * s).unwrap())),
        j: instance(Geometry::Line(Line::unbounded())),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: r * s,
    }
}

pub(super) fn point_circle(rng: &mut Rng, s: f64) -> Scene {
    let r = rng.uniform(0.3, 2.0);
    let pose_j = rng.pose(3.0);
    let d = rng.uniform(0.05, 0.99) * r;
    let pose_i = pose_j * Isometry3::translation(d, 0.0, 0.0);
    Scene {
        i: instance(Geometry::Point),
        j: instance(Geometry::Circle(Circle::new(r * s).unwrap())),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: r * s,
    }
}

/// Boundary against boundary: a cubic blob or a full arc (I) crossing another blob, an arc
/// whose gap faces away, a rectangle's top edge or a (possibly flipped) line (J).
pub(super) fn boundary_pair(rng: &mut Rng, s: f64) -> Scene {
    use crate::characterization::planar_overlap::{cubic_blob, planar_pose, rectangle};
    use std::f64::consts::{PI, TAU};
    let i = if rng.uniform(0.0, 1.0) < 0.5 {
        Geometry::Curve(std::sync::Arc::new(cubic_blob(s)))
    } else {
        Geometry::Arc(Arc::new(s, TAU).unwrap())
    };
    let frame = rng.pose(3.0);
    let spin = rng.uniform(0.0, TAU);
    let (x, y) = (rng.uniform(-2.0, 2.0), rng.uniform(-0.7, 0.7));
    let (j, offset_i, turn_j) = match (rng.uniform(0.0, 4.0) as usize).min(3) {
        kind @ (0 | 1) => {
            let phi = rng.uniform(0.0, TAU);
            let d = rng.uniform(0.6, 1.9);
            let offset = planar_pose(d * phi.cos(), d * phi.sin(), spin);
            if kind == 0 {
                let blob = Geometry::Curve(std::sync::Arc::new(cubic_blob(1.2 * s)));
                (instance(blob), offset, 0.0)
            } else {
                // The arc's gap (5 rad to 2π, centred at 5.64) faces away from I.
                let arc = Geometry::Arc(Arc::new(1.2 * s, 5.0).unwrap());
                (instance(arc), offset, phi + PI - 5.64)
            }
        }
        2 => (
            instance(rectangle(-4.0 * s, 4.0 * s, -4.0 * s, 0.0)),
            planar_pose(x, y, spin),
            0.0,
        ),
        _ => {
            let line = instance(Geometry::Line(Line::unbounded()));
            if rng.uniform(0.0, 1.0) < 0.5 {
                (line, planar_pose(x, y, spin), 0.0)
            } else {
                // Material above the flipped line: I mirrored to its side.
                (line.flipped(), planar_pose(x, -y, spin), 0.0)
            }
        }
    };
    Scene {
        i: instance(i),
        j,
        pose_i: scaled_pose(&(frame * offset_i), s),
        pose_j: scaled_pose(&(frame * planar_pose(0.0, 0.0, turn_j)), s),
        length: 2.0 * s,
    }
}

pub(crate) fn random_axes(rng: &mut Rng) -> Vector3 {
    Vector3::new(
        rng.uniform(0.3, 1.5),
        rng.uniform(0.3, 1.5),
        rng.uniform(0.3, 1.5),
    )
}

pub(crate) fn general_ellipsoid(semi: &Vector3, s: f64) -> GeometryInstance {
    instance(Geometry::Ellipsoid(
        Ellipsoid::new(semi.x * s, semi.y * s, semi.z * s).unwrap(),
    ))
}

/// Ellipsoid I at a random pose within reach `reach` of J's frame origin `pose_j`.
pub(crate) fn ellipsoid_near(rng: &mut Rng, pose_j: &Isometry3, reach: f64) -> Isometry3 {
    let offset = rng.unit_vector() * rng.uniform(0.0, reach);
    pose_j * Isometry3::from_parts(Translation3::from(offset), rng.rotation())
}

pub(super) fn ellipsoid_ellipsoid(rng: &mut Rng, s: f64) -> Scene {
    let (a, b) = (random_axes(rng), random_axes(rng));
    let pose_j = rng.pose(3.0);
    let pose_i = ellipsoid_near(rng, &pose_j, 0.9 * (a.max() + b.max()));
    Scene {
        i: general_ellipsoid(&a, s),
        j: general_ellipsoid(&b, s),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: a.max().max(b.max()) * s,
    }
}

pub(super) fn ellipsoid_box(rng: &mut Rng, s: f64) -> Scene {
    let a = random_axes(rng);
    let (b, length) = random_box(rng, s);
    let pose_j = rng.pose(3.0);
    let centre = pose_j * Point3::from(b.center().coords / s);
    let frame = Isometry3::from_parts(Translation3::from(centre.coords), pose_j.rotation);
    let pose_i = ellipsoid_near(rng, &frame, 0.8 * (a.max() + length / s));
    Scene {
        i: general_ellipsoid(&a, s),
        j: instance(Geometry::Cuboid(b)),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: a.max() * s + length,
    }
}

pub(super) fn ellipsoid_cylinder(rng: &mut Rng, s: f64) -> Scene {
    let a = random_axes(rng);
    let (r, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 2.0));
    let pose_j = rng.pose(3.0);
    let frame = pose_j * Isometry3::translation(0.0, 0.0, 0.5 * len);
    let pose_i = ellipsoid_near(rng, &frame, 0.8 * (a.max() + r + 0.5 * len));
    Scene {
        i: general_ellipsoid(&a, s),
        j: instance(Geometry::Cylinder(Cylinder::new(r * s, len * s).unwrap())),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: (a.max() + r + len) * s,
    }
}
