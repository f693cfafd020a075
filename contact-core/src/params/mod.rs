//! CONTACT arguments (SPEC §3) as given, and their validated form.
//!
//! [`ContactArgs`] holds what a dataset or a caller wrote (every argument optional);
//! [`ContactArgs::validate`] checks every range, fills Adams View's defaults (given in N-mm-s
//! and converted to the model's [`Units`]), and returns [`ContactParams`] with the
//! warnings a model check should print. Geometry lists and flips live with the geometry
//! ([`GeometryInstance`](crate::GeometryInstance)), not here.

use crate::error::InvalidArgument;
use crate::laws::{
    AugmentedLagrangian, CoulombFriction, CoulombParams, ImpactLaw, ImpactParams, PoissonLaw,
    PoissonParams,
};
use crate::units::{Dimension, Units};
use thiserror::Error;

/// The CONTACT TYPE argument (may be given, or inferred from the geometry).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactType {
    /// `solid_to_solid`.
    SolidToSolid,
    /// `curve_to_curve`.
    CurveToCurve,
    /// `point_to_curve`.
    PointToCurve,
    /// `point_to_plane`.
    PointToPlane,
    /// `curve_to_plane`.
    CurveToPlane,
    /// `sphere_to_plane`.
    SphereToPlane,
    /// `sphere_to_sphere`.
    SphereToSphere,
    /// `cylinder_to_cylinder`.
    CylinderToCylinder,
}

impl ContactType {
    /// Every type, in the statement's order.
    pub const ALL: [Self; 8] = [
        Self::SolidToSolid,
        Self::CurveToCurve,
        Self::PointToCurve,
        Self::PointToPlane,
        Self::CurveToPlane,
        Self::SphereToPlane,
        Self::SphereToSphere,
        Self::CylinderToCylinder,
    ];

    /// The Adams spelling, lower case.
    pub fn name(self) -> &'static str {
        match self {
            Self::SolidToSolid => "solid_to_solid",
            Self::CurveToCurve => "curve_to_curve",
            Self::PointToCurve => "point_to_curve",
            Self::PointToPlane => "point_to_plane",
            Self::CurveToPlane => "curve_to_plane",
            Self::SphereToPlane => "sphere_to_plane",
            Self::SphereToSphere => "sphere_to_sphere",
            Self::CylinderToCylinder => "cylinder_to_cylinder",
        }
    }

    /// Parses the Adams spelling, case-insensitively.
    pub fn parse(value: &str) -> Result<Self, InvalidArgument> {
        let lower = value.trim().to_ascii_lowercase();
        Self::ALL.into_iter().find(|t| t.name() == lower).ok_or_else(|| {
            InvalidArgument::with_text(
                "TYPE",
                value,
                "one of solid_to_solid, curve_to_curve, point_to_curve, point_to_plane, curve_to_plane, sphere_to_plane, sphere_to_sphere, cylinder_to_cylinder",
            )
        })
    }

    /// True for the 2-D types (curve, point and curve-to-plane contacts).
    pub fn is_planar(self) -> bool {
        matches!(
            self,
            Self::CurveToCurve | Self::PointToCurve | Self::PointToPlane | Self::CurveToPlane
        )
    }
}

/// `COULOMB_FRICTION = ON | OFF | DYNAMICS_ONLY`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FrictionSwitch {
    /// Friction in every analysis.
    On,
    /// No friction.
    Off,
    /// Friction in dynamics only (not in statics or kinematics).
    DynamicsOnly,
}

impl FrictionSwitch {
    /// Parses ON, OFF or DYNAMICS_ONLY, case-insensitively.
    pub fn parse(value: &str) -> Result<Self, InvalidArgument> {
        match value.trim().to_ascii_uppercase().as_str() {
            "ON" => Ok(Self::On),
            "OFF" => Ok(Self::Off),
            "DYNAMICS_ONLY" => Ok(Self::DynamicsOnly),
            _ => Err(InvalidArgument::with_text(
                "COULOMB_FRICTION",
                value,
                "ON, OFF or DYNAMICS_ONLY",
            )),
        }
    }
}

