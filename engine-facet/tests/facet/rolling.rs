//! The facets' own contact in motion (no implied solid: cylinders, tori, boxes on a plane) is
//! continuous in the pose: rolled across facet edges in steps of a few micrometres of arc, the
//! depth and the points move by no more than a few steps' worth (no jump as the ray through the
//! region's centroid crosses from one facet to the next), every sample stays within the chord
//! deviation of the exact engine's contact, and a second region appears at depth zero.

use crate::common::{engine, prepare, query_pair, u_shape};
use contact_core::geometry::{Cuboid, Cylinder, Plane, Torus};
use contact_core::nalgebra::Unit;
use contact_core::{
    Contact, FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, Isometry3,
    PreparedPair, UnitQuaternion, Vector3,
};

fn plane() -> Geometry {
    Geometry::Plane(Plane::unbounded())
}

fn exact(g: &Geometry) -> Box<dyn PreparedPair> {
    engine_exact::ExactEngine
        .prepare(
            &[GeometryInstance::new(g.clone())],
            &[GeometryInstance::new(plane())],
        )
        .unwrap()
}

/// Sweeps `pose_of(s)` for `steps` values of `s` in `[0, span)`, where one step of `s` moves
/// the body's surface by at most `arc`; asserts the contact's continuity and its agreement
/// with the exact engine (every 50th sample).
fn roll(name: &str, g: Geometry, pose_of: impl Fn(f64) -> Isometry3, span: f64, arc: f64) {
    let length = g.characteristic_length().unwrap();
    let reference = exact(&g);
    let steps = 4000;
    for ft in [300.0028, 3000.0] {
        let deviation = FacetingTolerance::new(ft).unwrap().chord_deviation(length);
        let pair = prepare(&engine(ft), g.clone(), plane());
        let mut last: Option<Contact> = None;
        let (mut depth_step, mut point_step) = (0.0f64, 0.0f64);
        for k in 0..steps {
            let s = span * f64::from(k) / f64::from(steps);
            let pose = pose_of(s);
            let (got, _) = query_pair(pair.as_ref(), pose, Isometry3::identity());
            assert_eq!(got.len(), 1, "{name}, FT {ft}, s = {s}: {got:?}");
            let c = got[0];
            if k % 50 == 0 {
                let (want, _) = query_pair(reference.as_ref(), pose, Isometry3::identity());
                assert_eq!(want.len(), 1, "{name}, s = {s}: {want:?}");
                assert!(
                    (c.penetration - want[0].penetration).abs() <= deviation,
                    "{name}, FT {ft}, s = {s}: {c:?} against {want:?}"
                );
            }
            if let Some(l) = last {
                depth_step = depth_step.max((c.penetration - l.penetration).abs());
                point_step = point_step.max((c.point_i_w - l.point_i_w).norm());
            }
            last = Some(c);
        }
        assert!(
            depth_step <= arc && point_step <= 3.0 * arc,
            "{name}, FT {ft}: depth step {depth_step:e}, point step {point_step:e}, arc {arc:e}"
        );
    }
}

#[test]
fn a_cylinder_rolled_across_its_facets_keeps_a_continuous_contact() {
    // Radius 0.1, length 0.3, on its side (axis along x), 2 mm deep, rolled a quarter turn.
    let cylinder = Geometry::Cylinder(Cylinder::new(0.1, 0.3).unwrap());
    let side = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), std::f64::consts::FRAC_PI_2);
    let pose = |angle: f64| {
        let r = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), angle) * side;
        let centre = r * Vector3::new(0.0, 0.0, 0.15);
        Isometry3::from_parts((Vector3::new(0.0, 0.0, 0.098) - centre).into(), r)
    };
    let span = 0.5;
    roll("cylinder", cylinder, pose, span, 0.1 * span / 4000.0);
}

#[test]
fn a_tilting_torus_keeps_a_continuous_contact() {
    // R = 0.2, r = 0.05, tilted about a generic horizontal axis, its lowest point 3 mm deep.
    let torus = Geometry::Torus(Torus::new(0.2, 0.05).unwrap());
    let axis = Unit::new_normalize(Vector3::new(0.3, 1.0, 0.0));
    let pose = |angle: f64| {
        let tilt = 0.2 + angle;
        let r = UnitQuaternion::from_axis_angle(&axis, tilt);
        let lowest = 0.05 + 0.2 * tilt.sin();
        Isometry3::from_parts(Vector3::new(0.0, 0.0, lowest - 0.003).into(), r)
    };
    let span = 0.3;
    roll("torus", torus, pose, span, 0.25 * span / 4000.0);
}

