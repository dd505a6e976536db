//! Shared inputs of the native benchmarks: a fixed set of random unit quaternion pairs.

use kli::{DQuat, from_wxyz};

/// `n` pairs of unit quaternions and a parameter in `[0, 1]` each, the same on every run.
pub fn random_pairs(n: usize) -> Vec<(DQuat, DQuat, f64)> {
    let mut seed = 0x2545_F491_4F6C_DD1D_u64;
    let mut uniform = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed as f64 / u64::MAX as f64
    };
    (0..n)
        .map(|_| {
            let mut q = || from_wxyz([0.0; 4].map(|_: f64| uniform() * 2.0 - 1.0)).normalize();
            (q(), q(), uniform())
        })
        .collect()
}
