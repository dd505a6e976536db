//! Piecewise SLERP between consecutive keys (three.js's `QuaternionKeyframeTrack`): constant
//! angular velocity on each segment, jumping at the keys.

use glam::DQuat;

use super::{Curve, Keys, locate};
use crate::great_arc::GreatArc;

/// SLERP from key to key.
#[derive(Debug, Clone)]
pub struct PiecewiseSlerp {
    keys: Keys,
    /// The arc of each segment, built once.
    arcs: Vec<GreatArc>,
}

impl PiecewiseSlerp {
    pub fn new(keys: Keys) -> Self {
        let q = keys.quaternions();
        let arcs = q
            .windows(2)
            .map(|w| GreatArc::new(w[0], w[1], false).unwrap_or_else(|_| GreatArc::at_point(w[0])))
            .collect();
        Self { keys, arcs }
    }

    pub fn keys(&self) -> &Keys {
        &self.keys
    }
}

impl Curve for PiecewiseSlerp {
    fn at(&self, t: f64) -> DQuat {
        let (i, u) = locate(self.keys.times(), t);
        crate::slerp::point_at(&self.arcs[i], u)
    }

    fn start_time(&self) -> f64 {
        self.keys.times()[0]
    }

    fn end_time(&self) -> f64 {
        *self.keys.times().last().unwrap_or(&0.0)
    }
}
