//! A solid circle against a bounded 2-D line (PLANE in a 2-D contact with a finite XMIN
//! and/or XMAX): closed form.
//!
//! **The solid.** As [`super::point_line`] reads a bounded line (and the 3-D pairs a bounded
//! plane's prism), its material is the half-strip `H = {XMIN ≤ x ≤ XMAX, side·y ≤ 0}` of
//! `b`'s frame. The overlap region is `R = D ∩ H`, `D` the disc: convex, its outline made of
//! the stretches of `H`'s edges inside `D` — the line itself and, where an end lies over the
//! disc, the vertical through that end — joined by arcs of the circle.
//!
//! **The contact** (SPEC §4 as `planar::overlap` reads a region, here in closed form). With
//! `h₀`, `h₁` the lengths of the verticals through XMIN and XMAX inside `R`, `L` the length of
//! the line inside the disc and `W` the width of `R` along the line:
//! - `S = ½(S_a − S_b)`: `S_a = ∫ n dl` over the circle's arcs on `R`'s outline, which is
//!   `(h₀ − h₁, −L)` because the outline closes; `S_b = (0, W)`, the line's outward normal
//!   over the part of the line above `R`. While the centre is above the line that part is
//!   the line's stretch inside the disc (`W = L`), and `S` is the overlap module's. Once the
//!   centre has sunk below the line the region bulges past that stretch and `W` is its whole
//!   width: the normal stays defined, and continuous, down to a disc wholly below the line
//!   (`L = 0`), where the overlap rule would lose its vertical part.
//! - Normal `n = −S/|S|` (from the line into the circle); `|S| ≥ W/2 > 0` for any region.
//! - `g`, the centroid of `R`: the polygon of `R`'s outline vertices (a fan about their mean,
//!   a point of `R`, so a small region keeps its digits) plus the circular segment of each
//!   arc (`½r²(σ − sin σ)`, centroid `4r sin³(σ/2) / (3(σ − sin σ))` from the centre along
//!   the arc's middle, with `σ − sin σ` by its series below a radian), all in closed form.
//! - Points: where the line through `g` along `n` meets the circle going along `−n`, and the
//!   line `y = 0` going along `+n`; when it meets that line beyond an end (the region hangs
//!   past the end and `n` leans over it), the end itself, so the point stays continuous.
//!   δ is their distance.
//! - Length (the 2-D "area"): `R`'s extent across `n`.
//!
//! **Limits.** Where the range covers the disc's span this is the unbounded line's closed
//! form (`point_line::circle_line`): `n = (0, side)`, δ = `r − d`, the chord (or the
//! diameter once the centre is below the line) as length. An end cuts in continuously: as it
//! enters the disc, `h₀` grows from zero (as the square root of its way in, so the normal is
//! continuous but not smooth there). A circle wholly beyond an end, or touching the line or an
//! end's vertical from outside (a region of zero area), has no contact. The end's vertical
//! closes the region but is not a surface of the line: a circle whose centre lies below the
//! line, coming in past an end, starts its contact with the sliver under the line, whose
//! depth is measured up to the line's end (about the centre's depth), not from zero as a box's
//! side face would give.
//!
//! **Degenerate branches.** A centre exactly on an end needs none: the region is the quarter
//! disc, `h₀ = L = r`. A corner of `H` on the circle to round-off is judged inside or outside
//! once (`x² + y² < r²`) and both edges through it follow that judgement, so the outline
//! closes; an arc between two stretches whose ends agree to `1e-9·r` but turn the wrong way by
//! round-off is empty, not a full turn (between two stretches a legitimate arc never ends
//! that close to where it starts).
//!
//! **Against arcs.** A closed 360° arc on a bounded line goes through the general overlap,
//! which closes a region at an end inside the disc with the segment to the end's closest point
//! on the circle (radial, not vertical) and does not cut a region at an end outside the disc.
//! The two agree where the region's span lies within the range, and where an end inside the
//! disc lies straight below a centre above the line (the radial segment is then the vertical);
//! elsewhere the circle follows the half-strip, as the point does.

use super::InPlane;
use crate::kernel::PairContact;
use contact_core::Vector2;
use std::f64::consts::TAU;

/// Below this angle `σ − sin σ` is summed as its series (the subtraction would lose
/// `−log₁₀(σ²/6)` digits); at and above it the subtraction loses under one.
const SERIES_BELOW: f64 = 1.0;

/// Arc ends closer than this (times the radius) that turn the wrong way make an empty arc.
const SAME_POINT: f64 = 1e-9;

