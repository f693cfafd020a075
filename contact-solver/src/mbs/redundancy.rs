//! Redundant constraint equations: found at the initial configuration by a rank-revealing
//! factorization of the constraint Jacobian, removed from the equations, and checked for
//! consistency once the positions are assembled.
//!
//! Method: the velocity Jacobian `Φ_v` (m equations × 6n part velocities) is made
//! dimensionless — translation columns times the model's length scale `L`, length equations
//! divided by `L` — and its transpose factorized by column-pivoted QR,
//! `Φ_vᵀ·P = Q·R`. An equation is redundant when its pivot `|R_kk|` is at most
//! [`RANK_TOLERANCE`] times the first (largest) one: its gradient is, to that tolerance, a
//! combination of the gradients already taken. The combination, `R₁₁⁻¹·R₁₂`, names the
//! equations it depends on. Removing the equation changes neither the motion nor the
//! reactions when the redundancy is consistent (its value vanishes wherever the kept equations
//! do); when it is not (a second REVOLUTE whose axis is not the first one's), the kept
//! equations cannot hold it and [`MultibodySystem::check_redundant_equations`] refuses the
//! model, naming the elements.

use super::constraints::ConstraintElement;
use super::constraints::primitives::{Axis, Primitive};
use super::error::MbsError;
use super::layout::StateLayout;
use super::system::MultibodySystem;
use nalgebra::{DMatrix, DVector};

/// An equation whose pivot is at most this fraction of the largest is redundant: about
/// `sqrt(ε)`, far above the round-off of a Jacobian of O(1) entries and far below any pivot
/// of a mechanism away from a singular (toggle) position.
pub const RANK_TOLERANCE: f64 = 1e-8;

/// A removed equation's value at the assembled positions, relative (lengths over `L`), above
/// which the redundancy is inconsistent. The kept equations are assembled to `1e-10`; a
/// consistent redundant equation holds to that order too.
pub const CONSISTENCY_TOLERANCE: f64 = 1e-6;

/// One constraint equation removed as redundant, as Adams lists it.
#[derive(Debug, Clone, PartialEq)]
pub struct RedundantEquation {
    /// The element (`JOINT/3`, `JPRIM/2`, `MOTION/1`).
    pub element: String,
    /// The equation's index within its element (0-based, in the element's equation order).
    pub equation: usize,
    /// What the equation constrains, in Adams' words (`translation along X`,
    /// `rotation between Zi & Xj`).
    pub description: String,
    /// The elements whose kept equations make this one redundant (sorted, without
    /// duplicates; may include its own element).
    pub depends_on: Vec<String>,
}

impl std::fmt::Display for RedundantEquation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} equation {}: {} (implied by {})",
            self.element,
            self.equation + 1,
            self.description,
            self.depends_on.join(", ")
        )
    }
}

/// Adams' wording of what a primitive equation constrains.
pub(crate) fn describe(primitive: &Primitive) -> String {
    let axis = |a: &Axis| match a {
        Axis::X => "X",
        Axis::Y => "Y",
        Axis::Z => "Z",
    };
    match primitive {
        Primitive::Coincident(k) => format!("translation along {}", ["X", "Y", "Z"][*k]),
        Primitive::Perpendicular { axis_i, axis_j } => {
            format!("rotation between {}i & {}j", axis(axis_i), axis(axis_j))
        }
        Primitive::InPlane {
            normal_j,
            drive: None,
        } => format!("translation along {}j", axis(normal_j)),
        Primitive::InPlane {
            normal_j,
            drive: Some(_),
        } => format!("motion along {}j", axis(normal_j)),
        Primitive::Angle { .. } => "motion about Zj".to_string(),
        Primitive::Distance { .. } => "distance between I and J".to_string(),
        Primitive::RackPin { .. } => "rotation of I with the travel along Zj".to_string(),
    }
}

/// The equations of `constraints` (rows of `jacobian`, in order) that are redundant, with the
/// rows each depends on. `jacobian` is the dimensionless `Φ_v` (see the module docs).
fn redundant_rows(jacobian: &DMatrix<f64>) -> Vec<(usize, Vec<usize>)> {
    let m = jacobian.nrows();
    if m == 0 {
        return Vec::new();
    }
    let qr = jacobian.transpose().col_piv_qr();
    let r = qr.r();
    let mut order = DMatrix::from_fn(1, m, |_, j| j as f64);
    qr.p().permute_columns(&mut order);
    let order: Vec<usize> = order.iter().map(|&j| j as usize).collect();
    let pivots = r.nrows().min(m);
    let largest = (0..pivots).map(|k| r[(k, k)].abs()).fold(0.0, f64::max);
    let rank = (0..pivots)
        .take_while(|&k| r[(k, k)].abs() > RANK_TOLERANCE * largest)
        .count();
    let r11 = r.view((0, 0), (rank, rank)).into_owned();
    (rank..m)
        .map(|k| {
            let column: DVector<f64> = r.view((0, k), (rank, 1)).column(0).into_owned();
            let weights = r11.solve_upper_triangular(&column).unwrap_or(column);
            let biggest = weights.amax();
            let depends = (0..rank)
                .filter(|&i| weights[i].abs() > 1e-6 * biggest)
                .map(|i| order[i])
                .collect();
            (order[k], depends)
        })
        .collect()
}

