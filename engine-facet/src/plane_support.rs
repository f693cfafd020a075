//! A tessellated smooth body against a half-space: the contact its true surface makes, where
//! the facets can say what that is.
//!
//! A polyhedron on a plane touches at a vertex, an edge or a face, and the line through the
//! facets' intersection centroid misses the smooth body's centre by up to a facet's size: a
//! faceted ball spins up at every bounce, rocks over its vertices as it rolls, and rests
//! wherever a face is level. The facets of a tessellated primitive carry the true normals at
//! their corners, and with them the smooth surface they stand for ([`crate::smooth_patch`]):
//!
//! - the **support triangle and weights**: the triangle whose corner normals' cone holds
//!   `−n`, and the barycentric weights `β` where its Phong normal field is `−n` (the triangles'
//!   cones tile the directions, so `β` moves continuously from one triangle to the next);
//! - the **implied sphere**: radius `1/κ̄` from the mean of the principal curvatures the corner
//!   normals imply, centre `c = Σ β_i·(p_i − n_i/κ̄)`; the **support point** `q = c − n/κ̄`, its
//!   **depth** `δ_s = −h(q)` (`h` the height above the plane) and the cap's **area**
//!   `π·δ_s·(2/κ̄ − δ_s)`. A tessellated sphere's corners and normals imply the sphere itself,
//!   so for it these are the exact engine's answers, independent of the facets.
//!
//! That answer is the ray rule's (SPEC §4) for a sphere: the cap is symmetric about the normal
//! through `q`. It is taken for meshes that are tessellated spheres (every corner on one sphere
//! with its normal along the radius, [`FacetMesh::implied_sphere`]) while the cap is small
//! beside the radius (`x = κ₂·√(2δ_s/κ₁) ≤ ½`, with the shape operator's principal curvatures;
//! for a sphere `x = √(2δ_s/R)`), where [`sphere_on_plane`] gives it without a search; deeper it
//! is blended with the facets' own contact (`plane_contact`) by a smoothstep down to nothing at
//! `x ≥ 1`: depths
//! linearly, points weighted by each answer's share of the depth, so the blend is continuous.
//! A tessellated ellipsoid ([`FacetMesh::implied_ellipsoid`]) answers as the ellipsoid
//! ([`ellipsoid_on_plane`]): off a sphere the cap's centroid leaves the support point's normal
//! (an ellipsoid's lies on the diameter through `q`), which a local quadric does not resolve
//! but the ellipsoid's affine map to the unit ball does, at every depth. Other meshes keep the
//! facets' contact: the curvature taken per triangle would step where the support point
//! crosses an edge. A support point is joined
//! to the facets' region with the nearest triangle (within two edge lengths); where none is, it
//! makes a contact of its own (the sphere touches before its inscribed facets do).
//!
//! Accuracy: for a sphere the point lies on the line from the centre (the force has no arm
//! about it, as for the true sphere) and the depth and area are the sphere's to round-off.

use crate::contact_region::LocalContact;
use crate::facet_mesh::FacetMesh;
use crate::smooth_patch::{principal_curvatures, support};
use contact_core::Vector3;

/// The smooth surface's lowest point below a plane, as found on one triangle.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Support {
    /// The point on the PN patch.
    q: Vector3,
    /// Its depth below the plane (> 0).
    depth: f64,
    /// The weight of this local answer against the facets' contact, in [0, 1].
    pub weight: f64,
    /// The quadric cap's area at that depth.
    area: f64,
}

