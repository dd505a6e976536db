//! Riemannian Newton on `SO(d)ⁿ × ℝ^{dn}` for the pose-graph cost with its translations kept,
//! damped as Levenberg–Marquardt (Absil, Mahony and Sepulchre 2008, §6.2; Nielsen's damping
//! update, 1999): the rank-`d` level of the staircase, where every tight graph ends.
//!
//! The trust region works on the cost with the translations eliminated, `tr(Xᵀ Q X)`, whose `Q`
//! is dense: its Hessian can only be applied, so each step is conjugate gradients (parking-garage:
//! 5 steps, 171 products, each a triangular solve with `M`'s factor; slower there than GTSAM's
//! Levenberg–Marquardt). With the translations kept, `f` is a sum over the edges and its Hessian is
//! sparse, the graph's pattern in blocks of `p + d` (`p = d(d − 1)/2` rotation coordinates and the
//! `d` of a translation): one sparse Cholesky factorisation solves a step exactly, and a handful of
//! steps from the chordal start reach rounding (quadratic convergence).
//!
//! Coordinates at `(R, t)`: `R_i ← R_i exp([ω_i])` (`[ω]` = `Σ ω_k G_k`, `G_k` the generators of
//! `so(d)`), `t_i ← t_i + δ_i`; node 0 is held fixed (the gauge). `exp` is the exponential of the
//! bi-invariant metric, so the Hessian of `f` pulled back through it is the Riemannian Hessian.
//! On an edge `(i, j)`, with `A = R_j − R_i R̃_ij` and `b = t_j − t_i − R_i t̃_ij` at the point:
//!
//! - `∂A/∂ω_jk = R_j G_k`, `∂A/∂ω_ik = −R_i G_k R̃_ij`; `∂b/∂δ_j = I`, `∂b/∂δ_i = −I`,
//!   `∂b/∂ω_ik = −R_i G_k t̃_ij`;
//! - the gradient `2 Jᵀ W r` and the Gauss–Newton part `2 Jᵀ W J` (`W`: `κ` on `A`'s entries, `τ` on
//!   `b`'s);
//! - plus the second-order terms of `exp([ω]) = I + [ω] + ½ [ω]² + …`, with
//!   `S_kl = ½ (G_k G_l + G_l G_k)`: `2κ ⟨A, R_j S_kl⟩` in `ω_j`'s block,
//!   `−2κ ⟨A, R_i S_kl R̃_ij⟩ − 2τ ⟨b, R_i S_kl t̃_ij⟩` in `ω_i`'s.
//!
//! Each step solves `(H + μ D) δ = −g` (`D` the Gauss–Newton diagonal, Marquardt's scaling: radians
//! and metres weighed alike); `μ` starts at 0, Newton's step, grows where the factorisation fails
//! or a step raises `f`, and shrinks by Nielsen's factor when a step is taken. It stops when the
//! gradient is below the caller's tolerance or stops halving near it, or after
//! [`MAX_ITERATIONS`] steps; the point it returns is never worse than its start, and the trust
//! region and the certificate take it from there.

use faer::sparse::Pair;

use super::reduced::Reduced;
use super::sparse::{Layout, Lower};
use super::stiefel::{Block, Stack};

/// At most this many Newton steps (a tight graph from the chordal start takes a handful).
pub(super) const MAX_ITERATIONS: usize = 100;

/// Where the method stopped: the rotations as a rank-`d` point (`X_i = R_iᵀ`) and the steps taken.
pub(super) struct Refined {
    pub x: Stack,
    pub iterations: usize,
    /// Whether it ended at the tolerance or at rounding (not at a step it could not take, or at
    /// [`MAX_ITERATIONS`]): the trust region need not go on from there.
    pub converged: bool,
}

/// `so(d)`'s generators: `[e_x]×`, `[e_y]×`, `[e_z]×` in 3D; in 2D `[e_z]×`'s upper 2 × 2 block.
fn generators(d: usize) -> Vec<Block> {
    let z = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]];
    if d == 2 {
        return vec![z];
    }
    let x = [[0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];
    let y = [[0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]];
    vec![x, y, z]
}

