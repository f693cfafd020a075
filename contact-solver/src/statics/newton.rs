//! Newton on the static residual in virtual displacements.
//!
//! Unknowns `x = [δr_k, δθ′_k (per moving part), λ]` (6n + m). Rows: the dynamic rows of the
//! multibody residual at `v = 0`, `v̇ = 0` (`Φ_vᵀλ − Q`, 6 per part, torques in the body frame)
//! and the position constraints `Φ` (m). The Jacobian comes from the integrator's Newton
//! matrix at `c = 0` (`∂F/∂y`): its position columns as they are, its Euler-parameter columns
//! times `∂e/∂θ′ = ½G(e)ᵀ` (from `ė = ½G(e)ᵀω′`), its λ columns as they are. A rotation
//! increment is applied as `e ← e ⊗ exp(δθ′)`, so the parameters stay unit and the
//! normalization row needs no unknown.

use super::StaticsSettings;
use crate::dae::EvaluationError;
use crate::mbs::quaternion::{g_matrix, parameters_of, rotation_of};
use crate::mbs::{MultibodySystem, PartId, StateView, difference_partials};
use nalgebra::{DMatrix, DVector, Matrix3, UnitQuaternion, Vector3};

/// What a converged Newton did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NewtonReport {
    /// Iterations (Jacobian solves).
    pub iterations: usize,
    /// The final imbalance.
    pub imbalance: f64,
}

/// Why Newton stopped without converging; `y` holds the last iterate.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{cause} after {iterations} iterations (imbalance {imbalance:e})")]
pub struct NewtonFailure {
    /// Iterations done.
    pub iterations: usize,
    /// The imbalance at the last iterate (infinite if it could not be evaluated).
    pub imbalance: f64,
    /// What went wrong.
    pub cause: String,
}

/// The static residual `[dynamic rows; Φ]` (6n + m) at `y` (velocities must be zero).
pub fn static_residual(
    system: &mut MultibodySystem,
    t: f64,
    y: &DVector<f64>,
) -> Result<DVector<f64>, EvaluationError> {
    let layout = *system.layout();
    let mut full = DVector::zeros(layout.size());
    system.compute_residual(t, y, &DVector::zeros(layout.size()), &mut full)?;
    let (n, m) = (layout.parts(), layout.constraint_rows());
    let mut r = DVector::zeros(6 * n + m);
    for (k, part) in system.moving_parts().enumerate() {
        r.rows_mut(6 * k, 6)
            .copy_from(&full.rows(layout.velocity_offset(part), 6));
    }
    r.rows_mut(6 * n, m)
        .copy_from(&full.rows(layout.position_constraint_offset(), m));
    Ok(r)
}

/// The force imbalance of a static residual: the largest force row, and torque rows over
/// the length scale `L` (so both are forces).
pub fn imbalance(system: &MultibodySystem, r: &DVector<f64>) -> f64 {
    let n = system.layout().parts();
    (0..6 * n)
        .map(|i| {
            if i % 6 < 3 {
                r[i].abs()
            } else {
                r[i].abs() / system.length_scale()
            }
        })
        .fold(0.0, f64::max)
}

