//! Oriented bounding boxes: fitting to triangles and the 15-axis separating-axis test.

use contact_core::{Matrix3, Point3, Vector3};

/// An oriented box in a mesh's frame: `center`, the box axes as the columns of `axes` (a
/// rotation), and the half extents along them (each ≥ 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Obb {
    /// The centre.
    pub center: Vector3,
    /// Box axes as columns (orthonormal, right-handed).
    pub axes: Matrix3,
    /// Half extents along the axes.
    pub half_extents: Vector3,
}

impl Obb {
    /// Fits a box to the points: axes from the eigenvectors of the points' covariance (the
    /// principal directions), extents from the points' projections. Degenerate point sets (all on
    /// a line or a point) still give a valid box: the eigen solver returns an orthonormal basis.
    pub fn fit(points: impl Iterator<Item = Point3> + Clone) -> Self {
        let mut count = 0.0;
        let mut sum = Vector3::zeros();
        for p in points.clone() {
            sum += p.coords;
            count += 1.0;
        }
        let mean = if count > 0.0 { sum / count } else { sum };
        let mut cov = Matrix3::zeros();
        for p in points.clone() {
            let d = p.coords - mean;
            cov += d * d.transpose();
        }
        let eig = nalgebra::SymmetricEigen::new(cov);
        let mut axes = eig.eigenvectors;
        if axes.determinant() < 0.0 {
            axes.set_column(2, &(-axes.column(2)));
        }
        Self::fit_with_axes(points, axes)
    }

    /// The tightest box with the given axes (columns, orthonormal) around the points.
    pub fn fit_with_axes(points: impl Iterator<Item = Point3>, axes: Matrix3) -> Self {
        let mut lo = Vector3::repeat(f64::INFINITY);
        let mut hi = Vector3::repeat(f64::NEG_INFINITY);
        let axes_t = axes.transpose();
        for p in points {
            let q = axes_t * p.coords;
            lo = lo.inf(&q);
            hi = hi.sup(&q);
        }
        if lo.x > hi.x {
            lo = Vector3::zeros();
            hi = Vector3::zeros();
        }
        Self {
            center: axes * (0.5 * (lo + hi)),
            axes,
            half_extents: 0.5 * (hi - lo),
        }
    }

    /// A size measure for choosing which tree to descend: the sum of the half extents.
    pub fn size(&self) -> f64 {
        self.half_extents.x + self.half_extents.y + self.half_extents.z
    }

    /// True when the point (in the box's frame of reference) lies inside or on the box.
    pub fn contains(&self, p: &Point3) -> bool {
        let q = self.axes.transpose() * (p.coords - self.center);
        q.x.abs() <= self.half_extents.x
            && q.y.abs() <= self.half_extents.y
            && q.z.abs() <= self.half_extents.z
    }
}

/// The 15-axis separating-axis test (Gottschalk, Lin & Manocha 1996, "OBBTree"): box A with half
/// extents `a`, box B with half extents `b`, B's axes expressed in A's box frame as the columns of
/// `r`, B's centre in A's box frame `t`. True when no separating axis exists (the boxes overlap
/// or touch). `abs_eps` pads `|r|` against round-off on near-parallel edge axes, relative to 1.
#[inline]
pub fn boxes_overlap(a: &Vector3, b: &Vector3, r: &Matrix3, t: &Vector3) -> bool {
    let mut ar = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            ar[i][j] = r[(i, j)].abs() + ABS_EPS;
        }
    }
    // A's face axes.
    for i in 0..3 {
        let rb = b.x * ar[i][0] + b.y * ar[i][1] + b.z * ar[i][2];
        if t[i].abs() > a[i] + rb {
            return false;
        }
    }
    overlap_on_b_and_edge_axes(a, b, r, &ar, t)
}

/// Pads `|r|` against round-off on near-parallel edge axes, relative to 1.
const ABS_EPS: f64 = 1e-12;

/// The last 12 axes of [`boxes_overlap`] (B's faces, then the edge–edge axes), given `|r| + ε`
/// as `ar`: true when none of them separates the boxes. Each group is judged with one branch
/// rather than one per axis (near the intersection curve an axis' outcome is a coin toss).
#[inline]
fn overlap_on_b_and_edge_axes(
    a: &Vector3,
    b: &Vector3,
    r: &Matrix3,
    ar: &[[f64; 3]; 3],
    t: &Vector3,
) -> bool {
    // B's face axes.
    let mut apart = false;
    for j in 0..3 {
        let ra = a.x * ar[0][j] + a.y * ar[1][j] + a.z * ar[2][j];
        let tj = t.x * r[(0, j)] + t.y * r[(1, j)] + t.z * r[(2, j)];
        apart |= tj.abs() > ra + b[j];
    }
    if apart {
        return false;
    }
    // Edge–edge axes A_i × B_j.
    for i in 0..3 {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        for j in 0..3 {
            let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
            let ra = a[i1] * ar[i2][j] + a[i2] * ar[i1][j];
            let rb = b[j1] * ar[i][j2] + b[j2] * ar[i][j1];
            let tl = (t[i2] * r[(i1, j)] - t[i1] * r[(i2, j)]).abs();
            apart |= tl > ra + rb;
        }
    }
    !apart
}

