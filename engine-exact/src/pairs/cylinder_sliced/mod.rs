//! A cylinder against a cylinder, a box or a bounded plane: the intersection's moments by
//! slicing ([`crate::methods::sliced`]; two parallel cylinders and a box in closed form, two crossed
//! ones by the divergence theorem over their lateral surfaces, `revolved_pair`),
//! the contact from them by [`crate::methods::volume_contact`].
//!
//! ## The slicing direction `n` (perpendicular to the first cylinder's axis)
//! - **Cylinder–cylinder** (axes within `revolved_pair::PARALLEL` of parallel, and
//!   the divergence theorem's check): `n = â × b̂ / |â × b̂|`, perpendicular to both axes, so each plane
//!   `x·n = t` cuts both cylinders parallel to their axes (two rectangles). In `a`'s frame
//!   `â = ẑ` and `â × b̂ = (−b_y, b_x, 0)` is exact, so `n·b̂` is a round-off of `|â × b̂|`
//!   itself and stays tiny however close to parallel the axes are; `b̂` is then projected on
//!   the slicing planes (a change at round-off). **Parallel** axes (`|â × b̂| ≤ 4ε` in each
//!   component, the round-off of a rotation composed from two poses) are not sliced: the intersection is a lens times an axial overlap, in closed form
//!   ([`crate::methods::cylinder_parallel`]), and near-parallel axes (the general case, with no
//!   branch) approach it continuously (1e-12 rad off: within 4e-12 of it, see the
//!   characterization table).
//! - **Cylinder–box, cylinder–bounded plane**: a box with an axis parallel (or opposite) to
//!   the cylinder's, to the same `4ε`, is not sliced: its section inside the disc times the axial
//!   overlap, in closed form ([`crate::methods::cylinder_prism`]); a box at any other tilt is not
//!   sliced either (the divergence theorem over the intersection's boundary, in closed form:
//!   `cylinder_polyhedron`), nor is a bounded plane's prism (its faces cut to the cylinder's
//!   reach), unless a face is within 1e-3 of parallel to the axis, where that closed form
//!   would lose precision. Otherwise, among directions
//!   perpendicular to the axis (64 sampled over a half turn), the one farthest from every
//!   face normal (smallest largest `|m·n|`): a face parallel to the slicing planes would be
//!   a jump in the section, and three lines through the origin always leave a direction at
//!   least 30° from each, so every face keeps `|g| ≥ 1/2` in-plane.
//!
//! ## The contact (SPEC §4, as [`crate::methods::volume_contact`] reads it)
//! One region (two convex solids meet in one convex piece; the bounded plane's solid is the
//! prism `z ≤ 0`, or `z ≥ 0` when flipped, over its rectangle). Normal `−S_a/|S_a|`, `S_a` the
//! area vector of the cylinder's surface inside the other solid; points where the line
//! through the centroid along the normal leaves each solid; area `|S_a|`.
//!
//! **Containment** (`|S_a|` at most 1e-12 of the intersection's surface): when no surface of
//! the other solid lies inside the cylinder, the cylinder is inside it and the normal is the
//! outward normal of the other solid's face nearest the centroid; otherwise (the other solid
//! inside the cylinder, or two identical cylinders on each other) the opposite of the
//! cylinder's nearest face normal (the bottom, then side, then top on ties); area a quarter of
//! the intersection's surface. Touching (no volume) is no contact.

mod bounds;

use super::revolved_pair;
use crate::kernel::PairContact;
use crate::methods::clipped::{HalfSpace, nearest_face, ray_exit, unit_for};
use crate::methods::cylinder_parallel::{self, ParallelB};
use crate::methods::cylinder_polyhedron;
use crate::methods::cylinder_prism::{self, Prism};
use crate::methods::sliced::{Bound, MAX_B_CUTS, MAX_BOUNDS, SlicedMoments, SlicedPair};
use crate::methods::solid_distance::{Solid, signed_distance};
use crate::methods::volume_contact::{self, ENCLOSED, VolumeMoments};
use crate::ray_exit::{surface_point_along, surface_point_along_w};
use contact_core::geometry::{Cuboid, Cylinder, Plane};
use contact_core::{Isometry3, Matrix3, Point3, Vector2, Vector3, WorkCounters};

