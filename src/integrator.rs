//! One time step of the model `q' = r - (q·r) q` (see [`crate::model`]), by three schemes.

use std::fmt;
use std::str::FromStr;

use glam::DQuat;

use crate::error::{ErrorKind, KliError};
use crate::model::velocity;

/// How Algorithm 1 advances `q` by one step `δ`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Integrator {
    /// Classical fourth-order Runge–Kutta in R⁴. Accurate; `|q|` drifts by rounding-level amounts.
    #[default]
    Rk4,
    /// Explicit Euler, `q + δ f(q)`: the naive scheme, first order. `|q|` grows by `δ²|f|²/2` each
    /// step, which makes it the one to show drift with.
    Euler,
    /// The RK4 increment taken as a rotation along the great circle through `q` (the exponential
    /// map of S³), so `|q| = 1` by construction. Fourth order.
    Geodesic,
}

impl Integrator {
    /// Every integrator, in the order the JavaScript API lists them.
    pub const ALL: [Integrator; 3] = [Integrator::Rk4, Integrator::Euler, Integrator::Geodesic];

    /// The name used by the JavaScript API: `"rk4"`, `"euler"` or `"geodesic"`.
    pub fn name(self) -> &'static str {
        match self {
            Integrator::Rk4 => "rk4",
            Integrator::Euler => "euler",
            Integrator::Geodesic => "geodesic",
        }
    }

    /// `q(t + h)` from `q(t)`, flowing towards `r`.
    #[inline]
    pub fn step(self, q: DQuat, r: DQuat, h: f64) -> DQuat {
        match self {
            Integrator::Euler => q + velocity(q, r) * h,
            Integrator::Rk4 => q + rk4_increment(q, r, h),
            Integrator::Geodesic => along_great_circle(q, rk4_increment(q, r, h)),
        }
    }
}

/// `h/6 (k1 + 2 k2 + 2 k3 + k4)`.
#[inline]
fn rk4_increment(q: DQuat, r: DQuat, h: f64) -> DQuat {
    let k1 = velocity(q, r);
    let k2 = velocity(q + k1 * (0.5 * h), r);
    let k3 = velocity(q + k2 * (0.5 * h), r);
    let k4 = velocity(q + k3 * h, r);
    (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0)
}

/// `exp_q` of the increment: rotate `q` towards the increment's tangential part by the angle
/// between `q` and `q + increment`, i.e. `cos α q + sin α u` with `u ⟂ q`, `|u| = 1`.
#[inline]
pub(crate) fn along_great_circle(q: DQuat, increment: DQuat) -> DQuat {
    let tangential = increment - q * increment.dot(q);
    let length = tangential.length();
    if length == 0.0 {
        return q;
    }
    let (sin, cos) = crate::trig::sin_cos(length.atan2(1.0 + increment.dot(q)));
    q * cos + tangential * (sin / length)
}

/// The names of [`Integrator::ALL`], in order.
const NAMES: [&str; 3] = ["rk4", "euler", "geodesic"];

impl fmt::Display for Integrator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

impl FromStr for Integrator {
    type Err = KliError;

    fn from_str(name: &str) -> Result<Self, KliError> {
        Integrator::ALL.into_iter().find(|i| i.name() == name).ok_or_else(|| {
            let kind = ErrorKind::UnknownName { got: name.into(), allowed: &NAMES };
            KliError::new("integrator", kind)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quaternion::from_wxyz;

    /// Each integrator displays as its name, padded as a `str` is.
    #[test]
    fn names_are_displayed() {
        for (integrator, name) in [
            (Integrator::Rk4, "rk4"),
            (Integrator::Euler, "euler"),
            (Integrator::Geodesic, "geodesic"),
        ] {
            assert_eq!(format!("{integrator}"), name);
            assert_eq!(format!("[{integrator:>9}]"), format!("[{name:>9}]"));
        }
    }

    /// Error at t = 1 against the closed form φ(t) = 2 atan(tan(φ0/2) e^-t) on the paper's pair.
    fn error_at_one(integrator: Integrator, h: f64) -> f64 {
        let p = from_wxyz([0.0, 0.0, 0.0, 1.0]);
        let r = from_wxyz([0.5; 4]);
        let mut q = p;
        for _ in 0..(1.0 / h).round() as usize {
            q = integrator.step(q, r, h);
        }
        // Independent exact value: on the p–r circle at angle φ(1) from r.
        let phi0 = std::f64::consts::FRAC_PI_3;
        let phi = 2.0 * ((phi0 / 2.0).tan() * (-1.0_f64).exp()).atan();
        let exact = (p * phi.sin() + r * (phi0 - phi).sin()) * (1.0 / phi0.sin());
        (q - exact).length()
    }

    #[test]
    fn orders_of_accuracy() {
        // Halving h divides the error by 2^order.
        for (integrator, order) in
            [(Integrator::Euler, 1.0), (Integrator::Rk4, 4.0), (Integrator::Geodesic, 4.0)]
        {
            let ratio = error_at_one(integrator, 0.02) / error_at_one(integrator, 0.01);
            let measured = ratio.log2();
            assert!((measured - order).abs() < 0.2, "{integrator}: order {measured}");
        }
    }

    #[test]
    fn geodesic_stays_on_the_sphere() {
        let r = from_wxyz([0.5; 4]);
        let mut q = from_wxyz([0.0, 0.0, 0.0, 1.0]);
        for _ in 0..2000 {
            q = Integrator::Geodesic.step(q, r, 0.01);
            assert!((q.length() - 1.0).abs() < 1e-14);
        }
    }

    #[test]
    fn euler_drifts_outwards() {
        let r = from_wxyz([0.5; 4]);
        let q = Integrator::Euler.step(from_wxyz([0.0, 0.0, 0.0, 1.0]), r, 0.1);
        // |q + h f|² = 1 + h² |f|², |f| = sin(π/3).
        assert!((q.length_squared() - (1.0 + 0.01 * 0.75)).abs() < 1e-15);
    }

    #[test]
    fn names_round_trip_and_unknown_is_rejected() {
        for i in Integrator::ALL {
            assert_eq!(i.name().parse::<Integrator>().unwrap(), i);
        }
        let err = "RK4".parse::<Integrator>().unwrap_err().to_string();
        assert!(err.starts_with("integrator must be") && err.contains("\"RK4\""), "{err}");
    }
}
