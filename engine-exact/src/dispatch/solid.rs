//! The 3-D pairs' kernels, one helper per row of the dispatch table: sphere and ellipsoid
//! pairs, plane pairs, box pairs, revolved (cylinder, frustum, torus) pairs and mesh pairs.
//! Each takes the pair in canonical order and says which flips it takes.

use super::{FLIP_NOT_BUILT, MESH_OPEN, NOT_A_CONTACT, NOT_BUILT, Pair, Selected, canonical, side};
use crate::kernel::{Kernel, PlaneKernel, SolidKernel};
use crate::pairs::box_mesh::box_mesh;
use crate::pairs::cylinder_sliced::SlicedSolid;
use crate::pairs::ellipsoid_cavity::Cavity;
use crate::pairs::sphere_solid::Solid;
use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid, Plane, Torus, TriangleMesh};
use contact_core::{Geometry, Unsupported};

// ---- Sphere and ellipsoid pairs.
impl Pair<'_> {
    /// Two ellipsoids: two spheres in closed form (one of them may be a cavity), else the
    /// general slicing; one general ellipsoid flipped (a cavity), the slicing along its axis.
    pub(super) fn ellipsoid_ellipsoid(
        &self,
        ea: &Ellipsoid,
        eb: &Ellipsoid,
    ) -> Result<Selected, Unsupported> {
        match (
            ea.sphere_radius(),
            eb.sphere_radius(),
            self.flip_a,
            self.flip_b,
        ) {
            (Some(radius_a), Some(radius_b), false, false) => {
                Ok(canonical(Kernel::Solid(SolidKernel::SphereSphere {
                    radius_a,
                    radius_b,
                })))
            }
            (Some(radius_a), Some(radius_b), false, true) => {
                Ok(canonical(Kernel::Solid(SolidKernel::SphereInCavity {
                    radius_a,
                    radius_b,
                })))
            }
            (Some(radius_a), Some(radius_b), true, false) => Ok(Selected {
                kernel: Kernel::Solid(SolidKernel::SphereInCavity {
                    radius_a: radius_b,
                    radius_b: radius_a,
                }),
                swap: true,
            }),
            (_, _, true, true) => Err(self.no(NOT_A_CONTACT)),
            (_, _, false, false) => Ok(canonical(Kernel::Solid(SolidKernel::EllipsoidEllipsoid {
                semi_a: ea.semi_axes(),
                semi_b: eb.semi_axes(),
            }))),
            // A general ellipsoid in an ellipsoid (or a sphere in a general one): sliced
            // along the cavity's axis.
            (_, _, false, true) => Ok(canonical(Kernel::Solid(SolidKernel::EllipsoidInCavity {
                semi_axes: ea.semi_axes(),
                cavity: Cavity::Ellipsoid(eb.semi_axes()),
            }))),
            (_, _, true, false) => Ok(Selected {
                kernel: Kernel::Solid(SolidKernel::EllipsoidInCavity {
                    semi_axes: eb.semi_axes(),
                    cavity: Cavity::Ellipsoid(ea.semi_axes()),
                }),
                swap: true,
            }),
        }
    }

    /// An ellipsoid (sphere or general) against a plane (bounded or not); refused when the
    /// ellipsoid is flipped.
    pub(super) fn ellipsoid_plane(
        &self,
        e: &Ellipsoid,
        p: &Plane,
    ) -> Result<Selected, Unsupported> {
        if self.flip_a {
            return Err(self.no(FLIP_NOT_BUILT));
        }
        let side = side(self.flip_b);
        if !p.is_unbounded() {
            return Ok(canonical(match e.sphere_radius() {
                Some(radius) => Kernel::Plane(PlaneKernel::SphereBoundedPlane {
                    radius,
                    plane: *p,
                    side,
                }),
                None => Kernel::Plane(PlaneKernel::EllipsoidBoundedPlane {
                    semi_axes: e.semi_axes(),
                    plane: *p,
                    side,
                }),
            }));
        }
        Ok(canonical(match e.sphere_radius() {
            Some(radius) => Kernel::Plane(PlaneKernel::SpherePlane { radius, side }),
            None => Kernel::Plane(PlaneKernel::EllipsoidPlane {
                semi_axes: e.semi_axes(),
                side,
            }),
        }))
    }

    /// An ellipsoid (or sphere) in a box-shaped cavity `b`: the ellipsoid against the
    /// cavity's walls as a mesh.
    pub(super) fn ellipsoid_in_box_cavity(
        &self,
        e: &Ellipsoid,
        cavity: &Cuboid,
    ) -> Result<Selected, Unsupported> {
        let mesh = self.cavity(cavity)?;
        Ok(canonical(Kernel::Solid(SolidKernel::EllipsoidMesh {
            semi_axes: e.semi_axes(),
            mesh,
        })))
    }

    /// An ellipsoid against the convex solid `b` (box, cylinder, frustum, torus): a sphere
    /// in closed form on one face (only `a` may be flipped), else the general slicing; in a
    /// cylinder-, frustum- or torus-shaped cavity (`b` flipped), the slicing along the
    /// cavity's axis.
    pub(super) fn ellipsoid_solid(&self, e: &Ellipsoid) -> Result<Selected, Unsupported> {
        let solid = self.solid(self.b)?;
        let cavity = match solid {
            Solid::Cylinder(c) => Some(Cavity::Cylinder(c)),
            Solid::Frustum(f) => Some(Cavity::Frustum(f)),
            Solid::Torus(t) => Some(Cavity::Torus(t)),
            Solid::Box(_) => None,
        };
        if let (Some(cavity), true, false) = (cavity, self.flip_b, self.flip_a) {
            return Ok(canonical(Kernel::Solid(SolidKernel::EllipsoidInCavity {
                semi_axes: e.semi_axes(),
                cavity,
            })));
        }
        match e.sphere_radius() {
            Some(radius) if !self.flip_b => self.no_flip(
                self.flip_a,
                Kernel::Solid(SolidKernel::SphereSolid { radius, solid }),
            ),
            Some(_) => Err(self.no(FLIP_NOT_BUILT)),
            None => general_ellipsoid_solid(e, &solid, self.flip_a || self.flip_b)
                .map_err(|reason| self.no(reason)),
        }
    }

    /// An ellipsoid against a closed mesh: a sphere by its signed distance to the mesh, a
    /// meshed cavity or a general ellipsoid by the slicing.
    pub(super) fn ellipsoid_mesh(
        &self,
        e: &Ellipsoid,
        mesh: &TriangleMesh,
    ) -> Result<Selected, Unsupported> {
        match e.sphere_radius() {
            Some(radius) if !self.flip_b => {
                let mesh = self.mesh(mesh, false)?;
                self.no_flip(
                    self.flip_a,
                    Kernel::Solid(SolidKernel::SphereMesh { radius, mesh }),
                )
            }
            // A sphere in a meshed cavity: the general ellipsoid slicing, which finds every
            // wall it meets as its own region.
            Some(_) | None => {
                let prepared = self.mesh(mesh, self.flip_b)?;
                self.no_flip(
                    self.flip_a,
                    Kernel::Solid(SolidKernel::EllipsoidMesh {
                        semi_axes: e.semi_axes(),
                        mesh: prepared,
                    }),
                )
            }
        }
    }
}

