//! Shared by the STL and OBJ targets: the readers take a path, so each input is written to a
//! file of this process's own in the temporary directory and read back as a user's file is.

use contact_core::geometry::Geometry;
use contact_core::mesh_file::read_mesh_geometry;
use std::path::PathBuf;

/// Writes `data` to `fuzz-<pid>.<extension>`, reads it as a mesh file, and when it reads,
/// prepares it for the faceted engine (tree build) and queries it against a sphere.
pub fn read_and_prepare(data: &[u8], extension: &str) {
    let path = input_path(extension);
    std::fs::write(&path, data).expect("the temporary directory is writable");
    if let Ok(geometry) = read_mesh_geometry(&path) {
        query_against_sphere(geometry);
    }
}

fn input_path(extension: &str) -> PathBuf {
    std::env::temp_dir().join(format!("fuzz-{}.{extension}", std::process::id()))
}

fn query_against_sphere(mesh: Geometry) {
    use contact_core::{FacetingTolerance, GeometryInstance, Isometry3, WorkCounters};
    use engine_facet::FacetEngine;
    use contact_core::GeometryEngine;
    let engine = FacetEngine::new(FacetingTolerance::default());
    let i = GeometryInstance::new(mesh);
    let j = GeometryInstance::new(Geometry::sphere(0.5).expect("a valid radius"));
    let Ok(pair) = engine.prepare(std::slice::from_ref(&i), std::slice::from_ref(&j)) else {
        return;
    };
    let mut contacts = Vec::new();
    let mut work = WorkCounters::default();
    if pair
        .query(&Isometry3::identity(), &Isometry3::identity(), &mut contacts, &mut work)
        .is_ok()
    {
        for c in &contacts {
            assert!(c.is_well_formed(), "ill-formed contact {c:?}");
        }
    }
}
