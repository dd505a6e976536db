//! The chordal L2 mean (MATH.md, "Averaging rotations"): the top eigenvector of the scatter
//! matrix `M = Σ w_j r_j r_jᵀ`, where the sign-blind Kuramoto–Lohe flow `q' = M q − (qᵀM q) q` of
//! one follower coupled to every measurement settles (Oja's flow: gradient ascent of `qᵀMq` on
//! S³). SciPy's `Rotation.mean` and Markley et al. (2007) compute the same eigenvector.

use glam::DQuat;

use super::Data;
use super::eigen::{Symmetric4, eigen};
use crate::error::{ErrorKind, KliError};
use crate::quaternion::{from_wxyz, to_wxyz};

/// How close the two largest eigenvalues may be, relative to the largest, before the mean is
/// not unique: rounding, with room for the sum of 10⁶ products.
const TIE: f64 = 1e-12;

/// `M = Σ w_j r_j r_jᵀ` over `[w, x, y, z]` components, in one pass over the data; `weights`
/// `None` is all 1 (the swarm's `λ_max`).
pub fn scatter(rotations: &[DQuat], weights: Option<&[f64]>) -> Symmetric4 {
    let mut sum = [0.0; 10];
    for (j, &r) in rotations.iter().enumerate() {
        let w = weights.map_or(1.0, |w| w[j]);
        let [a, b, c, d] = to_wxyz(r);
        let (wa, wb, wc, wd) = (w * a, w * b, w * c, w * d);
        let products =
            [wa * a, wa * b, wa * c, wa * d, wb * b, wb * c, wb * d, wc * c, wc * d, wd * d];
        for (s, p) in sum.iter_mut().zip(products) {
            *s += p;
        }
    }
    let [aa, ab, ac, ad, bb, bc, bd, cc, cd, dd] = sum;
    [[aa, ab, ac, ad], [ab, bb, bc, bd], [ac, bc, cc, cd], [ad, bd, cd, dd]]
}

/// The chordal mean of `data` with the scalar part ≥ 0, and the relative eigen-residual
/// `|M q − λ q| / λ`; an Error ([`ErrorKind::NotUnique`]) when the top eigenvalue is repeated.
pub(super) fn chordal(data: &Data) -> Result<(DQuat, f64), KliError> {
    let m = scatter(&data.rotations, Some(&data.weights));
    let (values, vectors) = eigen(m);
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
