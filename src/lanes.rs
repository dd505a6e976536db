//! Two `f64` lanes, so the batch kernels handle two pairs per step: wasm SIMD (`f64x2`) on
//! wasm32 built with `simd128`, SSE2 (`__m128d`, part of every x86-64) natively there, and a
//! plain `[f64; 2]` elsewhere. One kernel source serves all three, and, through [`Simd`],
//! [`crate::quad::Quad`]'s four lanes too.

use std::ops::{Add, BitAnd, Div, Mul, Neg, Sub};

/// What a branch-free kernel computes with: [`Lanes`], or [`crate::quad::Quad`] (two `Lanes`
/// in flight). Each operation acts lane by lane.
pub trait Simd:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// A comparison's result, lane by lane.
    type Mask: SimdMask;
    /// How many lanes: pairs a step of a batch kernel.
    const LANES: usize;
    /// The first `LANES` numbers of `x`.
    fn load(x: &[f64]) -> Self;
    /// The first `LANES` quaternions of `q` (`[w, x, y, z]` each, one after another) as one
    /// vector a component: a transpose, done in registers.
    fn load_quaternions(q: &[f64]) -> [Self; 4];
    /// [`Simd::load_quaternions`] backwards: writes `LANES` quaternions to the front of `out`.
    fn store_quaternions(q: [Self; 4], out: &mut [f64]);
    fn splat(x: f64) -> Self;
    fn abs(self) -> Self;
    fn sqrt(self) -> Self;
    /// As wasm's `pmax`: `o` where `self < o`, else `self`.
    fn max(self, o: Self) -> Self;
    /// For `|x| < 2^51`.
    fn round_ties_even(self) -> Self;
    fn le(self, o: Self) -> Self::Mask;
    fn lt(self, o: Self) -> Self::Mask;
    fn eq(self, o: Self) -> Self::Mask;
    fn select(mask: Self::Mask, yes: Self, no: Self) -> Self;
    /// `f64::from_bits((bits - o) << 52)` lane-wise.
    fn bits_sub_shl52(self, o: u64) -> Self;

    /// `e^x` lane-wise for `x ≤ 0`, to about 1 ulp (`x < -708` is taken as `-708`, whose `e^x`
    /// is already below every use here). Cody–Waite reduction `x = k ln 2 + r`, `|r| ≤ ln2/2`,
    /// a degree-13 Taylor polynomial (remainder < 4e-18), and `2^k` built from bits: no branch,
    /// no call.
    #[inline(always)]
    fn exp_nonpositive(self) -> Self {
        const LN2_HI: f64 = 6.931_471_803_691_238e-1; // fdlibm: ln 2 with the low 32 bits clear
        const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;
        const INVERSE_FACTORIALS: [f64; 14] = [
            1.0,
            1.0,
            0.5,
            1.0 / 6.0,
            1.0 / 24.0,
            1.0 / 120.0,
            1.0 / 720.0,
            1.0 / 5040.0,
            1.0 / 40320.0,
            1.0 / 362_880.0,
            1.0 / 3_628_800.0,
            1.0 / 39_916_800.0,
            1.0 / 479_001_600.0,
            1.0 / 6_227_020_800.0,
        ];
        let x = self.max(Self::splat(-708.0));
        let k = (x * Self::splat(std::f64::consts::LOG2_E)).round_ties_even();
        let r = (x - k * Self::splat(LN2_HI)) - k * Self::splat(LN2_LO);
        // Estrin's scheme: four levels of independent multiply-adds instead of a 13-deep Horner
        // chain, whose latency would bound the whole kernel (measured 25% faster in Node).
        let c = INVERSE_FACTORIALS.map(Self::splat);
        let (r2, pairs) = (r * r, [0, 1, 2, 3, 4, 5, 6].map(|k| c[2 * k] + c[2 * k + 1] * r));
        let r4 = r2 * r2;
        let quads = [
            pairs[0] + pairs[1] * r2,
            pairs[2] + pairs[3] * r2,
            pairs[4] + pairs[5] * r2,
            pairs[6],
        ];
        let p = (quads[0] + quads[1] * r4) + (quads[2] + quads[3] * r4) * (r4 * r4);
        // 2^k: k + 1023 + 2^52 holds k + 1023 in its low mantissa bits; shift it into the exponent.
        let biased = k + Self::splat(1023.0 + 4_503_599_627_370_496.0);
        p * biased.bits_sub_shl52(0x4330_0000_0000_0000)
    }
}

