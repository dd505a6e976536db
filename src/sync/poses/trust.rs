//! The Riemannian trust-region method with truncated preconditioned conjugate gradients on
//! `St(d, r)ⁿ` (Absil, Baker and Gallivan 2007, "Trust-region methods on Riemannian manifolds";
//! Absil, Mahony and Sepulchre 2008, Algorithms 10 and 11): SE-Sync's local optimiser (IJRR 2019,
//! §4.2.2, Algorithm 1's `RTR`).
//!
//! Each step minimises the model `m(η) = F + ⟨g, η⟩ + ½ ⟨η, Hess F[η]⟩` within `‖η‖_{P⁻¹} ≤ Δ` by
//! Steihaug–Toint conjugate gradients preconditioned by `P`, stopped at the boundary, at negative
//! curvature, or when the residual falls below `‖g‖ min(κ, max((‖g‖ / ‖g₀‖)^θ, 10⁻⁶))` (κ = 0.1,
//! θ = 1: the outer iteration converges quadratically); it is taken when
//! `ρ = (F − F(R(η))) / (m(0) − m(η)) > 0.1`, and `Δ` doubles when `ρ > ¾` at the boundary and
//! shrinks when `ρ < ¼`: by 4, or, when the step raised `F`, to where the parabola through `F`, its
//! slope `⟨g, η⟩` and `F(R(η))` along the step has its minimum (an interpolation in
//! the manner of Conn, Gould and Toint, "Trust-region methods", 2000, ch. 17), within `[1/64, 1/4]` of the step. After the staircase's
//! escape the model may be off by a factor of a thousand at the first radius (w20000: `ρ` −2,000
//! at `Δ` = 155, good at 0.04); shrinking by 4 took six rejected steps of 100 conjugate-gradient
//! steps each to get there, the parabola two.
//!
//! Rounding ends it as well as the gradient's tolerance: `F` is computed to about
//! `ε_F = 10⁻¹⁵ (|F| + dnr · scale)`, so conjugate gradients stop when a step lowers the model by
//! less than `10⁻⁶ ε_F`, the method stops when the model predicts less than `10⁻³ ε_F`, and a step
//! that changes `F` by less than `ε_F` is taken only if it lowers the gradient.
//!
//! The preconditioner is SE-Sync's (§4.2.3): `P Ẋ = Proj_X((Q + λ I)⁻¹ Ẋ)` with `λ = 10⁻⁶` of
//! `Q`'s scale, applied through one factorisation of the full matrix `M` (its Schur complement is
//! `Q`), made once a problem. Above rank `d` the Hessian `2 Proj_X((Q − Λ) Ẋ)` is not close to
//! `Q`: there the staircase climbed because the relaxation's optimum may have a higher rank, and
//! near it `S = Q − Λ` is nearly singular in many directions that `Q` is not, so conjugate
//! gradients preconditioned by `Q` took 100–450 steps (w20000, rank 3). There each step's
//! preconditioner is `Proj_X((Q − Λ + λ I)⁻¹ Ẋ)`, with the step's own `Λ`, where that matrix is
//! positive definite (a factorisation of `M` shifted by `−Λ + λ I`, as the certificate makes it),
//! and `Q`'s otherwise: w20000's rank 3 took 6.5 s against 14.5 s natively. At rank `d` (every
//! graph whose relaxation is tight) it changes nothing measurable and costs a factorisation a
//! step, so it is not used there.

use super::reduced::Reduced;
use super::staircase::shifted;
use super::stiefel::{Stack, multipliers, project, retract};
use crate::sync::sparse::Factor;

/// At most this many trust-region steps on one level of the staircase.
pub(super) const MAX_ITERATIONS: usize = 300;

/// At most this many conjugate-gradient steps within one trust-region step.
const MAX_INNER: usize = 500;

/// The preconditioner's regularisation `λ` over `Q`'s scale (SE-Sync §4.2.3).
const REGULARISATION: f64 = 1e-6;

/// `(Q + λ I)⁻¹`, by one factorisation.
pub(super) struct Preconditioner(Factor);

impl Preconditioner {
    pub fn new(problem: &Reduced) -> Option<Preconditioner> {
        // `λ I`: the shift of multipliers that are all 0.
        let none = vec![[[0.0; 3]; 3]; problem.n];
        let shift = shifted(&none, problem.d, REGULARISATION * problem.scale);
        problem.factor_shifted(&shift).map(Preconditioner)
    }

    /// `P z` at `model`'s point: with its own factor of `Q − Λ + λ I` where it has one.
    pub(super) fn apply(&self, problem: &Reduced, model: &Model, z: &Stack) -> Stack {
        let factor = model.local.as_ref().unwrap_or(&self.0);
        project(&model.x, &problem.solve_shifted(factor, z))
    }
}

