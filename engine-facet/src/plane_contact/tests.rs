//! The convex path against the general one, and the convexity it relies on.

use super::mesh_plane;
use crate::contact_region::LocalContact;
use crate::facet_mesh::FacetMesh;
use crate::scratch::Scratch;
use crate::tessellate::{Tessellation, flat_corner_normals, tessellate};
use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid, Frustum, Plane, Torus};
use contact_core::{
    FacetingTolerance, Geometry, Isometry3, Point3, UnitQuaternion, Vector3, WorkCounters,
};

fn mesh(geometry: Geometry, ft: f64) -> FacetMesh {
    let t = tessellate(&geometry, FacetingTolerance::new(ft).unwrap()).unwrap();
    FacetMesh::build(t, true)
}

fn convex_solids() -> Vec<(&'static str, FacetMesh)> {
    let mut solids = Vec::new();
    for ft in [300.0028, 3000.0] {
        solids.push((
            "box",
            mesh(
                Geometry::Cuboid(Cuboid::from_corner(0.4, 0.3, 0.2).unwrap()),
                ft,
            ),
        ));
        solids.push((
            "cylinder",
            mesh(Geometry::Cylinder(Cylinder::new(0.1, 0.02).unwrap()), ft),
        ));
        solids.push((
            "frustum",
            mesh(Geometry::Frustum(Frustum::new(0.2, 0.05, 0.3).unwrap()), ft),
        ));
        solids.push((
            "ellipsoid",
            mesh(
                Geometry::Ellipsoid(Ellipsoid::new(0.3, 0.2, 0.1).unwrap()),
                ft,
            ),
        ));
    }
    solids
}

/// Mesh `m`'s contacts with the unbounded plane at `pose_a_plane` in its frame.
pub(crate) fn contacts(m: &FacetMesh, pose_a_plane: &Isometry3) -> Vec<LocalContact> {
    let mut out = Vec::new();
    let (mut s, mut work) = (Scratch::default(), WorkCounters::default());
    mesh_plane(
        m,
        &Plane::unbounded(),
        pose_a_plane,
        &mut s,
        &mut work,
        &mut out,
    );
    out
}

/// The plane's pose in the mesh frame: its normal `n` at generic tilt number `k`, its origin
/// `depth` above the mesh's lowest vertex along `n` (the plane's half-space is below it).
fn plane_pose(m: &FacetMesh, k: usize, depth: f64) -> Isometry3 {
    let t = k as f64;
    let axis = Vector3::new((0.37 * t).sin(), (0.71 * t).cos(), 0.5).normalize();
    let rotation = UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_normalize(axis), 2.1 * t);
    let n = rotation * Vector3::z();
    let lowest = m
        .vertices
        .iter()
        .map(|v| n.dot(&v.coords))
        .fold(f64::INFINITY, f64::min);
    Isometry3::from_parts((n * (lowest + depth)).into(), rotation)
}

/// The bits of what the convex path sums as the general one does: the normal, the area and
/// J's point (the centroid on the plane).
fn summed_bits(c: &LocalContact) -> Vec<u64> {
    let v = |x: &Vector3| [x.x, x.y, x.z];
    [v(&c.normal), v(&c.point_j)]
        .concat()
        .into_iter()
        .chain([c.area])
        .map(f64::to_bits)
        .collect()
}

/// From grazing (1e-9 of the size) through a vertex-deep touch to the whole body under the
/// plane (which the general path answers in all), at pose number `k` of 300.
fn depth_of_pose(k: usize, size: f64) -> f64 {
    match k % 6 {
        0 => 1e-9 * size,
        1 => 0.0,
        5 => 2.0 * size,
        _ => size * (k as f64 * 0.618).fract() * 0.5,
    }
}

#[test]
fn the_convex_path_sums_as_the_general_one_and_finds_the_same_exit() {
    let mut compared = 0;
    for (name, faces) in convex_solids() {
        assert!(faces.convex, "{name} is convex");
        let mut convex = faces.clone();
        convex.flat_faces = None;
        let mut general = convex.clone();
        general.convex = false;
        let size = convex.size;
        for k in 0..300 {
            let pose = plane_pose(&convex, k, depth_of_pose(k, size));
            let (fast, slow) = (contacts(&convex, &pose), contacts(&general, &pose));
            assert_eq!(fast.len(), slow.len(), "{name}, pose {k}");
            for (f, s) in fast.iter().zip(&slow) {
                assert_eq!(
                    summed_bits(f),
                    summed_bits(s),
                    "{name}, pose {k}: {f:?} against {s:?}"
                );
                // I's point: the convex solid's exit against the ray test, to round-off.
                let apart = (f.point_i - s.point_i).norm();
                let deeper = (f.penetration - s.penetration).abs();
                assert!(
                    apart <= 1e-13 * size && deeper <= 1e-13 * size,
                    "{name}, pose {k}: points {apart:e} apart, depths {deeper:e}: {f:?} against {s:?}"
                );
                compared += 1;
            }
        }
    }
    assert!(compared > 1500, "{compared} contacts compared");
}

