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
//! Regions are traced by the walk both engines share ([`contact_core::geometry::outline`]:
//! along `a` while it is inside `b`'s material, switching to `b` where `a` leaves it, and
//! back; open ends inside the other's material closed by the straight segment to their foot),
//! on the lifted arcs. Per region, with
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
use contact_core::geometry::outline::{self, OutlineBuffers, OutlineChain, OutlineSums};
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

/// Per-thread buffers of a query.
#[derive(Debug, Default)]
pub(crate) struct OverlapBuffers {
    /// `a` placed in `b`'s plane.
    pub a: Chain,
    /// `b` (its own points, or the cut line).
    pub b: Chain,
    crossings: Vec<Crossing>,
    crossing_buffers: CrossingBuffers,
    outline: OutlineBuffers,
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

/// Adds the arc `ctrl` over `[s0, s1]` to `sums` (Gauss–Legendre, [`GAUSS_5`]).
fn add_arc(sums: &mut OutlineSums, ctrl: &[Vector2; 4], s0: f64, s1: f64) {
    let (half, mid) = (0.5 * (s1 - s0), 0.5 * (s0 + s1));
    for (x, w) in GAUSS_5 {
        let s = mid + half * x;
        sums.add_node(bezier_point(ctrl, s), bezier_derivative(ctrl, s), w * half);
    }
}

/// The lifted chain as the shared tracer walks it: its Hermite arcs, ends by the polyline's
/// own points, feet and material tests.
impl OutlineChain for Chain {
    fn closed(&self) -> bool {
        self.closed
    }

    fn real_ends(&self) -> [bool; 2] {
        self.real_ends
    }

    fn count(&self) -> f64 {
        Chain::count(self)
    }

    fn point(&self, tau: f64) -> Vector2 {
        Chain::point(self, tau)
    }

    fn start(&self) -> Vector2 {
        self.points[0]
    }

    fn end(&self) -> Vector2 {
        self.points[self.points.len() - 1]
    }

    fn inside(&self, q: &Vector2, size: f64, _: &mut WorkCounters) -> bool {
        Chain::inside(self, q, size)
    }

    fn foot(&self, q: &Vector2, size: f64, _: &mut WorkCounters) -> Option<(f64, Vector2)> {
        Chain::foot(self, q, size)
    }

    fn add_stretch(&self, from: f64, length: f64, sums: &mut OutlineSums) {
        self.walk(from, length, |arc, s0, s1| add_arc(sums, arc, s0, s1));
    }

    fn add_segment(&self, p: Vector2, q: Vector2, sums: &mut OutlineSums) {
        let third = (q - p) / 3.0;
        add_arc(sums, &[p, p + third, q - third, q], 0.0, 1.0);
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
        outline,
        hits,
    } = buffers;
    let (a, b) = (&*a, &*b);
    let (lo_a, hi_a) = a.bounding_box();
    let (lo_b, hi_b) = b.bounding_box();
    let size = (hi_a - lo_a).norm().max((hi_b - lo_b).norm());
    if !(size > 0.0 && size.is_finite()) || a.chords() == 0 || b.chords() == 0 {
        return;
    }
    crossings::find(a, b, size, crossing_buffers, work, found);
    let any = outline::regions([a, b], found, size, work, outline, |sums| {
        if let Some(c) = region_contact(sums, a, b, size, hits) {
            emit(c);
        }
    });
    if !any && let Some(c) = contained(a, b, size, hits) {
        emit(c);
    }
}

/// The contact of a traced region.
fn region_contact(
    sums: &OutlineSums,
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
    outline::pick_hit(hits, g, direction).or_else(|| chain.foot(g, size).map(|(_, p)| p))
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
    let mut sums = OutlineSums::new(inner.points[0]);
    for k in 0..inner.chords() {
        add_arc(&mut sums, &inner.arc(k), 0.0, 1.0);
    }
    let area = 0.5 * sums.twice_area;
    if area.is_nan() || area <= 1e-12 * size * size {
        return None;
    }
    let g = sums.origin + sums.moment / area;
    let (_, q) = Chain::foot(outer, &g, size)?;
    let towards = q - g;
    let distance = towards.norm();
    if distance.is_nan() || distance <= 1e-12 * size {
        return None;
    }
    let n = towards / distance;
    line_hits(inner, &g, &n, size, hits);
    let point_inner = outline::pick_hit(hits, &g, &-n)?;
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
