//! A prepared mesh: triangles, their neighbours across each edge, exact corner normals, mass
//! properties and the OBB tree — everything a query reads, built once by `prepare`.

use crate::flat_faces::{FlatFaces, flat_faces};
use crate::mesh_build::{
    MassProperties, bounds, edge_neighbours, is_convex, longest_edge, vertex_normals,
};
use crate::obb_tree::ObbTree;
use crate::patches::PatchIndex;
use crate::smooth_patch::{pn_control_points, pn_point, pn_reach};
use crate::tessellate::Tessellation;
use contact_core::geometry::{closest_point_on_triangle, line_triangle};
use contact_core::{Point3, Vector3};

/// Barycentric widening of the ray–facet test: a ray through a shared edge or vertex meets at
/// least one facet there despite round-off (both give the same point within 1e-9).
const RAY_WIDEN: f64 = 1e-9;

/// A facet whose unit normal `n` has `|n·dir| < PARALLEL_TO_RAY` runs parallel to the ray for
/// the ray test (`line_triangle`), which refuses `|det| ≤ 1e-14·|e₁||e₂|` where
/// `|det| = |e₁ × e₂|·|n·dir| ≤ |e₁||e₂|·|n·dir|`: the cheap test skips only facets it refuses,
/// with a tenfold margin for the round-off of the stored normal.
const PARALLEL_TO_RAY: f64 = 1e-15;

/// No neighbour across an edge (open meshes only).
pub const NO_NEIGHBOR: u32 = u32::MAX;

/// A triangle mesh ready for queries, in its geometry frame `G`.
#[derive(Debug, Clone)]
pub struct FacetMesh {
    /// Vertices.
    pub vertices: Vec<Point3>,
    /// Counter-clockwise triangles seen from outside.
    pub triangles: Vec<[u32; 3]>,
    /// Across edge `k` (from corner `k` to corner `k+1`) of each triangle: the neighbour, or
    /// [`NO_NEIGHBOR`].
    pub neighbors: Vec<[u32; 3]>,
    /// Unit facet normals.
    pub face_normals: Vec<Vector3>,
    /// The true surface normal at each triangle corner (facet normals for meshes read from files).
    pub corner_normals: Vec<[Vector3; 3]>,
    /// Each vertex's angle-weighted pseudo-normal (unit; zero where it cancels): the direction
    /// the triangle tests move a vertex lying on the other surface's plane, inwards, when they
    /// take the mesh as eroded by an infinitesimal amount
    /// ([`crate::triangle_pair::intersect_perturbed`]).
    pub vertex_normals: Vec<Vector3>,
    /// The OBB tree.
    pub tree: ObbTree,
    /// The tree's subtrees as surface patches, for the inside flood.
    pub patches: PatchIndex,
    /// Enclosed volume (0 for an open mesh).
    pub volume: f64,
    /// Centroid of the enclosed volume (of the vertices for an open mesh).
    pub centroid: Point3,
    /// Surface area.
    pub area: f64,
    /// Bounding-box diagonal: the mesh's length scale.
    pub size: f64,
    /// The longest triangle edge: the scale of the triangle test's on-plane band.
    pub longest_edge: f64,
    /// True when closed and outward oriented (inside tests are meaningful).
    pub closed: bool,
    /// True for a solid turned inside out ([`FacetMesh::build_inside_out`]): the space outside
    /// a closed surface, a cavity. Its facets face into the cavity, its
    /// [`contains`](Self::contains) is the complement of the solid's, and its `volume` is the
    /// cavity's, negative.
    pub inside_out: bool,
    /// True when closed and convex: one edge-connected surface, every neighbour link returned,
    /// and at every edge the neighbour's far corner on or behind the triangle's plane within
    /// `1e-12·size`. Its surface below any plane is then one region.
    pub convex: bool,
    /// How far any curved PN triangle reaches beyond its flat facet (0 for flat facets):
    /// every point of the smooth surface lies within it of the facets.
    pub pn_reach: f64,
    /// The sphere the mesh stands for, `(centre, radius)`, when every corner lies on it with
    /// its normal along the radius (`|p − c − R·n| ≤ 1e-9·R` at every corner of every
    /// triangle): a tessellated sphere, whose contact with a plane is the sphere's
    /// (engine-facet's plane contact: `plane_support`).
    pub implied_sphere: Option<(Point3, f64)>,
    /// The ellipsoid the mesh stands for, `(centre, semi-axes)` along the mesh's own axes, when
    /// it is not a sphere and every corner lies on `Σ ((p − c)ᵢ/sᵢ)² = 1` to 1e-9 with its normal
    /// along that surface's gradient to 1e-9 rad: a tessellated ellipsoid, whose contact with an
    /// unbounded plane is the ellipsoid's (`plane_support::ellipsoid_on_plane`).
    pub implied_ellipsoid: Option<(Point3, Vector3)>,
    /// A convex mesh's flat faces (at most [`crate::flat_faces::MOST_FACES`]), for its contact
    /// with a plane.
    pub(crate) flat_faces: Option<FlatFaces>,
}

