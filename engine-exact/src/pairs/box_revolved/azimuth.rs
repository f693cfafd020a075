//! The separate regions of a box against a ring torus, by azimuth.
//!
//! A meridian half-plane `H_φ` (the points at azimuth `φ` about the torus' axis) cuts the
//! box in a convex polygon and the torus in the tube's disc (radius `ρ` about `(R, 0)` in
//! `(radial, z)` coordinates), so `H_φ` meets the intersection in a convex, hence connected,
//! piece; and the half-planes partition space off the axis, which a ring torus does not
//! touch. So the intersection's regions are the connected arcs of `Φ = {φ : H_φ meets both}`,
//! one region per arc, and a wedge between two half-planes that miss the intersection holds
//! exactly the regions whose arcs lie between them.
//!
//! `Φ` is found from `g(φ)`, the distance from the tube's centre to the box's polygon in
//! `H_φ` less `ρ` (negative on `Φ`): sampled at 128 azimuths, and each sampled local minimum
//! that stays positive refined by golden-section search, so an arc narrower than the
//! sampling (a corner dipping into the tube) is still found when `g` is unimodal about it.
//! A region between two samples that the refinement misses too would share its neighbour's
//! wedge (one contact for two regions); the cut half-planes themselves are always checked
//! clear (`g > 0`), so a region is never split.
//!
//! Nothing here needs the box but its convex meridian sections: [`region_wedges_of`] takes
//! any `g` (an ellipsoid's, for the ellipsoid–torus pair).

use crate::methods::section::Polygon;
use crate::methods::sliced::golden_maximum;
use contact_core::{Vector2, Vector3};
use std::f64::consts::TAU;

/// Azimuth samples.
pub(crate) const SAMPLES: usize = 128;

/// The wedges `[start, end]` (radians, `end > start`, spans summing to 2π) each holding one
/// region; the count. Zero wedges when the sampling saw one region or none (the whole
/// turn is then one region).
pub(crate) fn region_wedges(
    faces: &[(Vector3, f64); 6],
    big: f64,
    small: f64,
) -> ([(f64, f64); SAMPLES / 2], usize) {
    region_wedges_of(|phi| gap(faces, big, small, phi), small)
}

/// [`region_wedges`] for any solid whose meridian sections are convex: `g(φ)` is the distance
/// from the tube's centre to the solid's section in `H_φ`, less the tube's radius (negative
/// where `H_φ` meets both). The sampled positive local minima below `refine_below` are
/// refined (a box's `g` is the tube's radius wherever it misses: only the lower ones can hide
/// a dip).
pub(crate) fn region_wedges_of(
    g: impl Fn(f64) -> f64,
    refine_below: f64,
) -> ([(f64, f64); SAMPLES / 2], usize) {
    let mut values = [0.0; SAMPLES];
    let mut angles = [0.0; SAMPLES];
    for k in 0..SAMPLES {
        angles[k] = k as f64 * TAU / SAMPLES as f64;
        values[k] = g(angles[k]);
    }
    // Positive local minima: refine, and take a negative minimum as its own sample.
    let step = TAU / SAMPLES as f64;
    let mut refined = values;
    for k in 0..SAMPLES {
        let (prev, next) = (
            values[(k + SAMPLES - 1) % SAMPLES],
            values[(k + 1) % SAMPLES],
        );
        if values[k] > 0.0 && values[k] <= prev && values[k] <= next && values[k] < refine_below {
            let phi = golden_maximum(angles[k] - step, angles[k] + step, |x| -g(x));
            let v = g(phi);
            if v < 0.0 {
                refined[k] = v;
                angles[k] = phi;
            }
        }
    }
    let inside = |k: usize| refined[k % SAMPLES] < 0.0;
    let mut wedges = [(0.0, 0.0); SAMPLES / 2];
    // A run starts where a sample inside follows one outside.
    let mut starts = [0usize; SAMPLES / 2];
    let mut count = 0;
    for k in 0..SAMPLES {
        if inside(k) && !inside(k + SAMPLES - 1) && count < starts.len() {
            starts[count] = k;
            count += 1;
        }
    }
    if count < 2 {
        return (wedges, 0);
    }
    // Cut in each gap at its clearest sample (largest g): the gap before each run start.
    let mut cuts = [0.0; SAMPLES / 2];
    for (n, &start) in starts[..count].iter().enumerate() {
        let mut k = start + SAMPLES - 1;
        let mut best = (f64::NEG_INFINITY, 0.0);
        while !inside(k) {
            let i = k % SAMPLES;
            if refined[i] > best.0 {
                best = (refined[i], angles[i]);
            }
            k -= 1;
        }
        cuts[n] = best.1;
    }
    let mut sorted = cuts;
    sorted[..count].sort_by(f64::total_cmp);
    for n in 0..count {
        let start = sorted[n];
        let end = if n + 1 < count {
            sorted[n + 1]
        } else {
            sorted[0] + TAU
        };
        wedges[n] = (start, end);
    }
    (wedges, count)
}

/// `g(φ)`: the distance from the tube's centre `(R, 0)` to the box's polygon in `H_φ`, less
/// the tube's radius; `−ρ` when the centre is inside the polygon, `+ρ` when the polygon
/// misses the tube's bounding square.
fn gap(faces: &[(Vector3, f64); 6], big: f64, small: f64, phi: f64) -> f64 {
    let (sin, cos) = phi.sin_cos();
    let mut polygon = Polygon::rectangle(Vector2::new(small, small));
    // (radial, z) about the tube's centre: radial = R + u.
    for (k, (n, d)) in faces.iter().enumerate() {
        let a = n.x * cos + n.y * sin;
        polygon.clip(&Vector2::new(a, n.z), d - a * big, 4 + k as u8);
    }
    let v = polygon.vertices();
    if v.len() < 3 || polygon.area() <= 0.0 {
        return small;
    }
    // Inside (all edges turn left of the origin) or the nearest edge's distance.
    let mut nearest = f64::INFINITY;
    let mut inside = true;
    for k in 0..v.len() {
        let (p, q) = (v[k], v[(k + 1) % v.len()]);
        let e = q - p;
        if e.x * (-p.y) - e.y * (-p.x) < 0.0 {
            inside = false;
        }
        let len2 = e.norm_squared();
        let s = if len2 > 0.0 {
            (-p.dot(&e) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        nearest = nearest.min((p + s * e).norm());
    }
    if inside { -small } else { nearest - small }
}
