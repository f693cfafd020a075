//! The FRS5 model's transmit file (../shared/datasets/real-models/FRS5): 43 solid bodies that
//! Adams uses in CONTACTs, read, found by their Adams names and tessellated closed.

use contact_core::FacetingTolerance;
use parasolid::{Body, Part, body_mesh};
use std::path::PathBuf;

fn frs5() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/datasets/real-models/FRS5/FRS5_doe_8_LAUL_analysis.xmt_txt")
}

fn part() -> Part {
    let path = frs5();
    Part::read(&path).unwrap_or_else(|e| panic!("the FRS5 transmit file must read: {e}"))
}

#[test]
fn the_file_reads_with_its_43_bodies_and_their_adams_names() {
    let p = part();
    assert_eq!(p.schema(), "SCH_3101206_31100_13006");
    let names = p.body_names().unwrap();
    assert_eq!(names.len(), 43);
    assert!(
        names
            .iter()
            .all(|n| n.part.is_some() && n.element.is_some())
    );
    // SOURCES.md: ELEMENT names repeat across parts; part + element is unique.
    let mut pairs: Vec<_> = names
        .iter()
        .map(|n| (n.part.clone(), n.element.clone()))
        .collect();
    pairs.sort();
    pairs.dedup();
    assert_eq!(pairs.len(), 43);
    let mut elements: Vec<_> = names.iter().map(|n| n.element.clone()).collect();
    elements.sort();
    elements.dedup();
    assert!(elements.len() < 43, "some ELEMENT names repeat");
    let i = p.find_body("fwd_housing", "SOLID5").unwrap();
    assert_eq!(i, 2);
    assert!(p.find_body("fwd_housing", "SOLID99").is_err());
}

#[test]
fn the_face_and_edge_counts_are_those_of_the_sources_note() {
    let p = part();
    let (mut faces, mut edges) = (0, 0);
    for i in p.body_indices().unwrap() {
        let b = Body::read(&p, i).unwrap();
        faces += b.faces.len();
        edges += b.edges.len();
    }
    assert_eq!((faces, edges), (1695, 4114));
}

#[test]
fn every_body_tessellates_closed_at_the_default_tolerance() {
    let p = part();
    let mut failures = Vec::new();
    for n in p.body_names().unwrap() {
        let name = format!(
            "{}/{}",
            n.part.as_deref().unwrap_or("?"),
            n.element.as_deref().unwrap_or("?")
        );
        let r = Body::read(&p, n.index)
            .and_then(|b| body_mesh(&p, &b, FacetingTolerance::DEFAULT, &name));
        match r {
            Ok(m) => eprintln!(
                "{name}: {} triangles, volume {:e}",
                m.triangles().len(),
                m.signed_volume()
            ),
            Err(e) => failures.push(format!("{name}: {e}")),
        }
    }
    // Faces whose loops cross their periodic seam or lie on B-splines are not yet triangulated:
    // these five bodies are refused by name, the other 38 close.
    let expected = [
        "SOLID1138",
        "SOLID1_2",
        "ferguson_camF/SOLID7",
        "ferguson_camF/SOLID1",
        "feed_rotorF/SOLID1",
    ];
    assert_eq!(failures.len(), expected.len(), "{}", failures.join("\n"));
    for (f, e) in failures.iter().zip(expected) {
        assert!(f.contains(e), "{f}");
    }
}
