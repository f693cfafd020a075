//! The regions of an ellipsoid outside a cavity: the slicing range cut where the lunes
//! change, each piece's lunes labelled at its middle, and the lunes joined across the cuts
//! (see the parent module's doc).

use super::Slicing;
use crate::methods::ellipsoid_sliced::disc_less::{INNER, Lunes, MAX_LUNES, WHOLE};
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
fn arc_middle(lune: &DiscOverlap) -> f64 {
    lune.arcs
        .spans()
        .first()
        .map_or(0.0, |(t0, t1)| (0.5 * (t0 + t1)).rem_euclid(TAU))
}

/// A part's mark, by which the slices of one piece are matched to its middle's: the middle
/// of its first circle arc, and the cavity curve that bounds it ([`Lunes::curves`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct Mark {
    middle: f64,
    curve: u8,
}

/// The marks of `lunes`' parts.
pub(super) fn marks(lunes: &Lunes) -> Vec<Mark> {
    lunes
        .parts()
        .iter()
        .zip(lunes.curves())
        .map(|(p, &curve)| Mark {
            middle: arc_middle(p),
            curve,
        })
        .collect()
}

/// Whether two parts of nearby slices are one component: a whole section meets every part;
/// parts bounded by different curves of the cavity never meet (a torus' tube keeps its hole
/// from its outside at every height); the one part in an annulus' hole is itself; lunes are
/// one where their circle arcs overlap.
fn parts_overlap((a, ca): (&DiscOverlap, u8), (b, cb): (&DiscOverlap, u8)) -> bool {
    if ca == WHOLE || cb == WHOLE {
        return true;
    }
    if ca != cb {
        return false;
    }
    if ca == INNER {
        return true;
    }
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

/// Maps each part of `here` to one of the `reference` marks: a part bounded by an annulus'
/// inner curve, or a whole section, to the reference's part of the same kind; lunes among
/// the reference's lunes by the cyclic shift nearest in the arcs' middles when the counts
/// agree, else one to one, each reference middle taking the nearest lune left (a lune
/// vanishing at a cut, read within round-off of it, is left out).
pub(super) fn labels(reference: &[Mark], here: &Lunes) -> [Option<usize>; MAX_LUNES] {
    let mut out = [None; MAX_LUNES];
    let parts = here.parts();
    let curves = here.curves();
    for (i, &curve) in curves.iter().enumerate() {
        if curve != 0 {
            out[i] = reference.iter().position(|m| m.curve == curve);
        }
    }
    let refs: Vec<usize> = (0..reference.len())
        .filter(|&j| reference[j].curve == 0)
        .collect();
    let lunes: Vec<usize> = (0..parts.len()).filter(|&i| curves[i] == 0).collect();
    let k = refs.len();
    if k == 0 || lunes.is_empty() {
        return out;
    }
    let middle = |i: usize| arc_middle(&parts[i]);
    if lunes.len() == k {
        let cost = |shift: usize| -> f64 {
            (0..k)
                .map(|j| {
                    angular_distance(reference[refs[j]].middle, middle(lunes[(j + shift) % k]))
                        .powi(2)
                })
                .sum()
        };
        let best = (0..k)
            .min_by(|&x, &y| cost(x).total_cmp(&cost(y)))
            .unwrap_or(0);
        for j in 0..k {
            out[lunes[(j + best) % k]] = Some(refs[j]);
        }
        return out;
    }
    let mut taken = [false; MAX_LUNES];
    for &j in &refs {
        let m = reference[j].middle;
        let nearest = lunes
            .iter()
            .copied()
            .filter(|&i| !taken[i])
            .min_by(|&x, &y| {
                angular_distance(middle(x), m).total_cmp(&angular_distance(middle(y), m))
            });
        if let Some(i) = nearest {
            taken[i] = true;
            out[i] = Some(j);
        }
    }
    out
}

/// [`labels`] for the integrals: a lune left out there (a change between the samples that
/// found none, a lune appearing and merging within one spacing) goes to the reference
/// lune nearest in its middle, so that no volume is lost.
pub(super) fn labels_for_integrals(reference: &[Mark], here: &Lunes) -> [Option<usize>; MAX_LUNES] {
    let mut out = labels(reference, here);
    for (i, part) in here.parts().iter().enumerate() {
        if out[i].is_none() {
            let m = arc_middle(part);
            out[i] = (0..reference.len())
                .filter(|&j| reference[j].curve == here.curves()[i] || reference[j].curve == 0)
                .min_by(|&x, &y| {
                    angular_distance(reference[x].middle, m)
                        .total_cmp(&angular_distance(reference[y].middle, m))
                });
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
    pub(super) middles: Vec<Mark>,
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
        let middles: Vec<Mark> = slicing
            .lunes(mid)
            .map(|(_, l)| marks(&l))
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
    let label = labels(&marks(&a), &b);
    b.parts()
        .iter()
        .zip(label)
        .zip(b.curves())
        .all(|((p, j), &c)| {
            j.is_some_and(|j| parts_overlap((&a.parts()[j], a.curves()[j]), (p, c)))
        })
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
/// [`hidden_events`]): halves the interval `depth` times at most, keeping a half whose ends
/// are not continuous (the first), so the work is linear in `depth` (a second jump within
/// one sample's spacing is not sought).
fn locate_jump(slicing: &Slicing, mut a: f64, mut b: f64, depth: usize, cuts: &mut Vec<f64>) {
    let class = slicing.shape(a);
    for _ in 0..depth {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            break;
        }
        if slicing.shape(mid) != class || slicing.shape(b) != class {
            let mut found = [0.0; 4];
            let mut n = 0;
            shape_events(a, b, |t| slicing.shape(t), &mut found, &mut n);
            cuts.extend_from_slice(&found[..n]);
            return;
        }
        if !continuous(slicing, a, mid) {
            b = mid;
        } else if !continuous(slicing, mid, b) {
            a = mid;
        } else {
            // Continuous on both halves: the lunes moved fast, nothing jumped.
            return;
        }
    }
    cuts.push(0.5 * (a + b));
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
            let parts: Vec<(DiscOverlap, u8, usize)> = l
                .parts()
                .iter()
                .zip(l.curves())
                .zip(label)
                .filter_map(|((p, &c), j)| j.map(|j| (*p, c, piece.first + j)))
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
        for (part_d, c_d, id_d) in &down {
            for (part_u, c_u, id_u) in &up {
                if parts_overlap((part_d, *c_d), (part_u, *c_u)) {
                    regions.join(*id_d, *id_u);
                }
            }
        }
    }
}
