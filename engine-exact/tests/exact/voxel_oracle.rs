//! Meshes made of grid cells, and the closed form of their contact with a box aligned with
//! the grid: the intersection is a union of cell–box overlaps (boxes), so its regions,
//! volume and centroid are sums of interval products, the mesh surface inside the box is a
//! sum of clipped face rectangles, and the line through the centroid meets the cell faces at
//! closed-form parameters. Written apart from the engine's clipping.

use crate::common::Expected;
use contact_core::geometry::TriangleMesh;
use contact_core::{Point3, Vector3};
use std::collections::HashMap;

/// A set of unit cells `(i, j, k)` (the cell `[i, i+1] × [j, j+1] × [k, k+1]` times `size`).
/// No two cells may touch along an edge only (the surface would not be a 2-manifold).
pub struct Voxels {
    pub cells: Vec<[i32; 3]>,
    pub size: f64,
}

/// An axis-aligned box `[lo, hi]`.
#[derive(Debug, Clone, Copy)]
pub struct Aabb {
    pub lo: Point3,
    pub hi: Point3,
}

impl Aabb {
    pub fn centre(&self) -> Point3 {
        nalgebra::center(&self.lo, &self.hi)
    }

    pub fn half(&self) -> Vector3 {
        0.5 * (self.hi - self.lo)
    }
}

/// One boundary face of the cells: the cell, the axis and the outward sign.
struct Face {
    cell: usize,
    axis: usize,
    sign: f64,
}

impl Voxels {
    fn has(&self, c: [i32; 3]) -> bool {
        self.cells.contains(&c)
    }

    fn cell_box(&self, c: [i32; 3]) -> Aabb {
        let lo = Point3::new(c[0] as f64, c[1] as f64, c[2] as f64) * self.size;
        Aabb {
            lo,
            hi: lo + Vector3::repeat(self.size),
        }
    }

    fn faces(&self) -> Vec<Face> {
        let mut out = Vec::new();
        for (i, c) in self.cells.iter().enumerate() {
            for axis in 0..3 {
                for sign in [1.0, -1.0] {
                    let mut n = *c;
                    n[axis] += sign as i32;
                    if !self.has(n) {
                        out.push(Face {
                            cell: i,
                            axis,
                            sign,
                        });
                    }
                }
            }
        }
        out
    }

    /// The face's rectangle: its plane coordinate and its extents on the other two axes.
    fn face_rect(&self, f: &Face) -> (f64, Aabb) {
        let b = self.cell_box(self.cells[f.cell]);
        let x = if f.sign > 0.0 {
            b.hi[f.axis]
        } else {
            b.lo[f.axis]
        };
        (x, b)
    }

