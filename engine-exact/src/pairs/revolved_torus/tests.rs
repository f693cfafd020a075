use super::slice::{TorusPair, Wedge};
use crate::pairs::revolved_pair::quadric::Quadric;
use contact_core::{Vector3, WorkCounters};
use std::f64::consts::PI;

/// The torus (R = 2, ρ = 0.5) against `b`.
fn pair(b: Quadric) -> TorusPair {
    TorusPair {
        big: 2.0,
        small: 0.5,
        b,
    }
}

fn cylinder(origin: Vector3, axis: Vector3, r: f64, len: f64) -> Quadric {
    Quadric {
        origin,
        axis: axis.normalize(),
        r0: r,
        slope: 0.0,
        len,
    }
}

#[test]
fn a_coaxial_sleeve_holds_the_whole_annulus_and_both_walls() {
    // A coaxial cylinder of radius 3 from z = −1 to 1 holds the whole torus.
    let p = pair(cylinder(
        Vector3::new(0.0, 0.0, -1.0),
        Vector3::z(),
        3.0,
        2.0,
    ));
    let mut work = WorkCounters::default();
    let psi = 0.3f64;
    let s = 0.5 * psi.cos();
    let slice = p.slice(psi, &Wedge::WHOLE, &mut work);
    assert!((slice[0] - 4.0 * PI * 2.0 * s).abs() < 1e-13, "{slice:?}");
    assert!(slice[1].abs() < 1e-13 && slice[2].abs() < 1e-13);
    assert!((slice[3] - 2.0 * PI).abs() < 1e-13 && (slice[6] - 2.0 * PI).abs() < 1e-13);
    // Two half turns add up to the whole.
    let halves = [
        Wedge {
            start: 0.4,
            end: 0.4 + PI,
        },
        Wedge {
            start: 0.4 + PI,
            end: 0.4 + 2.0 * PI,
        },
    ]
    .map(|w| p.slice(psi, &w, &mut work));
    assert!((halves[0][0] + halves[1][0] - slice[0]).abs() < 1e-13);
    assert!((halves[0][1] + halves[1][1]).abs() < 1e-13);
}

#[test]
fn the_gap_is_negative_where_a_rod_crosses_the_tube_and_positive_elsewhere() {
    // A rod along x through the hole, crossing the tube at azimuths 0 and π.
    let p = pair(cylinder(
        Vector3::new(-3.0, 0.0, 0.0),
        Vector3::x(),
        0.2,
        6.0,
    ));
    assert!(p.gap(0.0).0 < -0.1 && p.gap(PI).0 < -0.1);
    assert!(p.gap(0.5 * PI).0 > 0.0);
    let (regions, count) = p.regions();
    assert_eq!(count, 2);
    for (w, seed) in &regions[..count] {
        let seed = seed.unwrap();
        assert!(w.contains(seed.phi) && seed.gap < 0.0);
    }
}

#[test]
fn a_seed_is_inside_both_solids_and_its_slice_meets_them() {
    // A cylinder standing on the tube's top, sunk 1e-7: the lens is found from the seed.
    let p = pair(cylinder(
        Vector3::new(2.0, 0.0, 0.5 - 1e-7),
        Vector3::z(),
        0.3,
        1.0,
    ));
    let (regions, count) = p.regions();
    assert_eq!(count, 1);
    let seed = regions[0].1.unwrap();
    assert!(seed.gap < 0.0 && seed.gap > -1e-7, "{seed:?}");
    let psi = p.angle(seed.t);
    assert!(p.not_empty(psi, &Wedge::WHOLE));
    let mut work = WorkCounters::default();
    let r = p.region(&Wedge::WHOLE, Some(seed), &mut work).unwrap();
    assert!(r[0] > 0.0 && r[6] > 0.0, "{r:?}");
}
