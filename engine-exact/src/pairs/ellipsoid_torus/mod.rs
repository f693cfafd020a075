//! Ellipsoid against ring torus, by slicing across the torus' axis: one contact per region.
//!
//! ## The slices
//! In the torus' frame (axis `z`, centre at the origin, lengths divided by a power of two near
//! the pair's size) the plane `z = t`, `|t| < ρ`, cuts the torus in the annulus
//! `R − s ≤ |p| ≤ R + s`, `s = √(ρ² − t²)`, and the ellipsoid in an ellipse. Its overlap with
//! each of the annulus' circles is in closed form
//! ([`crate::methods::ellipsoid_sliced::disc_overlap::disc_ellipse`], the crossings a quartic's roots),
//! and the annulus' is the outer disc's less the inner one's (the inner disc lies in the
//! outer): volume, centroid and the area vector of the ellipsoid's surface inside the torus
//! by [`crate::methods::ellipsoid_sliced::integrand`] (linear in the overlap, the unsigned curved area
//! included since the ellipse's arcs inside the inner disc lie among those inside the outer).
//! The torus' own surface inside the ellipsoid, for the containment test and the area
//! estimate: `(ρ/s)·ρ_c·Δφ` per unit of `t` on each circle of radius `ρ_c = R ± s` (the tube's
//! element `ρ (R + ρ cos ψ) dψ dφ` with `t = ρ sin ψ`).
//!
//! The integration variable is that angle `ψ`: with `t = ρ sin ψ`, `s = ρ cos ψ` keeps its
//! digits near `t = ±ρ`, and the torus' surface rate, singular per `dt`, is `ρ·ρ_c·Δφ` per `dψ`
//! (as in [`super::box_revolved`]). Cuts: each region's lowest and highest slice and the
//! slices where the sections turn tangent inside ([`crate::methods::ellipsoid_sliced::shape_events`],
//! on the outer and inner overlaps' crossing counts); [`crate::quadrature::Adaptive`] with the
//! general ellipsoid pairs' floors between them.
//!
//! ## Regions
//! The torus is not convex: a rod through its hole meets the ring twice. A meridian
//! half-plane cuts both solids in convex sets (an ellipse, the tube's disc), so the regions
//! are the arcs of azimuth where those meet ([`meridian`], and
//! [`super::box_revolved::azimuth::region_wedges_of`], the box–torus pair's search): each is
//! integrated over the slices' part inside its wedge ([`wedge`]: Green's integrals about the
//! axis, on which the wedge's rays contribute nothing), one contact each. A region's lowest and
//! highest slice are the least and greatest `z` over its azimuths of the meridian sections'
//! overlap (the 2-D pencil extent, to round-off). When the sampling sees a single region
//! (or the ring all around, an ellipsoid through the hole) the whole turn is one region. The
//! box–torus pair's limit applies: a second region narrower than the 128 azimuth samples that
//! the golden-section refinement of the sampled minima also misses would share its
//! neighbour's wedge (one contact for the two); a region is never split.
//!
//! ## The contact
//! By [`crate::methods::volume_contact::contact_of_region`]. A region of a torus need not be convex, but
//! one thinner than 1e-6 of the size is a lens about a tangency (the gap between the surfaces
//! concave over a bounded footprint), so the convex pairs' test for unresolved lenses applies:
//! a lens whose sections are round-off (1e-9 of the size between curved surfaces) is touching.
//! When the area vector vanishes: with no surface of the torus inside the ellipsoid (the
//! ellipsoid inside the tube) the normal is the torus' outward normal at the surface point
//! nearest the centroid; otherwise (the torus inside the ellipsoid, or a symmetric overlap)
//! against the ellipsoid's level-surface normal at the centroid (`b`'s `−z` at its centre);
//! the area a quarter of the region's surface. Touching is no contact.

pub(crate) mod meridian;
pub(crate) mod wedge;

use super::box_revolved::azimuth::region_wedges_of;
use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::ellipsoid_sliced::disc_overlap::{DiscOverlap, disc_ellipse};
use crate::methods::ellipsoid_sliced::{
    COMPONENTS, Section, SlicedEllipsoid, ellipsoid_exit_w, ellipsoid_in, integrand, integrate,
    inward_of_ellipsoid, shape_events, to_world,
};
use crate::methods::solid_distance::{Solid, signed_distance};
use crate::ray_exit::surface_point_along_w;
use contact_core::geometry::Torus;
use contact_core::{Isometry3, Vector3, WorkCounters};
use meridian::{Meridians, lowest_and_highest};
use std::f64::consts::TAU;
use wedge::{Wedge, restrict};

