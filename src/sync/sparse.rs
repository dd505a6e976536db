//! Sparse symmetric matrices with a fixed pattern, factorised by faer's sparse Cholesky (with its
//! fill-reducing ordering). For rotations, the graph's 3×3 block matrices (`blocks::Pattern`: the
//! connection Laplacian, the certificate's `S`, the Newton system); for pose graphs, the anchored
//! translational Laplacian `L_τ`, the anchored rotational connection Laplacian of the chordal
//! start, the full pose-graph matrix `M` of SE-Sync's eq. (20), shifted on its rotation block for
//! the preconditioner and the certificate, and the Newton system of `poses::newton`.
//!
//! The pattern (and faer's symbolic analysis) is built once; each numeric factorisation takes the
//! values in the order the pattern's entries were listed, duplicates added up.

use std::sync::Arc;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::linalg::amd;
use faer::sparse::linalg::cholesky::CholeskySymbolicParams;
use faer::sparse::linalg::cholesky::{
    LltRef, SymbolicCholesky, SymbolicCholeskyRaw, SymmetricOrdering, factorize_symbolic_cholesky,
};
use faer::sparse::{Pair, SparseColMatRef, SymbolicSparseColMat, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par, Side};

/// The lower triangle of a symmetric `size × size` matrix, as a list of entries `(row ≥ col)`,
/// held already permuted to the factor's ordering and in the triangle faer's factorisation reads
/// (the upper for its simplicial one, the lower for its supernodal one): each numeric
/// factorisation then adds the listed values into place and factors them as they are. Handing faer
/// the matrix in its own order and the ordering beside it, each factorisation sorted the entries
/// and permuted the matrix again: in wasm w20000 took 3.65–4.0 s that way against 3.2–3.5 s
/// (its 60 or so factorisations of up to 120,000 unknowns); the graphs that factor a few times
/// within ±5%.
pub(super) struct Lower {
    /// The triangle [`read_side`] names.
    pattern: SymbolicSparseColMat<usize>,
    /// The slot in the pattern's values of each listed entry.
    slots: Vec<usize>,
    ordering: Arc<Ordering>,
}

/// A fill-reducing ordering and the symbolic factorisation of the matrix permuted by it.
struct Ordering {
    /// Row `k` of the matrix is row `inverse[k]` of the factored one.
    inverse: Vec<usize>,
    cholesky: SymbolicCholesky<usize>,
}

/// A numeric Cholesky factorisation `A = L Lᵀ` that succeeded.
pub(super) struct Factor {
    ordering: Arc<Ordering>,
    values: Vec<f64>,
}

/// How a factor is ordered: by faer's minimum degree on the entries; or, for a matrix of dense
/// `v × v` blocks, on the blocks, each kept whole (the Newton system's: natively w20000's rank 3
/// took 3.25 s against 4.17 s ordered by the entries, its rank 2 0.76 against 0.82 s, w10000's
/// 0.34 against 0.39 s). Either way faer chooses between its simplicial (column by column) and
/// supernodal (dense blocks) factorisations from the ratio of flops to the factor's entries
/// (for blocks, natively, at a lower ratio: `BLOCKS_SUPERNODAL`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Layout {
    Auto,
    Blocks(usize),
}

/// `order` sorted stably by `key` (below `size`).
fn counting_sort(size: usize, order: &[usize], key: impl Fn(usize) -> usize) -> Vec<usize> {
    let mut starts = vec![0usize; size + 1];
    for &k in order {
        starts[key(k) + 1] += 1;
    }
    for c in 0..size {
        starts[c + 1] += starts[c];
    }
    let mut sorted = vec![0usize; order.len()];
    for &k in order {
        let at = &mut starts[key(k)];
        sorted[*at] = k;
        *at += 1;
    }
    sorted
}

