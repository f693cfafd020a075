//! One slice of two convex solids: a convex polygon clipped by labelled half-planes, with the
//! measures the sliced pairs integrate (area, first moments, and each half-plane's edge
//! length inside the polygon).
//!
//! The polygon starts as the section of the first solid (a rectangle, its four edges labelled
//! 0–3) and is clipped by the second solid's half-planes `g·p ≤ d` (labels 4 on) with
//! Sutherland–Hodgman: every edge of the result keeps the label of the half-plane it lies on,
//! so an edge's length can be charged to the surface it belongs to. An edge on a line two
//! half-planes share keeps the label it had first (the first solid's): a face the two solids
//! share counts as the first solid's surface inside the second.

use contact_core::Vector2;

/// Most half-planes a section has (4 for the first solid, up to 6 for the second).
pub(crate) const MAX_LABELS: usize = 10;
/// Most vertices a clipped polygon has (each clip adds at most one).
const MAX_VERTICES: usize = 4 + MAX_LABELS;

/// A convex polygon, counter-clockwise; edge `k` runs from vertex `k` to `k + 1` and lies on
/// the half-plane `labels[k]`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Polygon {
    vertices: [Vector2; MAX_VERTICES],
    labels: [u8; MAX_VERTICES],
    count: usize,
}

/// What a slice contributes: the polygon's area and first moments, and the length of its
/// boundary on each half-plane.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SectionMeasures {
    /// Area.
    pub area: f64,
    /// `∫ p dA` (both in-plane coordinates).
    pub moment: Vector2,
    /// Edge length on each half-plane, by label.
    pub lengths: [f64; MAX_LABELS],
}

impl Polygon {
    /// The rectangle `|p.x| ≤ half.x`, `|p.y| ≤ half.y` with edges labelled
    /// 0 (`+x`), 1 (`−x`), 2 (`+y`), 3 (`−y`).
    pub fn rectangle(half: Vector2) -> Self {
        let mut vertices = [Vector2::zeros(); MAX_VERTICES];
        vertices[0] = Vector2::new(half.x, -half.y);
        vertices[1] = Vector2::new(half.x, half.y);
        vertices[2] = Vector2::new(-half.x, half.y);
        vertices[3] = Vector2::new(-half.x, -half.y);
        let mut labels = [0; MAX_VERTICES];
        labels[..4].copy_from_slice(&[0, 2, 1, 3]);
        Self {
            vertices,
            labels,
            count: 4,
        }
    }

    /// Keeps the part with `g·p ≤ d`; the new edge (if any) gets `label`.
    pub fn clip(&mut self, g: &Vector2, d: f64, label: u8) {
        // A vertex within round-off of the line counts as on it, so a line through an edge
        // (two solids sharing a face) keeps the edge and its label whatever the round-off.
        // The slack's norms are taken only for a vertex that might be within it: `|x| + |y|`
        // bounds `|p|`, so a vertex beyond the cheap bound is beyond the slack too.
        let g_norm = g.norm();
        let on = |p: &Vector2| {
            let v = g.dot(p) - d;
            let bound = 4.0 * f64::EPSILON * (d.abs() + g_norm * (p.x.abs() + p.y.abs()));
            if v.abs() > bound * (1.0 + 1e-12) {
                return v;
            }
            let slack = 4.0 * f64::EPSILON * (d.abs() + g_norm * p.norm());
            if v.abs() <= slack { 0.0 } else { v }
        };
        // Most lines cut nothing: each vertex's side once, and the polygon kept whole (same
        // vertices and labels) or emptied without rebuilding it.
        let mut sides = [0.0; MAX_VERTICES];
        let (mut any_out, mut all_out) = (false, true);
        for (side, p) in sides.iter_mut().zip(&self.vertices[..self.count]) {
            *side = on(p);
            any_out |= *side > 0.0;
            all_out &= *side > 0.0;
        }
        if !any_out {
            return;
        }
        if all_out {
            self.count = 0;
            return;
        }
        let mut out = [Vector2::zeros(); MAX_VERTICES];
        let mut out_labels = [0u8; MAX_VERTICES];
        let mut n = 0;
        let mut push = |p: Vector2, l: u8, n: &mut usize| {
            if *n < MAX_VERTICES {
                out[*n] = p;
                out_labels[*n] = l;
                *n += 1;
            }
        };
        for k in 0..self.count {
            let next = if k + 1 == self.count { 0 } else { k + 1 };
            let (p, q) = (self.vertices[k], self.vertices[next]);
            let edge = self.labels[k];
            let (dp, dq) = (sides[k], sides[next]);
            if dp <= 0.0 {
                push(p, edge, &mut n);
                if dq > 0.0 {
                    // Leaving: the edge runs to the crossing, then along the clip line.
                    push(p + (q - p) * (dp / (dp - dq)), label, &mut n);
                }
            } else if dq <= 0.0 {
                // Entering: from the crossing the edge runs on along its own line.
                push(p + (q - p) * (dp / (dp - dq)), edge, &mut n);
            }
        }
        self.vertices = out;
        self.labels = out_labels;
        self.count = n;
    }

