//! One Newton-matrix evaluation and factorisation of the sphere pile (`src/pile.rs`) at 64 and
//! 512 spheres (`n = 896` and `7168` unknowns), dense (nalgebra's LU of the `n × n` matrix)
//! against sparse (triplets, compressed columns, rsparse's LU), at the initial state with the
//! integrator's `c = 1/h` for `h = 1e-3`, each time into a fresh matrix (so the sparse time
//! includes the triplet sort and the AMD ordering that a run does only when the pattern
//! changes). Both factorisations solve the same right-hand side and the bench checks they
//! agree to 1e-9 relative before timing.
//!
//! The dense factorisation at 512 spheres takes minutes (`⅔n³ ≈ 2.5·10¹¹` operations), too
//! long for criterion's ten samples: it is timed once and printed. Short profile (10 samples,
//! 2 s) otherwise. The group `newton_matrix/chain` times both on pendulum chains of 2 to 64
//! links for the dense/sparse crossover.

use contact::pile::SpherePile;
use contact::run::lower::{LoweredModel, lower};
use contact::solver::bdf::NewtonMatrix;
use contact::solver::contact_force::Analysis;
use contact::solver::{DaeSystem, NewtonStorage};
use criterion::{BenchmarkId, Criterion};
use nalgebra::DVector;
use std::time::{Duration, Instant};

/// The step the matrix is built for.
const H: f64 = 1e-3;

/// The pile of `count` spheres, lowered with the exact engine, and its initial state.
fn pile(count: usize) -> (LoweredModel, DVector<f64>, DVector<f64>) {
    let pile = SpherePile::new(count).unwrap();
    lowered(&pile.dataset(), "pile.adm")
}

/// The dataset `text` (no meshes) lowered with the exact engine for dynamics, and its initial
/// state.
fn lowered(text: &str, name: &str) -> (LoweredModel, DVector<f64>, DVector<f64>) {
    let loaded = contact::dataset::read_str(text, name, None);
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let no_meshes = |_: &contact::model::MeshFile| Err(format!("no meshes in {name}"));
    let model = lower(
        &loaded.model,
        &engine_exact::ExactEngine,
        Analysis::Dynamics,
        &no_meshes,
    )
    .unwrap();
    let initial = model.system.compute_initial_state(0.0).unwrap();
    (model, initial.y, initial.yp)
}

/// Evaluates and factorises the matrix stored as `storage`.
fn factorise(
    model: &mut LoweredModel,
    storage: NewtonStorage,
    y: &DVector<f64>,
    yp: &DVector<f64>,
) -> NewtonMatrix {
    model.system.set_newton_storage(Some(storage));
    let kinds = model.system.variable_kinds();
    let mut matrix = NewtonMatrix::new(y.len());
    matrix
        .refresh(&mut model.system, 0.0, y, yp, 1.0 / H, H, &kinds)
        .unwrap();
    matrix
}

/// The solution of `J·Δ = r` for a fixed `r`.
fn solution(matrix: &NewtonMatrix, n: usize) -> DVector<f64> {
    let mut r = DVector::from_fn(n, |i, _| (0.37 * i as f64).sin());
    assert!(matrix.solve(&mut r));
    r
}

fn newton(c: &mut Criterion) {
    let mut group = c.benchmark_group("newton_matrix/pile");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    for count in [64, 512] {
        let (mut model, y, yp) = pile(count);
        let n = y.len();
        let sparse = solution(&factorise(&mut model, NewtonStorage::Sparse, &y, &yp), n);
        let start = Instant::now();
        let dense = factorise(&mut model, NewtonStorage::Dense, &y, &yp);
        let dense_once = start.elapsed();
        let dense = solution(&dense, n);
        let gap = (&dense - &sparse).norm() / dense.norm();
        eprintln!(
            "pile {count}: n = {n}; dense once {:.3} s; sparse and dense solutions differ by {gap:.1e} relative",
            dense_once.as_secs_f64()
        );
        assert!(gap <= 1e-9, "pile {count}: {gap:e}");
        group.bench_with_input(BenchmarkId::new("sparse", count), &count, |b, _| {
            b.iter(|| factorise(&mut model, NewtonStorage::Sparse, &y, &yp))
        });
        if count <= 64 {
            group.bench_with_input(BenchmarkId::new("dense", count), &count, |b, _| {
                b.iter(|| factorise(&mut model, NewtonStorage::Dense, &y, &yp))
            });
        }
    }
    group.finish();
}

/// A chain of `links` unit rods hanging from the ground on REVOLUTE joints (parallel axes),
/// lowered, and its initial state: a model whose Newton matrix grows with `links` while each
/// row stays short, to find where the sparse factorisation overtakes the dense one.
fn chain(links: usize) -> (LoweredModel, DVector<f64>, DVector<f64>) {
    let mut text = String::from(
        "chain\nUNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
         PART/1, GROUND\nMARKER/10, PART = 1, REULER = 0, 90D, 0\n",
    );
    for k in 0..links {
        let part = 2 + k;
        let x = k as f64;
        text.push_str(&format!(
            "PART/{part}, MASS = 1, CM = {part}0, IP = 0.1, 0.1, 1E-3\n\
             MARKER/{part}0, PART = {part}, QP = {}, 0, 0\n\
             MARKER/{part}1, PART = {part}, QP = {x}, 0, 0, REULER = 0, 90D, 0\n\
             MARKER/{part}2, PART = {part}, QP = {}, 0, 0, REULER = 0, 90D, 0\n",
            x + 0.5,
            x + 1.0
        ));
        let j = if k == 0 { 10 } else { (part - 1) * 10 + 2 };
        text.push_str(&format!("JOINT/{part}, REVOLUTE, I = {part}1, J = {j}\n"));
    }
    text.push_str("ACCGRAV/ KGRAV = -9.81\nEND\n");
    lowered(&text, "chain.adm")
}

/// Dense against sparse on chains of 2 to 64 links: the crossover behind
/// `contact_solver::mbs::SPARSE_FROM_SIZE`.
fn crossover(c: &mut Criterion) {
    let mut group = c.benchmark_group("newton_matrix/chain");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    for links in [2, 4, 8, 16, 32, 64] {
        let (mut model, y, yp) = chain(links);
        let n = y.len();
        let sparse = solution(&factorise(&mut model, NewtonStorage::Sparse, &y, &yp), n);
        let dense = solution(&factorise(&mut model, NewtonStorage::Dense, &y, &yp), n);
        let gap = (&dense - &sparse).norm() / dense.norm();
        eprintln!("chain {links}: n = {n}; sparse and dense differ by {gap:.1e} relative");
        assert!(gap <= 1e-9, "chain {links}: {gap:e}");
        for (name, storage) in [
            ("sparse", NewtonStorage::Sparse),
            ("dense", NewtonStorage::Dense),
        ] {
            group.bench_with_input(BenchmarkId::new(name, n), &n, |b, _| {
                b.iter(|| factorise(&mut model, storage, &y, &yp))
            });
        }
    }
    group.finish();
}

fn main() {
    let mut criterion = Criterion::default().configure_from_args();
    crossover(&mut criterion);
    newton(&mut criterion);
    criterion.final_summary();
}
