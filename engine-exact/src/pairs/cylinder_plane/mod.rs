//! Cylinder against an unbounded plane: quadrature of closed-form slices, converged to
//! round-off.
//!
//! In the cylinder's frame (axis +z, bottom face at z = 0, top at `L`, radius `R`) the plane's
//! solid is `n·x ≤ h`; write `n = a·e + b·ẑ` with `e` the unit radial direction of `n`
//! (`a ≥ 0`). A line of the cylinder parallel to its axis at radial coordinate `u = e·x`
//! lies in the solid over the interval `z ∈ [z_lo(u), z_hi(u)] ∩ [0, L]` — `z ≤ (h − a u)/b`
//! for `b > 0`, `z ≥ (h − a u)/b` for `b < 0`, all or nothing for `b = 0` — a length `ℓ(u)`
//! that is piecewise linear in `u` with at most two kinks. So the volume and moments are
//! one-dimensional integrals over the disc's chords, `V = ∫ 2√(R² − u²)·ℓ(u) du`; with
//! `u = R sin φ` the integrand `2R² cos²φ·ℓ(R sin φ)` is a trigonometric polynomial on each
//! piece between kinks. On a piece `ℓ = L₀ + L₁u` and the height moment is quadratic in `u`,
//! so the piece needs only `∫ 2√(R² − u²) uᵏ du`, `k ≤ 2`, whose antiderivatives are closed
//! forms in `φ`, `sin φ = u/R` and `cos φ`: no trigonometric call beyond the kinks' `asin`.
//! A piece within `R/2` of the rim whose inner end is a kink (the cuts of shallow contacts)
//! takes its moments about that kink (`end_piece`, `rim_moments`): series in the distance
//! from the rim, free of the cancellations below and of the kink's `asin`. For the other
//! pieces, a difference of antiderivatives loses digits on a small piece and `L₀ + L₁u` on
//! an axis nearly parallel to the plane (huge `L₀`, `L₁` of opposite sign), so each piece's
//! closed form is kept only where its round-off bound (8ε times the terms' magnitudes) is
//! below 1e-13 of the piece's integrals; otherwise the piece is summed node by node by
//! 12-node Gauss–Legendre in `φ` ([`crate::quadrature`]), exact to round-off on these
//! polynomials, each interval's length formed at its node. In practice a shallow contact is
//! wholly series (a wheel on the ground: no `asin` at all), a deep one wholly closed form,
//! and the node rule is left to pieces that are neither. This stays exact when
//! the axis is parallel to the plane (a wheel on the ground, `b = 0`) or perpendicular to it
//! (`a = 0`).
//!
//! - **an axis parallel to the plane within round-off** (`|b|·L` no larger than a few ulps of
//!   the lengths that went into `h`) is taken as parallel (`b = 0`). A line contact's
//!   centroid slides along the axis by about `b·L²/(8h)`, so at a grazing depth (`h` of
//!   1e-12 of the size) a tilt at round-off, 1e-16, would move it by 1e-4 of the size: noise
//!   amplified 10¹². The answer for `b = 0` is the exact answer for an orientation within
//!   round-off of the given one (backward stable), and it differs from the unsnapped answer
//!   by less than 1e-12 of the size once the depth exceeds 1e-4·L (ε·L²/h);
//! - contact iff the volume is positive; normal: the plane's outward normal;
//! - points (SPEC §4, taken along the normal through the centroid `g`: `ray_exit`):
//!   the foot of `g` on the plane, and where the line from `g` along `−n` leaves the cylinder
//!   (side or cap); δ is their distance;
//! - area (an estimate, exact for a wheel on its side or a cylinder standing upright): the
//!   plane's section inside the cylinder, `(1/|b|)·∫ chord` over the `u` where the plane
//!   meets the cylinder between its caps (its `b → 0` limit `chord(h/a)·L` once
//!   `|b| < 1e-9`); when the plane no longer cuts the cylinder (full immersion), the
//!   quarter of the cylinder's surface `π R (R + L)/2` (its mean projected area, as for
//!   the box pairs).

