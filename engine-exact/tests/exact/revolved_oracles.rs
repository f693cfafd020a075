//! Oracles for a frustum (or cone) and a ring torus against the plane z = 0, written apart
//! from the engine: the engine integrates over the azimuth, these slice across the axis
//! (discs and annuli cut by a line: closed-form circular segments) or use Pappus.
//!
//! The points follow SPEC §4 along the normal: the foot of the intersection's centroid on the
//! plane, and where the line from the centroid along −z leaves the solid, found by bisection
//! on the solid's inside test ([`crate::oracles::exit_by_bisection`]); a centroid outside the
//! solid (in a torus' hole) takes the solid's closest surface point instead, through the
//! nearest tube centre.

use crate::common::Expected;
use contact_core::{Isometry3, Point3, UnitQuaternion, Vector2, Vector3};
use std::f64::consts::{FRAC_PI_2, PI};

/// A solid of revolution in its own frame (axis +z).
#[derive(Debug, Clone, Copy)]
pub enum Revolved {
    /// Radius `r0` at z = 0, `r1` at z = `len`.
    Frustum { r0: f64, r1: f64, len: f64 },
    /// Major radius `big`, minor `small`, centred at the origin.
    Torus { big: f64, small: f64 },
}

/// The closest surface point to the interior point `(rho, z)` of a frustum's half-section: the
/// nearest of bottom cap, side, top cap (that order on ties).
pub fn frustum_foot(r0: f64, r1: f64, len: f64, rho: f64, z: f64) -> (f64, f64) {
    let side = Vector2::new(len, -(r1 - r0)).normalize();
    let gap_side = side.dot(&(Vector2::new(r0, 0.0) - Vector2::new(rho, z)));
    let tie = 1e-12 * r0.max(r1).max(len);
    if z <= gap_side + tie && z <= len - z + tie {
        (rho, 0.0)
    } else if gap_side <= len - z + tie {
        let foot = Vector2::new(rho, z) + gap_side * side;
        (foot.x, foot.y)
    } else {
        (rho, len)
    }
}

/// The closest point of a torus' surface to the point `(rho, z)` of its half-plane: along the
/// line from the tube centre `(big, 0)`.
pub fn torus_foot(big: f64, small: f64, rho: f64, z: f64) -> (f64, f64) {
    let d = Vector2::new(rho - big, z);
    let foot = Vector2::new(big, 0.0) + small * d / d.norm();
    (foot.x, foot.y)
}

/// The contact for the centroid `g` (solid frame) of the solid at `pose` against z = 0.
fn expected_for(solid: &Revolved, pose: &Isometry3, g: &Vector3) -> Expected {
    let down = pose.rotation.inverse_transform_vector(&-Vector3::z());
    let inside = |x: &Vector3| match *solid {
        Revolved::Frustum { r0, r1, len } => {
            x.z >= 0.0 && x.z <= len && x.xy().norm() <= r0 + (r1 - r0) * x.z / len
        }
        Revolved::Torus { big, small } => (x.xy().norm() - big).hypot(x.z) <= small,
    };
    if inside(g) {
        let (reach, step) = match *solid {
            Revolved::Frustum { r0, r1, len } => (4.0 * (r0 + r1 + len), 0.0),
            Revolved::Torus { big, small } => (4.0 * (big + small), small / 64.0),
        };
        let exit = crate::oracles::exit_by_bisection(inside, g, &down, reach, step);
        let point_i = pose * Point3::from(exit);
        let g_w = pose * Point3::from(*g);
        let point_j = Point3::new(g_w.x, g_w.y, 0.0);
        return Expected {
            point_i,
            point_j,
            normal: Vector3::z(),
            depth: (point_i - point_j).norm(),
        };
    }
    let rho = g.xy().norm();
    let scale = match *solid {
        Revolved::Frustum { r0, r1, len } => r0.max(r1).max(len),
        Revolved::Torus { big, .. } => big,
    };
    let (rho, radial) = if rho > 1e-12 * scale {
        (rho, g.xy() / rho)
    } else {
        (0.0, Vector2::x())
    };
    let (rf, zf) = match *solid {
        Revolved::Frustum { r0, r1, len } => frustum_foot(r0, r1, len, rho, g.z),
        Revolved::Torus { big, small } => torus_foot(big, small, rho, g.z),
    };
    let point_i = pose * Point3::new(radial.x * rf, radial.y * rf, zf);
    let g_w = pose * Point3::from(*g);
    let point_j = Point3::new(g_w.x, g_w.y, 0.0);
    Expected {
        point_i,
        point_j,
        normal: Vector3::z(),
        depth: (point_i - point_j).norm(),
    }
}

/// A frustum standing on its bottom, sunk by `sunk` into the plane, its base centre at
/// `(x, y, −sunk)`: the part below is a frustum of height `sunk`, `V = π∫R²`, `z̄ = ∫zR²/∫R²`
/// with `R(z) = r0 + k z` (polynomials). A cone on its tip is `r0 = 0`.
pub fn frustum_upright(r0: f64, r1: f64, len: f64, sunk: f64, x: f64, y: f64) -> Expected {
    let k = (r1 - r0) / len;
    let s = sunk;
    let moment0 = r0 * r0 * s + r0 * k * s * s + k * k * s.powi(3) / 3.0;
    let moment1 = r0 * r0 * s * s / 2.0 + 2.0 * r0 * k * s.powi(3) / 3.0 + k * k * s.powi(4) / 4.0;
    let g = Vector3::new(0.0, 0.0, moment1 / moment0);
    expected_for(
        &Revolved::Frustum { r0, r1, len },
        &Isometry3::translation(x, y, -sunk),
        &g,
    )
}

