//! The box against a closed mesh and a mesh against a bounded plane: agreement with the
//! box–box and box–plane clipping where the mesh is a box, separate regions, holes in the
//! caps, containment, touching and grazing, and the invariants of [`crate::properties`].

use crate::characterization::mesh_box::{l_bar, tube};
use crate::common::{
    Expected, Rng, assert_close, boxes_mesh, errors, instance, nearest, one, query,
};
use crate::properties::{Maker, Scene, check_motion, check_scale, check_swap, scaled_pose};
use crate::voxel_oracle::{Aabb, Voxels};
use contact_core::geometry::{Cuboid, Plane, TriangleMesh};
use contact_core::{Contact, Geometry, GeometryInstance, Isometry3, Point3, Vector3};
use std::sync::Arc;

fn cuboid(h: Vector3) -> GeometryInstance {
    instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap()))
}

fn mesh_of(voxels: &Voxels) -> GeometryInstance {
    instance(Geometry::Mesh(Arc::new(voxels.mesh())))
}

fn box_mesh(centre: Point3, h: Vector3) -> GeometryInstance {
    instance(Geometry::Mesh(Arc::new(boxes_mesh(&[(centre, h)]))))
}

/// The box `b` against the cells: every region's contact against the closed form, matched by
/// the nearest box point.
fn check_against_cells(voxels: &Voxels, b: Aabb, regions: usize, world: &Isometry3, what: &str) {
    let expected: Vec<Expected> = voxels
        .contacts(&b)
        .into_iter()
        .map(|e| e.expect("a regular region"))
        .collect();
    assert_eq!(expected.len(), regions, "{what}: the closed form's regions");
    let c = b.centre();
    let found = query(
        &cuboid(b.half()),
        &mesh_of(voxels),
        &(world * Isometry3::translation(c.x, c.y, c.z)),
        world,
    );
    assert_eq!(found.len(), regions, "{what}: {found:?}");
    for e in &expected {
        let e = e.moved(world);
        let got = nearest(&found, &e.point_i);
        let err = errors(got, &e, 3.0);
        assert!(
            err.iter().all(|&x| x <= 1e-12),
            "{what}: {err:?}\n{got:?}\n{e:?}"
        );
    }
}

#[test]
fn a_box_mesh_gives_the_box_box_answer_at_any_pose() {
    let mut rng = Rng::new(71);
    let (ha, hb) = (Vector3::new(0.7, 0.4, 1.1), Vector3::new(0.9, 0.6, 0.5));
    let offset = Point3::new(0.2, -0.1, 0.3);
    let mut seen = 0;
    for _ in 0..400 {
        let pose_a = rng.pose(2.0);
        let pose_b = pose_a * rng.pose(1.8);
        let reference = query(
            &cuboid(ha),
            &instance(Geometry::Cuboid(
                Cuboid::centered(hb.x, hb.y, hb.z).unwrap(),
            )),
            &pose_a,
            &(pose_b * Isometry3::translation(offset.x, offset.y, offset.z)),
        );
        let got = query(&cuboid(ha), &box_mesh(offset, hb), &pose_a, &pose_b);
        assert_eq!(got.len(), reference.len(), "{got:?} / {reference:?}");
        for (g, r) in got.iter().zip(&reference) {
            assert_close(g, r, 2.0, 4.0, 1e-12, "box–box mesh");
            seen += 1;
        }
    }
    assert!(seen > 100, "only {seen} contacts");
}

#[test]
fn a_box_mesh_on_a_bounded_plane_gives_the_box_plane_answer() {
    let mut rng = Rng::new(72);
    let h = Vector3::new(0.7, 0.4, 1.1);
    let plane = Plane::bounded(-1.0, 0.5, -2.0, 0.8).unwrap();
    let mut seen = 0;
    for _ in 0..300 {
        let pose_plane = rng.pose(2.0);
        let pose_i = pose_plane * rng.pose(1.5);
        let reference = query(
            &cuboid(h),
            &instance(Geometry::Plane(plane)),
            &pose_i,
            &pose_plane,
        );
        let got = query(
            &box_mesh(Point3::origin(), h),
            &instance(Geometry::Plane(plane)),
            &pose_i,
            &pose_plane,
        );
        assert_eq!(got.len(), reference.len(), "{got:?} / {reference:?}");
        for (g, r) in got.iter().zip(&reference) {
            assert_close(g, r, 2.0, 4.0, 1e-12, "box mesh–bounded plane");
            seen += 1;
        }
    }
    assert!(seen > 100, "only {seen} contacts");
}

