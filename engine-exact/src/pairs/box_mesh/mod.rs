//! A box against a closed triangle mesh (taken as exact), and a mesh against a bounded
//! PLANE (the box that stands for it, [`crate::methods::bounded_plane`]): exact polyhedral
//! intersection, one contact per connected region.
//!
//! In the box's frame (centred, `|x_k| ≤ h_k`, lengths divided by a power of two near the
//! box's size):
//! - **Mesh surface inside.** Every triangle that reaches the box is clipped to it
//!   ([`clip`]), each piece remembering which triangle edge or box plane it came from.
//! - **Regions.** Clipped triangles that share a mesh edge inside the box are one region; the
//!   box's own surface inside the mesh then joins regions that meet only through it: the
//!   parts of the box edges inside the mesh, and the holes in a face's caps ([`faces`]). A
//!   mesh resting on the box by two feet is two contacts; a box cut through a thick-walled
//!   tube is one.
//! - **Volume and centroid** of each region by the divergence theorem about a point `o` of
//!   the region (so round-off is relative to the region's size): with `∫(x − o)·n/3` for the
//!   volume and `∫ ½(x_i − o_i)² n_i` for the first moments. On a face of the box these are
//!   constant times the face's cap area, so the caps enter only by their areas, which come
//!   from Green's theorem over the pieces bounding them; the clipped triangles are integrated
//!   exactly (polynomials over triangles).
//! - **Normal** (from the mesh into the box, SPEC §4 as [`crate::methods::clipped`] reads it): `S/|S|`,
//!   `S` the area vector of the mesh's surface inside the box. When it vanishes (`|S| ≤ 1e-12`
//!   of that surface's area, or none): with no mesh surface inside, the box lies in the mesh
//!   and the normal points from the centroid to the closest point of the mesh; otherwise the
//!   opposite of the box face nearest the centroid.
//! - **Points**: where the line through the centroid along the normal leaves the box (along
//!   `−n`) and first meets the mesh (along `+n`; the closest point of the mesh when the line
//!   misses it); δ is their distance. **Area**: `|S|`, or a quarter of the region's whole
//!   surface when `S` vanishes.
//! - Touching (a mesh face flush with a box face, a vertex on it) has no volume and is no
//!   contact: points on the box's surface count as outside it.
//! - **Flipped** (a cavity): the mesh turned inside out ([`PreparedMesh::inverted`]) bounds
//!   the space outside it, and everything above holds as written: the reversed triangles'
//!   normals point into the cavity, the winding number's threshold moves, and the mesh's ball
//!   no longer bounds its solid. A box in a box-shaped cavity is the box against the cavity's
//!   walls as such a mesh ([`box_mesh`]).
//!
//! Work is `O(vertices + triangles)` per query (the mesh is moved into the box's frame), plus
//! the clipping of the triangles that reach the box.

pub(crate) mod clip;
pub(crate) mod faces;

use super::mesh_plane::{PreparedMesh, closest_on_mesh, exit_along};
use super::sphere_mesh::solid_angle;
use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::ray_exit::box_exit;
use clip::{Clipped, Edge, plane};
use contact_core::geometry::Cuboid;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use nalgebra::Translation3;

/// No node / polygon.
pub(crate) const NONE: u32 = u32::MAX;

/// Union–find over the regions' nodes (the clipped polygons, then the box's eight corners).
#[derive(Debug)]
pub(crate) struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    /// `count` nodes, each its own set.
    pub(crate) fn new(count: usize) -> Self {
        Self {
            parent: (0..count as u32).collect(),
        }
    }

    /// The representative of `a`'s set: its smallest node.
    pub(crate) fn find(&mut self, mut a: u32) -> u32 {
        while self.parent[a as usize] != a {
            let up = self.parent[self.parent[a as usize] as usize];
            self.parent[a as usize] = up;
            a = up;
        }
        a
    }

    /// Joins the sets of `a` and `b`.
    pub(crate) fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.parent[ra.max(rb) as usize] = ra.min(rb);
        }
    }
}

