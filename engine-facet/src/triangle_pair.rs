//! Triangle–triangle intersection with the intersection segment (Möller 1997, "A fast
//! triangle-triangle intersection test": the interval step on each cut end's coordinate along
//! the line's dominant axis, the segment's points formed only for a crossing).
//!
//! Each triangle's vertices are classified against the other's plane by signed distance. A
//! distance within a band of zero counts as *on* the plane, so vertices on a plane, shared
//! edges and touching vertices all take the on-plane branch consistently (the same band for
//! both triangles): `PLANE_EPS · |edge|max` of the pair in [`intersect`], and one band for a
//! whole query, relative to the longest edge of either mesh, when the contact search calls
//! [`intersect_on_planes`] (a vertex near a plane is then classified alike in every pair it
//! takes part in). Degenerate outcomes:
//! - both triangles in one plane: [`TrianglePair::Coplanar`] when their 2-D projections overlap
//!   (an area contact; it bounds no volume, so contact regions ignore it);
//! - a single touching point: a zero-length segment.

use contact_core::Vector3;

/// Relative tolerance for "on the plane": 1e-12 of the pair's longest edge.
pub const PLANE_EPS: f64 = 1e-12;

/// The outcome of a triangle–triangle test.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TrianglePair {
    /// The closed triangles do not meet.
    Disjoint,
    /// They cross along this segment, oriented along `n_p × n_q` (the normals of the first and
    /// second triangle, counter-clockwise).
    Segment(Vector3, Vector3),
    /// They lie in one plane and overlap.
    Coplanar,
}

/// Where an end of a crossing segment lies on the triangle it came from: on the edge from
/// corner `k` to corner `k + 1`, or at corner `k` (a corner on the other triangle's plane).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Feature {
    /// The edge from corner `k` to corner `k + 1`.
    Edge(u8),
    /// Corner `k`.
    Corner(u8),
}

/// An end of a crossing segment: the triangle it lies on the boundary of (`first`: the first
/// triangle given to [`intersect_with_ends`]) and where.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SegmentEnd {
    /// On the first triangle's boundary (else the second's).
    pub first: bool,
    /// The edge or corner.
    pub feature: Feature,
}

/// Signed distances of `p`'s vertices to the plane of `q` (normal `n`, through `q0`).
#[inline]
fn distances(p: &[Vector3; 3], n: &Vector3, q0: &Vector3) -> [f64; 3] {
    [
        n.dot(&(p[0] - q0)),
        n.dot(&(p[1] - q0)),
        n.dot(&(p[2] - q0)),
    ]
}

/// `d` with the values within the band snapped to zero: `|d| ≤ band·|n|`, compared squared
/// (`band_n² = band²·|n|²`) so no root is taken.
#[inline]
fn snapped(d: [f64; 3], band_n_squared: f64) -> [f64; 3] {
    d.map(|v| if v * v <= band_n_squared { 0.0 } else { v })
}

/// `d` with its zeros given the sign of `toward` (kept at zero where `toward` is zero), at a
/// magnitude that moves no point formed from them.
#[inline]
fn nudged(d: [f64; 3], toward: f64) -> [f64; 3] {
    let tiny = f64::MIN_POSITIVE;
    let signed = if toward > 0.0 {
        tiny
    } else if toward < 0.0 {
        -tiny
    } else {
        0.0
    };
    d.map(|v| if v == 0.0 { signed } else { v })
}

#[inline]
fn same_side(d: &[f64; 3]) -> bool {
    // Non-short-circuit: one branch on the outcome rather than one per comparison.
    ((d[0] > 0.0) & (d[1] > 0.0) & (d[2] > 0.0)) | ((d[0] < 0.0) & (d[1] < 0.0) & (d[2] < 0.0))
}

/// Intersects triangles `p` and `q` (vertices in one frame).
pub fn intersect(p: &[Vector3; 3], q: &[Vector3; 3]) -> TrianglePair {
    intersect_with_ends(p, q).0
}

