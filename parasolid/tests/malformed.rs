//! Bad transmit files give errors that name the file and the node, never a panic: truncated
//! files, unknown node types, dangling references and damaged bytes.

use contact_core::FacetingTolerance;
use parasolid::{Body, ErrorKind, Part, body_mesh};
use std::path::{Path, PathBuf};

fn frs5_bytes() -> Vec<u8> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/data/frs5/FRS5_doe_8_LAUL_analysis.xmt_txt");
    std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn name() -> &'static Path {
    Path::new("bad.xmt_txt")
}

/// Replaces the first occurrence of `from` (which must exist) by `to`.
fn edited(bytes: &[u8], from: &str, to: &str) -> Vec<u8> {
    let at = bytes
        .windows(from.len())
        .position(|w| w == from.as_bytes())
        .unwrap_or_else(|| panic!("{from:?} is in the file"));
    [&bytes[..at], to.as_bytes(), &bytes[at + from.len()..]].concat()
}

#[test]
fn a_truncated_file_is_an_error_naming_the_file_and_the_node_it_ends_in() {
    let bytes = frs5_bytes();
    let mut named = 0;
    for k in 1..40 {
        let cut = bytes.len() * k / 40;
        let e = Part::from_bytes(name(), &bytes[..cut]).expect_err("a cut file is an error");
        let text = e.to_string();
        assert!(text.starts_with("bad.xmt_txt: "), "{text}");
        if let ErrorKind::Truncated { what } = &e.kind {
            named += usize::from(what.contains("node "));
        }
    }
    // Cuts inside a node's fields name the node (index and type).
    assert!(named > 30, "{named}");
    let e = Part::from_bytes(name(), b"**ABC\n**PART1;\n").unwrap_err();
    assert!(matches!(e.kind, ErrorKind::Truncated { .. }), "{e}");
    let e = Part::from_bytes(name(), b"").unwrap_err();
    assert!(matches!(e.kind, ErrorKind::Truncated { .. }), "{e}");
}

#[test]
fn an_unknown_node_type_is_an_error_naming_it_and_its_index() {
    let bytes = edited(&frs5_bytes(), " 51 255 385 ", " 997 255 385 ");
    let e = Part::from_bytes(name(), &bytes).unwrap_err();
    assert_eq!(
        e.kind,
        ErrorKind::UnknownNodeType {
            index: 385,
            node_type: 997
        },
        "{e}"
    );
    assert!(
        e.to_string().contains("node 385: node type 997 is unknown"),
        "{e}"
    );
}

#[test]
fn a_dangling_reference_is_an_error_naming_the_node_and_field() {
    // The first BODY's region pointer (52) to a node that does not exist.
    let bytes = edited(
        &frs5_bytes(),
        "48 49 50 51 0 0 52 53 54",
        "48 49 50 51 0 0 99999 53 54",
    );
    let p = Part::from_bytes(name(), &bytes).unwrap();
    let e = Body::read(&p, 2).unwrap_err();
    match &e.kind {
        ErrorKind::DanglingReference {
            node,
            field,
            target,
            ..
        } => {
            assert_eq!(
                (node.index, node.node_type, *field, *target),
                (2, 12, "region", 99999)
            );
        }
        k => panic!("{k:?}"),
    }
    assert!(
        e.to_string()
            .contains("node 2 (BODY, type 12): field region refers to node 99999"),
        "{e}"
    );
    // A pointer to a node of the wrong kind is refused the same way.
    let bytes = edited(
        &frs5_bytes(),
        "48 49 50 51 0 0 52 53 54",
        "48 49 50 51 0 0 53 53 54",
    );
    let p = Part::from_bytes(name(), &bytes).unwrap();
    let e = Body::read(&p, 2).unwrap_err();
    assert!(matches!(e.kind, ErrorKind::DanglingReference { .. }), "{e}");
}

#[test]
fn damaged_bytes_never_panic() {
    let bytes = frs5_bytes();
    let start = bytes
        .windows(15)
        .position(|w| w == b"**END_OF_HEADER")
        .unwrap();
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..24 {
        let mut b = bytes.clone();
        for _ in 0..3 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let at = start + (seed as usize) % (b.len() - start);
            b[at] = b"0123456789 ?T-.e"[(seed >> 40) as usize % 16];
        }
        if let Ok(p) = Part::from_bytes(name(), &b) {
            for i in p.body_indices().unwrap_or_default().into_iter().take(3) {
                let _ = Body::read(&p, i)
                    .and_then(|body| body_mesh(&p, &body, FacetingTolerance::DEFAULT, "x"));
            }
        }
    }
}

/// The small cam-and-pin file (planes, a cylinder, a periodic B-surface and B-curves, name
/// attributes) with one of its numbers replaced by an extreme one, 3,000 times: every read and
/// recognition, and the tessellation of every 60th, gives an answer or an error, never a panic
/// (tests run with overflow checks; the tessellation of all 3,000 is a release-build minute,
/// and gave no panic either).
#[test]
fn extreme_numbers_in_a_b_spline_file_never_panic() {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/data/parasolid/cam_and_pin.x_t");
    let text = String::from_utf8(std::fs::read(&path).unwrap()).unwrap();
    let start = text.find("**END_OF_HEADER").unwrap();
    // Where each number of the stream starts.
    let b = text.as_bytes();
    let numbers: Vec<usize> = (start..text.len())
        .filter(|&i| b[i].is_ascii_digit() && !b[i - 1].is_ascii_alphanumeric() && b[i - 1] != b'.')
        .collect();
    let extremes = [
        "0",
        "-1",
        "1",
        "2",
        "15",
        "16",
        "9223372036854775807",
        "-9223372036854775808",
        "4294967295",
        "67108864",
        "1e308",
        "-1e308",
        "1e-308",
        "?",
    ];
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    for k in 0..3000 {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        let at = numbers[(seed as usize) % numbers.len()];
        let end = at
            + text[at..]
                .find(|c: char| !(c.is_ascii_digit() || matches!(c, '.' | 'e' | '-')))
                .unwrap_or(0);
        let with = extremes[(seed >> 32) as usize % extremes.len()];
        let bytes = format!("{}{with}{}", &text[..at], &text[end..]);
        let Ok(p) = Part::from_bytes(name(), bytes.as_bytes()) else {
            continue;
        };
        let _ = p.body_names();
        for i in p.body_indices().unwrap_or_default() {
            if let Ok(body) = Body::read(&p, i) {
                let _ = parasolid::primitive::recognise(&body);
                if k % 60 == 0 {
                    let _ = body_mesh(&p, &body, FacetingTolerance::new(30.0).unwrap(), "x");
                }
            }
        }
    }
}
