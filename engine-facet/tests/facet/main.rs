//! Integration tests of the faceted engine (one binary, modules inside).

mod common;
mod convergence;
mod engine;
mod grazing_corner;
mod pinned;
mod planar;
mod stl_files;
mod tessellation;
mod threads;
mod triangles;