#[test]
fn a_slab_through_the_tubes_hole_meets_two_walls_as_two_regions() {
    let world = Rng::new(73).pose(3.0);
    let b = Aabb {
        lo: Point3::new(0.8, 1.2, 1.0),
        hi: Point3::new(2.2, 1.8, 3.0),
    };
    check_against_cells(&tube(1.0), b, 2, &world, "slab through the hole");
}

#[test]
fn a_cap_around_a_hole_is_one_region_with_the_outer_wall() {
    // The box's z faces lie in the tube's wall material around the hole; the hole's rim is
    // joined to the cap through the face's right edge.
    let world = Rng::new(74).pose(3.0);
    let b = Aabb {
        lo: Point3::new(-0.3, 0.5, 1.0),
        hi: Point3::new(2.5, 2.5, 3.0),
    };
    check_against_cells(&tube(1.0), b, 1, &world, "cap around the hole");
}

#[test]
fn a_box_across_both_arms_of_a_u_gives_one_contact_per_arm() {
    let mut cells = Vec::new();
    for i in 0..3 {
        cells.push([i, 0, 0]);
    }
    cells.push([0, 1, 0]);
    cells.push([2, 1, 0]);
    let u = Voxels { cells, size: 1.0 };
    let world = Rng::new(75).pose(3.0);
    let b = Aabb {
        lo: Point3::new(0.5, 1.3, 0.2),
        hi: Point3::new(2.5, 1.8, 0.7),
    };
    check_against_cells(&u, b, 2, &world, "both arms");
}

#[test]
fn a_box_in_the_tubes_hole_touches_nothing() {
    let found = query(
        &cuboid(Vector3::new(0.4, 0.4, 3.0)),
        &mesh_of(&tube(1.0)),
        &Isometry3::translation(1.5, 1.5, 2.0),
        &Isometry3::identity(),
    );
    assert!(found.is_empty(), "{found:?}");
}

#[test]
fn a_mesh_inside_the_box_pushes_out_through_the_nearest_face() {
    // The tube (centroid (1.5, 1.5, 2), in its hole) inside a box whose −y face is nearest.
    let lo = Point3::new(-1.0, -0.5, -2.0);
    let hi = Point3::new(4.0, 3.6, 6.0);
    let b = Aabb { lo, hi };
    let world = Rng::new(76).pose(2.0);
    let c = b.centre();
    let got = one(
        &cuboid(b.half()),
        &mesh_of(&tube(1.0)),
        &(world * Isometry3::translation(c.x, c.y, c.z)),
        &world,
    );
    let expected = Expected {
        // Leaving the box along −n = −y, and meeting the hole's wall y = 2 along +y.
        point_i: Point3::new(1.5, -0.5, 2.0),
        point_j: Point3::new(1.5, 2.0, 2.0),
        normal: Vector3::y(),
        depth: 2.5,
    }
    .moved(&world);
    let err = errors(&got, &expected, 4.0);
    assert!(err.iter().all(|&x| x <= 1e-12), "{err:?} {got:?}");
    // A quarter of the tube's surface: outer walls 48, inner 16, ends 16.
    assert!((got.area - 20.0).abs() <= 1e-12 * 20.0, "{}", got.area);
}

