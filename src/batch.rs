//! Many interpolations in one call, for animation and data: flat `f64` slices of scalar-first
//! quaternions (`4·n` numbers) and `n` parameters.
//!
//! The batch kernels work in the half-angle frame of a pair: with unit `p` and target `t`,
//! `d = p - t` and `s = p + t` are orthogonal, `|d| = 2 sin(φ0/2)`, `|s| = 2 cos(φ0/2)`, and the
//! point at angle `φ` from the target is `cos(φ - φ0/2) s/|s| + sin(φ - φ0/2) d/|d|`. Both
//! differences are exact for nearly equal or opposite ends, which keeps the kernels accurate near
//! `p ≈ t`. For KLI, with `u0 = |d|/|s| = tan(φ0/2)`, `E = e^(-t)` and `u = u0 E = tan(φ/2)`:
//!
//! ```text
//! q(t) = [(1 - u² + 2 u0 u) s + (2E - 1 + u²) d] / (2 (1 + u²))
//! ```
//!
//! one `exp`, one square root and three divisions a pair, no trigonometry. For SLERP,
//! with `ψ0 = φ0/2`: `q(σ) = cos((1-2σ) ψ0) s/|s| + sin((1-2σ) ψ0) d/|d|`.
//!
//! Only when the target is nearly `-p` (the long way round) does the frame lose orthogonality
//! (`s·d = |p|² - |t|²` is rounding, `|s|` is tiny); those pairs take [`GreatArc`]'s careful path.

use glam::DQuat;

use crate::closed_form::point_from_half_angle_tan;
use crate::error::KliError;
use crate::great_arc::GreatArc;
use crate::quaternion::{from_wxyz, unit};
use crate::slerp;

/// Reads quaternion `i` of a flat scalar-first slice and normalises it, naming it
/// `name[first + i]` in errors. The common case (a length² in the normal range) takes one
/// square root.
#[inline]
fn read_unit(values: &[f64], i: usize, first: usize, name: &str) -> Result<DQuat, KliError> {
    let q = from_wxyz([values[4 * i], values[4 * i + 1], values[4 * i + 2], values[4 * i + 3]]);
    let length_squared = q.length_squared();
    if (1e-290..1e290).contains(&length_squared) {
        return Ok(q * (1.0 / length_squared.sqrt()));
    }
    read_unit_slowly(q, first + i, name)
}

/// Extreme magnitudes and invalid input: the rare path, kept out of the loop.
#[cold]
#[inline(never)]
fn read_unit_slowly(q: DQuat, index: usize, name: &str) -> Result<DQuat, KliError> {
    unit("q", q).map_err(|e| e.renamed(format!("{name}[{index}]")))
}

#[inline]
fn write(out: &mut [f64], i: usize, q: DQuat) {
    out[4 * i..4 * i + 4].copy_from_slice(&[q.w, q.x, q.y, q.z]);
}

/// Checks that `starts`, `ends` and `out` hold `4·n` numbers for the `n` parameters.
pub fn check_lengths(starts: usize, ends: usize, parameters: usize, out: usize, parameter_name: &str) -> Result<(), KliError> {
    let expected = 4 * parameters;
    for (name, length) in [("starts", starts), ("ends", ends), ("out", out)] {
        if length != expected {
            return Err(KliError::InvalidArgument {
                name: name.into(),
                problem: format!(
                    "must hold 4 numbers per {parameter_name} value: {expected} for {parameters} values (got {length})"
                ),
            });
        }
    }
    Ok(())
}

/// The arc of pair `i`; errors name the pair by `first + i`, its index in the caller's arrays.
fn arc(starts: &[f64], ends: &[f64], i: usize, first: usize, shortest_path: bool) -> Result<GreatArc, KliError> {
    let p = read_unit(starts, i, first, "starts")?;
    let r = read_unit(ends, i, first, "ends")?;
    GreatArc::new(p, r, shortest_path).map_err(|e| match e {
        KliError::Antipodal => KliError::InvalidArgument {
            name: format!("starts[{}]", first + i),
            problem: format!("and ends[{}] are antipodal and shortestPath is false: no path is determined", first + i),
        },
        other => other,
    })
}

