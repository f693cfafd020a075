//! A mesh–mesh region's volume, volume moment and centroid: the cones over each crossing
//! triangle's inside part and over the inside flood's takings, about the region's apex, summed
//! in each mesh's frame and closed in A's (see [`crate::contact_region`]).

use crate::contact_region::{RelativePose, clip, corners_in_a, loop_normal, other_plane};
use crate::facet_mesh::FacetMesh;
use crate::inside_flood::PATCH_BIT;
use crate::piece_boundary::{add_inside_part, corner_inside};
use crate::scratch::{RegionSums, Scratch};
use contact_core::Vector3;

pub(crate) fn sum_volumes(a: &FacetMesh, b: &FacetMesh, x: &RelativePose, s: &mut Scratch) {
    // Each region's cones about its own apex (its loop's centroid, see `sum_loops`), in A's
    // frame and in B's.
    for r in s.regions.iter_mut() {
        r.apex_b = x.inverse_apply(&r.apex);
    }
    sum_crossing_triangles(a, b, x, s);
    sum_takings(a, b, s);
    for r in s.regions.iter_mut() {
        close_region(r, x);
    }
}

/// Each crossing triangle's inside part, in A's frame about its region's apex: from the
/// triangle's trace where its chains are clean, else the triangle clipped by the planes of
/// the triangles it crosses.
fn sum_crossing_triangles(a: &FacetMesh, b: &FacetMesh, x: &RelativePose, s: &mut Scratch) {
    let Scratch {
        nodes,
        regions,
        hits,
        node_hits,
        polygon,
        polygon_next,
        boundary,
        ..
    } = s;
    let touch = 1e-10 * a.size.max(b.size);
    for node in nodes.iter() {
        let mesh = if node.side == 0 { a } else { b };
        let corners = corners_in_a(mesh, node.side, node.tri, x);
        let r = &mut regions[node.region as usize];
        // The inside part from the triangle's trace (`crate::piece_boundary`), each segment
        // turned to have the other solid's inside on its left.
        boundary.segments.clear();
        for i in 0..node.hit_count {
            let hit = &hits[node_hits[(node.hit_start + i) as usize] as usize];
            boundary.segments.push(if node.side == 0 {
                (hit.s0, hit.s1)
            } else {
                (hit.s1, hit.s0)
            });
        }
        let normal = (corners[1] - corners[0]).cross(&(corners[2] - corners[0]));
        // No chain reaches the boundary: all of it is inside or none. With no trace left at
        // all (the triangle only touches the other surface, at points the perturbation of the
        // triangle tests puts on one side, so that all of it but infinitesimal corners lies on
        // one side), its centroid says which: behind every plane it crosses, or in front of
        // all; else (the centroid on a plane, or on both sides of a concave fold) its corners
        // clear of the other surface do.
        let inside_corners = node.inside_corners.count_ones();
        let centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
        let centroid_sides = (0..node.hit_count).fold([true; 2], |[behind, ahead], i| {
            let hit = &hits[node_hits[(node.hit_start + i) as usize] as usize];
            let (n, p0) = other_plane(node.side, hit);
            let d = n.dot(&(centroid - p0));
            [behind && d < 0.0, ahead && d > 0.0]
        });
        let whole_boundary = |segments: &[(Vector3, Vector3)]| {
            if segments.is_empty() {
                return Some(match centroid_sides {
                    [true, false] => true,
                    [false, true] => false,
                    _ => inside_corners >= 2,
                });
            }
            (!node.split)
                .then(|| corner_inside(segments, &normal, &corners[0]))
                .flatten()
        };
        if add_inside_part(
            &corners,
            boundary,
            whole_boundary,
            touch,
            &r.apex,
            &mut r.sums_a,
        ) {
            continue;
        }
        // Chains that are not clean: the triangle clipped by the planes it crosses.
        polygon.clear();
        polygon.extend_from_slice(&corners);
        for i in 0..node.hit_count {
            let hit = hits[node_hits[(node.hit_start + i) as usize] as usize];
            let (n, p0) = other_plane(node.side, &hit);
            clip(polygon, polygon_next, &n, &p0);
            std::mem::swap(polygon, polygon_next);
            if polygon.len() < 3 {
                break;
            }
        }
        r.sums_a.add_polygon(polygon, &r.apex);
    }
}

/// The inside flood's takings (whole triangles and whole patches), each in its own mesh's
/// frame about its region's apex there.
fn sum_takings(a: &FacetMesh, b: &FacetMesh, s: &mut Scratch) {
    let Scratch {
        nodes,
        regions,
        taken,
        ..
    } = s;
    for &(seed, item) in taken.iter() {
        let node = &nodes[seed as usize];
        let r = &mut regions[node.region as usize];
        let (mesh, apex, sums) = if node.side == 0 {
            (a, r.apex, &mut r.sums_a)
        } else {
            (b, r.apex_b, &mut r.sums_b)
        };
        if item & PATCH_BIT != 0 {
            sums.merge(
                &mesh
                    .patches
                    .cones(item & !PATCH_BIT, &apex, |t| mesh.corners(t)),
            );
        } else {
            let [p, q, r] = mesh.corners(item);
            sums.add_triangle(&p, &q, &r, &apex);
        }
    }
}

/// A region's volume, moment (in A's frame) and centroid from its two meshes' sums.
fn close_region(r: &mut RegionSums, x: &RelativePose) {
    // B's sums are about the same physical apex: only their moment turns into A's frame.
    r.volume = r.sums_a.volume + r.sums_b.volume;
    r.volume_moment = r.sums_a.moment + x.rot * r.sums_b.moment;
    let scale = r.loop_length.max(1e-300);
    // A loop that encloses no area bounds no measurable volume: its sums are round-off
    // (at a corner grazing a face, crossing triangles clipped by one plane each leave
    // slivers whose cones do not cancel), and their centroid can lie anywhere.
    r.centroid = if r.volume > 1e-15 * scale * scale * scale && loop_normal(r).is_some() {
        r.apex + r.volume_moment / r.volume
    } else {
        r.apex
    };
}
