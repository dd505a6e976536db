//! # kli — Kuramoto–Lohe Interpolation of rotations
//!
//! The method of Kapić and Crnkić, "Interpolating Rotations with Non-abelian Kuramoto Model on the
//! 3-Sphere": to go from the rotation `p` to `r`, integrate
//!
//! ```text
//! q' = r - (q·r) q,   q(0) = p          (paper eq. 3)
//! ```
//!
//! until `||r - q|| < ε` (Algorithm 1). The solution is known in closed form
//! (`docs/MATH.md`): it is SLERP along the same great circle, with the clock
//! `tan(φ(t)/2) = tan(φ0/2) e^(-t)`.
//!
//! Quaternions are [`glam::DQuat`] (f64). The paper, and the JavaScript API, write them scalar
//! first, `[w, x, y, z]`: see [`from_wxyz`] and [`to_wxyz`]. Every public function either checks its
//! inputs and returns a [`KliError`] naming the bad argument, or is *total*: it answers any input
//! (NaN in, NaN out) and says so, as the building blocks that take a checked arc or unit
//! quaternion do ([`hopf()`], [`slerp::point_at`], [`closed_form::point_at`]). None panics and
//! none runs unbounded: `tests/hostile.rs` calls each with NaN, ±∞, ±0, negatives, 1e308 and
//! subnormals under a time bound.
//!
//! ```
//! use kli::{kli, from_wxyz, KliOptions};
//!
//! let p = from_wxyz([0.0, 0.0, 0.0, 1.0]);
//! let r = from_wxyz([0.5, 0.5, 0.5, 0.5]);
//! let path = kli(p, r, &KliOptions::default())?;
//! assert_eq!(path.steps(), 1166);
//! assert!((path.final_time() - 11.66).abs() < 1e-12);
//! # Ok::<(), kli::KliError>(())
//! ```
//!
//! Modules, one concept each: [`average`] (the mean of many rotations: chordal, quaternion,
//! Karcher, median), [`model`] (the vector field), [`integrator`] (RK4, Euler, geodesic),
//! [`algorithm`] (Algorithm 1), [`great_arc`] (the circle from `p` to the target),
//! [`closed_form`] (the exact solution), [`slerp`](mod@slerp), [`hopf`](mod@hopf),
//! [`axis_angle`](mod@axis_angle) (polar form), [`batch`] (many pairs at once), [`spline`]
//! (curves through keyframes: the Kuramoto–Lohe chain), [`swarm`] (the many-oscillator model the
//! paper is named after), [`error`].
//!
//! This crate knows nothing of WebAssembly: the JavaScript package is the `kli-wasm` crate beside
//! it, and the demo page's renderer the `kli-demo` crate.

pub mod axis_angle;
pub mod batch;

pub mod algorithm;
pub mod average;
pub mod closed_form;
pub mod error;
pub mod great_arc;
pub mod hopf;
pub mod integrator;
mod lanes;
pub mod model;
mod quad;
pub mod quaternion;
pub mod slerp;
pub mod spline;
pub mod swarm;
#[cfg(feature = "sync")]
pub mod sync;
mod trig;

pub use algorithm::{KliOptions, KliPath, kli};
pub use axis_angle::{axis_angle, from_axis_angle};
pub use closed_form::{kli_exact, kli_reach_time, kli_to_slerp_parameter};
pub use error::{ErrorKind, KliError, Requirement, Shape, require};
pub use glam::{DQuat, DVec3};
pub use hopf::hopf;
pub use integrator::Integrator;
pub use quaternion::{from_wxyz, to_wxyz};
pub use slerp::slerp;
