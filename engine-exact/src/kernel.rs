//! The evaluated form of a pair: a [`Kernel`] chosen once by [`crate::dispatch::select`],
//! holding a copy of the shape data it needs, evaluated at every query without allocation.

use crate::planar::curve_eval::PlanarCurve;
use crate::{pairs, planar};
use contact_core::geometry::{Cuboid, Cylinder, Frustum, Line, Plane, Torus};
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use std::sync::Arc;

/// One contact between the pair's first geometry `a` and second `b`, in the world frame.
/// The normal points from `b` into `a`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PairContact {
    /// Point on `a`'s surface.
    pub point_a: Point3,
    /// Point on `b`'s surface.
    pub point_b: Point3,
    /// Unit normal from `b` into `a`.
    pub normal: Vector3,
    /// Penetration δ > 0.
    pub depth: f64,
    /// Projected area (length in 2-D).
    pub area: f64,
}

impl PairContact {
    /// The errors of `self` against `want`: depth, normal and the points' distances relative
    /// to `size`, the area to `size²` (for the tests that hold one method to another).
    #[cfg(test)]
    pub fn errors(&self, want: &Self, size: f64) -> [f64; 4] {
        [
            (self.depth - want.depth).abs() / size,
            (self.normal - want.normal).norm(),
            ((self.point_a - want.point_a).norm() + (self.point_b - want.point_b).norm()) / size,
            (self.area - want.area).abs() / (size * size),
        ]
    }

    /// The same contact with `a` and `b` exchanged.
    pub fn swapped(self) -> Self {
        Self {
            point_a: self.point_b,
            point_b: self.point_a,
            normal: -self.normal,
            ..self
        }
    }
}

/// Why a pair could not be evaluated at the given poses (the caller adds labels and poses).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum PairError {
    /// Two 2-D geometries are not in one plane.
    OutOfPlane {
        /// Angle between the plane normals (either orientation).
        angle_rad: f64,
        /// Distance of `a`'s origin from `b`'s plane.
        offset: f64,
    },
}

