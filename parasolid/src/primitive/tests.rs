//! Bodies built face by face at generic poses are recognised with the dimensions and frames
//! they were built with; near misses (a cap tilted, a ring off the axis, a box corner moved, a
//! bounded sphere) are not; and a recognised frustum's closed-form volume is the one its
//! tessellation converges to.

use super::*;
use crate::brep::{Edge, FinUse};
use crate::error::NodeRef;
use crate::part::Part;
use crate::tess::tessellate;
use contact_core::FacetingTolerance;

fn node(index: u32) -> NodeRef {
    NodeRef {
        index,
        node_type: 0,
    }
}

/// A unit frame (axis, x, y) about a generic direction.
fn axes() -> (Vector3, Vector3, Vector3) {
    let r = UnitQuaternion::from_scaled_axis(Vector3::new(0.3, -0.7, 0.4));
    (r * Vector3::z(), r * Vector3::x(), r * Vector3::y())
}

const ORIGIN: Point3 = Point3::new(0.011, -0.023, 0.0047);

fn face(surface: Surface, loops: Vec<Vec<FinUse>>) -> Face {
    Face {
        node: node(1),
        surface,
        surface_node: node(2),
        loops,
    }
}

fn ring(c: Point3, x: Vector3, y: Vector3, r: f64) -> Edge {
    Edge {
        node: node(3),
        curve: Curve::Ellipse {
            c,
            x,
            y,
            a: r,
            b: r,
        },
        with_curve: true,
        start: None,
        end: None,
        surfaces: None,
    }
}

fn fin(edge: usize, forward: bool) -> Vec<FinUse> {
    vec![FinUse { edge, forward }]
}

fn plane(o: Point3, x: Vector3, y: Vector3) -> Surface {
    Surface::Plane { o, x, y }
}

/// A frustum from radius `r0` at `ORIGIN` to `r1` at `ORIGIN + L·axis`, its top cap tilted by
/// `tilt` radians about x and its top ring moved `shift` along x.
fn frustum(r0: f64, r1: f64, l: f64, tilt: f64, shift: f64) -> Body {
    let (a, x, y) = axes();
    let top = ORIGIN + a * l;
    let turn =
        UnitQuaternion::from_axis_angle(&contact_core::nalgebra::Unit::new_normalize(x), tilt);
    Body {
        node: node(0),
        faces: vec![
            face(
                Surface::Cone {
                    o: ORIGIN,
                    a,
                    x,
                    y,
                    r: r0,
                    tan: (r1 - r0) / l,
                },
                vec![fin(0, true), fin(1, false)],
            ),
            face(plane(ORIGIN, y, x), vec![fin(0, false)]),
            face(plane(top, turn * x, turn * y), vec![fin(1, true)]),
        ],
        edges: vec![ring(ORIGIN, x, y, r0), ring(top + x * shift, x, y, r1)],
        vertices: Vec::new(),
    }
}

