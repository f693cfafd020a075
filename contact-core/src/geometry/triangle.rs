//! Small triangle utilities both engines share.

use crate::{Point3, Vector3};

/// The point of triangle `a b c` closest to `p` (Ericson, *Real-Time Collision Detection*
/// §5.1.5): the Voronoi region of `p` (a vertex, an edge or the face) picks the answer. A
/// degenerate triangle is handled by the vertex and edge regions.
pub fn closest_point_on_triangle(p: &Point3, a: &Point3, b: &Point3, c: &Point3) -> Point3 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(&ap), ac.dot(&ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return *a;
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(&bp), ac.dot(&bp));
    if d3 >= 0.0 && d4 <= d3 {
        return *b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(&cp), ac.dot(&cp));
    if d6 >= 0.0 && d5 <= d6 {
        return *c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    // The face: `p` projected on the plane. The barycentric weights `va, vb, vc` above are
    // differences of products of dot products, which lose digits when `p` lies far off the
    // face or near an edge (1e-12 of the triangle's size was seen); the projection keeps them.
    let n = ab.cross(&ac);
    p - n * (ap.dot(&n) / n.norm_squared())
}

/// The parameter `s` at which the line `p + s·dir` meets triangle `a b c` (Möller–Trumbore),
/// with the barycentric bounds widened by `widen` so a line through a shared edge or corner
/// meets at least one of its triangles despite round-off; `None` when it misses or runs
/// parallel to the triangle. `s` may be negative (behind `p`).
pub fn line_triangle(
    p: &Vector3,
    dir: &Vector3,
    a: &Vector3,
    b: &Vector3,
    c: &Vector3,
    widen: f64,
) -> Option<f64> {
    let (e1, e2) = (b - a, c - a);
    let h = dir.cross(&e2);
    let det = e1.dot(&h);
    if det.abs() <= 1e-14 * e1.norm() * e2.norm() {
        return None;
    }
    let inv = 1.0 / det;
    let s = p - a;
    let u = s.dot(&h) * inv;
    let q = s.cross(&e1);
    let v = dir.dot(&q) * inv;
    (u >= -widen && v >= -widen && u + v <= 1.0 + widen).then(|| e2.dot(&q) * inv)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_voronoi_region_against_brute_force() {
        let (a, b, c) = (
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(0.5, 1.5, 0.0),
        );
        // Brute force over a fine barycentric grid.
        let brute = |p: &Point3| {
            let mut best = (f64::INFINITY, a);
            let n = 400;
            for i in 0..=n {
                for j in 0..=n - i {
                    let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                    let q = a + (b - a) * u + (c - a) * v;
                    let d = (q - p).norm();
                    if d < best.0 {
                        best = (d, q);
                    }
                }
            }
            best.0
        };
        for p in [
            Point3::new(-1.0, -1.0, 0.3),
            Point3::new(3.0, -0.5, -0.2),
            Point3::new(0.2, 3.0, 1.0),
            Point3::new(1.0, -1.0, 0.0),
            Point3::new(-1.0, 1.0, 0.5),
            Point3::new(2.0, 1.5, 0.0),
            Point3::new(0.8, 0.5, 0.7),
        ] {
            let q = closest_point_on_triangle(&p, &a, &b, &c);
            assert!(((q - p).norm() - brute(&p)).abs() < 1e-2, "{p}");
        }
    }
}
