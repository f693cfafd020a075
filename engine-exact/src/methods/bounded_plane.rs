//! A bounded PLANE seen by one body as a box: the plane's solid is the prism `z ≤ 0` (or
//! `z ≥ 0` flipped) over the rectangle `[xmin, xmax] × [ymin, ymax]` of its frame, and a body
//! that fits in a ball of radius `reach` about `c` meets only the part of that prism within
//! `reach` of `c`. So the prism is cut, per query, to a finite box about `c` whose added faces
//! lie at least `R = 4·reach + 2|c_z|` from `c`:
//! - the body never reaches an added face (`R > reach`), so the intersection — volume,
//!   centroid, the body's surface inside — is the prism's, bit for bit the same geometry;
//! - a point at `c` inside the prism is nearer its top face (`|c_z|` away) than any added face
//!   (`≥ R`), so a signed-distance answer never picks an added face either;
//! - the box stays within a few `reach` of the body, so its size, not the plane's (which may be
//!   infinite), sets the working precision.
//!
//! When the rectangle lies farther than `R` from `c` in x or y the body cannot touch it: `None`.
//!
//! When instead the ball lies well inside the rectangle (`well_inside`: every wall farther
//! from each of its points than the plane itself), the prism meets the body as the half-space
//! does, and the pairs answer with their unbounded-plane closed forms.

use contact_core::geometry::{Cuboid, Plane};
use contact_core::{Isometry3, Point3};
use nalgebra::Translation3;

/// The finite box (and its pose `X_WB`) that stands for `plane` (its solid on the `side`: +1
/// below `z = 0`, −1 above) at `pose_plane`, for a body within `reach` of the world point
/// `centre`; `None` when the body cannot touch the plane's rectangle.
pub(crate) fn local_box(
    plane: &Plane,
    side: f64,
    pose_plane: &Isometry3,
    centre: &Point3,
    reach: f64,
) -> Option<(Cuboid, Isometry3)> {
    let c = pose_plane.inverse_transform_point(centre);
    let margin = 4.0 * reach + 2.0 * c.z.abs();
    let clamp = |[lo, hi]: [f64; 2], at: f64| -> Option<(f64, f64)> {
        let (lo, hi) = (lo.max(at - margin), hi.min(at + margin));
        (lo < hi).then_some((lo, hi))
    };
    let (x0, x1) = clamp(plane.x_range(), c.x)?;
    let (y0, y1) = clamp(plane.y_range(), c.y)?;
    let (z0, z1) = if side > 0.0 {
        (c.z.min(0.0) - margin, 0.0)
    } else {
        (0.0, c.z.max(0.0) + margin)
    };
    let half = |lo: f64, hi: f64| 0.5 * (hi - lo);
    let cuboid = Cuboid::centered(half(x0, x1), half(y0, y1), half(z0, z1)).ok()?;
    let middle = Translation3::new(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1));
    Some((cuboid, pose_plane * middle))
}

