//! A cylinder against a convex polyhedron (a box at any tilt), in closed form: the
//! intersection's volume, centroid and surface measures by the divergence theorem over its
//! boundary, every piece of which is a plane region bounded by segments and circular arcs or
//! a patch of the cylinder's side bounded by the arcs the faces and caps cut from it. The
//! polyhedron is a box ([`box_faces`]) or a component of a closed mesh, its triangles the
//! faces ([`mesh`]). A component that is not convex is taken the same way but for its caps,
//! which come from its section ([`section_cap`]), and for the test that its intersection
//! with the cylinder is one region ([`links`]).
//!
//! ## The method
//! In the working frame (the cylinder's axes, origin at its centre, caps at `z = ±h`, radius
//! `r`) the boundary of the intersection `C ∩ P` (convex for a convex `P`) is made of
//! - **the caps' parts inside `P`**: the disc `|p| ≤ r` inside `P`'s section at `z = ±h` (for
//!   a convex `P` a convex polygon: the disc's square clipped by each face,
//!   [`super::disc_region`]; otherwise the section's chords and the rim's arcs inside it);
//! - **`P`'s faces' parts inside `C`**: a face not parallel to the axis (`n_z ≠ 0`), seen
//!   along the axis, is its projected polygon clipped to the slab `|z| ≤ h`, and the
//!   cylinder's surface is the circle `|p| = r` there, so its part inside `C` is the disc's
//!   part inside that polygon — the face's area and moments are the projection's divided by
//!   `|n_z|`, its height the plane's `z(p)`. A face parallel to the axis (`n_z = 0`) meets
//!   the cylinder in a strip `|t| ≤ √(r² − q²)` (`q` its distance from the axis, `t` along
//!   it), clipped to the face and the slab: a polygon;
//! - **the cylinder's side inside `P`**: in the coordinates `(φ, z)` of the side it is the
//!   region between the lower bounds and the upper bounds that `P`'s faces and the caps set on
//!   `z`, and the bounding curves are exactly the rim arcs of the pieces above (an arc of a
//!   face with `n_z > 0` is an upper bound, `z(φ) = (d − r(n_x cos φ + n_y sin φ))/n_z`; of
//!   `n_z < 0`, a lower one; of the top and bottom caps, `z = ±h`; against a `P` that is not
//!   convex a generator may have several intervals inside it, each still between such a
//!   lower and upper bound, so the sums below are unchanged). By Green's theorem each
//!   integral `∬ g(φ) zᵏ dφ dz` over the side is `±∫ g zᵏ⁺¹/(k+1) dφ` along those arcs:
//!   products of up to three functions `a + b cos φ + c sin φ`, integrated in closed form
//!   about each arc's middle ([`trig`], so a short arc keeps its precision).
//!
//! Then `V = ⅓ ∮ (x − o)·n dA` and `∫(x − o) dV = ¼ ∮ (x − o)((x − o)·n) dA` (from
//! `∇·(xᵢ x) = 4xᵢ`), about `o` the centroid of the flat pieces (a point of a convex
//! intersection, near one that is not): `(x − o)·n` is `r − o_x cos φ − o_y sin φ` on the
//! side and a constant on each flat piece, every term as small as the region, so a shallow
//! region keeps its precision (about the cylinder's centre, terms of the pair's size cancel
//! to the region's: measured 1e-6 relative spread of a depth of 4e-4 of the size under
//! rotations about the axis, against 2e-12 about `o`). The cylinder's surface inside `P` (area vector and area,
//! for the normal) is the side's and the caps'; `P`'s inside `C` is the faces'.
//!
//! ## Degenerate branches
//! - **A face nearly parallel to the axis** (`0 < |n_z| < 10⁻³`): its projection is a sliver
//!   whose area, divided by `|n_z|`, loses `1/|n_z|` of its precision, so the pair is not
//!   taken here ([`moments`] answers `None`) and the caller slices it. Exactly parallel faces
//!   are the strips above.
//! - **A face normal along the axis** (`n_h = 0`: a box with an axis along the cylinder's) is
//!   the caller's prism closed form ([`super::cylinder_prism`]), never this one; a cap flush
//!   with such a face would otherwise count twice.
//! - **Containment**: the cylinder inside `P` has both full caps (one arc each of a full
//!   turn) and no face pieces; `P` inside the cylinder has face pieces only.
//! - **Touching**: no region has area, so no volume: no contact.