/// A pair computation with its shape data. `side` is +1, or −1 for a flipped plane or line
/// (the material then lies on the +z / +y side).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Kernel {
    /// Sphere `a` against an unbounded plane `b`.
    SpherePlane { radius: f64, side: f64 },
    /// Sphere `a` against a bounded plane `b` (seen as a box near the sphere).
    SphereBoundedPlane {
        radius: f64,
        plane: Plane,
        side: f64,
    },
    /// Sphere `a` against a box, cylinder, frustum or torus `b`: one contact per region.
    SphereSolid {
        radius: f64,
        solid: pairs::sphere_solid::Solid,
    },
    /// Sphere `a` against closed mesh `b`.
    SphereMesh {
        radius: f64,
        mesh: Arc<pairs::mesh_plane::PreparedMesh>,
    },
    /// Two solid spheres.
    SphereSphere { radius_a: f64, radius_b: f64 },
    /// Solid sphere `a` inside the spherical cavity `b` (a flipped sphere).
    SphereInCavity { radius_a: f64, radius_b: f64 },
    /// Ellipsoid `a` against an unbounded plane `b`.
    EllipsoidPlane { semi_axes: Vector3, side: f64 },
    /// General ellipsoid `a` against ellipsoid `b` (sliced).
    EllipsoidEllipsoid { semi_a: Vector3, semi_b: Vector3 },
    /// General ellipsoid `a` against box `b` (sliced).
    EllipsoidBox { semi_axes: Vector3, cuboid: Cuboid },
    /// General ellipsoid `a` against cylinder `b` (sliced).
    EllipsoidCylinder {
        semi_axes: Vector3,
        cylinder: Cylinder,
    },
    /// General ellipsoid `a` against frustum (or cone) `b` (sliced across `b`'s axis).
    EllipsoidFrustum {
        semi_axes: Vector3,
        frustum: Frustum,
    },
    /// General ellipsoid `a` against ring torus `b` (sliced across `b`'s axis): one contact
    /// per region.
    EllipsoidTorus { semi_axes: Vector3, torus: Torus },
    /// Cylinder `a` against an unbounded plane `b`.
    CylinderPlane { cylinder: Cylinder, side: f64 },
    /// Cylinder `a` against a cylinder, box or bounded plane `b`, by slicing (a parallel
    /// cylinder, or a box with an axis along `a`'s, in closed form).
    CylinderSliced {
        cylinder: Cylinder,
        other: pairs::cylinder_sliced::SlicedSolid,
    },
    /// Cylinder or frustum `a` against a frustum `b`, sliced across `a`'s axis and
    /// integrated in polar coordinates about it.
    RevolvedPair {
        a: pairs::sphere_solid::Solid,
        b: pairs::sphere_solid::Solid,
    },
    /// Cylinder or frustum `a` against ring torus `b`, sliced across the torus' axis and
    /// integrated in polar coordinates about it: one contact per region.
    RevolvedTorus {
        solid: pairs::sphere_solid::Solid,
        torus: Torus,
    },
    /// Frustum or torus `a` against an unbounded plane `b`.
    RevolvedPlane {
        solid: pairs::sphere_solid::Solid,
        side: f64,
    },
    /// Closed mesh `a` against an unbounded plane `b`: one contact per region.
    MeshPlane {
        mesh: Arc<pairs::mesh_plane::PreparedMesh>,
        side: f64,
    },
    /// Closed mesh `a` against closed mesh `b`, as given: one contact per region.
    MeshMesh { pair: pairs::mesh_mesh::MeshPair },
    /// Box `a` against a closed mesh `b`: one contact per region.
    BoxMesh {
        cuboid: Cuboid,
        mesh: Arc<pairs::mesh_plane::PreparedMesh>,
    },
    /// Cylinder, frustum or torus `a` against a closed mesh `b` (sliced across `a`'s axis):
    /// one contact per region.
    RevolvedMesh {
        solid: pairs::sphere_solid::Solid,
        mesh: Arc<pairs::mesh_plane::PreparedMesh>,
    },
    /// General ellipsoid `a` against a closed mesh `b` (the mesh mapped onto the unit
    /// sphere's space and sliced): one contact per region.
    EllipsoidMesh {
        semi_axes: Vector3,
        mesh: Arc<pairs::mesh_plane::PreparedMesh>,
    },
    /// Closed mesh `a` against a bounded plane `b` (the box–mesh pair on the plane's prism cut
    /// to a box about the mesh): one contact per region.
    MeshBoundedPlane {
        mesh: Arc<pairs::mesh_plane::PreparedMesh>,
        plane: Plane,
        side: f64,
    },
    /// Box `a` against a (possibly bounded) plane `b`.
    BoxPlane {
        cuboid: Cuboid,
        plane: Plane,
        side: f64,
    },
    /// Two boxes.
    BoxBox { a: Cuboid, b: Cuboid },
    /// Box `a` against a frustum or torus `b` (sliced across `b`'s axis): one contact per
    /// region.
    BoxRevolved {
        cuboid: Cuboid,
        solid: pairs::sphere_solid::Solid,
    },
    /// Frustum or torus `a` against a bounded plane `b` (the box pair on the plane's prism).
    RevolvedBoundedPlane {
        solid: pairs::sphere_solid::Solid,
        plane: Plane,
        side: f64,
    },
    /// General ellipsoid `a` against a bounded plane `b` (the ellipsoid–box pair on the
    /// plane's prism cut to a box about the ellipsoid).
    EllipsoidBoundedPlane {
        semi_axes: Vector3,
        plane: Plane,
        side: f64,
    },
    /// 2-D point `a` against line `b`.
    PointLine { line: Line, side: f64 },
    /// 2-D point `a` against solid circle `b` (or a circular hole when `hole`).
    PointCircle { radius: f64, hole: bool },
    /// Two solid 2-D circles.
    CircleCircle { radius_a: f64, radius_b: f64 },
    /// Solid circle `a` inside the circular hole `b` (a flipped circle).
    CircleInHole { radius_a: f64, radius_b: f64 },
    /// 2-D point `a` against arc `b`.
    PointArc { radius: f64, range: f64, side: f64 },
    /// Solid circle `a` against arc `b`.
    CircleArc {
        radius_a: f64,
        radius: f64,
        range: f64,
        side: f64,
    },
    /// 2-D point `a` against curve `b`.
    PointCurve { curve: Arc<PlanarCurve>, side: f64 },
    /// Solid circle `a` against curve `b`.
    CircleCurve {
        radius: f64,
        curve: Arc<PlanarCurve>,
        side: f64,
    },
    /// Solid circle `a` against an unbounded line `b`.
    CircleLine { radius: f64, side: f64 },
    /// Solid circle `a` against line `b` over `x_range` (an end finite): the disc cut by the
    /// line's half-strip.
    CircleBoundedLine {
        radius: f64,
        x_range: [f64; 2],
        side: f64,
    },
    /// Boundary `a` against boundary `b` (arcs and curves, oriented by their flips): one
    /// contact per overlap region (it allocates per query, see
    /// `planar::overlap`).
    Overlap {
        a: Arc<planar::boundary::Chain>,
        b: Arc<planar::boundary::Chain>,
    },
    /// Boundary `a` (arc or curve) against line `b`: one contact per overlap region.
    OverlapLine {
        a: Arc<planar::boundary::Chain>,
        x_range: [f64; 2],
        side: f64,
    },
}

