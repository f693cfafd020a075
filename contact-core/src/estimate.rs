//! The small-part contact stiffness and damping estimate of the Adams CONTACT documentation.

use crate::Units;
use crate::error::{InvalidArgument, positive};

/// Suggested IMPACT STIFFNESS and DAMPING for a contact between small parts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SmallPartEstimate {
    /// The reduced mass `M* = M1·M2/(M1 + M2)` (`M1` alone against ground).
    pub reduced_mass: f64,
    /// STIFFNESS `K = 5·M*·g / (0.001·R)^e` (force / length^e).
    pub stiffness: f64,
    /// DAMPING `C = 2·sqrt(K·M*)`, with K taken as a linear stiffness (force / length) and M* in
    /// force·time²/length: critical damping of the contact at its design load.
    pub damping: f64,
}

/// Estimates STIFFNESS and DAMPING so the contact carries 5 g of the reduced mass's weight at a
/// penetration of 0.1 % of the radius (SPEC §10; Adams CONTACT "parts with small mass").
///
/// - `mass_i`, `mass_j`: part masses in model units (`None` for ground: `M* = mass_i`).
/// - `radius`: a characteristic radius of the contact in model length.
/// - `exponent`: the IMPACT exponent e.
/// - `gravity`: the magnitude of gravity in model acceleration units.
///
/// Example (Adams doc): 4e-6 kg against ground, R = 1 mm, e = 2.2, N-mm-s-kg:
/// K ≈ 781 N/mm^2.2 and C ≈ 3.5e-3 N·s/mm.
pub fn estimate_small_part(
    mass_i: f64,
    mass_j: Option<f64>,
    radius: f64,
    exponent: f64,
    gravity: f64,
    units: &Units,
) -> Result<SmallPartEstimate, InvalidArgument> {
    let m1 = positive("MASS (I part)", mass_i)?;
    let reduced_mass = match mass_j {
        Some(m2) => {
            let m2 = positive("MASS (J part)", m2)?;
            m1 * m2 / (m1 + m2)
        }
        None => m1,
    };
    let radius = positive("radius", radius)?;
    let exponent = positive("EXPONENT", exponent)?;
    let gravity = positive("gravity", gravity)?;
    let to_force = units.force_per_mass_acceleration();
    let weight = reduced_mass * gravity * to_force;
    let stiffness = 5.0 * weight / (0.001 * radius).powf(exponent);
    let damping = 2.0 * (stiffness * reduced_mass * to_force).sqrt();
    Ok(SmallPartEstimate {
        reduced_mass,
        stiffness,
        damping,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_the_adams_small_part_example() {
        let e = estimate_small_part(4e-6, None, 1.0, 2.2, 9810.0, &Units::MMKS).unwrap();
        assert!((e.stiffness - 781.1).abs() < 0.1, "{}", e.stiffness);
        assert!((e.damping - 3.535e-3).abs() < 1e-5, "{}", e.damping);
    }

    #[test]
    fn reduced_mass_of_two_equal_parts_is_half() {
        let e = estimate_small_part(2.0, Some(2.0), 30.0, 2.2, 9.81, &Units::MKS).unwrap();
        assert_eq!(e.reduced_mass, 1.0);
    }

    #[test]
    fn bad_arguments_are_named() {
        let err = estimate_small_part(1.0, None, 0.0, 2.2, 9.81, &Units::MKS).unwrap_err();
        assert_eq!(err.argument, "radius");
    }
}