#[test]
fn a_box_inside_the_mesh_pushes_out_towards_the_closest_face() {
    let world = Rng::new(77).pose(2.0);
    let big = Vector3::new(3.0, 2.0, 4.0);
    let h = Vector3::new(0.5, 0.3, 0.4);
    // Centre 1.2 below the big box's +y face, farther from the others.
    let at = Point3::new(0.4, 0.8, -0.5);
    let got = one(
        &cuboid(h),
        &box_mesh(Point3::origin(), big),
        &(world * Isometry3::translation(at.x, at.y, at.z)),
        &world,
    );
    let expected = Expected {
        point_i: Point3::new(at.x, at.y - h.y, at.z),
        point_j: Point3::new(at.x, big.y, at.z),
        normal: Vector3::y(),
        depth: big.y - at.y + h.y,
    }
    .moved(&world);
    let err = errors(&got, &expected, 4.0);
    assert!(err.iter().all(|&x| x <= 1e-12), "{err:?} {got:?}");
}

#[test]
fn touching_is_no_contact_and_grazing_is_resolved() {
    let h = Vector3::new(0.5, 0.5, 0.5);
    let mesh = box_mesh(Point3::origin(), Vector3::new(1.0, 1.0, 1.0));
    // Flush on the top face, an edge on an edge, a corner on a corner: exactly touching.
    for at in [(0.2, 0.1, 1.5), (1.5, 0.0, 1.5), (1.5, 1.5, 1.5)] {
        let pose = Isometry3::translation(at.0, at.1, at.2);
        let found = query(&cuboid(h), &mesh, &pose, &Isometry3::identity());
        assert!(found.is_empty(), "{found:?}");
    }
    for depth in [1e-3, 1e-6, 1e-9] {
        let pose = Isometry3::translation(0.2, 0.1, 1.5 - depth);
        let got = one(&cuboid(h), &mesh, &pose, &Isometry3::identity());
        let rel = (got.penetration - depth).abs() / depth;
        assert!(rel <= 1e-6, "{depth:e}: {got:?}");
        assert!((got.normal_w - Vector3::z()).norm() <= 1e-12, "{got:?}");
        assert!((got.area - 1.0).abs() <= 1e-12, "{got:?}");
    }
}

#[test]
fn a_u_on_a_bounded_plane_stands_on_the_feet_the_rectangle_holds() {
    // A U upside down: two feet (x cells 0 and 2) under a bridge.
    let cells = vec![[0, 0, 0], [2, 0, 0], [0, 0, 1], [1, 0, 1], [2, 0, 1]];
    let u = Voxels { cells, size: 1.0 };
    let sunk = 0.3;
    for (x1, feet) in [(3.5, 2), (1.5, 1)] {
        let plane = Plane::bounded(-0.5, x1, -0.5, 1.5).unwrap();
        let found = query(
            &mesh_of(&u),
            &instance(Geometry::Plane(plane)),
            &Isometry3::translation(0.0, 0.0, -sunk),
            &Isometry3::identity(),
        );
        assert_eq!(found.len(), feet, "{found:?}");
        for c in &found {
            assert!((c.penetration - sunk).abs() <= 1e-12, "{c:?}");
            assert!((c.normal_w - Vector3::z()).norm() <= 1e-12, "{c:?}");
            assert!((c.area - 1.0).abs() <= 1e-12, "{c:?}");
        }
    }
}

fn box_mesh_scene(rng: &mut Rng, s: f64) -> Scene {
    let pose_j = rng.pose(3.0);
    let pose_i = pose_j
        * Isometry3::from_parts(
            nalgebra::Translation3::new(
                rng.uniform(0.0, 5.0),
                rng.uniform(0.0, 1.0),
                rng.uniform(0.0, 2.0),
            ),
            rng.rotation(),
        );
    let h = Vector3::new(
        rng.uniform(0.2, 1.0),
        rng.uniform(0.2, 1.0),
        rng.uniform(0.2, 1.0),
    );
    Scene {
        i: cuboid(h * s),
        j: mesh_of(&l_bar(s)),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: 5.0 * s,
    }
}

fn mesh_bounded_plane_scene(rng: &mut Rng, s: f64) -> Scene {
    let plane_pose = rng.pose(3.0);
    let pose_i = plane_pose
        * Isometry3::from_parts(
            nalgebra::Translation3::new(
                rng.uniform(-1.0, 1.0),
                rng.uniform(-1.0, 1.0),
                rng.uniform(0.3, 1.5),
            ),
            rng.rotation(),
        )
        * Isometry3::translation(-1.0, -1.0, -1.0);
    let plane = Plane::bounded(-s, 1.5 * s, -2.0 * s, 0.5 * s).unwrap();
    Scene {
        i: mesh_of(&l_bar(s)),
        j: instance(Geometry::Plane(plane)),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&plane_pose, s),
        length: 5.0 * s,
    }
}

