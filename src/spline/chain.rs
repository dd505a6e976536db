//! The Kuramoto–Lohe chain through keyframes (MATH.md, "Many rotations"): samples `x_0 … x_N` on
//! S³, `S` to a segment (so `h_j = (t_{i+1} − t_i)/S` on segment `i`), the samples at key times
//! pinned to the keys, the others at an equilibrium of the projected gradient flow of
//!
//! ```text
//! E(x) = (α/2) Σ_j |x_{j+1} − x_j|²/h_j + (β/2) Σ_j w_j |D²x_j|²,   α = 1 − smoothness, β = smoothness
//! D²x_j = [(x_{j+1} − x_j)/h_j − (x_j − x_{j−1})/h_{j−1}] / w_j,    w_j = (h_{j−1} + h_j)/2
//! ```
//!
//! (for even spacing, MATH.md's `(α/2h) Σ |Δx|² + (β/2h³) Σ |Δ²x|²`). `E = ½ xᵀ L x` with a
//! pentadiagonal `L` shared by the four components. The solve is Riemannian Newton: at a free
//! sample the tangent basis `B_j = [x_j i, x_j j, x_j k]`, the gradient `g_j = B_jᵀ(Lx)_j`, the
//! multiplier `μ_j = x_j·(Lx)_j`, the Hessian blocks `H_ab = L_ab B_aᵀB_b − δ_ab μ_a I₃`
//! (block-pentadiagonal, factorised banded); the step `x_j ← normalise(x_j + s B_j d_j)`, with
//! `−g` when `H` is not positive definite and `s` halved until `E` drops (Armijo). It starts
//! from piecewise SLERP, the exact equilibrium for `smoothness = 0`. Between the samples it is
//! evaluated by the C² cubic in rotation vectors through them ([`RotvecCubic`]), or, where that
//! has no solution (consecutive samples near a half turn apart beside spans 10⁶ times shorter:
//! only with a few samples a segment), by Squad through them (C¹).

use glam::{DQuat, DVec3};

use super::{Curve, Keys, PiecewiseSlerp, RotvecCubic, Squad, locate, slerp};
use crate::error::{KliError, Requirement, require};

/// The knobs of [`KliSpline::new`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChainOptions {
    /// From 0 (neighbour coupling only: piecewise SLERP) to 1 (bending only). Default 1.
    pub smoothness: f64,
    /// Samples a segment, from 2 to [`MAX_SAMPLES_PER_SEGMENT`]. Default 32.
    pub samples_per_segment: usize,
}

impl Default for ChainOptions {
    fn default() -> Self {
        Self { smoothness: 1.0, samples_per_segment: 32 }
    }
}

/// The most samples a segment: beyond 256 the bending term's condition number (it grows as
/// the fourth power of the samples a segment) keeps the solve's residual above 1e-10
/// (measured: 1.5e-10 at 512, 2e-8 and 100 iterations at 4096).
pub const MAX_SAMPLES_PER_SEGMENT: usize = 256;

/// The most samples a chain: the solve's time grows with them (about 2.5 µs a sample natively,
/// so 2^17 samples take a few tenths of a second).
pub const MAX_SAMPLES: usize = 1 << 17;

/// The residual the solve aims at, free of `E`'s scale: `max_j |g_j| / max_j |(Lx)_j|`.
pub const TOLERANCE: f64 = 1e-12;
const MAX_ITERATIONS: usize = 100;

/// The chain's equilibrium through the keys, evaluated between its samples by the C² cubic in
/// rotation vectors through them (continuous angular acceleration).
#[derive(Debug, Clone)]
pub struct KliSpline {
    keys: Keys,
    samples: Keys,
    curve: Between,
    /// Samples a segment: sample interval `i·S + j` is the `j`-th of segment `i`.
    per: usize,
    /// At smoothness 0 the equilibrium is piecewise SLERP exactly, kinks at the keys included:
    /// then it is evaluated as such (a smooth curve through the samples would round the kinks).
    exact: Option<PiecewiseSlerp>,
    residual: f64,
    iterations: usize,
}

/// How the chain is evaluated between its samples.
#[derive(Debug, Clone)]
enum Between {
    /// C²: the cubic in rotation vectors through the samples.
    Cubic(RotvecCubic),
    /// C¹: Squad through the samples, where the cubic has no solution.
    Squad(Squad),
}

