//! Where two chains cross: chord against chord on the polylines (exact signs, every crossing
//! found once), then each crossing moved onto the lifted Hermite arcs by Newton.
//!
//! **On the polylines.** Chords are grouped in blocks of about `√N` consecutive chords with
//! a box each; pairs of overlapping blocks are searched chord against chord. Two chords cross
//! iff each one's ends lie on opposite sides of the other's line, the sides taken exactly by
//! [`super::orient`], with ties broken as if chain `a` were shifted by an infinitesimal
//! `ε·(1, ε)`. So a crossing at a shared vertex is counted by exactly one of the two chords
//! meeting there, a chain touching the other at a vertex counts zero or two crossings (a
//! sliver of no area), collinear overlapping chords do not cross, and the crossings alternate
//! in and out along each chain — the parity the region walk relies on holds by construction.
//!
//! **On the lifted arcs.** Newton on `H_a(τ_a) = H_b(τ_b)` from the polyline crossing (steps
//! limited to half a chord, parameters kept in an open chain's range), to a step below
//! `1e-15·L`. The refined crossing is kept when it closes to [`CLOSE`]`·L`, stays
//! within [`MAX_SHIFT`] chords of its start, and its tangents cross with the polyline
//! crossing's sense and a sine above [`MIN_SINE`]; otherwise the polyline crossing stands.
//! Should refinement change the order of the crossings along either chain (two crossings of a
//! nearly tangent pair within a chord), every crossing of the query keeps its polyline
//! position. A crossing left on the polylines is marked: the lifted arcs do not cross there
//! (the polylines do within `d` of touching), and its region gives no contact.

use super::chain::{Chain, bezier_derivative, bezier_point};
use super::orient::{fixed_point_side, shifted_point_side};
use contact_core::{Vector2, WorkCounters};

/// Smallest sine between the lifted tangents at a refined crossing.
pub const MIN_SINE: f64 = 1e-9;
/// Largest move of a refined crossing along either chain, in chords.
pub const MAX_SHIFT: f64 = 4.0;
/// A refined crossing's largest gap `|H_a − H_b|`, relative to the pair's length.
pub const CLOSE: f64 = 1e-12;
/// Newton steps per crossing.
pub const MAX_NEWTON_STEPS: usize = 30;

/// A crossing of chain `a` and chain `b`; `usable` is true once moved onto the lifted arcs
/// (false: the polylines cross here, the lifted arcs nowhere near, or not in this order).
pub(crate) type Crossing = contact_core::geometry::outline::OutlineCrossing;

/// Reusable buffers of [`find`].
#[derive(Debug, Default)]
pub(crate) struct CrossingBuffers {
    boxes_a: Vec<(Vector2, Vector2)>,
    boxes_b: Vec<(Vector2, Vector2)>,
    refined: Vec<Crossing>,
    order: Vec<usize>,
}

/// Every crossing of `a` and `b` into `out` (cleared first); `size` is the pair's length.
pub(crate) fn find(
    a: &Chain,
    b: &Chain,
    size: f64,
    buffers: &mut CrossingBuffers,
    work: &mut WorkCounters,
    out: &mut Vec<Crossing>,
) {
    out.clear();
    let (na, nb) = (a.chords(), b.chords());
    if na == 0 || nb == 0 {
        return;
    }
    let block_a = block_size(na);
    let block_b = block_size(nb);
    block_boxes(a, block_a, &mut buffers.boxes_a);
    block_boxes(b, block_b, &mut buffers.boxes_b);
    for (ia, box_a) in buffers.boxes_a.iter().enumerate() {
        for (ib, box_b) in buffers.boxes_b.iter().enumerate() {
            work.bounding_volume_tests += 1;
            if !boxes_meet(box_a, box_b) {
                continue;
            }
            for ka in ia * block_a..((ia + 1) * block_a).min(na) {
                let (p0, p1) = a.chord(ka);
                let chord_a = (p0.inf(&p1), p0.sup(&p1));
                for kb in ib * block_b..((ib + 1) * block_b).min(nb) {
                    let (q0, q1) = b.chord(kb);
                    if !boxes_meet(&chord_a, &(q0.inf(&q1), q0.sup(&q1))) {
                        continue;
                    }
                    work.primitive_tests += 1;
                    if let Some(c) = chord_crossing(&p0, &p1, &q0, &q1) {
                        out.push(Crossing {
                            tau_a: ka as f64 + c.0,
                            tau_b: kb as f64 + c.1,
                            a_enters: c.2,
                            usable: false,
                        });
                    }
                }
            }
        }
    }
    refine_all(a, b, size, buffers, work, out);
}

