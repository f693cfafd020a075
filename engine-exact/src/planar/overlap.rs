//! Two boundaries — arcs, curves, lines — against each other: one contact per region where
//! their materials overlap (SPEC §4 in 2-D).
//!
//! Both boundaries are [`Chain`]s in `b`'s plane with their material on the left; the
//! regions are traced by the walk both engines share
//! ([`contact_core::geometry::outline`]: crossings, open ends closed by the segment to their
//! foot, the outline integrals), on the exact pieces. At a crossing (found by
//! [`crossings::find`]) `a` enters `b` iff `t_a × t_b < 0`.
//!
//! **Per region** (outline on the left, integrals relative to a point `o` of the region for
//! round-off): area `A = ½∮(x dy − y dx)`, centroid `g = o + (∮ ½x² dy, −∮ ½y² dx)/A`, each
//! integral exact by Gauss–Legendre on the polynomial pieces and to round-off on the
//! quarter-turn arcs; `S_a = Σ (Δy, −Δx)` over the stretches of `a` on the outline (the
//! chord of each stretch turned by −90°: `∫ n dl` of `a`'s boundary inside `b`), `S_b` the
//! same over `b`'s, and `S = ½(S_a − S_b)` — equal to `S_a` when one stretch of each joins
//! the same two crossings (then `S_b = −S_a`), and symmetric in `a` and `b` when an open
//! end's closing segment or several crossings make the chords differ; normal
//! `n = −S/|S|` (from `b` into `a`); length ("area") `|S|`. The contact points are where the
//! line through `g` along `n` first meets each boundary: `a`'s going along `−n`, `b`'s going
//! along `+n` (the farthest meeting on the other side if there is none ahead); the
//! penetration is their distance. Usually both lie on the region's outline; when the region
//! overhangs its chord so far that the line misses `a`'s stretch inside `b`, `a`'s point is
//! where the line leaves `a` — still continuous in the pose. Regions with `|S| ≤ 1e-12·L` or
//! `A ≤ 1e-10·|S|²` (grazing: the round-off of `A`, integrated about a point of the region,
//! is ~1e-16·|S|²) give no contact.
//!
//! Exactly touching boundaries agree to round-off along a short stretch, so they may give a
//! contact whose penetration is at round-off level (below `1e-13·L`) instead of none.
//!
//! **No crossing, both closed.** When one chain's material lies inside the other's, one
//! contact: the inner shape's area centroid `g`, the normal from `g` towards the nearest point
//! `q` of the outer chain (the way out), `q` as the outer point, the inner point on the line
//! through `g` as above, the inner shape's extent across the normal as the length.
//!
//! **Coincident boundaries** cross nowhere transversally (every crossing has a zero angle
//! and is dropped, [`crossings::MIN_SINE`]), and neither lies strictly inside the other:
//! no contact. The penetration of a boundary lying on another is zero everywhere along it,
//! so this is the limit of the touching case.
//!
//! A region whose outline does not close (a missed crossing, see [`crossings`]), or whose
//! walk along a chain passes a place where the outline should enter that chain (an open end
//! whose foot lies on a part of the other chain that does not bound the region — the foot
//! rule is meant for ends near the region, not for wiggly open curves), gives no contact
//! rather than a wrong one. With both boundaries open and ends inside each other's
//! material, the feet need not pair up, and the answer can then depend on which is I (about
//! 2% of random open–open scenes in the tests); with one boundary closed, exchanging I and J
//! gives the swapped contact.
//!
//! Unlike the closed-form pairs, a query allocates: `a`'s chain placed in `b`'s plane, the
//! crossings, the outline's bookkeeping and the ray hits (a few small vectors).

use super::boundary::{Chain, Piece};
use super::{InPlane, closest, crossings};
use crate::kernel::PairContact;
use crate::quadrature;
use contact_core::geometry::outline::{
    self, OutlineBuffers, OutlineChain, OutlineCrossing, OutlineSums,
};
use contact_core::{Isometry3, Point2, Vector2, Vector3, WorkCounters};