impl KliSpline {
    pub fn new(keys: Keys, options: &ChainOptions) -> Result<Self, KliError> {
        let smoothness = require("smoothness", options.smoothness, Requirement::Between(0.0, 1.0))?;
        let per = options.samples_per_segment;
        if !(2..=MAX_SAMPLES_PER_SEGMENT).contains(&per) {
            let problem =
                format!("must be a whole number from 2 to {MAX_SAMPLES_PER_SEGMENT} (got {per})");
            return Err(KliError::invalid("samples_per_segment", problem));
        }
        let (k, t) = (keys.quaternions(), keys.times());
        if (k.len() - 1).saturating_mul(per) > MAX_SAMPLES {
            let problem = format!(
                "× (keys − 1) must be at most {MAX_SAMPLES} chain samples (got {per} × {})",
                k.len() - 1
            );
            return Err(KliError::invalid("samples_per_segment", problem));
        }
        let mut times = Vec::with_capacity((k.len() - 1) * per + 1);
        let mut samples = Vec::with_capacity(times.capacity());
        let mut pinned = Vec::with_capacity(times.capacity());
        for i in 0..k.len() - 1 {
            for s in 0..per {
                let u = s as f64 / per as f64;
                times.push(t[i] + u * (t[i + 1] - t[i]));
                samples.push(slerp(k[i], k[i + 1], u));
                pinned.push(s == 0);
            }
        }
        times.push(t[t.len() - 1]);
        samples.push(k[k.len() - 1]);
        pinned.push(true);
        let chain = Chain::new(&times, 1.0 - smoothness, smoothness, pinned);
        let (iterations, residual) = chain.solve(&mut samples, MAX_ITERATIONS);
        // Signs made consistent (consecutive samples more than a half turn apart: coarse chains).
        let samples = Keys::unchecked_spans(&samples, Some(&times))?;
        let curve = match RotvecCubic::new(samples.quaternions(), &times) {
            Ok(cubic) => Between::Cubic(cubic),
            Err(_) => Between::Squad(Squad::new(samples.clone())),
        };
        let exact = (smoothness == 0.0).then(|| PiecewiseSlerp::new(keys.clone()));
        Ok(Self { keys, samples, curve, per, exact, residual, iterations })
    }

    /// The keys as used (signs consistent).
    pub fn keys(&self) -> &Keys {
        &self.keys
    }

    /// The chain's samples and their times (the keys among them).
    pub fn samples(&self) -> &Keys {
        &self.samples
    }

    /// The relative residual reached, `max_j |g_j| / max_j |(Lx)_j|` (0 for a chain at rest,
    /// such as equal keys, where `Lx` is within rounding of 0). The solve also stops when the
    /// residual stops halving with every `|g_j|` within rounding of `L`'s size: for nearly equal
    /// keys `|Lx|` is of second order, and the residual then left is rounding's.
    pub fn residual(&self) -> f64 {
        self.residual
    }

    /// Newton iterations taken.
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// Whether the curve is C² (the cubic through the samples), not C¹ (Squad through them).
    pub fn is_c2(&self) -> bool {
        matches!(self.curve, Between::Cubic(_)) && self.exact.is_none()
    }
}

impl Curve for KliSpline {
    fn at(&self, t: f64) -> DQuat {
        if let Some(exact) = &self.exact {
            return exact.at(t);
        }
        let (j, u) = self.interval(t);
        match &self.curve {
            Between::Cubic(cubic) => cubic.at_interval(j, u),
            Between::Squad(squad) => squad.at_interval(j, u),
        }
    }

    fn start_time(&self) -> f64 {
        self.keys.times()[0]
    }

    fn end_time(&self) -> f64 {
        self.keys.times()[self.keys.len() - 1]
    }

    /// Exact: `q Ω q̄` with the cubic's body rate `Ω = J(θ) θ'`.
    fn angular_velocity(&self, t: f64) -> DVec3 {
        if let Some(exact) = &self.exact {
            return exact.angular_velocity(t);
        }
        match &self.curve {
            Between::Cubic(cubic) => {
                let (j, u) = self.interval(t);
                cubic.angular_velocity_interval(j, u)
            }
            Between::Squad(squad) => squad.angular_velocity(t),
        }
    }
}

impl KliSpline {
    /// The sample interval holding `t` and the fraction `u` within it: the samples are even
    /// within a segment, so find the segment, then the interval (no search over the samples).
    fn interval(&self, t: f64) -> (usize, f64) {
        let (segment, u) = locate(self.keys.times(), t);
        let position = u * self.per as f64;
        let j = (position.floor() as usize).min(self.per - 1);
        (segment * self.per + j, position - j as f64)
    }
}

