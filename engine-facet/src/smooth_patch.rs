//! The smooth surface a tessellated primitive's facets stand for, one triangle at a time.
//!
//! A tessellated primitive keeps the true surface normal at each triangle corner. Two
//! surfaces follow from the corners and those normals, both continuous across the triangles'
//! shared edges (corners and corner normals are shared):
//!
//! - the **curved PN triangle** (Vlachos et al., 2001): the cubic Bézier patch
//!   `b(w, u, v) = Σ b_ijk · 3!/(i! j! k!) · wⁱ uʲ vᵏ` whose edge control points are the corners
//!   moved a third of the way along each edge and projected on the corner's tangent plane,
//!   `b_210 = (2p₁ + p₂ − ((p₂ − p₁)·n₁)·n₁)/3`, and whose centre is
//!   `b_111 = E + (E − V)/2` (`E` the mean of the six edge points, `V` of the corners). Every
//!   point of the patch is a convex combination of its ten control points;
//! - the **Phong normal field** `n(w, u, v) = w·n₁ + u·n₂ + v·n₃` (unnormalised) over the flat
//!   triangle. On a sphere `n_i = (p_i − c)/R`, so `n(w, u, v) = (p(w, u, v) − c)/R`: the point
//!   of the flat triangle where the field points along a direction `d` lies exactly on the
//!   ray from the centre along `d`.
//!
//! [`support`] finds that point (the smooth surface's support point in direction `d`), and
//! [`principal_curvatures`] the shape operator `dn = S·dp` the corner normals imply, in the
//! plane normal to `d`. For a sphere both are exact (`S = I/R`); for other smooth surfaces
//! the field and `S` carry the interpolation's error, `O(h²)` in the facet size `h`.

use contact_core::Vector3;

/// The ten control points of the curved PN triangle over corners `p` with normals `n`, in the
/// order `b300, b030, b003, b210, b120, b021, b012, b102, b201, b111`.
pub(crate) fn pn_control_points(p: &[Vector3; 3], n: &[Vector3; 3]) -> [Vector3; 10] {
    let edge =
        |pi: &Vector3, pj: &Vector3, ni: &Vector3| (2.0 * pi + pj - (pj - pi).dot(ni) * ni) / 3.0;
    let b210 = edge(&p[0], &p[1], &n[0]);
    let b120 = edge(&p[1], &p[0], &n[1]);
    let b021 = edge(&p[1], &p[2], &n[1]);
    let b012 = edge(&p[2], &p[1], &n[2]);
    let b102 = edge(&p[2], &p[0], &n[2]);
    let b201 = edge(&p[0], &p[2], &n[0]);
    let e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
    let centre = (p[0] + p[1] + p[2]) / 3.0;
    let b111 = e + 0.5 * (e - centre);
    [p[0], p[1], p[2], b210, b120, b021, b012, b102, b201, b111]
}

/// The PN patch at barycentric coordinates `(w, u, v)` (`w` on corner 1, `u` on 2, `v` on 3).
pub(crate) fn pn_point(b: &[Vector3; 10], [w, u, v]: [f64; 3]) -> Vector3 {
    b[0] * (w * w * w)
        + b[1] * (u * u * u)
        + b[2] * (v * v * v)
        + b[3] * (3.0 * w * w * u)
        + b[4] * (3.0 * w * u * u)
        + b[8] * (3.0 * w * w * v)
        + b[5] * (3.0 * u * u * v)
        + b[7] * (3.0 * w * v * v)
        + b[6] * (3.0 * u * v * v)
        + b[9] * (6.0 * w * u * v)
}

/// How far the PN patch can reach from the flat triangle: the largest distance of a control
/// point from the point of the flat triangle with the same barycentric weights. Every point of
/// the patch lies within it of the flat triangle (both are the same convex combinations).
pub(crate) fn pn_reach(p: &[Vector3; 3], n: &[Vector3; 3]) -> f64 {
    let b = pn_control_points(p, n);
    let flat = |w: f64, u: f64, v: f64| p[0] * w + p[1] * u + p[2] * v;
    let third = 1.0 / 3.0;
    let at = [
        flat(2.0 * third, third, 0.0),
        flat(third, 2.0 * third, 0.0),
        flat(0.0, 2.0 * third, third),
        flat(0.0, third, 2.0 * third),
        flat(third, 0.0, 2.0 * third),
        flat(2.0 * third, 0.0, third),
        flat(third, third, third),
    ];
    (3..10)
        .map(|k| (b[k] - at[k - 3]).norm())
        .fold(0.0, f64::max)
}

/// The barycentric coordinates of the point of the flat triangle where the Phong normal field
/// of corner normals `n` points along `d` (`d` in the cone of the three normals), or `None`
/// when `d` lies outside that cone, the normals are all but coplanar (a flat face, a
/// cylinder's side) or the field turns against the triangle's orientation `face_normal`
/// (a saddle or a concave part, where the point is no support point).
pub(crate) fn support(n: &[Vector3; 3], face_normal: &Vector3, d: &Vector3) -> Option<[f64; 3]> {
    // Positive Gaussian curvature: the field turns the same way round as the triangle.
    let turn = (n[1] - n[0]).cross(&(n[2] - n[0]));
    if turn.dot(face_normal) <= 1e-12 {
        return None;
    }
    let det = n[0].dot(&n[1].cross(&n[2]));
    if det.abs() <= 1e-14 {
        return None;
    }
    // Cramer's rule for n₁·w + n₂·u + n₃·v = s·d.
    let w = d.dot(&n[1].cross(&n[2])) / det;
    let u = n[0].dot(&d.cross(&n[2])) / det;
    let v = n[0].dot(&n[1].cross(d)) / det;
    let sum = w + u + v;
    if sum <= 0.0 {
        return None;
    }
    let slack = -1e-12 * sum;
    (w >= slack && u >= slack && v >= slack)
        .then(|| [w / sum, u / sum, v / sum].map(|x| x.max(0.0)))
}

