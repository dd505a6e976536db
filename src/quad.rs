//! Four `f64` lanes as two [`Lanes`] in flight: each operation does its first half, then its
//! second, so a kernel written once over [`Simd`] runs two independent chains instruction by
//! instruction. The batch kernels are chains of square roots, divisions and polynomials whose
//! latency, not their count, bounds them; with two chains interleaved the processor has an
//! independent operation to issue while the other waits.

use std::ops::{Add, BitAnd, Div, Mul, Neg, Sub};

use crate::lanes::{Lanes, Mask, Simd, SimdMask};

/// Four lanes: `.0` the first two, `.1` the last two.
#[derive(Clone, Copy)]
pub struct Quad(pub Lanes, pub Lanes);

/// A comparison of two [`Quad`]s, lane by lane.
#[derive(Clone, Copy)]
pub struct QuadMask(pub Mask, pub Mask);

// The kernels load and store through `Simd`; these are for the tests.
#[cfg(test)]
impl Quad {
    #[inline(always)]
    pub fn new(a: f64, b: f64, c: f64, d: f64) -> Self {
        Quad(Lanes::new(a, b), Lanes::new(c, d))
    }

    #[inline(always)]
    pub fn to_array(self) -> [f64; 4] {
        let ([a, b], [c, d]) = (self.0.to_array(), self.1.to_array());
        [a, b, c, d]
    }
}

impl SimdMask for QuadMask {
    #[inline(always)]
    fn splat(value: bool) -> Self {
        QuadMask(Mask::splat(value), Mask::splat(value))
    }

    #[inline(always)]
    fn all(self) -> bool {
        (self.0 & self.1).all()
    }
}

impl Simd for Quad {
    type Mask = QuadMask;
    const LANES: usize = 4;
    #[inline(always)]
    fn load(x: &[f64]) -> Self {
        Quad(Lanes::load(&x[..2]), Lanes::load(&x[2..4]))
    }
    #[inline(always)]
    fn load_quaternions(q: &[f64]) -> [Self; 4] {
        let (a, b) = (Lanes::load_quaternions(&q[..8]), Lanes::load_quaternions(&q[8..16]));
        [0, 1, 2, 3].map(|c| Quad(a[c], b[c]))
    }
    #[inline(always)]
    fn store_quaternions(q: [Self; 4], out: &mut [f64]) {
        Lanes::store_quaternions(q.map(|c| c.0), &mut out[..8]);
        Lanes::store_quaternions(q.map(|c| c.1), &mut out[8..16]);
    }
    #[inline(always)]
    fn splat(x: f64) -> Self {
        Quad(Lanes::splat(x), Lanes::splat(x))
    }
    #[inline(always)]
    fn abs(self) -> Self {
        Quad(self.0.abs(), self.1.abs())
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Quad(self.0.sqrt(), self.1.sqrt())
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Quad(self.0.max(o.0), self.1.max(o.1))
    }
    #[inline(always)]
    fn round_ties_even(self) -> Self {
        Quad(self.0.round_ties_even(), self.1.round_ties_even())
    }
    #[inline(always)]
    fn le(self, o: Self) -> QuadMask {
        QuadMask(self.0.le(o.0), self.1.le(o.1))
    }
    #[inline(always)]
    fn lt(self, o: Self) -> QuadMask {
        QuadMask(self.0.lt(o.0), self.1.lt(o.1))
    }
    #[inline(always)]
    fn eq(self, o: Self) -> QuadMask {
        QuadMask(self.0.eq(o.0), self.1.eq(o.1))
    }
    #[inline(always)]
    fn select(mask: QuadMask, yes: Self, no: Self) -> Self {
        Quad(Lanes::select(mask.0, yes.0, no.0), Lanes::select(mask.1, yes.1, no.1))
    }
    #[inline(always)]
    fn bits_sub_shl52(self, o: u64) -> Self {
        Quad(self.0.bits_sub_shl52(o), self.1.bits_sub_shl52(o))
    }
}

macro_rules! both_halves {
    ($trait:ident, $method:ident) => {
        impl $trait for Quad {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                Quad(self.0.$method(o.0), self.1.$method(o.1))
            }
        }
    };
}

both_halves!(Add, add);
both_halves!(Sub, sub);
both_halves!(Mul, mul);
both_halves!(Div, div);

impl Neg for Quad {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Quad(-self.0, -self.1)
    }
}

impl BitAnd for QuadMask {
    type Output = Self;
    #[inline(always)]
    fn bitand(self, o: Self) -> Self {
        QuadMask(self.0 & o.0, self.1 & o.1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_lane_as_lanes_computes_it() {
        let (a, b) = (Quad::new(1.0, -5.0, 0.25, 9.0), Quad::new(2.0, 3.0, 0.25, -1.0));
        assert_eq!((a + b).to_array(), [3.0, -2.0, 0.5, 8.0]);
        assert_eq!((a - b).to_array(), [-1.0, -8.0, 0.0, 10.0]);
        assert_eq!((a * b).to_array(), [2.0, -15.0, 0.0625, -9.0]);
        assert_eq!((a / b).to_array(), [0.5, -5.0 / 3.0, 1.0, -9.0]);
        assert_eq!((-a).abs().sqrt().to_array(), [1.0, 5.0_f64.sqrt(), 0.5, 3.0]);
        assert_eq!(Quad::select(a.lt(b), a, b).to_array(), [1.0, -5.0, 0.25, -1.0]);
        assert_eq!(Quad::select(a.eq(b), a, b).to_array(), [2.0, 3.0, 0.25, -1.0]);
        assert_eq!(a.max(b).to_array(), [2.0, 3.0, 0.25, 9.0]);
        assert!(a.le(a).all() && !a.le(b).all() && (b.le(b) & a.le(a)).all());
        let x = Quad::new(-0.5, -700.0, 0.0, -20.25);
        let [p, q] = Lanes::new(-0.5, -700.0).exp_nonpositive().to_array();
        let [r, s] = Lanes::new(0.0, -20.25).exp_nonpositive().to_array();
        assert_eq!(x.exp_nonpositive().to_array(), [p, q, r, s]);
        assert_eq!(
            Quad::new(2.5, -3.5, 0.5, 1.5).round_ties_even().to_array(),
            [2.0, -4.0, 0.0, 2.0]
        );
    }

    #[test]
    fn quaternions_go_in_and_out_whole() {
        let q: Vec<f64> = (0..16).map(f64::from).collect();
        let [w, x, y, z] = Quad::load_quaternions(&q);
        assert_eq!(w.to_array(), [0.0, 4.0, 8.0, 12.0]);
        assert_eq!(x.to_array(), [1.0, 5.0, 9.0, 13.0]);
        assert_eq!(y.to_array(), [2.0, 6.0, 10.0, 14.0]);
        assert_eq!(z.to_array(), [3.0, 7.0, 11.0, 15.0]);
        let mut out = [f64::NAN; 16];
        Quad::store_quaternions([w, x, y, z], &mut out);
        assert_eq!(out.to_vec(), q);
        assert_eq!(Quad::load(&[1.0, 2.0, 3.0, 4.0, 5.0]).to_array(), [1.0, 2.0, 3.0, 4.0]);
    }
}
