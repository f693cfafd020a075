//! A general ellipsoid against a closed mesh, as the unit sphere against the mesh mapped by
//! the ellipsoid's inverse semi-axes (see the module doc of `crate::pairs::revolved_mesh`).

use crate::kernel::PairContact;
use crate::methods::volume_contact::{self, ENCLOSED, VolumeMoments};
use crate::pairs::mesh_plane::PreparedMesh;
use crate::pairs::revolved_mesh::{Profile, fallback, on_mesh, sliced_regions};
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};

/// The contacts of the general ellipsoid of `semi` axes (`a`, at `pose_a`) with `mesh` (`b`,
/// at `pose_b`), one per region: the mesh mapped by the ellipsoid's inverse semi-axes against
/// the unit sphere (a torus of no major radius), the moments mapped back (volume by `abc`, the
/// centroid by the semi-axes, area vectors by the cofactor `(bc, ac, ab)`, unsigned areas by
/// each piece's own factor). The normal when the area vector vanishes with the mesh inside
/// is against the ellipsoid's level surface through the centroid.
pub(crate) fn contacts(
    semi: &Vector3,
    pose_a: &Isometry3,
    mesh: &PreparedMesh,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let relative = pose_a.inv_mul(pose_b);
    let reach = (relative * mesh.centre).coords;
    if !mesh.inverted && (0..3).any(|k| reach[k].abs() - mesh.radius >= semi[k]) {
        return;
    }
    let local: Vec<Vector3> = mesh
        .vertices
        .iter()
        .map(|v| (relative * v).coords.component_div(semi))
        .collect();
    let cofactor = Vector3::new(semi.y * semi.z, semi.x * semi.z, semi.x * semi.y);
    let profile = Profile::Torus {
        big: 0.0,
        small: 1.0,
    };
    let length = semi.max();
    sliced_regions(
        profile,
        &local,
        mesh,
        Some(cofactor),
        work,
        &mut |region, root, work| {
            let r = region.integrals(root, work);
            let volume = r[0];
            if volume.is_nan() || volume <= 0.0 {
                return;
            }
            let centroid_e = Vector3::new(r[2], r[3], r[1]).component_mul(semi) / volume;
            let centroid = pose_a * Point3::from(centroid_e);
            let s_solid = pose_a.rotation * cofactor.component_mul(&Vector3::new(r[4], r[5], r[6]));
            let moments = VolumeMoments {
                volume: volume * semi.x * semi.y * semi.z,
                centroid,
                area_vector_a: s_solid,
                surface_area: r[7] + r[8],
                length,
            };
            let mesh = region.setup.mesh;
            let solid_inside = r[8] <= ENCLOSED * (r[7] + r[8]);
            let against_level = || {
                let gradient = centroid_e.component_div(&semi.component_mul(semi));
                if gradient.norm() > 0.0 {
                    -(pose_a.rotation * gradient.normalize())
                } else {
                    -(pose_a.rotation * Vector3::z())
                }
            };
            let on_ellipsoid = |g: &Point3, d: &Vector3| {
                let o = pose_a.inverse_transform_point(g).coords;
                let dir = pose_a.inverse_transform_vector(d);
                let t = crate::ray_exit::ellipsoid_exit(semi, &o, &dir).unwrap_or(0.0);
                pose_a * Point3::from(o + t * dir)
            };
            let found = volume_contact::contact_of_region(
                &moments,
                on_ellipsoid,
                |g, d| on_mesh(mesh, pose_b, g, d),
                || fallback(solid_inside, mesh, pose_b, &centroid, against_level),
                false,
            );
            if let Some(c) = found {
                emit(c);
            }
        },
    );
}
