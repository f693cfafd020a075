//! The partials of a CONTACT's loads for the Newton matrix, from one engine query.
//!
//! [`ContactForce`] applies, per contact, `F = Fn(δ, δ̇)·n + F_t(v_t, Fn)` at the midpoint `p`
//! of the two surface points (`+F` on I, `−F` on J) and the friction torque `T(ω_n, Fn, A)·n`
//! (see [`crate::contact_force`]). [`compute_contact_partials`] linearizes that from the
//! contacts of one query at the state, with the contact's **geometry frozen**: the normal `n`,
//! the point `p` (as a material point of each body, lever arms `s_I = p − r_I`,
//! `s_J = p − r_J`) and the area `A` keep their values, and only the gap and the relative
//! velocity move:
//! ```text
//! d  = displacement of I's material point at p relative to J's   (d0 = 0)
//! δ  ≈ δ0 − n·d,      δ̇ = −n·ḋ,      v_t = (I − n nᵀ)·ḋ,      ω_n = n·(ω_I − ω_J)
//! ∂F/∂d = −(n + ∂F_t/∂Fn)·∂Fn/∂δ·nᵀ
//! ∂F/∂ḋ = −(n + ∂F_t/∂Fn)·∂Fn/∂δ̇·nᵀ + ∂F_t/∂v_t·(I − n nᵀ)
//! ∂T    = ∂T/∂Fn·(∂Fn/∂δ·∂δ + ∂Fn/∂δ̇·∂δ̇) + ∂T/∂ω_n·nᵀ·∂(ω_I − ω_J) + ∂T/∂v_t·(I − n nᵀ)·∂ḋ
//! ```
//! and `∂F_t/∂ω_n·nᵀ·∂(ω_I − ω_J)` added to `∂F`: slip and spin share one Coulomb budget
//! ([`contact_core::laws::SlipAndSpin`]).
//! with the force laws' analytic partials from `contact_core::laws` (IMPACT, POISSON, the
//! augmented-Lagrangian force at the current multipliers, Coulomb friction force and torque).
//! The chain rule to the parts' `(δr, θ, u, ω)` is [`point_pair_partials`]' with
//! `∂d/∂(r, θ) = (I, −s̃)` and `∂ḋ/∂(u, ω) = (I, −s̃)`.
//!
//! **What the frozen geometry leaves out** ([`GeometryTerms::ContactFrame`], the default): the
//! motion of the contact point over the surfaces as the poses change (it rolls: how far depends
//! on the curvatures, which an engine does not report), the turning of the normal (for two
//! spheres at centre distance `D`, `Fn·(I − n nᵀ)/D`), the lever arms' change and the change of
//! the area. Each is of order `Fn` or `|F_t|` per unit length or per radian, against the
//! contact stiffness `∂Fn/∂δ`, of order `Fn/δ`: a relative size of `δ/ℓ` (ℓ the lever arm or
//! radius of curvature), 1e-3 and below for stiff contacts. For a sphere on a plane the
//! normal-force partials are exact (its contact point does not move when the sphere turns
//! about its centre, and the normal is the plane's).
//!
//! [`GeometryTerms::MaterialPoints`] instead moves `p` with each body as a material point,
//! which adds the lever-arm term `∂(s × F)/∂θ = F̃ s̃` and the transport term
//! `∂ḋ/∂θ = −ω̃ s̃`: right for a contact at a body's vertex (a box corner), wrong for a smooth
//! surface whose contact point stays put when the body turns (a sphere about its centre).
//! Both are first-order-small against the contact stiffness; the tests in
//! `contact_partials/tests.rs` measure both against a central difference, and the default is
//! the one that is exact for a sphere on a plane.
//!
//! **Augmented Lagrangian.** The multipliers (and the compression work and deepest penetration
//! the restitution branch uses) change only between corrector passes and at accepted steps,
//! never inside one Newton iteration, so the force that Newton sees is a function of `(δ, δ̇)`
//! at fixed multipliers and the law's partials at the current multipliers are its exact
//! partials.
//!
//! **Fallbacks.** A contact that is an extended patch rather than a point (a face, a line or a
//! flat end: [`is_extended`]) has a tilt stiffness a frozen point cannot carry, so the element
//! is differenced. User force routines (NORMAL_ROUTINE / FRICTION_ROUTINE) have no analytic
//! partials: `None`, and the system differences the element. So does a query that fails (the
//! difference evaluates the element again and reports the error). The system-wide switch
//! [`crate::mbs::ForcePartials::Difference`] differences every element instead.

use crate::contact_force::{Analysis, ContactForce};
use crate::dae::EvaluationError;
use crate::mbs::quaternion::skew;
use crate::mbs::{ForceElement, StateView, point_pair_partials};
use contact_core::laws::NormalForce;
use contact_core::{FrictionModel, NormalModel};
use nalgebra::{DMatrix, Matrix3, RowVector3, Vector3};

