//! A box against a frustum (or cone) or a ring torus, and through the box a bounded PLANE
//! against them: the intersection's moments by slicing perpendicular to the solid's axis,
//! the contact from them by [`crate::methods::volume_contact`].
//!
//! ## The slices
//! In the revolved solid's frame (axis `z`, lengths divided by a power of two near the pair's
//! size) the plane `z = t` cuts the box in a convex polygon `P(t)` (a square about the axis,
//! larger than the solid's section, clipped by the box's six faces) and the solid in a disc
//! of radius `r(t) = r₀ + k t` (frustum, `0 ≤ t ≤ L`) or the annulus `R − s ≤ |p| ≤ R + s`,
//! `s = √(ρ² − t²)` (torus). [`crate::methods::disc_section`] gives the overlap of `P(t)` with a disc in
//! closed form: area, first moments, the circle's arcs inside `P` (angle `A` and `∫ν dφ`) and
//! each face's edge length inside; an annulus is the outer disc less the inner one.
//!
//! - `V = ∫ area dt`, the centroid from `∫(∫p dA, t·area) dt / V`.
//! - The area vector of the solid's lateral surface inside the box, by the moving section: an
//!   arc of the circle of radius `r(t)` sweeps `(ν − r′ e_z) r dφ dt` (outward), so per slice
//!   `r ∫ν dφ − r′ r A e_z`; the torus' inner circle, whose outward normal is `−ν`, sweeps
//!   `(−ν + r_i′ e_z) r_i dφ dt`. The frustum's caps add `∓e_z` times their overlap with `P` at
//!   `t = 0, L`. The box's surface inside the solid closes the same region, so its area vector
//!   is the opposite: `S_box = −S_solid`, which [`crate::methods::volume_contact`] takes as `S_a`.
//! - Unsigned areas: the lateral surface's `√(1 + r′²) r A` per slice (`ρ/s` for the torus),
//!   the box faces' edge lengths inside the section over `|g|` (the in-plane part of the unit
//!   face normal: a face's area per slice and per unit of edge), and the flat faces parallel to
//!   the slices (a box face, a cap) as their overlap at their height.
//!
//! A box face in the plane of a cap with the same outward normal (the box standing on the cap,
//! or the cap on the box: their solids on one side) is shared: it counts as the box's surface
//! (the first solid's, as in [`crate::methods::section`]), so the cap adds nothing. Faces within 1e-13
//! of the slices' direction (working units) count as parallel, and heights within 1e-13 as
//! coplanar.
//!
//! The quadrature ([`crate::quadrature::Adaptive`], 1e-13 relative per piece, the floors of
//! the general ellipsoid pairs) runs between the closed-form cuts of [`events`], on which
//! the overlap is smooth or has a square-root end (the sine-mapped rule absorbs those). A
//! torus is integrated in the angle `θ` of `t = ρ sin θ`, where its tube's half width
//! `ρ cos θ` keeps its digits near `t = ±ρ` and the swept terms, singular per `dt`, are
//! smooth (from `t`, the sections there lost the last 3e-7 of the area vector).
//!
//! ## Regions
//! A box meets a convex frustum in one convex region. A torus it may meet in several (a plate
//! through the ring): [`azimuth`] finds them as arcs of azimuth and each is integrated inside
//! its own wedge (a pair of half-planes through the axis that miss the intersection: the
//! section is further clipped by them, a wedge wider than π as two halves), one contact each.
//!
//! ## The contact (SPEC §4)
//! Normal `S_solid/|S_solid|` (from the solid into the box is `−S_box/|S_box|`, and the caller's
//! order decides the sign), points where the line through the centroid along it leaves each
//! body, area `|S|`. When `|S|` vanishes against the region's surface (one body inside the
//! other): with no surface of the solid inside the box, the box is inside the solid and the
//! normal is the solid's outward normal at its surface point nearest the centroid (pushing the
//! box out that way); otherwise the solid is inside the box and the normal is against the
//! outward normal of the box's face nearest the centroid; area a quarter of the surface.
//! Touching is no contact.