/// A tessellated sphere (`FacetMesh::implied_sphere`) against an unbounded plane, without a
/// search of its triangles: what [`supports_by_region`] finds on any of them, since every
/// triangle implies the same sphere (centre `c`, radius `R`). `Some(None)`: no contact (the
/// facets are inscribed in the sphere, so they cannot reach below the plane where it does
/// not); `Some(Some(contact))` while the local answer holds whole (`δ ≤ R/8`, `x ≤ ½`);
/// `None` deeper, where the facets' contact is blended in by the general path.
pub(crate) fn sphere_on_plane(
    a: &FacetMesh,
    n: &Vector3,
    height: &impl Fn(&Vector3) -> f64,
) -> Option<Option<LocalContact>> {
    let (centre, radius) = a.implied_sphere?;
    let depth = radius - height(&centre.coords);
    if depth.is_nan() || depth <= 0.0 {
        return Some(None);
    }
    if blend_weight((2.0 * depth / radius).sqrt()) < 1.0 {
        return None;
    }
    let q = centre.coords - n * radius;
    Some(Some(LocalContact {
        point_i: q,
        point_j: q + n * depth,
        normal: *n,
        penetration: depth,
        area: std::f64::consts::PI * depth * (2.0 * radius - depth),
    }))
}

/// A tessellated ellipsoid (centre `c`, semi-axes `s` along the mesh's axes, `S = diag(s)`)
/// against an unbounded plane of unit normal `n`, `height` the signed height above it: the
/// ellipsoid's own contact, as the exact engine defines it. The map `x = c + S·y` sends the
/// ellipsoid to the unit ball; with `k = |S n|` and the centre's height `d`, the cap's height
/// there is `t = (k − d)/k`, its centroid `g = c − S² n · 3(2 − t)²/(4(3 − t)) / k`; the points
/// are where the line through `g` along `n` meets the plane and leaves the ellipsoid, the depth
/// their distance, the area the plane section `π·abc·(1 − σ²)/k` with `σ = min(−d/k, 0)` (the
/// central section once the centre is below the plane).
///
/// `None`: no contact (the facets are inscribed, so they do not reach below the plane where
/// the ellipsoid does not). Otherwise the answer with its blend weight: 1 while the cap is
/// small in the unit ball (`x = √(2t) ≤ ½`, as a sphere's `√(2δ/R)`), falling to 0 at `x = 1`,
/// below which the facets' contact is blended in ([`blended`], [`alone_contact`]).
pub(crate) fn ellipsoid_on_plane(
    centre: &Vector3,
    semi: &Vector3,
    n: &Vector3,
    height: &impl Fn(&Vector3) -> f64,
) -> Option<Support> {
    let sn = semi.component_mul(n);
    let k = sn.norm();
    let d = height(centre);
    let t = ((k - d) / k).min(2.0);
    if t.is_nan() || t <= 0.0 {
        return None;
    }
    let g_ball = 3.0 * (2.0 - t) * (2.0 - t) / (4.0 * (3.0 - t));
    let g = centre - semi.component_mul(&sn) * (g_ball / k);
    let exit = ellipsoid_exit(semi, &(g - centre), &(-n));
    let q = g - n * exit;
    let depth = exit - height(&g);
    let sigma = (-d / k).min(0.0);
    let abc = semi.x * semi.y * semi.z;
    Some(Support {
        q,
        depth,
        weight: blend_weight((2.0 * t).sqrt()),
        area: std::f64::consts::PI * abc * (1.0 - sigma) * (1.0 + sigma) / k,
    })
}

/// How far the ray from `p` (inside the ellipsoid of semi-axes `s` about the origin) along
/// `u` goes before it leaves: the positive root of `|(p + τu) ⊘ s|² = 1`, taken without
/// cancellation; 0 where `p` is not inside.
fn ellipsoid_exit(s: &Vector3, p: &Vector3, u: &Vector3) -> f64 {
    let (ps, us) = (p.component_div(s), u.component_div(s));
    let (a, b, c) = (us.norm_squared(), ps.dot(&us), ps.norm_squared() - 1.0);
    let disc = (b * b - a * c).max(0.0).sqrt();
    if c >= 0.0 || a <= 0.0 {
        return 0.0;
    }
    if b <= 0.0 {
        (disc - b) / a
    } else {
        -c / (b + disc)
    }
}

/// The smooth answer's weight for a cap whose longest semi-axis is `x` curvature radii:
/// 1 up to ½, 0 from 1, a smoothstep between.
fn blend_weight(x: f64) -> f64 {
    if x.is_nan() || x >= 1.0 {
        return 0.0;
    }
    if x <= 0.5 {
        return 1.0;
    }
    let s = (1.0 - x) / 0.5;
    s * s * (3.0 - 2.0 * s)
}