/// The exact chain as the shared tracer walks it: its pieces integrated by the
/// Gauss–Legendre nodes of [`quadrature::for_each_node`], ends by [`closest`].
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

    fn inside(&self, q: &Vector2, size: f64, work: &mut WorkCounters) -> bool {
        closest::inside(self, q, size, work)
    }

    fn foot(&self, q: &Vector2, size: f64, work: &mut WorkCounters) -> Option<(f64, Vector2)> {
        let f = closest::foot(self, q, size, work);
        Some((f.tau, f.point))
    }

    fn add_stretch(&self, from: f64, length: f64, sums: &mut OutlineSums) {
        self.walk(from, length, |_, piece, s0, s1| {
            add_piece(sums, piece, s0, s1)
        });
    }

    fn add_segment(&self, p: Vector2, q: Vector2, sums: &mut OutlineSums) {
        add_piece(sums, &Piece::segment(p, q), 0.0, 1.0);
    }
}

/// Adds `piece` over `[s0, s1]` to `sums`.
fn add_piece(sums: &mut OutlineSums, piece: &Piece, s0: f64, s1: f64) {
    quadrature::for_each_node(s0, s1, |s, w| {
        sums.add_node(piece.point(s), piece.derivative(s), w);
    });
}

/// `a`'s chain (in its own frame) placed in `b`'s plane: the in-plane rotation (a reflection
/// when `a`'s z axis is reversed) and `a`'s origin.
pub(crate) fn place(a: &Chain, frame: &InPlane<'_>, pose_a: &Isometry3) -> Chain {
    let relative = frame.pose_b.inv_mul(pose_a);
    let x = relative.rotation * Vector3::x();
    let y = relative.rotation * Vector3::y();
    let m = nalgebra::Matrix2::new(x.x, y.x, x.y, y.y);
    a.mapped(&m, &frame.origin_a.coords)
}

/// The contacts of chain `a` against chain `b`, both in `b`'s plane.
pub(crate) fn contacts(
    a: &Chain,
    b: &Chain,
    frame: &InPlane<'_>,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let (lo_a, hi_a) = a.bounding_box();
    let (lo_b, hi_b) = b.bounding_box();
    let size = (hi_a - lo_a).norm().max((hi_b - lo_b).norm());
    if !(size > 0.0 && size.is_finite()) {
        return;
    }
    let found: Vec<OutlineCrossing> = crossings::find(a, b, size, work)
        .iter()
        .map(|c| OutlineCrossing {
            tau_a: c.tau_a,
            tau_b: c.tau_b,
            a_enters: c.sine < 0.0,
            usable: true,
        })
        .collect();
    let mut buffers = OutlineBuffers::default();
    let mut traced = Vec::new();
    let any = outline::regions([a, b], &found, size, work, &mut buffers, |sums| {
        traced.push(*sums);
    });
    if !any {
        contained(a, b, size, frame, work, emit);
        return;
    }
    for sums in &traced {
        if let Some(c) = region_contact(sums, a, b, size, frame, work) {
            emit(c);
        }
    }
}

/// The contact of a traced region.
fn region_contact(
    sums: &OutlineSums,
    a: &Chain,
    b: &Chain,
    size: f64,
    frame: &InPlane<'_>,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let area = 0.5 * sums.twice_area;
    let length = sums.chord_normal.norm();
    if !(length > 1e-12 * size && area > 1e-10 * length * length) {
        return None;
    }
    let g = sums.origin + sums.moment / area;
    let n = -sums.chord_normal / length;
    let point_a = ray_hit(a, &g, &-n, size, work);
    let point_b = ray_hit(b, &g, &n, size, work);
    Some(PairContact {
        point_a: frame.point_w(&Point2::from(point_a)),
        point_b: frame.point_w(&Point2::from(point_b)),
        normal: frame.vector_w(&n),
        depth: (point_b - point_a).norm(),
        area: length,
    })
}

/// Where the line through `g` first meets `chain` going along `direction` (the farthest
/// meeting behind `g` if there is none ahead; the closest point of the chain if the line
/// misses it).
fn ray_hit(
    chain: &Chain,
    g: &Vector2,
    direction: &Vector2,
    size: f64,
    work: &mut WorkCounters,
) -> Vector2 {
    let reach = 4.0 * size;
    let ray = Piece::segment(g - reach * direction, g + reach * direction);
    let mut hits = Vec::new();
    for piece in &chain.pieces {
        crossings::between_pieces(&ray, piece, size, work, &mut |_, _, p, _| hits.push(p));
    }
    outline::pick_hit(&hits, g, direction)
        .unwrap_or_else(|| closest::foot(chain, g, size, work).point)
}