/// Which geometric terms the linearization keeps (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GeometryTerms {
    /// The contact frame (point, normal, lever arms, area) held fixed: `Jᵀ·(K·J)` with `J`
    /// the material-point Jacobian at the contact point. Exact for a sphere on a plane.
    #[default]
    ContactFrame,
    /// The contact point moves with each body as a material point: adds the lever-arm and
    /// transport terms (exact for a body's vertex, spurious for a smooth surface).
    MaterialPoints,
}

/// The partials of `contact`'s loads at `state` in the layout of
/// [`crate::mbs::ForceElement::partials`] (12 × 24), from one engine query, with
/// [`GeometryTerms::ContactFrame`]. `None` for user force routines, when the query fails and
/// when a contact is an extended patch ([`is_extended`]): the system then differences the
/// element.
pub fn compute_contact_partials(
    contact: &ContactForce,
    t: f64,
    state: &StateView<'_>,
) -> Option<Result<DMatrix<f64>, EvaluationError>> {
    compute_contact_partials_with(contact, t, state, GeometryTerms::default())
}

/// [`compute_contact_partials`] with the geometric terms of `terms`.
pub fn compute_contact_partials_with(
    contact: &ContactForce,
    t: f64,
    state: &StateView<'_>,
    terms: GeometryTerms,
) -> Option<Result<DMatrix<f64>, EvaluationError>> {
    let (params, analysis) = contact.laws();
    if matches!(params.normal, NormalModel::User(_))
        || matches!(params.friction, FrictionModel::User(_))
    {
        return None;
    }
    let friction = match (&params.friction, analysis) {
        (FrictionModel::On(c), _) | (FrictionModel::DynamicsOnly(c), Analysis::Dynamics) => Some(c),
        _ => None,
    };
    let reports = contact.reports(t, state).ok()?;
    let (si, sj) = match contact.parts() {
        [i, j] => (state.part(*i), state.part(*j)),
        _ => return None,
    };
    let (r_i, r_j) = (si.pose_w.translation.vector, sj.pose_w.translation.vector);
    let material = terms == GeometryTerms::MaterialPoints;
    let (omega_i, omega_j) = if material {
        (si.angular_velocity_w, sj.angular_velocity_w)
    } else {
        (Vector3::zeros(), Vector3::zeros())
    };
    let levers = contact
        .parts()
        .iter()
        .filter(|id| !id.is_ground())
        .map(|id| state.part(*id).pose_w.translation.vector)
        .collect::<Vec<_>>();
    if reports
        .iter()
        .any(|r| r.normal_force > 0.0 && is_extended(&r.contact, &levers))
    {
        return None;
    }
    let mut out = DMatrix::zeros(12, 24);
    let mut one = DMatrix::zeros(12, 24);
    for (index, report) in reports.iter().enumerate() {
        let c = &report.contact;
        let p = c.midpoint_w().coords;
        let n = c.normal_w;
        let (s_i, s_j) = (p - r_i, p - r_j);
        let normal = normal_force(contact, index, c.penetration, report.penetration_rate);
        debug_assert_eq!(normal.force.to_bits(), report.normal_force.to_bits());
        if normal.force == 0.0 && normal.d_penetration == 0.0 && normal.d_rate == 0.0 {
            // Not touching, or separating fast enough that the law clamps to zero.
            continue;
        }
        // ∂Fn/∂d and ∂Fn/∂ḋ (rows).
        let fn_d: RowVector3<f64> = n.transpose() * -normal.d_penetration;
        let fn_v: RowVector3<f64> = n.transpose() * -normal.d_rate;
        let tangent = Matrix3::identity() - n * n.transpose();
        let v = si.point_velocity_w(&p) - sj.point_velocity_w(&p);
        let (along_fn, slip_partial, friction) = match friction {
            Some(law) => {
                let slip = v - n * n.dot(&v);
                let spin = (si.angular_velocity_w - sj.angular_velocity_w).dot(&n);
                let both = law.slip_and_spin(&slip, spin, normal.force, c.area);
                (
                    n + both.force.d_normal_force,
                    both.force.d_slip * tangent,
                    Some(both),
                )
            }
            None => (n, Matrix3::zeros(), None),
        };
        let k = along_fn * fn_d;
        let damping = along_fn * fn_v + slip_partial;
        let force = if material {
            n * report.normal_force + report.friction_force_w
        } else {
            Vector3::zeros()
        };
        point_pair_partials(
            &s_i, &s_j, &omega_i, &omega_j, &force, &k, &damping, &mut one,
        );
        out += &one;
        if let Some(both) = friction {
            let torque = both.torque;
            add_torque_partials(
                &mut out,
                &n,
                &(fn_d * torque.d_normal_force),
                &(fn_v * torque.d_normal_force + both.torque_d_slip.transpose() * tangent),
                torque.d_spin,
                [&s_i, &s_j],
                [&omega_i, &omega_j],
            );
            add_spin_force_partials(&mut out, &(both.force_d_spin * n.transpose()), [&s_i, &s_j]);
        }
    }
    Some(Ok(out))
}

/// How much larger than its shortest lever arm a contact's effective radius may be before its
/// frozen partials are refused (see [`is_extended`]).
pub const EXTENDED_PATCH_RATIO: f64 = 2.0;

