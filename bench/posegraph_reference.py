"""Independent reference optima for kli::sync::synchronize_poses (SE-Sync's cost, MATH.md "Pose
graphs"): f = sum kappa ||R_j - R_i Rt_ij||_F^2 + tau ||t_j - t_i - R_i tt_ij||^2 (no 1/2), the
weights read from each g2o edge's information matrix as SE-Sync's reader does (2D: tau = 2/tr(S_t),
kappa = I_33; 3D: tau = 3/tr(S_t), kappa = 3/(2 tr(S_R)), S the inverse of a diagonal block).

Minimised by Levenberg-Marquardt (Nielsen's damping) with a sparse exact Jacobian, every rotation
perturbed on the right (R_i exp(w_i^)), pose 0 held fixed, from the chordal rotations (linear least
squares with R_0 = I, each block projected to SO(d) by SVD) and the least-squares translations for
them. Nothing here is shared with the Rust code.

    target/bench-venv/bin/python bench/posegraph_reference.py tests/fixtures/posegraphs/smallGrid3D.g2o
prints the file, poses, edges, f at the start and at the end, and LM's iterations.
"""
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla


def read(path):
    edges = []
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == "EDGE_SE2":
            i, j = int(w[1]), int(w[2])
            dx, dy, th = map(float, w[3:6])
            i11, i12, i13, i22, i23, i33 = map(float, w[6:12])
            st = np.linalg.inv(np.array([[i11, i12], [i12, i22]]))
            rot = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
            edges.append((i, j, rot, np.array([dx, dy]), i33, 2.0 / np.trace(st)))
        elif w[0] == "EDGE_SE3:QUAT":
            i, j = int(w[1]), int(w[2])
            x, y, z, qx, qy, qz, qw = map(float, w[3:10])
            up = list(map(float, w[10:31]))
            info = np.zeros((6, 6))
            k = 0
            for r in range(6):
                for c in range(r, 6):
                    info[r, c] = info[c, r] = up[k]
                    k += 1
            q = np.array([qw, qx, qy, qz])
            q /= np.linalg.norm(q)
            a, b, c, d = q
            rot = np.array([
                [a*a + b*b - c*c - d*d, 2*(b*c - a*d), 2*(b*d + a*c)],
                [2*(b*c + a*d), a*a - b*b + c*c - d*d, 2*(c*d - a*b)],
                [2*(b*d - a*c), 2*(c*d + a*b), a*a - b*b - c*c + d*d],
            ])
            tau = 3.0 / np.trace(np.linalg.inv(info[:3, :3]))
            kappa = 3.0 / (2.0 * np.trace(np.linalg.inv(info[3:, 3:])))
            edges.append((i, j, rot, np.array([x, y, z]), kappa, tau))
    ids = sorted({e[0] for e in edges} | {e[1] for e in edges})
    index = {v: k for k, v in enumerate(ids)}
    edges = [(index[i], index[j], R, t, k, s) for (i, j, R, t, k, s) in edges]
    return edges[0][2].shape[0], len(ids), edges


def hats(d):
    if d == 2:
        return [np.array([[0.0, -1.0], [1.0, 0.0]])]
    e = []
    for k in range(3):
        v = np.zeros(3)
        v[k] = 1.0
        e.append(np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]]))
    return e


def expm(w, d):
    if d == 2:
        c, s = np.cos(w[0]), np.sin(w[0])
        return np.array([[c, -s], [s, c]])
    th = np.linalg.norm(w)
    K = hats(3)[0] * w[0] + hats(3)[1] * w[1] + hats(3)[2] * w[2]
    if th < 1e-12:
        return np.eye(3) + K + 0.5 * K @ K
    return np.eye(3) + np.sin(th) / th * K + (1 - np.cos(th)) / th**2 * K @ K


def project(a):
    u, _, vt = np.linalg.svd(a)
    r = u @ vt
    if np.linalg.det(r) < 0:
        u[:, -1] *= -1
        r = u @ vt
    return r


def chordal(d, n, edges):
    """min sum kappa ||R_j - R_i Rt||^2 over d x d matrices, R_0 = I; rows of R are independent:
    the unknown is the stacked R^T (dn x d), L x = 0 on free blocks."""
    rows, cols, vals = [], [], []
    for (i, j, R, t, k, s) in edges:
        for a in range(d):
            rows += [d*i + a, d*j + a]
            cols += [d*i + a, d*j + a]
            vals += [k, k]
            for b in range(d):
                rows += [d*i + a, d*j + b]
                cols += [d*j + b, d*i + a]
                vals += [-k * R[a, b], -k * R[a, b]]
    L = sp.csc_matrix((vals, (rows, cols)), shape=(d*n, d*n))
    free = np.arange(d, d*n)
    X0 = np.eye(d)
    rhs = -(L[free][:, :d] @ X0)
    Xf = spla.spsolve(L[free][:, free].tocsc(), rhs)
    X = np.vstack([X0, Xf.reshape(-1, d)])
    return [project(X[d*i:d*i + d].T) for i in range(n)]