/// The imbalance that round-off alone leaves at `y`: a position known to `ε·max(|r|, L)`
/// (translation) and `ε` (rotation, radians) moves each force row by up to
/// `Σ_j |K_ij|·s_j·ε`, with `K` the static `jacobian` and `s_j` those scales. A stiff contact
/// carrying a large load (`K ≈ e·F/δ` for a penetration `δ` far below the part's distance from
/// the origin) leaves an imbalance many orders above `ε·F` that no iteration can remove.
/// Returns `64·ε·max_i Σ_j |K_ij|·s_j` over the force rows (torque rows over `L`, as
/// [`imbalance`]); the factor covers the residual's own sums.
pub fn roundoff_imbalance(
    system: &MultibodySystem,
    y: &DVector<f64>,
    jacobian: &DMatrix<f64>,
) -> f64 {
    let layout = *system.layout();
    let length = system.length_scale();
    let scales: Vec<f64> = system
        .moving_parts()
        .flat_map(|part| {
            let r = MultibodySystem::vector_at(y, layout.position_offset(part)).norm();
            let translation = r.max(length);
            [translation, translation, translation, 1.0, 1.0, 1.0]
        })
        .collect();
    let rows = scales.len();
    (0..rows)
        .map(|i| {
            let sum: f64 = scales
                .iter()
                .enumerate()
                .map(|(j, s)| jacobian[(i, j)].abs() * s)
                .sum();
            if i % 6 < 3 { sum } else { sum / length }
        })
        .fold(0.0, f64::max)
        * 64.0
        * f64::EPSILON
}

/// The static Jacobian `∂[dynamic rows; Φ]/∂[δr, δθ′, λ]` at `y` (velocities zero), with
/// `stability` times the mass and damping matrices added to the position columns of the
/// dynamic rows: `K + s·(M + C)` in place of the stiffness `K`.
///
/// `C = ∂(ω′×Jω′ − Q)/∂[u, ω′]` is the damping matrix, the velocity columns of the same
/// dynamic rows (the gyroscopic part vanishes at rest, so it is `−∂Q/∂v`: contact damping,
/// damped SFORCEs). Velocities `[u, ω′]` and virtual displacements `[δr, δθ′]` are in the
/// same frames (world, body), so `C` adds column for column. The added term only changes the
/// Newton matrix, never the residual: it scales the iteration step, so the equilibrium that
/// Newton converges to is the same for every `stability`.
pub fn static_jacobian(
    system: &mut MultibodySystem,
    t: f64,
    y: &DVector<f64>,
    stability: f64,
) -> Result<DMatrix<f64>, EvaluationError> {
    let layout = *system.layout();
    let size = layout.size();
    let mut full = DMatrix::zeros(size, size);
    system.compute_newton_matrix(t, y, &DVector::zeros(size), 0.0, &mut full)?;
    let (n, m) = (layout.parts(), layout.constraint_rows());
    let dim = 6 * n + m;
    let rows: Vec<usize> = system
        .moving_parts()
        .flat_map(|p| (0..6).map(move |i| layout.velocity_offset(p) + i))
        .chain((0..m).map(|i| layout.position_constraint_offset() + i))
        .collect();
    let mut jacobian = DMatrix::zeros(dim, dim);
    for (k, part) in system.moving_parts().enumerate() {
        let qo = layout.position_offset(part);
        let e = system.parameters(y, part);
        let de_dtheta = g_matrix(&(e / e.norm())).transpose() * 0.5;
        for (i, &row) in rows.iter().enumerate() {
            for c in 0..3 {
                jacobian[(i, 6 * k + c)] = full[(row, qo + c)];
            }
            let by_parameter = full.fixed_view::<1, 4>(row, qo + 3) * de_dtheta;
            for c in 0..3 {
                jacobian[(i, 6 * k + 3 + c)] = by_parameter[c];
            }
        }
    }
    for (i, &row) in rows.iter().enumerate() {
        for j in 0..m {
            jacobian[(i, 6 * n + j)] = full[(row, layout.lambda_offset() + j)];
        }
    }
    if stability > 0.0 {
        let velocity_columns: Vec<usize> = system
            .moving_parts()
            .flat_map(|p| (0..6).map(move |i| layout.velocity_offset(p) + i))
            .collect();
        for (i, &row) in rows.iter().take(6 * n).enumerate() {
            for (j, &column) in velocity_columns.iter().enumerate() {
                jacobian[(i, j)] += stability * full[(row, column)];
            }
        }
        for (k, (mass, inertia)) in system.mass_properties().enumerate() {
            for c in 0..3 {
                jacobian[(6 * k + c, 6 * k + c)] += stability * mass;
            }
            let mut block = jacobian.fixed_view_mut::<3, 3>(6 * k + 3, 6 * k + 3);
            block += inertia * stability;
        }
    }
    Ok(jacobian)
}

