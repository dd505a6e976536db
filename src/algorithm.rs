//! The KLI algorithm (paper, Algorithm 1): from `q(0) = p`, advance `T` by `δ` until
//! `||r - q(T)|| < ε`, and return the path sampled at `0, δ, 2δ, …, T`.
//!
//! `max_time` bounds the paper's otherwise endless loop (MATH.md, "Edge cases").

use glam::{DQuat, DVec3};

use crate::closed_form;
use crate::error::{KliError, require_positive};
use crate::great_arc::GreatArc;
use crate::hopf::hopf;
use crate::integrator::Integrator;

/// The most samples a path may hold (40 MB of times and quaternions).
pub const MAX_SAMPLES: usize = 1_000_000;

/// `||q| - 1|` past which a step in R⁴ is taken to have left S³. Euler on the paper's example
/// drifts by 1e-3, far inside this.
pub const LEFT_SPHERE: f64 = 0.25;

/// The knobs of Algorithm 1. `Default` gives the paper's `ε = 1e-5`, `δ = 0.01`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KliOptions {
    /// `ε`: stop once `||target - q(T)|| < ε`.
    pub tolerance: f64,
    /// `δ`: the time step.
    pub step: f64,
    /// Give up (with [`KliError::NotReached`]) past this time.
    pub max_time: f64,
    /// How each step is taken.
    pub integrator: Integrator,
    /// Go to `-r` when `p·r < 0` (the same rotation, the shorter arc).
    pub shortest_path: bool,
}

impl Default for KliOptions {
    fn default() -> Self {
        Self {
            tolerance: 1e-5,
            step: 0.01,
            max_time: 100.0,
            integrator: Integrator::Rk4,
            shortest_path: true,
        }
    }
}

impl KliOptions {
    /// Checks that `tolerance`, `step` and `max_time` are finite and positive.
    pub fn validate(&self) -> Result<(), KliError> {
        require_positive("tolerance", self.tolerance)?;
        require_positive("step", self.step)?;
        require_positive("maxTime", self.max_time)?;
        Ok(())
    }
}

/// The sampled path that Algorithm 1 returns, with the exact solution beside it.
#[derive(Debug, Clone)]
pub struct KliPath {
    times: Vec<f64>,
    quaternions: Vec<DQuat>,
    arc: GreatArc,
    options: KliOptions,
}

/// Runs Algorithm 1 from `p` towards `r` (inputs are normalised).
pub fn kli(p: DQuat, r: DQuat, options: &KliOptions) -> Result<KliPath, KliError> {
    options.validate()?;
    let arc = closed_form::arc(p, r, options.shortest_path)?;
    let target = arc.target();
    let KliOptions { tolerance, step, max_time, integrator, .. } = *options;

    // n δ ≤ max_time, forgiving the rounding of max_time / step.
    let steps_allowed = (max_time / step * (1.0 + 4.0 * f64::EPSILON)).floor();
    let last = steps_allowed.min((MAX_SAMPLES - 1) as f64) as usize;
    let predicted = closed_form::reach_time(&arc, tolerance);
    let expected = (predicted / step).ceil() as usize + 2;
    let capacity = expected.min(last + 1);
    let (mut times, mut quaternions) = (Vec::with_capacity(capacity), Vec::with_capacity(capacity));

    let mut q = arc.start();
    let mut closest = f64::INFINITY;
    for n in 0..=last {
        times.push(n as f64 * step);
        quaternions.push(q);
        let distance = (target - q).length();
        if distance < tolerance {
            return Ok(KliPath { times, quaternions, arc, options: *options });
        }
        closest = closest.min(distance);
        let next = integrator.step(q, target, step);
        // Written so that a NaN norm counts as having left.
        if !matches!(
            (next.length() - 1.0).abs().partial_cmp(&LEFT_SPHERE),
            Some(std::cmp::Ordering::Less)
        ) {
            let time = (n + 1) as f64 * step;
            return Err(KliError::LeftSphere {
                integrator: integrator.name(),
                time,
                norm: next.length(),
            });
        }
        if next == q {
            // Stuck: at the antipode (a numerical equilibrium), or at the target closer than
            // f64 resolves, where looping on to max_time would change nothing.
            if distance > 1.0 {
                return Err(KliError::Stalled { time: n as f64 * step, distance });
            }
            break;
        }
        q = next;
    }
    if quaternions.len() == last + 1 && steps_allowed > last as f64 {
        Err(KliError::TooManySteps { steps: steps_allowed, limit: MAX_SAMPLES - 1 })
    } else {
        Err(KliError::NotReached { tolerance, max_time, closest, predicted })
    }
}

impl KliPath {
    /// `T`, the time at which the tolerance was met (a multiple of `δ`).
    pub fn final_time(&self) -> f64 {
        *self.times.last().expect("a path holds at least q(0)")
    }

