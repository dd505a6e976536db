//! The pose-graph problem with its translations eliminated (Rosen et al., IJRR 2019, §3 and
//! Appendix B; MATH.md, "Pose graphs"): for fixed rotations the cost is quadratic in the
//! translations, whose minimum leaves `f(R) = tr(R Q Rᵀ)` with
//!
//! `Q = L(G̃^ρ) + Σ̃ − Vᵀ L_τ† V`  (SE-Sync eqs. (19)–(24)),
//!
//! - `L(G̃^ρ)` (dn × dn) the rotational connection Laplacian with the weights `κ`: diagonal blocks
//!   `Σ κ_ij I_d`, block `(i, j)` = `−κ_ij R̃_ij`, block `(j, i)` its transpose;
//! - `L_τ` (n × n) the graph Laplacian of the weights `τ`;
//! - `V` (n × dn): for each edge, `τ_ij t̃_ijᵀ` added in row `j` and subtracted in row `i`, both in
//!   column block `i`;
//! - `Σ̃` (dn × dn) block-diagonal, `Σ̃_ii = Σ_{edges (i, ·)} τ_ij t̃_ij t̃_ijᵀ`;
//!
//! and the optimal translations `T = R Vᵀ L_τ†` (SE-Sync eq. (25)). `Q` is dense; it is applied,
//! never formed, through one sparse Cholesky factorisation of `L_τ` with node 0's row and column
//! left out (the anchored Laplacian is positive definite on a connected graph; `1ᵀ V = 0`, so its
//! solve gives `L_τ† V X` up to a constant row, which `Vᵀ` annihilates).
//!
//! The full matrix of SE-Sync's eq. (20), `M = [[L_τ, −V], [−Vᵀ, L(G̃^ρ) + Σ̃]]` (translations
//! first, node 0's left out), is sparse and its Schur complement on the rotation block is `Q`: a
//! Cholesky factorisation of `M` with a shift `B` on its rotation block factors `Q + B` without
//! forming it, and the rotation block of `M⁻¹ [0; Z]` is `(Q + B)⁻¹ Z`. The preconditioner
//! (`B = λ I`, SE-Sync §4.2.3) and the certificate (`B = −Λ − σ I`) use it.

use faer::sparse::Pair;

use super::stiefel::{Block, Stack};
use crate::sync::sparse::{Factor, Layout, Lower};

/// One measurement: `T̃_ij ≈ T_i⁻¹ T_j` with `R̃_ij` (`d × d`, unused entries 0), `t̃_ij` (z = 0 in
/// 2D), and its weights.
#[derive(Debug, Clone)]
pub(super) struct Edge {
    pub i: usize,
    pub j: usize,
    pub kappa: f64,
    pub tau: f64,
    pub rotation: Block,
    pub t: [f64; 3],
}

/// The eliminated problem: the data, `L_τ`'s factor and `M`'s pattern.
pub(super) struct Reduced {
    pub d: usize,
    pub n: usize,
    pub edges: Vec<Edge>,
    /// The largest diagonal entry of `L(G̃^ρ) + Σ̃`: the scale of `Q`, and of the tolerances.
    pub scale: f64,
    laplacian: Factor,
    /// [`Lower::fill`] of `L_τ` (node 0 left out): how much a sparse factorisation on the graph's
    /// pattern fills in.
    pub fill: f64,
    full: Lower,
    /// `M`'s listed values, the rotation block's shift entries 0.
    base: Vec<f64>,
    /// Where the shift entries start in `base`: for node `i`, `(a, b)` with `b ≤ a`, in order.
    shift_at: usize,
}

/// Node `k`'s translation row in the anchored matrices (node 0 is left out).
fn t_index(k: usize) -> Option<usize> {
    k.checked_sub(1)
}