/// Whether a body within `reach` of the world point `centre` meets `plane`'s prism (at
/// `pose_plane`) exactly as it meets the half-space: each wall lies farther than
/// `|c_z| + 2·reach` from `c` (`c` the centre in the plane's frame), so no point of the body
/// reaches a wall, every point of it is nearer the plane than any wall (a containment's
/// nearest face is the plane's) and a line from it along the plane's normal leaves the prism
/// through the plane. Then the intersection, its centroid, the points along the normal and
/// the normal are the half-space's: the bounded pairs may take the unbounded plane's answer.
pub(crate) fn well_inside(
    plane: &Plane,
    pose_plane: &Isometry3,
    centre: &Point3,
    reach: f64,
) -> bool {
    let c = pose_plane.inverse_transform_point(centre);
    let clearance = c.z.abs() + 2.0 * reach;
    let [x0, x1] = plane.x_range();
    let [y0, y1] = plane.y_range();
    c.x - x0 > clearance && x1 - c.x > clearance && c.y - y0 > clearance && y1 - c.y > clearance
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::PairContact;
    use crate::methods::solid_distance::Solid;
    use crate::pairs::cylinder_sliced::{self, SlicedSolid};
    use crate::pairs::{cylinder_plane, ellipsoid_box, ellipsoid_plane, revolved_plane};
    use contact_core::geometry::{Cylinder, Frustum, Torus};
    use contact_core::{UnitQuaternion, Vector3, WorkCounters};

    /// The worst errors (depth, normal, points, area) of the contacts compared with the
    /// half-space's, and how many were compared.
    #[derive(Default)]
    struct Tally {
        worst: [f64; 4],
        compared: usize,
    }

    impl Tally {
        /// Compares `got` with the half-space's `want` at the length scale `size`; when
        /// either is none, both must be (placement `k`).
        fn one(
            &mut self,
            k: usize,
            got: Option<PairContact>,
            want: Option<PairContact>,
            size: f64,
        ) {
            if let (Some(g), Some(w)) = (got, want) {
                let e = g.errors(&w, size);

                for (worst, e) in self.worst.iter_mut().zip(e) {
                    *worst = worst.max(e);
                }
                self.compared += 1;
            } else {
                assert_eq!(got.is_some(), want.is_some(), "{k}: {got:?} {want:?}");
            }
        }
    }

    /// The plane of [`well_inside_the_prism_is_the_half_space`] and its pose.
    fn wide_plane() -> (Plane, Isometry3) {
        let plane = Plane::bounded(-10.0, 12.0, -9.0, 11.0).unwrap();
        let pose_plane = Isometry3::new(Vector3::new(0.3, -0.2, 0.5), Vector3::new(0.2, -0.1, 0.3));
        (plane, pose_plane)
    }

    /// Placement `k` of 40 over the plane: the side, the tilt and the depth a body sinks by.
    struct Placement {
        k: usize,
        side: f64,
        tilt: UnitQuaternion,
        depth: f64,
        pose_plane: Isometry3,
    }

    impl Placement {
        fn new(k: usize, pose_plane: Isometry3) -> Self {
            let f = k as f64;
            Self {
                k,
                side: if k.is_multiple_of(2) { 1.0 } else { -1.0 },
                tilt: UnitQuaternion::from_euler_angles(0.3 + 0.07 * f, 0.9 - 0.05 * f, 0.11 * f),
                depth: 0.05 + 0.03 * f,
                pose_plane,
            }
        }

        /// The pose of a body reaching `reach` from its centre: the centre above (below,
        /// flipped) the plane by less than the body's reach.
        fn at(&self, reach: f64) -> Isometry3 {
            let f = self.k as f64;
            let local = Point3::new(
                1.0 - 0.1 * f,
                0.5 + 0.05 * f,
                self.side * (reach - self.depth),
            );
            Isometry3::from_parts(
                (self.pose_plane * local).coords.into(),
                self.pose_plane.rotation * self.tilt,
            )
        }
    }

    /// A body well inside the rectangle: the prism's answer (slicing, clipping, or the
    /// ellipsoid–box and sphere–box pairs on the local box) is the half-space's closed form,
    /// for a cylinder, a frustum, a torus, an ellipsoid, a sphere and a mesh at tilts and
    /// depths across their range, either side.
    #[test]
    fn well_inside_the_prism_is_the_half_space() {
        let (plane, pose_plane) = wide_plane();
        let mut tally = Tally::default();
        for k in 0..40 {
            let at = Placement::new(k, pose_plane);
            let mut work = WorkCounters::default();
            cylinder_well_inside(&at, &plane, &mut tally, &mut work);
            revolved_well_inside(&at, &plane, &mut tally, &mut work);
            ellipsoid_well_inside(&at, &plane, &mut tally, &mut work);
            sphere_well_inside(&at, &plane, &mut tally, &mut work);
        }
        mesh_well_inside(&plane, &pose_plane, &mut tally);
        let Tally { worst, compared } = tally;
        assert!(compared > 100, "{compared}");
        // Measured over 220 contacts: 7.4e-15 (depth), 7.0e-15 (normal), 1.2e-14 (points),
        // 8.3e-15 (area).
        assert!(worst.iter().all(|&e| e <= 1e-12), "{worst:?}");
    }

    /// The cylinder, sliced on the prism, against the unbounded plane's closed form.
    fn cylinder_well_inside(
        at: &Placement,
        plane: &Plane,
        tally: &mut Tally,
        work: &mut WorkCounters,
    ) {
        let (k, side, pose_plane) = (at.k, at.side, at.pose_plane);
        // Cylinder (frame at its bottom: the centre is half its length up the axis).
        let cylinder = Cylinder::new(0.6, 1.4).unwrap();
        let reach = 0.6f64.hypot(0.7);
        let centred = at.at(0.7);
        let pose = centred * Isometry3::translation(0.0, 0.0, -0.7);
        assert!(well_inside(
            plane,
            &pose_plane,
            &(pose * Point3::new(0.0, 0.0, 0.7)),
            reach
        ));
        let sliced = cylinder_sliced::contact_by(
            &cylinder,
            &pose,
            &SlicedSolid::Plane {
                plane: *plane,
                side,
            },
            &pose_plane,
            work,
            cylinder_sliced::Method::Sliced,
        );
        tally.one(
            k,
            sliced,
            cylinder_plane::contact(&cylinder, &pose, &pose_plane, side, work),
            1.4,
        );
    }

    /// The frustum and the torus: the box–revolved pair on the prism.
    fn revolved_well_inside(
        at: &Placement,
        plane: &Plane,
        tally: &mut Tally,
        work: &mut WorkCounters,
    ) {
        let (k, side, pose_plane) = (at.k, at.side, at.pose_plane);
        // Frustum and torus: the box–revolved pair on the prism.
        for (solid, middle, size) in [
            (
                Solid::Frustum(Frustum::new(0.8, 0.3, 1.2).unwrap()),
                0.6,
                1.2,
            ),
            (Solid::Torus(Torus::new(1.0, 0.3).unwrap()), 0.0, 1.3),
        ] {
            let pose = at.at(0.6) * Isometry3::translation(0.0, 0.0, -middle);
            let mut found = Vec::new();
            crate::pairs::revolved_bounded_plane::prism_contacts(
                &solid,
                &pose,
                plane,
                side,
                &pose_plane,
                work,
                &mut |c| found.push(c),
            );
            let want = revolved_plane::contact(&solid, &pose, &pose_plane, side, work);
            if found.len() == 1 {
                tally.one(k, Some(found[0]), want, size);
            } else {
                assert!(
                    found.is_empty() && want.is_none(),
                    "{k}: {found:?} {want:?}"
                );
            }
        }
    }

    /// The ellipsoid: the ellipsoid–box pair on the local box, its centre on the plane's free
    /// side (below, the two pairs' area estimates differ by design).
    fn ellipsoid_well_inside(
        at: &Placement,
        plane: &Plane,
        tally: &mut Tally,
        work: &mut WorkCounters,
    ) {
        let (k, side, pose_plane, depth) = (at.k, at.side, at.pose_plane, at.depth);
        let f = k as f64;
        let semi = Vector3::new(0.9, 0.5, 0.4);
        let pose = at.at(depth + 0.35 - 0.008 * f);
        let centre = Point3::from(pose.translation.vector);
        let boxed = local_box(plane, side, &pose_plane, &centre, semi.max()).and_then(
            |(cuboid, pose_box)| ellipsoid_box::contact(&semi, &pose, &cuboid, &pose_box, work),
        );
        tally.one(
            k,
            boxed,
            ellipsoid_plane::contact(&semi, &pose, &pose_plane, side),
            0.9,
        );
    }

    /// The sphere: the sphere–box pair on the local box, its centre on the free side.
    fn sphere_well_inside(
        at: &Placement,
        plane: &Plane,
        tally: &mut Tally,
        work: &mut WorkCounters,
    ) {
        let (k, side, pose_plane, depth) = (at.k, at.side, at.pose_plane, at.depth);
        let radius = 0.45;
        let pose = at.at(depth.min(0.4) + 0.02);
        let centre = Point3::from(pose.translation.vector);
        let boxed =
            local_box(plane, side, &pose_plane, &centre, radius).and_then(|(cuboid, pose_box)| {
                let solid = crate::pairs::sphere_solid::Solid::Box(cuboid);
                crate::pairs::sphere_solid::contact(radius, &pose, &solid, &pose_box, work)
            });
        // With the centre below the plane the sphere–plane pair reports `π r²`, the
        // sphere–box pair `|S| = π(r² − d²)` while the ball crosses the plane (and a
        // quarter of its surface, `π r²` again, once immersed): the area estimates differ
        // by convention.
        let height = depth.min(0.4) + 0.02 - depth;
        let half_space =
            crate::pairs::sphere_plane::contact(radius, &pose, &pose_plane, side).map(|w| {
                PairContact {
                    area: if height < 0.0 && height > -radius {
                        std::f64::consts::PI * (radius - height) * (radius + height)
                    } else {
                        w.area
                    },
                    ..w
                }
            });
        tally.one(k, boxed, half_space, 0.45);
    }

    /// A mesh (a box of 12 triangles): the box–mesh pair on the prism, each region against
    /// the mesh–plane pair's.
    fn mesh_well_inside(plane: &Plane, pose_plane: &Isometry3, tally: &mut Tally) {
        let cuboid = contact_core::geometry::Cuboid::centered(0.7, 0.4, 0.5).unwrap();
        let mesh = crate::pairs::box_mesh::box_mesh(&cuboid).unwrap();
        for k in 0..20 {
            let f = k as f64;
            let side = if k % 2 == 0 { 1.0 } else { -1.0 };
            let tilt = UnitQuaternion::from_euler_angles(0.5 + 0.1 * f, 0.2 - 0.05 * f, 0.13 * f);
            let local = Point3::new(0.5, -1.0 + 0.1 * f, side * (0.6 - 0.04 * f));
            let pose = Isometry3::from_parts(
                (pose_plane * local).coords.into(),
                pose_plane.rotation * tilt,
            );
            let mut work = WorkCounters::default();
            let (mut prism, mut half) = (Vec::new(), Vec::new());
            crate::pairs::mesh_bounded_plane::prism_contacts(
                &mesh,
                &pose,
                plane,
                side,
                pose_plane,
                &mut work,
                &mut |c| prism.push(c),
            );
            crate::pairs::mesh_plane::contacts(
                &mesh,
                &pose,
                pose_plane,
                side,
                &mut work,
                &mut |c| half.push(c),
            );
            assert_eq!(prism.len(), half.len(), "{k}");
            for (g, w) in prism.iter().zip(&half) {
                let e = g.errors(w, 1.4);
                assert!(e[3] <= 1e-9, "mesh {k}: {g:?} {w:?}");
                for (worst, e) in tally.worst.iter_mut().zip(e) {
                    *worst = worst.max(e);
                }
                tally.compared += 1;
            }
        }
    }

    /// A ball reaching within `|c_z| + 2·reach` of a wall is not well inside.
    #[test]
    fn near_a_wall_is_not_well_inside() {
        let plane = Plane::bounded(-1.0, 1.0, f64::NEG_INFINITY, f64::INFINITY).unwrap();
        let id = Isometry3::identity();
        assert!(well_inside(&plane, &id, &Point3::new(0.0, 5.0, 0.1), 0.4));
        assert!(!well_inside(&plane, &id, &Point3::new(0.0, 5.0, 0.1), 0.46));
        assert!(!well_inside(&plane, &id, &Point3::new(0.2, 0.0, 0.1), 0.4));
    }
}
