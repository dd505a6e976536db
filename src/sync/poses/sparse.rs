//! Sparse symmetric matrices with a fixed pattern, factorised by faer's sparse Cholesky (with its
//! fill-reducing ordering): the anchored translational Laplacian `L_τ`, the anchored rotational
//! connection Laplacian of the chordal start, the full pose-graph matrix `M` of SE-Sync's
//! eq. (20), shifted on its rotation block for the preconditioner and the certificate, and the
//! Newton system of `newton`.
//!
//! The pattern (and faer's symbolic analysis) is built once; each numeric factorisation takes the
//! values in the order the pattern's entries were listed, duplicates added up.

use std::sync::Arc;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::perm::PermRef;
use faer::sparse::linalg::amd;
use faer::sparse::linalg::cholesky::{
    LltRef, SymbolicCholesky, SymmetricOrdering, factorize_symbolic_cholesky,
};
use faer::sparse::{Argsort, Pair, SparseColMat, SymbolicSparseColMat};
use faer::{Conj, MatMut, Par, Side};

/// The lower triangle of a symmetric `size × size` matrix, as a list of entries `(row ≥ col)`.
pub(super) struct Lower {
    symbolic: SymbolicSparseColMat<usize>,
    argsort: Argsort<usize>,
    cholesky: Arc<SymbolicCholesky<usize>>,
}

/// A numeric Cholesky factorisation `A = L Lᵀ` that succeeded.
pub(super) struct Factor {
    cholesky: Arc<SymbolicCholesky<usize>>,
    values: Vec<f64>,
}

/// How a factor is ordered: by faer's minimum degree on the entries; or, for a matrix of dense
/// `v × v` blocks, on the blocks, each kept whole (the Newton system's: natively w20000's rank 3
/// took 3.25 s against 4.17 s ordered by the entries, its rank 2 0.76 against 0.82 s, w10000's
/// 0.34 against 0.39 s). Either way faer chooses between its simplicial (column by column) and
/// supernodal (dense blocks) factorisations from the ratio of flops to the factor's entries.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Layout {
    Auto,
    Blocks(usize),
}

/// The entries' rows and columns ordered block by block: faer's minimum degree on the `v × v`
/// blocks' pattern, each block's `v` rows kept together in order.
fn block_ordering(size: usize, pairs: &[Pair<usize, usize>], v: usize) -> (Vec<usize>, Vec<usize>) {
    let blocks = size / v;
    let block_pairs: Vec<Pair<usize, usize>> =
        pairs.iter().map(|p| Pair { row: p.row / v, col: p.col / v }).collect();
    let (pattern, _) = SymbolicSparseColMat::try_new_from_indices(blocks, blocks, &block_pairs)
        .expect("the blocks are below the dimension by construction");
    let (mut forward, mut inverse) = (vec![0usize; blocks], vec![0usize; blocks]);
    let scratch = amd::order_maybe_unsorted_scratch::<usize>(blocks, pattern.compute_nnz());
    let ordered = MemBuffer::try_new(scratch).ok().and_then(|mut buffer| {
        amd::order_maybe_unsorted(
            &mut forward,
            &mut inverse,
            pattern.as_ref(),
            Default::default(),
            MemStack::new(&mut buffer),
        )
        .ok()
    });
    if ordered.is_none() {
        // The identity: a valid ordering, if a poor one.
        forward.iter_mut().enumerate().for_each(|(k, f)| *f = k);
        inverse.iter_mut().enumerate().for_each(|(k, f)| *f = k);
    }
    let full_forward = (0..size).map(|k| v * forward[k / v] + k % v).collect();
    let full_inverse = (0..size).map(|k| v * inverse[k / v] + k % v).collect();
    (full_forward, full_inverse)
}

impl Lower {
    /// The pattern of the entries `pairs` (each with `row ≥ col`, repeats allowed).
    pub fn new(size: usize, pairs: &[Pair<usize, usize>], layout: Layout) -> Lower {
        let (symbolic, argsort) = SymbolicSparseColMat::try_new_from_indices(size, size, pairs)
            .expect("the entries are below the dimension by construction");
        let analysed = match layout {
            Layout::Auto => factorize_symbolic_cholesky(
                symbolic.as_ref(),
                Side::Lower,
                SymmetricOrdering::Amd,
                Default::default(),
            ),
            Layout::Blocks(v) => {
                let (forward, inverse) = block_ordering(size, pairs, v);
                factorize_symbolic_cholesky(
                    symbolic.as_ref(),
                    Side::Lower,
                    SymmetricOrdering::Custom(PermRef::new_checked(&forward, &inverse, size)),
                    Default::default(),
                )
            }
        };
        let cholesky = analysed.expect("a square pattern has a symbolic Cholesky factorisation");
        Lower { symbolic, argsort, cholesky: Arc::new(cholesky) }
    }

    /// The Cholesky factor of the matrix whose listed entries are `values` (in the order of the
    /// pattern's pairs), or `None` when it is not positive definite to the working precision (a
    /// pivot `≤ 0`, or a value that is not finite).
    pub fn factor(&self, values: &[f64]) -> Option<Factor> {
        if values.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let matrix =
            SparseColMat::new_from_argsort(self.symbolic.clone(), &self.argsort, values).ok()?;
        let mut out = vec![0.0; self.cholesky.len_val()];
        let scratch =
            self.cholesky.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default());
        let mut buffer = MemBuffer::try_new(scratch).ok()?;
        self.cholesky
            .factorize_numeric_llt(
                &mut out,
                matrix.as_ref(),
                Side::Lower,
                Default::default(),
                Par::Seq,
                MemStack::new(&mut buffer),
                Default::default(),
            )
            .ok()?;
        Some(Factor { cholesky: self.cholesky.clone(), values: out })
    }
}

impl Factor {
    /// Solves `A X = B` in place for the `columns` right-hand sides in `b` (column-major, `size`
    /// rows each).
    pub fn solve(&self, b: &mut [f64], columns: usize) {
        let rows = b.len() / columns.max(1);
        let scratch = self.cholesky.solve_in_place_scratch::<f64>(columns, Par::Seq);
        let Ok(mut buffer) = MemBuffer::try_new(scratch) else {
            b.fill(f64::NAN);
            return;
        };
        LltRef::new(&self.cholesky, &self.values).solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(b, rows, columns),
            Par::Seq,
            MemStack::new(&mut buffer),
        );
    }
}
