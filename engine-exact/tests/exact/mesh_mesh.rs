//! Mesh against mesh: a box given as a mesh against grid-cell meshes, each region against the
//! cells' closed form ([`crate::voxel_oracle`], written apart from the engine) and against the
//! box–mesh pair with the box as a primitive (another method: clipping in the box's frame).
//! Boxes whose faces, edges and corners lie on the cells' planes make every degenerate
//! contact the triangle tests must resolve alike: faces coplanar with the other mesh's
//! triangle edges, vertices on faces, edges on edges, faces flush with the cells' faces (the
//! common patch counts as I's surface inside J, as the closed form and the box–mesh pair take
//! it), faces touching them (no volume, no contact), and two regions that touch only where
//! their faces meet at zero volume. Left out of the sweep, and open: a box whose faces are
//! flush along all three axes, or flush and touching at once; where such faces meet at a
//! vertex of the cells the engine's region can be short of a sliver (its centroid off by up
//! to 0.05 of the box in three of 1000 boxes).

use crate::characterization::mesh_box::{l_bar, tube};
use crate::common::{Expected, Rng, assert_close, boxes_mesh, errors, instance, nearest, query};
use crate::voxel_oracle::{Aabb, Voxels};
use contact_core::geometry::Cuboid;
use contact_core::{Contact, Geometry, GeometryInstance, Isometry3, Point3, Vector3};
use std::sync::Arc;

fn mesh_of(voxels: &Voxels) -> GeometryInstance {
    instance(Geometry::Mesh(Arc::new(voxels.mesh())))
}

fn box_mesh(b: &Aabb) -> GeometryInstance {
    instance(Geometry::Mesh(Arc::new(boxes_mesh(&[(
        b.centre(),
        b.half(),
    )]))))
}

/// A U of cells: three along x, and an arm up from each end.
fn u_cells() -> Voxels {
    let mut cells: Vec<[i32; 3]> = (0..3).map(|i| [i, 0, 0]).collect();
    cells.extend([[0, 1, 0], [2, 1, 0]]);
    Voxels { cells, size: 1.0 }
}

/// The box `b` given as a mesh (I) against the cells (J), both at `world`: the number of
/// regions and each region against the closed form, matched by the nearest box point. Returns
/// false, checking nothing, where the closed form has a region with no net area vector (its
/// irregular branch) or no region at all.
fn matches_cells(voxels: &Voxels, b: &Aabb, world: &Isometry3, what: &str) -> bool {
    let Some(expected) = voxels
        .contacts(b)
        .into_iter()
        .collect::<Option<Vec<Expected>>>()
    else {
        return false;
    };
    let found = query(&box_mesh(b), &mesh_of(voxels), world, world);
    assert_eq!(found.len(), expected.len(), "{what}: {b:?}\n{found:?}");
    for e in &expected {
        let e = e.moved(world);
        let got = nearest(&found, &e.point_i);
        let mut err = errors(got, &e, 3.0);
        // A centroid outside the cells whose line misses them (a U's or an L's region): J's
        // point is then the closest point of the cells' surface, which two faces can tie for;
        // the normal and I's point are still the closed form's.
        if (e.point_j - e.point_i).cross(&e.normal).norm() > 1e-12 {
            err = [0.0, err[1], (got.point_i_w - e.point_i).norm() / 3.0];
        }
        assert!(
            err.iter().all(|&x| x <= 1e-12),
            "{what}: {b:?} {err:?}\n{got:?}\n{e:?}"
        );
    }
    !expected.is_empty()
}

fn aabb(lo: [f64; 3], hi: [f64; 3]) -> Aabb {
    Aabb {
        lo: Point3::from(lo),
        hi: Point3::from(hi),
    }
}

#[test]
fn mesh_against_mesh_is_the_cells_closed_form_per_region() {
    let world = Rng::new(76).pose(3.0);
    // Through the tube's hole, meeting two walls: two regions whose faces at z = 1 and 3 lie
    // on the cells' planes, joined by nothing but zero-volume touching there.
    let slab = aabb([0.8, 1.2, 1.0], [2.2, 1.8, 3.0]);
    assert!(matches_cells(
        &tube(1.0),
        &slab,
        &world,
        "slab through the hole"
    ));
    assert_eq!(tube(1.0).contacts(&slab).len(), 2);
    let cap = aabb([-0.3, 0.5, 1.0], [2.5, 2.5, 3.0]);
    assert!(matches_cells(
        &tube(1.0),
        &cap,
        &world,
        "cap around the hole"
    ));
    let arms = aabb([0.5, 1.3, 0.2], [2.5, 1.8, 0.7]);
    assert!(matches_cells(&u_cells(), &arms, &world, "both arms"));
    assert_eq!(u_cells().contacts(&arms).len(), 2);
}

/// A coordinate on the half-unit grid, on a cell plane half of the time.
fn grid(rng: &mut Rng, lo: i32, hi: i32) -> f64 {
    let k = lo + (rng.next_u64() % (hi - lo + 1) as u64) as i32;
    if rng.next_u64().is_multiple_of(2) {
        f64::from(k)
    } else {
        f64::from(k) + 0.5
    }
}

