//! The Newton matrix stored and factorised sparse: for models of many parts, where the dense
//! LU's `⅔n³` operations and `n²` storage dominate the run (a 512-part model has `n = 7168`:
//! 400 MB and `2.5·10¹¹` operations per factorisation), while its nonzeros grow like `n`.
//!
//! The system writes its entries as triplets ([`DaeSystem::newton_entries`]); they are sorted
//! into compressed columns, duplicates summed in the order written; then the same scaling as
//! the dense path (`super::newton_matrix`: column `j` of an algebraic variable of index `i`
//! times `h^(1−i)`, every row divided by its largest entry, the same checks for a zero or
//! non-finite row) and rsparse's LU, a port of CSparse (Davis 2006): an approximate minimum
//! degree ordering of `A + Aᵀ`, then a left-looking LU with partial pivoting. A matrix whose
//! graph falls apart into islands (parts sharing no joint and no contact) is factorised
//! island by island instead (`super::islands`): small ones dense, large ones by this LU on
//! their own block.
//!
//! The ordering is a column permutation, valid for any pattern; only its fill depends on the
//! pattern it was computed for. It is kept when the pattern changes (a contact the broad phase
//! lets in or out adds or drops a few blocks) and computed afresh when the fill it gives,
//! per entry of the matrix, has grown past [`FILL_GROWTH`] times the fill per entry it gave
//! when it was computed. The first factorisation's storage is CSparse's guess (`4·nnz + n`);
//! later ones start from the last fill plus `n`, so nothing is cleared that is never used.

use super::error::FailureCause;
use super::islands::{ISLAND_MAX, IslandFactors, Islands, KeptOrdering};
use super::newton_matrix::column_scale;
use crate::parallel::Parallelism;
use crate::{DaeSystem, VariableKind};
use nalgebra::DVector;
use rsparse::data::{Nmrc, Sprs, Symb};

/// Partial pivoting: the largest entry of the column is the pivot unless the diagonal is as
/// large (CSparse's `tol = 1`).
pub(super) const PIVOT_TOLERANCE: f64 = 1.0;

/// How far the fill per matrix entry (`nnz(L) + nnz(U)` over `nnz(A)`) may grow past the fill
/// per entry at the ordering's own pattern before the ordering is computed again.
pub(super) const FILL_GROWTH: f64 = 1.5;

/// A factorised, scaled sparse Newton matrix.
#[derive(Default)]
pub(super) struct SparseNewton {
    /// The triplets of the last assembly (kept to reuse the allocation).
    entries: Vec<(usize, usize, f64)>,
    /// Where each triplet of the last assembly went in the compressed values, and the
    /// places it was written to, in order: an assembly writing the same places in the same
    /// order (the usual case) is compressed without sorting.
    slots: Vec<usize>,
    places: Vec<(usize, usize)>,
    /// The scaled matrix in compressed columns.
    matrix: Option<Sprs<f64>>,
    /// The fill-reducing ordering (with the storage guesses for the next factorisation).
    symbolic: Option<Symb>,
    /// The fill per entry, `(nnz(L) + nnz(U)) / nnz(A)`, at the ordering's own pattern.
    ordering_fill: f64,
    /// Whether the next factorisation orders afresh (the fill grew past [`FILL_GROWTH`]).
    reorder: bool,
    lu: Option<Nmrc<f64>>,
    /// The islands of the current pattern (`None`: one is too large, or not yet known) and
    /// whether they were found for the current pattern.
    islands: Option<Islands>,
    islands_known: bool,
    /// Never split into islands (the general sparse LU alone; its own tests).
    general_only: bool,
    /// Each island's factors, when the islands path factorised the matrix.
    island_lus: Option<Vec<IslandFactors>>,
    /// The large islands' orderings, kept while their unknowns stay the same.
    island_orderings: Vec<KeptOrdering>,
    row_scale: Vec<f64>,
    col_scale: Vec<f64>,
}

