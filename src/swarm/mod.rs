//! The non-abelian Kuramoto (Lohe) model on S³ (MATH.md, "The swarm"): `N` oscillators
//!
//! ```text
//! q_i' = w_i q_i + (K/N) Σ_j a_ij (q_j - (q_i·q_j) q_i)
//! ```
//!
//! with coupling `K`, graph weights `a_ij` ([`Graph`]) and left natural frequencies `w_i` (pure
//! quaternions). Identical oscillators (`w = 0`) all-to-all follow the gradient of the potential
//! `(K N / 2)|m|²`: with `K > 0` they synchronise (`R → 1`), with `K < 0` they balance (`R → 0`).
//! KLI is the smallest case: one pinned leader `r` and one follower, whose equation
//! `q' = (K/2)(r - (q·r) q)` is the paper's at time `K t / 2`.
//!
//! Steps are geodesic RK4: the classical RK4 increment of every oscillator, taken along its great
//! circle, so each `|q_i| = 1` to rounding (Euler plus renormalising would turn about the wrong
//! axis).
//!
//! ```
//! use kli::swarm::{Graph, Swarm, SwarmOptions};
//!
//! let mut swarm = Swarm::new(&SwarmOptions { count: 500, coupling: 1.0, graph: Graph::All, seed: 7, ..Default::default() })?;
//! swarm.step(0.05, 400)?;
//! assert!(swarm.order_parameter() > 0.999); // identical oscillators, K > 0: they synchronise
//! # Ok::<(), kli::KliError>(())
//! ```

mod order;
mod random;

pub use order::{mean, order_parameter, rotation_order};
pub use random::Random;

use std::str::FromStr;

use glam::{DQuat, DVec3};

use crate::error::{ErrorKind, KliError, Requirement, require};
use crate::hopf::hopf;
use crate::integrator::along_great_circle;
use crate::quaternion::unit;

/// Who is coupled to whom.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Graph {
    /// Every pair (`a_ij = 1`): one step costs O(N), through the mean.
    #[default]
    All,
    /// Each oscillator to its two neighbours on a ring (one, for `N = 2`).
    Ring,
    /// All-to-all, but the first [`SwarmOptions::leaders`] oscillators are pinned: they pull
    /// and are not pulled.
    Leader,
}

impl Graph {
    /// The name in the JavaScript API: `"all"`, `"ring"`, `"leader"`.
    pub fn name(self) -> &'static str {
        match self {
            Graph::All => "all",
            Graph::Ring => "ring",
            Graph::Leader => "leader",
        }
    }
}

const GRAPHS: [&str; 3] = ["all", "ring", "leader"];

impl FromStr for Graph {
    type Err = KliError;

    fn from_str(name: &str) -> Result<Self, KliError> {
        [Graph::All, Graph::Ring, Graph::Leader].into_iter().find(|g| g.name() == name).ok_or_else(
            || {
                KliError::new(
                    "graph",
                    ErrorKind::UnknownName { got: name.into(), allowed: &GRAPHS },
                )
            },
        )
    }
}

/// The most oscillators a swarm may hold.
pub const MAX_COUNT: usize = 1_000_000;

/// The largest `|K|` and frequency spread: with them and [`MAX_STEP`] every RK4 stage stays
/// finite (a slope is at most about `|K| + 6σ√3`), so the swarm stays finite and on S³.
pub const MAX_RATE: f64 = 1e6;

/// The largest start spread, in radians: beyond a few π the start is uniform anyway.
pub const MAX_START_SPREAD: f64 = 1000.0;

/// The largest time step `dt`.
pub const MAX_STEP: f64 = 100.0;

/// The most steps one [`Swarm::step`] call takes (the JavaScript API's bound too).
pub const MAX_STEPS: usize = 1_000_000;

/// How to build a [`Swarm`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SwarmOptions {
    /// `N`, from 1 to [`MAX_COUNT`].
    pub count: usize,
    /// `K`: > 0 synchronises, < 0 balances.
    pub coupling: f64,
    pub graph: Graph,
    /// For [`Graph::Leader`]: how many of the oscillators (the first ones) are pinned, 1 to `N`.
    pub leaders: usize,
    /// The standard deviation of each component of the natural frequencies `w_i`, `≥ 0`.
    pub frequency_spread: f64,
    /// `None`: a start uniform on S³; `Some(σ)`: near the identity, `σ` radians of spread in
    /// each direction of S³ (see [`Random::near`]).
    pub start_spread: Option<f64>,
    /// The same seed gives the same swarm.
    pub seed: u64,
}

