//! The methods the pair kernels share: slicing, section polygons, closed-form disc regions,
//! the clipping and volume ends, signed distances, mesh components.

pub(crate) mod bounded_plane;
pub(crate) mod clipped;
pub(crate) mod cylinder_parallel;
pub(crate) mod cylinder_polyhedron;
pub(crate) mod cylinder_prism;
pub(crate) mod disc_region;
pub(crate) mod disc_section;
pub(crate) mod ellipsoid_sliced;
pub(crate) mod mesh_parts;
pub(crate) mod section;
pub(crate) mod slice_events;
pub(crate) mod sliced;
pub(crate) mod solid_distance;
pub(crate) mod volume_contact;