use crate::kernel::PairContact;
use crate::methods::solid_distance::Solid;
use crate::quadrature;
use crate::ray_exit::{cylinder_exit, surface_point_along};
use contact_core::geometry::Cylinder;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use std::f64::consts::{FRAC_PI_2, PI};

/// Contact of `cylinder` at `pose_c` with the plane at `pose_plane` (flipped when `side < 0`).
pub(crate) fn contact(
    cylinder: &Cylinder,
    pose_c: &Isometry3,
    pose_plane: &Isometry3,
    side: f64,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    contact_by(cylinder, pose_c, pose_plane, side, work, Rule::ClosedForm)
}

/// [`contact`], handed to `emit` when there is one: built where it is consumed, so the
/// contact is not stored on return and read back before the stores retire.
pub(crate) fn emit_contact(
    cylinder: &Cylinder,
    pose_c: &Isometry3,
    pose_plane: &Isometry3,
    side: f64,
    work: &mut WorkCounters,
    emit: &mut impl FnMut(PairContact),
) {
    if let Some(c) = contact_by(cylinder, pose_c, pose_plane, side, work, Rule::ClosedForm) {
        emit(c);
    }
}

/// How each piece's chord integrals are taken.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Rule {
    /// In closed form where its round-off bound allows, else node by node.
    ClosedForm,
    /// Node by node always (the reference the closed form is tested against).
    #[cfg(test)]
    Nodes,
}

/// [`contact`] with the rule for the pieces' integrals.
#[inline(always)]
fn contact_by(
    cylinder: &Cylinder,
    pose_c: &Isometry3,
    pose_plane: &Isometry3,
    side: f64,
    work: &mut WorkCounters,
    rule: Rule,
) -> Option<PairContact> {
    let (r, len) = (cylinder.radius(), cylinder.length());
    let rotation = pose_c.rotation;
    let normal_w = side * (pose_plane.rotation * Vector3::z());
    let n = rotation.inverse_transform_vector(&normal_w);
    // A rotation keeps dot products: the plane's height over the cylinder's origin is read in
    // the world, one rotation fewer.
    let h = normal_w.dot(&(pose_plane.translation.vector - pose_c.translation.vector));
    let a = n.xy().norm();
    let b = parallel_within_round_off(n.z, h, len, r, pose_c, pose_plane);
    // The cylinder's lowest point along n: reject before integrating.
    if (b * len).min(0.0) - a * r >= h {
        return None;
    }
    let e = if a > 0.0 {
        n.xy() * (1.0 / a)
    } else {
        nalgebra::Vector2::x()
    };
    let (volume, moment_u, moment_z, section) = slice_moments(a, b, h, r, len, rule, work);
    if volume <= 0.0 {
        return None;
    }
    let inv_volume = 1.0 / volume;
    let u_bar = moment_u * inv_volume;
    let centroid = Vector3::new(e.x * u_bar, e.y * u_bar, moment_z * inv_volume);
    let to_plane = (h - n.dot(&centroid)).max(0.0);
    let on_plane = centroid + to_plane * n;
    // Along the normal the two points are `to_plane + t` apart, `t` the ray's exit from the
    // cylinder: no root of their difference's square (the last step of a long chain).
    let (on_cylinder, depth) = match cylinder_exit(cylinder, &centroid, &-n) {
        Some(t) => (centroid - t * n, to_plane + t),
        None => {
            let on = surface_point_along(&Solid::Cylinder(*cylinder), &centroid, &-n);
            (on, (on_plane - on).norm())
        }
    };
    let area = if b.abs() < 1e-9 {
        let u = h / a;
        if u.abs() < r {
            2.0 * ((r - u) * (r + u)).sqrt() * len / a
        } else {
            0.0
        }
    } else {
        section / b.abs()
    };
    let area = if area > 0.0 {
        area
    } else {
        0.5 * PI * r * (r + len)
    };
    let center = pose_c.translation.vector;
    let world = |p: Vector3| Point3::from(center + rotation * p);
    Some(PairContact {
        point_a: world(on_cylinder),
        point_b: world(on_plane),
        normal: normal_w,
        depth,
        area,
    })
}