impl SparseNewton {
    /// Whether a factorisation exists.
    pub fn is_factorised(&self) -> bool {
        self.lu.is_some() || self.island_lus.is_some()
    }

    /// Drops the factorisation (the ordering stays).
    pub fn invalidate(&mut self) {
        self.lu = None;
        self.island_lus = None;
    }

    /// Evaluates, scales and factorises the matrix at `(t, y, y′)` with coefficient `cj` and
    /// step size `h` (see the module docs).
    #[expect(
        clippy::too_many_arguments,
        reason = "the point, c, h and the classes are all needed"
    )]
    pub fn refresh(
        &mut self,
        system: &mut dyn DaeSystem,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        cj: f64,
        h: f64,
        kinds: &[VariableKind],
    ) -> Result<(), FailureCause> {
        self.invalidate();
        let n = y.len();
        self.entries.clear();
        system
            .newton_entries(t, y, yp, cj, &mut self.entries)
            .map_err(FailureCause::Evaluation)?;
        let same_places = self.places.len() == self.entries.len()
            && self
                .places
                .iter()
                .zip(&self.entries)
                .all(|(p, e)| *p == (e.0, e.1));
        let (mut matrix, pattern_changed) = match self.matrix.take() {
            Some(mut matrix) if same_places && matrix.n == n => {
                matrix.x.fill(0.0);
                for (&slot, e) in self.slots.iter().zip(&self.entries) {
                    matrix.x[slot] += e.2;
                }
                (matrix, false)
            }
            old => {
                self.places.clear();
                self.places.extend(self.entries.iter().map(|e| (e.0, e.1)));
                let matrix = compress(&self.entries, n, &mut self.slots);
                let changed = old.is_none_or(|old| old.p != matrix.p || old.i != matrix.i);
                (matrix, changed)
            }
        };
        self.col_scale.clear();
        self.col_scale
            .extend(kinds.iter().map(|&kind| column_scale(kind, h)));
        for (j, &s) in self.col_scale.iter().enumerate() {
            if s != 1.0 {
                let range = column(&matrix, j);
                for v in &mut matrix.x[range] {
                    *v *= s;
                }
            }
        }
        self.row_scale = scale_rows(&mut matrix)?;
        self.factorise(matrix, pattern_changed, &system.parallelism())
    }

    /// Factorises the scaled `matrix`, ordering it afresh if there is no ordering yet or the
    /// last factorisation found the ordering's fill grown too far (see the module docs).
    fn factorise(
        &mut self,
        matrix: Sprs<f64>,
        pattern_changed: bool,
        parallelism: &Parallelism,
    ) -> Result<(), FailureCause> {
        if pattern_changed || !self.islands_known {
            // A matrix that is one large island takes the general sparse LU below.
            self.islands = Some(Islands::of(&matrix)).filter(|islands| {
                !self.general_only && (islands.count() > 1 || islands.largest() <= ISLAND_MAX)
            });
            self.islands_known = true;
        }
        if let Some(islands) = &self.islands {
            let lus = islands
                .factorise(&matrix, parallelism, &mut self.island_orderings)
                .ok_or(FailureCause::SingularMatrix)?;
            self.island_lus = Some(lus);
            self.matrix = Some(matrix);
            return Ok(());
        }
        let n = matrix.n;
        let fresh_ordering = self.reorder
            || self
                .symbolic
                .as_ref()
                .is_none_or(|s| s.q.as_ref().is_none_or(|q| q.len() < n));
        if fresh_ordering {
            // Order 1: minimum degree on A + Aᵀ, for LU.
            self.symbolic = Some(rsparse::sqr(&matrix, 1, false));
            self.reorder = false;
        }
        let Some(symbolic) = self.symbolic.as_mut() else {
            return Err(FailureCause::SingularMatrix);
        };
        let (lnz, unz) = (symbolic.lnz, symbolic.unz);
        let lu = rsparse::lu(&matrix, symbolic, PIVOT_TOLERANCE);
        // `lu` leaves the fill it found in `lnz`/`unz`; the next one starts from it.
        (symbolic.lnz, symbolic.unz) = match &lu {
            Ok(lu) => (lu.l.x.len() + n, lu.u.x.len() + n),
            Err(_) => (lnz, unz),
        };
        let lu = lu.map_err(|_| FailureCause::SingularMatrix)?;
        let fill = (lu.l.x.len() + lu.u.x.len()) as f64 / matrix.x.len().max(1) as f64;
        if fresh_ordering {
            self.ordering_fill = fill;
        } else if pattern_changed && fill > FILL_GROWTH * self.ordering_fill {
            self.reorder = true;
        }
        self.matrix = Some(matrix);
        self.lu = Some(lu);
        Ok(())
    }

    /// Solves `J·Δ = r` in place with the stored factorisation; false if there is none or the
    /// answer is not finite.
    pub fn solve(&self, r: &mut DVector<f64>) -> bool {
        if let (Some(islands), Some(lus)) = (&self.islands, &self.island_lus) {
            // x = R·r; each island's block solved; Δ = C·x.
            for (v, s) in r.iter_mut().zip(&self.row_scale) {
                *v *= s;
            }
            if !islands.solve(lus, r.as_mut_slice()) {
                return false;
            }
            for (v, s) in r.iter_mut().zip(&self.col_scale) {
                *v *= s;
            }
            return r.iter().all(|v| v.is_finite());
        }
        let (Some(lu), Some(symbolic)) = (&self.lu, &self.symbolic) else {
            return false;
        };
        let (Some(pinv), n) = (&lu.pinv, r.len()) else {
            return false;
        };
        // x = P·(R·r); L·U·z = x; Δ = C·(Q·z).
        let mut x = vec![0.0; n];
        for (k, (v, s)) in r.iter().zip(&self.row_scale).enumerate() {
            x[pinv[k] as usize] = v * s;
        }
        rsparse::lsolve(&lu.l, &mut x);
        rsparse::usolve(&lu.u, &mut x);
        match &symbolic.q {
            Some(q) => {
                for (k, v) in x.iter().enumerate() {
                    r[q[k] as usize] = *v;
                }
            }
            None => r.as_mut_slice().copy_from_slice(&x),
        }
        for (v, s) in r.iter_mut().zip(&self.col_scale) {
            *v *= s;
        }
        r.iter().all(|v| v.is_finite())
    }
}

