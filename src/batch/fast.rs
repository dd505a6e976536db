//! The batch kernels for the common case, branch-free: unit inputs up to rounding, parameters
//! in range, the target not near `-p`. Each reports whether every pair was in its domain; if
//! one was not, the caller redoes the call pair by pair. Formulas: the half-angle frame of the
//! parent module's docs. The kernels are written once over [`Simd`] and run where each was
//! measured fastest (`node bench/batch.mjs`, docs/performance.md): SLERP and NLERP four pairs a
//! step on [`Quad`], two chains interleaved instruction by instruction (SLERP's chain of square
//! roots, a division, `atan` and `sin`/`cos` is latency-bound: 1.27× faster than two pairs a
//! step); KLI's closed form two pairs a step on [`Lanes`] (its `exp` polynomial keeps enough
//! values live that two chains of it ran 0.85× as fast).

use super::BatchKind;
use crate::lanes::{Lanes, Simd, SimdMask};
use crate::quad::Quad;
use crate::slerp::MAX_PARAMETER;
use crate::trig::sin_cos_small;

/// Runs the fast kernel of `kind`; returns whether every pair was in its domain (when not,
/// `out` holds garbage for the pairs outside it).
pub(super) fn run(
    kind: BatchKind,
    starts: &[f64],
    ends: &[f64],
    parameters: &[f64],
    out: &mut [f64],
    shortest_path: bool,
) -> bool {
    match kind {
        BatchKind::KliExact => kli_exact(starts, ends, parameters, out, shortest_path),
        BatchKind::Slerp => slerp(starts, ends, parameters, out, shortest_path),
        BatchKind::Nlerp => nlerp(starts, ends, parameters, out),
    }
}

/// `1/√n` for `n` within [`NEARLY_UNIT`] of 1, as the series `1 - e/2 + 3e²/8 - 5e³/16` in
/// `e = n - 1` (remainder `35e⁴/128` < 3e-17): inputs that are unit quaternions up to rounding,
/// including single-precision ones, need no square root or division.
#[inline(always)]
fn inverse_sqrt_near_one<S: Simd>(n: S) -> S {
    let e = n - S::splat(1.0);
    S::splat(1.0) + e * (S::splat(-0.5) + e * (S::splat(0.375) - S::splat(0.3125) * e))
}

/// How far `|q|²` may be from 1 for [`inverse_sqrt_near_one`].
const NEARLY_UNIT: f64 = 1e-4;

/// One quaternion component per element, a pair per lane.
type Quats<S> = [S; 4];

/// The dot product in glam's order (x, y, z, then w), so that `|q|² = 1` here exactly when
/// [`crate::quaternion::unit`] sees it so and leaves `q` as it is.
#[inline(always)]
fn dot4<S: Simd>(a: &Quats<S>, b: &Quats<S>) -> S {
    a[1] * b[1] + a[2] * b[2] + a[3] * b[3] + a[0] * b[0]
}

/// The half-angle frame (module docs) of two pairs as the fast kernels build it: `d = p - t`,
/// `s = p + t` for `p` and the target `t` normalised by [`inverse_sqrt_near_one`], their squared
/// lengths, and whether both inputs were near enough to unit for that. `p` and `t` themselves
/// are kept for the ends: an input with `|q|² = 1` is multiplied by exactly 1.
struct Frame<S: Simd> {
    p: Quats<S>,
    t: Quats<S>,
    d: Quats<S>,
    s: Quats<S>,
    dd: S,
    ss: S,
    nearly_unit: S::Mask,
}

impl<S: Simd> Frame<S> {
    #[inline(always)]
    fn new(p: &Quats<S>, r: &Quats<S>, shortest_path: bool) -> Self {
        let (np, nr) = (dot4(p, p), dot4(r, r));
        let (ip, ir) = (inverse_sqrt_near_one(np), inverse_sqrt_near_one(nr));
        let ir = if shortest_path { S::select(dot4(p, r).lt(S::splat(0.0)), -ir, ir) } else { ir };
        let (p, t) = (p.map(|c| c * ip), r.map(|c| c * ir));
        let d = [0, 1, 2, 3].map(|c| p[c] - t[c]);
        let s = [0, 1, 2, 3].map(|c| p[c] + t[c]);
        let limit = S::splat(NEARLY_UNIT);
        let nearly_unit =
            (np - S::splat(1.0)).abs().le(limit) & (nr - S::splat(1.0)).abs().le(limit);
        Self { dd: dot4(&d, &d), ss: dot4(&s, &s), p, t, d, s, nearly_unit }
    }
}

