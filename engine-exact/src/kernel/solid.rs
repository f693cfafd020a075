//! The kernels of two solids: spheres, ellipsoids, boxes, cylinders, frustums, tori and
//! meshes.

use super::PairContact;
use crate::pairs;
use contact_core::geometry::{Cuboid, Cylinder, Frustum, Torus};
use contact_core::{Isometry3, Vector3, WorkCounters};
use std::sync::Arc;

/// The solid–solid kernels of [`super::Kernel`], each with the shape data it holds.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum SolidKernel {
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
    /// Ellipsoid (or sphere) `a` in the cavity `b` (a flipped cylinder, frustum or
    /// ellipsoid, sliced along its axis): one contact per region.
    EllipsoidInCavity {
        semi_axes: Vector3,
        cavity: pairs::ellipsoid_cavity::Cavity,
    },
    /// General ellipsoid `a` against ring torus `b` (sliced across `b`'s axis): one contact
    /// per region.
    EllipsoidTorus { semi_axes: Vector3, torus: Torus },
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
    /// Ring torus `a` against ring torus `b`, by meridians of `a` integrated in polar
    /// coordinates about its tube: one contact per region.
    TorusTorus { a: Torus, b: Torus },
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
    /// Two boxes.
    BoxBox { a: Cuboid, b: Cuboid },
    /// Box `a` against a frustum or torus `b` (sliced across `b`'s axis): one contact per
    /// region.
    BoxRevolved {
        cuboid: Cuboid,
        solid: pairs::sphere_solid::Solid,
    },
}

impl SolidKernel {
    /// The kernels of two solids (spheres, ellipsoids, boxes, cylinders, frustums, tori,
    /// meshes): the single contact, or `None` when there is none or when the kernel handed
    /// each of its contacts (one per region) to `emit` itself. [`Self::evaluate`] sends no
    /// other kernel here.
    pub(crate) fn contact<E: FnMut(PairContact)>(
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
            Self::EllipsoidInCavity {
                ref semi_axes,
                ref cavity,
            } => {
                pairs::ellipsoid_cavity::contacts(semi_axes, pose_a, cavity, pose_b, work, emit);
                None
            }
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
            Self::TorusTorus { ref a, ref b } => {
                pairs::torus_torus::contacts(a, pose_a, b, pose_b, work, emit);
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
        }
    }
}
