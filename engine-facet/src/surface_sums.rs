//! Volume and first moment enclosed by surface triangles, as cones from one apex (divergence
//! theorem, one tetrahedron per triangle).
//!
//! For a triangle `(a, b, c)` and the apex `o`, the tetrahedron's signed volume is
//! `v = (a−o)·((b−o)×(c−o))/6` and its moment about `o` is `v·((a−o)+(b−o)+(c−o))/4`. Summed over
//! a closed surface (or over pieces that, with a lid through `o`, close it) these give the
//! enclosed volume and `volume × (centroid − o)`. One apex per contact region for both meshes
//! (the region's loop centroid) keeps round-off relative to the contact's size, not the
//! bodies'.

use contact_core::Vector3;

/// Running volume and moment about the apex.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SurfaceSums {
    /// Signed volume.
    pub volume: f64,
    /// First moment about the apex.
    pub moment: Vector3,
}

impl SurfaceSums {
    /// Adds the cone from `apex` over a counter-clockwise (outward) triangle.
    #[inline]
    pub fn add_triangle(&mut self, a: &Vector3, b: &Vector3, c: &Vector3, apex: &Vector3) {
        let (p, q, r) = (a - apex, b - apex, c - apex);
        let v = p.dot(&q.cross(&r)) / 6.0;
        self.volume += v;
        self.moment += (0.25 * v) * (p + q + r);
    }

    /// Adds a convex polygon as a fan.
    #[inline]
    pub fn add_polygon(&mut self, poly: &[Vector3], apex: &Vector3) {
        for k in 1..poly.len().saturating_sub(1) {
            self.add_triangle(&poly[0], &poly[k], &poly[k + 1], apex);
        }
    }

    /// Adds another set of sums taken about the same apex, in the same frame.
    #[inline]
    pub fn merge(&mut self, o: &Self) {
        self.volume += o.volume;
        self.moment += o.moment;
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
        for apex in [v(0.0, 0.0, 0.0), v(3.0, -2.0, 7.0), v(0.5, 0.5, 0.5)] {
            let mut sums = SurfaceSums::default();
            for q in quads {
                sums.add_polygon(&q.map(|i| c[i]), &apex);
            }
            assert!((sums.volume - 1.0).abs() < 1e-12, "{}", sums.volume);
            let centroid = apex + sums.moment / sums.volume;
            assert!((centroid - v(0.5, 0.5, 0.5)).norm() < 1e-12, "{centroid}");
        }
    }
}
