//! The exact engine's test binary (one binary, modules inside, to keep linking cheap).
//!
//! - [`oracles`]: closed forms written independently of the engine (slicing instead of the
//!   engine's affine map, axis-aligned box overlap instead of clipping, …);
//! - [`revolved_oracles`]: frustum and torus against a plane by slicing across the axis and
//!   by Pappus;
//! - [`sliced_oracles`]: cylinder–cylinder and cylinder–box by closed forms and by slicing
//!   along other directions;
//! - [`characterization`]: the accuracy contract, one row per pair;
//! - [`properties`]: I/J swap, rigid motion and scale covariance;
//! - [`degenerate`]: touching, grazing, containment, coincident centres, extreme scales;
//! - [`degenerate_sliced`]: the same for the sliced cylinder pairs;
//! - [`degenerate_boundaries`]: the same for arcs, curves and lines against each other;
//! - [`circle_bounded_line`]: a circle on a bounded line: invariants, the unbounded limit,
//!   agreement with a closed arc, continuity across an end, degenerate branches;
//! - [`ellipsoid_revolved`]: general ellipsoid–frustum: the coaxial and apex-divergence
//!   oracles, a frustum of equal radii against the cylinder pair, invariants, degenerate
//!   branches;
//! - [`frustum_oracles`]: ellipsoid–frustum in general poses by the divergence theorem about
//!   the apex;
//! - [`ellipsoid_cavity`]: ellipsoids and balls in cylinder-, frustum- and ellipsoid-shaped
//!   cavities: two caps through a bore's ends and a spheroid across a socket in closed form,
//!   a crescent and two regions against the wall's area integral, a ball wholly in the
//!   material, balls at rims against brute force, region counts against a grid;
//! - [`ellipsoid_torus`]: general ellipsoid–torus: two regions, invariants, degenerate
//!   branches; [`torus_oracles`]: its coaxial and divergence oracles;
//! - [`box_revolved`]: box–frustum/torus and frustum, torus, ellipsoid–bounded plane:
//!   invariants, separate regions, degenerate branches;
//! - [`mesh_box`]: box–mesh and mesh–bounded plane: the clipping pairs where the mesh is a
//!   box, regions, holes in the caps, containment, touching, invariants;
//! - [`mesh_revolved`]: cylinder–mesh and frustum–mesh: the slicings where the mesh is a box,
//!   regions, a hole in the section, containment, touching, invariants;
//! - [`revolved_pairs`]: frustum–frustum and cylinder–frustum: frusta of equal radii against
//!   the cylinder pair, coaxial stacks' closed form, touching, containment, identical solids,
//!   perpendicular and near-parallel axes at 1e-6 and 1e6;
//! - [`revolved_torus`]: cylinder–torus and frustum–torus: coaxial pairs against the meridian
//!   closed form, general poses and two-region rods against the divergence theorem, degenerate
//!   branches, invariants; [`torus_pair_oracles`]: those oracles;
//! - [`voxel_oracle`]: grid-cell meshes and their closed-form contact with aligned boxes;
//! - [`model_check`]: what `supports`/`prepare` accept and refuse;
//! - [`sphere_solid`]: sphere–box, –cylinder, –frustum and –torus at edges, rims, corners,
//!   centres inside, a frustum's side and a torus' tube, against a brute-force sampling of
//!   the intersection; the torus reproduction;
//! - [`regressions`]: bugs found, with their reproducers.

mod bounded_plane;
mod box_revolved;
mod characterization;
mod circle_bounded_line;
mod common;
mod degenerate;
mod degenerate_boundaries;
mod degenerate_sliced;
mod ellipsoid_cavity;
mod ellipsoid_degenerate;
mod ellipsoid_oracles;
mod ellipsoid_revolved;
mod ellipsoid_torus;
mod frustum_oracles;
mod mesh_box;
mod mesh_mesh;
mod mesh_revolved;
mod model_check;
mod oracles;
mod properties;
mod regressions;
mod revolved_oracles;
mod revolved_pairs;
mod revolved_torus;
mod sliced_oracles;
mod sphere_solid;
mod spherical_reference;
mod torus_oracles;
mod torus_pair_oracles;
mod torus_torus;
mod voxel_oracle;
