//! Contact kinematics: the rates a force law needs, from a [`Contact`] and the two bodies'
//! motion.
//!
//! The formulas are on [`ContactKinematics`].

use crate::{Contact, Isometry3, Point3, Vector3};

/// A rigid body's pose and velocity, all in the world frame `W`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyMotion {
    /// The body frame `B` measured in `W` (`X_WB`).
    pub pose_w: Isometry3,
    /// The velocity of the body frame's origin `Bo`, in `W`.
    pub velocity_w: Vector3,
    /// The body's angular velocity, in `W`.
    pub angular_velocity_w: Vector3,
}

impl BodyMotion {
    /// A body at `pose_w` at rest.
    pub fn at_rest(pose_w: Isometry3) -> Self {
        Self {
            pose_w,
            velocity_w: Vector3::zeros(),
            angular_velocity_w: Vector3::zeros(),
        }
    }

    /// The velocity of the body's material point at world position `point_w`:
    /// `v + ω × (point_w − p_WBo)`.
    pub fn point_velocity_w(&self, point_w: &Vector3) -> Vector3 {
        self.velocity_w
            + self
                .angular_velocity_w
                .cross(&(point_w - self.pose_w.translation.vector))
    }
}

/// The rates of one contact.
///
/// Both bodies are rigid. Body `B` (I or J) has its frame at `X_WB` (`pose_w`), the velocity
/// `v_B` of its frame origin `Bo` and its angular velocity `ω_B`, all in the world frame `W`.
/// The velocity of B's material point at world position `p` is
///
/// `v_B(p) = v_B + ω_B × (p − p_WBo)`.
///
/// At a contact the force acts at the midpoint `p = (point_i_w + point_j_w)/2` of the two
/// surface points, and with `n` the unit normal from J into I and `v = v_I(p) − v_J(p)` the
/// velocity of I's material point relative to J's:
///
/// - penetration rate `δ̇ = −n·v` (positive while the bodies approach, the sign the normal laws
///   take);
/// - slip velocity `v_t = v − (n·v)·n` (the tangential part of `v`, what
///   [`CoulombFriction::force`](crate::laws::CoulombFriction::force) takes);
/// - spin rate `ω_n = (ω_I − ω_J)·n` (the relative rotation about the normal, what
///   [`CoulombFriction::torque`](crate::laws::CoulombFriction::torque) takes).
///
/// The multibody solver computes its contact forces with these functions, so an embedder who
/// uses them gets the solver's numbers bit for bit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactKinematics {
    /// The force application point `p`, midway between the two surface points, in `W`.
    pub point_w: Point3,
    /// `v = v_I(p) − v_J(p)`: I's material point at `p` relative to J's, in `W`.
    pub relative_velocity_w: Vector3,
    /// `δ̇ = −n·v`, positive while the bodies approach.
    pub penetration_rate: f64,
    /// `v_t = v − (n·v)·n`, the slip of I relative to J in the tangent plane, in `W`.
    pub slip_velocity_w: Vector3,
    /// `ω_n = (ω_I − ω_J)·n`, I's spin relative to J about the normal.
    pub spin: f64,
}

