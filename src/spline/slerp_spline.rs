//! Piecewise SLERP between consecutive keys (three.js's `QuaternionKeyframeTrack`): constant
//! angular velocity on each segment, jumping at the keys.

use glam::DQuat;

use super::{Curve, Keys, locate, slerp};

/// SLERP from key to key.
#[derive(Debug, Clone)]
pub struct PiecewiseSlerp {
    keys: Keys,
}

impl PiecewiseSlerp {
    pub fn new(keys: Keys) -> Self {
        Self { keys }
    }

    pub fn keys(&self) -> &Keys {
        &self.keys
    }
}

impl Curve for PiecewiseSlerp {
    fn at(&self, t: f64) -> DQuat {
        let (i, u) = locate(self.keys.times(), t);
        let q = self.keys.quaternions();
        slerp(q[i], q[i + 1], u)
    }

    fn start_time(&self) -> f64 {
        self.keys.times()[0]
    }

    fn end_time(&self) -> f64 {
        *self.keys.times().last().unwrap_or(&0.0)
    }
}
