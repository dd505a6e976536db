"""GTSAM beside kli's synchronizePoses (bench/poses.mjs): on each pose graph, GTSAM's chordal
initialisation + Levenberg-Marquardt, timed here, and every answer (GTSAM's, and kli's and
SE-Sync's C++'s, passed in)
evaluated in SE-Sync's cost by bench/posegraph_reference.py's reader and cost, the one currency.

- 3D: gtsam.InitializePose3.initialize, then LevenbergMarquardtOptimizer (default parameters)
  on the file's factors and a prior on the first pose.
- 2D: GTSAM's lago refuses the files' non-diagonal noise models, so the start is
  posegraph_reference.py's chordal rotations + least-squares translations (timed with it), then
  GTSAM's LevenbergMarquardtOptimizer as in 3D.
- g2o (g2opy, the pip wheel of g2o's own Python bindings): its Levenberg-Marquardt from the same
  chordal start (g2o_run), timed as the start (once) + loading and optimising.
GTSAM and g2o read each file with their own readers and its information matrices: they minimise
their own costs, not SE-Sync's. Ceres (pyceres) is not a peer: its wheel has no pose-graph cost,
and one written in Python would time Python callbacks.
A run is the median of 3 where the first takes at most 2 s, else the one run.

stdin: {"scratch": a folder to write in, "graphs": [{"name", "path", "dimension", "kli":
{"rotations": [w x y z ...], "translations": [x y z ...]}, "seSync"?: {"rotations": [d x d row by
row ...], "translations": [d a pose ...]}}]}; stdout: {"versions": {...}, "rows": [{"name",
"poses", "edges", "seconds", "runs", "cost", "kliCost", "seSyncCost", "startSeconds", "g2o":
{"seconds", "runs", "cost"} or {"error"}, "error"?}]}.
"""
import json
import os
import sys
import time

import importlib.metadata

import gtsam
import numpy as np

try:
    import g2opy as g2o
except ImportError:  # bench/poses.mjs installs it into the venv; without it, g2o is not run
    g2o = None

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import posegraph_reference as reference  # noqa: E402


def ids_of(path):
    """The pose ids the reference reader numbers from 0 (ascending), as it finds them."""
    ids = set()
    for line in open(path):
        w = line.split()
        if w and w[0] in ("EDGE_SE2", "EDGE_SE3:QUAT"):
            ids.update((int(w[1]), int(w[2])))
    return sorted(ids)


def rotation(q):
    a, b, c, d = q
    return np.array([
        [a*a + b*b - c*c - d*d, 2*(b*c - a*d), 2*(b*d + a*c)],
        [2*(b*c + a*d), a*a - b*b + c*c - d*d, 2*(c*d - a*b)],
        [2*(b*d - a*c), 2*(c*d + a*b), a*a - b*b - c*c + d*d],
    ])


def kli_poses(d, kli):
    q = np.array(kli["rotations"]).reshape(-1, 4)
    t = np.array(kli["translations"]).reshape(-1, 3)
    return [rotation(x)[:d, :d] for x in q], [x[:d] for x in t]


def start(path, d, edges, n, ids, read=None):
    """GTSAM's graph (with a prior on the first pose) and the chordal start: 3D GTSAM's
    InitializePose3, 2D the reference's chordal rotations + least-squares translations. `read`,
    a list, is given the seconds the file's reading took."""
    began = time.perf_counter()
    graph, _ = gtsam.readG2o(path, d == 3)
    if read is not None:
        read.append(time.perf_counter() - began)
    first = ids[0]
    if d == 3:
        graph.add(gtsam.PriorFactorPose3(first, gtsam.Pose3(), gtsam.noiseModel.Isotropic.Sigma(6, 1e-6)))
        return graph, gtsam.InitializePose3.initialize(graph)
    graph.add(gtsam.PriorFactorPose2(first, gtsam.Pose2(), gtsam.noiseModel.Isotropic.Sigma(3, 1e-6)))
    Rs = reference.chordal(d, n, edges)
    ts = reference.translations(d, n, edges, Rs)
    initial = gtsam.Values()
    for k, key in enumerate(ids):
        initial.insert(key, gtsam.Pose2(ts[k][0], ts[k][1], np.arctan2(Rs[k][1, 0], Rs[k][0, 0])))
    return graph, initial


