use super::*;
use crate::dae::EvaluationError;
use crate::mbs::{Load, StateView};
use contact_core::{Geometry, Isometry3};
use nalgebra::{Translation3, UnitQuaternion};

#[test]
fn one_ellipsoid_is_a_ball_and_a_list_a_box_in_the_part() {
    let ball = GeometryInstance::new(Geometry::sphere(0.5).unwrap())
        .at(Isometry3::translation(1.0, 0.0, 0.0));
    let b = Bounds::enclosing(std::slice::from_ref(&ball)).unwrap();
    assert_eq!(b.centre_p, Vector3::new(1.0, 0.0, 0.0));
    assert_eq!(b.shape, BoundsShape::Ball(0.5));
    let other = GeometryInstance::new(Geometry::sphere(0.25).unwrap())
        .at(Isometry3::translation(-1.0, 0.0, 0.0));
    let b = Bounds::enclosing(&[ball, other]).unwrap();
    assert_eq!(b.centre_p, Vector3::new(0.125, 0.0, 0.0));
    assert_eq!(b.shape, BoundsShape::Box(Vector3::new(1.375, 0.5, 0.5)));
    let plane = GeometryInstance::new(Geometry::Plane(contact_core::geometry::Plane::unbounded()));
    assert!(Bounds::enclosing(&[plane]).is_none());
    let cavity = GeometryInstance::new(Geometry::sphere(1.0).unwrap()).flipped();
    assert!(Bounds::enclosing(&[cavity]).is_none());
    assert!(Bounds::enclosing(&[]).is_none());
}

#[test]
fn apart_keeps_the_margin_on_every_axis() {
    let h = Vector3::repeat(1.0);
    let a = (Vector3::zeros(), h);
    for axis in 0..3 {
        let far = Vector3::ith(axis, 2.0 * (1.0 + MARGIN) + 1e-12);
        assert!(Bounds::apart(&a, &(far, h)));
        let near = Vector3::ith(axis, 2.0 * (1.0 + MARGIN) - 1e-12);
        assert!(!Bounds::apart(&a, &(near, h)));
    }
}

/// An element between two parts with given bounds (or none), whose loads are never asked.
struct Bounded {
    parts: [PartId; 2],
    bounds: Option<[Bounds; 2]>,
}

impl ForceElement for Bounded {
    fn name(&self) -> &str {
        "bounded"
    }

    fn parts(&self) -> &[PartId] {
        &self.parts
    }

    fn evaluate(&self, _: f64, _: &StateView<'_>, _: &mut [Load]) -> Result<(), EvaluationError> {
        Ok(())
    }

    fn bounds(&self) -> Option<[Bounds; 2]> {
        self.bounds
    }
}

/// SplitMix64 in [0, 1).
fn uniform(state: &mut u64) -> f64 {
    *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
}

#[test]
fn the_sweep_finds_exactly_the_pairs_the_brute_force_test_keeps() {
    let mut seed = 7;
    let parts = 40;
    let mut bounds_of_part = Vec::new();
    for _ in 0..=parts {
        let centre_p = Vector3::from_fn(|_, _| 0.1 * (uniform(&mut seed) - 0.5));
        let shape = if uniform(&mut seed) < 0.5 {
            BoundsShape::Ball(0.05 + 0.1 * uniform(&mut seed))
        } else {
            BoundsShape::Box(Vector3::from_fn(|_, _| 0.02 + 0.2 * uniform(&mut seed)))
        };
        bounds_of_part.push(Bounds { centre_p, shape });
    }
    // Every pair of parts (ground included), a tenth without bounds.
    let mut elements: Vec<Box<dyn ForceElement>> = Vec::new();
    for a in 0..=parts {
        for b in a + 1..=parts {
            let bounds = (uniform(&mut seed) > 0.1).then(|| [bounds_of_part[a], bounds_of_part[b]]);
            elements.push(Box::new(Bounded {
                parts: [PartId(a), PartId(b)],
                bounds,
            }));
        }
    }
    let broad = BroadPhase::new(&elements);
    let mut some_skipped = false;
    for round in 0..20 {
        let spread = 0.2 + 0.1 * round as f64;
        let states: Vec<PartState> = (0..=parts)
            .map(|k| {
                let mut state = PartState::GROUND;
                if k > 0 {
                    let r = Vector3::from_fn(|_, _| spread * (uniform(&mut seed) - 0.5));
                    let axis = Vector3::from_fn(|_, _| uniform(&mut seed) - 0.5);
                    state.pose_w = Isometry3::from_parts(
                        Translation3::from(r),
                        UnitQuaternion::from_scaled_axis(axis * 3.0),
                    );
                }
                state
            })
            .collect();
        let brute: Vec<usize> = elements
            .iter()
            .enumerate()
            .filter(|(_, e)| match (e.bounds(), e.parts()) {
                (Some([ba, bb]), [pa, pb]) => {
                    !Bounds::apart(&ba.world_box(&states[pa.0]), &bb.world_box(&states[pb.0]))
                }
                _ => true,
            })
            .map(|(k, _)| k)
            .collect();
        let swept = broad.candidates(&states);
        assert_eq!(swept, brute, "round {round}");
        some_skipped |= swept.len() < elements.len();
    }
    assert!(some_skipped);
    let (evaluated, skipped) = broad.counts();
    assert_eq!(evaluated + skipped, 20 * elements.len() as u64);
}

