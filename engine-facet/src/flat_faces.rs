//! A convex mesh's flat faces: the edge-connected triangles of one plane merged into one
//! polygon, so a query against a plane takes a box's side or a cylinder's cap once rather than
//! triangle by triangle.
//!
//! Triangles join their seed's face when their normal points the seed's way and all three
//! corners lie within `1e-12·size` of the seed's plane (the tolerance [`FacetMesh::convex`]
//! allows an edge): a fan of coplanar facets, as a tessellated cap, or the two triangles of a
//! cylinder's side strip. Adjacent facets of a curved surface meet at an angle of the order of
//! the faceting's chord, far above that, and stay apart. A face whose boundary is not one
//! simple loop keeps its triangles as faces of their own.
//!
//! [`FacetMesh::convex`]: crate::facet_mesh::FacetMesh::convex

use crate::facet_mesh::{FacetMesh, NO_NEIGHBOR};
use contact_core::Vector3;
use std::collections::HashMap;

/// One flat face of a convex mesh.
#[derive(Debug, Clone)]
pub(crate) struct FlatFace {
    /// Its boundary's corners (indices into `FlatFaces::corners`), counter-clockwise seen from
    /// outside.
    pub corners: std::ops::Range<u32>,
    /// Its triangles (indices into `FlatFaces::triangles`).
    pub triangles: std::ops::Range<u32>,
    /// The unit outward normal: the area vector normalised (the seed facet's normal for a face
    /// without area).
    pub normal: Vector3,
    /// The vector area, `Σ ½ (q − p) × (r − p)` over its triangles.
    pub area_vector: Vector3,
    /// The area centroid.
    pub centroid: Vector3,
    /// Some triangle of it stands for a curved surface (its corner normals differ).
    pub curved: bool,
}

/// A convex mesh's triangles grouped into flat faces.
#[derive(Debug, Clone, Default)]
pub(crate) struct FlatFaces {
    pub faces: Vec<FlatFace>,
    /// The faces' boundary corners, as vertex indices, face after face.
    pub corners: Vec<u32>,
    /// The faces' triangles, face after face.
    pub triangles: Vec<u32>,
    /// The distinct vertices on the faces' boundaries (the only heights a plane query needs).
    pub vertices: Vec<u32>,
}

impl FlatFaces {
    /// The vertex indices of `face`'s boundary.
    pub fn corners_of(&self, face: &FlatFace) -> &[u32] {
        &self.corners[face.corners.start as usize..face.corners.end as usize]
    }

    /// The triangles of `face`.
    pub fn triangles_of(&self, face: &FlatFace) -> &[u32] {
        &self.triangles[face.triangles.start as usize..face.triangles.end as usize]
    }

    /// Heap bytes held.
    pub fn heap_bytes(&self) -> usize {
        self.faces.capacity() * std::mem::size_of::<FlatFace>()
            + (self.corners.capacity() + self.triangles.capacity() + self.vertices.capacity()) * 4
    }
}

/// A convex mesh of more faces than this keeps its OBB tree against a plane: the heights of
/// every face's corners would cost more than the tree's cull of the faces far above it.
pub(crate) const MOST_FACES: usize = 128;

