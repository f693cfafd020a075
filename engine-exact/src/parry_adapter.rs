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
pub fn contact(
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
