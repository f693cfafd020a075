//! CONTACTs lowered onto the solver: each geometry list placed on its solver part, the pair
//! prepared by the engine, and the force element given its bounds, length scale, planar guard
//! and user laws.

use super::{
    CmFrames, LowerError, MeshLoader, contact_user_laws, element_error, on_solver_part, unsupported,
};
use crate::model::{ContactElement, ContactGeometry, Model};
use crate::user_routines::UserRoutines;
use contact_core::{GeometryEngine, GeometryInstance};
use contact_solver::broad_phase::Bounds;
use contact_solver::contact_force::{Analysis, ContactForce, SharedContact};
use contact_solver::contact_plane::PlanarGuard;
use contact_solver::mbs::{MultibodyBuilder, PartId};
use std::sync::Arc;

/// What lowering a CONTACT reads besides the contact itself.
pub(super) struct ContactLowering<'a> {
    /// The engine that prepares each pair.
    pub engine: &'a dyn GeometryEngine,
    /// The analysis (decides whether DYNAMICS_ONLY friction acts).
    pub analysis: Analysis,
    /// The reader of mesh files.
    pub meshes: MeshLoader<'a>,
    /// User laws registered in code, looked up before the libraries.
    pub routines: &'a UserRoutines,
    /// The CM frame of every part.
    pub cm_of: &'a CmFrames,
}

impl ContactLowering<'_> {
    /// Adds every CONTACT of `model` as a force element; returns them, in model order, shared
    /// with the system.
    pub fn add_contacts(
        &self,
        model: &Model,
        builder: &mut MultibodyBuilder,
    ) -> Result<Vec<Arc<ContactForce>>, LowerError> {
        let mut contacts = Vec::new();
        for c in &model.contacts {
            let force = self.contact_force(c)?;
            let shared = Arc::new(force);
            builder
                .add_force(Box::new(SharedContact(shared.clone())))
                .map_err(element_error(&c.origin))?;
            contacts.push(shared);
        }
        Ok(contacts)
    }

    /// The force element of CONTACT `c`: its geometries placed on the solver parts, the pair
    /// prepared, its user laws found, with bounds, length scale and (for two planar
    /// geometries) a planar guard.
    fn contact_force(&self, c: &ContactElement) -> Result<ContactForce, LowerError> {
        let (i_list, j_list) = (
            self.place(c, &c.i_geometries, c.i_part)?,
            self.place(c, &c.j_geometries, c.j_part)?,
        );
        let pair = self
            .engine
            .prepare(&i_list, &j_list)
            .map_err(|source| LowerError::Prepare {
                origin: c.origin.clone(),
                id: c.id,
                source: Box::new(source),
            })?;
        let (pi, pj) = (self.cm_of[&c.i_part].0, self.cm_of[&c.j_part].0);
        let user = contact_user_laws(&c.params, &c.origin, self.routines).map_err(|source| {
            LowerError::UserRoutine {
                origin: c.origin.clone(),
                id: c.id,
                source: Box::new(source),
            }
        })?;
        let force = ContactForce::with_user_laws(
            format!("CONTACT/{}", c.id),
            pi,
            pj,
            pair,
            c.params.clone(),
            self.analysis,
            user,
        )
        .map_err(|e| unsupported(&c.origin, e.to_string()))?
        .with_bounds(Bounds::enclosing(&i_list), Bounds::enclosing(&j_list));
        let force = with_length_scale(force, &i_list, &j_list);
        Ok(with_planar_guard(force, c, &i_list, &j_list, [pi, pj]))
    }

    /// The geometries of one side of CONTACT `c` (mesh files read), each placed on the solver
    /// part of Adams part `part`.
    fn place(
        &self,
        c: &ContactElement,
        list: &[(u32, ContactGeometry)],
        part: u32,
    ) -> Result<Vec<GeometryInstance>, LowerError> {
        list.iter()
            .map(|(_, g)| {
                let mut instance = match g {
                    ContactGeometry::Geometry(instance) => instance.clone(),
                    ContactGeometry::MeshFile(file) => {
                        (self.meshes)(file).map_err(|message| LowerError::Mesh {
                            origin: c.origin.clone(),
                            message,
                        })?
                    }
                };
                let (_, pose) = on_solver_part(self.cm_of, part, &instance.pose_part_geometry)
                    .ok_or_else(|| {
                        unsupported(
                            &c.origin,
                            format!("CONTACT/{}: PART/{part} is not a part of the model", c.id),
                        )
                    })?;
                instance.pose_part_geometry = pose;
                Ok(instance)
            })
            .collect()
    }
}

/// `force` with the length scale of its geometries, the largest characteristic length of
/// either list (unchanged if none has one).
fn with_length_scale(
    force: ContactForce,
    i_list: &[GeometryInstance],
    j_list: &[GeometryInstance],
) -> ContactForce {
    let length = i_list
        .iter()
        .chain(j_list)
        .filter_map(|g| g.geometry.characteristic_length())
        .fold(0.0, f64::max);
    if length > 0.0 {
        force.with_length_scale(length)
    } else {
        force
    }
}

/// `force` with a planar guard when the first geometry of each side is planar (unchanged
/// otherwise); `[pi, pj]` are the solver parts of the I and J sides.
fn with_planar_guard(
    force: ContactForce,
    c: &ContactElement,
    i_list: &[GeometryInstance],
    j_list: &[GeometryInstance],
    [pi, pj]: [PartId; 2],
) -> ContactForce {
    match (i_list.first(), j_list.first()) {
        (Some(gi), Some(gj)) if gi.geometry.is_planar() && gj.geometry.is_planar() => {
            let length = [&gi.geometry, &gj.geometry]
                .iter()
                .filter_map(|g| g.characteristic_length())
                .fold(0.0, f64::max);
            force.with_planar_guard(PlanarGuard::new(
                [gi.pose_part_geometry, gj.pose_part_geometry],
                [format!("PART/{}", c.i_part), format!("PART/{}", c.j_part)],
                [pi.is_ground(), pj.is_ground()],
                length,
            ))
        }
        _ => force,
    }
}
