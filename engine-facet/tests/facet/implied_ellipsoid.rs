//! A tessellated ellipsoid against an unbounded plane answers as the ellipsoid: the exact
//! engine's contact (its own closed form, written apart) wherever the cap is small in the
//! ellipsoid's unit-ball image, and a blend with the facets' contact deeper that stays within
//! the chord deviation of both and is continuous in the depth.

use crate::common::{Rng, engine, prepare, query_pair};
use contact_core::geometry::{Ellipsoid, Plane};
use contact_core::{Contact, Vector3};
use contact_core::{FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, Isometry3};

const SEMI: [f64; 3] = [0.1, 0.07, 0.05];

fn ellipsoid() -> Geometry {
    Geometry::Ellipsoid(Ellipsoid::new(SEMI[0], SEMI[1], SEMI[2]).unwrap())
}

/// The ellipsoid at a seeded orientation with its centre `d` above the plane `z = 0`, where
/// `d = k·(1 − t)` puts the unit-ball cap's height at `t` (`k` the support function).
fn pose(rng: &mut Rng, t: f64) -> Isometry3 {
    let rotation = rng.rotation();
    let n = rotation.inverse_transform_vector(&Vector3::z());
    let k = Vector3::from(SEMI).component_mul(&n).norm();
    Isometry3::from_parts(
        Vector3::new(rng.range(-1.0, 1.0), 0.3, k * (1.0 - t)).into(),
        rotation,
    )
}

fn exact(pose: &Isometry3) -> Vec<Contact> {
    let pair = engine_exact::ExactEngine
        .prepare(
            &[GeometryInstance::new(ellipsoid())],
            &[GeometryInstance::new(Geometry::Plane(Plane::unbounded()))],
        )
        .unwrap();
    query_pair(pair.as_ref(), *pose, Isometry3::identity()).0
}

fn errors(got: &Contact, want: &Contact) -> [f64; 4] {
    [
        (got.penetration - want.penetration).abs(),
        (got.normal_w - want.normal_w).norm(),
        (got.point_i_w - want.point_i_w).norm() + (got.point_j_w - want.point_j_w).norm(),
        (got.area - want.area).abs(),
    ]
}

#[test]
fn a_small_cap_is_the_exact_engines_contact_at_every_tolerance() {
    for ft in [30.0, 300.0028, 3000.0] {
        let pair = prepare(
            &engine(ft),
            ellipsoid(),
            Geometry::Plane(Plane::unbounded()),
        );
        let mut rng = Rng(0x5eed_e11f);
        let mut compared = 0;
        for k in 0..200 {
            // Cap heights in the unit ball from just apart to 1/8 (the whole local answer).
            let t = -0.01 + 0.135 * f64::from(k % 20) / 19.0;
            let pose = pose(&mut rng, t);
            let (got, _) = query_pair(pair.as_ref(), pose, Isometry3::identity());
            let want = exact(&pose);
            assert_eq!(
                got.len(),
                want.len(),
                "FT {ft}, t = {t}: {got:?} against {want:?}"
            );
            for (g, w) in got.iter().zip(&want) {
                let [depth, normal, points, area] = errors(g, w);
                // Round-off, with the semi-axes fitted to the corners (to some 1e-13 of their
                // size).
                let size = SEMI[0];
                assert!(
                    depth < 1e-13 * size && normal < 1e-14 && points < 1e-13 * size,
                    "FT {ft}, {k}: {:?}",
                    errors(g, w)
                );
                // The section's `1 − σ²` cancels near grazing: round-off of the size's square.
                assert!(area < 1e-12 * size * size, "FT {ft}, {k}: {g:?} {w:?}");
                compared += 1;
            }
        }
        assert!(compared > 150, "{compared}");
    }
}

#[test]
fn a_deep_cap_blends_continuously_and_stays_within_the_chord_deviation() {
    let length = ellipsoid().characteristic_length().unwrap();
    for ft in [300.0028, 3000.0] {
        let deviation = FacetingTolerance::new(ft).unwrap().chord_deviation(length);
        let pair = prepare(
            &engine(ft),
            ellipsoid(),
            Geometry::Plane(Plane::unbounded()),
        );
        for seed in 1..6 {
            let mut previous: Option<Contact> = None;
            let steps = 400;
            for k in 0..=steps {
                // Through the blend (t from 1/8 to 1/2) in fine steps at one orientation.
                let t = 0.1 + 0.45 * f64::from(k) / f64::from(steps);
                let pose = pose(&mut Rng(seed), t);
                let (got, _) = query_pair(pair.as_ref(), pose, Isometry3::identity());
                let want = exact(&pose);
                assert_eq!(got.len(), 1, "FT {ft}, seed {seed}, t = {t}");
                let [depth, _, points, _] = errors(&got[0], &want[0]);
                assert!(
                    depth <= deviation,
                    "FT {ft}, seed {seed}, t = {t}: {depth:e}"
                );
                assert!(
                    points <= 4.0 * deviation,
                    "FT {ft}, seed {seed}, t = {t}: {points:e}"
                );
                if let Some(p) = previous {
                    // A step of 0.45/400 in t moves the exact depth by about k·Δt ≤ 1.3e-4:
                    // the blend adds no jump of the facets' size on top.
                    let jump = (got[0].penetration - p.penetration).abs();
                    assert!(jump < 2e-4, "FT {ft}, seed {seed}, t = {t}: jump {jump:e}");
                }
                previous = Some(got[0]);
            }
        }
    }
}

#[test]
fn only_tessellated_ellipsoids_are_taken_for_ellipsoids() {
    use engine_facet::Shape;
    let facet = engine(300.0028);
    let shape = |g: Geometry| match facet
        .prepare_geometry(&GeometryInstance::new(g), contact_core::Side::I)
        .unwrap()
        .shape
    {
        Shape::Mesh(m) => (m.implied_sphere.is_some(), m.implied_ellipsoid),
        _ => panic!("a mesh"),
    };
    let (sphere, none) = shape(Geometry::sphere(0.3).unwrap());
    assert!(sphere && none.is_none());
    let (_, found) = shape(ellipsoid());
    let (centre, semi) = found.expect("a tessellated ellipsoid");
    assert!(centre.coords.norm() < 1e-15);
    assert!((semi - Vector3::from(SEMI)).norm() < 1e-14, "{semi}");
    let torus = contact_core::geometry::Torus::new(0.1, 0.03).unwrap();
    assert_eq!(shape(Geometry::Torus(torus)), (false, None));
    let cylinder = contact_core::geometry::Cylinder::new(0.1, 0.3).unwrap();
    assert_eq!(shape(Geometry::Cylinder(cylinder)), (false, None));
}
