//! `sin` and `cos` for the core's scalar paths, from the batch kernels' polynomials: the angle
//! is reduced to `[-π, π]` by multiples of `2π` (Cody and Waite's two-part constant, exact in
//! the first part for `|x|` up to `2^20·2π`) and then by quadrants to `[-π/4, π/4]`. The
//! result is within 4e-16 of the true `sin` and `cos` of the reduced angle, which is `x` up to
//! about `|x|·1e-17`: below the rounding of any angle computed as a product of that size
//! (SLERP's `(1 - s) φ0`). With these, std's `sin`/`cos`, their large-argument reduction and
//! `fmod` stay out of the wasm module.

use std::f64::consts::{FRAC_1_PI, FRAC_2_PI, PI};

use crate::lanes::{Lanes, Simd};

/// `π/2` in two parts, `PIO2_HI` with 33 significant bits (so `k·PIO2_HI` is exact for
/// `|k| < 2^20`) and the rest (fdlibm's `pio2_1` and `pio2_1t`); `2π` is four times each.
const PIO2_HI: f64 = f64::from_bits(0x3ff9_21fb_5440_0000);
const PIO2_LO: f64 = f64::from_bits(0x3dd0_b461_1a62_6331);

/// `x` minus the nearest multiple of `2π`, in `[-π, π]` up to rounding. Angles beyond `2^20·2π`
/// (only absurd inputs) take a few more rounds and lose the digits their size has no room for.
fn reduce(x: f64) -> f64 {
    let mut r = x;
    for _ in 0..64 {
        if r.abs() <= PI {
            break;
        }
        let k = (r * (0.5 * FRAC_1_PI)).round();
        r = (r - k * (4.0 * PIO2_HI)) - k * (4.0 * PIO2_LO);
    }
    r
}

/// `(sin x, cos x)` for finite `x`.
pub fn sin_cos(x: f64) -> (f64, f64) {
    let r = reduce(x);
    let k = (r * FRAC_2_PI).round();
    let y = (r - k * PIO2_HI) - k * PIO2_LO;
    let (sin, cos) = sin_cos_small(Lanes::splat(y));
    let (s, c) = (sin.to_array()[0], cos.to_array()[0]);
    match k as i32 {
        0 => (s, c),
        1 => (c, -s),
        -1 => (-c, s),
        _ => (-s, -c),
    }
}

/// `(sin x, cos x)` lane-wise for `|x| ≤ π/4`, branch-free Taylor polynomials in `y = x²` (to
/// `x¹⁷` and `x¹⁶`: remainders below 1e-17), by Estrin's scheme.
#[inline(always)]
pub(crate) fn sin_cos_small<S: Simd>(x: S) -> (S, S) {
    let (sinc, cos) = sinc_cos_small_squared(x * x);
    (x * sinc, cos)
}

/// `(sin x / x, cos x)` lane-wise from `y = x²` for `|x| ≤ π/4`: the polynomials of
/// [`sin_cos_small`], so `exp` of a small rotation needs no square root and no division.
#[inline(always)]
pub(crate) fn sinc_cos_small_squared<S: Simd>(y: S) -> (S, S) {
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
    let (y2, y4) = (y * y, y * y * (y * y));
    let estrin = |c: [f64; 9]| {
        let c = c.map(S::splat);
        let pairs = [0, 1, 2, 3].map(|k| c[2 * k] + c[2 * k + 1] * y);
        (pairs[0] + pairs[1] * y2) + (pairs[2] + pairs[3] * y2) * y4 + c[8] * (y4 * y4)
    };
    (estrin(SIN), estrin(COS))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_std_within_the_rounding_of_the_reduction() {
        let mut worst = 0.0_f64;
        let mut check = |x: f64| {
            let (s, c) = sin_cos(x);
            let allowed = 4e-16 + x.abs() * 1e-16;
            let error = (s - x.sin()).abs().max((c - x.cos()).abs());
            assert!(error <= allowed, "x = {x:e}: {error:e} > {allowed:e}");
            worst = worst.max(error / allowed);
        };
        for k in -200_000..=200_000 {
            check(k as f64 * 1e-4 * std::f64::consts::PI);
        }
        for k in 0..2000 {
            let x = 3.2e6 * (k as f64 / 2000.0).powi(3);
            check(x);
            check(-x);
        }
        for x in [
            0.0,
            -0.0,
            1e-300,
            std::f64::consts::FRAC_PI_4,
            PI,
            -PI,
            1e6 * std::f64::consts::FRAC_PI_3,
        ] {
            check(x);
        }
        assert!(worst <= 1.0);
    }

    #[test]
    fn the_two_parts_of_pi_over_2() {
        // fdlibm's pio2_1 = 1.57079632673412561417e+00, pio2_1t = 6.07710050650619224932e-11.
        assert!((PIO2_HI - 1.570_796_326_734_125_6).abs() < 1e-16);
        assert_eq!(PIO2_HI.to_bits() & 0x1f_ffff, 0, "k·PIO2_HI must be exact for |k| < 2^20");
        assert!((PIO2_HI + PIO2_LO - std::f64::consts::FRAC_PI_2).abs() < 1e-16);
        assert!((PIO2_LO - 6.077_100_506_506_192e-11).abs() < 1e-26);
    }

    #[test]
    fn exact_at_the_quadrants_ends() {
        assert_eq!(sin_cos(0.0), (0.0, 1.0));
        let (s, c) = sin_cos(std::f64::consts::FRAC_PI_2);
        assert!((s - 1.0).abs() < 1e-16 && c.abs() < 1e-16);
    }
}
