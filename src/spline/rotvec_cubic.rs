//! A C² cubic in rotation vectors through samples `x_0 … x_n` at times `t_0 < … < t_n` (MATH.md,
//! "Smoothness: the C² evaluation"), the construction of SciPy's `RotationSpline`, here with
//! natural ends:
//!
//! ```text
//! q(t) = x_j exp(θ_j(s)/2),   s = t − t_j ∈ [0, h_j],   θ_j(s) = ω_j s + b_j s² + a_j s³
//! θ_j(h_j) = Δ_j = rotation vector of x̄_j x_{j+1},   Ω = J(θ) θ'   (body rate, q' = ½ q Ω)
//! J(θ) = I − k₁ [θ]× + k₂ [θ]×²,   k₁ = (1 − cos φ)/φ²,   k₂ = (φ − sin φ)/φ³,   φ = |θ|
//! ```
//!
//! Each piece leaves `x_j` with body rate `ω_j` and arrives at `x_{j+1}` with `ω_{j+1}`
//! (`θ_j'(h_j) = J(Δ_j)⁻¹ ω_{j+1}`), which fixes `a_j` and `b_j`. Asking the body angular
//! acceleration `Ω' = J θ'' + (dJ/ds) θ'` to agree at every inner sample, and to vanish at the
//! two ends, gives for the rates the block-tridiagonal system
//!
//! ```text
//! (2/h_{j−1}) J(Δ_{j−1}) ω_{j−1} + 4 (1/h_{j−1} + 1/h_j) ω_j + (2/h_j) J(Δ_j)⁻¹ ω_{j+1}
//!     = 6 Δ_{j−1}/h_{j−1}² + 6 Δ_j/h_j² − N(Δ_{j−1}, J(Δ_{j−1})⁻¹ ω_j)
//! ```
//!
//! where `N(θ, θ') = (dJ/ds) θ'` is quadratic in the rates; it is solved by Newton's method
//! (for dense samples `N`'s share is about `|Δ|²/12` and two or three steps reach rounding).

use glam::{DMat3, DQuat, DVec3};

use crate::error::KliError;
use crate::quaternion::{exp, log};

/// One piece: `q(s) = start · exp(θ(s)/2)`, `θ(s) = s (rate + s (b + s a))`.
#[derive(Debug, Clone, Copy)]
struct Piece {
    start: DQuat,
    rate: DVec3,
    b: DVec3,
    a: DVec3,
}

/// The C² cubic through samples (see the module's documentation).
#[derive(Debug, Clone)]
pub struct RotvecCubic {
    times: Vec<f64>,
    pieces: Vec<Piece>,
    end: DQuat,
    iterations: usize,
}

/// Newton stops when no rate moves by more than this, relative to the largest rate.
const TOLERANCE: f64 = 1e-14;
const MAX_ITERATIONS: usize = 30;

/// `Σ (−1)ⁿ c_n xⁿ` for `x = φ²`, with `c_n = weight(n)/(n + shift)!`: the series of the
/// coefficients below, accurate to rounding for `φ < 0.5` in 9 terms.
fn series(x: f64, shift: usize, weight: impl Fn(usize) -> f64) -> f64 {
    let mut factorial: f64 = (1..=shift).map(|k| k as f64).product();
    let (mut sum, mut power) = (0.0, 1.0);
    for n in 0..9 {
        if n > 0 {
            factorial *= ((2 * n + shift - 1) * (2 * n + shift)) as f64;
            power *= -x;
        }
        sum += weight(n) * power / factorial;
    }
    sum
}

/// Below this angle the coefficients come from their series (the closed forms cancel).
const SERIES_BELOW: f64 = 0.5;

/// `k₁ = (1 − cos φ)/φ²` and `k₂ = (φ − sin φ)/φ³` of `J`.
fn k12(phi: f64) -> (f64, f64) {
    if phi < SERIES_BELOW {
        let x = phi * phi;
        return (series(x, 2, |_| 1.0), series(x, 3, |_| 1.0));
    }
    let (sin, cos) = crate::trig::sin_cos(phi);
    ((1.0 - cos) / (phi * phi), (phi - sin) / (phi * phi * phi))
}

