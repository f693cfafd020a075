//! One mesh triangle clipped to the box `|x_k| ≤ h_k` (Sutherland–Hodgman), keeping where
//! each piece of the result came from.
//!
//! - Every vertex carries the set of box planes it lies on (`on`: bit `j` for plane `j`,
//!   [`plane`]). A vertex on two planes of different axes lies on a box edge: that is where the
//!   mesh surface pierces the edge, which the face analysis needs (`super::faces`).
//! - Every polygon edge carries its origin ([`Edge`]): part of the triangle's edge `k`, or a
//!   cut along box plane `j`. A cut is where the mesh surface meets a box face, so it bounds
//!   that face's cap; a kept part of edge `k` joins the triangle to its neighbour across `k`.
//! - A vertex is inside a plane when strictly below it (`d < 0`), so a triangle lying in a
//!   box face, or touching the box only along its surface, gives nothing: the box face's own
//!   cap stands for it, and touching is not a contact. The points where an edge crosses a
//!   plane are computed from the edge's two ends in a fixed (lexicographic) order, so two
//!   triangles sharing an edge get the same bits for the same crossing.

use contact_core::{Point3, Vector3};

/// Box plane `j`: axis `j / 2`, outward sign `+` for even `j`; its signed distance `d =
/// ±x_axis − h_axis` (inside when negative).
pub(crate) fn plane(j: usize) -> (usize, f64) {
    (j / 2, if j.is_multiple_of(2) { 1.0 } else { -1.0 })
}

/// Where a polygon edge came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Edge {
    /// A part of the triangle's edge `k` (from vertex `k` to `k + 1`).
    Triangle(u8),
    /// A cut along box plane `j`.
    Cut(u8),
}

/// The most vertices a triangle clipped by six planes can have.
pub(crate) const MAX_VERTICES: usize = 9;

/// A convex polygon: `points[i]` with the planes it lies on, and the edge from it to the next.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Clipped {
    pub points: [Point3; MAX_VERTICES],
    pub on: [u8; MAX_VERTICES],
    pub edges: [Edge; MAX_VERTICES],
    pub len: usize,
}

impl Clipped {
    /// The triangle `a b c`, before clipping.
    pub fn triangle(a: Point3, b: Point3, c: Point3) -> Self {
        let mut points = [Point3::origin(); MAX_VERTICES];
        points[..3].copy_from_slice(&[a, b, c]);
        let mut edges = [Edge::Triangle(0); MAX_VERTICES];
        edges[1] = Edge::Triangle(1);
        edges[2] = Edge::Triangle(2);
        Self {
            points,
            on: [0; MAX_VERTICES],
            edges,
            len: 3,
        }
    }

    /// Clips by all six planes of the box with half extents `half`; false when nothing is
    /// left (fewer than three vertices).
    pub fn clip_to_box(&mut self, half: &Vector3) -> bool {
        for j in 0..6 {
            let (axis, sign) = plane(j);
            if !self.clip(j, axis, sign, half[axis]) {
                return false;
            }
        }
        true
    }

    /// Clips by plane `j` (`sign·x[axis] < h`).
    fn clip(&mut self, j: usize, axis: usize, sign: f64, h: f64) -> bool {
        let n = self.len;
        let d = |p: &Point3| sign * p[axis] - h;
        let mut distance = [0.0; MAX_VERTICES];
        let mut any_out = false;
        for (slot, p) in distance.iter_mut().zip(&self.points[..n]) {
            *slot = d(p);
            any_out |= *slot >= 0.0;
        }
        if !any_out {
            return true;
        }
        let mut out = Self {
            points: [Point3::origin(); MAX_VERTICES],
            on: [0; MAX_VERTICES],
            edges: [Edge::Cut(j as u8); MAX_VERTICES],
            len: 0,
        };
        let mut push = |p: Point3, on: u8, edge: Edge| {
            // A convex polygon cut by one plane gains at most one vertex.
            if out.len < MAX_VERTICES {
                out.points[out.len] = p;
                out.on[out.len] = on;
                out.edges[out.len] = edge;
                out.len += 1;
            }
        };
        for i in 0..n {
            let k = (i + 1) % n;
            let (p, q) = (self.points[i], self.points[k]);
            let (dp, dq) = (distance[i], distance[k]);
            let p_in = dp < 0.0;
            let q_in = dq < 0.0;
            if p_in {
                push(p, self.on[i], self.edges[i]);
            }
            if p_in != q_in {
                let x = crossing(&p, dp, &q, dq);
                let on = (self.on[i] & self.on[k]) | (1 << j);
                // Leaving: the edge from the crossing runs along the cut; entering: it is the
                // rest of this edge.
                let edge = if p_in {
                    Edge::Cut(j as u8)
                } else {
                    self.edges[i]
                };
                push(x, on, edge);
            }
        }
        *self = out;
        self.len >= 3
    }
}

/// The point where the segment `p q` crosses the plane with signed distances `dp`, `dq` of
/// opposite sides, computed from the lexicographically smaller end so both triangles of an
/// edge get the same bits.
fn crossing(p: &Point3, dp: f64, q: &Point3, dq: f64) -> Point3 {
    let p_first = (p.x, p.y, p.z) < (q.x, q.y, q.z);
    let (a, da, b, db) = if p_first {
        (p, dp, q, dq)
    } else {
        (q, dq, p, dp)
    };
    a + (b - a) * (da / (da - db))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A triangle through a box corner region: the clipped polygon's area matches the
    /// polygon of the triangle's plane inside the unit box computed by hand, and the vertices
    /// on two planes are exactly those on box edges.
    #[test]
    fn a_triangle_cut_by_two_planes_keeps_its_origins() {
        let half = Vector3::new(1.0, 1.0, 1.0);
        // In the plane z = 0, a triangle reaching past x = 1 and y = 1.
        let mut c = Clipped::triangle(
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(3.0, 0.0, 0.0),
            Point3::new(0.0, 3.0, 0.0),
        );
        assert!(c.clip_to_box(&half));
        // The square [0,1]² minus nothing (the hypotenuse x + y = 3 misses it).
        let mut area = 0.0;
        for i in 1..c.len - 1 {
            area += 0.5
                * (c.points[i] - c.points[0])
                    .cross(&(c.points[i + 1] - c.points[0]))
                    .z;
        }
        assert!((area - 1.0).abs() < 1e-15, "{area}");
        let cuts = c.edges[..c.len]
            .iter()
            .filter(|e| matches!(e, Edge::Cut(_)))
            .count();
        assert_eq!(cuts, 2, "{c:?}");
        // (1, 1, 0) lies on the planes x = 1 (bit 0) and y = 1 (bit 2).
        let corner = (0..c.len)
            .find(|&i| (c.points[i] - Point3::new(1.0, 1.0, 0.0)).norm() < 1e-15)
            .unwrap();
        assert_eq!(c.on[corner], 0b101);
    }

    /// Touching only (a vertex on a face) and lying in a face both give nothing.
    #[test]
    fn a_triangle_on_the_surface_gives_nothing() {
        let half = Vector3::new(1.0, 1.0, 1.0);
        let mut touching = Clipped::triangle(
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(2.0, 0.5, 0.0),
            Point3::new(2.0, -0.5, 0.0),
        );
        assert!(!touching.clip_to_box(&half));
        let mut flush = Clipped::triangle(
            Point3::new(-0.5, -0.5, 1.0),
            Point3::new(0.5, -0.5, 1.0),
            Point3::new(0.0, 0.5, 1.0),
        );
        assert!(!flush.clip_to_box(&half));
    }
}