/// About `√n` chords per block (at least 8).
fn block_size(n: usize) -> usize {
    ((n as f64).sqrt().ceil() as usize).max(8)
}

/// The boxes of consecutive blocks of `block` chords.
fn block_boxes(chain: &Chain, block: usize, out: &mut Vec<(Vector2, Vector2)>) {
    out.clear();
    let n = chain.chords();
    let mut k = 0;
    while k < n {
        let end = (k + block).min(n);
        let mut lo = chain.points[k];
        let mut hi = lo;
        for j in k + 1..=end {
            let p = chain.points[j % chain.points.len()];
            lo = lo.inf(&p);
            hi = hi.sup(&p);
        }
        out.push((lo, hi));
        k = end;
    }
}

/// Closed boxes meet (touching counts: the shift that breaks ties may make them cross).
fn boxes_meet(a: &(Vector2, Vector2), b: &(Vector2, Vector2)) -> bool {
    a.0.x <= b.1.x && b.0.x <= a.1.x && a.0.y <= b.1.y && b.0.y <= a.1.y
}

/// The crossing of chord `p0 → p1` of the shifted chain with chord `q0 → q1` of the fixed
/// one: `(s on p, t on q, whether p enters q's material)`.
fn chord_crossing(
    p0: &Vector2,
    p1: &Vector2,
    q0: &Vector2,
    q1: &Vector2,
) -> Option<(f64, f64, bool)> {
    let (sa0, sa1) = (
        shifted_point_side(q0, q1, p0),
        shifted_point_side(q0, q1, p1),
    );
    if sa0 == sa1 || sa0 == 0 || sa1 == 0 {
        return None;
    }
    let (sb0, sb1) = (fixed_point_side(p0, p1, q0), fixed_point_side(p0, p1, q1));
    if sb0 == sb1 || sb0 == 0 || sb1 == 0 {
        return None;
    }
    let cross = |u: Vector2, v: Vector2| u.x * v.y - u.y * v.x;
    let fraction = |d0: f64, d1: f64| {
        let f = d0 / (d0 - d1);
        if f.is_finite() {
            f.clamp(0.0, 1.0)
        } else {
            0.5
        }
    };
    let s = fraction(cross(q1 - q0, p0 - q0), cross(q1 - q0, p1 - q0));
    let t = fraction(cross(p1 - p0, q0 - p0), cross(p1 - p0, q1 - p0));
    // The material is on the left: p enters where its end is left of q's line.
    Some((s, t, sa1 > 0))
}

/// Moves the crossings onto the lifted arcs, unless that reorders them along a chain.
fn refine_all(
    a: &Chain,
    b: &Chain,
    size: f64,
    buffers: &mut CrossingBuffers,
    work: &mut WorkCounters,
    crossings: &mut [Crossing],
) {
    buffers.refined.clear();
    buffers.refined.extend(
        crossings
            .iter()
            .map(|c| refine(a, b, c, size, work).unwrap_or(*c)),
    );
    let keeps_order = |chain: &Chain, of: fn(&Crossing) -> f64, order: &mut Vec<usize>| {
        order.clear();
        order.extend(0..crossings.len());
        order.sort_by(|&i, &j| of(&crossings[i]).total_cmp(&of(&crossings[j])));
        in_order(chain, order.iter().map(|&i| of(&buffers.refined[i])))
    };
    let mut order = std::mem::take(&mut buffers.order);
    let ok = keeps_order(a, |c| c.tau_a, &mut order) && keeps_order(b, |c| c.tau_b, &mut order);
    buffers.order = order;
    if ok {
        crossings.copy_from_slice(&buffers.refined);
    }
}