impl Default for SwarmOptions {
    fn default() -> Self {
        Self {
            count: 200,
            coupling: 1.0,
            graph: Graph::All,
            leaders: 1,
            frequency_spread: 0.0,
            start_spread: None,
            seed: 1,
        }
    }
}

impl SwarmOptions {
    /// Checks every option; errors name it.
    pub fn validate(&self) -> Result<(), KliError> {
        let count = self.count;
        if !(1..=MAX_COUNT).contains(&count) {
            let requirement = Requirement::Between(1.0, MAX_COUNT as f64);
            let kind = ErrorKind::OutOfRange { value: count as f64, requirement };
            return Err(KliError::new("count", kind));
        }
        require("coupling", self.coupling, Requirement::AtMost(MAX_RATE))?;
        let spread = Requirement::Between(0.0, MAX_RATE);
        require("frequency_spread", self.frequency_spread, spread)?;
        if let Some(start) = self.start_spread {
            require("start_spread", start, Requirement::Between(0.0, MAX_START_SPREAD))?;
        }
        if self.graph == Graph::Leader && !(1..=count).contains(&self.leaders) {
            let problem =
                format!("must be a whole number from 1 to count ({count}) (got {})", self.leaders);
            return Err(KliError::invalid("leaders", problem));
        }
        Ok(())
    }
}

/// `N` oscillators on S³ and the time they have run.
#[derive(Debug, Clone)]
pub struct Swarm {
    quaternions: Vec<DQuat>,
    /// `w_i` as pure quaternions (zero for the pinned).
    frequencies: Vec<DQuat>,
    coupling: f64,
    graph: Graph,
    /// How many of the first oscillators are pinned (0 unless [`Graph::Leader`]).
    pinned: usize,
    time: f64,
    /// The RK4 stages' slopes and state, kept so a step allocates nothing.
    scratch: [Vec<DQuat>; 5],
}

impl Swarm {
    /// A swarm as `options` say, from its seed.
    pub fn new(options: &SwarmOptions) -> Result<Self, KliError> {
        options.validate()?;
        let n = options.count;
        let mut random = Random::new(options.seed);
        let quaternions: Vec<DQuat> = (0..n)
            .map(|_| match options.start_spread {
                None => random.unit_quaternion(),
                Some(spread) => random.near(DQuat::IDENTITY, spread),
            })
            .collect();
        let pinned = if options.graph == Graph::Leader { options.leaders } else { 0 };
        let frequencies = (0..n)
            .map(|i| {
                let v = random.gaussian3() * options.frequency_spread;
                if i < pinned { pure(DVec3::ZERO) } else { pure(v) }
            })
            .collect();
        let zero = vec![pure(DVec3::ZERO); n];
        Ok(Self {
            quaternions,
            frequencies,
            coupling: options.coupling,
            graph: options.graph,
            pinned,
            time: 0.0,
            scratch: [zero.clone(), zero.clone(), zero.clone(), zero.clone(), zero],
        })
    }

    /// `N`.
    pub fn len(&self) -> usize {
        self.quaternions.len()
    }

    /// Never: a swarm holds at least one oscillator.
    pub fn is_empty(&self) -> bool {
        self.quaternions.is_empty()
    }

    /// The time run so far.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// `q_i`, unit quaternions.
    pub fn quaternions(&self) -> &[DQuat] {
        &self.quaternions
    }

    /// Replaces every `q_i` (normalised; the count must match). The time is kept.
    pub fn set_quaternions(&mut self, quaternions: &[DQuat]) -> Result<(), KliError> {
        if quaternions.len() != self.len() {
            let problem =
                format!("must hold {} quaternions (got {})", self.len(), quaternions.len());
            return Err(KliError::invalid("quaternions", problem));
        }
        for (i, (slot, &q)) in self.quaternions.iter_mut().zip(quaternions).enumerate() {
            *slot = unit("quaternions", q).map_err(|e| e.renamed(format!("quaternions[{i}]")))?;
        }
        Ok(())
    }

