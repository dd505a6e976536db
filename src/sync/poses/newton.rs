//! Riemannian Newton on the pose-graph cost with its translations kept, damped as
//! Levenberg–Marquardt (Absil, Mahony and Sepulchre 2008, §6.2; Nielsen's damping update, 1999),
//! at rank `r ≤ 3` where `St(d, r)` has no directions that leave the cost unchanged (`r ≤ d + 1`):
//! the pose graphs of the plane at ranks 2 and 3, and 3D graphs at rank 3 where they fill in
//! little (`NEWTON_FILL_3D`, in the parent module).
//!
//! The trust region works on the cost with the translations eliminated, `tr(Xᵀ Q X)`, whose `Q`
//! is dense: its Hessian can only be applied, so each step is conjugate gradients (city10000: 5
//! steps, each a few dozen triangular solves with `M`'s factor). With the translations kept, `f`
//! is a sum over the edges and its Hessian is sparse, the graph's pattern in blocks of `p + r` (`p
//! = r(r − 1)/2` rotation coordinates and the `r` of a translation): one sparse Cholesky
//! factorisation solves a step exactly, and a handful of steps from the chordal start reach
//! rounding (quadratic convergence).
//!
//! SE-Sync's rank-`r` problem with its translations (Rosen et al., IJRR 2019, Problem 4 relaxed
//! as in §4.1): each pose is `Y_i` (`r × d`, orthonormal columns: `X_i = Y_iᵀ`; at `r = d` a
//! rotation) and `t_i ∈ ℝʳ`, and `f = Σ κ_ij ‖Y_j − Y_i R̃_ij‖²_F + τ_ij ‖t_j − t_i − Y_i t̃_ij‖²`.
//! Coordinates at `(Y, t)`: `Y_i ← exp([Ω_i]) Y_i` (`[Ω]` = `Σ Ω_k G_k`, `G_k` the generators of
//! `so(r)`; `O(r)` moves `St(d, r)` onto itself, and at `r ≤ d + 1` no `[Ω] ≠ 0` fixes `Y_i`),
//! `t_i ← t_i + δ_i`; node 0 is held fixed (the gauge). `exp` is the exponential of the
//! bi-invariant metric, so the Hessian of `f` pulled back through it is the Riemannian Hessian at
//! a critical point. On an edge `(i, j)`, with `A = Y_j − Y_i R̃_ij` and `b = t_j − t_i − Y_i t̃_ij`
//! at the point:
//!
//! - `∂A/∂Ω_jk = G_k Y_j`, `∂A/∂Ω_ik = −G_k Y_i R̃_ij`; `∂b/∂δ_j = I`, `∂b/∂δ_i = −I`,
//!   `∂b/∂Ω_ik = −G_k Y_i t̃_ij`;
//! - the gradient `2 Jᵀ W r` and the Gauss–Newton part `2 Jᵀ W J` (`W`: `κ` on `A`'s entries, `τ` on
//!   `b`'s);
//! - plus the second-order terms of `exp([Ω]) = I + [Ω] + ½ [Ω]² + …`, with
//!   `S_kl = ½ (G_k G_l + G_l G_k)`: `2κ ⟨A, S_kl Y_j⟩` in `Ω_j`'s block,
//!   `−2κ ⟨A, S_kl Y_i R̃_ij⟩ − 2τ ⟨b, S_kl Y_i t̃_ij⟩` in `Ω_i`'s.
//!
//! Each step solves `(H + μ D) δ = −g` (`D` the Gauss–Newton diagonal, Marquardt's scaling: radians
//! and metres weighed alike); `μ` starts at 0, Newton's step, grows by Nielsen's rule where the
//! factorisation fails or a step raises `f` even halved five times (a backtracking line search:
//! each trial a rotation update, the translations and `f`, cheap beside a factorisation), and
//! shrinks by Nielsen's factor when a step is taken, to 0 when the model foretold the step, or
//! bettered it, to within a quarter. After each step the translations are solved afresh for the new
//! rotations. It stops when the gradient is below the caller's tolerance or stops halving near
//! it, after a step whose predicted decrease is within `f`'s rounding, or after
//! [`MAX_ITERATIONS`] steps; the point it returns is never worse than its start, and the trust
//! region and the certificate take it from there.