impl Kernel {
    /// The triangles and heap bytes of the meshes this pair holds (for the prepared pair's
    /// statistics).
    pub(crate) fn held_meshes(&self) -> Option<(usize, usize)> {
        match self {
            Self::SphereMesh { mesh, .. }
            | Self::MeshPlane { mesh, .. }
            | Self::BoxMesh { mesh, .. }
            | Self::RevolvedMesh { mesh, .. }
            | Self::EllipsoidMesh { mesh, .. }
            | Self::MeshBoundedPlane { mesh, .. } => {
                Some((mesh.triangles.len(), mesh.heap_bytes()))
            }
            Self::MeshMesh { pair } => Some(pair.held()),
            _ => None,
        }
    }

    /// Evaluates the pair with `a` at `pose_a` (`X_WGa`) and `b` at `pose_b` (`X_WGb`),
    /// handing each contact to `emit`. `length` is the pair's length scale (for the 2-D
    /// in-plane tolerance).
    ///
    /// Each kernel goes to its family: two solids ([`Self::solid_solid`]), a solid and a
    /// plane ([`Self::solid_plane`]), or two 2-D geometries ([`Self::planar`]), the last
    /// after the in-plane frame is set up (or [`PairError::OutOfPlane`]).
    pub fn evaluate<E: FnMut(PairContact)>(
        &self,
        pose_a: &Isometry3,
        pose_b: &Isometry3,
        length: f64,
        work: &mut WorkCounters,
        emit: &mut E,
    ) -> Result<(), PairError> {
        work.primitive_tests += 1;
        let found = match *self {
            Self::SphereSolid { .. }
            | Self::SphereMesh { .. }
            | Self::SphereSphere { .. }
            | Self::SphereInCavity { .. }
            | Self::EllipsoidEllipsoid { .. }
            | Self::EllipsoidBox { .. }
            | Self::EllipsoidCylinder { .. }
            | Self::EllipsoidFrustum { .. }
            | Self::EllipsoidTorus { .. }
            | Self::EllipsoidMesh { .. }
            | Self::CylinderSliced { .. }
            | Self::RevolvedPair { .. }
            | Self::RevolvedTorus { .. }
            | Self::RevolvedMesh { .. }
            | Self::MeshMesh { .. }
            | Self::BoxMesh { .. }
            | Self::BoxBox { .. }
            | Self::BoxRevolved { .. } => self.solid_solid(pose_a, pose_b, work, emit),
            Self::SpherePlane { .. }
            | Self::SphereBoundedPlane { .. }
            | Self::EllipsoidPlane { .. }
            | Self::EllipsoidBoundedPlane { .. }
            | Self::CylinderPlane { .. }
            | Self::RevolvedPlane { .. }
            | Self::RevolvedBoundedPlane { .. }
            | Self::MeshPlane { .. }
            | Self::MeshBoundedPlane { .. }
            | Self::BoxPlane { .. } => self.solid_plane(pose_a, pose_b, work, emit),
            Self::PointLine { .. }
            | Self::PointCircle { .. }
            | Self::CircleCircle { .. }
            | Self::CircleInHole { .. }
            | Self::PointArc { .. }
            | Self::CircleArc { .. }
            | Self::PointCurve { .. }
            | Self::CircleCurve { .. }
            | Self::CircleLine { .. }
            | Self::CircleBoundedLine { .. }
            | Self::Overlap { .. }
            | Self::OverlapLine { .. } => {
                let frame = planar::InPlane::new(pose_a, pose_b, length)?;
                self.planar(&frame, pose_a, work, emit)
            }
        };
        if let Some(c) = found {
            emit(c);
        }
        Ok(())
    }

