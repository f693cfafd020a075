//! OBJ input: a quad-faced box, written with every corner form, reads back as a closed solid of
//! the box's volume; defects are errors naming the file (and line).

use contact_core::mesh_file::obj::ObjError;
use contact_core::mesh_file::{MeshFileError, read_mesh_file};
use std::path::PathBuf;

fn temp(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("engine-facet-obj-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// A 1 × 2 × 3 box from the origin: 8 corners, 6 outward quads (counter-clockwise from
/// outside), with plain, texture, normal and relative corner references.
const BOX: &str = "\
# box 1 x 2 x 3
o box
v 0 0 0
v 1 0 0
v 1 2 0
v 0 2 0
v 0 0 3
v 1 0 3
v 1 2 3
v 0 2 3
vt 0 0
vn 0 0 1
s off
f 1 4 3 2
f 5/1 6/1 7/1 8/1
f 1//1 2//1 6//1 5//1
f 2/1/1 3/1/1 7/1/1 6/1/1
f -5 -1 -2 -6
f 4 1 5 8
";

#[test]
fn a_quad_faced_box_reads_as_a_closed_solid_of_the_box_volume() {
    let mesh = read_mesh_file(&temp("box.obj", BOX), false).unwrap();
    assert!(mesh.warnings.is_empty());
    assert_eq!(mesh.mesh.vertices().len(), 8);
    assert_eq!(mesh.mesh.triangles().len(), 12);
    assert!(mesh.mesh.is_closed());
    assert!((mesh.mesh.signed_volume() - 6.0).abs() < 1e-15);
    let (lo, hi) = mesh.mesh.bounding_box();
    assert_eq!((lo.coords.max(), hi.x, hi.y, hi.z), (0.0, 1.0, 2.0, 3.0));
    // Upper-case extensions are the same format.
    assert!(read_mesh_file(&temp("BOX.OBJ", BOX), false).is_ok());
}

#[test]
fn open_inverted_and_malformed_objs_are_errors_naming_the_file() {
    // One face left out: open (accepted with a warning on request).
    let open = BOX.replace("f 4 1 5 8\n", "");
    let path = temp("open.obj", &open);
    let err = read_mesh_file(&path, false).unwrap_err();
    assert!(
        matches!(&err, MeshFileError::Obj(ObjError::Mesh { .. })),
        "{err}"
    );
    assert!(err.to_string().contains("open.obj"), "{err}");
    let accepted = read_mesh_file(&path, true).unwrap();
    assert!(
        accepted.warnings[0].contains("accepted although"),
        "{:?}",
        accepted.warnings
    );

    // Every face reversed: inside out.
    let reversed: String = BOX
        .lines()
        .map(|l| match l.strip_prefix("f ") {
            Some(rest) => {
                let mut corners: Vec<&str> = rest.split_whitespace().collect();
                corners.reverse();
                format!("f {}\n", corners.join(" "))
            }
            None => format!("{l}\n"),
        })
        .collect();
    let err = read_mesh_file(&temp("inside_out.obj", &reversed), false).unwrap_err();
    assert!(err.to_string().contains("inside out"), "{err}");

    let bad = BOX.replace("f 4 1 5 8", "f 4 1 5 9");
    let err = read_mesh_file(&temp("bad.obj", &bad), false).unwrap_err();
    assert!(err.to_string().contains("bad.obj:19:"), "{err}");
    assert!(err.to_string().contains("names vertex 9"), "{err}");

    let err = read_mesh_file(&temp("mesh.ply", "ply\n"), false).unwrap_err();
    assert!(matches!(err, MeshFileError::Format(_)), "{err}");
    let err =
        read_mesh_file(&temp("missing.obj", BOX).with_file_name("nope.obj"), false).unwrap_err();
    assert!(err.to_string().contains("nope.obj"), "{err}");
}
