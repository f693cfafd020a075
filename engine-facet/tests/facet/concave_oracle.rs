//! Mesh against a non-convex mesh, as given, against an oracle written apart from the engine:
//! the L-shaped prism `B = B₁ ∪ B₂` (two boxes meeting along a face) is the union of convex
//! pieces, so `A ∩ B` for a convex `A` is the sum of the convex clips `A ∩ B₁` and `A ∩ B₂`
//! (their volumes, moments, and the vector area of A's faces inside each). A box `A` pressed
//! into the L's concave edge crosses both arms: one region where its interior meets the square
//! where the arms meet, else two (it passes the concave edge on its outer side and meets each
//! arm apart, each region its arm's clip). The faceted engine's contact (its normal, the
//! line through its centroid, and the depth along that line between the two surfaces) must be
//! the polyhedral intersection's to round-off — no approximation where B is concave, and the
//! same for either triangulation of the L's faces.

use crate::common::{Rng, engine, prepare, prism, query_pair};
use contact_core::geometry::{Cuboid, TriangleMesh};
use contact_core::{Geometry, Isometry3, Point3, UnitQuaternion, Vector3};

/// The L's profile in (x, z), counter-clockwise, extruded over 0 ≤ y ≤ 1: the arm
/// `B₁ = [0, 2]×[0, 1]×[0, 1]` and the arm `B₂ = [0, 1]×[0, 1]×[1, 2]`.
const PROFILE: [(f64, f64); 6] = [
    (0.0, 0.0),
    (2.0, 0.0),
    (2.0, 1.0),
    (1.0, 1.0),
    (1.0, 2.0),
    (0.0, 2.0),
];

/// The L prism, its caps and side quads split one way or the other.
fn l_prism(other_split: bool) -> Geometry {
    let caps = if other_split {
        [[1, 2, 3], [1, 3, 0], [0, 3, 4], [0, 4, 5]]
    } else {
        [[0, 1, 2], [0, 2, 3], [0, 3, 5], [3, 4, 5]]
    };
    prism(&PROFILE, &caps, 1.0, other_split)
}

/// A convex polygon clipped to `n·x ≤ d`.
fn clip(poly: &[Vector3], n: &Vector3, d: f64) -> Vec<Vector3> {
    let mut out = Vec::new();
    for k in 0..poly.len() {
        let (u, v) = (poly[k], poly[(k + 1) % poly.len()]);
        let (du, dv) = (n.dot(&u) - d, n.dot(&v) - d);
        if du <= 0.0 {
            out.push(u);
        }
        if du * dv < 0.0 {
            out.push(u + (v - u) * (du / (du - dv)));
        }
    }
    out
}

/// The half-spaces `n·x ≤ d` of an axis-aligned box.
fn box_planes(lo: Vector3, hi: Vector3) -> Vec<(Vector3, f64)> {
    (0..3)
        .flat_map(|k| {
            let e = Vector3::ith(k, 1.0);
            [(e, hi[k]), (-e, -lo[k])]
        })
        .collect()
}

/// Volume, first moment about the origin, and the vector area of A's faces, of A (its faces,
/// counter-clockwise outward) clipped to a convex set of half-spaces.
fn clipped(faces: &[Vec<Vector3>], planes: &[(Vector3, f64)]) -> (f64, Vector3, Vector3) {
    let mut faces: Vec<Vec<Vector3>> = faces.to_vec();
    let mut a_area = Vector3::zeros();
    for f in &faces {
        let mut p = f.clone();
        for (n, d) in planes {
            p = clip(&p, n, *d);
        }
        a_area += polygon_area(&p);
    }
    for (n, d) in planes {
        let mut cut: Vec<Vector3> = Vec::new();
        faces = faces
            .iter()
            .map(|f| {
                let c = clip(f, n, *d);
                cut.extend(c.iter().filter(|p| (n.dot(p) - d).abs() < 1e-12));
                c
            })
            .filter(|f| f.len() >= 3)
            .collect();
        if cut.len() >= 3 {
            // The cap on the plane, ordered counter-clockwise about n.
            let centre = cut.iter().sum::<Vector3>() / cut.len() as f64;
            let u = (cut[0] - centre).normalize();
            let w = n.cross(&u);
            cut.sort_by(|a, b| {
                let angle = |p: &Vector3| (p - centre).dot(&w).atan2((p - centre).dot(&u));
                angle(a).total_cmp(&angle(b))
            });
            faces.push(cut);
        }
    }
    let (mut volume, mut moment) = (0.0, Vector3::zeros());
    for f in &faces {
        for k in 1..f.len() - 1 {
            let v = f[0].dot(&f[k].cross(&f[k + 1])) / 6.0;
            volume += v;
            moment += v * (f[0] + f[k] + f[k + 1]) / 4.0;
        }
    }
    (volume, moment, a_area)
}