/// The solid a cylinder is sliced against.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum SlicedSolid {
    /// A second cylinder.
    Cylinder(Cylinder),
    /// A box.
    Box(Cuboid),
    /// A bounded plane's prism, `side` −1 when flipped.
    Plane {
        /// The plane and its bounds.
        plane: Plane,
        /// +1 (material below) or −1 (above).
        side: f64,
    },
}

/// Directions sampled when choosing `n` against a polyhedron's faces.
const DIRECTION_SAMPLES: usize = 64;

/// The unit `n ⟂ ẑ` farthest from the given unit normals (smallest largest `|m·n|`).
fn direction_away_from(normals: &[Vector3]) -> Vector3 {
    let mut best = (f64::INFINITY, Vector3::x());
    for k in 0..DIRECTION_SAMPLES {
        let phi = k as f64 * std::f64::consts::PI / DIRECTION_SAMPLES as f64;
        let n = Vector3::new(phi.cos(), phi.sin(), 0.0);
        let worst = normals.iter().map(|m| m.dot(&n).abs()).fold(0.0, f64::max);
        // A clear improvement only, so round-off of the pose does not flip the choice.
        if worst < best.0 - 1e-9 {
            best = (worst, n);
        }
    }
    best.1
}

/// The bounded plane's prism as half-spaces in the plane's frame (up to five).
fn prism(plane: &Plane, side: f64) -> ([HalfSpace; 5], usize) {
    let mut out = [HalfSpace {
        normal: Vector3::z() * side,
        offset: 0.0,
    }; 5];
    let mut count = 1;
    let [x0, x1] = plane.x_range();
    let [y0, y1] = plane.y_range();
    for (normal, offset) in [
        (Vector3::x(), x1),
        (-Vector3::x(), -x0),
        (Vector3::y(), y1),
        (-Vector3::y(), -y0),
    ] {
        if offset.is_finite() {
            out[count] = HalfSpace { normal, offset };
            count += 1;
        }
    }
    (out, count)
}

/// Contact of cylinder `a` at `pose_a` with `b` at `pose_b`; the normal points from `b`
/// into `a`.
pub(crate) fn contact(
    a: &Cylinder,
    pose_a: &Isometry3,
    b: &SlicedSolid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    contact_by(a, pose_a, b, pose_b, work, Method::ClosedForm)
}

/// How crossed cylinders, a tilted box or a bounded plane are taken: the closed forms (and
/// the divergence theorem) where they apply, or always sliced (their independent check).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Method {
    /// Crossed cylinders (axes at least [`revolved_pair::PARALLEL`] apart) by the divergence
    /// theorem over the lateral surfaces ([`revolved_pair`]); [`cylinder_polyhedron`]
    /// unless a face is nearly parallel to the axis; a bounded plane with every edge out of
    /// reach as the unbounded one.
    ClosedForm,
    /// Sliced.
    #[cfg_attr(not(test), allow(dead_code))]
    Sliced,
}

