//! Whole-integration benches of the BDF integrator on the reference problems: Robertson to
//! t = 1e11 (stiff, 3 unknowns) and Andrews' squeezing mechanism to t = 0.03 (index 3, 27
//! unknowns, difference Newton matrix). Each prints its step counts once, so the cost per step
//! can be read next to the time. Short profile (10 samples, 2 s) to stay cheap in CI.

use contact::solver::DaeSystem;
use contact::solver::bdf::reference::{Andrews, Robertson};
use contact::solver::bdf::{Bdf, IntegratorSettings, IntegratorStats};
use criterion::{BenchmarkId, Criterion};
use nalgebra::DVector;
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

fn main() {
    // criterion_group!/criterion_main! expand to an undocumented `pub fn`; this is their body.
    let mut criterion = Criterion::default()
        .sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .configure_from_args();
    robertson(&mut criterion);
    andrews(&mut criterion);
    criterion.final_summary();
}