/// `k₁'(φ)/φ` and `k₂'(φ)/φ`, the derivatives of `J`'s coefficients along the curve.
fn dk12(phi: f64) -> (f64, f64) {
    if phi < SERIES_BELOW {
        // k₁'/φ = Σ_{n≥1} (−1)ⁿ 2n φ^{2n−2}/(2n+2)!: the series of k₁ differentiated, shifted.
        let x = phi * phi;
        let d = |shift| -series(x, shift, |n| 2.0 * (n + 1) as f64);
        return (d(4), d(5));
    }
    let (sin, cos) = crate::trig::sin_cos(phi);
    let p4 = phi.powi(4);
    ((phi * sin - 2.0 * (1.0 - cos)) / p4, (3.0 * sin - 2.0 * phi - phi * cos) / (p4 * phi))
}

/// `exp(θ/2)`: for rotations up to a half turn (all of a dense chain's) straight from the
/// polynomials in `|θ|²/4`, with no square root, division or reduction.
#[inline]
fn exp_half(theta: DVec3) -> DQuat {
    let y = 0.25 * theta.length_squared();
    if y > (0.25 * std::f64::consts::PI).powi(2) {
        return exp(theta * 0.5);
    }
    let (sinc, cos) = crate::trig::sinc_cos_small_squared(crate::lanes::Lanes::splat(y));
    let v = theta * (0.5 * sinc.to_array()[0]);
    DQuat::from_xyzw(v.x, v.y, v.z, cos.to_array()[0])
}

/// `[v]×`, so that `[v]× u = v × u`.
fn cross_matrix(v: DVec3) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(0.0, v.z, -v.y),
        DVec3::new(-v.z, 0.0, v.x),
        DVec3::new(v.y, -v.x, 0.0),
    )
}

/// `J(θ)`, the map from `θ'` to the body rate `Ω` of `exp(θ/2)`.
fn jacobian(theta: DVec3) -> DMat3 {
    let (k1, k2) = k12(theta.length());
    let c = cross_matrix(theta);
    DMat3::IDENTITY - c * k1 + c * c * k2
}

/// A piece's end rotation vector `θ = Δ` with the coefficients of `N` at it, computed once: the
/// Newton steps evaluate `N` and its derivative there many times.
struct Turn {
    theta: DVec3,
    k2: f64,
    /// `[θ]×`
    cross: DMat3,
    /// `A = −(k₁'/φ)[θ]× + (k₂'/φ)[θ]×²`
    a: DMat3,
}

impl Turn {
    fn new(theta: DVec3) -> Self {
        let (dk1, dk2) = dk12(theta.length());
        let (_, k2) = k12(theta.length());
        let cross = cross_matrix(theta);
        Turn { theta, k2, cross, a: cross * (-dk1) + cross * cross * dk2 }
    }

    /// `N(θ, v) = (dJ/ds) v = (θ·v) A v + k₂ v × (θ × v)`, with `φ' = θ·v/φ`.
    fn n(&self, v: DVec3) -> DVec3 {
        self.theta.dot(v) * (self.a * v) + self.k2 * v.cross(self.theta.cross(v))
    }

    /// `∂N(θ, v)/∂v`.
    fn dn(&self, v: DVec3) -> DMat3 {
        let (theta, a) = (self.theta, self.a);
        let outer = DMat3::from_cols(a * v * theta.x, a * v * theta.y, a * v * theta.z);
        // d/dv [v × (θ × v)] e = e × (θ × v) + v × (θ × e)
        let cross = cross_matrix(v) * self.cross - cross_matrix(theta.cross(v));
        outer + a * theta.dot(v) + cross * self.k2
    }
}

/// Solves `lower_j x_{j−1} + diagonal_j x_j + upper_j x_{j+1} = rhs_j` (block Thomas).
fn solve_block_tridiagonal(
    lower: &[DMat3],
    diagonal: &[DMat3],
    upper: &[DMat3],
    rhs: &[DVec3],
) -> Vec<DVec3> {
    let n = rhs.len();
    let mut solved_upper = Vec::with_capacity(n);
    let mut forward = Vec::with_capacity(n);
    for j in 0..n {
        let (m, r) = if j == 0 {
            (diagonal[0], rhs[0])
        } else {
            (diagonal[j] - lower[j] * solved_upper[j - 1], rhs[j] - lower[j] * forward[j - 1])
        };
        let pivot = m.inverse();
        solved_upper.push(pivot * upper[j]);
        forward.push(pivot * r);
    }
    let mut x = vec![DVec3::ZERO; n];
    for j in (0..n).rev() {
        x[j] = if j + 1 < n { forward[j] - solved_upper[j] * x[j + 1] } else { forward[j] };
    }
    x
}