pub(crate) mod half_spaces;
mod links;
pub(crate) mod mesh;
mod section_cap;
mod trig;

use super::disc_region::{DiscRegion, RimArc, disc_region};
use super::section::Polygon;
use super::sliced::SlicedMoments;
use contact_core::{Matrix3, Vector2, Vector3};
use trig::{Arc, Poly};

/// Faces closer than this to parallel with the axis (`|n_z|`, not zero) are sliced instead.
pub(crate) const NEAR_VERTICAL: f64 = 1e-3;

/// Most corners a face has (a bounded plane's top face: its square clipped by four walls).
pub(crate) const FACE_CORNERS: usize = 9;

/// One face of the polyhedron: the plane `normal·x = offset` (unit outward normal) and its
/// first `count` corners, counter-clockwise seen from outside.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Face {
    /// Outward unit normal.
    pub normal: Vector3,
    /// `normal·x` on the face.
    pub offset: f64,
    /// Corners, counter-clockwise seen from outside.
    pub corners: [Vector3; FACE_CORNERS],
    /// How many corners it has.
    pub count: usize,
}

/// The six faces of the box with centre `centre`, unit axes the columns of `axes` (right
/// handed) and half extents `half`.
pub(crate) fn box_faces(centre: &Vector3, axes: &Matrix3, half: &Vector3) -> [Face; 6] {
    let corner =
        |s: [f64; 3]| centre + axes * Vector3::new(s[0] * half.x, s[1] * half.y, s[2] * half.z);
    // Corners of the face +axis k, counter-clockwise seen from outside: the other two signs
    // round (+,+), (−,+), (−,−), (+,−) in the right-handed order (k+1, k+2).
    std::array::from_fn(|f| {
        let (k, sign) = (f / 2, if f % 2 == 0 { 1.0 } else { -1.0 });
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let mut quad = [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)];
        if sign < 0.0 {
            quad.reverse();
        }
        let normal = sign * axes.column(k).into_owned();
        Face {
            normal,
            offset: normal.dot(centre) + half[k],
            corners: std::array::from_fn(|c| {
                let (si, sj) = quad[c % 4];
                let mut s = [0.0; 3];
                s[k] = sign;
                s[i] = si;
                s[j] = sj;
                corner(s)
            }),
            count: 4,
        }
    })
}

/// A rim arc of a bound `z(φ) = a + b cos φ + c sin φ` on the cylinder's side: `sign` +1
/// for an upper bound, −1 for a lower one.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Bound {
    arc: RimArc,
    sign: f64,
    z: [f64; 3],
    /// The node of the boundary piece it lies on ([`links`]).
    owner: u8,
}

/// Most rim arcs kept against a box (a dozen in practice; more is sliced).
const BOX_ARCS: usize = 64;

/// A flat piece of the intersection's boundary: its plane's `n·x` offset from the frame's
/// origin along its unit normal, area, and first moment about the frame's origin.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Flat {
    normal: Vector3,
    offset: f64,
    area: f64,
    moment: Vector3,
    /// The cylinder's cap (its surface), not the polyhedron's.
    cap: bool,
}

/// Most flat pieces against a box: two caps and its six faces.
const BOX_FLATS: usize = 8;

/// [`moments`] against a box's six faces.
pub(crate) fn box_moments(r: f64, h: f64, faces: &[Face; 6]) -> Option<Option<SlicedMoments>> {
    moments::<BOX_FLATS, BOX_ARCS>(r, h, faces)
}

/// [`moments`] against at most six faces (a bounded plane's prism).
pub(crate) fn polyhedron_moments(r: f64, h: f64, faces: &[Face]) -> Option<Option<SlicedMoments>> {
    moments::<BOX_FLATS, BOX_ARCS>(r, h, faces)
}

/// Clips `poly` to the convex polygon `corners` (counter-clockwise when `orient` is +1,
/// clockwise when −1).
fn clip_to(poly: &mut Polygon, corners: &[Vector2], orient: f64) {
    let n = corners.len();
    for k in 0..n {
        let (p, q) = (corners[k], corners[(k + 1) % n]);
        let e = (q - p) * orient;
        let g = Vector2::new(e.y, -e.x);
        poly.clip(&g, g.dot(&p), 4);
    }
}