pub(crate) mod azimuth;
pub(crate) mod events;

use super::revolved_mesh::Profile;
use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::disc_section::{DiscSection, disc_section};
use crate::methods::ellipsoid_sliced::{ADAPTIVE, COMPONENTS, floor};
use crate::methods::section::Polygon;
use crate::methods::solid_distance::{Solid, signed_distance};
use crate::methods::volume_contact::{self, ENCLOSED, VolumeMoments};
use crate::quadrature::MAX_PIECES;
use crate::ray_exit::surface_point_along_w;
use contact_core::geometry::Cuboid;
use contact_core::{Isometry3, Point3, Vector2, Vector3, WorkCounters};

/// A face whose normal's in-plane part is at most this is parallel to the slices.
const FLAT: f64 = 1e-13;
/// Heights closer than this (working units) are the same plane.
const COPLANAR: f64 = 1e-13;
/// Most cuts (ends, corners, tangencies, piercings) of one pair.
const MAX_CUTS: usize = 96;

/// Up to two sub-wedges `(from, to)` (unit directions, counter-clockwise, each at most π)
/// that the section is clipped to; none for the whole turn.
#[derive(Debug, Clone, Copy)]
struct Wedge {
    halves: [(Vector2, Vector2); 2],
    count: usize,
}

impl Wedge {
    /// No clipping: the whole turn.
    fn whole() -> Self {
        Self {
            halves: [(Vector2::x(), Vector2::x()); 2],
            count: 0,
        }
    }

    fn new(start: f64, end: f64) -> Self {
        let dir = |a: f64| Vector2::new(a.cos(), a.sin());
        let span = end - start;
        if span <= std::f64::consts::PI {
            Self {
                halves: [(dir(start), dir(end)); 2],
                count: 1,
            }
        } else {
            let mid = start + 0.5 * span;
            Self {
                halves: [(dir(start), dir(mid)), (dir(mid), dir(end))],
                count: 2,
            }
        }
    }
}

/// The box (as six half-spaces and eight corners in the solid's frame) and the solid.
struct Setup {
    faces: [(Vector3, f64); 6],
    corners: [Vector3; 8],
    profile: Profile,
}

impl Setup {
    /// The box's section at `t` clipped to the wedge half `half` (if any), starting from a
    /// square of half side `2·outer`; the faces of axis `skip` are left out (a flat face's own
    /// pair, whose polygon is the face).
    fn polygon(
        &self,
        t: f64,
        outer: f64,
        skip: Option<usize>,
        half: Option<&(Vector2, Vector2)>,
    ) -> Polygon {
        let mut polygon = Polygon::rectangle(Vector2::new(2.0 * outer, 2.0 * outer));
        for (k, (n, d)) in self.faces.iter().enumerate() {
            if skip == Some(k / 2) {
                continue;
            }
            polygon.clip(&Vector2::new(n.x, n.y), d - n.z * t, 4 + k as u8);
        }
        if let Some((from, to)) = half {
            polygon.clip(&Vector2::new(from.y, -from.x), 0.0, 10);
            polygon.clip(&Vector2::new(-to.y, to.x), 0.0, 11);
        }
        polygon
    }

    /// Σ over the box faces of their edge length inside the section per unit of slice
    /// thickness.
    fn face_area_rate(&self, o: &DiscSection) -> f64 {
        let mut sum = 0.0;
        for (k, (n, _)) in self.faces.iter().enumerate() {
            let g = n.x.hypot(n.y);
            if g > FLAT {
                sum += o.lengths[4 + k] / g;
            }
        }
        sum
    }

    /// `(section overlap area with the solid at t)` for a polygon: the disc's or annulus'.
    fn overlap_area(&self, t: f64, polygon: &Polygon) -> f64 {
        let (v, l) = (polygon.vertices(), polygon.labels());
        match self.profile {
            Profile::Frustum { r0, slope, .. } => disc_section(r0 + slope * t, v, l).area,
            Profile::Torus { big, small } => {
                let s = ((small - t) * (small + t)).max(0.0).sqrt();
                disc_section(big + s, v, l).area - disc_section(big - s, v, l).area
            }
        }
    }

