//! Seeded randomness for the swarm: SplitMix64, so the same seed gives the same swarm on every
//! platform (Rust natively, and the npm package, which runs this same code).

use glam::{DQuat, DVec3};

use crate::quaternion::exp;
use crate::trig::sin_cos;

/// SplitMix64 (Steele, Lea and Flood 2014): a 64-bit state, one multiply-xorshift output.
pub struct Random(u64);

impl Random {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`, 53 random bits.
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Standard normal, by Box and Muller.
    pub fn gaussian(&mut self) -> f64 {
        let radius = (-2.0 * (1.0 - self.uniform()).ln()).sqrt();
        radius * sin_cos(std::f64::consts::TAU * self.uniform()).1
    }

    /// Three independent standard normals.
    pub fn gaussian3(&mut self) -> DVec3 {
        DVec3::new(self.gaussian(), self.gaussian(), self.gaussian())
    }

    /// Uniform on S³: four normals, normalised (the Gaussian is rotation invariant).
    pub fn unit_quaternion(&mut self) -> DQuat {
        loop {
            let q = DQuat::from_xyzw(
                self.gaussian(),
                self.gaussian(),
                self.gaussian(),
                self.gaussian(),
            );
            let length = q.length();
            if length > 1e-150 {
                return q / length;
            }
        }
    }

    /// A point of S³ near `center`: `center · exp(v)` with `v` normal of standard deviation
    /// `spread` in each tangent direction (radians along S³).
    pub fn near(&mut self, center: DQuat, spread: f64) -> DQuat {
        center * exp(self.gaussian3() * spread)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix64_reference_values() {
        // The first outputs for seed 0, from the reference implementation (Vigna's splitmix64.c).
        let mut random = Random::new(0);
        assert_eq!(random.next_u64(), 0xe220_a839_7b1d_cdaf);
        assert_eq!(random.next_u64(), 0x6e78_9e6a_a1b9_65f4);
        assert_eq!(random.next_u64(), 0x06c4_5d18_8009_454f);
    }

    #[test]
    fn gaussians_have_mean_0_and_variance_1() {
        let mut random = Random::new(42);
        let n = 200_000;
        let xs: Vec<f64> = (0..n).map(|_| random.gaussian()).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let variance = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / n as f64;
        // Standard errors: 1/√n ≈ 0.0022 for the mean, √(2/n) ≈ 0.0032 for the variance.
        assert!(mean.abs() < 0.01, "{mean}");
        assert!((variance - 1.0).abs() < 0.015, "{variance}");
    }

    #[test]
    fn uniform_quaternions_have_the_moments_of_the_uniform_measure() {
        // For q uniform on S³, E[q] = 0 and E[q_c²] = 1/4 for each component.
        let mut random = Random::new(7);
        let n = 100_000;
        let (mut sum, mut squares) = (DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0), [0.0; 4]);
        for _ in 0..n {
            let q = random.unit_quaternion();
            assert!((q.length() - 1.0).abs() < 1e-15);
            sum += q;
            for (s, c) in squares.iter_mut().zip([q.x, q.y, q.z, q.w]) {
                *s += c * c;
            }
        }
        assert!((sum / n as f64).length() < 0.01);
        for s in squares {
            assert!((s / n as f64 - 0.25).abs() < 0.005, "{s}");
        }
    }
}
