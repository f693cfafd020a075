//! [`FacetEngine`]: the faceted [`GeometryEngine`].

use crate::facet_mesh::FacetMesh;
use crate::prepared::{PreparedFacetPair, PreparedGeometry, Shape};
use crate::tessellate::{self, Tessellation};
use contact_core::geometry::Geometry;
use contact_core::{
    FacetingTolerance, GeometryEngine, GeometryInstance, InvalidArgument, PrepareError,
    PreparedPair, Side, Unsupported, check_lists,
};
use std::collections::HashMap;
use std::sync::Arc;

/// The faceted engine (Adams' DEFAULT_LIBRARY / RAPID): primitives are tessellated at a faceting
/// tolerance, meshes indexed by OBB trees, contacts computed on the triangles.
///
/// Supports every pair of 3-D solids and meshes, and solids against a 3-D PLANE (half-space),
/// except PLANE against PLANE. 2-D geometry is not answered by this engine (`Unsupported`, found
/// when the model is checked: use the exact engine). A flipped 3-D solid (IFLIP_NORMAL, "the
/// space outside it") is rejected by `prepare`.
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
        if g.flip_normal && !g.geometry.is_planar() {
            return Err(PrepareError::InvalidArgument {
                label: g.label.clone(),
                source: InvalidArgument::with_text(
                    if side == Side::I {
                        "IFLIP_NORMAL"
                    } else {
                        "JFLIP_NORMAL"
                    },
                    "set on a 3-D solid",
                    "unset for the faceted engine (a flipped solid, the space outside it, is not meshed)",
                ),
            });
        }
        let shape = match g.geometry.as_ref() {
            Geometry::Plane(p) => Shape::HalfSpace(*p),
            Geometry::Mesh(m) => {
                let t = Tessellation {
                    vertices: m.vertices().to_vec(),
                    triangles: m.triangles().to_vec(),
                    corner_normals: tessellate::flat_corner_normals(m.vertices(), m.triangles()),
                };
                Shape::Mesh(Arc::new(FacetMesh::build(t, m.is_closed())))
            }
            other => {
                let tolerance = g.faceting_tolerance.unwrap_or(self.faceting_tolerance);
                let unsupported = || Unsupported {
                    engine: "faceted",
                    i: other.kind(),
                    j: other.kind(),
                    reason: "2-D geometry is not answered by the faceted engine; use the exact engine",
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
                Shape::Mesh(Arc::new(FacetMesh::build(t, true)))
            }
        };
        Ok(PreparedGeometry {
            shape,
            pose_part_geometry: g.pose_part_geometry,
            label: g.label.clone(),
        })
    }
}

impl GeometryEngine for FacetEngine {
    fn name(&self) -> &'static str {
        "faceted"
    }

    fn supports(&self, i: &Geometry, j: &Geometry) -> Result<(), Unsupported> {
        let (ki, kj) = (i.kind(), j.kind());
        let reason = if ki.is_planar() || kj.is_planar() {
            Some("2-D contacts are not answered by the faceted engine; use the exact engine")
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
        let mut built: HashMap<(usize, u64), Shape> = HashMap::new();
        let mut prepare_list = |list: &[GeometryInstance], side: Side| {
            list.iter()
                .map(|g| {
                    let tolerance = g.faceting_tolerance.unwrap_or(self.faceting_tolerance);
                    let key = (
                        Arc::as_ptr(&g.geometry) as usize,
                        tolerance.value().to_bits(),
                    );
                    if let Some(shape) = built.get(&key) {
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
        let i_list = prepare_list(i, Side::I)?;
        let j_list = prepare_list(j, Side::J)?;
        Ok(Box::new(PreparedFacetPair::new(i_list, j_list)))
    }
}