/// The compressed columns of the entries `pairs` (repeats allowed) and each entry's slot in them:
/// two stable counting sorts (by row, then by column) and one pass merging repeats, in `O(nnz +
/// size)`. (faer's `try_new_from_indices` sorts by comparison: on w10000 that sort was a tenth of
/// the solve.)
fn compressed(
    size: usize,
    pairs: &[Pair<usize, usize>],
) -> (SymbolicSparseColMat<usize>, Vec<usize>) {
    let listed: Vec<usize> = (0..pairs.len()).collect();
    let by_row = counting_sort(size, &listed, |k| pairs[k].row);
    let order = counting_sort(size, &by_row, |k| pairs[k].col);
    let mut col_ptr = vec![0usize; size + 1];
    let mut row_idx = Vec::with_capacity(pairs.len());
    let mut slots = vec![0usize; pairs.len()];
    let mut last: Option<(usize, usize)> = None;
    for &k in &order {
        let Pair { row, col } = pairs[k];
        if last != Some((row, col)) {
            row_idx.push(row);
            col_ptr[col + 1] += 1;
            last = Some((row, col));
        }
        slots[k] = row_idx.len() - 1;
    }
    for c in 0..size {
        col_ptr[c + 1] += col_ptr[c];
    }
    (SymbolicSparseColMat::new_checked(size, size, col_ptr, None, row_idx), slots)
}

/// Where a matrix of dense blocks turns supernodal, natively: at a quarter of faer's own ratio of
/// flops to the factor's entries. The Newton systems of the large 2D graphs sit between the two,
/// where faer's simplicial factorisation, column by column, spent 44% of w20000's time. Natively
/// w20000 took 3.32 → 2.58 s, w10000 571 → 463 ms, the other graphs within 3% (one run each).
/// In wasm faer's dense kernels are slower, and the same choice made w20000 slower (3.38 →
/// 3.73 s, medians of 3, alternately), so there faer's own ratio stays.
#[cfg(not(target_arch = "wasm32"))]
const BLOCKS_SUPERNODAL: SupernodalThreshold = SupernodalThreshold(0.25);
#[cfg(target_arch = "wasm32")]
const BLOCKS_SUPERNODAL: SupernodalThreshold = SupernodalThreshold::AUTO;

/// The triangle faer's numeric factorisation reads: the upper for its simplicial form, the lower
/// for its supernodal one (the other it would transpose first, each time).
fn read_side(cholesky: &SymbolicCholesky<usize>) -> Side {
    match cholesky.raw() {
        SymbolicCholeskyRaw::Simplicial(_) => Side::Upper,
        SymbolicCholeskyRaw::Supernodal(_) => Side::Lower,
    }
}

/// faer's minimum degree ordering of the entries `pairs`: row `k` goes to `inverse[k]`.
fn entry_ordering(size: usize, pairs: &[Pair<usize, usize>]) -> Vec<usize> {
    minimum_degree(size, compressed(size, pairs).0.as_ref())
}

/// The rows and columns ordered block by block: faer's minimum degree on the `v × v` blocks'
/// pattern, each block's `v` rows kept together in order; row `k` goes to `inverse[k]`. A dense
/// block lists its first entry, so the blocks' pattern is read from those alone (w20000's rank 3
/// lists 1.4 million entries for 47,000 blocks: natively 56 → 9 ms to order); a block listed
/// without it would only make the ordering worse, never the factor wrong.
fn block_ordering(size: usize, pairs: &[Pair<usize, usize>], v: usize) -> Vec<usize> {
    let blocks = size / v;
    let block_pairs: Vec<Pair<usize, usize>> = pairs
        .iter()
        .filter(|p| p.row % v == 0 && p.col % v == 0)
        .map(|p| Pair { row: p.row / v, col: p.col / v })
        .collect();
    let inverse = minimum_degree(blocks, compressed(blocks, &block_pairs).0.as_ref());
    (0..size).map(|k| v * inverse[k / v] + k % v).collect()
}

