//! Every parry call of the exact engine, in one module: parry's `contact` query on the same
//! pairs, for the side-by-side benches and accuracy comparisons. The engine's own answers
//! never go through here.
//!
//! parry has no ellipsoid, so only spheres, boxes, cylinders and unbounded planes are mapped;
//! a box is a parry `Cuboid` centred on its own centre, a cylinder a parry `Cylinder` (axis y,
//! centred) moved onto ours (the pose is shifted accordingly), and a plane a `HalfSpace` with
//! normal +z (−z when flipped).

use contact_core::{Geometry, Isometry3, Point3, Vector3};
use parry3d_f64::query;
use parry3d_f64::shape::{Ball, Cuboid, Cylinder, HalfSpace, Shape};

/// One geometry as a parry shape, with the offset of the shape's origin in the geometry frame.
#[derive(Debug)]
pub struct PeerShape {
    shape: PeerKind,
    offset: Isometry3,
}

#[derive(Debug)]
enum PeerKind {
    Ball(Ball),
    Cuboid(Cuboid),
    Cylinder(Cylinder),
    HalfSpace(HalfSpace),
}

/// parry's answer: points on each shape, the normal from the second into the first, depth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeerContact {
    /// Point on the first shape, world frame.
    pub point_a: Point3,
    /// Point on the second shape, world frame.
    pub point_b: Point3,
    /// Unit normal from the second shape into the first.
    pub normal: Vector3,
    /// Penetration depth (≥ 0 when penetrating).
    pub depth: f64,
}

impl PeerShape {
    /// The parry shape of `geometry` (flipped planes supported), or `None` for a kind parry
    /// cannot represent exactly (ellipsoids, every 2-D shape, bounded planes, …).
    pub fn new(geometry: &Geometry, flip: bool) -> Option<Self> {
        let identity = Isometry3::identity();
        match geometry {
            Geometry::Ellipsoid(e) if !flip => e.sphere_radius().map(|r| Self {
                shape: PeerKind::Ball(Ball::new(r)),
                offset: identity,
            }),
            Geometry::Cuboid(b) if !flip => Some(Self {
                shape: PeerKind::Cuboid(Cuboid::new(b.half_extents())),
                offset: Isometry3::translation(b.center().x, b.center().y, b.center().z),
            }),
            // parry's cylinder is centred with its axis along y; ours starts at the origin
            // along +z: shift by half the length and turn y onto z (a quarter turn about x).
            Geometry::Cylinder(c) if !flip => Some(Self {
                shape: PeerKind::Cylinder(Cylinder::new(0.5 * c.length(), c.radius())),
                offset: Isometry3::new(
                    Vector3::new(0.0, 0.0, 0.5 * c.length()),
                    Vector3::new(std::f64::consts::FRAC_PI_2, 0.0, 0.0),
                ),
            }),
            Geometry::Plane(p) if p.is_unbounded() => {
                let z = if flip { -Vector3::z() } else { Vector3::z() };
                Some(Self {
                    shape: PeerKind::HalfSpace(HalfSpace::new(nalgebra::Unit::new_unchecked(z))),
                    offset: identity,
                })
            }
            _ => None,
        }
    }

    fn shape(&self) -> &dyn Shape {
        match &self.shape {
            PeerKind::Ball(s) => s,
            PeerKind::Cuboid(s) => s,
            PeerKind::Cylinder(s) => s,
            PeerKind::HalfSpace(s) => s,
        }
    }
}

/// parry's `contact` between `a` at `pose_a` and `b` at `pose_b` (geometry-frame poses
/// `X_WG`), with zero prediction distance: `None` when separated or when parry cannot answer.
///
/// A half-space is always passed to parry first (and the answer flipped back): parry 0.25.3's
/// `contact_support_map_halfspace` hands its `pos12` to `contact_halfspace_support_map`
/// without inverting it, so a support map *followed by* a half-space gets a wrong depth
/// (a ball 0.9 above the ground reports 1.9 instead of 0.1; [`contact_in_given_order`] shows
/// it, and the test `parry_adapter::tests` pins it so an upgrade that fixes it is noticed).
pub fn contact(
    a: &PeerShape,
    pose_a: &Isometry3,
    b: &PeerShape,
    pose_b: &Isometry3,
) -> Option<PeerContact> {
    if matches!(b.shape, PeerKind::HalfSpace(_)) && !matches!(a.shape, PeerKind::HalfSpace(_)) {
        return contact_in_given_order(b, pose_b, a, pose_a).map(|c| PeerContact {
            point_a: c.point_b,
            point_b: c.point_a,
            normal: -c.normal,
            depth: c.depth,
        });
    }
    contact_in_given_order(a, pose_a, b, pose_b)
}

/// parry's `contact` with the shapes in the order given (see [`contact`] for why the order
/// matters in parry 0.25.3).
pub fn contact_in_given_order(
    a: &PeerShape,
    pose_a: &Isometry3,
    b: &PeerShape,
    pose_b: &Isometry3,
) -> Option<PeerContact> {
    let pa = pose_a * a.offset;
    let pb = pose_b * b.offset;
    let c = query::contact(&pa, a.shape(), &pb, b.shape(), 0.0).ok()??;
    Some(PeerContact {
        point_a: c.point1,
        point_b: c.point2,
        // parry's normal1 points from the first shape towards the second.
        normal: -c.normal1.into_inner(),
        depth: -c.dist,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::geometry::Plane;

    #[test]
    fn parry_answers_a_ball_on_the_ground_only_with_the_half_space_first() {
        let ball = PeerShape::new(&Geometry::sphere(1.0).unwrap(), false).unwrap();
        let ground = PeerShape::new(&Geometry::Plane(Plane::unbounded()), false).unwrap();
        let above = Isometry3::translation(0.0, 0.0, 0.9);
        let id = Isometry3::identity();
        let good = contact(&ball, &above, &ground, &id).unwrap();
        assert!((good.depth - 0.1).abs() < 1e-15 && good.normal == Vector3::z());
        // The support-map-first path of parry 0.25.3 mistakes the pose direction.
        let given = contact_in_given_order(&ball, &above, &ground, &id).unwrap();
        assert!((given.depth - 1.9).abs() < 1e-15, "{given:?}");
    }
}
