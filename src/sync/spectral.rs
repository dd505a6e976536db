//! The spectral relaxation (Singer 2011; Arrigoni et al. 2018): the start of the chordal and
//! robust methods.
//!
//! With `Y = [R_1ᵀ; …; R_nᵀ]`, `f = tr(Yᵀ L Y)` for the connection Laplacian `L` (MATH.md, "The
//! certificate"). Dropping the constraint `R_i ∈ SO(3)` for `YᵀY = n I` leaves the three
//! eigenvectors of `L` with the smallest eigenvalues, `V` (3n×3): `V_i ≈ R_iᵀ O` for one 3×3
//! orthogonal `O` (the gauge). Each block is then rounded to the nearest rotation. MATH.md
//! states it with the top eigenvectors of the connection matrix `W = D − L`; with equal degrees
//! they are the same vectors, and `L`'s are what shift-and-invert Lanczos finds in a few dozen
//! steps with the same factorisation as the rest of the solver.

use glam::{DMat3, DQuat, DVec3};

use super::blocks::{Blocks, Pattern};
use super::graph::Graph;
use super::lanczos;
use crate::average::eigen;
use crate::quaternion::from_wxyz;

/// The connection Laplacian `L`: diagonal blocks `d_i I₃`, block `(i, j)` = `−w_ij R_ij`.
pub(crate) fn laplacian(graph: &Graph) -> Blocks {
    let mut l = Blocks::zeros(graph);
    let edges = graph.edges().iter().zip(graph.relative()).zip(graph.weights());
    for (k, ((&[i, j], &relative), &w)) in edges.enumerate() {
        l.diag[i] += DMat3::IDENTITY * w;
        l.diag[j] += DMat3::IDENTITY * w;
        l.off[k] = DMat3::from_quat(relative) * -w;
    }
    l
}

/// The rotation nearest `a` in the Frobenius norm (maximising `tr(Rᵀ a)`), as a unit quaternion:
/// `tr(R(q)ᵀ a) = qᵀ K q` for the symmetric 4×4 `K` of Bar-Itzhack (2000), so `q` is `K`'s top
/// eigenvector. The determinant is +1 by construction, with no SVD and no reflection to undo.
pub(crate) fn nearest_rotation(a: DMat3) -> DQuat {
    let b = |r: usize, c: usize| a.col(c)[r];
    let k = [
        [b(0, 0) + b(1, 1) + b(2, 2), b(2, 1) - b(1, 2), b(0, 2) - b(2, 0), b(1, 0) - b(0, 1)],
        [b(2, 1) - b(1, 2), b(0, 0) - b(1, 1) - b(2, 2), b(0, 1) + b(1, 0), b(0, 2) + b(2, 0)],
        [b(0, 2) - b(2, 0), b(0, 1) + b(1, 0), -b(0, 0) + b(1, 1) - b(2, 2), b(1, 2) + b(2, 1)],
        [b(1, 0) - b(0, 1), b(0, 2) + b(2, 0), b(1, 2) + b(2, 1), -b(0, 0) - b(1, 1) + b(2, 2)],
    ];
    let (_, vectors) = eigen(k);
    let q = from_wxyz(vectors[0]);
    if q.w < 0.0 { -q } else { q }
}

/// The spectral estimate of every `q_i`, up to the gauge, and the Lanczos steps it took.
pub(crate) fn spectral(graph: &Graph, pattern: &Pattern) -> (Vec<DQuat>, usize) {
    let l = laplacian(graph);
    let n = graph.count();
    let scale = graph.degrees().into_iter().fold(0.0, f64::max);
    if pattern.fills() {
        // A graph whose factor fills in is an expander: L's smallest eigenvalues stand apart, and
        // Lanczos on `2 d_max I − L` (its largest, `≥ 0` since `λ_max(L) ≤ 2 d_max`) finds them
        // from products alone.
        let top = 2.0 * scale;
        let v = three(3 * n, |x, y| {
            l.apply(graph, x, y);
            y.iter_mut().zip(x).for_each(|(yi, xi)| *yi = top * xi - *yi);
        });
        return (round(&v.0, n), v.1);
    }
    // L ⪰ 0 with eigenvalues as small as 0 (consistent data): a shift keeps the factor positive
    // definite, and larger shifts are tried if rounding makes a pivot non-positive.
    // The weights come scaled to a largest of 1 (`synchronize`), so `scale ≥ 1`; by the last try
    // the shift is far beyond `L`'s largest eigenvalue (`≤ 2 scale`).
    let mut shift = 1e-9 * scale.max(1.0);
    let mut factor = None;
    for _try in 0..8 {
        factor = pattern.factor(graph, &l, shift);
        if factor.is_some() {
            break;
        }
        shift *= 100.0;
    }
    let Some(factor) = factor else {
        // Unreachable for finite weights; a start at the identity keeps the call total.
        return (vec![DQuat::IDENTITY; n], 0);
    };
    let (v, steps) = three(3 * n, |x, y| {
        y.copy_from_slice(x);
        factor.solve(y, 1);
    });
    (round(&v, n), steps)
}

