//! Two boundaries — arcs, curves, lines — against each other on their polylines: one contact
//! per region where their materials overlap, the exact engine's definition (its
//! `planar::overlap` module) reproduced on the tessellation.
//!
//! **Method.** `a` (I's boundary) is placed in `b`'s plane (J's; the line is always `b`, so
//! for a line as I the roles swap and the contact is swapped back). Both are [`Chain`]s with
//! their material on the left. The *topology* — which crossings there are and whether `a`
//! enters or leaves `b` at each — comes from the polylines with exact signs
//! ([`super::crossings`]), so the crossings alternate along each chain however the chords
//! meet. The *geometry* is computed on the lifted chains (each chord replaced by the cubic
//! Hermite arc through its ends with the true tangents there, [`super::chain`]): the crossings
//! are moved onto the arcs by Newton, and everything below integrates or intersects the arcs.
//! The lift is chosen because it makes every error second order in the chord deviation where
//! the polylines leave first-order ones: a chord lies `R·θ²/8` inside a circle, so on the
//! chords the depth of a shallow overlap would be biased by about one chord deviation, and the
//! crossings, hence the normal, would move by `d/sin α` for a crossing angle `α`.
//!
//! Regions are traced as in polygon clipping (along `a` while it is inside `b`'s material,
//! switching to `b` where `a` leaves it, and back), each on the left of its outline. Open ends
//! inside the other's material are closed by the straight segment to their foot (the closest
//! point of the other chain) and the outline goes on from the foot. Per region, with
//! integrals about a point `o` of the region: area `A = ½∮(x dy − y dx)` and centroid
//! `g = o + (∮ ½x² dy, −∮ ½y² dx)/A` (Gauss–Legendre, exact on the cubic arcs and segments);
//! `S = ½(S_a − S_b)` from the chords of each boundary's stretches on the outline (turned by
//! −90°); normal `n = −S/|S|` (from `b` into `a`); length `|S|`; contact points where the line
//! through `g` along `n` first meets each lifted chain (`a` going along `−n`, `b` along `+n`,
//! the farthest meeting behind if none ahead, the closest point if the line misses); depth
//! their distance.
//!
//! **Error bound.** Each polyline lies within `d = L/FT` of its shape and the lifted arcs
//! within `O(d²/ρ)` (ρ the smallest radius of curvature): the crossings, the outline and so the
//! area, centroid, depth and contact points move by `O(d²/ρ)` (divided by the sine of the
//! crossing angle for the crossings), the normal by `O(d²/(ρ·w))` rad for a region of chord
//! `w`. The tests measure the errors against the exact engine falling at second order and
//! below `d` at every FT (the region's own size scales what `d` can do: a region narrower than
//! `d` may have different crossings on the polylines).
//!
//! **Degenerate branches.**
//! - *Grazing and slivers:* a region with `|S| ≤ 1e-12·L` or `A ≤ 1e-10·|S|²` gives no contact
//!   (the exact engine's thresholds); the polylines touching at a vertex give such a sliver.
//! - *Touching or within `d` of touching:* the polylines may cross where the shapes do not, or
//!   not cross where they do; the contact then appears or vanishes with a depth of order
//!   `d²/ρ` or below, continuously.
//! - *Coincident boundaries:* identical chords never cross; a boundary lying on the other
//!   (the same shape at the same pose) yields at most a sliver: no contact.
//! - *Containment* (no crossing, both closed): one contact, the inner shape's centroid `g`,
//!   the normal towards the nearest point `q` of the outer chain, `q` as the outer point, the
//!   inner point on the line through `g`, the inner extent across the normal (over its points)
//!   as the length.
//! - *Outlines that do not close* (an open end's foot on a part of the other chain that does
//!   not bound the region): no contact rather than a wrong one, as in the exact engine.
//!
//! Queries reuse per-thread buffers: no allocation once warm.

use super::chain::{Chain, bezier_derivative, bezier_point};
use super::crossings::{self, Crossing, CrossingBuffers};
use contact_core::{Vector2, WorkCounters};
use std::cell::RefCell;

/// A contact in `b`'s plane: `a`'s point, `b`'s point, the normal from `b` into `a`, the
/// depth and the length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RegionContact {
    pub point_a: Vector2,
    pub point_b: Vector2,
    pub normal: Vector2,
    pub depth: f64,
    pub length: f64,
}

/// Where the outline leaves chain `on` at `tau` for chain `to` at `to_tau`, with a straight
/// closing segment in between for an open end.
#[derive(Debug, Clone, Copy)]
struct Departure {
    on: usize,
    tau: f64,
    to: usize,
    to_tau: f64,
    jump: Option<(Vector2, Vector2)>,
    /// False for a crossing the lifted arcs do not share (see [`crossings`]).
    on_arcs: bool,
}

