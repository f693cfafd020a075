//! One prepared pair queried from several threads at once gives the bits one thread gives.

use crate::common::*;
use contact_core::{Contact, Geometry, Isometry3, WorkCounters};

#[test]
fn concurrent_queries_match_a_single_thread_bit_for_bit() {
    let pair = prepare(
        &engine(300.0028),
        Geometry::sphere(1.0).unwrap(),
        Geometry::sphere(0.7).unwrap(),
    );
    let mut rng = Rng(5);
    let poses: Vec<Isometry3> = (0..24)
        .map(|_| {
            Isometry3::from_parts(
                (rng.unit_vector() * rng.range(0.4, 2.0)).into(),
                rng.rotation(),
            )
        })
        .collect();
    let run = |poses: &[Isometry3]| -> Vec<Vec<Contact>> {
        poses
            .iter()
            .map(|p| {
                let mut c = Vec::new();
                pair.query(
                    p,
                    &Isometry3::identity(),
                    &mut c,
                    &mut WorkCounters::default(),
                )
                .unwrap();
                c
            })
            .collect()
    };
    let serial = run(&poses);
    assert!(serial.iter().filter(|c| !c.is_empty()).count() > 10);
    let bits = |all: &[Vec<Contact>]| -> Vec<u64> {
        all.iter()
            .flatten()
            .flat_map(|c| {
                [
                    c.penetration,
                    c.area,
                    c.normal_w.x,
                    c.normal_w.y,
                    c.normal_w.z,
                    c.point_i_w.x,
                    c.point_j_w.z,
                ]
                .map(f64::to_bits)
            })
            .collect()
    };
    let results: Vec<Vec<Vec<Contact>>> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..4)
            .map(|k| {
                let mut order = poses.clone();
                order.rotate_left(k * 5); // each thread in a different order
                let run = &run;
                s.spawn(move || {
                    let mut r = run(&order);
                    r.rotate_right(k * 5);
                    r
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    for r in results {
        assert_eq!(bits(&r), bits(&serial));
    }
}