/// Where the method stopped.
pub(super) struct Optimised {
    pub x: Stack,
    pub iterations: usize,
}

/// The local model at `X`: `Q X`, `Λ`, the gradient `2 (Q X − Λ X)`.
pub(super) struct Model {
    pub x: Stack,
    pub cost: f64,
    lambda: Vec<super::stiefel::Block>,
    pub gradient: Stack,
    /// The factor of `Q − Λ + λ I` that preconditions steps from here, above rank `d` where it
    /// is positive definite (the module's documentation).
    local: Option<Factor>,
}

impl Model {
    pub fn at(problem: &Reduced, x: Stack) -> Model {
        let (cost, qx) = problem.cost(&x);
        let lambda = multipliers(&x, &qx);
        let mut gradient = qx;
        gradient.subtract_block_products(&lambda, &x);
        let gradient = gradient.scaled(2.0);
        Model { x, cost, lambda, gradient, local: None }
    }

    /// This model, with its own preconditioner above rank `d` (where `Q − Λ + λ I` factors).
    pub fn preconditioned(mut self, problem: &Reduced) -> Model {
        if self.x.r > problem.d {
            let shift = shifted(&self.lambda, problem.d, REGULARISATION * problem.scale);
            self.local = problem.factor_shifted(&shift);
        }
        self
    }

    /// `Hess F(X)[Ẋ] = 2 Proj_X(Q Ẋ − Λ Ẋ)`.
    pub fn hessian(&self, problem: &Reduced, v: &Stack) -> Stack {
        let mut qv = problem.apply(v);
        qv.subtract_block_products(&self.lambda, v);
        project(&self.x, &qv).scaled(2.0)
    }
}

/// The step `η`, `Hess[η]`, and whether it reached the trust region's boundary.
struct Step {
    eta: Stack,
    hessian_eta: Stack,
    boundary: bool,
    /// `‖η‖_{P⁻¹}`.
    size: f64,
}

/// What a trial step tells the radius: its `ρ`, whether it reached the boundary, its size
/// `‖η‖_{P⁻¹}`, the slope `⟨g, η⟩ < 0` along it and the rise `F(R(η)) − F`.
pub(super) struct Trial {
    pub rho: f64,
    pub boundary: bool,
    pub size: f64,
    pub slope: f64,
    pub rise: f64,
}

/// The radius after `trial` (the module's documentation): where the step raised `F` (`ρ < 0`),
/// `t* · min(Δ, size)` with `t*` the minimum of the parabola `φ(t) = slope · t + (rise − slope)
/// t²` (`φ(0) = 0`, `φ'(0) = slope`, `φ(1) = rise`), `t* = −slope / (2 (rise − slope))`, kept
/// within `[1/64, 1/4]` (a quarter where `t*` is not a positive number: a slope that rounding
/// made `≥ 0`); else a quarter when `ρ < ¼` (or not a number); doubled, at most `max_radius`, when
/// `ρ > ¾` at the boundary; else unchanged.
pub(super) fn next_radius(radius: f64, max_radius: f64, trial: &Trial) -> f64 {
    if trial.rho < 0.0 {
        let size = trial.size.min(radius);
        let t = -trial.slope / (2.0 * (trial.rise - trial.slope));
        if t.is_finite() && t > 0.0 { t.clamp(1.0 / 64.0, 0.25) * size } else { size / 4.0 }
    } else if trial.rho.is_nan() || trial.rho < 0.25 {
        radius / 4.0
    } else if trial.rho > 0.75 && trial.boundary {
        (2.0 * radius).min(max_radius)
    } else {
        radius
    }
}