impl FacetMesh {
    /// Builds the neighbours, mass properties and tree of a tessellation.
    pub fn build(t: Tessellation, closed: bool) -> Self {
        let Tessellation {
            vertices,
            triangles,
            corner_normals,
        } = t;
        let neighbors = edge_neighbours(&triangles);
        let (lo, hi) = bounds(&vertices);
        let mass = MassProperties::of(&vertices, &triangles, 0.5 * (lo + hi), closed);
        let (volume, centroid, area, face_normals) =
            (mass.volume, mass.centroid, mass.area, mass.face_normals);
        let mut tree = ObbTree::build(&vertices, &triangles);
        // Triangles (and their vertices) renumbered in the tree's leaf order, after the mass
        // properties and the tree are formed in the given order (so neither changes by a bit):
        // every subtree is then one range of triangles, a patch the inside flood can take whole.
        let old_of_new = tree.renumber_in_leaf_order();
        let (mut vertices, mut triangles, mut neighbors) = (vertices, triangles, neighbors);
        let (mut face_normals, mut corner_normals) = (face_normals, corner_normals);
        into_leaf_order(
            &old_of_new,
            &mut vertices,
            &mut triangles,
            &mut neighbors,
            &mut face_normals,
            &mut corner_normals,
        );
        let patches = PatchIndex::build(&tree, &vertices, &triangles, &neighbors);
        let vertex_normals = vertex_normals(&vertices, &triangles, &face_normals);
        let longest_edge = longest_edge(&vertices, &triangles);
        let pn_reach = triangles
            .iter()
            .zip(&corner_normals)
            .filter(|(_, n)| n[0] != n[1] || n[1] != n[2])
            .map(|(t, n)| pn_reach(&t.map(|v| vertices[v as usize].coords), n))
            .fold(0.0, f64::max);
        let size = (hi - lo).norm();
        let convex = closed && is_convex(&vertices, &triangles, &neighbors, &face_normals, size);
        let implied_sphere =
            implied_sphere(closed, &centroid, &vertices, &triangles, &corner_normals);
        let implied_ellipsoid = if implied_sphere.is_none() {
            implied_ellipsoid(closed, &centroid, &vertices, &triangles, &corner_normals)
        } else {
            None
        };
        let mut mesh = Self {
            vertices,
            triangles,
            neighbors,
            face_normals,
            corner_normals,
            vertex_normals,
            tree,
            patches,
            volume: if closed { volume } else { 0.0 },
            centroid,
            area,
            size,
            longest_edge,
            closed,
            inside_out: false,
            convex,
            pn_reach,
            implied_sphere,
            implied_ellipsoid,
            flat_faces: None,
        };
        if convex {
            mesh.flat_faces = flat_faces(&mesh);
        }
        mesh
    }

