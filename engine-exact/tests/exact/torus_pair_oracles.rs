//! Oracles for a cylinder or frustum against a ring torus, written without the engine's
//! polar slicing or its azimuth search (used by [`crate::revolved_torus`] and the
//! characterization rows). The torus sits at the origin with axis `z`; I is the cylinder or
//! frustum, J the torus.
//!
//! - [`coaxial`]: a frustum on the torus' axis (bottom at `z₀`): by symmetry the volume is
//!   `2π∬ρ dA` and its first moment `2π∬ρz dA` over the meridian section (the tube's disc cut
//!   by the lines `ρ = r₀ + k(z − z₀)`, `z = z₀`, `z = z₀ + L`): a 1-D integral in the tube's
//!   angle `ψ` (`z = ρ_t sin ψ`) of the chords' closed-form moments, analytic between the
//!   angles where the slanted line crosses the tube's circle (a quadratic) and the caps'
//!   heights, by 48-node Gauss–Legendre per piece; the torus' area vector inside is
//!   `2π ρ_t [−R cos θ + ½ρ_t sin²θ] e_z` over the arcs `θ` of the meridian circle inside
//!   (closed form).
//! - [`divergence`]: any pose, by the divergence theorem over the intersection's boundary:
//!   the frustum's side and caps inside the torus and the torus' surface inside the frustum,
//!   each patch by [`crate::ellipsoid_oracles::surface_moments`] (boundary crossings sampled
//!   and bisected along each parameter line, Gauss–Kronrod across); optionally restricted to
//!   the half-space `x·v > 0` (a plane through the axis that must miss the intersection), for
//!   one of two regions. Its own error is the change between two tolerances and the closure
//!   `|S_I + S_J|` of the two surfaces' area vectors integrated apart: near 1e-15 for most
//!   poses, up to 2e-6 where a crossing's sampling misses a piece of an arc.
//! - [`rod_through_hole`]: a rod along `x` through the hole, its ends inside the tube: along
//!   each line parallel to the rod the region at `x > 0` is `[x_in, a]`, `x_in` where the
//!   line leaves the hole through the inner wall (`√((R − √(ρ_t² − z²))² − y²)`), so the
//!   moments are integrals over the rod's disc of closed forms, smooth there (Gauss–Legendre
//!   in the radius, the trapezoid rule around): converged to round-off. The rod's surface
//!   inside the torus is its end cap and the band of its side from `x_in` to `a`.

use crate::common::Expected;
use crate::ellipsoid_oracles::{CapPatch, Moments, Patch, contact_from, surface_moments};
use crate::ellipsoid_revolved::{frustum_exit, gauss};
use crate::torus_oracles::{torus_exit, torus_margin};
use contact_core::{Isometry3, Point3, Vector3};
use std::f64::consts::{PI, TAU};

/// A frustum of radii `r0` (bottom) and `r1` over `len`.
#[derive(Debug, Clone, Copy)]
pub struct Cone {
    pub r0: f64,
    pub r1: f64,
    pub len: f64,
}

impl Cone {
    fn slope(&self) -> f64 {
        (self.r1 - self.r0) / self.len
    }

    /// Positive inside (in the frustum's own frame).
    pub fn margin(&self, x: &Vector3) -> f64 {
        (self.r0 + self.slope() * x.z - x.xy().norm())
            .min(x.z)
            .min(self.len - x.z)
    }
}

