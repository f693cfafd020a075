//! 2-D contacts held in one plane (SPEC §3): the check that stops a run when a part of a 2-D
//! contact leaves the plane, naming the contact, the part and the time.
//!
//! A 2-D geometry (point, line, circle, arc, curve) lies in the x-y plane of its marker. A 2-D
//! contact needs the I part's plane and the J part's plane to coincide; the plane of each part
//! is that of the first geometry of its list (all geometries of a list share a part, and 2-D
//! lists are drawn in one plane). The planes coincide when the angle between their normals
//! (either orientation) is at most [`PLANE_ANGLE_TOLERANCE`] rad and the I plane's origin is
//! within `PLANE_OFFSET_TOLERANCE · L` of the J plane, with `L` the larger of the pair's length
//! scale and the distance of the planes' origins from the world origin (round-off in a pose
//! grows with its coordinates, and the solver's difference Jacobian moves a part by
//! `√ε·max(|r|, L)`, well inside this band). These are the exact engine's tolerances, so both
//! engines stop at the same state; the faceted engine would otherwise answer silently on
//! polylines out of plane.
//!
//! **Which part left.** The planes of both parts are recorded at the start and after every
//! accepted step ([`PlanarGuard::record`]); when the check fails, the part whose plane moved
//! further from its recorded plane (tilt in rad plus offset over `L`) is named. A ground part
//! never moves, so the other part is named.
//!
//! The failure is an [`EvaluationError`] marked fatal: no smaller step can bring a part back
//! into its plane, so the integrator stops at once and the run keeps its output.

use crate::dae::EvaluationError;
use contact_core::{Isometry3, Vector3};
pub use engine_exact::planar::{PLANE_ANGLE_TOLERANCE, PLANE_OFFSET_TOLERANCE};
use std::sync::Mutex;

/// A plane in the world: unit normal and a point (the marker origin).
#[derive(Debug, Clone, Copy, PartialEq)]
struct PlaneW {
    normal: Vector3,
    origin: Vector3,
}

impl PlaneW {
    fn of(pose_w_part: &Isometry3, pose_part_geometry: &Isometry3) -> Self {
        let pose = pose_w_part * pose_part_geometry;
        Self {
            normal: pose.rotation * Vector3::z(),
            origin: pose.translation.vector,
        }
    }

    /// The angle between the two planes' normals, either orientation, in [0, π/2].
    fn angle_to(&self, other: &Self) -> f64 {
        self.normal
            .cross(&other.normal)
            .norm()
            .atan2(self.normal.dot(&other.normal).abs())
    }

    /// The signed distance of `point` from this plane.
    fn offset_of(&self, point: &Vector3) -> f64 {
        (point - self.origin).dot(&self.normal)
    }
}

/// The plane check of one 2-D CONTACT.
#[derive(Debug)]
pub struct PlanarGuard {
    pose_part_geometry: [Isometry3; 2],
    part_names: [String; 2],
    grounded: [bool; 2],
    length: f64,
    recorded: Mutex<Option<[PlaneW; 2]>>,
}

/// How far the two planes of a 2-D contact are apart.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlaneMismatch {
    /// Angle between the normals (rad).
    pub angle_rad: f64,
    /// Distance of the I plane's origin from the J plane.
    pub offset: f64,
    /// The offset allowed (`PLANE_OFFSET_TOLERANCE · L`).
    pub offset_tolerance: f64,
}

impl PlanarGuard {
    /// The check for a 2-D contact whose I geometry sits at `pose_part_geometry[0]` in the I
    /// part's frame (the frame its pose is given in) and J geometry at `[1]` in the J part's;
    /// `part_names` name the parts in messages (e.g. `PART/2`), `grounded` says which is the
    /// ground, `length` is the pair's length scale (> 0; a non-positive or non-finite value is
    /// replaced by 1 model unit).
    pub fn new(
        pose_part_geometry: [Isometry3; 2],
        part_names: [String; 2],
        grounded: [bool; 2],
        length: f64,
    ) -> Self {
        let length = if length.is_finite() && length > 0.0 {
            length
        } else {
            1.0
        };
        Self {
            pose_part_geometry,
            part_names,
            grounded,
            length,
            recorded: Mutex::new(None),
        }
    }

    fn planes(&self, pose_w_i: &Isometry3, pose_w_j: &Isometry3) -> [PlaneW; 2] {
        [
            PlaneW::of(pose_w_i, &self.pose_part_geometry[0]),
            PlaneW::of(pose_w_j, &self.pose_part_geometry[1]),
        ]
    }

    /// Whether the planes at these poses coincide; otherwise by how much they differ.
    pub fn mismatch(&self, pose_w_i: &Isometry3, pose_w_j: &Isometry3) -> Option<PlaneMismatch> {
        let [i, j] = self.planes(pose_w_i, pose_w_j);
        let angle_rad = i.angle_to(&j);
        let offset = j.offset_of(&i.origin);
        let scale = self.length.max(i.origin.norm()).max(j.origin.norm());
        let offset_tolerance = PLANE_OFFSET_TOLERANCE * scale;
        let apart = !(angle_rad <= PLANE_ANGLE_TOLERANCE && offset.abs() <= offset_tolerance);
        apart.then_some(PlaneMismatch {
            angle_rad,
            offset,
            offset_tolerance,
        })
    }

