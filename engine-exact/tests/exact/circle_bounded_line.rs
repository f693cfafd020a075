//! A circle against a bounded 2-D line: invariants (I/J swap, rigid motion, scale), the
//! reduction to the unbounded line's closed form, agreement with a closed 360° arc where the
//! overlap pairs read the line's end the same way, continuity as an end sweeps across the
//! disc, and the degenerate branches: touching, grazing at 1e-9, a centre on an end, a disc
//! wholly below the line, an end exactly on the circle or on its vertical tangent.

use crate::characterization::bounded_line::{disc_in_strip, line};
use crate::common::{Expected, Rng, assert_close, errors, instance, one, query};
use crate::properties::{Maker, Scene, check_motion, check_scale, check_swap, scaled_pose};
use contact_core::geometry::{Arc, Circle, Line};
use contact_core::{
    Contact, Geometry, GeometryEngine, GeometryInstance, Isometry3, Point3, Vector3,
};
use engine_exact::ExactEngine;
use std::f64::consts::{PI, TAU};

fn circle(r: f64) -> GeometryInstance {
    instance(Geometry::Circle(Circle::new(r).unwrap()))
}

fn at(x: f64, y: f64) -> Isometry3 {
    Isometry3::translation(x, y, 0.0)
}

/// A circle near a bounded line's end (or both ends), its centre from well below the line
/// to just under its radius above, the line flipped now and then.
fn circle_bounded_line(rng: &mut Rng, s: f64) -> Scene {
    let r = rng.uniform(0.3, 2.0);
    let x = rng.uniform(-2.0, 2.0);
    let x0 = x + rng.uniform(-1.2, 1.2) * r;
    let x1 = if rng.uniform(0.0, 1.0) < 0.5 {
        f64::INFINITY
    } else {
        x0 + rng.uniform(0.3, 3.0) * r
    };
    let flip = rng.uniform(0.0, 1.0) < 0.3;
    let height = rng.uniform(-1.5, 0.9) * r;
    let y = if flip { -height } else { height };
    let pose_j = rng.pose(3.0);
    let j = instance(line(x0 * s, x1 * s));
    Scene {
        i: circle(r * s),
        j: if flip { j.flipped() } else { j },
        pose_i: scaled_pose(&(pose_j * at(x, y)), s),
        pose_j: scaled_pose(&pose_j, s),
        length: r * s,
    }
}

const MAKERS: [(&str, Maker); 1] = [("circle–bounded line", circle_bounded_line)];

#[test]
fn exchanging_i_and_j_gives_the_swapped_contact() {
    check_swap(&MAKERS, 31);
}

#[test]
fn a_rigid_motion_of_both_bodies_moves_the_contact() {
    check_motion(&MAKERS, 32);
}

#[test]
fn scaling_the_scene_scales_depth_and_points() {
    check_scale(&MAKERS, 33);
}

/// The unbounded line's closed form for a circle of radius `r` centred at `(x, d)`.
fn unbounded(r: f64, x: f64, d: f64) -> Expected {
    Expected {
        point_i: Point3::new(x, d - r, 0.0),
        point_j: Point3::new(x, 0.0, 0.0),
        normal: Vector3::y(),
        depth: r - d,
    }
}

fn assert_expected(c: &Contact, e: &Expected, length: f64, tol: f64, what: &str) {
    let err = errors(c, e, length);
    assert!(
        err.iter().all(|&x| x <= tol),
        "{what}: {err:?}\n{c:?}\n{e:?}"
    );
}

#[test]
fn a_range_covering_the_disc_is_the_unbounded_line_also_wholly_below_it() {
    let mut rng = Rng::new(41);
    let wide = instance(line(-1e8, 1e8));
    let open = instance(Geometry::Line(Line::unbounded()));
    for _ in 0..200 {
        let r = rng.uniform(0.3, 2.0);
        let world = rng.pose(10.0);
        let pose_i = world * at(rng.uniform(-20.0, 20.0), rng.uniform(-2.5, 0.99) * r);
        let a = one(&circle(r), &wide, &pose_i, &world);
        let b = one(&circle(r), &open, &pose_i, &world);
        assert_close(&a, &b, r, r, 1e-12, "wide vs unbounded");
    }
    // The disc's edge exactly on an end's vertical, inside: the ends cut nothing. (Dyadic
    // values, so the end lies on the vertical to the last bit: an end inside by ε cuts a
    // chord of √(8rε), which tilts the normal by about that much.)
    for (d, x) in [(0.4, 0.25), (-0.6, -1.125), (-1.7, 2.0)] {
        let r = 0.75;
        for range in [
            [x - r, f64::INFINITY],
            [f64::NEG_INFINITY, x + r],
            [x - r, x + r],
        ] {
            let c = one(
                &circle(r),
                &instance(line(range[0], range[1])),
                &at(x, d),
                &Isometry3::identity(),
            );
            assert_expected(
                &c,
                &unbounded(r, x, d),
                r,
                1e-12,
                "edge on the end's vertical",
            );
            let chord = if d > 0.0 {
                2.0 * (r * r - d * d).sqrt()
            } else {
                2.0 * r
            };
            assert!((c.area - chord).abs() < 1e-12, "{c:?}");
        }
    }
}

