//! The expression context of REQUEST output: the state's measures, plus what needs the
//! frame's accelerations and reactions — `JOINT(id, jflag, comp, rm)` and
//! `MOTION(id, jflag, comp, rm)` (the constraint's reaction on its I or J marker), `SFORCE(…)`
//! (the force as the solver applies it), `ORIENT(27, …)`, and the net force and torque at a
//! marker, `FX(i[, j[, k]])` … `TM(i[, j])`: the sum over the JOINTs, JPRIMs, GCONs, MOTIONs
//! and SFORCEs between markers i and j (every one acting at i when j is 0) of what each
//! applies at i, the torque about i's origin, in k's axes. CONTACT forces act between
//! geometries, not markers, and are not part of it.

use super::measures::{MAX_VARIABLE_DEPTH, StateContext};
use crate::expr::{Context, ElementKind, EvalError, ForceMeasure, Measure};
use crate::model::{Freedom, SForce};
use contact_core::{Isometry3, UnitQuaternion, Vector3};
use contact_solver::frame::FrameDynamics;
use contact_solver::mbs::PartState;
use std::collections::BTreeMap;

/// The expression context of request output: the state's measures, plus ORIENT and JOINT
/// reactions from the frame's dynamics.
pub(super) struct RequestContext<'a> {
    pub state: StateContext<'a>,
    pub dynamics: Option<&'a FrameDynamics>,
    pub joints: &'a BTreeMap<u32, (usize, u32, u32)>,
    /// MOTION id → index into the frame's reactions.
    pub motions: &'a BTreeMap<u32, usize>,
    /// Every constraint element with markers: (index into the frame's reactions, I, J).
    pub constraints: &'a [(usize, u32, u32)],
    pub sforces: &'a BTreeMap<u32, SForce>,
    pub off_sforces: &'a std::collections::BTreeSet<u32>,
}

impl RequestContext<'_> {
    pub(super) fn pose(&self, id: u32) -> Isometry3 {
        if id == 0 {
            return Isometry3::identity();
        }
        self.state
            .markers
            .pose_w(id, self.state.parts)
            .unwrap_or_else(Isometry3::identity)
    }

    pub(super) fn axes(&self, id: u32) -> UnitQuaternion {
        self.pose(id).rotation
    }

    pub(super) fn velocity(&self, id: u32) -> (Vector3, Vector3) {
        if id == 0 {
            return (Vector3::zeros(), Vector3::zeros());
        }
        self.state
            .markers
            .velocity_w(id, self.state.parts)
            .unwrap_or_default()
    }

    /// The world acceleration of marker `id`'s origin and its part's angular acceleration:
    /// `a = a_cm + α × r + ω × (ω × r)`, `r` from the CM to the marker.
    pub(super) fn acceleration(&self, id: u32) -> Option<(Vector3, Vector3)> {
        if id == 0 {
            return Some((Vector3::zeros(), Vector3::zeros()));
        }
        let dynamics = self.dynamics?;
        let m = self.state.markers.markers.get(&id)?;
        let s: &PartState = self.state.parts.get(m.part.0)?;
        let (a_cm, alpha) = *dynamics.accelerations.get(m.part.0)?;
        let r = s.pose_w.rotation * m.pose_cm_marker.translation.vector;
        let w = s.angular_velocity_w;
        Some((a_cm + alpha.cross(&r) + w.cross(&w.cross(&r)), alpha))
    }

    /// JOINT/`id`'s reaction force and torque on its I marker (`jflag` 0) or J marker (1),
    /// world axes.
    fn joint_reaction(&self, id: u32, jflag: u32) -> Result<(Vector3, Vector3), EvalError> {
        let &(k, _, _) = self.joints.get(&id).ok_or(EvalError::NeedsState("JOINT"))?;
        self.reaction(k, jflag == 0, "JOINT")
    }

    /// MOTION/`id`'s reaction, as [`Self::joint_reaction`]: the force and torque that drive
    /// the motion, on the I marker (`jflag` 0) or the J marker (1) of its joint (or its own
    /// I and J markers).
    fn motion_reaction(&self, id: u32, jflag: u32) -> Result<(Vector3, Vector3), EvalError> {
        let &k = self
            .motions
            .get(&id)
            .ok_or(EvalError::NeedsState("MOTION"))?;
        self.reaction(k, jflag == 0, "MOTION")
    }

    /// The reaction `k` of the frame's dynamics on the element's I marker or its J marker.
    fn reaction(
        &self,
        k: usize,
        on_i: bool,
        what: &'static str,
    ) -> Result<(Vector3, Vector3), EvalError> {
        let e = self
            .dynamics
            .and_then(|d| d.reactions.get(k))
            .ok_or(EvalError::NeedsState(what))?;
        Ok(if on_i {
            (e.force_i_w, e.torque_i_w)
        } else {
            (e.force_j_w, e.torque_j_w)
        })
    }

    /// A FORCE request's force and torque at marker `i`: [`Self::net_at`] between `i` and
    /// `j`, or with `j = 0` the action-only SFORCEs whose I marker is `i` (as Adams defines
    /// FORCE requests).
    pub(super) fn force_request(&self, i: u32, j: u32) -> Result<(Vector3, Vector3), EvalError> {
        if j != 0 {
            return self.net_at(i, j);
        }
        let (mut force, mut torque) = (Vector3::zeros(), Vector3::zeros());
        for s in self.sforces.values().filter(|s| s.action_only && s.i == i) {
            let (f, t) = self.sforce_load(s.id, 0)?;
            force += f;
            torque += t;
        }
        Ok((force, torque))
    }

    /// The force and torque (about `i`'s origin), world axes, that the constraint elements and
    /// SFORCEs between markers `i` and `j` apply at marker `i`; with `j = 0`, every such
    /// element with a marker at `i` (Adams Solver (C++)'s reading of `FX(i)`). An
    /// action-only SFORCE applies nothing at its J marker.
    pub(super) fn net_at(&self, i: u32, j: u32) -> Result<(Vector3, Vector3), EvalError> {
        let between = |a: u32, b: u32| a == i && (j == 0 || b == j);
        let (mut force, mut torque) = (Vector3::zeros(), Vector3::zeros());
        for &(k, ei, ej) in self.constraints {
            let on_i = if between(ei, ej) {
                true
            } else if between(ej, ei) {
                false
            } else {
                continue;
            };
            let (f, t) = self.reaction(k, on_i, "a reaction force")?;
            force += f;
            torque += t;
        }
        for s in self.sforces.values() {
            let jflag = if between(s.i, s.j) {
                0
            } else if between(s.j, s.i) {
                1
            } else {
                continue;
            };
            let (f, t) = self.sforce_load(s.id, jflag)?;
            force += f;
            torque += t;
        }
        Ok((force, torque))
    }

    /// SFORCE/`id`'s force and torque on its I marker (`jflag` 0) or J marker (1), world
    /// axes, as the solver applies them: TRANSLATIONAL `f·(p_I − p_J)/|p_I − p_J|` on I (`f·z_J`
    /// with ACTIONONLY), the opposite on J (nothing with ACTIONONLY), no torque (the line of
    /// action passes through both markers); ROTATIONAL `f·z_J` torque on I, the opposite on J
    /// (nothing with ACTIONONLY), no force. `f` is the FUNCTION at this frame; zero while the
    /// SFORCE is switched off.
    fn sforce_load(&self, id: u32, jflag: u32) -> Result<(Vector3, Vector3), EvalError> {
        let s = self
            .sforces
            .get(&id)
            .ok_or(EvalError::NeedsState("SFORCE"))?;
        if self.off_sforces.contains(&id) {
            return Ok((Vector3::zeros(), Vector3::zeros()));
        }
        let value = s.function.eval(&self.state)?;
        let (pose_i, pose_j) = (self.pose(s.i), self.pose(s.j));
        let z_j = pose_j.rotation * Vector3::z();
        let sign = match (jflag, s.action_only) {
            (0, _) => 1.0,
            (_, true) => 0.0,
            (_, false) => -1.0,
        };
        Ok(match s.freedom {
            Freedom::Translational => {
                let direction = if s.action_only {
                    z_j
                } else {
                    let d = pose_i.translation.vector - pose_j.translation.vector;
                    let length = d.norm();
                    if length == 0.0 {
                        return Err(EvalError::NeedsState(
                            "an SFORCE whose I and J markers coincide",
                        ));
                    }
                    d / length
                };
                (direction * (value * sign), Vector3::zeros())
            }
            Freedom::Rotational => (Vector3::zeros(), z_j * (value * sign)),
        })
    }
}

