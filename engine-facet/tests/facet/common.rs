//! Shared helpers: a seeded RNG, scenes, and engine shortcuts.

use contact_core::{
    Contact, Geometry, GeometryEngine, GeometryInstance, Isometry3, PreparedPair, UnitQuaternion,
    Vector3, WorkCounters,
};
use engine_facet::FacetEngine;

/// xorshift64*: a tiny seeded generator, so tests need no crate and never change.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_f64(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }

    pub fn rotation(&mut self) -> UnitQuaternion {
        let q = nalgebra::Quaternion::new(
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
        );
        UnitQuaternion::from_quaternion(q)
    }

    pub fn unit_vector(&mut self) -> Vector3 {
        self.rotation() * Vector3::z()
    }
}

pub fn prepare(engine: &FacetEngine, i: Geometry, j: Geometry) -> Box<dyn PreparedPair> {
    engine
        .prepare(&[GeometryInstance::new(i)], &[GeometryInstance::new(j)])
        .unwrap()
}

pub fn query_pair(
    pair: &dyn PreparedPair,
    pose_i: Isometry3,
    pose_j: Isometry3,
) -> (Vec<Contact>, WorkCounters) {
    let mut contacts = Vec::new();
    let mut work = WorkCounters::default();
    pair.query(&pose_i, &pose_j, &mut contacts, &mut work)
        .unwrap();
    for c in &contacts {
        assert!(c.is_well_formed(), "{c:?}");
    }
    (contacts, work)
}

pub fn query(
    engine: &FacetEngine,
    i: Geometry,
    j: Geometry,
    pose_i: Isometry3,
    pose_j: Isometry3,
) -> (Vec<Contact>, WorkCounters) {
    query_pair(prepare(engine, i, j).as_ref(), pose_i, pose_j)
}

pub fn engine(ft: f64) -> FacetEngine {
    FacetEngine::new(contact_core::FacetingTolerance::new(ft).unwrap())
}

/// Angle in degrees between two unit vectors.
pub fn angle_deg(a: &Vector3, b: &Vector3) -> f64 {
    a.dot(b).clamp(-1.0, 1.0).acos().to_degrees()
}