/// A [`Simd::Mask`]: lane-wise booleans.
pub trait SimdMask: Copy + BitAnd<Output = Self> {
    fn splat(value: bool) -> Self;
    /// Whether every lane is true.
    fn all(self) -> bool;
}

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
mod imp {
    use core::arch::wasm32::*;

    #[derive(Clone, Copy)]
    pub struct Lanes(pub v128);
    #[derive(Clone, Copy)]
    pub struct Mask(pub v128);

    impl Lanes {
        #[inline(always)]
        pub fn new(a: f64, b: f64) -> Self {
            Self(f64x2(a, b))
        }
        #[inline(always)]
        pub fn to_array(self) -> [f64; 2] {
            [f64x2_extract_lane::<0>(self.0), f64x2_extract_lane::<1>(self.0)]
        }
        #[inline(always)]
        pub fn add(self, o: Self) -> Self {
            Self(f64x2_add(self.0, o.0))
        }
        #[inline(always)]
        pub fn sub(self, o: Self) -> Self {
            Self(f64x2_sub(self.0, o.0))
        }
        #[inline(always)]
        pub fn mul(self, o: Self) -> Self {
            Self(f64x2_mul(self.0, o.0))
        }
        #[inline(always)]
        pub fn div(self, o: Self) -> Self {
            Self(f64x2_div(self.0, o.0))
        }
        #[inline(always)]
        pub fn neg(self) -> Self {
            Self(f64x2_neg(self.0))
        }
        #[inline(always)]
        pub fn abs(self) -> Self {
            Self(f64x2_abs(self.0))
        }
        #[inline(always)]
        pub fn sqrt(self) -> Self {
            Self(f64x2_sqrt(self.0))
        }
        #[inline(always)]
        pub fn max(self, o: Self) -> Self {
            Self(f64x2_pmax(self.0, o.0))
        }
        #[inline(always)]
        pub fn round_ties_even(self) -> Self {
            Self(f64x2_nearest(self.0))
        }
        #[inline(always)]
        pub fn le(self, o: Self) -> Mask {
            Mask(f64x2_le(self.0, o.0))
        }
        #[inline(always)]
        pub fn lt(self, o: Self) -> Mask {
            Mask(f64x2_lt(self.0, o.0))
        }
        #[inline(always)]
        pub fn eq(self, o: Self) -> Mask {
            Mask(f64x2_eq(self.0, o.0))
        }
        #[inline(always)]
        pub fn select(mask: Mask, yes: Self, no: Self) -> Self {
            Self(v128_bitselect(yes.0, no.0, mask.0))
        }
        /// `(self[0], o[0])` and `(self[1], o[1])`: a 2×2 transpose.
        #[inline(always)]
        pub fn interleave(self, o: Self) -> (Self, Self) {
            (Self(i64x2_shuffle::<0, 2>(self.0, o.0)), Self(i64x2_shuffle::<1, 3>(self.0, o.0)))
        }
        /// Lane-wise `bits(self) - bits(o)`, shifted left by 52, as f64 bits.
        #[inline(always)]
        pub fn bits_sub_shl52(self, o: u64) -> Self {
            Self(i64x2_shl(i64x2_sub(self.0, u64x2_splat(o)), 52))
        }
    }

    impl Mask {
        #[inline(always)]
        pub fn and(self, o: Self) -> Self {
            Self(v128_and(self.0, o.0))
        }
        #[inline(always)]
        pub fn all(self) -> bool {
            i64x2_all_true(self.0)
        }
        #[inline(always)]
        pub fn splat(value: bool) -> Self {
            Self(i64x2_splat(if value { -1 } else { 0 }))
        }
    }
}

#[cfg(target_arch = "x86_64")]
mod imp {
    use core::arch::x86_64::*;