/// The support point on triangle `t` of `a` against the plane of unit normal `n` (A's
/// frame), `height` the signed height above it; `None` where the triangle holds none or it is
/// above the plane.
fn support_on(
    a: &FacetMesh,
    t: u32,
    n: &Vector3,
    height: &impl Fn(&Vector3) -> f64,
) -> Option<Support> {
    let normals = a.corner_normals[t as usize];
    let bary = support(&normals, &a.face_normals[t as usize], &(-n))?;
    let corners = a.corners(t);
    let (k1, k2) = principal_curvatures(&corners, &normals, n)?;
    if k1.is_nan() || k1 <= 0.0 {
        return None;
    }
    // The sphere the corners and normals imply (mean curvature κ̄): its centre, each corner
    // moved 1/κ̄ inward along its normal, taken at the support point's weights; its lowest point
    // lies 1/κ̄ from there along −n. A tessellated sphere's own, exactly.
    let radius = 2.0 / (k1 + k2);
    let centre = (0..3)
        .map(|i| (corners[i] - normals[i] * radius) * bary[i])
        .sum::<Vector3>();
    let q = centre - n * radius;
    let depth = -height(&q);
    if depth.is_nan() || depth <= 0.0 {
        return None;
    }
    let x = k2 * (2.0 * depth / k1).sqrt();
    let weight = blend_weight(x);
    if weight == 0.0 {
        return None;
    }
    Some(Support {
        q,
        depth,
        weight,
        area: std::f64::consts::PI * depth * (2.0 * radius - depth),
    })
}

/// The smooth surface's support points below the plane, each joined to the facets' region
/// it belongs to: `by_region[r]` for region `r` (`None` where it has none, or two: the local
/// answer does not hold there), and `alone` for those with no region near them (the smooth
/// surface touches before the facets do). `candidates` are the curved triangles whose smooth
/// surface may reach below the plane; `region_tris` lists `(triangle, region)` of the facets'
/// regions. A region whose support has weight 1 needs no facet sums.
pub(crate) fn supports_by_region(
    a: &FacetMesh,
    n: &Vector3,
    height: &impl Fn(&Vector3) -> f64,
    candidates: &[u32],
    region_tris: &[(u32, u32)],
    by_region: &mut [Option<Support>],
    alone: &mut Vec<Support>,
) {
    let mut found: Vec<Support> = Vec::new();
    for &t in candidates {
        let Some(s) = support_on(a, t, n, height) else {
            continue;
        };
        // A support on a shared edge or corner is found on each triangle there.
        if found
            .iter()
            .all(|f| (f.q - s.q).norm() > 1e-9 * a.size.max(f64::MIN_POSITIVE))
        {
            found.push(s);
        }
    }
    let reach = 2.0 * a.longest_edge;
    let mut twice = vec![false; by_region.len()];
    for s in found {
        let nearest = region_tris
            .iter()
            .map(|&(tri, _)| {
                let c = a.corners(tri);
                ((c[0] + c[1] + c[2]) / 3.0 - s.q).norm()
            })
            .zip(region_tris)
            .filter(|(d, _)| *d <= reach)
            .min_by(|x, y| x.0.total_cmp(&y.0))
            .map(|(_, &(_, region))| region as usize);
        match nearest {
            Some(r) if by_region[r].is_some() || twice[r] => {
                by_region[r] = None;
                twice[r] = true;
            }
            Some(r) => by_region[r] = Some(s),
            None => alone.push(s),
        }
    }
}

/// The contact of a support point with no facets' region: the smooth answer scaled by its
/// weight, so it meets the blend where the facets' region appears.
pub(crate) fn alone_contact(s: &Support, n: &Vector3) -> LocalContact {
    LocalContact {
        point_i: s.q,
        point_j: s.q + n * (s.weight * s.depth),
        normal: *n,
        penetration: s.weight * s.depth,
        area: s.weight * s.area,
    }
}

