//! Faceted-engine benches: OBB-tree build and all-contacts queries for two spheres of about
//! 1k, 10k and 100k triangles at seeded random poses (half overlapping, half separated), and
//! two tori; parry's trimesh–trimesh contact manifolds on the same meshes and poses beside them;
//! and the exact engine beside the faceted one on the 10k and 100k spheres given as meshes.
//! Short profile (10 samples, 1 s) so `cargo bench --bench facet_meshes` takes a few minutes.

#![expect(
    missing_docs,
    reason = "criterion_group! generates an undocumented pub fn"
)]

use contact::peer::ParryPeer;
use contact_core::{
    FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, Isometry3, UnitQuaternion,
    Vector3, WorkCounters,
};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use engine_facet::FacetEngine;
use engine_facet::facet_mesh::FacetMesh;
use engine_facet::tessellate::tessellate;
use std::hint::black_box;
use std::time::Duration;

/// xorshift64*: seeded, so every run benches the same poses.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    fn rotation(&mut self) -> UnitQuaternion {
        let q = nalgebra::Quaternion::new(
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
        );
        UnitQuaternion::from_quaternion(q)
    }

    /// A pose at centre distance in `[lo, hi]` along a random direction, randomly rotated.
    fn pose(&mut self, lo: f64, hi: f64) -> Isometry3 {
        let dir = self.rotation() * Vector3::z();
        Isometry3::from_parts((dir * self.range(lo, hi)).into(), self.rotation())
    }
}

/// The faceting tolerance that cuts a unit sphere's meridian circle into `n` segments
/// (`2n(⌈n/2⌉ − 1)` triangles; see `engine_facet::tessellate`).
fn sphere_tolerance(n: f64) -> FacetingTolerance {
    let deviation = 2.0 * (1.0 - (std::f64::consts::PI / n).cos());
    FacetingTolerance::new(0.999 * 2.0 * 3f64.sqrt() / deviation).unwrap()
}

fn configure() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .measurement_time(Duration::from_secs(1))
        .warm_up_time(Duration::from_millis(300))
}

struct Scene {
    name: String,
    i: Geometry,
    j: Geometry,
    tolerance: FacetingTolerance,
    overlapping: Vec<Isometry3>,
    separated: Vec<Isometry3>,
}

fn scenes() -> Vec<Scene> {
    let mut rng = Rng(0x5EED);
    let mut out = Vec::new();
    for (label, n) in [("1k", 32.0), ("10k", 100.0), ("100k", 316.0)] {
        out.push(Scene {
            name: format!("spheres-{label}"),
            i: Geometry::sphere(1.0).unwrap(),
            j: Geometry::sphere(1.0).unwrap(),
            tolerance: sphere_tolerance(n),
            overlapping: (0..8).map(|_| rng.pose(0.5, 1.9)).collect(),
            separated: (0..8).map(|_| rng.pose(2.1, 4.0)).collect(),
        });
    }
    let torus = Geometry::Torus(contact_core::geometry::Torus::new(1.0, 0.35).unwrap());
    out.push(Scene {
        name: "tori".into(),
        i: torus.clone(),
        j: torus,
        tolerance: FacetingTolerance::new(1000.0).unwrap(),
        overlapping: (0..8).map(|_| rng.pose(0.2, 1.2)).collect(),
        separated: (0..8).map(|_| rng.pose(3.0, 4.0)).collect(),
    });
    out
}

fn mesh(g: &Geometry, tolerance: FacetingTolerance) -> FacetMesh {
    FacetMesh::build(tessellate(g, tolerance).unwrap(), true)
}

fn build(c: &mut Criterion) {
    let mut group = c.benchmark_group("facet/tree-build");
    for scene in scenes() {
        let t = tessellate(&scene.i, scene.tolerance).unwrap();
        let label = format!("{}({} tris)", scene.name, t.triangles.len());
        group.bench_function(BenchmarkId::new("ours", &label), |b| {
            b.iter(|| FacetMesh::build(black_box(t.clone()), true))
        });
        let m = mesh(&scene.i, scene.tolerance);
        group.bench_function(BenchmarkId::new("parry", &label), |b| {
            b.iter(|| ParryPeer::new(black_box(&m), &m).unwrap())
        });
    }
    group.finish();
}

fn queries(c: &mut Criterion) {
    for scene in scenes() {
        let engine = FacetEngine::new(scene.tolerance);
        let pair = engine
            .prepare(
                &[GeometryInstance::new(scene.i.clone())],
                &[GeometryInstance::new(scene.j.clone())],
            )
            .unwrap();
        let (a, b) = (
            mesh(&scene.i, scene.tolerance),
            mesh(&scene.j, scene.tolerance),
        );
        let mut peer = ParryPeer::new(&a, &b).unwrap();
        let mut group = c.benchmark_group(format!("facet/query/{}", scene.name));
        for (kind, poses) in [
            ("overlapping", &scene.overlapping),
            ("separated", &scene.separated),
        ] {
            let mut contacts = Vec::new();
            let mut work = WorkCounters::default();
            let mut k = 0;
            group.bench_function(BenchmarkId::new("ours", kind), |bench| {
                bench.iter(|| {
                    k = (k + 1) % poses.len();
                    pair.query(&poses[k], &Isometry3::identity(), &mut contacts, &mut work)
                        .unwrap();
                    black_box(contacts.len())
                })
            });
            let mut k = 0;
            group.bench_function(BenchmarkId::new("parry", kind), |bench| {
                bench.iter(|| {
                    k = (k + 1) % poses.len();
                    black_box(peer.contact_points(&poses[k].inverse()).unwrap())
                })
            });
        }
        group.finish();
    }
}

/// The two engines on the same two meshes given as meshes (the spheres' tessellations), at the
/// overlapping poses: the exact engine answers two meshes by their polyhedral intersection,
/// with the faceted engine's method on the meshes as given.
fn mesh_pairs(c: &mut Criterion) {
    let large = |s: &Scene| s.name == "spheres-10k" || s.name == "spheres-100k";
    for scene in scenes().into_iter().filter(large) {
        let t = tessellate(&scene.i, scene.tolerance).unwrap();
        let mesh = contact_core::geometry::TriangleMesh::new(t.vertices, t.triangles).unwrap();
        let given = GeometryInstance::new(Geometry::Mesh(std::sync::Arc::new(mesh)));
        let both = [given.clone()];
        let faceted = FacetEngine::new(scene.tolerance)
            .prepare(&both, &both)
            .unwrap();
        let exact = engine_exact::ExactEngine.prepare(&both, &both).unwrap();
        let mut group = c.benchmark_group(format!("facet/mesh-pair/{}", scene.name));
        for (name, pair) in [("faceted", &faceted), ("exact", &exact)] {
            let mut contacts = Vec::new();
            let mut work = WorkCounters::default();
            let mut k = 0;
            let poses = &scene.overlapping;
            group.bench_function(BenchmarkId::new(name, "overlapping"), |bench| {
                bench.iter(|| {
                    k = (k + 1) % poses.len();
                    pair.query(&poses[k], &Isometry3::identity(), &mut contacts, &mut work)
                        .unwrap();
                    black_box(contacts.len())
                })
            });
        }
        group.finish();
    }
}

criterion_group! {
    name = benches;
    config = configure();
    targets = build, queries, mesh_pairs
}
criterion_main!(benches);