/// Which batch computation, for callers that feed the pairs in chunks ([`run_batch`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BatchKind {
    /// `out[i] = Slerp(starts[i], ends[i]; s[i])`.
    Slerp,
    /// `out[i] = q(t[i])`, the exact KLI solution from `starts[i]` towards `ends[i]`.
    KliExact,
    /// Normalised linear interpolation with the shorter arc: the cheapest possible
    /// interpolation (not constant speed), the benchmarks' baseline.
    Nlerp,
}

impl BatchKind {
    /// The name of the parameter array in errors: `s` or `t`.
    pub fn parameter_name(self) -> &'static str {
        if self == BatchKind::KliExact { "t" } else { "s" }
    }
}

/// Runs `kind` over pairs `first .. first + parameters.len()` of the caller's arrays, given here
/// as the matching slices. On an error the pairs before the bad one are already written.
pub fn run_batch(kind: BatchKind, starts: &[f64], ends: &[f64], parameters: &[f64], out: &mut [f64], first: usize, shortest_path: bool) -> Result<(), KliError> {
    check_lengths(starts.len(), ends.len(), parameters.len(), out.len(), kind.parameter_name())?;
    for (i, &x) in parameters.iter().enumerate() {
        let valid = x.is_finite() && (kind != BatchKind::KliExact || x >= 0.0);
        if !valid {
            let requirement = if kind == BatchKind::KliExact { "a finite number ≥ 0" } else { "a finite number" };
            return Err(KliError::InvalidNumber { name: format!("{}[{}]", kind.parameter_name(), first + i), value: x, requirement });
        }
        let q = match kind {
            BatchKind::Slerp | BatchKind::KliExact => {
                let p = read_unit(starts, i, first, "starts")?;
                let r = read_unit(ends, i, first, "ends")?;
                let target = if shortest_path && p.dot(r) < 0.0 { -r } else { r };
                let (d, s) = (p - target, p + target);
                let (dd, ss) = (d.length_squared(), s.length_squared());
                if ss < FRAME_LIMIT {
                    careful(kind, starts, ends, i, first, shortest_path, x)?
                } else if dd == 0.0 {
                    p
                } else if kind == BatchKind::KliExact {
                    let u0 = (dd / ss).sqrt();
                    let e = (-x).exp();
                    let u = u0 * e;
                    let u2 = u * u;
                    let k = 0.5 / (1.0 + u2);
                    s * ((1.0 - u2 + 2.0 * u0 * u) * k) + d * ((2.0 * e - 1.0 + u2) * k)
                } else {
                    let (dn, sn) = (dd.sqrt(), ss.sqrt());
                    let (sin, cos) = ((1.0 - 2.0 * x) * dn.atan2(sn)).sin_cos();
                    s * (cos / sn) + d * (sin / dn)
                }
            }
            BatchKind::Nlerp => {
                let p = read_unit(starts, i, first, "starts")?;
                let r = read_unit(ends, i, first, "ends")?;
                let r = if p.dot(r) < 0.0 { -r } else { r };
                let q = p + (r - p) * x;
                q * (1.0 / q.length())
            }
        };
        write(out, i, q);
    }
    Ok(())
}

/// `|s|²` below which the half-angle frame is not orthogonal to 1e-12 (`s·d/(|s||d|)` is
/// rounding over `|s|`): the target is within 1e-3 of `-p`.
const FRAME_LIMIT: f64 = 1e-6;

/// The pair through [`GreatArc`], which re-orthogonalises its frame.
#[cold]
fn careful(kind: BatchKind, starts: &[f64], ends: &[f64], i: usize, first: usize, shortest_path: bool, x: f64) -> Result<DQuat, KliError> {
    let arc = arc(starts, ends, i, first, shortest_path)?;
    Ok(match kind {
        BatchKind::Slerp => slerp::point_at(&arc, x),
        _ => point_from_half_angle_tan(&arc, arc.half_angle_tan() * (-x).exp()),
    })
}

