//! Sparse symmetric matrices with a fixed pattern, factorised by faer's sparse Cholesky (with its
//! fill-reducing ordering): the anchored translational Laplacian `L_τ`, the anchored rotational
//! connection Laplacian of the chordal start, and the full pose-graph matrix `M` of SE-Sync's
//! eq. (20), shifted on its rotation block for the preconditioner and the certificate.
//!
//! The pattern (and faer's symbolic analysis) is built once; each numeric factorisation takes the
//! values in the order the pattern's entries were listed, duplicates added up.

use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::{Argsort, Pair, SparseColMat, SymbolicSparseColMat};
use faer::{MatMut, Side};

/// The lower triangle of a symmetric `size × size` matrix, as a list of entries `(row ≥ col)`.
pub(super) struct Lower {
    symbolic: SymbolicSparseColMat<usize>,
    argsort: Argsort<usize>,
    llt: SymbolicLlt<usize>,
}

/// A numeric Cholesky factorisation `A = L Lᵀ` that succeeded.
pub(super) struct Factor(Llt<usize, f64>);

impl Lower {
    /// The pattern of the entries `pairs` (each with `row ≥ col`, repeats allowed).
    pub fn new(size: usize, pairs: &[Pair<usize, usize>]) -> Lower {
        let (symbolic, argsort) = SymbolicSparseColMat::try_new_from_indices(size, size, pairs)
            .expect("the entries are below the dimension by construction");
        let llt = SymbolicLlt::try_new(symbolic.as_ref(), Side::Lower)
            .expect("a square pattern has a symbolic Cholesky factorisation");
        Lower { symbolic, argsort, llt }
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
        Llt::try_new_with_symbolic(self.llt.clone(), matrix.as_ref(), Side::Lower).ok().map(Factor)
    }
}

impl Factor {
    /// Solves `A X = B` in place for the `columns` right-hand sides in `b` (column-major, `size`
    /// rows each).
    pub fn solve(&self, b: &mut [f64], columns: usize) {
        use faer::prelude::Solve;
        let rows = b.len() / columns.max(1);
        self.0.solve_in_place(MatMut::from_column_major_slice_mut(b, rows, columns));
    }
}