#[test]
fn touching_the_line_or_an_ends_vertical_from_outside_is_no_contact() {
    let r = 0.7;
    let none = |range: [f64; 2], x: f64, y: f64| {
        let found = query(
            &circle(r),
            &instance(line(range[0], range[1])),
            &at(x, y),
            &Isometry3::identity(),
        );
        assert!(found.is_empty(), "{range:?} ({x}, {y}): {found:?}");
    };
    // On the line from above, inside the range and right over an end.
    none([-1.0, 2.0], 0.5, r);
    none([-1.0, 2.0], -1.0, r);
    none([-1.0, 2.0], 2.0, r);
    // Beyond an end, touching its vertical from outside: above, across and below the line.
    for y in [0.3, 0.0, -0.5, -2.0] {
        none([-1.0, 2.0], -1.0 - r, y);
        none([-1.0, 2.0], 2.0 + r, y);
        none([0.0, f64::INFINITY], -r, y);
    }
    // Just inside, a contact (the test would pass on an engine that never answers).
    assert_eq!(
        query(
            &circle(r),
            &instance(line(0.0, f64::INFINITY)),
            &at(-r + 1e-3, -0.5),
            &Isometry3::identity()
        )
        .len(),
        1
    );
}

#[test]
fn grazing_by_1e_9_gives_the_closed_form_depth_and_a_tiny_contact_at_an_end() {
    let r = 1.0;
    let d = r - 1e-9;
    let bounded = instance(line(-1.0, 2.0));
    let c = one(&circle(r), &bounded, &at(0.5, d), &Isometry3::identity());
    assert!((c.penetration - (r - d)).abs() <= 1e-15, "{c:?}");
    assert_expected(
        &c,
        &unbounded(r, 0.5, d),
        r,
        1e-12,
        "grazing inside the range",
    );
    // Straight over an end: a quarter of the lens, the same depth to its own round-off,
    // the normal leaning off the end by about ½h₀/L = ½·1e-9/√(2e-9).
    for (x, lean) in [(-1.0, -1.0), (2.0, 1.0)] {
        let c = one(&circle(r), &bounded, &at(x, d), &Isometry3::identity());
        assert!(c.penetration > 0.0 && c.penetration <= 1.1e-9, "{c:?}");
        let tilt = 0.5e-9 / 2e-9f64.sqrt();
        assert!((c.normal_w.x - lean * tilt).abs() < 1e-3 * tilt, "{c:?}");
        assert!(c.area > 0.0 && c.area < 1e-4, "{c:?}");
    }
}

/// The contact of a circle of radius `r` centred at the origin on the end of `[0, ∞)`, by
/// hand: the quarter disc, centroid `c(1, −1)` with `c = 4r/3π`; `h₀ = L = W = r`, so
/// `S = (r/2, −r)` and `n = (−1, 2)/√5`; the normal's line meets the line at `(c/2, 0)`.
fn quarter(r: f64) -> (Expected, f64) {
    let c = 4.0 * r / (3.0 * PI);
    let n = Vector3::new(-1.0, 2.0, 0.0) / 5f64.sqrt();
    let g = Vector3::new(c, -c, 0.0);
    let gn = g.dot(&n);
    let back = gn + (r * r - g.norm_squared() + gn * gn).sqrt();
    let on_circle = Point3::from(g - back * n);
    let on_line = Point3::new(0.5 * c, 0.0, 0.0);
    let expected = Expected {
        point_i: on_circle,
        point_j: on_line,
        normal: n,
        depth: (on_line - on_circle).norm(),
    };
    // Extent across n: the vertices (0, 0), (0, −r), (r, 0) seen along (−2, −1)/√5.
    (expected, 3.0 * r / 5f64.sqrt())
}

