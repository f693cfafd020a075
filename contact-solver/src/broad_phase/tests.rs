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
