//! How far an engine's contacts are from the reference contacts at one pose.

use contact_core::Contact;

/// Errors of one answer against its reference, relative to a length scale.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PoseErrors {
    /// Largest |δ − δ_ref| / scale over matched contacts; an unmatched contact counts its whole
    /// depth.
    pub depth: f64,
    /// Largest angle between matched normals, degrees, over resolved contacts (reference
    /// depth above the faceting band).
    pub normal_deg: f64,
    /// Largest distance between matched contact points (either body's) / scale, over resolved
    /// contacts.
    pub point: f64,
    /// Matched reference contacts deeper than the band: those the normal and point errors are
    /// taken over.
    pub resolved: usize,
    /// Reference contacts the engine did not return.
    pub missed: usize,
    /// Contacts the engine returned that the reference does not have.
    pub extra: usize,
}

impl PoseErrors {
    /// The worst of two.
    pub fn max(self, o: Self) -> Self {
        Self {
            depth: self.depth.max(o.depth),
            normal_deg: self.normal_deg.max(o.normal_deg),
            point: self.point.max(o.point),
            missed: self.missed + o.missed,
            extra: self.extra + o.extra,
            resolved: self.resolved + o.resolved,
        }
    }
}

/// Compares `got` to `reference`: contacts pair up greedily by geometry indices and nearest
/// midpoint. `scale` is the scene's length scale.
///
/// Depth is compared for every contact. Normal and point are compared only for reference
/// contacts deeper than `band` (model length): [`resolved_depth`], 0 for engines without
/// facets. A contact shallower than the band is a sliver of a facet or two
/// whose normal and point follow the facet phase rather than the geometry: its error does not
/// fall with the tolerance, and its whole depth already counts in the depth error if missed.
///
/// [`resolved_depth`]: super::resolved_depth
pub fn compare(got: &[Contact], reference: &[Contact], scale: f64, band: f64) -> PoseErrors {
    let mut used = vec![false; got.len()];
    let mut e = PoseErrors::default();
    for r in reference {
        let best = got
            .iter()
            .enumerate()
            .filter(|(k, g)| {
                !used[*k] && g.geometry_i == r.geometry_i && g.geometry_j == r.geometry_j
            })
            .min_by(|(_, a), (_, b)| {
                let da = (a.midpoint_w() - r.midpoint_w()).norm();
                let db = (b.midpoint_w() - r.midpoint_w()).norm();
                da.total_cmp(&db)
            })
            .map(|(k, _)| k);
        match best {
            Some(k) => {
                used[k] = true;
                let g = &got[k];
                e.depth = e.depth.max((g.penetration - r.penetration).abs() / scale);
                if r.penetration <= band {
                    continue;
                }
                e.resolved += 1;
                let cos = g.normal_w.dot(&r.normal_w).clamp(-1.0, 1.0);
                // atan2 of |cross| and dot is accurate for tiny angles, where acos is not.
                let angle = g.normal_w.cross(&r.normal_w).norm().atan2(cos).to_degrees();
                e.normal_deg = e.normal_deg.max(angle);
                let point = (g.point_i_w - r.point_i_w)
                    .norm()
                    .max((g.point_j_w - r.point_j_w).norm());
                e.point = e.point.max(point / scale);
            }
            None => {
                e.missed += 1;
                e.depth = e.depth.max(r.penetration / scale);
            }
        }
    }
    for (k, g) in got.iter().enumerate() {
        if !used[k] {
            e.extra += 1;
            e.depth = e.depth.max(g.penetration / scale);
        }
    }
    e
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::{Point3, Vector3};

    fn contact(depth: f64, normal: Vector3) -> Contact {
        Contact {
            point_i_w: Point3::new(0.0, 0.0, -depth),
            point_j_w: Point3::origin(),
            normal_w: normal.normalize(),
            penetration: depth,
            area: 1.0,
            geometry_i: 0,
            geometry_j: 0,
        }
    }

    #[test]
    fn errors_of_a_matched_pair_and_of_misses() {
        let r = contact(0.1, Vector3::z());
        let g = contact(0.11, Vector3::new(0.0, 1f64.to_radians().tan(), 1.0));
        let e = compare(&[g], &[r], 2.0, 0.0);
        assert!((e.depth - 0.005).abs() < 1e-15);
        assert!((e.normal_deg - 1.0).abs() < 1e-12);
        assert!((e.point - 0.005).abs() < 1e-15);
        assert_eq!((e.missed, e.extra, e.resolved), (0, 0, 1));
        let e = compare(&[], &[r], 2.0, 0.0);
        assert_eq!((e.missed, e.depth), (1, 0.05));
        let e = compare(&[g, g], &[r], 1.0, 0.0);
        assert_eq!(e.extra, 1);
    }

    #[test]
    fn contacts_within_the_band_count_their_depth_but_not_their_normal_or_point() {
        let r = contact(0.1, Vector3::z());
        let g = contact(0.11, Vector3::new(0.0, 1f64.to_radians().tan(), 1.0));
        let e = compare(&[g], &[r], 2.0, 0.1);
        assert!((e.depth - 0.005).abs() < 1e-15);
        assert_eq!((e.normal_deg, e.point, e.resolved), (0.0, 0.0, 0));
        let e = compare(&[g], &[r], 2.0, 0.0999);
        assert!((e.normal_deg - 1.0).abs() < 1e-12);
        assert_eq!(e.resolved, 1);
    }
}
