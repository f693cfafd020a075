//! The four basic constraint equations every joint, JPRIM and MOTION is made of.
//!
//! Each equation relates marker I (on part `a`) to marker J (on part `b`). With `s_I`, `s_J` the
//! marker origins relative to their parts' CMs (world frame), `d = p_I − p_J`, and `x_I … z_J`
//! the marker axes in the world frame:
//!
//! | primitive | Φ | ∂Φ/∂r_a | ∂Φ/∂θ_a | ∂Φ/∂r_b | ∂Φ/∂θ_b |
//! | --- | --- | --- | --- | --- | --- |
//! | `Coincident(k)` | `d_k` (world axis k) | `e_k` | `s_I × e_k` | `−e_k` | `−s_J × e_k` |
//! | `Perpendicular(a_I, a_J)` | `a_I · a_J` | 0 | `a_I × a_J` | 0 | `a_J × a_I` |
//! | `InPlane(a_J)` | `a_J · d − f(t)` | `a_J` | `s_I × a_J` | `−a_J` | `a_J × (d + s_J)` |
//! | `Angle` | `wrap(atan2(x_I·y_J, x_I·x_J) − f(t))` | 0 | `(c ∇s − s ∇c)/(c² + s²)` | 0 | same |
//!
//! θ is a small rotation in the world frame (`δa = θ × a` for a vector fixed in the part); the
//! system turns it into the body frame (`θ = A π′`). `Angle` measures the rotation of x_I about
//! z_J from x_J, assuming z_I ∥ z_J (the joint keeps them so); `wrap` maps to (−π, π], so the
//! drive may run through any number of turns. `f(t)` is a MOTION's time function (0 otherwise).

use crate::mbs::motion::TimeFunction;
use nalgebra::Vector3;
use std::f64::consts::{PI, TAU};

/// A marker axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Axis {
    X = 0,
    Y = 1,
    Z = 2,
}

/// One scalar constraint equation (see the module table).
#[derive(Clone)]
pub(crate) enum Primitive {
    /// The marker origins agree along world axis `k`.
    Coincident(usize),
    /// Axis `axis_i` of marker I is perpendicular to axis `axis_j` of marker J.
    Perpendicular { axis_i: Axis, axis_j: Axis },
    /// The I origin lies in the plane through the J origin normal to J's `normal_j` axis, offset
    /// by the drive when there is one (a translational MOTION).
    InPlane {
        normal_j: Axis,
        drive: Option<TimeFunction>,
    },
    /// The rotation of x_I about z_J equals the drive (a rotational MOTION).
    Angle { drive: TimeFunction },
    /// `|d| − length`: the I origin at `length` (> 0) from the J origin (GCON `DM(i, j) − L`).
    Distance { length: f64 },
    /// RACKPIN, pitch radius `radius` (> 0): `r·wrap(θ − s/r)`, where θ is the rotation of
    /// I (the pinion) about z_I measured from z_J to x_I, `atan2(x_I·(z_I × z_J), x_I·z_J)`,
    /// and `s = (p_J − p_I)·z_J` the rack's travel along its z axis. Zero when x_I points along
    /// z_J with the origins level along z_J; θ = s/r after that. The wrapped difference keeps
    /// the equation smooth through any number of turns.
    RackPin { radius: f64 },
}

impl std::fmt::Debug for Primitive {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Coincident(k) => write!(f, "Coincident({k})"),
            Self::Perpendicular { axis_i, axis_j } => {
                write!(f, "Perpendicular({axis_i:?}_I, {axis_j:?}_J)")
            }
            Self::InPlane { normal_j, drive } => {
                write!(f, "InPlane({normal_j:?}_J, driven: {})", drive.is_some())
            }
            Self::Angle { .. } => write!(f, "Angle(driven)"),
            Self::Distance { length } => write!(f, "Distance({length:?})"),
            Self::RackPin { radius } => write!(f, "RackPin({radius:?})"),
        }
    }
}

/// Marker geometry of one constraint element at one configuration, world frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ElementFrames {
    /// I origin minus part a's CM.
    pub s_i: Vector3<f64>,
    /// J origin minus part b's CM.
    pub s_j: Vector3<f64>,
    /// `p_I − p_J`.
    pub d: Vector3<f64>,
    /// x, y, z axes of marker I.
    pub axes_i: [Vector3<f64>; 3],
    /// x, y, z axes of marker J.
    pub axes_j: [Vector3<f64>; 3],
}

/// A gradient in world virtual displacements: `[∂/∂r_a, ∂/∂θ_a, ∂/∂r_b, ∂/∂θ_b]`.
pub(crate) type WorldGradient = [Vector3<f64>; 4];

/// Maps an angle to (−π, π].
fn wrap_angle(angle: f64) -> f64 {
    let wrapped = (angle + PI).rem_euclid(TAU) - PI;
    if wrapped <= -PI {
        wrapped + TAU
    } else {
        wrapped
    }
}