    /// The kernels of two solids (spheres, ellipsoids, boxes, cylinders, frustums, tori,
    /// meshes): the single contact, or `None` when there is none or when the kernel handed
    /// each of its contacts (one per region) to `emit` itself. [`Self::evaluate`] sends no
    /// other kernel here.
    fn solid_solid<E: FnMut(PairContact)>(
        &self,
        pose_a: &Isometry3,
        pose_b: &Isometry3,
        work: &mut WorkCounters,
        emit: &mut E,
    ) -> Option<PairContact> {
        match *self {
            Self::SphereSolid { radius, ref solid } => {
                pairs::sphere_solid::contacts(radius, pose_a, solid, pose_b, work, emit);
                None
            }
            Self::SphereMesh { radius, ref mesh } => {
                pairs::sphere_mesh::contact(radius, pose_a, mesh, pose_b, work)
            }
            Self::SphereSphere { radius_a, radius_b } => {
                pairs::sphere_sphere::contact(radius_a, pose_a, radius_b, pose_b)
            }
            Self::SphereInCavity { radius_a, radius_b } => {
                pairs::sphere_sphere::contact_in_cavity(radius_a, pose_a, radius_b, pose_b)
            }
            Self::EllipsoidEllipsoid { semi_a, semi_b } => {
                pairs::ellipsoid_ellipsoid::contact(&semi_a, pose_a, &semi_b, pose_b, work)
            }
            Self::EllipsoidBox {
                semi_axes,
                ref cuboid,
            } => pairs::ellipsoid_box::contact(&semi_axes, pose_a, cuboid, pose_b, work),
            Self::EllipsoidCylinder {
                semi_axes,
                ref cylinder,
            } => pairs::ellipsoid_cylinder::contact(&semi_axes, pose_a, cylinder, pose_b, work),
            Self::EllipsoidFrustum {
                semi_axes,
                ref frustum,
            } => pairs::ellipsoid_frustum::contact(&semi_axes, pose_a, frustum, pose_b, work),
            Self::EllipsoidTorus {
                ref semi_axes,
                ref torus,
            } => {
                pairs::ellipsoid_torus::contacts(semi_axes, pose_a, torus, pose_b, work, emit);
                None
            }
            Self::EllipsoidMesh {
                ref semi_axes,
                ref mesh,
            } => {
                pairs::ellipsoid_mesh::contacts(semi_axes, pose_a, mesh, pose_b, work, emit);
                None
            }
            Self::CylinderSliced {
                ref cylinder,
                ref other,
            } => pairs::cylinder_sliced::contact(cylinder, pose_a, other, pose_b, work),
            Self::RevolvedPair { ref a, ref b } => {
                pairs::revolved_pair::contact(a, pose_a, b, pose_b, work)
            }
            Self::RevolvedTorus {
                ref solid,
                ref torus,
            } => {
                pairs::revolved_torus::contacts(solid, pose_a, torus, pose_b, work, emit);
                None
            }
            Self::RevolvedMesh {
                ref solid,
                ref mesh,
            } => {
                pairs::revolved_mesh::contacts(solid, pose_a, mesh, pose_b, work, emit);
                None
            }
            Self::MeshMesh { ref pair } => {
                pair.contacts(pose_a, pose_b, work, emit);
                None
            }
            Self::BoxMesh {
                ref cuboid,
                ref mesh,
            } => {
                pairs::box_mesh::contacts(cuboid, pose_a, mesh, pose_b, work, emit);
                None
            }
            Self::BoxBox { ref a, ref b } => pairs::box_box::contact(a, pose_a, b, pose_b, work),
            Self::BoxRevolved {
                ref cuboid,
                ref solid,
            } => {
                pairs::box_revolved::contacts(cuboid, pose_a, solid, pose_b, work, emit);
                None
            }
            _ => unreachable!("`Kernel::evaluate` sends only this family here"),
        }
    }

