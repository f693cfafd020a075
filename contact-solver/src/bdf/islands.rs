//! The sparse Newton matrix split into islands: the connected components of its graph (an
//! entry `(i, j)` joins unknowns `i` and `j`). Parts that share no joint and no contact the
//! broad phase lets in give independent blocks — a pile of parts in flight is hundreds of
//! 14-unknown islands — and the matrix, permuted to gather each island, is block diagonal.
//! Each island is factorised on its own: a small one (at most [`ISLAND_MAX`] unknowns) by a
//! dense LU with partial pivoting (nalgebra's), which for small blocks costs a fraction of a
//! general sparse LU's symbolic work per column; a larger one (a heap of parts in contact) by
//! the general sparse LU on its own block (`super::sparse_newton`'s, with an ordering kept
//! while the island's unknowns stay the same). The islands are shared among the run's threads,
//! each factorised alone, so every thread count gives the same bits. A solve gathers each
//! island's entries, solves and scatters them back.
//!
//! The factors are those of a partial-pivoting elimination restricted to each block, so the
//! answers equal the whole matrix's LU to round-off. A matrix that is one island is left to
//! the whole-matrix sparse LU (`super::sparse_newton`).

use super::sparse_newton::{FILL_GROWTH, PIVOT_TOLERANCE};
use crate::parallel::Parallelism;
use nalgebra::{DMatrix, DVectorViewMut, Dyn, LU};
use rsparse::data::{Nmrc, Sprs, Symb};

/// The largest island (in unknowns) factorised dense; a larger one takes the general sparse
/// LU. At 96 unknowns a dense LU takes about 0.3 Mflop.
pub(super) const ISLAND_MAX: usize = 96;

/// One island's factors.
pub(super) enum IslandFactors {
    /// A small island's dense LU.
    Dense(LU<f64, Dyn, Dyn>),
    /// A large island's sparse LU of its block, and the block's column ordering.
    Sparse {
        lu: Nmrc<f64>,
        q: Option<Vec<isize>>,
    },
}

/// A large island's fill-reducing ordering, kept while the island has the same unknowns
/// (computed again when its fill per entry grows past [`FILL_GROWTH`] times the fill it gave
/// at its own pattern, as for the whole matrix).
#[derive(Debug, Clone)]
pub(super) struct KeptOrdering {
    members: Vec<usize>,
    symbolic: Symb,
    ordering_fill: f64,
    reorder: bool,
}

/// The islands of a pattern: each island's unknowns, ascending, islands ordered by their
/// smallest unknown.
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) struct Islands {
    members: Vec<Vec<usize>>,
    /// Each unknown's island and its place in it.
    place: Vec<(u32, u32)>,
}

impl Islands {
    /// The islands of `matrix`'s pattern.
    pub fn of(matrix: &Sprs<f64>) -> Self {
        let n = matrix.n;
        let mut parent: Vec<usize> = (0..n).collect();
        for j in 0..n {
            for &i in &matrix.i[matrix.p[j] as usize..matrix.p[j + 1] as usize] {
                let (a, b) = (root(&mut parent, i), root(&mut parent, j));
                // The smaller index is the root: islands are numbered deterministically.
                parent[a.max(b)] = a.min(b);
            }
        }
        let mut island_of_root = vec![u32::MAX; n];
        let mut members: Vec<Vec<usize>> = Vec::new();
        let mut place = Vec::with_capacity(n);
        for k in 0..n {
            let r = root(&mut parent, k);
            if island_of_root[r] == u32::MAX {
                island_of_root[r] = members.len() as u32;
                members.push(Vec::new());
            }
            let island = island_of_root[r];
            let list = &mut members[island as usize];
            place.push((island, list.len() as u32));
            list.push(k);
        }
        Self { members, place }
    }

    /// The number of islands.
    pub fn count(&self) -> usize {
        self.members.len()
    }

