//! Running a model with one engine setting and recording what the trade needs: every output
//! frame's part poses, each CONTACT's resultant force, and the relative poses of each
//! CONTACT's two parts at every frame where it touches.
//!
//! The *reference run* is the run every other setting is compared with: the exact engine where
//! it answers every contact of the model ([`reference_setting`]), else the faceted engine at
//! the finest tolerance of the sweep. Its touching poses are where the per-query sweep
//! measures ([`crate::scenes::from_run`]); its trajectory is what whole runs are held to
//! ([`super::compare_runs`]).

use crate::model::Model;
use crate::scenes::Scene;
use crate::session::{RunError, RunLayout, RunOptions, RunSink, run_model};
use contact_core::{
    FacetingTolerance, GeometryEngine, GeometryLibrary, Isometry3, Point3, Vector3,
};
use contact_solver::simulate::Frame;
use serde::Serialize;
use std::path::Path;

/// One candidate of the trade: an engine and, for the faceted engine, its tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Setting {
    /// The engine.
    #[serde(serialize_with = "library_name")]
    pub engine: GeometryLibrary,
    /// The model-wide faceting tolerance, for the faceted engine (`None` for the exact one).
    pub faceting_tolerance: Option<f64>,
}

fn library_name<S: serde::Serializer>(l: &GeometryLibrary, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(l.name())
}

impl Setting {
    /// The exact engine.
    pub const EXACT: Setting = Setting {
        engine: GeometryLibrary::Exact,
        faceting_tolerance: None,
    };

    /// The faceted engine at `tolerance`.
    pub fn faceted(tolerance: FacetingTolerance) -> Self {
        Self {
            engine: GeometryLibrary::Faceted,
            faceting_tolerance: Some(tolerance.value()),
        }
    }

    /// `exact` or `faceted FT t`.
    pub fn describe(&self) -> String {
        match self.faceting_tolerance {
            Some(t) => format!("{} FT {t}", self.engine.name()),
            None => self.engine.name().to_string(),
        }
    }
}

/// The relative placement of a CONTACT's two parts at one output frame where it touches.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TouchingPose {
    /// The frame's time.
    pub t: f64,
    /// `X_WI`: the I part's frame (the Adams part frame its geometries are placed in).
    pub pose_world_i: Isometry3,
    /// `X_WJ`: the J part's frame.
    pub pose_world_j: Isometry3,
    /// The deepest penetration among the contact's points at this frame.
    pub penetration: f64,
    /// That deepest point's penetration rate `δ̇` (positive while approaching): with the
    /// penetration it places the contact's onset or release between output frames.
    pub penetration_rate: f64,
    /// The unit normal (J into I, world) of that deepest point.
    pub normal_w: Vector3,
    /// The deepest contact's point: midway between its points on I and on J (world).
    pub point_w: Point3,
}

/// What one run of a model delivered.
#[derive(Debug, Clone, PartialEq)]
pub struct RunRecord {
    /// The engine setting it ran with.
    pub setting: Setting,
    /// Wall time of the analyses, seconds (the model's first lowering excluded).
    pub wall_s: f64,
    /// Wall time of lowering the model (engine preparation included), seconds.
    pub prepare_s: f64,
    /// Simulated time covered, from the first analysis's start to the last's end.
    pub simulated_s: f64,
    /// Why the run stopped early, if it did (its frames up to there are kept).
    pub failure: Option<String>,
    /// The Adams ids of the moving parts, in the order of each frame's poses.
    pub parts: Vec<u32>,
    /// The contact names (`CONTACT/id`), in model order.
    pub contacts: Vec<String>,
    /// Output frame times.
    pub times: Vec<f64>,
    /// Per frame, each moving part's centre-of-mass pose in the world.
    pub part_poses: Vec<Vec<Isometry3>>,
    /// Per frame, each CONTACT's resultant force on I (normal plus friction, summed over its
    /// contact points), magnitude.
    pub contact_forces: Vec<Vec<f64>>,
    /// Per CONTACT, every frame where it touches (at least one contact point).
    pub touching: Vec<Vec<TouchingPose>>,
}

impl RunRecord {
    /// Wall time per simulated second (`wall_s / simulated_s`; infinite for an empty span).
    pub fn wall_per_simulated_s(&self) -> f64 {
        if self.simulated_s > 0.0 {
            self.wall_s / self.simulated_s
        } else {
            f64::INFINITY
        }
    }
}