    /// The kernels of a solid against a plane, unbounded or bounded: as
    /// [`Self::solid_solid`].
    fn solid_plane<E: FnMut(PairContact)>(
        &self,
        pose_a: &Isometry3,
        pose_b: &Isometry3,
        work: &mut WorkCounters,
        emit: &mut E,
    ) -> Option<PairContact> {
        match *self {
            Self::SpherePlane { radius, side } => {
                pairs::sphere_plane::contact(radius, pose_a, pose_b, side)
            }
            Self::SphereBoundedPlane {
                radius,
                ref plane,
                side,
            } => pairs::sphere_bounded_plane::contact(radius, pose_a, plane, side, pose_b, work),
            Self::EllipsoidPlane { semi_axes, side } => {
                pairs::ellipsoid_plane::contact(&semi_axes, pose_a, pose_b, side)
            }
            Self::EllipsoidBoundedPlane {
                semi_axes,
                ref plane,
                side,
            } => pairs::ellipsoid_bounded_plane::contact(
                &semi_axes, pose_a, plane, side, pose_b, work,
            ),
            Self::CylinderPlane { ref cylinder, side } => {
                pairs::cylinder_plane::emit_contact(cylinder, pose_a, pose_b, side, work, emit);
                None
            }
            Self::RevolvedPlane { ref solid, side } => {
                pairs::revolved_plane::contact(solid, pose_a, pose_b, side, work)
            }
            Self::RevolvedBoundedPlane {
                ref solid,
                ref plane,
                side,
            } => {
                pairs::revolved_bounded_plane::contacts(
                    solid, pose_a, plane, side, pose_b, work, emit,
                );
                None
            }
            Self::MeshPlane { ref mesh, side } => {
                pairs::mesh_plane::contacts(mesh, pose_a, pose_b, side, work, emit);
                None
            }
            Self::MeshBoundedPlane {
                ref mesh,
                ref plane,
                side,
            } => {
                pairs::mesh_bounded_plane::contacts(mesh, pose_a, plane, side, pose_b, work, emit);
                None
            }
            Self::BoxPlane {
                ref cuboid,
                ref plane,
                side,
            } => pairs::box_plane::contact(cuboid, pose_a, plane, side, pose_b),
            _ => unreachable!("`Kernel::evaluate` sends only this family here"),
        }
    }

    /// The kernels of two 2-D geometries in the in-plane `frame` (points, circles, arcs,
    /// curves, lines, boundaries): as [`Self::solid_solid`].
    fn planar<E: FnMut(PairContact)>(
        &self,
        frame: &planar::InPlane,
        pose_a: &Isometry3,
        work: &mut WorkCounters,
        emit: &mut E,
    ) -> Option<PairContact> {
        match *self {
            Self::PointLine { ref line, side } => planar::point_line::contact(frame, line, side),
            Self::PointCircle { radius, hole } => {
                planar::circles::point_circle(frame, radius, hole)
            }
            Self::CircleCircle { radius_a, radius_b } => {
                planar::circles::circle_circle(frame, radius_a, radius_b)
            }
            Self::CircleInHole { radius_a, radius_b } => {
                planar::circles::circle_in_hole(frame, radius_a, radius_b)
            }
            Self::PointArc {
                radius,
                range,
                side,
            } => planar::arc::point_arc(frame, radius, range, side),
            Self::CircleArc {
                radius_a,
                radius,
                range,
                side,
            } => planar::arc::circle_arc(frame, radius_a, radius, range, side),
            Self::PointCurve { ref curve, side } => {
                planar::point_curve::point_curve(frame, curve, side, work)
            }
            Self::CircleCurve {
                radius,
                ref curve,
                side,
            } => planar::point_curve::circle_curve(frame, radius, curve, side, work),
            Self::CircleLine { radius, side } => {
                planar::point_line::circle_line(frame, radius, side)
            }
            Self::CircleBoundedLine {
                radius,
                x_range,
                side,
            } => planar::circle_bounded_line::contact(frame, radius, x_range, side),
            Self::Overlap { ref a, ref b } => {
                planar::overlap::chain_chain(frame, pose_a, a, b, work, emit);
                None
            }
            Self::OverlapLine {
                ref a,
                x_range,
                side,
            } => {
                planar::overlap::chain_line(frame, pose_a, a, x_range, side, work, emit);
                None
            }
            _ => unreachable!("`Kernel::evaluate` sends only this family here"),
        }
    }
}