/// The intersection's moments for the cylinder of radius `r` and caps at `z = ±h` against the
/// convex polyhedron `faces`, in the working frame of the module docs: `Some(None)` when they
/// do not overlap with volume, `None` when a face is nearly parallel to the axis or the
/// pieces exceed the capacities (`FLATS` flat pieces, two of them the caps; `ARCS` rim arcs),
/// which the caller slices.
pub(crate) fn moments<const FLATS: usize, const ARCS: usize>(
    r: f64,
    h: f64,
    faces: &[Face],
) -> Option<Option<SlicedMoments>> {
    moments_of::<FLATS, ARCS>(r, h, faces, Caps::Convex, None)
}

/// How the caps' parts inside the polyhedron are found.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Caps<'a> {
    /// The polyhedron is convex: its section is the disc's square clipped by every face.
    Convex,
    /// Any closed polyhedron, these its triangles (working frame): the disc against their
    /// section ([`section_cap`]).
    Section(&'a [[Vector3; 3]]),
}

/// The intersection's boundary pieces found so far: the flat ones (the caps' and the faces')
/// and the rim arcs bounding its part of the cylinder's side, and whether more arcs came than
/// `ARCS` holds.
struct Pieces<const FLATS: usize, const ARCS: usize> {
    flats: [Flat; FLATS],
    flat_count: usize,
    bounds: [Bound; ARCS],
    arc_count: usize,
    overflow: bool,
}

impl<const FLATS: usize, const ARCS: usize> Pieces<FLATS, ARCS> {
    /// None found yet.
    fn new() -> Self {
        Self {
            flats: [Flat {
                normal: Vector3::zeros(),
                offset: 0.0,
                area: 0.0,
                moment: Vector3::zeros(),
                cap: false,
            }; FLATS],
            flat_count: 0,
            bounds: [Bound {
                arc: RimArc {
                    start: 0.0,
                    half_angle: 0.0,
                    half_chord: 0.0,
                },
                sign: 0.0,
                z: [0.0; 3],
                owner: 0,
            }; ARCS],
            arc_count: 0,
            overflow: false,
        }
    }

    /// Keeps the rim arc `arc` of the bound `z` (`sign` +1 for an upper bound, −1 for a
    /// lower one) lying on the piece `owner`, or notes the overflow past `ARCS` arcs.
    fn keep(&mut self, arc: &RimArc, sign: f64, z: [f64; 3], owner: usize) {
        if self.arc_count < ARCS {
            self.bounds[self.arc_count] = Bound {
                arc: *arc,
                sign,
                z,
                owner: owner as u8,
            };
            self.arc_count += 1;
        } else {
            self.overflow = true;
        }
    }

    /// Adds a flat piece (at most `FLATS`: the caller admits two caps and `FLATS − 2` faces).
    fn push(&mut self, flat: Flat) {
        self.flats[self.flat_count] = flat;
        self.flat_count += 1;
    }
}

/// [`moments`] with the caps found as `caps` says, and, when `links` is given, each face with
/// a piece inside the cylinder marked there and the pieces the caps and the side join
/// joined, so that the caller can tell whether the intersection is one region.
pub(crate) fn moments_of<const FLATS: usize, const ARCS: usize>(
    r: f64,
    h: f64,
    faces: &[Face],
    caps: Caps,
    mut links: Option<&mut links::Links>,
) -> Option<Option<SlicedMoments>> {
    if faces.len() + 2 > FLATS
        || faces
            .iter()
            .any(|f| f.normal.z != 0.0 && f.normal.z.abs() < NEAR_VERTICAL)
    {
        return None;
    }
    let mut pieces = Pieces::<FLATS, ARCS>::new();
    // The caps: the disc inside the polyhedron's section.
    for (z, sign) in [(h, 1.0), (-h, -1.0)] {
        let cap = cap_region_of(r, (z, sign), faces, caps, &mut pieces, links.as_deref_mut())?;
        if let Some(cap) = cap {
            pieces.push(Flat {
                normal: Vector3::z() * sign,
                offset: h,
                area: cap.area,
                moment: Vector3::new(cap.moment.x, cap.moment.y, z * cap.area),
                cap: true,
            });
        }
    }
    // The faces' pieces inside the cylinder.
    for (k, f) in faces.iter().enumerate() {
        let piece = if f.normal.z == 0.0 {
            strip_piece(r, h, f)
        } else {
            face_piece(r, h, k, f, &mut pieces)
        };
        if let Some(flat) = piece {
            if let Some(links) = links.as_deref_mut() {
                links.piece(k);
            }
            pieces.push(flat);
        }
    }
    if pieces.overflow {
        return None;
    }
    let bounds = &pieces.bounds[..pieces.arc_count];
    if let Some(links) = links {
        if !links.one() {
            links::join_across_side(links, bounds);
        }
    }
    Some(divergence_moments(
        r,
        &pieces.flats[..pieces.flat_count],
        bounds,
    ))
}

