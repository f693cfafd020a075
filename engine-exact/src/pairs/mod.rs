//! The 3-D pair kernels, one module per [`crate::kernel::SolidKernel`] or
//! [`crate::kernel::PlaneKernel`] variant and named as it is (`SolidKernel::BoxMesh` →
//! `box_mesh`; `SphereInCavity` lives beside `SphereSphere`, the
//! cylinder's slicing partners in `cylinder_sliced`); the methods they share are in
//! `crate::methods`. Every function takes the world poses `X_WG` of its two
//! geometries (first `a`, second `b`, in canonical order) and returns the contact with the
//! normal from `b` into `a`, or `None` when the intersection has no volume.
//!
//! Normals by family: against a plane, the plane's outward normal; between spheres, the line
//! of centres; between boxes, the area-weighted outward normal of the part of `b`'s surface
//! inside `a` (the direction of the net force of a uniform pressure on that surface).
//!
//! Points by SPEC §4, taken along the normal through the intersection's centroid (where that
//! line leaves each body; see `crate::ray_exit`); the curved solid–solid pairs share that
//! last step in `crate::methods::volume_contact`.

pub(crate) mod box_box;
pub(crate) mod box_mesh;
pub(crate) mod box_plane;
pub(crate) mod box_revolved;
pub(crate) mod cylinder_plane;
pub(crate) mod cylinder_sliced;
pub(crate) mod ellipsoid_bounded_plane;
pub(crate) mod ellipsoid_box;
pub(crate) mod ellipsoid_cavity;
pub(crate) mod ellipsoid_cylinder;
pub(crate) mod ellipsoid_ellipsoid;
pub(crate) mod ellipsoid_frustum;
pub(crate) mod ellipsoid_mesh;
pub(crate) mod ellipsoid_plane;
pub(crate) mod ellipsoid_torus;
pub(crate) mod mesh_bounded_plane;
pub(crate) mod mesh_mesh;
pub(crate) mod mesh_plane;
pub(crate) mod revolved_bounded_plane;
pub(crate) mod revolved_mesh;
pub(crate) mod revolved_pair;
pub(crate) mod revolved_plane;
pub(crate) mod revolved_torus;
pub(crate) mod sphere_bounded_plane;
pub(crate) mod sphere_mesh;
pub(crate) mod sphere_plane;
pub(crate) mod sphere_solid;
pub(crate) mod sphere_sphere;
pub(crate) mod torus_torus;
