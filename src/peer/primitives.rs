//! parry's `contact` query on the exact engine's primitive pairs, for the side-by-side benches
//! and accuracy comparisons. The exact engine's own answers never go through here.
//!
//! parry has no ellipsoid and no frustum, so only spheres, boxes, cylinders, cones (a frustum
//! with one radius zero) and unbounded planes are mapped; a box is a parry `Cuboid` centred on
//! its own centre, a cylinder a parry `Cylinder` (axis y, centred) and a cone a parry `Cone`
//! (axis y, centred, apex at +y) moved onto ours (the pose is shifted accordingly), and a
//! plane a `HalfSpace` with normal +z (−z when flipped).

use contact_core::{
    Contact, Geometry, GeometryEngine, GeometryInstance, Isometry3, Point3, PrepareError,
    PreparedPair, PreparedStats, QueryError, Unsupported, Vector3, WorkCounters,
};
use parry3d_f64::query;
use parry3d_f64::shape::{Ball, Cone, Cuboid, Cylinder, HalfSpace, Shape, TriMesh};

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
    Cone(Cone),
    HalfSpace(HalfSpace),
    /// Boxed: a mesh is far larger than the primitives.
    TriMesh(Box<TriMesh>),
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
    /// A closed mesh as a parry `TriMesh`, for the benches' side-by-side timing (the trade
    /// peer [`ParryEngine`] keeps to [`PeerShape::new`]'s shapes); `None` if parry refuses it.
    pub fn mesh(mesh: &contact_core::geometry::TriangleMesh) -> Option<Self> {
        let shape = TriMesh::new(mesh.vertices().to_vec(), mesh.triangles().to_vec()).ok()?;
        Some(Self {
            shape: PeerKind::TriMesh(Box::new(shape)),
            offset: Isometry3::identity(),
        })
    }

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
            // A cone: parry's has its base at y = −h and its apex at y = +h; ours has the apex
            // at the end whose radius is zero: shift by half the length and turn y onto +z
            // (apex on top) or −z (apex at the bottom).
            Geometry::Frustum(f)
                if !flip && ((f.top_radius() == 0.0) != (f.bottom_radius() == 0.0)) =>
            {
                let (radius, turn) = if f.top_radius() == 0.0 {
                    (f.bottom_radius(), std::f64::consts::FRAC_PI_2)
                } else {
                    (f.top_radius(), -std::f64::consts::FRAC_PI_2)
                };
                Some(Self {
                    shape: PeerKind::Cone(Cone::new(0.5 * f.length(), radius)),
                    offset: Isometry3::new(
                        Vector3::new(0.0, 0.0, 0.5 * f.length()),
                        Vector3::new(turn, 0.0, 0.0),
                    ),
                })
            }
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
            PeerKind::Cone(s) => s,
            PeerKind::HalfSpace(s) => s,
            PeerKind::TriMesh(s) => s.as_ref(),
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
/// it, and the test in this module pins it so an upgrade that fixes it is noticed).
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

/// parry as a peer engine: its `contact` query behind the same [`GeometryEngine`] trait, so the
/// trade report measures it on the same scenes, poses and error definitions as ours. It
/// answers what [`PeerShape`] can represent (spheres, boxes, cylinders, cones, unbounded planes) with
/// one contact per geometry pair: parry's deepest-point depth and normal, and no area (0).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ParryEngine;

const PARRY: &str = "parry";

impl GeometryEngine for ParryEngine {
    fn name(&self) -> &'static str {
        PARRY
    }

    fn supports(&self, i: &Geometry, j: &Geometry) -> Result<(), Unsupported> {
        if PeerShape::new(i, false).is_some() && PeerShape::new(j, false).is_some() {
            Ok(())
        } else {
            Err(Unsupported {
                engine: PARRY,
                i: i.kind(),
                j: j.kind(),
                reason: "parry's contact query has no exact shape for this geometry",
            })
        }
    }

    fn prepare(
        &self,
        i: &[GeometryInstance],
        j: &[GeometryInstance],
    ) -> Result<Box<dyn PreparedPair>, PrepareError> {
        contact_core::check_lists(self, i, j)?;
        let shapes =
            |list: &[GeometryInstance]| -> Result<Vec<(PeerShape, Isometry3)>, PrepareError> {
                list.iter()
                    .map(|g| {
                        let shape = PeerShape::new(&g.geometry, g.flip_normal).ok_or(Unsupported {
                        engine: PARRY,
                        i: g.geometry.kind(),
                        j: g.geometry.kind(),
                        reason: "parry's contact query has no exact shape for this geometry",
                    })?;
                        Ok((shape, g.pose_part_geometry))
                    })
                    .collect()
            };
        Ok(Box::new(PreparedParry {
            i: shapes(i)?,
            j: shapes(j)?,
        }))
    }
}

