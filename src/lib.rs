//! # contact: rigid multibody dynamics with compliant contact, as the Adams CONTACT statement
//!
//! The application package of the workspace: it composes the shared vocabulary
//! ([`contact_core`]) and the two geometry engines into a solver.
//!
//! - [`solver`]: the implicit DAE interface ([`solver::DaeSystem`]) and the GSTIFF-style BDF
//!   integrator ([`solver::bdf::Bdf`]) with the step-by-step API contact prediction needs.
//!
//! ## Example: integrate y′ = −y to t = 1
//! ```
//! use contact::solver::bdf::{Bdf, IntegratorSettings};
//! use contact::solver::{DaeSystem, EvaluationError, VariableKind};
//! use nalgebra::{DMatrix, DVector};
//!
//! struct Decay;
//! impl DaeSystem for Decay {
//!     fn size(&self) -> usize { 1 }
//!     fn variable_kinds(&self) -> Vec<VariableKind> { vec![VariableKind::Differential] }
//!     fn residual(&mut self, _t: f64, y: &DVector<f64>, yp: &DVector<f64>,
//!                 out: &mut DVector<f64>) -> Result<(), EvaluationError> {
//!         out[0] = yp[0] + y[0];
//!         Ok(())
//!     }
//!     fn newton_matrix(&mut self, _t: f64, _y: &DVector<f64>, _yp: &DVector<f64>, c: f64,
//!                      out: &mut DMatrix<f64>) -> Result<(), EvaluationError> {
//!         out[(0, 0)] = 1.0 + c;
//!         Ok(())
//!     }
//! }
//!
//! let mut system = Decay;
//! let settings = IntegratorSettings { error: 1e-7, ..IntegratorSettings::default() };
//! let y0 = DVector::from_element(1, 1.0);
//! let mut bdf = Bdf::new(&system, 0.0, y0.clone(), -y0, settings)?;
//! bdf.set_stop_time(Some(1.0))?;
//! while bdf.t() < 1.0 {
//!     bdf.step(&mut system)?;
//! }
//! assert!((bdf.y()[0] - (-1.0_f64).exp()).abs() < 1e-6);
//! # Ok::<(), contact::solver::bdf::IntegratorError>(())
//! ```
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod solver;
