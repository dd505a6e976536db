//! The literal reading of the paper for many keys: Algorithm 1 run from each key to the next,
//! each stopping within `ε` of its target, the segment's KLI time `[0, T_i]` stretched over the
//! key interval `[t_i, t_{i+1}]`. Between integrated samples, normalised linear interpolation.
//! Each segment starts exactly at its key, so the curve jumps by up to `ε` at the keys, and its
//! angular velocity jumps there as well (KLI slows to a crawl near each target).

use glam::DQuat;

use super::{Curve, Keys, locate};
use crate::algorithm::{KliOptions, KliPath, kli};
use crate::error::KliError;

/// Algorithm 1 key to key.
#[derive(Debug, Clone)]
pub struct SequentialKli {
    keys: Keys,
    paths: Vec<KliPath>,
}

impl SequentialKli {
    /// One KLI run a segment with `options` (their `shortest_path` is moot: the keys' signs are
    /// consistent); errors as [`kli`]'s.
    pub fn new(keys: Keys, options: &KliOptions) -> Result<Self, KliError> {
        let q = keys.quaternions();
        let paths = q.windows(2).map(|w| kli(w[0], w[1], options)).collect::<Result<_, _>>()?;
        Ok(Self { keys, paths })
    }

    pub fn keys(&self) -> &Keys {
        &self.keys
    }

    /// Algorithm 1's path of each segment.
    pub fn paths(&self) -> &[KliPath] {
        &self.paths
    }
}

impl Curve for SequentialKli {
    fn at(&self, t: f64) -> DQuat {
        let (i, u) = locate(self.keys.times(), t);
        let path = &self.paths[i];
        let samples = path.quaternions();
        let position = u * path.steps() as f64;
        // u ≤ 1: n ≤ the path's steps, its last sample.
        let n = position.floor() as usize;
        let next = (n + 1).min(samples.len() - 1);
        let f = position - n as f64;
        (samples[n] * (1.0 - f) + samples[next] * f).normalize()
    }

    fn start_time(&self) -> f64 {
        self.keys.times()[0]
    }

    fn end_time(&self) -> f64 {
        *self.keys.times().last().unwrap_or(&0.0)
    }
}