fn polygon_area(p: &[Vector3]) -> Vector3 {
    (1..p.len().saturating_sub(1))
        .map(|k| 0.5 * (p[k] - p[0]).cross(&(p[k + 1] - p[0])))
        .sum()
}

/// The parameters `[t0, t1]` of the line `g + t·n` inside a convex set of half-spaces.
fn slab(g: &Vector3, n: &Vector3, planes: &[(Vector3, f64)]) -> (f64, f64) {
    let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
    for (m, d) in planes {
        let (along, at) = (m.dot(n), d - m.dot(g));
        if along > 0.0 {
            t1 = t1.min(at / along);
        } else if along < 0.0 {
            t0 = t0.max(at / along);
        }
    }
    (t0, t1)
}

#[test]
fn a_box_in_the_concave_edge_of_an_l_is_the_polyhedral_intersection() {
    for other_split in [false, true] {
        checked_poses(other_split);
    }
}

/// The engine against the oracle at seeded poses of the box in the L's concave edge.
fn checked_poses(other_split: bool) {
    let (arm1, arm2) = (
        box_planes(Vector3::zeros(), Vector3::new(2.0, 1.0, 1.0)),
        box_planes(Vector3::new(0.0, 0.0, 1.0), Vector3::new(1.0, 1.0, 2.0)),
    );
    let half = Vector3::new(0.3, 0.2, 0.25);
    let cuboid = Geometry::Cuboid(Cuboid::centered(half.x, half.y, half.z).unwrap());
    let pair = prepare(&engine(300.0028), cuboid, l_prism(other_split));
    let mut rng = Rng(0x1A7E);
    let (mut checked, mut separate) = (0, 0);
    for k in 0..20 {
        let rotation = UnitQuaternion::from_scaled_axis(rng.unit_vector() * rng.range(0.05, 0.5));
        let centre = Vector3::new(
            rng.range(1.15, 1.3),
            rng.range(0.4, 0.6),
            rng.range(1.15, 1.3),
        );
        let pose = Isometry3::from_parts(centre.into(), rotation);
        // A's faces in the world, counter-clockwise outward, and its half-spaces.
        let corner = |s: [f64; 3]| pose * Point3::from(half.component_mul(&Vector3::from(s)));
        let mut faces = Vec::new();
        let mut a_planes = Vec::new();
        for axis in 0..3 {
            for sign in [-1.0, 1.0] {
                let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
                let quad: Vec<Vector3> = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
                    .iter()
                    .map(|&(a, b)| {
                        let mut s = [0.0; 3];
                        s[axis] = sign;
                        s[u] = a * sign;
                        s[v] = b;
                        corner(s).coords
                    })
                    .collect();
                let n = pose.rotation * Vector3::ith(axis, sign);
                a_planes.push((n, n.dot(&quad[0])));
                faces.push(quad);
            }
        }
        let (v1, m1, s1) = clipped(&faces, &arm1);
        let (v2, m2, s2) = clipped(&faces, &arm2);
        if !arms_joined(&a_planes) {
            check_separate_arms(pair.as_ref(), &pose, [(v1, m1, s1), (v2, m2, s2)], k);
            separate += 1;
            continue;
        }
        let g = (m1 + m2) / (v1 + v2);
        let normal = -(s1 + s2).normalize();
        // The centroid inside both bodies (else the engine holds the depth to its bound).
        let inside = |planes: &[(Vector3, f64)]| planes.iter().all(|(n, d)| n.dot(&g) < *d);
        if !(inside(&a_planes) && (inside(&arm1) || inside(&arm2))) {
            continue;
        }
        // I's point: where the line leaves A going along −n; J's: where it leaves B₁ ∪ B₂
        // going along +n (the two arms' intervals joined where they meet).
        let t_i = -slab(&g, &normal, &a_planes).0;
        let (r1, r2) = (slab(&g, &normal, &arm1), slab(&g, &normal, &arm2));
        let mut t_j = f64::NEG_INFINITY;
        for (lo, hi) in [r1, r2, r1, r2] {
            if lo <= t_j.max(0.0) + 1e-12 && hi > t_j {
                t_j = hi;
            }
        }
        let want_depth = t_i + t_j;
        let (contacts, _) = query_pair(pair.as_ref(), pose, Isometry3::identity());

        assert_eq!(contacts.len(), 1, "pose {k}: {contacts:?}");
        let c = &contacts[0];
        let off_line = (g - c.point_i_w.coords).cross(&c.normal_w).norm();
        let errors = [
            (c.normal_w - normal).norm(),
            off_line,
            (c.penetration - want_depth).abs(),
        ];
        assert!(
            errors.iter().all(|e| *e <= 1e-9),
            "pose {k} (other split: {other_split}): errors (normal, centroid off the line, depth) {errors:?}\n{c:?}\ncentroid {g}, depth {want_depth}"
        );
        checked += 1;
    }
    assert!(
        checked >= 5 && checked + separate >= 10,
        "{checked} poses joined, {separate} apart"
    );
}