/// A rotation from three uniform numbers (Shoemake's method: uniform over rotations).
fn random_rotation(seed: &mut u64) -> UnitQuaternion<f64> {
    let (u1, u2, u3) = (uniform(seed), uniform(seed), uniform(seed));
    let tau = std::f64::consts::TAU;
    let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
    UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
        b * (tau * u3).cos(),
        a * (tau * u2).sin(),
        a * (tau * u2).cos(),
        b * (tau * u3).sin(),
    ))
}

fn random_pose(seed: &mut u64, reach: f64) -> Isometry3 {
    let t = Vector3::new(uniform(seed), uniform(seed), uniform(seed)) * 2.0 * reach
        - Vector3::repeat(reach);
    Isometry3::from_parts(Translation3::from(t), random_rotation(seed))
}

/// The solids a CONTACT's side may hold, each with points of its surface sampled from its own
/// parametrisation (the geometry frame conventions of `contact_core::geometry`: cylinder and
/// frustum along +z from z = 0, torus about z, box about its centre, mesh by its vertices).
fn solids_with_surface_points(seed: &mut u64) -> Vec<(Geometry, Vec<Vector3<f64>>)> {
    use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid, Frustum, Torus};
    let tau = std::f64::consts::TAU;
    let mut angles = |k: usize| -> Vec<(f64, f64, f64)> {
        (0..k)
            .map(|_| (tau * uniform(seed), tau * uniform(seed), uniform(seed)))
            .collect()
    };
    let (a, b, c) = (0.3, 0.2, 0.1);
    let ellipsoid = angles(400)
        .into_iter()
        .map(|(u, v, _)| Vector3::new(a * u.sin() * v.cos(), b * u.sin() * v.sin(), c * u.cos()))
        .collect();
    let (r, l) = (0.25, 0.7);
    let cylinder = angles(400)
        .into_iter()
        .map(|(u, _, s)| Vector3::new(r * u.cos(), r * u.sin(), l * s))
        .collect();
    let (r0, r1) = (0.1, 0.35);
    let frustum = angles(400)
        .into_iter()
        .map(|(u, _, s)| {
            let radius = r0 + (r1 - r0) * s;
            Vector3::new(radius * u.cos(), radius * u.sin(), l * s)
        })
        .collect();
    let (big, small) = (0.4, 0.12);
    let torus = angles(400)
        .into_iter()
        .map(|(u, v, _)| {
            let ring = big + small * v.cos();
            Vector3::new(ring * u.cos(), ring * u.sin(), small * v.sin())
        })
        .collect();
    let corner = Vector3::new(0.3, -0.2, 0.5);
    let cuboid = (0..8)
        .map(|k| Vector3::new(f64::from(k & 1), f64::from((k >> 1) & 1), f64::from(k >> 2)))
        .map(|unit| corner.component_mul(&unit))
        .collect();
    let tetrahedron = [
        Vector3::new(0.0, 0.0, 0.0),
        Vector3::new(0.5, 0.1, 0.0),
        Vector3::new(0.1, 0.4, -0.1),
        Vector3::new(0.2, 0.1, 0.6),
    ];
    let mesh = contact_core::geometry::TriangleMesh::new(
        tetrahedron
            .iter()
            .map(|v| nalgebra::Point3::from(*v))
            .collect(),
        vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
    )
    .unwrap();
    vec![
        (
            Geometry::Ellipsoid(Ellipsoid::new(a, b, c).unwrap()),
            ellipsoid,
        ),
        (Geometry::Cylinder(Cylinder::new(r, l).unwrap()), cylinder),
        (Geometry::Frustum(Frustum::new(r0, r1, l).unwrap()), frustum),
        (Geometry::Torus(Torus::new(big, small).unwrap()), torus),
        (
            Geometry::Cuboid(Cuboid::from_corner(corner.x, corner.y, corner.z).unwrap()),
            cuboid,
        ),
        (
            Geometry::Mesh(std::sync::Arc::new(mesh)),
            tetrahedron.to_vec(),
        ),
    ]
}