/// [`contact`], a tilted box or a bounded plane taken by `method`.
pub(crate) fn contact_by(
    a: &Cylinder,
    pose_a: &Isometry3,
    b: &SlicedSolid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    method: Method,
) -> Option<PairContact> {
    let (ra, hla) = (a.radius(), 0.5 * a.length());
    // A bounded plane with every edge out of reach is the unbounded plane, in closed form.
    if let (SlicedSolid::Plane { plane, side }, Method::ClosedForm) = (b, method) {
        let centre = pose_a * Point3::new(0.0, 0.0, hla);
        if crate::methods::bounded_plane::well_inside(plane, pose_b, &centre, ra.hypot(hla)) {
            return super::cylinder_plane::contact(a, pose_a, pose_b, *side, work);
        }
    }
    let size_b = match b {
        SlicedSolid::Cylinder(c) => c.radius().max(0.5 * c.length()),
        SlicedSolid::Box(c) => c.half_extents().norm(),
        SlicedSolid::Plane { .. } => 0.0,
    };
    let unit = unit_for(ra.max(hla).max(size_b));
    // Everything in a's geometry frame first; the working frame is centred on a's centre.
    let pose_ab = pose_a.inv_mul(pose_b);
    let rot_ab = pose_ab.rotation.to_rotation_matrix().into_inner();
    let centre_a = Vector3::new(0.0, 0.0, hla);
    let (prism_planes, prism_count) = match b {
        SlicedSolid::Plane { plane, side } => prism(plane, *side),
        _ => (
            [HalfSpace {
                normal: Vector3::z(),
                offset: 0.0,
            }; 5],
            0,
        ),
    };
    // Parallel axes, or a box axis along the cylinder's: a prism, in closed form.
    if let Some(m) = aligned_moments(a, b, &rot_ab, &pose_ab, unit) {
        work.bounding_volume_tests += 1;
        let frame = Matrix3::identity();
        return finish(a, pose_a, b, pose_b, &m?, (&frame, &centre_a, unit), &[]);
    }
    let placed = Placed {
        ra,
        hla,
        unit,
        pose_ab,
        rot_ab,
        centre_a,
        prism_planes,
        prism_count,
    };
    if let Some(found) = tilted_closed_form(a, pose_a, b, pose_b, work, method, &placed) {
        return found;
    }
    sliced(a, pose_a, b, pose_b, work, &placed)
}

/// The pair in `a`'s geometry frame, as the closed forms and the slicing take it.
#[derive(Clone, Copy)]
struct Placed {
    /// `a`'s radius.
    ra: f64,
    /// `a`'s half-length.
    hla: f64,
    /// The working frame's length unit ([`unit_for`] the larger solid's size).
    unit: f64,
    /// `b`'s pose in `a`'s geometry frame.
    pose_ab: Isometry3,
    /// `pose_ab`'s rotation as a matrix.
    rot_ab: Matrix3,
    /// `a`'s centre in its geometry frame (the working frame's origin).
    centre_a: Vector3,
    /// A bounded plane's prism as half-spaces in the plane's frame, the first `prism_count`.
    prism_planes: [HalfSpace; 5],
    /// How many of `prism_planes` bound the prism (none for a solid `b`).
    prism_count: usize,
}

impl Placed {
    /// The bounded plane's prism planes (empty for a solid `b`).
    fn prism(&self) -> &[HalfSpace] {
        &self.prism_planes[..self.prism_count]
    }
}

/// The closed forms for a `b` at any tilt, with `method` [`Method::ClosedForm`] only: a box
/// by the divergence theorem over the intersection's boundary, a bounded plane's prism
/// likewise (its faces cut to the cylinder's reach), crossed cylinders by the divergence
/// theorem over the two lateral surfaces. `Some(found)` when one decided the pair (`found`
/// `None`: no contact); `None` when the pair is to be sliced (a face nearly parallel to the
/// axis, cylinders near parallel or only grazing).
fn tilted_closed_form(
    a: &Cylinder,
    pose_a: &Isometry3,
    b: &SlicedSolid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    method: Method,
    placed: &Placed,
) -> Option<Option<PairContact>> {
    if method != Method::ClosedForm {
        return None;
    }
    let Placed {
        ra,
        hla,
        unit,
        pose_ab,
        rot_ab,
        centre_a,
        ..
    } = *placed;
    let frame = Matrix3::identity();
    match b {
        // A box at any other tilt: the divergence theorem over the intersection's boundary,
        // in closed form, unless a face is nearly parallel to the axis.
        SlicedSolid::Box(c) => {
            let centre = (pose_ab * c.center()).coords - centre_a;
            let half = c.half_extents();
            work.bounding_volume_tests += 1;
            let box_a = (
                Vector3::zeros(),
                Matrix3::identity(),
                Vector3::new(ra, ra, hla),
            );
            if separated(&box_a, &(centre, rot_ab, half)) {
                return Some(None);
            }
            let faces = cylinder_polyhedron::box_faces(&(centre / unit), &rot_ab, &(half / unit));
            let m = cylinder_polyhedron::box_moments(ra / unit, hla / unit, &faces)?;
            Some(m.and_then(|m| finish(a, pose_a, b, pose_b, &m, (&frame, &centre_a, unit), &[])))
        }
        // A bounded plane's prism, likewise (its faces cut to the cylinder's reach).
        SlicedSolid::Plane { .. } => {
            let m = prism_moments(
                placed.prism(),
                (&rot_ab, &pose_ab.translation.vector, &centre_a),
                (ra, hla, unit),
            )?;
            work.bounding_volume_tests += 1;
            let planes = placed.prism();
            Some(
                m.and_then(|m| finish(a, pose_a, b, pose_b, &m, (&frame, &centre_a, unit), planes)),
            )
        }
        // Crossed cylinders: the divergence theorem over the two lateral surfaces, unless
        // they only graze.
        SlicedSolid::Cylinder(c) => {
            let axis = rot_ab.column(2);
            if axis.x.hypot(axis.y) >= revolved_pair::PARALLEL {
                let (a, c) = (Solid::Cylinder(*a), Solid::Cylinder(*c));
                // A grazing sliver it declines is sliced ([`sliced`]).
                if let Ok(found) = revolved_pair::divergence_contact(&a, pose_a, &c, pose_b, work) {
                    return Some(found);
                }
            }
            None
        }
    }
}

