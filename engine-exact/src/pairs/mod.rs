//! 3-D pair families, one file each. Every function takes the world poses `X_WG` of its two
//! geometries (first `a`, second `b`, in canonical order) and returns the contact with the
//! normal from `b` into `a`, or `None` when the intersection has no volume.
//!
//! Normals by family: against a plane, the plane's outward normal; between spheres, the line
//! of centres; between boxes, the area-weighted outward normal of the part of `b`'s surface
//! inside `a` (the direction of the net force of a uniform pressure on that surface).
//!
//! Points by SPEC §4, taken along the normal through the intersection's centroid (where that
//! line leaves each body; see `crate::ray_exit`); the curved solid–solid pairs share that
//! last step in [`volume_contact`].

pub mod bounded_plane;
pub mod box_box;
pub mod box_half_space;
pub mod box_plane;
pub(crate) mod box_revolved;
pub mod clipped;
pub mod cylinder_parallel;
pub mod cylinder_plane;
pub(crate) mod cylinder_polyhedron;
pub mod cylinder_prism;
pub mod cylinder_solid;
pub(crate) mod disc_region;
pub(crate) mod disc_section;
pub mod ellipsoid_box;
pub mod ellipsoid_cylinder;
pub mod ellipsoid_ellipsoid;
pub(crate) mod ellipsoid_frustum;
pub mod ellipsoid_plane;
pub(crate) mod ellipsoid_sliced;
pub(crate) mod ellipsoid_torus;
pub(crate) mod mesh_box;
pub(crate) mod mesh_parts;
pub mod mesh_plane;
pub(crate) mod mesh_revolved;
pub(crate) mod revolved_pair;
pub mod revolved_plane;
pub(crate) mod revolved_torus;
pub mod section;
pub mod slice_events;
pub mod sliced;
pub mod solid_distance;
pub mod sphere_mesh;
pub mod sphere_plane;
pub mod sphere_solid;
pub mod sphere_sphere;
pub mod volume_contact;