#[test]
fn the_bounds_enclose_every_point_of_their_geometry_at_every_pose() {
    let mut seed = 11;
    let solids = solids_with_surface_points(&mut seed);
    for trial in 0..200 {
        // One or two solids on the part, each at its own pose in the part frame.
        let count = 1 + trial % 2;
        let picked: Vec<usize> = (0..count)
            .map(|_| (uniform(&mut seed) * solids.len() as f64) as usize)
            .collect();
        let instances: Vec<GeometryInstance> = picked
            .iter()
            .map(|&k| GeometryInstance::new(solids[k].0.clone()).at(random_pose(&mut seed, 0.5)))
            .collect();
        let bounds = Bounds::enclosing(&instances).unwrap();
        let state = PartState {
            pose_w: random_pose(&mut seed, 3.0),
            ..PartState::GROUND
        };
        let (centre, half) = bounds.world_box(&state);
        for (instance, &k) in instances.iter().zip(&picked) {
            for p in &solids[k].1 {
                let world =
                    state.pose_w * (instance.pose_part_geometry * nalgebra::Point3::from(*p));
                let outside = (world.coords - centre).abs() - half;
                assert!(
                    outside.max() <= 1e-12,
                    "trial {trial}, {:?}: {p:?} is {outside:?} outside",
                    solids[k].0.kind()
                );
            }
        }
    }
}

#[test]
fn where_the_bounds_are_apart_neither_engine_finds_a_contact() {
    use contact_core::{FacetingTolerance, GeometryEngine, WorkCounters};
    let mut seed = 12;
    let solids: Vec<Geometry> = solids_with_surface_points(&mut seed)
        .into_iter()
        .map(|(g, _)| g)
        .collect();
    let engines: [Box<dyn GeometryEngine>; 2] = [
        Box::new(engine_exact::ExactEngine),
        Box::new(engine_facet::FacetEngine::new(
            FacetingTolerance::new(300.0028).unwrap(),
        )),
    ];
    let mut apart = 0;
    for (ki, i) in solids.iter().enumerate() {
        for j in &solids[ki..] {
            let list_i = [GeometryInstance::new(i.clone()).at(random_pose(&mut seed, 0.2))];
            let list_j = [GeometryInstance::new(j.clone()).at(random_pose(&mut seed, 0.2))];
            let (bi, bj) = (
                Bounds::enclosing(&list_i).unwrap(),
                Bounds::enclosing(&list_j).unwrap(),
            );
            for engine in &engines {
                let Ok(pair) = engine.prepare(&list_i, &list_j) else {
                    continue;
                };
                for _ in 0..40 {
                    // Part J along a random direction from part I, just beyond the distance
                    // where the two world boxes come apart (found by bisection: apartness grows
                    // with the distance along a fixed direction).
                    let state_i = PartState {
                        pose_w: random_pose(&mut seed, 0.1),
                        ..PartState::GROUND
                    };
                    let rotation_j = random_rotation(&mut seed);
                    let direction = random_pose(&mut seed, 1.0).translation.vector.normalize();
                    let at = |distance: f64| PartState {
                        pose_w: Isometry3::from_parts(
                            Translation3::from(
                                state_i.pose_w.translation.vector + direction * distance,
                            ),
                            rotation_j,
                        ),
                        ..PartState::GROUND
                    };
                    let is_apart = |distance: f64| {
                        Bounds::apart(&bi.world_box(&state_i), &bj.world_box(&at(distance)))
                    };
                    let (mut near, mut far) = (0.0, 10.0);
                    for _ in 0..60 {
                        let mid = 0.5 * (near + far);
                        if is_apart(mid) {
                            far = mid;
                        } else {
                            near = mid;
                        }
                    }
                    let state_j = at(far);
                    if !is_apart(far) {
                        continue;
                    }
                    apart += 1;
                    let mut contacts = Vec::new();
                    let mut work = WorkCounters::default();
                    if pair
                        .query(&state_i.pose_w, &state_j.pose_w, &mut contacts, &mut work)
                        .is_ok()
                        && !contacts.is_empty()
                    {
                        panic!(
                            "{}: {:?} and {:?} apart by their bounds, yet {contacts:?}",
                            engine.name(),
                            i.kind(),
                            j.kind()
                        );
                    }
                }
            }
        }
    }
    assert!(apart > 500, "only {apart} apart poses");
}
