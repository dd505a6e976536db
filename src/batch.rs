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
//! For SLERP,
//! with `ψ0 = φ0/2`: `q(σ) = cos((1-2σ) ψ0) s/|s| + sin((1-2σ) ψ0) d/|d|`.
//!
//! Only when the target is nearly `-p` (the long way round) does the frame lose orthogonality
//! (`s·d = |p|² - |t|²` is rounding, `|s|` is tiny); those pairs take [`GreatArc`]'s careful path.

use glam::DQuat;

use crate::closed_form::point_from_half_angle_tan;
use crate::error::KliError;
use crate::great_arc::GreatArc;
use crate::lanes::{Lanes, Mask};
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
pub fn check_lengths(
    starts: usize,
    ends: usize,
    parameters: usize,
    out: usize,
    parameter_name: &str,
) -> Result<(), KliError> {
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
fn arc(
    starts: &[f64],
    ends: &[f64],
    i: usize,
    first: usize,
    shortest_path: bool,
) -> Result<GreatArc, KliError> {
    let p = read_unit(starts, i, first, "starts")?;
    let r = read_unit(ends, i, first, "ends")?;
    GreatArc::new(p, r, shortest_path).map_err(|e| match e {
        KliError::Antipodal => KliError::InvalidArgument {
            name: format!("starts[{}]", first + i),
            problem: format!(
                "and ends[{}] are antipodal and shortestPath is false: no path is determined",
                first + i
            ),
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
    // The common case first, branch-free so the compiler can pipeline and vectorise it; if any
    // pair falls outside it (bad input, extreme magnitudes, a target near -p), the general loop
    // below redoes the call and reports or handles that pair.
    let all_fast = match kind {
        BatchKind::KliExact => kli_exact_fast(starts, ends, parameters, out, shortest_path),
        BatchKind::Nlerp => nlerp_fast(starts, ends, parameters, out),
        BatchKind::Slerp => slerp_fast(starts, ends, parameters, out, shortest_path),
    };
    if all_fast {
        return Ok(());
    }
    for (i, &x) in parameters.iter().enumerate() {
        let valid = x.is_finite() && (kind != BatchKind::KliExact || x >= 0.0);
        if !valid {
            let requirement = if kind == BatchKind::KliExact {
                "a finite number ≥ 0"
            } else {
                "a finite number"
            };
            return Err(KliError::InvalidNumber {
                name: format!("{}[{}]", kind.parameter_name(), first + i),
                value: x,
                requirement,
            });
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

/// `1/√n` for `n` within [`NEARLY_UNIT`] of 1, as the series `1 - e/2 + 3e²/8 - 5e³/16` in
/// `e = n - 1` (remainder `35e⁴/128` < 3e-17): inputs that are unit quaternions up to rounding,
/// including single-precision ones, need no square root or division.
#[inline(always)]
fn inverse_sqrt_near_one(n: Lanes) -> Lanes {
    let e = n - Lanes::splat(1.0);
    Lanes::splat(1.0)
        + e * (Lanes::splat(-0.5) + e * (Lanes::splat(0.375) - Lanes::splat(0.3125) * e))
}

/// How far `|q|²` may be from 1 for [`inverse_sqrt_near_one`].
const NEARLY_UNIT: f64 = 1e-4;

/// One quaternion component per element, two pairs per lane.
type Quat2 = [Lanes; 4];

#[inline(always)]
fn dot4(a: &Quat2, b: &Quat2) -> Lanes {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]
}

/// The half-angle frame (module docs) of two pairs as the fast kernels build it: `d = p - t`,
/// `s = p + t` for `p` and the target `t` normalised by [`inverse_sqrt_near_one`], their squared
/// lengths, and whether both inputs were near enough to unit for that.
struct Frame {
    d: Quat2,
    s: Quat2,
    dd: Lanes,
    ss: Lanes,
    nearly_unit: Mask,
}

impl Frame {
    #[inline(always)]
    fn new(p: &Quat2, r: &Quat2, shortest_path: bool) -> Self {
        let (np, nr) = (dot4(p, p), dot4(r, r));
        let (ip, ir) = (inverse_sqrt_near_one(np), inverse_sqrt_near_one(nr));
        let ir = if shortest_path {
            Lanes::select(dot4(p, r).lt(Lanes::splat(0.0)), -ir, ir)
        } else {
            ir
        };
        let d = [0, 1, 2, 3].map(|c| p[c] * ip - r[c] * ir);
        let s = [0, 1, 2, 3].map(|c| p[c] * ip + r[c] * ir);
        let limit = Lanes::splat(NEARLY_UNIT);
        let nearly_unit =
            (np - Lanes::splat(1.0)).abs().le(limit) & (nr - Lanes::splat(1.0)).abs().le(limit);
        Self { dd: dot4(&d, &d), ss: dot4(&s, &s), d, s, nearly_unit }
    }
}

/// Runs `kernel` over the pairs two at a time (an odd last pair fills both lanes) and writes its
/// results to `out`; returns whether every pair was in the kernel's domain.
#[inline(always)]
fn two_pairs_at_a_time(
    starts: &[f64],
    ends: &[f64],
    parameters: &[f64],
    out: &mut [f64],
    kernel: impl Fn(&Quat2, &Quat2, Lanes) -> (Quat2, Mask),
) -> bool {
    let lanes = |a: &[f64], b: &[f64]| -> Quat2 { [0, 1, 2, 3].map(|c| Lanes::new(a[c], b[c])) };
    let mut all = Mask::splat(true);
    let mut run = |p: &[f64], p2: &[f64], r: &[f64], r2: &[f64], x: Lanes, q: &mut [f64]| {
        let (result, valid) = kernel(&lanes(p, p2), &lanes(r, r2), x);
        all = all & valid;
        for c in 0..4 {
            let [first, second] = result[c].to_array();
            q[c] = first;
            if q.len() > 4 {
                q[4 + c] = second;
            }
        }
    };
    let (starts2, ends2, parameters2) =
        (starts.chunks_exact(8), ends.chunks_exact(8), parameters.chunks_exact(2));
    let (start_rest, end_rest, parameter_rest) =
        (starts2.remainder(), ends2.remainder(), parameters2.remainder());
    let mut out2 = out.chunks_exact_mut(8);
    for (((p, r), x), q) in starts2.zip(ends2).zip(parameters2).zip(&mut out2) {
        run(&p[..4], &p[4..], &r[..4], &r[4..], Lanes::new(x[0], x[1]), q);
    }
    if let ([x], 4, 4) = (parameter_rest, start_rest.len(), end_rest.len()) {
        run(start_rest, start_rest, end_rest, end_rest, Lanes::splat(*x), out2.into_remainder());
    }
    all.all()
}

/// The KLI closed form for every pair, assuming each is in the common case (unit inputs up to
/// rounding, `t ≥ 0`, the target not near `-p`); returns whether all were.
///
/// In the half-angle frame (module docs) with `dd = |d|²`, `ss = |s|²`, `E = e^(-t)` and
/// `u = tan(φ/2) = (|d|/|s|) E`, multiplying through by `ss` removes every square root:
/// `q = [(ss - dd E² + 2 dd E) s + (2E ss - ss + dd E²) d] / (2 (ss + dd E²))`.
fn kli_exact_fast(
    starts: &[f64],
    ends: &[f64],
    t: &[f64],
    out: &mut [f64],
    shortest_path: bool,
) -> bool {
    two_pairs_at_a_time(starts, ends, t, out, |p, r, t| {
        let Frame { d, s, dd, ss, nearly_unit } = Frame::new(p, r, shortest_path);
        let e = (-t).exp_nonpositive();
        let dde = dd * e;
        let half = Lanes::splat(0.5) / (ss + dde * e);
        let a = (ss - dde * e + Lanes::splat(2.0) * dde) * half;
        let b = (Lanes::splat(2.0) * e * ss - ss + dde * e) * half;
        let q = [0, 1, 2, 3].map(|c| a * s[c] + b * d[c]);
        let zero = Lanes::splat(0.0);
        (
            q,
            nearly_unit
                & Lanes::splat(FRAME_LIMIT).le(ss)
                & zero.le(t)
                & t.le(Lanes::splat(f64::MAX)),
        )
    })
}

/// `atan(u)` lane-wise for `0 ≤ u ≤ 1`, branch-free: two half-angle steps
/// `u ↦ u / (1 + √(1 + u²))` bring `u` below `tan(π/16) ≈ 0.199`, where the Taylor series to
/// `u²³` is exact to 1e-19.
#[inline(always)]
fn atan_unit_interval(u: Lanes) -> Lanes {
    const C: [f64; 12] = [
        1.0,
        -1.0 / 3.0,
        1.0 / 5.0,
        -1.0 / 7.0,
        1.0 / 9.0,
        -1.0 / 11.0,
        1.0 / 13.0,
        -1.0 / 15.0,
        1.0 / 17.0,
        -1.0 / 19.0,
        1.0 / 21.0,
        -1.0 / 23.0,
    ];
    // Both halvings at once, with one division: for a = √(1 + u²), the second step of
    // v = u / (1 + a) is w = u / (1 + a + √((1 + a)² + u²)).
    let one = Lanes::splat(1.0);
    let u2 = u * u;
    let one_plus_a = one + (one + u2).sqrt();
    let w = u / (one_plus_a + (one_plus_a * one_plus_a + u2).sqrt());
    // The series in z = w², by Estrin's scheme (see `Lanes::exp_nonpositive`).
    let c = C.map(Lanes::splat);
    let z = w * w;
    let (z2, pairs) = (z * z, [0, 1, 2, 3, 4, 5].map(|k| c[2 * k] + c[2 * k + 1] * z));
    let z4 = z2 * z2;
    let series = (pairs[0] + pairs[1] * z2)
        + (pairs[2] + pairs[3] * z2) * z4
        + (pairs[4] + pairs[5] * z2) * (z4 * z4);
    Lanes::splat(4.0) * w * series
}

/// `(sin x, cos x)` lane-wise for `|x| ≤ π/4`, branch-free Taylor polynomials in `y = x²` (to
/// `x¹⁷` and `x¹⁶`: remainders below 1e-17), by Estrin's scheme.
#[inline(always)]
fn sin_cos_small(x: Lanes) -> (Lanes, Lanes) {
    const SIN: [f64; 9] = [
        1.0,
        -1.0 / 6.0,
        1.0 / 120.0,
        -1.0 / 5040.0,
        1.0 / 362_880.0,
        -1.0 / 39_916_800.0,
        1.0 / 6_227_020_800.0,
        -1.0 / 1_307_674_368_000.0,
        1.0 / 355_687_428_096_000.0,
    ];
    const COS: [f64; 9] = [
        1.0,
        -0.5,
        1.0 / 24.0,
        -1.0 / 720.0,
        1.0 / 40_320.0,
        -1.0 / 3_628_800.0,
        1.0 / 479_001_600.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 20_922_789_888_000.0,
    ];
    let y = x * x;
    let (y2, y4) = (y * y, y * y * (y * y));
    let estrin = |c: [f64; 9]| {
        let c = c.map(Lanes::splat);
        let pairs = [0, 1, 2, 3].map(|k| c[2 * k] + c[2 * k + 1] * y);
        (pairs[0] + pairs[1] * y2) + (pairs[2] + pairs[3] * y2) * y4 + c[8] * (y4 * y4)
    };
    (x * estrin(SIN), estrin(COS))
}

/// SLERP for every pair in the common case (unit inputs up to rounding, `σ ∈ [0, 1]`, the
/// target within 90° of `p` in R⁴); returns whether all were. In the half-angle frame,
/// `q = cos((1-2σ) ψ0) s/|s| + sin((1-2σ) ψ0) d/|d|` with `ψ0 = atan(|d|/|s|) ≤ π/4`.
fn slerp_fast(
    starts: &[f64],
    ends: &[f64],
    sigma: &[f64],
    out: &mut [f64],
    shortest_path: bool,
) -> bool {
    two_pairs_at_a_time(starts, ends, sigma, out, |p, r, sigma| {
        let Frame { d, s, dd, ss, nearly_unit } = Frame::new(p, r, shortest_path);
        // One division for 1/|s|, 1/|d| and |d|/|s|. When p = t exactly, |d| is floored so the
        // quotient stays finite; sin is 0 there and the d term vanishes.
        let (dn, sn) = (dd.sqrt().max(Lanes::splat(f64::MIN_POSITIVE)), ss.sqrt());
        let inverse = Lanes::splat(1.0) / (dn * sn);
        let half_angle = atan_unit_interval(dd * inverse);
        let (sin, cos) =
            sin_cos_small((Lanes::splat(1.0) - Lanes::splat(2.0) * sigma) * half_angle);
        let (a, b) = (cos * dn * inverse, sin * sn * inverse);
        let q = [0, 1, 2, 3].map(|c| a * s[c] + b * d[c]);
        (q, nearly_unit & dd.le(ss) & Lanes::splat(0.0).le(sigma) & sigma.le(Lanes::splat(1.0)))
    })
}

/// Normalised linear interpolation for every pair, assuming unit inputs up to rounding (as
/// [`kli_exact_fast`] does, so the baseline is as cheap as it can be); returns whether all were.
fn nlerp_fast(starts: &[f64], ends: &[f64], s: &[f64], out: &mut [f64]) -> bool {
    two_pairs_at_a_time(starts, ends, s, out, |p, r, sigma| {
        // In the frame, p = (s + d)/2 and the target t = (s - d)/2: lerp is s/2 + (1/2 - σ) d.
        let Frame { d, s: sum, nearly_unit, .. } = Frame::new(p, r, true);
        let half = Lanes::splat(0.5);
        let m = [0, 1, 2, 3].map(|c| half * sum[c] + (half - sigma) * d[c]);
        let scale = Lanes::splat(1.0) / dot4(&m, &m).sqrt();
        let finite = sigma.abs().le(Lanes::splat(f64::MAX));
        (m.map(|c| c * scale), nearly_unit & finite)
    })
}

/// `|s|²` below which the half-angle frame is not orthogonal to 1e-12 (`s·d/(|s||d|)` is
/// rounding over `|s|`): the target is within 1e-3 of `-p`.
const FRAME_LIMIT: f64 = 1e-6;

/// The pair through [`GreatArc`], which re-orthogonalises its frame.
#[cold]
fn careful(
    kind: BatchKind,
    starts: &[f64],
    ends: &[f64],
    i: usize,
    first: usize,
    shortest_path: bool,
    x: f64,
) -> Result<DQuat, KliError> {
    let arc = arc(starts, ends, i, first, shortest_path)?;
    Ok(match kind {
        BatchKind::Slerp => slerp::point_at(&arc, x),
        _ => point_from_half_angle_tan(&arc, arc.half_angle_tan() * (-x).exp()),
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

/// The step of times sampled evenly, when every `times[k]` is `times[0] + k·step` to rounding.
fn even_steps(times: &[f64]) -> Option<f64> {
    let (&first, &last) = (times.first()?, times.last()?);
    if times.len() < 3 {
        return None;
    }
    let step = (last - first) / (times.len() - 1) as f64;
    let even = times.iter().enumerate().all(|(k, &t)| {
        (t - (first + k as f64 * step)).abs() <= 8.0 * f64::EPSILON * (1.0 + t.abs())
    });
    even.then_some(step)
}

/// How many samples the even-step recurrence runs before it re-anchors on an exact `exp`, so
/// rounding in `u` stays within a few ulp.
const REANCHOR: usize = 32;

/// One KLI path from `p` towards `r`, at each of `times` (each finite and `≥ 0`), into `out`
/// (`4·times.len()` numbers). Evenly spaced times advance `e^(-t)` by a fixed factor.
pub fn kli_sample_into(
    p: DQuat,
    r: DQuat,
    times: &[f64],
    out: &mut [f64],
    shortest_path: bool,
) -> Result<(), KliError> {
    if out.len() != 4 * times.len() {
        return Err(KliError::InvalidArgument {
            name: "out".into(),
            problem: format!(
                "must hold 4 numbers per time: {} (got {})",
                4 * times.len(),
                out.len()
            ),
        });
    }
    if let Some(k) = times.iter().position(|t| !(t.is_finite() && *t >= 0.0)) {
        return Err(KliError::InvalidNumber {
            name: format!("times[{k}]"),
            value: times[k],
            requirement: "a finite number ≥ 0",
        });
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
                .starts_with("starts must hold 4 numbers per t value: 4 for 1 values (got 8)")
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
    }

    #[test]
    fn fast_paths_match_the_general_loop_and_fall_back_when_they_must() {
        // Unit inputs up to single-precision rounding take the fast path; its results agree
        // with the general loop's to 1e-15.
        let starts = flat(&[[0.3, -0.1, 0.7, 0.2], [1.0, 0.0, 0.0, 0.0], [0.5; 4]]);
        let ends =
            flat(&[[0.5, 0.4, -0.2, 0.6], [-0.6, 0.8, 0.0, 0.0], [0.5, 0.5, 0.5, 0.5 + 1e-12]]);
        let unit = |v: &[f64]| -> Vec<f64> {
            v.chunks(4)
                .flat_map(|q| {
                    let n = q.iter().map(|c| c * c).sum::<f64>().sqrt();
                    q.iter().map(move |c| ((c / n) as f32) as f64)
                })
                .collect()
        };
        let (starts, ends) = (unit(&starts), unit(&ends));
        let t = [0.0, 0.7, 30.0];
        for shortest in [true, false] {
            let mut fast = vec![0.0; 12];
            assert!(kli_exact_fast(&starts, &ends, &t, &mut fast, shortest));
            let mut general = vec![0.0; 12];
            for i in 0..3 {
                let p = unit_q(&starts[4 * i..4 * i + 4]);
                let r = unit_q(&ends[4 * i..4 * i + 4]);
                general[4 * i..4 * i + 4]
                    .copy_from_slice(&to_wxyz(kli_exact(p, r, t[i], shortest).unwrap()));
            }
            for (a, b) in fast.iter().zip(&general) {
                assert!((a - b).abs() < 1e-15, "{fast:?} vs {general:?}");
            }
        }
        // Not nearly unit, or the long way near -p: the fast path declines.
        let mut out = vec![0.0; 4];
        assert!(!kli_exact_fast(
            &[2.0, 0.0, 0.0, 0.0],
            &[0.0, 1.0, 0.0, 0.0],
            &[1.0],
            &mut out,
            true
        ));
        assert!(!kli_exact_fast(
            &[1.0, 0.0, 0.0, 0.0],
            &[-1.0, 1e-9, 0.0, 0.0],
            &[1.0],
            &mut out,
            false
        ));
        assert!(!kli_exact_fast(
            &[1.0, 0.0, 0.0, 0.0],
            &[0.0, 1.0, 0.0, 0.0],
            &[f64::NAN],
            &mut out,
            true
        ));
        // …and the call still answers, through the general loop.
        kli_exact_batch(&[2.0, 0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, 0.0], &[1.0], &mut out, true)
            .unwrap();
        assert!((out.iter().map(|c| c * c).sum::<f64>() - 1.0).abs() < 1e-15);
    }

    fn unit_q(q: &[f64]) -> DQuat {
        unit("q", from_wxyz(q.try_into().unwrap())).unwrap()
    }

    #[test]
    fn branch_free_atan_sin_cos_are_accurate() {
        let mut worst = 0.0_f64;
        for k in 0..=100_000 {
            let u = k as f64 / 100_000.0;
            worst = worst.max((atan_unit_interval(Lanes::splat(u)).to_array()[0] - u.atan()).abs());
            let x = (u - 0.5) * std::f64::consts::FRAC_PI_2;
            let (sin, cos) = sin_cos_small(Lanes::splat(x));
            worst = worst
                .max((sin.to_array()[0] - x.sin()).abs())
                .max((cos.to_array()[1] - x.cos()).abs());
        }
        assert!(worst < 4e-16, "worst absolute error {worst:e}");
    }

    #[test]
    fn slerp_fast_path_matches_the_single_call() {
        let starts = flat(&[[0.3, -0.1, 0.7, 0.2], [1.0, 0.0, 0.0, 0.0], [0.5; 4], [0.5; 4]]);
        let ends = flat(&[
            [0.5, 0.4, -0.2, 0.6],
            [-0.6, 0.8, 0.0, 0.0],
            [0.5, 0.5, 0.5, 0.5 + 1e-12],
            [0.5; 4],
        ]);
        let normalised: Vec<f64> =
            starts.chunks(4).chain(ends.chunks(4)).flat_map(|q| to_wxyz(unit_q(q))).collect();
        let (starts, ends) = normalised.split_at(16);
        let sigma = [0.0, 0.35, 0.8, 1.0];
        let mut fast = vec![0.0; 16];
        assert!(slerp_fast(starts, ends, &sigma, &mut fast, true));
        for i in 0..4 {
            let single = to_wxyz(
                crate::slerp(
                    unit_q(&starts[4 * i..4 * i + 4]),
                    unit_q(&ends[4 * i..4 * i + 4]),
                    sigma[i],
                    true,
                )
                .unwrap(),
            );
            for c in 0..4 {
                assert!(
                    (fast[4 * i + c] - single[c]).abs() < 1e-15,
                    "pair {i}: {:?} vs {single:?}",
                    &fast[4 * i..4 * i + 4]
                );
            }
        }
        // Extrapolation and the long way round leave it to the general loop.
        let mut out = vec![0.0; 4];
        assert!(!slerp_fast(&[1.0, 0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, 0.0], &[1.5], &mut out, true));
        assert!(!slerp_fast(
            &[1.0, 0.0, 0.0, 0.0],
            &[-0.6, 0.8, 0.0, 0.0],
            &[0.5],
            &mut out,
            false
        ));
    }

    fn good_q() -> DQuat {
        from_wxyz([1.0, 0.0, 0.0, 0.0])
    }
}