/// Whether the box (its half-spaces) joins the two arms: the arms' clips are convex, so
/// their union has a connected interior exactly when the box's interior meets the square
/// `z = 1, 0 ≤ x, y ≤ 1` where the arms meet (else the box passes the concave edge on its
/// outer side and meets each arm apart).
fn arms_joined(a_planes: &[(Vector3, f64)]) -> bool {
    let mut square = vec![
        Vector3::new(0.0, 0.0, 1.0),
        Vector3::new(1.0, 0.0, 1.0),
        Vector3::new(1.0, 1.0, 1.0),
        Vector3::new(0.0, 1.0, 1.0),
    ];
    for (n, d) in a_planes {
        square = clip(&square, n, *d);
    }
    polygon_area(&square).norm() > 1e-12
}

/// Two regions, one per arm: each contact's normal, its area `|S|` and the line through its
/// arm's centroid, against that arm's clip `(volume, moment, S)`.
fn check_separate_arms(
    pair: &dyn contact_core::PreparedPair,
    pose: &Isometry3,
    arms: [(f64, Vector3, Vector3); 2],
    k: usize,
) {
    let (contacts, _) = query_pair(pair, *pose, Isometry3::identity());
    let present: Vec<_> = arms.iter().filter(|a| a.0 > 1e-12).collect();
    assert_eq!(contacts.len(), present.len(), "pose {k}: {contacts:?}");
    for (v, m, s) in present {
        let normal = -s.normalize();
        let c = contacts
            .iter()
            .min_by(|a, b| {
                let d = |c: &&contact_core::Contact| (c.normal_w - normal).norm();
                d(a).total_cmp(&d(b))
            })
            .unwrap();
        let g = m / *v;
        let errors = [
            (c.normal_w - normal).norm(),
            (g - c.point_i_w.coords).cross(&c.normal_w).norm(),
            (c.area - s.norm()).abs(),
        ];
        assert!(
            errors.iter().all(|e| *e <= 1e-9),
            "pose {k}, separate arms: errors (normal, off the line, area) {errors:?}\n{c:?}"
        );
    }
}