/// The top three eigenvectors of `apply`, one at a time, each run deflating the ones found: a
/// single Krylov sequence holds one vector of a repeated eigenvalue, and noise-free data make the
/// smallest eigenvalue of `L` triple. With the Lanczos steps taken.
fn three(dimension: usize, mut apply: impl FnMut(&[f64], &mut [f64])) -> (Vec<Vec<f64>>, usize) {
    let mut v: Vec<Vec<f64>> = Vec::new();
    let mut steps = 0;
    for _ in 0..3 {
        let ritz = lanczos::largest(dimension, &mut apply, &v, 1, 200, 1e-10);
        steps += ritz.steps;
        v.extend(ritz.vectors);
    }
    (v, steps)
}

/// Each node's rotation from the three eigenvectors `v` (`V = [v₀ v₁ v₂]`, 3n×3).
fn round(v: &[Vec<f64>], n: usize) -> Vec<DQuat> {
    if v.len() < 3 {
        // Lanczos returns a vector a run for finite input; this keeps the call total.
        return vec![DQuat::IDENTITY; n];
    }
    let block = |i: usize| {
        // Row r of V_i is (v₀, v₁, v₂)[3i + r]; the columns of V_iᵀ are those rows.
        DMat3::from_cols(
            DVec3::new(v[0][3 * i], v[1][3 * i], v[2][3 * i]),
            DVec3::new(v[0][3 * i + 1], v[1][3 * i + 1], v[2][3 * i + 1]),
            DVec3::new(v[0][3 * i + 2], v[1][3 * i + 2], v[2][3 * i + 2]),
        )
    };
    // V = Y O with det O = ±1: if most blocks are reflections, so is O; flipping one column of V
    // makes it a rotation.
    let reflections = (0..n).filter(|&i| block(i).determinant() < 0.0).count();
    let flip = if 2 * reflections > n {
        DMat3::from_diagonal(DVec3::new(-1.0, 1.0, 1.0))
    } else {
        DMat3::IDENTITY
    };
    // V_iᵀ = Oᵀ R_i: the nearest rotation is R_i up to the gauge Oᵀ.
    (0..n).map(|i| nearest_rotation(flip * block(i))).collect()
}

#[cfg(test)]
mod tests {
    use glam::{DMat3, DQuat, DVec3};

    use super::round;
    use crate::swarm::Random;

    /// The blocks of `V = Y O` for an orthogonal `O` with `det O = −1` are all reflections, and
    /// one column of `V` flipped makes them rotations: with 6 of 10 blocks `R_iᵀ O` (reflections)
    /// and 4 `R_iᵀ G` (rotations), the majority decides, and the six come out as the truth up to
    /// one gauge (`R_0ᵀ R_i` exact).
    #[test]
    fn the_majority_of_reflections_decides_the_flip() {
        let mut random = Random::new(12);
        let n = 10;
        let truth: Vec<DMat3> =
            (0..n).map(|_| DMat3::from_quat(random.unit_quaternion())).collect();
        let g = DMat3::from_quat(random.unit_quaternion());
        let o = DMat3::from_diagonal(DVec3::new(-1.0, 1.0, 1.0)) * g;
        let blocks: Vec<DMat3> =
            (0..n).map(|i| truth[i].transpose() * if i < 6 { o } else { g }).collect();
        // v[c][3i + r] = (V_i)_rc.
        let v: Vec<Vec<f64>> =
            (0..3).map(|c| (0..3 * n).map(|k| blocks[k / 3].col(c)[k % 3]).collect()).collect();
        let q: Vec<DQuat> = round(&v, n);
        let r: Vec<DMat3> = q.iter().map(|&q| DMat3::from_quat(q)).collect();
        for i in 1..6 {
            let (got, want) = (r[0].transpose() * r[i], truth[0].transpose() * truth[i]);
            assert!(got.abs_diff_eq(want, 1e-12), "{i}: {got:?} vs {want:?}");
        }
    }
}
