//! Apex-free sums over surface triangles from which the volume and first moment they enclose
//! with any apex follow (divergence theorem, one tetrahedron per triangle).
//!
//! For a triangle `(a, b, c)` and an apex `o`, the tetrahedron's signed volume is
//! `v = (det(a, b, c) − o·N)/6` with `N = a×b + b×c + c×a`, and its moment
//! `v·(a + b + c + o)/4`. Summing `det`, `N`, `s = a+b+c`, `det·s` and `s·Nᵀ` over triangles
//! lets the apex be chosen after the triangles were visited, so a flood over thousands of
//! triangles only adds numbers.

use contact_core::{Matrix3, Vector3};

/// The running sums (19 numbers).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceSums {
    det: f64,
    n: Vector3,
    s: Vector3,
    det_s: Vector3,
    s_nt: Matrix3,
}

impl Default for SurfaceSums {
    fn default() -> Self {
        Self {
            det: 0.0,
            n: Vector3::zeros(),
            s: Vector3::zeros(),
            det_s: Vector3::zeros(),
            s_nt: Matrix3::zeros(),
        }
    }
}

impl SurfaceSums {
    /// Adds a counter-clockwise (outward) triangle.
    #[inline]
    pub fn add_triangle(&mut self, a: &Vector3, b: &Vector3, c: &Vector3) {
        let det = a.dot(&b.cross(c));
        let n = a.cross(b) + b.cross(c) + c.cross(a);
        let s = a + b + c;
        self.det += det;
        self.n += n;
        self.s += s;
        self.det_s += det * s;
        self.s_nt += s * n.transpose();
    }

    /// Adds a convex polygon as a fan.
    #[inline]
    pub fn add_polygon(&mut self, poly: &[Vector3]) {
        for k in 1..poly.len().saturating_sub(1) {
            self.add_triangle(&poly[0], &poly[k], &poly[k + 1]);
        }
    }

    /// Adds another set of sums.
    #[inline]
    pub fn merge(&mut self, o: &Self) {
        self.det += o.det;
        self.n += o.n;
        self.s += o.s;
        self.det_s += o.det_s;
        self.s_nt += o.s_nt;
    }

    /// The volume and the first moment (about the frame's origin) of the cones from `apex` over
    /// the triangles summed.
    pub fn volume_moment(&self, apex: &Vector3) -> (f64, Vector3) {
        let on = apex.dot(&self.n);
        let volume = (self.det - on) / 6.0;
        let moment = (self.det_s + self.det * apex - self.s_nt * apex - on * apex) / 24.0;
        (volume, moment)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_unit_cube_has_volume_one_and_centroid_at_its_centre_for_any_apex() {
        let v = |x: f64, y: f64, z: f64| Vector3::new(x, y, z);
        let c = [
            v(0., 0., 0.),
            v(1., 0., 0.),
            v(0., 1., 0.),
            v(1., 1., 0.),
            v(0., 0., 1.),
            v(1., 0., 1.),
            v(0., 1., 1.),
            v(1., 1., 1.),
        ];
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let mut sums = SurfaceSums::default();
        for q in quads {
            sums.add_polygon(&q.map(|i| c[i]));
        }
        for apex in [v(0.0, 0.0, 0.0), v(3.0, -2.0, 7.0), v(0.5, 0.5, 0.5)] {
            let (vol, m) = sums.volume_moment(&apex);
            assert!((vol - 1.0).abs() < 1e-12, "{vol}");
            assert!((m / vol - v(0.5, 0.5, 0.5)).norm() < 1e-12, "{m}");
        }
    }
}
