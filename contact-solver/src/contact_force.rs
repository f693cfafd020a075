//! A CONTACT as a force element: the engine's contact kinematics plus contact-core's force laws.
//!
//! At each evaluation the prepared pair is queried at the two parts' poses. For every contact
//! (SPEC §4) the force acts at the midpoint `p` of the two surface points:
//! - the relative velocity of I's material point at `p` against J's, `v = v_I(p) − v_J(p)`;
//!   the penetration rate is `δ̇ = −n·v` (positive while approaching, `n` from J into I);
//!   these rates, the slip and the spin below come from contact-core's
//!   [`ContactKinematics`], so an embedder using it gets these numbers;
//! - the normal force `Fn(δ, δ̇) ≥ 0` from IMPACT or POISSON, pushing I along `n`;
//! - with friction, the slip `v_t = v − (n·v)·n` gives `F_t = μ(|v_t|)·Fn·v̂_t` (μ signed, so it
//!   opposes the slip) and the relative spin `ω_n = (ω_I − ω_J)·n` gives the torque
//!   `(2/3)·R·μ(ω_n·R)·Fn` about `n`, `R = sqrt(A/π)`; when the patch slips and spins at once
//!   the two share one Coulomb budget, with μ at the speed `sqrt(|v_t|² + (ω_n·R)²)`
//!   ([`contact_core::laws::SlipAndSpin`]);
//! - I receives `Fn·n + F_t` at `p` and the torque; J the opposite.
//!
//! NORMAL_ROUTINE and FRICTION_ROUTINE replace the normal law and the friction law by user
//! laws ([`UserLaws`], registered or loaded by the Adams layer) given the same contact, rate,
//! slip and spin; a user friction law returns the force and torque on I itself. A user law's
//! error or non-finite result stops the run, naming the contact and the routine.
//!
//! Partials come from one query at the state: the force laws' analytic partials with the
//! contact geometry frozen ([`crate::contact_partials`]); user force routines, and a
//! query that fails, are left to the system's element-local difference (12 evaluations per
//! moving part).
//!
//! A 2-D contact carries a [`PlanarGuard`]: before the engine is asked, the two parts' planes
//! are checked, and a part that left the plane stops the run with a fatal error naming the
//! contact, the part and the time (SPEC §3).

use crate::broad_phase::Bounds;
use crate::contact_multipliers::Multipliers;
use crate::contact_plane::PlanarGuard;
use crate::dae::EvaluationError;
use crate::mbs::{ForceElement, Load, PartId, StateView};
use contact_core::{
    Contact, ContactKinematics, ContactParams, FrictionModel, InvalidArgument, Isometry3,
    NormalModel, PreparedPair, Vector3, WorkCounters,
    laws::{
        NormalForce, UserContact, UserFrictionLaw, UserNormalLaw, checked_friction,
        checked_normal_force,
    },
};
use nalgebra::DMatrix;
use std::sync::{Arc, Mutex};

/// Which analysis is running: DYNAMICS_ONLY friction acts in dynamics only.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Analysis {
    /// Transient dynamics.
    Dynamics,
    /// Statics or kinematics.
    Quasistatic,
}

/// One contact's kinematics and forces, for output.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactReport {
    /// The engine's contact.
    pub contact: Contact,
    /// δ̇ (positive approaching).
    pub penetration_rate: f64,
    /// Normal force magnitude.
    pub normal_force: f64,
    /// Friction force on I, world frame.
    pub friction_force_w: Vector3,
    /// Friction torque on I about the normal.
    pub friction_torque: f64,
}

/// Why a CONTACT cannot become a force element.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ContactForceError {
    /// NORMAL_ROUTINE / FRICTION_ROUTINE without its law ([`ContactForce::with_user_laws`]).
    #[error("{contact}: the user force routine {routine} has no law (it was not resolved)")]
    UserRoutine {
        /// The contact's name.
        contact: String,
        /// `library::function`.
        routine: String,
    },
    /// A force-law parameter could not be used.
    #[error("{contact}: {source}")]
    Law {
        /// The contact's name.
        contact: String,
        /// What was wrong.
        source: InvalidArgument,
    },
}