/// Sets every velocity (and normalization multiplier) in `y` to zero.
pub fn zero_velocities(system: &MultibodySystem, y: &mut DVector<f64>) {
    let layout = system.layout();
    for part in system.moving_parts() {
        y.rows_mut(layout.velocity_offset(part), 6).fill(0.0);
        y[layout.mu_offset(part)] = 0.0;
    }
}

/// Applies a step `[δr, δθ′ per part, δλ]` to `y`, each part's translation clamped to
/// `tlimit` and rotation to `alimit`; returns the relative correction actually applied
/// (translations over `L`, rotations in radians).
fn apply_step(
    system: &MultibodySystem,
    y: &mut DVector<f64>,
    step: &DVector<f64>,
    tlimit: f64,
    alimit: f64,
) -> f64 {
    let layout = *system.layout();
    let n = layout.parts();
    let mut correction: f64 = 0.0;
    for (k, part) in system.moving_parts().enumerate() {
        let qo = layout.position_offset(part);
        let mut dr: Vector3<f64> = step.fixed_rows::<3>(6 * k).into_owned();
        let mut dtheta: Vector3<f64> = step.fixed_rows::<3>(6 * k + 3).into_owned();
        if dr.norm() > tlimit {
            dr *= tlimit / dr.norm();
        }
        if dtheta.norm() > alimit {
            dtheta *= alimit / dtheta.norm();
        }
        correction = correction
            .max(dr.norm() / system.length_scale())
            .max(dtheta.norm());
        for i in 0..3 {
            y[qo + i] += dr[i];
        }
        let rotation = rotation_of(&system.parameters(y, part))
            .unwrap_or_else(UnitQuaternion::identity)
            * UnitQuaternion::from_scaled_axis(dtheta);
        y.fixed_rows_mut::<4>(qo + 3)
            .copy_from(&parameters_of(&rotation));
    }
    let m = layout.constraint_rows();
    let mut lambda = y.rows_mut(layout.lambda_offset(), m);
    lambda += step.rows(6 * n, m);
    correction
}

/// The force elements that act at `y`: a nonzero load on some part, or (with `stiffness`) a
/// nonzero partial derivative (a spring at its free length acts through its stiffness).
fn acting_elements(
    system: &MultibodySystem,
    t: f64,
    y: &DVector<f64>,
    stiffness: bool,
) -> Result<Vec<bool>, EvaluationError> {
    let states = system.part_states(y)?;
    let view = StateView::new(&states);
    let loads = system.element_loads(t, &states)?;
    let mut acting = Vec::with_capacity(loads.len());
    for (element, loads) in system.forces.iter().zip(&loads) {
        let loaded = loads
            .iter()
            .any(|l| l.force_w.norm() > 0.0 || l.torque_w.norm() > 0.0);
        let stiff = stiffness && !loaded && {
            let partials = match element.partials(t, &view) {
                Some(p) => p?,
                None => difference_partials(element.as_ref(), t, &states, system.length_scale())?,
            };
            partials.amax() > 0.0
        };
        acting.push(loaded || stiff);
    }
    Ok(acting)
}

