//! The regions where two 2-D boundaries' materials overlap, traced as in polygon clipping —
//! the walk both engines' 2-D overlap pairs share; each engine supplies its boundary
//! ([`OutlineChain`]: exact pieces or lifted polyline arcs) and its crossings.
//!
//! Both boundaries are chains in one plane with their material on the left, parametrised by
//! `τ` from 0 to their piece count. The outline of a region runs along `a` while `a` is inside
//! `b`'s material, switches to `b` where `a` leaves it, runs along `b` while `b` is inside
//! `a`'s, and back to `a` where `b` leaves — each region on the left of its own outline. A
//! switch is a [`Departure`]: at a crossing where `a` enters `b`'s material the outline leaves
//! `b` for `a`, and where `a` leaves it, `a` for `b`.
//!
//! **Open ends.** Whether an open chain's end lies in the other's material follows from its
//! crossings (inside after an entry, outside after an exit), or, when it crosses nowhere,
//! from the other chain ([`OutlineChain::inside`]). An open chain that *ends* inside the
//! other's material closes its region with the straight segment from that end `E` to its foot
//! `F` (the closest point of the other chain), and the outline goes on along the other chain
//! from `F`; one that *starts* inside is reached the same way, from the foot of its start. As
//! the end leaves the material the segment shrinks to nothing and the region turns
//! continuously into the one bounded by two crossings. The cut ends of an unbounded line are
//! not ends ([`OutlineChain::real_ends`]).
//!
//! **Per region** the tracer sums, about a point `o` of the region (for round-off), the
//! outline integrals `2A = ∮(x dy − y dx)` and `(∮ ½x² dy, −∮ ½y² dx)` (the centroid is
//! `o + moment/A`), and the chord normal `S = ½(S_a − S_b)`, `S_a = Σ (Δy, −Δx)` over the
//! stretches of `a` on the outline (each stretch's chord turned by −90°: `∫ n dl` of `a`'s
//! boundary inside `b`), `S_b` the same over `b`'s: equal to `S_a` when one stretch of each
//! joins the same two crossings, symmetric in `a` and `b` when an open end's closing segment
//! or several crossings make the chords differ.
//!
//! A region whose outline does not close (a missed crossing), or whose walk along a chain
//! passes a place where the outline should enter that chain (an open end whose foot lies on a
//! part of the other chain that does not bound the region), or that meets a crossing marked
//! not [`OutlineCrossing::usable`], is not traced: no contact rather than a wrong one.

use crate::{Vector2, WorkCounters};

/// A transversal crossing of chains `a` and `b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutlineCrossing {
    /// Forward parameter on `a`.
    pub tau_a: f64,
    /// Forward parameter on `b`.
    pub tau_b: f64,
    /// True where `a` enters `b`'s material (`t_a × t_b < 0`).
    pub a_enters: bool,
    /// False where the chains' true curves do not share the crossing (a faceted engine's
    /// polylines crossing where their lifted arcs do not): an outline through it is not traced.
    pub usable: bool,
}

/// Where the outline leaves chain `on` (0 for `a`, 1 for `b`) at `tau` for chain `to` at
/// `to_tau`, with a straight closing segment `jump` in between for an open end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Departure {
    /// The chain left.
    pub on: usize,
    /// Where on it.
    pub tau: f64,
    /// The chain taken.
    pub to: usize,
    /// Where on it.
    pub to_tau: f64,
    /// The straight segment from the end left to the point taken, for an open end.
    pub jump: Option<(Vector2, Vector2)>,
    /// See [`OutlineCrossing::usable`] (true at open ends).
    pub usable: bool,
}

impl Departure {
    /// The departure at crossing `c`: from `b` to `a` where `a` enters `b`'s material, from `a`
    /// to `b` where it leaves.
    pub fn at_crossing(c: &OutlineCrossing) -> Self {
        let (on, tau, to, to_tau) = if c.a_enters {
            (1, c.tau_b, 0, c.tau_a)
        } else {
            (0, c.tau_a, 1, c.tau_b)
        };
        Self {
            on,
            tau,
            to,
            to_tau,
            jump: None,
            usable: c.usable,
        }
    }
}

