//! The product of Stiefel manifolds `St(d, r)ⁿ` on which SE-Sync's rank-`r` relaxation lives
//! (Rosen et al., IJRR 2019, §4.1, Problem 9; the geometry of Edelman, Arias and Smith 1998 and
//! Absil, Mahony and Sepulchre 2008, §3.6 and §4.1.1).
//!
//! SE-Sync writes a point as `Y = [Y_1 … Y_n]` (`r × dn`, each `Y_i` an `r × d` block with
//! orthonormal columns). Here it is stored transposed, `X = Yᵀ` (`dn × r`), the layout faer's
//! solves take: block `X_i = Y_iᵀ` is `d × r` with orthonormal rows, and at `r = d` on a rotation
//! estimate `X_i = R_iᵀ`. The cost is `F(X) = tr(Xᵀ Q X) = tr(Q YᵀY)`.
//!
//! - the tangent space at `X`: `X_i Ẋ_iᵀ + Ẋ_i X_iᵀ = 0` for every block; the orthogonal
//!   projection onto it, `Proj_X(Z)_i = Z_i − sym(Z_i X_iᵀ) X_i` (SE-Sync eq. (40), transposed);
//! - the multipliers `Λ_i = sym((Q X)_i X_iᵀ)`, `SymBlockDiag_d(Q YᵀY)` (SE-Sync eq. (41)), so that
//!   the Riemannian gradient is `2 Proj_X(Q X) = 2 (Q X − Λ X)` and the Riemannian Hessian
//!   `Hess F(X)[Ẋ] = 2 Proj_X(Q Ẋ − Λ Ẋ)` (SE-Sync eqs. (42)–(44));
//! - the retraction: each block of `X + Ẋ` replaced by its orthonormal polar factor
//!   `(A Aᵀ)^{-1/2} A` (the nearest point of `St(d, r)`, Absil et al. Example 4.1.3); for a
//!   tangent `Ẋ`, `A Aᵀ = I + Ẋ_i Ẋ_iᵀ ⪰ I`, so it is always defined;
//! - rounding to `SO(d)ⁿ` (SE-Sync Algorithm 2): the top `d` right singular vectors of `Y`, each
//!   block's determinant counted, one reflection if most are negative, then each block to its
//!   nearest rotation.

use faer::{Mat, MatRef, Side};
use glam::{DMat3, DQuat, DVec3};

use crate::sync::spectral::nearest_rotation;

/// A `d × d` block (`d ≤ 3`; unused entries 0).
pub(super) type Block = [[f64; 3]; 3];

/// `n` blocks of `d × r` stacked: a `dn × r` matrix, column-major.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Stack {
    pub d: usize,
    pub n: usize,
    pub r: usize,
    pub data: Vec<f64>,
}

impl Stack {
    pub fn zeros(d: usize, n: usize, r: usize) -> Stack {
        Stack { d, n, r, data: vec![0.0; d * n * r] }
    }

    /// The number of rows, `dn`.
    pub fn rows(&self) -> usize {
        self.d * self.n
    }

    pub fn at(&self, row: usize, col: usize) -> f64 {
        self.data[col * self.d * self.n + row]
    }

    pub fn at_mut(&mut self, row: usize, col: usize) -> &mut f64 {
        let rows = self.d * self.n;
        &mut self.data[col * rows + row]
    }

    /// The Frobenius inner product, the metric of the embedding (SE-Sync §4.1).
    pub fn dot(&self, other: &Stack) -> f64 {
        self.data.iter().zip(&other.data).map(|(a, b)| a * b).sum()
    }

    pub fn norm(&self) -> f64 {
        self.dot(self).sqrt()
    }

    /// `self += alpha · other`.
    pub fn axpy(&mut self, alpha: f64, other: &Stack) {
        self.data.iter_mut().zip(&other.data).for_each(|(a, b)| *a += alpha * b);
    }

    pub fn scaled(&self, alpha: f64) -> Stack {
        Stack { data: self.data.iter().map(|a| a * alpha).collect(), ..self.clone() }
    }