impl RotvecCubic {
    /// The cubic through `samples` at `times` (at least two; times increasing; consecutive
    /// samples less than a half turn apart, which the chain's are by far). Errs when the input
    /// is not that (the samples and times checked as [`Keys`](super::Keys) checks keys: errors
    /// name `keys[i]` or `times[i]`), or when the rates do not settle, which needs consecutive
    /// samples near a half turn apart or spans too short to square.
    pub fn new(samples: &[DQuat], times: &[f64]) -> Result<Self, KliError> {
        let checked = super::Keys::unchecked_spans(samples, Some(times))?;
        let (samples, times) = (checked.quaternions(), checked.times());
        let n = samples.len();
        let h: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
        let delta: Vec<DVec3> = samples
            .windows(2)
            .map(|w| {
                let relative = w[0].conjugate() * w[1];
                2.0 * log(if relative.w < 0.0 { -relative } else { relative })
            })
            .collect();
        let jac: Vec<DMat3> = delta.iter().map(|&d| jacobian(d)).collect();
        let inv: Vec<DMat3> = jac.iter().map(|j| j.inverse()).collect();
        let turns: Vec<Turn> = delta.iter().map(|&d| Turn::new(d)).collect();

        // Rows `F_j = lower_j ω_{j−1} + diagonal_j ω_j + upper_j ω_{j+1} + N_j − rhs_j = 0`, with
        // `N_j = N(Δ_{j−1}, J(Δ_{j−1})⁻¹ ω_j)`, solved by Newton: `N_j`'s derivative joins the
        // diagonal block. From zero rates the first step is the linear solve (N is quadratic).
        let lower: Vec<DMat3> = (0..n)
            .map(|j| if j > 0 { jac[j - 1] * (2.0 / h[j - 1]) } else { DMat3::ZERO })
            .collect();
        let upper: Vec<DMat3> =
            (0..n).map(|j| if j < n - 1 { inv[j] * (2.0 / h[j]) } else { DMat3::ZERO }).collect();
        let weight = |j: usize| {
            let left = if j > 0 { 4.0 / h[j - 1] } else { 0.0 };
            let right = if j < n - 1 { 4.0 / h[j] } else { 0.0 };
            left + right
        };
        let rhs: Vec<DVec3> = (0..n)
            .map(|j| {
                let left =
                    if j > 0 { delta[j - 1] * (6.0 / (h[j - 1] * h[j - 1])) } else { DVec3::ZERO };
                let right = if j < n - 1 { delta[j] * (6.0 / (h[j] * h[j])) } else { DVec3::ZERO };
                left + right
            })
            .collect();
        let residual = |rates: &[DVec3]| -> Vec<DVec3> {
            (0..n)
                .map(|j| {
                    let mut f = weight(j) * rates[j] - rhs[j];
                    if j > 0 {
                        f += lower[j] * rates[j - 1] + turns[j - 1].n(inv[j - 1] * rates[j]);
                    }
                    if j < n - 1 {
                        f += upper[j] * rates[j + 1];
                    }
                    f
                })
                .collect()
        };
        let size = |f: &[DVec3]| f.iter().map(|v| v.length()).fold(0.0, f64::max);

        let mut rates = vec![DVec3::ZERO; n];
        let mut f = residual(&rates);
        let mut iterations = 0;
        loop {
            let diagonal: Vec<DMat3> = (0..n)
                .map(|j| {
                    let d = DMat3::from_diagonal(DVec3::splat(weight(j)));
                    if j == 0 {
                        return d;
                    }
                    d + turns[j - 1].dn(inv[j - 1] * rates[j]) * inv[j - 1]
                })
                .collect();
            let minus_f: Vec<DVec3> = f.iter().map(|v| -*v).collect();
            let step = solve_block_tridiagonal(&lower, &diagonal, &upper, &minus_f);
            // Backtrack while the residual grows (far from the solution Newton can overshoot).
            let mut scale = 1.0;
            let (next, next_f) = loop {
                let trial: Vec<DVec3> =
                    rates.iter().zip(&step).map(|(r, d)| *r + *d * scale).collect();
                let trial_f = residual(&trial);
                if size(&trial_f) < size(&f) || scale < 1e-3 {
                    break (trial, trial_f);
                }
                scale *= 0.5;
            };
            let change = size(&step) * scale;
            let largest = size(&next);
            iterations += 1;
            if !(change.is_finite() && largest.is_finite()) || iterations > MAX_ITERATIONS {
                return Err(KliError::invalid(
                    "keys",
                    "give no C² curve: consecutive chain samples are too far apart (more samples a segment help)",
                ));
            }
            (rates, f) = (next, next_f);
            if change <= TOLERANCE * largest {
                break;
            }
        }

        let pieces = (0..n - 1)
            .map(|j| {
                let (hj, d, w0) = (h[j], delta[j], rates[j]);
                let w1 = inv[j] * rates[j + 1];
                let a = (w1 + w0 - d * (2.0 / hj)) / (hj * hj);
                let b = (d * (3.0 / hj) - w0 * 2.0 - w1) / hj;
                Piece { start: samples[j], rate: w0, b, a }
            })
            .collect();
        Ok(Self { times: times.to_vec(), pieces, end: samples[n - 1], iterations })
    }