/// One piece of `R`'s outline, counter-clockwise, in the frame centred on the circle with the
/// material below `v = k`.
#[derive(Debug, Clone, Copy, Default)]
struct Piece {
    from: Vector2,
    to: Vector2,
    /// The angle swept about the centre for an arc; `None` for a straight stretch.
    sweep: Option<f64>,
}

/// The contact in the frame centred on the circle, unflipped (material at `v ≤ k`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Local {
    /// Unit normal from the line into the circle.
    pub normal: Vector2,
    /// Point on the circle.
    pub on_circle: Vector2,
    /// Point on the line.
    pub on_line: Vector2,
    /// Area of `R`.
    pub area: f64,
    /// Centroid of `R`.
    pub centroid: Vector2,
    /// `R`'s extent across the normal.
    pub length: f64,
}

/// `σ − sin σ` without cancellation for small `σ ≥ 0`; `sin` is `sin σ`, used at and above
/// [`SERIES_BELOW`].
fn sigma_minus_sin(sigma: f64, sin: f64) -> f64 {
    if sigma >= SERIES_BELOW {
        return sigma - sin;
    }
    // Σ (−1)^m σ^(2m+3) / (2m+3)!: each term is below σ²/20 of the one before, so ten
    // terms leave under 1e-17 of the sum for σ < 1.
    let s2 = sigma * sigma;
    let mut term = sigma * s2 / 6.0;
    let mut sum = 0.0;
    for m in 0..10 {
        sum += term;
        let next = (2 * m + 4) as f64 * (2 * m + 5) as f64;
        term *= -s2 / next;
    }
    sum
}

