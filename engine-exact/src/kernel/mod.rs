//! The evaluated form of a pair: a [`Kernel`] chosen once by [`crate::dispatch::select`],
//! holding a copy of the shape data it needs, evaluated at every query without allocation.

use crate::planar;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
pub(crate) use planar_pairs::PlanarKernel;
pub(crate) use plane::PlaneKernel;
pub(crate) use solid::SolidKernel;

mod planar_pairs;
mod plane;
mod solid;

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

/// A pair computation with its shape data, by family: two solids, a solid and a plane, or
/// two 2-D geometries. `side` is +1, or −1 for a flipped plane or line (the material then
/// lies on the +z / +y side).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Kernel {
    /// Two solids.
    Solid(SolidKernel),
    /// A solid against a plane.
    Plane(PlaneKernel),
    /// Two 2-D geometries.
    Planar(PlanarKernel),
}

impl From<SolidKernel> for Kernel {
    fn from(kernel: SolidKernel) -> Self {
        Self::Solid(kernel)
    }
}

impl From<PlaneKernel> for Kernel {
    fn from(kernel: PlaneKernel) -> Self {
        Self::Plane(kernel)
    }
}

impl From<PlanarKernel> for Kernel {
    fn from(kernel: PlanarKernel) -> Self {
        Self::Planar(kernel)
    }
}

impl Kernel {
    /// The triangles and heap bytes of the meshes this pair holds (for the prepared pair's
    /// statistics).
    pub(crate) fn held_meshes(&self) -> Option<(usize, usize)> {
        match self {
            Self::Solid(
                SolidKernel::SphereMesh { mesh, .. }
                | SolidKernel::BoxMesh { mesh, .. }
                | SolidKernel::RevolvedMesh { mesh, .. }
                | SolidKernel::EllipsoidMesh { mesh, .. },
            )
            | Self::Plane(
                PlaneKernel::MeshPlane { mesh, .. } | PlaneKernel::MeshBoundedPlane { mesh, .. },
            ) => Some((mesh.triangles.len(), mesh.heap_bytes())),
            Self::Solid(SolidKernel::MeshMesh { pair }) => Some(pair.held()),
            Self::Solid(_) | Self::Plane(_) | Self::Planar(_) => None,
        }
    }

    /// Evaluates the pair with `a` at `pose_a` (`X_WGa`) and `b` at `pose_b` (`X_WGb`),
    /// handing each contact to `emit`. `length` is the pair's length scale (for the 2-D
    /// in-plane tolerance).
    ///
    /// Each family has its own kernels: two solids ([`SolidKernel::contact`]), a solid and a
    /// plane ([`PlaneKernel::contact`]), or two 2-D geometries ([`PlanarKernel::contact`]),
    /// the last after the in-plane frame is set up (or [`PairError::OutOfPlane`]).
    pub fn evaluate<E: FnMut(PairContact)>(
        &self,
        pose_a: &Isometry3,
        pose_b: &Isometry3,
        length: f64,
        work: &mut WorkCounters,
        emit: &mut E,
    ) -> Result<(), PairError> {
        work.primitive_tests += 1;
        let found = match self {
            Self::Solid(kernel) => kernel.contact(pose_a, pose_b, work, emit),
            Self::Plane(kernel) => kernel.contact(pose_a, pose_b, work, emit),
            Self::Planar(kernel) => {
                let frame = planar::InPlane::new(pose_a, pose_b, length)?;
                kernel.contact(&frame, pose_a, work, emit)
            }
        };
        if let Some(c) = found {
            emit(c);
        }
        Ok(())
    }
}