/// The cap at `z` (`sign` +1 for the top, −1 for the bottom) inside the polyhedron, found as
/// `caps` says, its rim arcs kept in `pieces`; with `links`, each rim arc joins the pieces it
/// connects. `None` when [`section_cap::cap_region`] declines the section (sliced instead).
fn cap_region_of<const FLATS: usize, const ARCS: usize>(
    r: f64,
    (z, sign): (f64, f64),
    faces: &[Face],
    caps: Caps,
    pieces: &mut Pieces<FLATS, ARCS>,
    mut links: Option<&mut links::Links>,
) -> Option<Option<DiscRegion>> {
    let square = Vector2::new(r, r);
    Some(match caps {
        Caps::Convex => {
            let mut section = Polygon::rectangle(square);
            for f in faces {
                section.clip(&f.normal.xy(), f.offset - f.normal.z * z, 4);
            }
            let arcs = |arc: &RimArc| pieces.keep(arc, sign, [z, 0.0, 0.0], 0);
            disc_region(r, section.vertices(), arcs)
        }
        Caps::Section(triangles) => {
            // A rim arc lies on the cap's region by the chord it leaves from, and joins
            // that chord's triangle to the one it enters by; the whole rim is its own node.
            let rim = if sign > 0.0 {
                links::TOP_RIM
            } else {
                links::TOP_RIM + 1
            };
            let arcs = |arc: &RimArc, chords: Option<(usize, usize)>| {
                let owner = match chords {
                    Some((from, to)) => {
                        if let Some(links) = links.as_deref_mut() {
                            links.join(from, to);
                        }
                        from
                    }
                    None => {
                        if let Some(links) = links.as_deref_mut() {
                            links.piece(rim);
                        }
                        rim
                    }
                };
                pieces.keep(arc, sign, [z, 0.0, 0.0], owner)
            };
            section_cap::cap_region(r, z, triangles, arcs)?
        }
    })
}

/// The piece inside the cylinder (radius `r`, caps at `z = ±h`) of the face `f`, parallel to
/// the axis: the strip `|t| ≤ w` of its plane, clipped to the face; `None` when it has no
/// area.
fn strip_piece(r: f64, h: f64, f: &Face) -> Option<Flat> {
    let (n, d) = (f.normal, f.offset);
    // Parallel to the axis: the strip |t| ≤ w of the plane inside the cylinder.
    let across = n.xy();
    let length = across.norm();
    let q = d / length;
    let w2 = (r - q.abs()) * (r + q.abs());
    if w2.is_nan() || w2 <= 0.0 {
        return None;
    }
    let along = Vector2::new(-across.y, across.x) / length;
    let mut strip = Polygon::rectangle(Vector2::new(w2.sqrt(), h));
    // (t, z) is right-handed seen from outside: the corners stay counter-clockwise.
    let corners = f.corners.map(|c| Vector2::new(along.dot(&c.xy()), c.z));
    clip_to(&mut strip, &corners[..f.count], 1.0);
    let m = strip.measures();
    if m.area > 0.0 {
        let xy = across * (q / length * m.area) + along * m.moment.x;
        return Some(Flat {
            normal: n,
            offset: d,
            area: m.area,
            moment: Vector3::new(xy.x, xy.y, m.moment.y),
            cap: false,
        });
    }
    None
}

