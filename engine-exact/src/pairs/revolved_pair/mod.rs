//! Frustum–frustum and cylinder–frustum (a cylinder is the frustum of equal radii; cones
//! included): the intersection's moments by the divergence theorem over the two lateral
//! surfaces ([`lateral`]: one-dimensional integrals over each surface's azimuth, cut at
//! closed-form events), or, for axes within [`PARALLEL`] of parallel, by slicing across `a`'s
//! axis and integrating each slice in polar coordinates about that axis; the contact from
//! them by [`crate::methods::volume_contact`].
//!
//! This file holds the entry points, the choice of method and the contact from the moments;
//! [`lateral`] and [`divergence`] the divergence theorem (`caps_clear`: when one lateral
//! surface is enough), [`mod@slice`] one slice's polar integrals, `outer` the integral over
//! the slices, [`quadric`] the surfaces and their closed-form events.
//!
//! ## The divergence theorem
//! With `ŵ` perpendicular to both axes, fields along `ŵ` have no flux through any cap, so the
//! volume and the first moments are fluxes through the lateral surfaces alone ([`lateral`]).
//! They are taken about the midpoint of the axes' closest points, and again about the
//! centroid so found when that point lies more than `REFERENCE_REACH` ([`divergence`]) of the region's
//! thicknesses from it (a small or thin region, whose fluxes would otherwise cancel far
//! above its volume). `a`'s area vector is its lateral surface's (the same integrals) and
//! its caps' overlaps with `b` (the polar slices below, at `t = 0, L`). Each azimuthal
//! integral runs on the 41-node Kronrod pair: the pieces between the events are analytic, and
//! the wider rule takes most of them whole where the 21-node one halves them twice.
//!
//! Where no cap can meet the intersection (the other solid wholly on one side of each cap's
//! plane, or the cap's disc outside its widest cylinder), one lateral surface is enough
//! ([`divergence`]): fields along a cylinder's axis, or radial from a cone's apex, are
//! tangent to that solid's lateral surface, so all their flux crosses the other's (half the
//! integrals: two long cylinders crossing away from their ends, a cylinder through a cone's
//! side).
//!
//! Grazing slivers (every generator meeting the other solid within 1e-5 of tangent to its
//! quadric, on both surfaces: their interval lengths have lost their digits) are declined
//! and sliced.
//!
//! ## The slicing (axes near parallel, grazing slivers, and the independent check)
//! In `a`'s frame (axis `z`, bottom at `z = 0`, lengths divided by a power of two near the
//! pair's size) the plane `z = t` cuts `a` in the disc `ρ ≤ R(t) = r₀ + k t`. In polar
//! coordinates `(ρ, φ)` about the axis point, the ray along `u(φ)` meets `b` in one interval in
//! closed form ([`mod@slice`]: a quadratic for `b`'s lateral surface, two planes for its caps),
//! so the section's area `∫½(β² − α²) dφ` and first moments `∫⅓(β³ − α³) u dφ` (`[α, β]` the
//! interval clipped to `[0, R]`) are one-dimensional integrals over `φ` of closed forms. They
//! are cut at [`quadric`]'s closed-form events (rays tangent to `b`'s section, rays through
//! its corners, `a`'s circle crossing `b`'s surface), where the ends have square-root ends or
//! kinks, so the sine-mapped adaptive rule ([`crate::quadrature::Adaptive`], 1e-13 relative)
//! converges on smooth pieces. The outer integral over `t` (the same rule, 1e-11 relative:
//! looser than the slices, whose acceptance noise it must not chase) runs between `a`'s ends,
//! `b`'s extent along `z` (its rims' extreme heights), the heights where `b`'s rims pierce
//! `a`'s lateral surface (a quartic each), where `a`'s radius equals `b`'s at the axis (a
//! coaxial `b`'s surface meeting `a`'s circle), the heights where the count of `a`'s circle's
//! crossings with `b`'s surface changes (the circle becoming tangent to it: the critical
//! heights of the intersection curve, found in each piece between the closed-form cuts by 64
//! samples and 40 more geometrically towards each end, and bisection, as in the ellipsoid
//! pairs' `shape_events`: a tangency often follows a rim's piercing within 1e-5), and the intersection's own lowest and highest slice. Cuts closer
//! than 1e-9 of the extent are merged: such a piece holds nothing, and its slices (within
//! round-off of a tangency) cost the inner rule its whole depth.
//!
//! Rays along `u` never lose precision with the axes' angle: `b`'s section, a huge far
//! ellipse or a long strip when its axis is nearly perpendicular to `a`'s, is never formed —
//! only its distance along each ray, by the stable root formula (`c/q` for the small root).
//!
//! ## The normal and the areas
//! The area vector of `a`'s surface inside `b` (outward of `a`), which
//! [`crate::methods::volume_contact`] turns into the normal: `a`'s lateral surface at `(t, φ)` is
//! inside `b` when `R(t)` lies in `b`'s interval along the ray, and sweeps
//! `(u − k e_z) R dφ dt` there; `a`'s caps add `∓e_z` times their overlap with `b` (the polar
//! section at `t = 0, L`, with `b`'s slab closed by 1e-12 so that a cap flush with `b`'s cap
//! counts). The unsigned area of `a`'s surface inside `b`: its lateral `√(1 + k²) R` per unit
//! of `φ` and `t` and its caps' overlaps. That of `b`'s surface inside `a` is not integrated
//! alongside (per ray it is `ρ/|n·u|`, singular where rays graze `b`): it serves only to judge
//! a vanishing `S_a` and to size a containment's area, so it is `b`'s whole surface (closed
//! form) when none of `a`'s is inside `b` (`b` inside `a`), `|S_a|` (the projected area, a
//! lower bound) while that is not vanishing, and otherwise the same slicing across `b`'s
//! axis (`a`'s surface inside `b` with the roles exchanged). A surface within 1e-6 of its
//! whole is taken as the whole in closed form, so either order gives the same area.
//!
//! ## Degenerate branches
//! - **Coaxial** (or parallel) axes: `b`'s sections are discs; no tangent rays from an axis
//!   inside, and a circle on `b`'s surface has no crossings (its coefficients vanish): `a`'s
//!   circle counts as inside `b` within 1e-12 of its radius, and the height where the two
//!   radii meet is a cut. A cap flush with `a`'s counts as `a`'s.
//! - **Perpendicular** axes: rays along `b`'s axis make the quadratic's leading coefficient
//!   vanish (the lateral roots go to infinity, the caps bound the interval); just above `b`'s
//!   lowest line its section is a strip of round-off width, whose slices the merged cuts skip.
//! - **Grazing**: the intersection's extent in `t` is found by bisection on "the slice is not
//!   empty" (exact between the `φ` cuts) from a slice inside: a cut piece's midpoint, one of
//!   33 samples, or for a sliver the maximiser of the concave margin
//!   `min(−h_a, −h_b)` (`h` the distance-like convex functions of [`quadric::Quadric::inside`])
//!   by nested golden sections; a positive margin nowhere is no contact. Touching is no
//!   contact.
//! - **One inside the other**, **symmetric crossings** (a rod through both caps of a disc)
//!   and **identical solids**: `|S_a|` vanishes against the intersection's surface; as in the
//!   cylinder pairs, with no surface of `b` inside `a` (`a` inside `b`) the normal is `b`'s
//!   outward normal at its face nearest the centroid, otherwise (`b` inside `a`, a crossing,
//!   identical solids) the opposite of `a`'s nearest face normal; area a quarter of the
//!   intersection's surface.