    /// The integrand at `t`: `[area, t·area, ∫x, ∫y, S_solid (3), solid's surface inside the
    /// box, box's surface inside the solid]` per unit of `t` for a frustum; for a torus per
    /// unit of `θ`, `t = ρ sin θ` (see [`Setup::torus_slice`]).
    fn slice(&self, t: f64, wedge: &Wedge) -> [f64; COMPONENTS] {
        let mut out = [0.0; COMPONENTS];
        let outer = self.profile.circles(t).0;
        if outer <= 0.0 {
            return out;
        }
        let Profile::Frustum { r0, slope, .. } = self.profile else {
            return out;
        };
        for h in 0..wedge.count.max(1) {
            let half = (wedge.count > 0).then(|| &wedge.halves[h]);
            let polygon = self.polygon(t, outer, None, half);
            let (v, l) = (polygon.vertices(), polygon.labels());
            if v.len() < 3 {
                continue;
            }
            let r = r0 + slope * t;
            let o = disc_section(r, v, l);
            out[0] += o.area;
            out[1] += t * o.area;
            out[2] += o.moment.x;
            out[3] += o.moment.y;
            out[4] += r * o.normal_integral.x;
            out[5] += r * o.normal_integral.y;
            out[6] -= slope * r * o.angle;
            out[7] += (1.0 + slope * slope).sqrt() * r * o.angle;
            out[8] += self.face_area_rate(&o);
        }
        out
    }

    /// The torus' integrand in the angle `θ` of `t = ρ sin θ`: the tube's half width
    /// `s = ρ cos θ` then has no cancellation near `t = ±ρ` (from `t` it loses all its digits
    /// there, and the swept terms `(t/s, ρ/s)·(r_o A_o + r_i A_i)` per `dt` are singular), and
    /// with `dt = s dθ` the swept terms per `dθ` are `(t, ρ)·(r_o A_o + r_i A_i)`: smooth.
    fn torus_slice(&self, theta: f64, wedge: &Wedge) -> [f64; COMPONENTS] {
        let mut out = [0.0; COMPONENTS];
        let Profile::Torus { big, small } = self.profile else {
            return out;
        };
        let (sin, cos) = theta.sin_cos();
        let (t, s) = (small * sin, small * cos);
        if s.is_nan() || s <= 0.0 {
            return out;
        }
        let (ro, ri) = (big + s, big - s);
        for h in 0..wedge.count.max(1) {
            let half = (wedge.count > 0).then(|| &wedge.halves[h]);
            let polygon = self.polygon(t, ro, None, half);
            let (v, l) = (polygon.vertices(), polygon.labels());
            if v.len() < 3 {
                continue;
            }
            let (oo, oi) = (disc_section(ro, v, l), disc_section(ri, v, l));
            let area = (oo.area - oi.area) * s;
            let swept = ro * oo.angle + ri * oi.angle;
            out[0] += area;
            out[1] += t * area;
            out[2] += (oo.moment.x - oi.moment.x) * s;
            out[3] += (oo.moment.y - oi.moment.y) * s;
            out[4] += (ro * oo.normal_integral.x - ri * oi.normal_integral.x) * s;
            out[5] += (ro * oo.normal_integral.y - ri * oi.normal_integral.y) * s;
            out[6] += t * swept;
            out[7] += small * swept;
            out[8] += (self.face_area_rate(&oo) - self.face_area_rate(&oi)) * s;
        }
        out
    }