/// `L` by its terms, and which samples are pinned.
struct Chain {
    /// `E = ½ Σ_j w_j |x_{j+1} − x_j|² + ½ Σ_j f_j |D_j|²`, `D_j = (x_{j+1} − x_j)/h_j −
    /// (x_j − x_{j−1})/h_{j−1} = Σ_a c_a x_{j−1+a}` (MATH.md's energy on uneven times): `w_j`
    /// and `(f_j, c)`. `Lx` summed from these, from differences of nearby samples, rounds to its
    /// own size (and so does `E = ½ x·Lx`); through `L`'s entries (up to `1/h³`) it rounds to
    /// `ε max_a Σ_b |L_ab|`, which for close keys exceeds the change a Newton step makes.
    stretch: Vec<f64>,
    bend: Vec<(f64, [f64; 3])>,
    pinned: Vec<bool>,
    /// `max_a Σ_b |L_ab|`, the largest `|(Lx)_a|` could be for unit samples.
    norm: f64,
}

/// The unit quaternions `i`, `j`, `k`.
const UNITS: [DQuat; 3] = [
    DQuat::from_xyzw(1.0, 0.0, 0.0, 0.0),
    DQuat::from_xyzw(0.0, 1.0, 0.0, 0.0),
    DQuat::from_xyzw(0.0, 0.0, 1.0, 0.0),
];

fn pure(v: DVec3) -> DQuat {
    DQuat::from_xyzw(v.x, v.y, v.z, 0.0)
}

fn vector(q: DQuat) -> DVec3 {
    DVec3::new(q.x, q.y, q.z)
}

impl Chain {
    fn new(times: &[f64], alpha: f64, beta: f64, pinned: Vec<bool>) -> Self {
        let stretch = times.windows(2).map(|h| alpha / (h[1] - h[0])).collect();
        let bend = times
            .windows(3)
            .map(|t| {
                let (h0, h1) = (t[1] - t[0], t[2] - t[1]);
                (beta / (0.5 * (h0 + h1)), [1.0 / h0, -(1.0 / h0 + 1.0 / h1), 1.0 / h1])
            })
            .collect();
        let mut chain = Self { stretch, bend, pinned, norm: 0.0 };
        let n = times.len();
        let row = |a: usize| -> f64 {
            (a.saturating_sub(2)..(a + 3).min(n)).map(|b| chain.l(a, b).abs()).sum()
        };
        chain.norm = (0..n).map(row).fold(0.0, f64::max);
        chain
    }

    /// `L_ab`, the sum of the terms that couple `a` and `b`: a stretch term `w_j` adds `±w_j` on
    /// `j, j + 1`; a bend term `f_j c_a c_b` on `j + a, j + b`.
    // Out of line: inlined into the Hessian and the norm, it costs 125 B gzipped of wasm.
    #[inline(never)]
    fn l(&self, a: usize, b: usize) -> f64 {
        let (a, b) = (a.min(b), a.max(b));
        let w = |j: usize| self.stretch.get(j).map_or(0.0, |w| *w);
        let stretch = match b - a {
            0 => w(a.wrapping_sub(1)) + w(a),
            1 => -w(a),
            _ => 0.0,
        };
        let terms = self.bend.iter().enumerate().take(a + 1).skip(b.saturating_sub(2));
        let bend = terms.map(|(j, &(f, c))| f * c[a - j] * c[b - j]).sum::<f64>();
        stretch + bend
    }

    /// `Lx`, term by term: a stretch term adds `∓w_j (x_{j+1} − x_j)` at `j`, `j + 1`; a bend
    /// adds `f_j c_a D_j` at `j − 1 + a`, `D_j` from the differences of neighbours.
    fn apply(&self, x: &[DQuat]) -> Vec<DQuat> {
        let mut lx = vec![pure(DVec3::ZERO); x.len()];
        for ((j, x), &w) in x.windows(2).enumerate().zip(&self.stretch) {
            let pull = (x[1] - x[0]) * w;
            lx[j] -= pull;
            lx[j + 1] += pull;
        }
        for ((j, x), &(f, c)) in x.windows(3).enumerate().zip(&self.bend) {
            let d = (x[2] - x[1]) * c[2] - (x[1] - x[0]) * c[0];
            for (sum, c) in lx[j..j + 3].iter_mut().zip(c) {
                *sum += d * (f * c);
            }
        }
        lx
    }

    /// `E = ½ Σ_a x_a·(Lx)_a`: with `Lx` summed from differences, each term is accurate to its
    /// own size (near the chain `(Lx)_a` is nearly along `x_a`), so `E` is too.
    fn energy(&self, x: &[DQuat]) -> f64 {
        energy(x, &self.apply(x))
    }