/// Newton from `y` (positions assembled, velocities zero) to equilibrium; `y` holds the last
/// iterate whatever the outcome.
///
/// With `guard_onsets`, a step after which a force element acts that did not act before it (a
/// contact coming into contact) stops Newton: the Jacobian had no stiffness for that element,
/// so the step is as long as TLIMIT allows and the penetration it makes is arbitrary (the
/// reference document's "excessive contact"); the quasi-dynamic method takes over.
pub fn solve(
    system: &mut MultibodySystem,
    t: f64,
    y: &mut DVector<f64>,
    settings: &StaticsSettings,
    guard_onsets: bool,
) -> Result<NewtonReport, NewtonFailure> {
    let fail = |iterations: usize, imbalance: f64, cause: String| NewtonFailure {
        iterations,
        imbalance,
        cause,
    };
    let mut last_correction = f64::INFINITY;
    let mut last_jacobian: Option<DMatrix<f64>> = None;
    let mut iterations = 0;
    loop {
        let r = static_residual(system, t, y)
            .map_err(|e| fail(iterations, f64::INFINITY, e.to_string()))?;
        let now = imbalance(system, &r);
        if !now.is_finite() {
            return Err(fail(iterations, now, "the residual is not finite".into()));
        }
        // At the round-off the stiffness leaves, a further step only chases that round-off:
        // in a neutral direction (a ball's rotation, stiff only through STABILITY) a torque of
        // 1e-16 moves the part by 1e-9, so the correction never reaches a tight ERROR.
        let floor = last_jacobian
            .as_ref()
            .map_or(0.0, |j| roundoff_imbalance(system, y, j));
        if now <= settings.imbalance.max(floor)
            && (last_correction <= settings.error || now <= floor)
        {
            return Ok(NewtonReport {
                iterations,
                imbalance: now,
            });
        }
        if iterations == settings.maxit {
            return Err(fail(
                iterations,
                now,
                format!(
                    "MAXIT = {} reached (last correction {last_correction:e}, ERROR {:e}; IMBALANCE {:e})",
                    settings.maxit, settings.error, settings.imbalance
                ),
            ));
        }
        let jacobian = static_jacobian(system, t, y, settings.stability)
            .map_err(|e| fail(iterations, now, e.to_string()))?;
        let step = jacobian
            .clone()
            .lu()
            .solve(&(-&r))
            .filter(|s| s.iter().all(|x| x.is_finite()))
            .ok_or_else(|| {
                fail(
                    iterations,
                    now,
                    "the static Jacobian is singular (a direction without stiffness: a part with no contact yet, or a neutral equilibrium; raise STABILITY or use EQUILIBRIUM/DYNAMIC)".into(),
                )
            })?;
        let acting_before = if guard_onsets {
            acting_elements(system, t, y, true).map_err(|e| fail(iterations, now, e.to_string()))?
        } else {
            Vec::new()
        };
        iterations += 1;
        last_correction = apply_step(system, y, &step, settings.tlimit, settings.alimit);
        last_jacobian = Some(jacobian);
        if guard_onsets {
            let acting = acting_elements(system, t, y, false)
                .map_err(|e| fail(iterations, f64::INFINITY, e.to_string()))?;
            let onset = acting
                .iter()
                .zip(&acting_before)
                .position(|(now, before)| *now && !*before);
            if let Some(k) = onset {
                return Err(fail(
                    iterations,
                    now,
                    format!(
                        "{} started acting during a Newton step taken without its stiffness",
                        system.forces[k].name()
                    ),
                ));
            }
        }
    }
}

impl MultibodySystem {
    /// Each moving part's mass and body inertia, in state order.
    pub fn mass_properties(&self) -> impl Iterator<Item = (f64, Matrix3<f64>)> + '_ {
        self.parts.iter().map(|p| (p.mass, p.inertia))
    }

    /// The largest speed of any part relative to the time scale `time_scale`: `|u|·T/L` and
    /// `|ω′|·T`, at `y`.
    pub fn relative_speed(&self, y: &DVector<f64>, time_scale: f64) -> f64 {
        self.moving_parts()
            .map(|part: PartId| {
                let vo = self.layout.velocity_offset(part);
                let u = Self::vector_at(y, vo).norm() * time_scale / self.length_scale;
                u.max(Self::vector_at(y, vo + 3).norm() * time_scale)
            })
            .fold(0.0, f64::max)
    }
}
