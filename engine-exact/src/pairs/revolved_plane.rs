//! A solid of revolution (frustum or cone, ring torus; a cylinder too) against an unbounded
//! plane: one-dimensional quadrature of closed-form sections, converged to 1e-12 of the
//! pair's size.
//!
//! Cylinders are dispatched to [`super::cylinder_plane`], whose chord quadrature needs no
//! adaptivity and is several times faster; this kernel answers them too, and a test holds the
//! two to 1e-11.
//!
//! ## Volume and centroid: integrate over the azimuth
//! In the solid's frame (axis +z) write the plane's solid as `n·x ≤ h` with `n = a·e + b·ẑ`,
//! `e` the unit radial direction of `n` (`a ≥ 0`; `e = x̂` when `a = 0`). The half-plane at
//! azimuth φ from `e` meets the solid in its profile `P` (the frustum's quadrilateral
//! `[(0,0), (r₀,0), (r₁,L), (0,L)]` in `(ρ, z)`, the torus' disc of radius `r` about
//! `(R, 0)`), and the plane's solid in the half-plane `ρ·a cos φ + z·b ≤ h`: a straight cut.
//! So with `Q(φ)` the clipped profile (a polygon or a circular segment, both with closed-form
//! moments):
//! - `V = 2∫₀^π ∫∫_Q ρ dρ dz dφ`, the moment along `e`: `2∫₀^π cos φ ∫∫_Q ρ² dρ dz dφ`,
//!   along `z`: `2∫₀^π ∫∫_Q z ρ dρ dz dφ` (the moment across `e` is zero by symmetry).
//! - The integrand is analytic in φ except where the cut passes a rim vertex of the
//!   quadrilateral (`cos φ = (h − b z_v)/(a ρ_v)`) or is tangent to the torus' disc
//!   (`(R A − h)² = r²(A² + b²)`, `A = a cos φ`, a quadratic in `A`), where it has a
//!   square-root-type end. Those angles split `[0, π]`; each piece is mapped by
//!   `φ = m + w·sin t`, which turns a square-root end into a smooth one, and integrated by
//!   the 21-node Gauss–Kronrod rule, halved adaptively until its error estimate is within
//!   1e-13 relative, or 1e-14 of the whole volume.
//!
//! Axis along the normal (`a = 0`: no cut depends on φ) and axis in the plane (`b = 0`) are
//! ordinary cases of the same formulas.
//!
//! ## Section area: integrate across the plane
//! The contact area is `|S|`, the plane's section inside the solid. In the plane, with
//! `t₁ = b e − a ẑ` and `t₂ = ẑ × e`, the point `h n + u t₁ + v t₂` has `z = h b − u a` and
//! `ρ² = (h a + u b)² + v²`, so the line of constant `u` is perpendicular to the axis and its
//! chord inside the solid is closed form (`2√(R(z)² − ρ₀²)` for the frustum; the difference of
//! two such terms for the torus' annulus). The chord's square-root ends are at roots of
//! quadratics in `u` (the frustum's factors into two lines) and at the caps or `z = ±r`: the
//! same split, map and rule integrate it, to 1e-13 relative or 1e-14 of the solid's size
//! squared.
//!
//! ## The contact (SPEC §4)
//! - one region: a half-space meets a convex frustum in one convex piece; it meets a ring
//!   torus in one connected piece too, since for each φ the section is one segment of the
//!   disc and the set of φ where that segment is not empty, `R a cos φ − r√(a²cos²φ + b²) <
//!   h`, is an interval about φ = π (the left side grows with `cos φ` because `R > r`);
//! - normal: the plane's outward normal; area: the section (a quarter of the solid's surface
//!   once the plane no longer cuts it);
//! - points (taken along the normal through the centroid `g`: `ray_exit`): the foot
//!   of `g` on the plane, and where the line from `g` along `−n` leaves the solid; when `g`
//!   lies outside the solid (in a torus' hole) the point of the solid's surface closest to
//!   `g`; δ is their distance.

use crate::kernel::PairContact;
use crate::methods::solid_distance::Solid;
use crate::quadrature;
use crate::ray_exit::surface_point_along;
use contact_core::{Isometry3, Point3, Vector2, Vector3, WorkCounters};
use std::f64::consts::PI;

/// The adaptive rule: error estimates within 1e-13 relative; at most 8 halvings per
/// piece (a piece then spans 1/256 of its first width). Deeper halving changed no answer of
/// the trade suite's poses by more than 1e-12 of the size; it only spent time (up to 40 ms a
/// query) where a grazing cut (depth ~1e-13 of the size) leaves the integrand at round-off
/// near its azimuthal end and the halves never agree to 1e-13.
const ADAPTIVE: quadrature::Adaptive = quadrature::Adaptive {
    tolerance: 1e-13,
    max_depth: 8,
    pair: crate::quadrature::Pair::Kronrod21,
};