/// `out[i] = Slerp(starts[i], ends[i]; s[i])` for every `i < s.len()`.
pub fn slerp_batch(starts: &[f64], ends: &[f64], s: &[f64], out: &mut [f64], shortest_path: bool) -> Result<(), KliError> {
    run_batch(BatchKind::Slerp, starts, ends, s, out, 0, shortest_path)
}

/// `out[i] = q(t[i])`, the exact KLI solution from `starts[i]` towards `ends[i]`.
pub fn kli_exact_batch(starts: &[f64], ends: &[f64], t: &[f64], out: &mut [f64], shortest_path: bool) -> Result<(), KliError> {
    run_batch(BatchKind::KliExact, starts, ends, t, out, 0, shortest_path)
}

/// Normalised linear interpolation (see [`BatchKind::Nlerp`]).
pub fn nlerp_batch(starts: &[f64], ends: &[f64], s: &[f64], out: &mut [f64]) -> Result<(), KliError> {
    run_batch(BatchKind::Nlerp, starts, ends, s, out, 0, true)
}

/// The step of times sampled evenly, when every `times[k]` is `times[0] + k·step` to rounding.
fn even_steps(times: &[f64]) -> Option<f64> {
    let (&first, &last) = (times.first()?, times.last()?);
    if times.len() < 3 {
        return None;
    }
    let step = (last - first) / (times.len() - 1) as f64;
    let even = times.iter().enumerate().all(|(k, &t)| (t - (first + k as f64 * step)).abs() <= 8.0 * f64::EPSILON * (1.0 + t.abs()));
    even.then_some(step)
}

/// How many samples the even-step recurrence runs before it re-anchors on an exact `exp`, so
/// rounding in `u` stays within a few ulp.
const REANCHOR: usize = 32;

