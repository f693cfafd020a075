//! User force laws: NORMAL_ROUTINE and FRICTION_ROUTINE (SPEC §5).
//!
//! A CONTACT may name its own normal force or friction law as `library::function` with up to
//! 30 constants (`NORMAL_FUNCTION = USER(r1, …, r30)`). In Rust the law is a trait object
//! ([`UserNormalLaw`], [`UserFrictionLaw`]), and any closure of the right shape is one; the
//! application registers it under the routine's name or loads it from a shared library through
//! the C ABI of [`UserContactAbi`].
//!
//! Each call describes one contact (one intersection region of the pair) at one evaluation:
//! [`UserContact`]. The normal law returns the normal force magnitude, which pushes I along the
//! normal (J into I); unlike IMPACT it is not clamped, so a law may pull (adhesion). The
//! friction law returns the friction force on I (world frame) and the torque on I about the
//! normal; J receives the opposite. Both are evaluated from several threads at once when the
//! solver runs in parallel, so a law must not keep mutable state between calls.
//!
//! # The C ABI
//!
//! A routine in a shared library is a function
//!
//! ```c
//! int32_t function(const struct contact_user_input *input, double *output);
//! ```
//!
//! with `struct contact_user_input` laid out as [`UserContactAbi`] (`examples/user_routines/
//! contact_user.h` in the repository is the header). A normal routine writes one value
//! (`output[0]` = the normal force); a friction routine writes four (`output[0..3]` = the
//! friction force on I in world coordinates, `output[3]` = the torque on I about the normal).
//! It returns 0 on success; any other value is an error that stops the run, naming the contact,
//! the routine and the code. Pointers in the input are valid only during the call.

use crate::Vector3;

/// The version of [`UserContactAbi`]'s layout; a routine may check `input.abi_version`.
pub const USER_ABI_VERSION: u32 = 1;

/// One contact at one evaluation, as a user law sees it. Vectors are in world coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UserContact<'a> {
    /// Simulation time.
    pub time: f64,
    /// Which contact of the pair (0-based, in the engine's order of intersection regions).
    pub index: usize,
    /// The contact point on I's surface.
    pub point_i: Vector3,
    /// The contact point on J's surface.
    pub point_j: Vector3,
    /// The unit normal from J into I: the direction a positive normal force pushes I.
    pub normal: Vector3,
    /// The penetration δ ≥ 0.
    pub penetration: f64,
    /// δ̇, positive while the bodies approach.
    pub penetration_rate: f64,
    /// The contact area estimate.
    pub area: f64,
    /// The slip velocity of I against J at the contact point, tangential part.
    pub slip_velocity: Vector3,
    /// The relative spin of I against J about the normal.
    pub spin: f64,
    /// The normal force this contact carries: 0 for the normal law (not yet known), the normal
    /// law's result for the friction law.
    pub normal_force: f64,
    /// The USER constants, as given.
    pub parameters: &'a [f64],
}

/// What a friction law returns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UserFriction {
    /// The friction force on I, world frame (J receives the opposite).
    pub force_w: Vector3,
    /// The torque on I about the normal (J receives the opposite).
    pub torque: f64,
}

/// Why a user law gave no force.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum UserLawError {
    /// The routine reported a failure with a nonzero code.
    #[error("returned error code {0}")]
    Code(i32),
    /// The routine returned a value that is not a finite number.
    #[error("returned {value} for {what}, which is not a finite number")]
    NotFinite {
        /// Which output.
        what: &'static str,
        /// The value.
        value: f64,
    },
    /// The law's own message.
    #[error("{0}")]
    Message(String),
}