/// faer's approximate minimum degree ordering of a symmetric pattern (one triangle of it), as
/// `inverse`; the identity (a valid ordering, if a poor one) where it fails.
fn minimum_degree(size: usize, pattern: SymbolicSparseColMatRef<'_, usize>) -> Vec<usize> {
    let (mut forward, mut inverse) = (vec![0usize; size], vec![0usize; size]);
    let scratch = amd::order_maybe_unsorted_scratch::<usize>(size, pattern.compute_nnz());
    let ordered = MemBuffer::try_new(scratch).ok().and_then(|mut buffer| {
        amd::order_maybe_unsorted(
            &mut forward,
            &mut inverse,
            pattern,
            Default::default(),
            MemStack::new(&mut buffer),
        )
        .ok()
    });
    if ordered.is_none() {
        return (0..size).collect();
    }
    inverse
}

impl Lower {
    /// The pattern of the entries `pairs` (each with `row ≥ col`, repeats allowed).
    pub fn new(size: usize, pairs: &[Pair<usize, usize>], layout: Layout) -> Lower {
        let inverse = match layout {
            Layout::Auto => entry_ordering(size, pairs),
            Layout::Blocks(v) => block_ordering(size, pairs, v),
        };
        // Without an ordering to apply, faer analyses the matrix as its upper triangle.
        let upper: Vec<Pair<usize, usize>> = pairs
            .iter()
            .map(|p| {
                let (a, b) = (inverse[p.row], inverse[p.col]);
                Pair { row: a.min(b), col: a.max(b) }
            })
            .collect();
        let (pattern, slots) = compressed(size, &upper);
        let cholesky = factorize_symbolic_cholesky(
            pattern.as_ref(),
            Side::Upper,
            SymmetricOrdering::Identity,
            CholeskySymbolicParams {
                supernodal_flop_ratio_threshold: match layout {
                    Layout::Auto => SupernodalThreshold::AUTO,
                    Layout::Blocks(_) => BLOCKS_SUPERNODAL,
                },
                ..Default::default()
            },
        )
        .expect("a square pattern has a symbolic Cholesky factorisation");
        let (pattern, slots) = match read_side(&cholesky) {
            Side::Upper => (pattern, slots),
            Side::Lower => {
                let lower: Vec<Pair<usize, usize>> =
                    upper.iter().map(|p| Pair { row: p.col, col: p.row }).collect();
                compressed(size, &lower)
            }
        };
        Lower { pattern, slots, ordering: Arc::new(Ordering { inverse, cholesky }) }
    }

    /// How many entries the Cholesky factor holds (its fill).
    pub fn factor_len(&self) -> usize {
        self.ordering.cholesky.len_val()
    }

    /// The factor's entries over the lower triangle's own: 1 where the factorisation fills in
    /// nothing (a tree), larger the more the graph's cycles interlock.
    pub fn fill(&self) -> f64 {
        self.factor_len() as f64 / self.pattern.row_idx().len().max(1) as f64
    }

    /// The Cholesky factor of the matrix whose listed entries are `values` (in the order of the
    /// pattern's pairs), or `None` when it is not positive definite to the working precision (a
    /// pivot `≤ 0`, or a value that is not finite).
    pub fn factor(&self, values: &[f64]) -> Option<Factor> {
        self.factor_in(values, &mut Vec::new())
    }

    /// [`Lower::factor`] with the factor's values in `storage` (taken on success, left on
    /// refusal): a method that factors one pattern many times hands back each spent factor's
    /// ([`Factor::into_storage`]), which then needs neither an allocation nor zeroing (faer writes
    /// every value of the factor before reading it: the simplicial factorisation row by row, the
    /// supernodal one after zeroing its supernodes itself). Allocating 33 MB zeroed for each of
    /// w20000's rank-3 factorisations was 3% of its time in wasm: there w20000 took 2.97 → 2.90 s,
    /// w10000 603 → 583 ms (medians of 5, alternately); parking-garage the same.
    pub fn factor_in(&self, values: &[f64], storage: &mut Vec<f64>) -> Option<Factor> {
        if values.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let mut permuted = vec![0.0; self.pattern.row_idx().len()];
        for (&slot, &value) in self.slots.iter().zip(values) {
            permuted[slot] += value;
        }
        let matrix = SparseColMatRef::new(self.pattern.as_ref(), &permuted);
        let cholesky = &self.ordering.cholesky;
        storage.resize(cholesky.len_val(), 0.0);
        let scratch = cholesky.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default());
        let mut buffer = MemBuffer::try_new(scratch).ok()?;
        cholesky
            .factorize_numeric_llt(
                storage,
                matrix,
                read_side(cholesky),
                Default::default(),
                Par::Seq,
                MemStack::new(&mut buffer),
                Default::default(),
            )
            .ok()?;
        Some(Factor { ordering: self.ordering.clone(), values: std::mem::take(storage) })
    }
}