/// The outline integrals of one region (see the module's docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutlineSums {
    /// The point the integrals are taken about.
    pub origin: Vector2,
    /// `∮(x dy − y dx)` about `origin`: twice the area.
    pub twice_area: f64,
    /// `(∮ ½x² dy, −∮ ½y² dx)` about `origin`: the area times the centroid's offset.
    pub moment: Vector2,
    /// `S = ½(S_a − S_b)`.
    pub chord_normal: Vector2,
}

impl OutlineSums {
    /// Empty sums about `origin`.
    pub fn new(origin: Vector2) -> Self {
        Self {
            origin,
            twice_area: 0.0,
            moment: Vector2::zeros(),
            chord_normal: Vector2::zeros(),
        }
    }

    /// Adds one quadrature node of the outline: the point `point`, the derivative `d` of the
    /// outline there and the node's weight `w`.
    #[inline]
    pub fn add_node(&mut self, point: Vector2, d: Vector2, w: f64) {
        let p = point - self.origin;
        self.twice_area += w * (p.x * d.y - p.y * d.x);
        self.moment.x += w * 0.5 * p.x * p.x * d.y;
        self.moment.y -= w * 0.5 * p.y * p.y * d.x;
    }
}

/// What the tracer asks of a boundary chain (material on its left, `τ` from 0 to
/// [`OutlineChain::count`]).
pub trait OutlineChain {
    /// Whether the chain closes on itself.
    fn closed(&self) -> bool;
    /// Whether its start and its end are real ends (not the cut ends of an unbounded line).
    fn real_ends(&self) -> [bool; 2];
    /// The parameter at its end.
    fn count(&self) -> f64;
    /// The point at `tau`.
    fn point(&self, tau: f64) -> Vector2;
    /// Its first point.
    fn start(&self) -> Vector2 {
        self.point(0.0)
    }
    /// Its last point.
    fn end(&self) -> Vector2 {
        self.point(self.count())
    }
    /// Whether `q` lies in its material (`size` the pair's length scale).
    fn inside(&self, q: &Vector2, size: f64, work: &mut WorkCounters) -> bool;
    /// Its point closest to `q`, `(τ, point)`, if found.
    fn foot(&self, q: &Vector2, size: f64, work: &mut WorkCounters) -> Option<(f64, Vector2)>;
    /// Adds the stretch from `τ = from` forward by `length` to `sums` ([`OutlineSums::add_node`]
    /// at the chain's own quadrature nodes).
    fn add_stretch(&self, from: f64, length: f64, sums: &mut OutlineSums);
    /// Adds the straight segment `p → q` to `sums`.
    fn add_segment(&self, p: Vector2, q: Vector2, sums: &mut OutlineSums);

    /// The forward distance in `τ` from `from` to `to` (wrapping on a closed chain); `None`
    /// when `to` lies behind `from` on an open chain.
    fn ahead(&self, from: f64, to: f64) -> Option<f64> {
        let d = to - from;
        if self.closed() {
            Some(d.rem_euclid(self.count()))
        } else {
            (d >= 0.0).then_some(d)
        }
    }
}