pub(super) fn mul(a: &Block, b: &Block, d: usize) -> Block {
    let mut out = [[0.0; 3]; 3];
    for r in 0..d {
        for c in 0..d {
            out[r][c] = (0..d).map(|k| a[r][k] * b[k][c]).sum();
        }
    }
    out
}

fn times(a: &Block, v: &[f64; 3], d: usize) -> [f64; 3] {
    std::array::from_fn(|r| if r < d { (0..d).map(|k| a[r][k] * v[k]).sum() } else { 0.0 })
}

fn inner(a: &Block, b: &Block, d: usize) -> f64 {
    (0..d).flat_map(|r| (0..d).map(move |c| (r, c))).map(|(r, c)| a[r][c] * b[r][c]).sum()
}

/// `exp([ω])`: Rodrigues' formula in 3D, the rotation by `ω₀` in 2D.
pub(super) fn exp(omega: &[f64], d: usize) -> Block {
    if d == 2 {
        let (s, c) = omega[0].sin_cos();
        return [[c, -s, 0.0], [s, c, 0.0], [0.0; 3]];
    }
    let m = glam::DMat3::from_quat(glam::DQuat::from_scaled_axis(glam::DVec3::new(
        omega[0], omega[1], omega[2],
    )));
    std::array::from_fn(|r| std::array::from_fn(|c| m.col(c)[r]))
}

/// The Newton system's pattern: node `i ≥ 1`'s unknowns are rows `v (i − 1) …`, `v = p + d`.
pub(super) struct System {
    d: usize,
    pub p: usize,
    pub v: usize,
    lower: Lower,
    /// Where each free node's diagonal block (its lower triangle, row by row) starts in the values.
    diagonal_at: Vec<usize>,
    /// Where each edge's off-diagonal block starts (none when an end is node 0).
    edge_at: Vec<Option<usize>>,
    /// The positions of the diagonal entries in the values, row by row.
    pivots: Vec<usize>,
    len: usize,
}

impl System {
    pub(super) fn new(problem: &Reduced) -> System {
        let (d, n) = (problem.d, problem.n);
        let p = d * (d - 1) / 2;
        let v = p + d;
        let mut pairs = Vec::new();
        let mut diagonal_at = vec![0; n];
        let mut pivots = Vec::with_capacity(v * (n - 1));
        for i in 1..n {
            diagonal_at[i] = pairs.len();
            for s in 0..v {
                for t in 0..=s {
                    if s == t {
                        pivots.push(pairs.len());
                    }
                    pairs.push(Pair { row: v * (i - 1) + s, col: v * (i - 1) + t });
                }
            }
        }
        let edge_at = problem
            .edges
            .iter()
            .map(|e| {
                (e.i != 0 && e.j != 0).then(|| {
                    let at = pairs.len();
                    let (big, small) = (e.i.max(e.j), e.i.min(e.j));
                    for s in 0..v {
                        for t in 0..v {
                            pairs.push(Pair { row: v * (big - 1) + s, col: v * (small - 1) + t });
                        }
                    }
                    at
                })
            })
            .collect();
        let len = pairs.len();
        System {
            d,
            p,
            v,
            lower: Lower::new(v * (n - 1), &pairs, Layout::Blocks(v)),
            diagonal_at,
            edge_at,
            pivots,
            len,
        }
    }
}