/// The poses and the contacts of a CONTACT's last engine query.
#[derive(Debug)]
struct LastQuery {
    /// Both poses' translations and quaternions, as bits.
    key: [u64; 14],
    contacts: Vec<Contact>,
}

impl LastQuery {
    fn key(pose_i: &Isometry3, pose_j: &Isometry3) -> [u64; 14] {
        let mut key = [0; 14];
        for (slot, pose) in [pose_i, pose_j].into_iter().enumerate() {
            let q = pose.rotation.quaternion().coords;
            let t = pose.translation.vector;
            let values = [t.x, t.y, t.z, q.x, q.y, q.z, q.w];
            for (k, v) in values.into_iter().enumerate() {
                key[7 * slot + k] = v.to_bits();
            }
        }
        key
    }
}

/// A CONTACT between two parts.
#[derive(Debug)]
pub struct ContactForce {
    name: String,
    parts: [PartId; 2],
    pair: Box<dyn PreparedPair>,
    params: ContactParams,
    analysis: Analysis,
    work: Mutex<WorkCounters>,
    last_query: Mutex<Option<LastQuery>>,
    planar: Option<PlanarGuard>,
    multipliers: Option<Multipliers>,
    user: UserLaws,
    bounds: Option<[Bounds; 2]>,
}

impl ContactForce {
    /// A contact named `name` (e.g. `CONTACT/3`) between `part_i` (the I geometry's part) and
    /// `part_j`, with geometry prepared as `pair` in the parts' CM frames. A contact with a
    /// NORMAL_ROUTINE or FRICTION_ROUTINE needs [`Self::with_user_laws`].
    pub fn new(
        name: impl Into<String>,
        part_i: PartId,
        part_j: PartId,
        pair: Box<dyn PreparedPair>,
        params: ContactParams,
        analysis: Analysis,
    ) -> Result<Self, ContactForceError> {
        Self::with_user_laws(
            name,
            part_i,
            part_j,
            pair,
            params,
            analysis,
            UserLaws::default(),
        )
    }

    /// As [`Self::new`], with the laws of the contact's NORMAL_ROUTINE and FRICTION_ROUTINE
    /// (each must be given when the parameters name one; laws not named are not used).
    pub fn with_user_laws(
        name: impl Into<String>,
        part_i: PartId,
        part_j: PartId,
        pair: Box<dyn PreparedPair>,
        params: ContactParams,
        analysis: Analysis,
        user: UserLaws,
    ) -> Result<Self, ContactForceError> {
        let name = name.into();
        let routine = match (&params.normal, &params.friction) {
            (NormalModel::User(u), _) if user.normal.is_none() => {
                Some(format!("{}::{}", u.library, u.function))
            }
            (_, FrictionModel::User(u)) if user.friction.is_none() => {
                Some(format!("{}::{}", u.library, u.function))
            }
            _ => None,
        };
        let multipliers =
            Self::build_multipliers(&params, 1.0).map_err(|source| ContactForceError::Law {
                contact: name.clone(),
                source,
            })?;
        if let Some(routine) = routine {
            return Err(ContactForceError::UserRoutine {
                contact: name,
                routine,
            });
        }
        Ok(Self {
            name,
            parts: [part_i, part_j],
            pair,
            params,
            analysis,
            work: Mutex::new(WorkCounters::default()),
            last_query: Mutex::new(None),
            planar: None,
            multipliers,
            user,
            bounds: None,
        })
    }

    /// Sets the pair's length scale (> 0), to which the augmented-Lagrangian penetration
    /// tolerance is relative (1 model unit until set).
    pub fn with_length_scale(mut self, length: f64) -> Self {
        if let Ok(Some(m)) = Self::build_multipliers(&self.params, length) {
            self.multipliers = Some(m);
        }
        self
    }

    fn build_multipliers(
        params: &ContactParams,
        length: f64,
    ) -> Result<Option<Multipliers>, InvalidArgument> {
        match &params.normal {
            NormalModel::Poisson {
                law,
                augmented_lagrangian: Some(al),
            } => Multipliers::new(*law, *al, length).map(Some),
            _ => Ok(None),
        }
    }

