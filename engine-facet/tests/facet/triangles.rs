//! Triangle–triangle intersection against an independent oracle, and the tree descent against
//! a brute-force all-pairs check.

use crate::common::Rng;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use engine_facet::facet_mesh::FacetMesh;
use engine_facet::obb_tree::{BoxCache, descend_pair};
use engine_facet::tessellate::Tessellation;
use engine_facet::triangle_pair::{TrianglePair, intersect};

/// Oracle: a segment meets a triangle (closed), by signed volumes — no plane distances, no
/// intervals, nothing shared with the code under test.
fn segment_meets_triangle(p: &Vector3, q: &Vector3, t: &[Vector3; 3]) -> bool {
    let vol =
        |a: &Vector3, b: &Vector3, c: &Vector3, d: &Vector3| (b - a).dot(&(c - a).cross(&(d - a)));
    let (sp, sq) = (vol(&t[0], &t[1], &t[2], p), vol(&t[0], &t[1], &t[2], q));
    if sp * sq > 0.0 {
        return false;
    }
    let s = [
        vol(p, q, &t[0], &t[1]),
        vol(p, q, &t[1], &t[2]),
        vol(p, q, &t[2], &t[0]),
    ];
    (s[0] >= 0.0 && s[1] >= 0.0 && s[2] >= 0.0) || (s[0] <= 0.0 && s[1] <= 0.0 && s[2] <= 0.0)
}

/// Two non-coplanar triangles meet iff an edge of one meets the other.
fn oracle(p: &[Vector3; 3], q: &[Vector3; 3]) -> bool {
    (0..3).any(|k| segment_meets_triangle(&p[k], &p[(k + 1) % 3], q))
        || (0..3).any(|k| segment_meets_triangle(&q[k], &q[(k + 1) % 3], p))
}

fn random_triangle(rng: &mut Rng, spread: f64) -> [Vector3; 3] {
    let c = Vector3::new(
        rng.range(-spread, spread),
        rng.range(-spread, spread),
        rng.range(-spread, spread),
    );
    [0, 1, 2].map(|_| {
        c + Vector3::new(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        )
    })
}

#[test]
fn random_triangle_pairs_agree_with_the_edge_oracle_and_segments_lie_on_both() {
    let mut rng = Rng(42);
    let mut hits = 0;
    for _ in 0..20_000 {
        let (p, q) = (
            random_triangle(&mut rng, 0.8),
            random_triangle(&mut rng, 0.8),
        );
        let got = intersect(&p, &q);
        assert_eq!(
            matches!(got, TrianglePair::Segment(..)),
            oracle(&p, &q),
            "{p:?} {q:?}"
        );
        if let TrianglePair::Segment(a, b) = got {
            hits += 1;
            // Both ends lie on both planes and the segment runs along n_p × n_q.
            let np = (p[1] - p[0]).cross(&(p[2] - p[0])).normalize();
            let nq = (q[1] - q[0]).cross(&(q[2] - q[0])).normalize();
            for e in [a, b] {
                assert!(np.dot(&(e - p[0])).abs() < 1e-12 && nq.dot(&(e - q[0])).abs() < 1e-12);
            }
            assert!((b - a).dot(&np.cross(&nq)) >= -1e-15);
        }
    }
    // Both outcomes occur often, else the comparison could not fail.
    assert!(hits > 500 && hits < 19_500, "{hits}");
}

#[test]
fn coplanar_and_touching_triangles_are_handled() {
    let v = |x: f64, y: f64, z: f64| Vector3::new(x, y, z);
    let p = [v(0., 0., 0.), v(2., 0., 0.), v(0., 2., 0.)];
    // Coplanar, overlapping; coplanar, apart.
    assert_eq!(
        intersect(&p, &[v(0.5, 0.5, 0.), v(3., 0.5, 0.), v(0.5, 3., 0.)]),
        TrianglePair::Coplanar
    );
    assert_eq!(
        intersect(&p, &[v(5., 5., 0.), v(6., 5., 0.), v(5., 6., 0.)]),
        TrianglePair::Disjoint
    );
    // Touching at a single vertex: a zero-length segment at that vertex.
    match intersect(&p, &[v(0.5, 0.5, 0.), v(1., 1., 1.), v(0., 1., 1.)]) {
        TrianglePair::Segment(a, b) => {
            assert!((a - v(0.5, 0.5, 0.)).norm() < 1e-15 && (a - b).norm() < 1e-15)
        }
        other => panic!("{other:?}"),
    }
    // Sharing an edge at an angle (a mesh's neighbours): the shared edge.
    match intersect(&p, &[v(0., 0., 0.), v(2., 0., 0.), v(1., -1., 1.)]) {
        TrianglePair::Segment(a, b) => assert!(((b - a).norm() - 2.0).abs() < 1e-12),
        other => panic!("{other:?}"),
    }
    // Crossing through the interior, perpendicular: segment from y = 0.25 to 1.25 at x = 0.5.
    match intersect(&p, &[v(0.5, 0.25, -1.), v(0.5, 0.25, 1.), v(0.5, 5.0, 0.)]) {
        TrianglePair::Segment(a, b) => {
            let (lo, hi) = if a.y < b.y { (a, b) } else { (b, a) };
            assert!((lo - v(0.5, 0.25, 0.)).norm() < 1e-12, "{lo}");
            assert!((hi - v(0.5, 1.5, 0.)).norm() < 1e-12, "{hi}");
        }
        other => panic!("{other:?}"),
    }
}

