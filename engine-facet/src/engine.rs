//! [`FacetEngine`]: the faceted [`GeometryEngine`].

use crate::facet_mesh::FacetMesh;
use crate::planar;
use crate::prepared::{PreparedFacetPair, PreparedGeometry, Shape};
use crate::tessellate::{self, Tessellation};
use contact_core::geometry::{Geometry, Plane};
use contact_core::{
    FacetingTolerance, GeometryEngine, GeometryInstance, InvalidArgument, Isometry3, PrepareError,
    PreparedPair, Side, Unsupported, Vector3, check_lists,
};
use std::collections::HashMap;
use std::sync::Arc;

/// The faceted engine (Adams' DEFAULT_LIBRARY / RAPID): primitives are tessellated at a faceting
/// tolerance, meshes indexed by OBB trees, contacts computed on the triangles.
///
/// Supports every pair of 3-D solids and meshes, and solids against a 3-D PLANE (half-space),
/// except PLANE against PLANE; and the 2-D pairs of [`crate::planar`] (a point or a circle
/// against a line, circle, arc or curve, and an arc or curve against an arc, curve or line,
/// on polylines). A flipped PLANE is the half-space above it; a flipped 3-D solid
/// (IFLIP_NORMAL, "the space outside it", a cavity) is its tessellation turned inside out
/// ([`FacetMesh::build_inside_out`]), answered against any solid or mesh but not against a
/// PLANE or another cavity (their intersection is unbounded).
#[derive(Debug, Clone, PartialEq)]
pub struct FacetEngine {
    faceting_tolerance: FacetingTolerance,
    max_triangles: u64,
}

impl Default for FacetEngine {
    fn default() -> Self {
        Self::new(FacetingTolerance::default())
    }
}

impl FacetEngine {
    /// An engine using `faceting_tolerance` for geometry without its own.
    pub fn new(faceting_tolerance: FacetingTolerance) -> Self {
        Self {
            faceting_tolerance,
            max_triangles: tessellate::MAX_TRIANGLES,
        }
    }

    /// Lowers (or raises) the cap on triangles per tessellated geometry (≥ 4).
    pub fn with_max_triangles(mut self, max_triangles: u64) -> Result<Self, InvalidArgument> {
        if max_triangles < 4 {
            return Err(InvalidArgument::new(
                "max_triangles",
                max_triangles as f64,
                ">= 4",
            ));
        }
        self.max_triangles = max_triangles;
        Ok(self)
    }

    /// The model-wide faceting tolerance.
    pub fn faceting_tolerance(&self) -> FacetingTolerance {
        self.faceting_tolerance
    }

    /// Tessellates and indexes one geometry instance (no caching).
    pub fn prepare_geometry(
        &self,
        g: &GeometryInstance,
        side: Side,
    ) -> Result<PreparedGeometry, PrepareError> {
        if g.geometry.is_planar() {
            return self.prepare_planar(g, side);
        }
        open_cavity(g, side)?;
        let mut pose_part_geometry = g.pose_part_geometry;
        let shape = match g.geometry.as_ref() {
            Geometry::Plane(p) if g.flip_normal => {
                let (plane, turn) = flipped_plane(p);
                pose_part_geometry *= turn;
                Shape::HalfSpace(plane)
            }
            Geometry::Plane(p) => Shape::HalfSpace(*p),
            Geometry::Mesh(m) => {
                let t = Tessellation {
                    vertices: m.vertices().to_vec(),
                    triangles: m.triangles().to_vec(),
                    corner_normals: tessellate::flat_corner_normals(m.vertices(), m.triangles()),
                };
                Shape::Mesh(Arc::new(if g.flip_normal {
                    FacetMesh::build_inside_out(t)
                } else {
                    FacetMesh::build(t, m.is_closed())
                }))
            }
            other => {
                let tolerance = g.faceting_tolerance.unwrap_or(self.faceting_tolerance);
                let unsupported = || PrepareError::NotTessellated {
                    label: g.label.clone(),
                    kind: other.kind(),
                };
                let counts = tessellate::counts(other, tolerance).ok_or_else(unsupported)?;
                if counts.triangles > self.max_triangles {
                    return Err(PrepareError::TooManyTriangles {
                        label: g.label.clone(),
                        tolerance: tolerance.value(),
                        requested: counts.triangles,
                        limit: self.max_triangles,
                    });
                }
                let t = tessellate::tessellate(other, tolerance).ok_or_else(unsupported)?;
                Shape::Mesh(Arc::new(if g.flip_normal {
                    FacetMesh::build_inside_out(t)
                } else {
                    FacetMesh::build(t, true)
                }))
            }
        };
        Ok(PreparedGeometry {
            shape,
            pose_part_geometry,
            label: g.label.clone(),
        })
    }
}