#[test]
fn a_centre_on_an_end_cuts_the_quarter_disc_and_mirrors_with_the_line() {
    let r = 1.5;
    let (e, length) = quarter(r);
    let c = one(
        &circle(r),
        &instance(line(0.0, f64::INFINITY)),
        &Isometry3::identity(),
        &Isometry3::identity(),
    );
    assert_expected(&c, &e, r, 1e-14, "quarter disc");
    assert!((c.area - length).abs() < 1e-14, "{c:?}");
    // The range mirrored in x, and the line flipped (its material above): mirrored answers.
    let mirror_x: fn(Point3) -> Point3 = |p| Point3::new(-p.x, p.y, 0.0);
    let mirror_y: fn(Point3) -> Point3 = |p| Point3::new(p.x, -p.y, 0.0);
    let cases = [
        (instance(line(f64::NEG_INFINITY, 0.0)), mirror_x),
        (instance(line(0.0, f64::INFINITY)).flipped(), mirror_y),
    ];
    for (j, mirror) in cases {
        let m = one(
            &circle(r),
            &j,
            &Isometry3::identity(),
            &Isometry3::identity(),
        );
        let normal = mirror(Point3::from(e.normal)).coords;
        let expected = Expected {
            point_i: mirror(e.point_i),
            point_j: mirror(e.point_j),
            normal,
            depth: e.depth,
        };
        assert_expected(&m, &expected, r, 1e-14, "mirrored quarter disc");
    }
}

#[test]
fn a_disc_wholly_below_the_line_pushes_up_inside_the_range_and_leans_off_an_end() {
    let r = 0.9;
    let j = instance(line(0.0, 5.0));
    // Inside the range: the unbounded closed form, depth past the diameter.
    let c = one(&circle(r), &j, &at(2.0, -1.5 * r), &Isometry3::identity());
    assert_expected(&c, &unbounded(r, 2.0, -1.5 * r), r, 1e-12, "sunk");
    assert!((c.area - 2.0 * r).abs() < 1e-12, "{c:?}");
    // Centred on the end, sunk by 2r: the half disc right of the end, centroid 4r/3π right
    // of the centre; h₀ = 2r, L = 0, W = r, so S = (r, −r/2) and n = (−2, 1)/√5, whose line
    // meets the line left of the end: the end itself.
    let c = one(&circle(r), &j, &at(0.0, -2.0 * r), &Isometry3::identity());
    let n = Vector3::new(-2.0, 1.0, 0.0) / 5f64.sqrt();
    let g = Vector3::new(4.0 * r / (3.0 * PI), -2.0 * r, 0.0);
    let centre = Vector3::new(0.0, -2.0 * r, 0.0);
    let gn = (g - centre).dot(&n);
    let back = gn + (r * r - (g - centre).norm_squared() + gn * gn).sqrt();
    let on_circle = Point3::from(g - back * n);
    let expected = Expected {
        point_i: on_circle,
        point_j: Point3::origin(),
        normal: n,
        depth: on_circle.coords.norm(),
    };
    assert_expected(&c, &expected, r, 1e-14, "sunk on the end");
}

#[test]
fn an_end_on_the_circle_is_the_limit_of_the_end_just_inside_or_outside() {
    let (r, x, d) = (1.0f64, 0.2, 0.35);
    let w = (r * r - d * d).sqrt();
    let lens = unbounded(r, x, d);
    for (x0, x1) in [(x - w, f64::INFINITY), (f64::NEG_INFINITY, x + w)] {
        let c = one(
            &circle(r),
            &instance(line(x0, x1)),
            &at(x, d),
            &Isometry3::identity(),
        );
        assert_expected(&c, &lens, r, 1e-12, "end on the crossing");
        for nudge in [-1e-9, 1e-9] {
            let (y0, y1) = if x0.is_finite() {
                (x0 + nudge, x1)
            } else {
                (x0, x1 - nudge)
            };
            let near = one(
                &circle(r),
                &instance(line(y0, y1)),
                &at(x, d),
                &Isometry3::identity(),
            );
            assert_close(&near, &c, r, r, 1e-7, "end nudged across the crossing");
        }
    }
}

/// A closed 360° arc answers as the circle where the overlap reads the end the same way.
#[test]
fn a_closed_arc_agrees_where_the_overlap_reads_the_half_strip() {
    let mut rng = Rng::new(43);
    let arc = instance(Geometry::Arc(Arc::new(1.0, TAU).unwrap()));
    for k in 0..80 {
        let (x, d) = (rng.uniform(-1.0, 1.0), rng.uniform(0.05, 0.9));
        let w = (1.0 - d * d).sqrt();
        // Even k: the region's span (the lens) inside the range, an end over the disc but
        // outside the lens. Odd k: an end straight below the centre.
        let (range, whole) = if k % 2 == 0 {
            ([x - w - rng.uniform(0.02, 0.98) * (1.0 - w), x + 3.0], true)
        } else if k % 4 == 1 {
            ([x, f64::INFINITY], false)
        } else {
            ([f64::NEG_INFINITY, x], false)
        };
        let j = instance(line(range[0], range[1]));
        let world = rng.pose(3.0);
        let pose_i = world * at(x, d);
        let from_arc = one(&arc, &j, &(world * at(x, d)), &world);
        let from_circle = one(&circle(1.0), &j, &pose_i, &world);
        // The arc's length is |S|, the circle's the region's extent across n: equal for the
        // lens, not for the quarter lens.
        let compared = if whole {
            from_circle
        } else {
            Contact {
                area: from_arc.area,
                ..from_circle
            }
        };
        assert_close(&compared, &from_arc, 1.0, 1.0, 1e-9, "circle vs closed arc");
    }
}