    pub fn as_mat(&self) -> MatRef<'_, f64> {
        MatRef::from_column_major_slice(&self.data, self.rows(), self.r)
    }

    /// The same matrix with `extra` zero columns appended (the next level of the staircase).
    pub fn widened(&self, extra: usize) -> Stack {
        let mut data = self.data.clone();
        data.resize(self.rows() * (self.r + extra), 0.0);
        Stack { r: self.r + extra, data, ..*self }
    }

    /// `A_i B_iᵀ` for block `i` of `self` (A) and `other` (B), `d × d`.
    pub fn block_product(&self, other: &Stack, i: usize) -> Block {
        let mut out = [[0.0; 3]; 3];
        for (a, row) in out.iter_mut().enumerate().take(self.d) {
            for (b, cell) in row.iter_mut().enumerate().take(self.d) {
                *cell = (0..self.r)
                    .map(|c| self.at(self.d * i + a, c) * other.at(self.d * i + b, c))
                    .sum();
            }
        }
        out
    }

    /// `self_i −= B_i X_i` for every block: `self − diag(B) X`.
    pub fn subtract_block_products(&mut self, blocks: &[Block], x: &Stack) {
        // Column by column over whole slices, `d` fixed for each loop: the trust region's
        // conjugate gradients call this three times a step (w20000: 8% of the solve).
        let rows = self.rows();
        for (out, x) in self.data.chunks_exact_mut(rows).zip(x.data.chunks_exact(rows)) {
            match self.d {
                2 => subtract_blocks::<2>(out, blocks, x),
                _ => subtract_blocks::<3>(out, blocks, x),
            }
        }
    }
}

/// `out_i −= B_i x_i` for every `D`-row block of one column.
fn subtract_blocks<const D: usize>(out: &mut [f64], blocks: &[Block], x: &[f64]) {
    for ((out, x), block) in out.chunks_exact_mut(D).zip(x.chunks_exact(D)).zip(blocks) {
        for (a, o) in out.iter_mut().enumerate() {
            let v: f64 = (0..D).map(|b| block[a][b] * x[b]).sum();
            *o -= v;
        }
    }
}

/// `sym(M) = (M + Mᵀ)/2`.
fn sym(m: Block) -> Block {
    std::array::from_fn(|a| std::array::from_fn(|b| 0.5 * (m[a][b] + m[b][a])))
}

/// `Λ_i = sym((Q X)_i X_iᵀ)` for every block (SE-Sync eq. (41)).
pub(super) fn multipliers(x: &Stack, qx: &Stack) -> Vec<Block> {
    (0..x.n).map(|i| sym(qx.block_product(x, i))).collect()
}

/// `Proj_X(Z)_i = Z_i − sym(Z_i X_iᵀ) X_i`.
pub(super) fn project(x: &Stack, z: &Stack) -> Stack {
    let blocks = multipliers(x, z);
    let mut out = z.clone();
    out.subtract_block_products(&blocks, x);
    out
}

/// The symmetric eigen-decomposition of a `d × d` block by faer: eigenvalues ascending, and the
/// eigenvectors as the columns of the second.
fn eigen(m: &Block, d: usize) -> Option<(Vec<f64>, Mat<f64>)> {
    let a = Mat::<f64>::from_fn(d, d, |r, c| m[r][c]);
    let e = a.self_adjoint_eigen(Side::Lower).ok()?;
    let s = e.S().column_vector();
    Some(((0..d).map(|k| s[k]).collect(), e.U().to_owned()))
}

/// `R_X(Ẋ)`: each block of `X + Ẋ` replaced by `(A Aᵀ)^{-1/2} A`.
pub(super) fn retract(x: &Stack, step: &Stack) -> Stack {
    let mut a = x.clone();
    a.axpy(1.0, step);
    let d = x.d;
    let mut out = a.clone();
    for i in 0..x.n {
        let gram = a.block_product(&a, i);
        let Some((values, u)) = eigen(&gram, d) else { continue };
        // (A Aᵀ)^{-1/2} = U diag(λ^{-1/2}) Uᵀ; λ ≥ 1 for a tangent step.
        let mut inverse_root = [[0.0; 3]; 3];
        for (r, row) in inverse_root.iter_mut().enumerate().take(d) {
            for (c, cell) in row.iter_mut().enumerate().take(d) {
                *cell = (0..d)
                    .map(|k| u[(r, k)] * u[(c, k)] / values[k].max(f64::MIN_POSITIVE).sqrt())
                    .sum();
            }
        }
        for col in 0..x.r {
            for (r, row) in inverse_root.iter().enumerate().take(d) {
                *out.at_mut(d * i + r, col) = (0..d).map(|k| row[k] * a.at(d * i + k, col)).sum();
            }
        }
    }
    out
}