/// A user normal force law (NORMAL_ROUTINE).
pub trait UserNormalLaw: Send + Sync {
    /// The normal force magnitude for one contact (positive pushes I along the normal).
    fn normal_force(&self, contact: &UserContact<'_>) -> Result<f64, UserLawError>;
}

/// A user friction law (FRICTION_ROUTINE).
pub trait UserFrictionLaw: Send + Sync {
    /// The friction force and torque on I for one contact.
    fn friction(&self, contact: &UserContact<'_>) -> Result<UserFriction, UserLawError>;
}

impl<F> UserNormalLaw for F
where
    F: Fn(&UserContact<'_>) -> f64 + Send + Sync,
{
    fn normal_force(&self, contact: &UserContact<'_>) -> Result<f64, UserLawError> {
        Ok(self(contact))
    }
}

impl<F> UserFrictionLaw for F
where
    F: Fn(&UserContact<'_>) -> UserFriction + Send + Sync,
{
    fn friction(&self, contact: &UserContact<'_>) -> Result<UserFriction, UserLawError> {
        Ok(self(contact))
    }
}

/// The normal law's result, checked: a non-finite force is an error, never a force.
pub fn checked_normal_force(
    law: &dyn UserNormalLaw,
    contact: &UserContact<'_>,
) -> Result<f64, UserLawError> {
    let force = law.normal_force(contact)?;
    if !force.is_finite() {
        return Err(UserLawError::NotFinite {
            what: "the normal force",
            value: force,
        });
    }
    Ok(force)
}

/// The friction law's result, checked: a non-finite component is an error, never a force.
pub fn checked_friction(
    law: &dyn UserFrictionLaw,
    contact: &UserContact<'_>,
) -> Result<UserFriction, UserLawError> {
    let friction = law.friction(contact)?;
    for (what, value) in [
        ("the friction force's x", friction.force_w.x),
        ("the friction force's y", friction.force_w.y),
        ("the friction force's z", friction.force_w.z),
        ("the friction torque", friction.torque),
    ] {
        if !value.is_finite() {
            return Err(UserLawError::NotFinite { what, value });
        }
    }
    Ok(friction)
}

/// The input of a user routine across the C ABI (`struct contact_user_input`): plain `double`s
/// and 32-bit integers, no padding between fields on any platform with 8-byte doubles.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UserContactAbi {
    /// [`USER_ABI_VERSION`].
    pub abi_version: u32,
    /// Which contact of the pair (0-based).
    pub index: u32,
    /// Simulation time.
    pub time: f64,
    /// The contact point on I's surface, world frame.
    pub point_i: [f64; 3],
    /// The contact point on J's surface, world frame.
    pub point_j: [f64; 3],
    /// The unit normal from J into I, world frame.
    pub normal: [f64; 3],
    /// The penetration δ ≥ 0.
    pub penetration: f64,
    /// δ̇, positive while approaching.
    pub penetration_rate: f64,
    /// The contact area estimate.
    pub area: f64,
    /// The tangential slip velocity of I against J, world frame.
    pub slip_velocity: [f64; 3],
    /// The relative spin about the normal.
    pub spin: f64,
    /// The normal force (0 for a normal routine).
    pub normal_force: f64,
    /// The USER constants (`parameter_count` of them; null when there are none).
    pub parameters: *const f64,
    /// How many USER constants.
    pub parameter_count: u32,
    /// Reserved, 0.
    pub reserved: u32,
}

impl UserContactAbi {
    /// The C view of `contact`; its `parameters` pointer borrows `contact.parameters`, so it is
    /// valid while that slice lives.
    pub fn new(contact: &UserContact<'_>) -> Self {
        let v = |x: &Vector3| [x.x, x.y, x.z];
        Self {
            abi_version: USER_ABI_VERSION,
            index: u32::try_from(contact.index).unwrap_or(u32::MAX),
            time: contact.time,
            point_i: v(&contact.point_i),
            point_j: v(&contact.point_j),
            normal: v(&contact.normal),
            penetration: contact.penetration,
            penetration_rate: contact.penetration_rate,
            area: contact.area,
            slip_velocity: v(&contact.slip_velocity),
            spin: contact.spin,
            normal_force: contact.normal_force,
            parameters: if contact.parameters.is_empty() {
                std::ptr::null()
            } else {
                contact.parameters.as_ptr()
            },
            parameter_count: u32::try_from(contact.parameters.len()).unwrap_or(u32::MAX),
            reserved: 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contact(parameters: &[f64]) -> UserContact<'_> {
        UserContact {
            time: 0.5,
            index: 2,
            point_i: Vector3::new(1.0, 2.0, 3.0),
            point_j: Vector3::new(1.0, 2.0, 2.9),
            normal: Vector3::z(),
            penetration: 0.1,
            penetration_rate: -0.2,
            area: 0.3,
            slip_velocity: Vector3::new(0.4, 0.0, 0.0),
            spin: 0.5,
            normal_force: 6.0,
            parameters,
        }
    }

    #[test]
    fn closures_are_laws_and_non_finite_results_are_errors() {
        let spring = |c: &UserContact<'_>| c.parameters[0] * c.penetration;
        let c = contact(&[1e3]);
        assert_eq!(checked_normal_force(&spring, &c), Ok(100.0));
        let broken = |_: &UserContact<'_>| f64::NAN;
        let err = checked_normal_force(&broken, &c).unwrap_err();
        assert!(err.to_string().contains("normal force"), "{err}");
        let sticky = |c: &UserContact<'_>| UserFriction {
            force_w: -c.slip_velocity * c.normal_force,
            torque: f64::INFINITY,
        };
        let err = checked_friction(&sticky, &c).unwrap_err();
        assert!(err.to_string().contains("friction torque"), "{err}");
    }

    #[test]
    fn the_c_view_carries_every_field_and_the_documented_layout() {
        let parameters = [1.0, 2.0];
        let c = contact(&parameters);
        let abi = UserContactAbi::new(&c);
        assert_eq!(abi.abi_version, USER_ABI_VERSION);
        assert_eq!(abi.index, 2);
        assert_eq!(abi.point_j, [1.0, 2.0, 2.9]);
        assert_eq!(abi.slip_velocity, [0.4, 0.0, 0.0]);
        assert_eq!(abi.parameter_count, 2);
        assert_eq!(abi.parameters, parameters.as_ptr());
        assert!(UserContactAbi::new(&contact(&[])).parameters.is_null());
        // The offsets the C header documents (64-bit pointers).
        #[cfg(target_pointer_width = "64")]
        {
            assert_eq!(std::mem::offset_of!(UserContactAbi, time), 8);
            assert_eq!(std::mem::offset_of!(UserContactAbi, point_i), 16);
            assert_eq!(std::mem::offset_of!(UserContactAbi, normal), 64);
            assert_eq!(std::mem::offset_of!(UserContactAbi, penetration), 88);
            assert_eq!(std::mem::offset_of!(UserContactAbi, slip_velocity), 112);
            assert_eq!(std::mem::offset_of!(UserContactAbi, normal_force), 144);
            assert_eq!(std::mem::offset_of!(UserContactAbi, parameters), 152);
            assert_eq!(std::mem::size_of::<UserContactAbi>(), 168);
        }
    }
}
