//! Per-pair query cost of the exact engine, side by side with parry on the same pair where
//! parry has the shapes (spheres, boxes, cylinders, cones, unbounded planes, meshes).
//!
//! `cargo bench --bench exact_pairs` (release). The pairs are the reference scenes
//! ([`contact::scenes::suite`]) and the kernel scenes ([`contact::scenes::kernel_scenes`]: one
//! characteristic configuration per path of the exact engine's dispatch), each timed at one
//! pose: the first touching pose at or past a tenth of the scene's scale in nominal depth.
//! Each group `contact/<scene>` has the ids `exact` (a prepared pair's full `query`: pose
//! composition, dispatch, the kernel, the push into a reused buffer) and `parry`
//! ([`contact::peer::ParryPeerEngine`] behind the same trait where it takes the pair; parry's
//! `contact` on a primitive and a `TriMesh` otherwise). Before timing, each group prints both
//! answers' depths beside the scene's closed form where it has one, so speed and accuracy are
//! read together.

#![expect(
    missing_docs,
    reason = "criterion_group! generates an undocumented public function"
)]

use contact::peer::ParryPeerEngine;
use contact::peer::primitives::{self, PeerShape};
use contact::scenes::{self, Scene, ScenePose};
use contact_core::{
    Contact, Geometry, GeometryEngine, GeometryInstance, Isometry3, PreparedPair, WorkCounters,
};
use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, Criterion, criterion_group, criterion_main};
use engine_exact::ExactEngine;
use std::hint::black_box;
use std::time::Duration;

/// The pose a scene is timed at, with the exact engine's answer there.
fn timed_pose<'a>(scene: &'a Scene, pair: &dyn PreparedPair) -> Option<(&'a ScenePose, Contact)> {
    let mut buffer = Vec::new();
    let mut work = WorkCounters::default();
    scene
        .poses
        .iter()
        .filter(|p| p.nominal_depth >= 0.1 * scene.scale)
        .find_map(|p| {
            buffer.clear();
            pair.query(&p.pose_world_i, &p.pose_world_j, &mut buffer, &mut work)
                .ok()?;
            buffer.first().map(|c| (p, *c))
        })
}

/// parry on a scene's pair: its peer engine, or its `contact` query on one shape a side.
enum Peer {
    Engine(Box<dyn PreparedPair>),
    Shapes(Box<[(PeerShape, Isometry3); 2]>),
}

impl Peer {
    /// The peer engine where it takes the pair, else parry's shapes for one primitive or mesh
    /// a side (parry's `TriMesh`, which the trade's peer keeps out of its primitive pairs).
    fn new(scene: &Scene) -> Option<Self> {
        if let Ok(pair) = ParryPeerEngine.prepare(&scene.i, &scene.j) {
            return Some(Self::Engine(pair));
        }
        let shape = |list: &[GeometryInstance]| match list {
            [g] if !g.flip_normal => match &*g.geometry {
                Geometry::Mesh(m) => PeerShape::mesh(m),
                other => PeerShape::new(other, false),
            }
            .map(|s| (s, g.pose_part_geometry)),
            _ => None,
        };
        Some(Self::Shapes(Box::new([shape(&scene.i)?, shape(&scene.j)?])))
    }

    /// parry's deepest answer at `pose` (its depth and normal), if it answers.
    fn answer(&self, pose: &ScenePose) -> Option<(f64, [f64; 3])> {
        match self {
            Self::Engine(pair) => {
                deepest(pair.as_ref(), pose).map(|c| (c.penetration, c.normal_w.into()))
            }
            Self::Shapes(shapes) => {
                let [(a, xa), (b, xb)] = &**shapes;
                primitives::contact(a, &(pose.pose_world_i * xa), b, &(pose.pose_world_j * xb))
                    .filter(|c| c.depth >= 0.0)
                    .map(|c| (c.depth, c.normal.into()))
            }
        }
    }
}

/// The deepest contact `pair` answers at `pose`, if any.
fn deepest(pair: &dyn PreparedPair, pose: &ScenePose) -> Option<Contact> {
    let mut buffer = Vec::new();
    let mut work = WorkCounters::default();
    pair.query(
        &pose.pose_world_i,
        &pose.pose_world_j,
        &mut buffer,
        &mut work,
    )
    .ok()?;
    buffer
        .into_iter()
        .max_by(|a, b| a.penetration.total_cmp(&b.penetration))
}

fn bench_scene(c: &mut Criterion, scene: &Scene) {
    let Ok(exact) = ExactEngine.prepare(&scene.i, &scene.j) else {
        panic!("{}: the exact engine answers every scene", scene.name);
    };
    let Some((pose, answer)) = timed_pose(scene, exact.as_ref()) else {
        panic!(
            "{}: a scene must touch past a tenth of its scale",
            scene.name
        );
    };
    let parry = Peer::new(scene).filter(|p| p.answer(pose).is_some());
    let closed_form = scene.closed_form.map_or("none".to_string(), |f| {
        f(scene, pose)
            .first()
            .map_or("no contact".to_string(), |c| {
                format!("{:.17}", c.penetration)
            })
    });
    eprintln!(
        "{}: nominal depth {:.6}; closed form {closed_form}; exact {:.17} (normal {:?}); parry {}",
        scene.name,
        pose.nominal_depth,
        answer.penetration,
        answer.normal_w.as_slice(),
        parry
            .as_ref()
            .and_then(|p| p.answer(pose))
            .map_or("n/a".to_string(), |(depth, normal)| format!(
                "{depth:.17} (normal {normal:?})"
            )),
    );
    let mut group = c.benchmark_group(format!("contact/{}", scene.name));
    group
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(30);
    time_pair(&mut group, "exact", exact.as_ref(), pose);
    match &parry {
        Some(Peer::Engine(pair)) => time_pair(&mut group, "parry", pair.as_ref(), pose),
        Some(Peer::Shapes(shapes)) => {
            group.bench_function("parry", |bench| {
                let [(a, xa), (b, xb)] = &**shapes;
                bench.iter(|| {
                    primitives::contact(
                        a,
                        &(black_box(pose.pose_world_i) * xa),
                        b,
                        &(black_box(pose.pose_world_j) * xb),
                    )
                })
            });
        }
        None => {}
    }
    group.finish();
}

/// Times `pair`'s query at `pose` as `id` in `group`.
fn time_pair(
    group: &mut BenchmarkGroup<'_, WallTime>,
    id: &str,
    pair: &dyn PreparedPair,
    pose: &ScenePose,
) {
    let mut buffer: Vec<Contact> = Vec::with_capacity(4);
    let mut work = WorkCounters::default();
    group.bench_function(id, |b| {
        b.iter(|| {
            pair.query(
                black_box(&pose.pose_world_i),
                black_box(&pose.pose_world_j),
                &mut buffer,
                &mut work,
            )
            .ok();
            black_box(buffer.len())
        })
    });
}

fn bench_pairs(c: &mut Criterion) {
    for scene in scenes::suite().iter().chain(&scenes::kernel_scenes()) {
        bench_scene(c, scene);
    }
}

criterion_group!(benches, bench_pairs);
criterion_main!(benches);
