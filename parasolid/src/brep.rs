//! A body's topology (reference: model structure): regions own shells, shells own faces,
//! a face is bounded by loops of fins, and each fin is one side of an edge.
//!
//! Edge direction and ends: an edge runs along its curve's parameter when the curve's sense
//! is `+`, against it otherwise. Its two fins run in opposite directions; a fin's vertex is
//! the one the fin runs into, so the `+` fin's vertex is the edge's end and the `−` fin's
//! vertex its start. A ring edge (a closed curve with no vertex) has neither. A tolerant edge
//! has no curve of its own; its `+` fin's curve stands for it.

use crate::error::{Error, ErrorKind, NodeRef};
use crate::geom::{Curve, Surface, curve_at, surface_at};
use crate::part::Part;
use crate::schema::types as ty;
use crate::stream::Node;
use contact_core::Point3;
use std::collections::HashMap;

/// One side of an edge in a loop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FinUse {
    /// The edge (index into [`Body::edges`]).
    pub edge: usize,
    /// Whether the loop runs with the edge's direction.
    pub forward: bool,
}

/// An edge.
#[derive(Debug, Clone, PartialEq)]
pub struct Edge {
    /// The EDGE node.
    pub node: NodeRef,
    /// Its curve.
    pub curve: Curve,
    /// Whether the edge runs with the curve's parameter.
    pub with_curve: bool,
    /// Start vertex (index into [`Body::vertices`]); `None` for a ring edge.
    pub start: Option<usize>,
    /// End vertex.
    pub end: Option<usize>,
    /// For an intersection curve, the two surfaces it is the intersection of (its stored
    /// points are refined onto both).
    pub surfaces: Option<Box<(Surface, Surface)>>,
}

/// A face.
#[derive(Debug, Clone, PartialEq)]
pub struct Face {
    /// The FACE node.
    pub node: NodeRef,
    /// Its surface.
    pub surface: Surface,
    /// The surface node.
    pub surface_node: NodeRef,
    /// Its loops, each the fins in loop order. Loops of a lone vertex (no edge) are left out.
    pub loops: Vec<Vec<FinUse>>,
}

/// A body: faces, edges and vertex positions.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// The BODY node.
    pub node: NodeRef,
    /// Faces.
    pub faces: Vec<Face>,
    /// Edges.
    pub edges: Vec<Edge>,
    /// Vertex positions.
    pub vertices: Vec<Point3>,
}

/// Follows a `next` chain from `first`, with a bound against cycles.
fn chain<'p>(
    part: &'p Part,
    from: &'p Node,
    first: &'static str,
    next: &'static str,
    allowed: &[u16],
) -> Result<Vec<&'p Node>, Error> {
    let mut out: Vec<&Node> = Vec::new();
    let mut at = from;
    let mut field = first;
    while let Some(i) = part.ptr(at, field)? {
        let n = part.node_of(i, at, field, allowed)?;
        if out.len() > 10_000_000 || (out.first().is_some_and(|f| f.index == n.index)) {
            break;
        }
        out.push(n);
        at = n;
        field = next;
    }
    Ok(out)
}

/// The two surfaces of an intersection curve node, when both are read.
fn intersection_surfaces(
    part: &Part,
    index: u32,
) -> Result<Option<Box<(Surface, Surface)>>, Error> {
    let Some(node) = part.get(index) else {
        return Ok(None);
    };
    let ids = part.ints(node, "surface")?;
    if ids.len() != 2 {
        return Ok(None);
    }
    let mut out = Vec::new();
    for &i in ids {
        let s = u32::try_from(i).ok().and_then(|i| part.get(i));
        match s.map(|s| crate::geom::surface(part, s, 0)) {
            Some(Ok(s)) => out.push(s),
            _ => return Ok(None),
        }
    }
    let b = out.pop();
    let a = out.pop();
    Ok(a.zip(b).map(Box::new))
}

struct Builder<'p> {
    part: &'p Part,
    edges: Vec<Edge>,
    edge_of: HashMap<u32, usize>,
    vertices: Vec<Point3>,
    vertex_of: HashMap<u32, usize>,
}

impl<'p> Builder<'p> {
    fn vertex(&mut self, fin: &Node) -> Result<Option<usize>, Error> {
        let Some(vi) = self.part.ptr(fin, "vertex")? else {
            return Ok(None);
        };
        if let Some(&k) = self.vertex_of.get(&vi) {
            return Ok(Some(k));
        }
        let v = self.part.node_of(vi, fin, "vertex", &[ty::VERTEX])?;
        let p = self.part.follow(v, "point", &[ty::POINT])?;
        let pos = Point3::from(self.part.vector(p, "pvec")?);
        self.vertices.push(pos);
        self.vertex_of.insert(vi, self.vertices.len() - 1);
        Ok(Some(self.vertices.len() - 1))
    }