/// The cuts of `u ∈ [−R, R]` for [`slice_moments`]: its ends (`φ = ±π/2`) and between them
/// the kinks of `ℓ(u)`, where the plane `a·u + b·z = h` meets the planes of the bottom and
/// top caps (clamped to `±R`), sorted by `u`; the cuts and their number (two to four).
#[inline(always)]
fn kink_cuts(a: f64, b: f64, h: f64, r: f64, len: f64) -> ([Cut; 4], usize) {
    // Kinks of ℓ(u) with the sine u/R of their angle φ = asin(u/R), sorted, with the ends
    // ±π/2. The angle itself (an `asin`) and its cosine are taken only for a piece that
    // needs them: one the end-piece series does not serve.
    let end = |s: f64| Cut {
        phi: s * FRAC_PI_2,
        sin: s,
        u: s * r,
        z: f64::NAN,
    };
    let mut cuts = [end(-1.0), end(1.0), end(1.0), end(1.0)];
    let mut count = 1;
    // Divisions are slow and chain: each divisor's reciprocal once.
    let inv_r = 1.0 / r;
    if a > 0.0 {
        let inv_a = 1.0 / a;
        let kinks = if b != 0.0 {
            [(h * inv_a, 0.0), ((h - b * len) * inv_a, len)]
        } else {
            [(h * inv_a, 0.0), (h * inv_a, 0.0)]
        };
        for (u, z) in kinks {
            let clamped = u.clamp(-r, r);
            cuts[count] = Cut {
                // A kink clamped to the rim has its angle already: ±π/2.
                phi: if clamped == u {
                    f64::NAN
                } else {
                    clamped.signum() * FRAC_PI_2
                },
                sin: clamped * inv_r,
                u: clamped,
                z: if clamped == u { z } else { f64::NAN },
            };
            count += 1;
        }
    }
    cuts[count] = end(1.0);
    count += 1;
    // The ends are the extremes (the kinks are clamped to ±R): only the kinks need ordering,
    // by `u` (the angle rises with it).
    if count == 4 && cuts[1].u.total_cmp(&cuts[2].u).is_gt() {
        cuts.swap(1, 2);
    }
    (cuts, count)
}

/// The solid's volume, its first moments along `e` (radial, towards the plane's normal) and
/// along the axis, and the chords' integral where the plane crosses between the caps, for
/// the plane `a·u + b·z ≤ h` in the cylinder's frame (see the module doc).
#[inline(always)]
fn slice_moments(
    a: f64,
    b: f64,
    h: f64,
    r: f64,
    len: f64,
    rule: Rule,
    work: &mut WorkCounters,
) -> (f64, f64, f64, f64) {
    let (cuts, count) = kink_cuts(a, b, h, r, len);
    // Divisions are slow and chain: each divisor's reciprocal once.
    let inv_r = 1.0 / r;
    // Each cut's angle and antiderivatives at most once, for the pieces on both sides of it.
    let (mut antiderivatives, mut formed) = ([[0.0; 3]; 4], [false; 4]);
    let (mut volume, mut moment_u, mut moment_z, mut section) = (0.0, 0.0, 0.0, 0.0);
    // The plane's line z = (h − a u)/b as `constant + slope·u` (b ≠ 0).
    let line = if b != 0.0 {
        let inv_b = 1.0 / b;
        (h * inv_b, -a * inv_b)
    } else {
        (0.0, 0.0)
    };
    for k in 0..count - 1 {
        let (c0, c1) = (cuts[k], cuts[k + 1]);
        if c1.u <= c0.u {
            continue;
        }
        // On a piece the solid's z interval has fixed branches, read inside it (the middle of
        // its `u` range): each end is `const + slope·u`.
        let mid = 0.5 * (c0.u + c1.u);
        let ((lo_c, lo_s), (hi_c, hi_s)) = interval_branches(a, b, h, len, line, mid);
        if hi_c + hi_s * mid <= lo_c + lo_s * mid {
            continue;
        }
        // Does the plane cross the cylinder between its caps over this piece?
        let crosses = b != 0.0 && (0.0..=len).contains(&(line.0 + line.1 * mid));
        // A piece within R/2 of the rim (a shallow cut) takes the end-piece series, free of
        // the closed form's cancellations and of its `asin`; the others the closed form where
        // its round-off bound allows, else the node rule.
        let near_end = (rule == Rule::ClosedForm)
            .then(|| end_piece(r, &c0, &c1, (lo_c, lo_s), (hi_c, hi_s)))
            .flatten();
        let (v, mu, mz, chords) = match near_end {
            Some(sums) => sums,
            None => {
                for i in [k, k + 1] {
                    if !formed[i] {
                        antiderivatives[i] = chord_antiderivatives(&cuts[i], r, inv_r);
                        formed[i] = true;
                    }
                }
                let (f0, f1) = (antiderivatives[k], antiderivatives[k + 1]);
                closed_or_nodes(
                    (a, b, h, r, len),
                    (&c0, &c1),
                    (&f0, &f1),
                    ((lo_c, lo_s), (hi_c, hi_s)),
                    rule,
                    work,
                )
            }
        };
        volume += v;
        moment_u += mu;
        moment_z += mz;
        if crosses {
            section += chords;
        }
    }
    (volume, moment_u, moment_z, section)
}

