//! The patch index against brute force: for every node of the tree of a sphere, a torus and a
//! box (the box's few large faces make nodes that are not connected), its range, connectedness,
//! rim and cone sums are recomputed from the triangles alone.

use crate::common::Rng;
use contact_core::{FacetingTolerance, Geometry, Vector3};
use engine_facet::facet_mesh::FacetMesh;
use engine_facet::patches::MIN_PATCH;
use engine_facet::surface_sums::SurfaceSums;
use engine_facet::tessellate::tessellate;

fn meshes() -> Vec<FacetMesh> {
    let torus = Geometry::Torus(contact_core::geometry::Torus::new(1.0, 0.35).unwrap());
    let cuboid =
        Geometry::Cuboid(contact_core::geometry::Cuboid::from_corner(2.0, 1.0, 0.5).unwrap());
    [
        (Geometry::sphere(1.0).unwrap(), 300.0),
        (torus, 300.0),
        (cuboid, 10.0),
    ]
    .into_iter()
    .map(|(g, ft)| {
        FacetMesh::build(
            tessellate(&g, FacetingTolerance::new(ft).unwrap()).unwrap(),
            true,
        )
    })
    .collect()
}

/// Edge-connected components of the triangles `first..end`, by a flood inside the range.
fn components(m: &FacetMesh, first: u32, end: u32) -> usize {
    let mut seen = vec![false; (end - first) as usize];
    let mut count = 0;
    for start in first..end {
        if seen[(start - first) as usize] {
            continue;
        }
        count += 1;
        let mut stack = vec![start];
        seen[(start - first) as usize] = true;
        while let Some(t) = stack.pop() {
            for &n in &m.neighbors[t as usize] {
                if n >= first && n < end && !seen[(n - first) as usize] {
                    seen[(n - first) as usize] = true;
                    stack.push(n);
                }
            }
        }
    }
    count
}

#[test]
fn the_patch_index_matches_brute_force_on_every_node() {
    let mut rng = Rng(0xFACE7);
    let mut disconnected = 0;
    let mut stored = 0;
    for m in meshes() {
        let nodes = m.tree.nodes();
        let p = &m.patches;
        // Triangles are numbered in leaf order: each leaf's triangles are its own range.
        for (i, node) in nodes.iter().enumerate() {
            if node.count > 0 {
                let leaf: Vec<u32> = m.tree.leaf_triangles(node).to_vec();
                let expected: Vec<u32> = (node.index..node.index + node.count).collect();
                assert_eq!(leaf, expected);
                for &t in &leaf {
                    assert_eq!(p.leaf_of[t as usize], i as u32);
                }
            }
        }
        for i in 0..nodes.len() as u32 {
            let (first, end) = p.range[i as usize];
            // The range holds exactly the triangles of the subtree's leaves.
            let mut below = Vec::new();
            m.tree.visit_subtree(i, |t| below.push(t));
            below.sort_unstable();
            assert_eq!(below, (first..end).collect::<Vec<_>>(), "node {i}");
            let parts = components(&m, first, end);
            assert_eq!(
                p.connected[i as usize],
                parts == 1,
                "node {i}: {parts} parts"
            );
            disconnected += usize::from(parts > 1);
            let mut rim = Vec::new();
            p.for_each_rim(i, &m.neighbors, |n| rim.push(n));
            let mut brute = Vec::new();
            for t in first..end {
                for &n in &m.neighbors[t as usize] {
                    if n < first || n >= end {
                        brute.push(n);
                    }
                }
            }
            assert_eq!(rim, brute, "node {i}");
            let apex = Vector3::new(
                rng.range(-2.0, 2.0),
                rng.range(-2.0, 2.0),
                rng.range(-2.0, 2.0),
            );
            let got = p.cones(i, &apex, |t| m.corners(t));
            let mut direct = SurfaceSums::default();
            let mut scale = 0.0;
            for t in first..end {
                let [a, b, c] = m.corners(t);
                direct.add_triangle(&a, &b, &c, &apex);
                let mut one = SurfaceSums::default();
                one.add_triangle(&a, &b, &c, &apex);
                scale += one.volume.abs();
            }
            assert!(
                (got.volume - direct.volume).abs() <= 1e-12 * scale,
                "node {i}"
            );
            assert!(
                (got.moment - direct.moment).norm() <= 1e-12 * scale * 4.0,
                "node {i}"
            );
            stored += usize::from(end - first >= MIN_PATCH);
        }
    }
    // Both branches of each check occur, or the test could not fail.
    assert!(disconnected > 0 && stored > 50, "{disconnected} {stored}");
}