/// Calls `on_loop` with each closed loop of the `count` items linked by `next` (the item
/// after `at`, `None` where a chain ends), in the order walked. Each item is walked once; a
/// chain that ends, or runs into items walked before, is not a loop.
pub(crate) fn closed_loops(
    count: usize,
    next: impl Fn(usize) -> Option<usize>,
    mut on_loop: impl FnMut(&[usize]),
) {
    let mut visited = vec![false; count];
    let mut walk = Vec::new();
    for start in 0..count {
        if visited[start] {
            continue;
        }
        walk.clear();
        let mut at = start;
        let closed = loop {
            visited[at] = true;
            walk.push(at);
            match next(at) {
                Some(n) if n == start => break true,
                Some(n) if n < count && !visited[n] => at = n,
                _ => break false,
            }
        };
        if closed {
            on_loop(&walk);
        }
    }
}

/// Per-region sums, about the region's anchor `o`.
#[derive(Debug, Clone, Copy)]
struct Sums {
    anchor: Option<Point3>,
    /// `∫(x − o)·n` over the clipped triangles.
    flux: f64,
    /// `∫ ½(x_i − o_i)² n_i` over the clipped triangles.
    moment: Vector3,
    /// The area vector `S` of the mesh's surface inside the box.
    area_vector: Vector3,
    /// The unsigned area of that surface.
    area: f64,
    /// The cap area on each box face.
    caps: [f64; 6],
}

impl Default for Sums {
    fn default() -> Self {
        Self {
            anchor: None,
            flux: 0.0,
            moment: Vector3::zeros(),
            area_vector: Vector3::zeros(),
            area: 0.0,
            caps: [0.0; 6],
        }
    }
}

/// Contacts of `cuboid` at `pose_box` (`a`) with `mesh` at `pose_mesh` (`b`), one per
/// region, handed to `emit` in the order of each region's first clipped triangle.
pub(crate) fn contacts(
    cuboid: &Cuboid,
    pose_box: &Isometry3,
    mesh: &PreparedMesh,
    pose_mesh: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let unit = unit_for(cuboid.half_extents().norm());
    let frame = pose_box * Translation3::from(cuboid.center().coords);
    let relative = frame.inv_mul(pose_mesh);
    let half = cuboid.half_extents() / unit;
    // The mesh's ball must reach the box (a cavity's solid reaches everywhere).
    let reach = (relative * mesh.centre).coords / unit;
    let radius = mesh.radius / unit;
    if !mesh.inverted && (0..3).any(|k| reach[k].abs() - radius >= half[k]) {
        return;
    }
    let local: Vec<Point3> = mesh
        .vertices
        .iter()
        .map(|v| Point3::from((relative * v).coords / unit))
        .collect();
    let clipped = clip_triangles(mesh, &local, &half, work);
    let inside = |p: &Point3| inside_mesh(mesh, &local, p);
    if clipped.polygons.is_empty() && !inside(&Point3::origin()) {
        return;
    }
    let (mut forest, intervals, face_cuts) = regions(mesh, &clipped, &half, inside);
    let sums = region_sums(
        &clipped.polygons,
        &face_cuts,
        &half,
        &intervals,
        &mut forest,
    );
    for (root, s) in sums.iter().enumerate() {
        let Some(o) = s.anchor else { continue };
        if forest.find(root as u32) as usize != root {
            continue;
        }
        if let Some(c) = region_contact(s, &o, &half, mesh, pose_mesh, &frame, unit) {
            emit(c);
        }
    }
}

/// The mesh's triangles clipped to the box: the polygons left, and for each its triangle's
/// (unnormalised) normal and index; for each triangle, its polygon (`NONE` when none).
struct ClippedMesh {
    polygons: Vec<Clipped>,
    normals: Vec<Vector3>,
    triangle_of: Vec<usize>,
    polygon_of: Vec<u32>,
}

/// Clips each triangle of `mesh` (its vertices `local`, in the box's frame and unit) that
/// reaches the box of half extents `half` to the box.
fn clip_triangles(
    mesh: &PreparedMesh,
    local: &[Point3],
    half: &Vector3,
    work: &mut WorkCounters,
) -> ClippedMesh {
    let mut polygons = Vec::new();
    let mut normals = Vec::new();
    let mut triangle_of = Vec::new();
    let mut polygon_of = vec![NONE; mesh.triangles.len()];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let [a, b, c] = tri.map(|v| local[v as usize]);
        if (0..3)
            .any(|k| a[k].min(b[k]).min(c[k]) >= half[k] || a[k].max(b[k]).max(c[k]) <= -half[k])
        {
            continue;
        }
        work.primitive_tests += 1;
        let mut poly = Clipped::triangle(a, b, c);
        if poly.clip_to_box(half) {
            polygon_of[t] = polygons.len() as u32;
            polygons.push(poly);
            normals.push((b - a).cross(&(c - a)));
            triangle_of.push(t);
        }
    }
    ClippedMesh {
        polygons,
        normals,
        triangle_of,
        polygon_of,
    }
}

