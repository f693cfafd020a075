//! The FRS5 model's transmit file (tests/data/frs5, a copy of the public dataset): 43 solid bodies that
//! Adams uses in CONTACTs, read, found by their Adams names and tessellated closed.

use contact_core::FacetingTolerance;
use parasolid::{Body, Part, body_mesh, tessellate};
use std::path::PathBuf;

fn frs5() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/data/frs5/FRS5_doe_8_LAUL_analysis.xmt_txt")
}

fn part() -> Part {
    let path = frs5();
    Part::read(&path).unwrap_or_else(|e| panic!("the FRS5 transmit file must read: {e}"))
}

fn label(n: &parasolid::BodyName) -> String {
    format!(
        "{}/{}",
        n.part.as_deref().unwrap_or("?"),
        n.element.as_deref().unwrap_or("?")
    )
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
    // GRAPHICS/.., RM = 4818 (on PART/9, fwd_housing), ELEMENT = SOLID5: the file's body 2.
    assert_eq!(p.find_body("fwd_housing", "SOLID5").unwrap(), 2);
    assert_eq!(p.find_body_on_part(9, None, "SOLID5").unwrap(), 2);
    // SOLID1 names bodies on several parts; the part picks one.
    let a = p.find_body_on_part(156, None, "SOLID1").unwrap();
    let b = p
        .find_body_on_part(156, Some("projectileU4"), "solid1")
        .unwrap();
    assert_eq!(a, b);
    assert_ne!(a, p.find_body("fwd_gateF", "SOLID1").unwrap());
    let e = p
        .find_body_on_part(9, None, "SOLID99")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("FRS5_doe_8_LAUL_analysis.xmt_txt") && e.contains("SOLID99"),
        "{e}"
    );
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