/// The coaxial frustum `cone` with its bottom at height `z0` against the torus (`big`,
/// `small`): the expected contact (I the frustum), `None` when apart or when the area vector
/// vanishes.
pub fn coaxial(cone: &Cone, z0: f64, big: f64, small: f64) -> Option<Expected> {
    let k = cone.slope();
    let top = z0 + cone.len;
    // The slanted line ρ = r0 + k(z − z0) against the circle (ρ − R)² + z² = ρ_t²:
    // (1 + k²) z² + 2k(d − k z0) z + (d − k z0)² − ρ_t² = 0, d = r0 − R.
    let e = cone.r0 - big - k * z0;
    let (a, b, c) = (1.0 + k * k, k * e, e * e - small * small);
    let disc = b * b - a * c;
    let mut heights = vec![-small, small];
    if disc > 0.0 {
        heights.push((-b - disc.sqrt()) / a);
        heights.push((-b + disc.sqrt()) / a);
    }
    heights.push(z0);
    heights.push(top);
    let mut angles: Vec<f64> = heights
        .iter()
        .filter(|z| z.abs() <= small)
        .map(|z| (z / small).asin())
        .collect();
    angles.sort_by(f64::total_cmp);
    let rule = gauss(48);
    let (mut volume, mut first) = (0.0, 0.0);
    for w in angles.windows(2) {
        let (p0, p1) = (w[0], w[1]);
        for &(x, weight) in &rule {
            let psi = p0 + (p1 - p0) * x;
            let (z, s) = (small * psi.sin(), small * psi.cos());
            if z < z0 || z > top {
                continue;
            }
            let lo = big - s;
            let hi = (big + s).min(cone.r0 + k * (z - z0));
            if hi <= lo {
                continue;
            }
            // ∫ρ dρ over the chord, times dz = s dψ.
            let chord = 0.5 * (hi * hi - lo * lo) * s * weight * (p1 - p0);
            volume += TAU * chord;
            first += TAU * z * chord;
        }
    }
    if volume <= 0.0 {
        return None;
    }
    // The meridian circle's arcs inside the frustum: cut where it crosses its three lines.
    let inside = |theta: f64| {
        let (rho, z) = (big + small * theta.cos(), small * theta.sin());
        z >= z0 && z <= top && rho <= cone.r0 + k * (z - z0)
    };
    let mut cuts = Vec::new();
    for z in &heights[2..] {
        if z.abs() <= small {
            let t = (z / small).asin();
            cuts.extend([t, PI - t]);
        }
    }
    let mut cuts: Vec<f64> = cuts.into_iter().map(|t| t.rem_euclid(TAU)).collect();
    cuts.extend([0.0, TAU]);
    cuts.sort_by(f64::total_cmp);
    let antiderivative = |t: f64| -big * t.cos() + 0.5 * small * t.sin().powi(2);
    let mut s_z = 0.0;
    for w in cuts.windows(2) {
        if w[1] > w[0] && inside(0.5 * (w[0] + w[1])) {
            s_z += TAU * small * (antiderivative(w[1]) - antiderivative(w[0]));
        }
    }
    if s_z.abs() <= 1e-9 * small * small {
        return None;
    }
    let m = Moments {
        volume,
        centroid: Point3::new(0.0, 0.0, first / volume),
        // S_I + S_J = 0 over the intersection's closed surface.
        area_vector_i: -Vector3::z() * s_z,
    };
    let shift = Vector3::new(0.0, 0.0, z0);
    Some(contact_from(
        &m,
        |g, d| frustum_exit(cone.r0, cone.r1, cone.len, &(g - shift), d) + shift,
        |g, d| torus_exit(big, small, g, d),
    ))
}

/// A patch of a body at `pose`.
struct Posed<'a> {
    patch: &'a dyn Patch,
    pose: Isometry3,
}

impl Patch for Posed<'_> {
    fn s_range(&self) -> (f64, f64) {
        self.patch.s_range()
    }
    fn v_range(&self, s: f64) -> (f64, f64, bool) {
        self.patch.v_range(s)
    }
    fn point(&self, s: f64, v: f64) -> (Vector3, Vector3) {
        let (x, n) = self.patch.point(s, v);
        ((self.pose * Point3::from(x)).coords, self.pose.rotation * n)
    }
}

/// A frustum's lateral surface (`s` = height, `v` = angle).
struct Side(Cone);

