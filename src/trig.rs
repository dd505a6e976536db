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

/// `(sin x, cos x)` lane-wise for `|x| ≤ π/4`, branch-free polynomials in `y = x²` by Estrin's
/// scheme (see [`sinc_cos_small_squared`]).
#[inline(always)]
pub(crate) fn sin_cos_small<S: Simd>(x: S) -> (S, S) {
    let (sinc, cos) = sinc_cos_small_squared(x * x);
    (x * sinc, cos)
}

/// `(sin x / x, cos x)` lane-wise from `y = x²` for `|x| ≤ π/4`, so `exp` of a small rotation
/// needs no square root and no division. Each is the Chebyshev economisation on
/// `[0, (π/4)²]` of its Taylor series in `y` (to `y¹³`, projected onto Chebyshev polynomials
/// there and cut, in exact rational arithmetic): degree 6 for `sin x / x` (within 4e-18) and 7
/// for `cos x` (within 4e-20), where the Taylor series need degree 8 for that.
#[inline(always)]
pub(crate) fn sinc_cos_small_squared<S: Simd>(y: S) -> (S, S) {
    const SINC: [f64; 7] = [
        1.0,
        -0.166_666_666_666_666_16,
        0.008_333_333_333_320_366,
        -0.000_198_412_698_286_530_24,
        2.755_731_337_725_188_3e-6,
        -2.505_071_709_683_615_5e-8,
        1.589_474_328_386_339_8e-10,
    ];
    const COS: [f64; 8] = [
        1.0,
        -0.5,
        0.041_666_666_666_666_45,
        -0.001_388_888_888_886_110_1,
        2.480_158_728_388_399e-5,
        -2.755_731_309_846_481_6e-7,
        2.087_558_246_021_268_7e-9,
        -1.135_338_332_274_935_4e-11,
    ];
    let (sinc, cos) = (SINC.map(S::splat), COS.map(S::splat));
    let (y2, y4) = (y * y, y * y * (y * y));
    let s = [0, 1, 2].map(|k| sinc[2 * k] + sinc[2 * k + 1] * y);
    let c = [0, 1, 2, 3].map(|k| cos[2 * k] + cos[2 * k + 1] * y);
    ((s[0] + s[1] * y2) + (s[2] + sinc[6] * y2) * y4, (c[0] + c[1] * y2) + (c[2] + c[3] * y2) * y4)
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