/// True when `p` is inside `mesh`'s solid (its vertices `local`), by the winding number
/// (the solid angles' sum over `4π`).
fn inside_mesh(mesh: &PreparedMesh, local: &[Point3], p: &Point3) -> bool {
    let winding: f64 = mesh
        .triangles
        .iter()
        .map(|tri| {
            let [a, b, c] = tri.map(|v| local[v as usize]);
            solid_angle(p, &a, &b, &c)
        })
        .sum();
    // Inside-out, the sum is −4π inside the mesh and 0 outside, where its solid is.
    let threshold = if mesh.inverted { -2.0 } else { 2.0 };
    winding > threshold * std::f64::consts::PI
}

/// The regions (see the module doc): the clipped polygons joined across the mesh's edges
/// inside the box, along the box's edges (`inside` tells a box corner's side) and from each
/// hole in a face's caps to the cap around it, in a union–find over the polygons and the
/// box's corners; with the box edges' intervals and each face's cuts, which the caps take.
fn regions(
    mesh: &PreparedMesh,
    clipped: &ClippedMesh,
    half: &Vector3,
    inside: impl Fn(&Point3) -> bool,
) -> (UnionFind, faces::Intervals, Vec<Vec<(u32, usize)>>) {
    let polygons = &clipped.polygons;
    let count = polygons.len();
    let mut forest = UnionFind::new(count + 8);
    let next_polygon = |i: u32, k: u8| -> u32 {
        let t = clipped.triangle_of[i as usize];
        clipped.polygon_of[mesh.neighbours[t][k as usize] as usize]
    };
    // Clipped triangles sharing a mesh edge inside the box.
    for (i, poly) in polygons.iter().enumerate() {
        for e in 0..poly.len {
            if let Edge::Triangle(k) = poly.edges[e] {
                let j = next_polygon(i as u32, k);
                if j != NONE && poly.points[e] != poly.points[(e + 1) % poly.len] {
                    forest.union(i as u32, j);
                }
            }
        }
    }
    let mut intervals = faces::Intervals::new();
    faces::box_edges(
        polygons,
        &clipped.normals,
        half,
        &mut forest,
        |c| {
            let corner = Point3::new(
                if c & 1 != 0 { half.x } else { -half.x },
                if c & 2 != 0 { half.y } else { -half.y },
                if c & 4 != 0 { half.z } else { -half.z },
            );
            inside(&corner)
        },
        &mut intervals,
    );
    let face_cuts: Vec<Vec<(u32, usize)>> = (0..6).map(|f| faces::cuts(polygons, f)).collect();
    let mut cut_index = vec![NONE; count];
    for (f, cuts) in face_cuts.iter().enumerate() {
        cut_index.fill(NONE);
        for (s, &(i, _)) in cuts.iter().enumerate() {
            cut_index[i as usize] = s as u32;
        }
        faces::join_holes(
            polygons,
            f,
            cuts,
            &cut_index,
            next_polygon,
            half,
            &intervals,
            &mut forest,
        );
    }
    (forest, intervals, face_cuts)
}

/// The sums of each region (see the module doc), at its root in `forest`: its clipped
/// polygons' flux, moment and area, and its caps' areas on the box's faces.
fn region_sums(
    polygons: &[Clipped],
    face_cuts: &[Vec<(u32, usize)>],
    half: &Vector3,
    intervals: &faces::Intervals,
    forest: &mut UnionFind,
) -> Vec<Sums> {
    let count = polygons.len();
    // The sums of each region, at its root.
    let mut sums = vec![Sums::default(); count + 8];
    for (i, poly) in polygons.iter().enumerate() {
        let root = forest.find(i as u32) as usize;
        let s = &mut sums[root];
        let o = *s.anchor.get_or_insert(poly.points[0]);
        let a = poly.points[0] - o;
        for k in 1..poly.len - 1 {
            let (b, c) = (poly.points[k] - o, poly.points[k + 1] - o);
            let area_vector = 0.5 * (b - a).cross(&(c - a));
            s.flux += a.dot(&area_vector);
            for axis in 0..3 {
                let (x, y, z) = (a[axis], b[axis], c[axis]);
                s.moment[axis] +=
                    area_vector[axis] * (x * x + y * y + z * z + x * y + y * z + z * x) / 12.0;
            }
            s.area_vector += area_vector;
            s.area += area_vector.norm();
        }
    }
    for (f, cuts) in face_cuts.iter().enumerate() {
        let (axis, sign) = plane(f);
        faces::cap_pieces(polygons, f, cuts, half, intervals, |node, p, q| {
            let root = forest.find(node) as usize;
            let s = &mut sums[root];
            let o = *s.anchor.get_or_insert(Point3::origin());
            s.caps[f] += 0.5 * sign * (p - o).cross(&(q - o))[axis];
        });
    }
    sums
}