    /// `steps` geodesic RK4 steps of `dt` (finite, > 0, at most [`MAX_STEP`]); `steps` at most
    /// [`MAX_STEPS`], so a call's work is bounded (`O(N · steps)`).
    pub fn step(&mut self, dt: f64, steps: usize) -> Result<(), KliError> {
        let dt = require("dt", dt, Requirement::Positive)?;
        require("dt", dt, Requirement::AtMost(MAX_STEP))?;
        if steps > MAX_STEPS {
            let requirement = Requirement::Between(0.0, MAX_STEPS as f64);
            let kind = ErrorKind::OutOfRange { value: steps as f64, requirement };
            return Err(KliError::new("steps", kind));
        }
        for _ in 0..steps {
            self.rk4_step(dt);
        }
        Ok(())
    }

    fn rk4_step(&mut self, h: f64) {
        let [k1, k2, k3, k4, stage] = &mut self.scratch;
        let q = &self.quaternions;
        let field = |state: &[DQuat], out: &mut [DQuat]| {
            field(state, &self.frequencies, self.coupling, self.graph, self.pinned, out)
        };
        field(q, k1);
        offset(q, k1, 0.5 * h, stage);
        field(stage, k2);
        offset(q, k2, 0.5 * h, stage);
        field(stage, k3);
        offset(q, k3, h, stage);
        field(stage, k4);
        for (i, q) in self.quaternions.iter_mut().enumerate() {
            let increment = (k1[i] + (k2[i] + k3[i]) * 2.0 + k4[i]) * (h / 6.0);
            // Renormalised: the step keeps |q| = 1 only to first order in its error, and under
            // fast frequencies that error grows from step to step (|q| fell to 0.04 at σ = 2,
            // dt = 0.5).
            *q = along_great_circle(*q, increment).normalize();
        }
        self.time += h;
    }

    /// `R = |m|` (see [`order_parameter`]).
    pub fn order_parameter(&self) -> f64 {
        order_parameter(&self.quaternions)
    }

    /// `λ_max(Q)` (see [`rotation_order`]).
    pub fn rotation_order(&self) -> f64 {
        rotation_order(&self.quaternions)
    }

    /// `(K N / 2)|m|²`: for identical oscillators all-to-all, the potential whose gradient the
    /// flow follows, so it never decreases.
    pub fn potential(&self) -> f64 {
        0.5 * self.coupling * self.len() as f64 * mean(&self.quaternions).length_squared()
    }

    /// The Hopf image of each oscillator on S² (where it sends the body x-axis).
    pub fn hopf_points(&self) -> Vec<DVec3> {
        self.quaternions.iter().map(|&q| hopf(q)).collect()
    }
}

/// The pure quaternion `v`.
fn pure(v: DVec3) -> DQuat {
    DQuat::from_xyzw(v.x, v.y, v.z, 0.0)
}

/// `out = q + h k`.
fn offset(q: &[DQuat], k: &[DQuat], h: f64, out: &mut [DQuat]) {
    for ((o, &q), &k) in out.iter_mut().zip(q).zip(k) {
        *o = q + k * h;
    }
}

/// The vector field at `state` into `out`. All-to-all (and leaders): the coupling sum is
/// `N m - N (q_i·m) q_i`, so `f_i = w_i q_i + K (m - (q_i·m) q_i)`.
fn field(
    state: &[DQuat],
    frequencies: &[DQuat],
    coupling: f64,
    graph: Graph,
    pinned: usize,
    out: &mut [DQuat],
) {
    let n = state.len();
    match graph {
        Graph::All | Graph::Leader => {
            let m = mean(state);
            for (i, ((o, &q), &w)) in out.iter_mut().zip(state).zip(frequencies).enumerate() {
                *o = if i < pinned {
                    pure(DVec3::ZERO)
                } else {
                    w * q + (m - q * q.dot(m)) * coupling
                };
            }
        }
        Graph::Ring => {
            let k = coupling / n as f64;
            for (i, ((o, &q), &w)) in out.iter_mut().zip(state).zip(frequencies).enumerate() {
                let (before, after) = ((i + n - 1) % n, (i + 1) % n);
                let pull = |j: usize| {
                    if j == i { pure(DVec3::ZERO) } else { state[j] - q * q.dot(state[j]) }
                };
                // For N = 2 both neighbours are the same oscillator: one edge, counted once.
                let coupled =
                    if before == after { pull(after) } else { pull(before) + pull(after) };
                *o = w * q + coupled * k;
            }
        }
    }
}

#[cfg(test)]
mod tests;
