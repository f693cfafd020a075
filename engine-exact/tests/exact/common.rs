//! Shared helpers: a seeded RNG, poses, and a one-pair query.

use contact_core::{
    Contact, Geometry, GeometryEngine, GeometryInstance, Isometry3, Point3, UnitQuaternion,
    Vector3, WorkCounters,
};
use engine_exact::ExactEngine;
use nalgebra::{Quaternion, Translation3};

/// SplitMix64: small, seeded, reproducible.
#[derive(Clone)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [lo, hi).
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let u = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * u
    }

    pub fn unit_vector(&mut self) -> Vector3 {
        loop {
            let v = Vector3::new(
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
            );
            let n = v.norm();
            if n > 0.1 && n <= 1.0 {
                return v / n;
            }
        }
    }

    pub fn rotation(&mut self) -> UnitQuaternion {
        loop {
            let q = Quaternion::new(
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
            );
            let n = q.norm();
            if n > 0.1 && n <= 1.0 {
                return UnitQuaternion::from_quaternion(q);
            }
        }
    }

    /// A rigid motion with translation of size up to `reach`.
    pub fn pose(&mut self, reach: f64) -> Isometry3 {
        let t = self.unit_vector() * self.uniform(0.0, reach);
        Isometry3::from_parts(Translation3::from(t), self.rotation())
    }
}

/// Queries the exact engine for one I geometry against one J geometry.
pub fn query(
    i: &GeometryInstance,
    j: &GeometryInstance,
    pose_i: &Isometry3,
    pose_j: &Isometry3,
) -> Vec<Contact> {
    let pair = ExactEngine
        .prepare(std::slice::from_ref(i), std::slice::from_ref(j))
        .unwrap();
    let mut out = Vec::new();
    let mut work = WorkCounters::default();
    pair.query(pose_i, pose_j, &mut out, &mut work).unwrap();
    for c in &out {
        assert!(c.is_well_formed(), "{c:?}");
    }
    out
}

/// The single contact of a pair that must touch.
pub fn one(
    i: &GeometryInstance,
    j: &GeometryInstance,
    pose_i: &Isometry3,
    pose_j: &Isometry3,
) -> Contact {
    let out = query(i, j, pose_i, pose_j);
    assert_eq!(out.len(), 1, "expected one contact, got {out:?}");
    out[0]
}

pub fn instance(g: Geometry) -> GeometryInstance {
    GeometryInstance::new(g)
}

/// An expected contact.
#[derive(Debug, Clone, Copy)]
pub struct Expected {
    pub point_i: Point3,
    pub point_j: Point3,
    pub normal: Vector3,
    pub depth: f64,
}

impl Expected {
    /// The same contact seen from world frame `t`.
    pub fn moved(&self, t: &Isometry3) -> Self {
        Self {
            point_i: t * self.point_i,
            point_j: t * self.point_j,
            normal: t.rotation * self.normal,
            depth: self.depth,
        }
    }
}

/// Errors relative to `length`: (depth, normal, points).
pub fn errors(got: &Contact, expected: &Expected, length: f64) -> [f64; 3] {
    [
        (got.penetration - expected.depth).abs() / length,
        (got.normal_w - expected.normal).norm(),
        ((got.point_i_w - expected.point_i).norm() + (got.point_j_w - expected.point_j).norm())
            / length,
    ]
}

/// Asserts two contacts agree to `tol` relative to the pair's size: `length` for depth and
/// points, `area_scale` (length² in 3-D, length in 2-D, where the area is a length) for area.
pub fn assert_close(a: &Contact, b: &Contact, length: f64, area_scale: f64, tol: f64, what: &str) {
    let e = errors(
        a,
        &Expected {
            point_i: b.point_i_w,
            point_j: b.point_j_w,
            normal: b.normal_w,
            depth: b.penetration,
        },
        length,
    );
    let area_err = (a.area - b.area).abs() / area_scale;
    assert!(
        e.iter().all(|&x| x <= tol) && area_err <= tol,
        "{what}: errors {e:?}, area {area_err:e} > {tol:e}\n{a:?}\n{b:?}"
    );
}

/// A closed, outward-oriented triangle mesh of the boxes `(centre, half extents)`, all in one
/// mesh (separate boxes make separate components).
pub fn boxes_mesh(boxes: &[(Point3, Vector3)]) -> contact_core::geometry::TriangleMesh {
    contact_core::geometry::TriangleMesh::boxes(boxes).unwrap()
}

/// The contact of `found` whose I point is nearest `point` (regions come in no fixed order).
pub fn nearest<'a>(found: &'a [Contact], point: &Point3) -> &'a Contact {
    found
        .iter()
        .min_by(|a, b| {
            let d = |c: &Contact| (c.point_i_w - point).norm();
            d(a).total_cmp(&d(b))
        })
        .expect("at least one contact")
}