    /// The contact with bounds fixed in its I and J parts that hold its I and J geometry
    /// lists ([`Bounds::enclosing`]): where they are apart the engine is not asked
    /// (no contact), and the system's broad phase skips the contact. `None` on either side
    /// leaves the contact unbounded (asked always).
    pub fn with_bounds(mut self, i: Option<Bounds>, j: Option<Bounds>) -> Self {
        self.bounds = i.zip(j).map(|(i, j)| [i, j]);
        self
    }

    /// Whether the bounds are apart at these part states (no contact possible).
    fn apart(&self, si: &crate::mbs::PartState, sj: &crate::mbs::PartState) -> bool {
        self.bounds
            .is_some_and(|[bi, bj]| Bounds::apart(&bi.world_box(si), &bj.world_box(sj)))
    }

    /// The force-law parameters and the analysis they are evaluated for.
    pub fn laws(&self) -> (&ContactParams, Analysis) {
        (&self.params, self.analysis)
    }

    /// The augmented-Lagrangian multipliers, for a POISSON contact that has them.
    pub fn multipliers(&self) -> Option<&Multipliers> {
        self.multipliers.as_ref()
    }

    /// The driver rolled the last accepted step back (contact prediction): state kept per
    /// accepted step returns to the step before.
    pub fn rolled_back(&self) {
        if let Some(m) = &self.multipliers {
            m.rolled_back();
        }
    }

    /// The same contact checked as a 2-D contact: both parts must stay in one plane.
    pub fn with_planar_guard(mut self, guard: PlanarGuard) -> Self {
        self.planar = Some(guard);
        self
    }

    /// Records the planes of a 2-D contact at an accepted state (the start or the end of an
    /// accepted step): the reference for naming the part that leaves the plane. Does nothing
    /// for a 3-D contact.
    pub fn record_accepted(&self, state: &StateView<'_>) {
        if let Some(guard) = &self.planar {
            let (si, sj) = (state.part(self.parts[0]), state.part(self.parts[1]));
            guard.record(&si.pose_w, &sj.pose_w);
        }
    }

    /// The work the engine has done for this contact so far.
    pub fn work(&self) -> WorkCounters {
        self.work.lock().map(|w| *w).unwrap_or_default()
    }

    /// The engine's contacts at the two parts' poses: the last query's again when both poses
    /// are the same to the bit (a query is a pure function of the poses), as they are for
    /// every velocity column of a differenced Jacobian.
    fn query(
        &self,
        pose_i: &Isometry3,
        pose_j: &Isometry3,
    ) -> Result<Vec<Contact>, EvaluationError> {
        let key = LastQuery::key(pose_i, pose_j);
        if let Ok(last) = self.last_query.lock()
            && let Some(last) = last.as_ref()
            && last.key == key
        {
            return Ok(last.contacts.clone());
        }
        let mut contacts = Vec::new();
        let mut work = WorkCounters::default();
        self.pair
            .query(pose_i, pose_j, &mut contacts, &mut work)
            .map_err(|e| EvaluationError {
                element: self.name.clone(),
                message: e.to_string(),
                fatal: false,
            })?;
        if let Ok(mut total) = self.work.lock() {
            *total += work;
        }
        if let Ok(mut last) = self.last_query.lock() {
            *last = Some(LastQuery {
                key,
                contacts: contacts.clone(),
            });
        }
        Ok(contacts)
    }