impl Reduced {
    /// The problem of `edges` on `n ≥ 2` poses in dimension `d`, or `None` when `L_τ` (anchored)
    /// cannot be factored (weights so small beside others that it is singular in f64).
    pub fn new(d: usize, n: usize, edges: Vec<Edge>) -> Option<Reduced> {
        // L_τ with node 0 left out.
        let mut pairs = Vec::new();
        let mut values = Vec::new();
        let push = |pairs: &mut Vec<Pair<usize, usize>>, r: usize, c: usize| {
            let (row, col) = if r >= c { (r, c) } else { (c, r) };
            pairs.push(Pair { row, col });
        };
        for e in &edges {
            let (ti, tj) = (t_index(e.i), t_index(e.j));
            if let Some(ti) = ti {
                push(&mut pairs, ti, ti);
                values.push(e.tau);
            }
            if let Some(tj) = tj {
                push(&mut pairs, tj, tj);
                values.push(e.tau);
            }
            if let (Some(ti), Some(tj)) = (ti, tj) {
                push(&mut pairs, ti, tj);
                values.push(-e.tau);
            }
        }
        let laplacian_pairs = pairs.len();
        // n − 1 ≥ 1 translation rows; a node other than 0 with no edge cannot occur (connected).
        let pattern = Lower::new(n - 1, &pairs, Layout::Auto);
        let fill = pattern.fill();
        let laplacian = pattern.factor(&values[..laplacian_pairs])?;
        // M: the same L_τ entries, then −V's transpose below them, then the rotation block.
        let rot = |i: usize, a: usize| n - 1 + d * i + a;
        for e in &edges {
            for a in 0..d {
                if let Some(tj) = t_index(e.j) {
                    push(&mut pairs, rot(e.i, a), tj);
                    values.push(-e.tau * e.t[a]);
                }
                if let Some(ti) = t_index(e.i) {
                    push(&mut pairs, rot(e.i, a), ti);
                    values.push(e.tau * e.t[a]);
                }
            }
        }
        let mut diagonal = vec![[[0.0; 3]; 3]; n];
        for e in &edges {
            for a in 0..d {
                for b in 0..d {
                    push(&mut pairs, rot(e.i, a), rot(e.j, b));
                    values.push(-e.kappa * e.rotation[a][b]);
                    diagonal[e.i][a][b] += e.tau * e.t[a] * e.t[b];
                }
                diagonal[e.i][a][a] += e.kappa;
                diagonal[e.j][a][a] += e.kappa;
            }
        }
        let scale =
            diagonal.iter().flat_map(|block| (0..d).map(move |a| block[a][a])).fold(0.0, f64::max);
        for (i, block) in diagonal.iter().enumerate() {
            for a in 0..d {
                for b in 0..=a {
                    push(&mut pairs, rot(i, a), rot(i, b));
                    values.push(block[a][b]);
                }
            }
        }
        let shift_at = pairs.len();
        for i in 0..n {
            for a in 0..d {
                for b in 0..=a {
                    push(&mut pairs, rot(i, a), rot(i, b));
                    values.push(0.0);
                }
            }
        }
        let full = Lower::new(n - 1 + d * n, &pairs, Layout::Auto);
        Some(Reduced { d, n, edges, scale, laplacian, fill, full, base: values, shift_at })
    }

    /// `L_τ⁻¹ (V X)` with node 0's row held at 0 (`n × r`, column-major): the translations
    /// `Tᵀ = L_τ† V Rᵀ` shifted so that `t_0 = 0` when `X = Rᵀ`.
    pub fn translations(&self, x: &Stack) -> Vec<f64> {
        let (d, n, r) = (self.d, self.n, x.r);
        let mut vx = vec![0.0; n * r];
        for e in &self.edges {
            for c in 0..r {
                let tx: f64 = (0..d).map(|a| e.t[a] * x.at(d * e.i + a, c)).sum::<f64>() * e.tau;
                vx[c * n + e.j] += tx;
                vx[c * n + e.i] -= tx;
            }
        }
        // Node 0's row dropped, solved, and put back as 0.
        let mut reduced: Vec<f64> =
            (0..r).flat_map(|c| vx[c * n + 1..(c + 1) * n].iter().copied()).collect();
        self.laplacian.solve(&mut reduced, r);
        let mut z = vec![0.0; n * r];
        for c in 0..r {
            z[c * n + 1..(c + 1) * n].copy_from_slice(&reduced[c * (n - 1)..(c + 1) * (n - 1)]);
        }
        z
    }