    /// Factorises each island's block of `matrix` (whose pattern gave these islands), the
    /// islands shared among `parallelism`'s threads (each alone: the same bits at any count);
    /// `kept` holds the large islands' orderings, taken where an island has the same unknowns
    /// and replaced by this factorisation's. `None` if a block is singular.
    pub fn factorise(
        &self,
        matrix: &Sprs<f64>,
        parallelism: &Parallelism,
        kept: &mut Vec<KeptOrdering>,
    ) -> Option<Vec<IslandFactors>> {
        let previous: &[KeptOrdering] = kept;
        let results = parallelism.map_indexed(self.members.len(), |island| {
            let members = &self.members[island];
            if members.len() <= ISLAND_MAX {
                return self
                    .dense_block(matrix, island)
                    .map(|lu| (IslandFactors::Dense(lu), None));
            }
            let ordering = previous.iter().find(|k| k.members == *members);
            sparse_block(&self.block(matrix, island), members, ordering)
        });
        let mut orderings = Vec::new();
        let mut factors = Vec::with_capacity(results.len());
        for result in results {
            let (f, ordering) = result?;
            factors.push(f);
            orderings.extend(ordering);
        }
        *kept = orderings;
        Some(factors)
    }

    /// Island `island`'s block of `matrix`, dense, factorised; `None` if singular.
    fn dense_block(&self, matrix: &Sprs<f64>, island: usize) -> Option<LU<f64, Dyn, Dyn>> {
        let members = &self.members[island];
        let mut block = DMatrix::zeros(members.len(), members.len());
        for (col, &j) in members.iter().enumerate() {
            for k in matrix.p[j] as usize..matrix.p[j + 1] as usize {
                let (_, row) = self.place[matrix.i[k]];
                block[(row as usize, col)] += matrix.x[k];
            }
        }
        let lu = block.lu();
        lu.is_invertible().then_some(lu)
    }

    /// Island `island`'s block of `matrix` in compressed columns, in its own numbering (rows
    /// stay sorted: the members are ascending).
    fn block(&self, matrix: &Sprs<f64>, island: usize) -> Sprs<f64> {
        let members = &self.members[island];
        let mut block = Sprs::<f64>::new();
        (block.m, block.n) = (members.len(), members.len());
        block.p.reserve(members.len() + 1);
        block.p.push(0);
        for &j in members {
            for k in matrix.p[j] as usize..matrix.p[j + 1] as usize {
                let (_, row) = self.place[matrix.i[k]];
                block.i.push(row as usize);
                block.x.push(matrix.x[k]);
            }
            block.p.push(block.i.len() as isize);
        }
        block.nzmax = block.i.len();
        block
    }

    /// Solves the block-diagonal system in place: `x` holds the right-hand side and receives
    /// the answer. False if a block's solve fails.
    pub fn solve(&self, factors: &[IslandFactors], x: &mut [f64]) -> bool {
        let mut local = vec![0.0; self.largest()];
        let mut permuted = Vec::new();
        self.members.iter().zip(factors).all(|(members, f)| {
            let local = &mut local[..members.len()];
            for (v, &g) in local.iter_mut().zip(members) {
                *v = x[g];
            }
            let solved = match f {
                IslandFactors::Dense(lu) => {
                    lu.solve_mut(&mut DVectorViewMut::from_slice(local, members.len()))
                }
                IslandFactors::Sparse { lu, q } => {
                    sparse_solve(lu, q.as_deref(), local, &mut permuted)
                }
            };
            for (&g, v) in members.iter().zip(local.iter()) {
                x[g] = *v;
            }
            solved
        })
    }

    /// The number of unknowns of the largest island.
    pub fn largest(&self) -> usize {
        self.members.iter().map(Vec::len).max().unwrap_or(0)
    }
}