/// The slice `t = ρ sin ψ`: the ellipsoid's section, the overlaps with the outer and inner
/// circles (restricted to the region's wedge), `s` and the circles' radii.
struct Slice {
    t: f64,
    s: f64,
    section: Section,
    outer: DiscOverlap,
    inner: DiscOverlap,
    radii: (f64, f64),
}

/// The torus (`big`, `small`) and the ellipsoid in its frame, working units.
struct Setup {
    ellipsoid: SlicedEllipsoid,
    big: f64,
    small: f64,
}

impl Setup {
    /// The slice at angle `psi`, restricted to `wedge` (`None`: the whole turn).
    fn slice(&self, psi: f64, wedge: Option<&Wedge>) -> Option<Slice> {
        let (sin, cos) = psi.sin_cos();
        let (t, s) = (self.small * sin, self.small * cos);
        if s.is_nan() || s <= 0.0 {
            return None;
        }
        let section = self.ellipsoid.section(t)?;
        let inverse = section.matrix.try_inverse()?;
        let q = inverse * -section.center;
        let radii = (self.big + s, self.big - s);
        let overlap = |radius: f64| {
            let o = disc_ellipse(&q, &(inverse * radius));
            match wedge {
                Some(w) => restrict(&o, &section.center, &section.matrix, radius, w),
                None => o,
            }
        };
        Some(Slice {
            t,
            s,
            section,
            outer: overlap(radii.0),
            inner: overlap(radii.1),
            radii,
        })
    }

    /// The integrand per unit of `ψ`.
    fn integrand(&self, psi: f64, wedge: Option<&Wedge>) -> [f64; COMPONENTS] {
        let Some(slice) = self.slice(psi, wedge) else {
            return [0.0; COMPONENTS];
        };
        let span = |o: &DiscOverlap| o.other_arcs.spans().iter().map(|(a, b)| b - a).sum::<f64>();
        // ρ·ρ_c·Δφ per dψ on each circle.
        let torus_surface =
            self.small * (slice.radii.0 * span(&slice.outer) + slice.radii.1 * span(&slice.inner));
        let outer = integrand(slice.t, &slice.section, &slice.outer, 0.0);
        let inner = integrand(slice.t, &slice.section, &slice.inner, 0.0);
        let mut out = [0.0; COMPONENTS];
        for k in 0..COMPONENTS {
            out[k] = (outer[k] - inner[k]) * slice.s;
        }
        out[COMPONENTS - 1] = torus_surface;
        out
    }

    /// The overlaps' shape class at `psi` (whole turn).
    fn shape(&self, psi: f64) -> usize {
        self.slice(psi, None)
            .map_or(0, |s| s.outer.shape + 8 * s.inner.shape)
    }
}

/// The contacts of the ellipsoid with `semi_axes` (`a`, at `pose_a`) with `torus` (`b`, at
/// `pose_b`), one per region, normals from `b` into `a`.
pub(crate) fn contacts(
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    torus: &Torus,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let unit = unit_for(
        semi_axes
            .max()
            .max(torus.major_radius() + torus.minor_radius()),
    );
    let (c, l) = ellipsoid_in(pose_b, pose_a, semi_axes, unit);
    let (big, small) = (torus.major_radius() / unit, torus.minor_radius() / unit);
    work.bounding_volume_tests += 1;
    let reach_z = l.row(2).norm();
    let reach_xy = (l.row(0).norm_squared() + l.row(1).norm_squared()).sqrt();
    let rho = c.xy().norm();
    // Above, below, beyond the ring, or within the cylinder of the hole's waist.
    if c.z - reach_z >= small
        || c.z + reach_z <= -small
        || rho >= big + small + reach_xy
        || rho + reach_xy <= big - small
    {
        return;
    }
    let Some(ellipsoid) = SlicedEllipsoid::new(c, &l) else {
        return;
    };
    let setup = Setup {
        ellipsoid,
        big,
        small,
    };
    let reach = l
        .column(0)
        .norm()
        .max(l.column(1).norm())
        .max(l.column(2).norm());
    let meridians = Meridians {
        q: ellipsoid.inverse().transpose() * ellipsoid.inverse(),
        c,
        big,
        small,
        outside: big + c.norm() + reach,
    };
    let gap = |phi: f64| meridians.gap(phi);
    // Every sampled local minimum is refined: the gap has no upper bound here.
    let (cuts_at, count) = region_wedges_of(gap, f64::INFINITY);
    let mut wedges = [Wedge {
        start: 0.0,
        end: TAU,
    }; 64];
    let regions = if count == 0 {
        1
    } else {
        for (w, &(start, end)) in wedges.iter_mut().zip(&cuts_at[..count]) {
            *w = Wedge { start, end };
        }
        count
    };
    let solid = Solid::Torus(*torus);
    for wedge in &wedges[..regions] {
        let restricted = (count > 0).then_some(wedge);
        let Some((integrals, inside_torus)) = region(&setup, &meridians, wedge, restricted, work)
        else {
            continue;
        };
        let moments = to_world(&integrals, pose_b, unit);
        let g = moments.centroid;
        let found = crate::methods::volume_contact::contact_of_region(
            &moments,
            |g, d| ellipsoid_exit_w(semi_axes, pose_a, g, d),
            |g, d| surface_point_along_w(&solid, pose_b, g, d),
            || {
                if inside_torus {
                    let p = pose_b.inverse_transform_point(&g).coords;
                    pose_b.rotation * signed_distance(&solid, &p).2
                } else {
                    inward_of_ellipsoid(semi_axes, pose_a, &g, pose_b)
                }
            },
            // The chord bound behind `unresolved_lens` is only applied to thin regions, and a
            // region of the torus thinner than 1e-6 of the size is a lens about a tangency,
            // between two surfaces whose gap is concave there (a bounded footprint): the bound
            // holds, and a lens whose sections are round-off gives no contact, as in the
            // convex pairs.
            true,
        );
        if let Some(contact) = found {
            emit(contact);
        }
    }
}

