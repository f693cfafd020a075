//! One region of a sliced solid against a mesh: its integrals over the pieces, and its
//! contact from them (see the module doc of [`super`]).

use super::Profile;
use super::section::{arc_moments, chord_moments};
use super::{Setup, Slice, arcs, regions};
use crate::kernel::PairContact;
use crate::methods::disc_section::disc_section;
use crate::methods::ellipsoid_sliced::{ADAPTIVE, COMPONENTS, floor};
use crate::methods::solid_distance::{Solid, signed_distance};
use crate::methods::volume_contact::{self, ENCLOSED, VolumeMoments};
use crate::pairs::mesh_plane::{PreparedMesh, closest_on_mesh, exit_along};
use crate::quadrature::MAX_PIECES;
use crate::ray_exit::surface_point_along_w;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use std::f64::consts::TAU;

/// `∫ |c ∘ ν(φ)| dφ` over the arc from `start` over `sweep` of the circle of radius `r` at
/// height `t` on the sphere of radius `rho` (`ν` its unit normal there): the arc's unsigned
/// area element mapped back by the cofactor `c` (12-node Gauss per quarter turn; only the
/// unsigned area, for the vanishing test and a contained region's area, uses it).
pub(super) fn mapped_arc(c: &Vector3, r: f64, t: f64, rho: f64, start: f64, sweep: f64) -> f64 {
    let parts = (sweep / std::f64::consts::FRAC_PI_2).ceil().max(1.0);
    let step = sweep / parts;
    let mut sum = 0.0;
    for k in 0..parts as usize {
        let a = start + k as f64 * step;
        crate::quadrature::for_each_node(a, a + step, |phi, w| {
            let (sin, cos) = phi.sin_cos();
            let nu = Vector3::new(r * cos, r * sin, t) / rho;
            sum += w * c.component_mul(&nu).norm();
        });
    }
    sum
}

/// A triangle's area factor back from the sliced space: `|cof ∘ n| / |n|` (1 unmapped).
pub(super) fn area_scale(v: &[Vector3; 3], cofactor: Option<Vector3>) -> f64 {
    match cofactor {
        None => 1.0,
        Some(c) => {
            let n = (v[1] - v[0]).cross(&(v[2] - v[0]));
            c.component_mul(&n).norm() / n.norm()
        }
    }
}

/// At `x` (the height `t` for a frustum, the angle `θ` of `t = ρ sin θ` for a torus): `t`,
/// `dt/dx`, and per circle (outer, inner) the factor of `r·sweep` in `S_z` and in the
/// unsigned area; `None` where a torus' `s = ρ cos θ` is not positive.
fn profile_scales(profile: &Profile, x: f64) -> Option<(f64, f64, (f64, f64), f64)> {
    // t, dt/dx, and per circle the factor of `r·sweep` in S_z and in the unsigned area.
    Some(match *profile {
        Profile::Frustum { slope, .. } => (x, 1.0, (-slope, 0.0), (1.0 + slope * slope).sqrt()),
        Profile::Torus { small, .. } => {
            let (sin, cos) = x.sin_cos();
            let (t, s) = (small * sin, small * cos);
            if s.is_nan() || s <= 0.0 {
                return None;
            }
            (t, s, (t, t), small)
        }
    })
}

/// Adds a piece's section moments `m` (area, `∫x`, `∫y`), times `sign`, to the integrand
/// `out`.
fn add_moments(out: &mut [f64; COMPONENTS], m: [f64; 3], sign: f64) {
    out[0] += sign * m[0];
    out[2] += sign * m[1];
    out[3] += sign * m[2];
}

/// What a region's integration reads.
pub(crate) struct Region<'a> {
    pub(crate) setup: &'a Setup<'a>,
    pub(super) roots: &'a [u32],
    pub(super) labels: &'a regions::Labels,
    pub(super) flat: &'a [(u32, [Vector3; 3])],
    /// `(triangle, root)` for every chord, sorted.
    pub(super) touched: &'a [(u32, u32)],
}