#[cfg(test)]
impl System {
    /// `H x` for the Hessian whose listed values are `values` (its lower triangle mirrored).
    pub(super) fn apply(
        &self,
        values: &[f64],
        x: &[f64],
        n: usize,
        edges: &[super::reduced::Edge],
    ) -> Vec<f64> {
        let v = self.v;
        let mut y = vec![0.0; x.len()];
        let entry = |row: usize, col: usize, value: f64, y: &mut Vec<f64>| {
            y[row] += value * x[col];
            if row != col {
                y[col] += value * x[row];
            }
        };
        for i in 1..n {
            let mut at = self.diagonal_at[i];
            for s in 0..v {
                for t in 0..=s {
                    entry(v * (i - 1) + s, v * (i - 1) + t, values[at], &mut y);
                    at += 1;
                }
            }
        }
        for (k, e) in edges.iter().enumerate() {
            if let Some(mut at) = self.edge_at[k] {
                let (big, small) = (e.i.max(e.j), e.i.min(e.j));
                for s in 0..v {
                    for t in 0..v {
                        entry(v * (big - 1) + s, v * (small - 1) + t, values[at], &mut y);
                        at += 1;
                    }
                }
            }
        }
        y
    }
}

/// The poses' cost `f` (the module's sum, with the solver's weights).
pub(super) fn cost(problem: &Reduced, r: &[Block], t: &[[f64; 3]]) -> f64 {
    let d = problem.d;
    let mut f = 0.0;
    for e in &problem.edges {
        let rr = mul(&r[e.i], &e.rotation, d);
        let rt = times(&r[e.i], &e.t, d);
        for a in 0..d {
            for b in 0..d {
                f += e.kappa * (r[e.j][a][b] - rr[a][b]).powi(2);
            }
            f += e.tau * (t[e.j][a] - t[e.i][a] - rt[a]).powi(2);
        }
    }
    f
}

