//! The one region of a convex mesh against an unbounded plane, face by face
//! ([`crate::flat_faces`]): the general path's sums over whole flat faces instead of their
//! triangles.
//!
//! A face wholly below the plane adds its cone from the apex in closed form: for a planar
//! polygon of vector area `a` and area centroid `c`, the cone from `o` has volume
//! `a·(c − o)/3` and its centroid at `o + ¾ (c − o)`. A face crossing the plane is clipped as
//! one polygon and adds one waterline segment (two coplanar triangles would add two collinear
//! ones). The sums are those of the triangles in another order: they agree to round-off.

use super::{PlaneFrame, add_loop_segment, contact_below, region_contact, volume_centroid};
use crate::contact_region::{LocalContact, add_polygon, clip_by_heights};
use crate::facet_mesh::FacetMesh;
use crate::flat_faces::{FlatFace, FlatFaces};
use crate::scratch::{RegionSums, Scratch};
use contact_core::{Vector3, WorkCounters};

/// The region of convex mesh `a`, with flat faces `faces`, below the plane: `Some(None)` when
/// no face reaches it; `None` when the region has no waterline (it only touches the plane, or
/// the whole body is under it) or a face crosses the plane more than once (round-off on a face
/// nearly in the plane), which the general path answers.
pub(super) fn faces_region(
    a: &FacetMesh,
    faces: &FlatFaces,
    frame: &PlaneFrame,
    s: &mut Scratch,
    work: &mut WorkCounters,
) -> Option<Option<LocalContact>> {
    let n = frame.n;
    let heights = &mut s.vertex_heights;
    if heights.len() < a.vertices.len() {
        heights.resize(a.vertices.len(), 0.0);
    }
    for &v in &faces.vertices {
        heights[v as usize] = frame.height(&a.vertices[v as usize].coords);
    }
    let mut r = RegionSums::default();
    s.touched.clear();
    s.polygon.clear();
    for (index, face) in faces.faces.iter().enumerate() {
        work.primitive_tests += 1;
        let corners = faces.corners_of(face);
        let (mut lowest, mut highest) = (f64::INFINITY, f64::NEG_INFINITY);
        for &v in corners {
            let h = heights[v as usize];
            lowest = if h < lowest { h } else { lowest };
            highest = if h > highest { h } else { highest };
        }
        if lowest > 0.0 {
            continue;
        }
        let start = s.polygon.len() as u32;
        if highest > 0.0 {
            let crossings = clip_face(a, corners, heights, &mut s.polygon)?;
            add_loop_segment(&mut r, crossings, &face.normal.cross(&n));
        }
        s.touched
            .push((index as u32, start, s.polygon.len() as u32));
    }
    if s.touched.is_empty() {
        return Some(None);
    }
    if r.loop_length <= 0.0 {
        return None;
    }
    let on_loop = r.loop_moment / r.loop_length;
    r.apex = on_loop - n * frame.height(&on_loop);
    for &(index, start, end) in &s.touched {
        if start < end {
            add_polygon(&mut r, &s.polygon[start as usize..end as usize]);
        } else {
            let face = &faces.faces[index as usize];
            let to_face = face.centroid - r.apex;
            let volume = face.area_vector.dot(&to_face) / 3.0;
            r.volume += volume;
            r.volume_moment += volume * 0.75 * to_face;
        }
    }
    r.centroid = volume_centroid(&r);
    let touched = s
        .touched
        .iter()
        .map(|&(index, ..)| &faces.faces[index as usize]);
    Some(Some(
        match exit_below(a, faces, touched.clone(), frame, &r.centroid) {
            Some(below) => contact_below(a, frame, &r, below),
            None => {
                let in_region = touched.flat_map(|face| faces.triangles_of(face).iter().copied());
                region_contact(a, frame, in_region, &r)
            }
        },
    ))
}

/// The part of the polygon `corners` (heights in `heights`) at or below the plane, appended to
/// `out`, and where its boundary crosses the plane (`(h ≤ 0) ≠ (h' ≤ 0)` along an edge, as for
/// a triangle's waterline); `None` when it crosses other than twice.
fn clip_face(
    a: &FacetMesh,
    corners: &[u32],
    heights: &[f64],
    out: &mut Vec<Vector3>,
) -> Option<[Vector3; 2]> {
    let mut crossings = [Vector3::zeros(); 2];
    let mut k = 0;
    clip_by_heights(
        corners.len(),
        |i| {
            let v = corners[i] as usize;
            (a.vertices[v].coords, heights[v])
        },
        |p| out.push(p),
        |at| {
            if k < 2 {
                crossings[k] = at;
            }
            k += 1;
        },
    );
    (k == 2).then_some(crossings)
}

/// Where the line from `g` along −n leaves the convex mesh, among the faces reaching below the
/// plane: the nearest of their planes that face along the line,
/// `s = min n_f·(c_f − g)/(n_f·(−n))` over `n_f·(−n) > 0` (see
/// [`super::convex`]'s `exit_below`, the same rule on triangles). On a flat face that is the
/// point, on any of its triangles; on a curved face the ray test picks the triangle among the
/// faces whose planes tie within `1e-9` of the size. `None` when no plane faces along the line
/// or `g` lies outside one of them.
fn exit_below<'f>(
    a: &FacetMesh,
    faces: &'f FlatFaces,
    touched: impl Iterator<Item = &'f FlatFace> + Clone,
    frame: &PlaneFrame,
    g: &Vector3,
) -> Option<(u32, Vector3)> {
    let down = -frame.n;
    let along = |face: &FlatFace| {
        let facing = face.normal.dot(&down);
        (facing > 0.0).then(|| face.normal.dot(&(face.centroid - g)) / facing)
    };
    let mut best: Option<(f64, &FlatFace)> = None;
    for face in touched.clone() {
        if let Some(s) = along(face)
            && best.is_none_or(|(b, _)| s < b)
        {
            best = Some((s, face));
        }
    }
    let (s, face) = best?;
    if s < 0.0 {
        return None;
    }
    let exit = (faces.triangles_of(face)[0], g + down * s);
    if !face.curved {
        return Some(exit);
    }
    let tie = 1e-9 * a.size;
    let tied = touched
        .filter(|face| along(face).is_some_and(|t| t - s <= tie))
        .flat_map(|face| faces.triangles_of(face).iter().copied());
    Some(a.first_ray_hit_among(tied, g, &down).unwrap_or(exit))
}