    /// Every contact's kinematics and forces at the given state at time `t`.
    pub fn reports(
        &self,
        t: f64,
        state: &StateView<'_>,
    ) -> Result<Vec<ContactReport>, EvaluationError> {
        let (si, sj) = (state.part(self.parts[0]), state.part(self.parts[1]));
        if let Some(guard) = &self.planar {
            guard.check(&self.name, t, &si.pose_w, &sj.pose_w)?;
        }
        if self.apart(si, sj) {
            return Ok(Vec::new());
        }
        let contacts = self.query(&si.pose_w, &sj.pose_w)?;
        let friction = match (&self.params.friction, self.analysis) {
            (FrictionModel::On(c), _) | (FrictionModel::DynamicsOnly(c), Analysis::Dynamics) => {
                Some(c)
            }
            _ => None,
        };
        let mut out = Vec::with_capacity(contacts.len());
        let (motion_i, motion_j) = (si.motion(), sj.motion());
        for (index, contact) in contacts.into_iter().enumerate() {
            let n = contact.normal_w;
            let ContactKinematics {
                penetration_rate: rate,
                slip_velocity_w: slip,
                spin,
                ..
            } = ContactKinematics::compute(&contact, &motion_i, &motion_j);
            let mut user = UserContact {
                time: t,
                index,
                point_i: contact.point_i_w.coords,
                point_j: contact.point_j_w.coords,
                normal: n,
                penetration: contact.penetration,
                penetration_rate: rate,
                area: contact.area,
                slip_velocity: slip,
                spin,
                normal_force: 0.0,
                parameters: &[],
            };
            let normal = match (&self.params.normal, &self.user.normal) {
                (NormalModel::User(routine), Some(law)) => {
                    user.parameters = &routine.parameters;
                    let force = checked_normal_force(law.as_ref(), &user)
                        .map_err(|e| self.user_error(routine, t, &e))?;
                    NormalForce {
                        force,
                        d_penetration: 0.0,
                        d_rate: 0.0,
                    }
                }
                _ => self.normal_force(index, contact.penetration, rate),
            };
            let (friction_force_w, friction_torque) = match (&self.params.friction, friction) {
                (FrictionModel::User(routine), _) => match &self.user.friction {
                    Some(law) => {
                        user.parameters = &routine.parameters;
                        user.normal_force = normal.force;
                        let f = checked_friction(law.as_ref(), &user)
                            .map_err(|e| self.user_error(routine, t, &e))?;
                        (f.force_w, f.torque)
                    }
                    // Refused in `with_user_laws`.
                    None => (Vector3::zeros(), 0.0),
                },
                (_, Some(c)) => {
                    let both = c.slip_and_spin(&slip, spin, normal.force, contact.area);
                    (both.force.force, both.torque.torque)
                }
                (_, None) => (Vector3::zeros(), 0.0),
            };
            out.push(ContactReport {
                contact,
                penetration_rate: rate,
                normal_force: normal.force,
                friction_force_w,
                friction_torque,
            });
        }
        Ok(out)
    }

    fn normal_force(&self, index: usize, delta: f64, rate: f64) -> NormalForce {
        match &self.params.normal {
            NormalModel::Impact(law) => law.force(delta, rate),
            NormalModel::Poisson { law, .. } => match &self.multipliers {
                Some(m) => m.force(index, delta, rate),
                None => law.force(delta, rate),
            },
            // Answered by the user law in `reports` (refused in `with_user_laws` without one).
            NormalModel::User(_) => NormalForce::ZERO,
        }
    }

    /// A user law's failure: fatal, since no step size makes a routine's error go away.
    fn user_error(
        &self,
        routine: &contact_core::UserRoutine,
        t: f64,
        error: &contact_core::laws::UserLawError,
    ) -> EvaluationError {
        EvaluationError {
            element: self.name.clone(),
            message: format!(
                "user routine {}::{} at t = {t}: {error}",
                routine.library, routine.function
            ),
            fatal: true,
        }
    }
}

impl ForceElement for ContactForce {
    fn name(&self) -> &str {
        &self.name
    }

    fn parts(&self) -> &[PartId] {
        &self.parts
    }

    fn evaluate(
        &self,
        t: f64,
        state: &StateView<'_>,
        loads: &mut [Load],
    ) -> Result<(), EvaluationError> {
        let (cm_i, cm_j) = (
            state.part(self.parts[0]).pose_w.translation.vector,
            state.part(self.parts[1]).pose_w.translation.vector,
        );
        let mut on_i = Load::default();
        let mut on_j = Load::default();
        for r in self.reports(t, state)? {
            let p = r.contact.midpoint_w().coords;
            let n = r.contact.normal_w;
            let force = n * r.normal_force + r.friction_force_w;
            let torque = n * r.friction_torque;
            let li = Load::at_point(force, &p, &cm_i);
            let lj = Load::at_point(-force, &p, &cm_j);
            on_i.force_w += li.force_w;
            on_i.torque_w += li.torque_w + torque;
            on_j.force_w += lj.force_w;
            on_j.torque_w += lj.torque_w - torque;
        }
        loads[0] = on_i;
        loads[1] = on_j;
        Ok(())
    }