def g2o_run(path, d, ids, initial, work):
    """g2o's Levenberg-Marquardt (Eigen's sparse Cholesky, the solver g2opy offers) from the same
    chordal start: the file's edge lines as they are, after a vertex line a pose from the start
    (written out, not timed); the first pose fixed. Returns (rotations, translations) and the time
    of loading and optimising."""
    lines = []
    for key in ids:
        if d == 3:
            p = initial.atPose3(key)
            q = p.rotation().toQuaternion()
            t = p.translation()
            numbers = [t[0], t[1], t[2], q.x(), q.y(), q.z(), q.w()]
            lines.append(f"VERTEX_SE3:QUAT {key} " + " ".join(repr(float(x)) for x in numbers))
        else:
            p = initial.atPose2(key)
            lines.append(f"VERTEX_SE2 {key} {float(p.x())!r} {float(p.y())!r} {float(p.theta())!r}")
    lines += [line.rstrip("\n") for line in open(path) if line.startswith("EDGE_SE")]
    with open(work, "w") as f:
        f.write("\n".join(lines) + "\n")
    begin = time.perf_counter()
    o = g2o.SparseOptimizer()
    solver = g2o.BlockSolverSE3(g2o.LinearSolverEigenSE3()) if d == 3 else g2o.BlockSolverSE2(g2o.LinearSolverEigenSE2())
    o.set_algorithm(g2o.OptimizationAlgorithmLevenberg(solver))
    o.load(work)
    if len(o.vertices()) != len(ids):
        raise RuntimeError(f"g2o read {len(o.vertices())} of {len(ids)} poses")
    o.vertex(ids[0]).set_fixed(True)
    o.initialize_optimization()
    o.optimize(100)
    seconds = time.perf_counter() - begin
    if d == 3:
        m = [o.vertex(key).estimate().matrix() for key in ids]
        return [x[:3, :3] for x in m], [x[:3, 3] for x in m], seconds
    e = [o.vertex(key).estimate().to_vector() for key in ids]
    return [np.array([[np.cos(v[2]), -np.sin(v[2])], [np.sin(v[2]), np.cos(v[2])]]) for v in e], [v[:2] for v in e], seconds


def gtsam_run(path, d, edges, n, ids):
    """GTSAM's chordal start + LM; returns (rotations, translations) in the reference's order,
    the start, the seconds of LM alone (in 2D the start is the reference's chordal in NumPy and
    SciPy, which a C++ caller of GTSAM would do faster: LM alone is shown beside) and those of
    reading the file (left out of GTSAM's time, as kli's and SE-Sync's leave out theirs)."""
    read = []
    graph, initial = start(path, d, edges, n, ids, read)
    begin = time.perf_counter()
    values = gtsam.LevenbergMarquardtOptimizer(graph, initial, gtsam.LevenbergMarquardtParams()).optimize()
    lm = time.perf_counter() - begin
    if d == 3:
        poses = [values.atPose3(key) for key in ids]
        return [p.rotation().matrix() for p in poses], [np.array(p.translation()) for p in poses], initial, lm, read[0]
    poses = [values.atPose2(key) for key in ids]
    return [p.rotation().matrix() for p in poses], [np.array([p.x(), p.y()]) for p in poses], initial, lm, read[0]


def main():
    given = json.load(sys.stdin)
    graphs, scratch = given["graphs"], given["scratch"]
    rows = []
    for g in graphs:
        path = g["path"]
        d, n, edges = reference.read(path)
        ids = ids_of(path)
        row = {"name": g["name"], "poses": n, "edges": len(edges)}
        Rk, tk = kli_poses(d, g["kli"])
        row["kliCost"] = reference.cost(edges, Rk, tk) if len(Rk) == n else None
        if g.get("seSync"):
            # SE-Sync's poses by its own indices (a file's ids from 0, as SE-Sync reads them)
            Rs = np.array(g["seSync"]["rotations"]).reshape(-1, d, d)
            ts = np.array(g["seSync"]["translations"]).reshape(-1, d)
            row["seSyncCost"] = reference.cost(edges, list(Rs), list(ts)) if len(Rs) == n and ids == list(range(n)) else None
        try:
            times, lms = [], []
            while True:
                began = time.perf_counter()
                Rs, ts, initial, lm, read = gtsam_run(path, d, edges, n, ids)
                times.append(time.perf_counter() - began - read)
                lms.append(lm)
                # the median of 3 where a run is short, else the one run
                if len(times) == 3 or times[0] > 2.0:
                    break
            row["seconds"] = sorted(times)[len(times) // 2]
            row["lmSeconds"] = sorted(lms)[len(lms) // 2]
            row["runs"] = len(times)
            row["cost"] = reference.cost(edges, Rs, ts)
        except Exception as e:  # noqa: BLE001 — reported in the table
            row["error"] = f"{type(e).__name__}: {e}"
            initial = None
        if initial is not None and g2o is None:
            row["g2o"] = {"error": "g2opy is not installed"}
        elif initial is not None:
            try:
                begin = time.perf_counter()
                start(path, d, edges, n, ids)
                row["startSeconds"] = time.perf_counter() - begin
                work = os.path.join(scratch, "g2o-start.g2o")
                times = []
                while True:
                    Rs, ts, seconds = g2o_run(path, d, ids, initial, work)
                    times.append(seconds)
                    if len(times) == 3 or times[0] > 2.0:
                        break
                start_seconds = row["startSeconds"]
                row["g2o"] = {"seconds": start_seconds + sorted(times)[len(times) // 2], "runs": len(times),
                              "cost": reference.cost(edges, Rs, ts)}
            except Exception as e:  # noqa: BLE001 — reported in the table
                row["g2o"] = {"error": f"{type(e).__name__}: {e}"}
        rows.append(row)
        print(f"  GTSAM {g['name']}: {row.get('seconds', 0):.2f} s, g2o {row.get('g2o', {}).get('seconds', 0):.2f} s", file=sys.stderr)
    versions = {name: importlib.metadata.version(name) for name in ("gtsam", "numpy")}
    versions["g2opy"] = importlib.metadata.version("g2opy") if g2o else "not installed"
    json.dump({"versions": versions, "rows": rows}, sys.stdout)


if __name__ == "__main__":
    main()