mod caps_clear;
mod divergence;
#[cfg(test)]
mod divergence_tests;
pub(crate) mod lateral;
mod outer;
pub(crate) mod quadric;
pub(crate) mod slice;
#[cfg(test)]
mod tests;

use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::ellipsoid_sliced::COMPONENTS;
use crate::methods::solid_distance::{Solid, signed_distance};
use crate::methods::volume_contact::{self, ENCLOSED, VolumeMoments};
use crate::quadrature::Adaptive;
use crate::ray_exit::surface_point_along_w;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
pub(crate) use divergence::Unresolved;
use divergence::{Surfaces, divergence_sums};
use quadric::Quadric;
use slice::Pair;

/// A surface inside the other solid within this fraction of its whole is all of it (the
/// unsigned areas converge to 1e-9).
const WHOLE: f64 = 1e-6;

/// `(bottom radius, top radius, length)` of a cylinder or frustum; `None` otherwise.
pub(crate) fn dimensions(solid: &Solid) -> Option<(f64, f64, f64)> {
    match solid {
        Solid::Cylinder(c) => Some((c.radius(), c.radius(), c.length())),
        Solid::Frustum(f) => Some((f.bottom_radius(), f.top_radius(), f.length())),
        Solid::Box(_) | Solid::Torus(_) => None,
    }
}

