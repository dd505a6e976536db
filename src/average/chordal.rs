//! The chordal L2 mean (MATH.md, "Averaging rotations"): the top eigenvector of the scatter
//! matrix `M = Σ w_j r_j r_jᵀ`, where the sign-blind Kuramoto–Lohe flow `q' = M q − (qᵀM q) q` of
//! one follower coupled to every measurement settles (Oja's flow: gradient ascent of `qᵀMq` on
//! S³). SciPy's `Rotation.mean` and Markley et al. (2007) compute the same eigenvector.

use glam::DQuat;

use super::eigen::{Symmetric4, eigen};
use crate::error::{ErrorKind, KliError};
use crate::lanes::Lanes;
use crate::quaternion::{from_wxyz, to_wxyz};

/// How close the two largest eigenvalues may be, relative to the largest, before the mean is
/// not unique: rounding, with room for the sum of 10⁶ products.
const TIE: f64 = 1e-12;

/// `M = Σ w_j r_j r_jᵀ` over `[w, x, y, z]` components, in one pass over the data; `weights`
/// `None` is all 1 (the swarm's `λ_max`).
pub fn scatter(rotations: &[DQuat], weights: Option<&[f64]>) -> Symmetric4 {
    let mut sum = Scatter::default();
    for (j, &r) in rotations.iter().enumerate() {
        sum.add(weights.map_or(1.0, |w| w[j]), r);
    }
    sum.matrix()
}

/// The running sum `Σ w_j r_j r_jᵀ`: its ten distinct entries, as two-lane pairs so that each
/// datum is five multiply-adds of two lanes.
#[derive(Clone, Copy)]
pub struct Scatter {
    // (aa, bb) (ab, bc) (ac, bd) (ad, cc) (cd, dd), for r = [a, b, c, d] = [w, x, y, z].
    sums: [Lanes; 5],
}

impl Default for Scatter {
    fn default() -> Scatter {
        Scatter { sums: [Lanes::splat(0.0); 5] }
    }
}

impl Scatter {
    /// Adds `w r rᵀ`.
    #[inline(always)]
    pub fn add(&mut self, w: f64, r: DQuat) {
        let [a, b, c, d] = to_wxyz(r);
        let left = [
            Lanes::new(a, b),
            Lanes::new(a, b),
            Lanes::new(a, b),
            Lanes::new(a, c),
            Lanes::new(c, d),
        ];
        let right = [
            Lanes::new(a, b),
            Lanes::new(b, c),
            Lanes::new(c, d),
            Lanes::new(d, c),
            Lanes::new(d, d),
        ];
        let w = Lanes::splat(w);
        for ((s, l), r) in self.sums.iter_mut().zip(left).zip(right) {
            *s = *s + w * l * r;
        }
    }

    /// The sum as a symmetric 4×4 matrix.
    pub fn matrix(&self) -> Symmetric4 {
        let [[aa, bb], [ab, bc], [ac, bd], [ad, cc], [cd, dd]] = self.sums.map(Lanes::to_array);
        [[aa, ab, ac, ad], [ab, bb, bc, bd], [ac, bc, cc, cd], [ad, bd, cd, dd]]
    }
}

/// The chordal mean for the scatter matrix `m`, with the scalar part ≥ 0, and the relative
/// eigen-residual `|M q − λ q| / λ`; an Error ([`ErrorKind::NotUnique`]) when the top eigenvalue
/// is repeated.
pub(super) fn top(m: &Symmetric4) -> Result<(DQuat, f64), KliError> {
    let (values, vectors) = eigen(*m);
    if values[0] - values[1] <= TIE * values[0] {
        let kind = ErrorKind::NotUnique { top: values[0], second: values[1] };
        return Err(KliError::new("quaternions", kind));
    }
    let q = canonical(from_wxyz(vectors[0]));
    let v = to_wxyz(q);
    let residual = (0..4)
        .map(|i| (0..4).map(|j| m[i][j] * v[j]).sum::<f64>() - values[0] * v[i])
        .map(|e| e * e)
        .sum::<f64>()
        .sqrt()
        / values[0];
    Ok((q, residual))
}

/// `q` or `−q` (one rotation), the one whose first non-zero component (`w, x, y, z`) is positive.
fn canonical(q: DQuat) -> DQuat {
    let first = to_wxyz(q).into_iter().find(|c| *c != 0.0).unwrap_or(1.0);
    if first < 0.0 { -q } else { q }
}

/// The follower's path under the sign-blind flow `q' = M q − (qᵀM q) q` from `start`: RK4 steps
/// of `dt`, each normalised back onto S³. At an eigenvector the field is 0 exactly, so the path
/// settles on the top eigenvector to rounding (from almost every start: not from one orthogonal
/// to it). Scale `M` by the total weight for `dt` of order 1 to be stable.
pub fn chordal_flow(m: Symmetric4, start: DQuat, dt: f64) -> impl Iterator<Item = DQuat> {
    let field = move |q: [f64; 4]| {
        let mq: [f64; 4] = [0, 1, 2, 3].map(|i| (0..4).map(|j| m[i][j] * q[j]).sum());
        let qmq: f64 = (0..4).map(|i| q[i] * mq[i]).sum();
        [0, 1, 2, 3].map(|i| mq[i] - qmq * q[i])
    };
    let add = |q: [f64; 4], k: [f64; 4], h: f64| [0, 1, 2, 3].map(|i| q[i] + h * k[i]);
    std::iter::successors(Some(start.normalize()), move |&q| {
        let q = to_wxyz(q);
        let k1 = field(q);
        let k2 = field(add(q, k1, 0.5 * dt));
        let k3 = field(add(q, k2, 0.5 * dt));
        let k4 = field(add(q, k3, dt));
        let next =
            [0, 1, 2, 3].map(|i| q[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        Some(from_wxyz(next).normalize())
    })
}
