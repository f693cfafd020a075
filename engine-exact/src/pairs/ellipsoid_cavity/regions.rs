//! The regions of an ellipsoid outside a cavity: the slicing range cut where the lunes
//! change, each piece's lunes labelled at its middle, and the lunes joined across the cuts
//! (see the parent module's doc).

use super::Slicing;
use crate::methods::ellipsoid_sliced::disc_less::{Lunes, MAX_LUNES};
use crate::methods::ellipsoid_sliced::disc_overlap::DiscOverlap;
use crate::methods::ellipsoid_sliced::shape_events;
use std::f64::consts::TAU;

/// Most cuts of the slicing range from the shape samples (the ellipsoid's two ends, the
/// cavity's two, and the shape changes between).
const MAX_CUTS: usize = 24;

/// Where, as a fraction of a piece, the lunes next to a cut are read for the regions'
/// connections across it.
const NEAR_CUT: f64 = 1e-6;

/// Cuts closer than this fraction of the ellipsoid's height are one.
const MERGE: f64 = 1e-9;

/// The middle of a circle arc, in `[0, 2π)`.
pub(super) fn arc_middle(lune: &DiscOverlap) -> f64 {
    lune.arcs
        .spans()
        .first()
        .map_or(0.0, |(t0, t1)| (0.5 * (t0 + t1)).rem_euclid(TAU))
}

/// Whether two components share a stretch of the circle (any of their arcs overlap).
fn parts_overlap(a: &DiscOverlap, b: &DiscOverlap) -> bool {
    a.arcs
        .spans()
        .iter()
        .any(|&x| b.arcs.spans().iter().any(|&y| arcs_overlap(x, y)))
}

