//! REQUEST output: each REQUEST's six columns evaluated at an output frame, as Adams defines
//! them, in the model's units (angles of displacement requests in degrees, as Adams writes them).
//!
//! | request | columns |
//! |---|---|
//! | DISPLACEMENT (`D`) | `x y z` of I's origin relative to J's, in RM's axes; `ψ θ φ`, the body-fixed 3-1-3 Euler angles of I's axes relative to J's, in degrees (θ in [0°, 180°], ψ and φ in (−180°, 180°]) |
//! | VELOCITY (`V`) | `v_I − v_J` and `ω_I − ω_J`, in RM's axes (derivatives taken in ground) |
//! | ACCELERATION (`A`) | `a_I − a_J` and `α_I − α_J`, in RM's axes |
//! | FORCE (`F`) | the force and torque (about I's origin) at marker I from every JOINT, JPRIM, GCON, MOTION and SFORCE between markers I and J (J omitted: the action-only SFORCEs at I), in RM's axes |
//! | F2 … F8 | F2 F3 F4 F6 F7 F8 (F1 and F5 are not written; a component not given is 0) |
//!
//! RM omitted (or 0) means ground. In expressions, `ORIENT(27, k, i, j)` is the k-th Euler
//! parameter (e0 scalar first) of I's axes relative to J's, and `JOINT(id, jflag, comp, rm)`
//! (and `MOTION`, `SFORCE`) the element's force on its I marker (jflag 0) or J marker (1):
//! comp 1 |F|, 2–4 F, 5 |T|, 6–8 T (about that marker's origin), in rm's axes (0: ground);
//! `FX(i, j, k)` … `TM(i, j)` the net force and torque at a marker (see `request_context`).
//! Accelerations and reactions come from the frame's
//! [`FrameDynamics`](contact_solver::frame::FrameDynamics): the solution of the equations of
//! motion at the frame's state.

use super::frames::MarkerTable;
use super::measures::StateContext;
use super::request_context::RequestContext;
use crate::expr::{EvalError, Expr, parse_expr};
use crate::model::{Model, MotionTarget, SForce};
use contact_core::{UnitQuaternion, Vector3};
use contact_solver::simulate::Frame;
use std::collections::BTreeMap;
use std::sync::Arc;

/// A request's kind, with its Adams type number (`.req` TYPE column).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RequestKind {
    /// DISPLACEMENT (type 1).
    Displacement,
    /// VELOCITY (type 2).
    Velocity,
    /// ACCELERATION (type 3).
    Acceleration,
    /// FORCE (type 4).
    Force,
    /// F2 … F8 expressions (type 5).
    Expressions,
}

impl RequestKind {
    /// The Adams type number written in a `.req` header.
    pub fn type_number(self) -> u32 {
        match self {
            Self::Displacement => 1,
            Self::Velocity => 2,
            Self::Acceleration => 3,
            Self::Force => 4,
            Self::Expressions => 5,
        }
    }

    /// The name written in `requests.csv`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Displacement => "displacement",
            Self::Velocity => "velocity",
            Self::Acceleration => "acceleration",
            Self::Force => "force",
            Self::Expressions => "expressions",
        }
    }
}

/// One REQUEST ready to evaluate.
#[derive(Debug, Clone)]
pub struct RequestSpec {
    /// The Adams id.
    pub id: u32,
    /// The kind.
    pub kind: RequestKind,
    /// I, J, RM (0 = omitted; I and J are 0 for expressions).
    pub markers: [u32; 3],
    /// COMMENT (empty if none).
    pub comment: String,
    /// The expressions of F2 F3 F4 F6 F7 F8 (columns 1–6), `None` where not given or not
    /// evaluable (the check warned).
    pub functions: [Option<Expr>; 6],
}

/// Every REQUEST of a model, with what evaluating them needs.
#[derive(Debug, Clone)]
pub struct RequestSet {
    /// The requests in id order.
    pub requests: Vec<RequestSpec>,
    markers: Arc<MarkerTable>,
    variables: Arc<BTreeMap<u32, Expr>>,
    /// JOINT id → index into the frame's reactions (and the joint's I, J markers).
    joints: BTreeMap<u32, (usize, u32, u32)>,
    /// MOTION id → index into the frame's reactions.
    motions: BTreeMap<u32, usize>,
    /// Every constraint element with markers: (index into the frame's reactions, I, J).
    constraints: Vec<(usize, u32, u32)>,
    /// SFORCE id → the element (markers, freedom, FUNCTION), for `SFORCE(id, …)`.
    sforces: BTreeMap<u32, SForce>,
    /// The SFORCEs switched off by DEACTIVATE: their force reads zero.
    off_sforces: std::collections::BTreeSet<u32>,
}

/// Why a request has no value at a frame.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RequestError {
    /// The frame carries no accelerations and reactions.
    #[error("REQUEST/{id}: the frame at t = {t:?} has no accelerations or reactions")]
    NoDynamics {
        /// The request.
        id: u32,
        /// The frame's time.
        t: f64,
    },
    /// An expression failed.
    #[error("REQUEST/{id}: {column}: at t = {t:?}: {source}")]
    Expression {
        /// The request.
        id: u32,
        /// F2 … F8.
        column: &'static str,
        /// The frame's time.
        t: f64,
        /// Why.
        source: EvalError,
    },
}