/// A general ellipsoid against a box, a cylinder, a frustum or a torus (sliced), or the
/// reason it is refused.
fn general_ellipsoid_solid(
    e: &Ellipsoid,
    solid: &Solid,
    flipped: bool,
) -> Result<Selected, &'static str> {
    let semi_axes = e.semi_axes();
    let kernel = match *solid {
        Solid::Box(cuboid) => Kernel::Solid(SolidKernel::EllipsoidBox { semi_axes, cuboid }),
        Solid::Cylinder(cylinder) => Kernel::Solid(SolidKernel::EllipsoidCylinder {
            semi_axes,
            cylinder,
        }),
        Solid::Frustum(frustum) => {
            Kernel::Solid(SolidKernel::EllipsoidFrustum { semi_axes, frustum })
        }
        Solid::Torus(torus) => Kernel::Solid(SolidKernel::EllipsoidTorus { semi_axes, torus }),
    };
    if flipped {
        Err(FLIP_NOT_BUILT)
    } else {
        Ok(canonical(kernel))
    }
}

// ---- Plane pairs (the plane `b` may be flipped).
impl Pair<'_> {
    /// A cylinder against a plane: chords in closed form for an unbounded plane, the
    /// sliced cylinder for a bounded one.
    pub(super) fn cylinder_plane(
        &self,
        cylinder: &Cylinder,
        p: &Plane,
    ) -> Result<Selected, Unsupported> {
        if p.is_unbounded() {
            self.no_flip(
                self.flip_a,
                Kernel::Plane(PlaneKernel::CylinderPlane {
                    cylinder: *cylinder,
                    side: side(self.flip_b),
                }),
            )
        } else {
            self.no_flip(
                self.flip_a,
                Kernel::Solid(SolidKernel::CylinderSliced {
                    cylinder: *cylinder,
                    other: SlicedSolid::Plane {
                        plane: *p,
                        side: side(self.flip_b),
                    },
                }),
            )
        }
    }

    /// A frustum or torus `a` against a plane, bounded or not.
    pub(super) fn revolved_plane(&self, p: &Plane) -> Result<Selected, Unsupported> {
        let solid = self.solid(self.a)?;
        if p.is_unbounded() {
            self.no_flip(
                self.flip_a,
                Kernel::Plane(PlaneKernel::RevolvedPlane {
                    solid,
                    side: side(self.flip_b),
                }),
            )
        } else {
            self.no_flip(
                self.flip_a,
                Kernel::Plane(PlaneKernel::RevolvedBoundedPlane {
                    solid,
                    plane: *p,
                    side: side(self.flip_b),
                }),
            )
        }
    }

    /// A box against a plane (bounded or not).
    pub(super) fn box_plane(
        &self,
        cuboid: &Cuboid,
        plane: &Plane,
    ) -> Result<Selected, Unsupported> {
        self.no_flip(
            self.flip_a,
            Kernel::Plane(PlaneKernel::BoxPlane {
                cuboid: *cuboid,
                plane: *plane,
                side: side(self.flip_b),
            }),
        )
    }

    /// A closed mesh against a plane, bounded or not.
    pub(super) fn mesh_plane(
        &self,
        mesh: &TriangleMesh,
        p: &Plane,
    ) -> Result<Selected, Unsupported> {
        let mesh = self.mesh(mesh, false)?;
        let side = side(self.flip_b);
        self.no_flip(
            self.flip_a,
            if p.is_unbounded() {
                Kernel::Plane(PlaneKernel::MeshPlane { mesh, side })
            } else {
                Kernel::Plane(PlaneKernel::MeshBoundedPlane {
                    mesh,
                    plane: *p,
                    side,
                })
            },
        )
    }
}