use faer::sparse::Pair;

use super::reduced::Reduced;
use super::stiefel::{Block, Stack};
use crate::sync::sparse::{Layout, Lower};

/// At most this many Newton steps (a tight graph from the chordal start takes a handful).
pub(super) const MAX_ITERATIONS: usize = 100;

/// Where the method stopped: the point (`X_i = Y_iᵀ`) and the steps taken.
pub(super) struct Refined {
    pub x: Stack,
    pub iterations: usize,
    /// Whether it ended at the tolerance or at rounding (not at a step it could not take, or at
    /// [`MAX_ITERATIONS`]): the trust region need not go on from there.
    pub converged: bool,
}

/// Whether Newton's method applies at rank `rank` in dimension `d` (the module's documentation).
pub(super) fn applies(d: usize, rank: usize) -> bool {
    rank <= 3 && rank <= d + 1
}

/// `so(r)`'s generators: `[e_x]×`, `[e_y]×`, `[e_z]×` for `r = 3`; for `r = 2` `[e_z]×`'s upper
/// 2 × 2 block.
fn generators(r: usize) -> Vec<Block> {
    let z = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]];
    if r == 2 {
        return vec![z];
    }
    let x = [[0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];
    let y = [[0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]];
    vec![x, y, z]
}

/// The `m × n` product of `a` (`m × k`) and `b` (`k × n`).
#[inline(always)]
fn mul(a: &Block, b: &Block, (m, k, n): (usize, usize, usize)) -> Block {
    let mut out = [[0.0; 3]; 3];
    for r in 0..m {
        for c in 0..n {
            out[r][c] = (0..k).map(|l| a[r][l] * b[l][c]).sum();
        }
    }
    out
}

/// `a v` for `a` of `m × k`.
#[inline(always)]
fn times(a: &Block, v: &[f64; 3], (m, k): (usize, usize)) -> [f64; 3] {
    std::array::from_fn(|r| if r < m { (0..k).map(|l| a[r][l] * v[l]).sum() } else { 0.0 })
}

/// `exp([Ω])` (`r × r`): Rodrigues' formula for `r = 3`, the rotation by `Ω₀` for `r = 2`.
pub(super) fn exp(omega: &[f64], r: usize) -> Block {
    if r == 2 {
        let (s, c) = omega[0].sin_cos();
        return [[c, -s, 0.0], [s, c, 0.0], [0.0; 3]];
    }
    let m = glam::DMat3::from_quat(glam::DQuat::from_scaled_axis(glam::DVec3::new(
        omega[0], omega[1], omega[2],
    )));
    std::array::from_fn(|a| std::array::from_fn(|c| m.col(c)[a]))
}