/// The entries of column `j`.
fn column(matrix: &Sprs<f64>, j: usize) -> std::ops::Range<usize> {
    matrix.p[j] as usize..matrix.p[j + 1] as usize
}

/// Sorts the triplets into compressed columns (`n × n`), summing duplicates in the order they
/// were written (the sort is stable); `slots` receives where each triplet went.
fn compress(entries: &[(usize, usize, f64)], n: usize, slots: &mut Vec<usize>) -> Sprs<f64> {
    // A counting sort by column (stable), then each column's few entries by row (stable).
    let mut starts = vec![0usize; n + 1];
    for &(_, col, _) in entries {
        starts[col + 1] += 1;
    }
    for j in 0..n {
        starts[j + 1] += starts[j];
    }
    let mut order = vec![0u32; entries.len()];
    let mut next = starts.clone();
    for (k, &(_, col, _)) in entries.iter().enumerate() {
        order[next[col]] = k as u32;
        next[col] += 1;
    }
    for j in 0..n {
        order[starts[j]..starts[j + 1]].sort_by_key(|&k| entries[k as usize].0);
    }
    slots.clear();
    slots.resize(entries.len(), 0);
    let mut matrix = Sprs::<f64>::new();
    matrix.m = n;
    matrix.n = n;
    matrix.p.reserve(n + 1);
    matrix.p.push(0);
    let mut col = 0;
    for &k in &order {
        let (row, c, v) = entries[k as usize];
        while col < c {
            matrix.p.push(matrix.i.len() as isize);
            col += 1;
        }
        let start = matrix.p[col] as usize;
        if matrix.i.len() > start && matrix.i.last() == Some(&row) {
            if let Some(last) = matrix.x.last_mut() {
                *last += v;
            }
        } else {
            matrix.i.push(row);
            matrix.x.push(v);
        }
        slots[k as usize] = matrix.i.len() - 1;
    }
    while col < n {
        matrix.p.push(matrix.i.len() as isize);
        col += 1;
    }
    matrix.nzmax = matrix.i.len();
    matrix
}