#[test]
fn sliding_across_an_end_moves_the_contact_continuously() {
    let r = 1.0f64;
    let j = instance(line(0.0, f64::INFINITY));
    let step_x = 3.0 / 4000.0;
    for d in [0.6, 0.0, -0.5, -1.2, -2.5] {
        // The region appears when the lens (centre above the line) or the disc (below it)
        // reaches the end.
        let reach = if d > 0.0 { (r * r - d * d).sqrt() } else { r };
        let mut last: Option<Contact> = None;
        let mut touching = 0;
        for step in 0..=4000 {
            let x = -1.5 + step_x * step as f64;
            let found = query(&circle(r), &j, &at(x, d), &Isometry3::identity());
            match (found.as_slice(), last) {
                ([c], Some(p)) => {
                    touching += 1;
                    // An end entering or leaving the disc cuts a chord growing as the square
                    // root of its way in, so a step of 7.5e-4 r may turn the normal by a few
                    // 1e-2, and move the line's point by that times the lever |d| + r; a
                    // jump would be of order one.
                    let what = format!("d {d}, x {x}: {p:?} → {c:?}");
                    let lever = 0.1 * (1.0 + d.abs());
                    assert!((c.normal_w - p.normal_w).norm() < 0.1, "{what}");
                    assert!((c.penetration - p.penetration).abs() < lever, "{what}");
                    assert!((c.point_i_w - p.point_i_w).norm() < lever, "{what}");
                    assert!((c.point_j_w - p.point_j_w).norm() < lever, "{what}");
                }
                // A contact appears only as the region starts: at the crossing with no depth
                // when the centre is above the line; with the centre below it the sliver
                // entering past the end lies under the line, and its depth is measured to the
                // end (documented in the module).
                ([c], None) => {
                    assert!((x + reach).abs() <= 2.0 * step_x, "d {d}, x {x}: {c:?}");
                    if d >= 0.0 {
                        assert!(c.penetration < 0.03, "d {d}, x {x}: {c:?}");
                    }
                }
                ([], Some(_)) => panic!("d {d}, x {x}: the contact vanished"),
                ([], None) => {}
                (many, _) => panic!("{many:?}"),
            }
            last = found.first().copied();
        }
        assert!(touching > 1000, "d {d}: {touching}");
        // Far inside the range, the unbounded closed form.
        assert_expected(&last.unwrap(), &unbounded(r, 1.5, d), r, 1e-12, "inside");
    }
}

#[test]
fn a_flipped_circle_on_a_bounded_line_is_refused_before_any_query() {
    let hole = circle(1.0).flipped();
    let j = instance(line(0.0, 1.0));
    for (i, j) in [(hole.clone(), j.clone()), (j, hole)] {
        let err = ExactEngine.prepare(&[i], &[j]).unwrap_err();
        assert!(err.to_string().contains("flipped"), "{err}");
    }
}

#[test]
fn the_oracle_and_the_engine_agree_on_sunk_and_doubly_cut_discs() {
    // Beyond the characterization's family: centres sunk below the line, both ends over the
    // disc, a short line inside a large disc.
    let mut rng = Rng::new(47);
    let mut checked = 0;
    while checked < 300 {
        let r = rng.uniform(0.5, 2.0);
        let (x, y) = (rng.uniform(-1.0, 1.0), rng.uniform(-2.5, 0.9) * r);
        let x0 = x + rng.uniform(-1.1, 0.9) * r;
        let x1 = x0 + rng.uniform(0.05, 2.5) * r;
        let Some(strip) = disc_in_strip(r, -y, x0 - x, x1 - x) else {
            continue;
        };
        if strip.area < 0.02 * r * r {
            continue;
        }
        let c = one(
            &circle(r),
            &instance(line(x0, x1)),
            &at(x, y),
            &Isometry3::identity(),
        );
        assert_expected(
            &c,
            &strip.expected(x, y, 1.0),
            r,
            1e-12,
            "sunk or doubly cut",
        );
        checked += 1;
    }
}