    /// The gradients `g_j` at the free samples, the relative residual (0 for a chain at rest:
    /// where `|(Lx)_j|` is itself within rounding of `L`'s size, as for equal keys, the ratio
    /// would be rounding over rounding), and whether every `|g_j|` is within rounding of `L`'s
    /// size (`8ε max_a Σ_b |L_ab|`: a sample is stored to ε, so however `Lx` is summed, moving
    /// the samples by their own rounding moves it that much), where no step can lower the
    /// residual further.
    fn gradient(&self, x: &[DQuat], lx: &[DQuat], free: &[usize]) -> (Vec<DVec3>, f64, bool) {
        let g: Vec<DVec3> = free.iter().map(|&a| vector(x[a].conjugate() * lx[a])).collect();
        let scale = free.iter().map(|&a| lx[a].length()).fold(0.0, f64::max);
        let largest = g.iter().map(|v| v.length()).fold(0.0, f64::max);
        let rounding = 8.0 * f64::EPSILON * self.norm;
        (g, if scale > rounding { largest / scale } else { 0.0 }, largest <= rounding)
    }

    /// Runs Newton to [`TOLERANCE`] (or until rounding stops progress, or `max_iterations`
    /// steps); returns the iterations and the residual reached.
    fn solve(&self, x: &mut [DQuat], max_iterations: usize) -> (usize, f64) {
        let free: Vec<usize> = (0..x.len()).filter(|&a| !self.pinned[a]).collect();
        if free.is_empty() {
            return (0, 0.0);
        }
        let mut lx = self.apply(x);
        let (mut g, mut residual, mut at_rounding) = self.gradient(x, &lx, &free);
        let mut floor = false;
        for iteration in 0..max_iterations {
            if residual <= TOLERANCE || floor {
                return (iteration, residual);
            }
            let hessian = self.hessian(x, &lx, &free);
            let minus_g: Vec<f64> = g.iter().flat_map(|v| (-*v).to_array()).collect();
            // E's slope along d, gᵀd: Newton's direction where the Hessian is positive definite
            // and it descends (by rounding it might not), else steepest descent.
            let slope = |d: &[f64]| d.iter().zip(&minus_g).map(|(a, b)| -a * b).sum::<f64>();
            let d = match hessian.solve(&minus_g) {
                Some(d) if slope(&d) < 0.0 => d,
                _ => minus_g.clone(),
            };
            let slope = slope(&d);
            let trial = self.step(x, &free, &d, slope, energy(x, &lx), residual);
            let trial_lx = self.apply(&trial);
            let (trial_g, trial_residual, trial_at_rounding) =
                self.gradient(&trial, &trial_lx, &free);
            // At the rounding floor (the gradient within rounding of L's size: the samples are
            // where their own rounding leaves them, as for a stiff chain or nearly equal keys,
            // whose |Lx| is of second order), steps stop halving the residual: keep the better
            // state and stop.
            floor = at_rounding && trial_residual > 0.5 * residual;
            if floor && trial_residual >= residual {
                return (iteration, residual);
            }
            x.copy_from_slice(&trial);
            (lx, g, residual, at_rounding) = (trial_lx, trial_g, trial_residual, trial_at_rounding);
        }
        (max_iterations, residual)
    }

    /// The next state along `d`: near the equilibrium (`E`'s slope along `d` below `1e-10 E`, so
    /// that a step changes `E` by less than its sum's rounding could hide: Armijo cannot judge
    /// it) the full Newton step when it lowers the residual; else the Armijo step on `E` (halved
    /// until `E` drops by `1e-4 · step · slope`), or the full step if even that fails.
    fn step(
        &self,
        x: &[DQuat],
        free: &[usize],
        d: &[f64],
        slope: f64,
        energy: f64,
        residual: f64,
    ) -> Vec<DQuat> {
        let full = retract(x, free, d, 1.0);
        if -slope < 1e-10 * energy && self.gradient(&full, &self.apply(&full), free).1 < residual {
            return full;
        }
        let mut step = 1.0;
        while step >= 1e-12 {
            let trial = retract(x, free, d, step);
            if self.energy(&trial) <= energy + 1e-4 * step * slope {
                return trial;
            }
            step *= 0.5;
        }
        full
    }

    /// The tangent Hessian, block-pentadiagonal in the order of the free samples.
    fn hessian(&self, x: &[DQuat], lx: &[DQuat], free: &[usize]) -> Band {
        let mut band = Band::new(3 * free.len(), 8);
        for (p, &a) in free.iter().enumerate() {
            let mu = x[a].dot(lx[a]);
            for (q, &b) in free.iter().enumerate().take(p + 1).skip(p.saturating_sub(2)) {
                if a - b > 2 {
                    continue;
                }
                let lab = self.l(a, b);
                let y = x[a].conjugate() * x[b];
                // M = B_aᵀ B_b: column c is the vector part of y e_c.
                for (c, e) in UNITS.iter().enumerate() {
                    let column = vector(y * *e);
                    for (r, value) in column.to_array().into_iter().enumerate() {
                        let (i, j) = (3 * p + r, 3 * q + c);
                        if j <= i {
                            let diagonal = if i == j { mu } else { 0.0 };
                            band.set(i, j, lab * value - diagonal);
                        }
                    }
                }
            }
        }
        band
    }
}

