//! Two boundaries — arcs, curves, lines — against each other: one contact per region where
//! their materials overlap (SPEC §4 in 2-D).
//!
//! Both boundaries are [`Chain`]s in `b`'s plane with their material on the left, so the
//! overlap regions are traced as in polygon clipping: along `a` while it is inside `b`'s
//! material, switching to `b` where `a` leaves it, along `b` while it is inside `a`'s, back
//! to `a` where `b` leaves — each region on the left of its own outline. At a crossing
//! (found by [`crossings::find`]) `a` enters `b` iff `t_a × t_b < 0`.
//!
//! **Open ends.** Whether an open chain's end lies in the other's material follows from its
//! crossings (inside after an entry, outside after an exit), or, when it crosses nowhere,
//! from the other chain's closest point. An open chain that *ends* inside the other's
//! material closes its region with the straight segment from that end `E` to its foot `F`
//! (the closest point of the other chain), and the outline goes on along the other chain
//! from `F`; an open chain that
//! *starts* inside the other's material is reached the same way, from the foot of its start.
//! As the end leaves the material `F → E` and the segment shrinks to nothing, so the region
//! turns continuously into the one bounded by the two crossings. An end meeting the other
//! chain head-on (a probe along the normal) encloses no area and gives no contact. The cut
//! ends of an unbounded line are not ends.
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
use contact_core::{Isometry3, Point2, Vector2, Vector3, WorkCounters};

/// Where the outline leaves chain `on` at `tau` for chain `to` at `to_tau`, with a straight
/// closing segment in between for an open end.
#[derive(Debug, Clone, Copy)]
struct Departure {
    on: usize,
    tau: f64,
    to: usize,
    to_tau: f64,
    jump: Option<(Vector2, Vector2)>,
}

/// Sums of one region's outline integrals.
#[derive(Debug, Clone, Copy)]
struct Sums {
    origin: Vector2,
    twice_area: f64,
    moment: Vector2,
    chord_normal: Vector2,
}

impl Sums {
    fn add(&mut self, piece: &Piece, s0: f64, s1: f64) {
        let o = self.origin;
        quadrature::for_each_node(s0, s1, |s, w| {
            let p = piece.point(s) - o;
            let d = piece.derivative(s);
            self.twice_area += w * (p.x * d.y - p.y * d.x);
            self.moment.x += w * 0.5 * p.x * p.x * d.y;
            self.moment.y -= w * 0.5 * p.y * p.y * d.x;
        });
    }
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
    let chains = [a, b];
    let found = crossings::find(a, b, size, work);
    let mut departures: Vec<Departure> = found
        .iter()
        .map(|c| {
            if c.sine < 0.0 {
                Departure {
                    on: 1,
                    tau: c.tau_b,
                    to: 0,
                    to_tau: c.tau_a,
                    jump: None,
                }
            } else {
                Departure {
                    on: 0,
                    tau: c.tau_a,
                    to: 1,
                    to_tau: c.tau_b,
                    jump: None,
                }
            }
        })
        .collect();
    for x in 0..2 {
        let (own, other) = (chains[x], chains[1 - x]);
        if own.closed {
            continue;
        }
        // Whether each end lies in the other's material: by the parity of the crossings
        // along this chain when it has any (so the ends agree with the crossings), else by
        // the closest point.
        let (first, last) = ends_by_parity(&found, x);
        let start = own.point(0.0);
        let end = own.point(own.count());
        let start_inside = first.unwrap_or_else(|| closest::inside(other, &start, size, work));
        let end_inside = last.unwrap_or_else(|| closest::inside(other, &end, size, work));
        if own.real_ends[1] && end_inside {
            let f = closest::foot(other, &end, size, work);
            departures.push(Departure {
                on: x,
                tau: own.count(),
                to: 1 - x,
                to_tau: f.tau,
                jump: Some((end, f.point)),
            });
        }
        if own.real_ends[0] && start_inside {
            let f = closest::foot(other, &start, size, work);
            departures.push(Departure {
                on: 1 - x,
                tau: f.tau,
                to: x,
                to_tau: 0.0,
                jump: Some((f.point, start)),
            });
        }
    }
    if departures.is_empty() {
        contained(a, b, size, frame, work, emit);
        return;
    }
    let mut used = vec![false; departures.len()];
    for first in 0..departures.len() {
        if departures[first].to != 0 || used[first] {
            continue;
        }
        used[first] = true;
        if let Some(sums) = trace(&chains, &departures, first, &mut used) {
            if let Some(c) = region_contact(&sums, a, b, size, frame, work) {
                emit(c);
            }
        }
    }
}

/// For chain `x` (0 = `a`, 1 = `b`): whether its start and its end lie in the other's
/// material, from its first and last crossings (`None` without crossings).
fn ends_by_parity(found: &[crossings::Crossing], x: usize) -> (Option<bool>, Option<bool>) {
    // (τ on chain x, whether chain x enters the other's material there)
    let along = |c: &crossings::Crossing| {
        if x == 0 {
            (c.tau_a, c.sine < 0.0)
        } else {
            (c.tau_b, c.sine > 0.0)
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
) -> Option<Sums> {
    let start = departures[first];
    let mut sums = Sums {
        origin: chains[0].point(start.to_tau),
        twice_area: 0.0,
        moment: Vector2::zeros(),
        chord_normal: Vector2::zeros(),
    };
    let (mut on, mut tau) = (start.to, start.to_tau);
    let mut entries: Vec<usize> = Vec::new();
    for _ in 0..=departures.len() {
        let chain = chains[on];
        let (next, distance) = departures
            .iter()
            .enumerate()
            .filter(|(_, d)| d.on == on)
            .filter_map(|(k, d)| chain.ahead(tau, d.tau).map(|t| (k, t)))
            .min_by(|x, y| x.1.total_cmp(&y.1))?;
        // Walking past a place where the outline enters this chain means the departures do
        // not pair up (an open end's foot on a part of the other chain that does not bound
        // this region): the outline is not traced.
        let passes_arrival = departures.iter().any(|d| {
            d.to == on
                && chain
                    .ahead(tau, d.to_tau)
                    .is_some_and(|t| t > 1e-12 && t < distance - 1e-12)
        });
        if passes_arrival {
            return None;
        }
        chain.walk(tau, distance, |_, piece, s0, s1| sums.add(piece, s0, s1));
        // S = ½(S_a − S_b): the same as S_a where one stretch of each boundary joins the
        // same two crossings, and symmetric in a and b where open ends or several crossings
        // make the stretches' chords differ.
        if distance > 0.0 {
            let d = chain.point(tau + distance) - chain.point(tau);
            let weight = if on == 0 { 0.5 } else { -0.5 };
            sums.chord_normal += weight * Vector2::new(d.y, -d.x);
        }
        let d = departures[next];
        if let Some((p, q)) = d.jump {
            sums.add(&Piece::segment(p, q), 0.0, 1.0);
        }
        if next == first {
            // Only a closed outline claims its entries: one that fails here may still be
            // traced from an entry of its own.
            for &k in &entries {
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
    pick(&hits, g, direction).unwrap_or_else(|| closest::foot(chain, g, size, work).point)
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
    let mut sums = Sums {
        origin: inner.point(0.0),
        twice_area: 0.0,
        moment: Vector2::zeros(),
        chord_normal: Vector2::zeros(),
    };
    for piece in &inner.pieces {
        sums.add(piece, 0.0, 1.0);
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
    let point_inner = pick(&hits, &g, &-n)?;
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