/// The function argument of each written column.
pub const COLUMNS: [&str; 6] = ["F2", "F3", "F4", "F6", "F7", "F8"];

impl RequestSet {
    /// Switches off the elements `inactive` names (and back on every other): a switched-off
    /// SFORCE's force reads zero in `SFORCE(id, …)`, as its element applies none. (A
    /// switched-off constraint's reaction is zero in the frame itself.)
    pub fn switch_off(&mut self, inactive: &crate::run::active::Inactive) {
        self.off_sforces = inactive
            .ids(crate::run::active::ElementClass::Sforce)
            .collect();
    }

    /// The model's requests; `constraint_names` are the solver's constraint names in
    /// reaction order (`JOINT/3`, `JPRIM/1`, `GCON/2`, …), `markers` and `variables` as the
    /// lowered model has them.
    pub fn new<'a>(
        model: &Model,
        constraint_names: impl Iterator<Item = &'a str>,
        markers: Arc<MarkerTable>,
        variables: Arc<BTreeMap<u32, Expr>>,
    ) -> Self {
        let mut element_markers: BTreeMap<String, (u32, u32)> = BTreeMap::new();
        for j in &model.joints {
            element_markers.insert(format!("JOINT/{}", j.id), (j.i, j.j));
        }
        for p in &model.primitives {
            element_markers.insert(format!("JPRIM/{}", p.id), (p.i, p.j));
        }
        for g in &model.gcons {
            element_markers.insert(format!("GCON/{}", g.id), (g.i, g.j));
        }
        for m in &model.motions {
            let markers = match m.target {
                MotionTarget::Joint { joint, .. } => model
                    .joints
                    .iter()
                    .find(|j| j.id == joint)
                    .map(|j| (j.i, j.j)),
                MotionTarget::Markers { i, j, .. } => Some((i, j)),
            };
            if let Some(markers) = markers {
                element_markers.insert(format!("MOTION/{}", m.id), markers);
            }
        }
        let placed: Vec<(usize, String, u32, u32)> = constraint_names
            .enumerate()
            .filter_map(|(k, name)| {
                let (i, j) = element_markers.get(name)?;
                Some((k, name.to_owned(), *i, *j))
            })
            .collect();
        let joints = placed
            .iter()
            .filter_map(|(k, name, i, j)| {
                let id = name.strip_prefix("JOINT/")?.parse().ok()?;
                Some((id, (*k, *i, *j)))
            })
            .collect();
        let motions = placed
            .iter()
            .filter_map(|(k, name, _, _)| Some((name.strip_prefix("MOTION/")?.parse().ok()?, *k)))
            .collect();
        let constraints = placed.iter().map(|(k, _, i, j)| (*k, *i, *j)).collect();
        let requests = model
            .requests
            .iter()
            .map(|r| {
                let kind = match r.kind {
                    Some("DISPLACEMENT") => RequestKind::Displacement,
                    Some("VELOCITY") => RequestKind::Velocity,
                    Some("ACCELERATION") => RequestKind::Acceleration,
                    Some(_) => RequestKind::Force,
                    None => RequestKind::Expressions,
                };
                let mut functions: [Option<Expr>; 6] = Default::default();
                for (name, text) in &r.functions {
                    if let Some(k) = COLUMNS.iter().position(|c| c == name) {
                        functions[k] = parse_expr(text).ok();
                    }
                }
                let [i, j, rm] = r.markers.map(|m| m.unwrap_or(0));
                RequestSpec {
                    id: r.id,
                    kind,
                    markers: if kind == RequestKind::Expressions {
                        [0, 0, 0]
                    } else {
                        [i, j, rm]
                    },
                    comment: r.comment.clone().unwrap_or_default(),
                    functions,
                }
            })
            .collect();
        Self {
            requests,
            markers,
            variables,
            joints,
            motions,
            constraints,
            sforces: model.sforces.iter().map(|s| (s.id, s.clone())).collect(),
            off_sforces: std::collections::BTreeSet::new(),
        }
    }

    /// Whether the model has no requests.
    pub fn is_empty(&self) -> bool {
        self.requests.is_empty()
    }

    /// Every request's six columns at `frame` (which must carry its dynamics when any request
    /// needs accelerations or reactions).
    pub fn evaluate(&self, frame: &Frame) -> Result<Vec<[f64; 6]>, RequestError> {
        self.requests
            .iter()
            .map(|r| self.evaluate_one(r, frame))
            .collect()
    }

    fn evaluate_one(&self, r: &RequestSpec, frame: &Frame) -> Result<[f64; 6], RequestError> {
        let ctx = RequestContext {
            state: StateContext {
                t: frame.t,
                parts: &frame.parts,
                markers: &self.markers,
                variables: &self.variables,
                depth: 0,
            },
            dynamics: frame.dynamics.as_ref(),
            joints: &self.joints,
            motions: &self.motions,
            constraints: &self.constraints,
            sforces: &self.sforces,
            off_sforces: &self.off_sforces,
        };
        let no_dynamics = || RequestError::NoDynamics {
            id: r.id,
            t: frame.t,
        };
        let [i, j, rm] = r.markers;
        let axes = ctx.axes(rm);
        let in_rm = |v: Vector3| axes.inverse_transform_vector(&v);
        let pack = |a: Vector3, b: Vector3| [a.x, a.y, a.z, b.x, b.y, b.z];
        Ok(match r.kind {
            RequestKind::Displacement => {
                let (pi, pj) = (ctx.pose(i), ctx.pose(j));
                let d = in_rm(pi.translation.vector - pj.translation.vector);
                let [psi, theta, phi] = euler_313(&(pj.rotation.inverse() * pi.rotation));
                [
                    d.x,
                    d.y,
                    d.z,
                    psi.to_degrees(),
                    theta.to_degrees(),
                    phi.to_degrees(),
                ]
            }
            RequestKind::Velocity => {
                let ((vi, wi), (vj, wj)) = (ctx.velocity(i), ctx.velocity(j));
                pack(in_rm(vi - vj), in_rm(wi - wj))
            }
            RequestKind::Acceleration => {
                let (ai, bi) = ctx.acceleration(i).ok_or_else(no_dynamics)?;
                let (aj, bj) = ctx.acceleration(j).ok_or_else(no_dynamics)?;
                pack(in_rm(ai - aj), in_rm(bi - bj))
            }
            RequestKind::Force => {
                ctx.dynamics.ok_or_else(no_dynamics)?;
                let (f, t) =
                    ctx.force_request(i, j)
                        .map_err(|source| RequestError::Expression {
                            id: r.id,
                            column: "FORCE",
                            t: frame.t,
                            source,
                        })?;
                pack(in_rm(f), in_rm(t))
            }
            RequestKind::Expressions => {
                let mut out = [0.0; 6];
                for (k, function) in r.functions.iter().enumerate() {
                    if let Some(e) = function {
                        out[k] = e.eval(&ctx).map_err(|source| RequestError::Expression {
                            id: r.id,
                            column: COLUMNS[k],
                            t: frame.t,
                            source,
                        })?;
                    }
                }
                out
            }
        })
    }
}