impl ContactKinematics {
    /// The rates of `contact` between body I moving as `body_i` and body J moving as `body_j`.
    ///
    /// Any finite motion gives finite rates; the normal is used as given (the engines return
    /// it unit length).
    pub fn compute(contact: &Contact, body_i: &BodyMotion, body_j: &BodyMotion) -> Self {
        let p = contact.midpoint_w();
        let n = contact.normal_w;
        let v = body_i.point_velocity_w(&p.coords) - body_j.point_velocity_w(&p.coords);
        Self {
            point_w: p,
            relative_velocity_w: v,
            penetration_rate: -n.dot(&v),
            slip_velocity_w: v - n * n.dot(&v),
            spin: (body_i.angular_velocity_w - body_j.angular_velocity_w).dot(&n),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contact(point_i: Point3, point_j: Point3, normal: Vector3) -> Contact {
        Contact {
            point_i_w: point_i,
            point_j_w: point_j,
            normal_w: normal,
            penetration: (point_j - point_i).dot(&normal),
            area: 0.0,
            geometry_i: 0,
            geometry_j: 0,
        }
    }

    /// A ball falling at 2 m/s onto resting ground: δ̇ = 2, no slip, no spin.
    #[test]
    fn a_falling_body_approaches_at_its_speed() {
        let c = contact(Point3::new(0.0, 0.0, -0.01), Point3::origin(), Vector3::z());
        let ball = BodyMotion {
            pose_w: Isometry3::translation(0.0, 0.0, 0.99),
            velocity_w: Vector3::new(0.0, 0.0, -2.0),
            angular_velocity_w: Vector3::zeros(),
        };
        let k = ContactKinematics::compute(&c, &ball, &BodyMotion::at_rest(Isometry3::identity()));
        assert_eq!(k.point_w, Point3::new(0.0, 0.0, -0.005));
        assert_eq!(k.penetration_rate, 2.0);
        assert_eq!(k.slip_velocity_w, Vector3::zeros());
        assert_eq!(k.spin, 0.0);
    }

    /// By hand: I's origin at (0, 0, 1) moving (1, 0, −1) and turning ω_I = (0, 2, 3); J's
    /// origin at (1, 0, 0) moving (0, 0.5, 0) and turning ω_J = (0, 0, 1); the contact's
    /// midpoint p = (0, 0, 0), n = z.
    ///
    /// v_I(p) = (1, 0, −1) + (0, 2, 3) × (0, 0, −1) = (1, 0, −1) + (−2, 0, 0) = (−1, 0, −1);
    /// v_J(p) = (0, 0.5, 0) + (0, 0, 1) × (−1, 0, 0) = (0, 0.5, 0) + (0, −1, 0) = (0, −0.5, 0);
    /// v = (−1, 0.5, −1): δ̇ = 1, v_t = (−1, 0.5, 0), ω_n = 3 − 1 = 2.
    #[test]
    fn rates_of_two_moving_bodies_match_the_hand_computation() {
        let c = contact(
            Point3::new(0.0, 0.0, -0.001),
            Point3::new(0.0, 0.0, 0.001),
            Vector3::z(),
        );
        let i = BodyMotion {
            pose_w: Isometry3::translation(0.0, 0.0, 1.0),
            velocity_w: Vector3::new(1.0, 0.0, -1.0),
            angular_velocity_w: Vector3::new(0.0, 2.0, 3.0),
        };
        let j = BodyMotion {
            pose_w: Isometry3::translation(1.0, 0.0, 0.0),
            velocity_w: Vector3::new(0.0, 0.5, 0.0),
            angular_velocity_w: Vector3::new(0.0, 0.0, 1.0),
        };
        let k = ContactKinematics::compute(&c, &i, &j);
        assert_eq!(k.point_w, Point3::origin());
        assert_eq!(k.relative_velocity_w, Vector3::new(-1.0, 0.5, -1.0));
        assert_eq!(k.penetration_rate, 1.0);
        assert_eq!(k.slip_velocity_w, Vector3::new(-1.0, 0.5, 0.0));
        assert_eq!(k.spin, 2.0);
        // Exchanging the bodies and swapping the contact gives the same rate and spin, and
        // the opposite slip.
        let back = ContactKinematics::compute(&c.swapped(), &j, &i);
        assert_eq!(back.penetration_rate, 1.0);
        assert_eq!(back.spin, 2.0);
        assert_eq!(back.slip_velocity_w, -k.slip_velocity_w);
    }

    /// A tilted normal: the slip is orthogonal to it and slip + rate along −n rebuild v.
    #[test]
    fn slip_and_rate_decompose_the_relative_velocity() {
        let n = Vector3::new(1.0, -2.0, 2.0) / 3.0;
        let c = contact(Point3::new(0.2, 0.1, 0.0), Point3::new(0.4, -0.3, 0.4), n);
        let i = BodyMotion {
            pose_w: Isometry3::new(Vector3::new(0.1, 0.2, 0.3), Vector3::new(0.3, 0.0, 0.1)),
            velocity_w: Vector3::new(0.7, -0.1, 0.2),
            angular_velocity_w: Vector3::new(0.5, 0.4, -0.3),
        };
        let j = BodyMotion::at_rest(Isometry3::identity());
        let k = ContactKinematics::compute(&c, &i, &j);
        assert!(k.slip_velocity_w.dot(&n).abs() < 1e-14);
        let rebuilt = k.slip_velocity_w - n * k.penetration_rate;
        assert!((rebuilt - k.relative_velocity_w).norm() < 1e-14);
        assert_eq!(k.spin, Vector3::new(0.5, 0.4, -0.3).dot(&n));
    }
}
