//! The paper's model on a graph: the Lohe flow of MATH.md with the measurements as twists,
//! sign-blind, the gradient flow of `F = Σ w_ij c_ij² = Σ w_ij − f/8`:
//!
//! ```text
//! q_i' = 2 Σ_j w_ij c_ij (x_ij − c_ij q_i),   x_ij = q_j q̄_ij,   c_ij = ⟨q_i, x_ij⟩
//! ```
//!
//! (an edge `(i, j)` predicts `j` as `x_ji = q_i q_ij`). Every neighbour pulls `q_i` towards its
//! prediction; with every `q_ij = 1` it is consensus, the swarm on a graph. Integrated by Euler
//! steps projected back to S³, as the swarm is: it never raises `f` for small steps.

use glam::DQuat;

use super::cost::{cost, residuals};
use super::graph::Graph;
use crate::error::{KliError, Requirement, require};
use crate::swarm::Random;

/// At most this many steps a call to [`SyncFlow::step`], so no call runs unbounded.
pub const MAX_STEPS: usize = 1_000_000;

/// The flow's state: every node's quaternion, and the time.
#[derive(Debug, Clone)]
pub struct SyncFlow {
    graph: Graph,
    q: Vec<DQuat>,
    time: f64,
    pull: Vec<DQuat>,
}

impl SyncFlow {
    /// The flow from `start` (one quaternion a node, normalised here).
    pub fn new(graph: Graph, start: &[DQuat]) -> Result<SyncFlow, KliError> {
        SyncFlow::starting(graph, start, "start")
    }

    /// As [`SyncFlow::new`], its refusals naming the caller's own argument for the start
    /// (`initial`, the file's poses, say): `initial[3]`, not `start[3]`.
    pub fn starting(graph: Graph, start: &[DQuat], argument: &str) -> Result<SyncFlow, KliError> {
        if start.len() != graph.count() {
            return Err(KliError::new(
                argument,
                crate::error::ErrorKind::WrongLength {
                    expected: 4 * graph.count(),
                    got: start.len().saturating_mul(4),
                    per: "node".into(),
                },
            ));
        }
        let q = start
            .iter()
            .enumerate()
            .map(|(i, &q)| crate::quaternion::unit(&format!("{argument}[{i}]"), q))
            .collect::<Result<Vec<_>, _>>()?;
        let pull = vec![DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0); q.len()];
        Ok(SyncFlow { graph, q, time: 0.0, pull })
    }

    /// The flow from a start drawn uniformly on S³ for every node, reproducibly from `seed`.
    pub fn random(graph: Graph, seed: u64) -> SyncFlow {
        let mut random = Random::new(seed);
        let q: Vec<DQuat> = (0..graph.count()).map(|_| random.unit_quaternion()).collect();
        let pull = vec![DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0); q.len()];
        SyncFlow { graph, q, time: 0.0, pull }
    }

    /// `steps` Euler steps of length `dt`, each followed by normalisation. Refused: `dt` not
    /// finite and `> 0`, more than [`MAX_STEPS`] steps.
    pub fn step(&mut self, dt: f64, steps: usize) -> Result<(), KliError> {
        require("dt", dt, Requirement::Positive)?;
        if steps > MAX_STEPS {
            return Err(KliError::new(
                "steps",
                crate::error::ErrorKind::TooManySteps { steps: steps as f64, limit: MAX_STEPS },
            ));
        }
        for _ in 0..steps {
            self.pull.iter_mut().for_each(|p| *p = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0));
            let edges =
                self.graph.edges().iter().zip(self.graph.relative()).zip(self.graph.weights());
            for ((&[i, j], &relative), &w) in edges {
                let x_ij = self.q[j] * relative.conjugate();
                let c = self.q[i].dot(x_ij);
                // Both pulls of the edge: i towards x_ij, j towards x_ji = q_i q_ij (the same c).
                let x_ji = self.q[i] * relative;
                self.pull[i] = self.pull[i] + (x_ij - self.q[i] * c) * (2.0 * w * c);
                self.pull[j] = self.pull[j] + (x_ji - self.q[j] * c) * (2.0 * w * c);
            }
            for (q, p) in self.q.iter_mut().zip(&self.pull) {
                let next = *q + *p * dt;
                // A step too long for the pull (dt · |q'| of order 1) could land on 0.
                let length = next.length();
                if length.is_finite() && length > 1e-150 {
                    *q = next / length;
                }
            }
            self.time += dt;
        }
        Ok(())
    }

    /// Every node's quaternion now (not anchored: the flow does not fix the gauge).
    pub fn rotations(&self) -> &[DQuat] {
        &self.q
    }

    /// The chordal cost `f` now.
    pub fn cost(&self) -> f64 {
        cost(&self.graph, &self.q)
    }

    /// Each edge's residual angle now, radians.
    pub fn residuals(&self) -> Vec<f64> {
        residuals(&self.graph, &self.q)
    }

    /// The time flowed.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The graph.
    pub fn graph(&self) -> &Graph {
        &self.graph
    }
}
