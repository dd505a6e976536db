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
//! which the fast kernel rewrites without square roots: one `exp` and one division a pair.
//! For SLERP, with `ψ0 = φ0/2`: `q(σ) = cos((1-2σ) ψ0) s/|s| + sin((1-2σ) ψ0) d/|d|`.
//!
//! The fast kernels (`batch/fast.rs`) cover the common case. A call with any pair outside it (bad
//! input, extreme magnitudes, extrapolation, a target near `-p` where the frame loses
//! orthogonality) is redone pair by pair through the single calls' own code, so a batch and the
//! single calls agree on every input both accept, and refuse the same inputs.

mod fast;
mod sample;

pub use sample::kli_sample_into;

use glam::DQuat;

use crate::closed_form;
use crate::error::{ErrorKind, KliError, Requirement, require};
use crate::great_arc::GreatArc;
use crate::quaternion::{from_wxyz, unit};
use crate::slerp::{self, MAX_PARAMETER};

/// Which batch computation, for callers that feed the pairs in chunks ([`run_batch`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BatchKind {
    /// `out[i] = Slerp(starts[i], ends[i]; s[i])`.
    Slerp,
    /// `out[i] = q(t[i])`, the exact KLI solution from `starts[i]` towards `ends[i]`.
    KliExact,
    /// Normalised linear interpolation with the shorter arc, `(p + (r' - p) s)/|…|` for the
    /// normalised inputs, `r' = -r` when `p·r < 0` (a zero dot keeps `r`, as SLERP does): the
    /// cheapest possible interpolation (not constant speed), the benchmarks' baseline.
    Nlerp,
}

impl BatchKind {
    /// The name of the parameter array in errors: `s` or `t`.
    pub fn parameter_name(self) -> &'static str {
        if self == BatchKind::KliExact { "t" } else { "s" }
    }

    /// What each parameter must be: what the single call asks of it.
    fn requirement(self) -> Requirement {
        match self {
            BatchKind::KliExact => Requirement::NonNegative,
            BatchKind::Slerp | BatchKind::Nlerp => Requirement::AtMost(MAX_PARAMETER),
        }
    }
}

/// Checks that `starts`, `ends` and `out` hold `4·n` numbers for the `n` parameters.
pub fn check_lengths(
    starts: usize,
    ends: usize,
    parameters: usize,
    out: usize,
    parameter_name: &str,
) -> Result<(), KliError> {
    // Saturated, so a count no array can hold four times over is refused, not wrapped.
    let expected = parameters.saturating_mul(4);
    for (name, got) in [("starts", starts), ("ends", ends), ("out", out)] {
        if got != expected {
            let per = format!("{parameter_name} value");
            let kind = ErrorKind::WrongLength { expected, got, per };
            return Err(KliError::new(name, kind));
        }
    }
    Ok(())
}

/// Runs `kind` over pairs `first .. first + parameters.len()` of the caller's arrays, given here
/// as the matching slices. On an error the pairs before the bad one are already written.
pub fn run_batch(
    kind: BatchKind,
    starts: &[f64],
    ends: &[f64],
    parameters: &[f64],
    out: &mut [f64],
    first: usize,
    shortest_path: bool,
) -> Result<(), KliError> {
    check_lengths(starts.len(), ends.len(), parameters.len(), out.len(), kind.parameter_name())?;
    if fast::run(kind, starts, ends, parameters, out, shortest_path) {
        return Ok(());
    }
    for (i, &x) in parameters.iter().enumerate() {
        let q = pair(
            kind,
            &starts[4 * i..4 * i + 4],
            &ends[4 * i..4 * i + 4],
            x,
            first + i,
            shortest_path,
        )?;
        out[4 * i..4 * i + 4].copy_from_slice(&[q.w, q.x, q.y, q.z]);
    }
    Ok(())
}

/// Pair `index` of the caller's arrays, computed as the single call computes it (the same
/// checks, normalisation, arc and formula); errors name the element, e.g. `ends[7]`.
fn pair(
    kind: BatchKind,
    start: &[f64],
    end: &[f64],
    x: f64,
    index: usize,
    shortest_path: bool,
) -> Result<DQuat, KliError> {
    let element = |name: &str| format!("{name}[{index}]");
    let x = require("x", x, kind.requirement())
        .map_err(|e| e.renamed(element(kind.parameter_name())))?;
    let read = |name: &str, q: &[f64]| {
        let q = from_wxyz([q[0], q[1], q[2], q[3]]);
        unit(name, q).map_err(|e| e.renamed(element(name)))
    };
    let (p, r) = (read("starts", start)?, read("ends", end)?);
    if kind == BatchKind::Nlerp {
        let r = if p.dot(r) < 0.0 { -r } else { r };
        // |p + (r - p) x| ≥ 1 for p·r ≥ 0 and x outside [0, 1], ≥ 1/√2 inside: never zero.
        return Ok(unit("s", p + (r - p) * x).unwrap_or(p));
    }
    let arc = GreatArc::new(p, r, shortest_path).map_err(|e| match e.kind() {
        ErrorKind::Antipodal { .. } => {
            let kind = ErrorKind::Antipodal { start: element("starts"), end: element("ends") };
            KliError::new(element("starts"), kind)
        }
        _ => e,
    })?;
    Ok(match kind {
        BatchKind::Slerp | BatchKind::Nlerp => slerp::point_at(&arc, x),
        BatchKind::KliExact => closed_form::point_at(&arc, x),
    })
}