/// A piece's `(volume, u-moment, z-moment, ∫ chords)` in closed form from its ends'
/// antiderivatives `f0`, `f1` where the round-off bound of that difference is far below the
/// piece's own integrals, else by the node rule (whose error is relative to the integrand),
/// for the plane `a·u + b·z ≤ h` (`shape = (a, b, h, R, L)`) and the piece's branches.
fn closed_or_nodes(
    (a, b, h, r, len): (f64, f64, f64, f64, f64),
    (c0, c1): (&Cut, &Cut),
    (f0, f1): (&[f64; 3], &[f64; 3]),
    ((lo_c, lo_s), (hi_c, hi_s)): ((f64, f64), (f64, f64)),
    rule: Rule,
    work: &mut WorkCounters,
) -> (f64, f64, f64, f64) {
    // ℓ = L₀ + L₁u and ½(hi² − lo²) = Z₀ + Z₁u + Z₂u².
    let length = [hi_c - lo_c, hi_s - lo_s];
    let height = [
        0.5 * (hi_c * hi_c - lo_c * lo_c),
        hi_c * hi_s - lo_c * lo_s,
        0.5 * (hi_s * hi_s - lo_s * lo_s),
    ];
    let (closed, bound) = chord_moments(r, f0, f1);
    let v = length[0] * closed[0] + length[1] * closed[1];
    let mu = length[0] * closed[1] + length[1] * closed[2];
    let mz = height[0] * closed[0] + height[1] * closed[1] + height[2] * closed[2];
    let (abs_l, abs_z) = (
        [length[0].abs(), length[1].abs()],
        [height[0].abs(), height[1].abs(), height[2].abs()],
    );
    let error = 8.0
        * f64::EPSILON
        * ((abs_l[0] + abs_z[0]) * bound[0]
            + (abs_l[0] + abs_l[1] + abs_z[1]) * bound[1]
            + (abs_l[1] + abs_z[2]) * bound[2]);
    if rule == Rule::ClosedForm && error <= 1e-13 * (v.abs() + mu.abs() + mz.abs()) {
        return (v, mu, mz, closed[0]);
    }
    // Node by node, each interval's length formed where it is evaluated (a nearly parallel
    // axis makes `L₀ + L₁u` a difference of huge terms).
    let (mut v, mut mu, mut mz, mut chords) = (0.0, 0.0, 0.0, 0.0);
    quadrature::for_each_node(angle(c0), angle(c1), |phi, w| {
        let (sin, cos) = phi.sin_cos();
        let u = r * sin;
        let weight = w * 2.0 * r * r * cos * cos;
        let (lo, hi) = interval(a, b, h, len, u);
        let length = (hi - lo).max(0.0);
        v += weight * length;
        mu += weight * length * u;
        mz += weight * 0.5 * (hi + lo) * length;
        chords += weight;
    });
    work.iterations += quadrature::NODES as u64;
    (v, mu, mz, chords)
}