impl Region<'_> {
    /// The integrand for region `root` at `x` (the height `t` for a frustum, the angle `θ` of
    /// `t = ρ sin θ` for a torus): `[area, t·area, ∫x, ∫y, S_solid (3), solid's surface inside
    /// the mesh, mesh's surface inside the solid]` per unit of `x`.
    fn integrand(&self, root: u32, x: f64, slice: &mut Slice) -> [f64; COMPONENTS] {
        let setup = self.setup;
        let mut out = [0.0; COMPONENTS];
        let Some((t, jacobian, (sz_outer, sz_inner), unsigned)) = profile_scales(&setup.profile, x)
        else {
            return out;
        };
        let labels = self.labels;
        let pieces = labels.outer.len();
        let p = setup
            .cuts
            .partition_point(|&c| c <= t)
            .saturating_sub(1)
            .min(pieces.saturating_sub(1));
        let (ro, ri) = setup.profile.circles(t);
        if ro <= 0.0 {
            return out;
        }
        setup.slice(p, t, slice);
        let node = |c: usize| labels.offsets[p] + c;
        let mesh_area = self.chord_terms(root, p, slice, &mut out);
        // Per circle: radius, orientation (+1 outer, −1 inner), S_z factor, crossings, full.
        let mut lateral = [0.0; 4];
        let circles = [
            (
                ro,
                1.0,
                sz_outer,
                &slice.outer,
                labels.outer[p],
                labels.outer_node(p),
            ),
            (
                ri,
                -1.0,
                sz_inner,
                &slice.inner,
                labels.inner[p],
                labels.inner_node(p),
            ),
        ];
        for (r, sign, sz, crossings, full, full_node) in circles {
            if r <= 0.0 {
                continue;
            }
            let mut swept = |start: f64, sweep: f64| {
                let (m, normal) = arc_moments(r, start, sweep);
                add_moments(&mut out, m, sign);
                lateral[0] += sign * r * normal.x;
                lateral[1] += sign * r * normal.y;
                lateral[2] += sz * r * sweep;
                lateral[3] += unsigned
                    * r
                    * match setup.cofactor {
                        None => sweep,
                        Some(c) => mapped_arc(&c, r, t, unsigned, start, sweep),
                    };
            };
            if crossings.is_empty() {
                if full && self.roots[full_node] == root {
                    swept(0.0, TAU);
                }
            } else {
                for (i, start, sweep) in arcs(crossings) {
                    if self.roots.get(node(crossings[i].chord)) == Some(&root) {
                        swept(start, sweep);
                    }
                }
            }
        }
        // Per dx: the sections' terms times dt/dx; the swept S_z and unsigned terms already
        // are (a torus' `(t/s)·r·sweep` and `(ρ/s)·r·sweep` per dt are `t·r·sweep` and
        // `ρ·r·sweep` per dθ, smooth where `s` vanishes).
        out[0] *= jacobian;
        out[2] *= jacobian;
        out[3] *= jacobian;
        out[1] = t * out[0];
        out[4] = lateral[0] * jacobian;
        out[5] = lateral[1] * jacobian;
        out[6] = lateral[2];
        out[7] = lateral[3];
        out[8] = mesh_area * jacobian;
        out
    }

    /// The chords of region `root` in piece `p`'s `slice`: their section moments added to
    /// `out` (see [`add_moments`]), and the mesh's surface they sweep per unit of `t`.
    fn chord_terms(&self, root: u32, p: usize, slice: &Slice, out: &mut [f64; COMPONENTS]) -> f64 {
        let setup = self.setup;
        let node = |c: usize| self.labels.offsets[p] + c;
        let mut mesh_area = 0.0;
        for (c, &(k, a, e, _)) in slice.chords.iter().enumerate() {
            if self.roots.get(node(c)) != Some(&root) {
                continue;
            }
            add_moments(out, chord_moments(&a, &e), 1.0);
            let tri = &setup.sliced[setup.active[p][k] as usize];
            mesh_area += (e - a).norm() / tri.slope * tri.scale;
        }
        mesh_area
    }

    /// Region `root`'s contact with the revolved `solid`.
    pub(crate) fn contact(
        &self,
        root: u32,
        solid: &Solid,
        pose_a: &Isometry3,
        pose_b: &Isometry3,
        unit: f64,
        work: &mut WorkCounters,
    ) -> Option<PairContact> {
        let r = self.integrals(root, work);
        let volume = r[0];
        if volume.is_nan() || volume <= 0.0 {
            return None;
        }
        let centroid = pose_a * Point3::from(Vector3::new(r[2], r[3], r[1]) / volume * unit);
        let s_solid = pose_a.rotation * Vector3::new(r[4], r[5], r[6]) * (unit * unit);
        let moments = VolumeMoments {
            volume: volume * unit * unit * unit,
            centroid,
            area_vector_a: s_solid,
            surface_area: (r[7] + r[8]) * unit * unit,
            length: unit,
        };
        let mesh = self.setup.mesh;
        let solid_inside = r[8] <= ENCLOSED * (r[7] + r[8]);
        let against_solid = || {
            let p = pose_a.inverse_transform_point(&centroid).coords;
            -(pose_a.rotation * signed_distance(solid, &p).2)
        };
        volume_contact::contact_of_region(
            &moments,
            |g, d| surface_point_along_w(solid, pose_a, g, d),
            |g, d| on_mesh(mesh, pose_b, g, d),
            || fallback(solid_inside, mesh, pose_b, &centroid, against_solid),
            false,
        )
    }

    /// Region `root`'s integrals in the sliced space: `[volume, ∫z, ∫x, ∫y, S_solid (3),
    /// solid's surface inside the mesh, mesh's surface inside the solid]`.
    pub(crate) fn integrals(&self, root: u32, work: &mut WorkCounters) -> [f64; COMPONENTS] {
        let setup = self.setup;
        let mut slice = Slice::default();
        let torus = matches!(setup.profile, Profile::Torus { .. });
        let small = match setup.profile {
            Profile::Torus { small, .. } => small,
            Profile::Frustum { .. } => 1.0,
        };
        let mapped: Vec<f64> = if torus {
            setup
                .cuts
                .iter()
                .map(|c| (c / small).clamp(-1.0, 1.0).asin())
                .collect()
        } else {
            setup.cuts.clone()
        };
        let mut f = |x: f64| self.integrand(root, x, &mut slice);
        let mut r = [0.0; COMPONENTS];
        let n = mapped.len();
        let mut start = 0;
        while start + 1 < n {
            let end = (start + MAX_PIECES).min(n - 1);
            let mut cuts = mapped[start..=end].to_vec();
            let part = ADAPTIVE.integrate_pieces(&mut cuts, &mut f, &floor, work);
            for k in 0..COMPONENTS {
                r[k] += part[k];
            }
            start = end;
        }
        let mut slice = Slice::default();
        // A frustum's caps: the section's limit from inside at t = 0 and t = L.
        if let Profile::Frustum { len, .. } = setup.profile {
            for (t, sign) in [(0.0, -1.0), (len, 1.0)] {
                let c = self.integrand(root, t, &mut slice);
                r[6] += sign * c[0];
                r[7] += c[0];
            }
        }
        // Mesh faces parallel to the slices, by their overlap with the section at their height.
        let (z0, z1) = setup.profile.range();
        for (tri, v) in self.flat {
            let joined = setup.mesh.neighbours[*tri as usize]
                .iter()
                .any(|&n| self.touched.binary_search(&(n, root)).is_ok());
            let h = v[0].z;
            if !joined || h < z0 || h > z1 {
                continue;
            }
            let mut polygon = [v[0].xy(), v[1].xy(), v[2].xy()];
            if (polygon[1] - polygon[0]).perp(&(polygon[2] - polygon[0])) < 0.0 {
                polygon.swap(1, 2);
            }
            let (ro, ri) = setup.profile.circles(h);
            r[8] +=
                disc_section(ro, &polygon, &[0; 3]).area - disc_section(ri, &polygon, &[0; 3]).area;
        }
        r
    }
}

/// Where the line from `g` along `d` first meets the mesh (at `pose_b`), or its closest point.
pub(crate) fn on_mesh(mesh: &PreparedMesh, pose_b: &Isometry3, g: &Point3, d: &Vector3) -> Point3 {
    let from = pose_b.inverse_transform_point(g);
    let direction = pose_b.inverse_transform_vector(d);
    pose_b * exit_along(mesh, &from, &direction).unwrap_or_else(|| closest_on_mesh(mesh, &from))
}

/// The normal when the area vector vanishes: with no mesh surface inside the solid, from the
/// centroid to the mesh's closest point; otherwise `against_solid()`.
pub(crate) fn fallback(
    solid_inside: bool,
    mesh: &PreparedMesh,
    pose_b: &Isometry3,
    centroid: &Point3,
    against_solid: impl FnOnce() -> Vector3,
) -> Vector3 {
    if solid_inside {
        let c = pose_b.inverse_transform_point(centroid);
        let away = pose_b.rotation * (closest_on_mesh(mesh, &c) - c);
        if away.norm() > 0.0 {
            away.normalize()
        } else {
            Vector3::z()
        }
    } else {
        against_solid()
    }
}
