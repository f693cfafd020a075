//! The sphere–solid fast path: the conditions under which the intersection is the ball cut
//! by one face or by a cylinder's side alone, and the closed-form answer there (see the
//! parent module for why it is SPEC §4's).

use super::Solid;
use crate::kernel::PairContact;
use contact_core::{Isometry3, Point3, Vector3};
use std::f64::consts::PI;

/// The trapezoid rule's node count for the side's area (see [`side_area`]): its integrand is
/// analytic in the strip `|Im θ| < y`, `y = acosh(1/k) ≥ acosh(√2) ≈ 0.88`, where the rule's
/// relative error falls as `e^{−2Ny}`; `N = ⌈20.6/y⌉` (24 at the widest wrap, 7 for a shallow
/// contact with `k² = 0.01`) keeps it below 1e-16 with a tenth of `y` to spare.
fn side_nodes(k2: f64) -> usize {
    let y = (1.0 / k2.sqrt()).acosh();
    // NaN (no overlap) and huge values are clamped.
    (20.6 / y).ceil().clamp(4.0, 24.0) as usize
}

/// The fast path's answer in the solid's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Local {
    /// The solid's outward unit normal `n` (from the solid into the sphere).
    pub normal: Vector3,
    /// The foot `q = c − d n` on the solid's surface.
    pub foot: Vector3,
    /// The centre's signed height `d` above the surface (`|d| < r`).
    pub height: f64,
    /// The area estimate `|S|`.
    pub area: f64,
}

impl Local {
    /// The contact in the world frame: normal `n`, points `c − r n` and `q`, δ = `r − d`.
    pub(crate) fn to_world(
        self,
        radius: f64,
        pose_sphere: &Isometry3,
        pose_solid: &Isometry3,
    ) -> PairContact {
        let normal = pose_solid.rotation * self.normal;
        PairContact {
            point_a: Point3::from(pose_sphere.translation.vector - radius * normal),
            point_b: pose_solid * Point3::from(self.foot),
            normal,
            depth: radius - self.height,
            area: self.area,
        }
    }
}

/// The fast path's answer for the sphere of radius `r` centred at `c` (solid's frame), when
/// the intersection is the ball cut by one face or by a cylinder's side alone; `None`
/// otherwise (the general path then answers).
pub(crate) fn fast_path(r: f64, c: &Vector3, solid: &Solid) -> Option<Local> {
    match solid {
        Solid::Box(b) => {
            let centre = b.center().coords;
            box_face(r, &(c - centre), &b.half_extents()).map(|local| Local {
                foot: local.foot + centre,
                ..local
            })
        }
        Solid::Cylinder(cylinder) => {
            let (radius, length) = (cylinder.radius(), cylinder.length());
            cylinder_side(r, c, radius, length).or_else(|| cap(r, c, radius, radius, length))
        }
        Solid::Frustum(f) => cap(r, c, f.bottom_radius(), f.top_radius(), f.length()),
        Solid::Torus(_) => None,
    }
}

/// How far the region (the ball behind a plane at signed height `d` of its centre) reaches
/// along the plane from the centre's foot: the cap's base radius `√(r² − d²)` for `d ≥ 0`,
/// the ball's radius once the centre is behind the plane.
fn reach(r: f64, d: f64) -> f64 {
    if d >= 0.0 {
        ((r - d) * (r + d)).sqrt()
    } else {
        r
    }
}

/// A box of half-extents `h` about the origin, the centre at `p`: the face `p` is highest
/// above (the nearest one when inside), if the region is the ball behind it alone.
fn box_face(r: f64, p: &Vector3, h: &Vector3) -> Option<Local> {
    let mut best = (f64::NEG_INFINITY, 0, 1.0);
    for k in 0..3 {
        for sign in [1.0, -1.0] {
            let d = sign * p[k] - h[k];
            if d > best.0 {
                best = (d, k, sign);
            }
        }
    }
    let (d, k, sign) = best;
    if !(d > -r && d < r) {
        return None;
    }
    let a = reach(r, d);
    let within_face = (0..3).filter(|&j| j != k).all(|j| p[j].abs() + a <= h[j]);
    // The opposite face lies at `h_k + sign·p_k` from the centre.
    if !within_face || h[k] + sign * p[k] < r {
        return None;
    }
    let mut foot = *p;
    foot[k] = sign * h[k];
    Some(Local {
        normal: Vector3::ith(k, sign),
        foot,
        height: d,
        area: PI * (r - d) * (r + d),
    })
}