/// The gradient (node 0's left out) and the Hessian's listed values, and `D`, at `(r, t)`.
pub(super) fn model(
    system: &System,
    problem: &Reduced,
    r: &[Block],
    t: &[[f64; 3]],
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let (d, p, v) = (system.d, system.p, system.v);
    let n = problem.n;
    let g_k = generators(d);
    // S_kl = ½ (G_k G_l + G_l G_k).
    let s_kl: Vec<Vec<Block>> = (0..p)
        .map(|k| {
            (0..p)
                .map(|l| {
                    let (a, b) = (mul(&g_k[k], &g_k[l], d), mul(&g_k[l], &g_k[k], d));
                    std::array::from_fn(|x| std::array::from_fn(|y| 0.5 * (a[x][y] + b[x][y])))
                })
                .collect()
        })
        .collect();
    let mut gradient = vec![0.0; v * (n - 1)];
    let mut values = vec![0.0; system.len];
    let rows = d * d + d;
    for (k, e) in problem.edges.iter().enumerate() {
        let (ri, rj) = (&r[e.i], &r[e.j]);
        let rr = mul(ri, &e.rotation, d);
        let rt = times(ri, &e.t, d);
        // The residual r0 (A row by row, then b) and its Jacobian, columns (ω_i, δ_i, ω_j, δ_j).
        let mut residual = [0.0; 12];
        let mut weight = [0.0; 12];
        let mut jacobian = [[0.0; 12]; 12];
        for a in 0..d {
            for b in 0..d {
                residual[a * d + b] = rj[a][b] - rr[a][b];
                weight[a * d + b] = e.kappa;
            }
            residual[d * d + a] = t[e.j][a] - t[e.i][a] - rt[a];
            weight[d * d + a] = e.tau;
        }
        for (c, g) in g_k.iter().enumerate() {
            let dj = mul(rj, g, d);
            let di = mul(&mul(ri, g, d), &e.rotation, d);
            let dt = times(&mul(ri, g, d), &e.t, d);
            for a in 0..d {
                for b in 0..d {
                    jacobian[a * d + b][c] = -di[a][b];
                    jacobian[a * d + b][v + c] = dj[a][b];
                }
                jacobian[d * d + a][c] = -dt[a];
            }
        }
        for a in 0..d {
            jacobian[d * d + a][p + a] = -1.0;
            jacobian[d * d + a][v + p + a] = 1.0;
        }
        // 2 Jᵀ W J and 2 Jᵀ W r over each row's non-zero columns: A's rows touch ω_i and ω_j,
        // b's ω_i, δ_i and δ_j.
        let mut local = [[0.0; 12]; 12];
        let mut local_g = [0.0; 12];
        let on_a: Vec<usize> = (0..p).chain(v..v + p).collect();
        let on_b: Vec<usize> = (0..v).chain(v + p..2 * v).collect();
        for q in 0..rows {
            let columns = if q < d * d { &on_a } else { &on_b };
            let w = 2.0 * weight[q];
            for &x in columns {
                let wx = w * jacobian[q][x];
                local_g[x] += wx * residual[q];
                for &y in columns.iter().filter(|&&y| y <= x) {
                    local[x][y] += wx * jacobian[q][y];
                }
            }
        }
        for x in 0..2 * v {
            for y in 0..x {
                local[y][x] = local[x][y];
            }
        }
        let a_block: Block = std::array::from_fn(|x| {
            std::array::from_fn(|y| if x < d && y < d { residual[x * d + y] } else { 0.0 })
        });
        let b_vec: [f64; 3] =
            std::array::from_fn(|x| if x < d { residual[d * d + x] } else { 0.0 });
        for x in 0..p {
            for y in 0..p {
                let s = &s_kl[x][y];
                local[v + x][v + y] += 2.0 * e.kappa * inner(&a_block, &mul(rj, s, d), d);
                let ris = mul(ri, s, d);
                let ris_t = times(&ris, &e.t, d);
                local[x][y] -= 2.0 * e.kappa * inner(&a_block, &mul(&ris, &e.rotation, d), d)
                    + 2.0 * e.tau * (0..d).map(|a| b_vec[a] * ris_t[a]).sum::<f64>();
            }
        }
        // Scatter: the gradient and the diagonal blocks of the free ends, then the block (i, j).
        for (end, offset) in [(e.i, 0), (e.j, v)] {
            if end == 0 {
                continue;
            }
            for s in 0..v {
                gradient[v * (end - 1) + s] += local_g[offset + s];
            }
            let mut at = system.diagonal_at[end];
            for s in 0..v {
                for t in 0..=s {
                    values[at] += local[offset + s][offset + t];
                    at += 1;
                }
            }
        }
        if let Some(mut at) = system.edge_at[k] {
            let (big, small) = if e.i > e.j { (0, v) } else { (v, 0) };
            for s in 0..v {
                for t in 0..v {
                    values[at] += local[big + s][small + t];
                    at += 1;
                }
            }
        }
    }
    let diagonal = system.pivots.iter().map(|&at| values[at]).collect();
    (gradient, values, diagonal)
}

/// The damping after a refused factorisation or a rejected step (Nielsen): `μ ← max(νμ, 10⁻¹²)`
/// and `ν ← 2ν`.
fn grown(mu: f64, nu: f64) -> (f64, f64) {
    ((mu * nu).max(1e-12), 2.0 * nu)
}