/// A cut's angle `φ = asin(u/R)` (the ends carry theirs, ±π/2).
fn angle(c: &Cut) -> f64 {
    if c.phi.is_nan() { c.sin.asin() } else { c.phi }
}

/// A cut of the chords' range: the angle `φ` of `u = R sin φ` (NaN at a kink until
/// [`angle`] takes it) with its sine, `u` itself, and at a kink the height the plane's line
/// `(h − a u)/b` takes there exactly (0 or the length; NaN at the ends ±R).
#[derive(Debug, Clone, Copy)]
struct Cut {
    phi: f64,
    sin: f64,
    u: f64,
    z: f64,
}

/// The solid's z interval on the axial line at radial coordinate `u` (`z ≤ (h − a u)/b` for
/// `b > 0`, `z ≥ (h − a u)/b` for `b < 0`, all or nothing for `b = 0`), clipped to the caps.
fn interval(a: f64, b: f64, h: f64, len: f64, u: f64) -> (f64, f64) {
    if b > 0.0 {
        (0.0, ((h - a * u) / b).min(len))
    } else if b < 0.0 {
        (((h - a * u) / b).max(0.0), len)
    } else if a * u <= h {
        (0.0, len)
    } else {
        (0.0, 0.0)
    }
}

/// The solid's z interval on the axial line at radial coordinate `u`, as the branches that hold
/// there: `(lo, hi)`, each `(constant, slope)` of `const + slope·u` (`z ≤ (h − a u)/b` for
/// `b > 0` up to the top cap, `z ≥ (h − a u)/b` for `b < 0` from the bottom cap, all or
/// nothing for `b = 0`), with `line` the plane's line `(h/b, −a/b)`.
#[inline(always)]
fn interval_branches(
    a: f64,
    b: f64,
    h: f64,
    len: f64,
    line: (f64, f64),
    u: f64,
) -> ((f64, f64), (f64, f64)) {
    let z = line.0 + line.1 * u;
    if b > 0.0 {
        let hi = if z < len { line } else { (len, 0.0) };
        ((0.0, 0.0), hi)
    } else if b < 0.0 {
        let lo = if z > 0.0 { line } else { (0.0, 0.0) };
        (lo, (len, 0.0))
    } else if a * u <= h {
        ((0.0, 0.0), (len, 0.0))
    } else {
        ((0.0, 0.0), (0.0, 0.0))
    }
}

/// The antiderivatives of `∫ cos²φ sinᵏφ dφ`, `k = 0, 1, 2`, at a cut on the cylinder of
/// radius `r` (`inv_r` = 1/r): `(φ + s c)/2`, `−c³/3` and `φ/8 − s c (c² − s²)/8`. The cosine
/// is `√((R − u)(R + u))/R`, free of the cancellation of `√(1 − s²)` near the ends (0 there).
fn chord_antiderivatives(c: &Cut, r: f64, inv_r: f64) -> [f64; 3] {
    let co = ((r - c.u) * (r + c.u)).sqrt() * inv_r;
    let (s, phi) = (c.sin, angle(c));
    [
        0.5 * (phi + s * co),
        -co * co * co / 3.0,
        0.125 * (phi - s * co * (co * co - s * s)),
    ]
}

/// `∫ 2√(R² − u²)·uᵏ du` over the chords between two cuts, `k = 0, 1, 2`, in closed form
/// (with `u = R sin φ`: `2R^{2+k} ∫ cos²φ sinᵏφ dφ`, from the [`chord_antiderivatives`] `f0`,
/// `f1` at its ends), and for each the sum of the antiderivative's magnitudes at both ends: the
/// scale of its round-off.
fn chord_moments(r: f64, f0: &[f64; 3], f1: &[f64; 3]) -> ([f64; 3], [f64; 3]) {
    let scale = [2.0 * r * r, 2.0 * r * r * r, 2.0 * r * r * r * r];
    let mut moments = [0.0; 3];
    let mut bound = [0.0; 3];
    for k in 0..3 {
        moments[k] = scale[k] * (f1[k] - f0[k]);
        bound[k] = scale[k] * (f1[k].abs() + f0[k].abs());
    }
    (moments, bound)
}