/// The contact of one region from its sums (see the module doc), in the world.
fn region_contact(
    s: &Sums,
    o: &Point3,
    half: &Vector3,
    mesh: &PreparedMesh,
    pose_mesh: &Isometry3,
    frame: &Isometry3,
    unit: f64,
) -> Option<PairContact> {
    let mut flux = s.flux;
    let mut moment = s.moment;
    let mut caps_area = 0.0;
    for (f, &cap) in s.caps.iter().enumerate() {
        let (axis, sign) = plane(f);
        // The face's distance from `o`, and its `x_i − o_i`.
        let offset = half[axis] - sign * o[axis];
        flux += offset * cap;
        moment[axis] += 0.5 * sign * offset * offset * cap;
        caps_area += cap.abs();
    }
    let volume = flux / 3.0;
    if volume.is_nan() || volume <= 0.0 {
        return None;
    }
    let centroid = o + moment / volume;
    let s_norm = s.area_vector.norm();
    // A NaN area vector counts as vanishing too.
    let enclosed = s_norm.is_nan() || s_norm <= 1e-12 * s.area;
    let to_world = |p: &Point3| frame * Point3::from(p.coords * unit);
    let centroid_w = to_world(&centroid);
    let to_mesh = |p: &Point3| pose_mesh.inverse_transform_point(p);
    let normal = if !enclosed {
        s.area_vector / s_norm
    } else if s.area == 0.0 {
        // The box lies in the mesh: towards the mesh's closest point.
        let q = pose_mesh * closest_on_mesh(mesh, &to_mesh(&centroid_w));
        let away = frame.inverse_transform_vector(&(q - centroid_w));
        if away.norm() > 0.0 {
            away.normalize()
        } else {
            Vector3::z()
        }
    } else {
        // The mesh lies in the box: against the box face nearest the centroid.
        let (mut gap, mut face) = (f64::INFINITY, Vector3::z());
        for f in 0..6 {
            let (axis, sign) = plane(f);
            let g = half[axis] - sign * centroid[axis];
            if g < gap - 1e-12 {
                gap = g;
                face = Vector3::zeros();
                face[axis] = sign;
            }
        }
        -face
    };
    let area = if enclosed {
        0.25 * (s.area + caps_area)
    } else {
        s_norm
    };
    let to_box = box_exit(&Vector3::zeros(), half, &centroid.coords, &-normal).unwrap_or(0.0);
    let point_a = to_world(&(centroid - to_box * normal));
    let normal_w = frame.rotation * normal;
    let from = to_mesh(&centroid_w);
    let direction = pose_mesh.inverse_transform_vector(&normal_w);
    let on_mesh =
        exit_along(mesh, &from, &direction).unwrap_or_else(|| closest_on_mesh(mesh, &from));
    let point_b = pose_mesh * on_mesh;
    let depth = (point_b - point_a).norm();
    (depth > 0.0).then_some(PairContact {
        point_a,
        point_b,
        normal: normal_w,
        depth,
        area: area * unit * unit,
    })
}

/// The closed mesh of `cuboid`'s surface (12 triangles, outward), prepared (`None` only if
/// the box were degenerate, which its constructor rules out).
pub(crate) fn box_mesh(cuboid: &Cuboid) -> Option<PreparedMesh> {
    let mesh =
        contact_core::geometry::TriangleMesh::boxes(&[(cuboid.center(), cuboid.half_extents())])
            .ok()?;
    PreparedMesh::new(&mesh)
}

/// The surfaces of the boxes `(centre, half extents)` as one closed mesh (tests' shapes).
#[cfg(test)]
pub(crate) fn boxes_surface(boxes: &[(Point3, Vector3)]) -> contact_core::geometry::TriangleMesh {
    contact_core::geometry::TriangleMesh::boxes(boxes).expect("boxes are closed")
}
