//! The one error type of the crate. Every message starts with the argument it is about, so the
//! JavaScript `Error` built from it at the boundary names that argument too.

use std::fmt;

/// Why a call was refused.
#[derive(Debug, Clone, PartialEq)]
pub enum KliError {
    /// A quaternion argument (`name`) is not 4 finite numbers of non-zero length.
    InvalidQuaternion { name: String, problem: String },
    /// A number argument (`name`) broke its requirement, e.g. "a finite number > 0".
    InvalidNumber { name: String, value: f64, requirement: &'static str },
    /// An argument that is neither a quaternion nor a number, e.g. `integrator` or an options key.
    InvalidArgument { name: String, problem: String },
    /// `p = -r` and the long way round was asked for: `q' = 0`, an equilibrium (MATH.md, edge cases).
    Antipodal,
    /// Algorithm 1 did not meet the tolerance by `max_time`.
    NotReached { tolerance: f64, max_time: f64, closest: f64, predicted: f64 },
    /// A step left `q` unchanged short of the tolerance: `p` so close to `-r` (taken the long way)
    /// that `δ q'` is below the resolution of f64, a numerical equilibrium.
    Stalled { time: f64, distance: f64 },
    /// An integrator that works in R⁴ let `|q|` run away from 1. Near `-r` the sphere repels
    /// off-sphere errors (`d|q|²/dt = 2 (q·r)(1 - |q|²)`), so rounding grows like `e^(2t)`.
    LeftSphere { integrator: &'static str, time: f64, norm: f64 },
    /// `max_time / step` asks for more samples than a path may hold.
    TooManySteps { steps: f64, limit: usize },
}

impl fmt::Display for KliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            KliError::InvalidQuaternion { name, problem } => write!(
                f,
                "{name} must be a quaternion of 4 finite numbers [w, x, y, z], not all zero: {problem}"
            ),
            KliError::InvalidNumber { name, value, requirement } => {
                write!(f, "{name} must be {requirement} (got {value})")
            }
            KliError::InvalidArgument { name, problem } => write!(f, "{name} {problem}"),
            KliError::Antipodal => write!(
                f,
                "p and r are antipodal (p = -r) and shortestPath is false: q' = 0 there, an unstable \
                 equilibrium, so the flow never moves and no path is determined (p and r are the same \
                 rotation; use shortestPath: true)"
            ),
            KliError::NotReached { tolerance, max_time, closest, predicted } => write!(
                f,
                "tolerance {tolerance:e} not reached within maxTime {max_time} (closest distance \
                 {closest:e}; the closed form predicts T* = {predicted}): raise maxTime or the tolerance"
            ),
            KliError::Stalled { time, distance } => write!(
                f,
                "p is so close to -r that a step does not move q (stuck at distance {distance} from \
                 the target at t = {time}): with shortestPath false the flow starts at a numerical \
                 equilibrium; use shortestPath: true or a larger step"
            ),
            KliError::LeftSphere { integrator, time, norm } => write!(
                f,
                "integrator {integrator} left the sphere S³ (|q| = {norm} at t = {time}): near -r the \
                 sphere repels the rounding errors of a step taken in R⁴; use integrator \"geodesic\", \
                 which stays on S³, or shortestPath: true"
            ),
            KliError::TooManySteps { steps, limit } => write!(
                f,
                "step is too small for maxTime: maxTime / step = {steps:.0} steps, more than the \
                 {limit} a path may hold"
            ),
        }
    }
}

impl std::error::Error for KliError {}

impl KliError {
    /// The same error about another argument, e.g. `starts[3]` instead of `p` in a batch call.
    pub fn renamed(self, new_name: impl Into<String>) -> Self {
        match self {
            KliError::InvalidQuaternion { problem, .. } => KliError::InvalidQuaternion { name: new_name.into(), problem },
            KliError::InvalidNumber { value, requirement, .. } => {
                KliError::InvalidNumber { name: new_name.into(), value, requirement }
            }
            KliError::InvalidArgument { problem, .. } => KliError::InvalidArgument { name: new_name.into(), problem },
            other => other,
        }
    }
}

/// Checks that `value` is finite and `> 0`.
pub(crate) fn require_positive(name: &'static str, value: f64) -> Result<f64, KliError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(KliError::InvalidNumber { name: name.into(), value, requirement: "a finite number > 0" })
    }
}

/// Checks that `value` is finite and `≥ 0`.
pub(crate) fn require_non_negative(name: &'static str, value: f64) -> Result<f64, KliError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(KliError::InvalidNumber { name: name.into(), value, requirement: "a finite number ≥ 0" })
    }
}