/// A small piece at an end of the chords' range (`u` within `R/2` of `±R`, the cut of a
/// shallow contact), free of both cancellations of the closed form: its integrals about its
/// inner end `u_k` (a kink, where the plane's line takes its height exactly), with `ℓ` and
/// `½(hi² − lo²)` expanded about `u_k` and the moments `N_p = ∫ 2√(R² − u²)·|u − u_k|ᵖ du` by
/// the series of [`end_moments`]. `(volume, u-moment, z-moment, ∫ chords)`, or `None` for
/// any other piece.
#[inline(always)]
fn end_piece(
    r: f64,
    c0: &Cut,
    c1: &Cut,
    lo: (f64, f64),
    hi: (f64, f64),
) -> Option<(f64, f64, f64, f64)> {
    // The inner end (farther from the rim), the distances of both ends from the rim, and the
    // side of the piece (−1: next to u = −R).
    let (inner, eta, eta_rim, side) = if c1.u <= 0.0 {
        (c1, r + c1.u, r + c0.u, -1.0)
    } else if c0.u >= 0.0 {
        (c0, r - c0.u, r - c1.u, 1.0)
    } else {
        return None;
    };
    if eta > 0.5 * r || inner.z.is_nan() {
        return None;
    }
    // Each branch's value at the kink: a sloped one is the plane's line, exactly `z` there.
    let at = |(constant, slope): (f64, f64)| if slope != 0.0 { inner.z } else { constant };
    let (lo_k, hi_k) = (at(lo), at(hi));
    let (l0, l1) = (hi_k - lo_k, hi.1 - lo.1);
    let (z0, z1, z2) = (
        0.5 * (hi_k * hi_k - lo_k * lo_k),
        hi_k * hi.1 - lo_k * lo.1,
        0.5 * (hi.1 * hi.1 - lo.1 * lo.1),
    );
    let n = rim_moments(r, eta, eta_rim)?;
    // u − u_k = side·|u − u_k| over the piece.
    let volume = l0 * n[0] + side * l1 * n[1];
    let about_kink = side * (l0 * n[1] + side * l1 * n[2]);
    let height = z0 * n[0] + side * z1 * n[1] + z2 * n[2];
    Some((volume, inner.u * volume + about_kink, height, n[0]))
}

/// `∫ 2√(x(2R − x))·(η − x)ᵖ dx` over `x` from `η_rim` (the piece's end nearer the rim) to
/// `η`, `p = 0, 1, 2`: [`end_moments`] when the piece reaches the rim; the difference of the
/// whole range's moments and those below `η_rim` (re-centred on `η` by the binomial theorem,
/// all terms positive) when it is wide (`η − η_rim ≥ η/4`, so the difference keeps all but two
/// bits); else a Gauss rule of 8 nodes in `d = η − x` (4 on a piece narrower than `η/64`),
/// whose weight is then smooth (its root lies seven half-widths away or more): the rule's
/// error is below round-off.
/// `None` for a piece of no width.
#[inline(always)]
fn rim_moments(r: f64, eta: f64, eta_rim: f64) -> Option<[f64; 3]> {
    let width = eta - eta_rim;
    if width <= 0.0 {
        return None;
    }
    if eta_rim <= 0.0 {
        return Some(end_moments(r, eta));
    }
    if width >= 0.25 * eta {
        let (whole, below) = (end_moments(r, eta), end_moments(r, eta_rim));
        return Some([
            whole[0] - below[0],
            whole[1] - (below[1] + width * below[0]),
            whole[2] - (below[2] + 2.0 * width * below[1] + width * width * below[0]),
        ]);
    }
    // In the distance `d = η − x` from the inner end itself, so that `d` keeps its digits on
    // a piece far narrower than its distance from the rim. The weight is smooth here (its
    // root `x = 0` lies seven half-widths away or more): the n-node rule's relative error on
    // the p-th moment falls like `(width/η)^(2n − p)`, with small constants (measured:
    // 8e-12 at width η/8 for 4 nodes, 1e-15 at η/4 for 8). So 4 nodes reach round-off from
    // width η/64 (the narrow cut of a wheel resting all but parallel to the ground), 8 from
    // η/4 (the tests check both against a reference).
    let mut m = [0.0; 3];
    let add = |d: f64, w: f64| {
        let x = eta - d;
        let weight = w * 2.0 * (x * (2.0 * r - x)).sqrt();
        m[0] += weight;
        m[1] += weight * d;
        m[2] += weight * d * d;
    };
    if width <= eta / 64.0 {
        quadrature::for_each_node_4(0.0, width, add);
    } else {
        quadrature::for_each_node_8(0.0, width, add);
    }
    Some(m)
}

