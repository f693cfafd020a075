//! Andrews' squeezing mechanism: seven rigid bodies in a plane, an index-3 DAE of 27 unknowns
//! (Hairer & Wanner II, §VII.7; Bari IVP test set `andrews`, Mazzia & Magherini, release 2.4).
//! `y = (q, v, w, λ)`: seven angles `q`, their rates `v = q′`, accelerations `w = v′`, and six
//! multipliers; `M(q)·w = f(q, v) − Gᵀ(q)·λ`, `g(q) = 0`. Index: `q` 1, `v` 2, `w` and `λ` 3.
//! The reference at `t = 0.03` was computed by the test set's authors with PSIDE at 1e-14.

use super::difference_newton_matrix;
use crate::{DaeSystem, EvaluationError, VariableKind};
use nalgebra::{DMatrix, DVector, SMatrix, SVector};

// Masses, inertias and geometry of the mechanism (SI units), as in the problem description.
const M: [f64; 7] = [
    0.04325, 0.00365, 0.02373, 0.00706, 0.07050, 0.00706, 0.05498,
];
const I: [f64; 7] = [
    2.194e-6, 4.410e-7, 5.255e-6, 5.667e-7, 1.169e-5, 5.667e-7, 1.912e-5,
];
const XA: f64 = -0.06934;
const YA: f64 = -0.00227;
const XB: f64 = -0.03635;
const YB: f64 = 0.03273;
const XC: f64 = 0.014;
const YC: f64 = 0.072;
const C0: f64 = 4530.0;
const D: f64 = 28e-3;
const DA: f64 = 115e-4;
const E: f64 = 2e-2;
const EA: f64 = 1421e-5;
const RR: f64 = 7e-3;
const RA: f64 = 92e-5;
const L0: f64 = 7785e-5;
const SS: f64 = 35e-3;
const SA: f64 = 1874e-5;
const SB: f64 = 1043e-5;
const SC: f64 = 18e-3;
const SD: f64 = 2e-2;
const TA: f64 = 2308e-5;
const TB: f64 = 916e-5;
const U: f64 = 4e-2;
const UA: f64 = 1228e-5;
const UB: f64 = 449e-5;
const ZF: f64 = 2e-2;
const ZT: f64 = 4e-2;
const FA: f64 = 1421e-5;
const MOM: f64 = 33e-3;

/// Reference angles `q(0.03)` (test set, PSIDE at tolerance 1e-14).
pub const ANDREWS_ANGLES_AT_0_03: [f64; 7] = [
    0.1581077119629904e2,
    -0.1575637105984298e2,
    0.4082224013073101e-1,
    -0.5347301163226948,
    0.5244099658805304,
    0.5347301163226948,
    0.1048080741042263e1,
];

/// Consistent initial values of the test set: angles, and the non-zero accelerations and
/// multipliers (velocities are zero).
const Q0: [f64; 7] = [
    -0.06171389001427645,
    0.0,
    0.45527981916307037,
    0.22266839016588588,
    0.48736497954384256,
    -0.22266839016588588,
    1.2305474445498212,
];
const W0: [f64; 7] = [
    14222.443919954114,
    -10666.832939965585,
    0.0,
    0.0,
    0.0,
    0.0,
    0.0,
];
const LAMBDA0: [f64; 6] = [98.56687039624109, -6.122688344255662, 0.0, 0.0, 0.0, 0.0];

/// The mechanism as a [`DaeSystem`] of 27 unknowns; its Newton matrix comes from
/// [`difference_newton_matrix`].
pub struct Andrews;