/// The flat faces' path against the triangles' general one: the same sums in another order,
/// so the same contact to round-off: points and depth relative to the mesh's size, the area
/// relative to the size times the area's square root (a sliver's cross products).
#[test]
fn the_flat_faces_sum_as_their_triangles() {
    let (mut compared, mut worst) = (0, [0.0f64; 3]);
    for (name, faces) in convex_solids() {
        let mut general = faces.clone();
        general.convex = false;
        let size = faces.size;
        for k in 0..300 {
            let pose = plane_pose(&faces, k, depth_of_pose(k, size));
            let (fast, slow) = (contacts(&faces, &pose), contacts(&general, &pose));
            assert_eq!(fast.len(), slow.len(), "{name}, pose {k}");
            for (f, s) in fast.iter().zip(&slow) {
                assert_eq!(f.normal, s.normal, "{name}, pose {k}");
                let off = [
                    (f.point_j - s.point_j).norm() / size,
                    (f.point_i - s.point_i)
                        .norm()
                        .max((f.penetration - s.penetration).abs())
                        / size,
                    // The area sums cross products of points known to round-off of the size:
                    // its error scales with the size and the loop's extent, not the area.
                    (f.area - s.area).abs()
                        / (size * f.area.max(s.area).sqrt()).max(f64::MIN_POSITIVE),
                ];
                for (w, o) in worst.iter_mut().zip(off) {
                    *w = w.max(o);
                }
                assert!(
                    off[0] <= 1e-13 && off[1] <= 1e-12 && off[2] <= 1e-13,
                    "{name}, pose {k}: {off:?}: {f:?} against {s:?}"
                );
                compared += 1;
            }
        }
    }
    eprintln!("worst: J's point, I's point and depth, area: {worst:?}");
    assert!(compared > 1500, "{compared} contacts compared");
}

/// A unit box whose top face is four triangles meeting at its centre, raised to `apex_z`:
/// pushed in (below 1) it is closed and not convex, pulled out it is convex.
fn box_with_apex(apex_z: f64) -> FacetMesh {
    let mut vertices: Vec<Point3> = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.0, 1.0, 1.0],
    ]
    .into_iter()
    .map(|[x, y, z]| Point3::new(x, y, z))
    .collect();
    vertices.push(Point3::new(0.5, 0.5, apex_z));
    let triangles = vec![
        [0, 2, 1],
        [0, 3, 2],
        [0, 1, 5],
        [0, 5, 4],
        [1, 2, 6],
        [1, 6, 5],
        [2, 3, 7],
        [2, 7, 6],
        [3, 0, 4],
        [3, 4, 7],
        [4, 5, 8],
        [5, 6, 8],
        [6, 7, 8],
        [7, 4, 8],
    ];
    let corner_normals = flat_corner_normals(&vertices, &triangles);
    FacetMesh::build(
        Tessellation {
            vertices,
            triangles,
            corner_normals,
        },
        true,
    )
}

#[test]
fn convexity_is_known_from_the_edges() {
    for (name, m) in convex_solids() {
        assert!(m.convex, "{name}");
    }
    let torus = mesh(Geometry::Torus(Torus::new(1.0, 0.3).unwrap()), 300.0028);
    assert!(!torus.convex, "a torus");
    let dented = box_with_apex(0.8);
    assert!(dented.closed && dented.volume > 0.0);
    assert!(!dented.convex, "a dented box");
    assert!(box_with_apex(1.2).convex, "a bulged box");
    assert!(box_with_apex(1.0).convex, "a box with a flat fan on top");
    let open = FacetMesh::build(
        Tessellation {
            vertices: vec![
                Point3::origin(),
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
            ],
            triangles: vec![[0, 1, 2]],
            corner_normals: vec![[Vector3::z(); 3]],
        },
        false,
    );
    assert!(!open.convex, "an open triangle");
}