impl Primitive {
    /// `Φ` at the frames and time.
    pub fn value(&self, frames: &ElementFrames, t: f64) -> f64 {
        match self {
            Self::Coincident(k) => frames.d[*k],
            Self::Perpendicular { axis_i, axis_j } => {
                frames.axes_i[*axis_i as usize].dot(&frames.axes_j[*axis_j as usize])
            }
            Self::InPlane { normal_j, drive } => {
                let offset = drive.as_ref().map_or(0.0, |f| f(t).0);
                frames.axes_j[*normal_j as usize].dot(&frames.d) - offset
            }
            Self::Angle { drive } => {
                let [x_i, _, _] = frames.axes_i;
                let [x_j, y_j, _] = frames.axes_j;
                wrap_angle(x_i.dot(&y_j).atan2(x_i.dot(&x_j)) - drive(t).0)
            }
            Self::Distance { length } => frames.d.norm() - length,
            Self::RackPin { radius } => {
                let (x, a, u) = (frames.axes_i[0], frames.axes_i[2], frames.axes_j[2]);
                let theta = x.dot(&a.cross(&u)).atan2(x.dot(&u));
                let travel = -frames.d.dot(&u);
                radius * wrap_angle(theta - travel / radius)
            }
        }
    }

    /// `∂Φ/∂(r_a, θ_a, r_b, θ_b)`, world frame.
    pub fn gradient(&self, frames: &ElementFrames) -> WorldGradient {
        let zero = Vector3::zeros();
        match self {
            Self::Coincident(k) => {
                let e_k = Vector3::ith(*k, 1.0);
                [e_k, frames.s_i.cross(&e_k), -e_k, -frames.s_j.cross(&e_k)]
            }
            Self::Perpendicular { axis_i, axis_j } => {
                let a_i = frames.axes_i[*axis_i as usize];
                let a_j = frames.axes_j[*axis_j as usize];
                [zero, a_i.cross(&a_j), zero, a_j.cross(&a_i)]
            }
            Self::InPlane { normal_j, .. } => {
                let a_j = frames.axes_j[*normal_j as usize];
                [
                    a_j,
                    frames.s_i.cross(&a_j),
                    -a_j,
                    a_j.cross(&(frames.d + frames.s_j)),
                ]
            }
            Self::Angle { .. } => {
                let [x_i, _, _] = frames.axes_i;
                let [x_j, y_j, _] = frames.axes_j;
                let (s, c) = (x_i.dot(&y_j), x_i.dot(&x_j));
                let scale = 1.0 / (c * c + s * s);
                let theta_a = (x_i.cross(&y_j) * c - x_i.cross(&x_j) * s) * scale;
                let theta_b = (y_j.cross(&x_i) * c - x_j.cross(&x_i) * s) * scale;
                [zero, theta_a, zero, theta_b]
            }
            Self::Distance { .. } => {
                // ∂|d|/∂d = d/|d|; at |d| = 0 the direction is undefined and the row is zero
                // (the builder refuses markers that start coincident).
                let norm = frames.d.norm();
                let n = if norm > 0.0 { frames.d / norm } else { zero };
                [n, frames.s_i.cross(&n), -n, -frames.s_j.cross(&n)]
            }
            Self::RackPin { radius } => {
                // θ = atan2(S, C), S = x·(a × u), C = x·u (x, a = x_I, z_I; u = z_J):
                // ∂S/∂θ_I = x × w + a × (u × x), ∂S/∂θ_J = u × (x × a) with w = a × u;
                // ∂C/∂θ_I = x × u, ∂C/∂θ_J = u × x. The travel s = −d·u has the InPlane
                // gradient with the sign turned.
                let (x, a, u) = (frames.axes_i[0], frames.axes_i[2], frames.axes_j[2]);
                let w = a.cross(&u);
                let (s, c) = (x.dot(&w), x.dot(&u));
                let scale = radius / (s * s + c * c);
                let ds_a = x.cross(&w) + a.cross(&u.cross(&x));
                let ds_b = u.cross(&x.cross(&a));
                let (dc_a, dc_b) = (x.cross(&u), u.cross(&x));
                let theta_a = (ds_a * c - dc_a * s) * scale;
                let theta_b = (ds_b * c - dc_b * s) * scale;
                [
                    u,
                    theta_a + frames.s_i.cross(&u),
                    -u,
                    theta_b + u.cross(&(frames.d + frames.s_j)),
                ]
            }
        }
    }

    /// `∂Φ/∂t` and `∂²Φ/∂t²` (nonzero only for driven primitives).
    pub fn time_derivatives(&self, t: f64) -> (f64, f64) {
        let drive = match self {
            Self::InPlane { drive: Some(f), .. } | Self::Angle { drive: f } => f,
            _ => return (0.0, 0.0),
        };
        let (_, rate, acceleration) = drive(t);
        (-rate, -acceleration)
    }

    /// Whether Φ is a length (`true`) or an angle or cosine (`false`): sets its tolerance.
    pub fn is_length(&self) -> bool {
        matches!(
            self,
            Self::Coincident(_)
                | Self::InPlane { .. }
                | Self::Distance { .. }
                | Self::RackPin { .. }
        )
    }
}

#[cfg(test)]
mod tests {
    use super::wrap_angle;
    use std::f64::consts::PI;

    #[test]
    fn wrap_angle_maps_into_half_open_interval() {
        assert_eq!(wrap_angle(PI), PI);
        assert!((wrap_angle(-PI) - PI).abs() < 1e-15);
        assert!((wrap_angle(3.0 * PI + 0.25) - (-PI + 0.25)).abs() < 1e-12);
        assert!((wrap_angle(-0.5) + 0.5).abs() < 1e-15);
    }
}