/// Mass matrix, applied forces, constraint Jacobian and constraints at angles `q` and rates `v`.
pub(crate) fn mechanics(
    q: &[f64],
    v: &[f64],
) -> (
    SMatrix<f64, 7, 7>,
    SVector<f64, 7>,
    SMatrix<f64, 6, 7>,
    SVector<f64, 6>,
) {
    let (be, th, ga, ph, de, om, ep) = (q[0], q[1], q[2], q[3], q[4], q[5], q[6]);
    let (bep, thp, php, dep, omp, epp) = (v[0], v[1], v[3], v[4], v[5], v[6]);
    let [m1, m2, m3, m4, m5, m6, m7] = M;
    let [i1, i2, i3, i4, i5, i6, i7] = I;
    let mut mass = SMatrix::<f64, 7, 7>::zeros();
    mass[(0, 0)] = m1 * RA * RA + m2 * (RR * RR - 2.0 * DA * RR * th.cos() + DA * DA) + i1 + i2;
    mass[(1, 0)] = m2 * (DA * DA - DA * RR * th.cos()) + i2;
    mass[(1, 1)] = m2 * DA * DA + i2;
    mass[(2, 2)] = m3 * (SA * SA + SB * SB) + i3;
    let (e_ea, zf_fa) = (E - EA, ZF - FA);
    mass[(3, 3)] = m4 * e_ea * e_ea + i4;
    mass[(4, 3)] = m4 * (e_ea * e_ea + ZT * e_ea * ph.sin()) + i4;
    mass[(4, 4)] = m4 * (ZT * ZT + 2.0 * ZT * e_ea * ph.sin() + e_ea * e_ea)
        + m5 * (TA * TA + TB * TB)
        + i4
        + i5;
    mass[(5, 5)] = m6 * zf_fa * zf_fa + i6;
    mass[(6, 5)] = m6 * (zf_fa * zf_fa - U * zf_fa * om.sin()) + i6;
    mass[(6, 6)] = m6 * (zf_fa * zf_fa - 2.0 * U * zf_fa * om.sin() + U * U)
        + m7 * (UA * UA + UB * UB)
        + i6
        + i7;
    for j in 1..7 {
        for i in 0..j {
            mass[(i, j)] = mass[(j, i)];
        }
    }
    // The spring between the point D of body 3 and the fixed point C.
    let xd = SD * ga.cos() + SC * ga.sin() + XB;
    let yd = SD * ga.sin() - SC * ga.cos() + YB;
    let length = ((xd - XC).powi(2) + (yd - YC).powi(2)).sqrt();
    let tension = -C0 * (length - L0) / length;
    let (fx, fy) = (tension * (xd - XC), tension * (yd - YC));
    let force = SVector::<f64, 7>::from([
        MOM - m2 * DA * RR * thp * (thp + 2.0 * bep) * th.sin(),
        m2 * DA * RR * bep * bep * th.sin(),
        fx * (SC * ga.cos() - SD * ga.sin()) + fy * (SD * ga.cos() + SC * ga.sin()),
        m4 * ZT * e_ea * dep * dep * ph.cos(),
        -m4 * ZT * e_ea * php * (php + 2.0 * dep) * ph.cos(),
        -m6 * U * zf_fa * epp * epp * om.cos(),
        m6 * U * zf_fa * omp * (omp + 2.0 * epp) * om.cos(),
    ]);
    let (sbt, cbt) = ((be + th).sin(), (be + th).cos());
    let (spd, cpd) = ((ph + de).sin(), (ph + de).cos());
    let (soe, coe) = ((om + ep).sin(), (om + ep).cos());
    let mut gq = SMatrix::<f64, 6, 7>::zeros();
    for r in [0, 2, 4] {
        gq[(r, 0)] = -RR * be.sin() + D * sbt;
        gq[(r, 1)] = D * sbt;
        gq[(r + 1, 0)] = RR * be.cos() - D * cbt;
        gq[(r + 1, 1)] = -D * cbt;
    }
    gq[(0, 2)] = -SS * ga.cos();
    gq[(1, 2)] = -SS * ga.sin();
    gq[(2, 3)] = -E * cpd;
    gq[(2, 4)] = -E * cpd + ZT * de.sin();
    gq[(3, 3)] = -E * spd;
    gq[(3, 4)] = -E * spd - ZT * de.cos();
    gq[(4, 5)] = ZF * soe;
    gq[(4, 6)] = ZF * soe - U * ep.cos();
    gq[(5, 5)] = -ZF * coe;
    gq[(5, 6)] = -ZF * coe - U * ep.sin();
    let base_x = RR * be.cos() - D * cbt;
    let base_y = RR * be.sin() - D * sbt;
    let g = SVector::<f64, 6>::from([
        base_x - SS * ga.sin() - XB,
        base_y + SS * ga.cos() - YB,
        base_x - E * spd - ZT * de.cos() - XA,
        base_y + E * cpd - ZT * de.sin() - YA,
        base_x - ZF * coe - U * ep.sin() - XA,
        base_y - ZF * soe + U * ep.cos() - YA,
    ]);
    (mass, force, gq, g)
}

impl DaeSystem for Andrews {
    fn size(&self) -> usize {
        27
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        let mut kinds = vec![VariableKind::Differential; 7];
        kinds.extend([VariableKind::Algebraic { index: 2 }; 7]);
        kinds.extend([VariableKind::Algebraic { index: 3 }; 13]);
        kinds
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        let (mass, force, gq, g) = mechanics(&y.as_slice()[0..7], &y.as_slice()[7..14]);
        for i in 0..14 {
            out[i] = yp[i] - y[i + 7];
        }
        let w = SVector::<f64, 7>::from_column_slice(&y.as_slice()[14..21]);
        let lambda = SVector::<f64, 6>::from_column_slice(&y.as_slice()[21..27]);
        let dynamics = mass * w - force + gq.transpose() * lambda;
        out.rows_mut(14, 7).copy_from(&dynamics);
        out.rows_mut(21, 6).copy_from(&g);
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        difference_newton_matrix(self, t, y, yp, c, out)
    }
}

impl Andrews {
    /// The test set's consistent initial state `y(0)` and `y′(0)`.
    pub fn initial_state() -> (DVector<f64>, DVector<f64>) {
        let mut y0 = DVector::zeros(27);
        y0.rows_mut(0, 7).copy_from_slice(&Q0);
        y0.rows_mut(14, 7).copy_from_slice(&W0);
        y0.rows_mut(21, 6).copy_from_slice(&LAMBDA0);
        let mut yp0 = DVector::zeros(27);
        // q′ = v = 0, v′ = w.
        yp0.rows_mut(7, 7).copy_from_slice(&W0);
        (y0, yp0)
    }

    /// The largest constraint residual |g_i(q)| (metres) at the state `y`.
    pub fn constraint_residual(y: &DVector<f64>) -> f64 {
        let (_, _, _, g) = mechanics(&y.as_slice()[0..7], &y.as_slice()[7..14]);
        g.amax()
    }
}
