//! The KLI algorithm (paper, Algorithm 1): from `q(0) = p`, advance `T` by `δ` until
//! `||r - q(T)|| < ε`, and return the path sampled at `0, δ, 2δ, …, T`.
//!
//! `max_time` bounds the paper's otherwise endless loop (MATH.md, "Edge cases").

use glam::{DQuat, DVec3};

use crate::closed_form;
use crate::error::{ErrorKind, KliError, Requirement, require};
use crate::great_arc::GreatArc;
use crate::hopf::hopf;
use crate::integrator::Integrator;
use crate::quaternion::norm;

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
    /// Give up (with [`ErrorKind::NotReached`]) past this time.
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
        require("tolerance", self.tolerance, Requirement::Positive)?;
        require("step", self.step, Requirement::Positive)?;
        require("max_time", self.max_time, Requirement::Positive)?;
        Ok(())
    }

    /// The most steps `n` with `n δ ≤ max_time`, forgiving the rounding of `max_time / δ`.
    fn steps_allowed(&self) -> f64 {
        (self.max_time / self.step * (1.0 + 4.0 * f64::EPSILON)).floor()
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

/// Runs Algorithm 1 from `p` towards `r` (inputs are normalised). The last sample is within
/// `tolerance` of the target, or the call fails: it never returns a path that falls short.
pub fn kli(p: DQuat, r: DQuat, options: &KliOptions) -> Result<KliPath, KliError> {
    options.validate()?;
    let arc = GreatArc::between(p, r, options.shortest_path)?;
    let KliOptions { tolerance, step, integrator, .. } = *options;
    let last = options.steps_allowed().min((MAX_SAMPLES - 1) as f64) as usize;
    let predicted = closed_form::reach_time(&arc, tolerance);
    // In floats: with a subnormal step the quotient is ∞, which `as usize` saturates.
    let capacity = ((predicted / step).ceil() + 2.0).min((last + 1) as f64) as usize;
    let mut path = KliPath {
        times: Vec::with_capacity(capacity),
        quaternions: Vec::with_capacity(capacity),
        arc,
        options: *options,
    };
    let target = arc.target();
    let mut q = arc.start();
    let mut closest = f64::INFINITY;
    for n in 0..=last {
        path.times.push(n as f64 * step);
        path.quaternions.push(q);
        // `norm`, not `length`: a distance of 1e-312 must not round to 0 and pass any tolerance.
        let distance = norm(target - q);
        if distance < tolerance {
            return Ok(path);
        }
        closest = closest.min(distance);
        let next = integrator.step(q, target, step);
        check_on_sphere(next, &arc, options, (n + 1) as f64 * step)?;
        if next == q {
            // Stuck: at the antipode (a numerical equilibrium), or at the target closer than
            // f64 resolves, where looping on to max_time would change nothing.
            if distance > 1.0 {
                let kind = ErrorKind::Stalled { time: n as f64 * step, distance };
                return Err(KliError::new("shortest_path", kind));
            }
            break;
        }
        q = next;
    }
    Err(gave_up(&path, closest, predicted))
}

/// Fails when `q`, reached at `time`, has left S³ (a NaN norm counts as having left). On the
/// long way round (`p·r < 0`) the sphere repels rounding near `-r` (the integrator's fault);
/// elsewhere it attracts, and only a step beyond the integrator's stability leaves it.
fn check_on_sphere(
    q: DQuat,
    arc: &GreatArc,
    options: &KliOptions,
    time: f64,
) -> Result<(), KliError> {
    let norm = q.length();
    if (norm - 1.0).abs() < LEFT_SPHERE {
        return Ok(());
    }
    let integrator = options.integrator.name();
    Err(if arc.start().dot(arc.target()) < 0.0 {
        KliError::new("integrator", ErrorKind::LeftSphere { integrator, time, norm })
    } else {
        let kind = ErrorKind::Unstable { integrator, step: options.step, time, norm };
        KliError::new("step", kind)
    })
}

/// Why the loop ended without meeting the tolerance: it ran into the sample limit, or into
/// `max_time` (or stopped moving) with `closest` the nearest it came.
fn gave_up(path: &KliPath, closest: f64, predicted: f64) -> KliError {
    let KliOptions { tolerance, max_time, .. } = path.options;
    let steps = path.options.steps_allowed();
    if path.times.len() == MAX_SAMPLES && steps > (MAX_SAMPLES - 1) as f64 {
        KliError::new("step", ErrorKind::TooManySteps { steps, limit: MAX_SAMPLES - 1 })
    } else {
        let kind = ErrorKind::NotReached { tolerance, max_time, closest, predicted };
        KliError::new("tolerance", kind)
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

    /// The exact `q(t)` for any `t ≥ 0` (MATH.md, "Closed form"); the integrated samples are
    /// [`KliPath::quaternions`].
    pub fn exact_at(&self, t: f64) -> Result<DQuat, KliError> {
        let t = require("t", t, Requirement::NonNegative)?;
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
        assert!(err.starts_with("tolerance 1e-20 not reached within max_time 50"), "{err}");
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
        let e = kli(p, r, &options).unwrap_err();
        assert!(e.to_string().starts_with("shortest_path is false and p is so close to -r"), "{e}");
        // Stuck from the start: at t = 0, nearly 2 from the target.
        let ErrorKind::Stalled { time, distance } = e.kind() else { unreachable!() };
        assert_eq!(*time, 0.0);
        assert!((distance - 2.0).abs() < 1e-14, "{distance}");
    }

    #[test]
    fn antipodal_long_way_is_refused() {
        let (p, _) = paper();
        let options = KliOptions { shortest_path: false, ..Default::default() };
        let e = kli(p, -p, &options).unwrap_err();
        assert_eq!((e.argument(), e.kind().code()), ("shortest_path", "antipodal"));
    }

    #[test]
    fn bad_options_name_themselves() {
        let (p, r) = paper();
        for (options, name) in [
            (KliOptions { tolerance: 0.0, ..Default::default() }, "tolerance"),
            (KliOptions { step: f64::NAN, ..Default::default() }, "step"),
            (KliOptions { max_time: f64::INFINITY, ..Default::default() }, "max_time"),
        ] {
            let err = kli(p, r, &options).unwrap_err().to_string();
            assert!(err.starts_with(&format!("{name} must be a finite number > 0")), "{err}");
        }
    }

    #[test]
    fn the_tolerance_is_met_or_the_call_fails() {
        // 1e-312 apart: |r - p|² underflows to 0, so a plain length says the ends coincide.
        let p = from_wxyz([1.0, 0.0, 0.0, 0.0]);
        let r = from_wxyz([1.0, 1e-312, 0.0, 0.0]);
        for tolerance in [5e-324, 1e-318, 1e-312, 2e-312] {
            let options = KliOptions { tolerance, ..Default::default() };
            match kli(p, r, &options) {
                Ok(path) => {
                    let last = *path.quaternions().last().unwrap();
                    // Measured independently, scaled by 1e300 so that nothing underflows.
                    let d = ((r.x - last.x) * 1e300).hypot((r.w - last.w) * 1e300);
                    assert!(d < tolerance * 1e300, "ε = {tolerance:e}: {d:e} × 1e-300 left");
                }
                Err(e) => assert_eq!(e.kind().code(), "not-reached", "ε = {tolerance:e}: {e}"),
            }
        }
        // The first tolerance no f64 distance but 0 meets is refused, not passed at t = 0.
        let first = kli(p, r, &KliOptions { tolerance: 5e-324, ..Default::default() });
        assert!(first.map(|path| path.steps() > 0).unwrap_or(true));
        // A tolerance above the distance is met at once.
        assert_eq!(
            kli(p, r, &KliOptions { tolerance: 2e-312, ..Default::default() }).unwrap().steps(),
            0
        );
    }

    /// `max_time` allows the most steps `n` with `n δ ≤ max_time`, to the step: the paper's
    /// example needs 1166 steps of 0.01, so a `max_time` of 11.66 lets it arrive and 11.65 does
    /// not (11.66/0.01 is 1165.9999999999998 in floats: the rounding is forgiven).
    #[test]
    fn max_time_allows_exactly_its_steps() {
        let (p, r) = paper();
        let reach = |max_time| kli(p, r, &KliOptions { max_time, ..Default::default() });
        assert_eq!(reach(11.66).unwrap().steps(), 1166);
        let e = reach(11.65).unwrap_err();
        assert_eq!(e.kind().code(), "not-reached", "{e}");
    }

    /// At the sample limit: a run whose `max_time` allows exactly `MAX_SAMPLES − 1` steps and
    /// does not arrive is `not-reached` (the time ran out); one that would allow one more is
    /// refused as too many steps, naming the limit.
    #[test]
    fn the_sample_limit_and_max_time_are_told_apart() {
        let (p, r) = paper();
        let limit = MAX_SAMPLES - 1;
        // Steps of 2⁻¹⁷ (exact in binary): 10⁶ of them end near t = 7.6, short of T* = 11.66.
        let step = 2f64.powi(-17);
        let run = |steps: usize| {
            let options = KliOptions { step, max_time: steps as f64 * step, ..Default::default() };
            kli(p, r, &options).unwrap_err()
        };
        let exact = run(limit);
        assert_eq!(exact.kind().code(), "not-reached", "{exact}");
        let over = run(limit + 1);
        assert_eq!(
            over.kind(),
            &ErrorKind::TooManySteps { steps: (limit + 1) as f64, limit },
            "{over}"
        );
    }

    /// Leaving S³ is blamed on the step where the sphere attracts (`p·r ≥ 0`, at the time of the
    /// step that left) and on the integrator on the long way round.
    #[test]
    fn leaving_the_sphere_names_the_step_or_the_integrator() {
        let (one, i) = (from_wxyz([1.0, 0.0, 0.0, 0.0]), from_wxyz([0.0, 1.0, 0.0, 0.0]));
        let e = kli(one, i, &KliOptions { step: 5.0, ..Default::default() }).unwrap_err();
        assert_eq!((e.argument(), e.kind().code()), ("step", "unstable"), "{e}");
        let ErrorKind::Unstable { time, .. } = e.kind() else { unreachable!() };
        assert_eq!(*time, 5.0, "{e}");
        let r = from_wxyz([-0.6, 0.8, 0.0, 0.0]);
        let options = KliOptions { step: 5.0, shortest_path: false, ..Default::default() };
        let e = kli(one, r, &options).unwrap_err();
        assert_eq!((e.argument(), e.kind().code()), ("integrator", "left-sphere"), "{e}");
    }

    /// The path's accessors against independent values: each Hopf point is the body x-axis
    /// rotated (`q x q̄`), the target is `−r` on the shorter way from `p·r < 0`, the options are
    /// those given, and `exact_at` is the closed form.
    #[test]
    fn the_paths_accessors() {
        let p = from_wxyz([0.0, 0.0, 0.0, 1.0]);
        let r = from_wxyz([-0.5; 4]);
        let options = KliOptions { step: 0.02, tolerance: 1e-6, ..Default::default() };
        let path = kli(p, r, &options).unwrap();
        assert_eq!(path.target(), -r);
        assert_eq!(path.options(), &options);
        let curve = path.hopf_curve();
        assert_eq!(curve.len(), path.quaternions().len());
        for (point, q) in curve.iter().zip(path.quaternions()) {
            let x = *q * from_wxyz([0.0, 1.0, 0.0, 0.0]) * q.conjugate();
            assert!((*point - DVec3::new(x.x, x.y, x.z)).length() < 1e-15);
        }
        for t in [0.0, 0.5, 3.0] {
            let want = crate::closed_form::kli_exact(p, r, t, true).unwrap();
            assert!((path.exact_at(t).unwrap() - want).length() < 1e-15, "t = {t}");
        }
        assert_eq!(path.exact_at(-1.0).unwrap_err().argument(), "t");
    }

    #[test]
    fn a_step_too_large_is_blamed_on_the_step() {
        // δ = 5 on the paper's pair (p·r > 0, the sphere attracts): RK4 is unstable there.
        let (p, r) = paper();
        let e = kli(p, r, &KliOptions { step: 5.0, ..Default::default() }).unwrap_err();
        assert_eq!((e.argument(), e.kind().code()), ("step", "unstable"), "{e}");
        assert!(e.to_string().starts_with("step 5 is too large for integrator rk4"), "{e}");
    }
}