/// The quadric of a solid with `dims`, bottom centre `origin` and unit `axis`, lengths over
/// `unit`.
pub(crate) fn quadric_of(
    (r0, r1, len): (f64, f64, f64),
    origin: Vector3,
    axis: Vector3,
    unit: f64,
) -> Quadric {
    Quadric {
        origin,
        axis,
        r0: r0 / unit,
        slope: (r1 - r0) / len,
        len: len / unit,
    }
}

/// The whole surface of a frustum: its caps and its lateral surface `π(r₀ + r₁)·slant`.
pub(crate) fn surface_of(q: &Quadric) -> f64 {
    let r1 = q.r0 + q.slope * q.len;
    std::f64::consts::PI * (q.r0 * q.r0 + r1 * r1 + (q.r0 + r1) * q.len * q.slope.hypot(1.0))
}

/// How the intersection's moments are integrated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Method {
    /// By the divergence theorem over the lateral surfaces ([`lateral`]) unless the axes are
    /// within [`PARALLEL`] of parallel, sliced there.
    Divergence,
    /// Always sliced across `a`'s axis (the divergence theorem's independent check).
    #[cfg_attr(not(test), allow(dead_code))]
    Sliced,
    /// The divergence theorem, or [`Unresolved`] where it declines (the caller slices its
    /// own way).
    DivergenceOnly,
}

/// Axes whose angle's sine is below this are sliced: the lateral surfaces' tangency events
/// lose their conditioning as the generators turn parallel to the other's axis, and the
/// slicing's coaxial branches take over continuously.
pub(crate) const PARALLEL: f64 = 1e-3;

/// What [`sums`] found.
struct Sums {
    /// The pair in working units.
    pair: Pair,
    /// `[V, ∫t, ∫x, ∫y, S_a (3), a's surface inside b, b's surface inside a or 0]`.
    r: [f64; COMPONENTS],
    /// The working unit.
    unit: f64,
    /// Whether the last component is `b`'s surface inside `a` (the divergence theorem's),
    /// not yet to be found (the slicing's).
    surface_b: bool,
}

