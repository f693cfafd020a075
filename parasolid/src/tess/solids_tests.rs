//! Bodies built directly on the free-form faces a CAD system gives cam lobes and crowned
//! rollers, each without seam edges: a prism swept from a closed rational B-curve, the same
//! prism as a B-surface periodic in u, and a solid spun from an open B-curve profile. Oracle:
//! volume and centroid by brute force (the closed section or profile cut into 200,000
//! chords: area by the shoelace formula, volume of revolution by frustums), independent of
//! the tessellator.

use super::{body_mesh, tessellate};
use crate::brep::{Body, Edge, Face, FinUse};
use crate::error::NodeRef;
use crate::geom::{Curve, Surface};
use crate::nurbs::{Nurbs, NurbsSurface};
use crate::part::Part;
use contact_core::{FacetingTolerance, Point3, Vector3};

const H: f64 = 0.012;

fn node(index: u32) -> NodeRef {
    NodeRef {
        index,
        node_type: 0,
    }
}

/// A cam lobe's control polygon (metres), counter-clockwise about z, and its weights.
fn lobe() -> Vec<(f64, f64, f64)> {
    let radii = [0.030, 0.026, 0.020, 0.017, 0.016, 0.017, 0.020, 0.026];
    let weights = [1.0, 1.3, 0.8, 1.0, 1.2, 1.0, 0.8, 1.3];
    (0..8)
        .map(|k| {
            let a = k as f64 * std::f64::consts::FRAC_PI_4;
            (radii[k] * a.cos(), radii[k] * a.sin(), weights[k])
        })
        .collect()
}

/// The lobe at height `z` as a periodic cubic B-curve: uniform knots, the first three
/// vertices repeated at the end (XT Format Reference, periodic B-curves).
fn lobe_curve(z: f64, rational: bool) -> Curve {
    let pts = lobe();
    let mut v = Vec::new();
    for k in 0..11 {
        let (x, y, w) = pts[k % 8];
        let w = if rational { w } else { 1.0 };
        v.extend([x * w, y * w, z * w]);
        if rational {
            v.push(w);
        }
    }
    let knots = (0..15).map(f64::from).collect();
    let stride = if rational { 4 } else { 3 };
    Curve::Nurbs(Nurbs::new(3, knots, v, stride, rational).unwrap())
}

fn ring(index: u32, curve: Curve) -> Edge {
    Edge {
        node: node(index),
        curve,
        with_curve: true,
        start: None,
        end: None,
        surfaces: None,
    }
}

fn face(index: u32, surface: Surface, loops: Vec<Vec<FinUse>>) -> Face {
    Face {
        node: node(index),
        surface,
        surface_node: node(index + 100),
        loops,
    }
}

fn fin(edge: usize, forward: bool) -> Vec<FinUse> {
    vec![FinUse { edge, forward }]
}

fn plane(z: f64) -> Surface {
    Surface::Plane {
        o: Point3::new(0.0, 0.0, z),
        x: Vector3::x(),
        y: Vector3::y(),
    }
}

/// A solid between z = 0 and z = `H` with `side` as its lateral face: bottom ring edge 0
/// runs counter-clockwise seen from +z (forward on the side, reversed on the bottom cap),
/// top ring edge 1 the other way round.
fn prism(side: Surface, bottom: Curve, top: Curve) -> Body {
    Body {
        node: node(1),
        faces: vec![
            face(2, side, vec![fin(0, true), fin(1, false)]),
            face(3, plane(0.0), vec![fin(0, false)]),
            face(4, plane(H), vec![fin(1, true)]),
        ],
        edges: vec![ring(5, bottom), ring(6, top)],
        vertices: Vec::new(),
    }
}