/// Why a run of the trade could not be recorded.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    /// The run could not start, or (for the reference run) stopped early.
    #[error("the {setting} run: {source}")]
    Run {
        /// The setting, described.
        setting: String,
        /// Why.
        source: Box<RunError>,
    },
    /// The setting's faceting tolerance is out of range.
    #[error(transparent)]
    Tolerance(#[from] contact_core::InvalidArgument),
    /// The model's contacts could not be read as scenes (to choose the reference engine).
    #[error(transparent)]
    Scenes(#[from] crate::scenes::ModelSceneError),
    /// The exact engine does not answer every contact and no faceting tolerance was given.
    #[error(
        "no reference run: the exact engine does not answer every contact and the sweep has no \
         faceting tolerance"
    )]
    NoReference,
    /// The reference run stopped before its end: nothing can be held to it.
    #[error("the reference run ({setting}) stopped at t = {t}: {failure}")]
    ReferenceStopped {
        /// The setting, described.
        setting: String,
        /// The last output time reached.
        t: f64,
        /// Why it stopped.
        failure: String,
    },
}

/// The reference run of `model` (read from `source`): [`reference_setting`] over the model's
/// contacts, then [`record_run`] with it. A reference run that stops early is an error.
pub fn record_reference(
    model: &Model,
    source: &Path,
    exact: &dyn GeometryEngine,
    tolerances: &[FacetingTolerance],
    end: Option<f64>,
) -> Result<RunRecord, RecordError> {
    let scenes = crate::scenes::from_model(model)?;
    let setting = reference_setting(&scenes, exact, tolerances).ok_or(RecordError::NoReference)?;
    let record = record_run(model, source, setting, end, 1.0)?;
    match &record.failure {
        Some(failure) => Err(RecordError::ReferenceStopped {
            setting: setting.describe(),
            t: record.times.last().copied().unwrap_or(f64::NAN),
            failure: failure.clone(),
        }),
        None => Ok(record),
    }
}

/// The reference setting for `scenes` (a model's contacts, [`crate::scenes::from_model`]):
/// the exact engine when `exact` prepares every one of them, else the faceted engine at the
/// finest of `tolerances`; `None` when neither exists (no tolerance given).
pub fn reference_setting(
    scenes: &[Scene],
    exact: &dyn GeometryEngine,
    tolerances: &[FacetingTolerance],
) -> Option<Setting> {
    if scenes.iter().all(|s| exact.prepare(&s.i, &s.j).is_ok()) {
        return Some(Setting::EXACT);
    }
    tolerances
        .iter()
        .copied()
        .max_by(|a, b| a.value().total_cmp(&b.value()))
        .map(Setting::faceted)
}

/// Runs `model` (read from `source`) with `setting`, one thread, `end` overriding the last END
/// when given, every dynamic analysis at `error_scale` times its integrator ERROR (1: as the
/// model says; range `(0, 1]`), and records it. A run that stops early is kept with its
/// [`failure`](RunRecord::failure); a run that cannot start is an error.
pub fn record_run(
    model: &Model,
    source: &Path,
    setting: Setting,
    end: Option<f64>,
    error_scale: f64,
) -> Result<RunRecord, RecordError> {
    let faceting_tolerance = setting
        .faceting_tolerance
        .map(FacetingTolerance::new)
        .transpose()?;
    let options = RunOptions {
        engine: Some(setting.engine),
        faceting_tolerance,
        end,
        threads: Some(1),
        integrator_error_scale: (error_scale != 1.0).then_some(error_scale),
        ..RunOptions::default()
    };
    let mut recorder = Recorder::new(model, setting);
    let report = match run_model(model, source, &options, &mut recorder) {
        Ok(report) => report,
        Err(RunError::Stopped(report)) => {
            recorder.record.failure = report.failure.as_ref().map(|f| f.to_string());
            *report
        }
        Err(e) => {
            return Err(RecordError::Run {
                setting: setting.describe(),
                source: Box::new(e),
            });
        }
    };
    let mut record = recorder.record;
    record.wall_s = report.wall.as_secs_f64();
    record.prepare_s = report.prepare.as_secs_f64();
    record.simulated_s = report.end - report.start;
    Ok(record)
}

/// Where a CONTACT's part frame is found in a frame.
#[derive(Debug, Clone, Copy)]
enum PartFrame {
    /// A ground part: fixed at its pose.
    Fixed(Isometry3),
    /// A moving part: the solver part's CM pose times `X_CM,P`.
    Moving {
        index: usize,
        pose_cm_part: Isometry3,
    },
}