const MAKERS: [(&str, Maker); 2] = [
    ("box–mesh", box_mesh_scene),
    ("mesh–bounded plane", mesh_bounded_plane_scene),
];

#[test]
fn box_mesh_pairs_swap_move_and_scale_with_the_scene() {
    check_swap(&MAKERS, 81);
    check_motion(&MAKERS, 82);
    check_scale(&MAKERS, 83);
}

/// A prism `z ∈ [0, height]` over a polygon given by its loops (counter-clockwise outer,
/// clockwise holes) and a triangulation of its face (counter-clockwise), as a closed mesh
/// with as few triangles as that allows.
fn prism(loops: &[Vec<[f64; 2]>], face: &[[usize; 3]], height: f64) -> TriangleMesh {
    let flat: Vec<[f64; 2]> = loops.iter().flatten().copied().collect();
    let n = flat.len() as u32;
    let mut vertices: Vec<Point3> = flat.iter().map(|p| Point3::new(p[0], p[1], 0.0)).collect();
    vertices.extend(flat.iter().map(|p| Point3::new(p[0], p[1], height)));
    let mut triangles = Vec::new();
    for t in face {
        let [a, b, c] = t.map(|k| k as u32);
        triangles.push([a + n, b + n, c + n]);
        triangles.push([a, c, b]);
    }
    let mut start = 0u32;
    for l in loops {
        let m = l.len() as u32;
        for k in 0..m {
            let (a, b) = (start + k, start + (k + 1) % m);
            triangles.push([a, b, b + n]);
            triangles.push([a, b + n, a + n]);
        }
        start += m;
    }
    TriangleMesh::new(vertices, triangles).unwrap()
}

/// [`l_bar`] with as few triangles as its faces allow.
fn l_bar_coarse() -> TriangleMesh {
    let outer = vec![
        [0.0, 0.0],
        [5.0, 0.0],
        [5.0, 1.0],
        [1.0, 1.0],
        [1.0, 3.0],
        [0.0, 3.0],
    ];
    prism(&[outer], &[[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5]], 2.0)
}

