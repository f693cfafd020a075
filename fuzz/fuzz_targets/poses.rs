//! Fuzz target: arbitrary bytes as a `contact query` poses file (x y z qw qx qy qz per line),
//! and every pose it accepts queried on a few pairs with both engines. Any panic is a bug, and
//! so is a contact that is not well formed (non-finite numbers, negative depth, a normal that
//! is not unit).
#![no_main]

use contact::cli::query::{parse_geometry, parse_poses};
use contact_core::nalgebra::{Quaternion, UnitQuaternion};
use contact_core::{
    FacetingTolerance, GeometryEngine, GeometryInstance, Isometry3, PreparedPair, Vector3,
    WorkCounters,
};
use contact::engine_choice::build_engine;
use contact_core::GeometryLibrary;
use libfuzzer_sys::fuzz_target;
use std::sync::OnceLock;

/// The pairs every pose is tried on: flat faces, edges, curved sides and a plane.
const PAIRS: [(&str, &str); 5] = [
    ("sphere:r=0.6", "box:x=1,y=2,z=0.5"),
    ("box:x=1,y=1,z=1", "box:x=2,y=0.5,z=1"),
    ("cylinder:r=0.4,l=1", "torus:R=1,r=0.3"),
    ("ellipsoid:a=1,b=0.5,c=0.3", "plane"),
    ("frustum:r0=0.5,r1=0.2,l=1", "sphere:r=0.7"),
];

/// Poses per input: enough to reach every line form, few enough to keep runs fast.
const MAX_POSES: usize = 4;

fn prepared() -> &'static Vec<Box<dyn PreparedPair>> {
    static PREPARED: OnceLock<Vec<Box<dyn PreparedPair>>> = OnceLock::new();
    PREPARED.get_or_init(|| {
        let tolerance = FacetingTolerance::default();
        let mut pairs = Vec::new();
        for library in [GeometryLibrary::Exact, GeometryLibrary::Faceted] {
            let engine: Box<dyn GeometryEngine> = build_engine(library, tolerance);
            for (i, j) in PAIRS {
                let instance = |spec: &str| {
                    GeometryInstance::new(parse_geometry(spec, false).expect("valid spec").0)
                };
                let (i, j) = (instance(i), instance(j));
                let pair = engine
                    .prepare(std::slice::from_ref(&i), std::slice::from_ref(&j))
                    .expect("both engines answer these pairs");
                pairs.push(pair);
            }
        }
        pairs
    })
}

/// Each line's seven finite numbers as a pose with its quaternion normalised, whatever its
/// norm: the parser refuses a quaternion that is not unit, which random bytes almost never
/// are, and the queries are to be fuzzed all the same.
fn lenient_poses(text: &str) -> Vec<Isometry3> {
    text.lines()
        .filter_map(|line| {
            let v: Vec<f64> = line
                .split(|c: char| c == ',' || c.is_whitespace())
                .filter(|s| !s.is_empty())
                .map(str::parse)
                .collect::<Result<_, _>>()
                .ok()?;
            let [x, y, z, w, i, j, k] = v[..] else {
                return None;
            };
            let q = Quaternion::new(w, i, j, k);
            let usable = v.iter().all(|a| a.is_finite()) && q.norm().is_finite() && q.norm() > 0.0;
            usable.then(|| {
                Isometry3::from_parts(
                    Vector3::new(x, y, z).into(),
                    UnitQuaternion::from_quaternion(q),
                )
            })
        })
        .collect()
}

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let parsed = parse_poses(&text).unwrap_or_default();
    let lenient = lenient_poses(&text);
    let mut contacts = Vec::new();
    let mut work = WorkCounters::default();
    for pose in parsed.iter().chain(&lenient).take(MAX_POSES) {
        for pair in prepared() {
            if pair
                .query(pose, &Isometry3::identity(), &mut contacts, &mut work)
                .is_ok()
            {
                for c in &contacts {
                    assert!(c.is_well_formed(), "ill-formed contact {c:?} at {pose:?}");
                }
            }
        }
    }
});