/// `solid_a` at `pose_a` and `solid_b` at `pose_b` in working units (`a`'s frame over the
/// returned unit), with `b`'s extent `[lo, hi]` along `a`'s axis clipped to `a`: `(pair,
/// unit, lo, hi)`, or `None` when they are apart.
fn setup(
    solid_a: &Solid,
    pose_a: &Isometry3,
    solid_b: &Solid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Option<(Pair, f64, f64, f64)> {
    let (dims_a, dims_b) = (dimensions(solid_a)?, dimensions(solid_b)?);
    let size = |(r0, r1, len): (f64, f64, f64)| r0.max(r1).max(len);
    let unit = unit_for(size(dims_a).max(size(dims_b)));
    let pose_ab = pose_a.inv_mul(pose_b);
    let pair = Pair {
        a: quadric_of(dims_a, Vector3::zeros(), Vector3::z(), unit),
        b: quadric_of(
            dims_b,
            pose_ab.translation.vector / unit,
            pose_ab.rotation * Vector3::z(),
            unit,
        ),
    };
    // Bounding spheres about the axes' midpoints: apart.
    work.bounding_volume_tests += 1;
    let ball = |q: &Quadric| {
        let r1 = q.r0 + q.slope * q.len;
        (
            q.origin + q.axis * (0.5 * q.len),
            q.r0.max(r1).hypot(0.5 * q.len),
        )
    };
    let ((ca, ra), (cb, rb)) = (ball(&pair.a), ball(&pair.b));
    if (ca - cb).norm() >= ra + rb {
        return None;
    }
    let (b_lo, b_hi) = pair.b_range();
    let (lo, hi) = (b_lo.max(0.0), b_hi.min(pair.a.len));
    if lo.is_nan() || hi.is_nan() || lo >= hi {
        return None;
    }
    Some((pair, unit, lo, hi))
}

/// The integrals `[V, ∫t, ∫x, ∫y, S_a (3), a's surface inside b, …]` of `solid_a` at `pose_a`
/// against `solid_b` at `pose_b` in working units (`a`'s frame over the returned unit), or
/// `None` when they are apart or only touch; `Unresolved` when `method` asks for the
/// divergence theorem only and it declines.
fn sums(
    solid_a: &Solid,
    pose_a: &Isometry3,
    solid_b: &Solid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    method: Method,
) -> Result<Option<Sums>, Unresolved> {
    let Some((pair, unit, lo, hi)) = setup(solid_a, pose_a, solid_b, pose_b, work) else {
        return Ok(None);
    };
    let across = Vector3::new(-pair.b.axis.y, pair.b.axis.x, 0.0);
    if method != Method::Sliced && across.norm() >= PARALLEL {
        match divergence_sums(
            &pair,
            &across.normalize(),
            (lo, hi),
            Surfaces::OneWherePossible,
            work,
        ) {
            Ok(r) => {
                return Ok(r.map(|r| Sums {
                    pair,
                    r,
                    unit,
                    surface_b: true,
                }));
            }
            Err(unresolved) if method == Method::DivergenceOnly => return Err(unresolved),
            Err(_) => {}
        }
    }
    Ok(outer::sliced_sums(pair, unit, (lo, hi), work))
}

/// Adds `a`'s caps inside `b` (zero when `b`'s extent `[lo, hi]` along `z` misses them) to
/// the area vector and the unsigned area of `r`, by the polar slices of `rule` and `floor`,
/// `b`'s slab widened by [`slice::ON_SURFACE`] when `closed`.
fn add_caps(
    pair: &Pair,
    (lo, hi): (f64, f64),
    (rule, floor, closed): (&Adaptive, f64, bool),
    r: &mut [f64; COMPONENTS],
    work: &mut WorkCounters,
) {
    for (cap, sign) in [(0.0, -1.0), (pair.a.len, 1.0)] {
        if cap >= lo && cap <= hi {
            let area = pair.slice_by((rule, floor), cap, closed, work)[0];
            r[6] += sign * area;
            r[7] += area;
        }
    }
}

/// The contact of the cylinder or frustum `solid_a` at `pose_a` with the cylinder or frustum
/// `solid_b` at `pose_b` (normal from `b` into `a`), or `None` without overlap.
pub(crate) fn contact(
    solid_a: &Solid,
    pose_a: &Isometry3,
    solid_b: &Solid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    contact_by(solid_a, pose_a, solid_b, pose_b, work, Method::Divergence)
}

/// [`contact`], the moments integrated by `method` (never [`Method::DivergenceOnly`], whose
/// refusal [`divergence_contact`] reports).
pub(crate) fn contact_by(
    solid_a: &Solid,
    pose_a: &Isometry3,
    solid_b: &Solid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    method: Method,
) -> Option<PairContact> {
    contact_with(solid_a, pose_a, solid_b, pose_b, work, method)
        .ok()
        .flatten()
}

/// [`contact`] by the divergence theorem alone (axes at least [`PARALLEL`] apart), or
/// [`Unresolved`] for a grazing sliver it does not resolve.
pub(crate) fn divergence_contact(
    solid_a: &Solid,
    pose_a: &Isometry3,
    solid_b: &Solid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Result<Option<PairContact>, Unresolved> {
    contact_with(
        solid_a,
        pose_a,
        solid_b,
        pose_b,
        work,
        Method::DivergenceOnly,
    )
}

/// [`contact`] by `method`.
fn contact_with(
    solid_a: &Solid,
    pose_a: &Isometry3,
    solid_b: &Solid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    method: Method,
) -> Result<Option<PairContact>, Unresolved> {
    let Some(Sums {
        pair,
        mut r,
        unit,
        surface_b,
    }) = sums(solid_a, pose_a, solid_b, pose_b, work, method)?
    else {
        return Ok(None);
    };
    let volume = r[0];
    if volume.is_nan() || volume <= 0.0 {
        return Ok(None);
    }
    // b's surface inside a (see the module docs): all of it when none of a's is inside b,
    // else |S_a| stands for it unless S_a vanishes, when it is integrated across b's axis.
    let s_a = Vector3::new(r[4], r[5], r[6]);
    let (whole_a, whole_b) = (surface_of(&pair.a), surface_of(&pair.b));
    // A whole surface inside the other solid, in closed form: either order then gives the
    // same area.
    let whole = |r: &mut [f64; COMPONENTS]| {
        if r[7] >= (1.0 - WHOLE) * whole_a {
            r[7] = whole_a;
        }
        if r[8] >= (1.0 - WHOLE) * whole_b {
            r[8] = whole_b;
        }
    };
    if surface_b {
        whole(&mut r);
    } else {
        let none_of_a = r[7] <= ENCLOSED * whole_b;
        r[8] = if none_of_a { whole_b } else { s_a.norm() };
        if !none_of_a && s_a.norm() <= ENCLOSED * (r[7] + r[8]) {
            r[8] = sums(solid_b, pose_b, solid_a, pose_a, work, method)
                .ok()
                .flatten()
                .map_or(0.0, |s| s.r[7]);
            whole(&mut r);
        }
    }
    Ok(region_contact(
        &r,
        unit,
        (solid_a, pose_a),
        (solid_b, pose_b),
        true,
    ))
}

/// The contact of one region of two revolved solids (or a torus) from its sums `r` in
/// `a`'s frame, lengths in units of `unit` (the layout of [`sums`]: volume, the z, x and y
/// moments, `a`'s area vector inside `b`, `a`'s surface inside `b` and `b`'s inside `a`,
/// both settled by the caller). The points follow the ray rule on the two surfaces; where
/// the area vector vanishes, the normal is the closest-point one of the body holding the
/// other. `convex` false for a region that need not be convex (a torus').
pub(crate) fn region_contact(
    r: &[f64; COMPONENTS],
    unit: f64,
    (solid_a, pose_a): (&Solid, &Isometry3),
    (solid_b, pose_b): (&Solid, &Isometry3),
    convex: bool,
) -> Option<PairContact> {
    let volume = r[0];
    let centroid = pose_a * Point3::from(Vector3::new(r[2], r[3], r[1]) / volume * unit);
    let s_a = Vector3::new(r[4], r[5], r[6]);
    let a_inside_b = r[8] <= ENCLOSED * (r[7] + r[8]);
    let moments = VolumeMoments {
        volume: volume * unit * unit * unit,
        centroid,
        area_vector_a: pose_a.rotation * s_a * (unit * unit),
        surface_area: (r[7] + r[8]) * unit * unit,
        length: unit,
    };
    let fallback = || {
        if a_inside_b {
            let p = pose_b.inverse_transform_point(&centroid).coords;
            pose_b.rotation * signed_distance(solid_b, &p).2
        } else {
            let p = pose_a.inverse_transform_point(&centroid).coords;
            -(pose_a.rotation * signed_distance(solid_a, &p).2)
        }
    };
    volume_contact::contact_of_region(
        &moments,
        |g, d| surface_point_along_w(solid_a, pose_a, g, d),
        |g, d| surface_point_along_w(solid_b, pose_b, g, d),
        fallback,
        convex,
    )
}