impl Patch for Side {
    fn s_range(&self) -> (f64, f64) {
        (0.0, self.0.len)
    }
    fn v_range(&self, _: f64) -> (f64, f64, bool) {
        (0.0, TAU, true)
    }
    fn point(&self, s: f64, v: f64) -> (Vector3, Vector3) {
        let (sin, cos) = v.sin_cos();
        let (k, r) = (self.0.slope(), self.0.r0 + self.0.slope() * s);
        // ∂_v × ∂_h, outward.
        (
            Vector3::new(r * cos, r * sin, s),
            Vector3::new(r * cos, r * sin, -k * r),
        )
    }
}

/// The torus' surface (`s` = tube angle, `v` = azimuth).
pub struct Tube {
    pub big: f64,
    pub small: f64,
    /// The azimuths `[v0, v1]` covered (the whole turn: periodic).
    pub azimuths: (f64, f64),
    /// The tube angles covered.
    pub angles: (f64, f64),
}

impl Patch for Tube {
    fn s_range(&self) -> (f64, f64) {
        self.angles
    }
    fn v_range(&self, _: f64) -> (f64, f64, bool) {
        let (v0, v1) = self.azimuths;
        (v0, v1, v1 - v0 >= TAU)
    }
    fn point(&self, s: f64, v: f64) -> (Vector3, Vector3) {
        let (ss, cs) = s.sin_cos();
        let (sv, cv) = v.sin_cos();
        let rc = self.big + self.small * cs;
        (
            Vector3::new(rc * cv, rc * sv, self.small * ss),
            Vector3::new(cs * cv, cs * sv, ss) * (self.small * rc),
        )
    }
}

/// The frustum `cone` at `pose` (I) against the torus (J) by the divergence theorem, inside
/// the half-space `x·v > 0` when `half` is given, the torus' surface sampled over
/// `azimuths` (by default those the frustum's bounding ball reaches: the crossings along each
/// of its circles are found on 64 samples, which must be fine where the footprint is). The
/// moments, `None` when empty; with the oracle's own error: the larger of the change between
/// absolute tolerances `tol` and `100 tol` and the closure `|S_I + S_J|` of the two surfaces'
/// area vectors, integrated apart.
pub fn divergence(
    cone: &Cone,
    pose: &Isometry3,
    big: f64,
    small: f64,
    half: Option<Vector3>,
    azimuths: Option<(f64, f64)>,
    tol: f64,
) -> Option<(Moments, f64)> {
    let side = Side(*cone);
    let bottom = CapPatch {
        r: cone.r0,
        z: 0.0,
        up: false,
    };
    let top = CapPatch {
        r: cone.r1,
        z: cone.len,
        up: true,
    };
    let (s, b, t) = (
        Posed {
            patch: &side,
            pose: *pose,
        },
        Posed {
            patch: &bottom,
            pose: *pose,
        },
        Posed {
            patch: &top,
            pose: *pose,
        },
    );
    let mut own: Vec<&dyn Patch> = vec![&s];
    if cone.r0 > 0.0 {
        own.push(&b);
    }
    if cone.r1 > 0.0 {
        own.push(&t);
    }
    let middle = pose * Point3::new(0.0, 0.0, 0.5 * cone.len);
    let ball = cone.r0.max(cone.r1).hypot(0.5 * cone.len);
    let rho = middle.coords.xy().norm();
    let azimuths = azimuths.unwrap_or(if rho > ball {
        let (phi, spread) = (middle.y.atan2(middle.x), (ball / rho).asin() * 1.01);
        (phi - spread, phi + spread)
    } else {
        (0.0, TAU)
    });
    // The tube in 16 bands of its angle, each with its own 64 samples of the crossings'
    // count along the angle.
    let bands: Vec<Tube> = (0..16)
        .map(|k| Tube {
            big,
            small,
            azimuths,
            angles: (TAU * k as f64 / 16.0, TAU * (k + 1) as f64 / 16.0),
        })
        .collect();
    let tube: Vec<&dyn Patch> = bands.iter().map(|b| b as &dyn Patch).collect();
    let cut = |x: &Vector3, m: f64| half.map_or(m, |v| m.min(x.dot(&v)));
    let margin_torus = |x: &Vector3| cut(x, torus_margin(big, small, x));
    let margin_cone = |x: &Vector3| {
        cut(
            x,
            cone.margin(&pose.inverse_transform_point(&Point3::from(*x)).coords),
        )
    };
    let at = |tol: f64| surface_moments(&own, &margin_torus, &tube, &margin_cone, tol);
    let coarse = at(100.0 * tol)?;
    let fine = at(tol)?;
    // The same volume with the roles exchanged: its "I" area vector is the torus'.
    let s_j = surface_moments(&tube, &margin_cone, &own, &margin_torus, tol)?.area_vector_i;
    let error = (fine.volume - coarse.volume)
        .abs()
        .max((fine.centroid - coarse.centroid).norm())
        .max((fine.area_vector_i - coarse.area_vector_i).norm())
        .max((fine.area_vector_i + s_j).norm());
    Some((fine, error))
}