/// One KLI path from `p` towards `r`, at each of `times` (each finite and `≥ 0`), into `out`
/// (`4·times.len()` numbers). Evenly spaced times advance `e^(-t)` by a fixed factor.
pub fn kli_sample_into(p: DQuat, r: DQuat, times: &[f64], out: &mut [f64], shortest_path: bool) -> Result<(), KliError> {
    if out.len() != 4 * times.len() {
        return Err(KliError::InvalidArgument {
            name: "out".into(),
            problem: format!("must hold 4 numbers per time: {} (got {})", 4 * times.len(), out.len()),
        });
    }
    if let Some(k) = times.iter().position(|t| !(t.is_finite() && *t >= 0.0)) {
        return Err(KliError::InvalidNumber { name: format!("times[{k}]"), value: times[k], requirement: "a finite number ≥ 0" });
    }
    let arc = GreatArc::new(unit("p", p)?, unit("r", r)?, shortest_path)?;
    let u0 = arc.half_angle_tan();
    match even_steps(times) {
        Some(step) => {
            let factor = (-step).exp();
            let mut u = 0.0;
            for (k, &t) in times.iter().enumerate() {
                u = if k % REANCHOR == 0 { u0 * (-t).exp() } else { u * factor };
                write(out, k, point_from_half_angle_tan(&arc, u));
            }
        }
        None => {
            for (k, &t) in times.iter().enumerate() {
                write(out, k, point_from_half_angle_tan(&arc, u0 * (-t).exp()));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::closed_form::kli_exact;
    use crate::quaternion::to_wxyz;

    fn flat(qs: &[[f64; 4]]) -> Vec<f64> {
        qs.iter().flatten().copied().collect()
    }

    #[test]
    fn batches_match_the_single_calls() {
        let starts = flat(&[[0.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0, 0.0], [0.3, -0.1, 0.7, 0.2]]);
        let ends = flat(&[[0.5; 4], [-0.6, 0.8, 0.0, 0.0], [-0.3, 0.1, -0.7, -0.2 + 1e-12]]);
        let params = [0.3, 0.7, 2.0];
        let mut out = vec![0.0; 12];
        for shortest in [true, false] {
            slerp_batch(&starts, &ends, &params, &mut out, shortest).unwrap();
            for i in 0..3 {
                let p = from_wxyz(starts[4 * i..4 * i + 4].try_into().unwrap());
                let r = from_wxyz(ends[4 * i..4 * i + 4].try_into().unwrap());
                let single = to_wxyz(crate::slerp(p, r, params[i], shortest).unwrap());
                for c in 0..4 {
                    assert!((out[4 * i + c] - single[c]).abs() < 1e-12);
                }
            }
            let mut exact = vec![0.0; 12];
            kli_exact_batch(&starts, &ends, &params, &mut exact, shortest).unwrap();
            for i in 0..3 {
                let p = from_wxyz(starts[4 * i..4 * i + 4].try_into().unwrap());
                let r = from_wxyz(ends[4 * i..4 * i + 4].try_into().unwrap());
                let single = to_wxyz(kli_exact(p, r, params[i], shortest).unwrap());
                for c in 0..4 {
                    assert!((exact[4 * i + c] - single[c]).abs() < 1e-15);
                }
            }
        }
    }

    #[test]
    fn even_sampling_stays_within_1e12_of_the_plain_formula() {
        let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
        let times: Vec<f64> = (0..5000).map(|k| k as f64 * 0.004).collect();
        assert!(even_steps(&times).is_some());
        let mut out = vec![0.0; 4 * times.len()];
        kli_sample_into(p, r, &times, &mut out, true).unwrap();
        for (k, &t) in times.iter().enumerate() {
            // Plain formula: φ = 2 atan(tan(φ0/2) e^-t) and the SLERP form of MATH.md.
            let phi0 = std::f64::consts::FRAC_PI_3;
            let phi = 2.0 * ((phi0 / 2.0).tan() * (-t).exp()).atan();
            let expected = to_wxyz((p * phi.sin() + r * (phi0 - phi).sin()) * (1.0 / phi0.sin()));
            for c in 0..4 {
                assert!((out[4 * k + c] - expected[c]).abs() < 1e-12, "t = {t}");
            }
        }
        // Uneven times take the plain path.
        assert!(even_steps(&[0.0, 0.1, 0.3]).is_none());
    }

    #[test]
    fn errors_name_the_element() {
        let mut out = vec![0.0; 8];
        let good = flat(&[[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]);
        let bad = flat(&[[1.0, 0.0, 0.0, 0.0], [0.0, f64::NAN, 0.0, 0.0]]);
        let message = |r: Result<(), KliError>| r.unwrap_err().to_string();
        assert!(message(slerp_batch(&good, &bad, &[0.5, 0.5], &mut out, true)).starts_with("ends[1] must be a quaternion"));
        assert!(message(slerp_batch(&good, &good, &[0.5, f64::NAN], &mut out, true)).starts_with("s[1] must be a finite number"));
        assert!(message(kli_exact_batch(&good, &good, &[0.5, -1.0], &mut out, true)).starts_with("t[1] must be a finite number ≥ 0"));
        assert!(message(kli_exact_batch(&good, &good, &[0.5], &mut out, true)).starts_with("starts must hold 4 numbers per t value: 4 for 1 values (got 8)"));
        let antipodal = flat(&[[-1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]);
        assert!(message(slerp_batch(&good, &antipodal, &[0.5, 0.5], &mut out, false)).starts_with("starts[0] and ends[0] are antipodal"));
        assert!(message(run_batch(BatchKind::Slerp, &good, &bad, &[0.5, 0.5], &mut out, 1000, true)).starts_with("ends[1001] must be"));
        let huge = flat(&[[1e300, 0.0, 0.0, 0.0], [0.0, 1e-300, 0.0, 0.0]]);
        slerp_batch(&huge, &huge, &[0.5, 0.5], &mut out, true).unwrap();
        assert_eq!(out, flat(&[[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]));
        assert!(message(kli_sample_into(good_q(), good_q(), &[0.0, -2.0], &mut out, true)).starts_with("times[1] must be"));
    }

    fn good_q() -> DQuat {
        from_wxyz([1.0, 0.0, 0.0, 0.0])
    }
}