/// The octahedron `|x| + |y| + |z| ≤ 1` as a closed mesh.
fn octahedron() -> Geometry {
    let v = |x: f64, y: f64, z: f64| Point3::new(x, y, z);
    let vertices = vec![
        v(1.0, 0.0, 0.0),
        v(-1.0, 0.0, 0.0),
        v(0.0, 1.0, 0.0),
        v(0.0, -1.0, 0.0),
        v(0.0, 0.0, 1.0),
        v(0.0, 0.0, -1.0),
    ];
    let triangles = vec![
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    Geometry::Mesh(std::sync::Arc::new(
        TriangleMesh::new(vertices, triangles).unwrap(),
    ))
}

/// Vertices and edges exactly on a face's plane: a box whose bottom face holds the
/// octahedron's four equatorial vertices (and its equator's edges) cuts it in half. Closed
/// form: one region, the upper half (volume 2/3, centroid (0, 0, 1/4)), I's surface inside J
/// the square `|x| + |y| ≤ 1` facing down, so the normal is `+z`, and the line through the
/// centroid leaves the box at z = 0 and the octahedron at its apex: depth 1, area 2. The box
/// turned about z and the pair moved and turned as a whole.
#[test]
fn vertices_on_a_face_plane_cut_exactly() {
    let box_geometry = Geometry::Cuboid(Cuboid::centered(2.0, 2.0, 1.0).unwrap());
    let pair = prepare(&engine(300.0028), box_geometry, octahedron());
    let mut rng = Rng(0x0C7A);
    for k in 0..12 {
        let world = Isometry3::from_parts(
            (rng.unit_vector() * rng.range(0.0, 3.0)).into(),
            rng.rotation(),
        );
        let spin = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.range(-3.2, 3.2));
        let pose_i = world * Isometry3::from_parts(Vector3::new(0.0, 0.0, 1.0).into(), spin);
        let (contacts, _) = query_pair(pair.as_ref(), pose_i, world);
        assert_eq!(contacts.len(), 1, "pose {k}: {contacts:?}");
        let c = &contacts[0];
        let up = world.rotation * Vector3::z();
        let (bottom, apex) = (world * Point3::origin(), world * Point3::new(0.0, 0.0, 1.0));
        let errors = [
            (c.normal_w - up).norm(),
            (c.penetration - 1.0).abs(),
            (c.point_i_w - bottom).norm(),
            (c.point_j_w - apex).norm(),
            (c.area - 2.0).abs(),
        ];
        assert!(
            errors.iter().all(|e| *e <= 1e-9),
            "pose {k}: {errors:?}\n{c:?}"
        );
    }
}

/// A box whose faces take the planes of the tube's cell boundaries (z = 1 and 3 pass through
/// its wall vertices and edges), around the hole: the region is the box's part of the tube,
/// `[0, 2.5]×[0.5, 2.5]×[1, 3]` less the hole, volume 8 and centroid (1.1875, 1.5, 2) (in the
/// hole); I's surface inside J is its face x = 2.5 (the y and z faces cancel), so the normal
/// is `−x`; the line through the centroid leaves the box at x = 2.5 and first meets the tube
/// at the hole's wall x = 1: depth 1.5.
#[test]
fn a_box_on_the_cell_planes_of_a_tube() {
    let tube = crate::voxels::tube();
    let half = Vector3::new(1.4, 1.0, 1.0);
    let box_geometry = Geometry::Cuboid(Cuboid::centered(half.x, half.y, half.z).unwrap());
    let pair = prepare(&engine(300.0028), box_geometry, tube);
    let centre = Vector3::new(-0.3 + half.x, 0.5 + half.y, 1.0 + half.z);
    let mut rng = Rng(0x7B0E);
    for k in 0..40 {
        let world = Isometry3::from_parts(
            (rng.unit_vector() * rng.range(0.0, 3.0)).into(),
            rng.rotation(),
        );
        let pose_i = world * Isometry3::translation(centre.x, centre.y, centre.z);
        let (contacts, _) = query_pair(pair.as_ref(), pose_i, world);
        assert_eq!(contacts.len(), 1, "pose {k}: {contacts:?}");
        let c = &contacts[0];
        let normal = -(world.rotation * Vector3::x());
        let g = world * Point3::new(1.1875, 1.5, 2.0);
        let off_line = (g - c.point_i_w).cross(&c.normal_w).norm();
        let errors = [
            (c.normal_w - normal).norm(),
            off_line,
            (c.penetration - 1.5).abs(),
        ];
        assert!(
            errors.iter().all(|e| *e <= 1e-9),
            "pose {k}: {errors:?}\n{c:?}"
        );
    }
}