    /// The flat pieces: the frustum's caps inside the box (area vector and unsigned area of
    /// the solid) and the box's faces parallel to the slices inside the solid.
    fn flat_terms(&self, wedge: &Wedge, s_z: &mut f64, solid_area: &mut f64, box_area: &mut f64) {
        let (b_lo, b_hi) = self.profile.range();
        let (z_lo, z_hi) = self.corner_range();
        let halves = wedge.count.max(1);
        let flat_faces = self.faces.iter().enumerate().filter_map(|(k, (n, d))| {
            (n.x.hypot(n.y) <= FLAT && n.z != 0.0).then_some((k, d / n.z, n.z.signum()))
        });
        for (k, height, _) in flat_faces.clone() {
            if height < b_lo || height > b_hi {
                continue;
            }
            let outer = self.profile.circles(height).0;
            for h in 0..halves {
                let half = (wedge.count > 0).then(|| &wedge.halves[h]);
                let polygon = self.polygon(height, outer, Some(k / 2), half);
                *box_area += self.overlap_area(height, &polygon);
            }
        }
        if let Profile::Frustum { len, .. } = self.profile {
            for (cap, sign) in [(0.0, -1.0), (len, 1.0)] {
                if cap < z_lo || cap > z_hi {
                    continue;
                }
                let shared = flat_faces
                    .clone()
                    .any(|(_, height, up)| (height - cap).abs() <= COPLANAR && up == sign);
                if shared {
                    continue;
                }
                let outer = self.profile.circles(cap).0;
                for h in 0..halves {
                    let half = (wedge.count > 0).then(|| &wedge.halves[h]);
                    let area = self.overlap_area(cap, &self.polygon(cap, outer, None, half));
                    *s_z += sign * area;
                    *solid_area += area;
                }
            }
        }
    }

    fn corner_range(&self) -> (f64, f64) {
        self.corners
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
                (lo.min(c.z), hi.max(c.z))
            })
    }
}

/// `∫ slice` over the pieces between `cuts` (heights), in runs of at most [`MAX_PIECES`]
/// pieces; a torus in the angle `θ` of `t = ρ sin θ`.
fn integrate(
    setup: &Setup,
    wedge: &Wedge,
    cuts: &[f64],
    work: &mut WorkCounters,
) -> [f64; COMPONENTS] {
    let mut mapped = [0.0; MAX_CUTS];
    let n = cuts.len().min(MAX_CUTS);
    mapped[..n].copy_from_slice(&cuts[..n]);
    let torus = match setup.profile {
        Profile::Torus { small, .. } => {
            for c in &mut mapped[..n] {
                *c = (*c / small).clamp(-1.0, 1.0).asin();
            }
            true
        }
        Profile::Frustum { .. } => false,
    };
    let mut f = |x: f64| {
        if torus {
            setup.torus_slice(x, wedge)
        } else {
            setup.slice(x, wedge)
        }
    };
    let mut total = [0.0; COMPONENTS];
    let mut start = 0;
    while start + 1 < n {
        let end = (start + MAX_PIECES).min(n - 1);
        let part = ADAPTIVE.integrate_pieces(&mut mapped[start..=end], &mut f, &floor, work);
        for k in 0..COMPONENTS {
            total[k] += part[k];
        }
        start = end;
    }
    total
}

