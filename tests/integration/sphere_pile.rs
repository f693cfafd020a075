//! The 64-sphere pile (`src/pile.rs`, `examples/sphere_pile/`): one layer of spheres, 0.11 m
//! apart, falls onto the floor and comes to rest side by side. Oracles written apart from the
//! solver: the static rest height `R − m·g/k` of a sphere on a linear IMPACT spring, the
//! spheres' unchanged horizontal positions (nothing pushes them sideways), and the same run
//! with the Newton matrix forced dense (the path every small model takes) and on two threads.

use contact::pile::{GRAVITY, MASS, RADIUS, STIFFNESS, SpherePile};
use contact::run::lower::{LoweredModel, lower};
use contact::solver::NewtonStorage;
use contact::solver::bdf::IntegratorSettings;
use contact::solver::contact_force::Analysis;
use contact::solver::mbs::PartState;
use contact::solver::parallel::Parallelism;
use contact::solver::simulate::{DynamicsSettings, RunSummary, simulate};

fn lowered() -> LoweredModel {
    let pile = SpherePile::new(64).unwrap();
    let loaded = crate::inline("pile_64.adm", &pile.dataset());
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in the pile".to_string());
    lower(
        &loaded.model,
        &engine_exact::ExactEngine,
        Analysis::Dynamics,
        &no_meshes,
    )
    .unwrap()
}

/// Runs the pile to `end` (ERROR 1e-4, the dataset's) and returns the spheres' last states.
fn run(end: f64, storage: Option<NewtonStorage>, threads: usize) -> (Vec<PartState>, RunSummary) {
    let mut model = lowered();
    model.system.set_newton_storage(storage);
    model
        .system
        .set_parallelism(Parallelism::with_threads(threads).unwrap());
    let settings = DynamicsSettings {
        start: 0.0,
        end,
        output_step: end,
        integrator: IntegratorSettings {
            error: 1e-4,
            ..IntegratorSettings::default()
        },
    };
    let mut last = Vec::new();
    let summary = simulate(
        &mut model.system,
        &model.contacts,
        &settings,
        &mut |frame| {
            last = model
                .parts
                .iter()
                .map(|(id, _)| frame.parts[id.0])
                .collect();
            Ok(())
        },
    )
    .unwrap();
    (last, summary)
}

#[test]
fn the_pile_of_64_comes_to_rest_on_the_floor_at_the_impact_penetration() {
    // The whole dataset's span: the last bounces die out between 1.5 s and 2 s.
    let (last, summary) = run(2.0, None, 1);
    let centres = SpherePile::new(64).unwrap().centres();
    assert_eq!(last.len(), 64);
    let squeeze = MASS * GRAVITY / STIFFNESS;
    let rest = RADIUS - squeeze;
    for (state, start) in last.iter().zip(&centres) {
        let p = state.pose_w.translation.vector;
        // Resting: on the spring's static deflection, to a hundredth of it.
        assert!((p.z - rest).abs() <= 1e-2 * squeeze, "{p:?} against {rest}");
        assert!(state.velocity_w.norm() <= 1e-4, "{:?}", state.velocity_w);
        // Straight down: the floor pushes only along z.
        assert!((p.x - start[0]).abs() <= 1e-9 && (p.y - start[1]).abs() <= 1e-9);
    }
    // The spheres never touch each other or the walls: every pair and wall contact is skipped
    // in most evaluations.
    let all = summary.broad_phase_evaluated + summary.broad_phase_skipped;
    assert!(
        summary.broad_phase_skipped as f64 >= 0.7 * all as f64,
        "{summary:?}"
    );
}

#[test]
fn the_sparse_run_is_the_dense_run_to_round_off_and_threads_change_no_bit() {
    let end = 0.15;
    let (sparse, _) = run(end, None, 1);
    let (dense, _) = run(end, Some(NewtonStorage::Dense), 1);
    let (two, _) = run(end, None, 2);
    for ((s, d), t) in sparse.iter().zip(&dense).zip(&two) {
        let (ps, pd) = (s.pose_w.translation.vector, d.pose_w.translation.vector);
        assert!(
            (ps - pd).norm() <= 1e-12 * pd.norm(),
            "{ps:?} against {pd:?}"
        );
        let scale = d.velocity_w.norm().max(1e-3);
        assert!((s.velocity_w - d.velocity_w).norm() <= 1e-9 * scale);
        assert_eq!(s.pose_w, t.pose_w);
        assert_eq!(s.velocity_w, t.velocity_w);
    }
}