/// The Newton system's pattern at rank `r`: node `i ≥ 1`'s unknowns are rows `v (i − 1) …`,
/// `v = p + r`.
pub(super) struct System {
    d: usize,
    pub r: usize,
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
    pub(super) fn new(problem: &Reduced, r: usize) -> System {
        let (d, n) = (problem.d, problem.n);
        let p = r * (r - 1) / 2;
        let v = p + r;
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
            r,
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
        edges: &[super::reduced::Edge],
    ) -> Vec<f64> {
        let v = self.v;
        let n = self.diagonal_at.len();
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

/// The cost `f` at rank `r` (the module's sum, with the solver's weights): `y[i]` is `Y_i`
/// (`r × d`), `t[i]` is `t_i` (`r`).
pub(super) fn cost(problem: &Reduced, r: usize, y: &[Block], t: &[[f64; 3]]) -> f64 {
    let d = problem.d;
    let mut f = 0.0;
    for e in &problem.edges {
        let yr = mul(&y[e.i], &e.rotation, (r, d, d));
        let yt = times(&y[e.i], &e.t, (r, d));
        for a in 0..r {
            for b in 0..d {
                f += e.kappa * (y[e.j][a][b] - yr[a][b]).powi(2);
            }
            f += e.tau * (t[e.j][a] - t[e.i][a] - yt[a]).powi(2);
        }
    }
    f
}

/// The gradient (node 0's left out), the Hessian's listed values, and `D` (the Gauss–Newton
/// diagonal), at `(y, t)`.
pub(super) fn model(
    system: &System,
    problem: &Reduced,
    y: &[Block],
    t: &[[f64; 3]],
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    // Each rank Newton is used at compiled for its own sizes, every loop's bound a constant: in
    // wasm w20000 took 3.6–4.0 s against 4.0–4.4 s, w10000 623 against 684 ms, for 7 KB more of
    // kli/sync gzipped (+2.7%); 3D's rank 3, parking-garage's whole solve 255–263 against
    // 206–225 ms. Other sizes (the tests' `r < d`) take the general code.
    match (system.r, system.d) {
        (2, 2) => assemble(system, problem, y, t, 2, 2),
        (3, 2) => assemble(system, problem, y, t, 3, 2),
        (3, 3) => assemble(system, problem, y, t, 3, 3),
        (r, d) => assemble(system, problem, y, t, r, d),
    }
}

/// [`model`] at rank `r` in dimension `d`.
#[inline(always)]
fn assemble(
    system: &System,
    problem: &Reduced,
    y: &[Block],
    t: &[[f64; 3]],
    r: usize,
    d: usize,
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let p = r * (r - 1) / 2;
    let v = p + r;
    let n = problem.n;
    let square = (r, r, r);
    let g_k = generators(r);
    // S_kl = ½ (G_k G_l + G_l G_k).
    let s_kl: Vec<Vec<Block>> = (0..p)
        .map(|k| {
            (0..p)
                .map(|l| {
                    let (a, b) = (mul(&g_k[k], &g_k[l], square), mul(&g_k[l], &g_k[k], square));
                    std::array::from_fn(|x| std::array::from_fn(|z| 0.5 * (a[x][z] + b[x][z])))
                })
                .collect()
        })
        .collect();
    let mut gradient = vec![0.0; v * (n - 1)];
    let mut scale = vec![0.0; v * (n - 1)];
    let mut values = vec![0.0; system.len];
    // A's r·d entries row by row, then b's r.
    let rows = r * d + r;
    let on_a: Vec<usize> = (0..p).chain(v..v + p).collect();
    let on_b: Vec<usize> = (0..v).chain(v + p..2 * v).collect();
    for (k, e) in problem.edges.iter().enumerate() {
        let (yi, yj) = (&y[e.i], &y[e.j]);
        let yr = mul(yi, &e.rotation, (r, d, d));
        let yt = times(yi, &e.t, (r, d));
        // The residual (A, then b) and its Jacobian, columns (Ω_i, δ_i, Ω_j, δ_j).
        let mut residual = [0.0; 12];
        let mut weight = [0.0; 12];
        let mut jacobian = [[0.0; 12]; 12];
        for a in 0..r {
            for b in 0..d {
                residual[a * d + b] = yj[a][b] - yr[a][b];
                weight[a * d + b] = e.kappa;
            }
            residual[r * d + a] = t[e.j][a] - t[e.i][a] - yt[a];
            weight[r * d + a] = e.tau;
        }
        for (c, g) in g_k.iter().enumerate() {
            let dj = mul(g, yj, (r, r, d));
            let gi = mul(g, yi, (r, r, d));
            let di = mul(&gi, &e.rotation, (r, d, d));
            let dt = times(&gi, &e.t, (r, d));
            for a in 0..r {
                for b in 0..d {
                    jacobian[a * d + b][c] = -di[a][b];
                    jacobian[a * d + b][v + c] = dj[a][b];
                }
                jacobian[r * d + a][c] = -dt[a];
            }
        }
        for a in 0..r {
            jacobian[r * d + a][p + a] = -1.0;
            jacobian[r * d + a][v + p + a] = 1.0;
        }
        // 2 Jᵀ W J and 2 Jᵀ W r over each row's non-zero columns: A's rows touch Ω_i and Ω_j,
        // b's Ω_i, δ_i and δ_j.
        let mut local = [[0.0; 12]; 12];
        let mut local_g = [0.0; 12];
        for q in 0..rows {
            let columns = if q < r * d { &on_a } else { &on_b };
            let w = 2.0 * weight[q];
            for &x in columns {
                let wx = w * jacobian[q][x];
                local_g[x] += wx * residual[q];
                for &z in columns.iter().filter(|&&z| z <= x) {
                    local[x][z] += wx * jacobian[q][z];
                }
            }
        }
        for x in 0..2 * v {
            for z in 0..x {
                local[z][x] = local[x][z];
            }
        }
        // D, the damping's scale: the Gauss–Newton diagonal, positive, where the second-order
        // terms below may make H's own diagonal negative (then no μ D would make H + μ D
        // positive definite).
        for (end, offset) in [(e.i, 0), (e.j, v)] {
            if end != 0 {
                for s in 0..v {
                    scale[v * (end - 1) + s] += local[offset + s][offset + s];
                }
            }
        }
        for x in 0..p {
            for z in 0..p {
                let s = &s_kl[x][z];
                let sj = mul(s, yj, (r, r, d));
                let si = mul(s, yi, (r, r, d));
                let sir = mul(&si, &e.rotation, (r, d, d));
                let sit = times(&si, &e.t, (r, d));
                let (mut on_j, mut on_i) = (0.0, 0.0);
                for a in 0..r {
                    for b in 0..d {
                        on_j += residual[a * d + b] * sj[a][b];
                        on_i += e.kappa * residual[a * d + b] * sir[a][b];
                    }
                    on_i += e.tau * residual[r * d + a] * sit[a];
                }
                local[v + x][v + z] += 2.0 * e.kappa * on_j;
                local[x][z] -= 2.0 * on_i;
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
    (gradient, values, scale)
}

/// The least damping (`μ` relative to `D`, the Gauss–Newton diagonal).
const LEAST_DAMPING: f64 = 1e-12;

/// How often a rejected step is halved before `μ` grows: down to 1/32 of it. Near the saddle the
/// staircase escaped from (w20000 at rank 3), Newton's own step, and the lightly damped ones,
/// overshoot along directions of little curvature, where a shorter step of the same direction
/// lowers `f`; each halving costs the translations and `f` (4 ms there), a growth of `μ` another
/// factorisation (100 ms).
pub(super) const HALVINGS: usize = 5;

/// The damping after a refused factorisation or a step that raised `f` even halved: from Newton's
/// own step (`μ = 0`) a tenth of `factored`, the last damping with which a step was taken (the
/// least if none was), rather than up from the least again (w20000 at rank 3: five factorisations
/// refused or steps rejected a step); then, while no damped step has been taken on this level
/// (`factored = 0`, nothing known of the scale that works), a hundredfold each time; after that
/// Nielsen's `μ ← max(νμ, least)`, `ν ← 2ν`.
///
/// The hundredfold probe: Nielsen's growth from the least took 5 to 9 refused factorisations to
/// reach the first that worked at the start of w20000's three levels (1e-9 to 7e-2; a refusal
/// costs nearly a factorisation, 23 ms natively at rank 3), the probe 2 to 5: natively w20000
/// 2.52 → 2.39 s, w10000 462 → 438 ms, parking-garage 140 → 131 ms, and 12 synthetic plane
/// graphs of 500–2,000 poses at high noise equal or faster (one 559 → 453 ms), every answer the
/// same. (Tenfold after every refusal, Marquardt's factor, was tried: on such synthetic graphs it
/// left `μ` stuck a step above what factors, each step then damped too much: one took 1.4 s
/// against 0.5 s. The probe ends at the first step taken.)
pub(super) fn grown(mu: f64, nu: f64, factored: f64) -> (f64, f64) {
    if mu == 0.0 {
        return ((factored / 10.0).max(LEAST_DAMPING), 2.0);
    }
    if factored == 0.0 {
        return (mu * 100.0, nu);
    }
    ((mu * nu).max(LEAST_DAMPING), 2.0 * nu)
}

/// The decrease `m(0) − m(αδ)` of Newton's model `m(δ) = f + gᵀδ + ½ δᵀHδ` along the damped step
/// `δ`, `(H + μD) δ = −g`, from its `δᵀDδ` (`damped`) and `gᵀδ` (`slope`): with `δᵀHδ = −gᵀδ −
/// μ δᵀDδ`, `α (½ α μ δᵀDδ − (1 − ½ α) gᵀδ)`; at `α = 1`, `½ (μ δᵀDδ − gᵀδ)` > 0.
pub(super) fn decrease(alpha: f64, mu: f64, damped: f64, slope: f64) -> f64 {
    alpha * (0.5 * alpha * mu * damped - (1.0 - 0.5 * alpha) * slope)
}

/// Whether a trial with this `ρ` (its change in `f` over the model's) is taken: it lowered `f`.
pub(super) fn lowers(rho: f64) -> bool {
    rho.is_finite() && rho > 0.0
}

/// A backtracking line search along a step: `trial(α)` at `α = 1, ½, ¼, …` until one [`lowers`]
/// `f` or the step has been halved [`HALVINGS`] times; the last trial, its `ρ` and the halvings.
pub(super) fn backtrack<T>(mut trial: impl FnMut(f64) -> (T, f64)) -> (T, f64, usize) {
    let mut alpha = 1.0;
    let mut halvings = 0;
    loop {
        let (out, rho) = trial(alpha);
        if lowers(rho) || halvings == HALVINGS {
            return (out, rho, halvings);
        }
        alpha *= 0.5;
        halvings += 1;
    }
}

/// Whether a step taken ends the method: Newton's own (`μ = 0`, not halved) whose model said it
/// would lower `f` by no more than `f`'s rounding, `noise`. A damped or halved step predicts little
/// because `μ` or the halving held it back, not because `f` has nothing left to give.
pub(super) fn last_step(mu: f64, halvings: usize, predicted: f64, noise: f64) -> bool {
    mu == 0.0 && halvings == 0 && predicted <= noise
}

/// The damping after a step taken with `ρ`: a step the model foretold, or bettered, to within a
/// quarter is followed by Newton's own (`μ = 0`; Marquardt's threshold for good agreement), since
/// Nielsen's factor, a third at best, kept `μD` weighing on a long chain's ill-conditioned
/// directions for many steps (and with "within 10%" instead w20000 took 3.7 s natively against
/// 3.4 s: its damped steps from the chordal start do 10–30% better than foretold); otherwise
/// Nielsen's `μ · max(⅓, 1 − (2ρ − 1)³)`, whose floor of a third is then never reached (at `ρ ≤
/// 0.75` the factor is at least 0.875).
pub(super) fn damping_after(mu: f64, rho: f64) -> f64 {
    if rho > 0.75 { 0.0 } else { mu * (1.0 - (2.0 * rho - 1.0).powi(3)) }
}

/// Newton's method from the point `x` (the translations optimal for it), at its rank, which
/// [`applies`], until the gradient's norm is below `tolerance`, or rounding ends it.
pub(super) fn refine(
    problem: &Reduced,
    x: &Stack,
    tolerance: f64,
    step_begins: &mut dyn FnMut(usize),
) -> Refined {
    let (d, n, r) = (problem.d, problem.n, x.r);
    let system = System::new(problem, r);
    let mut y = blocks(x);
    let mut t = translations(problem, &y, r);
    let mut f = cost(problem, r, &y, &t);
    // f's rounding: 4 ulps a term.
    let noise = |f: f64| 4.0 * f64::EPSILON * f.abs() * (problem.edges.len() as f64).sqrt();
    let (mut mu, mut nu) = (0.0, 2.0);
    // The last damping > 0 with which a step was taken.
    let mut factored: f64 = 0.0;
    let mut iterations = 0;
    let mut last = f64::INFINITY;
    // Each factorisation's values, handed on to the next (`Lower::factor_in`).
    let mut storage = Vec::new();
    // The Hessian's values with the damping on its diagonal, made afresh for each μ.
    let mut shifted = vec![0.0; system.len];
    let converged = loop {
        if iterations >= MAX_ITERATIONS {
            break false;
        }
        let (g, values, diagonal) = model(&system, problem, &y, &t);
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
        // At most 64 growths of μ (ν doubling each time, so far beyond any scale).
        for _ in 0..64 {
            shifted.copy_from_slice(&values);
            for (&at, &dk) in system.pivots.iter().zip(&diagonal) {
                shifted[at] += mu * dk;
            }
            let Some(factor) = system.lower.factor_in(&shifted, &mut storage) else {
                (mu, nu) = grown(mu, nu, factored);
                continue;
            };
            let mut step: Vec<f64> = g.iter().map(|x| -x).collect();
            factor.solve(&mut step, 1);
            storage = factor.into_storage();
            let damped: f64 = (0..step.len()).map(|k| diagonal[k] * step[k] * step[k]).sum();
            let slope: f64 = g.iter().zip(&step).map(|(a, b)| a * b).sum();
            let ((y_trial, t_trial, f_trial, predicted), rho, halvings) = backtrack(|alpha| {
                let mut y_trial = y.clone();
                let mut omega = vec![0.0; system.p];
                for i in 1..n {
                    let at = system.v * (i - 1);
                    for (o, s) in omega.iter_mut().zip(&step[at..at + system.p]) {
                        *o = alpha * s;
                    }
                    y_trial[i] = mul(&exp(&omega, r), &y[i], (r, r, d));
                }
                // The step's rotations with their own optimal translations: never worse than the
                // step's translations, and the Ω part of the step is then Newton's step on the
                // cost with the translations eliminated (the Schur complement of H on the
                // rotations is that cost's Hessian where ∂f/∂t = 0), quadratically convergent
                // where the translations' own steps, through a long chain, were not.
                let t_trial = translations(problem, &y_trial, r);
                let f_trial = cost(problem, r, &y_trial, &t_trial);
                let predicted = decrease(alpha, mu, damped, slope);
                let change = f - f_trial;
                // A change within f's rounding is judged by the model.
                let rho = if change.abs() <= noise(f) { 1.0 } else { change / predicted };
                ((y_trial, t_trial, f_trial, predicted), rho)
            });
            if lowers(rho) {
                taken = Some(last_step(mu, halvings, predicted, noise(f)));
                (y, t, f) = (y_trial, t_trial, f_trial);
                if mu > 0.0 {
                    factored = mu;
                }
                mu = damping_after(mu, rho);
                nu = 2.0;
                break;
            }
            (mu, nu) = grown(mu, nu, factored);
        }
        match taken {
            // A step the model said would lower f by no more than its rounding: the last.
            Some(true) => break true,
            Some(false) => {}
            None => break false,
        }
    };
    Refined { x: point(d, r, &y), iterations, converged }
}

/// Each block `Y_i = X_iᵀ` of `x` (`r × d`).
pub(super) fn blocks(x: &Stack) -> Vec<Block> {
    let (d, r) = (x.d, x.r);
    (0..x.n)
        .map(|i| {
            std::array::from_fn(|c| {
                std::array::from_fn(|a| if c < r && a < d { x.at(d * i + a, c) } else { 0.0 })
            })
        })
        .collect()
}

/// The point whose blocks are `Y_i`: `X_i = Y_iᵀ`.
fn point(d: usize, r: usize, y: &[Block]) -> Stack {
    let mut x = Stack::zeros(d, y.len(), r);
    for (i, yi) in y.iter().enumerate() {
        for a in 0..d {
            for c in 0..r {
                *x.at_mut(d * i + a, c) = yi[c][a];
            }
        }
    }
    x
}

/// The translations that minimise `f` for the blocks `y` (`t_0 = 0`), each in `ℝʳ`.
pub(super) fn translations(problem: &Reduced, y: &[Block], r: usize) -> Vec<[f64; 3]> {
    let n = problem.n;
    let z = problem.translations(&point(problem.d, r, y));
    (0..n).map(|k| std::array::from_fn(|a| if a < r { z[a * n + k] } else { 0.0 })).collect()
}
