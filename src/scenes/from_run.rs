//! Scenes from a model's own motion: each CONTACT's poses are where it touched in a reference
//! run ([`crate::tradeoff::record_run`]), so the trade measures the pairs at the depths,
//! angles and places the model really reaches.
//!
//! # The poses of a contact
//! - The reference run's frames where the contact touches (at least one contact point), in
//!   time order. When there are more than `max_poses` of them, `max_poses` are taken evenly
//!   spread over them (the first and the last included), so the whole run is sampled.
//! - Then one *spread* pose per sampled pose, seeded by the contact's id: I is moved along the
//!   recorded normal by a uniform fraction in [−1, 1] of the recorded depth (from just touching
//!   to twice as deep) and turned by up to [`SPREAD_TILT_DEG`] about the recorded contact point
//!   (about a random axis; for a 2-D contact about the normal of its plane of motion).
//!
//! A pose's `nominal_depth` is the run's deepest penetration there (for a spread pose, that
//! depth plus its shift); it only labels the pose, the reference answer is the exact engine's.
//! The geometry and the contact's size are [`super::from_model`]'s.
//!
//! A contact that never touched in the reference run has no poses: it is listed in
//! [`RunScenes::untouched`] and never measured, so it can never read as error 0.

use super::{Scene, ScenePose, SplitMix64, from_model};
use crate::model::{ContactDimension, Model};
use crate::scenes::ModelSceneError;
use crate::tradeoff::{RunRecord, TouchingPose};
use contact_core::{Isometry3, UnitQuaternion, Vector3};
use nalgebra::Translation3;

/// The default number of poses sampled per contact from the reference run.
pub const RUN_POSES_PER_CONTACT: usize = 50;

/// The largest turn of I in a spread pose, degrees.
pub const SPREAD_TILT_DEG: f64 = 1.0;

/// A model's contacts as scenes at the poses of a reference run.
#[derive(Debug, Clone)]
pub struct RunScenes {
    /// The contacts that touched, each with its sampled and spread poses, in model order.
    pub scenes: Vec<Scene>,
    /// The contacts (`CONTACT/id`) that never touched in the reference run.
    pub untouched: Vec<String>,
}

/// One scene per CONTACT of `model` that touched in `run` (recorded on that model), at up to
/// `max_poses` of its touching frames plus as many spread poses (see the module docs).
pub fn from_run(
    model: &Model,
    run: &RunRecord,
    max_poses: usize,
) -> Result<RunScenes, ModelSceneError> {
    let mut out = RunScenes {
        scenes: Vec::new(),
        untouched: Vec::new(),
    };
    for (k, (mut scene, c)) in from_model(model)?
        .into_iter()
        .zip(&model.contacts)
        .enumerate()
    {
        let touching = run.touching.get(k).map_or(&[][..], Vec::as_slice);
        let sampled = spread_evenly(touching, max_poses);
        if sampled.is_empty() {
            out.untouched.push(scene.name.to_string());
            continue;
        }
        let plane_normal = (c.dimension == ContactDimension::TwoD).then(|| {
            scene.j.first().map_or_else(Vector3::z, |g| {
                (sampled[0].pose_world_j * g.pose_part_geometry) * Vector3::z()
            })
        });
        let mut rng = SplitMix64::new(u64::from(c.id).wrapping_mul(0xd1b5_4a32_d192_ed03));
        scene.description = format!(
            "{}: the dataset's contact at {}, at {} poses of the {} run",
            c.origin,
            model.title,
            sampled.len(),
            run.setting.describe()
        )
        .into();
        scene.poses = sampled
            .iter()
            .map(|p| ScenePose {
                nominal_depth: p.penetration,
                pose_world_i: p.pose_world_i,
                pose_world_j: p.pose_world_j,
            })
            .collect();
        for p in &sampled {
            let shift = rng.range(-1.0, 1.0) * p.penetration;
            let axis = plane_normal.unwrap_or_else(|| rng.unit_vector());
            let angle = rng.range(-SPREAD_TILT_DEG, SPREAD_TILT_DEG).to_radians();
            let turn = UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_normalize(axis), angle);
            // Turn about the contact point, then move against the normal (deeper for shift > 0).
            let about = p.point_w.coords;
            let turned = Isometry3::from_parts(
                Translation3::from(about - turn * about - p.normal_w * shift),
                turn,
            ) * p.pose_world_i;
            scene.poses.push(ScenePose {
                nominal_depth: p.penetration + shift,
                pose_world_i: turned,
                pose_world_j: p.pose_world_j,
            });
        }
        out.scenes.push(scene);
    }
    Ok(out)
}

/// Up to `n` of `all`, evenly spread over it (the first and the last included).
fn spread_evenly(all: &[TouchingPose], n: usize) -> Vec<TouchingPose> {
    if all.len() <= n {
        return all.to_vec();
    }
    match n {
        0 => Vec::new(),
        1 => vec![all[0]],
        _ => (0..n)
            .map(|k| all[(k * (all.len() - 1) + (n - 1) / 2) / (n - 1)])
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::{Point3, Vector3};

    fn pose(t: f64) -> TouchingPose {
        TouchingPose {
            t,
            pose_world_i: Isometry3::identity(),
            pose_world_j: Isometry3::identity(),
            penetration: 1e-3,
            penetration_rate: 0.0,
            normal_w: Vector3::z(),
            point_w: Point3::origin(),
        }
    }

    #[test]
    fn sampling_spreads_over_the_whole_run() {
        let all: Vec<_> = (0..1000).map(|k| pose(f64::from(k))).collect();
        let picked = spread_evenly(&all, 50);
        assert_eq!(picked.len(), 50);
        assert_eq!(picked[0].t, 0.0);
        assert_eq!(picked[49].t, 999.0);
        assert!(picked.windows(2).all(|w| w[1].t - w[0].t > 19.0));
        assert_eq!(spread_evenly(&all[..7], 50).len(), 7);
        assert!(spread_evenly(&all, 0).is_empty());
    }
}