/// A torus lying flat, centre at `(x, y, −c)`, so the plane cuts its local `z < c`, `|c| < r`:
/// the part below is the tube's segment `{z < c}` swept about the axis. The segment is
/// symmetric about ρ = R, so (Pappus) the centroid is on the axis at the segment's height
/// `z̄ = −(2/3)(r² − c²)^{3/2} / (r² acos(−c/r) + c√(r² − c²))`.
pub fn torus_flat(big: f64, small: f64, c: f64, x: f64, y: f64) -> Expected {
    let r = small;
    let area = r * r * (-c / r).acos() + c * (r * r - c * c).sqrt();
    let z_bar = -2.0 / 3.0 * (r * r - c * c).powf(1.5) / area;
    expected_for(
        &Revolved::Torus { big, small },
        &Isometry3::translation(x, y, -c),
        &Vector3::new(0.0, 0.0, z_bar),
    )
}

/// Area and first moment (along the cut's normal) of the part `u ≤ s` of a disc of radius `rho`
/// about the origin.
fn disc_part(rho: f64, s: f64) -> (f64, f64) {
    if s <= -rho {
        (0.0, 0.0)
    } else if s >= rho {
        (PI * rho * rho, 0.0)
    } else {
        let root = (rho * rho - s * s).sqrt();
        (
            rho * rho * (PI - (s / rho).acos()) + s * root,
            -2.0 / 3.0 * root.powi(3),
        )
    }
}

/// The solid at `(0, 0, z0)` turned by `q`, against z = 0, by slices across its axis: each is
/// a disc (frustum) or an annulus (torus) cut by the line `u ≤ s(ζ) = (h − bζ)/a`, with
/// closed-form segments; the 1-D integral over ζ is split where a circle of the slice becomes
/// tangent to the line, each piece mapped by `ζ = m + w sin t` and summed by composite Simpson
/// (N and 2N panels: the difference is the oracle's own error estimate, asserted below 1e-11
/// of the solid's size). Needs the axis tilted from the normal (`a > 0`).
pub fn revolved_slices(solid: &Revolved, q: &UnitQuaternion, z0: f64) -> Expected {
    let n = q.inverse_transform_vector(&Vector3::z());
    let h = -z0;
    let (a, b) = (n.xy().norm(), n.z);
    assert!(a > 1e-6, "the slicing oracle needs a tilted axis");
    let e = n.xy() / a;
    let s_of = |zeta: f64| (h - b * zeta) / a;
    let slice = |zeta: f64| -> [f64; 3] {
        let s = s_of(zeta);
        let (area, moment) = match *solid {
            Revolved::Frustum { r0, r1, len } => disc_part(r0 + (r1 - r0) * zeta / len, s),
            Revolved::Torus { big, small } => {
                let w = (small * small - zeta * zeta).max(0.0).sqrt();
                let (ao, mo) = disc_part(big + w, s);
                let (ai, mi) = disc_part(big - w, s);
                (ao - ai, mo - mi)
            }
        };
        [area, moment, zeta * area]
    };
    // Breakpoints: the ends, and the tangencies ρ(ζ) = |s(ζ)|.
    let (lo, hi, mut cuts) = match *solid {
        Revolved::Frustum { r0, r1, len } => {
            let k = (r1 - r0) / len;
            let mut cuts = vec![];
            for sigma in [1.0, -1.0] {
                // a (r0 + kζ) = σ (h − bζ).
                cuts.push((sigma * h - a * r0) / (a * k + sigma * b));
            }
            (0.0, len, cuts)
        }
        Revolved::Torus { big, small } => {
            let mut cuts = vec![];
            for sigma in [1.0, -1.0] {
                // (σ s − R)² + ζ² = r², i.e. ζ = σ b P ± a √(r² − P²) with P = σ h − a R.
                let p = sigma * h - a * big;
                if small * small >= p * p {
                    let root = a * (small * small - p * p).sqrt();
                    cuts.push(sigma * b * p + root);
                    cuts.push(sigma * b * p - root);
                }
            }
            (-small, small, cuts)
        }
    };
    cuts.retain(|c| c.is_finite() && *c > lo && *c < hi);
    cuts.push(lo);
    cuts.push(hi);
    cuts.sort_by(f64::total_cmp);
    let simpson = |panels: usize| -> [f64; 3] {
        let mut total = [0.0; 3];
        for piece in cuts.windows(2) {
            let (m, w) = (0.5 * (piece[0] + piece[1]), 0.5 * (piece[1] - piece[0]));
            let step = PI / panels as f64;
            for k in 0..=panels {
                let t = -FRAC_PI_2 + k as f64 * step;
                let weight = if k == 0 || k == panels {
                    1.0
                } else if k % 2 == 1 {
                    4.0
                } else {
                    2.0
                } * step
                    / 3.0;
                let f = slice(m + w * t.sin());
                for c in 0..3 {
                    total[c] += weight * w * t.cos() * f[c];
                }
            }
        }
        total
    };
    let coarse = simpson(2000);
    let fine = simpson(4000);
    let size = match *solid {
        Revolved::Frustum { r0, r1, len } => r0.max(r1).max(len),
        Revolved::Torus { big, small } => big + small,
    };
    let g = Vector3::new(
        e.x * fine[1] / fine[0],
        e.y * fine[1] / fine[0],
        fine[2] / fine[0],
    );
    let g_coarse = Vector3::new(
        e.x * coarse[1] / coarse[0],
        e.y * coarse[1] / coarse[0],
        coarse[2] / coarse[0],
    );
    assert!(
        (g - g_coarse).norm() < 1e-11 * size,
        "slicing oracle not converged: {g:?} vs {g_coarse:?}"
    );
    let pose = Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, z0), *q);
    expected_for(solid, &pose, &g)
}