/// The shapes of one CONTACT for [`ParryEngine`].
#[derive(Debug)]
struct PreparedParry {
    i: Vec<(PeerShape, Isometry3)>,
    j: Vec<(PeerShape, Isometry3)>,
}

impl PreparedPair for PreparedParry {
    fn query(
        &self,
        pose_world_i: &Isometry3,
        pose_world_j: &Isometry3,
        contacts: &mut Vec<Contact>,
        work: &mut WorkCounters,
    ) -> Result<(), QueryError> {
        QueryError::check_poses(pose_world_i, pose_world_j)?;
        contacts.clear();
        work.queries += 1;
        for (gi, (si, xi)) in self.i.iter().enumerate() {
            for (gj, (sj, xj)) in self.j.iter().enumerate() {
                work.geometry_pairs += 1;
                work.primitive_tests += 1;
                let Some(c) = contact(si, &(pose_world_i * xi), sj, &(pose_world_j * xj)) else {
                    continue;
                };
                if c.depth < 0.0 {
                    continue;
                }
                contacts.push(Contact {
                    point_i_w: c.point_a,
                    point_j_w: c.point_b,
                    normal_w: c.normal,
                    penetration: c.depth,
                    area: 0.0,
                    geometry_i: gi as u32,
                    geometry_j: gj as u32,
                });
                work.contacts += 1;
            }
        }
        Ok(())
    }

    fn stats(&self) -> PreparedStats {
        PreparedStats {
            geometries: self.i.len() + self.j.len(),
            triangles: 0,
            bytes: (self.i.capacity() + self.j.capacity())
                * std::mem::size_of::<(PeerShape, Isometry3)>(),
        }
    }
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

    /// A cone (a frustum with one radius zero) lands where ours is: standing on its base or
    /// on its apex, sunk 0.1 into the ground, and a ball above the apex, by hand; a frustum
    /// with two radii has no parry shape.
    #[test]
    fn a_cone_maps_onto_ours_apex_up_or_down() {
        use contact_core::geometry::Frustum;
        let ground = PeerShape::new(&Geometry::Plane(Plane::unbounded()), false).unwrap();
        let id = Isometry3::identity();
        let sunk = Isometry3::translation(0.0, 0.0, -0.1);
        for (bottom, top) in [(0.8, 0.0), (0.0, 0.8)] {
            let cone = Geometry::Frustum(Frustum::new(bottom, top, 2.0).unwrap());
            let peer = PeerShape::new(&cone, false).unwrap();
            let c = contact(&peer, &sunk, &ground, &id).unwrap();
            assert!((c.depth - 0.1).abs() < 1e-9, "{bottom} {top}: {c:?}");
            assert!((c.normal - Vector3::z()).norm() < 1e-9, "{c:?}");
            // The ball of radius 0.5 centred 0.4 above the top end (z = 2) overlaps that end by
            // 0.1 whether the apex or the flat base is there.
            let ball = PeerShape::new(&Geometry::sphere(0.5).unwrap(), false).unwrap();
            let c = contact(&ball, &Isometry3::translation(0.0, 0.0, 2.4), &peer, &id).unwrap();
            assert!((c.depth - 0.1).abs() < 1e-9, "{bottom} {top}: {c:?}");
        }
        let frustum = Geometry::Frustum(Frustum::new(0.8, 0.4, 2.0).unwrap());
        assert!(PeerShape::new(&frustum, false).is_none());
    }
}