/// Area and centroid of a closed curve in the xy plane, as a 200,000-gon.
fn section(c: &Curve) -> (f64, f64, f64) {
    let (lo, hi) = c.range().unwrap();
    let n = 200_000;
    let p: Vec<Point3> = (0..n)
        .map(|i| c.eval(lo + (hi - lo) * i as f64 / n as f64))
        .collect();
    let (mut a, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let (p0, p1) = (p[i], p[(i + 1) % n]);
        let cross = p0.x * p1.y - p1.x * p0.y;
        a += cross / 2.0;
        cx += (p0.x + p1.x) * cross / 6.0;
        cy += (p0.y + p1.y) * cross / 6.0;
    }
    (a, cx / a, cy / a)
}

/// Checks the body closes at FT 300 and 3000, and that its volume and centroid lie within
/// the chord bound of the oracle's at each (every mesh point within δ of the surface: volume
/// within δ·A, centroid within δ + δ·A·L/V) and the volume error falls as FT rises.
fn converges(body: &Body, volume: f64, centroid: Point3) {
    let part = Part::empty(std::path::Path::new("built.x_t"));
    let mut errors = [0.0; 2];
    for (k, ft) in [300.0, 3000.0].into_iter().enumerate() {
        let tol = FacetingTolerance::new(ft).unwrap();
        let mesh = body_mesh(&part, body, tol, "built").unwrap_or_else(|e| panic!("{e}"));
        let t = tessellate(&part, body, tol).unwrap();
        let area: f64 = (0..mesh.triangles().len())
            .map(|i| mesh.triangle_area(i))
            .sum();
        let (v, c) = (t.signed_volume(), t.centroid());
        errors[k] = (v - volume).abs();
        assert!(
            errors[k] < t.deviation * area,
            "FT {ft}: volume {v:e} against {volume:e}, bound {:e}",
            t.deviation * area
        );
        let (lo, hi) = mesh.bounding_box();
        let bound = t.deviation + t.deviation * area * (hi - lo).norm() / volume;
        assert!(
            (c - centroid).norm() < bound,
            "FT {ft}: centroid {c:?} against {centroid:?}"
        );
    }
    assert!(errors[1] < errors[0] / 3.0, "volume errors {errors:?}");
}

#[test]
fn a_prism_swept_from_a_closed_rational_b_curve_closes_and_converges() {
    let bottom = lobe_curve(0.0, true);
    let (a, cx, cy) = section(&bottom);
    let side = Surface::Swept {
        section: Box::new(bottom.clone()),
        d: Vector3::z(),
    };
    assert!(side.periods().0.is_some_and(|p| (p - 8.0).abs() < 1e-12));
    let body = prism(side, bottom, lobe_curve(H, true));
    converges(&body, a * H, Point3::new(cx, cy, H / 2.0));
}

#[test]
fn a_prism_on_a_b_surface_periodic_in_u_closes_and_converges() {
    let pts = lobe();
    let mut vertices = Vec::new();
    for k in 0..11 {
        let (x, y, _) = pts[k % 8];
        vertices.extend([x, y, 0.0, x, y, H]);
    }
    let n = NurbsSurface {
        u_degree: 3,
        v_degree: 1,
        u_knots: (0..15).map(f64::from).collect(),
        v_knots: vec![0.0, 0.0, 1.0, 1.0],
        vertices,
        n_u: 11,
        n_v: 2,
        stride: 3,
        rational: false,
        u_closed: false,
        v_closed: false,
    }
    .with_closure(crate::geom::CLOSED);
    assert!(n.u_closed && !n.v_closed);
    let bottom = lobe_curve(0.0, false);
    let (a, cx, cy) = section(&bottom);
    let body = prism(Surface::Nurbs(n), bottom, lobe_curve(H, false));
    converges(&body, a * H, Point3::new(cx, cy, H / 2.0));
}