/// The principal curvatures `κ₁ ≤ κ₂` of the shape operator the corner normals imply, in the
/// plane normal to `axis`: the 2×2 map `S` with `n_j − n_1 = S·(p_j − p_1)` for the two edges
/// from corner 1 (both projected on the plane), symmetrised. `None` for a degenerate triangle.
pub(crate) fn principal_curvatures(
    p: &[Vector3; 3],
    n: &[Vector3; 3],
    axis: &Vector3,
) -> Option<(f64, f64)> {
    let ex = axis.cross(&Vector3::x());
    let ex = if ex.norm_squared() > 1e-6 {
        ex.normalize()
    } else {
        axis.cross(&Vector3::y()).normalize()
    };
    let ey = axis.cross(&ex);
    let flat = |v: Vector3| [v.dot(&ex), v.dot(&ey)];
    let [e1, e2] = [flat(p[1] - p[0]), flat(p[2] - p[0])];
    let [f1, f2] = [flat(n[1] - n[0]), flat(n[2] - n[0])];
    let det = e1[0] * e2[1] - e2[0] * e1[1];
    if det.abs() <= 1e-300 || !det.is_finite() {
        return None;
    }
    // S = F·E⁻¹ with E = [e1 e2], F = [f1 f2] as columns.
    let inv = [[e2[1] / det, -e2[0] / det], [-e1[1] / det, e1[0] / det]];
    let s = |r: usize, c: usize| f1[r] * inv[0][c] + f2[r] * inv[1][c];
    let (a, d) = (s(0, 0), s(1, 1));
    let b = 0.5 * (s(0, 1) + s(1, 0));
    let mean = 0.5 * (a + d);
    let spread = (0.25 * (a - d) * (a - d) + b * b).sqrt();
    let (k1, k2) = (mean - spread, mean + spread);
    (k1.is_finite() && k2.is_finite()).then_some((k1, k2))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A triangle on the sphere of radius `r` about `c`, its corners at the given unit
    /// directions, with the sphere's normals.
    fn on_sphere(c: Vector3, r: f64, dirs: [Vector3; 3]) -> ([Vector3; 3], [Vector3; 3]) {
        let n = dirs.map(|d| d.normalize());
        (n.map(|d| c + d * r), n)
    }

    #[test]
    fn sphere_support_lies_on_the_ray_from_the_centre() {
        let c = Vector3::new(0.3, -1.2, 2.0);
        let (p, n) = on_sphere(
            c,
            2.5,
            [
                Vector3::new(0.1, 0.05, -1.0),
                Vector3::new(-0.12, 0.1, -1.0),
                Vector3::new(0.02, -0.15, -1.0),
            ],
        );
        let face = (p[1] - p[0]).cross(&(p[2] - p[0])).normalize();
        let d = Vector3::new(0.01, -0.02, -1.0).normalize();
        let bary = support(&n, &face, &d).expect("d inside the cone");
        let flat = p[0] * bary[0] + p[1] * bary[1] + p[2] * bary[2];
        let off_ray = (flat - c).cross(&d).norm();
        assert!(off_ray < 1e-13, "{off_ray:e}");
        let (k1, k2) = principal_curvatures(&p, &n, &d).expect("curvatures");
        assert!(
            (k1 - 0.4).abs() < 1e-12 && (k2 - 0.4).abs() < 1e-12,
            "{k1} {k2}"
        );
        // Outside the cone and turned the other way round: no support.
        assert!(support(&n, &face, &Vector3::new(1.0, 0.0, -0.2).normalize()).is_none());
        assert!(support(&n, &-face, &d).is_none());
    }

    #[test]
    fn pn_patch_stays_within_its_reach_and_near_the_sphere() {
        let (p, n) = on_sphere(
            Vector3::zeros(),
            1.0,
            [
                Vector3::new(0.2, 0.0, -1.0),
                Vector3::new(-0.1, 0.17, -1.0),
                Vector3::new(-0.1, -0.17, -1.0),
            ],
        );
        let b = pn_control_points(&p, &n);
        let reach = pn_reach(&p, &n);
        let mut worst_sphere: f64 = 0.0;
        for i in 0..=20 {
            for j in 0..=20 - i {
                let (u, v) = (i as f64 / 20.0, j as f64 / 20.0);
                let w = 1.0 - u - v;
                let q = pn_point(&b, [w, u, v]);
                let flat = p[0] * w + p[1] * u + p[2] * v;
                assert!((q - flat).norm() <= reach + 1e-15);
                worst_sphere = worst_sphere.max((q.norm() - 1.0).abs());
            }
        }
        // The flat triangle sags ~7e-3 below the unit sphere; the patch is far closer.
        let sag = 1.0 - ((p[0] + p[1] + p[2]) / 3.0).norm();
        assert!(worst_sphere < 0.1 * sag, "{worst_sphere:e} against {sag:e}");
        // Corners are interpolated.
        assert!((pn_point(&b, [1.0, 0.0, 0.0]) - p[0]).norm() < 1e-15);
    }
}