/// A large island's `block` factorised by the general sparse LU, with the ordering `kept` for
/// its unknowns `members` if any (see [`KeptOrdering`]); returns the factors and the ordering
/// to keep. `None` if the block is singular.
fn sparse_block(
    block: &Sprs<f64>,
    members: &[usize],
    kept: Option<&KeptOrdering>,
) -> Option<(IslandFactors, Option<KeptOrdering>)> {
    let fresh = kept.is_none_or(|k| k.reorder);
    let mut ordering = match kept {
        Some(k) if !fresh => k.clone(),
        _ => KeptOrdering {
            members: members.to_vec(),
            // Order 1: minimum degree on A + Aᵀ, for LU.
            symbolic: rsparse::sqr(block, 1, false),
            ordering_fill: 0.0,
            reorder: false,
        },
    };
    let lu = rsparse::lu(block, &mut ordering.symbolic, PIVOT_TOLERANCE).ok()?;
    let n = block.n;
    (ordering.symbolic.lnz, ordering.symbolic.unz) = (lu.l.x.len() + n, lu.u.x.len() + n);
    let fill = (lu.l.x.len() + lu.u.x.len()) as f64 / block.x.len().max(1) as f64;
    if fresh {
        ordering.ordering_fill = fill;
    } else if fill > FILL_GROWTH * ordering.ordering_fill {
        ordering.reorder = true;
    }
    let q = ordering.symbolic.q.clone();
    Some((IslandFactors::Sparse { lu, q }, Some(ordering)))
}

/// Solves `L·U·z = P·b`, `x = Q·z` in place in `x` (`b` on entry), `scratch` for the permuted
/// vector; false without a pivot permutation.
fn sparse_solve(
    lu: &Nmrc<f64>,
    q: Option<&[isize]>,
    x: &mut [f64],
    scratch: &mut Vec<f64>,
) -> bool {
    let Some(pinv) = &lu.pinv else {
        return false;
    };
    scratch.clear();
    scratch.resize(x.len(), 0.0);
    for (k, v) in x.iter().enumerate() {
        scratch[pinv[k] as usize] = *v;
    }
    rsparse::lsolve(&lu.l, scratch);
    rsparse::usolve(&lu.u, scratch);
    match q {
        Some(q) => {
            for (k, v) in scratch.iter().enumerate() {
                x[q[k] as usize] = *v;
            }
        }
        None => x.copy_from_slice(scratch),
    }
    true
}