/// Boxes with every face on a cell plane or halfway between two, at seeded world poses,
/// against a tube, a U and an L: the closed form per region, in both counts and values.
#[test]
fn boxes_on_the_cell_planes_are_the_cells_closed_form() {
    let mut rng = Rng::new(0x3E5);
    let shapes = [("tube", tube(1.0)), ("U", u_cells()), ("L", l_bar(1.0))];
    let (mut checked, mut two) = (0, 0);
    let (mut flush, mut touching, mut left_out) = (0, 0, 0);
    for k in 0..1000 {
        let (name, voxels) = &shapes[k % shapes.len()];
        let world = rng.pose(3.0);
        let mut lo = [0.0; 3];
        let mut hi = [0.0; 3];
        for axis in 0..3 {
            let (a, b) = (grid(&mut rng, -1, 4), grid(&mut rng, -1, 4));
            if a == b {
                (lo[axis], hi[axis]) = (a, a + 0.5);
            } else {
                (lo[axis], hi[axis]) = (a.min(b), a.max(b));
            }
        }
        let b = aabb(lo, hi);
        // Left out: faces flush along all three axes (a box corner on a corner of the cells,
        // every face there shared), and flush faces together with touching ones; the engine's
        // centroid can be off where they meet at a vertex of the cells (see the module docs).
        let (flush_axes, touching_axes) = voxels.coplanar_axes(&b);
        if flush_axes == 0b111 || (flush_axes != 0 && touching_axes != 0) {
            left_out += 1;
            continue;
        }
        flush += usize::from(flush_axes != 0);
        touching += usize::from(touching_axes != 0);
        if matches_cells(voxels, &b, &world, &format!("{name} box {k}")) {
            checked += 1;
            two += usize::from(voxels.contacts(&b).len() >= 2);
        }
    }
    assert!(
        checked > 300 && two > 5 && flush > 100 && touching > 100,
        "{checked} boxes, {two} with two regions, {flush} with flush faces, {touching} with \
         touching ones, {left_out} left out"
    );
}

/// Boxes at any orientation against the cells, given as a mesh and as a box: the mesh–mesh
/// pair answers what the box–mesh pair answers (each region's points, normal, depth, area).
#[test]
fn a_box_mesh_gives_the_box_primitive_answer_against_cells() {
    let mut rng = Rng::new(0x3E6);
    let shapes = [tube(1.0), u_cells(), l_bar(1.0)];
    let mut seen = 0;
    for k in 0..300 {
        let voxels = &shapes[k % shapes.len()];
        let world = rng.pose(3.0);
        let h = Vector3::new(
            rng.uniform(0.2, 1.2),
            rng.uniform(0.2, 1.2),
            rng.uniform(0.2, 1.2),
        );
        let centre = Point3::new(
            rng.uniform(-0.5, 3.5),
            rng.uniform(-0.5, 3.5),
            rng.uniform(-0.5, 2.5),
        );
        let at = Isometry3::from_parts(centre.coords.into(), rng.rotation());
        let pose_i = world * at;
        let b = aabb([-h.x, -h.y, -h.z], [h.x, h.y, h.z]);
        let cuboid = instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap()));
        let want = by_point(query(&cuboid, &mesh_of(voxels), &pose_i, &world));
        let got = by_point(query(&box_mesh(&b), &mesh_of(voxels), &pose_i, &world));
        assert_eq!(got.len(), want.len(), "pose {k}: {got:?}\n{want:?}");
        for (g, w) in got.iter().zip(&want) {
            assert_close(g, w, 4.0, 16.0, 1e-9, &format!("pose {k}"));
            seen += 1;
        }
    }
    assert!(seen > 100, "only {seen} contacts");
}

/// Contacts ordered by their I point (regions come in no fixed order).
fn by_point(mut contacts: Vec<Contact>) -> Vec<Contact> {
    contacts.sort_by(|a, b| {
        let key = |c: &Contact| (c.point_i_w.x, c.point_i_w.y, c.point_i_w.z);
        key(a).partial_cmp(&key(b)).unwrap()
    });
    contacts
}

#[test]
fn a_mesh_pair_counts_the_triangles_it_holds() {
    use contact_core::GeometryEngine;
    let cells = u_cells();
    let u_mesh = mesh_of(&cells);
    let cube = box_mesh(&aabb([0.2, 0.2, 0.2], [0.8, 0.8, 0.8]));
    let count = |g: &GeometryInstance| match g.geometry.as_ref() {
        Geometry::Mesh(m) => m.triangles().len(),
        _ => unreachable!("a mesh"),
    };
    let (u_triangles, cube_triangles) = (count(&u_mesh), count(&cube));
    let pair = engine_exact::ExactEngine
        .prepare(std::slice::from_ref(&u_mesh), std::slice::from_ref(&cube))
        .unwrap();
    let stats = pair.stats();
    assert_eq!(stats.triangles, u_triangles + cube_triangles);
    assert!(
        stats.bytes > 48 * (u_triangles + cube_triangles),
        "{} bytes",
        stats.bytes
    );
    // A mesh against two planes: each pair prepares the mesh for itself.
    let ground = instance(Geometry::Plane(contact_core::geometry::Plane::unbounded()));
    let pair = engine_exact::ExactEngine
        .prepare(&[u_mesh], &[ground.clone(), ground])
        .unwrap();
    let twice = pair.stats();
    assert_eq!(twice.triangles, 2 * u_triangles);
    assert!(twice.bytes > 2 * 48 * u_triangles, "{} bytes", twice.bytes);
}