/// The slicing direction `n ⟂ ẑ` in `a`'s frame (see the module docs): across both axes for
/// a cylinder `b`, away from every face normal for a box or a bounded plane's prism
/// (`planes`, in the plane's frame; `rot_ab` maps `b`'s frame into `a`'s).
fn slicing_direction(b: &SlicedSolid, rot_ab: &Matrix3, planes: &[HalfSpace]) -> Vector3 {
    match b {
        SlicedSolid::Cylinder(_) => {
            let axis = rot_ab.column(2);
            let rho = axis.x.hypot(axis.y);
            if rho > 0.0 {
                Vector3::new(-axis.y / rho, axis.x / rho, 0.0)
            } else {
                Vector3::x()
            }
        }
        SlicedSolid::Box(_) => direction_away_from(
            &[rot_ab.column(0), rot_ab.column(1), rot_ab.column(2)].map(|c| c.into_owned()),
        ),
        SlicedSolid::Plane { .. } => {
            let mut normals = [Vector3::zeros(); 5];
            for (k, h) in planes.iter().enumerate() {
                normals[k] = rot_ab * h.normal;
            }
            direction_away_from(&normals[..planes.len()])
        }
    }
}

/// The pair sliced ([`SlicedPair`]) across [`slicing_direction`], in the working frame F:
/// axes `(n, ẑ × n, ẑ)` of `a`'s frame, origin at `a`'s centre, lengths divided by the unit;
/// `b`'s bounds and events from [`bounds`].
fn sliced(
    a: &Cylinder,
    pose_a: &Isometry3,
    b: &SlicedSolid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    placed: &Placed,
) -> Option<PairContact> {
    let Placed {
        ra,
        hla,
        unit,
        rot_ab,
        centre_a,
        ..
    } = *placed;
    let n = slicing_direction(b, &rot_ab, placed.prism());
    // Working frame F: axes (n, ẑ × n, ẑ) of a's frame, origin at a's centre, lengths / unit.
    let frame = Matrix3::from_columns(&[n, Vector3::z().cross(&n), Vector3::z()]);
    let mut pair = SlicedPair {
        radius_a: ra / unit,
        half_length_a: hla / unit,
        bounds: [Bound::Plane {
            normal: Vector3::z(),
            offset: 0.0,
        }; MAX_BOUNDS],
        bound_count: 0,
        range_b: (f64::NEG_INFINITY, f64::INFINITY),
        cuts_b: [0.0; MAX_B_CUTS],
        cut_count: 0,
    };
    // The cylinder's bounding box against b's, on the six face axes: a cheap rejection.
    let box_a = (
        Vector3::zeros(),
        Matrix3::identity(),
        Vector3::new(ra, ra, hla) / unit,
    );
    match b {
        SlicedSolid::Cylinder(c) => bounds::cylinder(&mut pair, c, &frame, &box_a, placed, work)?,
        SlicedSolid::Box(c) => bounds::cuboid(&mut pair, c, &frame, &box_a, placed, work)?,
        SlicedSolid::Plane { plane, .. } => {
            bounds::prism(&mut pair, plane, &frame, &box_a, placed, work)?
        }
    }
    let m = pair.integrate(work)?;
    finish(
        a,
        pose_a,
        b,
        pose_b,
        &m,
        (&frame, &centre_a, unit),
        placed.prism(),
    )
}