/// Runs `kernel` over the pairs `S::LANES` at a time (the last few padded with copies of the
/// last pair) and writes its results to `out`; returns whether every pair was in the kernel's
/// domain.
#[inline(always)]
fn in_steps<S: Simd>(
    starts: &[f64],
    ends: &[f64],
    parameters: &[f64],
    out: &mut [f64],
    kernel: impl Fn(&Quats<S>, &Quats<S>, S) -> (Quats<S>, S::Mask),
) -> bool {
    let (lanes, width) = (S::LANES, 4 * S::LANES);
    let mut all = steps(starts, ends, parameters, out, &kernel);
    let (start_rest, end_rest, parameter_rest) = (
        starts.chunks_exact(width).remainder(),
        ends.chunks_exact(width).remainder(),
        parameters.chunks_exact(lanes).remainder(),
    );
    let rest = parameter_rest.len();
    let out_rest = out.chunks_exact_mut(width).into_remainder();
    if rest > 0
        && start_rest.len() == 4 * rest
        && end_rest.len() == 4 * rest
        && out_rest.len() == 4 * rest
    {
        let pad = |values: &[f64], size: usize| -> [f64; 16] {
            let mut padded = [0.0; 16];
            for (i, slot) in padded.chunks_exact_mut(size).enumerate() {
                let from = size * i.min(rest - 1);
                slot.copy_from_slice(&values[from..from + size]);
            }
            padded
        };
        let (p, r, x) = (pad(start_rest, 4), pad(end_rest, 4), pad(parameter_rest, 1));
        let mut q = [0.0; 16];
        all = all & steps(&p[..width], &r[..width], &x[..lanes], &mut q[..width], &kernel);
        out_rest.copy_from_slice(&q[..4 * rest]);
    }
    all.all()
}

/// [`in_steps`]'s loop over the whole steps: quaternions go in and out of the lanes whole, a
/// transpose in registers each way ([`Simd::load_quaternions`]), and the fixed-size chunks
/// leave no bounds check in it. Out of line so that the kernel is compiled once for the array
/// and its padded rest.
#[inline(never)]
fn steps<S: Simd>(
    starts: &[f64],
    ends: &[f64],
    parameters: &[f64],
    out: &mut [f64],
    kernel: &impl Fn(&Quats<S>, &Quats<S>, S) -> (Quats<S>, S::Mask),
) -> S::Mask {
    let (lanes, width) = (S::LANES, 4 * S::LANES);
    let mut all = S::Mask::splat(true);
    let chunks = starts.chunks_exact(width).zip(ends.chunks_exact(width));
    for ((p, r), (x, q)) in
        chunks.zip(parameters.chunks_exact(lanes).zip(out.chunks_exact_mut(width)))
    {
        let (result, valid) = kernel(&S::load_quaternions(p), &S::load_quaternions(r), S::load(x));
        all = all & valid;
        S::store_quaternions(result, q);
    }
    all
}

/// The KLI closed form for every pair, assuming each is in the common case (unit inputs up to
/// rounding, `t ≥ 0`, the target not near `-p`); returns whether all were.
///
/// In the half-angle frame (module docs) with `dd = |d|²`, `ss = |s|²`, `E = e^(-t)` and
/// `u = tan(φ/2) = (|d|/|s|) E`, multiplying through by `ss` removes every square root:
/// `q = [(ss - dd E² + 2 dd E) s + (2E ss - ss + dd E²) d] / (2 (ss + dd E²))`.
fn kli_exact(
    starts: &[f64],
    ends: &[f64],
    t: &[f64],
    out: &mut [f64],
    shortest_path: bool,
) -> bool {
    in_steps::<Lanes>(starts, ends, t, out, |p, r, t| kli_exact_kernel(p, r, t, shortest_path))
}