/// Steihaug–Toint truncated conjugate gradients, preconditioned (Absil et al. Algorithm 11, as
/// Manopt's `tCG` writes it, with the `P⁻¹`-norm of the iterate tracked by recurrences).
fn truncated_cg(
    problem: &Reduced,
    preconditioner: &Preconditioner,
    model: &Model,
    radius: f64,
    target: f64,
    noise: f64,
) -> Step {
    let g = &model.gradient;
    let mut eta = Stack::zeros(g.d, g.n, g.r);
    let mut hessian_eta = eta.clone();
    let mut r = g.clone();
    let mut z = preconditioner.apply(problem, model, &r);
    let mut z_r = z.dot(&r);
    let mut d_pd = z_r;
    let mut delta = z.scaled(-1.0);
    let (mut e_pd, mut e_pe) = (0.0, 0.0);
    // The model's value m(η) − m(0) = ⟨g, η⟩ + ½ ⟨η, Hess[η]⟩.
    let mut value = 0.0;
    for _ in 0..MAX_INNER {
        let hd = model.hessian(problem, &delta);
        let d_hd = delta.dot(&hd);
        let alpha = z_r / d_hd;
        let e_pe_new = e_pe + 2.0 * alpha * e_pd + alpha * alpha * d_pd;
        if d_hd.is_nan() || d_hd <= 0.0 || e_pe_new >= radius * radius || !alpha.is_finite() {
            // To the boundary along δ: ‖η + τ δ‖²_{P⁻¹} = Δ².
            let discriminant = e_pd * e_pd + d_pd * (radius * radius - e_pe);
            let tau = (-e_pd + discriminant.max(0.0).sqrt()) / d_pd;
            if tau.is_finite() {
                eta.axpy(tau, &delta);
                hessian_eta.axpy(tau, &hd);
            }
            return Step { eta, hessian_eta, boundary: true, size: radius };
        }
        e_pe = e_pe_new;
        eta.axpy(alpha, &delta);
        hessian_eta.axpy(alpha, &hd);
        r.axpy(alpha, &hd);
        if r.norm() <= target {
            break;
        }
        // A step that lowers the model by less than 10⁻⁶ of F's rounding: what is left is rounding
        // (at the optimum, the residual cannot fall below the gradient's own rounding).
        let next = g.dot(&eta) + 0.5 * eta.dot(&hessian_eta);
        if value - next <= 1e-6 * noise {
            break;
        }
        value = next;
        z = preconditioner.apply(problem, model, &r);
        let previous = z_r;
        z_r = z.dot(&r);
        let beta = z_r / previous;
        delta = delta.scaled(beta);
        delta.axpy(-1.0, &z);
        e_pd = beta * (e_pd + alpha * d_pd);
        d_pd = z_r + beta * beta * d_pd;
    }
    Step { eta, hessian_eta, boundary: false, size: e_pe.sqrt() }
}

/// The trust-region method from `x` until the gradient is below `tolerance`, stops shrinking, or
/// `max_iterations` steps; `step_begins` is told each step's number (from 1) as it begins, for a
/// caller's progress.
pub(super) fn optimise(
    problem: &Reduced,
    preconditioner: &Preconditioner,
    x: Stack,
    tolerance: f64,
    max_iterations: usize,
    step_begins: &mut dyn FnMut(usize),
) -> Optimised {
    let mut model = Model::at(problem, x).preconditioned(problem);
    let first = model.gradient.norm();
    // Δ in the P⁻¹-norm (`≈ √(ηᵀ Q η)`): moving every block by O(1) costs about `dn · scale`.
    let max_radius = ((model.x.rows() as f64) * problem.scale).sqrt();
    let mut radius = max_radius / 8.0;
    let mut iterations = 0;
    let mut last_gradient = f64::INFINITY;
    while iterations < max_iterations {
        let size = model.gradient.norm();
        if !size.is_finite() || size <= tolerance {
            break;
        }
        // Rounding has the last word: the gradient stopped shrinking by half, near the optimum.
        if size > 0.5 * last_gradient && size < 1e3 * tolerance {
            break;
        }
        if radius < 1e-15 * max_radius {
            break;
        }
        iterations += 1;
        step_begins(iterations);
        // F's rounding: each of its `dn r` products carries errors of `Q`'s scale.
        let noise = 1e-15 * (model.cost.abs() + model.x.data.len() as f64 * problem.scale);
        // Quadratic convergence down to a residual of 1e-6 of the gradient: below it conjugate
        // gradients meet the Hessian's kernel (the gauge, `X ↦ X O`) through rounding alone.
        let relative = if first > 0.0 { size / first } else { 1.0 };
        let target = size * relative.clamp(1e-6, 0.1);
        let step = truncated_cg(problem, preconditioner, &model, radius, target, noise);
        let predicted = -(model.gradient.dot(&step.eta) + 0.5 * step.eta.dot(&step.hessian_eta));
        // The model predicts less than a thousandth of F's rounding: stationary to rounding.
        if predicted.is_nan() || predicted <= 1e-3 * noise {
            break;
        }
        let trial = Model::at(problem, retract(&model.x, &step.eta));
        let actual = model.cost - trial.cost;
        // A change within rounding of F is judged by the model (ρ = 1) if it lowers the gradient;
        // one that does not is rounding's floor, and the method stops there.
        let within = actual.abs() <= noise;
        let lower = trial.gradient.norm() < size;
        if within && !lower {
            break;
        }
        let rho = if within { 1.0 } else { actual / predicted };
        let slope = model.gradient.dot(&step.eta);
        let outcome = Trial { rho, boundary: step.boundary, size: step.size, slope, rise: -actual };
        radius = next_radius(radius, max_radius, &outcome);
        if rho > 0.1 && trial.cost.is_finite() {
            last_gradient = size;
            model = trial.preconditioned(problem);
        }
    }
    Optimised { x: model.x, iterations }
}
