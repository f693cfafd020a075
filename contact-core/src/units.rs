//! Model units: every number stays in the model's own units; these helpers convert defaults and
//! rescale stiffness when lengths change.

use crate::error::{InvalidArgument, positive};

/// The size of one model unit of force, mass, length and time, each in SI (N, kg, m, s).
///
/// Adams' named systems: [`Units::MKS`], [`Units::MMKS`] (the Adams View default N-mm-s with kg),
/// [`Units::CGS`], [`Units::IPS`], [`Units::FPS`]. Units need not be consistent (pound-force
/// with pound-mass): [`Units::consistency_factor`] is what Adams calls the UCF.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Units {
    /// One model force unit in newtons.
    pub force_newton: f64,
    /// One model mass unit in kilograms.
    pub mass_kg: f64,
    /// One model length unit in metres.
    pub length_metre: f64,
    /// One model time unit in seconds.
    pub time_second: f64,
}

/// Physical dimension exponents of a quantity: force^f · mass^m · length^l · time^t.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dimension {
    /// Exponent of force.
    pub force: f64,
    /// Exponent of mass.
    pub mass: f64,
    /// Exponent of length.
    pub length: f64,
    /// Exponent of time.
    pub time: f64,
}

impl Dimension {
    /// A dimensionless quantity.
    pub const NONE: Self = Self {
        force: 0.0,
        mass: 0.0,
        length: 0.0,
        time: 0.0,
    };
    /// Length.
    pub const LENGTH: Self = Self {
        force: 0.0,
        mass: 0.0,
        length: 1.0,
        time: 0.0,
    };
    /// Velocity.
    pub const VELOCITY: Self = Self {
        force: 0.0,
        mass: 0.0,
        length: 1.0,
        time: -1.0,
    };
    /// Acceleration.
    pub const ACCELERATION: Self = Self {
        force: 0.0,
        mass: 0.0,
        length: 1.0,
        time: -2.0,
    };
    /// Damping: force · time / length.
    pub const DAMPING: Self = Self {
        force: 1.0,
        mass: 0.0,
        length: -1.0,
        time: 1.0,
    };

    /// Contact stiffness for exponent `e`: force / length^e.
    pub fn stiffness(exponent: f64) -> Self {
        Self {
            force: 1.0,
            mass: 0.0,
            length: -exponent,
            time: 0.0,
        }
    }
}

impl Units {
    /// Newton, kilogram, metre, second.
    pub const MKS: Self = Self {
        force_newton: 1.0,
        mass_kg: 1.0,
        length_metre: 1.0,
        time_second: 1.0,
    };
    /// Newton, kilogram, millimetre, second (Adams View's default).
    pub const MMKS: Self = Self {
        force_newton: 1.0,
        mass_kg: 1.0,
        length_metre: 1e-3,
        time_second: 1.0,
    };
    /// Dyne, gram, centimetre, second.
    pub const CGS: Self = Self {
        force_newton: 1e-5,
        mass_kg: 1e-3,
        length_metre: 1e-2,
        time_second: 1.0,
    };
    /// Pound-force, pound-mass, inch, second.
    pub const IPS: Self = Self {
        force_newton: 4.448_221_615_260_5,
        mass_kg: 0.453_592_37,
        length_metre: 0.0254,
        time_second: 1.0,
    };
    /// Pound-force, pound-mass, foot, second.
    pub const FPS: Self = Self {
        force_newton: 4.448_221_615_260_5,
        mass_kg: 0.453_592_37,
        length_metre: 0.3048,
        time_second: 1.0,
    };

    /// Units with the given SI sizes (each finite and > 0).
    pub fn new(
        force_newton: f64,
        mass_kg: f64,
        length_metre: f64,
        time_second: f64,
    ) -> Result<Self, InvalidArgument> {
        Ok(Self {
            force_newton: positive("FORCE unit", force_newton)?,
            mass_kg: positive("MASS unit", mass_kg)?,
            length_metre: positive("LENGTH unit", length_metre)?,
            time_second: positive("TIME unit", time_second)?,
        })
    }

    /// One model `mass·length/time²` expressed in model force units: multiply `m·a` by this to
    /// get a force. 1 for consistent units (MKS, CGS), 1e-3 for MMKS (kg·mm/s² = 1e-3 N).
    pub fn force_per_mass_acceleration(&self) -> f64 {
        self.mass_kg * self.length_metre / (self.time_second * self.time_second) / self.force_newton
    }

    /// Adams' UCF: `1 / force_per_mass_acceleration()`.
    pub fn consistency_factor(&self) -> f64 {
        1.0 / self.force_per_mass_acceleration()
    }

    /// The SI size of one model unit of `dimension`.
    pub fn si_size(&self, dimension: Dimension) -> f64 {
        self.force_newton.powf(dimension.force)
            * self.mass_kg.powf(dimension.mass)
            * self.length_metre.powf(dimension.length)
            * self.time_second.powf(dimension.time)
    }

    /// Converts `value` of `dimension` from units `from` into these units.
    pub fn convert_from(&self, value: f64, dimension: Dimension, from: &Units) -> f64 {
        value * from.si_size(dimension) / self.si_size(dimension)
    }
}

/// Rescales a contact stiffness (force / length^e) when the length unit changes: `k × f^e`,
/// where `f` is how many old length units make one new unit. Example (Adams): 3800 N/mm^2
/// becomes 3800 × 1000² = 3.8e9 N/m^2 (f = 1000 mm per m, e = 2).
pub fn scale_stiffness(stiffness: f64, old_units_per_new_unit: f64, exponent: f64) -> f64 {
    stiffness * old_units_per_new_unit.powf(exponent)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stiffness_scales_as_length_to_the_exponent() {
        assert_eq!(scale_stiffness(3800.0, 1000.0, 2.0), 3.8e9);
        let k_m = Units::MKS.convert_from(3800.0, Dimension::stiffness(2.0), &Units::MMKS);
        assert!((k_m - 3.8e9).abs() < 1e-6 * 3.8e9);
    }

    #[test]
    fn consistency_factors_of_the_named_systems() {
        assert_eq!(Units::MKS.consistency_factor(), 1.0);
        assert!((Units::MMKS.consistency_factor() - 1000.0).abs() < 1e-9);
        assert!((Units::CGS.consistency_factor() - 1.0).abs() < 1e-12);
        // lbf with lbm and inches: the classic 386.088 (g in in/s²).
        assert!((Units::IPS.consistency_factor() - 386.088_582_677).abs() < 1e-6);
    }

    #[test]
    fn default_velocities_convert_between_systems() {
        let v = Units::MKS.convert_from(100.0, Dimension::VELOCITY, &Units::MMKS);
        assert!((v - 0.1).abs() < 1e-15);
    }
}