    #[derive(Clone, Copy)]
    pub struct Lanes(pub __m128d);
    #[derive(Clone, Copy)]
    pub struct Mask(pub __m128d);

    impl Lanes {
        #[inline(always)]
        pub fn new(a: f64, b: f64) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_set_pd(b, a)) }
        }
        #[inline(always)]
        pub fn to_array(self) -> [f64; 2] {
            let mut out = [0.0; 2];
            // SAFETY: `out` holds two f64; storeu has no alignment requirement.
            unsafe { _mm_storeu_pd(out.as_mut_ptr(), self.0) };
            out
        }
        #[inline(always)]
        pub fn add(self, o: Self) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_add_pd(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn sub(self, o: Self) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_sub_pd(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn mul(self, o: Self) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_mul_pd(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn div(self, o: Self) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_div_pd(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn neg(self) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_xor_pd(self.0, _mm_set1_pd(-0.0))) }
        }
        #[inline(always)]
        pub fn abs(self) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_andnot_pd(_mm_set1_pd(-0.0), self.0)) }
        }
        #[inline(always)]
        pub fn sqrt(self) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_sqrt_pd(self.0)) }
        }
        #[inline(always)]
        pub fn max(self, o: Self) -> Self {
            // As wasm's pmax: `o` when `self < o`, else `self`.
            Self::select(self.lt(o), o, self)
        }
        /// For `|x| < 2^51`, which is all the kernels need: adding and removing 1.5·2^52 rounds
        /// to an integer, ties to even (SSE4.1's round is not part of the x86-64 baseline).
        #[inline(always)]
        pub fn round_ties_even(self) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            let shift = unsafe { _mm_set1_pd(6_755_399_441_055_744.0) };
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_sub_pd(_mm_add_pd(self.0, shift), shift)) }
        }
        #[inline(always)]
        pub fn le(self, o: Self) -> Mask {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Mask(_mm_cmple_pd(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn lt(self, o: Self) -> Mask {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Mask(_mm_cmplt_pd(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn eq(self, o: Self) -> Mask {
            // SAFETY: as above.
            unsafe { Mask(_mm_cmpeq_pd(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn select(mask: Mask, yes: Self, no: Self) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_or_pd(_mm_and_pd(mask.0, yes.0), _mm_andnot_pd(mask.0, no.0))) }
        }
        /// `(self[0], o[0])` and `(self[1], o[1])`: a 2×2 transpose.
        #[inline(always)]
        pub fn interleave(self, o: Self) -> (Self, Self) {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { (Self(_mm_unpacklo_pd(self.0, o.0)), Self(_mm_unpackhi_pd(self.0, o.0))) }
        }
        #[inline(always)]
        pub fn bits_sub_shl52(self, o: u64) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            let bits = unsafe { _mm_castpd_si128(self.0) };
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe {
                Self(_mm_castsi128_pd(_mm_slli_epi64::<52>(_mm_sub_epi64(
                    bits,
                    _mm_set1_epi64x(o as i64),
                ))))
            }
        }
    }

    impl Mask {
        #[inline(always)]
        pub fn and(self, o: Self) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_and_pd(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn all(self) -> bool {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { _mm_movemask_pd(self.0) == 0b11 }
        }
        #[inline(always)]
        pub fn splat(value: bool) -> Self {
            // SAFETY: SSE2 is part of every x86-64 CPU (the target's baseline).
            unsafe { Self(_mm_castsi128_pd(_mm_set1_epi64x(if value { -1 } else { 0 }))) }
        }
    }
}

/// The plain lanes: the implementation where neither of the above is, and under test
/// everywhere, so that the native tests check it lane by lane too (it is what wasm without
/// `simd128` and every other target run).
#[cfg(any(
    test,
    not(any(all(target_arch = "wasm32", target_feature = "simd128"), target_arch = "x86_64"))
))]
pub(crate) mod portable {
    #[derive(Clone, Copy)]
    pub struct Lanes(pub [f64; 2]);
    #[derive(Clone, Copy)]
    pub struct Mask(pub [bool; 2]);

    impl Lanes {
        #[inline(always)]
        pub fn new(a: f64, b: f64) -> Self {
            Self([a, b])
        }
        #[inline(always)]
        pub fn to_array(self) -> [f64; 2] {
            self.0
        }
        #[inline(always)]
        fn map2(self, o: Self, f: impl Fn(f64, f64) -> f64) -> Self {
            Self([f(self.0[0], o.0[0]), f(self.0[1], o.0[1])])
        }
        #[inline(always)]
        pub fn add(self, o: Self) -> Self {
            self.map2(o, |a, b| a + b)
        }
        #[inline(always)]
        pub fn sub(self, o: Self) -> Self {
            self.map2(o, |a, b| a - b)
        }
        #[inline(always)]
        pub fn mul(self, o: Self) -> Self {
            self.map2(o, |a, b| a * b)
        }
        #[inline(always)]
        pub fn div(self, o: Self) -> Self {
            self.map2(o, |a, b| a / b)
        }
        #[inline(always)]
        pub fn neg(self) -> Self {
            Self(self.0.map(|a| -a))
        }
        #[inline(always)]
        pub fn abs(self) -> Self {
            Self(self.0.map(f64::abs))
        }
        #[inline(always)]
        pub fn sqrt(self) -> Self {
            Self(self.0.map(f64::sqrt))
        }
        #[inline(always)]
        pub fn max(self, o: Self) -> Self {
            // As wasm's pmax: `o` when `self < o`, else `self`.
            self.map2(o, |a, b| if a < b { b } else { a })
        }
        /// For `|x| < 2^51`, which is all the kernels need: adding and removing 1.5·2^52 rounds
        /// to an integer, ties to even, without a call (`f64::round_ties_even` is one on
        /// x86-64 without SSE4.1).
        #[inline(always)]
        pub fn round_ties_even(self) -> Self {
            const SHIFT: f64 = 6_755_399_441_055_744.0;
            Self(self.0.map(|x| (x + SHIFT) - SHIFT))
        }
        #[inline(always)]
        pub fn le(self, o: Self) -> Mask {
            Mask([self.0[0] <= o.0[0], self.0[1] <= o.0[1]])
        }
        #[inline(always)]
        pub fn lt(self, o: Self) -> Mask {
            Mask([self.0[0] < o.0[0], self.0[1] < o.0[1]])
        }
        #[inline(always)]
        pub fn eq(self, o: Self) -> Mask {
            Mask([self.0[0] == o.0[0], self.0[1] == o.0[1]])
        }
        #[inline(always)]
        pub fn select(mask: Mask, yes: Self, no: Self) -> Self {
            Self([0, 1].map(|i| if mask.0[i] { yes.0[i] } else { no.0[i] }))
        }
        /// `(self[0], o[0])` and `(self[1], o[1])`: a 2×2 transpose.
        #[inline(always)]
        pub fn interleave(self, o: Self) -> (Self, Self) {
            (Self([self.0[0], o.0[0]]), Self([self.0[1], o.0[1]]))
        }
        #[inline(always)]
        pub fn bits_sub_shl52(self, o: u64) -> Self {
            Self(self.0.map(|a| f64::from_bits(a.to_bits().wrapping_sub(o) << 52)))
        }
    }

    impl Mask {
        #[inline(always)]
        pub fn and(self, o: Self) -> Self {
            Self([self.0[0] & o.0[0], self.0[1] & o.0[1]])
        }
        #[inline(always)]
        pub fn all(self) -> bool {
            self.0[0] & self.0[1]
        }
        #[inline(always)]
        pub fn splat(value: bool) -> Self {
            Self([value; 2])
        }
    }
}

#[cfg(not(any(
    all(target_arch = "wasm32", target_feature = "simd128"),
    target_arch = "x86_64"
)))]
use portable as imp;