/// A box of half extents `h` about `centre` on the generic axes, corner 0 moved by `nudge`.
fn cuboid_body(centre: Point3, h: [f64; 3], nudge: f64) -> Body {
    let (a, x, y) = axes();
    let e = [x, y, a];
    let vertices: Vec<Point3> = (0..8)
        .map(|k: usize| {
            let s = |i: usize| if k >> i & 1 == 1 { 1.0 } else { -1.0 };
            centre + e[0] * s(0) * h[0] + e[1] * s(1) * h[1] + e[2] * s(2) * h[2]
        })
        .enumerate()
        .map(|(k, p)| if k == 0 { p + x * nudge } else { p })
        .collect();
    // Twelve edges: along each axis, between corners differing in that bit.
    let mut edges = Vec::new();
    for axis in 0..3 {
        for k in (0..8usize).filter(|k| k >> axis & 1 == 0) {
            let (p, q) = (vertices[k], vertices[k | 1 << axis]);
            edges.push(Edge {
                node: node(4),
                curve: Curve::Line {
                    p,
                    d: (q - p).normalize(),
                },
                with_curve: true,
                start: Some(k),
                end: Some(k | 1 << axis),
                surfaces: None,
            });
        }
    }
    let faces = (0..6)
        .map(|f| {
            let (axis, side) = (f / 2, if f % 2 == 0 { -1.0 } else { 1.0 });
            let n = e[axis] * side;
            let u = e[(axis + 1) % 3];
            let loops = vec![
                (0..4)
                    .map(|edge| FinUse {
                        edge,
                        forward: true,
                    })
                    .collect(),
            ];
            face(plane(centre + n * h[axis], u, n.cross(&u)), loops)
        })
        .collect();
    Body {
        node: node(0),
        faces,
        edges,
        vertices,
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12
}

#[test]
fn spheres_and_tori_are_recognised_at_their_centres() {
    let (a, x, y) = axes();
    let sphere = Body {
        node: node(0),
        faces: vec![face(
            Surface::Sphere {
                c: ORIGIN,
                a,
                x,
                y,
                r: 0.013,
            },
            Vec::new(),
        )],
        edges: Vec::new(),
        vertices: Vec::new(),
    };
    let p = recognise(&sphere).unwrap();
    assert_eq!(p.shape, Shape::Sphere { radius: 0.013 });
    assert!((p.frame * Point3::origin() - ORIGIN).norm() < 1e-15);
    // A bounded sphere (a loop) is not one.
    let mut capped = sphere.clone();
    capped.faces[0].loops.push(fin(0, true));
    capped.edges.push(ring(ORIGIN, x, y, 0.013));
    assert_eq!(recognise(&capped), None);

    let torus = |big: f64| Body {
        node: node(0),
        faces: vec![face(
            Surface::Torus {
                c: ORIGIN,
                a,
                x,
                y,
                big,
                small: 0.004,
            },
            Vec::new(),
        )],
        edges: Vec::new(),
        vertices: Vec::new(),
    };
    let p = recognise(&torus(0.02)).unwrap();
    assert_eq!(
        p.shape,
        Shape::Torus {
            major: 0.02,
            minor: 0.004
        }
    );
    assert!((p.frame * Vector3::z() - a).norm() < 1e-15);
    // A spindle torus (minor > major) is not a ring torus.
    assert_eq!(recognise(&torus(0.003)), None);
}

#[test]
fn cylinders_and_frusta_are_recognised_with_their_bottom_at_the_origin() {
    let (a, _, _) = axes();
    for (r0, r1) in [(0.01, 0.01), (0.012, 0.005), (0.004, 0.009)] {
        let p = recognise(&frustum(r0, r1, 0.03, 0.0, 0.0)).unwrap();
        let Shape::Frustum {
            bottom,
            top,
            length,
        } = p.shape
        else {
            panic!("{p:?}");
        };
        assert!(
            close(bottom, r0) && close(top, r1) && close(length, 0.03),
            "{p:?}"
        );
        assert!((p.frame * Point3::origin() - ORIGIN).norm() < 1e-15);
        assert!((p.frame * Vector3::z() - a).norm() < 1e-15);
    }
    // A cap tilted or a ring moved off the axis by 1e-6 (a hundred resolutions) is no frustum.
    assert_eq!(recognise(&frustum(0.01, 0.01, 0.03, 1e-6, 0.0)), None);
    assert_eq!(recognise(&frustum(0.01, 0.01, 0.03, 0.0, 1e-6)), None);
}

#[test]
fn boxes_are_recognised_centred_on_their_axes() {
    let (a, x, y) = axes();
    let h = [0.01, 0.02, 0.005];
    let p = recognise(&cuboid_body(ORIGIN, h, 0.0)).unwrap();
    let Shape::Box { half } = p.shape else {
        panic!("{p:?}")
    };
    // The frame's axes are the box's, in some order and sense; the half extents follow.
    for (k, e) in [x, y, a].iter().enumerate() {
        let along = (0..3)
            .find(|&i| (p.frame * Vector3::ith(i, 1.0)).cross(e).norm() < 1e-12)
            .unwrap_or_else(|| panic!("axis {k} of the box is not an axis of {p:?}"));
        assert!(close(half[along], h[k]), "{half:?} against {h:?}");
    }
    assert!((p.frame * Point3::origin() - ORIGIN).norm() < 1e-15);
    let r = p.frame.rotation.to_rotation_matrix();
    assert!((r.matrix().determinant() - 1.0).abs() < 1e-12);
    // One corner moved by 1e-6: not a box.
    assert_eq!(recognise(&cuboid_body(ORIGIN, h, 1e-6)), None);
}

/// The tessellation of a recognised frustum converges on the frustum's closed-form volume
/// `π·L·(r₀² + r₀r₁ + r₁²)/3`: the recognised dimensions are the body's.
#[test]
fn a_recognised_frustum_is_the_solid_its_tessellation_converges_on() {
    let body = frustum(0.012, 0.005, 0.03, 0.0, 0.0);
    let Shape::Frustum {
        bottom,
        top,
        length,
    } = recognise(&body).unwrap().shape
    else {
        panic!()
    };
    let exact = std::f64::consts::PI * length * (bottom * bottom + bottom * top + top * top) / 3.0;
    let area = std::f64::consts::PI
        * ((bottom + top) * (length.powi(2) + (bottom - top).powi(2)).sqrt()
            + bottom * bottom
            + top * top);
    let part = Part::empty(std::path::Path::new("built.x_t"));
    // Every mesh point lies within the chord deviation δ of the surface: the volume within δ·A.
    let errors: Vec<f64> = [300.0, 3000.0]
        .into_iter()
        .map(|ft| {
            let mesh = tessellate(&part, &body, FacetingTolerance::new(ft).unwrap()).unwrap();
            let error = (mesh.signed_volume() - exact).abs();
            assert!(error < mesh.deviation * area, "FT {ft}: {error:e}");
            error
        })
        .collect();
    assert!(errors[1] < errors[0] / 5.0, "{errors:?}");
}
