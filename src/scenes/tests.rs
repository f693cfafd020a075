//! The suite is well formed, and the closed forms agree with the nominal placements where the
//! placement is exact (spheres, circles, a cylinder on its side).

use super::*;

#[test]
fn every_named_scene_exists_with_finite_poses_over_every_depth() {
    let all = suite();
    assert_eq!(all.len(), NAMES.len());
    for s in &all {
        assert_eq!(s.poses.len(), POSES, "{}", s.name);
        for p in &s.poses {
            let finite = |x: &Isometry3| {
                x.translation
                    .vector
                    .iter()
                    .chain(x.rotation.coords.iter())
                    .all(|c| c.is_finite())
            };
            assert!(
                finite(&p.pose_world_i) && finite(&p.pose_world_j),
                "{}",
                s.name
            );
        }
    }
    assert!(scene("no_such_scene").is_none());
}

#[test]
fn closed_forms_return_the_nominal_depth_where_placement_is_exact() {
    for name in [
        "sphere_plane",
        "sphere_sphere",
        "cylinder_plane_side",
        "circle_circle",
    ] {
        let s = scene(name).unwrap();
        let f = s.closed_form.unwrap();
        for p in &s.poses {
            let contacts = f(&s, p);
            if p.nominal_depth < 0.0 {
                assert!(
                    contacts.is_empty(),
                    "{name}: separated pose gave {contacts:?}"
                );
                continue;
            }
            assert_eq!(contacts.len(), 1, "{name}");
            let c = contacts[0];
            assert!(c.is_well_formed(), "{name}: {c:?}");
            assert!(
                (c.penetration - p.nominal_depth).abs() < 1e-12 * s.scale.max(1.0) * 10.0,
                "{name}: {} vs {}",
                c.penetration,
                p.nominal_depth
            );
            // The points are δ apart along the normal, I's deeper into J.
            let gap = c.point_i_w - c.point_j_w;
            assert!((gap + c.normal_w * c.penetration).norm() < 1e-9, "{name}");
        }
    }
}

#[test]
fn scaling_a_scene_scales_its_closed_form_answer() {
    let s = scene("sphere_sphere").unwrap();
    for factor in [1e-6, 1e6] {
        let big = s.scaled(factor).unwrap();
        for (p, q) in s.poses.iter().zip(&big.poses) {
            let (a, b) = (sphere_sphere(&s, p), sphere_sphere(&big, q));
            assert_eq!(a.len(), b.len());
            for (a, b) in a.iter().zip(&b) {
                assert!(
                    (b.penetration / factor - a.penetration).abs()
                        <= 1e-9 * a.penetration.max(1e-12) + 1e-15
                );
            }
        }
    }
}

#[test]
fn scaled_curves_stay_the_same_shape() {
    let s = scene("curve_curve").unwrap();
    let big = s.scaled(1e3).unwrap();
    let (Geometry::Curve(a), Geometry::Curve(b)) = (&*s.j[0].geometry, &*big.j[0].geometry) else {
        panic!("curves")
    };
    for k in 0..20 {
        let u = a.domain()[1] * k as f64 / 20.0;
        assert!((b.point(u) - a.point(u) * 1e3).norm() < 1e-9);
    }
}

/// The contacts `pair` answers at `pose`.
fn exact_contacts(pair: &dyn contact_core::PreparedPair, pose: &ScenePose) -> Vec<Contact> {
    let mut out = Vec::new();
    pair.query(
        &pose.pose_world_i,
        &pose.pose_world_j,
        &mut out,
        &mut contact_core::WorkCounters::default(),
    )
    .unwrap();
    out
}

/// How far inside the round surface about its frame's origin a mesh may lie: its largest
/// vertex radius less its faces' smallest distance from the origin (for a mesh inscribed in a
/// sphere, an upper bound on its chord sagitta); zero for anything but a mesh.
fn inscribed_gap(g: &GeometryInstance) -> f64 {
    let Geometry::Mesh(mesh) = &*g.geometry else {
        return 0.0;
    };
    let v = mesh.vertices();
    let outer = v.iter().map(|p| p.coords.norm()).fold(0.0, f64::max);
    let inner = mesh
        .triangles()
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|k| v[k as usize]);
            let n = (b - a).cross(&(c - a)).normalize();
            a.coords.dot(&n).abs()
        })
        .fold(f64::INFINITY, f64::min);
    outer - inner
}