    /// The space outside the closed solid `t` describes (a flipped solid, a cavity): its
    /// triangles wound the other way and its corner normals reversed, so every facet faces
    /// into the cavity and the PN patches lie on the same surface. None of the shortcuts a
    /// solid takes applies: it is not convex and stands for no sphere or ellipsoid.
    pub fn build_inside_out(t: Tessellation) -> Self {
        let Tessellation {
            vertices,
            triangles,
            corner_normals,
        } = t;
        let triangles = triangles.iter().map(|&[i, j, k]| [i, k, j]).collect();
        let corner_normals = corner_normals
            .iter()
            .map(|&[p, q, r]| [-p, -r, -q])
            .collect();
        let mut mesh = Self::build(
            Tessellation {
                vertices,
                triangles,
                corner_normals,
            },
            true,
        );
        mesh.inside_out = true;
        mesh.convex = false;
        mesh.implied_sphere = None;
        mesh.implied_ellipsoid = None;
        mesh.flat_faces = None;
        mesh
    }

    /// The corners of triangle `t`.
    #[inline]
    pub fn corners(&self, t: u32) -> [Vector3; 3] {
        // Spelled out rather than `array::map`, which compiles to a slower loop on this hot path.
        let [i, j, k] = self.triangles[t as usize];
        [
            self.vertices[i as usize].coords,
            self.vertices[j as usize].coords,
            self.vertices[k as usize].coords,
        ]
    }

    /// Heap bytes held.
    pub fn heap_bytes(&self) -> usize {
        self.vertices.capacity() * std::mem::size_of::<Point3>()
            + self.triangles.capacity() * 12
            + self.neighbors.capacity() * 12
            + self.face_normals.capacity() * std::mem::size_of::<Vector3>()
            + self.corner_normals.capacity() * 3 * std::mem::size_of::<Vector3>()
            + self.vertex_normals.capacity() * std::mem::size_of::<Vector3>()
            + self.tree.heap_bytes()
            + self.patches.heap_bytes()
            + self.flat_faces.as_ref().map_or(0, FlatFaces::heap_bytes)
    }

    /// Whether `p` (mesh frame) is inside the closed mesh's solid (outside the cavity, for an
    /// inside-out one): parity of ray crossings, cast along up to three fixed skew directions
    /// until one meets no edge or vertex within a relative 1e-9 (then the parity is
    /// unambiguous); the majority of the three otherwise. Always false for an open mesh.
    pub fn contains(&self, p: &Point3) -> bool {
        if !self.closed {
            return false;
        }
        self.inside_out != self.solid_contains(p)
    }

    /// Whether `p` lies inside the closed surface (inside the cavity, for an inside-out mesh).
    fn solid_contains(&self, p: &Point3) -> bool {
        if !self.tree.root().contains(p) {
            return false;
        }
        // Skew directions (normalised below) unlikely to run along edges of tessellated meshes.
        const DIRECTIONS: [[f64; 3]; 3] = [
            [0.577_2, 0.318_4, 0.751_9],
            [-0.267_9, 0.854_1, -0.445_0],
            [0.141_4, -0.693_2, 0.706_8],
        ];
        let mut votes = 0;
        for (k, d) in DIRECTIONS.iter().enumerate() {
            let dir = Vector3::new(d[0], d[1], d[2]).normalize();
            match self.ray_parity(p, &dir) {
                Some(inside) => return inside,
                None => votes += usize::from(self.ray_parity_loose(p, &dir)),
            }
            if k == 2 {
                return votes >= 2;
            }
        }
        false
    }

    fn ray_crossings(&self, p: &Point3, dir: &Vector3) -> (usize, bool) {
        let (mut count, mut ambiguous) = (0, false);
        let tol = 1e-9;
        self.tree.visit(
            |obb| ray_hits_box(obb, p, dir),
            |t| {
                let [a, b, c] = self.corners(t);
                if let Some((s, u, v)) = ray_triangle(&p.coords, dir, &a, &b, &c) {
                    let w = 1.0 - u - v;
                    if s > 0.0 {
                        count += 1;
                        if u < tol || v < tol || w < tol {
                            ambiguous = true;
                        }
                    }
                }
            },
        );
        (count, ambiguous)
    }

    fn ray_parity(&self, p: &Point3, dir: &Vector3) -> Option<bool> {
        let (count, ambiguous) = self.ray_crossings(p, dir);
        (!ambiguous).then_some(count % 2 == 1)
    }

    fn ray_parity_loose(&self, p: &Point3, dir: &Vector3) -> bool {
        self.ray_crossings(p, dir).0 % 2 == 1
    }