#[test]
fn a_roller_spun_from_a_b_curve_profile_closes_and_converges() {
    // Crowned profile in the xz plane from (0.020, 0) through (0.026, H/2) to (0.020, H).
    let profile = Curve::Nurbs(
        Nurbs::new(
            2,
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            vec![0.020, 0.0, 0.0, 0.032, 0.0, H / 2.0, 0.020, 0.0, H],
            3,
            false,
        )
        .unwrap(),
    );
    let circle = |z: f64| Curve::Ellipse {
        c: Point3::new(0.0, 0.0, z),
        x: Vector3::x(),
        y: Vector3::y(),
        a: 0.020,
        b: 0.020,
    };
    // Volume and axial moment by frustums between 200,000 profile points.
    let n = 200_000;
    let p: Vec<Point3> = (0..=n).map(|i| profile.eval(i as f64 / n as f64)).collect();
    let (mut v, mut mz) = (0.0, 0.0);
    for w in p.windows(2) {
        let (r0, r1, h) = (w[0].x, w[1].x, w[1].z - w[0].z);
        let dv = std::f64::consts::PI * h * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
        v += dv;
        mz += dv * 0.5 * (w[0].z + w[1].z);
    }
    let side = Surface::Spun {
        profile: Box::new(profile),
        b: Point3::origin(),
        a: Vector3::z(),
    };
    let body = prism(side, circle(0.0), circle(H));
    converges(&body, v, Point3::new(0.0, 0.0, mz / v));
}

/// A thin cylinder (r = 2.5 mm, h = 23 mm) whose top circle's samples sit a twist φ round
/// from its bottom circle's, at tolerances coarse enough that the chord deviation δ = L/FT
/// runs from 0.3 r to 0.99 r, where the chord bound alone spaces the lateral grid by up to
/// half a turn: at φ = π/2 and δ ≥ 0.8 r a grid column then lies exactly half a turn from
/// the seam's middle point. It closes at each, with its volume within δ·A of π r² h (A the
/// mesh's area: every mesh point lies within δ of the surface).
#[test]
fn a_thin_cylinder_closes_at_tolerances_near_its_radius() {
    let (r, h) = (0.0025, 0.023);
    let circle = |z: f64, phi: f64| Curve::Ellipse {
        c: Point3::new(0.0, 0.0, z),
        x: Vector3::new(phi.cos(), phi.sin(), 0.0),
        y: Vector3::new(-phi.sin(), phi.cos(), 0.0),
        a: r,
        b: r,
    };
    let side = Surface::Cone {
        o: Point3::origin(),
        a: Vector3::z(),
        x: Vector3::x(),
        y: Vector3::y(),
        r,
        tan: 0.0,
    };
    let part = Part::empty(std::path::Path::new("built.x_t"));
    let length = (8.0 * r * r + h * h).sqrt();
    let volume = std::f64::consts::PI * r * r * h;
    let mut failures = Vec::new();
    for phi in (0..8).map(|k| k as f64 * std::f64::consts::PI / 12.0) {
        let body = Body {
            node: node(1),
            faces: vec![
                face(2, side.clone(), vec![fin(0, true), fin(1, false)]),
                face(3, plane(0.0), vec![fin(0, false)]),
                face(4, plane(h), vec![fin(1, true)]),
            ],
            edges: vec![ring(5, circle(0.0, 0.0)), ring(6, circle(h, phi))],
            vertices: Vec::new(),
        };
        for k in 0..=40 {
            let delta = r * (0.3 + 0.69 * k as f64 / 40.0);
            let at = format!("φ {phi:.3}, δ/r {:.3}", delta / r);
            let tol = FacetingTolerance::new(length / delta).unwrap();
            let mesh = match body_mesh(&part, &body, tol, "cylinder") {
                Ok(m) => m,
                Err(e) => {
                    failures.push(format!("{at}: {e}"));
                    continue;
                }
            };
            let area: f64 = (0..mesh.triangles().len())
                .map(|i| mesh.triangle_area(i))
                .sum();
            let v = mesh.signed_volume();
            if (v - volume).abs() >= delta * area {
                failures.push(format!("{at}: volume {v:e} against {volume:e}"));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
