//! The sparse Newton matrix split into islands: the connected components of its graph (an
//! entry `(i, j)` joins unknowns `i` and `j`). Parts that share no joint and no contact the
//! broad phase lets in give independent blocks — a pile of parts in flight is hundreds of
//! 14-unknown islands — and the matrix, permuted to gather each island, is block diagonal.
//! Each island is then factorised on its own by a dense LU with partial pivoting (nalgebra's),
//! which for small blocks costs a fraction of a general sparse LU's symbolic work per column.
//! A solve gathers each island's entries, solves and scatters them back.
//!
//! The factors are those of the same partial-pivoting elimination restricted to each block, so
//! the answers equal the whole matrix's sparse LU to round-off. Islands are used only while the
//! largest has at most [`ISLAND_MAX`] unknowns (dense storage grows with the square of an
//! island); a larger one sends the whole matrix to the general sparse LU.

use crate::parallel::Parallelism;
use nalgebra::{DMatrix, DVectorViewMut, Dyn, LU};
use rsparse::data::Sprs;

/// The largest island (in unknowns) factorised dense: past it the whole matrix goes to the
/// general sparse LU. At 96 unknowns a dense LU takes about 0.3 Mflop.
pub(super) const ISLAND_MAX: usize = 96;

/// The islands of a pattern: each island's unknowns, ascending, islands ordered by their
/// smallest unknown.
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) struct Islands {
    members: Vec<Vec<usize>>,
    /// Each unknown's island and its place in it.
    place: Vec<(u32, u32)>,
}

impl Islands {
    /// The islands of `matrix`'s pattern, or `None` if one has more than [`ISLAND_MAX`]
    /// unknowns.
    pub fn of(matrix: &Sprs<f64>) -> Option<Self> {
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
            if list.len() == ISLAND_MAX {
                return None;
            }
            place.push((island, list.len() as u32));
            list.push(k);
        }
        Some(Self { members, place })
    }

    /// Factorises each island's block of `matrix` (whose pattern gave these islands), the
    /// islands shared among `parallelism`'s threads (each alone: the same bits at any count);
    /// `None` if a block is singular.
    pub fn factorise(
        &self,
        matrix: &Sprs<f64>,
        parallelism: &Parallelism,
    ) -> Option<Vec<LU<f64, Dyn, Dyn>>> {
        parallelism
            .map_indexed(self.members.len(), |island| {
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
            })
            .into_iter()
            .collect()
    }

    /// Solves the block-diagonal system in place: `x` holds the right-hand side and receives
    /// the answer. False if a block's solve fails.
    pub fn solve(&self, lus: &[LU<f64, Dyn, Dyn>], x: &mut [f64]) -> bool {
        let mut local = vec![0.0; self.largest()];
        self.members.iter().zip(lus).all(|(members, lu)| {
            let local = &mut local[..members.len()];
            for (v, &g) in local.iter_mut().zip(members) {
                *v = x[g];
            }
            let solved = lu.solve_mut(&mut DVectorViewMut::from_slice(local, members.len()));
            for (&g, v) in members.iter().zip(local.iter()) {
                x[g] = *v;
            }
            solved
        })
    }

    /// The number of unknowns of the largest island.
    fn largest(&self) -> usize {
        self.members.iter().map(Vec::len).max().unwrap_or(0)
    }
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
        let islands = Islands::of(&m).unwrap();
        assert_eq!(islands.members, vec![vec![0, 3, 5], vec![1, 4], vec![2]]);
        let lus = islands.factorise(&m, &Parallelism::serial()).unwrap();
        let b = DVector::from_fn(6, |i, _| 1.0 + i as f64);
        let mut x = b.as_slice().to_vec();
        assert!(islands.solve(&lus, &mut x));
        // The oracle: nalgebra's LU of the whole matrix.
        let expected = a.clone().lu().solve(&b).unwrap();
        let x = DVector::from_vec(x);
        assert!((&x - &expected).norm() <= 1e-14 * expected.norm());
    }

    #[test]
    fn an_island_past_the_limit_sends_the_matrix_to_the_sparse_lu() {
        let n = ISLAND_MAX + 1;
        // A chain: every unknown coupled to the next, one island of n.
        let chain = DMatrix::from_fn(n, n, |i, j| match i.abs_diff(j) {
            0 => 4.0,
            1 => 1.0,
            _ => 0.0,
        });
        assert_eq!(Islands::of(&sparse(&chain)), None);
        let short = chain.view((0, 0), (ISLAND_MAX, ISLAND_MAX)).into_owned();
        assert_eq!(
            Islands::of(&sparse(&short)).map(|i| i.members.len()),
            Some(1)
        );
    }

    #[test]
    fn a_singular_island_is_reported() {
        let m = sparse(&three_islands());
        let islands = Islands::of(&m).unwrap();
        // The same pattern with unknown 2's only entry zero: its island is singular.
        let mut zeroed = m.clone();
        for (k, &row) in m.i.iter().enumerate() {
            if row == 2 {
                zeroed.x[k] = 0.0;
            }
        }
        assert!(islands.factorise(&m, &Parallelism::serial()).is_some());
        assert!(islands.factorise(&zeroed, &Parallelism::serial()).is_none());
    }
}
