//! Section 9's turning rate: `ω(t)` along two curves through the tour's four keyframes, the
//! Kuramoto–Lohe chain at the reader's smoothness and piecewise SLERP (the chain at smoothness 0),
//! sampled for the figure, with the jump of `ω` at each inner key and the largest `|ω̇|`
//! ([`crate::turning`], as the keyframes page measures them). The keys are those the
//! `<kli-figure view="keyframes">` beside it draws (www/keyframes/state.js, `FIGURE_DEFAULTS`),
//! at times 0, 1, 2, 3; tests/e2e/learn.test.mjs checks the jump the text quotes against one it
//! computes from those keys.

use glam::{DQuat, DVec3};
use kli::spline::{ChainOptions, Curve, Keys, KliSpline, PiecewiseSlerp};
use kli::{KliError, from_wxyz};

use crate::turning;

/// The four keyframes, `[w, x, y, z]`: a 74° turn about x, then two of 123° about other axes.
/// The tour's keyframes figure beside the plot is given them (`rates.keys` of the summary).
pub const KEYS: [[f64; 4]; 4] =
    [[1.0, 0.0, 0.0, 0.0], [0.8, 0.6, 0.0, 0.0], [0.6, 0.0, 0.8, 0.0], [0.0, 0.0, 0.6, 0.8]];

/// Samples a unit of time (the keyframes page's own count).
const PER_UNIT: usize = 256;

/// One curve's `ω` at the plotted times, and what the text quotes of it.
pub struct Rate {
    /// `ω` at each of [`Rates::times`]: at an inner key, which is there twice, its value just
    /// before the key and then just after (a sample at the key itself would read a chord across
    /// a jump, drawn as a dip).
    pub omega: Vec<DVec3>,
    /// `|ω(t⁺) − ω(t⁻)|` at each inner key, in order (k1, k2).
    pub jumps: Vec<f64>,
    /// The largest `|ω̇|`, by central differences over evenly spaced samples; meaningful only
    /// where `ω` is continuous (across a jump it reads the jump over two sample intervals).
    pub acceleration: f64,
}

impl Rate {
    fn new(curve: &dyn Curve, keys: &Keys, even: &[f64]) -> Rate {
        let inner = &keys.times()[1..keys.len() - 1];
        let even_omega = turning::angular_velocities(curve, even);
        let acceleration =
            turning::accelerations(&even_omega, even[1] - even[0]).into_iter().fold(0.0, f64::max);
        let mut omega = Vec::with_capacity(even.len() + inner.len());
        for (&t, &w) in even.iter().zip(&even_omega) {
            if at_key(inner, t) {
                omega.push(curve.angular_velocity(t - turning::JUMP_STEP));
                omega.push(curve.angular_velocity(t + turning::JUMP_STEP));
            } else {
                omega.push(w);
            }
        }
        Rate {
            omega,
            jumps: inner.iter().map(|&t| turning::jump(curve, t).length()).collect(),
            acceleration,
        }
    }

    /// The largest jump and its key's index (1 for k1, …).
    pub fn largest_jump(&self) -> (f64, usize) {
        self.jumps
            .iter()
            .enumerate()
            .fold((0.0, 1), |(m, at), (i, &j)| if j > m { (j, i + 1) } else { (m, at) })
    }
}

/// The two curves' turning rates through [`KEYS`].
pub struct Rates {
    pub keys: Keys,
    pub smoothness: f64,
    /// The plotted times, evenly spaced from the first key to the last, each inner key twice
    /// (see [`Rate::omega`]).
    pub times: Vec<f64>,
    /// The chain at [`Rates::smoothness`].
    pub chain: Rate,
    /// Piecewise SLERP, the same at every smoothness.
    pub slerp: Rate,
}

impl Rates {
    /// The chain (with `smoothness`, 0 to 1) and piecewise SLERP through [`KEYS`]; errors as
    /// kliSpline's.
    pub fn new(smoothness: f64) -> Result<Rates, KliError> {
        let q: Vec<DQuat> = KEYS.iter().map(|&k| from_wxyz(k)).collect();
        let keys = Keys::new(&q, None)?;
        let chain =
            KliSpline::new(keys.clone(), &ChainOptions { smoothness, ..Default::default() })?;
        let slerp = PiecewiseSlerp::new(keys.clone());
        let (start, end) = (keys.times()[0], keys.times()[keys.len() - 1]);
        let n = ((end - start) as usize).max(1) * PER_UNIT;
        let even: Vec<f64> = (0..=n).map(|k| start + (end - start) * k as f64 / n as f64).collect();
        let inner = &keys.times()[1..keys.len() - 1];
        let times = even
            .iter()
            .flat_map(|&t| std::iter::repeat_n(t, if at_key(inner, t) { 2 } else { 1 }))
            .collect();
        Ok(Rates {
            chain: Rate::new(&chain, &keys, &even),
            slerp: Rate::new(&slerp, &keys, &even),
            keys,
            smoothness,
            times,
        })
    }

    /// Whether the chain's `ω` is continuous: at any smoothness above 0 (at 0 it is piecewise
    /// SLERP, kinks and all).
    pub fn continuous(&self) -> bool {
        self.smoothness > 0.0
    }
}

/// Whether `t` is one of the inner key times `inner` (the even samples fall on them: whole
/// multiples of 1/[`PER_UNIT`]).
fn at_key(inner: &[f64], t: f64) -> bool {
    inner.iter().any(|&k| (t - k).abs() < 1e-9)
}