/// [`intersect`], with the boundary feature each end of a crossing segment lies on (the
/// intersection curve goes on across it into the neighbouring triangle); the ends are
/// meaningless for other outcomes. The on-plane band is `PLANE_EPS` times the pair's longest
/// edge.
pub fn intersect_with_ends(p: &[Vector3; 3], q: &[Vector3; 3]) -> (TrianglePair, [SegmentEnd; 2]) {
    let np = (p[1] - p[0]).cross(&(p[2] - p[0]));
    let nq = (q[1] - q[0]).cross(&(q[2] - q[0]));
    let scale = 0.0f64
        .max((p[1] - p[0]).norm_squared())
        .max((p[2] - p[1]).norm_squared())
        .max((p[0] - p[2]).norm_squared())
        .max((q[1] - q[0]).norm_squared())
        .max((q[2] - q[1]).norm_squared())
        .max((q[0] - q[2]).norm_squared())
        .sqrt();
    let dq = distances(q, &np, &p[0]);
    intersect_on_planes(p, q, &np, &nq, dq, PLANE_EPS * scale)
}

/// The test itself, on planes the caller has formed: `np = (p₁ − p₀) × (p₂ − p₀)`, `nq` the
/// same for `q`, `dq` the distances `np·(q_k − p₀)` (not yet snapped), and `band` the
/// on-plane band as a length (a distance `d` to a plane of normal `n` counts as zero when
/// `|d| ≤ band·|n|`). A caller testing many pairs forms each plane once and can share one band
/// across them all, so a vertex near a plane is classified alike in every pair it takes part
/// in.
#[inline]
pub fn intersect_on_planes(
    p: &[Vector3; 3],
    q: &[Vector3; 3],
    np: &Vector3,
    nq: &Vector3,
    dq: [f64; 3],
    band: f64,
) -> (TrianglePair, [SegmentEnd; 2]) {
    intersect_nudged(p, q, np, nq, dq, band, &Vector3::zeros())
}

/// [`intersect_on_planes`] with `p`'s solid moved by an infinitesimal `ε·nudge`
/// (simulation of simplicity): a vertex within the band of the other triangle's plane is put
/// on the side the nudge moves it to — `p`'s vertex on `q`'s plane on the side of
/// `sign(n_q·nudge)`, `q`'s on `p`'s plane on the side of `−sign(n_p·nudge)` — while its point
/// stays where it is. Where the nudge is perpendicular to a normal (or zero) the vertex stays
/// on the plane. [`intersect_perturbed`] with those sides.
#[inline]
pub fn intersect_nudged(
    p: &[Vector3; 3],
    q: &[Vector3; 3],
    np: &Vector3,
    nq: &Vector3,
    dq: [f64; 3],
    band: f64,
    nudge: &Vector3,
) -> (TrianglePair, [SegmentEnd; 2]) {
    let sides = Sides {
        p: |_| nq.dot(nudge),
        q: -np.dot(nudge),
    };
    intersect_perturbed(p, q, np, nq, dq, band, sides)
}

/// Where [`intersect_perturbed`] puts the vertices that lie on the other triangle's plane
/// (within the band): `p`'s corner `k` on `q`'s plane on the side of the sign of `p(k)`, every
/// corner of `q` on `p`'s plane on the side of the sign of `q` (zero: on the plane).
#[derive(Debug, Clone, Copy)]
pub struct Sides<F: Fn(usize) -> f64> {
    /// The side of `p`'s corner `k` (asked only for a corner on `q`'s plane).
    pub p: F,
    /// The side of any corner of `q` on `p`'s plane.
    pub q: f64,
}