/// `E = ½ Σ_a x_a·(Lx)_a` from `Lx`.
fn energy(x: &[DQuat], lx: &[DQuat]) -> f64 {
    0.5 * x.iter().zip(lx).map(|(a, la)| a.dot(*la)).sum::<f64>()
}

/// `x_j ← normalise(x_j + s x_j (d_j as a pure quaternion))` at the free samples.
fn retract(x: &[DQuat], free: &[usize], d: &[f64], s: f64) -> Vec<DQuat> {
    let mut out = x.to_vec();
    for (&a, d) in free.iter().zip(d.chunks_exact(3)) {
        let step = pure(DVec3::from_slice(d) * s);
        let moved = x[a] + x[a] * step;
        out[a] = moved / moved.length();
    }
    out
}

/// A symmetric band matrix (the lower band, `w` below the diagonal) and its Cholesky solve.
struct Band {
    n: usize,
    w: usize,
    /// `rows[i][k] = A[i][i − k]`.
    rows: Vec<[f64; 9]>,
}

impl Band {
    fn new(n: usize, w: usize) -> Self {
        Self { n, w, rows: vec![[0.0; 9]; n] }
    }

    fn set(&mut self, i: usize, j: usize, value: f64) {
        self.rows[i][i - j] = value;
    }

    /// `A⁻¹ b` by Cholesky, or `None` when `A` is not positive definite.
    fn solve(&self, b: &[f64]) -> Option<Vec<f64>> {
        let (n, w) = (self.n, self.w);
        let mut l = vec![[0.0; 9]; n];
        for i in 0..n {
            for j in i.saturating_sub(w)..=i {
                let mut sum = self.rows[i][i - j];
                for p in i.saturating_sub(w).max(j.saturating_sub(w))..j {
                    sum -= l[i][i - p] * l[j][j - p];
                }
                if i == j {
                    if sum <= 0.0 || sum.is_nan() {
                        return None;
                    }
                    l[i][0] = sum.sqrt();
                } else {
                    l[i][i - j] = sum / l[j][0];
                }
            }
        }
        let mut y = b.to_vec();
        for (i, row) in l.iter().enumerate() {
            let from = i.saturating_sub(w);
            let sum: f64 = (from..i).map(|p| row[i - p] * y[p]).sum();
            y[i] = (y[i] - sum) / row[0];
        }
        for i in (0..n).rev() {
            let sum: f64 = (i + 1..(i + w + 1).min(n)).map(|p| l[p][p - i] * y[p]).sum();
            y[i] = (y[i] - sum) / l[i][0];
        }
        Some(y)
    }
}

// faer's dense Cholesky is the reference; it comes with the feature `sync`.
#[cfg(test)]
#[cfg(feature = "sync")]
mod tests {
    use faer::prelude::Solve;
    use faer::{Mat, Side};
    use glam::{DQuat, DVec3};

    use super::{Chain, MAX_ITERATIONS, TOLERANCE};
    use crate::quaternion::{exp, farthest_apart};
    use crate::spline::tests::chain_energy;
    use crate::swarm::Random;

    /// Which branches of the solve a run went through.
    #[derive(Debug, Default, Clone, Copy)]
    struct Branches {
        /// The tangent Hessian not positive definite: the step is along `−g`.
        refused: usize,
        /// The Armijo step shorter than the full one.
        halved: usize,
        /// The full step taken near the equilibrium because it lowers the residual.
        near: usize,
        /// Stopped at rounding's floor (the residual no longer halving, the gradient at rounding's
        /// level).
        floor: usize,
    }

