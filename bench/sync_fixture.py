# Reference solutions for the `sync` tests, computed without kli: GTSAM minimises the chordal cost
# Σ w ‖R_i R_ij − R_j‖²_F itself (FrobeniusBetweenFactorRot3, Levenberg–Marquardt to rounding,
# from GTSAM's own chordal initialisation), and NumPy's dense eigvalsh gives the certificate's
# eigenvalues (S = L − Λ, MATH.md). Graphs: GTSAM's pose3example-grid, and random graphs with
# weights, noise and random signs. Run in the bench's environment (bench/python.mjs):
#   make fixtures   (scripts/fixtures.mjs writes tests/fixtures/sync.json)
import json, sys
import numpy as np
import gtsam

rng = np.random.default_rng(20261125)


def quat_wxyz(R):
    q = gtsam.Rot3(R).toQuaternion()
    w = np.array([q.w(), q.x(), q.y(), q.z()])
    return w if w[0] >= 0 else -w


def rot(q):
    return gtsam.Rot3.Quaternion(*q).matrix()


def solve(n, edges, rel, weights):
    """The chordal optimum by GTSAM, anchored at node 0, and its certificate's eigenvalues."""
    graph = gtsam.NonlinearFactorGraph()
    for (i, j), q, w in zip(edges, rel, weights):
        # GTSAM's factor error is vec(R_i R_ij − R_j), halved and divided by σ² in the cost.
        noise = gtsam.noiseModel.Isotropic.Sigma(9, 1.0 / np.sqrt(2.0 * w))
        graph.add(gtsam.FrobeniusBetweenFactorRot3(i, j, gtsam.Rot3(rot(q)), noise))
    graph.add(gtsam.NonlinearEqualityRot3(0, gtsam.Rot3()))
    # GTSAM's chordal initialisation works on a Pose3 graph of BetweenFactorPose3.
    poses = gtsam.NonlinearFactorGraph()
    for (i, j), q in zip(edges, rel):
        poses.add(gtsam.BetweenFactorPose3(i, j, gtsam.Pose3(gtsam.Rot3(rot(q)), np.zeros(3)),
                                           gtsam.noiseModel.Isotropic.Sigma(6, 1.0)))
    poses.add(gtsam.PriorFactorPose3(0, gtsam.Pose3(), gtsam.noiseModel.Isotropic.Sigma(6, 1e-6)))
    init = gtsam.InitializePose3.computeOrientationsChordal(gtsam.InitializePose3.buildPose3graph(poses))
    params = gtsam.LevenbergMarquardtParams()
    params.setRelativeErrorTol(0.0)
    params.setAbsoluteErrorTol(0.0)
    params.setErrorTol(0.0)
    params.setMaxIterations(200)
    values = gtsam.LevenbergMarquardtOptimizer(graph, init, params).optimize()
    # LM stops once a step's decrease is below the cost's rounding, with the gradient still near
    # 1e-8; Gauss–Newton steps taken unconditionally converge (linearly) on to the stationary point.
    polish = gtsam.GaussNewtonOptimizer(graph, values, gtsam.GaussNewtonParams())
    for _ in range(60):
        polish.iterate()
    values = polish.values()
    R = [values.atRot3(i).matrix() for i in range(n)]
    cost = sum(w * np.sum((R[i] @ rot(q) - R[j]) ** 2) for (i, j), q, w in zip(edges, rel, weights))
    # The certificate, densely.
    L = np.zeros((3 * n, 3 * n))
    for (i, j), q, w in zip(edges, rel, weights):
        L[3*i:3*i+3, 3*i:3*i+3] += w * np.eye(3)
        L[3*j:3*j+3, 3*j:3*j+3] += w * np.eye(3)
        L[3*i:3*i+3, 3*j:3*j+3] -= w * rot(q)
        L[3*j:3*j+3, 3*i:3*i+3] -= w * rot(q).T
    Y = np.vstack([r.T for r in R])
    LY = L @ Y
    S = L.copy()
    for i in range(n):
        m = LY[3*i:3*i+3] @ R[i]
        S[3*i:3*i+3, 3*i:3*i+3] -= 0.5 * (m + m.T)
    eig = np.linalg.eigvalsh(S)
    return [quat_wxyz(r).tolist() for r in R], float(cost), eig[:5].tolist()


def random_graph(n, p, noise, seed_signs=True, weighted=True):
    truth = [gtsam.Rot3.Quaternion(*(v / np.linalg.norm(v))).matrix() for v in rng.normal(size=(n, 4))]
    edges = [(i, (i + 1) % n) for i in range(n)]
    edges += [(i, j) for i in range(n) for j in range(i + 2, n) if rng.random() < p and not (i == 0 and j == n - 1)]
    rel, weights = [], []
    for i, j in edges:
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        angle = noise * rng.normal()
        R = truth[i].T @ truth[j] @ gtsam.Rot3.AxisAngle(gtsam.Point3(*axis), angle).matrix()
        q = quat_wxyz(R) * (rng.choice([-1.0, 1.0]) if seed_signs else 1.0)
        rel.append(q.tolist())
        weights.append(float(rng.uniform(0.5, 2.0)) if weighted else 1.0)
    return n, edges, rel, weights


cases = []
grid = gtsam.findExampleDataFile("pose3example-grid")
graph, _ = gtsam.readG2o(grid, True)
edges, rel = [], []
for k in range(graph.size()):
    f = graph.at(k)
    if isinstance(f, gtsam.BetweenFactorPose3):
        keys = f.keys()
        edges.append((int(keys[0]), int(keys[1])))
        rel.append(quat_wxyz(f.measured().rotation().matrix()).tolist())
n = 1 + max(max(e) for e in edges)
cases.append(("pose3example-grid", n, edges, rel, [1.0] * len(edges)))
for name, args in [("random-30", (30, 0.2, np.radians(5))), ("random-60-noisy", (60, 0.1, np.radians(20)))]:
    cases.append((name, *random_graph(*args)))

out = []
for name, n, edges, rel, weights in cases:
    rotations, cost, eig = solve(n, edges, rel, weights)
    out.append({"name": name, "count": n, "edges": [list(e) for e in edges], "relative": rel,
                "weights": weights, "rotations": rotations, "cost": cost, "eigenvalues": eig})
json.dump({"generator": f"bench/sync_fixture.py, gtsam {gtsam.__version__ if hasattr(gtsam, '__version__') else '4.3.0'}, numpy {np.__version__}",
           "cases": out}, sys.stdout, indent=None)