    /// The vertices, counter-clockwise.
    pub fn vertices(&self) -> &[Vector2] {
        &self.vertices[..self.count]
    }

    /// Each edge's label (edge `k` runs from vertex `k` to `k + 1`).
    pub fn labels(&self) -> &[u8] {
        &self.labels[..self.count]
    }

    /// Area (about the first vertex, so a sliver far from the origin keeps its precision).
    pub fn area(&self) -> f64 {
        if self.count < 3 {
            return 0.0;
        }
        let o = self.vertices[0];
        let mut twice = 0.0;
        for k in 1..self.count - 1 {
            let (a, b) = (self.vertices[k] - o, self.vertices[k + 1] - o);
            twice += a.x * b.y - b.x * a.y;
        }
        (0.5 * twice).max(0.0)
    }

    /// Area, first moments and the edge length on each half-plane.
    pub fn measures(&self) -> SectionMeasures {
        let mut lengths = [0.0; MAX_LABELS];
        let mut m = SectionMeasures {
            area: 0.0,
            moment: Vector2::zeros(),
            lengths,
        };
        if self.count < 3 {
            return m;
        }
        let o = self.vertices[0];
        let (mut twice, mut sum_x, mut sum_y) = (0.0, 0.0, 0.0);
        for k in 1..self.count - 1 {
            let (a, b) = (self.vertices[k] - o, self.vertices[k + 1] - o);
            let cross = a.x * b.y - b.x * a.y;
            twice += cross;
            sum_x += (a.x + b.x) * cross;
            sum_y += (a.y + b.y) * cross;
        }
        let area = 0.5 * twice;
        if area.is_nan() || area <= 0.0 {
            return m;
        }
        for k in 0..self.count {
            let edge = self.vertices[(k + 1) % self.count] - self.vertices[k];
            if let Some(l) = lengths.get_mut(self.labels[k] as usize) {
                *l += edge.norm();
            }
        }
        m.area = area;
        m.moment = Vector2::new(area * o.x + sum_x / 6.0, area * o.y + sum_y / 6.0);
        m.lengths = lengths;
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit square clipped by the diagonal `x + y ≤ 0`: the triangle below it, its moments
    /// and edge lengths by hand.
    #[test]
    fn a_square_cut_by_its_diagonal() {
        let mut p = Polygon::rectangle(Vector2::new(1.0, 1.0));
        let g = Vector2::new(1.0, 1.0) / 2f64.sqrt();
        p.clip(&g, 0.0, 4);
        let m = p.measures();
        assert!((m.area - 2.0).abs() < 1e-15, "{m:?}");
        // Centroid of the triangle (1,−1), (−1,1), (−1,−1): (−1/3, −1/3).
        assert!((m.moment - Vector2::new(-2.0 / 3.0, -2.0 / 3.0)).norm() < 1e-15);
        let expected = [0.0, 2.0, 0.0, 2.0, 8f64.sqrt()];
        for (k, e) in expected.iter().enumerate() {
            assert!((m.lengths[k] - e).abs() < 1e-15, "{k}: {m:?}");
        }
    }

    /// Clipping by a line outside keeps everything; by one beyond the polygon, nothing.
    #[test]
    fn clipping_outside_or_beyond() {
        let mut p = Polygon::rectangle(Vector2::new(1.0, 2.0));
        p.clip(&Vector2::x(), 3.0, 4);
        assert!((p.area() - 8.0).abs() < 1e-15);
        assert_eq!(p.measures().lengths[4], 0.0);
        p.clip(&Vector2::x(), -1.5, 5);
        assert_eq!(p.area(), 0.0);
    }
}
