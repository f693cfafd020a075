//! STL input: ascii and binary round trips, welding, and defects reported with the file name.

use contact_core::Point3;
use contact_core::mesh_file::stl::{StlError, read_stl};
use std::io::Write;
use std::path::PathBuf;

/// A cube's 12 triangles, outward, as corner triples.
fn cube() -> Vec<[[f32; 3]; 3]> {
    let t = engine_facet::tessellate::cuboid(
        &contact_core::geometry::Cuboid::centered(0.5, 1.0, 1.5).unwrap(),
    );
    t.triangles
        .iter()
        .map(|tri| {
            tri.map(|v| {
                let p = t.vertices[v as usize];
                [p.x as f32, p.y as f32, p.z as f32]
            })
        })
        .collect()
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("engine-facet-stl-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn write_ascii(name: &str, tris: &[[[f32; 3]; 3]]) -> PathBuf {
    let path = temp(name);
    let mut f = std::fs::File::create(&path).unwrap();
    writeln!(f, "solid test").unwrap();
    for t in tris {
        writeln!(f, "facet normal 0 0 0\n outer loop").unwrap();
        for v in t {
            writeln!(f, "  vertex {} {} {}", v[0], v[1], v[2]).unwrap();
        }
        writeln!(f, " endloop\nendfacet").unwrap();
    }
    writeln!(f, "endsolid test").unwrap();
    path
}

fn write_binary(name: &str, tris: &[[[f32; 3]; 3]]) -> PathBuf {
    let path = temp(name);
    let mut f = std::fs::File::create(&path).unwrap();
    let triangles: Vec<stl_io::Triangle> = tris
        .iter()
        .map(|t| stl_io::Triangle {
            normal: stl_io::Vector::new([0.0; 3]),
            vertices: t.map(stl_io::Vector::new),
        })
        .collect();
    stl_io::write_stl(&mut f, triangles.iter()).unwrap();
    path
}

#[test]
fn ascii_and_binary_cubes_read_back_as_the_same_closed_solid() {
    for path in [
        write_ascii("cube.stl", &cube()),
        write_binary("cube_bin.stl", &cube()),
    ] {
        let m = read_stl(&path, false).unwrap();
        assert!(m.warnings.is_empty());
        assert_eq!(m.mesh.vertices().len(), 8, "welded to 8 corners");
        assert_eq!(m.mesh.triangles().len(), 12);
        assert!((m.mesh.signed_volume() - 6.0).abs() < 1e-6);
        assert!(m.mesh.vertices().contains(&Point3::new(-0.5, -1.0, -1.5)));
    }
}

#[test]
fn nearly_equal_corners_are_welded() {
    let mut tris = cube();
    tris[3][1][0] += 1e-8; // far below the weld distance of 1e-7 × the diagonal
    let m = read_stl(&write_ascii("jitter.stl", &tris), false).unwrap();
    assert_eq!(m.mesh.vertices().len(), 8);
}

fn error_of(name: &str, tris: &[[[f32; 3]; 3]]) -> (StlError, String) {
    let path = write_binary(name, tris);
    let e = read_stl(&path, false).unwrap_err();
    let text = e.to_string();
    assert!(text.contains(name), "the message names the file: {text}");
    (e, text)
}

#[test]
fn open_non_manifold_inconsistent_and_degenerate_meshes_are_errors_naming_the_file() {
    let mut open = cube();
    open.pop();
    let (_, text) = error_of("open.stl", &open);
    assert!(text.contains("open"), "{text}");
    // The flag accepts an open mesh with a warning.
    let ok = read_stl(&write_binary("open2.stl", &open), true).unwrap();
    assert!(!ok.mesh.is_closed() && ok.warnings[0].contains("open2.stl"));

    let mut flipped = cube();
    flipped[0].swap(1, 2);
    let (_, text) = error_of("flipped.stl", &flipped);
    assert!(text.contains("inconsistently oriented"), "{text}");

    let mut extra = cube();
    extra.push(extra[0]);
    let (_, text) = error_of("nonmanifold.stl", &extra);
    assert!(
        text.contains("non-manifold") || text.contains("inconsistently"),
        "{text}"
    );

    let mut degenerate = cube();
    degenerate[5][2] = degenerate[5][1];
    let (_, text) = error_of("degenerate.stl", &degenerate);
    assert!(text.contains("zero area"), "{text}");

    let missing = read_stl(&temp("missing.stl"), false).unwrap_err();
    assert!(missing.to_string().contains("missing.stl"));
}
