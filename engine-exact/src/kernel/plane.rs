//! The kernels of a solid against a plane, unbounded or bounded.

use super::PairContact;
use crate::pairs;
use contact_core::geometry::{Cuboid, Cylinder, Plane};
use contact_core::{Isometry3, Vector3, WorkCounters};
use std::sync::Arc;

/// The solid–plane kernels of [`super::Kernel`], each with the shape data it holds.
#[derive(Debug, Clone, PartialEq)]
#[expect(
    clippy::enum_variant_names,
    reason = "each variant is named as its pair module is: sphere_plane, mesh_plane, box_plane"
)]
pub(crate) enum PlaneKernel {
    /// Sphere `a` against an unbounded plane `b`.
    SpherePlane { radius: f64, side: f64 },
    /// Sphere `a` against a bounded plane `b` (seen as a box near the sphere).
    SphereBoundedPlane {
        radius: f64,
        plane: Plane,
        side: f64,
    },
    /// Ellipsoid `a` against an unbounded plane `b`.
    EllipsoidPlane { semi_axes: Vector3, side: f64 },
    /// Cylinder `a` against an unbounded plane `b`.
    CylinderPlane { cylinder: Cylinder, side: f64 },
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
}

impl PlaneKernel {
    /// The kernels of a solid against a plane, unbounded or bounded: as
    /// [`super::SolidKernel::contact`].
    pub(crate) fn contact<E: FnMut(PairContact)>(
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
        }
    }
}