def translations(d, n, edges, Rs):
    rows, cols, vals, b = [], [], [], []
    r = 0
    for (i, j, R, t, k, s) in edges:
        w = np.sqrt(s)
        rhs = w * (Rs[i] @ t)
        for a in range(d):
            if j > 0:
                rows.append(r); cols.append(d*(j - 1) + a); vals.append(w)
            if i > 0:
                rows.append(r); cols.append(d*(i - 1) + a); vals.append(-w)
            b.append(rhs[a])
            r += 1
    A = sp.csc_matrix((vals, (rows, cols)), shape=(r, d*(n - 1)))
    x = spla.spsolve((A.T @ A).tocsc(), A.T @ np.array(b))
    return [np.zeros(d)] + [x[d*k:d*k + d] for k in range(n - 1)]


def cost(edges, Rs, ts):
    f = 0.0
    for (i, j, R, t, k, s) in edges:
        f += k * np.sum((Rs[j] - Rs[i] @ R)**2) + s * np.sum((ts[j] - ts[i] - Rs[i] @ t)**2)
    return f


def lm(d, n, edges, Rs, ts, max_iterations=200):
    E = hats(d)
    p = len(E)          # rotation parameters per pose
    block = p + d       # parameters per pose
    f = cost(edges, Rs, ts)
    mu, nu = None, 2.0
    for it in range(max_iterations):
        rows, cols, vals, res = [], [], [], []
        r = 0
        for (i, j, R, t, k, s) in edges:
            sk, st = np.sqrt(k), np.sqrt(s)
            E_rot = Rs[j] - Rs[i] @ R
            res += list(sk * E_rot.ravel())
            for m in range(p):
                Di = -(Rs[i] @ E[m] @ R) * sk     # d/dw_i of -(R_i R~)
                Dj = (Rs[j] @ E[m]) * sk          # d/dw_j of R_j
                for q in range(d*d):
                    if i > 0:
                        rows.append(r + q); cols.append(block*(i - 1) + m); vals.append(Di.ravel()[q])
                    if j > 0:
                        rows.append(r + q); cols.append(block*(j - 1) + m); vals.append(Dj.ravel()[q])
            r += d*d
            e_t = ts[j] - ts[i] - Rs[i] @ t
            res += list(st * e_t)
            for a in range(d):
                if j > 0:
                    rows.append(r + a); cols.append(block*(j - 1) + p + a); vals.append(st)
                if i > 0:
                    rows.append(r + a); cols.append(block*(i - 1) + p + a); vals.append(-st)
                for m in range(p):
                    if i > 0:
                        rows.append(r + a); cols.append(block*(i - 1) + m); vals.append(-st * (Rs[i] @ E[m] @ t)[a])
            r += d
        J = sp.csc_matrix((vals, (rows, cols)), shape=(r, block*(n - 1)))
        res = np.array(res)
        H = (J.T @ J).tocsc()
        g = J.T @ res
        if mu is None:
            mu = 1e-6 * H.diagonal().max()
        while True:
            step = spla.spsolve((H + mu * sp.identity(H.shape[0])).tocsc(), -g)
            R2 = [Rs[0]] + [Rs[i] @ expm(step[block*(i - 1):block*(i - 1) + p], d) for i in range(1, n)]
            t2 = [ts[0]] + [ts[i] + step[block*(i - 1) + p:block*i] for i in range(1, n)]
            f2 = cost(edges, R2, t2)
            pred = -(g @ step) - 0.5 * step @ (H @ step)
            rho = (f - f2) / (2 * pred) if pred > 0 else -1.0   # f = 2 * (1/2 |r|^2)
            if rho > 0:
                done = (f - f2) <= 1e-15 * f
                Rs, ts, f = R2, t2, f2
                mu *= max(1/3, 1 - (2*rho - 1)**3)
                nu = 2.0
                break
            mu *= nu
            nu *= 2
            if mu > 1e20:
                return Rs, ts, f, it
        if done or np.linalg.norm(g) <= 1e-12 * max(1.0, f):
            return Rs, ts, f, it + 1
    return Rs, ts, f, max_iterations


if __name__ == "__main__":
    for path in sys.argv[1:]:
        d, n, edges = read(path)
        Rs = chordal(d, n, edges)
        ts = translations(d, n, edges, Rs)
        f0 = cost(edges, Rs, ts)
        Rs, ts, f, iterations = lm(d, n, edges, Rs, ts)
        print(f"{path}: d = {d}, {n} poses, {len(edges)} edges, f(chordal) = {f0:.10f}, "
              f"f(LM) = {f:.12g} after {iterations} iterations")
