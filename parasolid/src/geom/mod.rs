//! Curves and surfaces read from their nodes, with their natural parametrisations:
//! evaluation `(u, v) → point` and the inverse `point → (u, v)` the tessellator needs.
//!
//! | surface | u | v |
//! |---|---|---|
//! | plane (origin o, normal n, x axis x, y = n × x) | (p − o)·x | (p − o)·y |
//! | cylinder (axis a through o, radius r) | angle from x about a | (p − o)·a |
//! | cone (radius r at o, half angle α) | angle | (p − o)·a; radius r + v·tan α |
//! | sphere (centre c, radius r) | longitude about a | latitude |
//! | torus (R, r) | angle about a | angle round the tube |
//! | B-surface | its own u | its own v |
//! | swept (section C, direction d) | C's parameter | distance along d |
//! | spun (profile C about axis a through b) | C's parameter | angle about a |

use crate::error::{Error, ErrorKind};
use crate::nurbs::{Nurbs, NurbsSurface, expand_knots, unwrap_periodic_knots, wrap_vertices};
use crate::part::Part;
use crate::schema::types as ty;
use crate::stream::Node;
use contact_core::{Point3, Vector3};

mod eval;
pub use eval::golden;

/// A curve.
#[derive(Debug, Clone, PartialEq)]
pub enum Curve {
    /// `p + t d` (d unit).
    Line {
        /// A point.
        p: Point3,
        /// Unit direction.
        d: Vector3,
    },
    /// `c + r (cos t x + sin t y)` (or an ellipse with radii a along x, b along y).
    Ellipse {
        /// Centre.
        c: Point3,
        /// Unit x axis.
        x: Vector3,
        /// Unit y axis (normal × x).
        y: Vector3,
        /// Radius along x.
        a: f64,
        /// Radius along y.
        b: f64,
    },
    /// Stored points of an intersection curve; t runs over the point indices.
    Polyline(Vec<Point3>),
    /// A B-spline curve in space.
    Nurbs(Nurbs),
    /// A B-spline curve in a surface's parameter space.
    OnSurface {
        /// The surface.
        surface: Box<Surface>,
        /// The (u, v) curve.
        uv: Nurbs,
    },
    /// A part `[t0, t1]` of a basis curve.
    Trimmed {
        /// The basis curve.
        basis: Box<Curve>,
        /// Start parameter.
        t0: f64,
        /// End parameter.
        t1: f64,
    },
}

/// A surface.
#[derive(Debug, Clone, PartialEq)]
pub enum Surface {
    /// A plane.
    Plane {
        /// Origin.
        o: Point3,
        /// Unit x.
        x: Vector3,
        /// Unit y.
        y: Vector3,
    },
    /// A cylinder (or cone when `tan ≠ 0`): axis `a` through `o`, radius `r + v tan`.
    Cone {
        /// Axis point.
        o: Point3,
        /// Unit axis.
        a: Vector3,
        /// Unit x (angle 0).
        x: Vector3,
        /// Unit y = a × x.
        y: Vector3,
        /// Radius at `o`.
        r: f64,
        /// Radius change per unit of axial distance.
        tan: f64,
    },
    /// A sphere.
    Sphere {
        /// Centre.
        c: Point3,
        /// Unit axis (latitude ±π/2).
        a: Vector3,
        /// Unit x.
        x: Vector3,
        /// Unit y.
        y: Vector3,
        /// Radius.
        r: f64,
    },
    /// A torus.
    Torus {
        /// Centre.
        c: Point3,
        /// Unit axis.
        a: Vector3,
        /// Unit x.
        x: Vector3,
        /// Unit y.
        y: Vector3,
        /// Major radius.
        big: f64,
        /// Minor radius.
        small: f64,
    },
    /// A B-spline surface.
    Nurbs(NurbsSurface),
    /// A section curve swept along a vector: `C(u) + v d`.
    Swept {
        /// Section.
        section: Box<Curve>,
        /// Unit sweep direction.
        d: Vector3,
    },
    /// A profile curve spun about an axis: `rot(a, v)(C(u) − b) + b`.
    Spun {
        /// Profile.
        profile: Box<Curve>,
        /// A point of the axis.
        b: Point3,
        /// Unit axis.
        a: Vector3,
    },
}

fn unit(part: &Part, node: &Node, field: &'static str) -> Result<Vector3, Error> {
    let v = Vector3::from(part.vector(node, field)?);
    let n = v.norm();
    if !(n > 0.5 && n < 2.0) {
        return Err(part.error(ErrorKind::Geometry {
            node: node.reference(),
            what: format!("{field} is not a unit vector ({v:?})"),
        }));
    }
    Ok(v / n)
}