/// `N_p = ∫₀^η 2√(x(2R − x))·(η − x)ᵖ dx` for `p = 0, 1, 2` (the chords within `η` of the
/// rim, `x` the distance from it), by the binomial series of `√(2R − x)`:
/// `2√(2R)·η^{3/2+p}·Σ_j c_j (η/2R)^j B(3/2 + j, p + 1)`, `c_j = (−1)ʲ binom(½, j)`. Every
/// term has the sign of the first after it, and the ratio of terms is below `η/2R ≤ ¼`, so
/// the sum keeps its digits; 40 terms reach round-off.
#[inline(always)]
fn end_moments(r: f64, eta: f64) -> [f64; 3] {
    // 1/(2R) apart from η, which arrives last: one product on its way, not a division.
    let t = eta * (0.5 / r);
    let (mut sums, mut power) = ([0.0f64; 3], 1.0f64);
    for coefficients in &END_SERIES {
        sums[0] += coefficients[0] * power;
        sums[1] += coefficients[1] * power;
        sums[2] += coefficients[2] * power;
        if (coefficients[0] * power).abs() < 1e-18 * sums[0].abs() {
            break;
        }
        power *= t;
    }
    let lead = 2.0 * (2.0 * r).sqrt() * eta * eta.sqrt();
    [
        lead * sums[0],
        lead * eta * sums[1],
        lead * eta * eta * sums[2],
    ]
}

/// Terms of [`end_moments`]' series.
const END_TERMS: usize = 40;

/// `c_j·B(3/2 + j, p + 1)` for `p = 0, 1, 2`, `j < 40`, with `c_j = (−1)ʲ binom(½, j)`
/// (`B(x, 1) = 1/x`, `B(x, 2) = 1/(x(x+1))`, `B(x, 3) = 2/(x(x+1)(x+2))`): formed once, at
/// compile time, so the series is a sum of products.
const END_SERIES: [[f64; 3]; END_TERMS] = {
    let mut table = [[0.0; 3]; END_TERMS];
    let mut c = 1.0f64;
    let mut j = 0;
    while j < END_TERMS {
        let x = 1.5 + j as f64;
        let b1 = 1.0 / x;
        let b2 = b1 / (x + 1.0);
        let b3 = 2.0 * b2 / (x + 2.0);
        table[j] = [c * b1, c * b2, c * b3];
        c *= (j as f64 - 0.5) / (j as f64 + 1.0);
        j += 1;
    }
    table
};

/// `b` (the axis component of the plane normal in the cylinder's frame), or 0 when the tilt it
/// makes over the cylinder's length is within the round-off of the positions that went into
/// the plane height: the axis is then parallel to the plane as far as the input can tell.
fn parallel_within_round_off(
    b: f64,
    h: f64,
    len: f64,
    r: f64,
    pose_c: &Isometry3,
    pose_plane: &Isometry3,
) -> f64 {
    // The positions' magnitudes by their 1-norms (within √3 of their lengths, without a
    // square root on the way to every later step).
    let magnitude = pose_c.translation.vector.lp_norm(1)
        + pose_plane.translation.vector.lp_norm(1)
        + h.abs()
        + len
        + r;
    if b.abs() * len <= 8.0 * f64::EPSILON * magnitude {
        0.0
    } else {
        b
    }
}

#[cfg(test)]
mod tests;