    /// Records the planes at an accepted state: the reference for naming the part that left.
    pub fn record(&self, pose_w_i: &Isometry3, pose_w_j: &Isometry3) {
        if let Ok(mut recorded) = self.recorded.lock() {
            *recorded = Some(self.planes(pose_w_i, pose_w_j));
        }
    }

    /// The part that left its plane: the one whose plane moved further from its recorded
    /// plane; both names if nothing was recorded and neither is the ground.
    fn part_that_left(&self, pose_w_i: &Isometry3, pose_w_j: &Isometry3) -> String {
        match self.grounded {
            [true, false] => return self.part_names[1].clone(),
            [false, true] => return self.part_names[0].clone(),
            _ => {}
        }
        let recorded = self.recorded.lock().ok().and_then(|r| *r);
        let Some(before) = recorded else {
            return format!("{} or {}", self.part_names[0], self.part_names[1]);
        };
        let now = self.planes(pose_w_i, pose_w_j);
        let moved = |k: usize| {
            now[k].angle_to(&before[k]) + before[k].offset_of(&now[k].origin).abs() / self.length
        };
        if moved(0) >= moved(1) {
            self.part_names[0].clone()
        } else {
            self.part_names[1].clone()
        }
    }

    /// `Ok` when the planes coincide at these poses; otherwise a fatal [`EvaluationError`] of
    /// element `contact` naming the part that left the plane and the time `t`.
    pub fn check(
        &self,
        contact: &str,
        t: f64,
        pose_w_i: &Isometry3,
        pose_w_j: &Isometry3,
    ) -> Result<(), EvaluationError> {
        let Some(m) = self.mismatch(pose_w_i, pose_w_j) else {
            return Ok(());
        };
        let part = self.part_that_left(pose_w_i, pose_w_j);
        Err(EvaluationError {
            element: contact.to_owned(),
            message: format!(
                "{part} left the plane of this 2-D contact at t = {t:?}: the planes are {:e} rad \
                 apart (tolerance {PLANE_ANGLE_TOLERANCE:e}) and offset by {:e} (tolerance \
                 {:e}); a 2-D contact needs both parts held in one plane (a PLANAR joint or \
                 INPLANE/ORIENTATION primitives)",
                m.angle_rad, m.offset, m.offset_tolerance
            ),
            fatal: true,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Translation3, UnitQuaternion};

    fn guard(grounded: [bool; 2]) -> PlanarGuard {
        PlanarGuard::new(
            [
                Isometry3::identity(),
                Isometry3::translation(0.0, -1.0, 0.0),
            ],
            ["PART/2".into(), "PART/3".into()],
            grounded,
            2.0,
        )
    }

    fn tilted(angle: f64, z: f64) -> Isometry3 {
        Isometry3::from_parts(
            Translation3::new(0.5, 0.0, z),
            UnitQuaternion::from_scaled_axis(Vector3::x() * angle),
        )
    }

    #[test]
    fn in_plane_motion_passes() {
        let g = guard([false, false]);
        let spun = Isometry3::from_parts(
            Translation3::new(3.0, -2.0, 0.0),
            UnitQuaternion::from_scaled_axis(Vector3::z() * 2.0),
        );
        assert!(g.mismatch(&spun, &Isometry3::identity()).is_none());
        assert!(
            g.check("CONTACT/1", 0.0, &spun, &Isometry3::identity())
                .is_ok()
        );
    }

    #[test]
    fn a_tilt_or_an_offset_past_tolerance_is_a_fatal_error_naming_the_moved_part() {
        let g = guard([false, false]);
        g.record(&Isometry3::identity(), &Isometry3::identity());
        // Angle just under the tolerance passes, just over fails.
        assert!(
            g.mismatch(&tilted(0.9e-6, 0.0), &Isometry3::identity())
                .is_none()
        );
        let m = g
            .mismatch(&tilted(2e-6, 0.0), &Isometry3::identity())
            .unwrap();
        assert!((m.angle_rad - 2e-6).abs() < 1e-15, "{m:?}");
        // Offset: L = max(2, |origin| ≈ 0.5) = 2, tolerance 2e-6.
        assert!(
            g.mismatch(&tilted(0.0, 1.9e-6), &Isometry3::identity())
                .is_none()
        );
        let err = g
            .check(
                "CONTACT/7",
                0.25,
                &Isometry3::identity(),
                &tilted(0.0, 3e-6),
            )
            .unwrap_err();
        assert!(err.fatal);
        assert_eq!(err.element, "CONTACT/7");
        assert!(err.message.contains("PART/3 left the plane"), "{err}");
        assert!(err.message.contains("t = 0.25"), "{err}");
    }

    #[test]
    fn the_moving_part_is_named_against_the_ground_and_without_a_record() {
        let moved = tilted(1e-3, 0.0);
        let err = guard([true, false])
            .check("CONTACT/1", 1.0, &Isometry3::identity(), &moved)
            .unwrap_err();
        assert!(err.message.starts_with("PART/3 left"), "{err}");
        let err = guard([false, false])
            .check("CONTACT/1", 1.0, &Isometry3::identity(), &moved)
            .unwrap_err();
        assert!(err.message.starts_with("PART/2 or PART/3 left"), "{err}");
    }
}