/// [`kli_exact`]'s formula for the pairs of `p` and `r` at `t`, and where they are in its domain.
#[inline(always)]
fn kli_exact_kernel<S: Simd>(
    p: &Quats<S>,
    r: &Quats<S>,
    t: S,
    shortest_path: bool,
) -> (Quats<S>, S::Mask) {
    let Frame { p, d, s, dd, ss, nearly_unit, .. } = Frame::new(p, r, shortest_path);
    let e = (-t).exp_nonpositive();
    let dde = dd * e;
    let half = S::splat(0.5) / (ss + dde * e);
    let a = (ss - dde * e + S::splat(2.0) * dde) * half;
    let b = (S::splat(2.0) * e * ss - ss + dde * e) * half;
    let zero = S::splat(0.0);
    let start = t.eq(zero);
    let q = [0, 1, 2, 3].map(|c| S::select(start, p[c], a * s[c] + b * d[c]));
    (q, nearly_unit & S::splat(FRAME_LIMIT).le(ss) & zero.le(t) & t.le(S::splat(f64::MAX)))
}

/// `atan(w)` lane-wise for `0 ≤ w ≤ tan(π/16) ≈ 0.199`, as `w·f(w²)` with
/// `f(z) = Σ (-1)^k z^k / (2k + 1)`. `f` is taken as its Chebyshev economisation of degree 7 on
/// `[0, tan²(π/16)]` (the Taylor series to `z²⁹` projected onto Chebyshev polynomials there and
/// cut after `T₇`, in exact rational arithmetic): within 1e-17 of `f`, where the Taylor series
/// needs 12 terms for that.
#[inline(always)]
fn atan_small<S: Simd>(w: S) -> S {
    const C: [f64; 8] = [
        1.0,
        -0.333_333_333_333_303_2,
        0.199_999_999_983_953_24,
        -0.142_857_139_599_587_57,
        0.111_110_785_842_619_92,
        -0.090_891_404_294_023_34,
        0.076_387_284_486_595_44,
        -0.058_095_230_933_953_22,
    ];
    // By Estrin's scheme (see `Simd::exp_nonpositive`).
    let c = C.map(S::splat);
    let z = w * w;
    let (z2, pairs) = (z * z, [0, 1, 2, 3].map(|k| c[2 * k] + c[2 * k + 1] * z));
    w * ((pairs[0] + pairs[1] * z2) + (pairs[2] + pairs[3] * z2) * (z2 * z2))
}

/// SLERP for every pair in the common case (unit inputs up to rounding, `σ ∈ [0, 1]`, the
/// target within 90° of `p` in R⁴); returns whether all were. In the half-angle frame,
/// `q = cos((1-2σ) ψ0) s/|s| + sin((1-2σ) ψ0) d/|d|` with `ψ0 = atan(|d|/|s|) ≤ π/4`.
fn slerp(
    starts: &[f64],
    ends: &[f64],
    sigma: &[f64],
    out: &mut [f64],
    shortest_path: bool,
) -> bool {
    in_steps::<Quad>(starts, ends, sigma, out, |p, r, sigma| {
        slerp_kernel(p, r, sigma, shortest_path)
    })
}