/// The facets' contact `facets` blended with the support `s` by its weight: depths and areas
/// linearly, points weighted by each answer's share of the depth.
pub(crate) fn blended(facets: &LocalContact, s: &Support, n: &Vector3) -> LocalContact {
    let (ws, wf) = (s.weight * s.depth, (1.0 - s.weight) * facets.penetration);
    let depth = ws + wf;
    if depth.is_nan() || depth <= 0.0 {
        return *facets;
    }
    let point_i = (s.q * ws + facets.point_i * wf) / depth;
    let point_j = ((s.q + n * s.depth) * ws + facets.point_j * wf) / depth;
    LocalContact {
        point_i,
        point_j,
        normal: facets.normal,
        penetration: depth,
        area: s.weight * s.area + (1.0 - s.weight) * facets.area,
    }
}

#[cfg(test)]
mod tests {
    use crate::contact_region::LocalContact;
    use crate::facet_mesh::FacetMesh;
    use crate::plane_contact::tests::contacts;
    use crate::tessellate::tessellate;
    use contact_core::geometry::Ellipsoid;
    use contact_core::{FacetingTolerance, Geometry, Isometry3, Vector3};

    fn mesh(a: f64, b: f64, c: f64, ft: f64) -> FacetMesh {
        let geometry = Geometry::Ellipsoid(Ellipsoid::new(a, b, c).unwrap());
        let t = tessellate(&geometry, FacetingTolerance::new(ft).unwrap()).unwrap();
        FacetMesh::build(t, true)
    }

    #[test]
    fn a_tessellated_sphere_is_known_and_its_shortcut_is_the_search_over_its_triangles() {
        assert!(mesh(1.0, 0.6, 0.4, 300.0).implied_sphere.is_none());
        for ft in [30.0, 300.0028, 3000.0] {
            let sphere = mesh(0.5, 0.5, 0.5, ft);
            let (centre, radius) = sphere.implied_sphere.expect("a tessellated sphere");
            assert!(centre.coords.norm() < 1e-12 && (radius - 0.5).abs() < 1e-12);
            let curved: Vec<u32> = (0..sphere.triangles.len() as u32)
                .filter(|&t| sphere.is_curved(t))
                .collect();
            let mut compared = 0;
            for k in 0..200 {
                // Planes at generic tilts, 0 to 0.06 deep (within R/8), in the mesh frame.
                let t = k as f64;
                let axis = Vector3::new((0.37 * t).sin(), (0.71 * t).cos(), 0.5).normalize();
                let rotation = contact_core::UnitQuaternion::from_axis_angle(
                    &nalgebra::Unit::new_normalize(axis),
                    2.1 * t,
                );
                let n = rotation * Vector3::z();
                let depth = 0.06 * (k % 20) as f64 / 19.0 - 0.003;
                let origin = -n * (0.5 - depth);
                let pose = Isometry3::from_parts(origin.into(), rotation);
                let short = contacts(&sphere, &pose);
                // The search over every curved triangle, with no facets' region to join.
                let height = |v: &Vector3| n.dot(&(v - origin));
                let mut alone = Vec::new();
                super::supports_by_region(&sphere, &n, &height, &curved, &[], &mut [], &mut alone);
                let long: Vec<LocalContact> =
                    alone.iter().map(|s| super::alone_contact(s, &n)).collect();
                assert_eq!(short.len(), usize::from(depth > 0.0), "{k}");
                assert_eq!(long.len(), short.len(), "{k}: {long:?}");
                for (s, l) in short.iter().zip(&long) {
                    assert!((s.penetration - depth).abs() < 1e-12, "{k}: {s:?}");
                    assert!((s.penetration - l.penetration).abs() < 1e-12, "{k}");
                    assert!((s.point_i - l.point_i).norm() < 1e-12, "{k}");
                    assert!((s.point_j - l.point_j).norm() < 1e-12, "{k}");
                    assert!((s.area - l.area).abs() < 1e-12, "{k}");
                    compared += 1;
                }
            }
            assert!(compared > 150, "{compared}");
        }
    }
}