/// Groups a convex mesh's triangles into flat faces (see the module's docs); `None` past
/// [`MOST_FACES`].
pub(crate) fn flat_faces(m: &FacetMesh) -> Option<FlatFaces> {
    let tolerance = 1e-12 * m.size;
    let mut face_of = vec![u32::MAX; m.triangles.len()];
    let mut out = FlatFaces::default();
    let mut group = Vec::new();
    for seed in 0..m.triangles.len() as u32 {
        if face_of[seed as usize] != u32::MAX {
            continue;
        }
        let id = out.faces.len() as u32;
        let (n0, p0) = (
            m.face_normals[seed as usize],
            m.vertices[m.triangles[seed as usize][0] as usize],
        );
        let in_plane = |t: u32| {
            m.face_normals[t as usize].dot(&n0) > 0.0
                && m.triangles[t as usize]
                    .iter()
                    .all(|&v| n0.dot(&(m.vertices[v as usize] - p0)).abs() <= tolerance)
        };
        group.clear();
        group.push(seed);
        face_of[seed as usize] = id;
        let mut next = 0;
        while next < group.len() {
            let t = group[next];
            next += 1;
            for nb in m.neighbors[t as usize] {
                if nb != NO_NEIGHBOR && face_of[nb as usize] == u32::MAX && in_plane(nb) {
                    face_of[nb as usize] = id;
                    group.push(nb);
                }
            }
        }
        match boundary_loop(m, &group, &face_of, id) {
            Some(corners) if group.len() > 1 => push_face(&mut out, m, &group, &corners, n0),
            _ => {
                // Each triangle a face of its own (a single triangle is its own loop).
                for (k, &t) in group.iter().enumerate() {
                    face_of[t as usize] = id + k as u32;
                    let corners = m.triangles[t as usize];
                    push_face(&mut out, m, &[t], &corners, m.face_normals[t as usize]);
                }
            }
        }
    }
    let mut seen = vec![false; m.vertices.len()];
    for &v in &out.corners {
        if !std::mem::replace(&mut seen[v as usize], true) {
            out.vertices.push(v);
        }
    }
    (out.faces.len() <= MOST_FACES).then_some(out)
}

/// The boundary of the triangles `group` (face `id`) as one loop of vertices in the
/// triangles' winding, or `None` when its edges do not chain into one simple loop.
fn boundary_loop(m: &FacetMesh, group: &[u32], face_of: &[u32], id: u32) -> Option<Vec<u32>> {
    let mut next_of: HashMap<u32, u32> = HashMap::new();
    for &t in group {
        let tri = m.triangles[t as usize];
        for k in 0..3 {
            let nb = m.neighbors[t as usize][k];
            if (nb == NO_NEIGHBOR || face_of[nb as usize] != id)
                && next_of.insert(tri[k], tri[(k + 1) % 3]).is_some()
            {
                return None;
            }
        }
    }
    let &start = next_of.keys().min()?;
    let mut corners = vec![start];
    let mut at = next_of[&start];
    while at != start {
        if corners.len() >= next_of.len() {
            return None;
        }
        corners.push(at);
        at = *next_of.get(&at)?;
    }
    (corners.len() == next_of.len()).then_some(corners)
}

/// Appends the face of `triangles` bounded by `corners`, `seed_normal` its normal if it has no
/// area.
fn push_face(
    out: &mut FlatFaces,
    m: &FacetMesh,
    triangles: &[u32],
    corners: &[u32],
    seed_normal: Vector3,
) {
    let mut area_vector = Vector3::zeros();
    let (mut area, mut moment) = (0.0, Vector3::zeros());
    for &t in triangles {
        let [p, q, r] = m.triangles[t as usize].map(|v| m.vertices[v as usize].coords);
        let a = 0.5 * (q - p).cross(&(r - p));
        area_vector += a;
        let size = a.norm();
        area += size;
        moment += size * (p + q + r) / 3.0;
    }
    let centroid = if area > 0.0 {
        moment / area
    } else {
        m.vertices[corners[0] as usize].coords
    };
    let length = area_vector.norm();
    let normal = if length > 0.0 {
        area_vector / length
    } else {
        seed_normal
    };
    let (c0, t0) = (out.corners.len() as u32, out.triangles.len() as u32);
    out.corners.extend_from_slice(corners);
    out.triangles.extend_from_slice(triangles);
    out.faces.push(FlatFace {
        corners: c0..out.corners.len() as u32,
        triangles: t0..out.triangles.len() as u32,
        normal,
        area_vector,
        centroid,
        curved: triangles.iter().any(|&t| m.is_curved(t)),
    });
}