/// A user force routine: `library::function` with its `USER(r1, …, r30)` constants.
#[derive(Debug, Clone, PartialEq)]
pub struct UserRoutine {
    /// The shared library, as written before `::`.
    pub library: String,
    /// The function name, as written after `::`.
    pub function: String,
    /// The USER constants (at most 30).
    pub parameters: Vec<f64>,
}

/// Every CONTACT argument as given (`None` / `false` = not given).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ContactArgs {
    /// TYPE.
    pub contact_type: Option<ContactType>,
    /// IMPACT flag.
    pub impact: bool,
    /// POISSON flag.
    pub poisson: bool,
    /// STIFFNESS.
    pub stiffness: Option<f64>,
    /// DAMPING.
    pub damping: Option<f64>,
    /// DMAX.
    pub dmax: Option<f64>,
    /// EXPONENT.
    pub exponent: Option<f64>,
    /// PENALTY.
    pub penalty: Option<f64>,
    /// RESTITUTION_COEFFICIENT.
    pub restitution_coefficient: Option<f64>,
    /// The POISSON compression/restitution blend velocity (ours; default 1 mm/s in the model's
    /// units, see [`PoissonLaw`]).
    pub poisson_transition_velocity: Option<f64>,
    /// AUGMENTED_LAGRANGIAN_FORMULATION flag.
    pub augmented_lagrangian: bool,
    /// NORMAL_FUNCTION = USER(…) constants.
    pub normal_function: Option<Vec<f64>>,
    /// NORMAL_ROUTINE = library::function.
    pub normal_routine: Option<String>,
    /// FRICTION_FUNCTION = USER(…) constants.
    pub friction_function: Option<Vec<f64>>,
    /// FRICTION_ROUTINE = library::function.
    pub friction_routine: Option<String>,
    /// COULOMB_FRICTION.
    pub coulomb_friction: Option<FrictionSwitch>,
    /// MU_STATIC.
    pub mu_static: Option<f64>,
    /// MU_DYNAMIC.
    pub mu_dynamic: Option<f64>,
    /// STICTION_TRANSITION_VELOCITY.
    pub stiction_transition_velocity: Option<f64>,
    /// FRICTION_TRANSITION_VELOCITY.
    pub friction_transition_velocity: Option<f64>,
    /// STICTION = ON/OFF (accepted; ON is ignored with a warning).
    pub stiction: Option<bool>,
}

/// The normal force model of a validated contact.
#[derive(Debug, Clone, PartialEq)]
pub enum NormalModel {
    /// IMPACT.
    Impact(ImpactLaw),
    /// POISSON, with the augmented-Lagrangian refinement when requested.
    Poisson {
        /// The law.
        law: PoissonLaw,
        /// AUGMENTED_LAGRANGIAN_FORMULATION.
        augmented_lagrangian: Option<AugmentedLagrangian>,
    },
    /// NORMAL_ROUTINE with NORMAL_FUNCTION.
    User(UserRoutine),
}

/// The friction model of a validated contact.
#[derive(Debug, Clone, PartialEq)]
pub enum FrictionModel {
    /// No friction.
    Off,
    /// Coulomb friction in every analysis.
    On(CoulombFriction),
    /// Coulomb friction in dynamics only.
    DynamicsOnly(CoulombFriction),
    /// FRICTION_ROUTINE with FRICTION_FUNCTION.
    User(UserRoutine),
}

/// A validated CONTACT's force parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactParams {
    /// TYPE, if given.
    pub contact_type: Option<ContactType>,
    /// The normal force model.
    pub normal: NormalModel,
    /// The friction model.
    pub friction: FrictionModel,
}

