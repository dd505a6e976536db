//! Keyframes as the curves use them: unit quaternions with consistent signs
//! (`k_{i+1}·k_i ≥ 0`, the shorter way between consecutive keys) at strictly increasing times.

use glam::DQuat;

use crate::error::{ErrorKind, KliError, Requirement, require, rust_number};
use crate::quaternion::unit;

/// The largest key time's magnitude: 1e15 keeps a millisecond timestamp (1.7e12) and its
/// spans' digits, and every difference of times finite.
pub const MAX_TIME: f64 = 1e15;

/// The shortest span between keys, absolute and relative to the whole time range.
pub const MIN_SPAN: f64 = 1e-9;

/// Checked keyframes.
#[derive(Debug, Clone, PartialEq)]
pub struct Keys {
    quaternions: Vec<DQuat>,
    times: Vec<f64>,
}

impl Keys {
    /// `quaternions` (normalised, signs made consistent) at `times` (`None`: 0, 1, …, m−1).
    /// Errors name the element: `keys[3]`, `times[2]`.
    pub fn new(quaternions: &[DQuat], times: Option<&[f64]>) -> Result<Self, KliError> {
        let keys = Self::unchecked_spans(quaternions, times)?;
        keys.check_spans()?;
        Ok(keys)
    }

    /// [`Keys::new`] without the shortest-span rule: for the chain's own samples, a segment's
    /// span divided evenly (the rule holds for the keys the caller gave).
    pub(crate) fn unchecked_spans(
        quaternions: &[DQuat],
        times: Option<&[f64]>,
    ) -> Result<Self, KliError> {
        let m = quaternions.len();
        if m < 2 {
            return Err(KliError::invalid(
                "keys",
                format!("must hold at least 2 quaternions (got {m})"),
            ));
        }
        let mut keys = Vec::with_capacity(m);
        for (i, &q) in quaternions.iter().enumerate() {
            let q = unit("keys", q).map_err(|e| e.renamed(format!("keys[{i}]")))?;
            let previous: Option<&DQuat> = keys.last();
            keys.push(match previous {
                Some(p) if p.dot(q) < 0.0 => -q,
                _ => q,
            });
        }
        let times = match times {
            None => (0..m).map(|i| i as f64).collect(),
            Some(times) => {
                if times.len() != m {
                    let kind = ErrorKind::Invalid(format!(
                        "must hold one time per key: {m} (got {})",
                        times.len()
                    ));
                    return Err(KliError::new("times", kind));
                }
                for (i, &t) in times.iter().enumerate() {
                    require("times", t, Requirement::AtMost(MAX_TIME))
                        .map_err(|e| e.renamed(format!("times[{i}]")))?;
                    if i > 0 && t <= times[i - 1] {
                        let problem = format!(
                            "must be greater than times[{}] (strictly increasing times)",
                            i - 1
                        );
                        return Err(KliError::invalid(format!("times[{i}]"), problem));
                    }
                }
                times.to_vec()
            }
        };
        Ok(Self { quaternions: keys, times })
    }

    /// A span too short beside the whole range (or below [`MIN_SPAN`]) makes ω and ω̇ overflow
    /// or the chain's solve ill-conditioned.
    fn check_spans(&self) -> Result<(), KliError> {
        let times = &self.times;
        let m = times.len();
        let shortest = MIN_SPAN.max(MIN_SPAN * (times[m - 1] - times[0]));
        for i in 1..m {
            if times[i] - times[i - 1] < shortest {
                let problem = format!(
                    "must be at least {} after times[{}] (no span may be shorter than 1e-9 × \
                     the whole time range, nor than 1e-9)",
                    rust_number(shortest),
                    i - 1
                );
                return Err(KliError::invalid(format!("times[{i}]"), problem));
            }
        }
        Ok(())
    }

    /// The keys as used: unit, with consistent signs.
    pub fn quaternions(&self) -> &[DQuat] {
        &self.quaternions
    }

    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// `m`, at least 2.
    pub fn len(&self) -> usize {
        self.quaternions.len()
    }

    /// Never: keys hold at least two quaternions.
    pub fn is_empty(&self) -> bool {
        self.quaternions.is_empty()
    }
}