/// `a × b`.
fn cross(a: &Vector2, b: &Vector2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The stretches of `H`'s edges inside `D` (see [`edge_stretches`]), with their lengths.
struct Stretches {
    /// Each stretch as (start, end, whether the centre lies on its material side), in
    /// counter-clockwise order; the first `count` are set.
    list: [(Vector2, Vector2, bool); 3],
    /// How many stretches there are.
    count: usize,
    /// `L`: the line's stretch inside the disc.
    top: f64,
    /// `h₀`: the vertical through `a` inside `R`.
    h0: f64,
    /// `h₁`: the vertical through `b` inside `R`.
    h1: f64,
}

/// The contact of the disc of radius `r` about the origin with the half-strip
/// `a ≤ u ≤ b, v ≤ k` (`a < b`, either may be infinite); `None` when they share no area.
pub(crate) fn local_contact(r: f64, k: f64, a: f64, b: f64) -> Option<Local> {
    if !(k > -r && a < r && b > -r && r > 0.0) {
        return None;
    }
    let edges = edge_stretches(r, k, a, b);
    let whole_disc = edges.count == 0;
    if whole_disc && !(a <= -r && b >= r && k >= r) {
        return None;
    }
    let (pieces, n) = outline(r, &edges.list[..edges.count]);
    let pieces = &pieces[..n];
    let (area, centroid) = if whole_disc {
        (std::f64::consts::PI * r * r, Vector2::zeros())
    } else {
        moments(r, pieces)
    };
    if !(area > 0.0 && area.is_finite()) {
        return None;
    }
    // S = ½(S_a − S_b) with S_a = (h₀ − h₁, −L) and S_b = (0, W).
    let width = if k > 0.0 {
        b.min(r) - a.max(-r)
    } else {
        edges.top
    };
    let s = Vector2::new(0.5 * (edges.h0 - edges.h1), -0.5 * (edges.top + width));
    let normal = -s / s.norm();
    let (on_line, on_circle) = contact_points(r, k, (a, b), &centroid, &normal);
    Some(Local {
        normal,
        on_circle,
        on_line,
        area,
        centroid,
        length: extent_across(r, k, (a, b), pieces, &normal),
    })
}

/// The stretches of `H`'s edges inside `D`, in counter-clockwise order: the line (towards
/// −u), the vertical through `a` (downwards), the vertical through `b` (upwards).
fn edge_stretches(r: f64, k: f64, a: f64, b: f64) -> Stretches {
    let half = |t: f64| ((r - t) * (r + t)).sqrt();
    // Each corner is judged once, so the two edges through it agree.
    let corner_a = a * a + k * k < r * r;
    let corner_b = b * b + k * k < r * r;
    // Each with whether the centre lies on its material side (for a lone stretch's arc).
    let mut stretches = [(Vector2::zeros(), Vector2::zeros(), false); 3];
    let mut count = 0;
    let (mut top, mut h0, mut h1) = (0.0, 0.0, 0.0);
    if k < r {
        let w = half(k);
        let lo = if corner_a { a } else { a.max(-w) };
        let hi = if corner_b { b } else { b.min(w) };
        if lo < hi {
            top = hi - lo;
            stretches[count] = (Vector2::new(hi, k), Vector2::new(lo, k), k > 0.0);
            count += 1;
        }
    }
    if a > -r {
        let w = half(a);
        let v = if corner_a { k } else { k.min(w) };
        if -w < v {
            h0 = v + w;
            stretches[count] = (Vector2::new(a, v), Vector2::new(a, -w), a < 0.0);
            count += 1;
        }
    }
    if b < r {
        let w = half(b);
        let v = if corner_b { k } else { k.min(w) };
        if -w < v {
            h1 = v + w;
            stretches[count] = (Vector2::new(b, -w), Vector2::new(b, v), b > 0.0);
            count += 1;
        }
    }
    Stretches {
        list: stretches,
        count,
        top,
        h0,
        h1,
    }
}

/// `R`'s outline from its `stretches` (at least one): each stretch, then the arc of the
/// circle (radius `r`) to the next one's start; the pieces and how many there are.
fn outline(r: f64, stretches: &[(Vector2, Vector2, bool)]) -> ([Piece; 6], usize) {
    let count = stretches.len();
    let mut pieces = [Piece::default(); 6];
    let mut n = 0;
    for s in 0..count {
        let (from, to, centre_inside) = stretches[s];
        pieces[n] = Piece {
            from,
            to,
            sweep: None,
        };
        n += 1;
        let next = stretches[(s + 1) % count].0;
        if next == to {
            continue;
        }
        let sweep = if count == 1 {
            // The arc back to the stretch's start: the long way round iff the centre lies
            // on the material side of the stretch.
            let short = cross(&to, &next).abs().atan2(to.dot(&next));
            if centre_inside { TAU - short } else { short }
        } else {
            let turn = cross(&to, &next).atan2(to.dot(&next));
            if turn >= 0.0 {
                turn
            } else if (next - to).norm() <= SAME_POINT * r {
                0.0
            } else {
                turn + TAU
            }
        };
        if sweep > 0.0 {
            pieces[n] = Piece {
                from: to,
                to: next,
                sweep: Some(sweep),
            };
            n += 1;
        }
    }
    (pieces, n)
}

/// The contact points from the centroid `centroid` along the unit `normal`: along `+n` to
/// the line `v = k`, clamped to the range `(a, b)`, and along `−n` to the circle of radius
/// `r`; (on the line, on the circle).
fn contact_points(
    r: f64,
    k: f64,
    (a, b): (f64, f64),
    centroid: &Vector2,
    normal: &Vector2,
) -> (Vector2, Vector2) {
    // Along +n from g to the line, clamped to the range; along −n to the circle.
    let reach = (k - centroid.y) / normal.y;
    let on_line = Vector2::new((centroid.x + reach * normal.x).clamp(a, b), k);
    let gn = centroid.dot(normal);
    let g_norm = centroid.norm();
    let inside = (r - g_norm) * (r + g_norm);
    let root = (gn * gn + inside).max(0.0).sqrt();
    let back = if gn >= 0.0 {
        gn + root
    } else {
        inside / (root - gn)
    };
    let on_circle = centroid - back * normal;
    (on_line, on_circle)
}

/// `R`'s extent across the unit `normal`: over the outline's vertices (the `pieces`' starts),
/// and the circle's own extremes (radius `r`) where they lie on `R`'s arcs (in the half-strip
/// `a ≤ u ≤ b, v ≤ k`).
fn extent_across(r: f64, k: f64, (a, b): (f64, f64), pieces: &[Piece], normal: &Vector2) -> f64 {
    // Extent across n: the outline's vertices, and the circle's own extremes where they lie
    // on R's arcs (in H).
    let across = Vector2::new(-normal.y, normal.x);
    let in_strip = |p: Vector2| p.y <= k && p.x >= a && p.x <= b;
    let mut extent = [f64::INFINITY, f64::NEG_INFINITY];
    for p in pieces.iter().map(|p| p.from) {
        let t = p.dot(&across);
        extent = [extent[0].min(t), extent[1].max(t)];
    }
    if in_strip(r * across) {
        extent[1] = r;
    }
    if in_strip(-r * across) {
        extent[0] = -r;
    }
    extent[1] - extent[0]
}

/// Area and centroid of the convex region bounded by `pieces` (arcs of the circle of radius
/// `r` about the origin, and straight stretches): the fan of triangles about the vertices'
/// mean, plus each arc's circular segment.
fn moments(r: f64, pieces: &[Piece]) -> (f64, Vector2) {
    let o = pieces.iter().map(|p| p.from).sum::<Vector2>() / pieces.len() as f64;
    let mut area = 0.0;
    let mut moment = Vector2::zeros();
    for piece in pieces {
        let (p, q) = (piece.from - o, piece.to - o);
        let triangle = 0.5 * cross(&p, &q);
        area += triangle;
        moment += triangle * (p + q) / 3.0;
        if let Some(sigma) = piece.sweep {
            let (sin_half, cos_half) = (0.5 * sigma).sin_cos();
            let excess = sigma_minus_sin(sigma, 2.0 * sin_half * cos_half);
            let segment = 0.5 * r * r * excess;
            // The arc's middle direction: its start turned by σ/2 (no angle needed).
            let u = piece.from / r;
            let mid = Vector2::new(
                cos_half * u.x - sin_half * u.y,
                sin_half * u.x + cos_half * u.y,
            );
            let distance = 4.0 * r * sin_half.powi(3) / (3.0 * excess);
            area += segment;
            moment += segment * (distance * mid - o);
        }
    }
    (area, o + moment / area)
}

/// Circle `a` of `radius` against line `b` over `x_range` (at least one end finite), its
/// material at `side·y ≤ 0`.
pub(crate) fn contact(
    frame: &InPlane<'_>,
    radius: f64,
    x_range: [f64; 2],
    side: f64,
) -> Option<PairContact> {
    let c = frame.origin_a;
    // The frame centred on the circle, mirrored when flipped so the material lies below.
    let height = side * c.y;
    let local = local_contact(radius, -height, x_range[0] - c.x, x_range[1] - c.x)?;
    let depth = (local.on_line - local.on_circle).norm();
    if !(depth > 0.0 && depth.is_finite()) {
        return None;
    }
    let back = |p: Vector2| contact_core::Point2::new(c.x + p.x, c.y + side * p.y);
    Some(PairContact {
        point_a: frame.point_w(&back(local.on_circle)),
        point_b: frame.point_w(&back(local.on_line)),
        normal: frame.vector_w(&Vector2::new(local.normal.x, side * local.normal.y)),
        depth,
        area: local.length,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn the_series_meets_the_subtraction_at_a_radian() {
        let s = SERIES_BELOW * (1.0 - 1e-15);
        let series = sigma_minus_sin(s, s.sin());
        assert!((series - (s - s.sin())).abs() <= 1e-16, "{series}");
        // Small angles keep their digits: σ³/6 − σ⁵/120 at σ = 1e-4.
        let tiny = 1e-4_f64;
        let expected = tiny.powi(3) / 6.0 - tiny.powi(5) / 120.0;
        assert!((sigma_minus_sin(tiny, tiny.sin()) / expected - 1.0).abs() < 1e-15);
    }

    #[test]
    fn a_centre_on_the_end_cuts_a_quarter_disc() {
        // Range [0, ∞), centre on the end at the line: the quarter below and to the right.
        let r = 1.5;
        let l = local_contact(r, 0.0, 0.0, f64::INFINITY).unwrap();
        assert!((l.area - 0.25 * PI * r * r).abs() < 1e-14, "{l:?}");
        let c = 4.0 * r / (3.0 * PI);
        assert!((l.centroid - Vector2::new(c, -c)).norm() < 1e-14, "{l:?}");
        // h₀ = r, L = W = r: S = (r/2, −r), n = (−1, 2)/√5.
        let n = Vector2::new(-1.0, 2.0) / 5f64.sqrt();
        assert!((l.normal - n).norm() < 1e-15, "{l:?}");
    }

    #[test]
    fn a_disc_inside_the_range_is_the_unbounded_closed_form() {
        for k in [-0.7, -0.2, 0.0, 0.4, 0.99, 1.3] {
            let l = local_contact(1.0, k, -5.0, 7.0).unwrap();
            assert!((l.normal - Vector2::y()).norm() < 1e-15, "{k}: {l:?}");
            assert!(
                (l.on_line - Vector2::new(0.0, k)).norm() < 1e-15,
                "{k}: {l:?}"
            );
            assert!((l.on_circle - Vector2::new(0.0, -1.0)).norm() < 1e-15);
            let chord = if k < 0.0 {
                2.0 * (1.0 - k * k).sqrt()
            } else {
                2.0
            };
            assert!((l.length - chord).abs() < 1e-15, "{k}: {l:?}");
        }
        assert!(local_contact(1.0, -1.0, -5.0, 7.0).is_none());
    }
}
