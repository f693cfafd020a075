//! Euler-parameter (unit quaternion) kinematics.
//!
//! A part's orientation is `e = (e₀, e₁, e₂, e₃)`, `e₀` the scalar part, stored raw in the state
//! vector (the integrator may move it slightly off the unit sphere; the normalization equation
//! `eᵀe − 1 = 0` brings it back). Rotations are always built from `ê = e/|e|`, so every
//! orientation-dependent quantity is invariant to the length of `e`.
//!
//! With ω′ the angular velocity in the body frame, `ė = ½ G(e)ᵀ ω′` where
//! `G(e) = [−ε, e₀I − ε̃]` (3×4, ε = (e₁, e₂, e₃)), equivalently `ė = ½ e ⊗ (0, ω′)`.
//! A small body-frame rotation δπ′ and a change δe of the raw parameters relate by
//! `δπ′ = 2 G(e) δe / |e|²` (exact for the normalized rotation, since `G(e) e = 0`).

use nalgebra::{Matrix3, Matrix3x4, Matrix4, Quaternion, UnitQuaternion, Vector3, Vector4};

/// `G(e)`, the 3×4 matrix with `ω′ = 2 G(e) ė` for unit `e`.
pub(crate) fn g_matrix(e: &Vector4<f64>) -> Matrix3x4<f64> {
    let (e0, e1, e2, e3) = (e[0], e[1], e[2], e[3]);
    Matrix3x4::new(
        -e1, e0, e3, -e2, //
        -e2, -e3, e0, e1, //
        -e3, e2, -e1, e0,
    )
}

/// `∂(G(e)ᵀ ω)/∂e`: `G(e)ᵀ ω = e ⊗ (0, ω)` is linear in `e`, with this matrix.
pub(crate) fn g_transpose_omega_partial(w: &Vector3<f64>) -> Matrix4<f64> {
    Matrix4::new(
        0.0, -w[0], -w[1], -w[2], //
        w[0], 0.0, w[2], -w[1], //
        w[1], -w[2], 0.0, w[0], //
        w[2], w[1], -w[0], 0.0,
    )
}

/// `∂π′/∂e = 2 G(e) / |e|²`: the body-frame rotation produced by a change of the raw parameters.
pub(crate) fn rotation_per_parameter(e: &Vector4<f64>) -> Matrix3x4<f64> {
    g_matrix(e) * (2.0 / e.norm_squared())
}

/// The normalized rotation of raw parameters `e`; `None` when `|e|` is zero or not finite
/// (the caller turns that into an error naming the part).
pub(crate) fn rotation_of(e: &Vector4<f64>) -> Option<UnitQuaternion<f64>> {
    let norm = e.norm();
    if !norm.is_finite() || norm <= f64::MIN_POSITIVE {
        return None;
    }
    Some(UnitQuaternion::new_unchecked(Quaternion::new(
        e[0] / norm,
        e[1] / norm,
        e[2] / norm,
        e[3] / norm,
    )))
}

/// The parameters `(e₀, e₁, e₂, e₃)` of a unit quaternion.
pub(crate) fn parameters_of(q: &UnitQuaternion<f64>) -> Vector4<f64> {
    Vector4::new(q.w, q.i, q.j, q.k)
}

/// The cross-product matrix: `skew(a) b = a × b`.
pub(crate) fn skew(a: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(
        0.0, -a[2], a[1], //
        a[2], 0.0, -a[0], //
        -a[1], a[0], 0.0,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn g_transpose_omega_is_the_quaternion_product() {
        let e = Vector4::new(0.3, -0.5, 0.7, 0.2);
        let w = Vector3::new(1.5, -0.25, 2.0);
        let product =
            Quaternion::new(e[0], e[1], e[2], e[3]) * Quaternion::new(0.0, w[0], w[1], w[2]);
        let expected = Vector4::new(product.w, product.i, product.j, product.k);
        assert!((g_matrix(&e).transpose() * w - expected).norm() < 1e-14);
        assert!((g_transpose_omega_partial(&w) * e - expected).norm() < 1e-14);
    }

    #[test]
    fn rotation_per_parameter_matches_a_small_rotation() {
        // Oracle: rotate by a tiny body-frame rotation and compare the parameter change.
        let q = UnitQuaternion::from_euler_angles(0.4, -1.1, 2.3);
        let e = parameters_of(&q) * 1.7; // off the unit sphere on purpose
        let dpi = Vector3::new(1e-7, -2e-7, 0.5e-7);
        let rotated = q * UnitQuaternion::from_scaled_axis(dpi);
        let de = parameters_of(&rotated) * 1.7 - e;
        let recovered = rotation_per_parameter(&e) * de;
        assert!((recovered - dpi).norm() < 1e-13, "{recovered} vs {dpi}");
    }
}