/// The test with the vertices on the other triangle's plane put on the `sides` given, their
/// points unmoved: the sides of an infinitesimal perturbation of the two solids (simulation
/// of simplicity). A contact search that takes every pair with sides that depend only on the
/// vertex and the plane classifies a vertex alike in every pair it takes part in, so the
/// segments of flush faces, shared edges and vertices on faces close into the loops of the
/// perturbed solids, whose limit the contact is; coplanar triangles come apart.
#[inline]
pub fn intersect_perturbed<F: Fn(usize) -> f64>(
    p: &[Vector3; 3],
    q: &[Vector3; 3],
    np: &Vector3,
    nq: &Vector3,
    dq: [f64; 3],
    band: f64,
    sides: Sides<F>,
) -> (TrianglePair, [SegmentEnd; 2]) {
    let none = [SegmentEnd {
        first: true,
        feature: Feature::Corner(0),
    }; 2];
    let outcome = |pair| (pair, none);
    let band_squared = band * band;
    let dq = nudged(snapped(dq, band_squared * np.norm_squared()), sides.q);
    if same_side(&dq) {
        return outcome(TrianglePair::Disjoint);
    }
    let mut dp = snapped(distances(p, nq, &q[0]), band_squared * nq.norm_squared());
    for (k, d) in dp.iter_mut().enumerate() {
        if *d == 0.0 {
            *d = nudged([0.0; 3], (sides.p)(k))[0];
        }
    }
    if same_side(&dp) {
        return outcome(TrianglePair::Disjoint);
    }
    if dp == [0.0; 3] || dq == [0.0; 3] {
        return outcome(if coplanar_overlap(p, q, np) {
            TrianglePair::Coplanar
        } else {
            TrianglePair::Disjoint
        });
    }
    let dir = np.cross(nq);
    // Ends are ordered along the cut line by their coordinate on the axis `dir` leans on most
    // (signed to run along `dir`): monotonic along the line as the projection on `dir` is, and
    // one lerp of a coordinate rather than a point and a dot product, so the 3-D points are
    // formed only for the two ends of a crossing.
    let axis = dir.iamax();
    let sign = if dir[axis] < 0.0 { -1.0 } else { 1.0 };
    let (Some((a0, a1)), Some((b0, b1))) =
        (plane_cut(p, &dp, axis, sign), plane_cut(q, &dq, axis, sign))
    else {
        return outcome(TrianglePair::Disjoint);
    };
    // Both cuts lie on the line of the two planes: overlap their intervals along it. Intervals
    // that overlap by no more than the band only touch (an edge resting on an edge, to
    // round-off): no crossing, as the triangles come apart under a nudge that does not push
    // them into each other, and a segment that short bounds nothing.
    if (a1.key <= b0.key + band) | (b1.key <= a0.key + band) {
        return outcome(TrianglePair::Disjoint);
    }
    let end_of = |first, feature| SegmentEnd { first, feature };
    let (start, start_end) = if a0.key >= b0.key {
        (a0.point(p), end_of(true, a0.feature))
    } else {
        (b0.point(q), end_of(false, b0.feature))
    };
    let (end, end_end) = if a1.key <= b1.key {
        (a1.point(p), end_of(true, a1.feature))
    } else {
        (b1.point(q), end_of(false, b1.feature))
    };
    (TrianglePair::Segment(start, end), [start_end, end_end])
}

