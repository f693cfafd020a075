//! Integration tests of the faceted engine (one binary, modules inside).

mod cavities;
mod common;
mod concave_oracle;
mod concave_regions;
mod convergence;
mod engine;
mod far_from_plane;
mod flipped_plane;
mod grazing_corner;
mod implied_ellipsoid;
mod mesh_regions;
mod obj_files;
mod patches;
mod pinned;
mod planar;
mod planar_overlap;
mod plane_edge;
mod rolling;
mod solid_on_face;
mod stl_files;
mod tessellation;
mod threads;
mod triangles;
mod voxels;