    /// Newton steps taken by the rates.
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// `q` at fraction `u ∈ [0, 1]` of interval `j`; the last sample exactly at the end.
    pub(crate) fn at_interval(&self, j: usize, u: f64) -> DQuat {
        if j == self.pieces.len() - 1 && u >= 1.0 {
            return self.end;
        }
        let piece = &self.pieces[j];
        let s = u * (self.times[j + 1] - self.times[j]);
        let theta = s * (piece.rate + s * (piece.b + s * piece.a));
        piece.start * exp_half(theta)
    }

    /// The world-frame angular velocity `ω = q Ω q̄` at fraction `u` of interval `j`, with the
    /// body rate `Ω = J(θ) θ'` exact (no differences).
    pub(crate) fn angular_velocity_interval(&self, j: usize, u: f64) -> DVec3 {
        let piece = &self.pieces[j];
        let s = u * (self.times[j + 1] - self.times[j]);
        let theta = s * (piece.rate + s * (piece.b + s * piece.a));
        let dtheta = piece.rate + s * (2.0 * piece.b + 3.0 * s * piece.a);
        let body = jacobian(theta) * dtheta;
        let q = piece.start * exp_half(theta);
        q * body
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The body rate of `exp(θ(s)/2)` by a central difference, `2 q̄ q'`: independent of `J`.
    fn body_rate(theta: impl Fn(f64) -> DVec3, s: f64) -> DVec3 {
        let d = 1e-6;
        let (a, b) = (exp(theta(s - d) * 0.5), exp(theta(s + d) * 0.5));
        let w = exp(theta(s) * 0.5).conjugate() * ((b - a) / (2.0 * d)) * 2.0;
        DVec3::new(w.x, w.y, w.z)
    }

    #[test]
    fn the_jacobian_maps_the_rotation_vectors_rate_to_the_body_rate() {
        for (theta, dtheta) in [
            (DVec3::new(0.3, -0.2, 0.1), DVec3::new(1.0, 2.0, -0.5)),
            (DVec3::new(0.29, 0.3, 0.2), DVec3::new(-1.0, 0.4, 0.7)), // |θ| = 0.46: series
            (DVec3::new(1.5, 1.0, -2.0), DVec3::new(0.2, -0.3, 0.9)),
            (DVec3::new(1e-5, 0.0, 2e-5), DVec3::new(0.0, 1.0, 0.0)),
        ] {
            let by_difference = body_rate(|s| theta + s * dtheta, 0.0);
            let exact = jacobian(theta) * dtheta;
            assert!((by_difference - exact).length() < 1e-9, "{theta}: {by_difference} vs {exact}");
            // N = (d/ds J(θ + s θ')) θ', by a central difference of J.
            let d = 1e-5;
            let numeric =
                (jacobian(theta + d * dtheta) - jacobian(theta - d * dtheta)) * dtheta / (2.0 * d);
            let turn = Turn::new(theta);
            let n = turn.n(dtheta);
            assert!((numeric - n).length() < 1e-8, "{theta}: {numeric} vs {n}");
            // ∂N/∂v, by central differences of N along each axis.
            let derivative = turn.dn(dtheta);
            for (axis, e) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
                let numeric = (turn.n(dtheta + d * e) - turn.n(dtheta - d * e)) / (2.0 * d);
                let column = derivative.col(axis);
                assert!(
                    (numeric - column).length() < 1e-8,
                    "{theta}, {axis}: {numeric} vs {column}"
                );
            }
        }
    }