/// The piece inside the cylinder (radius `r`, caps at `z = ±h`) of face `k` (`f`, not
/// parallel to the axis): seen along the axis, the projected face within the slab
/// `|z(p)| ≤ h` and the disc, its rim arcs kept in `pieces`; `None` when it has none.
fn face_piece<const FLATS: usize, const ARCS: usize>(
    r: f64,
    h: f64,
    k: usize,
    f: &Face,
    pieces: &mut Pieces<FLATS, ARCS>,
) -> Option<Flat> {
    let (n, d) = (f.normal, f.offset);
    // Seen along the axis: the projected face within the slab |z(p)| ≤ h.
    let orient = n.z.signum();
    let mut projected = Polygon::rectangle(Vector2::new(r, r));
    clip_to(
        &mut projected,
        &f.corners.map(|c| c.xy())[..f.count],
        orient,
    );
    let (nh, nz) = (n.xy(), n.z.abs());
    projected.clip(&(-orient * nh), h * nz - orient * d, 4);
    projected.clip(&(orient * nh), h * nz + orient * d, 4);
    let z = [d / n.z, -r * n.x / n.z, -r * n.y / n.z];
    let arcs = |arc: &RimArc| pieces.keep(arc, orient, z, k);
    let part = disc_region(r, projected.vertices(), arcs)?;
    let m = part.moment / nz;
    let mz = (d * part.area - nh.dot(&part.moment)) / (n.z * nz);
    Some(Flat {
        normal: n,
        offset: d,
        area: part.area / nz,
        moment: Vector3::new(m.x, m.y, mz),
        cap: false,
    })
}

/// The intersection's moments by the divergence theorem from its boundary: the flat pieces
/// `flats` and the side of the cylinder (radius `r`) between the rim arcs `bounds`; `None`
/// when it has no volume.
fn divergence_moments(r: f64, flats: &[Flat], bounds: &[Bound]) -> Option<SlicedMoments> {
    // The divergence theorem about a point of the intersection (the flat pieces' centroid:
    // the intersection is convex), so a shallow region's terms are as small as it is.
    let flat_area: f64 = flats.iter().map(|f| f.area).sum();
    if flat_area.is_nan() || flat_area <= 0.0 {
        return None;
    }
    let o = flats.iter().fold(Vector3::zeros(), |s, f| s + f.moment) / flat_area;
    // 3V and 4∫(x − o) dV, and the surfaces.
    let (mut volume3, mut moment4) = (0.0, Vector3::zeros());
    let (mut area_a, mut area_b, mut caps_z) = (0.0, 0.0, 0.0);
    for f in flats {
        let lever = f.offset - f.normal.dot(&o);
        volume3 += lever * f.area;
        moment4 += lever * (f.moment - o * f.area);
        if f.cap {
            area_a += f.area;
            caps_z += f.normal.z * f.area;
        } else {
            area_b += f.area;
        }
    }
    // The side, `dA = r dφ dz`, `(x − o)·n = w(φ) = r − o_x cos φ − o_y sin φ`: along each
    // arc the `z`-antiderivatives of `w`, `w·(x − o)` and `1`, `cos φ`, `sin φ` (the area and
    // its vector), with `ζ = z − o_z`.
    let (mut side_volume, mut side_moment) = (0.0, Vector3::zeros());
    let (mut side_area, mut side_vector) = (0.0, Vector2::zeros());
    for bound in bounds {
        let half = bound.arc.half_angle;
        let arc = Arc::new(bound.arc.start + half, half);
        let zeta = arc.local(bound.z[0] - o.z, bound.z[1], bound.z[2]);
        let zeta_w = zeta.poly().times(&arc.local(r, -o.x, -o.y));
        let at = |p: &Poly| bound.sign * arc.integral(p);
        side_volume += at(&zeta_w);
        side_moment += Vector3::new(
            at(&zeta_w.times(&arc.local(-o.x, r, 0.0))),
            at(&zeta_w.times(&arc.local(-o.y, 0.0, r))),
            0.5 * at(&zeta_w.times(&zeta)),
        );
        let zeta = zeta.poly();
        side_area += at(&zeta);
        side_vector += Vector2::new(
            at(&zeta.times(&arc.local(0.0, 1.0, 0.0))),
            at(&zeta.times(&arc.local(0.0, 0.0, 1.0))),
        );
    }
    volume3 += r * side_volume;
    moment4 += r * side_moment;
    let volume = volume3 / 3.0;
    if volume.is_nan() || volume <= 0.0 {
        return None;
    }
    Some(SlicedMoments {
        volume,
        centroid: o + moment4 / (4.0 * volume),
        area_vector_a: Vector3::new(r * side_vector.x, r * side_vector.y, caps_z),
        area_a: area_a + r * side_area,
        area_b,
    })
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_mesh;
