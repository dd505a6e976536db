//! The geodesic L1 median (Hartley, Aftab and Trumpf 2011; MATH.md, "Averaging rotations"): the
//! rotation that minimises `Σ w_j d(q, r_j)`. Weiszfeld's iteration in the tangent space,
//! `q ← q · exp(Σ c_j v_j / Σ c_j)`, `c_j = w_j / |v_j|`, with the Vardi–Zhang rule when `q` sits on
//! a datum `r_k`: it is the median if `|Σ_{j≠k} w_j v_j/|v_j|| ≤ w_k`, else the step is shortened
//! by `w_k / |…|`. A far datum pulls with its weight alone, however far it lies: robust.

use glam::{DQuat, DVec3};

use super::Data;
use super::tangent::{exp_at, log_at};

/// The most iterations (Weiszfeld converges linearly).
const MAX_ITERATIONS: usize = 1000;

/// Closer than this (radians) to a datum, `q` is on it.
const ON_DATUM: f64 = 1e-12;

/// A median and how it was reached.
pub(super) struct Median {
    pub rotation: DQuat,
    pub iterations: usize,
    pub residual: f64,
    /// Each datum's final Weiszfeld weight, `w_j / max(d_j, 1e-12)`, summing to 1.
    pub weights: Vec<f64>,
}

/// The median from `start`: iterates until a step is below 1e-14 rad.
pub(super) fn median(data: &Data, start: DQuat) -> Median {
    let (mut q, mut iterations, mut residual) = (start, 0, 0.0);
    while iterations < MAX_ITERATIONS {
        iterations += 1;
        let (mut pull, mut conductance, mut on) = (DVec3::ZERO, 0.0, 0.0);
        for (&r, &w) in data.rotations.iter().zip(&data.weights) {
            let v = log_at(q, r);
            let d = v.length();
            if d < ON_DATUM {
                on += w;
            } else {
                pull += v * (w / d);
                conductance += w / d;
            }
        }
        // The Weiszfeld point, in the tangent space at q.
        let toward = if conductance > 0.0 { pull / conductance } else { DVec3::ZERO };
        let step = if on > 0.0 {
            // Vardi–Zhang: `pull` is Σ_{j≠k} w_j v_j/|v_j|; against the datum's weight.
            let force = pull.length();
            if force <= on { DVec3::ZERO } else { toward * (1.0 - on / force) }
        } else {
            toward
        };
        residual = step.length();
        q = exp_at(q, step);
        if residual <= 1e-14 {
            break;
        }
    }
    let conductances: Vec<f64> = data
        .rotations
        .iter()
        .zip(&data.weights)
        .map(|(&r, &w)| w / log_at(q, r).length().max(ON_DATUM))
        .collect();
    let total: f64 = conductances.iter().sum();
    Median {
        rotation: q,
        iterations,
        residual,
        weights: conductances.iter().map(|c| c / total).collect(),
    }
}