/// `out[i] = Slerp(starts[i], ends[i]; s[i])` for every `i < s.len()`.
pub fn slerp_batch(
    starts: &[f64],
    ends: &[f64],
    s: &[f64],
    out: &mut [f64],
    shortest_path: bool,
) -> Result<(), KliError> {
    run_batch(BatchKind::Slerp, starts, ends, s, out, 0, shortest_path)
}

/// `out[i] = q(t[i])`, the exact KLI solution from `starts[i]` towards `ends[i]`.
pub fn kli_exact_batch(
    starts: &[f64],
    ends: &[f64],
    t: &[f64],
    out: &mut [f64],
    shortest_path: bool,
) -> Result<(), KliError> {
    run_batch(BatchKind::KliExact, starts, ends, t, out, 0, shortest_path)
}

/// Normalised linear interpolation (see [`BatchKind::Nlerp`]).
pub fn nlerp_batch(
    starts: &[f64],
    ends: &[f64],
    s: &[f64],
    out: &mut [f64],
) -> Result<(), KliError> {
    run_batch(BatchKind::Nlerp, starts, ends, s, out, 0, true)
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
    fn errors_name_the_element() {
        let mut out = vec![0.0; 8];
        let good = flat(&[[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]);
        let bad = flat(&[[1.0, 0.0, 0.0, 0.0], [0.0, f64::NAN, 0.0, 0.0]]);
        let message = |r: Result<(), KliError>| r.unwrap_err().to_string();
        assert!(
            message(slerp_batch(&good, &bad, &[0.5, 0.5], &mut out, true))
                .starts_with("ends[1] must be a quaternion")
        );
        assert!(
            message(slerp_batch(&good, &good, &[0.5, f64::NAN], &mut out, true))
                .starts_with("s[1] must be a finite number")
        );
        assert!(
            message(kli_exact_batch(&good, &good, &[0.5, -1.0], &mut out, true))
                .starts_with("t[1] must be a finite number ≥ 0")
        );
        assert!(
            message(kli_exact_batch(&good, &good, &[0.5], &mut out, true))
                .starts_with("starts must hold 4 numbers per t value: 4 for 1 t value (got 8)")
        );
        let antipodal = flat(&[[-1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]);
        assert!(
            message(slerp_batch(&good, &antipodal, &[0.5, 0.5], &mut out, false))
                .starts_with("starts[0] and ends[0] are antipodal")
        );
        assert!(
            message(run_batch(BatchKind::Slerp, &good, &bad, &[0.5, 0.5], &mut out, 1000, true))
                .starts_with("ends[1001] must be")
        );
        let huge = flat(&[[1e300, 0.0, 0.0, 0.0], [0.0, 1e-300, 0.0, 0.0]]);
        slerp_batch(&huge, &huge, &[0.5, 0.5], &mut out, true).unwrap();
        assert_eq!(out, flat(&[[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]));
        assert!(
            message(kli_sample_into(good_q(), good_q(), &[0.0, -2.0], &mut out, true))
                .starts_with("times[1] must be")
        );
        // Three times want 12 numbers out; the Error says so.
        let e = kli_sample_into(good_q(), good_q(), &[0.0, 1.0, 2.0], &mut out, true).unwrap_err();
        assert_eq!(e.argument(), "out");
        assert_eq!(
            e.kind(),
            &ErrorKind::WrongLength { expected: 12, got: 8, per: "time".into() },
            "{e}"
        );
    }

    fn good_q() -> DQuat {
        from_wxyz([1.0, 0.0, 0.0, 0.0])
    }

    fn exact_units(count: usize) -> Vec<[f64; 4]> {
        crate::quaternion::exact_units(0x9e37_79b9_7f4a_7c15, count)
    }

    #[test]
    fn unit_inputs_come_back_bit_for_bit_at_the_ends() {
        let keys = exact_units(64);
        let (starts, ends) = (flat(&keys[..32]), flat(&keys[32..]));
        let mut out = vec![0.0; 128];
        for shortest in [true, false] {
            for (call, x, end) in [("slerp", 0.0, false), ("slerp", 1.0, true), ("kli", 0.0, false)]
            {
                let parameters = [x; 32];
                if call == "slerp" {
                    slerp_batch(&starts, &ends, &parameters, &mut out, shortest).unwrap();
                } else {
                    kli_exact_batch(&starts, &ends, &parameters, &mut out, shortest).unwrap();
                }
                for i in 0..32 {
                    let (p, r) = (keys[i], keys[32 + i]);
                    let dot: f64 = (0..4).map(|c| p[c] * r[c]).sum();
                    let target = if shortest && dot < 0.0 { r.map(|c| -c) } else { r };
                    let expected = if end { target } else { p };
                    assert_eq!(&out[4 * i..4 * i + 4], &expected, "{call}({x}) pair {i}");
                }
            }
        }
        nlerp_batch(&starts, &ends, &[0.0; 32], &mut out).unwrap();
        assert_eq!(out, starts);
    }

    /// NLERP from its definition ([`BatchKind::Nlerp`]), written afresh: normalise, take the
    /// shorter arc, blend, normalise.
    fn nlerp_by_definition(p: [f64; 4], r: [f64; 4], s: f64) -> [f64; 4] {
        let unit = |q: [f64; 4]| q.map(|c| c / q.iter().map(|c| c * c).sum::<f64>().sqrt());
        let (p, r) = (unit(p), unit(r));
        let dot: f64 = (0..4).map(|c| p[c] * r[c]).sum();
        let r = if dot < 0.0 { r.map(|c| -c) } else { r };
        unit([0, 1, 2, 3].map(|c| p[c] + (r[c] - p[c]) * s))
    }

    fn largest_gap(a: &[f64], b: &[f64]) -> f64 {
        a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max)
    }

    #[test]
    fn nearly_unit_inputs_take_the_fast_kernels_and_agree_with_the_single_calls() {
        // |q|² = 1 ± 9e-5 is just inside the fast kernels' reach, where the 1/√n series' cubic
        // term is 4.6e-13: each of its terms shows. A pair's start and end sit on opposite sides
        // of 1, so that NLERP's final normalisation cannot hide a shared error.
        let scales = [1.0 + 9e-5, 1.0 - 9e-5, 1.0 + 1e-7, 1.0 - 3e-6];
        let keys: Vec<[f64; 4]> = exact_units(48)
            .iter()
            .enumerate()
            .map(|(i, q)| q.map(|c| c * f64::sqrt(scales[(i + i / 24) % 4])))
            .collect();
        let starts = &keys[..24];
        // Each end on its start's side (the kernels' domain either way), then across (the
        // shorter way's flip, in the domain only when asked for).
        let side = |sign: f64| -> Vec<[f64; 4]> {
            (0..24)
                .map(|i| {
                    let dot: f64 = (0..4).map(|c| starts[i][c] * keys[24 + i][c]).sum();
                    keys[24 + i].map(|c| c * sign * dot.signum())
                })
                .collect()
        };
        let s: Vec<f64> = (0..24).map(|i| i as f64 / 23.0).collect();
        let t: Vec<f64> = (0..24).map(|i| i as f64 * 0.4).collect();
        let mut out = vec![0.0; 96];
        let cases = [
            (BatchKind::Slerp, 1.0, false),
            (BatchKind::Slerp, 1.0, true),
            (BatchKind::Slerp, -1.0, true),
            (BatchKind::KliExact, 1.0, false),
            (BatchKind::KliExact, 1.0, true),
            (BatchKind::KliExact, -1.0, true),
            (BatchKind::Nlerp, 1.0, true),
            (BatchKind::Nlerp, -1.0, true),
        ];
        for (kind, sign, shortest) in cases {
            let ends = side(sign);
            let parameters = if kind == BatchKind::KliExact { &t } else { &s };
            assert!(
                fast::run(kind, &flat(starts), &flat(&ends), parameters, &mut out, shortest),
                "{kind:?}: the fast kernel refused nearly unit inputs"
            );
            for i in 0..24 {
                let (p, r, x) = (starts[i], ends[i], parameters[i]);
                let expected = match kind {
                    BatchKind::Slerp => {
                        to_wxyz(crate::slerp(from_wxyz(p), from_wxyz(r), x, shortest).unwrap())
                    }
                    BatchKind::KliExact => {
                        to_wxyz(kli_exact(from_wxyz(p), from_wxyz(r), x, shortest).unwrap())
                    }
                    BatchKind::Nlerp => nlerp_by_definition(p, r, x),
                };
                let gap = largest_gap(&out[4 * i..4 * i + 4], &expected);
                assert!(gap < 2e-15, "{kind:?} {sign} pair {i}, parameter {x}: {gap:e}");
            }
        }
    }

    #[test]
    fn nlerp_outside_the_fast_kernel_is_its_definition() {
        // Far from unit (scaled by powers of two, so exactly the same directions) and
        // extrapolated: the general loop, pair by pair. Pair 0's dot is exactly 0 (r kept),
        // pair 1's is negative (r negated).
        let mut keys = exact_units(16);
        keys[0] = [1.0, 0.0, 0.0, 0.0];
        keys[8] = [0.0, 1.0, 0.0, 0.0];
        keys[1] = [0.5, 0.5, 0.5, 0.5];
        keys[9] = [-1.0, 0.0, 0.0, 0.0];
        let scaled: Vec<[f64; 4]> =
            keys.iter().enumerate().map(|(i, q)| q.map(|c| c * 2f64.powi(i as i32 - 7))).collect();
        let s = [0.25, 0.7, -2.0, 3.5, 0.0, 1.0, 1e3, -0.5];
        let (mut general, mut fast) = (vec![0.0; 32], vec![0.0; 32]);
        nlerp_batch(&flat(&scaled[..8]), &flat(&scaled[8..]), &s, &mut general).unwrap();
        // The same directions, unit, in [0, 1]: the fast kernel, which must agree.
        let inside = s.map(|x| x.clamp(0.0, 1.0));
        nlerp_batch(&flat(&keys[..8]), &flat(&keys[8..]), &inside, &mut fast).unwrap();
        for i in 0..8 {
            let expected = nlerp_by_definition(keys[i], keys[8 + i], s[i]);
            let gap = largest_gap(&general[4 * i..4 * i + 4], &expected);
            assert!(gap < 2e-15, "pair {i}, s = {}: {gap:e}", s[i]);
            let expected = nlerp_by_definition(keys[i], keys[8 + i], inside[i]);
            let gap = largest_gap(&fast[4 * i..4 * i + 4], &expected);
            assert!(gap < 2e-15, "fast, pair {i}, s = {}: {gap:e}", inside[i]);
        }
    }

    #[test]
    fn huge_parameters_are_refused_as_the_single_call_refuses_them() {
        let keys = exact_units(2);
        let (p, r) = (from_wxyz(keys[0]), from_wxyz(keys[1]));
        let (starts, ends) = (flat(&keys[..1]), flat(&keys[1..]));
        let mut out = vec![0.0; 4];
        for s in [1e6 * (1.0 + f64::EPSILON), -3e6, 1e20, 1e300, f64::MAX] {
            let single = crate::slerp(p, r, s, true).unwrap_err();
            for batch in [
                slerp_batch(&starts, &ends, &[s], &mut out, true),
                nlerp_batch(&starts, &ends, &[s], &mut out),
            ] {
                let e = batch.unwrap_err();
                assert_eq!((e.argument(), e.kind()), ("s[0]", single.kind()), "s = {s:e}");
            }
        }
    }

    #[test]
    fn single_and_batch_calls_agree_on_every_input_both_accept() {
        let keys = exact_units(40);
        let mut starts = flat(&keys[..20]);
        let ends = flat(&keys[20..]);
        // Not unit: tiny, huge and single-precision inputs.
        starts[0..4].copy_from_slice(&[1e-300, 2e-300, 0.0, -1e-300]);
        starts[4..8].copy_from_slice(&[3e300, 0.0, 4e300, 0.0]);
        for c in &mut starts[8..12] {
            *c = *c as f32 as f64;
        }
        let inside: Vec<f64> = (0..20).map(|i| i as f64 / 19.0).collect();
        // Extrapolation up to the bound sends the whole call through the general loop.
        let outside: Vec<f64> = (0..20).map(|i| -1e6 + i as f64 * 1.05e5).collect();
        let mut out = vec![0.0; 80];
        for shortest in [true, false] {
            for (parameters, exact) in [(&inside, false), (&outside, true)] {
                slerp_batch(&starts, &ends, parameters, &mut out, shortest).unwrap();
                for i in 0..20 {
                    let p = from_wxyz(starts[4 * i..4 * i + 4].try_into().unwrap());
                    let r = from_wxyz(ends[4 * i..4 * i + 4].try_into().unwrap());
                    let single = to_wxyz(crate::slerp(p, r, parameters[i], shortest).unwrap());
                    let batch = &out[4 * i..4 * i + 4];
                    if exact {
                        assert_eq!(batch, &single, "pair {i}, s = {}", parameters[i]);
                    } else {
                        let gap = (0..4).map(|c| (batch[c] - single[c]).abs()).fold(0.0, f64::max);
                        assert!(gap < 1e-15, "pair {i}, s = {}: {gap:e}", parameters[i]);
                    }
                }
            }
        }
    }
}