/// Every body closes at FT 300.0028 (Adams' default) and 3000, and its volume and centroid
/// move between the two by less than the coarse mesh's chord-deviation bound: every surface
/// point of the coarse mesh lies within δ = L/300.0028 of the true surface, so the volumes
/// differ by at most δ·A (A the surface area) and the centroids by at most δ·A/V·(1 + |c|/…);
/// the test uses the plain bounds δ·A for the volume and δ + δ·A·L/V for the centroid.
#[test]
fn every_body_closes_at_two_tolerances_and_moves_less_than_the_chord_bound() {
    let p = part();
    let coarse = FacetingTolerance::new(300.0028).unwrap();
    let fine = FacetingTolerance::new(3000.0).unwrap();
    let mut failures = Vec::new();
    for n in p.body_names().unwrap() {
        let name = label(&n);
        let b = Body::read(&p, n.index).unwrap();
        let (mc, mf) = match (
            body_mesh(&p, &b, coarse, &name),
            body_mesh(&p, &b, fine, &name),
        ) {
            (Ok(c), Ok(f)) => (c, f),
            (c, f) => {
                failures.push(format!("{name}: {:?} {:?}", c.err(), f.err()));
                continue;
            }
        };
        assert!(mf.triangles().len() > mc.triangles().len(), "{name}");
        let delta = tessellate(&p, &b, coarse).unwrap().deviation;
        let area: f64 = (0..mf.triangles().len()).map(|t| mf.triangle_area(t)).sum();
        let (vc, vf) = (mc.signed_volume(), mf.signed_volume());
        let (lo, hi) = mf.bounding_box();
        let l = (hi - lo).norm();
        assert!(
            (vc - vf).abs() < delta * area,
            "{name}: volumes {vc:e} {vf:e}, bound {:e}",
            delta * area
        );
        let (cc, cf) = (centroid(&mc), centroid(&mf));
        let bound = delta + delta * area * l / vf;
        assert!(
            (cc - cf).norm() < bound,
            "{name}: centroids move {:e}, bound {bound:e}",
            (cc - cf).norm()
        );
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn centroid(m: &contact_core::geometry::TriangleMesh) -> contact_core::Point3 {
    let mut c = contact_core::Vector3::zeros();
    let mut v = 0.0;
    for t in 0..m.triangles().len() {
        let [a, b, d] = m.triangle(t).map(|p| p.coords);
        let dv = a.dot(&b.cross(&d)) / 6.0;
        v += dv;
        c += (a + b + d) * (dv / 4.0);
    }
    contact_core::Point3::from(c / v)
}

/// Volume and centroid converge as FT rises at a measured order. Without the exact values,
/// the order comes from three tolerances in ratio 2 (Richardson): k = log2(|X₁ − X₂| / |X₂ −
/// X₄|). A chord of angle θ on radius r deviates r θ²/8 = δ ∝ 1/FT and cuts off an area ∝ r θ³
/// ∝ δ^{3/2}, with ∝ δ^{−1/2} chords round a curve: the volume error is ∝ δ, order 1, and so
/// is the centroid's (the first moment's error is the same shell of thickness ∝ δ). Measured
/// on the housing (fwd_housing/SOLID5: planes, cylinders, cones, tori, a spun face,
/// intersection curves).
#[test]
fn volume_and_centroid_converge_at_a_measured_order() {
    let p = part();
    let i = p.find_body("fwd_housing", "SOLID5").unwrap();
    let b = Body::read(&p, i).unwrap();
    let at = |ft: f64| {
        let m = tessellate(&p, &b, FacetingTolerance::new(ft).unwrap()).unwrap();
        (m.signed_volume(), m.centroid())
    };
    let ((v1, c1), (v2, c2), (v4, c4)) = (at(400.0), at(800.0), at(1600.0));
    let order = ((v1 - v2) / (v2 - v4)).log2();
    let c_order = ((c1 - c2).norm() / (c2 - c4).norm()).log2();
    eprintln!("volumes {v1:e} {v2:e} {v4:e}: order {order:.2}; centroid order {c_order:.2}");
    assert!((0.7..=1.5).contains(&order), "volume order {order}");
    assert!((0.7..=1.5).contains(&c_order), "centroid order {c_order}");
}

/// At coarse tolerances (δ = L/50 is 8 mm on the 0.4 m frame) edge chords of nearly touching
/// loops cross; refining the edges of the faces concerned closes every body all the same.
#[test]
fn every_body_closes_at_coarse_tolerances() {
    let p = part();
    for ft in [50.0, 100.0] {
        let tol = FacetingTolerance::new(ft).unwrap();
        for n in p.body_names().unwrap() {
            let name = label(&n);
            let b = Body::read(&p, n.index).unwrap();
            body_mesh(&p, &b, tol, &name).unwrap_or_else(|e| panic!("FT {ft}: {name}: {e}"));
        }
    }
}

/// Every body closes at each tolerance given: the (FT, body) pairs that do not, listed.
fn all_close(p: &Part, fts: &[f64]) {
    let mut failures = Vec::new();
    for &ft in fts {
        let tol = FacetingTolerance::new(ft).unwrap();
        for n in p.body_names().unwrap() {
            let name = label(&n);
            let b = Body::read(p, n.index).unwrap();
            if let Err(e) = body_mesh(p, &b, tol, &name) {
                failures.push(format!("FT {ft}: {e}"));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Between FT 180 and 205 the chord bound let a small cylinder's grid step near half a turn,
/// and the face's two copies of a triangle across its seam shared an edge with a third and fourth triangle
/// (mid_frameX/SOLID1138). Every body closes there and at 250.
#[test]
fn every_body_closes_where_cylinder_steps_once_neared_half_a_turn() {
    all_close(&part(), &[182.676, 200.0, 202.967, 250.0]);
}

/// Every body closes at 63 tolerances from 20 to 10000 (log-spaced, with 200, 250 and
/// 300.0028). Long in a debug build: `cargo test --release -p parasolid --test frs5 -- --ignored`.
#[test]
#[ignore]
fn every_body_closes_over_a_dense_sweep_of_tolerances() {
    let mut fts: Vec<f64> = (0..60)
        .map(|k| 20.0 * 500f64.powf(k as f64 / 59.0))
        .collect();
    fts.extend([200.0, 250.0, 300.0028]);
    all_close(&part(), &fts);
}