/// Whether `contact` is an extended patch rather than a point: its effective radius of
/// relative curvature `ρ = A/(2π·δ)` (from `A ≈ 2π·ρ·δ` for smooth bodies; `r − δ/2` for a
/// sphere on a plane, `r₁r₂/(r₁ + r₂)` for two spheres, of the order of δ for a vertex)
/// exceeds [`EXTENDED_PATCH_RATIO`] times the distance from the nearest moving part's CM
/// (`cms_w`) to the contact point.
///
/// A point-like contact (ρ no larger than the lever arms) keeps its point under a small turn
/// of the bodies up to terms of order `δ/ρ`, as the frozen geometry assumes. On a face, a
/// line or a flat end (a box or a disk on a plane, a cylinder's side on a wall) the patch's
/// centroid runs across the patch as the bodies tilt and the patch's own tilt stiffness,
/// about `∂Fn/∂δ·R²/4` (`R² = A/π`), is missing from a single frozen point: without it a
/// box resting on its face has no rotational stiffness in the Newton matrix (measured: the
/// static Newton of `examples/box_rest` stops at MAXIT). Such contacts are differenced.
pub fn is_extended(contact: &contact_core::Contact, cms_w: &[Vector3<f64>]) -> bool {
    let p = contact.midpoint_w().coords;
    let lever = cms_w
        .iter()
        .map(|cm| (p - cm).norm())
        .fold(f64::INFINITY, f64::min);
    let delta = contact.penetration;
    if delta.is_nan() || delta <= 0.0 || !lever.is_finite() {
        return false;
    }
    contact.area > EXTENDED_PATCH_RATIO * lever * 2.0 * std::f64::consts::PI * delta
}

/// The normal force law of `contact` with its partials, as `ContactForce` evaluates it.
fn normal_force(contact: &ContactForce, index: usize, delta: f64, rate: f64) -> NormalForce {
    let (params, _) = contact.laws();
    match &params.normal {
        NormalModel::Impact(law) => law.force(delta, rate),
        NormalModel::Poisson { law, .. } => match contact.multipliers() {
            Some(m) => m.force(index, delta, rate),
            None => law.force(delta, rate),
        },
        NormalModel::User(_) => NormalForce::ZERO,
    }
}

/// Adds the partials of the friction torque `T·n` on I (and `−T·n` on J): `t_d`, `t_v` are
/// `∂T/∂d`, `∂T/∂ḋ` through Fn and `t_spin = ∂T/∂ω_n`. The material-point displacement and
/// velocity Jacobians are those of [`point_pair_partials`] (with its transport terms when
/// `omegas` are not zero).
fn add_torque_partials(
    out: &mut DMatrix<f64>,
    n: &Vector3<f64>,
    t_d: &RowVector3<f64>,
    t_v: &RowVector3<f64>,
    t_spin: f64,
    [s_i, s_j]: [&Vector3<f64>; 2],
    [omega_i, omega_j]: [&Vector3<f64>; 2],
) {
    let (skew_i, skew_j) = (skew(s_i), skew(s_j));
    let identity = Matrix3::identity();
    let zero = Matrix3::zeros();
    let dd = [identity, -skew_i, zero, zero, -identity, skew_j, zero, zero];
    let dv = [
        zero,
        -skew(omega_i) * skew_i,
        identity,
        -skew_i,
        zero,
        skew(omega_j) * skew_j,
        -identity,
        skew_j,
    ];
    let spin_row = n.transpose() * t_spin;
    for (block, (d, v)) in dd.iter().zip(dv.iter()).enumerate() {
        let mut dt = t_d * d + t_v * v;
        if block == 3 {
            dt += spin_row;
        } else if block == 7 {
            dt -= spin_row;
        }
        let dtorque = n * dt;
        let col = 3 * block;
        let mut on_i = out.fixed_view_mut::<3, 3>(3, col);
        on_i += dtorque;
        let mut on_j = out.fixed_view_mut::<3, 3>(9, col);
        on_j -= dtorque;
    }
}

/// Adds the friction force's dependence on the spin, `∂F/∂ω_n·nᵀ` (`df_spin`), to the
/// columns of `ω_I` (+) and `ω_J` (−): the force acts at `p` (`+F` on I with torque `s_I × F`,
/// `−F` on J with torque `−s_J × F`).
fn add_spin_force_partials(
    out: &mut DMatrix<f64>,
    df_spin: &Matrix3<f64>,
    [s_i, s_j]: [&Vector3<f64>; 2],
) {
    let (skew_i, skew_j) = (skew(s_i), skew(s_j));
    for (col, sign) in [(9, 1.0), (21, -1.0)] {
        let df = df_spin * sign;
        let mut force_i = out.fixed_view_mut::<3, 3>(0, col);
        force_i += df;
        let mut torque_i = out.fixed_view_mut::<3, 3>(3, col);
        torque_i += skew_i * df;
        let mut force_j = out.fixed_view_mut::<3, 3>(6, col);
        force_j -= df;
        let mut torque_j = out.fixed_view_mut::<3, 3>(9, col);
        torque_j -= skew_j * df;
    }
}

#[cfg(test)]
mod tests;