    /// The closest point of the whole surface to `p` (mesh frame) and its triangle: a
    /// branch-and-bound descent of the tree, nearer child first, pruning boxes farther than the
    /// best point so far. `stack` is scratch space.
    pub fn closest_point(&self, p: &Vector3, stack: &mut Vec<(u32, u32)>) -> (u32, Vector3) {
        let nodes = self.tree.nodes();
        let (mut best_d, mut best_t, mut best_p) = (f64::INFINITY, 0u32, *p);
        stack.clear();
        stack.push((0, 0));
        while let Some((i, _)) = stack.pop() {
            let node = &nodes[i as usize];
            if box_distance_squared(&node.obb, p) >= best_d {
                continue;
            }
            if node.count > 0 {
                for &t in self.tree.leaf_triangles(node) {
                    let q = self.closest_on_triangle(t, p);
                    let d = (q - p).norm_squared();
                    if d < best_d {
                        (best_d, best_t, best_p) = (d, t, q);
                    }
                }
            } else {
                let (l, r) = (i + 1, node.index);
                let dl = box_distance_squared(&nodes[l as usize].obb, p);
                let dr = box_distance_squared(&nodes[r as usize].obb, p);
                if dl <= dr {
                    stack.push((r, 0));
                    stack.push((l, 0));
                } else {
                    stack.push((l, 0));
                    stack.push((r, 0));
                }
            }
        }
        (best_t, best_p)
    }

    /// Where the ray `p + s·dir` (`s ≥ 0`, `dir` unit, mesh frame) first meets the surface: the
    /// triangle and the point, or `None` when it meets nothing. The hit moves continuously with
    /// `p` and `dir` across facet edges (neighbouring facets share the edge), unlike the closest
    /// point to `p`, which jumps between facets where two are equally near.
    pub fn first_ray_hit(&self, p: &Vector3, dir: &Vector3) -> Option<(u32, Vector3)> {
        let origin = Point3::from(*p);
        let mut best: Option<(f64, u32)> = None;
        self.tree.visit(
            |obb| ray_hits_box(obb, &origin, dir),
            |t| {
                if self.face_normals[t as usize].dot(dir).abs() < PARALLEL_TO_RAY {
                    return;
                }
                let [a, b, c] = self.corners(t);
                if let Some(s) = line_triangle(p, dir, &a, &b, &c, RAY_WIDEN) {
                    if s >= 0.0 && best.is_none_or(|(bs, _)| s < bs) {
                        best = Some((s, t));
                    }
                }
            },
        );
        best.map(|(s, t)| (t, p + dir * s))
    }

    /// The first hit of the ray `p + s·dir` (`s ≥ 0`) among the listed triangles only.
    pub fn first_ray_hit_among(
        &self,
        triangles: impl Iterator<Item = u32>,
        p: &Vector3,
        dir: &Vector3,
    ) -> Option<(u32, Vector3)> {
        let mut best: Option<(f64, u32)> = None;
        for t in triangles {
            if self.face_normals[t as usize].dot(dir).abs() < PARALLEL_TO_RAY {
                continue;
            }
            let [a, b, c] = self.corners(t);
            if let Some(s) = line_triangle(p, dir, &a, &b, &c, RAY_WIDEN) {
                if s >= 0.0 && best.is_none_or(|(bs, _)| s < bs) {
                    best = Some((s, t));
                }
            }
        }
        best.map(|(s, t)| (t, p + dir * s))
    }

    /// The closest point of triangle `t` to `p`.
    #[inline]
    pub fn closest_on_triangle(&self, t: u32, p: &Vector3) -> Vector3 {
        let [a, b, c] = self.corners(t);
        closest_point_on_triangle(
            &Point3::from(*p),
            &Point3::from(a),
            &Point3::from(b),
            &Point3::from(c),
        )
        .coords
    }
}

/// Squared distance from `p` to an oriented box (0 inside).
#[inline]
fn box_distance_squared(obb: &crate::obb::Obb, p: &Vector3) -> f64 {
    let q = obb.axes.tr_mul(&(p - obb.center));
    let d = (q.abs() - obb.half_extents).sup(&Vector3::zeros());
    d.norm_squared()
}