/// Something a model check should say about a valid CONTACT.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamWarning {
    /// STICTION = ON is accepted and ignored (no true stiction, as in Adams FORTRAN).
    StictionIgnored,
    /// An argument was not given; Adams View's default was used.
    Defaulted {
        /// The argument.
        argument: &'static str,
        /// The value used, in model units.
        value: f64,
    },
    /// An argument was given that the chosen model does not use.
    Unused {
        /// The argument.
        argument: &'static str,
        /// Why it has no effect.
        because: &'static str,
    },
}

impl std::fmt::Display for ParamWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::StictionIgnored => {
                f.write_str("STICTION = ON is ignored: the friction model has no true stiction")
            }
            Self::Defaulted { argument, value } => {
                write!(f, "{argument} not given: using the default {value:?}")
            }
            Self::Unused { argument, because } => write!(f, "{argument} has no effect: {because}"),
        }
    }
}

/// Why a CONTACT's arguments are invalid.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ParamError {
    /// A value out of range.
    #[error(transparent)]
    InvalidArgument(#[from] InvalidArgument),
    /// Two arguments that exclude each other.
    #[error("{first} and {second} cannot both be given")]
    Conflict {
        /// One argument.
        first: &'static str,
        /// The other.
        second: &'static str,
    },
    /// A required argument is missing.
    #[error("{argument} is required {because}")]
    Missing {
        /// What is missing.
        argument: &'static str,
        /// When it is required.
        because: &'static str,
    },
}

/// Adams View's defaults in N-mm-s (SPEC §3), with their dimensions.
mod defaults {
    pub const STIFFNESS: f64 = 1e5;
    pub const DAMPING: f64 = 10.0;
    pub const DMAX: f64 = 0.1;
    pub const EXPONENT: f64 = 2.2;
    pub const MU_STATIC: f64 = 0.3;
    pub const MU_DYNAMIC: f64 = 0.1;
    pub const STICTION_VELOCITY: f64 = 100.0;
    pub const FRICTION_VELOCITY: f64 = 1000.0;
    /// Ours: the POISSON blend velocity, 1 mm/s.
    pub const POISSON_TRANSITION_VELOCITY: f64 = 1.0;
}

const MAX_USER_CONSTANTS: usize = 30;