/// The root of `k`'s tree, halving the path on the way.
fn root(parent: &mut [usize], mut k: usize) -> usize {
    while parent[k] != k {
        parent[k] = parent[parent[k]];
        k = parent[k];
    }
    k
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;

    /// Compressed columns of `dense`'s nonzeros.
    fn sparse(dense: &DMatrix<f64>) -> Sprs<f64> {
        let n = dense.ncols();
        let mut m = Sprs::<f64>::new();
        (m.m, m.n) = (n, n);
        m.p.push(0);
        for j in 0..n {
            for i in 0..n {
                if dense[(i, j)] != 0.0 {
                    m.i.push(i);
                    m.x.push(dense[(i, j)]);
                }
            }
            m.p.push(m.i.len() as isize);
        }
        m.nzmax = m.i.len();
        m
    }

    /// Unknowns `{0, 3, 5}`, `{1, 4}` and `{2}` coupled only among themselves, with zero
    /// diagonal entries that need pivoting.
    fn three_islands() -> DMatrix<f64> {
        let mut a = DMatrix::zeros(6, 6);
        for (i, j, v) in [
            (0, 0, 0.0),
            (0, 3, 2.0),
            (3, 0, 1.5),
            (3, 5, -1.0),
            (5, 0, 0.25),
            (5, 5, 3.0),
            (3, 3, 0.5),
            (1, 4, 4.0),
            (4, 1, -2.0),
            (4, 4, 1.0),
            (2, 2, 7.0),
        ] {
            a[(i, j)] = v;
        }
        a
    }

    #[test]
    fn islands_are_the_connected_unknowns_and_solve_as_the_whole_lu() {
        let a = three_islands();
        let m = sparse(&a);
        let islands = Islands::of(&m);
        assert_eq!(islands.members, vec![vec![0, 3, 5], vec![1, 4], vec![2]]);
        let lus = islands
            .factorise(&m, &Parallelism::serial(), &mut Vec::new())
            .unwrap();
        let b = DVector::from_fn(6, |i, _| 1.0 + i as f64);
        let mut x = b.as_slice().to_vec();
        assert!(islands.solve(&lus, &mut x));
        // The oracle: nalgebra's LU of the whole matrix.
        let expected = a.clone().lu().solve(&b).unwrap();
        let x = DVector::from_vec(x);
        assert!((&x - &expected).norm() <= 1e-14 * expected.norm());
    }

    /// A chain of `n` unknowns from `first` (each coupled to the next) beside the three small
    /// islands: one island past [`ISLAND_MAX`], factorised by the sparse LU.
    fn chain_beside_islands(n: usize) -> DMatrix<f64> {
        let small = three_islands();
        let mut a = DMatrix::zeros(6 + n, 6 + n);
        a.view_mut((0, 0), (6, 6)).copy_from(&small);
        for i in 0..n {
            for j in 0..n {
                a[(6 + i, 6 + j)] = match i.abs_diff(j) {
                    0 => 4.0 + (i % 3) as f64,
                    1 => 1.0 - 0.1 * (j % 5) as f64,
                    _ => 0.0,
                };
            }
        }
        a
    }

    #[test]
    fn a_large_island_takes_the_sparse_lu_beside_the_dense_ones() {
        let n = ISLAND_MAX + 1;
        let a = chain_beside_islands(n);
        let m = sparse(&a);
        let islands = Islands::of(&m);
        assert_eq!(islands.count(), 4);
        assert_eq!(islands.largest(), n);
        let mut kept = Vec::new();
        let factors = islands
            .factorise(&m, &Parallelism::serial(), &mut kept)
            .unwrap();
        let kinds: Vec<bool> = factors
            .iter()
            .map(|f| matches!(f, IslandFactors::Sparse { .. }))
            .collect();
        assert_eq!(kinds, vec![false, false, false, true]);
        assert_eq!(kept.len(), 1);
        let b = DVector::from_fn(6 + n, |i, _| (1.0 + i as f64).sin());
        let mut x = b.as_slice().to_vec();
        assert!(islands.solve(&factors, &mut x));
        // The oracle: nalgebra's LU of the whole matrix.
        let expected = a.clone().lu().solve(&b).unwrap();
        let x = DVector::from_vec(x);
        assert!((&x - &expected).norm() <= 1e-13 * expected.norm());
        // The same unknowns again: the kept ordering, the same factors to the bit, and two
        // threads give the same bits.
        let again = islands
            .factorise(&m, &Parallelism::with_threads(2).unwrap(), &mut kept)
            .unwrap();
        let mut y = b.as_slice().to_vec();
        assert!(islands.solve(&again, &mut y));
        assert!(x.iter().zip(&y).all(|(p, q)| p.to_bits() == q.to_bits()));
        assert_eq!(kept.len(), 1);
    }

    #[test]
    fn a_singular_island_is_reported() {
        let m = sparse(&three_islands());
        let islands = Islands::of(&m);
        // The same pattern with unknown 2's only entry zero: its island is singular.
        let mut zeroed = m.clone();
        for (k, &row) in m.i.iter().enumerate() {
            if row == 2 {
                zeroed.x[k] = 0.0;
            }
        }
        let serial = Parallelism::serial();
        assert!(islands.factorise(&m, &serial, &mut Vec::new()).is_some());
        assert!(
            islands
                .factorise(&zeroed, &serial, &mut Vec::new())
                .is_none()
        );
    }
}