impl MultibodySystem {
    /// The dimensionless velocity Jacobian at the builder's positions: translation columns
    /// times `L`, length equations over `L`.
    fn scaled_jacobian(&self) -> Result<DMatrix<f64>, MbsError> {
        let states = self.part_states(&self.initial_y)?;
        let mut jacobian = self.velocity_jacobian(&states);
        let l = self.length_scale;
        for part in 0..self.parts.len() {
            for i in 0..3 {
                jacobian.column_mut(6 * part + i).scale_mut(l);
            }
        }
        for element in &self.constraints {
            for (k, primitive) in element.primitives.iter().enumerate() {
                if primitive.is_length() {
                    jacobian.row_mut(element.row + k).scale_mut(1.0 / l);
                }
            }
        }
        Ok(jacobian)
    }

    /// Finds the redundant equations at the builder's positions and removes them from the
    /// system (the layout shrinks by one multiplier each); they are kept aside for
    /// [`Self::check_redundant_equations`] and listed by [`Self::redundant_equations`].
    pub(crate) fn remove_redundant_equations(&mut self) -> Result<(), MbsError> {
        if self.layout.constraint_rows() == 0 {
            return Ok(());
        }
        let jacobian = self.scaled_jacobian()?;
        let mut owner = Vec::with_capacity(jacobian.nrows());
        for (e, element) in self.constraints.iter().enumerate() {
            owner.extend((0..element.primitives.len()).map(|k| (e, k)));
        }
        let mut found = redundant_rows(&jacobian);
        if found.is_empty() {
            return Ok(());
        }
        found.sort_by_key(|(row, _)| *row);
        let mut removed: Vec<(RedundantEquation, ConstraintElement)> = Vec::new();
        for (row, depends) in &found {
            let (e, k) = owner[*row];
            let element = &self.constraints[e];
            let mut depends_on: Vec<String> = depends
                .iter()
                .map(|&d| self.constraints[owner[d].0].name.clone())
                .collect();
            depends_on.sort();
            depends_on.dedup();
            let mut alone = element.clone();
            alone.primitives = vec![element.primitives[k].clone()];
            alone.row = 0;
            removed.push((
                RedundantEquation {
                    element: element.name.clone(),
                    equation: k,
                    description: describe(&element.primitives[k]),
                    depends_on,
                },
                alone,
            ));
        }
        for (e, element) in self.constraints.iter_mut().enumerate() {
            let drop: Vec<usize> = found
                .iter()
                .filter(|(row, _)| owner[*row].0 == e)
                .map(|(row, _)| owner[*row].1)
                .collect();
            let mut k = 0;
            element.primitives.retain(|_| {
                k += 1;
                !drop.contains(&(k - 1))
            });
        }
        self.relayout();
        self.redundant = removed;
        Ok(())
    }

    /// Numbers the constraint rows again after equations were removed, and shrinks the layout
    /// and the initial state to match (the multipliers are zero until the initial conditions
    /// are computed; positions and velocities come first and keep their offsets).
    fn relayout(&mut self) {
        let mut rows = 0;
        for element in &mut self.constraints {
            element.row = rows;
            rows += element.primitives.len();
        }
        let layout = StateLayout::new(self.parts.len(), rows, self.layout.formulation());
        let kept = 13 * self.parts.len();
        let mut y = DVector::zeros(layout.size());
        y.rows_mut(0, kept).copy_from(&self.initial_y.rows(0, kept));
        self.initial_y = y;
        self.layout = layout;
    }

    /// The equations removed as redundant at the initial configuration, in row order (empty
    /// when the constraints are independent).
    pub fn redundant_equations(&self) -> impl Iterator<Item = &RedundantEquation> {
        self.redundant.iter().map(|(equation, _)| equation)
    }

    /// Checks at assembled positions `y` and time `t` that every removed equation still holds
    /// (relative value at most [`CONSISTENCY_TOLERANCE`], lengths over `L`); otherwise the
    /// redundancy is inconsistent and the error names the equations and the elements involved.
    pub fn check_redundant_equations(&self, t: f64, y: &DVector<f64>) -> Result<(), MbsError> {
        let states = self.part_states(y)?;
        let mut violated = Vec::new();
        for (equation, element) in &self.redundant {
            let frames = element.frames(
                &states[element.part_i.0].pose_w,
                &states[element.part_j.0].pose_w,
            );
            let primitive = &element.primitives[0];
            let scale = if primitive.is_length() {
                self.length_scale
            } else {
                1.0
            };
            let value = primitive.value(&frames, t) / scale;
            if value.is_nan() || value.abs() > CONSISTENCY_TOLERANCE {
                violated.push((equation.clone(), value));
            }
        }
        if violated.is_empty() {
            return Ok(());
        }
        let mut elements: Vec<String> = violated
            .iter()
            .flat_map(|(e, _)| std::iter::once(e.element.clone()).chain(e.depends_on.clone()))
            .collect();
        elements.sort();
        elements.dedup();
        Err(MbsError::InconsistentRedundancy {
            elements,
            equations: violated
                .iter()
                .map(|(e, value)| format!("{e}, value {value:.3e} (lengths over L)"))
                .collect(),
        })
    }
}