    /// `Q X = L(G̃^ρ) X + Σ̃ X − Vᵀ L_τ† V X`.
    pub fn apply(&self, x: &Stack) -> Stack {
        // 3D at rank 3, where the trust region spends its time, compiled for its sizes (every
        // loop's bound a constant): in wasm, alternately, parking-garage took 253 against 284 ms,
        // sphere2500 310 against 317 ms, for 750 bytes of kli/sync gzipped. (The translations'
        // solve so compiled too changed nothing measurable.)
        match (self.d, x.r) {
            (3, 3) => self.apply_at(x, 3, 3),
            (d, r) => self.apply_at(x, d, r),
        }
    }

    /// [`Reduced::apply`] in dimension `d` at rank `r`.
    #[inline(always)]
    fn apply_at(&self, x: &Stack, d: usize, r: usize) -> Stack {
        let n = self.n;
        let z = self.translations(x);
        let mut out = Stack::zeros(d, n, r);
        for e in &self.edges {
            for c in 0..r {
                let xi: [f64; 3] =
                    std::array::from_fn(|a| if a < d { x.at(d * e.i + a, c) } else { 0.0 });
                let xj: [f64; 3] =
                    std::array::from_fn(|a| if a < d { x.at(d * e.j + a, c) } else { 0.0 });
                let tx: f64 = (0..d).map(|a| e.t[a] * xi[a]).sum();
                let dz = z[c * n + e.j] - z[c * n + e.i];
                for a in 0..d {
                    let rxj: f64 = (0..d).map(|b| e.rotation[a][b] * xj[b]).sum();
                    let rtxi: f64 = (0..d).map(|b| e.rotation[b][a] * xi[b]).sum();
                    // L(G̃^ρ): κ (x_i − R̃ x_j) on block i, κ (x_j − R̃ᵀ x_i) on block j.
                    *out.at_mut(d * e.i + a, c) += e.kappa * (xi[a] - rxj);
                    *out.at_mut(d * e.j + a, c) += e.kappa * (xj[a] - rtxi);
                    // Σ̃ X − Vᵀ Z: τ t̃ (t̃ · x_i) − τ t̃ (z_j − z_i) on block i.
                    *out.at_mut(d * e.i + a, c) += e.tau * e.t[a] * (tx - dz);
                }
            }
        }
        out
    }

    /// `F(X) = tr(Xᵀ Q X)` and `Q X`.
    pub fn cost(&self, x: &Stack) -> (f64, Stack) {
        let qx = self.apply(x);
        (x.dot(&qx), qx)
    }

    /// The Cholesky factor of `M` with `shift[i]` (symmetric, `d × d`) added to rotation block
    /// `i`'s diagonal block: it exists if and only if `Q + diag(shift)` is positive definite.
    pub fn factor_shifted(&self, shift: &[Block]) -> Option<Factor> {
        let mut values = self.base.clone();
        let mut k = self.shift_at;
        for block in shift {
            for a in 0..self.d {
                for b in 0..=a {
                    values[k] = 0.5 * (block[a][b] + block[b][a]);
                    k += 1;
                }
            }
        }
        self.full.factor(&values)
    }

    /// `(Q + diag(shift))⁻¹ Z`: the rotation block of `M_shift⁻¹ [0; Z]` for `M_shift`'s `factor`.
    pub fn solve_shifted(&self, factor: &Factor, z: &Stack) -> Stack {
        let (size, rows, r) = (self.n - 1 + z.rows(), z.rows(), z.r);
        let mut b = vec![0.0; size * r];
        for c in 0..r {
            b[c * size + self.n - 1..(c + 1) * size]
                .copy_from_slice(&z.data[c * rows..(c + 1) * rows]);
        }
        factor.solve(&mut b, r);
        let mut out = z.clone();
        for c in 0..r {
            out.data[c * rows..(c + 1) * rows]
                .copy_from_slice(&b[c * size + self.n - 1..(c + 1) * size]);
        }
        out
    }
}