/// Whether parameters met in this order run forward along `chain` (once round a closed one).
fn in_order(chain: &Chain, mut taus: impl Iterator<Item = f64>) -> bool {
    let Some(first) = taus.next() else {
        return true;
    };
    let mut previous = first;
    if chain.closed {
        let mut turned = 0.0;
        for tau in taus {
            turned += (tau - previous).rem_euclid(chain.count());
            previous = tau;
        }
        turned += (first - previous).rem_euclid(chain.count());
        // One full turn (or none, when every crossing sits at one place).
        turned <= chain.count() * (1.0 + 1e-12)
    } else {
        taus.all(|tau| {
            let ok = tau >= previous;
            previous = tau;
            ok
        })
    }
}

/// Newton on `H_a(τ_a) = H_b(τ_b)` from `c`; `None` when it does not settle as the module
/// doc requires.
fn refine(
    a: &Chain,
    b: &Chain,
    c: &Crossing,
    size: f64,
    work: &mut WorkCounters,
) -> Option<Crossing> {
    let cross = |u: &Vector2, v: &Vector2| u.x * v.y - u.y * v.x;
    let (mut ta, mut tb) = (c.tau_a, c.tau_b);
    let eval = |chain: &Chain, tau: f64| {
        let (k, s) = chain.locate(tau);
        let arc = chain.arc(k);
        (bezier_point(&arc, s), bezier_derivative(&arc, s))
    };
    for _ in 0..MAX_NEWTON_STEPS {
        work.iterations += 1;
        let (pa, da) = eval(a, ta);
        let (pb, db) = eval(b, tb);
        let r = pb - pa;
        let det = -cross(&da, &db);
        if det.is_nan() || det.abs() <= MIN_SINE * da.norm() * db.norm() {
            return None;
        }
        // [da, −db]·(Δa, Δb) = pb − pa.
        let (mut step_a, mut step_b) = (cross(&r, &-db) / det, cross(&da, &r) / det);
        // At most half a chord per step: a coarse start must not jump to another crossing.
        let longest = step_a.abs().max(step_b.abs());
        if longest > 0.5 {
            step_a *= 0.5 / longest;
            step_b *= 0.5 / longest;
        }
        // An open chain's parameter stays in its range; a crossing beyond an end does not
        // close at the end, and is refused below.
        ta = a.clamp(ta + step_a);
        tb = b.clamp(tb + step_b);
        if (step_a * da.norm()).abs().max((step_b * db.norm()).abs()) <= 1e-15 * size {
            break;
        }
    }
    if (ta - c.tau_a).abs() > MAX_SHIFT || (tb - c.tau_b).abs() > MAX_SHIFT {
        return None;
    }
    let (pa, da) = eval(a, ta);
    let (pb, db) = eval(b, tb);
    let sine = cross(&da, &db) / (da.norm() * db.norm());
    let same_sense = (sine < 0.0) == c.a_enters;
    if !((pa - pb).norm() <= CLOSE * size && sine.abs() > MIN_SINE && same_sense) {
        return None;
    }
    let wrap = |chain: &Chain, tau: f64| {
        if chain.closed {
            tau.rem_euclid(chain.count())
        } else {
            tau
        }
    };
    Some(Crossing {
        tau_a: wrap(a, ta),
        tau_b: wrap(b, tb),
        a_enters: c.a_enters,
        usable: true,
    })
}