/// Per-thread buffers of a query.
#[derive(Debug, Default)]
pub(crate) struct OverlapBuffers {
    /// `a` placed in `b`'s plane.
    pub a: Chain,
    /// `b` (its own points, or the cut line).
    pub b: Chain,
    crossings: Vec<Crossing>,
    crossing_buffers: CrossingBuffers,
    departures: Vec<Departure>,
    used: Vec<bool>,
    entries: Vec<usize>,
    hits: Vec<Vector2>,
}

thread_local! {
    static BUFFERS: RefCell<OverlapBuffers> = RefCell::new(OverlapBuffers::default());
}

/// Runs `f` with this thread's buffers.
pub(crate) fn with_buffers<R>(f: impl FnOnce(&mut OverlapBuffers) -> R) -> R {
    BUFFERS.with(|b| f(&mut b.borrow_mut()))
}

/// Gauss–Legendre nodes and weights on [−1, 1], 5 nodes: exact for the degree-8 integrands of
/// a cubic arc's moments.
const GAUSS_5: [(f64, f64); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// Sums of one region's outline integrals.
#[derive(Debug, Clone, Copy)]
struct Sums {
    origin: Vector2,
    twice_area: f64,
    moment: Vector2,
    chord_normal: Vector2,
}

impl Sums {
    fn new(origin: Vector2) -> Self {
        Self {
            origin,
            twice_area: 0.0,
            moment: Vector2::zeros(),
            chord_normal: Vector2::zeros(),
        }
    }

    /// Adds the arc `ctrl` over `[s0, s1]`.
    fn add(&mut self, ctrl: &[Vector2; 4], s0: f64, s1: f64) {
        let o = self.origin;
        let (half, mid) = (0.5 * (s1 - s0), 0.5 * (s0 + s1));
        for (x, w) in GAUSS_5 {
            let s = mid + half * x;
            let w = w * half;
            let p = bezier_point(ctrl, s) - o;
            let d = bezier_derivative(ctrl, s);
            self.twice_area += w * (p.x * d.y - p.y * d.x);
            self.moment.x += w * 0.5 * p.x * p.x * d.y;
            self.moment.y -= w * 0.5 * p.y * p.y * d.x;
        }
    }

    /// Adds the straight segment `p → q`.
    fn add_segment(&mut self, p: Vector2, q: Vector2) {
        let third = (q - p) / 3.0;
        self.add(&[p, p + third, q - third, q], 0.0, 1.0);
    }
}

/// The contacts of `buffers.a` against `buffers.b` (both in `b`'s plane).
pub(crate) fn contacts(
    buffers: &mut OverlapBuffers,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(RegionContact),
) {
    let OverlapBuffers {
        a,
        b,
        crossings: found,
        crossing_buffers,
        departures,
        used,
        entries,
        hits,
    } = buffers;
    let (a, b) = (&*a, &*b);
    let (lo_a, hi_a) = a.bounding_box();
    let (lo_b, hi_b) = b.bounding_box();
    let size = (hi_a - lo_a).norm().max((hi_b - lo_b).norm());
    if !(size > 0.0 && size.is_finite()) || a.chords() == 0 || b.chords() == 0 {
        return;
    }
    let chains = [a, b];
    crossings::find(a, b, size, crossing_buffers, work, found);
    departures.clear();
    departures.extend(found.iter().map(|c| {
        if c.a_enters {
            Departure {
                on: 1,
                tau: c.tau_b,
                to: 0,
                to_tau: c.tau_a,
                jump: None,
                on_arcs: c.on_arcs,
            }
        } else {
            Departure {
                on: 0,
                tau: c.tau_a,
                to: 1,
                to_tau: c.tau_b,
                jump: None,
                on_arcs: c.on_arcs,
            }
        }
    }));
    add_open_end_departures(&chains, found, size, departures);
    if departures.is_empty() {
        if let Some(c) = contained(a, b, size, hits) {
            emit(c);
        }
        return;
    }
    used.clear();
    used.resize(departures.len(), false);
    for first in 0..departures.len() {
        if departures[first].to != 0 || used[first] {
            continue;
        }
        used[first] = true;
        if let Some(sums) = trace(&chains, departures, first, used, entries) {
            if let Some(c) = region_contact(&sums, a, b, size, hits) {
                emit(c);
            }
        }
    }
}

/// The departures at open chains' real ends that lie in the other chain's material: from the
/// end to its foot on the other chain (an end inside), or from the foot to the start.
fn add_open_end_departures(
    chains: &[&Chain; 2],
    found: &[Crossing],
    size: f64,
    departures: &mut Vec<Departure>,
) {
    for x in 0..2 {
        let (own, other) = (chains[x], chains[1 - x]);
        if own.closed {
            continue;
        }
        // Whether each end lies in the other's material: by the parity of the crossings along
        // this chain when it has any, else by the closest point.
        let (first, last) = ends_by_parity(found, x);
        let start = own.points[0];
        let end = own.points[own.points.len() - 1];
        let start_inside = first.unwrap_or_else(|| other.inside(&start, size));
        let end_inside = last.unwrap_or_else(|| other.inside(&end, size));
        if own.real_ends[1] && end_inside {
            if let Some((tau, point)) = other.foot(&end, size) {
                departures.push(Departure {
                    on: x,
                    tau: own.count(),
                    to: 1 - x,
                    to_tau: tau,
                    jump: Some((end, point)),
                    on_arcs: true,
                });
            }
        }
        if own.real_ends[0] && start_inside {
            if let Some((tau, point)) = other.foot(&start, size) {
                departures.push(Departure {
                    on: 1 - x,
                    tau,
                    to: x,
                    to_tau: 0.0,
                    jump: Some((point, start)),
                    on_arcs: true,
                });
            }
        }
    }
}

/// For chain `x` (0 = `a`, 1 = `b`): whether its start and its end lie in the other's
/// material, from its first and last crossings (`None` without crossings).
fn ends_by_parity(found: &[Crossing], x: usize) -> (Option<bool>, Option<bool>) {
    // (τ on chain x, whether chain x enters the other's material there)
    let along = |c: &Crossing| {
        if x == 0 {
            (c.tau_a, c.a_enters)
        } else {
            (c.tau_b, !c.a_enters)
        }
    };
    let first = found.iter().map(along).min_by(|p, q| p.0.total_cmp(&q.0));
    let last = found.iter().map(along).max_by(|p, q| p.0.total_cmp(&q.0));
    (
        first.map(|(_, enters)| !enters),
        last.map(|(_, enters)| enters),
    )
}

/// Traces the outline that enters `a` by departure `first`; `None` if it does not close.
fn trace(
    chains: &[&Chain; 2],
    departures: &[Departure],
    first: usize,
    used: &mut [bool],
    entries: &mut Vec<usize>,
) -> Option<Sums> {
    let start = departures[first];
    let mut sums = Sums::new(chains[0].point(start.to_tau));
    let (mut on, mut tau) = (start.to, start.to_tau);
    entries.clear();
    for _ in 0..=departures.len() {
        let chain = chains[on];
        let (next, distance) = departures
            .iter()
            .enumerate()
            .filter(|(_, d)| d.on == on)
            .filter_map(|(k, d)| chain.ahead(tau, d.tau).map(|t| (k, t)))
            .min_by(|x, y| x.1.total_cmp(&y.1))?;
        // Walking past a place where the outline enters this chain means the departures do
        // not pair up: the outline is not traced.
        let passes_arrival = departures.iter().any(|d| {
            d.to == on
                && chain
                    .ahead(tau, d.to_tau)
                    .is_some_and(|t| t > 1e-12 && t < distance - 1e-12)
        });
        if passes_arrival {
            return None;
        }
        chain.walk(tau, distance, |arc, s0, s1| sums.add(arc, s0, s1));
        if distance > 0.0 {
            let d = chain.point(tau + distance) - chain.point(tau);
            let weight = if on == 0 { 0.5 } else { -0.5 };
            sums.chord_normal += weight * Vector2::new(d.y, -d.x);
        }
        let d = departures[next];
        if !d.on_arcs {
            return None;
        }
        if let Some((p, q)) = d.jump {
            sums.add_segment(p, q);
        }
        if next == first {
            for &k in entries.iter() {
                used[k] = true;
            }
            return Some(sums);
        }
        if d.to == 0 {
            if used[next] || entries.contains(&next) {
                return None;
            }
            entries.push(next);
        }
        on = d.to;
        tau = d.to_tau;
    }
    None
}

/// The contact of a traced region.
fn region_contact(
    sums: &Sums,
    a: &Chain,
    b: &Chain,
    size: f64,
    hits: &mut Vec<Vector2>,
) -> Option<RegionContact> {
    let area = 0.5 * sums.twice_area;
    let length = sums.chord_normal.norm();
    if !(length > 1e-12 * size && area > 1e-10 * length * length) {
        return None;
    }
    let g = sums.origin + sums.moment / area;
    let n = -sums.chord_normal / length;
    let point_a = ray_hit(a, &g, &-n, size, hits)?;
    let point_b = ray_hit(b, &g, &n, size, hits)?;
    Some(RegionContact {
        point_a,
        point_b,
        normal: n,
        depth: (point_b - point_a).norm(),
        length,
    })
}

/// Where the line through `g` first meets the lifted `chain` going along `direction` (the
/// farthest meeting behind `g` if there is none ahead; the closest point if the line misses).
fn ray_hit(
    chain: &Chain,
    g: &Vector2,
    direction: &Vector2,
    size: f64,
    hits: &mut Vec<Vector2>,
) -> Option<Vector2> {
    line_hits(chain, g, direction, size, hits);
    pick(hits, g, direction).or_else(|| chain.foot(g, size).map(|(_, p)| p))
}

/// Every meeting of the line through `g` along `direction` with the lifted chain: each chord
/// the line crosses, then Newton on `(H(τ) − g) × direction = 0` from the chord's crossing
/// (kept where it settles within a chord of it, else the chord's crossing).
fn line_hits(chain: &Chain, g: &Vector2, direction: &Vector2, size: f64, hits: &mut Vec<Vector2>) {
    hits.clear();
    let cross = |u: &Vector2, v: &Vector2| u.x * v.y - u.y * v.x;
    let side = |p: &Vector2| cross(direction, &(p - g));
    for k in 0..chain.chords() {
        let (p, q) = chain.chord(k);
        let (f0, f1) = (side(&p), side(&q));
        // A half-open rule: a line through a vertex meets one of its two chords.
        if (f0 > 0.0) == (f1 > 0.0) {
            continue;
        }
        let s0 = (f0 / (f0 - f1)).clamp(0.0, 1.0);
        let start = k as f64 + s0;
        let mut tau = start;
        let mut settled = false;
        for _ in 0..crossings::MAX_NEWTON_STEPS {
            let (kk, s) = chain.locate(tau);
            let arc = chain.arc(kk);
            let f = side(&bezier_point(&arc, s));
            let df = cross(direction, &bezier_derivative(&arc, s));
            if df.is_nan() || df == 0.0 {
                break;
            }
            let step = f / df;
            tau -= step;
            if !chain.holds(tau) || (tau - start).abs() > 1.0 {
                break;
            }
            if (step * bezier_derivative(&arc, s).norm()).abs() <= 1e-15 * size {
                settled = true;
                break;
            }
        }
        hits.push(if settled {
            chain.point(tau)
        } else {
            p + s0 * (q - p)
        });
    }
}

/// The hit nearest `g` along `direction` (ahead of `g`), else the farthest behind.
fn pick(hits: &[Vector2], g: &Vector2, direction: &Vector2) -> Option<Vector2> {
    let ahead = hits
        .iter()
        .map(|h| ((h - g).dot(direction), *h))
        .filter(|(t, _)| *t >= 0.0)
        .min_by(|x, y| x.0.total_cmp(&y.0));
    ahead
        .or_else(|| {
            hits.iter()
                .map(|h| ((h - g).dot(direction), *h))
                .max_by(|x, y| x.0.total_cmp(&y.0))
        })
        .map(|(_, h)| h)
}

/// No crossing and no open end inside: one closed chain may hold the other.
fn contained(a: &Chain, b: &Chain, size: f64, hits: &mut Vec<Vector2>) -> Option<RegionContact> {
    if !(a.closed && b.closed) {
        return None;
    }
    if b.inside(&a.points[0], size) {
        inner_contact(a, b, size, hits)
    } else if a.inside(&b.points[0], size) {
        inner_contact(b, a, size, hits).map(|c| RegionContact {
            point_a: c.point_b,
            point_b: c.point_a,
            normal: -c.normal,
            ..c
        })
    } else {
        None
    }
}

/// Closed `inner` wholly inside closed `outer`: the contact with `inner` as the first body.
fn inner_contact(
    inner: &Chain,
    outer: &Chain,
    size: f64,
    hits: &mut Vec<Vector2>,
) -> Option<RegionContact> {
    let mut sums = Sums::new(inner.points[0]);
    for k in 0..inner.chords() {
        sums.add(&inner.arc(k), 0.0, 1.0);
    }
    let area = 0.5 * sums.twice_area;
    if area.is_nan() || area <= 1e-12 * size * size {
        return None;
    }
    let g = sums.origin + sums.moment / area;
    let (_, q) = outer.foot(&g, size)?;
    let towards = q - g;
    let distance = towards.norm();
    if distance.is_nan() || distance <= 1e-12 * size {
        return None;
    }
    let n = towards / distance;
    line_hits(inner, &g, &n, size, hits);
    let point_inner = pick(hits, &g, &-n)?;
    let across = Vector2::new(-n.y, n.x);
    let (lo, hi) = inner
        .points
        .iter()
        .map(|p| (p - g).dot(&across))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), t| {
            (lo.min(t), hi.max(t))
        });
    Some(RegionContact {
        point_a: point_inner,
        point_b: q,
        normal: n,
        depth: (q - point_inner).norm(),
        length: hi - lo,
    })
}
