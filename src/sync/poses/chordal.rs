//! The chordal start (Martinec and Pajdla 2007; Carlone et al. 2015; SE-Sync §4.2.4, its
//! `chordal_initialization`): the rotation cost `Σ κ_ij ‖R_j − R_i R̃_ij‖²_F = tr(R L(G̃^ρ) Rᵀ)`
//! minimised over all `d × d` matrices with `R_0 = I` (a linear least-squares problem, solved by one
//! sparse Cholesky factorisation of `L(G̃^ρ)` without node 0's block row and column, positive
//! definite on a connected graph), then each block projected to its nearest rotation.
//!
//! With `X = Rᵀ` (block `i` = `R_iᵀ`), the free blocks solve `L_ff X_f = −L_f0`: an edge `(0, k)`
//! puts `κ R̃_0kᵀ` in node `k`'s right-hand side, an edge `(k, 0)` puts `κ R̃_k0`.

use faer::sparse::Pair;
use glam::DQuat;

use super::reduced::Reduced;
use super::stiefel::{Stack, to_rotations};
use crate::sync::sparse::{Layout, Lower};

/// Every `R_i` of the chordal estimate (`R_0 = I`), or `None` if the anchored connection
/// Laplacian cannot be factored.
pub(super) fn chordal(problem: &Reduced) -> Option<Vec<DQuat>> {
    let (d, n) = (problem.d, problem.n);
    // Node k ≥ 1's rows start at d (k − 1).
    let at = |k: usize, a: usize| k.checked_sub(1).map(|k| d * k + a);
    let mut pairs = Vec::new();
    let mut values = Vec::new();
    let mut rhs = vec![0.0; d * (n - 1) * d];
    let rows = d * (n - 1);
    for e in &problem.edges {
        for a in 0..d {
            for node in [e.i, e.j] {
                if let Some(row) = at(node, a) {
                    pairs.push(Pair { row, col: row });
                    values.push(e.kappa);
                }
            }
            for b in 0..d {
                let value = -e.kappa * e.rotation[a][b];
                match (at(e.i, a), at(e.j, b)) {
                    (Some(r), Some(c)) => {
                        pairs.push(Pair { row: r.max(c), col: r.min(c) });
                        values.push(value);
                    }
                    // Edge (k, 0): block (k, 0) = −κ R̃, moved to the right: +κ R̃_ab in
                    // row (k, a), column b.
                    (Some(r), None) => rhs[b * rows + r] -= value,
                    // Edge (0, k): block (k, 0) = −κ R̃ᵀ: +κ R̃_ab in row (k, b), column a.
                    (None, Some(c)) => rhs[a * rows + c] -= value,
                    (None, None) => {}
                }
            }
        }
    }
    let factor = Lower::new(rows, &pairs, Layout::Auto).factor(&values)?;
    factor.solve(&mut rhs, d);
    let mut x = Stack::zeros(d, n, d);
    for a in 0..d {
        *x.at_mut(a, a) = 1.0;
        for row in 0..rows {
            *x.at_mut(d + row, a) = rhs[a * rows + row];
        }
    }
    if x.data.iter().any(|v| !v.is_finite()) {
        return None;
    }
    Some(to_rotations(&x))
}