fn angular_distance(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

/// Whether two circle arcs share more than a point.
fn arcs_overlap((a0, a1): (f64, f64), (b0, b1): (f64, f64)) -> bool {
    if a1 - a0 >= TAU || b1 - b0 >= TAU {
        return true;
    }
    let shift = (b0 - a0).rem_euclid(TAU);
    let (b0, b1) = (a0 + shift, a0 + shift + (b1 - b0));
    (b0 < a1) || (b1 > a0 + TAU)
}

/// Maps each lune of `here` to one of the `reference` middles: the cyclic shift nearest in
/// the arcs' middles when the counts agree; else one to one, each reference middle taking the
/// nearest lune left (a lune vanishing at a cut, read within round-off of it, is left out).
pub(super) fn labels(reference: &[f64], here: &Lunes) -> [Option<usize>; MAX_LUNES] {
    let mut out = [None; MAX_LUNES];
    let parts = here.parts();
    let k = reference.len();
    if k == 0 {
        return out;
    }
    if parts.len() == k {
        let cost = |shift: usize| -> f64 {
            (0..k)
                .map(|j| {
                    angular_distance(reference[j], arc_middle(&parts[(j + shift) % k])).powi(2)
                })
                .sum()
        };
        let best = (0..k)
            .min_by(|&x, &y| cost(x).total_cmp(&cost(y)))
            .unwrap_or(0);
        for j in 0..k {
            out[(j + best) % k] = Some(j);
        }
        return out;
    }
    for (j, &m) in reference.iter().enumerate() {
        let nearest = (0..parts.len())
            .filter(|&i| out[i].is_none())
            .min_by(|&x, &y| {
                angular_distance(arc_middle(&parts[x]), m)
                    .total_cmp(&angular_distance(arc_middle(&parts[y]), m))
            });
        if let Some(i) = nearest {
            out[i] = Some(j);
        }
    }
    out
}

/// Union–find over the pieces' lunes.
pub(super) struct Regions {
    parent: Vec<usize>,
}

impl Regions {
    /// The regions of `count` lunes, each its own.
    pub(super) fn new(count: usize) -> Self {
        Self {
            parent: (0..count).collect(),
        }
    }

    /// The region of lune `x` (its root).
    pub(super) fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    fn join(&mut self, x: usize, y: usize) {
        let (rx, ry) = (self.find(x), self.find(y));
        if rx != ry {
            self.parent[rx.max(ry)] = rx.min(ry);
        }
    }
}

/// One piece of the slicing range: its ends and the middles of its lunes' arcs at its middle.
pub(super) struct Piece {
    pub(super) lo: f64,
    pub(super) hi: f64,
    pub(super) middles: Vec<f64>,
    /// The index of its first lune among all pieces' lunes.
    pub(super) first: usize,
}

/// The pieces between the cuts, each with its lunes' labels.
pub(super) fn pieces(slicing: &Slicing) -> Vec<Piece> {
    let (e_lo, e_hi) = slicing.a.range();
    let (c_lo, c_hi) = slicing.cavity_range();
    let mut cuts = [0.0; MAX_CUTS];
    cuts[..2].copy_from_slice(&[e_lo, e_hi]);
    let mut n = 2;
    for end in [c_lo, c_hi] {
        if end > e_lo && end < e_hi {
            cuts[n] = end;
            n += 1;
        }
    }
    let (lo, hi) = (e_lo.max(c_lo), e_hi.min(c_hi));
    if lo < hi {
        shape_events(lo, hi, |t| slicing.shape(t), &mut cuts, &mut n);
    }
    let mut cuts = cuts[..n].to_vec();
    cuts.sort_by(f64::total_cmp);
    // Changes the shape samples cannot see: a lune vanishing and another appearing within
    // one sample's spacing (the class the same on both sides).
    let mut hidden = Vec::new();
    for w in cuts.windows(2) {
        if w[0] >= lo && w[1] <= hi && w[1] > w[0] {
            hidden_events(slicing, w[0], w[1], &mut hidden);
        }
    }
    cuts.extend(hidden);
    cuts.sort_by(f64::total_cmp);
    // Cuts within round-off of each other are one change (a tangency bisected from both
    // sides): a piece between them would hold no slice of its own.
    let merge = MERGE * (e_hi - e_lo);
    let mut kept: Vec<f64> = Vec::with_capacity(cuts.len());
    for &c in &cuts {
        let is_end = c == e_lo || c == e_hi || c == c_lo || c == c_hi;
        match kept.last_mut() {
            Some(last) if c - *last <= merge => {
                if is_end {
                    *last = c;
                }
            }
            _ => kept.push(c),
        }
    }
    let cuts = kept;
    let mut out: Vec<Piece> = Vec::new();
    let mut first = 0;
    for w in cuts.windows(2) {
        let mid = 0.5 * (w[0] + w[1]);
        let middles: Vec<f64> = slicing
            .lunes(mid)
            .map(|(_, l)| l.parts().iter().map(arc_middle).collect())
            .unwrap_or_default();
        let count = middles.len();
        out.push(Piece {
            lo: w[0],
            hi: w[1],
            middles,
            first,
        });
        first += count;
    }
    out
}

/// Samples across a piece between shape changes in [`hidden_events`].
const CONTINUITY_SAMPLES: usize = 32;

/// Bisections of a discontinuity between two samples (down to 2⁻⁵⁰ of their spacing).
const CONTINUITY_DEPTH: usize = 50;

/// Whether the lunes at `t0` and `t1` are the same lunes moved: as many, and each (in the
/// cyclic order nearest in their middles) overlapping its match.
fn continuous(slicing: &Slicing, t0: f64, t1: f64) -> bool {
    let (Some((_, a)), Some((_, b))) = (slicing.lunes(t0), slicing.lunes(t1)) else {
        return true;
    };
    if a.parts().len() != b.parts().len() {
        return false;
    }
    let middles: Vec<f64> = a.parts().iter().map(arc_middle).collect();
    let label = labels(&middles, &b);
    b.parts()
        .iter()
        .zip(label)
        .all(|(p, j)| j.is_some_and(|j| parts_overlap(&a.parts()[j], p)))
}

/// Adds to `cuts` the changes inside `(lo, hi)` that keep the crossing class on both sides:
/// consecutive samples whose lunes are not [`continuous`] are bisected until a slice of
/// another class appears between them (then its two class changes are bisected to
/// round-off, as [`shape_events`] does) or the interval is at round-off (a cut there).
fn hidden_events(slicing: &Slicing, lo: f64, hi: f64, cuts: &mut Vec<f64>) {
    let at = |k: usize| lo + (hi - lo) * k as f64 / CONTINUITY_SAMPLES as f64;
    for k in 0..CONTINUITY_SAMPLES {
        let (a, b) = (at(k), at(k + 1));
        if !continuous(slicing, a, b) {
            locate_jump(slicing, a, b, CONTINUITY_DEPTH, cuts);
        }
    }
}

/// Finds the change between `a` and `b` whose lunes are not continuous (see
/// [`hidden_events`]).
fn locate_jump(slicing: &Slicing, a: f64, b: f64, depth: usize, cuts: &mut Vec<f64>) {
    let mid = 0.5 * (a + b);
    if depth == 0 || mid <= a || mid >= b {
        cuts.push(mid);
        return;
    }
    let class = slicing.shape(a);
    if slicing.shape(mid) != class || slicing.shape(b) != class {
        let mut found = [0.0; 4];
        let mut n = 0;
        shape_events(a, b, |t| slicing.shape(t), &mut found, &mut n);
        cuts.extend_from_slice(&found[..n]);
        return;
    }
    for (x, y) in [(a, mid), (mid, b)] {
        if !continuous(slicing, x, y) {
            locate_jump(slicing, x, y, depth - 1, cuts);
        }
    }
}

/// Joins the lunes on both sides of every cut whose circle arcs overlap.
pub(super) fn connect_across_cuts(slicing: &Slicing, pieces: &[Piece], regions: &mut Regions) {
    let near = |piece: &Piece, at_hi: bool| {
        let t = if at_hi {
            piece.hi - NEAR_CUT * (piece.hi - piece.lo)
        } else {
            piece.lo + NEAR_CUT * (piece.hi - piece.lo)
        };
        slicing.lunes(t).map(|(_, l)| {
            let label = labels(&piece.middles, &l);
            let parts: Vec<(DiscOverlap, usize)> = l
                .parts()
                .iter()
                .zip(label)
                .filter_map(|(p, j)| j.map(|j| (*p, piece.first + j)))
                .collect();
            parts
        })
    };
    for w in pieces.windows(2) {
        let (below, above) = (&w[0], &w[1]);
        if below.middles.is_empty() || above.middles.is_empty() || below.hi != above.lo {
            continue;
        }
        let (Some(down), Some(up)) = (near(below, true), near(above, false)) else {
            continue;
        };
        for (part_d, id_d) in &down {
            for (part_u, id_u) in &up {
                if parts_overlap(part_d, part_u) {
                    regions.join(*id_d, *id_u);
                }
            }
        }
    }
}