/// [`slerp`]'s formula for the pairs of `p` and `r` at `σ`, and where they are in its domain.
#[inline(always)]
fn slerp_kernel<S: Simd>(
    p: &Quats<S>,
    r: &Quats<S>,
    sigma: S,
    shortest_path: bool,
) -> (Quats<S>, S::Mask) {
    let Frame { p, t, d, s, dd, ss, nearly_unit } = Frame::new(p, r, shortest_path);
    // For unit p and t, |d| = 2 sin ψ0 and |s| = 2 cos ψ0, so tan(ψ0/2) = |d| / (2 + |s|), and
    // one more half-angle step gives tan(ψ0/4) = |d| / (h + √(h² + |d|²)) with h = 2 + |s|:
    // ψ0/4 ≤ π/16, where `atan_small` holds. One division serves that quotient and 1/(|s||d|).
    // When p = t exactly, |d| is floored so the quotients stay finite; the angle and sin are 0
    // there and the d term vanishes.
    let (dn, sn) = (dd.sqrt().max(S::splat(f64::MIN_POSITIVE)), ss.sqrt());
    let h = S::splat(2.0) + sn;
    let denominator = h + (h * h + dd).sqrt();
    let reciprocal = S::splat(1.0) / (dn * sn * denominator);
    let (quarter, inverse) = (dd * sn * reciprocal, denominator * reciprocal);
    let half_angle = S::splat(4.0) * atan_small(quarter);
    let (sin, cos) = sin_cos_small((S::splat(1.0) - S::splat(2.0) * sigma) * half_angle);
    let (a, b) = (cos * dn * inverse, sin * sn * inverse);
    let q = with_exact_ends(&p, &t, sigma, [0, 1, 2, 3].map(|c| a * s[c] + b * d[c]));
    (q, nearly_unit & dd.le(ss) & S::splat(0.0).le(sigma) & sigma.le(S::splat(1.0)))
}

/// Normalised linear interpolation for every pair, assuming unit inputs up to rounding (as
/// [`kli_exact`] does, so the baseline is as cheap as it can be); returns whether all were.
fn nlerp(starts: &[f64], ends: &[f64], s: &[f64], out: &mut [f64]) -> bool {
    in_steps::<Quad>(starts, ends, s, out, |p, r, sigma| {
        // In the frame, p = (s + d)/2 and the target t = (s - d)/2: lerp is s/2 + (1/2 - σ) d.
        let Frame { p, t, d, s: sum, nearly_unit, .. } = Frame::new(p, r, true);
        let half = Quad::splat(0.5);
        let m = [0, 1, 2, 3].map(|c| half * sum[c] + (half - sigma) * d[c]);
        let scale = Quad::splat(1.0) / dot4(&m, &m).sqrt();
        let in_range = sigma.abs().le(Quad::splat(MAX_PARAMETER));
        (with_exact_ends(&p, &t, sigma, m.map(|c| c * scale)), nearly_unit & in_range)
    })
}

/// `q`, but the start `p` exactly where `σ = 0` and the target `t` exactly where `σ = 1`.
#[inline(always)]
fn with_exact_ends<S: Simd>(p: &Quats<S>, t: &Quats<S>, sigma: S, q: Quats<S>) -> Quats<S> {
    let (at_start, at_end) = (sigma.eq(S::splat(0.0)), sigma.eq(S::splat(1.0)));
    [0, 1, 2, 3].map(|c| S::select(at_start, p[c], S::select(at_end, t[c], q[c])))
}