    /// The number of steps taken, `n`; the path holds `n + 1` samples.
    pub fn steps(&self) -> usize {
        self.times.len() - 1
    }

    /// The sample times `0, δ, …, T`.
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// `q` at each sample time, as integrated.
    pub fn quaternions(&self) -> &[DQuat] {
        &self.quaternions
    }

    /// The Hopf image `h(q)` of each sample (paper eq. 5): the path of the body x-axis.
    pub fn hopf_curve(&self) -> Vec<DVec3> {
        self.quaternions.iter().map(|&q| hopf(q)).collect()
    }

    /// The end actually used: `r`, or `-r` when `shortest_path` and `p·r < 0`.
    pub fn target(&self) -> DQuat {
        self.arc.target()
    }

    /// The arc the exact solution follows.
    pub fn arc(&self) -> &GreatArc {
        &self.arc
    }

    /// The options the path was computed with.
    pub fn options(&self) -> &KliOptions {
        &self.options
    }

    /// The exact `q(t)` for any `t ≥ 0` (MATH.md, "Closed form").
    pub fn at(&self, t: f64) -> Result<DQuat, KliError> {
        let t = crate::error::require_non_negative("t", t)?;
        Ok(closed_form::point_at(&self.arc, t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quaternion::from_wxyz;

    fn paper() -> (DQuat, DQuat) {
        (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]))
    }

    #[test]
    fn paper_example_stops_at_11_66() {
        let (p, r) = paper();
        let path = kli(p, r, &KliOptions::default()).unwrap();
        assert_eq!(path.steps(), 1166);
        assert!((path.final_time() - 11.66).abs() < 1e-12);
        assert_eq!(path.times().len(), path.quaternions().len());
        assert_eq!(path.quaternions()[0], p);
    }

    #[test]
    fn fourth_order_integrators_stop_at_the_first_grid_time_past_t_star() {
        let (p, r) = paper();
        for integrator in [Integrator::Rk4, Integrator::Geodesic] {
            let path = kli(p, r, &KliOptions { integrator, ..Default::default() }).unwrap();
            assert_eq!(path.steps(), 1166, "{integrator}");
        }
        // Euler's first-order timing error moves T by a few steps (its own error, not the model's).
        let euler =
            kli(p, r, &KliOptions { integrator: Integrator::Euler, ..Default::default() }).unwrap();
        assert!((euler.final_time() - 11.6568).abs() < 0.1, "{}", euler.final_time());
    }

    #[test]
    fn identical_ends_take_no_step() {
        let (p, _) = paper();
        let path = kli(p, p * 3.0, &KliOptions::default()).unwrap();
        assert_eq!((path.steps(), path.final_time()), (0, 0.0));
    }

    #[test]
    fn unreachable_tolerance_is_reported_not_looped() {
        let (p, r) = paper();
        let options = KliOptions { tolerance: 1e-20, max_time: 50.0, ..Default::default() };
        let err = kli(p, r, &options).unwrap_err().to_string();
        assert!(err.starts_with("tolerance 1e-20 not reached within maxTime 50"), "{err}");
        let options = KliOptions { step: 1e-6, ..Default::default() };
        let err = kli(p, r, &options).unwrap_err().to_string();
        assert!(err.starts_with("step is too small"), "{err}");
    }

    #[test]
    fn numerical_equilibrium_is_reported() {
        // 2e-15 from -p: exact arithmetic would leave after ~45 time units, but δ q' ≈ 2e-17
        // is below the resolution of q's components.
        let p = from_wxyz([0.5; 4]);
        let r = -p + from_wxyz([0.5, -0.5, 0.5, -0.5]) * 2e-15;
        let options = KliOptions { shortest_path: false, ..Default::default() };
        let err = kli(p, r, &options).unwrap_err().to_string();
        assert!(err.starts_with("p is so close to -r that a step does not move q"), "{err}");
    }

    #[test]
    fn antipodal_long_way_is_refused() {
        let (p, _) = paper();
        let options = KliOptions { shortest_path: false, ..Default::default() };
        assert_eq!(kli(p, -p, &options).unwrap_err(), KliError::Antipodal);
    }

    #[test]
    fn bad_options_name_themselves() {
        let (p, r) = paper();
        for (options, name) in [
            (KliOptions { tolerance: 0.0, ..Default::default() }, "tolerance"),
            (KliOptions { step: f64::NAN, ..Default::default() }, "step"),
            (KliOptions { max_time: f64::INFINITY, ..Default::default() }, "maxTime"),
        ] {
            let err = kli(p, r, &options).unwrap_err().to_string();
            assert!(err.starts_with(&format!("{name} must be a finite number > 0")), "{err}");
        }
    }
}