    /// The chain's Newton method written afresh, densely, from the doc comments and MATH.md:
    /// `L` from MATH.md's energy `E = ½ Σ L_ab x_a·x_b` (`L_aa = 2E(e_a)`, `L_ab = E(e_a + e_b)
    /// − E(e_a) − E(e_b)`, exact for a quadratic), the tangent gradient `g_a = vec(x̄_a (Lx)_a)` and
    /// Hessian `L_ab B_aᵀB_b − (x_a·(Lx)_a) δ_ab I` (`B_a`'s columns `x_a i, x_a j, x_a k`) on
    /// the free samples, the direction by faer's dense Cholesky (`−g` where it fails), the step:
    /// where `|gᵀd| < 1e-10 E` the full step if it lowers the residual, else Armijo's on `E`
    /// from 1 halving down to 1e-12 (else the full step); `x_a ← normalise(x_a + x_a s d_a)`.
    /// The residual `max|g| / max|Lx|` (0 when `max|Lx| ≤ 8ε max_a Σ_b |L_ab|`); it stops at
    /// [`TOLERANCE`], or when the residual no longer halves with `max|g| ≤ 8ε max_a Σ_b |L_ab|`
    /// (keeping the better state). Each step's samples.
    fn dense(
        times: &[f64],
        alpha: f64,
        beta: f64,
        pinned: &[bool],
        start: &[DQuat],
    ) -> (Vec<Vec<DQuat>>, Branches, f64, bool) {
        let n = times.len();
        let energy = |x: &[DQuat]| {
            let (a, b) = chain_energy(x, times, alpha, beta);
            a + b
        };
        let l = energy_matrix(times, alpha, beta);
        let norm = (0..n).map(|a| (0..n).map(|b| l[(a, b)].abs()).sum::<f64>()).fold(0.0, f64::max);
        let free: Vec<usize> = (0..n).filter(|&a| !pinned[a]).collect();
        let units = [
            DQuat::from_xyzw(1.0, 0.0, 0.0, 0.0),
            DQuat::from_xyzw(0.0, 1.0, 0.0, 0.0),
            DQuat::from_xyzw(0.0, 0.0, 1.0, 0.0),
        ];
        let applied = |x: &[DQuat]| -> Vec<DQuat> {
            (0..n)
                .map(|a| {
                    (0..n)
                        .fold(DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0), |sum, b| sum + x[b] * l[(a, b)])
                })
                .collect()
        };
        let state = |x: &[DQuat]| {
            let lx = applied(x);
            let g: Vec<DVec3> = free
                .iter()
                .map(|&a| {
                    let v = x[a].conjugate() * lx[a];
                    DVec3::new(v.x, v.y, v.z)
                })
                .collect();
            let scale = free.iter().map(|&a| lx[a].length()).fold(0.0, f64::max);
            let largest = g.iter().map(|v| v.length()).fold(0.0, f64::max);
            let rounding = 8.0 * f64::EPSILON * norm;
            let residual = if scale > rounding { largest / scale } else { 0.0 };
            (lx, g, residual, largest <= rounding)
        };
        let moved = |x: &[DQuat], d: &[f64], s: f64| {
            let mut y = x.to_vec();
            for (p, &a) in free.iter().enumerate() {
                let v = DQuat::from_xyzw(d[3 * p] * s, d[3 * p + 1] * s, d[3 * p + 2] * s, 0.0);
                y[a] = (x[a] + x[a] * v).normalize();
            }
            y
        };
        let mut branches = Branches::default();
        let mut x = start.to_vec();
        let mut path = vec![x.clone()];
        let (mut lx, mut g, mut residual, mut at_rounding) = state(&x);
        while path.len() <= MAX_ITERATIONS && residual > TOLERANCE {
            let m = 3 * free.len();
            let hessian = Mat::<f64>::from_fn(m, m, |i, j| {
                let (p, q, r, c) = (i / 3, j / 3, i % 3, j % 3);
                let (a, b) = (free[p], free[q]);
                let value = l[(a, b)] * (x[a] * units[r]).dot(x[b] * units[c]);
                if i == j { value - x[a].dot(lx[a]) } else { value }
            });
            let minus_g: Vec<f64> = g.iter().flat_map(|v| (-*v).to_array()).collect();
            let mut d = match hessian.llt(Side::Lower) {
                Ok(llt) => {
                    let solved = llt.solve(Mat::<f64>::from_fn(m, 1, |i, _| minus_g[i]));
                    (0..m).map(|i| solved[(i, 0)]).collect()
                }
                Err(_) => {
                    branches.refused += 1;
                    minus_g.clone()
                }
            };
            let mut slope: f64 = d.iter().zip(&minus_g).map(|(a, b)| -a * b).sum();
            if slope.is_nan() || slope >= 0.0 {
                d = minus_g.clone();
                slope = -d.iter().map(|v| v * v).sum::<f64>();
            }
            let full = moved(&x, &d, 1.0);
            let e = energy(&x);
            let trial = if -slope < 1e-10 * e && state(&full).2 < residual {
                branches.near += 1;
                full
            } else {
                let mut s = 1.0;
                loop {
                    if s < 1e-12 {
                        break full;
                    }
                    let trial = moved(&x, &d, s);
                    if energy(&trial) <= e + 1e-4 * s * slope {
                        branches.halved += usize::from(s < 1.0);
                        break trial;
                    }
                    s /= 2.0;
                }
            };
            let (trial_lx, trial_g, trial_residual, trial_at_rounding) = state(&trial);
            let floor = at_rounding && trial_residual > residual / 2.0;
            if floor && trial_residual >= residual {
                branches.floor += 1;
                break;
            }
            x = trial;
            (lx, g, residual, at_rounding) = (trial_lx, trial_g, trial_residual, trial_at_rounding);
            path.push(x.clone());
            if floor {
                branches.floor += 1;
                break;
            }
        }
        (path, branches, residual, at_rounding)
    }

    /// `L` from MATH.md's energy `E = ½ Σ L_ab x_a·x_b` (`L_aa = 2E(e_a)`, `L_ab = E(e_a + e_b)
    /// − E(e_a) − E(e_b)`, exact for a quadratic), `E` as the spline tests write it.
    fn energy_matrix(times: &[f64], alpha: f64, beta: f64) -> Mat<f64> {
        let n = times.len();
        let unit = |entries: &[usize]| {
            let mut x = vec![DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0); n];
            for &a in entries {
                x[a].w += 1.0;
            }
            let (a, b) = chain_energy(&x, times, alpha, beta);
            a + b
        };
        Mat::<f64>::from_fn(n, n, |a, b| {
            if a == b { 2.0 * unit(&[a]) } else { unit(&[a, b]) - unit(&[a]) - unit(&[b]) }
        })
    }

    /// The chain's energy and `Lx`, summed term by term, and `L`'s entries (the Hessian's) are
    /// MATH.md's energy and its matrix, on uneven times with both terms at work.
    #[test]
    fn the_terms_are_the_energy_and_its_matrix() {
        let times = [0.0, 0.3, 0.5, 1.4, 1.5, 2.7, 3.0];
        let (alpha, beta) = (0.3, 0.7);
        let n = times.len();
        let mut random = Random::new(5);
        let x: Vec<DQuat> = (0..n).map(|_| random.unit_quaternion()).collect();
        let chain = Chain::new(&times, alpha, beta, vec![false; n]);
        let l = energy_matrix(&times, alpha, beta);
        let (a, b) = chain_energy(&x, &times, alpha, beta);
        let e = chain.energy(&x);
        assert!((e - (a + b)).abs() <= 1e-13 * (a + b), "{e} vs {}", a + b);
        let norm = (0..n).map(|a| (0..n).map(|b| l[(a, b)].abs()).sum::<f64>()).fold(0.0, f64::max);
        let lx = chain.apply(&x);
        for a in 0..n {
            let expected =
                (0..n).fold(DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0), |sum, b| sum + x[b] * l[(a, b)]);
            assert!((lx[a] - expected).length() <= 1e-13 * norm, "(Lx)_{a}");
            for b in 0..n {
                assert!((chain.l(a, b) - l[(a, b)]).abs() <= 1e-13 * norm, "L_{a}{b}");
            }
        }
        assert!((chain.norm - norm).abs() <= 1e-13 * norm);
    }

    /// Samples along SLERP between consecutive `keys`, `per` a segment, the last key last.
    fn slerp_samples(keys: &[DQuat], per: usize) -> Vec<DQuat> {
        let segments = keys.len() - 1;
        (0..=segments * per)
            .map(|k| {
                let (i, u) = (k / per, (k % per) as f64 / per as f64);
                if i == segments { keys[i] } else { crate::spline::slerp(keys[i], keys[i + 1], u) }
            })
            .collect()
    }

    /// The solve stopped after each number of steps is where the dense method is after as many
    /// (to 1e-9 while the residual is above 1e-8: below it rounding decides), and stops within
    /// two steps of it (rounding decides the last ones), at the tolerance or rounding's level: from SLERP samples (full steps near the equilibrium), from
    /// samples moved off them by up to a radian (an indefinite Hessian: steps along −g, Armijo
    /// halving them), and with uneven times. Where the dense method crawls along −g to its step
    /// bound, so must the solve.
    #[test]
    fn each_step_is_the_dense_methods() {
        let mut seen = Branches::default();
        let mut compare = |times: &[f64], smoothness: f64, pinned: &[bool], start: &[DQuat]| {
            let (alpha, beta) = (1.0 - smoothness, smoothness);
            let chain = Chain::new(times, alpha, beta, pinned.to_vec());
            let (path, branches, reached, at_rounding) = dense(times, alpha, beta, pinned, start);
            for (k, expected) in path.iter().enumerate() {
                let mut x = start.to_vec();
                let (iterations, residual) = chain.solve(&mut x, k);
                assert!(iterations <= k);
                let gap = farthest_apart(&x, expected);
                assert!(gap < 1e-9, "step {k} of {}: {gap:e} ({branches:?})", path.len() - 1);
                if residual < 1e-8 {
                    break;
                }
            }
            let mut x = start.to_vec();
            let (iterations, residual) = chain.solve(&mut x, MAX_ITERATIONS);
            let steps = path.len() - 1;
            assert!(iterations.abs_diff(steps) <= 2, "{iterations} vs {steps} ({branches:?})");
            // Far from the equilibrium, with the Hessian indefinite, steps along −g can crawl:
            // both run out of steps there.
            // Where the gradient is within rounding of L's size, the residual is rounding's.
            if reached <= TOLERANCE || at_rounding {
                assert!(residual <= 1e-9, "{residual:e}");
            } else {
                assert_eq!((iterations, steps), (MAX_ITERATIONS, MAX_ITERATIONS));
            }
            assert!(farthest_apart(&x, path.last().unwrap()) < 1e-9);
            seen.refused += branches.refused;
            seen.halved += branches.halved;
            seen.near += branches.near;
        };
        let mut random = Random::new(11);
        // Segments, samples a segment, uneven times, and the runs' smoothness and spread.
        type Case = (usize, usize, bool, &'static [(f64, f64)]);
        let cases: [Case; 3] = [
            (3, 6, false, &[(0.3, 0.0), (1.0, 0.0), (0.3, 0.4), (1.0, 0.4), (1.0, 1.0)]),
            (2, 8, true, &[(0.3, 0.0), (1.0, 0.0), (1.0, 0.1)]),
            (4, 5, true, &[(0.3, 0.0), (1.0, 0.0)]),
        ];
        for (segments, per, uneven, runs) in cases {
            let times: Vec<f64> = (0..=segments * per)
                .map(|k| {
                    let t = k as f64 / per as f64;
                    if uneven { t * t + 0.3 * t } else { t }
                })
                .collect();
            let pinned: Vec<bool> = (0..times.len()).map(|k| k % per == 0).collect();
            // Keys up to 2 rad apart, signs consistent (as `Keys` makes them).
            let mut keys = vec![random.unit_quaternion()];
            while keys.len() <= segments {
                let turn = exp(random.gaussian3().normalize() * random.uniform());
                keys.push(*keys.last().unwrap() * turn);
            }
            for &(smoothness, spread) in runs {
                let start: Vec<DQuat> =
                    slerp_samples(&keys, per)
                        .into_iter()
                        .zip(&pinned)
                        .map(|(on, &pin)| {
                            if pin {
                                on
                            } else {
                                (on * exp(random.gaussian3() * spread)).normalize()
                            }
                        })
                        .collect();
                compare(&times, smoothness, &pinned, &start);
            }
        }
        assert!(seen.refused > 0 && seen.halved > 0 && seen.near > 0, "{seen:?}");
    }

    /// A stiff chain (3 keys, 400 samples a segment: the bending term's condition grows as the
    /// fourth power of the samples) from its SLERP samples: Newton reaches rounding's floor
    /// above the tolerance and stops there, keeping the best state it met (its residual is the
    /// least of those after every number of steps) and reporting the steps that state took.
    #[test]
    fn a_stiff_chain_stops_at_roundings_floor_with_its_best_state() {
        let per = 400;
        let times: Vec<f64> = (0..=2 * per).map(|k| k as f64 / per as f64).collect();
        let pinned: Vec<bool> = (0..times.len()).map(|k| k % per == 0).collect();
        let keys = [
            DQuat::IDENTITY,
            exp(DVec3::new(0.3, 0.8, -0.2)),
            exp(DVec3::new(0.3, 0.8, -0.2)) * exp(DVec3::new(-0.7, 0.1, 0.5)),
        ];
        let start = slerp_samples(&keys, per);
        let chain = Chain::new(&times, 0.0, 1.0, pinned);
        let mut x = start.clone();
        let (iterations, residual) = chain.solve(&mut x, MAX_ITERATIONS);
        assert!(residual > TOLERANCE && residual < 1e-8, "{residual:e}");
        assert!(iterations < 20, "{iterations}");
        for k in 0..=iterations + 1 {
            let mut y = start.clone();
            let (_, after) = chain.solve(&mut y, k);
            assert!(residual <= after, "after {k}: {after:e} below {residual:e}");
            if k == iterations {
                assert_eq!(y, x, "the state after the steps reported");
            }
        }
    }
}
