//! Prints how far each integrator strays from the closed form (MATH.md) and from |q| = 1:
//! on the paper's example, and at worst over 3000 random pairs taken both ways round.
//! `cargo run --release --example accuracy`
use kli::{DQuat, Integrator, KliOptions, from_wxyz, kli};

/// max |q(tₙ) - exact(tₙ)| and max ||q(tₙ)| - 1| along the path, or None if Algorithm 1 refused.
fn deviation(p: DQuat, r: DQuat, options: &KliOptions) -> Option<(f64, f64, f64)> {
    let path = kli(p, r, options).ok()?;
    let (mut error, mut drift) = (0.0_f64, 0.0_f64);
    for (&t, &q) in path.times().iter().zip(path.quaternions()) {
        error = error.max((q - path.exact_at(t).ok()?).length());
        drift = drift.max((q.length() - 1.0).abs());
    }
    Some((path.final_time(), error, drift))
}

fn main() {
    let (p, r) = (from_wxyz([0.0, 0.0, 0.0, 1.0]), from_wxyz([0.5; 4]));
    println!("paper's example, ε = 1e-5, δ = 0.01:");
    for integrator in Integrator::ALL {
        let (t, error, drift) =
            deviation(p, r, &KliOptions { integrator, ..Default::default() }).unwrap();
        println!(
            "  {integrator:9} T = {t:<6} max|q - exact| = {error:.1e}  max||q| - 1| = {drift:.1e}"
        );
    }

    // xorshift: a fixed, dependency-free sequence of pairs.
    let mut seed = 0x2545_F491_4F6C_DD1D_u64;
    let mut uniform = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed as f64 / u64::MAX as f64) * 2.0 - 1.0
    };
    let pairs: Vec<(DQuat, DQuat)> = (0..3000)
        .map(|_| {
            let mut q = || from_wxyz([uniform(), uniform(), uniform(), uniform()]).normalize();
            (q(), q())
        })
        .collect();
    println!("worst over 3000 random pairs (δ = 0.01):");
    for integrator in Integrator::ALL {
        for shortest_path in [true, false] {
            let options = KliOptions { integrator, shortest_path, ..Default::default() };
            let (mut error, mut drift, mut refused) = (0.0_f64, 0.0_f64, 0);
            for &(p, r) in &pairs {
                match deviation(p, r, &options) {
                    Some((_, e, d)) => (error, drift) = (error.max(e), drift.max(d)),
                    None => refused += 1,
                }
            }
            let way = if shortest_path { "short way" } else { "long way " };
            println!(
                "  {integrator:9} {way} max|q - exact| = {error:.1e}  max||q| - 1| = {drift:.1e}  refused {refused}"
            );
        }
    }
}
