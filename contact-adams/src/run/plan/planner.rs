//! The state [`super::plan_run`] carries from command to command: the settings in force, the
//! span being collected, the current time and the elements switched off.

use super::{
    AnalysisStep, DegreesOfFreedomError, PlanError, PlanOverrides, RunPlan, Span, TransientChoice,
    convert_equilibrium, convert_integrator, finish,
};
use crate::dataset::Origin;
use crate::model::{
    Analysis as ModelAnalysis, Command, EquilibriumSettings, Model, OutputSteps, SimulationSpan,
};
use crate::run::active::Inactive;
use contact_solver::bdf::IntegratorSettings;
use contact_solver::linear::LinearSettings;
use std::ops::ControlFlow;

/// The degrees of freedom at time `t` without the `inactive` elements (see
/// [`super::plan_run`]).
pub(super) type DegreesOfFreedom<'a> =
    &'a mut dyn FnMut(f64, &Inactive) -> Result<usize, DegreesOfFreedomError>;

/// A run plan being built from a model's commands.
pub(super) struct Planner<'m> {
    model: &'m Model,
    overrides: PlanOverrides,
    notes: Vec<String>,
    switches: Vec<(Origin, String)>,
    integrator: IntegratorSettings,
    equilibrium: EquilibriumSettings,
    steps: Vec<(AnalysisStep, Inactive)>,
    span: Option<Span>,
    time: f64,
    inactive: Inactive,
}

impl<'m> Planner<'m> {
    /// Nothing planned yet, at time 0, with the model's INTEGRATOR and EQUILIBRIUM settings.
    pub fn new(model: &'m Model, overrides: PlanOverrides) -> Result<Self, PlanError> {
        let notes = Vec::new();
        let switches = Vec::new();
        let integrator = convert_integrator(&model.integrator)?;
        let equilibrium = model.equilibrium.clone();
        let steps: Vec<(AnalysisStep, Inactive)> = Vec::new();
        let span: Option<Span> = None;
        let time = 0.0;
        let inactive = Inactive::default();
        Ok(Self {
            model,
            overrides,
            notes,
            switches,
            integrator,
            equilibrium,
            steps,
            span,
            time,
            inactive,
        })
    }

    /// Applies one command; [`ControlFlow::Break`] at STOP. An analysis that would run with an
    /// active MOTION on a deactivated JOINT is refused.
    pub fn command(
        &mut self,
        origin: &Origin,
        command: &Command,
        degrees_of_freedom: DegreesOfFreedom<'_>,
    ) -> Result<ControlFlow<()>, PlanError> {
        if matches!(command, Command::Simulate { .. } | Command::Linear { .. })
            && let Some((motion, joint)) = self.inactive.orphan_motion(self.model)
        {
            return Err(PlanError::OrphanMotion {
                origin: origin.clone(),
                motion,
                joint,
            });
        }
        match command {
            Command::Integrator(s) => self.integrator = convert_integrator(s)?,
            Command::Equilibrium(s) => self.equilibrium = s.clone(),
            Command::Simulate {
                analysis,
                span: when,
                output,
            } => self.simulate(origin, analysis, when, output, degrees_of_freedom)?,
            Command::Linear { damping } => self.linear(*damping)?,
            Command::Activate { active, class, ids } => {
                let text = self.inactive.switch(*active, class, ids, self.time);
                self.notes.push(format!("{origin}: {command}: {text}"));
                self.switches
                    .push((origin.clone(), format!("{command}: {text}")));
            }
            Command::Stop => return Ok(ControlFlow::Break(())),
            other => self.notes.push(format!(
                "{origin}: {other} is not applied by this solver: the command is ignored"
            )),
        }
        Ok(ControlFlow::Continue(()))
    }

    /// A SIMULATE: STATICS and INITIAL_CONDITIONS as steps of their own, a timed analysis as a
    /// new span from the current time to its END (or for its DURATION).
    fn simulate(
        &mut self,
        origin: &Origin,
        analysis: &ModelAnalysis,
        when: &Option<SimulationSpan>,
        output: &Option<OutputSteps>,
        degrees_of_freedom: DegreesOfFreedom<'_>,
    ) -> Result<(), PlanError> {
        let (timed, transient) = self.timed_analysis(origin, analysis, degrees_of_freedom)?;
        let Some(timed) = timed else {
            return self.untimed(analysis);
        };
        let stop = match when {
            Some(SimulationSpan::End(t)) => *t,
            Some(SimulationSpan::Duration(d)) => self.time + d,
            None => {
                return Err(PlanError::NoSpan {
                    origin: origin.clone(),
                });
            }
        };
        // Each SIMULATE is its own span with its own END and output step; the next
        // one starts from the state this one reaches.
        self.close_span()?;
        self.span = Some(Span {
            origin: Some(origin.clone()),
            analysis: timed,
            start: self.time,
            end: stop,
            output: *output,
            integrator: self.integrator,
            transient,
            inactive: self.inactive.clone(),
        });
        self.time = stop;
        Ok(())
    }

