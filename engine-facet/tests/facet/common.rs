//! Shared helpers: a seeded RNG, scenes, and engine shortcuts.

use contact_core::geometry::TriangleMesh;
use contact_core::{
    Contact, Geometry, GeometryEngine, GeometryInstance, Isometry3, Point3, PreparedPair,
    UnitQuaternion, Vector3, WorkCounters,
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

/// The contacts of instances `i` and `j` at world poses `pose_i` and `pose_j`, from any
/// engine (the faceted one, or the exact one as an oracle).
pub fn instance_contacts(
    engine: &dyn GeometryEngine,
    i: &GeometryInstance,
    j: &GeometryInstance,
    pose_i: &Isometry3,
    pose_j: &Isometry3,
) -> Vec<Contact> {
    let pair = engine
        .prepare(std::slice::from_ref(i), std::slice::from_ref(j))
        .unwrap();
    let mut out = Vec::new();
    pair.query(pose_i, pose_j, &mut out, &mut WorkCounters::default())
        .unwrap();
    out
}

/// [`instance_contacts`] with `j` at the origin.
pub fn contacts_with_j_at_origin(
    engine: &dyn GeometryEngine,
    i: &GeometryInstance,
    j: &GeometryInstance,
    pose_i: &Isometry3,
) -> Vec<Contact> {
    instance_contacts(engine, i, j, pose_i, &Isometry3::identity())
}

/// `g` with its part frame at the middle of its bounding box (a cylinder's or a frustum's
/// frame is at its base).
pub fn centred(g: Geometry) -> GeometryInstance {
    let (lo, hi) = g.local_bounding_box();
    let m = 0.5 * (lo.coords + hi.coords);
    GeometryInstance::new(g).at(Isometry3::translation(-m.x, -m.y, -m.z))
}

pub fn engine(ft: f64) -> FacetEngine {
    FacetEngine::new(contact_core::FacetingTolerance::new(ft).unwrap())
}

/// Angle in degrees between two unit vectors.
pub fn angle_deg(a: &Vector3, b: &Vector3) -> f64 {
    a.dot(b).clamp(-1.0, 1.0).acos().to_degrees()
}

/// A U-shaped prism: the profile (x, z) of two legs 0.1 wide and 0.3 tall under a 0.1 bridge,
/// 0.5 across, extruded 0.1 along y; legs down, their bottoms at z = 0.
pub fn u_shape() -> Geometry {
    let profile = [
        (0.0, 0.0),
        (0.1, 0.0),
        (0.1, 0.3),
        (0.4, 0.3),
        (0.4, 0.0),
        (0.5, 0.0),
        (0.5, 0.4),
        (0.0, 0.4),
    ];
    // The profile as six triangles.
    let caps = [
        [0, 1, 2],
        [0, 2, 7],
        [7, 2, 3],
        [7, 3, 6],
        [3, 4, 5],
        [3, 5, 6],
    ];
    prism(&profile, &caps, 0.1, false)
}

/// The closed prism of a counter-clockwise profile in (x, z), extruded over `0 ≤ y ≤ depth`:
/// the caps triangulated as `caps` (indices into the profile), each side quad split along
/// one diagonal or (`other_split`) the other, every triangle turned to its outward normal.
pub fn prism(profile: &[(f64, f64)], caps: &[[u32; 3]], depth: f64, other_split: bool) -> Geometry {
    let n = profile.len() as u32;
    let vertices: Vec<Point3> = [0.0, depth]
        .iter()
        .flat_map(|&y| profile.iter().map(move |&(x, z)| Point3::new(x, y, z)))
        .collect();
    let mut triangles = Vec::new();
    let mut push = |t: [u32; 3], outward: Vector3| {
        let [a, b, c] = t.map(|k| vertices[k as usize]);
        let normal = (b - a).cross(&(c - a));
        triangles.push(if normal.dot(&outward) > 0.0 {
            t
        } else {
            [t[0], t[2], t[1]]
        });
    };
    for &t in caps {
        push(t, -Vector3::y());
        push(t.map(|k| k + n), Vector3::y());
    }
    for k in 0..n {
        let m = (k + 1) % n;
        let (a, b) = (profile[k as usize], profile[m as usize]);
        // Counter-clockwise profile: the outward normal of edge a→b is (dz, −dx) in (x, z).
        let outward = Vector3::new(b.1 - a.1, 0.0, -(b.0 - a.0));
        if other_split {
            push([k, m, k + n], outward);
            push([m, m + n, k + n], outward);
        } else {
            push([k, m, m + n], outward);
            push([k, m + n, k + n], outward);
        }
    }
    Geometry::Mesh(std::sync::Arc::new(
        TriangleMesh::new(vertices, triangles).unwrap(),
    ))
}
