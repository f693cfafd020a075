//! The solver settings (INTEGRATOR, EQUILIBRIUM) and the commands of a command file, as the
//! model keeps them.

use contact_core::Vector3;

/// INTEGRATOR settings (SPEC §8).
#[derive(Debug, Clone, PartialEq)]
pub struct IntegratorSettings {
    /// The method keyword given (GSTIFF, WSTIFF, HHT, …); the solver uses its own BDF.
    pub method: Option<&'static str>,
    /// The formulation keyword given (I3, SI2, SI1).
    pub formulation: Option<&'static str>,
    /// ERROR (default 1e-3).
    pub error: f64,
    /// HMAX.
    pub hmax: Option<f64>,
    /// HMIN.
    pub hmin: Option<f64>,
    /// HINIT.
    pub hinit: Option<f64>,
    /// KMAX (default 6).
    pub kmax: u32,
    /// MAXIT (default 10).
    pub maxit: u32,
    /// CORRECTOR (ORIGINAL, MODIFIED, …), as written upper case.
    pub corrector: Option<String>,
}

impl Default for IntegratorSettings {
    fn default() -> Self {
        Self {
            method: None,
            formulation: None,
            error: 1e-3,
            hmax: None,
            hmin: None,
            hinit: None,
            kmax: 6,
            maxit: 10,
            corrector: None,
        }
    }
}

/// EQUILIBRIUM settings.
#[derive(Debug, Clone, PartialEq)]
pub struct EquilibriumSettings {
    /// ALIMIT in radians (default 10°).
    pub alimit: f64,
    /// ERROR (default 1e-4).
    pub error: f64,
    /// IMBALANCE (default 1e-4).
    pub imbalance: f64,
    /// MAXIT (default 25).
    pub maxit: u32,
    /// STABILITY (default 1e-5).
    pub stability: f64,
    /// TLIMIT (default 20).
    pub tlimit: f64,
    /// DYNAMIC: the quasi-dynamic method.
    pub dynamic: bool,
}

impl Default for EquilibriumSettings {
    fn default() -> Self {
        Self {
            alimit: 10f64.to_radians(),
            error: 1e-4,
            imbalance: 1e-4,
            maxit: 25,
            stability: 1e-5,
            tlimit: 20.0,
            dynamic: false,
        }
    }
}

/// Which analysis a SIMULATE command runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Analysis {
    /// DYNAMICS.
    Dynamics,
    /// KINEMATICS.
    Kinematics,
    /// STATICS.
    Statics,
    /// TRANSIENT: dynamics or kinematics as the degrees of freedom require.
    Transient,
    /// INITIAL_CONDITIONS.
    InitialConditions,
}

/// When a SIMULATE ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SimulationSpan {
    /// END = t.
    End(f64),
    /// DURATION = t.
    Duration(f64),
}

/// How often a SIMULATE writes output.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OutputSteps {
    /// STEPS = n.
    Steps(u32),
    /// DTOUT = dt.
    Interval(f64),
}

/// A command of a command file (`.acf`).
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// SIMULATE.
    Simulate {
        /// The analysis.
        analysis: Analysis,
        /// END or DURATION (none for statics and initial conditions).
        span: Option<SimulationSpan>,
        /// STEPS or DTOUT.
        output: Option<OutputSteps>,
    },
    /// INTEGRATOR: new settings from here on.
    Integrator(IntegratorSettings),
    /// EQUILIBRIUM: new settings from here on.
    Equilibrium(EquilibriumSettings),
    /// ACTIVATE (`active`) or DEACTIVATE elements of a class (JOINT, CONTACT, …).
    Activate {
        /// True for ACTIVATE.
        active: bool,
        /// The element class keyword.
        class: &'static str,
        /// The ids.
        ids: Vec<u32>,
    },
    /// ACCGRAV: new gravity.
    Gravity(Vector3),
    /// LINEAR/EIGENSOL: the eigenvalues at the state reached so far.
    Linear {
        /// False with NODAMPIN: the damping matrix is left out.
        damping: bool,
    },
    /// STOP.
    Stop,
}

impl std::fmt::Display for Command {
    /// The command as a command file writes it (`DEACTIVATE/JOINT, ID = 1, 2`); the commands
    /// with settings are named only (`INTEGRATOR`).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Activate { active, class, ids } => {
                let ids: Vec<String> = ids.iter().map(u32::to_string).collect();
                let verb = if *active { "ACTIVATE" } else { "DEACTIVATE" };
                write!(f, "{verb}/{class}, ID = {}", ids.join(", "))
            }
            Self::Gravity(g) => write!(
                f,
                "ACCGRAV/ IGRAV = {}, JGRAV = {}, KGRAV = {}",
                g.x, g.y, g.z
            ),
            Self::Simulate { .. } => f.write_str("SIMULATE"),
            Self::Integrator(_) => f.write_str("INTEGRATOR"),
            Self::Equilibrium(_) => f.write_str("EQUILIBRIUM"),
            Self::Linear { .. } => f.write_str("LINEAR/EIGENSOL"),
            Self::Stop => f.write_str("STOP"),
        }
    }
}