/// Divides every row by its largest entry and returns the factors `1/max` (as the dense path:
/// a zero row is singular; a row whose largest entry is not finite names its first non-finite
/// column).
fn scale_rows(matrix: &mut Sprs<f64>) -> Result<Vec<f64>, FailureCause> {
    let n = matrix.m;
    let mut row_max = vec![0.0_f64; n];
    for (&row, v) in matrix.i.iter().zip(&matrix.x) {
        row_max[row] = row_max[row].max(v.abs());
    }
    for (i, &m) in row_max.iter().enumerate() {
        if !m.is_finite() {
            let index = (0..matrix.n)
                .find(|&j| column(matrix, j).any(|k| matrix.i[k] == i && !matrix.x[k].is_finite()))
                .unwrap_or(i);
            return Err(FailureCause::NonFinite { index });
        }
        if m == 0.0 {
            return Err(FailureCause::SingularMatrix);
        }
    }
    let scale: Vec<f64> = row_max.iter().map(|m| 1.0 / m).collect();
    for (&row, v) in matrix.i.iter().zip(&mut matrix.x) {
        *v *= scale[row];
    }
    Ok(scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;

    /// A sparse, unsymmetric matrix that needs pivoting (zero diagonal entries).
    fn sample(n: usize) -> DMatrix<f64> {
        DMatrix::from_fn(n, n, |i, j| {
            let d = i.abs_diff(j);
            match d {
                0 if i % 3 == 0 => 0.0,
                0 => 4.0 + i as f64,
                1 => 1.0 + 0.1 * (i + 2 * j) as f64,
                5 => -2.0 + 0.01 * i as f64,
                _ => 0.0,
            }
        })
    }

    #[test]
    fn duplicates_are_summed_and_the_lu_solves_as_the_dense_lu() {
        let n = 40;
        let dense = sample(n);
        // Every nonzero written as two halves, in scrambled order.
        let mut entries = Vec::new();
        for j in (0..n).rev() {
            for i in 0..n {
                if dense[(i, j)] != 0.0 {
                    entries.push((i, j, 0.25 * dense[(i, j)]));
                    entries.push((i, j, 0.75 * dense[(i, j)]));
                }
            }
        }
        let mut matrix = compress(&entries, n, &mut Vec::new());
        assert_eq!(matrix.x.len(), dense.iter().filter(|v| **v != 0.0).count());
        let scale = scale_rows(&mut matrix).unwrap();
        let mut symbolic = rsparse::sqr(&matrix, 1, false);
        let lu = rsparse::lu(&matrix, &mut symbolic, PIVOT_TOLERANCE).unwrap();
        let newton = SparseNewton {
            symbolic: Some(symbolic),
            lu: Some(lu),
            row_scale: scale,
            col_scale: vec![1.0; n],
            ..SparseNewton::default()
        };
        let b = DVector::from_fn(n, |i, _| (i as f64 * 0.7).sin());
        let mut x = b.clone();
        assert!(newton.solve(&mut x));
        // The oracle: nalgebra's dense LU of the unscaled matrix.
        let expected = dense.clone().lu().solve(&b).unwrap();
        assert!((&x - &expected).norm() <= 1e-12 * expected.norm());
        assert!((&dense * &x - &b).norm() <= 1e-12 * b.norm());
    }

    /// The triplets of `dense`'s nonzeros, column by column.
    fn triplets(dense: &DMatrix<f64>) -> Vec<(usize, usize, f64)> {
        let n = dense.ncols();
        let mut entries = Vec::new();
        for j in 0..n {
            for i in 0..n {
                if dense[(i, j)] != 0.0 {
                    entries.push((i, j, dense[(i, j)]));
                }
            }
        }
        entries
    }

    /// Factorises `dense` into `newton` (`changed`: a pattern other than the last one) and
    /// checks the solve against nalgebra's dense LU.
    fn factorise_and_check(newton: &mut SparseNewton, dense: &DMatrix<f64>, changed: bool) {
        let n = dense.ncols();
        let mut matrix = compress(&triplets(dense), n, &mut Vec::new());
        newton.row_scale = scale_rows(&mut matrix).unwrap();
        newton.col_scale = vec![1.0; n];
        newton
            .factorise(matrix, changed, &Parallelism::serial())
            .unwrap();
        let b = DVector::from_fn(n, |i, _| (i as f64 * 0.3).cos());
        let mut x = b.clone();
        assert!(newton.solve(&mut x));
        let expected = dense.clone().lu().solve(&b).unwrap();
        assert!((&x - &expected).norm() <= 1e-12 * expected.norm());
    }

    /// The ordering held by `newton`.
    fn ordering(newton: &SparseNewton) -> Vec<isize> {
        newton.symbolic.as_ref().unwrap().q.clone().unwrap()
    }

    #[test]
    fn a_changed_pattern_keeps_the_ordering_while_its_fill_stays_low() {
        let full = sample(40);
        // The same matrix less two far entries: a contact's block not yet in.
        let near = DMatrix::from_fn(40, 40, |i, j| match (i, j) {
            (10, 15) | (15, 10) => 0.0,
            _ => full[(i, j)],
        });
        let mut newton = SparseNewton {
            general_only: true,
            ..SparseNewton::default()
        };
        factorise_and_check(&mut newton, &near, true);
        let first = ordering(&newton);
        factorise_and_check(&mut newton, &full, true);
        assert_eq!(ordering(&newton), first);
        assert!(!newton.reorder);
    }

    #[test]
    fn an_ordering_whose_fill_grows_too_far_is_computed_again() {
        let n = 40;
        let diagonal = DMatrix::from_fn(n, n, |i, j| if i == j { 4.0 + i as f64 } else { 0.0 });
        // An arrow: the first row and column full. In the diagonal's ordering (which keeps
        // the first column first) its elimination fills the whole matrix; minimum degree
        // puts that column last and fills nothing.
        let arrow = DMatrix::from_fn(n, n, |i, j| match (i, j) {
            _ if i == j => 4.0 + i as f64,
            (0, _) | (_, 0) => 0.5,
            _ => 0.0,
        });
        let mut newton = SparseNewton {
            general_only: true,
            ..SparseNewton::default()
        };
        factorise_and_check(&mut newton, &diagonal, true);
        assert_eq!(
            newton.ordering_fill, 2.0,
            "L's unit diagonal and U's diagonal"
        );
        factorise_and_check(&mut newton, &arrow, true);
        assert!(
            newton.reorder,
            "the arrow in the diagonal's ordering fills in"
        );
        factorise_and_check(&mut newton, &arrow, false);
        assert!(!newton.reorder);
        let entries = (3 * n - 2) as f64;
        assert!(
            newton.ordering_fill * entries <= (4 * n) as f64,
            "{}",
            newton.ordering_fill
        );
    }

    #[test]
    fn a_zero_row_is_singular_and_an_infinite_entry_is_named() {
        let entries = vec![(0, 0, 1.0), (2, 2, 1.0), (1, 0, 0.0)];
        let mut matrix = compress(&entries, 3, &mut Vec::new());
        assert!(matches!(
            scale_rows(&mut matrix),
            Err(FailureCause::SingularMatrix)
        ));
        let entries = vec![(0, 0, 1.0), (1, 2, f64::INFINITY), (1, 1, 1.0), (2, 2, 1.0)];
        let mut matrix = compress(&entries, 3, &mut Vec::new());
        assert!(matches!(
            scale_rows(&mut matrix),
            Err(FailureCause::NonFinite { index: 2 })
        ));
    }
}