    /// The timed analysis a SIMULATE runs (none for STATICS and INITIAL_CONDITIONS): a
    /// TRANSIENT runs kinematics at zero degrees of freedom, else dynamics, with a note and
    /// the choice recorded.
    fn timed_analysis(
        &mut self,
        origin: &Origin,
        analysis: &ModelAnalysis,
        degrees_of_freedom: DegreesOfFreedom<'_>,
    ) -> Result<(Option<ModelAnalysis>, Option<TransientChoice>), PlanError> {
        let mut transient = None;
        let timed = match analysis {
            ModelAnalysis::Dynamics => Some(ModelAnalysis::Dynamics),
            ModelAnalysis::Transient => {
                let choice = TransientChoice {
                    degrees_of_freedom: degrees_of_freedom(self.time, &self.inactive).map_err(
                        |source| PlanError::Transient {
                            origin: origin.clone(),
                            source,
                        },
                    )?,
                };
                self.notes.push(format!("{origin}: {choice}"));
                transient = Some(choice);
                Some(if choice.degrees_of_freedom == 0 {
                    ModelAnalysis::Kinematics
                } else {
                    ModelAnalysis::Dynamics
                })
            }
            ModelAnalysis::Kinematics => Some(ModelAnalysis::Kinematics),
            ModelAnalysis::Statics | ModelAnalysis::InitialConditions => None,
        };
        Ok((timed, transient))
    }

    /// A SIMULATE/STATICS or SIMULATE/INITIAL_CONDITIONS: ends the span, then a step at the
    /// current time.
    fn untimed(&mut self, analysis: &ModelAnalysis) -> Result<(), PlanError> {
        self.close_span()?;
        let step = if *analysis == ModelAnalysis::Statics {
            AnalysisStep::Statics {
                t: self.time,
                settings: convert_equilibrium(&self.equilibrium, self.integrator),
            }
        } else {
            AnalysisStep::InitialConditions { t: self.time }
        };
        self.steps.push((step, self.inactive.clone()));
        Ok(())
    }

    /// A LINEAR/EIGENSOL: ends the span, then a step at the current time.
    fn linear(&mut self, damping: bool) -> Result<(), PlanError> {
        self.close_span()?;
        let step = AnalysisStep::Linear {
            t: self.time,
            settings: LinearSettings { damping },
        };
        self.steps.push((step, self.inactive.clone()));
        Ok(())
    }

    /// Ends the span being collected, if any, as a step (not the last: `--end` does not
    /// apply).
    fn close_span(&mut self) -> Result<(), PlanError> {
        if let Some(done) = self.span.take() {
            self.steps
                .push(finish(done, self.overrides, &mut self.notes, false)?);
        }
        Ok(())
    }

    /// After the last command: ends the span being collected as the last step (`--end` may
    /// override its END), or without any analysis runs dynamics from 0 to `--end`; returns the
    /// plan.
    pub fn finish(mut self) -> Result<RunPlan, PlanError> {
        let overrides = self.overrides;
        let mut notes = self.notes;
        let mut steps = self.steps;
        match self.span.take() {
            Some(done) => steps.push(finish(done, overrides, &mut notes, true)?),
            None if steps.is_empty() => {
                let end = overrides.end.ok_or(PlanError::NoEnd)?;
                let done = Span {
                    origin: None,
                    analysis: ModelAnalysis::Dynamics,
                    start: 0.0,
                    end,
                    output: None,
                    integrator: self.integrator,
                    transient: None,
                    inactive: self.inactive,
                };
                steps.push(finish(done, overrides, &mut notes, true)?);
            }
            None => {
                if overrides.end.is_some() {
                    notes.push(
                        "--end is not used: the command file runs no DYNAMICS or KINEMATICS".into(),
                    );
                }
            }
        }
        let (steps, inactive) = steps.into_iter().unzip();
        Ok(RunPlan {
            steps,
            inactive,
            notes,
            switches: self.switches,
        })
    }
}
