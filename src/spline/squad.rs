//! Shoemake's Squad, `squad(u) = slerp(slerp(q_i, q_{i+1}, u), slerp(a_i, b_{i+1}, u), 2u(1−u))`,
//! with helper points that make it C¹ in time for uneven key times as well.
//!
//! With `L₊ = log(q̄_i q_{i+1})`, `L₋ = log(q̄_i q_{i−1})` and the interval lengths `h_{i−1}`, `h_i`,
//! the curve leaves `q_i` with `q̄_i dq/du = L₊ + 2 log(q̄_i a_i)` and arrives with
//! `-L₋ - 2 log(q̄_i b_i)`. Asking both to equal the interval length times one tangent per unit
//! time, the weighted (Catmull–Rom) estimate `T_i = [h_{i−1} L₊/h_i - h_i L₋/h_{i−1}] / (h_{i−1} + h_i)`,
//! gives `a_i = q_i exp((h_i T_i − L₊)/2)` and `b_i = q_i exp(−(h_{i−1} T_i + L₋)/2)`; for even times
//! both are Shoemake's `q_i exp(−(L₊ + L₋)/4)`. At the ends the tangent is the one segment's
//! (`a_0 = q_0`, `b_{m−1} = q_{m−1}`). `log` of a repeated key is 0, not 0/0.

use glam::{DQuat, DVec3};

use super::{Curve, Keys, locate, slerp};
use crate::great_arc::GreatArc;
use crate::quaternion::{exp, log};

/// Squad through the keys.
#[derive(Debug, Clone)]
pub struct Squad {
    keys: Keys,
    /// Per interval, the arcs `q_i → q_{i+1}` and `a_i → b_{i+1}`, built once: evaluating then
    /// needs one arc (between their points) rather than three.
    arcs: Vec<(GreatArc, GreatArc)>,
}

/// The arc from `p` to `r` without choosing a sign; the point `p` if `r = -p` (never asked:
/// the keys' signs are consistent and the helpers lie near them).
fn arc(p: DQuat, r: DQuat) -> GreatArc {
    GreatArc::new(p, r, false).unwrap_or_else(|_| GreatArc::at_point(p))
}

impl Squad {
    pub fn new(keys: Keys) -> Self {
        let (q, t) = (keys.quaternions(), keys.times());
        let m = q.len();
        let mut out = q.to_vec();
        let mut into = q.to_vec();
        for i in 1..m - 1 {
            let (h0, h1) = (t[i] - t[i - 1], t[i + 1] - t[i]);
            let plus = log(q[i].conjugate() * q[i + 1]);
            let minus = log(q[i].conjugate() * q[i - 1]);
            let tangent: DVec3 = (plus * (h0 / h1) - minus * (h1 / h0)) / (h0 + h1);
            out[i] = q[i] * exp((tangent * h1 - plus) * 0.5);
            into[i] = q[i] * exp(-(tangent * h0 + minus) * 0.5);
        }
        let arcs = (0..m - 1).map(|i| (arc(q[i], q[i + 1]), arc(out[i], into[i + 1]))).collect();
        Self { keys, arcs }
    }

    pub fn keys(&self) -> &Keys {
        &self.keys
    }
}

impl Squad {
    /// The point at `u ∈ [0, 1]` of interval `i` (between keys `i` and `i + 1`).
    pub(crate) fn at_interval(&self, i: usize, u: f64) -> DQuat {
        let (outer, inner) = &self.arcs[i];
        let point = |arc: &GreatArc| crate::slerp::point_at(arc, u);
        slerp(point(outer), point(inner), 2.0 * u * (1.0 - u))
    }
}

impl Curve for Squad {
    fn at(&self, t: f64) -> DQuat {
        let (i, u) = locate(self.keys.times(), t);
        self.at_interval(i, u)
    }

    fn start_time(&self) -> f64 {
        self.keys.times()[0]
    }

    fn end_time(&self) -> f64 {
        *self.keys.times().last().unwrap_or(&0.0)
    }
}