    fn partials(
        &self,
        t: f64,
        state: &StateView<'_>,
    ) -> Option<Result<DMatrix<f64>, EvaluationError>> {
        crate::contact_partials::compute_contact_partials(self, t, state)
    }

    fn partials_are_exact(&self) -> bool {
        false
    }

    fn bounds(&self) -> Option<[Bounds; 2]> {
        self.bounds
    }

    fn velocity_scale(&self) -> Option<f64> {
        match &self.params.friction {
            FrictionModel::On(c) | FrictionModel::DynamicsOnly(c) => Some(c.stiction_velocity()),
            FrictionModel::Off | FrictionModel::User(_) => None,
        }
    }
}

/// A [`ContactForce`] shared between the system (which evaluates it) and the driver (which
/// reads its contacts for output and contact prediction).
#[derive(Debug, Clone)]
pub struct SharedContact(pub std::sync::Arc<ContactForce>);

impl ForceElement for SharedContact {
    fn name(&self) -> &str {
        self.0.name()
    }

    fn parts(&self) -> &[PartId] {
        self.0.parts()
    }

    fn evaluate(
        &self,
        t: f64,
        state: &StateView<'_>,
        loads: &mut [Load],
    ) -> Result<(), EvaluationError> {
        self.0.evaluate(t, state, loads)
    }

    fn partials(
        &self,
        t: f64,
        state: &StateView<'_>,
    ) -> Option<Result<DMatrix<f64>, EvaluationError>> {
        self.0.partials(t, state)
    }

    fn partials_are_exact(&self) -> bool {
        self.0.partials_are_exact()
    }

    fn velocity_scale(&self) -> Option<f64> {
        self.0.velocity_scale()
    }

    fn bounds(&self) -> Option<[Bounds; 2]> {
        self.0.bounds
    }

    fn tracks_steps(&self) -> bool {
        self.0.planar.is_some() || self.0.multipliers.is_some()
    }

    fn step_accepted(&mut self, t: f64, state: &StateView<'_>) {
        self.0.record_accepted(state);
        let Some(m) = &self.0.multipliers else {
            return;
        };
        // An accepted state was evaluated without error; a failure here keeps the old state.
        if let Ok(reports) = self.0.reports(t, state) {
            let contacts: Vec<(f64, f64, f64)> = reports
                .iter()
                .map(|r| (r.contact.penetration, r.penetration_rate, r.normal_force))
                .collect();
            m.step_accepted(&contacts);
        }
    }

    fn attempt_started(&mut self) {
        if let Some(m) = &self.0.multipliers {
            m.attempt_started();
        }
    }

    fn equilibrium_converged(&mut self, t: f64, state: &StateView<'_>) -> bool {
        let Some(m) = &self.0.multipliers else {
            return false;
        };
        // A failed query leaves the multipliers as they are; the next residual reports it.
        match self.0.reports(t, state) {
            Ok(reports) => {
                let penetrations: Vec<f64> =
                    reports.iter().map(|r| r.contact.penetration).collect();
                m.equilibrium_converged(&penetrations)
            }
            Err(_) => false,
        }
    }

    fn corrector_converged(&mut self, t: f64, state: &StateView<'_>) -> bool {
        let Some(m) = &self.0.multipliers else {
            return false;
        };
        // A failed query leaves the multipliers as they are; the next residual reports it.
        match self.0.reports(t, state) {
            Ok(reports) => {
                let contacts: Vec<(f64, f64)> = reports
                    .iter()
                    .map(|r| (r.contact.penetration, r.penetration_rate))
                    .collect();
                m.corrector_converged(&contacts)
            }
            Err(_) => false,
        }
    }
}

/// The user laws one CONTACT needs, resolved.
#[derive(Clone, Default)]
pub struct UserLaws {
    /// The NORMAL_ROUTINE's law (its constants stay in the contact's parameters).
    pub normal: Option<Arc<dyn UserNormalLaw>>,
    /// The FRICTION_ROUTINE's law.
    pub friction: Option<Arc<dyn UserFrictionLaw>>,
}

impl std::fmt::Debug for UserLaws {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("UserLaws")
            .field("normal", &self.normal.is_some())
            .field("friction", &self.friction.is_some())
            .finish()
    }
}

#[cfg(test)]
mod tests;