/// A flipped PLANE — the material above its rectangle, `z ≥ 0`, instead of below — as an
/// unflipped one: the same half-space seen from the plane's frame turned half a turn about its
/// x axis ([`Plane::turned_about_x`]). Returns that plane and the turn (to follow the
/// geometry's pose).
fn flipped_plane(p: &Plane) -> (Plane, Isometry3) {
    let turn = Isometry3::rotation(Vector3::x() * std::f64::consts::PI);
    (p.turned_about_x(), turn)
}

impl FacetEngine {
    /// A 2-D geometry: circles, arcs and curves to polylines at the faceting tolerance; the
    /// point and the line stay exact.
    fn prepare_planar(
        &self,
        g: &GeometryInstance,
        side: Side,
    ) -> Result<PreparedGeometry, PrepareError> {
        let geometry = g.geometry.as_ref();
        let tolerance = g.faceting_tolerance.unwrap_or(self.faceting_tolerance);
        let length = geometry.characteristic_length();
        let deviation = length.map(|l| tolerance.chord_deviation(l));
        let flip = g.flip_normal;
        let boundary =
            |line: tessellate::Polyline| planar::Boundary::new(line, flip, length.unwrap_or(1.0));
        let shape = match (geometry, deviation) {
            (Geometry::Point, _) if flip => {
                return Err(PrepareError::InvalidArgument {
                    label: g.label.clone(),
                    source: InvalidArgument::with_text(
                        flip_argument(side),
                        "set on a POINT",
                        "unset (a point has no normal to flip)",
                    ),
                });
            }
            (Geometry::Point, _) => planar::PlanarShape::Point,
            (Geometry::Line(line), _) => planar::PlanarShape::Line {
                line: *line,
                side: if flip { -1.0 } else { 1.0 },
            },
            (Geometry::Circle(c), Some(d)) => planar::PlanarShape::Disc {
                polygon: boundary(tessellate::circle_polyline(c, d)),
                hole: flip,
            },
            (Geometry::Arc(a), Some(d)) => {
                planar::PlanarShape::Boundary(boundary(tessellate::arc_polyline(a, d)))
            }
            (Geometry::Curve(c), Some(d)) => {
                planar::PlanarShape::Boundary(boundary(tessellate::curve_polyline(c, d)))
            }
            (other, _) => {
                return Err(PrepareError::Unsupported(Unsupported {
                    engine: "faceted",
                    i: other.kind(),
                    j: other.kind(),
                    reason: "this 2-D geometry has no size to facet",
                }));
            }
        };
        Ok(PreparedGeometry {
            shape: Shape::Planar(Arc::new(planar::Planar {
                kind: geometry.kind(),
                length,
                shape,
            })),
            pose_part_geometry: g.pose_part_geometry,
            label: g.label.clone(),
        })
    }
}

impl GeometryEngine for FacetEngine {
    fn name(&self) -> &'static str {
        "faceted"
    }

    /// [`Self::supports`], and the flips [`Self::prepare`] refuses: an open mesh flipped, and
    /// a flipped solid against another flipped solid or a PLANE.
    fn supports_instances(
        &self,
        i: &GeometryInstance,
        j: &GeometryInstance,
    ) -> Result<(), PrepareError> {
        self.supports(&i.geometry, &j.geometry)?;
        open_cavity(i, Side::I)?;
        open_cavity(j, Side::J)?;
        unbounded_pair(i, j)
    }

    fn supports(&self, i: &Geometry, j: &Geometry) -> Result<(), Unsupported> {
        let (ki, kj) = (i.kind(), j.kind());
        let reason = if ki.is_planar() && kj.is_planar() {
            planar_kinds_supported(i, j).err()
        } else if ki.is_planar() || kj.is_planar() {
            Some("2-D geometry cannot contact 3-D geometry (SPEC §3)")
        } else if matches!((i, j), (Geometry::Plane(_), Geometry::Plane(_))) {
            Some("two half-spaces have no bounded intersection")
        } else {
            None
        };
        match reason {
            Some(reason) => Err(Unsupported {
                engine: "faceted",
                i: ki,
                j: kj,
                reason,
            }),
            None => Ok(()),
        }
    }

    fn prepare(
        &self,
        i: &[GeometryInstance],
        j: &[GeometryInstance],
    ) -> Result<Box<dyn PreparedPair>, PrepareError> {
        check_lists(self, i, j)?;
        // One mesh per (shape, tolerance): a GRAPHICS used twice is faceted once.
        let mut built: HashMap<(usize, u64, bool), Shape> = HashMap::new();
        let mut prepare_list = |list: &[GeometryInstance], side: Side| {
            list.iter()
                .map(|g| {
                    let tolerance = g.faceting_tolerance.unwrap_or(self.faceting_tolerance);
                    // Turned inside out when flipped: a flip is part of the key. A flipped
                    // plane's frame turns with it, and a plane costs nothing to prepare again.
                    let key = (
                        Arc::as_ptr(&g.geometry) as usize,
                        tolerance.value().to_bits(),
                        g.flip_normal,
                    );
                    let plane = matches!(g.geometry.as_ref(), Geometry::Plane(_));
                    if let Some(shape) = built.get(&key).filter(|_| !plane) {
                        return Ok(PreparedGeometry {
                            shape: shape.clone(),
                            pose_part_geometry: g.pose_part_geometry,
                            label: g.label.clone(),
                        });
                    }
                    let prepared = self.prepare_geometry(g, side)?;
                    built.insert(key, prepared.shape.clone());
                    Ok(prepared)
                })
                .collect::<Result<Vec<_>, PrepareError>>()
        };
        for a in i {
            for b in j {
                unbounded_pair(a, b)?;
            }
        }
        let i_list = prepare_list(i, Side::I)?;
        let j_list = prepare_list(j, Side::J)?;
        for a in &i_list {
            for b in &j_list {
                if let (Shape::Planar(pa), Shape::Planar(pb)) = (&a.shape, &b.shape) {
                    planar::supported(&pa.shape, &pb.shape).map_err(|reason| Unsupported {
                        engine: "faceted",
                        i: pa.kind,
                        j: pb.kind,
                        reason,
                    })?;
                }
            }
        }
        Ok(Box::new(PreparedFacetPair::new(i_list, j_list)))
    }
}

