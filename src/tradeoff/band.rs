//! The faceting band: how shallow a contact can be and still be resolved by the facets.

use contact_core::{FacetingTolerance, Geometry, GeometryInstance};

/// How many faceting bands deep a contact must be to count as resolved in the normal and
/// point errors. At three bands the facets reach at least two thirds of the true depth, and
/// the faceted region spans several facets; shallower, it can be a sliver of a facet or two
/// whose normal and point follow the facet phase rather than the geometry (the depth error
/// still counts every contact). Measured over the suite with 5 and 10 facet phases per depth,
/// two bands left the worst case at the coarsest tolerances to a handful of samples and
/// to the luck of their phase (a parallel-cylinder normal 0.78° at FT 100, 0.93° at FT 300);
/// three bands gave errors that fall at every step of the default sweep for every scene.
pub const RESOLVED_BANDS: f64 = 3.0;

/// [`RESOLVED_BANDS`] times the [`faceting_band`]: the depth (model length) above which a
/// reference contact enters the normal and point errors.
pub fn resolved_depth(
    i: &[GeometryInstance],
    j: &[GeometryInstance],
    tolerance: FacetingTolerance,
) -> f64 {
    RESOLVED_BANDS * faceting_band(i, j, tolerance)
}

/// The faceting band of a scene at tolerance `tolerance`, in model length: the sum over the
/// two sides of the largest chord deviation `L/FT` among each side's tessellated geometries
/// (SPEC §7; an instance's own tolerance wins over `tolerance`, as in the engine).
///
/// The facets are inscribed in the true surfaces, so the faceted depth of a contact of true
/// depth δ lies between `δ − band` and δ: a contact shallower than the band may be missed
/// or found as a sliver of a facet or two. Geometry that is not tessellated adds nothing: a
/// box's facets are its faces, a mesh keeps its own, planes, lines and points stay exact.
pub fn faceting_band(
    i: &[GeometryInstance],
    j: &[GeometryInstance],
    tolerance: FacetingTolerance,
) -> f64 {
    side_deviation(i, tolerance) + side_deviation(j, tolerance)
}

fn side_deviation(side: &[GeometryInstance], tolerance: FacetingTolerance) -> f64 {
    side.iter()
        .filter(|g| is_tessellated(&g.geometry))
        .filter_map(|g| {
            let length = g.geometry.characteristic_length()?;
            Some(
                g.faceting_tolerance
                    .unwrap_or(tolerance)
                    .chord_deviation(length),
            )
        })
        .fold(0.0, f64::max)
}

/// Whether the faceted engine approximates this geometry by chords.
fn is_tessellated(g: &Geometry) -> bool {
    match g {
        Geometry::Ellipsoid(_)
        | Geometry::Cylinder(_)
        | Geometry::Frustum(_)
        | Geometry::Torus(_)
        | Geometry::Circle(_)
        | Geometry::Arc(_)
        | Geometry::Curve(_) => true,
        Geometry::Cuboid(_)
        | Geometry::Mesh(_)
        | Geometry::Plane(_)
        | Geometry::Point
        | Geometry::Line(_) => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_band_sums_each_sides_largest_deviation_of_curved_geometry() {
        let ft = FacetingTolerance::new(100.0).unwrap();
        let sphere = GeometryInstance::new(Geometry::sphere(1.0).unwrap());
        let cube = GeometryInstance::new(Geometry::Cuboid(
            contact_core::geometry::Cuboid::centered(1.0, 1.0, 1.0).unwrap(),
        ));
        // A unit sphere's bounding box has diagonal 2·√3.
        let one = 2.0 * 3f64.sqrt() / 100.0;
        let band = faceting_band(
            std::slice::from_ref(&sphere),
            std::slice::from_ref(&cube),
            ft,
        );
        assert!((band - one).abs() < 1e-15);
        let both = faceting_band(
            std::slice::from_ref(&sphere),
            std::slice::from_ref(&sphere),
            ft,
        );
        assert!((both - 2.0 * one).abs() < 1e-15);
        let mut own = sphere.clone();
        own.faceting_tolerance = Some(FacetingTolerance::new(1000.0).unwrap());
        let band = faceting_band(&[own], &[cube], ft);
        assert!((band - one / 10.0).abs() < 1e-16);
    }
}