/// The rotation `R_i` whose transpose is nearest block `i` (`d × d`, so `r = d`), as a unit
/// quaternion (about z in 2D): for `d = 3` by Bar-Itzhack's quaternion method
/// ([`nearest_rotation`]), for `d = 2` by the angle `atan2(B₀₁ − B₁₀, B₀₀ + B₁₁)` of `Bᵀ`.
pub(super) fn block_rotation(x: &Stack, i: usize) -> DQuat {
    let b = |r: usize, c: usize| x.at(x.d * i + r, c);
    if x.d == 2 {
        return DQuat::from_rotation_z((b(0, 1) - b(1, 0)).atan2(b(0, 0) + b(1, 1)));
    }
    // M = Bᵀ: column k of M is row k of B.
    let m = DMat3::from_cols(
        DVec3::new(b(0, 0), b(0, 1), b(0, 2)),
        DVec3::new(b(1, 0), b(1, 1), b(1, 2)),
        DVec3::new(b(2, 0), b(2, 1), b(2, 2)),
    );
    nearest_rotation(m)
}

/// `R` as a rank-`d` point: block `i` is `R_iᵀ`.
pub(super) fn from_rotations(d: usize, rotations: &[DQuat]) -> Stack {
    let mut x = Stack::zeros(d, rotations.len(), d);
    for (i, &q) in rotations.iter().enumerate() {
        let r = DMat3::from_quat(q);
        for a in 0..d {
            for c in 0..d {
                // (R_iᵀ)_ac = (R_i)_ca.
                *x.at_mut(d * i + a, c) = r.col(a)[c];
            }
        }
    }
    x
}

/// Every block replaced by its nearest rotation (`r = d`).
pub(super) fn to_rotations(x: &Stack) -> Vec<DQuat> {
    (0..x.n).map(|i| block_rotation(x, i)).collect()
}

/// SE-Sync's rounding (Algorithm 2): `Y = U Σ Vᵀ`, `R = Σ_d V_dᵀ = U_dᵀ Y`, i.e. `Rᵀ = X U_d` with
/// `U_d` the top `d` eigenvectors of `XᵀX = Y Yᵀ`; if fewer than half of the blocks have a
/// positive determinant, the last row of `R` is negated; then each block to `SO(d)`.
pub(super) fn round(x: &Stack) -> Vec<DQuat> {
    let (d, r) = (x.d, x.r);
    let gram = x.as_mat().transpose() * x.as_mat();
    let Ok(e) = gram.self_adjoint_eigen(Side::Lower) else {
        return vec![DQuat::IDENTITY; x.n];
    };
    let u = e.U();
    // Ascending eigenvalues: the top d are the last d columns, largest first.
    let mut projected = Stack::zeros(d, x.n, d);
    for k in 0..d {
        let column = r - 1 - k;
        for row in 0..x.rows() {
            *projected.at_mut(row, k) = (0..r).map(|c| x.at(row, c) * u[(c, column)]).sum();
        }
    }
    let positive = (0..x.n)
        .filter(|&i| {
            let b = |a: usize, c: usize| projected.at(d * i + a, c);
            let det = if d == 2 {
                b(0, 0) * b(1, 1) - b(0, 1) * b(1, 0)
            } else {
                DMat3::from_cols(
                    DVec3::new(b(0, 0), b(1, 0), b(2, 0)),
                    DVec3::new(b(0, 1), b(1, 1), b(2, 1)),
                    DVec3::new(b(0, 2), b(1, 2), b(2, 2)),
                )
                .determinant()
            };
            det > 0.0
        })
        .count();
    if 2 * positive < x.n {
        for row in 0..x.rows() {
            *projected.at_mut(row, d - 1) *= -1.0;
        }
    }
    to_rotations(&projected)
}