/// Slab test of the ray `p + s·dir`, `s ≥ 0`, against an oriented box.
fn ray_hits_box(obb: &crate::obb::Obb, p: &Point3, dir: &Vector3) -> bool {
    let o = obb.axes.tr_mul(&(p.coords - obb.center));
    let d = obb.axes.tr_mul(dir);
    let (mut lo, mut hi) = (0.0_f64, f64::INFINITY);
    for i in 0..3 {
        let h = obb.half_extents[i] * (1.0 + 1e-9) + 1e-300;
        if d[i].abs() < 1e-300 {
            if o[i].abs() > h {
                return false;
            }
        } else {
            let (s0, s1) = ((-h - o[i]) / d[i], (h - o[i]) / d[i]);
            lo = lo.max(s0.min(s1));
            hi = hi.min(s0.max(s1));
            if lo > hi {
                return false;
            }
        }
    }
    true
}

/// Möller–Trumbore: `(s, u, v)` with the hit at `p + s·dir = a + u(b − a) + v(c − a)`, or `None`.
fn ray_triangle(
    p: &Vector3,
    dir: &Vector3,
    a: &Vector3,
    b: &Vector3,
    c: &Vector3,
) -> Option<(f64, f64, f64)> {
    let (e1, e2) = (b - a, c - a);
    let h = dir.cross(&e2);
    let det = e1.dot(&h);
    if det.abs() <= 1e-14 * e1.norm() * e2.norm() {
        return None;
    }
    let inv = 1.0 / det;
    let s = p - a;
    let u = s.dot(&h) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(&e1);
    let v = dir.dot(&q) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    Some((e2.dot(&q) * inv, u, v))
}

impl FacetMesh {
    /// Lifts a point `p` of triangle `t` (mesh frame) onto the curved PN triangle (Vlachos et al.
    /// 2001, "Curved PN Triangles") through the triangle's corners and their true normals: the
    /// cubic patch that interpolates both. On a flat face (three equal corner normals) the patch
    /// is the triangle itself and `p` is returned unchanged; on a curved primitive it moves `p`
    /// from the chord back to within `O(h⁴/ρ³)` of the true surface (h the edge length, ρ the
    /// curvature radius), which removes the chord deviation from depths and contact points.
    pub fn lift_to_surface(&self, t: u32, p: &Vector3) -> Vector3 {
        let corners = self.corners(t);
        let normals = self.corner_normals[t as usize];
        if normals[0] == normals[1] && normals[1] == normals[2] {
            return *p;
        }
        let [p1, p2, p3] = corners;
        // Barycentric coordinates of p (on the triangle's plane).
        let (e1, e2, ep) = (p2 - p1, p3 - p1, p - p1);
        let (d11, d12, d22) = (e1.dot(&e1), e1.dot(&e2), e2.dot(&e2));
        let (dp1, dp2) = (ep.dot(&e1), ep.dot(&e2));
        let denom = d11 * d22 - d12 * d12;
        if denom <= 0.0 {
            return *p;
        }
        let u = (d22 * dp1 - d12 * dp2) / denom;
        let v = (d11 * dp2 - d12 * dp1) / denom;
        let b = pn_control_points(&corners, &normals);
        pn_point(&b, [1.0 - u - v, u, v])
    }

    /// Whether triangle `t` stands for a curved surface (its corner normals differ).
    #[inline]
    pub fn is_curved(&self, t: u32) -> bool {
        let [n1, n2, n3] = self.corner_normals[t as usize];
        n1 != n2 || n2 != n3
    }
}

/// The sphere a closed mesh's corners and corner normals lie on, if they all do: centre the
/// volume centroid, radius the mean corner distance from it, every corner within `1e-9·R` of
/// `c + R·n` for its own normal `n`.
fn implied_sphere(
    closed: bool,
    centroid: &Point3,
    vertices: &[Point3],
    triangles: &[[u32; 3]],
    corner_normals: &[[Vector3; 3]],
) -> Option<(Point3, f64)> {
    if !closed || triangles.is_empty() {
        return None;
    }
    let radius =
        vertices.iter().map(|v| (v - centroid).norm()).sum::<f64>() / vertices.len() as f64;
    let on_sphere = triangles.iter().zip(corner_normals).all(|(t, normals)| {
        t.iter()
            .zip(normals)
            .all(|(&v, n)| (vertices[v as usize] - centroid - n * radius).norm() <= 1e-9 * radius)
    });
    (on_sphere && radius > 0.0).then_some((*centroid, radius))
}