/// The moments of one region (azimuths `wedge`, the slices restricted to it when
/// `restricted`), and whether none of the torus' surface lies inside the ellipsoid; `None`
/// when the region is empty.
fn region(
    setup: &Setup,
    meridians: &Meridians,
    wedge: &Wedge,
    restricted: Option<&Wedge>,
    work: &mut WorkCounters,
) -> Option<(crate::methods::ellipsoid_sliced::Integrals, bool)> {
    // The region's deepest azimuth, a seed where its meridian overlap is not empty.
    let seed = deepest_azimuth(meridians, wedge);
    let (lo, hi) = lowest_and_highest(meridians, wedge.start, wedge.end, seed)?;
    let small = setup.small;
    let angle = |t: f64| (t / small).clamp(-1.0, 1.0).asin();
    let (lo, hi) = (angle(lo), angle(hi));
    if lo.is_nan() || hi.is_nan() || lo >= hi {
        return None;
    }
    let mut cuts = [0.0; 24];
    cuts[..2].copy_from_slice(&[lo, hi]);
    let mut n = 2;
    shape_events(lo, hi, |psi| setup.shape(psi), &mut cuts, &mut n);
    let mut f = |psi: f64| setup.integrand(psi, restricted);
    let integrals = integrate(&mut cuts[..n], &mut f, work);
    let inside_torus = integrals.surface_b == 0.0;
    Some((integrals, inside_torus))
}

/// The azimuth in `wedge` where the ellipsoid's meridian section comes nearest the tube's
/// centre, if its section overlaps the tube there: every sampled local minimum of the gap
/// refined by golden section (the gap decreases toward the ellipsoid's azimuths even where
/// the meridians miss it, see [`Meridians::gap`], so a narrow dip between samples lies
/// within a step of a sampled minimum).
fn deepest_azimuth(meridians: &Meridians, wedge: &Wedge) -> Option<f64> {
    const SAMPLES: usize = 96;
    let step = (wedge.end - wedge.start) / SAMPLES as f64;
    let at = |k: usize| wedge.start + step * (k as f64 + 0.5);
    let mut values = [0.0; SAMPLES];
    for (k, v) in values.iter_mut().enumerate() {
        *v = meridians.gap(at(k));
    }
    let whole = wedge.end - wedge.start >= TAU;
    let (mut best, mut value) = (at(0), f64::INFINITY);
    for k in 0..SAMPLES {
        let neighbour = |j: Option<usize>| j.map_or(f64::INFINITY, |j| values[j]);
        let (prev, next) = if whole {
            (
                values[(k + SAMPLES - 1) % SAMPLES],
                values[(k + 1) % SAMPLES],
            )
        } else {
            (
                neighbour(k.checked_sub(1)),
                neighbour((k + 1 < SAMPLES).then_some(k + 1)),
            )
        };
        if values[k] > prev || values[k] > next {
            continue;
        }
        let phi = crate::methods::sliced::golden_maximum(at(k) - step, at(k) + step, |x| {
            -meridians.gap(x)
        });
        let g = meridians.gap(phi).min(values[k]);
        if g < value {
            value = g;
            best = if meridians.gap(phi) <= values[k] {
                phi
            } else {
                at(k)
            };
        }
    }
    (value < 0.0).then_some(best)
}
