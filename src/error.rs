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

impl KliError {
    /// The message, with numbers written by `number`. The JavaScript boundary passes
    /// JavaScript's own `String(x)`, so the wasm build carries no float-formatting code.
    pub fn message_with(&self, number: &dyn Fn(f64) -> String) -> String {
        let n = number;
        match self {
            KliError::InvalidQuaternion { name, problem } => {
                format!("{name} must be a quaternion of 4 finite numbers [w, x, y, z], not all zero: {problem}")
            }
            KliError::InvalidNumber { name, value, requirement } => format!("{name} must be {requirement} (got {})", n(*value)),
            KliError::InvalidArgument { name, problem } => format!("{name} {problem}"),
            KliError::Antipodal => "p and r are antipodal (p = -r) and shortestPath is false: q' = 0 there, an unstable \
                 equilibrium, so the flow never moves and no path is determined (p and r are the same \
                 rotation; use shortestPath: true)"
                .into(),
            KliError::NotReached { tolerance, max_time, closest, predicted } => format!(
                "tolerance {} not reached within maxTime {} (closest distance {}; the closed form \
                 predicts T* = {}): raise maxTime or the tolerance",
                n(*tolerance),
                n(*max_time),
                n(*closest),
                n(*predicted)
            ),
            KliError::Stalled { time, distance } => format!(
                "p is so close to -r that a step does not move q (stuck at distance {} from the target \
                 at t = {}): with shortestPath false the flow starts at a numerical equilibrium; use \
                 shortestPath: true or a larger step",
                n(*distance),
                n(*time)
            ),
            KliError::LeftSphere { integrator, time, norm } => format!(
                "integrator {integrator} left the sphere S³ (|q| = {} at t = {}): near -r the sphere \
                 repels the rounding errors of a step taken in R⁴; use integrator \"geodesic\", which \
                 stays on S³, or shortestPath: true",
                n(*norm),
                n(*time)
            ),
            KliError::TooManySteps { steps, limit } => format!(
                "step is too small for maxTime: maxTime / step = {} steps, more than the {limit} a path \
                 may hold",
                n(*steps)
            ),
        }
    }
}

/// Rust's way of writing a number in a message: exponent form for the very small and large.
pub fn rust_number(x: f64) -> String {
    if x != 0.0 && x.is_finite() && (x.abs() < 1e-4 || x.abs() >= 1e16) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

impl fmt::Display for KliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message_with(&rust_number))
    }
}

/// Names a value that is not finite, without float formatting: `NaN`, `Infinity`, `-Infinity`.
pub(crate) fn non_finite(x: f64) -> &'static str {
    if x.is_nan() {
        "NaN"
    } else if x > 0.0 {
        "Infinity"
    } else {
        "-Infinity"
    }
}

impl std::error::Error for KliError {}

impl KliError {
    /// The same error about another argument, e.g. `starts[3]` instead of `p` in a batch call.
    pub fn renamed(self, new_name: impl Into<String>) -> Self {
        match self {
            KliError::InvalidQuaternion { problem, .. } => {
                KliError::InvalidQuaternion { name: new_name.into(), problem }
            }
            KliError::InvalidNumber { value, requirement, .. } => {
                KliError::InvalidNumber { name: new_name.into(), value, requirement }
            }
            KliError::InvalidArgument { problem, .. } => {
                KliError::InvalidArgument { name: new_name.into(), problem }
            }
            other => other,
        }
    }
}

/// Checks that `value` is finite and `> 0`.
pub(crate) fn require_positive(name: &'static str, value: f64) -> Result<f64, KliError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(KliError::InvalidNumber {
            name: name.into(),
            value,
            requirement: "a finite number > 0",
        })
    }
}

/// Checks that `value` is finite and `≥ 0`.
pub(crate) fn require_non_negative(name: &'static str, value: f64) -> Result<f64, KliError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(KliError::InvalidNumber {
            name: name.into(),
            value,
            requirement: "a finite number ≥ 0",
        })
    }
}