/// Newton's method from the rotations of the rank-`d` point `x` (the translations optimal for
/// them), until the gradient's norm is below `tolerance`, or rounding ends it.
pub(super) fn refine(
    problem: &Reduced,
    x: &Stack,
    tolerance: f64,
    step_begins: &mut dyn FnMut(usize),
) -> Refined {
    let (d, n) = (problem.d, problem.n);
    let system = System::new(problem);
    let mut r: Vec<Block> = (0..n)
        .map(|i| {
            std::array::from_fn(|a| {
                std::array::from_fn(|c| if a < d && c < d { x.at(d * i + c, a) } else { 0.0 })
            })
        })
        .collect();
    let mut t = translations(problem, &r);
    let mut f = cost(problem, &r, &t);
    // f's rounding: 4 ulps a term.
    let noise = |f: f64| 4.0 * f64::EPSILON * f.abs() * (problem.edges.len() as f64).sqrt();
    let (mut mu, mut nu) = (0.0, 2.0);
    let mut iterations = 0;
    let mut last = f64::INFINITY;
    let converged = loop {
        if iterations >= MAX_ITERATIONS {
            break false;
        }
        let (g, values, diagonal) = model(&system, problem, &r, &t);
        let size = g.iter().map(|x| x * x).sum::<f64>().sqrt();
        if !size.is_finite() {
            break false;
        }
        // Rounding has the last word: the gradient stopped halving, near the tolerance.
        if size <= tolerance || (size > 0.5 * last && size < 1e3 * tolerance) {
            break true;
        }
        last = size;
        iterations += 1;
        step_begins(iterations);
        let mut taken = None;
        // At most ~60 doublings of μ: from 1e-12 to 1e6.
        for _ in 0..64 {
            let mut shifted = values.clone();
            for (&at, &dk) in system.pivots.iter().zip(&diagonal) {
                shifted[at] += mu * dk;
            }
            let Some(factor) = system.lower.factor(&shifted) else {
                (mu, nu) = grown(mu, nu);
                continue;
            };
            let mut step: Vec<f64> = g.iter().map(|x| -x).collect();
            factor.solve(&mut step, 1);
            let mut r_trial = r.clone();
            for i in 1..n {
                let at = system.v * (i - 1);
                r_trial[i] = mul(&r[i], &exp(&step[at..at + system.p], d), d);
            }
            // The step's rotations with their own optimal translations: never worse than the
            // step's translations, and the ω part of the step is then Newton's step on the cost
            // with the translations eliminated (the Schur complement of H on the rotations is
            // that cost's Hessian where ∂f/∂t = 0), quadratically convergent where the
            // translations' own steps, through a long chain, were not.
            let t_trial = translations(problem, &r_trial);
            let f_trial = cost(problem, &r_trial, &t_trial);
            // The damped model's decrease, ½ (μ δᵀDδ − gᵀδ) > 0.
            let damped: f64 = (0..step.len()).map(|k| diagonal[k] * step[k] * step[k]).sum();
            let slope: f64 = g.iter().zip(&step).map(|(a, b)| a * b).sum();
            let predicted = 0.5 * (mu * damped - slope);
            let change = f - f_trial;
            // A change within f's rounding is judged by the model.
            let rho = if change.abs() <= noise(f) { 1.0 } else { change / predicted };
            if rho.is_finite() && rho > 0.0 {
                taken = Some(predicted <= noise(f));
                (r, t, f) = (r_trial, t_trial, f_trial);
                // A step the model foretold within 10% is followed by Newton's own: damping
                // would only slow it where the Hessian is ill-conditioned (a long chain's
                // translations), which μ D weighs most.
                mu = if (rho - 1.0).abs() < 0.1 {
                    0.0
                } else {
                    mu * (1.0_f64 / 3.0).max(1.0 - (2.0 * rho - 1.0).powi(3))
                };
                nu = 2.0;
                break;
            }
            (mu, nu) = grown(mu, nu);
        }
        match taken {
            // A step the model said would lower f by no more than its rounding: the last.
            Some(true) => break true,
            Some(false) => {}
            None => break false,
        }
    };
    Refined { x: point(d, &r), iterations, converged }
}

/// The rotations as a rank-`d` point: block `i` is `R_iᵀ`.
fn point(d: usize, r: &[Block]) -> Stack {
    let mut x = Stack::zeros(d, r.len(), d);
    for (i, ri) in r.iter().enumerate() {
        for a in 0..d {
            for c in 0..d {
                *x.at_mut(d * i + a, c) = ri[c][a];
            }
        }
    }
    x
}

/// The translations that minimise `f` for the rotations `r` (`t_0 = 0`).
fn translations(problem: &Reduced, r: &[Block]) -> Vec<[f64; 3]> {
    let (d, n) = (problem.d, problem.n);
    let z = problem.translations(&point(d, r));
    (0..n).map(|k| std::array::from_fn(|a| if a < d { z[a * n + k] } else { 0.0 })).collect()
}