/// `|s|²` below which the half-angle frame is not orthogonal to 1e-12 (`s·d/(|s||d|)` is
/// rounding over `|s|`): the target is within 1e-3 of `-p`.
const FRAME_LIMIT: f64 = 1e-6;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::closed_form::kli_exact as kli_exact_single;
    use crate::lanes::Lanes;
    use crate::quaternion::{from_wxyz, to_wxyz, unit};
    use glam::DQuat;

    fn flat(qs: &[[f64; 4]]) -> Vec<f64> {
        qs.iter().flatten().copied().collect()
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
            assert!(kli_exact(&starts, &ends, &t, &mut fast, shortest));
            let mut general = vec![0.0; 12];
            for i in 0..3 {
                let p = unit_q(&starts[4 * i..4 * i + 4]);
                let r = unit_q(&ends[4 * i..4 * i + 4]);
                general[4 * i..4 * i + 4]
                    .copy_from_slice(&to_wxyz(kli_exact_single(p, r, t[i], shortest).unwrap()));
            }
            for (a, b) in fast.iter().zip(&general) {
                assert!((a - b).abs() < 1e-15, "{fast:?} vs {general:?}");
            }
        }
        // Not nearly unit, or the long way near -p: the fast path declines.
        let mut out = vec![0.0; 4];
        assert!(!kli_exact(&[2.0, 0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, 0.0], &[1.0], &mut out, true));
        assert!(!kli_exact(
            &[1.0, 0.0, 0.0, 0.0],
            &[-1.0, 1e-9, 0.0, 0.0],
            &[1.0],
            &mut out,
            false
        ));
        assert!(!kli_exact(
            &[1.0, 0.0, 0.0, 0.0],
            &[0.0, 1.0, 0.0, 0.0],
            &[f64::NAN],
            &mut out,
            true
        ));
        // …and the call still answers, through the general loop.
        super::super::kli_exact_batch(
            &[2.0, 0.0, 0.0, 0.0],
            &[0.0, 1.0, 0.0, 0.0],
            &[1.0],
            &mut out,
            true,
        )
        .unwrap();
        assert!((out.iter().map(|c| c * c).sum::<f64>() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn branch_free_atan_sin_cos_are_accurate() {
        let mut worst = 0.0_f64;
        for k in 0..=100_000 {
            let u = k as f64 / 100_000.0;
            let w = u * (std::f64::consts::PI / 16.0).tan();
            worst = worst.max((atan_small(Lanes::splat(w)).to_array()[0] - w.atan()).abs());
            let both = atan_small(Quad::new(w, 0.5 * w, w, w * w)).to_array();
            assert_eq!(both[0], atan_small(Lanes::splat(w)).to_array()[0]);
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
        assert!(slerp(starts, ends, &sigma, &mut fast, true));
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
        assert!(!slerp(&[1.0, 0.0, 0.0, 0.0], &[0.0, 1.0, 0.0, 0.0], &[1.5], &mut out, true));
        assert!(!slerp(&[1.0, 0.0, 0.0, 0.0], &[-0.6, 0.8, 0.0, 0.0], &[0.5], &mut out, false));
    }

    #[test]
    fn every_count_of_pairs_writes_each_pair_and_no_more() {
        // Four pairs a step: counts 1 to 9 cover whole steps and every padded rest.
        let pair = |k: usize| -> ([f64; 4], [f64; 4]) {
            let a = k as f64;
            let p = to_wxyz(unit_q(&[1.0, 0.1 * a, -0.2, 0.05 * a]));
            let r = to_wxyz(unit_q(&[0.3 * a - 1.0, 0.7, 0.2 * a, -0.4]));
            (p, r)
        };
        for n in 1..=9 {
            let (starts, ends): (Vec<[f64; 4]>, Vec<[f64; 4]>) = (0..n).map(pair).unzip();
            let (starts, ends) = (flat(&starts), flat(&ends));
            let t: Vec<f64> = (0..n).map(|k| 0.3 + 0.9 * k as f64).collect();
            let sigma: Vec<f64> = (0..n).map(|k| (k as f64 + 0.5) / n as f64).collect();
            let mut kli = vec![7.0; 4 * n + 1];
            let mut sl = vec![7.0; 4 * n + 1];
            assert!(kli_exact(&starts, &ends, &t, &mut kli[..4 * n], true));
            assert!(slerp(&starts, &ends, &sigma, &mut sl[..4 * n], true));
            assert_eq!((kli[4 * n], sl[4 * n]), (7.0, 7.0), "n = {n}: wrote past the end");
            for i in 0..n {
                let p = unit_q(&starts[4 * i..4 * i + 4]);
                let r = unit_q(&ends[4 * i..4 * i + 4]);
                let exact = to_wxyz(kli_exact_single(p, r, t[i], true).unwrap());
                let single = to_wxyz(crate::slerp(p, r, sigma[i], true).unwrap());
                for c in 0..4 {
                    assert!((kli[4 * i + c] - exact[c]).abs() < 1e-15, "n = {n}, pair {i}");
                    assert!((sl[4 * i + c] - single[c]).abs() < 1e-15, "n = {n}, pair {i}");
                }
            }
        }
    }

    #[test]
    fn the_kernels_agree_lane_for_lane_on_lanes_and_quads() {
        // The same kernel source on two lanes and on four: the same bits.
        let q = |a: f64| to_wxyz(unit_q(&[0.2, a, 0.9, -0.3]));
        let (p, r) = ([q(0.1), q(-0.4)], [q(0.8), q(0.3)]);
        let lanes = |x: [[f64; 4]; 2]| [0, 1, 2, 3].map(|c| Lanes::new(x[0][c], x[1][c]));
        let quads =
            |x: [[f64; 4]; 2]| [0, 1, 2, 3].map(|c| Quad::new(x[0][c], x[1][c], x[1][c], x[0][c]));
        let (two, _) = slerp_kernel(&lanes(p), &lanes(r), Lanes::new(0.25, 0.75), true);
        let (four, _) = slerp_kernel(&quads(p), &quads(r), Quad::new(0.25, 0.75, 0.75, 0.25), true);
        for c in 0..4 {
            let ([a, b], [w, x, y, z]) = (two[c].to_array(), four[c].to_array());
            assert_eq!([a, b, b, a].map(f64::to_bits), [w, x, y, z].map(f64::to_bits));
        }
        let (two, _) = kli_exact_kernel(&lanes(p), &lanes(r), Lanes::new(0.5, 3.0), false);
        let (four, _) =
            kli_exact_kernel(&quads(p), &quads(r), Quad::new(0.5, 3.0, 3.0, 0.5), false);
        for c in 0..4 {
            let ([a, b], [w, x, y, z]) = (two[c].to_array(), four[c].to_array());
            assert_eq!([a, b, b, a].map(f64::to_bits), [w, x, y, z].map(f64::to_bits));
        }
    }

    #[test]
    fn the_plain_lanes_give_the_kernels_the_same_bits() {
        // What wasm without `simd128` runs (the plain [f64; 2] lanes) against the lanes in use
        // here, over pairs near, far and antipodal, at times in and past the flow's span.
        use crate::lanes::portable;
        let plain = |x: [[f64; 4]; 2]| [0, 1, 2, 3].map(|c| portable::Lanes::new(x[0][c], x[1][c]));
        let lanes = |x: [[f64; 4]; 2]| [0, 1, 2, 3].map(|c| Lanes::new(x[0][c], x[1][c]));
        let same = |a: [Lanes; 4], b: [portable::Lanes; 4]| {
            (0..4).all(|c| a[c].to_array().map(f64::to_bits) == b[c].to_array().map(f64::to_bits))
        };
        let q = |a: f64, b: f64| to_wxyz(unit_q(&[a.cos(), b.sin(), a.sin() * b.cos(), 0.3 - a]));
        let mut checked = 0;
        for k in 0..200 {
            let (a, b) = (0.37 * k as f64, 0.91 * k as f64 + 0.2);
            let (p, r) = ([q(a, b), q(b, a)], [q(a + 0.01 * b, b), q(a + 3.1, -b)]);
            let antipodal = [p[0].map(|x| -x), r[1]];
            for r in [r, antipodal] {
                for (t0, t1) in [(0.0, 1.0), (0.25, 0.75), (3.0, 11.66), (20.0, 1e-9)] {
                    for shortest in [true, false] {
                        let (x, _) =
                            slerp_kernel(&lanes(p), &lanes(r), Lanes::new(t0, t1), shortest);
                        let (y, _) = slerp_kernel(
                            &plain(p),
                            &plain(r),
                            portable::Lanes::new(t0, t1),
                            shortest,
                        );
                        assert!(same(x, y), "slerp at {k}, {t0}, {t1}");
                        let (x, _) =
                            kli_exact_kernel(&lanes(p), &lanes(r), Lanes::new(t0, t1), shortest);
                        let (y, _) = kli_exact_kernel(
                            &plain(p),
                            &plain(r),
                            portable::Lanes::new(t0, t1),
                            shortest,
                        );
                        assert!(same(x, y), "KLI at {k}, {t0}, {t1}");
                        checked += 1;
                    }
                }
            }
        }
        assert_eq!(checked, 3200);
    }

    fn unit_q(q: &[f64]) -> DQuat {
        unit("q", from_wxyz(q.try_into().unwrap())).unwrap()
    }
}