/// The profile of a solid of revolution in its `(ρ, z)` half-plane, lengths divided by the
/// working unit.
#[derive(Debug, Clone, Copy)]
enum Profile {
    /// Radius `r0` at `z = 0`, `r1` at `z = len`.
    Frustum { r0: f64, r1: f64, len: f64 },
    /// Disc of radius `small` about `(big, 0)`.
    Torus { big: f64, small: f64 },
}

/// The cut `ρ·cut.x + z·cut.y ≤ h` in the `(ρ, z)` half-plane at one azimuth.
#[derive(Debug, Clone, Copy)]
struct Cut {
    normal: Vector2,
    h: f64,
}

/// `[∫∫ρ, ∫∫ρ², ∫∫zρ]` over the profile clipped by `cut`.
fn moments(profile: &Profile, cut: &Cut) -> [f64; 3] {
    match *profile {
        Profile::Frustum { r0, r1, len } => {
            let quad = [
                Vector2::new(0.0, 0.0),
                Vector2::new(r0, 0.0),
                Vector2::new(r1, len),
                Vector2::new(0.0, len),
            ];
            let mut clipped = [Vector2::zeros(); 5];
            let mut count = 0;
            for k in 0..4 {
                let (p, q) = (quad[k], quad[(k + 1) % 4]);
                let dp = cut.normal.dot(&p) - cut.h;
                let dq = cut.normal.dot(&q) - cut.h;
                if dp <= 0.0 {
                    clipped[count] = p;
                    count += 1;
                }
                if (dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0) {
                    clipped[count] = p + (q - p) * (dp / (dp - dq));
                    count += 1;
                }
            }
            polygon_moments(&clipped[..count])
        }
        Profile::Torus { big, small } => {
            let norm = cut.normal.norm();
            if norm == 0.0 {
                // The cut does not depend on the point: all or nothing.
                return if cut.h >= 0.0 {
                    segment_moments(big, small, &Vector2::x(), small)
                } else {
                    [0.0; 3]
                };
            }
            let m = cut.normal / norm;
            let d = (cut.h - big * cut.normal.x) / norm;
            segment_moments(big, small, &m, d)
        }
    }
}

/// `[∫∫x, ∫∫x², ∫∫xy]` over the polygon `p` (counter-clockwise, `(x, y) = (ρ, z)`). The sums
/// run about the first vertex and are shifted back, so a sliver far from the origin keeps
/// its relative precision.
fn polygon_moments(p: &[Vector2]) -> [f64; 3] {
    let Some(&o) = p.first() else {
        return [0.0; 3];
    };
    // Local: [∫1, ∫x, ∫y, ∫x², ∫xy] about o.
    let mut sums = [0.0; 5];
    for k in 1..p.len().saturating_sub(1) {
        let (a, b) = (p[k] - o, p[k + 1] - o);
        let cross = a.x * b.y - b.x * a.y;
        sums[0] += cross;
        sums[1] += (a.x + b.x) * cross;
        sums[2] += (a.y + b.y) * cross;
        sums[3] += (a.x * a.x + a.x * b.x + b.x * b.x) * cross;
        sums[4] += (a.x * b.y + 2.0 * a.x * a.y + 2.0 * b.x * b.y + b.x * a.y) * cross;
    }
    let [area, mx, my, mxx, mxy] = [
        sums[0] / 2.0,
        sums[1] / 6.0,
        sums[2] / 6.0,
        sums[3] / 12.0,
        sums[4] / 24.0,
    ];
    [
        area * o.x + mx,
        area * o.x * o.x + 2.0 * o.x * mx + mxx,
        area * o.x * o.y + o.x * my + o.y * mx + mxy,
    ]
}

/// `x − sin x` for `x ≥ 0`, by its series below 0.5 (where the difference cancels).
fn x_minus_sin(x: f64) -> f64 {
    if x >= 0.5 {
        return x - x.sin();
    }
    let x2 = x * x;
    // x³/3! − x⁵/5! + … − x¹³/13!, Horner in x².
    let mut sum = 0.0;
    for denominator in [
        6_227_020_800.0,
        39_916_800.0,
        362_880.0,
        5_040.0,
        120.0,
        6.0,
    ] {
        sum = 1.0 / denominator - x2 * sum;
    }
    x * x2 * sum
}

