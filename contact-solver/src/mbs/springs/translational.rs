//! A translational spring-damper acting along the line between two markers.

use super::SpringParams;
use crate::dae::EvaluationError;
use crate::mbs::error::MbsError;
use crate::mbs::force::{ForceElement, Load, StateView, point_pair_partials};
use crate::mbs::part::PartId;
use nalgebra::{DMatrix, Matrix3, Vector3};

/// A spring-damper between point I on one part and point J on another.
///
/// With `d = p_I − p_J`, `l = |d|`, `n = d/l` and `l̇ = n·ḋ`, the force on I is
/// `f = −(k(l − l₀) + c·l̇ − F₀)·n` (Adams SPRINGDAMPER, positive `F₀` pushes apart) and J gets
/// `−f`; each force acts at its point, so parts also get the moment about their CM.
/// Partials are analytic: `∂f/∂d = −n(k nᵀ + c ḋᵀP/l) − s·P/l` and `∂f/∂ḋ = −c n nᵀ`,
/// `P = I − n nᵀ`, `s = k(l − l₀) + c l̇ − F₀`.
///
/// **Degenerate case:** when `l ≤ 1e-12·l₀` (or `l = 0` for `l₀ = 0`) the direction is
/// undefined and evaluation fails with an error naming the element.
#[derive(Debug, Clone)]
pub struct TranslationalSpringDamper {
    name: String,
    parts: [PartId; 2],
    point_i: Vector3<f64>,
    point_j: Vector3<f64>,
    params: SpringParams,
}

impl TranslationalSpringDamper {
    /// A spring from `point_i` (in part `part_i`'s CM frame) to `point_j` (in `part_j`'s).
    pub fn new(
        name: impl Into<String>,
        part_i: PartId,
        point_i: Vector3<f64>,
        part_j: PartId,
        point_j: Vector3<f64>,
        params: SpringParams,
    ) -> Result<Self, MbsError> {
        let name = name.into();
        params.validate(&name, true)?;
        if part_i == part_j {
            return Err(MbsError::SamePart {
                element: name,
                part: part_i.0,
            });
        }
        Ok(Self {
            name,
            parts: [part_i, part_j],
            point_i,
            point_j,
            params,
        })
    }

    /// The geometry at `state`: `(s_I, s_J, d, ḋ)`, world frame.
    fn kinematics(&self, state: &StateView<'_>) -> [Vector3<f64>; 4] {
        let (a, b) = (state.part(self.parts[0]), state.part(self.parts[1]));
        let s_i = a.pose_w.rotation * self.point_i;
        let s_j = b.pose_w.rotation * self.point_j;
        let d = a.pose_w.translation.vector + s_i - b.pose_w.translation.vector - s_j;
        let d_dot = a.velocity_w + a.angular_velocity_w.cross(&s_i)
            - b.velocity_w
            - b.angular_velocity_w.cross(&s_j);
        [s_i, s_j, d, d_dot]
    }

    /// `(n, l, s)` with the degenerate-length check.
    fn law(
        &self,
        d: &Vector3<f64>,
        d_dot: &Vector3<f64>,
    ) -> Result<(Vector3<f64>, f64, f64), EvaluationError> {
        let length = d.norm();
        let p = &self.params;
        if length <= 1e-12 * p.free_length || length == 0.0 {
            return Err(EvaluationError {
                element: self.name.clone(),
                message: format!(
                    "the spring's points coincide (length {length:e}); its direction is undefined"
                ),
                fatal: false,
            });
        }
        let n = d / length;
        let s = p.stiffness * (length - p.free_length) + p.damping * n.dot(d_dot) - p.preload;
        Ok((n, length, s))
    }
}

impl ForceElement for TranslationalSpringDamper {
    fn name(&self) -> &str {
        &self.name
    }

    fn parts(&self) -> &[PartId] {
        &self.parts
    }

    fn evaluate(
        &self,
        _t: f64,
        state: &StateView<'_>,
        loads: &mut [Load],
    ) -> Result<(), EvaluationError> {
        let [s_i, s_j, d, d_dot] = self.kinematics(state);
        let (n, _, s) = self.law(&d, &d_dot)?;
        let force = -n * s;
        loads[0] = Load {
            force_w: force,
            torque_w: s_i.cross(&force),
        };
        loads[1] = Load {
            force_w: -force,
            torque_w: -s_j.cross(&force),
        };
        Ok(())
    }

    fn partials(
        &self,
        _t: f64,
        state: &StateView<'_>,
    ) -> Option<Result<DMatrix<f64>, EvaluationError>> {
        let [s_i, s_j, d, d_dot] = self.kinematics(state);
        let (n, length, s) = match self.law(&d, &d_dot) {
            Ok(law) => law,
            Err(error) => return Some(Err(error)),
        };
        let p = &self.params;
        let projector = Matrix3::identity() - n * n.transpose();
        let k = -n
            * (n.transpose() * p.stiffness
                + (d_dot.transpose() * projector) * (p.damping / length))
            - projector * (s / length);
        let c = -(n * n.transpose()) * p.damping;
        let mut out = DMatrix::zeros(12, 24);
        let omega_a = state.part(self.parts[0]).angular_velocity_w;
        let omega_b = state.part(self.parts[1]).angular_velocity_w;
        point_pair_partials(&s_i, &s_j, &omega_a, &omega_b, &(-n * s), &k, &c, &mut out);
        Some(Ok(out))
    }
}