/// Where the line through a region's centroid `g` along `direction` meets a boundary, among
/// the line's `hits` with it: the hit nearest `g` ahead of it, else the farthest behind (the
/// contact points of SPEC §4 in 2-D); `None` without hits.
pub fn pick_hit(hits: &[Vector2], g: &Vector2, direction: &Vector2) -> Option<Vector2> {
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

/// Buffers of [`regions`], reused across queries.
#[derive(Debug, Default)]
pub struct OutlineBuffers {
    departures: Vec<Departure>,
    used: Vec<bool>,
    entries: Vec<usize>,
}

/// The overlap regions of `chains = [a, b]` crossing at `crossings` (`size` the pair's length
/// scale): calls `emit` with each traced region's sums. Returns false when there is no
/// departure at all (no crossing and no open end inside the other's material): then one
/// material holds the other or they are apart, which the caller tells.
pub fn regions<C: OutlineChain>(
    chains: [&C; 2],
    crossings: &[OutlineCrossing],
    size: f64,
    work: &mut WorkCounters,
    buffers: &mut OutlineBuffers,
    mut emit: impl FnMut(&OutlineSums),
) -> bool {
    let OutlineBuffers {
        departures,
        used,
        entries,
    } = buffers;
    departures.clear();
    departures.extend(crossings.iter().map(Departure::at_crossing));
    add_open_end_departures(chains, crossings, size, work, departures);
    if departures.is_empty() {
        return false;
    }
    used.clear();
    used.resize(departures.len(), false);
    for first in 0..departures.len() {
        if departures[first].to != 0 || used[first] {
            continue;
        }
        used[first] = true;
        if let Some(sums) = trace(chains, departures, first, used, entries) {
            emit(&sums);
        }
    }
    true
}

/// The departures at open chains' real ends that lie in the other chain's material: from the
/// end to its foot on the other chain (an end inside), or from the foot to the start.
fn add_open_end_departures<C: OutlineChain>(
    chains: [&C; 2],
    crossings: &[OutlineCrossing],
    size: f64,
    work: &mut WorkCounters,
    departures: &mut Vec<Departure>,
) {
    for x in 0..2 {
        let (own, other) = (chains[x], chains[1 - x]);
        if own.closed() {
            continue;
        }
        // Whether each end lies in the other's material: by the parity of the crossings along
        // this chain when it has any (so the ends agree with the crossings), else by the
        // other chain.
        let (first, last) = ends_by_parity(crossings, x);
        let (start, end) = (own.start(), own.end());
        let start_inside = first.unwrap_or_else(|| other.inside(&start, size, work));
        let end_inside = last.unwrap_or_else(|| other.inside(&end, size, work));
        let real_ends = own.real_ends();
        if real_ends[1]
            && end_inside
            && let Some((tau, point)) = other.foot(&end, size, work)
        {
            departures.push(Departure {
                on: x,
                tau: own.count(),
                to: 1 - x,
                to_tau: tau,
                jump: Some((end, point)),
                usable: true,
            });
        }
        if real_ends[0]
            && start_inside
            && let Some((tau, point)) = other.foot(&start, size, work)
        {
            departures.push(Departure {
                on: 1 - x,
                tau,
                to: x,
                to_tau: 0.0,
                jump: Some((point, start)),
                usable: true,
            });
        }
    }
}

/// For chain `x` (0 = `a`, 1 = `b`): whether its start and its end lie in the other's
/// material, from its first and last crossings (`None` without crossings).
fn ends_by_parity(crossings: &[OutlineCrossing], x: usize) -> (Option<bool>, Option<bool>) {
    // (τ on chain x, whether chain x enters the other's material there)
    let along = |c: &OutlineCrossing| {
        if x == 0 {
            (c.tau_a, c.a_enters)
        } else {
            (c.tau_b, !c.a_enters)
        }
    };
    let first = crossings
        .iter()
        .map(along)
        .min_by(|p, q| p.0.total_cmp(&q.0));
    let last = crossings
        .iter()
        .map(along)
        .max_by(|p, q| p.0.total_cmp(&q.0));
    (
        first.map(|(_, enters)| !enters),
        last.map(|(_, enters)| enters),
    )
}

/// Traces the outline that enters `a` by departure `first`; `None` if it does not close.
fn trace<C: OutlineChain>(
    chains: [&C; 2],
    departures: &[Departure],
    first: usize,
    used: &mut [bool],
    entries: &mut Vec<usize>,
) -> Option<OutlineSums> {
    let start = departures[first];
    let mut sums = OutlineSums::new(chains[0].point(start.to_tau));
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
        chain.add_stretch(tau, distance, &mut sums);
        if distance > 0.0 {
            let d = chain.point(tau + distance) - chain.point(tau);
            let weight = if on == 0 { 0.5 } else { -0.5 };
            sums.chord_normal += weight * Vector2::new(d.y, -d.x);
        }
        let d = departures[next];
        if !d.usable {
            return None;
        }
        if let Some((p, q)) = d.jump {
            chain.add_segment(p, q, &mut sums);
        }
        if next == first {
            // Only a closed outline claims its entries: one that fails here may still be
            // traced from an entry of its own.
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A polygon (closed) or polyline (open), material on the left, `τ` along its edges.
    struct Poly {
        points: Vec<Vector2>,
        closed: bool,
    }

    impl Poly {
        fn edges(&self) -> usize {
            self.points.len() - usize::from(!self.closed)
        }
        fn edge(&self, k: usize) -> (Vector2, Vector2) {
            (self.points[k], self.points[(k + 1) % self.points.len()])
        }
    }

    impl OutlineChain for Poly {
        fn closed(&self) -> bool {
            self.closed
        }
        fn real_ends(&self) -> [bool; 2] {
            [true, true]
        }
        fn count(&self) -> f64 {
            self.edges() as f64
        }
        fn point(&self, tau: f64) -> Vector2 {
            let tau = if self.closed {
                tau.rem_euclid(self.count())
            } else {
                tau
            };
            let k = (tau.floor() as usize).min(self.edges() - 1);
            let (p, q) = self.edge(k);
            p + (q - p) * (tau - k as f64)
        }
        fn inside(&self, q: &Vector2, _: f64, _: &mut WorkCounters) -> bool {
            // Crossing parity (closed polygons only in these tests).
            let mut inside = false;
            for k in 0..self.edges() {
                let (a, b) = self.edge(k);
                if (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x)
                {
                    inside = !inside;
                }
            }
            inside
        }
        fn foot(&self, q: &Vector2, _: f64, _: &mut WorkCounters) -> Option<(f64, Vector2)> {
            (0..self.edges())
                .map(|k| {
                    let (a, b) = self.edge(k);
                    let s = ((q - a).dot(&(b - a)) / (b - a).norm_squared()).clamp(0.0, 1.0);
                    (k as f64 + s, a + (b - a) * s)
                })
                .min_by(|x, y| (x.1 - q).norm().total_cmp(&(y.1 - q).norm()))
        }
        fn add_stretch(&self, from: f64, length: f64, sums: &mut OutlineSums) {
            let (mut tau, mut left) = (from, length);
            while left > 0.0 {
                let k = (tau.floor() as usize) % self.edges();
                let s = tau - tau.floor();
                let step = (1.0 - s).min(left);
                let (a, b) = self.edge(k);
                self.add_segment(a + (b - a) * s, a + (b - a) * (s + step), sums);
                left -= step;
                tau = (k + 1) as f64;
            }
        }
        fn add_segment(&self, p: Vector2, q: Vector2, sums: &mut OutlineSums) {
            // Two-point Gauss–Legendre: exact for the quadratic integrands of a segment.
            let x = 0.5 / 3f64.sqrt();
            for s in [0.5 - x, 0.5 + x] {
                sums.add_node(p + (q - p) * s, q - p, 0.5);
            }
        }
    }

    /// Crossings of two polygons' edges, with the entering sense `t_a × t_b < 0`.
    fn crossings(a: &Poly, b: &Poly) -> Vec<OutlineCrossing> {
        let cross = |u: Vector2, v: Vector2| u.x * v.y - u.y * v.x;
        let mut out = Vec::new();
        for i in 0..a.edges() {
            let (p, p1) = a.edge(i);
            for j in 0..b.edges() {
                let (q, q1) = b.edge(j);
                let (r, s) = (p1 - p, q1 - q);
                let den = cross(r, s);
                let t = cross(q - p, s) / den;
                let u = cross(q - p, r) / den;
                if (0.0..1.0).contains(&t) && (0.0..1.0).contains(&u) {
                    out.push(OutlineCrossing {
                        tau_a: i as f64 + t,
                        tau_b: j as f64 + u,
                        a_enters: den < 0.0,
                        usable: true,
                    });
                }
            }
        }
        out
    }

    fn square(x0: f64, y0: f64, side: f64) -> Poly {
        let v = |x, y| Vector2::new(x0 + x * side, y0 + y * side);
        Poly {
            points: vec![v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)],
            closed: true,
        }
    }

    fn traced(a: &Poly, b: &Poly) -> (bool, Vec<OutlineSums>) {
        let mut found = Vec::new();
        let any = regions(
            [a, b],
            &crossings(a, b),
            2.0,
            &mut WorkCounters::default(),
            &mut OutlineBuffers::default(),
            |s| found.push(*s),
        );
        (any, found)
    }

    #[test]
    fn two_squares_overlap_in_their_common_rectangle() {
        let (a, b) = (square(0.5, 0.25, 1.0), square(0.0, 0.0, 1.0));
        let (any, found) = traced(&a, &b);
        assert!(any);
        assert_eq!(found.len(), 1);
        let s = &found[0];
        // The rectangle [0.5, 1] × [0.25, 1]: area 0.375, centroid (0.75, 0.625).
        let area = 0.5 * s.twice_area;
        assert!((area - 0.375).abs() < 1e-15, "{area}");
        let g = s.origin + s.moment / area;
        assert!((g - Vector2::new(0.75, 0.625)).norm() < 1e-15, "{g}");
        // a's boundary inside b runs from (0.5, 1) down and right to (1, 0.25): chord
        // (0.5, −0.75), turned by −90° (−0.75, −0.5); b's inside a from (1, 0.25) to (0.5, 1):
        // (0.75, 0.5). S = ½(S_a − S_b) = (−0.75, −0.5), and n = −S/|S| points from b into a.
        assert!(
            (s.chord_normal - Vector2::new(-0.75, -0.5)).norm() < 1e-15,
            "{}",
            s.chord_normal
        );
    }

    #[test]
    fn two_crossings_per_side_give_two_regions() {
        // A thin bar across a U-shaped polygon's two prongs.
        let u = Poly {
            points: [
                (0.0, 0.0),
                (3.0, 0.0),
                (3.0, 2.0),
                (2.0, 2.0),
                (2.0, 1.0),
                (1.0, 1.0),
                (1.0, 2.0),
                (0.0, 2.0),
            ]
            .into_iter()
            .map(|(x, y)| Vector2::new(x, y))
            .collect(),
            closed: true,
        };
        let bar = Poly {
            points: [(-0.5, 1.5), (3.5, 1.5), (3.5, 1.75), (-0.5, 1.75)]
                .into_iter()
                .map(|(x, y)| Vector2::new(x, y))
                .collect(),
            closed: true,
        };
        let (_, found) = traced(&bar, &u);
        let mut areas: Vec<f64> = found.iter().map(|s| 0.5 * s.twice_area).collect();
        areas.sort_by(f64::total_cmp);
        assert_eq!(areas.len(), 2, "{areas:?}");
        for a in areas {
            assert!((a - 0.25).abs() < 1e-15, "{a}");
        }
    }

    #[test]
    fn an_open_end_inside_is_closed_by_its_foot() {
        // A probe entering the unit square through its left side and ending at (0.25, 0.5).
        let probe = Poly {
            points: vec![Vector2::new(-0.5, 0.25), Vector2::new(0.25, 0.5)],
            closed: false,
        };
        let (any, found) = traced(&probe, &square(0.0, 0.0, 1.0));
        assert!(any);
        assert_eq!(found.len(), 1);
        // The outline: along the probe from its crossing (0, 5/12) to its end (0.25, 0.5), the
        // segment to the foot (0, 0.5), down the square's side to (0, 5/12): a triangle of
        // area ½·0.25·(0.5 − 5/12) = 1/96.
        let area = 0.5 * found[0].twice_area;
        assert!((area - 1.0 / 96.0).abs() < 1e-15, "{area}");
    }

    #[test]
    fn apart_or_nested_leaves_the_answer_to_the_caller() {
        let (any, found) = traced(&square(3.0, 3.0, 1.0), &square(0.0, 0.0, 1.0));
        assert!(!any && found.is_empty());
        let (any, found) = traced(&square(0.25, 0.25, 0.5), &square(0.0, 0.0, 1.0));
        assert!(!any && found.is_empty());
    }

    #[test]
    fn the_nearest_hit_ahead_else_the_farthest_behind() {
        let g = Vector2::zeros();
        let dir = Vector2::x();
        let hits = [
            Vector2::new(-3.0, 0.0),
            Vector2::new(2.0, 0.0),
            Vector2::new(1.0, 0.0),
        ];
        assert_eq!(pick_hit(&hits, &g, &dir), Some(Vector2::new(1.0, 0.0)));
        assert_eq!(
            pick_hit(&hits[..1], &g, &dir),
            Some(Vector2::new(-3.0, 0.0))
        );
        assert_eq!(pick_hit(&[], &g, &dir), None);
    }
}