/// [`tube`] with as few triangles as its faces allow.
fn tube_coarse() -> TriangleMesh {
    let outer = vec![[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [0.0, 3.0]];
    let inner = vec![[1.0, 1.0], [1.0, 2.0], [2.0, 2.0], [2.0, 1.0]];
    // Outer o_k = k, inner i_k at (1,1), (2,1), (2,2), (1,2) = 4, 7, 6, 5.
    let i = [4, 7, 6, 5];
    let mut face = Vec::new();
    for k in 0..4 {
        let (o0, o1) = (k, (k + 1) % 4);
        face.push([o0, o1, i[(k + 1) % 4]]);
        face.push([o0, i[(k + 1) % 4], i[k]]);
    }
    prism(&[outer, inner], &face, 4.0)
}

fn by_point(mut v: Vec<Contact>) -> Vec<Contact> {
    v.sort_by(|a, b| a.point_i_w.x.total_cmp(&b.point_i_w.x));
    v
}

#[test]
fn one_solid_meshed_two_ways_gives_one_answer_at_any_pose() {
    // The grid meshes weld every cell corner; the coarse ones have long triangles whose
    // edges pierce the box elsewhere: the same solid, other clipping, piercings and cuts.
    let mut rng = Rng::new(78);
    for (fine, coarse, centre, reach) in [
        (
            l_bar(1.0).mesh(),
            l_bar_coarse(),
            Point3::new(2.0, 1.0, 1.0),
            2.5,
        ),
        (
            tube(1.0).mesh(),
            tube_coarse(),
            Point3::new(1.5, 1.5, 2.0),
            2.5,
        ),
    ] {
        let (fine, coarse) = (
            instance(Geometry::Mesh(Arc::new(fine))),
            instance(Geometry::Mesh(Arc::new(coarse))),
        );
        let mut seen = 0;
        for _ in 0..300 {
            let world = rng.pose(3.0);
            let h = Vector3::new(
                rng.uniform(0.2, 2.0),
                rng.uniform(0.2, 2.0),
                rng.uniform(0.2, 2.0),
            );
            let at = Isometry3::from_parts(
                nalgebra::Translation3::from(
                    centre.coords + rng.unit_vector() * rng.uniform(0.0, reach),
                ),
                rng.rotation(),
            );
            let a = by_point(query(&cuboid(h), &fine, &(world * at), &world));
            let b = by_point(query(&cuboid(h), &coarse, &(world * at), &world));
            assert_eq!(a.len(), b.len(), "{a:?}\n{b:?}");
            for (x, y) in a.iter().zip(&b) {
                assert_close(x, y, 4.0, 16.0, 1e-12, "two meshings");
                seen += 1;
            }
        }
        assert!(seen > 150, "only {seen} contacts");
    }
}

/// A box of half extents `h` at `at` in the box-shaped cavity of half extents `w` at the
/// origin: the closed form when every overlap is axis-aligned (the part of the box outside
/// the cavity is the box less one aligned box, its walls' pieces inside the box rectangles).
fn in_cavity_expected(h: Vector3, at: Point3, w: Vector3) -> Expected {
    let (lo, hi) = (at - h, at + h);
    let inner_lo = Point3::new(lo.x.max(-w.x), lo.y.max(-w.y), lo.z.max(-w.z));
    let inner_hi = Point3::new(hi.x.min(w.x), hi.y.min(w.y), hi.z.min(w.z));
    let inner = (inner_hi - inner_lo).map(|d| d.max(0.0));
    let (v_box, v_in) = ((2.0 * h).product(), inner.product());
    let centre_in = nalgebra::center(&inner_lo, &inner_hi);
    let centroid = Point3::from((v_box * at.coords - v_in * centre_in.coords) / (v_box - v_in));
    // The cavity's walls inside the box, normals into the cavity.
    let mut s = Vector3::zeros();
    for k in 0..3 {
        let (u, v) = ((k + 1) % 3, (k + 2) % 3);
        let face = inner[u] * inner[v];
        if lo[k] < w[k] && w[k] < hi[k] {
            s[k] -= face;
        }
        if lo[k] < -w[k] && -w[k] < hi[k] {
            s[k] += face;
        }
    }
    let n = s.normalize();
    // Leaving the box along −n, and reaching a wall plane along +n inside its rectangle.
    let to_box = (0..3)
        .filter(|&k| n[k] != 0.0)
        .map(|k| {
            let bound = if n[k] > 0.0 { lo[k] } else { hi[k] };
            (centroid[k] - bound) / n[k]
        })
        .fold(f64::INFINITY, f64::min);
    let mut to_wall = f64::INFINITY;
    for k in 0..3 {
        for side in [1.0, -1.0] {
            if n[k] == 0.0 {
                continue;
            }
            let t = (side * w[k] - centroid[k]) / n[k];
            let p = centroid + t * n;
            let on = (0..3).all(|m| m == k || p[m].abs() <= w[m]);
            if t >= 0.0 && on {
                to_wall = to_wall.min(t);
            }
        }
    }
    let (point_i, point_j) = (centroid - to_box * n, centroid + to_wall * n);
    Expected {
        point_i,
        point_j,
        normal: n,
        depth: (point_j - point_i).norm(),
    }
}

fn flipped(g: GeometryInstance) -> GeometryInstance {
    g.flipped()
}

#[test]
fn a_box_in_a_box_cavity_meets_the_walls_it_crosses() {
    let w = Vector3::new(2.0, 1.5, 1.0);
    let cavity = || flipped(cuboid(w));
    let h = Vector3::new(0.5, 0.4, 0.3);
    let world = Rng::new(79).pose(3.0);
    // Through one wall, through an edge (two walls), through a corner (three).
    for at in [
        Point3::new(1.8, 0.2, -0.1),
        Point3::new(1.8, 1.3, -0.1),
        Point3::new(-1.7, 1.3, 0.9),
    ] {
        let pose = world * Isometry3::translation(at.x, at.y, at.z);
        let got = one(&cuboid(h), &cavity(), &pose, &world);
        let e = in_cavity_expected(h, at, w).moved(&world);
        let err = errors(&got, &e, 2.0);
        assert!(
            err.iter().all(|&x| x <= 1e-12),
            "{at}: {err:?}\n{got:?}\n{e:?}"
        );
        // The same with the cavity as I.
        let back = one(&cavity(), &cuboid(h), &world, &pose);
        assert_close(&back.swapped(), &got, 2.0, 4.0, 1e-12, "cavity as I");
    }
    // Wholly inside: no contact. Wholly outside: the whole box, pushed back towards the
    // nearest wall point (the +x wall, 1.0 away from the centre at x = 3).
    let inside = query(
        &cuboid(h),
        &cavity(),
        &(world * Isometry3::translation(0.3, -0.2, 0.1)),
        &world,
    );
    assert!(inside.is_empty(), "{inside:?}");
    let out = one(
        &cuboid(h),
        &cavity(),
        &(world * Isometry3::translation(3.0, 0.2, 0.1)),
        &world,
    );
    assert!(
        (out.normal_w - world.rotation * -Vector3::x()).norm() <= 1e-12,
        "{out:?}"
    );
    assert!((out.penetration - 1.5).abs() <= 1e-12, "{out:?}");
    let surface = 8.0 * (h.x * h.y + h.y * h.z + h.z * h.x);
    assert!((out.area - 0.25 * surface).abs() <= 1e-12, "{out:?}");
}

#[test]
fn a_flipped_mesh_is_a_cavity_whatever_its_meshing() {
    let mut rng = Rng::new(80);
    let w = Vector3::new(1.5, 1.5, 2.0);
    let centre = Point3::new(1.5, 1.5, 2.0);
    let walls_fine = flipped(box_mesh(centre, w));
    let walls_coarse = flipped(instance(Geometry::Cuboid(
        Cuboid::from_corner(3.0, 3.0, 4.0).unwrap(),
    )));
    let tube_fine = flipped(mesh_of(&tube(1.0)));
    let tube_coarse = flipped(instance(Geometry::Mesh(Arc::new(tube_coarse()))));
    let mut seen = 0;
    for _ in 0..300 {
        let world = rng.pose(3.0);
        let h = Vector3::new(
            rng.uniform(0.2, 1.0),
            rng.uniform(0.2, 1.0),
            rng.uniform(0.2, 1.0),
        );
        let at = Isometry3::from_parts(
            nalgebra::Translation3::from(centre.coords + rng.unit_vector() * rng.uniform(0.0, 2.5)),
            rng.rotation(),
        );
        for (a, b) in [(&walls_fine, &walls_coarse), (&tube_fine, &tube_coarse)] {
            let x = by_point(query(&cuboid(h), a, &(world * at), &world));
            let y = by_point(query(&cuboid(h), b, &(world * at), &world));
            assert_eq!(x.len(), y.len(), "{x:?}\n{y:?}");
            for (p, q) in x.iter().zip(&y) {
                assert_close(p, q, 4.0, 16.0, 1e-12, "two meshings of a cavity");
                seen += 1;
            }
        }
    }
    assert!(seen > 200, "only {seen} contacts");
}

fn box_in_cavity_scene(rng: &mut Rng, s: f64) -> Scene {
    let pose_j = rng.pose(3.0);
    let pose_i = pose_j * rng.pose(1.6);
    let h = Vector3::new(
        rng.uniform(0.2, 0.8),
        rng.uniform(0.2, 0.8),
        rng.uniform(0.2, 0.8),
    );
    Scene {
        i: cuboid(h * s),
        j: flipped(cuboid(Vector3::new(1.5, 1.2, 1.0) * s)),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: 3.0 * s,
    }
}

#[test]
fn a_box_in_a_cavity_swaps_moves_and_scales_with_the_scene() {
    let makers: [(&str, Maker); 1] = [("box–box cavity", box_in_cavity_scene)];
    check_swap(&makers, 84);
    check_motion(&makers, 85);
    check_scale(&makers, 86);
}