pub use imp::{Lanes, Mask};

/// The traits over an implementation's inherent operations: for the lanes in use, and under
/// test for the plain lanes too where they are not the ones in use, so that the native tests run
/// the batch kernels on them as wasm without `simd128` does.
macro_rules! simd_traits {
    ($imp:ident) => {
        impl SimdMask for $imp::Mask {
            #[inline(always)]
            fn splat(value: bool) -> Self {
                $imp::Mask::splat(value)
            }
            #[inline(always)]
            fn all(self) -> bool {
                $imp::Mask::all(self)
            }
        }

        impl Simd for $imp::Lanes {
            type Mask = $imp::Mask;
            const LANES: usize = 2;
            #[inline(always)]
            fn load(x: &[f64]) -> Self {
                Self::new(x[0], x[1])
            }
            #[inline(always)]
            fn load_quaternions(q: &[f64]) -> [Self; 4] {
                // Each half of a quaternion is one load; two interleaves put the pairs side by side.
                let (wx0, yz0) = (Self::new(q[0], q[1]), Self::new(q[2], q[3]));
                let (wx1, yz1) = (Self::new(q[4], q[5]), Self::new(q[6], q[7]));
                let ((w, x), (y, z)) = (wx0.interleave(wx1), yz0.interleave(yz1));
                [w, x, y, z]
            }
            #[inline(always)]
            fn store_quaternions([w, x, y, z]: [Self; 4], out: &mut [f64]) {
                let ((wx0, wx1), (yz0, yz1)) = (w.interleave(x), y.interleave(z));
                for (k, half) in [wx0, yz0, wx1, yz1].into_iter().enumerate() {
                    out[2 * k..2 * k + 2].copy_from_slice(&half.to_array());
                }
            }
            #[inline(always)]
            fn splat(x: f64) -> Self {
                Self::new(x, x)
            }
            #[inline(always)]
            fn abs(self) -> Self {
                $imp::Lanes::abs(self)
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                $imp::Lanes::sqrt(self)
            }
            #[inline(always)]
            fn max(self, o: Self) -> Self {
                $imp::Lanes::max(self, o)
            }
            #[inline(always)]
            fn round_ties_even(self) -> Self {
                $imp::Lanes::round_ties_even(self)
            }
            #[inline(always)]
            fn le(self, o: Self) -> $imp::Mask {
                $imp::Lanes::le(self, o)
            }
            #[inline(always)]
            fn lt(self, o: Self) -> $imp::Mask {
                $imp::Lanes::lt(self, o)
            }
            #[inline(always)]
            fn eq(self, o: Self) -> $imp::Mask {
                $imp::Lanes::eq(self, o)
            }
            #[inline(always)]
            fn select(mask: $imp::Mask, yes: Self, no: Self) -> Self {
                $imp::Lanes::select(mask, yes, no)
            }
            #[inline(always)]
            fn bits_sub_shl52(self, o: u64) -> Self {
                $imp::Lanes::bits_sub_shl52(self, o)
            }
        }

        impl Add for $imp::Lanes {
            type Output = Self;
            #[inline(always)]
            fn add(self, o: Self) -> Self {
                $imp::Lanes::add(self, o)
            }
        }

        impl Sub for $imp::Lanes {
            type Output = Self;
            #[inline(always)]
            fn sub(self, o: Self) -> Self {
                $imp::Lanes::sub(self, o)
            }
        }

        impl Mul for $imp::Lanes {
            type Output = Self;
            #[inline(always)]
            fn mul(self, o: Self) -> Self {
                $imp::Lanes::mul(self, o)
            }
        }

        impl Div for $imp::Lanes {
            type Output = Self;
            #[inline(always)]
            fn div(self, o: Self) -> Self {
                $imp::Lanes::div(self, o)
            }
        }

        impl Neg for $imp::Lanes {
            type Output = Self;
            #[inline(always)]
            fn neg(self) -> Self {
                $imp::Lanes::neg(self)
            }
        }

        impl BitAnd for $imp::Mask {
            type Output = Self;
            #[inline(always)]
            fn bitand(self, o: Self) -> Self {
                self.and(o)
            }
        }
    };
}