impl Context for RequestContext<'_> {
    fn time(&self) -> f64 {
        self.state.t
    }

    fn measure(&self, measure: Measure, markers: &[u32]) -> Result<f64, EvalError> {
        self.state.measure(measure, markers)
    }

    /// A VARIABLE read from a request is evaluated with the request's reactions, so it may
    /// read JOINT, MOTION, SFORCE and FX … TM.
    fn variable(&self, id: u32) -> Result<f64, EvalError> {
        let function = self.state.variables.get(&id).ok_or(EvalError::NeedsState(
            "VARVAL of a VARIABLE the model does not define",
        ))?;
        if self.state.depth >= MAX_VARIABLE_DEPTH {
            return Err(EvalError::VariableCycle { id });
        }
        function.eval(&RequestContext {
            state: StateContext {
                depth: self.state.depth + 1,
                ..self.state
            },
            dynamics: self.dynamics,
            joints: self.joints,
            motions: self.motions,
            constraints: self.constraints,
            sforces: self.sforces,
            off_sforces: self.off_sforces,
        })
    }

    fn force_measure(&self, measure: ForceMeasure, markers: &[u32]) -> Result<f64, EvalError> {
        let arg = |k: usize| markers.get(k).copied().unwrap_or(0);
        let (force, torque) = self.net_at(arg(0), arg(1))?;
        let axes = self.axes(arg(2));
        Ok(measure.of(
            &axes.inverse_transform_vector(&force),
            &axes.inverse_transform_vector(&torque),
        ))
    }

    fn element_force(&self, kind: ElementKind, args: [u32; 4]) -> Result<f64, EvalError> {
        let [id, jflag, component, rm] = args;
        let (force, torque) = match kind {
            ElementKind::Joint => self.joint_reaction(id, jflag)?,
            ElementKind::Sforce => self.sforce_load(id, jflag)?,
            ElementKind::Motion => self.motion_reaction(id, jflag)?,
        };
        let axes = self.axes(rm);
        let (f, t) = (
            axes.inverse_transform_vector(&force),
            axes.inverse_transform_vector(&torque),
        );
        Ok(match component {
            1 => f.norm(),
            2..=4 => f[component as usize - 2],
            5 => t.norm(),
            6..=8 => t[component as usize - 6],
            _ => {
                return Err(EvalError::NeedsState(
                    "an element force with a component outside 1..=8",
                ));
            }
        })
    }

    fn orient(&self, [kind, component, i, j]: [u32; 4]) -> Result<f64, EvalError> {
        if kind != 27 || !(1..=4).contains(&component) {
            return Err(EvalError::NeedsState("ORIENT of a type other than 27"));
        }
        let q = self.axes(j).inverse() * self.axes(i);
        let q = q.quaternion();
        Ok([q.w, q.i, q.j, q.k][component as usize - 1])
    }
}