/// The moments of the cylinder (radius `ra`, half-length `hla`) against the bounded plane's
/// prism `planes` (in the plane's frame) in closed form, in the working
/// frame (`a`'s axes, origin `centre_a`, lengths divided by `unit`; `rot_ab`, `t_ab` map the
/// plane's frame into `a`'s); `None` where [`cylinder_polyhedron::box_moments`] would be.
fn prism_moments(
    planes: &[HalfSpace],
    (rot_ab, t_ab, centre_a): (&Matrix3, &Vector3, &Vector3),
    (ra, hla, unit): (f64, f64, f64),
) -> Option<Option<SlicedMoments>> {
    let reach = ra.hypot(hla) / unit;
    let to_working = |normal: &Vector3, offset: f64| {
        let n = rot_ab * normal;
        (n, (offset + n.dot(t_ab) - n.dot(centre_a)) / unit)
    };
    let mut working = [(Vector3::zeros(), 0.0); 5];
    for (w, h) in working.iter_mut().zip(planes) {
        *w = to_working(&h.normal, h.offset);
    }
    let mut faces = [cylinder_polyhedron::Face {
        normal: Vector3::zeros(),
        offset: 0.0,
        corners: [Vector3::zeros(); cylinder_polyhedron::FACE_CORNERS],
        count: 0,
    }; 5];
    let count =
        cylinder_polyhedron::half_spaces::faces(&working[..planes.len()], reach, &mut faces)?;
    cylinder_polyhedron::polyhedron_moments(ra / unit, hla / unit, &faces[..count])
}

/// The tilt below which two axes are parallel: `4ε`, the round-off of a rotation composed from
/// two poses. Within it the answer of the parallel closed form and that of the tilted pair
/// differ by about the tilt times the pair's size (the first-order change of the volume
/// cancels about the overlap's middle; the centroid, the normal and the caps move by the tilt
/// times a length): round-off of the poses themselves.
const ROUND_OFF_TILT: f64 = 4.0 * f64::EPSILON;

/// When the intersection is a prism along `a`'s axis (`b` a cylinder with its axis parallel or
/// opposite, or a box with an axis so, to [`ROUND_OFF_TILT`]), its moments in closed form in
/// the working frame (`a`'s axes, origin at `a`'s centre, lengths divided by `unit`):
/// `Some(None)` when they do not overlap. `None` for any other pose, which is sliced.
fn aligned_moments(
    a: &Cylinder,
    b: &SlicedSolid,
    rot_ab: &Matrix3,
    pose_ab: &Isometry3,
    unit: f64,
) -> Option<Option<SlicedMoments>> {
    let (ra, la) = (a.radius() / unit, a.length() / unit);
    let along =
        |k: usize| rot_ab[(0, k)].abs() <= ROUND_OFF_TILT && rot_ab[(1, k)].abs() <= ROUND_OFF_TILT;
    match b {
        SlicedSolid::Cylinder(c) if along(2) => {
            // b's frame has its origin on the bottom cap's centre, as a's does.
            let origin = pose_ab.translation.vector;
            let lb = c.length();
            let range = if rot_ab[(2, 2)] > 0.0 {
                (origin.z, origin.z + lb)
            } else {
                (origin.z - lb, origin.z)
            };
            let other = ParallelB {
                centre: Vector2::new(origin.x, origin.y) / unit,
                radius: c.radius() / unit,
                range: (range.0 / unit, range.1 / unit),
            };
            Some(cylinder_parallel::moments(ra, la, &other))
        }
        SlicedSolid::Box(c) => {
            let k = (0..3).find(|&k| along(k))?;
            let centre = pose_ab * c.center();
            let half = c.half_extents();
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            let u = Vector2::new(rot_ab[(0, i)], rot_ab[(1, i)]) * half[i];
            let v = Vector2::new(rot_ab[(0, j)], rot_ab[(1, j)]) * half[j];
            let middle = Vector2::new(centre.x, centre.y);
            // Counter-clockwise seen from +z: (i, j, k) is right-handed, so u × v has the sign
            // of the k axis' z.
            let mut corners = [
                middle + u + v,
                middle - u + v,
                middle - u - v,
                middle + u - v,
            ];
            if rot_ab[(2, k)] < 0.0 {
                corners.reverse();
            }
            let prism = Prism {
                corners: corners.map(|p| p / unit),
                range: ((centre.z - half[k]) / unit, (centre.z + half[k]) / unit),
            };
            Some(cylinder_prism::moments(ra, la, &prism))
        }
        _ => None,
    }
}