fn frame(
    part: &Part,
    node: &Node,
    axis: &'static str,
) -> Result<(Vector3, Vector3, Vector3), Error> {
    let a = unit(part, node, axis)?;
    let x = unit(part, node, "x_axis")?;
    let x = (x - a * a.dot(&x)).normalize();
    Ok((a, x, a.cross(&x)))
}

fn bad(part: &Part, node: &Node, what: impl Into<String>) -> Error {
    part.error(ErrorKind::Geometry {
        node: node.reference(),
        what: what.into(),
    })
}

fn positive(part: &Part, node: &Node, field: &'static str) -> Result<f64, Error> {
    let r = part.real(node, field)?;
    if r > 0.0 {
        Ok(r)
    } else {
        Err(bad(part, node, format!("{field} = {r} is not positive")))
    }
}

const CURVES: &[u16] = &[
    ty::LINE,
    ty::CIRCLE,
    ty::ELLIPSE,
    ty::INTERSECTION,
    ty::B_CURVE,
    ty::SP_CURVE,
    ty::TRIMMED_CURVE,
];

const SURFACES: &[u16] = &[
    ty::PLANE,
    ty::CYLINDER,
    ty::CONE,
    ty::SPHERE,
    ty::TORUS,
    ty::B_SURFACE,
    ty::SWEPT_SURF,
    ty::SPUN_SURF,
];

/// A curve node's `sense`: whether edges run with (`+`) or against the curve's parameter.
pub fn curve_sense(part: &Part, node: &Node) -> Result<bool, Error> {
    Ok(part.char(node, "sense")? != b'-')
}

/// Reads the curve at pointer `field` of `from`.
pub fn curve_at(
    part: &Part,
    from: &Node,
    field: &'static str,
    depth: u32,
) -> Result<(Curve, bool, crate::error::NodeRef), Error> {
    let node = part.follow(from, field, CURVES)?;
    Ok((
        curve(part, node, depth)?,
        curve_sense(part, node)?,
        node.reference(),
    ))
}

/// Whether logical field `name` is in the node's layout and true.
fn flag(node: &Node, name: &str) -> bool {
    matches!(node.get(name), Some(crate::stream::Value::Char(b'T')))
}

fn nurbs_curve(part: &Part, node: &Node) -> Result<Nurbs, Error> {
    let nc = part.follow(node, "nurbs", &[ty::NURBS_CURVE])?;
    let degree = part.int(nc, "degree")?;
    let dim = part.int(nc, "vertex_dim")?;
    let rational = part.char(nc, "rational")? == b'T';
    let verts = part.follow(nc, "bspline_vertices", &[ty::BSPLINE_VERTICES])?;
    let mult = part.follow(nc, "knot_mult", &[ty::KNOT_MULT])?;
    let knots = part.follow(nc, "knots", &[ty::KNOT_SET])?;
    let knots = expand_knots(part.reals(knots, "knots")?, part.ints(mult, "mult")?)
        .ok_or_else(|| bad(part, nc, "knots and multiplicities do not match"))?;
    if !(2..=4).contains(&dim) || !(1..=15).contains(&degree) {
        return Err(bad(
            part,
            nc,
            format!("degree {degree}, vertex dimension {dim}"),
        ));
    }
    let mut vertices = part.reals(verts, "vertices")?.to_vec();
    let mut knots = knots;
    let (p, stride) = (degree as usize, dim as usize);
    if flag(nc, "periodic") && knots.len() * stride == vertices.len() + stride {
        // Stored by one period: n vertices, n + 1 knots.
        knots = unwrap_periodic_knots(&knots, p).ok_or_else(|| {
            bad(
                part,
                nc,
                "a periodic B-curve with fewer vertices than its degree",
            )
        })?;
        vertices = wrap_vertices(&vertices, stride, p);
    }
    Nurbs::new(p, knots, vertices, stride, rational)
        .ok_or_else(|| bad(part, nc, "vertex and knot counts do not fit the degree"))
}