/// A cylinder of `radius` over `0 ≤ z ≤ length`: its side, if the region is the ball cut by
/// the infinite cylinder with its height inside the caps and the ball wraps at most a quarter
/// turn each way (`r² ≤ ρ² + R²`).
fn cylinder_side(r: f64, p: &Vector3, radius: f64, length: f64) -> Option<Local> {
    let rho = p.xy().norm();
    let d = rho - radius;
    if !(rho > 0.0 && d > -r && d < r && r * r <= rho * rho + radius * radius) {
        return None;
    }
    let a = reach(r, d);
    if p.z - a < 0.0 || p.z + a > length {
        return None;
    }
    let u = p.xy() / rho;
    Some(Local {
        normal: Vector3::new(u.x, u.y, 0.0),
        foot: Vector3::new(radius * u.x, radius * u.y, p.z),
        height: d,
        area: side_area(r, rho, radius),
    })
}

/// `|S|` for the ball of radius `r` centred `rho` from the axis of the infinite cylinder of
/// `radius`, where `r² ≤ ρ² + R²` and `|ρ − R| < r`: the side's area vector inside the ball,
/// `2R ∫ cos φ √(A + B cos φ) dφ` (`A = r² − R² − ρ²`, `B = 2Rρ`, over the arc where the root
/// is real). With `sin(φ/2) = k sin θ`, `k² = (A + B)/2B ≤ ½`, it is
/// `4(A + B)·√(R/ρ)·∫₀^{π/2} (1 − 2k² sin²θ) cos²θ / √(1 − k² sin²θ) dθ`, an analytic
/// `π`-periodic integrand, by the trapezoid rule.
pub(crate) fn side_area(r: f64, rho: f64, radius: f64) -> f64 {
    let d = rho - radius;
    let a_plus_b = (r - d) * (r + d);
    let k2 = a_plus_b / (4.0 * radius * rho);
    let n = side_nodes(k2);
    // Nodes θ_j = jπ/N; sin²θ_j = (1 − cos 2θ_j)/2, the cosines by the three-term recurrence
    // cos((j+1)x) = 2 cos x cos jx − cos((j−1)x), and the integrand is symmetric about π/2.
    let f = |s2: f64| (1.0 - 2.0 * k2 * s2) * (1.0 - s2) / (1.0 - k2 * s2).sqrt();
    let step = PI / n as f64;
    let c1 = (2.0 * step).cos();
    let (mut previous, mut current) = (1.0, c1);
    let mut sum = f(0.0);
    for _ in 1..n.div_ceil(2) {
        sum += 2.0 * f(0.5 * (1.0 - current));
        (previous, current) = (current, 2.0 * c1 * current - previous);
    }
    if n.is_multiple_of(2) {
        sum += f(1.0);
    }
    // ∫₀^{π/2} = ½ ∫₀^π.
    let integral = 0.5 * step * sum;
    4.0 * a_plus_b * (radius / rho).sqrt() * integral
}

/// A cylinder or frustum (radii `r0` at `z = 0`, `r1` at `z = length`): the cap the centre
/// is highest above, if the region is the ball behind it alone: it does not reach the other
/// cap, and its reach about the centre's foot stays within the solid's radius over the
/// heights it spans (linear in the height, so the smaller of its values at the two ends).
fn cap(r: f64, p: &Vector3, r0: f64, r1: f64, length: f64) -> Option<Local> {
    let rho = p.xy().norm();
    let (top, bottom) = (p.z - length, -p.z);
    let (d, sign, foot_z, cap_radius, far) = if top >= bottom {
        (top, 1.0, length, r1, p.z - r)
    } else {
        (bottom, -1.0, 0.0, r0, p.z + r)
    };
    if !(d > -r && d < r) || far < 0.0 || far > length {
        return None;
    }
    let radius_far = r0 + (r1 - r0) * (far / length);
    if rho + reach(r, d) > cap_radius.min(radius_far) {
        return None;
    }
    Some(Local {
        normal: Vector3::new(0.0, 0.0, sign),
        foot: Vector3::new(p.x, p.y, foot_z),
        height: d,
        area: PI * (r - d) * (r + d),
    })
}
