//! What a failed static solve reports: where the imbalance sits and what causes it.

use super::newton::{imbalance, static_residual};
use crate::mbs::{MultibodySystem, PartId};
use nalgebra::DVector;

/// The diagnosis of a static solve that did not converge, at its last iterate.
#[derive(Debug, Clone, PartialEq)]
pub struct StaticsDiagnosis {
    /// The methods tried and why each stopped.
    pub cause: String,
    /// Newton iterations, all attempts.
    pub iterations: usize,
    /// The force imbalance at the last iterate (largest force row, torque rows over `L`).
    pub imbalance: f64,
    /// The part with the largest imbalance and whether it is a force or a torque row.
    pub dominant_part: Option<(String, &'static str)>,
    /// The force element with the largest load on that part (`CONTACT/1`, `SFORCE/3`, …).
    pub dominant_element: Option<String>,
    /// The constraint with the largest violation `|Φ|` and its value.
    pub worst_constraint: Option<(String, f64)>,
}

impl std::fmt::Display for StaticsDiagnosis {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}; {} Newton iterations; imbalance {:e}",
            self.cause, self.iterations, self.imbalance
        )?;
        if let Some((part, row)) = &self.dominant_part {
            write!(f, ", largest on {part} ({row})")?;
        }
        if let Some(element) = &self.dominant_element {
            write!(f, ", dominated by {element}")?;
        }
        if let Some((name, value)) = &self.worst_constraint {
            write!(f, "; worst constraint {name} (|Φ| = {value:e})")?;
        }
        write!(
            f,
            ". Remedies: make contacts active with small penetration at the start, smaller TLIMIT/ALIMIT with larger MAXIT, a larger STABILITY for neutral equilibria, EQUILIBRIUM/DYNAMIC"
        )
    }
}

impl StaticsDiagnosis {
    /// The diagnosis at the iterate `y` (velocities zero) at time `t`.
    pub fn at(
        system: &mut MultibodySystem,
        t: f64,
        y: &DVector<f64>,
        cause: String,
        iterations: usize,
    ) -> Self {
        let mut diagnosis = Self {
            cause,
            iterations,
            imbalance: f64::INFINITY,
            dominant_part: None,
            dominant_element: None,
            worst_constraint: None,
        };
        let Ok(r) = static_residual(system, t, y) else {
            return diagnosis;
        };
        diagnosis.imbalance = imbalance(system, &r);
        let n = system.layout().parts();
        let scaled = |i: usize| {
            if i % 6 < 3 {
                r[i].abs()
            } else {
                r[i].abs() / system.length_scale()
            }
        };
        if let Some(row) = (0..6 * n).max_by(|&a, &b| scaled(a).total_cmp(&scaled(b))) {
            let part = PartId(row / 6 + 1);
            let kind = if row % 6 < 3 { "force" } else { "torque" };
            diagnosis.dominant_part = system.part_name(part).map(|s| (s.to_owned(), kind));
            diagnosis.dominant_element = system.largest_load_on(t, y, part, row % 6 >= 3);
        }
        let worst = (6 * n..r.len()).max_by(|&a, &b| r[a].abs().total_cmp(&r[b].abs()));
        if let Some(row) = worst {
            let m_row = row - 6 * n;
            let name = system
                .constraint_rows()
                .filter(|(_, first)| *first <= m_row)
                .last()
                .map(|(name, _)| name.to_owned());
            diagnosis.worst_constraint = name.map(|name| (name, r[row].abs()));
        }
        diagnosis
    }
}

impl MultibodySystem {
    /// The force element with the largest force (or torque) on `part` at `y`, if any acts.
    fn largest_load_on(
        &self,
        t: f64,
        y: &DVector<f64>,
        part: PartId,
        torque: bool,
    ) -> Option<String> {
        let states = self.part_states(y).ok()?;
        let loads = self.element_loads(t, &states).ok()?;
        self.forces
            .iter()
            .zip(loads)
            .filter_map(|(element, loads)| {
                let size: f64 = element
                    .parts()
                    .iter()
                    .zip(&loads)
                    .filter(|(p, _)| **p == part)
                    .map(|(_, l)| {
                        if torque {
                            l.torque_w.norm()
                        } else {
                            l.force_w.norm()
                        }
                    })
                    .sum();
                (size > 0.0).then(|| (element.name().to_owned(), size))
            })
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(name, _)| name)
    }
}