/// The same test as [`boxes_overlap`] from the boxes' frames directly: box A's axes (columns)
/// and centre, box B's axes and centre already in A's frame. `R = Aᵀ·B` and `T = Aᵀ·(c_B − c_A)`
/// are formed whole, and the axes are judged in three groups (A's faces, B's faces, the edges),
/// each with one branch rather than one per axis (measured in docs/performance.md).
#[inline]
pub fn boxes_overlap_in_frame(
    a_axes: &Matrix3,
    a_center: &Vector3,
    a_half: &Vector3,
    b_axes: &Matrix3,
    b_center: &Vector3,
    b_half: &Vector3,
) -> bool {
    let d = b_center - a_center;
    let mut r = Matrix3::zeros();
    let mut ar = [[0.0; 3]; 3];
    let mut t = Vector3::zeros();
    let mut apart = false;
    for i in 0..3 {
        let ai = a_axes.column(i);
        t[i] = ai.dot(&d);
        for j in 0..3 {
            r[(i, j)] = ai.dot(&b_axes.column(j));
            ar[i][j] = r[(i, j)].abs() + ABS_EPS;
        }
        let rb = b_half[0] * ar[i][0] + b_half[1] * ar[i][1] + b_half[2] * ar[i][2];
        apart |= t[i].abs() > a_half[i] + rb;
    }
    if apart {
        return false;
    }
    overlap_on_b_and_edge_axes(a_half, b_half, &r, &ar, &t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::UnitQuaternion;

    /// Brute-force oracle: the boxes overlap iff the convex hulls of their corners are not
    /// separated along any of the 15 candidate axes — checked here by projecting all 8+8 corners
    /// (no half-extent formula involved).
    fn overlap_by_corners(a: &Obb, b: &Obb) -> bool {
        let corners = |o: &Obb| -> Vec<Vector3> {
            (0..8)
                .map(|k| {
                    let s = |bit: u32| if k & (1 << bit) != 0 { 1.0 } else { -1.0 };
                    o.center
                        + o.axes
                            * Vector3::new(
                                s(0) * o.half_extents.x,
                                s(1) * o.half_extents.y,
                                s(2) * o.half_extents.z,
                            )
                })
                .collect()
        };
        let (ca, cb) = (corners(a), corners(b));
        let mut axes = Vec::new();
        for i in 0..3 {
            axes.push(a.axes.column(i).into_owned());
            axes.push(b.axes.column(i).into_owned());
            for j in 0..3 {
                let c = a.axes.column(i).cross(&b.axes.column(j));
                if c.norm() > 1e-9 {
                    axes.push(c);
                }
            }
        }
        axes.iter().all(|ax| {
            let (mut lo_a, mut hi_a, mut lo_b, mut hi_b) = (
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
            );
            for p in &ca {
                lo_a = lo_a.min(p.dot(ax));
                hi_a = hi_a.max(p.dot(ax));
            }
            for p in &cb {
                lo_b = lo_b.min(p.dot(ax));
                hi_b = hi_b.max(p.dot(ax));
            }
            hi_a >= lo_b && hi_b >= lo_a
        })
    }

    #[test]
    fn the_separating_axis_test_agrees_with_corner_projections() {
        let mut seed = 0x9E37_79B9_7F4A_7C15_u64;
        let mut rnd = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut agree = 0;
        let mut overlaps = 0;
        for _ in 0..2000 {
            let mut random_box = |spread: f64| Obb {
                center: Vector3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5) * spread,
                axes: UnitQuaternion::from_euler_angles(rnd() * 6.3, rnd() * 6.3, rnd() * 6.3)
                    .to_rotation_matrix()
                    .into_inner(),
                half_extents: Vector3::new(rnd() + 0.01, rnd() + 0.01, rnd() + 0.01) * 0.5,
            };
            let (a, b) = (random_box(1.5), random_box(1.5));
            let r = a.axes.transpose() * b.axes;
            let t = a.axes.transpose() * (b.center - a.center);
            let sat = boxes_overlap(&a.half_extents, &b.half_extents, &r, &t);
            assert_eq!(sat, overlap_by_corners(&a, &b), "{a:?} {b:?}");
            let lazy = boxes_overlap_in_frame(
                &a.axes,
                &a.center,
                &a.half_extents,
                &b.axes,
                &b.center,
                &b.half_extents,
            );
            assert_eq!(lazy, sat);
            agree += 1;
            overlaps += usize::from(sat);
        }
        // Both outcomes must occur, else the test could not fail.
        assert!(overlaps > 200 && overlaps < 1800, "{overlaps} of {agree}");
    }

    #[test]
    fn a_fitted_box_contains_its_points_and_follows_a_rotated_slab() {
        let rot = UnitQuaternion::from_euler_angles(0.3, -0.7, 1.1);
        let pts: Vec<Point3> = (0..50)
            .map(|k| {
                let u = k as f64 / 49.0;
                rot * Point3::new(10.0 * u - 5.0, (7.0 * u).sin(), 0.01 * (13.0 * u).cos())
            })
            .collect();
        let obb = Obb::fit(pts.iter().copied());
        for p in &pts {
            let q = obb.axes.transpose() * (p.coords - obb.center);
            assert!(
                q.abs()
                    .iter()
                    .zip(obb.half_extents.iter())
                    .all(|(x, h)| *x <= h + 1e-12)
            );
        }
        // The thin direction is found: the smallest extent is ≈ 0.01, not the slab's length.
        assert!(obb.half_extents.min() < 0.02, "{:?}", obb.half_extents);
    }
}