/// The contact from the intersection's moments `m` in the working frame (`frame`'s columns in
/// `a`'s axes, origin `centre_a`, lengths divided by `unit`), by [`volume_contact`]; `planes`
/// bound the bounded plane's prism (empty for a solid `b`).
fn finish(
    a: &Cylinder,
    pose_a: &Isometry3,
    b: &SlicedSolid,
    pose_b: &Isometry3,
    m: &SlicedMoments,
    (frame, centre_a, unit): (&Matrix3, &Vector3, f64),
    planes: &[HalfSpace],
) -> Option<PairContact> {
    // Back to the world.
    let rot_a = pose_a.rotation.to_rotation_matrix().into_inner() * frame;
    let centroid = Point3::from(
        pose_a.translation.vector + pose_a.rotation * centre_a + rot_a * m.centroid * unit,
    );
    let moments = VolumeMoments {
        volume: m.volume * unit * unit * unit,
        centroid,
        area_vector_a: rot_a * m.area_vector_a * (unit * unit),
        surface_area: (m.area_a + m.area_b) * unit * unit,
        length: unit,
    };
    let solid_a = Solid::Cylinder(*a);
    let exit_a = |g: &Point3, d: &Vector3| surface_point_along_w(&solid_a, pose_a, g, d);
    let solid_b = match b {
        SlicedSolid::Cylinder(c) => Some(Solid::Cylinder(*c)),
        SlicedSolid::Box(c) => Some(Solid::Box(*c)),
        SlicedSolid::Plane { .. } => None,
    };
    let exit_b = |g: &Point3, d: &Vector3| {
        let p = pose_b.inverse_transform_point(g);
        let dir = pose_b.inverse_transform_vector(d);
        let local = match &solid_b {
            Some(s) => surface_point_along(s, &p.coords, &dir),
            None => p.coords + ray_exit(&p, &dir, planes) * dir,
        };
        pose_b * Point3::from(local)
    };
    let a_inside_b = m.area_b <= ENCLOSED * (m.area_a + m.area_b);
    let fallback = || {
        if a_inside_b {
            let p = pose_b.inverse_transform_point(&centroid);
            let outward = match &solid_b {
                Some(s) => signed_distance(s, &p.coords).2,
                None => nearest_face(&p, planes).1,
            };
            pose_b.rotation * outward
        } else {
            let p = pose_a.inverse_transform_point(&centroid);
            -(pose_a.rotation * signed_distance(&solid_a, &p.coords).2)
        }
    };
    volume_contact::contact(&moments, exit_a, exit_b, fallback)
}

/// A box as (centre, unit axes as columns, half extents).
type Obb = (Vector3, Matrix3, Vector3);

/// True when a face axis of either box separates them.
fn separated(a: &Obb, b: &Obb) -> bool {
    let (ca, ra, ha) = a;
    let (cb, rb, hb) = b;
    let d = cb - ca;
    let project = |axis: &Vector3, r: &Matrix3, h: &Vector3| {
        (0..3)
            .map(|k| h[k] * r.column(k).dot(axis).abs())
            .sum::<f64>()
    };
    (0..3).any(|k| {
        let axis = ra.column(k).into_owned();
        d.dot(&axis).abs() >= ha[k] + project(&axis, rb, hb)
    }) || (0..3).any(|k| {
        let axis = rb.column(k).into_owned();
        d.dot(&axis).abs() >= hb[k] + project(&axis, ra, ha)
    })
}