/// A lumpy closed mesh: a UV sphere with seeded radial noise.
fn lumpy(rng: &mut Rng, n: usize) -> FacetMesh {
    let g = contact_core::Geometry::sphere(1.0).unwrap();
    let ft = contact_core::FacetingTolerance::new(n as f64).unwrap();
    let t = engine_facet::tessellate::tessellate(&g, ft).unwrap();
    let vertices: Vec<Point3> = t
        .vertices
        .iter()
        .map(|v| v * rng.range(0.85, 1.15))
        .collect();
    let normals = engine_facet::tessellate::flat_corner_normals(&vertices, &t.triangles);
    FacetMesh::build(
        Tessellation {
            vertices,
            triangles: t.triangles,
            corner_normals: normals,
        },
        true,
    )
}

#[test]
fn the_tree_descent_finds_exactly_the_brute_force_intersecting_pairs() {
    let mut rng = Rng(9);
    let (a, b) = (
        lumpy(&mut rng, 40.0 as usize),
        lumpy(&mut rng, 60.0 as usize),
    );
    let mut total = 0;
    for _ in 0..6 {
        let pose = Isometry3::from_parts(
            (rng.unit_vector() * rng.range(0.6, 1.9)).into(),
            rng.rotation(),
        );
        let rot = pose.rotation.to_rotation_matrix().into_inner();
        let t = pose.translation.vector;
        let tb = |k: u32| b.corners(k).map(|v| rot * v + t);
        let mut brute = Vec::new();
        for i in 0..a.triangles.len() as u32 {
            for j in 0..b.triangles.len() as u32 {
                if matches!(intersect(&a.corners(i), &tb(j)), TrianglePair::Segment(..)) {
                    brute.push((i, j));
                }
            }
        }
        let mut tree = Vec::new();
        let (mut stack, mut cache, mut work) =
            (Vec::new(), BoxCache::default(), WorkCounters::default());
        descend_pair(
            &a.tree,
            &b.tree,
            &rot,
            &t,
            &mut stack,
            &mut cache,
            &mut work,
            |i, j| {
                if matches!(intersect(&a.corners(i), &tb(j)), TrianglePair::Segment(..)) {
                    tree.push((i, j));
                }
            },
        );
        brute.sort_unstable();
        tree.sort_unstable();
        assert_eq!(tree, brute);
        total += brute.len();
        // The tree must prune: far fewer box tests than all pairs.
        assert!(work.bounding_volume_tests < (a.triangles.len() * b.triangles.len() / 4) as u64);
    }
    assert!(total > 50, "{total}");
}

/// Distance from `x` to the segment `a b`.
fn to_segment(x: &Vector3, a: &Vector3, b: &Vector3) -> f64 {
    let t = ((x - a).dot(&(b - a)) / (b - a).norm_squared()).clamp(0.0, 1.0);
    (a + (b - a) * t - x).norm()
}

#[test]
fn each_segment_end_lies_on_the_edge_or_corner_it_names() {
    use engine_facet::triangle_pair::{Feature, intersect_with_ends};
    let mut rng = Rng(0xE0D5);
    let mut crossings = 0;
    let mut on_each = [0; 2];
    for _ in 0..20000 {
        let (p, q) = (
            random_triangle(&mut rng, 1.0),
            random_triangle(&mut rng, 1.0),
        );
        let (pair, ends) = intersect_with_ends(&p, &q);
        let TrianglePair::Segment(s0, s1) = pair else {
            continue;
        };
        crossings += 1;
        for (point, end) in [(s0, ends[0]), (s1, ends[1])] {
            let t = if end.first { &p } else { &q };
            on_each[usize::from(!end.first)] += 1;
            let off = match end.feature {
                Feature::Edge(k) => to_segment(&point, &t[k as usize], &t[(k as usize + 1) % 3]),
                Feature::Corner(k) => (point - t[k as usize]).norm(),
            };
            assert!(off <= 1e-12, "{end:?} is {off:e} off: {p:?} {q:?}");
        }
    }
    // Ends on both triangles occur, or the test could not fail.
    assert!(
        crossings > 1000 && on_each[0] > 500 && on_each[1] > 500,
        "{crossings} {on_each:?}"
    );
}
