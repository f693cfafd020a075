//! Triangles whose three points lie on one line, left where a face's parameter space maps a
//! segment to a point (a cone's apex, a sphere's pole): the triangulation joins the pole to
//! two points of one generator line, which in space is a triangle of no area. Each is split
//! away with its neighbour across its longest edge, which covers exactly the same surface.

use contact_core::Point3;
use std::collections::HashMap;

/// Twice the area of a triangle.
fn double_area(p: &[Point3], t: [u32; 3]) -> f64 {
    let [a, b, c] = t.map(|i| p[i as usize]);
    (b - a).cross(&(c - a)).norm()
}

/// Replaces every triangle of (relatively) no area — below `1e-16 L²`, L the diagonal of the
/// points' box — and its neighbour across its longest edge by two triangles through the
/// middle point: `(x, m, y)` and `(x, y, r)` become `(x, m, r)` and `(m, y, r)`. The
/// directed edges the mesh loses (x→y, y→x) and gains (m→r, r→m) pair up, so a closed,
/// consistently oriented mesh stays so. Triangles with a repeated vertex or no neighbour are
/// left as they are.
pub fn split_slivers(points: &[Point3], triangles: &mut [[u32; 3]]) {
    let (mut lo, mut hi) = (points[0], points[0]);
    for p in points {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    let limit = 2e-16 * (hi - lo).norm_squared();
    let mut by_edge: HashMap<(u32, u32), usize> = HashMap::with_capacity(triangles.len() * 3);
    for (k, t) in triangles.iter().enumerate() {
        for e in 0..3 {
            by_edge.insert((t[e], t[(e + 1) % 3]), k);
        }
    }
    for _ in 0..4 {
        let mut changed = false;
        for k in 0..triangles.len() {
            let t = triangles[k];
            if t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || double_area(points, t) > limit {
                continue;
            }
            // m: the vertex opposite the longest edge.
            let len = |e: usize| (points[t[e] as usize] - points[t[(e + 1) % 3] as usize]).norm();
            let long = (0..3)
                .max_by(|&a, &b| len(a).total_cmp(&len(b)))
                .unwrap_or(0);
            let (y, x, m) = (t[long], t[(long + 1) % 3], t[(long + 2) % 3]);
            let Some(&n) = by_edge.get(&(x, y)) else {
                continue;
            };
            let nt = triangles[n];
            let Some(r) = nt.iter().copied().find(|&v| v != x && v != y) else {
                continue;
            };
            if r == m || n == k {
                continue;
            }
            for tri in [t, nt] {
                for e in 0..3 {
                    by_edge.remove(&(tri[e], tri[(e + 1) % 3]));
                }
            }
            triangles[k] = [x, m, r];
            triangles[n] = [m, y, r];
            for (idx, tri) in [(k, triangles[k]), (n, triangles[n])] {
                for e in 0..3 {
                    by_edge.insert((tri[e], tri[(e + 1) % 3]), idx);
                }
            }
            changed = true;
        }
        if !changed {
            break;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Directed edges without their reverse: a mesh's open boundary.
    fn boundary(t: &[[u32; 3]]) -> Vec<(u32, u32)> {
        let all: Vec<(u32, u32)> = t
            .iter()
            .flat_map(|t| (0..3).map(move |e| (t[e], t[(e + 1) % 3])))
            .collect();
        let mut out: Vec<_> = all
            .iter()
            .copied()
            .filter(|&(a, b)| !all.contains(&(b, a)))
            .collect();
        out.sort_unstable();
        out
    }

    #[test]
    fn a_sliver_at_a_pole_is_split_with_its_neighbour_and_the_boundary_is_kept() {
        // Apex 0, a point 3 midway down the generator 0-1: the triangle (0, 3, 1) has no
        // area; its neighbour across 1-0 is (0, 1, 4).
        let p = vec![
            Point3::new(0.0, 0.0, 1.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(0.5, 0.0, 0.5),
            Point3::new(0.0, -1.0, 0.0),
        ];
        let mut t = vec![[0, 3, 1], [0, 1, 4]];
        let before = boundary(&t);
        split_slivers(&p, &mut t);
        assert_eq!(t, vec![[0, 3, 4], [3, 1, 4]]);
        assert!(t.iter().all(|&tri| double_area(&p, tri) > 1e-6), "{t:?}");
        assert_eq!(boundary(&t), before);
    }
}