    /// The closed, outward-oriented triangle mesh of the cells' surface (two triangles per
    /// boundary face, corners welded on the grid).
    pub fn mesh(&self) -> TriangleMesh {
        let mut index: HashMap<[i32; 3], u32> = HashMap::new();
        let mut vertices = Vec::new();
        let mut triangles = Vec::new();
        let mut vertex = |p: [i32; 3], vertices: &mut Vec<Point3>| -> u32 {
            *index.entry(p).or_insert_with(|| {
                vertices.push(Point3::new(p[0] as f64, p[1] as f64, p[2] as f64) * self.size);
                (vertices.len() - 1) as u32
            })
        };
        for f in self.faces() {
            let c = self.cells[f.cell];
            let (u, v) = ((f.axis + 1) % 3, (f.axis + 2) % 3);
            let mut base = c;
            if f.sign > 0.0 {
                base[f.axis] += 1;
            }
            let corner = |du: i32, dv: i32| {
                let mut p = base;
                p[u] += du;
                p[v] += dv;
                p
            };
            // Counter-clockwise about +axis in (u, v); reversed for the −axis faces.
            let mut quad = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)];
            if f.sign < 0.0 {
                quad.reverse();
            }
            let q = quad.map(|p| vertex(p, &mut vertices));
            triangles.push([q[0], q[1], q[2]]);
            triangles.push([q[0], q[2], q[3]]);
        }
        TriangleMesh::new(vertices, triangles).unwrap()
    }

    /// The contacts of the box `b` (I) with the cells (J) in the cells' frame, one per region
    /// (cells overlapping `b` joined across shared faces), in no particular order; `None`
    /// for a region whose mesh surface inside `b` has no net area vector (the closed form
    /// here covers the regular branch only).
    pub fn contacts(&self, b: &Aabb) -> Vec<Option<Expected>> {
        let overlap = |c: &Aabb| -> Option<Aabb> {
            let lo = Point3::new(c.lo.x.max(b.lo.x), c.lo.y.max(b.lo.y), c.lo.z.max(b.lo.z));
            let hi = Point3::new(c.hi.x.min(b.hi.x), c.hi.y.min(b.hi.y), c.hi.z.min(b.hi.z));
            (0..3).all(|k| hi[k] > lo[k]).then_some(Aabb { lo, hi })
        };
        let n = self.cells.len();
        let parts: Vec<Option<Aabb>> = self
            .cells
            .iter()
            .map(|&c| overlap(&self.cell_box(c)))
            .collect();
        let mut region = self.regions(&parts);
        let faces = self.faces();
        let mut out = Vec::new();
        for r in 0..n {
            if parts[r].is_none() || root(&mut region, r) != r {
                continue;
            }
            let mut volume = 0.0;
            let mut moment = Vector3::zeros();
            for (a, p) in parts.iter().enumerate() {
                if let Some(p) = p {
                    if root(&mut region, a) == r {
                        let v = (p.hi - p.lo).product();
                        volume += v;
                        moment += v * p.centre().coords;
                    }
                }
            }
            let centroid = Point3::from(moment / volume);
            // The mesh surface inside the box.
            let mut s = Vector3::zeros();
            for f in &faces {
                if parts[f.cell].is_none() || root(&mut region, f.cell) != r {
                    continue;
                }
                let (x, rect) = self.face_rect(f);
                if !(b.lo[f.axis] < x && x < b.hi[f.axis]) {
                    continue;
                }
                let (u, v) = ((f.axis + 1) % 3, (f.axis + 2) % 3);
                let side = |k: usize| (rect.hi[k].min(b.hi[k]) - rect.lo[k].max(b.lo[k])).max(0.0);
                s[f.axis] += f.sign * side(u) * side(v);
            }
            if s.norm() == 0.0 {
                out.push(None);
                continue;
            }
            let normal = s.normalize();
            // Leaving the box along −n.
            let mut to_box = f64::INFINITY;
            for k in 0..3 {
                if normal[k] > 0.0 {
                    to_box = to_box.min((centroid[k] - b.lo[k]) / normal[k]);
                } else if normal[k] < 0.0 {
                    to_box = to_box.min((centroid[k] - b.hi[k]) / normal[k]);
                }
            }
            let point_i = centroid - to_box * normal;
            let point_j = self.surface_point_along(&faces, &centroid, &normal);
            out.push(Some(Expected {
                point_i,
                point_j,
                normal,
                depth: (point_j - point_i).norm(),
            }));
        }
        out
    }

    /// The first cell face the line from `centroid` along `normal` meets (`+n`), or, for a
    /// centroid outside the cells (an L-shaped region) whose line misses them, the closest
    /// point of their surface.
    fn surface_point_along(&self, faces: &[Face], centroid: &Point3, normal: &Vector3) -> Point3 {
        // The first cell face the line meets along +n.
        let mut to_mesh = f64::INFINITY;
        for f in faces {
            if normal[f.axis] == 0.0 {
                continue;
            }
            let (x, rect) = self.face_rect(f);
            let t = (x - centroid[f.axis]) / normal[f.axis];
            if t < 0.0 || t >= to_mesh {
                continue;
            }
            let hit = centroid + t * *normal;
            let (u, v) = ((f.axis + 1) % 3, (f.axis + 2) % 3);
            if (rect.lo[u]..=rect.hi[u]).contains(&hit[u])
                && (rect.lo[v]..=rect.hi[v]).contains(&hit[v])
            {
                to_mesh = t;
            }
        }
        // A centroid outside the cells (an L-shaped region) whose line misses them: the
        // closest point of their surface.
        if to_mesh.is_finite() {
            centroid + to_mesh * *normal
        } else {
            let mut best = (f64::INFINITY, *centroid);
            for f in faces {
                let (x, rect) = self.face_rect(f);
                let mut q = *centroid;
                for k in 0..3 {
                    q[k] = if k == f.axis {
                        x
                    } else {
                        q[k].clamp(rect.lo[k], rect.hi[k])
                    };
                }
                let d = (q - centroid).norm();
                if d < best.0 {
                    best = (d, q);
                }
            }
            best.1
        }
    }

    /// The axes along which a face of the box `b` lies on a cell face over a positive area, as
    /// bits: `(flush, touching)`, flush where both face the same way (the common patch bounds
    /// the intersection and belongs to both surfaces), touching where they face each other
    /// (no volume between them).
    pub fn coplanar_axes(&self, b: &Aabb) -> (u8, u8) {
        let (mut flush, mut touching) = (0, 0);
        for f in self.faces() {
            let (x, rect) = self.face_rect(&f);
            let (u, v) = ((f.axis + 1) % 3, (f.axis + 2) % 3);
            let overlap = |k: usize| rect.hi[k].min(b.hi[k]) > rect.lo[k].max(b.lo[k]);
            if !(overlap(u) && overlap(v)) {
                continue;
            }
            let (same, facing) = if f.sign > 0.0 {
                (b.hi[f.axis], b.lo[f.axis])
            } else {
                (b.lo[f.axis], b.hi[f.axis])
            };
            if same == x {
                flush |= 1 << f.axis;
            }
            if facing == x {
                touching |= 1 << f.axis;
            }
        }
        (flush, touching)
    }

    /// The region label of each cell, as [`root`] reads it: overlapping (`parts` not `None`)
    /// face neighbours are joined.
    fn regions(&self, parts: &[Option<Aabb>]) -> Vec<usize> {
        let n = self.cells.len();
        let mut region: Vec<usize> = (0..n).collect();
        for a in 0..n {
            for b2 in 0..n {
                let d: i32 = (0..3)
                    .map(|k| (self.cells[a][k] - self.cells[b2][k]).abs())
                    .sum();
                if d == 1 && parts[a].is_some() && parts[b2].is_some() {
                    let (ra, rb) = (root(&mut region, a), root(&mut region, b2));
                    region[ra.max(rb)] = ra.min(rb);
                }
            }
        }
        region
    }
}

/// The root of cell `a`'s region in the labels `region`.
fn root(region: &mut [usize], mut a: usize) -> usize {
    while region[a] != a {
        a = region[a];
    }
    a
}