/// The axis-aligned ellipsoid about the volume centroid `c` that a closed mesh's corners and
/// corner normals lie on, if they all do. The inverse squared semi-axes `w` are the least-squares
/// solution of `w · (d ∘ d) = 1` over the vertices (`d = p − c`); every corner must then satisfy
/// it to 1e-9 and carry the unit gradient `w ∘ d / |w ∘ d|` as its normal to 1e-9.
fn implied_ellipsoid(
    closed: bool,
    centroid: &Point3,
    vertices: &[Point3],
    triangles: &[[u32; 3]],
    corner_normals: &[[Vector3; 3]],
) -> Option<(Point3, Vector3)> {
    if !closed || vertices.len() < 6 {
        return None;
    }
    let squares = |p: &Point3| (p - centroid).component_mul(&(p - centroid));
    let (mut normal_matrix, mut rhs) = (nalgebra::Matrix3::<f64>::zeros(), Vector3::zeros());
    for v in vertices {
        let q = squares(v);
        normal_matrix += q * q.transpose();
        rhs += q;
    }
    let w = normal_matrix.lu().solve(&rhs)?;
    if !w.iter().all(|&x| x.is_finite() && x > 0.0) {
        return None;
    }
    let on_ellipsoid = triangles.iter().zip(corner_normals).all(|(t, normals)| {
        t.iter().zip(normals).all(|(&v, n)| {
            let p = vertices[v as usize];
            let gradient = (p - centroid).component_mul(&w);
            (w.dot(&squares(&p)) - 1.0).abs() <= 1e-9 && (gradient.normalize() - n).norm() <= 1e-9
        })
    });
    on_ellipsoid.then(|| (*centroid, w.map(|x| 1.0 / x.sqrt())))
}

/// Permutes the per-triangle arrays to the new numbering (`old_of_new[k]` is the old index of
/// new triangle `k`), renumbers the neighbours to match, and renumbers the vertices in order of
/// first use by the new triangles (unused vertices kept, last, in their old order).
fn into_leaf_order(
    old_of_new: &[u32],
    vertices: &mut Vec<Point3>,
    triangles: &mut Vec<[u32; 3]>,
    neighbors: &mut Vec<[u32; 3]>,
    face_normals: &mut Vec<Vector3>,
    corner_normals: &mut Vec<[Vector3; 3]>,
) {
    let mut new_of_old = vec![0u32; old_of_new.len()];
    for (new, &old) in old_of_new.iter().enumerate() {
        new_of_old[old as usize] = new as u32;
    }
    let mut vertex_new = vec![u32::MAX; vertices.len()];
    let mut new_vertices = Vec::with_capacity(vertices.len());
    let mut new_triangles = Vec::with_capacity(triangles.len());
    for &old in old_of_new {
        let tri = triangles[old as usize].map(|v| {
            if vertex_new[v as usize] == u32::MAX {
                vertex_new[v as usize] = new_vertices.len() as u32;
                new_vertices.push(vertices[v as usize]);
            }
            vertex_new[v as usize]
        });
        new_triangles.push(tri);
    }
    for (v, slot) in vertex_new.iter_mut().enumerate() {
        if *slot == u32::MAX {
            *slot = new_vertices.len() as u32;
            new_vertices.push(vertices[v]);
        }
    }
    let renumber = |n: u32| {
        if n == NO_NEIGHBOR {
            NO_NEIGHBOR
        } else {
            new_of_old[n as usize]
        }
    };
    *neighbors = old_of_new
        .iter()
        .map(|&old| neighbors[old as usize].map(renumber))
        .collect();
    *face_normals = old_of_new
        .iter()
        .map(|&old| face_normals[old as usize])
        .collect();
    *corner_normals = old_of_new
        .iter()
        .map(|&old| corner_normals[old as usize])
        .collect();
    *vertices = new_vertices;
    *triangles = new_triangles;
}