#[test]
fn a_second_region_appears_and_grows_from_depth_zero() {
    // The U tilted by 0.02 rad about a generic axis, lowered onto the plane: one leg's corner
    // touches first, then the other leg's, each region starting at depth zero; while the count
    // stays, every region's depth changes by no more than the descent (a tilted flat bottom
    // sinks as the body does, its ray-rule depth at most as fast).
    let body = u_shape();
    let tilt =
        UnitQuaternion::from_axis_angle(&Unit::new_normalize(Vector3::new(0.2, 1.0, 0.1)), 0.02);
    let lowest = |pose: &Isometry3| match &body {
        Geometry::Mesh(m) => m
            .vertices()
            .iter()
            .map(|v| (pose * v).z)
            .fold(f64::INFINITY, f64::min),
        _ => unreachable!(),
    };
    let start = -lowest(&Isometry3::from_parts(Vector3::zeros().into(), tilt));
    let steps = 4000;
    let dz = 0.02 / f64::from(steps);
    for ft in [300.0028, 3000.0] {
        let pair = prepare(&engine(ft), body.clone(), plane());
        let mut last: Vec<Contact> = Vec::new();
        let mut appeared = Vec::new();
        for k in 0..steps {
            let z = start + 1e-4 - dz * f64::from(k);
            let pose = Isometry3::from_parts(Vector3::new(0.0, 0.0, z).into(), tilt);
            let (mut got, _) = query_pair(pair.as_ref(), pose, Isometry3::identity());
            got.sort_by(|a, b| a.point_i_w.x.total_cmp(&b.point_i_w.x));
            let label = format!("FT {ft}, z = {z}");
            assert!(
                got.len() >= last.len() && got.len() <= 2,
                "{label}: {got:?}"
            );
            if got.len() > last.len() {
                appeared.push(z);
                let new = if last.is_empty() || got[0].point_i_w.x < last[0].point_i_w.x - 0.2 {
                    &got[0]
                } else {
                    &got[got.len() - 1]
                };
                assert!(new.penetration <= dz, "{label}: {got:?}");
            } else {
                for (a, b) in got.iter().zip(&last) {
                    let change = a.penetration - b.penetration;
                    assert!(
                        change >= 0.0 && change <= dz * (1.0 + 1e-9),
                        "{label}: {got:?} after {last:?}"
                    );
                }
            }
            last = got;
        }
        assert_eq!(
            appeared.len(),
            2,
            "FT {ft}: regions appeared at {appeared:?}"
        );
    }
}

#[test]
fn a_box_rocked_through_flat_is_the_exact_contact() {
    // A box is its own facets: through the flat pose (whole face down) the contact equals the
    // exact engine's to round-off.
    let cube = Geometry::Cuboid(Cuboid::centered(0.1, 0.1, 0.1).unwrap());
    let pair = prepare(&engine(300.0028), cube.clone(), plane());
    let reference = exact(&cube);
    for k in -200i32..=200 {
        let phi = 1e-4 * f64::from(k);
        let r = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), phi);
        let lowest = 0.1 * (phi.abs().cos() + phi.abs().sin());
        let pose = Isometry3::from_parts(Vector3::new(0.0, 0.0, lowest - 0.001).into(), r);
        let (got, _) = query_pair(pair.as_ref(), pose, Isometry3::identity());
        let (want, _) = query_pair(reference.as_ref(), pose, Isometry3::identity());
        assert_eq!(got.len(), 1);
        assert_eq!(want.len(), 1);
        let (g, w) = (got[0], want[0]);
        assert!(
            (g.penetration - w.penetration).abs() < 1e-15,
            "{phi}: {g:?} {w:?}"
        );
        assert!(
            (g.point_i_w - w.point_i_w).norm() < 1e-14,
            "{phi}: {g:?} {w:?}"
        );
        assert!(
            (g.normal_w - w.normal_w).norm() < 1e-14,
            "{phi}: {g:?} {w:?}"
        );
    }
}

#[test]
fn a_ring_lying_flat_is_held_to_its_thickness_and_pushed_at_its_centre() {
    // A torus (R 1, r 0.3) lying flat, `sink` into the plane: its region is a ring whose
    // centroid lies in the hole, where the line through it meets no surface of the torus. The
    // depth is held to the convex bound 3V/|S| (about twice the sink for a shallow ring; the
    // true thickness is the sink), the force's line through the centroid (the axis); tilting
    // it moves both continuously. SPEC §4 leaves this case open, and the exact engine answers
    // 0.74 here: it is no oracle for it.
    let torus = Geometry::Torus(Torus::new(1.0, 0.3).unwrap());
    let pair = prepare(&engine(3000.0), torus, plane());
    let sink = 0.002;
    let at = |tilt: f64| {
        let rotation = UnitQuaternion::from_axis_angle(
            &Unit::new_normalize(Vector3::new(0.6, 0.8, 0.0)),
            tilt,
        );
        Isometry3::from_parts(Vector3::new(0.0, 0.0, 0.3 - sink).into(), rotation)
    };
    let (flat, _) = query_pair(pair.as_ref(), at(0.0), Isometry3::identity());
    assert_eq!(flat.len(), 1, "{flat:?}");
    let c = flat[0];
    assert!(
        c.penetration >= 0.5 * sink && c.penetration <= 2.0 * sink,
        "{c:?}"
    );
    assert!(c.point_j_w.coords.xy().norm() < 1e-9, "{c:?}");
    let mut last = c;
    let step = 1e-6;
    for k in 1..=2000 {
        let (got, _) = query_pair(
            pair.as_ref(),
            at(step * f64::from(k)),
            Isometry3::identity(),
        );
        assert_eq!(got.len(), 1, "tilt {}: {got:?}", step * f64::from(k));
        let c = got[0];
        // One microradian tilts the ring's rim by a micrometre.
        assert!(
            (c.penetration - last.penetration).abs() < 1e-5 && c.penetration < 0.05,
            "tilt {}: {c:?} after {last:?}",
            step * f64::from(k)
        );
        last = c;
    }
}