    #[test]
    fn the_series_and_the_closed_forms_agree_where_they_meet() {
        let (below, above) = (SERIES_BELOW * (1.0 - 1e-12), SERIES_BELOW);
        let [(a1, a2), (b1, b2)] = [k12(below), k12(above)];
        let [(c1, c2), (d1, d2)] = [dk12(below), dk12(above)];
        for (x, y) in [(a1, b1), (a2, b2), (c1, d1), (c2, d2)] {
            assert!((x - y).abs() < 1e-12 * y.abs(), "{x} vs {y}");
        }
        // The leading terms: k₁ → 1/2, k₂ → 1/6, k₁'/φ → −1/12, k₂'/φ → −1/60.
        let (k1, k2) = k12(0.0);
        let (dk1, dk2) = dk12(0.0);
        assert_eq!((k1, k2, dk1, dk2), (0.5, 1.0 / 6.0, -1.0 / 12.0, -1.0 / 60.0));
    }

    #[test]
    fn a_constant_rate_rotation_is_reproduced_between_uneven_samples() {
        // q(t) = q₀ exp(t v/2): θ is linear in every piece, so the cubic is that curve exactly.
        let q0 = DQuat::from_xyzw(0.1, -0.5, 0.3, 0.8).normalize();
        let v = DVec3::new(0.7, -1.1, 0.4);
        let times = [0.0, 0.3, 0.35, 1.0, 1.9, 2.0, 3.2];
        let samples: Vec<DQuat> = times.iter().map(|&t| q0 * exp(v * (0.5 * t))).collect();
        let cubic = RotvecCubic::new(&samples, &times).unwrap();
        for j in 0..times.len() - 1 {
            for k in 0..=10 {
                let u = k as f64 / 10.0;
                let t = times[j] + u * (times[j + 1] - times[j]);
                let expected = q0 * exp(v * (0.5 * t));
                assert!((cubic.at_interval(j, u) - expected).length() < 1e-14, "t = {t}");
                // ω = q Ω q̄ with the body rate v: the world rate is q₀ v q̄₀ (exp(tv/2) fixes v).
                let w = cubic.angular_velocity_interval(j, u);
                assert!((w - q0 * v).length() < 1e-13, "t = {t}: {w}");
            }
        }
    }

    #[test]
    fn two_samples_give_the_great_arc_at_constant_speed() {
        let (p, r) = (DQuat::IDENTITY, DQuat::from_xyzw(0.5, 0.5, 0.5, 0.5));
        let cubic = RotvecCubic::new(&[p, r], &[1.0, 3.0]).unwrap();
        for k in 0..=8 {
            let u = k as f64 / 8.0;
            let expected = crate::spline::slerp(p, r, u);
            assert!((cubic.at_interval(0, u) - expected).length() < 1e-15, "u = {u}");
        }
        assert_eq!(cubic.at_interval(0, 1.0), r);
    }

    #[test]
    fn samples_near_a_half_turn_apart_about_turning_axes_settle_and_are_hit() {
        // Consecutive samples 179.99° apart about different axes, even and 10⁶-uneven spans:
        // Newton settles (the fixed point on N alone diverged here) and the curve is unit and
        // through the samples. (Where it cannot settle, tests.rs: the chain falls back to C¹.)
        let turn = |deg: f64, axis: DVec3| exp(axis.normalize() * (0.5 * deg.to_radians()));
        let (x, y) = (DVec3::X, DVec3::new(0.0, 1.0, 1.0));
        let samples =
            [DQuat::IDENTITY, turn(179.99, x), turn(179.99, x) * turn(179.99, y), turn(90.0, y)];
        for times in [[0.0, 1.0, 2.0, 3.0], [0.0, 1e-6, 1.0, 1.0 + 1e-6]] {
            let cubic = RotvecCubic::new(&samples, &times).unwrap();
            // It stops on a step that changes nothing: at least two.
            assert!((2..=10).contains(&cubic.iterations()), "{times:?}: {}", cubic.iterations());
            for j in 0..3 {
                assert!((cubic.at_interval(j, 0.0) - samples[j]).length() < 1e-15);
                let end = cubic.at_interval(j, 1.0);
                assert!((end.dot(samples[j + 1]).abs() - 1.0).abs() < 1e-12, "{times:?} {j}");
                for k in 0..=20 {
                    let q = cubic.at_interval(j, k as f64 / 20.0);
                    assert!((q.length() - 1.0).abs() < 1e-12, "{times:?} {j} {k}: {q}");
                }
            }
        }
    }
}