impl PartFrame {
    fn at(&self, frame: &Frame) -> Option<Isometry3> {
        match *self {
            PartFrame::Fixed(pose) => Some(pose),
            PartFrame::Moving {
                index,
                pose_cm_part,
            } => frame.parts.get(index).map(|s| s.pose_w * pose_cm_part),
        }
    }
}

/// The sink that records a run.
struct Recorder<'m> {
    model: &'m Model,
    /// Solver indices of the moving parts, in record order.
    indices: Vec<usize>,
    /// Per contact, its I and J part frames (`None` if a part is unknown: never touching).
    frames: Vec<Option<(PartFrame, PartFrame)>>,
    record: RunRecord,
}

impl<'m> Recorder<'m> {
    fn new(model: &'m Model, setting: Setting) -> Self {
        Self {
            model,
            indices: Vec::new(),
            frames: Vec::new(),
            record: RunRecord {
                setting,
                wall_s: 0.0,
                prepare_s: 0.0,
                simulated_s: 0.0,
                failure: None,
                parts: Vec::new(),
                contacts: Vec::new(),
                times: Vec::new(),
                part_poses: Vec::new(),
                contact_forces: Vec::new(),
                touching: Vec::new(),
            },
        }
    }

    /// Where Adams part `id`'s frame is, given the run's layout.
    fn part_frame(&self, layout: &RunLayout<'_>, id: u32) -> Option<PartFrame> {
        let part = self.model.parts.get(&id)?;
        if part.ground {
            return Some(PartFrame::Fixed(part.pose_world_part));
        }
        let (solver, _) = layout.parts.iter().find(|(_, adams)| *adams == id)?;
        let pose_part_cm = part
            .cm
            .and_then(|m| self.model.markers.get(&m))
            .map_or_else(Isometry3::identity, |m| m.pose_part_marker);
        Some(PartFrame::Moving {
            index: solver.0,
            pose_cm_part: pose_part_cm.inverse(),
        })
    }
}

impl RunSink for Recorder<'_> {
    fn start(&mut self, layout: &RunLayout<'_>) -> std::io::Result<()> {
        self.indices = layout.parts.iter().map(|(id, _)| id.0).collect();
        self.record.parts = layout.parts.iter().map(|(_, adams)| *adams).collect();
        self.record.contacts = layout.contacts.to_vec();
        self.frames = self
            .model
            .contacts
            .iter()
            .map(|c| {
                Some((
                    self.part_frame(layout, c.i_part)?,
                    self.part_frame(layout, c.j_part)?,
                ))
            })
            .collect();
        self.record.touching = vec![Vec::new(); self.frames.len()];
        Ok(())
    }

    fn frame(&mut self, frame: &Frame) -> std::io::Result<()> {
        let record = &mut self.record;
        record.times.push(frame.t);
        record.part_poses.push(
            self.indices
                .iter()
                .map(|&k| {
                    frame
                        .parts
                        .get(k)
                        .map_or_else(Isometry3::identity, |s| s.pose_w)
                })
                .collect(),
        );
        let mut forces = Vec::with_capacity(self.frames.len());
        for (k, placed) in self.frames.iter().enumerate() {
            let reports = frame.contacts.get(k).map_or(&[][..], Vec::as_slice);
            let resultant: Vector3 = reports
                .iter()
                .map(|r| r.contact.normal_w * r.normal_force + r.friction_force_w)
                .sum();
            forces.push(resultant.norm());
            let deepest = reports
                .iter()
                .max_by(|a, b| a.contact.penetration.total_cmp(&b.contact.penetration));
            if let (Some(deepest), Some((i, j))) = (deepest, placed) {
                if let (Some(pose_world_i), Some(pose_world_j)) = (i.at(frame), j.at(frame)) {
                    record.touching[k].push(TouchingPose {
                        t: frame.t,
                        pose_world_i,
                        pose_world_j,
                        penetration: deepest.contact.penetration,
                        penetration_rate: deepest.penetration_rate,
                        normal_w: deepest.contact.normal_w,
                        point_w: nalgebra::center(
                            &deepest.contact.point_i_w,
                            &deepest.contact.point_j_w,
                        ),
                    });
                }
            }
        }
        record.contact_forces.push(forces);
        Ok(())
    }
}