impl Factor {
    /// The factor's values, to factor the same pattern again into ([`Lower::factor_in`]).
    pub fn into_storage(self) -> Vec<f64> {
        self.values
    }

    /// Solves `A X = B` in place for the `columns` right-hand sides in `b` (column-major, `size`
    /// rows each).
    pub fn solve(&self, b: &mut [f64], columns: usize) {
        let rows = b.len() / columns.max(1);
        let Ordering { inverse, cholesky } = &*self.ordering;
        let mut permuted = vec![0.0; b.len()];
        for c in 0..columns {
            for (k, &to) in inverse.iter().enumerate() {
                permuted[c * rows + to] = b[c * rows + k];
            }
        }
        let scratch = cholesky.solve_in_place_scratch::<f64>(columns, Par::Seq);
        let Ok(mut buffer) = MemBuffer::try_new(scratch) else {
            b.fill(f64::NAN);
            return;
        };
        LltRef::new(cholesky, &self.values).solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(&mut permuted, rows, columns),
            Par::Seq,
            MemStack::new(&mut buffer),
        );
        for c in 0..columns {
            for (k, &from) in inverse.iter().enumerate() {
                b[c * rows + k] = permuted[c * rows + from];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The counting sorts against faer's own construction by comparison: the same columns and
    /// rows, and the listed values added into the same places, on random entries with repeats.
    #[test]
    fn compressed_columns_are_faers() {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = |bound: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % bound as u64) as usize
        };
        for (size, count) in [(1, 3), (7, 40), (50, 400), (200, 300)] {
            let pairs: Vec<Pair<usize, usize>> = (0..count)
                .map(|_| {
                    let (a, b) = (next(size), next(size));
                    Pair { row: a.max(b), col: a.min(b) }
                })
                .collect();
            let values: Vec<f64> = (0..count).map(|k| 1.0 + k as f64).collect();
            let (ours, slots) = compressed(size, &pairs);
            let (theirs, argsort) =
                SymbolicSparseColMat::try_new_from_indices(size, size, &pairs).unwrap();
            assert_eq!(ours.col_ptr(), theirs.col_ptr(), "{size}, {count}");
            assert_eq!(ours.row_idx(), theirs.row_idx(), "{size}, {count}");
            let mut summed = vec![0.0; ours.row_idx().len()];
            for (&slot, &value) in slots.iter().zip(&values) {
                summed[slot] += value;
            }
            let faers =
                faer::sparse::SparseColMat::new_from_argsort(theirs, &argsort, &values).unwrap();
            assert_eq!(summed, faers.val(), "{size}, {count}");
        }
    }

