//! Whole-integration benches of the BDF integrator on the reference problems: Robertson to
//! t = 1e11 (stiff, 3 unknowns), Andrews' squeezing mechanism to t = 0.03 (index 3, 27
//! unknowns, difference Newton matrix), and the integrator's share of the issue-7 speed target:
//! a 1 kg ball dropped 1 m on a plane under IMPACT (k = 1e6 N/m, e = 1) for 2 s, as a 1-DOF
//! system with contact-onset prediction (no geometry engine). Each prints its step counts once, so the cost per step
//! can be read next to the time. Short profile (10 samples, 2 s) to stay cheap in CI.

use contact::solver::bdf::reference::{Andrews, Robertson};
use contact::solver::bdf::{Bdf, IntegratorSettings, IntegratorStats};
use contact::solver::{DaeSystem, EvaluationError, VariableKind};
use contact_core::laws::{ImpactLaw, ImpactParams};
use criterion::{BenchmarkId, Criterion};
use nalgebra::{DMatrix, DVector};
use std::time::Duration;

fn integrate(
    system: &mut dyn DaeSystem,
    y0: &DVector<f64>,
    yp0: &DVector<f64>,
    end: f64,
    error: f64,
) -> IntegratorStats {
    let settings = IntegratorSettings {
        error,
        ..IntegratorSettings::default()
    };
    let mut bdf = Bdf::new(system, 0.0, y0.clone(), yp0.clone(), settings).unwrap();
    bdf.set_stop_time(Some(end)).unwrap();
    while bdf.t() < end {
        bdf.step(system).unwrap();
    }
    *bdf.stats()
}

fn robertson(c: &mut Criterion) {
    let mut group = c.benchmark_group("bdf/robertson_to_1e11");
    let y0 = DVector::from_vec(vec![1.0, 0.0, 0.0]);
    let yp0 = DVector::from_vec(vec![-0.04, 0.04, 0.0]);
    for error in [1e-6, 1e-10] {
        let stats = integrate(&mut Robertson { as_dae: false }, &y0, &yp0, 1e11, error);
        eprintln!("robertson ERROR={error:e}: {stats:?}");
        group.bench_with_input(BenchmarkId::new("error", error), &error, |b, &error| {
            b.iter(|| integrate(&mut Robertson { as_dae: false }, &y0, &yp0, 1e11, error))
        });
    }
    group.finish();
}

fn andrews(c: &mut Criterion) {
    let mut group = c.benchmark_group("bdf/andrews_to_0.03");
    let (y0, yp0) = Andrews::initial_state();
    for error in [1e-4, 1e-6] {
        let stats = integrate(&mut Andrews, &y0, &yp0, 0.03, error);
        eprintln!("andrews ERROR={error:e}: {stats:?}");
        group.bench_with_input(BenchmarkId::new("error", error), &error, |b, &error| {
            b.iter(|| integrate(&mut Andrews, &y0, &yp0, 0.03, error))
        });
    }
    group.finish();
}

/// The ball: `z′ = v`, `v′ = −g + Fn(δ, δ̇)/m` with `δ = r − z` (plane at z = 0, radius r).
struct Ball {
    law: ImpactLaw,
}
const GRAVITY: f64 = 9.81;
const RADIUS: f64 = 0.1;

impl DaeSystem for Ball {
    fn size(&self) -> usize {
        2
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![VariableKind::Differential; 2]
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        let force = self.law.force(RADIUS - y[0], -y[1]).force;
        out[0] = yp[0] - y[1];
        out[1] = yp[1] + GRAVITY - force;
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        let law = self.law.force(RADIUS - y[0], -y[1]);
        out[(0, 0)] = c;
        out[(0, 1)] = -1.0;
        out[(1, 0)] = law.d_penetration;
        out[(1, 1)] = c + law.d_rate;
        Ok(())
    }
}

/// Drops the ball from 1 m for 2 s with onset prediction: a step that ends in a contact that
/// was open at its start is rolled back and retried to `t − δ/δ̇` (or to a quarter of its
/// length while the estimate is unusable) until the entry penetration is below 1e-6·r; returns
/// the stats and the apex heights (from dense output).
fn drop_ball(error: f64) -> (IntegratorStats, Vec<f64>) {
    let mut ball = Ball {
        law: ImpactLaw::from_params(ImpactParams {
            stiffness: 1e6,
            exponent: 1.0,
            damping: 10.0,
            max_penetration: 1e-4,
        })
        .unwrap(),
    };
    let settings = IntegratorSettings {
        error,
        ..IntegratorSettings::default()
    };
    let y0 = DVector::from_vec(vec![1.0 + RADIUS, 0.0]);
    let yp0 = DVector::from_vec(vec![0.0, -GRAVITY]);
    let mut bdf = Bdf::new(&ball, 0.0, y0, yp0, settings).unwrap();
    bdf.set_stop_time(Some(2.0)).unwrap();
    let (mut in_contact, mut apexes) = (false, Vec::new());
    while bdf.t() < 2.0 {
        let v_before = bdf.y()[1];
        bdf.step(&mut ball).unwrap();
        let mut retries = 0;
        while !in_contact && bdf.y()[0] < RADIUS * (1.0 - 1e-6) && retries < 30 {
            let (t0, t1) = (bdf.t_previous(), bdf.t());
            let (delta, rate) = (RADIUS - bdf.y()[0], -bdf.y()[1]);
            let estimate = t1 - delta / rate;
            let target = if rate > 0.0 && estimate > t0 {
                estimate + 1e-9 * (t1 - t0)
            } else {
                t0 + 0.25 * (t1 - t0)
            };
            bdf.reject_last_step_and_retry_to(&mut ball, target)
                .unwrap();
            retries += 1;
        }
        if !in_contact && bdf.y()[0] < RADIUS {
            in_contact = true;
            bdf.request_newton_matrix();
        } else if in_contact && bdf.y()[0] > RADIUS {
            in_contact = false;
        }
        if v_before > 0.0 && bdf.y()[1] <= 0.0 {
            // Apex: v = 0 inside the step, located by bisection on the interpolant.
            let (mut a, mut b) = (bdf.t_previous(), bdf.t());
            for _ in 0..50 {
                let mid = 0.5 * (a + b);
                if bdf.interpolate(mid).unwrap().0[1] > 0.0 {
                    a = mid
                } else {
                    b = mid
                }
            }
            apexes.push(bdf.interpolate(a).unwrap().0[0] - RADIUS);
        }
    }
    (*bdf.stats(), apexes)
}

fn ball(c: &mut Criterion) {
    let mut group = c.benchmark_group("bdf/ball_1dof_impact_2s");
    for error in [1e-6, 1e-8] {
        let (stats, apexes) = drop_ball(error);
        eprintln!("ball ERROR={error:e}: apexes {apexes:?}; {stats:?}");
        group.bench_with_input(BenchmarkId::new("error", error), &error, |b, &error| {
            b.iter(|| drop_ball(error))
        });
    }
    group.finish();
}

fn main() {
    // criterion_group!/criterion_main! expand to an undocumented `pub fn`; this is their body.
    let mut criterion = Criterion::default()
        .sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .configure_from_args();
    robertson(&mut criterion);
    andrews(&mut criterion);
    ball(&mut criterion);
    criterion.final_summary();
}