    fn edge(&mut self, fin: &Node) -> Result<Option<usize>, Error> {
        let part = self.part;
        let Some(ei) = part.ptr(fin, "edge")? else {
            return Ok(None);
        };
        if let Some(&k) = self.edge_of.get(&ei) {
            return Ok(Some(k));
        }
        let e = part.node_of(ei, fin, "edge", &[ty::EDGE])?;
        let f0 = part.follow(e, "fin", &[ty::FIN])?;
        let (plus, minus) = if part.char(f0, "sense")? == b'-' {
            (
                part.ptr(f0, "other")?
                    .map(|o| part.node_of(o, f0, "other", &[ty::FIN]))
                    .transpose()?,
                Some(f0),
            )
        } else {
            (
                Some(f0),
                part.ptr(f0, "other")?
                    .map(|o| part.node_of(o, f0, "other", &[ty::FIN]))
                    .transpose()?,
            )
        };
        let end = match plus {
            Some(f) => self.vertex(f)?,
            None => None,
        };
        let start = match minus {
            Some(f) => self.vertex(f)?,
            None => None,
        };
        let mut surfaces = None;
        let (curve, with_curve) = if part.ptr(e, "curve")?.is_some() {
            let (c, s, r) = curve_at(part, e, "curve", 0)?;
            if r.node_type == ty::INTERSECTION {
                surfaces = intersection_surfaces(part, r.index)?;
            }
            (c, s)
        } else {
            // A tolerant edge: the + fin's own curve (fins run with the edge when +).
            let f = plus.or(minus).ok_or_else(|| {
                part.error(ErrorKind::Geometry {
                    node: e.reference(),
                    what: "an edge with neither a curve nor fins".into(),
                })
            })?;
            let (c, s, _) = curve_at(part, f, "curve", 0)?;
            let fin_plus = part.char(f, "sense")? != b'-';
            (c, s == fin_plus)
        };
        self.edges.push(Edge {
            node: e.reference(),
            curve,
            with_curve,
            start,
            end,
            surfaces,
        });
        self.edge_of.insert(ei, self.edges.len() - 1);
        Ok(Some(self.edges.len() - 1))
    }

    fn face(&mut self, f: &Node) -> Result<Face, Error> {
        let part = self.part;
        let (surface, surface_node) = surface_at(part, f, "surface")?;
        let mut loops = Vec::new();
        for l in chain(part, f, "loop", "next", &[ty::LOOP])? {
            let fins = chain(part, l, "fin", "forward", &[ty::FIN])?;
            let mut uses = Vec::with_capacity(fins.len());
            for fin in fins {
                if let Some(edge) = self.edge(fin)? {
                    uses.push(FinUse {
                        edge,
                        forward: part.char(fin, "sense")? != b'-',
                    });
                }
            }
            if !uses.is_empty() {
                loops.push(uses);
            }
        }
        Ok(Face {
            node: f.reference(),
            surface,
            surface_node,
            loops,
        })
    }
}

impl Body {
    /// Reads the body at node `index` of `part`.
    pub fn read(part: &Part, index: u32) -> Result<Self, Error> {
        let body = part
            .get(index)
            .filter(|n| n.node_type == ty::BODY)
            .ok_or_else(|| {
                part.error(ErrorKind::BodyNotFound {
                    part: String::new(),
                    element: format!("node {index}"),
                    known: String::new(),
                })
            })?;
        let mut b = Builder {
            part,
            edges: Vec::new(),
            edge_of: HashMap::new(),
            vertices: Vec::new(),
            vertex_of: HashMap::new(),
        };
        let mut seen = std::collections::HashSet::new();
        let mut faces = Vec::new();
        for region in chain(part, body, "region", "next", &[ty::REGION])? {
            for shell in chain(part, region, "shell", "next", &[ty::SHELL])? {
                let back = chain(part, shell, "face", "next", &[ty::FACE])?;
                let front = chain(part, shell, "front_face", "next_front", &[ty::FACE])?;
                for f in back.into_iter().chain(front) {
                    if seen.insert(f.index) {
                        faces.push(b.face(f)?);
                    }
                }
            }
        }
        if faces.is_empty() {
            return Err(part.error(ErrorKind::Geometry {
                node: body.reference(),
                what: "the body has no faces".into(),
            }));
        }
        Ok(Self {
            node: body.reference(),
            faces,
            edges: b.edges,
            vertices: b.vertices,
        })
    }
}