simd_traits!(imp);

impl Lanes {
    #[inline(always)]
    pub fn splat(x: f64) -> Self {
        Self::new(x, x)
    }
}
#[cfg(all(
    test,
    any(all(target_arch = "wasm32", target_feature = "simd128"), target_arch = "x86_64")
))]
simd_traits!(portable);

#[cfg(test)]
mod tests {
    use super::*;

    /// Every operation of an implementation's lanes against the same operation on each `f64`
    /// lane, bit for bit (signed zeros, subnormals, huge values and NaN among the inputs).
    macro_rules! each_operation_is_the_scalar_one {
        ($name:ident, $imp:path) => {
            #[test]
            fn $name() {
                use $imp as lanes;
                let values = [
                    0.0,
                    -0.0,
                    1.0,
                    -2.5,
                    3.75,
                    2.5,
                    -3.5,
                    0.1,
                    5e-324,
                    -1e300,
                    7.0,
                    1e300,
                    f64::NAN,
                ];
                let bits = |x: [f64; 2]| x.map(f64::to_bits);
                for (k, &a0) in values.iter().enumerate() {
                    let (a1, b0, b1) =
                        (values[(k + 3) % 13], values[(k + 5) % 13], values[(k + 8) % 13]);
                    let (a, b) = (lanes::Lanes::new(a0, a1), lanes::Lanes::new(b0, b1));
                    assert_eq!(bits(a.to_array()), bits([a0, a1]));
                    let each = |f: fn(f64, f64) -> f64| bits([f(a0, b0), f(a1, b1)]);
                    let case = format!("{a0:e}, {a1:e} with {b0:e}, {b1:e}");
                    assert_eq!(bits(a.add(b).to_array()), each(|x, y| x + y), "{case}");
                    assert_eq!(bits(a.sub(b).to_array()), each(|x, y| x - y), "{case}");
                    assert_eq!(bits(a.mul(b).to_array()), each(|x, y| x * y), "{case}");
                    assert_eq!(bits(a.div(b).to_array()), each(|x, y| x / y), "{case}");
                    assert_eq!(bits(a.neg().to_array()), each(|x, _| -x), "{case}");
                    assert_eq!(bits(a.abs().to_array()), each(|x, _| x.abs()), "{case}");
                    assert_eq!(bits(a.sqrt().to_array()), each(|x, _| x.sqrt()), "{case}");
                    assert_eq!(bits(a.max(b).to_array()), each(|x, y| if x < y { y } else { x }));
                    let small = lanes::Lanes::new(a0 % 1e15, b0 % 1e15).round_ties_even();
                    let rounded = [(a0 % 1e15).round_ties_even(), (b0 % 1e15).round_ties_even()];
                    // (The sign of a zero is not kept: `(x + 1.5·2^52) − 1.5·2^52` is +0.)
                    let same = |x: f64, y: f64| x == y || (x.is_nan() && y.is_nan());
                    let [p, q] = small.to_array();
                    assert!(same(p, rounded[0]) && same(q, rounded[1]), "{case}");
                    let (one, zero) = (lanes::Lanes::new(1.0, 1.0), lanes::Lanes::new(0.0, 0.0));
                    let picked = |m: lanes::Mask| lanes::Lanes::select(m, one, zero).to_array();
                    let truth = |f: fn(f64, f64) -> bool| [f(a0, b0), f(a1, b1)].map(f64::from);
                    assert_eq!(picked(a.le(b)), truth(|x, y| x <= y), "{case}");
                    assert_eq!(picked(a.lt(b)), truth(|x, y| x < y), "{case}");
                    assert_eq!(picked(a.eq(b)), truth(|x, y| x == y), "{case}");
                    let (le, lt) = (a.le(b), a.lt(b));
                    assert_eq!(picked(le.and(lt)), truth(|x, y| x < y), "{case}");
                    assert_eq!(le.all(), a0 <= b0 && a1 <= b1, "{case}");
                    let (low, high) = a.interleave(b);
                    assert_eq!(
                        (bits(low.to_array()), bits(high.to_array())),
                        (bits([a0, b0]), bits([a1, b1]))
                    );
                }
                // Equal lanes: `le` but not `lt` (NaN neither), so `and` of the two is `lt`.
                for &x in &values {
                    let a = lanes::Lanes::new(x, x);
                    let (one, zero) = (lanes::Lanes::new(1.0, 1.0), lanes::Lanes::new(0.0, 0.0));
                    let picked = |m: lanes::Mask| lanes::Lanes::select(m, one, zero).to_array();
                    assert_eq!(picked(a.lt(a)), [0.0; 2], "{x}");
                    assert_eq!(picked(a.le(a)), [f64::from(!x.is_nan()); 2], "{x}");
                    assert_eq!(picked(a.le(a).and(a.lt(a))), [0.0; 2], "{x}");
                }
                // pmax keeps `self` unless `self < o`: of equal zeros, the first.
                let zeros = lanes::Lanes::new(0.0, -0.0).max(lanes::Lanes::new(-0.0, 0.0));
                assert_eq!(bits(zeros.to_array()), bits([0.0, -0.0]));
                for (x, y) in [(true, true), (false, false)] {
                    let m = lanes::Mask::splat(x);
                    assert_eq!(m.all(), x);
                    assert_eq!(
                        lanes::Lanes::select(
                            m,
                            lanes::Lanes::new(1.0, 2.0),
                            lanes::Lanes::new(3.0, 4.0)
                        )
                        .to_array(),
                        if y { [1.0, 2.0] } else { [3.0, 4.0] }
                    );
                }
                // 2^k from bits: (k + 1023 + 2^52) less 0x4330… shifted into the exponent.
                for k in [-1022.0, -3.0, 0.0, 5.0, 1023.0] {
                    let biased = lanes::Lanes::new(
                        k + 1023.0 + 4_503_599_627_370_496.0,
                        1023.0 + 4_503_599_627_370_496.0,
                    );
                    let power = biased.bits_sub_shl52(0x4330_0000_0000_0000).to_array();
                    assert_eq!(power, [2f64.powf(k), 1.0], "2^{k}");
                }
            }
        };
    }

