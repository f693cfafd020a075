//! Answers pinned to the values of a reference version of the engine, so speed work on the tree,
//! the descent, the triangle test and the region step can be checked not to change them: every
//! contact (points, normal, penetration, area) of a few seeded scenes must match its pinned value
//! to 1e-12, relative to the larger of the value's magnitude and the scene's length scale (1).
//! Contacts are matched by nearest point, since the order of regions follows the order in which a
//! descent meets crossings.
//!
//! The table in `pinned_table.rs` is printed by the ignored test
//! `print_pinned_table` (`cargo test -p engine-facet --test facet print_pinned -- --ignored
//! --nocapture`); regenerate it only when the answers are meant to change.

use crate::common::*;
use contact_core::geometry::{Cylinder, Torus};
use contact_core::{Contact, Geometry, Isometry3, PreparedPair, Vector3};

#[path = "pinned_table.rs"]
mod table;

/// The faceting tolerance that cuts a unit sphere's meridian into `n` segments (as the benches).
fn sphere_tolerance(n: f64) -> f64 {
    let deviation = 2.0 * (1.0 - (std::f64::consts::PI / n).cos());
    0.999 * 2.0 * 3f64.sqrt() / deviation
}

fn pose(rng: &mut Rng, lo: f64, hi: f64) -> Isometry3 {
    let dir = rng.unit_vector();
    Isometry3::from_parts((dir * rng.range(lo, hi)).into(), rng.rotation())
}

/// Every scene's contacts: (scene, pose index, contacts at that pose).
fn compute_all() -> Vec<(&'static str, usize, Vec<Contact>)> {
    let mut rng = Rng(0x5EED);
    let sphere = |r: f64| Geometry::sphere(r).unwrap();
    let torus = Geometry::Torus(Torus::new(1.0, 0.35).unwrap());
    let cylinder = Geometry::Cylinder(Cylinder::new(0.5, 2.0).unwrap());
    let scenes: Vec<(&'static str, f64, Geometry, Geometry, Vec<Isometry3>)> = vec![
        (
            "spheres-1k",
            sphere_tolerance(32.0),
            sphere(1.0),
            sphere(1.0),
            (0..8).map(|_| pose(&mut rng, 0.5, 1.9)).collect(),
        ),
        (
            "spheres-10k",
            sphere_tolerance(100.0),
            sphere(1.0),
            sphere(1.0),
            (0..4).map(|_| pose(&mut rng, 0.5, 1.9)).collect(),
        ),
        (
            "tori",
            1000.0,
            torus.clone(),
            torus,
            (0..6).map(|_| pose(&mut rng, 0.2, 1.2)).collect(),
        ),
        (
            "sphere-cylinder",
            200.0,
            sphere(1.0),
            cylinder,
            (0..6).map(|_| pose(&mut rng, 0.6, 1.6)).collect(),
        ),
        (
            "sphere-inside-sphere",
            300.0,
            sphere(1.0),
            sphere(0.3),
            vec![Isometry3::translation(0.2, -0.1, 0.05)],
        ),
    ];
    let mut out = Vec::new();
    for (name, ft, i, j, poses) in scenes {
        let pair: Box<dyn PreparedPair> = prepare(&engine(ft), i, j);
        for (k, p) in poses.iter().enumerate() {
            let (contacts, _) = query_pair(pair.as_ref(), Isometry3::identity(), *p);
            out.push((name, k, contacts));
        }
    }
    out
}

fn values(c: &Contact) -> [f64; 11] {
    [
        c.point_i_w.x,
        c.point_i_w.y,
        c.point_i_w.z,
        c.point_j_w.x,
        c.point_j_w.y,
        c.point_j_w.z,
        c.normal_w.x,
        c.normal_w.y,
        c.normal_w.z,
        c.penetration,
        c.area,
    ]
}

#[test]
#[ignore = "prints the pinned table; run by hand when answers are meant to change"]
fn print_pinned_table() {
    println!("/// (scene, pose index, [point_i xyz, point_j xyz, normal xyz, penetration, area]).");
    println!("pub const PINNED: &[(&str, usize, [f64; 11])] = &[");
    for (name, k, contacts) in compute_all() {
        for c in &contacts {
            let v = values(c).map(|x| format!("{x:?}")).join(", ");
            println!("    (\"{name}\", {k}, [{v}]),");
        }
    }
    println!("];");
}

#[test]
fn contacts_match_the_pinned_answers() {
    const LENGTH_SCALE: f64 = 1.0;
    let all = compute_all();
    let mut checked = 0;
    for (name, k, contacts) in &all {
        let pinned: Vec<&[f64; 11]> = table::PINNED
            .iter()
            .filter(|(n, i, _)| n == name && i == k)
            .map(|(_, _, v)| v)
            .collect();
        assert_eq!(
            contacts.len(),
            pinned.len(),
            "{name} pose {k}: contact count"
        );
        for want in pinned {
            let point = Vector3::new(want[0], want[1], want[2]);
            let got = contacts
                .iter()
                .map(values)
                .min_by(|u, v| {
                    let d = |w: &[f64; 11]| (Vector3::new(w[0], w[1], w[2]) - point).norm();
                    d(u).total_cmp(&d(v))
                })
                .unwrap();
            for (g, w) in got.iter().zip(want.iter()) {
                let tol = 1e-12 * w.abs().max(LENGTH_SCALE);
                assert!(
                    (g - w).abs() <= tol,
                    "{name} pose {k}: got {got:?}, pinned {want:?}"
                );
            }
            checked += 1;
        }
    }
    // The scenes must produce contacts, else the comparison proves nothing.
    assert!(checked >= 20, "only {checked} contacts compared");
}
