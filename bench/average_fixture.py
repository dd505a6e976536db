# Reference means for tests/js/average.test.mjs, computed without kli: SciPy's Rotation.mean
# (the chordal mean, with weights) in both quaternion orders, and the Karcher mean and the L1
# median by a second implementation of their iterations on SciPy's rotation vectors (log and exp
# of SciPy, not kli's). Random sets: sizes 1 to 300, noise of 1° to 60°, some with outliers,
# random signs, half weighted. Writes JSON to stdout; scripts/fixtures.mjs commits it to
# tests/fixtures/average.json.
import json, sys
import numpy as np
import scipy
from scipy.spatial.transform import Rotation

rng = np.random.default_rng(20261123)


def karcher(R, w):
    """q <- q exp(sum w_j log(q^-1 r_j) / sum w), from the chordal mean, to rounding."""
    q = R.mean(weights=w)
    last = np.inf
    for k in range(500):
        v = (w[:, None] * (q.inv() * R).as_rotvec()).sum(axis=0) / w.sum()
        step = np.linalg.norm(v)
        if step >= last:
            break
        q = q * Rotation.from_rotvec(v)
        last = step
        if step < 1e-16:
            break
    return q, k


def median(R, w):
    """Weiszfeld on rotation vectors: q <- q exp(sum c_j v_j / sum c_j), c_j = w_j / |v_j|."""
    q = R.mean(weights=w)
    for k in range(20000):
        v = (q.inv() * R).as_rotvec()
        d = np.linalg.norm(v, axis=1)
        on = d < 1e-12
        c = np.where(on, 0.0, w / np.where(on, 1.0, d))
        step = (c[:, None] * v).sum(axis=0) / c.sum()
        if on.any():
            # Vardi and Zhang: on datum k, it is the median if the others pull less than w_k;
            # else the Weiszfeld step of the others, shortened by w_k / |pull|.
            pull = np.linalg.norm((c[:, None] * v).sum(axis=0))
            held = w[on].sum()
            if pull <= held:
                break
            step *= 1 - held / pull
        q = q * Rotation.from_rotvec(step)
        if np.linalg.norm(step) < 1e-15:
            break
    return q, k


def wxyz(rotation):
    x, y, z, w = rotation.as_quat()
    return [w, x, y, z]


sets = []
for n, noise, outliers, weighted in [
    (1, 5, 0.0, False), (2, 20, 0.0, True), (3, 10, 0.0, False), (5, 30, 0.0, True),
    (8, 1, 0.0, False), (10, 60, 0.0, True), (25, 5, 0.2, False), (50, 15, 0.1, True),
    (100, 5, 0.3, False), (120, 2, 0.0, True), (200, 10, 0.4, True), (300, 5, 0.1, False),
]:
    truth = Rotation.random(random_state=rng)
    noisy = truth * Rotation.from_rotvec(rng.normal(0, np.radians(noise), (n, 3)))
    wild = Rotation.random(n, random_state=rng)
    keep = rng.random(n) >= outliers
    q = np.where(keep[:, None], noisy.as_quat(), wild.as_quat())
    q *= np.where(rng.random(n) < 0.5, -1.0, 1.0)[:, None]
    weights = rng.uniform(0.1, 10.0, n) if weighted else None
    w = weights if weighted else np.ones(n)
    R = Rotation.from_quat(q)
    scalar_last = R.mean(weights=weights).as_quat()
    scalar_first = Rotation.from_quat(q[:, [3, 0, 1, 2]], scalar_first=True).mean(weights=weights).as_quat(scalar_first=True)
    assert np.allclose(np.abs(scalar_last @ scalar_first[[1, 2, 3, 0]]), 1, atol=1e-14)
    geodesic, _ = karcher(R, w)
    l1 = median(R, w) if n > 2 else (None, 0)
    sets.append({
        "quaternions": q[:, [3, 0, 1, 2]].tolist(),
        "weights": None if weights is None else weights.tolist(),
        "chordal": {"wxyz": scalar_first.tolist(), "xyzw": scalar_last.tolist()},
        "geodesic": wxyz(geodesic),
        "median": None if l1[0] is None else wxyz(l1[0]),
    })

json.dump({
    "generator": f"bench/average_fixture.py, SciPy {scipy.__version__}, NumPy {np.__version__}",
    "orders": "quaternions and geodesic/median as [w, x, y, z]; chordal in both orders",
    "sets": sets,
}, sys.stdout, indent=1)