/// The contact of SPEC §4 from the divergence moments (I the frustum at `pose`).
pub fn contact_of(m: &Moments, cone: &Cone, pose: &Isometry3, big: f64, small: f64) -> Expected {
    contact_from(
        m,
        |g, d| {
            let local = pose.inverse_transform_point(g);
            pose * frustum_exit(
                cone.r0,
                cone.r1,
                cone.len,
                &local,
                &(pose.inverse_transform_vector(d)),
            )
        },
        |g, d| torus_exit(big, small, g, d),
    )
}

/// The rod of radius `c` along `x` from `−a` to `a` at height `lift` (I) against the torus
/// (J), ends inside the tube: the contacts of the regions at `x > 0` and `x < 0`.
pub fn rod_through_hole(c: f64, a: f64, lift: f64, big: f64, small: f64) -> [Expected; 2] {
    let rule = gauss(40);
    let turns = 256;
    let x_in = |y: f64, z: f64| {
        let w = (small * small - z * z).sqrt();
        ((big - w).powi(2) - y * y).sqrt()
    };
    let (mut volume, mut first) = (0.0, Vector3::zeros());
    let mut side = Vector3::zeros();
    for k in 0..turns {
        let theta = TAU * k as f64 / turns as f64;
        let (sin, cos) = theta.sin_cos();
        let dtheta = TAU / turns as f64;
        for &(u, w) in &rule {
            let r = c * u;
            let (y, z) = (r * cos, lift + r * sin);
            let x0 = x_in(y, z);
            let da = r * c * w * dtheta;
            volume += (a - x0) * da;
            first += Vector3::new(0.5 * (a * a - x0 * x0), y * (a - x0), z * (a - x0)) * da;
        }
        let x0 = x_in(c * cos, lift + c * sin);
        side += Vector3::new(0.0, cos, sin) * ((a - x0) * c * dtheta);
    }
    let m = Moments {
        volume,
        centroid: Point3::from(first / volume),
        area_vector_i: Vector3::new(PI * c * c, 0.0, 0.0) + side,
    };
    let rod = |g: &Point3, d: &Vector3| -> Point3 {
        // The rod's frame: axis x ↦ z, bottom at x = −a.
        let local = Point3::new(g.y, g.z - lift, g.x + a);
        let dl = Vector3::new(d.y, d.z, d.x);
        let p = crate::ellipsoid_oracles::cylinder_exit(c, 2.0 * a, &local, &dl);
        Point3::new(p.z - a, p.x, p.y + lift)
    };
    let positive = contact_from(&m, rod, |g, d| torus_exit(big, small, g, d));
    // The region at x < 0 by the mirror x ↦ −x.
    let mirror = |p: Point3| Point3::new(-p.x, p.y, p.z);
    let negative = Expected {
        point_i: mirror(positive.point_i),
        point_j: mirror(positive.point_j),
        normal: Vector3::new(-positive.normal.x, positive.normal.y, positive.normal.z),
        depth: positive.depth,
    };
    [positive, negative]
}