/// The segment where a triangle meets a plane, given its vertices' signed distances (not all
/// zero, not all of one strict sign), its ends ordered along the cut line (coordinate `axis`
/// times `sign`), each with the corner or edge it lies on.
#[inline]
fn plane_cut(t: &[Vector3; 3], d: &[f64; 3], axis: usize, sign: f64) -> Option<(CutEnd, CutEnd)> {
    let cut = |i: usize, j: usize| {
        let lambda = d[i] / (d[i] - d[j]);
        CutEnd {
            lambda,
            feature: Feature::Edge(i as u8),
            key: sign * (t[i][axis] + (t[j][axis] - t[i][axis]) * lambda),
        }
    };
    let corner = |i: usize| CutEnd {
        lambda: 0.0,
        feature: Feature::Corner(i as u8),
        key: sign * t[i][axis],
    };
    if d[0] != 0.0 && d[1] != 0.0 && d[2] != 0.0 {
        // No corner on the plane (nearly always): one corner lies alone on its side and its
        // two edges cross, found from the signs rather than by a branch per edge. The same
        // points in the same order as the general loop below.
        let (s0, s1, s2) = (d[0] > 0.0, d[1] > 0.0, d[2] > 0.0);
        if (s0 == s1) & (s1 == s2) {
            return None;
        }
        // The lone corner's two edges, the lower-numbered first (edge k runs from corner k to
        // k + 1): corner 0 alone cuts edges 0 and 2, corner 1 edges 0 and 1, corner 2 edges 1
        // and 2.
        let (first, second) = if s1 == s2 {
            (cut(0, 1), cut(2, 0))
        } else if s0 == s2 {
            (cut(0, 1), cut(1, 2))
        } else {
            (cut(1, 2), cut(2, 0))
        };
        let lo = if second.key < first.key {
            second
        } else {
            first
        };
        let hi = if second.key > first.key {
            second
        } else {
            first
        };
        return Some((lo, hi));
    }
    let mut ends = [corner(0); 4];
    let mut n = 0;
    for i in 0..3 {
        let j = (i + 1) % 3;
        if d[i] == 0.0 {
            ends[n] = corner(i);
            n += 1;
        }
        if (d[i] > 0.0 && d[j] < 0.0) || (d[i] < 0.0 && d[j] > 0.0) {
            ends[n] = cut(i, j);
            n += 1;
        }
    }
    if n == 0 {
        return None;
    }
    let (mut lo, mut hi) = (ends[0], ends[0]);
    for e in &ends[1..n] {
        if e.key < lo.key {
            lo = *e;
        }
        if e.key > hi.key {
            hi = *e;
        }
    }
    Some((lo, hi))
}

/// An end of a triangle's cut by a plane: the corner or edge it lies on (on edge `k`, at
/// `lambda` from corner `k` towards corner `k + 1`) and its coordinate along the cut line.
#[derive(Debug, Clone, Copy)]
struct CutEnd {
    lambda: f64,
    feature: Feature,
    key: f64,
}

impl CutEnd {
    /// The end's point on triangle `t`.
    #[inline]
    fn point(&self, t: &[Vector3; 3]) -> Vector3 {
        match self.feature {
            Feature::Corner(k) => t[k as usize],
            Feature::Edge(k) => {
                let (i, j) = (k as usize, (k as usize + 1) % 3);
                t[i] + (t[j] - t[i]) * self.lambda
            }
        }
    }
}

/// Overlap of two triangles in one plane (normal `n`): project on the plane's dominant axes and
/// test edges for crossings, then containment of one vertex.
fn coplanar_overlap(p: &[Vector3; 3], q: &[Vector3; 3], n: &Vector3) -> bool {
    let drop = n.abs().imax();
    let (i, j) = ((drop + 1) % 3, (drop + 2) % 3);
    let pp = p.map(|v| [v[i], v[j]]);
    let qq = q.map(|v| [v[i], v[j]]);
    for a in 0..3 {
        for b in 0..3 {
            if segments_cross(pp[a], pp[(a + 1) % 3], qq[b], qq[(b + 1) % 3]) {
                return true;
            }
        }
    }
    inside_2d(&pp, qq[0]) || inside_2d(&qq, pp[0])
}

fn orient_2d(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

fn segments_cross(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let (o1, o2) = (orient_2d(a, b, c), orient_2d(a, b, d));
    let (o3, o4) = (orient_2d(c, d, a), orient_2d(c, d, b));
    o1 * o2 <= 0.0 && o3 * o4 <= 0.0 && !(o1 == 0.0 && o2 == 0.0 && o3 == 0.0 && o4 == 0.0)
}

fn inside_2d(t: &[[f64; 2]; 3], p: [f64; 2]) -> bool {
    let s = [
        orient_2d(t[0], t[1], p),
        orient_2d(t[1], t[2], p),
        orient_2d(t[2], t[0], p),
    ];
    (s[0] >= 0.0 && s[1] >= 0.0 && s[2] >= 0.0) || (s[0] <= 0.0 && s[1] <= 0.0 && s[2] <= 0.0)
}