fn nurbs_surface(part: &Part, node: &Node) -> Result<NurbsSurface, Error> {
    let ns = part.follow(node, "nurbs", &[ty::NURBS_SURF])?;
    let (pu, pv) = (part.int(ns, "u_degree")?, part.int(ns, "v_degree")?);
    let (nu, nv) = (part.int(ns, "n_u_vertices")?, part.int(ns, "n_v_vertices")?);
    let dim = part.int(ns, "vertex_dim")?;
    let rational = part.char(ns, "rational")? == b'T';
    let knots = |m: &'static str, k: &'static str| -> Result<Vec<f64>, Error> {
        let mult = part.follow(ns, m, &[ty::KNOT_MULT])?;
        let knots = part.follow(ns, k, &[ty::KNOT_SET])?;
        expand_knots(part.reals(knots, "knots")?, part.ints(mult, "mult")?)
            .ok_or_else(|| bad(part, ns, "knots and multiplicities do not match"))
    };
    let mut u_knots = knots("u_knot_mult", "u_knots")?;
    let mut v_knots = knots("v_knot_mult", "v_knots")?;
    let verts = part.follow(ns, "bspline_vertices", &[ty::BSPLINE_VERTICES])?;
    let mut vertices = part.reals(verts, "vertices")?.to_vec();
    let (mut nu, mut nv) = (nu, nv);
    // Counts beyond the vertices stored, or degrees out of range, cannot fit (checked first,
    // so that no product of them overflows).
    let stored = vertices.len() as i64;
    if !((1..=stored).contains(&nu)
        && (1..=stored).contains(&nv)
        && (3..=4).contains(&dim)
        && (1..=15).contains(&pu)
        && (1..=15).contains(&pv))
    {
        return Err(bad(
            part,
            ns,
            "vertex and knot counts do not fit the degrees",
        ));
    }
    // A direction stored by one period (n vertices, n + 1 knots) is unwrapped.
    let short = |n: i64, k: &[f64], p: i64| k.len() as i64 == n + 1 && n >= p;
    if flag(ns, "u_periodic") && short(nu, &u_knots, pu) {
        u_knots = unwrap_periodic_knots(&u_knots, pu as usize).unwrap_or_default();
        vertices = wrap_vertices(&vertices, (nv * dim) as usize, pu as usize);
        nu += pu;
    }
    if flag(ns, "v_periodic") && short(nv, &v_knots, pv) {
        v_knots = unwrap_periodic_knots(&v_knots, pv as usize).unwrap_or_default();
        let row = (nv * dim) as usize;
        vertices = vertices
            .chunks(row)
            .flat_map(|r| wrap_vertices(r, dim as usize, pv as usize))
            .collect();
        nv += pv;
    }
    let monotone =
        |k: &[f64]| k.iter().all(|t| t.is_finite()) && k.windows(2).all(|w| w[0] <= w[1]);
    let ok = nu > pu
        && nv > pv
        && monotone(&u_knots)
        && monotone(&v_knots)
        && vertices.iter().all(|x| x.is_finite())
        && u_knots.len() as i64 == nu + pu + 1
        && v_knots.len() as i64 == nv + pv + 1
        && vertices.len() as i64 == nu * nv * dim;
    if !ok {
        return Err(bad(
            part,
            ns,
            "vertex and knot counts do not fit the degrees, knots decrease, or a value is unset",
        ));
    }
    Ok(NurbsSurface {
        u_degree: pu as usize,
        v_degree: pv as usize,
        u_knots,
        v_knots,
        vertices,
        n_u: nu as usize,
        n_v: nv as usize,
        stride: dim as usize,
        rational,
        u_closed: false,
        v_closed: false,
    }
    .with_closure(CLOSED))
}

/// Two ends of a curve (or two boundaries of a surface) within this distance (metres, a
/// tenth of Parasolid's linear resolution) close it on itself.
pub const CLOSED: f64 = 1e-9;