/// The contacts of `cuboid` (`a`, at `pose_a`) with the frustum or torus `solid` (`b`, at
/// `pose_b`), one per region, normals from `b` into `a`. A box or cylinder `solid` gives none
/// (they have their own pairs).
pub(crate) fn contacts(
    cuboid: &Cuboid,
    pose_a: &Isometry3,
    solid: &Solid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    // A box or cylinder has its own pairs.
    if matches!(solid, Solid::Box(_) | Solid::Cylinder(_)) {
        return;
    }
    let Some((profile, size)) = Profile::of(solid) else {
        return;
    };
    let unit = unit_for(size.max(cuboid.half_extents().norm()));
    let profile = profile.scaled(unit);
    // The box in the solid's frame, working units.
    let pose_ba = pose_b.inv_mul(pose_a);
    let axes = pose_ba.rotation.to_rotation_matrix().into_inner();
    let centre = (pose_ba * cuboid.center()).coords / unit;
    let half = cuboid.half_extents() / unit;
    let mut faces = [(Vector3::zeros(), 0.0); 6];
    for k in 0..3 {
        let axis = axes.column(k).into_owned();
        for (s, sign) in [1.0, -1.0].into_iter().enumerate() {
            faces[2 * k + s] = (sign * axis, sign * axis.dot(&centre) + half[k]);
        }
    }
    let mut corners = [Vector3::zeros(); 8];
    for (v, corner) in corners.iter_mut().enumerate() {
        let s = |bit: usize| if v & (1 << bit) != 0 { 1.0 } else { -1.0 };
        *corner = centre + axes * Vector3::new(s(0) * half.x, s(1) * half.y, s(2) * half.z);
    }
    let setup = Setup {
        faces,
        corners,
        profile,
    };
    work.bounding_volume_tests += 1;
    let (z_lo, z_hi) = setup.corner_range();
    let (b_lo, b_hi) = profile.range();
    let (lo, hi) = (z_lo.max(b_lo), z_hi.min(b_hi));
    if lo.is_nan() || hi.is_nan() || lo >= hi {
        return;
    }
    // The box's reach from the axis against the solid's outer radius: apart.
    let radial = centre.xy().norm() - half.norm();
    if radial >= profile.outer() {
        return;
    }
    let (cuts, count) = setup.cuts(lo, hi);
    let (wedges, wedge_count) = match profile {
        Profile::Torus { big, small } => azimuth::region_wedges(&setup.faces, big, small),
        Profile::Frustum { .. } => ([(0.0, 0.0); 64], 0),
    };
    let whole = [Wedge::whole()];
    let mut parts = [Wedge::whole(); 64];
    for (part, &(start, end)) in parts.iter_mut().zip(&wedges[..wedge_count]) {
        *part = Wedge::new(start, end);
    }
    let regions = if wedge_count == 0 {
        &whole[..]
    } else {
        &parts[..wedge_count]
    };
    let (solid_a, solid_b) = (Solid::Box(*cuboid), *solid);
    for wedge in regions {
        let found = region_contact(
            &setup,
            wedge,
            &cuts[..count],
            (&solid_a, pose_a),
            (&solid_b, pose_b),
            unit,
            work,
        );
        if let Some(c) = found {
            emit(c);
        }
    }
}

/// The contact of the region of `setup`'s intersection within `wedge` (all of it for a
/// frustum), integrated between `cuts`: the box `a` (`solid_a` at `pose_a`) against the
/// frustum or torus `b` (`solid_b` at `pose_b`), lengths over `unit`; `None` when the region
/// has no volume.
fn region_contact(
    setup: &Setup,
    wedge: &Wedge,
    cuts: &[f64],
    (solid_a, pose_a): (&Solid, &Isometry3),
    (solid_b, pose_b): (&Solid, &Isometry3),
    unit: f64,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let profile = setup.profile;
    let rot_b = pose_b.rotation;
    let mut r = integrate(setup, wedge, cuts, work);
    let (mut s_z, mut solid_area, mut box_area) = (r[6], r[7], r[8]);
    setup.flat_terms(wedge, &mut s_z, &mut solid_area, &mut box_area);
    r[6] = s_z;
    let volume = r[0];
    if volume.is_nan() || volume <= 0.0 {
        return None;
    }
    let centroid_b = Vector3::new(r[2], r[3], r[1]) / volume * unit;
    let centroid = pose_b * Point3::from(centroid_b);
    let s_solid = rot_b * Vector3::new(r[4], r[5], r[6]) * (unit * unit);
    let moments = VolumeMoments {
        volume: volume * unit * unit * unit,
        centroid,
        area_vector_a: -s_solid,
        surface_area: (solid_area + box_area) * unit * unit,
        length: unit,
    };
    let box_inside = solid_area <= ENCLOSED * (solid_area + box_area);
    let fallback = || {
        if box_inside {
            let p = pose_b.inverse_transform_point(&centroid).coords;
            rot_b * signed_distance(solid_b, &p).2
        } else {
            let p = pose_a.inverse_transform_point(&centroid).coords;
            -(pose_a.rotation * signed_distance(solid_a, &p).2)
        }
    };
    let convex = matches!(profile, Profile::Frustum { .. });
    volume_contact::contact_of_region(
        &moments,
        |g, d| surface_point_along_w(solid_a, pose_a, g, d),
        |g, d| surface_point_along_w(solid_b, pose_b, g, d),
        fallback,
        convex,
    )
}