// ---- Box pairs.
impl Pair<'_> {
    /// Two boxes: convex clipping, or, when one is a cavity, the other box against the
    /// cavity's walls (a mesh turned inside out).
    pub(super) fn box_box(&self, a_box: &Cuboid, b_box: &Cuboid) -> Result<Selected, Unsupported> {
        match (self.flip_a, self.flip_b) {
            (false, false) => Ok(canonical(Kernel::Solid(SolidKernel::BoxBox {
                a: *a_box,
                b: *b_box,
            }))),
            // A box in a box-shaped cavity: the box against the cavity's walls, a mesh
            // turned inside out.
            (false, true) | (true, false) => {
                let (inner, cavity) = if self.flip_b {
                    (a_box, b_box)
                } else {
                    (b_box, a_box)
                };
                let walls = box_mesh(cavity)
                    .ok_or_else(|| self.no(MESH_OPEN))?
                    .inverted();
                Ok(Selected {
                    kernel: Kernel::Solid(SolidKernel::BoxMesh {
                        cuboid: *inner,
                        mesh: std::sync::Arc::new(walls),
                    }),
                    swap: self.flip_a,
                })
            }
            (true, true) => Err(self.no(NOT_A_CONTACT)),
        }
    }

    /// A box against a frustum or torus `b`, sliced across the axis (no flip).
    pub(super) fn box_revolved(&self, cuboid: &Cuboid) -> Result<Selected, Unsupported> {
        let solid = self.solid(self.b)?;
        self.no_flip(
            self.flip_a || self.flip_b,
            Kernel::Solid(SolidKernel::BoxRevolved {
                cuboid: *cuboid,
                solid,
            }),
        )
    }

    /// Two closed meshes, as given (`crate::pairs::mesh_mesh`); no flip.
    pub(super) fn mesh_mesh(
        &self,
        mesh_a: &std::sync::Arc<contact_core::geometry::TriangleMesh>,
        mesh_b: &std::sync::Arc<contact_core::geometry::TriangleMesh>,
    ) -> Result<Selected, Unsupported> {
        let pair = crate::pairs::mesh_mesh::MeshPair::new(mesh_a, mesh_b)
            .ok_or_else(|| self.no(MESH_OPEN))?;
        self.no_flip(
            self.flip_a || self.flip_b,
            Kernel::Solid(SolidKernel::MeshMesh { pair }),
        )
    }

    /// A box against a closed mesh (the mesh may be a cavity).
    pub(super) fn box_mesh(
        &self,
        cuboid: &Cuboid,
        mesh: &TriangleMesh,
    ) -> Result<Selected, Unsupported> {
        let prepared = self.mesh(mesh, self.flip_b)?;
        self.no_flip(
            self.flip_a,
            Kernel::Solid(SolidKernel::BoxMesh {
                cuboid: *cuboid,
                mesh: prepared,
            }),
        )
    }
}