    /// The blocks' ordering read from each block's first entry is the one read from every entry:
    /// dense 3 × 3 blocks on a random graph (each block's lower triangle on the diagonal).
    #[test]
    fn blocks_are_ordered_from_their_first_entries_as_from_all() {
        let (v, blocks) = (3, 60);
        let mut state = 7u64;
        let mut next = |n: usize| {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((state >> 33) as usize) % n
        };
        let mut pairs = Vec::new();
        for b in 0..blocks {
            for s in 0..v {
                for t in 0..=s {
                    pairs.push(Pair { row: v * b + s, col: v * b + t });
                }
            }
        }
        for _ in 0..150 {
            let (i, j) = (next(blocks), next(blocks));
            if i != j {
                let (big, small) = (i.max(j), i.min(j));
                for s in 0..v {
                    for t in 0..v {
                        pairs.push(Pair { row: v * big + s, col: v * small + t });
                    }
                }
            }
        }
        let size = v * blocks;
        let every: Vec<Pair<usize, usize>> =
            pairs.iter().map(|p| Pair { row: p.row / v, col: p.col / v }).collect();
        let inverse = minimum_degree(blocks, compressed(blocks, &every).0.as_ref());
        let expected: Vec<usize> = (0..size).map(|k| v * inverse[k / v] + k % v).collect();
        assert_eq!(block_ordering(size, &pairs, v), expected);
        assert_ne!(expected, (0..size).collect::<Vec<_>>(), "the identity orders nothing");
    }

    /// Both of faer's forms, each read from its own triangle, solve `A x = b` (checked by
    /// multiplying back) under both orderings: a chain of blocks factors column by column; all
    /// blocks coupled to all factor in dense supernodes once there are enough of them (faer's
    /// ratio of flops to entries, about a third of the size here, above 40), and natively sooner
    /// as blocks (above 10: `BLOCKS_SUPERNODAL`).
    #[test]
    fn both_forms_solve_under_both_orderings() {
        let v = 3;
        let native = !cfg!(target_arch = "wasm32");
        for (blocks, dense, auto, as_blocks) in
            [(40, false, false, false), (24, true, false, native), (50, true, true, true)]
        {
            let size = v * blocks;
            let coupled = |i: usize, j: usize| dense || i.abs_diff(j) <= 1;
            let mut dense_a = vec![0.0; size * size];
            for r in 0..size {
                for c in 0..r {
                    if coupled(r / v, c / v) {
                        let value = ((r * 7 + c * 13) % 11) as f64 / 11.0 - 0.5;
                        dense_a[r * size + c] = value;
                        dense_a[c * size + r] = value;
                    }
                }
            }
            for r in 0..size {
                dense_a[r * size + r] =
                    1.0 + (0..size).map(|c| dense_a[r * size + c].abs()).sum::<f64>();
            }
            let (mut pairs, mut values) = (Vec::new(), Vec::new());
            for r in 0..size {
                for c in 0..=r {
                    if dense_a[r * size + c] != 0.0 {
                        pairs.push(Pair { row: r, col: c });
                        values.push(dense_a[r * size + c]);
                    }
                }
            }
            let b: Vec<f64> = (0..size).map(|k| (k % 5) as f64 - 2.0).collect();
            for layout in [Layout::Auto, Layout::Blocks(v)] {
                let lower = Lower::new(size, &pairs, layout);
                let supernodal = read_side(&lower.ordering.cholesky) == Side::Lower;
                let expected = if layout == Layout::Auto { auto } else { as_blocks };
                assert_eq!(supernodal, expected, "{layout:?}, {blocks} blocks, dense {dense}");
                let mut x = b.clone();
                let factor = lower.factor(&values).unwrap();
                factor.solve(&mut x, 1);
                for r in 0..size {
                    let ax: f64 = (0..size).map(|c| dense_a[r * size + c] * x[c]).sum();
                    assert!((ax - b[r]).abs() < 1e-10, "{layout:?}, dense {dense}: row {r}");
                }
                // Into a spent factor's storage, every value overwritten (NaN where it is not),
                // the same factor; a refusal leaves the storage to its owner.
                let fresh = factor.into_storage();
                let mut storage = vec![f64::NAN; fresh.len()];
                let again = lower.factor_in(&values, &mut storage).unwrap().into_storage();
                assert!(storage.is_empty() && again == fresh, "{layout:?}, dense {dense}");
                let negative: Vec<f64> = values.iter().map(|v| -v).collect();
                let mut storage = vec![0.0; 7];
                assert!(lower.factor_in(&negative, &mut storage).is_none());
                assert_eq!(storage.len(), fresh.len(), "{layout:?}, dense {dense}");
            }
        }
    }
}