/// `[∫∫ρ, ∫∫ρ², ∫∫zρ]` over the part `m·y ≤ d` (`m` unit, `y` from the centre `(big, 0)`) of
/// the disc of radius `r`. With `s = m·y = −r cos ε'` (ε' ∈ [0, ε], `ε` the half-angle the
/// chord subtends from the far side) and `w` across: `∫1 = r²·g(2ε)/2`, `∫s = −(2/3) r³
/// sin³ε`, `∫s² = r⁴ g(4ε)/16`, `∫w² = (2/3) r⁴ (g(2ε)/4 − g(4ε)/32)` with `g(x) = x − sin x`
/// (stable for a sliver), and `∫w = ∫sw = 0`.
fn segment_moments(big: f64, r: f64, m: &Vector2, d: f64) -> [f64; 3] {
    if d <= -r {
        return [0.0; 3];
    }
    let eps = if d < 0.0 {
        2.0 * ((r + d) / (2.0 * r)).sqrt().asin()
    } else {
        (-d / r).max(-1.0).acos()
    };
    let (g2, g4) = (x_minus_sin(2.0 * eps), x_minus_sin(4.0 * eps));
    let r2 = r * r;
    let area = 0.5 * r2 * g2;
    let s1 = -2.0 / 3.0 * r2 * r * eps.sin().powi(3);
    let s2 = r2 * r2 * g4 / 16.0;
    let w2 = 2.0 / 3.0 * r2 * r2 * (0.25 * g2 - g4 / 32.0);
    let (mx, my) = (m.x, m.y);
    [
        big * area + mx * s1,
        big * big * area + 2.0 * big * mx * s1 + mx * mx * s2 + my * my * w2,
        big * my * s1 + mx * my * (s2 - w2),
    ]
}

/// The angles in `(0, π)` where the cut changes character, written into `out` after the ends.
fn azimuth_cuts(profile: &Profile, a: f64, b: f64, h: f64, out: &mut [f64; 6]) -> usize {
    out[0] = 0.0;
    out[1] = PI;
    let mut count = 2;
    let mut push_cos = |c: f64, count: &mut usize| {
        if c.is_finite() && c > -1.0 && c < 1.0 {
            out[*count] = c.acos();
            *count += 1;
        }
    };
    if a > 0.0 {
        match *profile {
            Profile::Frustum { r0, r1, len } => {
                for (rho, z) in [(r0, 0.0), (r1, len)] {
                    if rho > 0.0 {
                        push_cos((h - b * z) / (a * rho), &mut count);
                    }
                }
            }
            Profile::Torus { big, small } => {
                // (R A − h)² = r²(A² + b²): A = (R h ± r√(h² + (R² − r²) b²)) / (R² − r²).
                let k = (big - small) * (big + small);
                let root = small * (h * h + k * b * b).sqrt();
                for sign in [1.0, -1.0] {
                    push_cos((big * h + sign * root) / k / a, &mut count);
                }
            }
        }
    }
    count
}

/// The chord inside the solid of the line `u` of the plane (see the module docs).
fn chord(profile: &Profile, a: f64, b: f64, h: f64, u: f64) -> f64 {
    let z = h * b - u * a;
    let rho0 = h * a + u * b;
    let reach = |radius: f64| 2.0 * ((radius - rho0) * (radius + rho0)).max(0.0).sqrt();
    match *profile {
        Profile::Frustum { r0, r1, len } => {
            if !(0.0..=len).contains(&z) {
                return 0.0;
            }
            reach(r0 + (r1 - r0) * (z / len))
        }
        Profile::Torus { big, small } => {
            let w2 = (small - z) * (small + z);
            if w2 <= 0.0 {
                return 0.0;
            }
            let w = w2.sqrt();
            (reach(big + w) - reach(big - w)).max(0.0)
        }
    }
}