/// The 2-D pairs by kind (flips are checked when the pair is prepared): a point or a circle
/// against a line, circle, arc or curve, never a circle against a bounded line; and two
/// boundaries (arc or curve against arc, curve or line).
fn planar_kinds_supported(i: &Geometry, j: &Geometry) -> Result<(), &'static str> {
    let boundary = |g: &Geometry| matches!(g, Geometry::Arc(_) | Geometry::Curve(_));
    let line = |g: &Geometry| matches!(g, Geometry::Line(_));
    if (boundary(i) && (boundary(j) || line(j))) || (line(i) && boundary(j)) {
        return Ok(());
    }
    let mover = |g: &Geometry| matches!(g, Geometry::Point | Geometry::Circle(_));
    let surface = |g: &Geometry| {
        matches!(
            g,
            Geometry::Circle(_) | Geometry::Arc(_) | Geometry::Curve(_) | Geometry::Line(_)
        )
    };
    if !((mover(i) && surface(j)) || (mover(j) && surface(i))) {
        return Err(
            "the faceted engine answers a point or a circle against a line, circle, arc or curve, and an arc or curve against an arc, curve or line; not this pair",
        );
    }
    let bounded =
        |g: &Geometry| matches!(g, Geometry::Line(l) if l.x_range().iter().any(|x| x.is_finite()));
    let circle = |g: &Geometry| matches!(g, Geometry::Circle(_));
    if (circle(i) && bounded(j)) || (circle(j) && bounded(i)) {
        return Err("a circle against a bounded 2-D PLANE is not built; use an unbounded line");
    }
    Ok(())
}

/// A flipped mesh is the space outside a closed surface: an open one bounds no such space, and
/// is refused, naming the argument.
fn open_cavity(g: &GeometryInstance, side: Side) -> Result<(), PrepareError> {
    if let (Geometry::Mesh(m), true) = (g.geometry.as_ref(), g.flip_normal)
        && !m.is_closed()
    {
        return Err(PrepareError::InvalidArgument {
            label: g.label.clone(),
            source: InvalidArgument::with_text(
                flip_argument(side),
                "set on an open mesh",
                "unset, or a closed mesh (a flipped mesh is the space outside its surface)",
            ),
        });
    }
    Ok(())
}

/// Whether `g` is a flipped 3-D solid: the space outside it (a cavity), unbounded.
fn is_cavity(g: &GeometryInstance) -> bool {
    g.flip_normal && !g.geometry.is_planar() && !matches!(g.geometry.as_ref(), Geometry::Plane(_))
}

/// A cavity against another cavity or a half-space: their intersection is unbounded, so no
/// contact is defined; refused.
fn unbounded_pair(i: &GeometryInstance, j: &GeometryInstance) -> Result<(), PrepareError> {
    let plane = |g: &GeometryInstance| matches!(g.geometry.as_ref(), Geometry::Plane(_));
    let reason = if is_cavity(i) && is_cavity(j) {
        "two flipped solids (the spaces outside them) have no bounded intersection"
    } else if (is_cavity(i) && plane(j)) || (plane(i) && is_cavity(j)) {
        "a flipped solid (the space outside it) and a PLANE have no bounded intersection"
    } else {
        return Ok(());
    };
    Err(PrepareError::Unsupported(Unsupported {
        engine: "faceted",
        i: i.geometry.kind(),
        j: j.geometry.kind(),
        reason,
    }))
}

/// The CONTACT argument that flips a geometry on `side`.
fn flip_argument(side: Side) -> &'static str {
    if side == Side::I {
        "IFLIP_NORMAL"
    } else {
        "JFLIP_NORMAL"
    }
}
