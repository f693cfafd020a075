//! Per-pair query cost of the exact engine, side by side with parry's `contact` query on the
//! same pair where parry has the shapes (spheres, boxes, cylinders, cones, unbounded planes).
//!
//! `cargo bench --bench exact_pairs` (release). Each group `contact/<pair>` has the ids
//! `exact` (a prepared pair's full `query`: pose composition, dispatch, the kernel, the push
//! into a reused buffer) and `parry` (`parry3d_f64::query::contact` on pre-built shapes, pose
//! composition included). Before timing, each group prints both answers' depth against the
//! closed form, so speed and accuracy are read together. Inputs are fixed configurations.
//! Parry has no ellipsoid, frustum (other than a cone), torus or bounded plane, so the
//! general-ellipsoid groups (`ellipsoid_ellipsoid`, `ellipsoid_box`, `ellipsoid_cylinder`,
//! `ellipsoid_frustum`, `ellipsoid_torus`, `ellipsoid_torus_two_regions`,
//! `ellipsoid_bounded_plane`) and the box–frustum, box–torus, frustum/torus–bounded-plane,
//! frustum–frustum, cylinder–torus and frustum–torus groups time the exact engine alone;
//! `cylinder_frustum` (a cylinder across a cone) has parry's `Cone` beside it. A mesh is a
//! parry `TriMesh`; parry is timed only on the pairs it answers.

#![expect(
    missing_docs,
    reason = "criterion_group! generates an undocumented public function"
)]

use contact::peer::primitives::{self, PeerShape};
use contact_core::{Contact, Geometry, GeometryEngine, GeometryInstance, WorkCounters};
use criterion::{Criterion, criterion_group, criterion_main};
use engine_exact::ExactEngine;
use std::hint::black_box;
use std::time::Duration;

#[path = "exact_pairs/cases.rs"]
mod cases;
#[path = "exact_pairs/mesh_cases.rs"]
mod mesh_cases;

use cases::cases;

fn bench_pairs(c: &mut Criterion) {
    for case in cases() {
        let i = GeometryInstance::new(case.i.clone());
        let j = GeometryInstance::new(case.j.clone());
        let pair = ExactEngine.prepare(&[i], &[j]).unwrap();
        let mut buffer: Vec<Contact> = Vec::with_capacity(4);
        let mut work = WorkCounters::default();
        pair.query(&case.pose_i, &case.pose_j, &mut buffer, &mut work)
            .unwrap();
        let Some(&exact) = buffer.first() else {
            panic!("{}: the benchmark configuration must touch", case.name);
        };
        let peer_shape = |g: &Geometry| match g {
            Geometry::Mesh(m) => PeerShape::mesh(m),
            other => PeerShape::new(other, false),
        };
        let peers = peer_shape(&case.i).zip(peer_shape(&case.j));
        let peer = peers
            .as_ref()
            .and_then(|(a, b)| primitives::contact(a, &case.pose_i, b, &case.pose_j));
        // Timed only where parry answers the pair.
        let peers = peers.filter(|_| peer.is_some());
        let reference = case.depth.map_or(
            "none here (see the characterization test)".to_string(),
            |d| format!("{d:.17}"),
        );
        eprintln!(
            "{}: closed form {reference}; exact depth {:.17} normal {:?}; parry {}",
            case.name,
            exact.penetration,
            exact.normal_w.as_slice(),
            peer.map_or("n/a".to_string(), |p| format!(
                "depth {:.17} normal {:?}",
                p.depth,
                p.normal.as_slice()
            )),
        );
        let mut group = c.benchmark_group(format!("contact/{}", case.name));
        group
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2))
            .sample_size(30);
        group.bench_function("exact", |b| {
            b.iter(|| {
                pair.query(
                    black_box(&case.pose_i),
                    black_box(&case.pose_j),
                    &mut buffer,
                    &mut work,
                )
                .unwrap();
                black_box(buffer.len())
            })
        });
        if let Some((a, b)) = &peers {
            group.bench_function("parry", |bench| {
                bench.iter(|| {
                    primitives::contact(a, black_box(&case.pose_i), b, black_box(&case.pose_j))
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench_pairs);
criterion_main!(benches);