/// The `u` where the chord has a square-root end or a kink, after the ends: `±bound`
/// narrowed to where the plane's line `u` crosses the solid's axial extent.
fn section_cuts(
    profile: &Profile,
    a: f64,
    b: f64,
    h: f64,
    bound: f64,
    out: &mut [f64; 10],
) -> usize {
    let (z0, p0) = (h * b, h * a);
    // The u where z(u) = z0 − a·u spans the solid's axial extent [z_lo, z_hi].
    let (z_lo, z_hi) = match *profile {
        Profile::Frustum { len, .. } => (0.0, len),
        Profile::Torus { small, .. } => (-small, small),
    };
    let (lo, hi) = if a > 0.0 {
        (((z0 - z_hi) / a).max(-bound), ((z0 - z_lo) / a).min(bound))
    } else {
        (-bound, bound)
    };
    out[0] = lo;
    out[1] = hi.max(lo);
    let mut count = 2;
    let mut push = |u: f64, count: &mut usize| {
        if u.is_finite() && u > lo && u < hi {
            out[*count] = u;
            *count += 1;
        }
    };
    match *profile {
        Profile::Frustum { r0, r1, len } => {
            // R(z(u))² − ρ₀(u)² = (α − βu − γ − bu)(α − βu + γ + bu).
            let k = (r1 - r0) / len;
            let (alpha, beta) = (r0 + k * z0, k * a);
            push((alpha - p0) / (beta + b), &mut count);
            push((alpha + p0) / (beta - b), &mut count);
        }
        Profile::Torus { big, small } => {
            // (z0 − a u)² + (σ(p0 + b u) − R)² = r², a² + b² = 1.
            for sigma in [1.0, -1.0] {
                let q = sigma * p0 - big;
                let half_b = -a * z0 + sigma * b * q;
                let c = z0 * z0 + q * q - small * small;
                let disc = half_b * half_b - c;
                if disc >= 0.0 {
                    let root = disc.sqrt();
                    push(-half_b + root, &mut count);
                    push(-half_b - root, &mut count);
                }
            }
        }
    }
    count
}

/// Contact of `solid` (a cylinder, frustum or torus) at `pose_s` with the plane at
/// `pose_plane` (flipped when `side < 0`). `None` for a box.
pub(crate) fn contact(
    solid: &Solid,
    pose_s: &Isometry3,
    pose_plane: &Isometry3,
    side: f64,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let (profile, unit) = working_profile(solid)?;
    let rotation = pose_s.rotation;
    let normal_w = side * (pose_plane.rotation * Vector3::z());
    let n = rotation.inverse_transform_vector(&normal_w);
    let h =
        n.dot(&rotation.inverse_transform_vector(
            &(pose_plane.translation.vector - pose_s.translation.vector),
        )) / unit;
    let a = n.xy().norm();
    let b = n.z;
    let e = if a > 0.0 { n.xy() / a } else { Vector2::x() };
    // The solid's lowest point along n: reject before integrating.
    let lowest = match profile {
        Profile::Frustum { r0, r1, len } => (-a * r0).min(b * len - a * r1),
        Profile::Torus { big, small } => -big * a - small,
    };
    if lowest >= h {
        return None;
    }
    let mut cuts = [0.0; 6];
    let count = azimuth_cuts(&profile, a, b, h, &mut cuts);
    let mut per_azimuth = |phi: f64| {
        let cos = phi.cos();
        let m = moments(
            &profile,
            &Cut {
                normal: Vector2::new(a * cos, b),
                h,
            },
        );
        [m[0], m[1] * cos, m[2]]
    };
    // Each piece may keep an error of 1e-14 of the volume (times the unit length for the
    // moments, lengths being near 1 in working units).
    let volume_floor = |s: &[f64; 3]| [1e-14 * s[0].abs(); 3];
    let sums = ADAPTIVE.integrate_pieces(&mut cuts[..count], &mut per_azimuth, &volume_floor, work);
    if sums[0] <= 0.0 {
        return None;
    }
    let along_e = sums[1] / sums[0];
    let centroid = Vector3::new(e.x * along_e, e.y * along_e, sums[2] / sums[0]);
    let section = section_area(&profile, (a, b, h), work);
    let area = if section > 0.0 {
        section
    } else {
        0.25 * surface_area(&profile)
    } * unit
        * unit;
    let to_plane = (h - n.dot(&centroid)).max(0.0);
    let on_plane = (centroid + to_plane * n) * unit;
    let on_solid = surface_point_along(solid, &(centroid * unit), &-n);
    let center = pose_s.translation.vector;
    let world = |p: Vector3| Point3::from(center + rotation * p);
    Some(PairContact {
        point_a: world(on_solid),
        point_b: world(on_plane),
        normal: normal_w,
        depth: (on_plane - on_solid).norm(),
        area,
    })
}