    each_operation_is_the_scalar_one!(the_lanes_are_each_lanes_f64, super::imp);
    each_operation_is_the_scalar_one!(the_portable_lanes_are_each_lanes_f64, super::portable);

    #[test]
    fn exp_is_within_an_ulp_or_two() {
        let mut worst = 0.0_f64;
        for k in 0..100_000 {
            let x = (-(k as f64) * 708.0 / 100_000.0 - (k % 7) as f64 * 1e-9).max(-708.0);
            let [a, b] = Lanes::new(x, x * 0.5).exp_nonpositive().to_array();
            worst = worst
                .max((a - x.exp()).abs() / x.exp())
                .max((b - (0.5 * x).exp()).abs() / (0.5 * x).exp());
        }
        assert!(worst < 4.5e-16, "worst relative error {worst:e}");
        assert_eq!(Lanes::splat(0.0).exp_nonpositive().to_array(), [1.0, 1.0]);
        assert!(Lanes::splat(-1000.0).exp_nonpositive().to_array()[0] < 1e-307);
    }

    #[test]
    fn select_and_masks() {
        let (a, b) = (Lanes::new(1.0, 5.0), Lanes::new(2.0, 3.0));
        assert_eq!(Lanes::select(a.lt(b), a, b).to_array(), [1.0, 3.0]);
        assert_eq!(Lanes::select(a.eq(Lanes::new(1.0, 4.0)), a, b).to_array(), [1.0, 3.0]);
        assert!(!a.le(b).all() && Mask::splat(true).all() && (b.le(b) & a.le(a)).all());
        assert_eq!(a.max(b).to_array(), [2.0, 5.0]);
        assert_eq!((-a).abs().to_array(), [1.0, 5.0]);
    }

    #[test]
    fn quaternions_go_in_and_out_whole() {
        let q = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0];
        let [w, x, y, z] = Lanes::load_quaternions(&q);
        assert_eq!(
            [w, x, y, z].map(Lanes::to_array),
            [[1.0, 5.0], [2.0, 6.0], [3.0, 7.0], [4.0, 8.0]]
        );
        let mut out = [f64::NAN; 9];
        Lanes::store_quaternions([w, x, y, z], &mut out);
        assert_eq!(out[..8], q);
        assert!(out[8].is_nan());
        let (low, high) = Lanes::new(1.0, 2.0).interleave(Lanes::new(3.0, 4.0));
        assert_eq!((low.to_array(), high.to_array()), ([1.0, 3.0], [2.0, 4.0]));
    }
}