/// Every graded pose (nominal depth 1e-4 of the scale and deeper) touches, and every
/// separated pose does not, by the exact engine wherever it answers the scene: a placement
/// that misses (two turned ellipsoids placed by their support extents alone never touched)
/// would leave a scene without contacts to measure. Two meshes inscribed in the round solids
/// their nominal depth is measured on touch once that depth passes both meshes' gaps
/// ([`inscribed_gap`]): shallower, their faces may lie apart.
#[test]
fn graded_poses_touch_and_separated_poses_do_not() {
    use contact_core::{GeometryEngine, PrepareError};
    for s in suite() {
        let pair = match engine_exact::ExactEngine.prepare(&s.i, &s.j) {
            Ok(pair) => pair,
            Err(PrepareError::Unsupported(_)) => continue,
            Err(e) => panic!("{}: {e}", s.name),
        };
        let is_mesh = |g: &GeometryInstance| matches!(&*g.geometry, Geometry::Mesh(_));
        let gap = if s.i.iter().chain(&s.j).all(is_mesh) {
            s.i.iter().chain(&s.j).map(inscribed_gap).sum::<f64>() / s.scale
        } else {
            0.0
        };
        for (k, p) in s.poses.iter().enumerate() {
            let out = exact_contacts(pair.as_ref(), p);
            let relative = p.nominal_depth / s.scale;
            if relative >= 1e-4 + gap {
                assert!(!out.is_empty(), "{} pose {k} (depth {relative:e})", s.name);
            } else if relative < 0.0 {
                assert!(out.is_empty(), "{} pose {k}: {out:?}", s.name);
            }
        }
    }
}

/// The kernel scenes' nominal depths are how far I has travelled along the approach past
/// first touch, by the exact engine: each scene touches at every graded pose from 1e-3 of its
/// scale on (the labels are rounded up to four digits) and is clear at its separated poses; where the nominal depth is a closed form (a pin in a slot,
/// a sphere on a box face, on a cylinder's side and on a mesh foot, a box face across an
/// upright frustum) the engine's depth is the nominal depth at every graded pose.
#[test]
fn kernel_scenes_touch_past_first_touch_and_hold_their_closed_forms() {
    use contact_core::GeometryEngine;
    let closed = [
        "cylinder_box",
        "sphere_box_face",
        "sphere_cylinder_side",
        "sphere_mesh_foot",
        "box_frustum",
    ];
    let all = kernel_scenes();
    let mut wrong = Vec::new();
    assert_eq!(all.len(), KERNEL_NAMES.len());
    for s in &all {
        assert!(!NAMES.contains(&&*s.name), "{} is in the suite too", s.name);
        assert_eq!(scene(&s.name).map(|f| f.poses), Some(s.poses.clone()));
        assert_eq!(s.poses.len(), POSES, "{}", s.name);
        let pair = engine_exact::ExactEngine.prepare(&s.i, &s.j).unwrap();
        for (k, p) in s.poses.iter().enumerate() {
            let out = exact_contacts(pair.as_ref(), p);
            let relative = p.nominal_depth / s.scale;
            let depths: Vec<f64> = out.iter().map(|c| c.penetration).collect();
            if relative < 0.0 && !out.is_empty() {
                wrong.push(format!("{} pose {k}: separated, yet {depths:?}", s.name));
            } else if relative >= 1e-3 && out.is_empty() {
                wrong.push(format!("{} pose {k} at {relative:e}: no contact", s.name));
            }
            let closed_form = closed.contains(&&*s.name) && relative >= 1e-4;
            if closed_form
                && (depths.len() != 1 || (depths[0] - p.nominal_depth).abs() > 1e-12 * s.scale)
            {
                let nominal = p.nominal_depth;
                wrong.push(format!("{} pose {k}: {depths:?} against {nominal}", s.name));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