/// The profile of `solid` (a cylinder, frustum or torus) in working units, and the unit: a
/// power of two near the solid's size. `None` for a box.
fn working_profile(solid: &Solid) -> Option<(Profile, f64)> {
    let (profile, size) = match *solid {
        Solid::Cylinder(c) => {
            let (r, len) = (c.radius(), c.length());
            (Profile::Frustum { r0: r, r1: r, len }, r.max(len))
        }
        Solid::Frustum(f) => {
            let (r0, r1, len) = (f.bottom_radius(), f.top_radius(), f.length());
            (Profile::Frustum { r0, r1, len }, r0.max(r1).max(len))
        }
        Solid::Torus(t) => (
            Profile::Torus {
                big: t.major_radius(),
                small: t.minor_radius(),
            },
            t.major_radius() + t.minor_radius(),
        ),
        Solid::Box(_) => return None,
    };
    // Working unit: lengths divided by a power of two near the solid's size.
    let unit = crate::methods::clipped::unit_for(size);
    let profile = match profile {
        Profile::Frustum { r0, r1, len } => Profile::Frustum {
            r0: r0 / unit,
            r1: r1 / unit,
            len: len / unit,
        },
        Profile::Torus { big, small } => Profile::Torus {
            big: big / unit,
            small: small / unit,
        },
    };
    Some((profile, unit))
}

/// The area of the solid's section by the plane `n·x = h` (`n = (a·e, b)` in the solid's
/// frame, working units), integrated across the plane over `|u|` up to the solid's bounding
/// radius; not positive when the plane does not cut the solid.
fn section_area(profile: &Profile, (a, b, h): (f64, f64, f64), work: &mut WorkCounters) -> f64 {
    let profile = *profile;
    // Section area across the plane, over |u| ≤ the solid's bounding radius.
    let bound = match profile {
        Profile::Frustum { r0, r1, len } => r0.max(r1).hypot(len),
        Profile::Torus { big, small } => big + small,
    };
    let mut cuts = [0.0; 10];
    let count = section_cuts(&profile, a, b, h, bound, &mut cuts);
    let mut across = |u: f64| [chord(&profile, a, b, h, u)];
    // The area may keep an error of 1e-14 of the solid's size² per piece.
    let area_floor = 1e-14 * bound * bound;
    ADAPTIVE.integrate_pieces(&mut cuts[..count], &mut across, &|_| [area_floor], work)[0]
}

/// The whole surface of the solid (working units).
fn surface_area(profile: &Profile) -> f64 {
    match *profile {
        Profile::Frustum { r0, r1, len } => {
            PI * (r0 * r0 + r1 * r1 + (r0 + r1) * (r1 - r0).hypot(len))
        }
        Profile::Torus { big, small } => 4.0 * PI * PI * big * small,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::UnitQuaternion;
    use contact_core::geometry::Cylinder;
    use std::f64::consts::FRAC_PI_2;

    /// The cylinder through this kernel against the cylinder kernel's chord quadrature (a
    /// different slicing): volume-derived answers and the section area agree.
    #[test]
    fn a_cylinder_agrees_with_the_chord_quadrature() {
        let cylinder = Cylinder::new(0.7, 1.9).unwrap();
        let mut work = WorkCounters::default();
        for (k, tilt) in [0.0, 1e-9, 0.3, 0.9, 1.3, FRAC_PI_2, 2.0, 3.0]
            .iter()
            .enumerate()
        {
            for depth in [0.05, 0.4, 1.1, 2.5] {
                let q = UnitQuaternion::from_euler_angles(*tilt, 0.2 * k as f64, 0.4);
                let pose = Isometry3::from_parts(nalgebra::Translation3::new(0.1, -0.2, 0.0), q);
                let lowest = (0..2)
                    .flat_map(|end| {
                        (0..64).map(move |i| {
                            let angle = i as f64 * PI / 32.0;
                            let p = Vector3::new(
                                0.7 * angle.cos(),
                                0.7 * angle.sin(),
                                1.9 * end as f64,
                            );
                            (q * p).z
                        })
                    })
                    .fold(f64::INFINITY, f64::min);
                let pose = Isometry3::translation(0.0, 0.0, -lowest - depth) * pose;
                let plane = Isometry3::identity();
                let ours = contact(&Solid::Cylinder(cylinder), &pose, &plane, 1.0, &mut work);
                let theirs =
                    super::super::cylinder_plane::contact(&cylinder, &pose, &plane, 1.0, &mut work);
                let (Some(x), Some(y)) = (ours, theirs) else {
                    panic!("{tilt} {depth}: {ours:?} vs {theirs:?}");
                };
                assert!(
                    (x.depth - y.depth).abs() < 1e-11,
                    "{tilt} {depth}: {x:?} vs {y:?}"
                );
                assert!(
                    (x.point_a - y.point_a).norm() < 1e-11,
                    "{tilt} {depth}: {x:?} vs {y:?}"
                );
                assert!(
                    (x.point_b - y.point_b).norm() < 1e-11,
                    "{tilt} {depth}: {x:?} vs {y:?}"
                );
                assert!(
                    (x.area - y.area).abs() < 1e-9,
                    "{tilt} {depth}: {x:?} vs {y:?}"
                );
            }
        }
    }
}