#[cfg(test)]
mod tests {
    use super::MOST_FACES;
    use crate::facet_mesh::FacetMesh;
    use crate::tessellate::tessellate;
    use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid};
    use contact_core::{FacetingTolerance, Geometry, Vector3};

    fn mesh(geometry: Geometry, ft: f64) -> FacetMesh {
        let t = tessellate(&geometry, FacetingTolerance::new(ft).unwrap()).unwrap();
        FacetMesh::build(t, true)
    }

    /// Every triangle in one face, every face's corners in its plane, and the faces' areas
    /// summing to the mesh's.
    fn assert_partition(m: &FacetMesh) {
        let faces = m.flat_faces.as_ref().expect("faces");
        let mut owned = faces.triangles.clone();
        owned.sort_unstable();
        assert_eq!(owned, (0..m.triangles.len() as u32).collect::<Vec<_>>());
        let mut area = 0.0;
        for face in &faces.faces {
            for &v in faces.corners_of(face) {
                let off = face
                    .normal
                    .dot(&(m.vertices[v as usize].coords - face.centroid));
                assert!(off.abs() <= 1e-12 * m.size, "corner {off:e} off its face");
            }
            area += face.area_vector.norm();
        }
        assert!(
            (area - m.area).abs() <= 1e-12 * m.area,
            "{area} against {}",
            m.area
        );
    }

    #[test]
    fn a_box_has_six_faces_of_four_corners() {
        let (x, y, z) = (0.4, 0.3, 0.2);
        let m = mesh(
            Geometry::Cuboid(Cuboid::from_corner(x, y, z).unwrap()),
            300.0028,
        );
        assert_partition(&m);
        let faces = m.flat_faces.as_ref().unwrap();
        assert_eq!(faces.faces.len(), 6);
        assert_eq!(faces.vertices.len(), 8);
        for face in &faces.faces {
            assert_eq!(faces.corners_of(face).len(), 4);
            let axis = (0..3).find(|&i| face.normal[i].abs() > 0.5).unwrap();
            let expected = [y * z, x * z, x * y][axis];
            assert!((face.area_vector.norm() - expected).abs() <= 1e-15);
            let mut unit = Vector3::zeros();
            unit[axis] = face.normal[axis].signum();
            assert!((face.normal - unit).norm() <= 1e-15);
            assert!(!face.curved);
        }
    }

    #[test]
    fn a_cylinder_has_two_caps_and_a_strip_per_segment() {
        let m = mesh(
            Geometry::Cylinder(Cylinder::new(0.1, 0.02).unwrap()),
            300.0028,
        );
        assert_partition(&m);
        let faces = m.flat_faces.as_ref().unwrap();
        let caps: Vec<_> = faces.faces.iter().filter(|f| !f.curved).collect();
        assert_eq!(caps.len(), 2);
        let segments = faces.corners_of(caps[0]).len();
        assert_eq!(faces.faces.len(), segments + 2);
        for face in faces.faces.iter().filter(|f| f.curved) {
            assert_eq!(faces.corners_of(face).len(), 4, "a side strip");
            assert_eq!(faces.triangles_of(face).len(), 2);
        }
    }

    #[test]
    fn a_curved_convex_body_keeps_its_facets_or_its_tree() {
        // A UV ellipsoid's quads between two rings are planar (an affine image of a sphere's
        // trapezoids): their two triangles make one face, the poles' fans stay triangles.
        // Past MOST_FACES the mesh keeps only its tree.
        let coarse = mesh(
            Geometry::Ellipsoid(Ellipsoid::new(0.3, 0.2, 0.1).unwrap()),
            20.0,
        );
        let faces = coarse.flat_faces.as_ref().expect("faces");
        assert_partition(&coarse);
        let corners = |k: usize| faces.faces.iter().filter(|f| f.corners.len() == k).count();
        assert_eq!(corners(3) + corners(4), faces.faces.len());
        assert_eq!(corners(3) + 2 * corners(4), coarse.triangles.len());
        assert!(corners(4) > 0);
        let fine = mesh(
            Geometry::Ellipsoid(Ellipsoid::new(0.3, 0.2, 0.1).unwrap()),
            3000.0,
        );
        assert!(fine.convex && fine.triangles.len() > MOST_FACES);
        assert!(fine.flat_faces.is_none());
    }
}