/// The body-fixed 3-1-3 Euler angles `[ψ, θ, φ]` (radians) of `r = Rz(ψ)·Rx(θ)·Rz(φ)`:
/// θ in [0, π], ψ and φ in (−π, π]. At θ = 0 or π (gimbal lock) φ is 0 and ψ carries the
/// whole rotation about z.
pub fn euler_313(r: &UnitQuaternion) -> [f64; 3] {
    let m = r.to_rotation_matrix();
    let m = m.matrix();
    let theta = m[(2, 2)].clamp(-1.0, 1.0).acos();
    let sin_theta = (m[(0, 2)].powi(2) + m[(1, 2)].powi(2)).sqrt();
    if sin_theta < 1e-12 {
        // Rz(ψ)·Rx(0 or π)·Rz(0): m00 = cos ψ, m10 = sin ψ.
        return [m[(1, 0)].atan2(m[(0, 0)]), theta, 0.0];
    }
    let psi = m[(0, 2)].atan2(-m[(1, 2)]);
    let phi = m[(2, 0)].atan2(m[(2, 1)]);
    [psi, theta, phi]
}

#[cfg(test)]
mod tests {
    use super::euler_313;
    use contact_core::{UnitQuaternion, Vector3};

    fn from_313(psi: f64, theta: f64, phi: f64) -> UnitQuaternion {
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), psi)
            * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), theta)
            * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi)
    }

    #[test]
    fn euler_313_round_trips_away_from_gimbal_lock() {
        for (psi, theta, phi) in [(0.3, 0.7, -1.2), (3.0, 2.9, 0.1), (-2.0, 0.01, 2.5)] {
            let [a, b, c] = euler_313(&from_313(psi, theta, phi));
            assert!(
                (a - psi).abs() < 1e-12 && (b - theta).abs() < 1e-12,
                "{a} {b} {c}"
            );
            assert!((c - phi).abs() < 1e-12, "{c} vs {phi}");
        }
    }

    #[test]
    fn euler_313_of_adams_reuler_marker() {
        // REULER = 180D, 45D, 180D, as Adams writes it at t = 0 in Revolute_Case02.
        let [a, b, c] = euler_313(&from_313(
            std::f64::consts::PI,
            std::f64::consts::FRAC_PI_4,
            std::f64::consts::PI,
        ));
        assert!((a.abs().to_degrees() - 180.0).abs() < 1e-9);
        assert!((b.to_degrees() - 45.0).abs() < 1e-9);
        assert!((c.abs().to_degrees() - 180.0).abs() < 1e-9);
        // At θ = 0 the rotation about z is all in ψ.
        let [a, b, c] = euler_313(&from_313(0.4, 0.0, 0.3));
        assert!((a - 0.7).abs() < 1e-12 && b.abs() < 1e-7 && c == 0.0);
    }
}