// ---- Revolved pairs (cylinder, frustum, torus).
impl Pair<'_> {
    /// A cylinder `a` in a box-shaped cavity `b`: the cylinder against the cavity's walls.
    pub(super) fn cylinder_in_box_cavity(&self, cavity: &Cuboid) -> Result<Selected, Unsupported> {
        let solid = self.solid(self.a)?;
        let mesh = self.cavity(cavity)?;
        Ok(canonical(Kernel::Solid(SolidKernel::RevolvedMesh {
            solid,
            mesh,
        })))
    }

    /// A frustum or torus `b` in a box-shaped cavity `a`: the kernel's first geometry is J.
    pub(super) fn revolved_in_box_cavity(&self, cavity: &Cuboid) -> Result<Selected, Unsupported> {
        let solid = self.solid(self.b)?;
        let mesh = self.cavity(cavity)?;
        Ok(Selected {
            kernel: Kernel::Solid(SolidKernel::RevolvedMesh { solid, mesh }),
            swap: true,
        })
    }

    /// A cylinder against a cylinder or a box `b` (no flip).
    pub(super) fn cylinder_sliced(&self, cylinder: &Cylinder) -> Result<Selected, Unsupported> {
        use Geometry as G;
        let other = match self.b {
            G::Cuboid(c) => SlicedSolid::Box(*c),
            G::Cylinder(c) => SlicedSolid::Cylinder(*c),
            // Only cylinders and boxes reach here (the dispatch arm's patterns).
            G::Ellipsoid(_)
            | G::Frustum(_)
            | G::Torus(_)
            | G::Mesh(_)
            | G::Plane(_)
            | G::Point
            | G::Line(_)
            | G::Circle(_)
            | G::Arc(_)
            | G::Curve(_) => return Err(self.no(NOT_BUILT)),
        };
        self.no_flip(
            self.flip_a || self.flip_b,
            Kernel::Solid(SolidKernel::CylinderSliced {
                cylinder: *cylinder,
                other,
            }),
        )
    }

    /// A cylinder, frustum or torus `a` against a closed mesh (the mesh may be a cavity).
    pub(super) fn revolved_mesh(&self, mesh: &TriangleMesh) -> Result<Selected, Unsupported> {
        let solid = self.solid(self.a)?;
        let prepared = self.mesh(mesh, self.flip_b)?;
        self.no_flip(
            self.flip_a,
            Kernel::Solid(SolidKernel::RevolvedMesh {
                solid,
                mesh: prepared,
            }),
        )
    }

    /// A cylinder or frustum `a` against a frustum `b` (no flip).
    pub(super) fn revolved_pair(&self) -> Result<Selected, Unsupported> {
        let solid_a = self.solid(self.a)?;
        let solid_b = self.solid(self.b)?;
        self.no_flip(
            self.flip_a || self.flip_b,
            Kernel::Solid(SolidKernel::RevolvedPair {
                a: solid_a,
                b: solid_b,
            }),
        )
    }

    /// A cylinder or frustum `a` against a torus (no flip).
    pub(super) fn revolved_torus(&self, torus: &Torus) -> Result<Selected, Unsupported> {
        let solid = self.solid(self.a)?;
        self.no_flip(
            self.flip_a || self.flip_b,
            Kernel::Solid(SolidKernel::RevolvedTorus {
                solid,
                torus: *torus,
            }),
        )
    }

    /// A torus `a` against a torus `b` (no flip).
    pub(super) fn torus_torus(&self, a: &Torus, b: &Torus) -> Result<Selected, Unsupported> {
        self.no_flip(
            self.flip_a || self.flip_b,
            Kernel::Solid(SolidKernel::TorusTorus { a: *a, b: *b }),
        )
    }
}