/// No crossing and no open end inside: one closed chain may hold the other.
fn contained(
    a: &Chain,
    b: &Chain,
    size: f64,
    frame: &InPlane<'_>,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    if !(a.closed && b.closed) {
        return;
    }
    if closest::inside(b, &a.point(0.0), size, work) {
        if let Some(c) = inner_contact(a, b, size, frame, work) {
            emit(c);
        }
    } else if closest::inside(a, &b.point(0.0), size, work) {
        if let Some(c) = inner_contact(b, a, size, frame, work) {
            emit(c.swapped());
        }
    }
}

/// Closed `inner` wholly inside closed `outer`: the contact with `inner` as the first body.
fn inner_contact(
    inner: &Chain,
    outer: &Chain,
    size: f64,
    frame: &InPlane<'_>,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let mut sums = OutlineSums::new(inner.point(0.0));
    for piece in &inner.pieces {
        add_piece(&mut sums, piece, 0.0, 1.0);
    }
    let area = 0.5 * sums.twice_area;
    if area.is_nan() || area <= 1e-12 * size * size {
        return None;
    }
    let g = sums.origin + sums.moment / area;
    let q = closest::foot(outer, &g, size, work).point;
    let towards = q - g;
    let distance = towards.norm();
    if distance.is_nan() || distance <= 1e-12 * size {
        return None;
    }
    let n = towards / distance;
    let reach = 4.0 * size;
    let ray = Piece::segment(g - reach * n, g + reach * n);
    let mut hits = Vec::new();
    for piece in &inner.pieces {
        crossings::between_pieces(&ray, piece, size, work, &mut |_, _, p, _| hits.push(p));
    }
    let point_inner = outline::pick_hit(&hits, &g, &-n)?;
    // Extent across the normal: the pieces' closest points to two points far out on either
    // side (`1e3` sizes away, so they are the support points to ~1e-3 of the curvature's
    // effect — the length is an estimate, SPEC §4).
    let across = Vector2::new(-n.y, n.x);
    let reach = 1e3 * size;
    let mut extent = [f64::INFINITY, f64::NEG_INFINITY];
    for piece in &inner.pieces {
        for q in [g + reach * across, g - reach * across] {
            let (_, p, _) = closest::on_piece(piece, 0.0, 1.0, &q, size, work);
            let t = (p - g).dot(&across);
            extent = [extent[0].min(t), extent[1].max(t)];
        }
    }
    Some(PairContact {
        point_a: frame.point_w(&Point2::from(point_inner)),
        point_b: frame.point_w(&Point2::from(q)),
        normal: frame.vector_w(&n),
        depth: (q - point_inner).norm(),
        area: extent[1] - extent[0],
    })
}

/// The chain of line `b` (`x_range`, `side`) cut to where chain `a` (in `b`'s plane) can
/// reach it: `a`'s x extent widened by its size on each side. `None` when they miss.
pub(crate) fn line_chain(a: &Chain, x_range: [f64; 2], side: f64) -> Option<Chain> {
    let (lo, hi) = a.bounding_box();
    let margin = (hi - lo).norm();
    let (cut0, cut1) = (lo.x - margin, hi.x + margin);
    let (x0, x1) = (x_range[0].max(cut0), x_range[1].min(cut1));
    (x0 < x1).then(|| Chain::from_line(x0, x1, [x_range[0] >= cut0, x_range[1] <= cut1], side))
}

/// Chain `a` (in its own frame, at `pose_a`) against chain `b` (in `b`'s plane).
pub(crate) fn chain_chain(
    frame: &InPlane<'_>,
    pose_a: &Isometry3,
    a: &Chain,
    b: &Chain,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    contacts(&place(a, frame, pose_a), b, frame, work, emit);
}

/// Chain `a` (in its own frame, at `pose_a`) against the line `x_range` of `b` (`side` −1
/// when flipped).
pub(crate) fn chain_line(
    frame: &InPlane<'_>,
    pose_a: &Isometry3,
    a: &Chain,
    x_range: [f64; 2],
    side: f64,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let placed = place(a, frame, pose_a);
    if let Some(line) = line_chain(&placed, x_range, side) {
        contacts(&placed, &line, frame, work, emit);
    }
}