/// Reads a curve node (`depth` bounds nesting, so a cycle of references is an error).
pub fn curve(part: &Part, node: &Node, depth: u32) -> Result<Curve, Error> {
    if depth > 8 {
        return Err(bad(
            part,
            node,
            "curves nest too deeply (a reference cycle?)",
        ));
    }
    Ok(match node.node_type {
        ty::LINE => Curve::Line {
            p: Point3::from(part.vector(node, "pvec")?),
            d: unit(part, node, "direction")?,
        },
        ty::CIRCLE => {
            let (_, x, y) = frame(part, node, "normal")?;
            let r = positive(part, node, "radius")?;
            Curve::Ellipse {
                c: Point3::from(part.vector(node, "centre")?),
                x,
                y,
                a: r,
                b: r,
            }
        }
        ty::ELLIPSE => {
            let (_, x, y) = frame(part, node, "normal")?;
            Curve::Ellipse {
                c: Point3::from(part.vector(node, "centre")?),
                x,
                y,
                a: positive(part, node, "major_radius")?,
                b: positive(part, node, "minor_radius")?,
            }
        }
        ty::INTERSECTION => {
            let chart = part.follow(node, "chart", &[ty::CHART])?;
            let pts: Vec<Point3> = part
                .vectors(chart, "hvec")?
                .iter()
                .map(|v| Point3::from(*v))
                .collect();
            if pts.len() < 2 || pts.iter().any(|p| !p.coords.iter().all(|c| c.is_finite())) {
                return Err(bad(
                    part,
                    chart,
                    "fewer than two stored points, or unset ones",
                ));
            }
            Curve::Polyline(pts)
        }
        ty::B_CURVE => {
            let n = nurbs_curve(part, node)?;
            if n.stride - usize::from(n.rational) != 3 {
                return Err(bad(
                    part,
                    node,
                    "a B-curve in space needs three coordinates",
                ));
            }
            Curve::Nurbs(n)
        }
        ty::SP_CURVE => {
            let s = part.follow(node, "surface", SURFACES)?;
            let b = part.follow(node, "b_curve", &[ty::B_CURVE])?;
            let uv = nurbs_curve(part, b)?;
            if uv.stride - usize::from(uv.rational) != 2 {
                return Err(bad(
                    part,
                    node,
                    "a parameter-space curve needs two coordinates",
                ));
            }
            Curve::OnSurface {
                surface: Box::new(surface(part, s, depth + 1)?),
                uv,
            }
        }
        ty::TRIMMED_CURVE => {
            let basis = part.follow(node, "basis_curve", CURVES)?;
            Curve::Trimmed {
                basis: Box::new(curve(part, basis, depth + 1)?),
                t0: part.real(node, "parm_1")?,
                t1: part.real(node, "parm_2")?,
            }
        }
        t => {
            return Err(bad(
                part,
                node,
                format!(
                    "curve type {} is not read",
                    crate::schema::type_name(t).unwrap_or("unknown")
                ),
            ));
        }
    })
}

/// Reads a surface node.
pub fn surface(part: &Part, node: &Node, depth: u32) -> Result<Surface, Error> {
    if depth > 8 {
        return Err(bad(
            part,
            node,
            "surfaces nest too deeply (a reference cycle?)",
        ));
    }
    Ok(match node.node_type {
        ty::PLANE => {
            let (_, x, y) = frame(part, node, "normal")?;
            Surface::Plane {
                o: Point3::from(part.vector(node, "pvec")?),
                x,
                y,
            }
        }
        ty::CYLINDER | ty::CONE => {
            let (a, x, y) = frame(part, node, "axis")?;
            let tan = if node.node_type == ty::CONE {
                let s = part.real(node, "sin_half_angle")?;
                let c = part.real(node, "cos_half_angle")?;
                if c.abs() < 1e-9 {
                    return Err(bad(part, node, "a cone of half angle π/2"));
                }
                s / c
            } else {
                0.0
            };
            Surface::Cone {
                o: Point3::from(part.vector(node, "pvec")?),
                a,
                x,
                y,
                r: part.real(node, "radius")?,
                tan,
            }
        }
        ty::SPHERE => {
            let (a, x, y) = frame(part, node, "axis")?;
            Surface::Sphere {
                c: Point3::from(part.vector(node, "centre")?),
                a,
                x,
                y,
                r: positive(part, node, "radius")?,
            }
        }
        ty::TORUS => {
            let (a, x, y) = frame(part, node, "axis")?;
            Surface::Torus {
                c: Point3::from(part.vector(node, "centre")?),
                a,
                x,
                y,
                big: part.real(node, "major_radius")?,
                small: positive(part, node, "minor_radius")?,
            }
        }
        ty::B_SURFACE => Surface::Nurbs(nurbs_surface(part, node)?),
        ty::SWEPT_SURF => {
            let s = part.follow(node, "section", CURVES)?;
            Surface::Swept {
                section: Box::new(curve(part, s, depth + 1)?),
                d: unit(part, node, "sweep")?,
            }
        }
        ty::SPUN_SURF => {
            let s = part.follow(node, "profile", CURVES)?;
            Surface::Spun {
                profile: Box::new(curve(part, s, depth + 1)?),
                b: Point3::from(part.vector(node, "base")?),
                a: unit(part, node, "axis")?,
            }
        }
        t => {
            return Err(bad(
                part,
                node,
                format!(
                    "surface type {} is not read",
                    crate::schema::type_name(t).unwrap_or("unknown")
                ),
            ));
        }
    })
}

/// Reads the surface at pointer `field` of `from`.
pub fn surface_at(
    part: &Part,
    from: &Node,
    field: &'static str,
) -> Result<(Surface, crate::error::NodeRef), Error> {
    let node = part.follow(from, field, SURFACES)?;
    Ok((surface(part, node, 0)?, node.reference()))
}