impl ContactArgs {
    /// Validates the arguments in the model's `units`; see the module docs.
    pub fn validate(
        &self,
        units: &Units,
    ) -> Result<(ContactParams, Vec<ParamWarning>), ParamError> {
        let mut warnings = Vec::new();
        let mut or_default =
            |given: Option<f64>, argument: &'static str, nmms: f64, dim: Dimension| match given {
                Some(v) => v,
                None => {
                    let value = units.convert_from(nmms, dim, &Units::MMKS);
                    warnings.push(ParamWarning::Defaulted { argument, value });
                    value
                }
            };
        let normal = self.normal_model(&mut or_default)?;
        let friction = self.friction_model(&mut or_default)?;
        if self.stiction == Some(true) {
            warnings.push(ParamWarning::StictionIgnored);
        }
        self.unused_arguments(&normal, &friction, &mut warnings);
        Ok((
            ContactParams {
                contact_type: self.contact_type,
                normal,
                friction,
            },
            warnings,
        ))
    }

    fn normal_model(
        &self,
        or_default: &mut impl FnMut(Option<f64>, &'static str, f64, Dimension) -> f64,
    ) -> Result<NormalModel, ParamError> {
        if self.impact && self.poisson {
            return Err(ParamError::Conflict {
                first: "IMPACT",
                second: "POISSON",
            });
        }
        if self.augmented_lagrangian && !self.poisson {
            return Err(ParamError::Missing {
                argument: "POISSON",
                because: "for AUGMENTED_LAGRANGIAN_FORMULATION (it refines the POISSON model only)",
            });
        }
        if let Some(routine) = &self.normal_routine {
            if self.impact || self.poisson {
                let first = if self.impact { "IMPACT" } else { "POISSON" };
                return Err(ParamError::Conflict {
                    first,
                    second: "NORMAL_ROUTINE",
                });
            }
            return Ok(NormalModel::User(user_routine(
                "NORMAL_ROUTINE",
                routine,
                &self.normal_function,
            )?));
        }
        if self.normal_function.is_some() {
            return Err(ParamError::Missing {
                argument: "NORMAL_ROUTINE",
                because: "with NORMAL_FUNCTION = USER(…) (no default routine is linked)",
            });
        }
        if self.impact {
            let exponent = or_default(
                self.exponent,
                "EXPONENT",
                defaults::EXPONENT,
                Dimension::NONE,
            );
            let stiffness = or_default(
                self.stiffness,
                "STIFFNESS",
                defaults::STIFFNESS,
                Dimension::stiffness(exponent),
            );
            let damping = or_default(
                self.damping,
                "DAMPING",
                defaults::DAMPING,
                Dimension::DAMPING,
            );
            let dmax = or_default(self.dmax, "DMAX", defaults::DMAX, Dimension::LENGTH);
            return Ok(NormalModel::Impact(ImpactLaw::from_params(ImpactParams {
                stiffness,
                exponent,
                damping,
                max_penetration: dmax,
            })?));
        }
        if self.poisson {
            let penalty = self.penalty.ok_or(ParamError::Missing {
                argument: "PENALTY",
                because: "with POISSON",
            })?;
            let restitution = self.restitution_coefficient.ok_or(ParamError::Missing {
                argument: "RESTITUTION_COEFFICIENT",
                because: "with POISSON",
            })?;
            let vt = or_default(
                self.poisson_transition_velocity,
                "POISSON transition velocity",
                defaults::POISSON_TRANSITION_VELOCITY,
                Dimension::VELOCITY,
            );
            let law = PoissonLaw::from_params(PoissonParams {
                penalty,
                restitution,
                transition_velocity: vt,
            })?;
            let augmented_lagrangian = if self.augmented_lagrangian {
                Some(AugmentedLagrangian::new(penalty)?)
            } else {
                None
            };
            return Ok(NormalModel::Poisson {
                law,
                augmented_lagrangian,
            });
        }
        Err(ParamError::Missing {
            argument: "IMPACT, POISSON or NORMAL_ROUTINE",
            because: "to define the normal force",
        })
    }

    fn friction_model(
        &self,
        or_default: &mut impl FnMut(Option<f64>, &'static str, f64, Dimension) -> f64,
    ) -> Result<FrictionModel, ParamError> {
        if let Some(routine) = &self.friction_routine {
            if matches!(
                self.coulomb_friction,
                Some(FrictionSwitch::On | FrictionSwitch::DynamicsOnly)
            ) {
                return Err(ParamError::Conflict {
                    first: "COULOMB_FRICTION",
                    second: "FRICTION_ROUTINE",
                });
            }
            return Ok(FrictionModel::User(user_routine(
                "FRICTION_ROUTINE",
                routine,
                &self.friction_function,
            )?));
        }
        if self.friction_function.is_some() {
            return Err(ParamError::Missing {
                argument: "FRICTION_ROUTINE",
                because: "with FRICTION_FUNCTION = USER(…) (no default routine is linked)",
            });
        }
        let switch = self.coulomb_friction.unwrap_or(FrictionSwitch::Off);
        if switch == FrictionSwitch::Off {
            return Ok(FrictionModel::Off);
        }
        let dimensionless = Dimension::NONE;
        let mu_static = or_default(
            self.mu_static,
            "MU_STATIC",
            defaults::MU_STATIC,
            dimensionless,
        );
        let mu_dynamic = or_default(
            self.mu_dynamic,
            "MU_DYNAMIC",
            defaults::MU_DYNAMIC,
            dimensionless,
        );
        let vs = or_default(
            self.stiction_transition_velocity,
            "STICTION_TRANSITION_VELOCITY",
            defaults::STICTION_VELOCITY,
            Dimension::VELOCITY,
        );
        let vd = or_default(
            self.friction_transition_velocity,
            "FRICTION_TRANSITION_VELOCITY",
            defaults::FRICTION_VELOCITY,
            Dimension::VELOCITY,
        );
        let coulomb = CoulombFriction::from_params(CoulombParams {
            mu_static,
            mu_dynamic,
            stiction_velocity: vs,
            friction_velocity: vd,
        })?;
        Ok(match switch {
            FrictionSwitch::On => FrictionModel::On(coulomb),
            FrictionSwitch::DynamicsOnly => FrictionModel::DynamicsOnly(coulomb),
            FrictionSwitch::Off => FrictionModel::Off,
        })
    }

    fn unused_arguments(
        &self,
        normal: &NormalModel,
        friction: &FrictionModel,
        warnings: &mut Vec<ParamWarning>,
    ) {
        let impact_only = [
            ("STIFFNESS", self.stiffness.is_some()),
            ("DAMPING", self.damping.is_some()),
            ("DMAX", self.dmax.is_some()),
            ("EXPONENT", self.exponent.is_some()),
        ];
        let poisson_only = [
            ("PENALTY", self.penalty.is_some()),
            (
                "RESTITUTION_COEFFICIENT",
                self.restitution_coefficient.is_some(),
            ),
        ];
        let coulomb_only = [
            ("MU_STATIC", self.mu_static.is_some()),
            ("MU_DYNAMIC", self.mu_dynamic.is_some()),
            (
                "STICTION_TRANSITION_VELOCITY",
                self.stiction_transition_velocity.is_some(),
            ),
            (
                "FRICTION_TRANSITION_VELOCITY",
                self.friction_transition_velocity.is_some(),
            ),
        ];
        if !matches!(normal, NormalModel::Impact(_)) {
            for (argument, given) in impact_only {
                if given {
                    warnings.push(ParamWarning::Unused {
                        argument,
                        because: "the normal force model is not IMPACT",
                    });
                }
            }
        }
        if !matches!(normal, NormalModel::Poisson { .. }) {
            for (argument, given) in poisson_only {
                if given {
                    warnings.push(ParamWarning::Unused {
                        argument,
                        because: "the normal force model is not POISSON",
                    });
                }
            }
        }
        if !matches!(
            friction,
            FrictionModel::On(_) | FrictionModel::DynamicsOnly(_)
        ) {
            for (argument, given) in coulomb_only {
                if given {
                    warnings.push(ParamWarning::Unused {
                        argument,
                        because: "COULOMB_FRICTION is not ON or DYNAMICS_ONLY",
                    });
                }
            }
        }
    }
}

fn user_routine(
    argument: &'static str,
    routine: &str,
    constants: &Option<Vec<f64>>,
) -> Result<UserRoutine, ParamError> {
    let (library, function) = routine.split_once("::").ok_or_else(|| {
        InvalidArgument::with_text(argument, routine, "of the form library::function")
    })?;
    if library.trim().is_empty() || function.trim().is_empty() {
        return Err(
            InvalidArgument::with_text(argument, routine, "of the form library::function").into(),
        );
    }
    let parameters = constants.clone().unwrap_or_default();
    if parameters.len() > MAX_USER_CONSTANTS {
        return Err(InvalidArgument::with_text(
            if argument == "NORMAL_ROUTINE" {
                "NORMAL_FUNCTION"
            } else {
                "FRICTION_FUNCTION"
            },
            format!("USER with {} constants", parameters.len()),
            "at most 30 constants",
        )
        .into());
    }
    Ok(UserRoutine {
        library: library.trim().to_string(),
        function: function.trim().to_string(),
        parameters,
    })
}

#[cfg(test)]
mod tests;
