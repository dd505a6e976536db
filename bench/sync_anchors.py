# The anchors of bench/sync.mjs, on the same graphs as kli: GTSAM (chordal initialisation then
# Levenberg–Marquardt, ShonanAveraging3, GNC with the truncated least squares loss), Theia
# (RobustRotationEstimator: L1 then IRLS; the hybrid estimator: L1-IRLS then the Lagrange dual;
# the Lagrange dual alone) and COLMAP 4's rotation averaging (GLOMAP's). Reads JSON on stdin:
#   {"mode": "graphs"}                       → the bench's graphs (GTSAM's sphere2500 and seeded
#                                              synthetic graphs in the style of Chatterjee and
#                                              Govindu), as JSON
#   {"mode": "anchors", "graphs": [...], "kli": {...}}
#                                            → each method's time and result on each graph, and
#                                              the same measures of kli's results
# Quaternions are [w, x, y, z]; R_ij = R_iᵀ R_j (GTSAM's BetweenFactor<Rot3>). Theia and COLMAP
# take camera-from-world rotations C_i = R_iᵀ and relative rotations C_j C_iᵀ = R_ijᵀ.
import json, os, sys, time
import numpy as np
import gtsam
import pycolmap
import pytheia as pt
from scipy.spatial.transform import Rotation

SEED = 20261125


def quat_to_rot(q):
    w, x, y, z = q
    return Rotation.from_quat([x, y, z, w])


def rot_to_quat(R):
    x, y, z, w = Rotation.from_matrix(R).as_quat()
    q = np.array([w, x, y, z])
    return q if q[0] >= 0 else -q


def synthetic(n, degree, sigma_deg, wrong, seed):
    """Chatterjee–Govindu style: random truth, an Erdős–Rényi graph of mean degree `degree` plus
    a ring (connected), each edge's relative rotation turned by a Gaussian angle of `sigma_deg`
    about a random axis, a share `wrong` replaced by uniform random rotations, random signs."""
    rng = np.random.default_rng(seed)
    truth = Rotation.random(n, random_state=rng)
    p = degree / (n - 1)
    edges = {(i, (i + 1) % n) if i < (i + 1) % n else ((i + 1) % n, i) for i in range(n)}
    upper = np.argwhere(np.triu(rng.random((n, n)) < p, 1))
    edges |= {(int(i), int(j)) for i, j in upper}
    edges = sorted(edges)
    relative, is_wrong = [], []
    for i, j in edges:
        bad = rng.random() < wrong
        if bad:
            R = Rotation.random(random_state=rng)
        else:
            axis = rng.normal(size=3)
            axis /= np.linalg.norm(axis)
            R = truth[i].inv() * truth[j] * Rotation.from_rotvec(axis * np.radians(sigma_deg) * rng.normal())
        q = rot_to_quat(R.as_matrix()) * rng.choice([-1.0, 1.0])
        relative.append(q.tolist())
        is_wrong.append(bool(bad))
    return {"name": f"{n} nodes, σ {sigma_deg}°, {round(100 * wrong)}% wrong", "count": n,
            "edges": [list(e) for e in edges], "relative": relative, "sigma": np.radians(sigma_deg),
            "wrong": is_wrong, "truth": [rot_to_quat(t.as_matrix()).tolist() for t in truth]}


def sphere2500():
    graph, _ = gtsam.readG2o(gtsam.findExampleDataFile("sphere2500"), True)
    edges, relative = [], []
    for k in range(graph.size()):
        f = graph.at(k)
        if isinstance(f, gtsam.BetweenFactorPose3):
            keys = f.keys()
            edges.append([int(keys[0]), int(keys[1])])
            relative.append(rot_to_quat(f.measured().rotation().matrix()).tolist())
    return {"name": "sphere2500", "count": 1 + max(max(e) for e in edges), "edges": edges, "relative": relative}


def graphs():
    out = [sphere2500()]
    for n in (100, 1000):
        for sigma in (2, 5):
            for wrong in (0.1, 0.2, 0.3):
                out.append(synthetic(n, 10, sigma, wrong, SEED + n + 10 * sigma + round(100 * wrong)))
    return out


# ---- the anchors: each returns R_i as 3×3 matrices (our convention), and its time in seconds ----

def rot3_values(R):
    values = gtsam.Values()
    for i, r in enumerate(R):
        values.insert(i, gtsam.Rot3(r))
    return values


def gtsam_chordal_init(g):
    poses = gtsam.NonlinearFactorGraph()
    unit = gtsam.noiseModel.Isotropic.Sigma(6, 1.0)
    for (i, j), q in zip(g["edges"], g["relative"]):
        poses.add(gtsam.BetweenFactorPose3(i, j, gtsam.Pose3(gtsam.Rot3(quat_to_rot(q).as_matrix()), np.zeros(3)), unit))
    poses.add(gtsam.PriorFactorPose3(0, gtsam.Pose3(), gtsam.noiseModel.Isotropic.Sigma(6, 1e-6)))
    init = gtsam.InitializePose3.computeOrientationsChordal(gtsam.InitializePose3.buildPose3graph(poses))
    return [init.atRot3(i).matrix() for i in range(g["count"])]


def frobenius_graph(g, sigma=1.0):
    graph = gtsam.NonlinearFactorGraph()
    noise = gtsam.noiseModel.Isotropic.Sigma(9, sigma)
    for (i, j), q in zip(g["edges"], g["relative"]):
        graph.add(gtsam.FrobeniusBetweenFactorRot3(i, j, gtsam.Rot3(quat_to_rot(q).as_matrix()), noise))
    graph.add(gtsam.NonlinearEqualityRot3(0, gtsam.Rot3()))
    return graph


def gtsam_chordal_lm(g):
    """GTSAM's chordal initialisation, then Levenberg–Marquardt on the chordal (Frobenius) cost."""
    start = time.perf_counter()
    init = gtsam_chordal_init(g)
    values = gtsam.LevenbergMarquardtOptimizer(frobenius_graph(g), rot3_values(init), gtsam.LevenbergMarquardtParams()).optimize()
    elapsed = time.perf_counter() - start
    return [values.atRot3(i).matrix() for i in range(g["count"])], elapsed


def gtsam_shonan(g):
    measurements = gtsam.BinaryMeasurementsRot3()
    noise = gtsam.noiseModel.Isotropic.Sigma(3, 1.0)
    for (i, j), q in zip(g["edges"], g["relative"]):
        measurements.append(gtsam.BinaryMeasurementRot3(i, j, gtsam.Rot3(quat_to_rot(q).as_matrix()), noise))
    start = time.perf_counter()
    shonan = gtsam.ShonanAveraging3(measurements, gtsam.ShonanAveragingParameters3(gtsam.LevenbergMarquardtParams.CeresDefaults()))
    result, _ = shonan.run(shonan.initializeRandomly(), 3, 10)
    elapsed = time.perf_counter() - start
    return [result.atRot3(i).matrix() for i in range(g["count"])], elapsed


def gtsam_gnc_tls(g):
    """GNC with the TLS loss on BetweenFactor<Rot3>, from the chordal initialisation; the noise
    model is the data's own σ (as a user who knows the noise would set it)."""
    start = time.perf_counter()
    init = gtsam_chordal_init(g)
    graph = gtsam.NonlinearFactorGraph()
    noise = gtsam.noiseModel.Isotropic.Sigma(3, g["sigma"])
    for (i, j), q in zip(g["edges"], g["relative"]):
        graph.add(gtsam.BetweenFactorRot3(i, j, gtsam.Rot3(quat_to_rot(q).as_matrix()), noise))
    graph.add(gtsam.PriorFactorRot3(0, gtsam.Rot3(init[0]), gtsam.noiseModel.Isotropic.Sigma(3, 1e-6)))
    params = gtsam.GncLMParams()
    params.setLossType(gtsam.GncLossType.TLS)
    values = gtsam.GncLMOptimizer(graph, rot3_values(init), params).optimize()
    elapsed = time.perf_counter() - start
    return [values.atRot3(i).matrix() for i in range(g["count"])], elapsed


def theia_inputs(g):
    view_pairs = {}
    for (i, j), q in zip(g["edges"], g["relative"]):
        info = pt.sfm.TwoViewInfo()
        info.focal_length_1 = info.focal_length_2 = 1.0
        info.position_2 = np.zeros((3, 1))
        info.rotation_2 = quat_to_rot(q).inv().as_rotvec().reshape(3, 1)
        view_pairs[(i, j)] = info
    return view_pairs


def spanning_tree_start(g):
    """Orientations chained along a breadth-first spanning tree from node 0 (Theia's pipeline
    starts from a maximum spanning tree of the view graph; every edge here weighs the same)."""
    n = g["count"]
    neighbours = [[] for _ in range(n)]
    for (i, j), q in zip(g["edges"], g["relative"]):
        R = quat_to_rot(q).as_matrix()
        neighbours[i].append((j, R))
        neighbours[j].append((i, R.T))
    R = [None] * n
    R[0] = np.eye(3)
    queue = [0]
    for a in queue:
        for b, Rab in neighbours[a]:
            if R[b] is None:
                R[b] = R[a] @ Rab
                queue.append(b)
    return {i: Rotation.from_matrix(r.T).as_rotvec().reshape(3, 1) for i, r in enumerate(R)}


def theia_result(result, n):
    return [Rotation.from_rotvec(np.asarray(result[i]).ravel()).as_matrix().T for i in range(n)]


def theia_robust(g):
    view_pairs, start_rotations = theia_inputs(g), spanning_tree_start(g)
    start = time.perf_counter()
    estimator = pt.sfm.RobustRotationEstimator(pt.sfm.RobustRotationEstimatorOptions())
    result = estimator.EstimateRotations(view_pairs, start_rotations)
    return theia_result(result, g["count"]), time.perf_counter() - start


def theia_global(kind):
    """Theia's hybrid (L1-IRLS, then the Lagrange dual) or Lagrange dual estimator, reached through
    GlobalReconstructionEstimator with `global_rotation_estimator_type` set (pytheia's bindings of
    the estimators themselves return nothing: their output map is copied in and dropped). The time
    is the whole Estimate call; with no tracks, its position step is a small share."""
    def run(g):
        reconstruction, view_graph = pt.sfm.Reconstruction(), pt.sfm.ViewGraph()
        ids = [reconstruction.AddView(str(i), 0, float(i)) for i in range(g["count"])]
        rng = np.random.default_rng(SEED)
        for (i, j), q in zip(g["edges"], g["relative"]):
            info = pt.sfm.TwoViewInfo()
            info.focal_length_1 = info.focal_length_2 = 1.0
            info.rotation_2 = quat_to_rot(q).inv().as_rotvec().reshape(3, 1)
            direction = rng.normal(size=(3, 1))
            info.position_2 = direction / np.linalg.norm(direction)
            info.num_verified_matches = 100
            view_graph.AddEdge(ids[i], ids[j], info)
        options = pt.sfm.ReconstructionEstimatorOptions()
        options.global_rotation_estimator_type = getattr(pt.sfm.GlobalRotationEstimatorType, kind)
        start = time.perf_counter()
        pt.sfm.GlobalReconstructionEstimator(options).Estimate(view_graph, reconstruction)
        elapsed = time.perf_counter() - start
        R = [Rotation.from_rotvec(reconstruction.View(v).Camera().GetOrientationAsAngleAxis().ravel()).as_matrix().T for v in ids]
        return R, elapsed
    return run


def colmap(g):
    n = g["count"]
    reconstruction = pycolmap.Reconstruction()
    camera = pycolmap.Camera(model="SIMPLE_PINHOLE", width=640, height=480, params=[500, 320, 240], camera_id=1)
    reconstruction.add_camera_with_trivial_rig(camera)
    for i in range(n):
        reconstruction.add_image_with_trivial_frame(pycolmap.Image(name=f"{i}", camera_id=1, image_id=i + 1))
    pose_graph = pycolmap.PoseGraph()
    for (i, j), q in zip(g["edges"], g["relative"]):
        x, y, z, w = quat_to_rot(q).inv().as_quat()
        edge = pycolmap.PoseGraphEdge(pycolmap.Rigid3d(pycolmap.Rotation3d([x, y, z, w]), np.zeros(3)))
        edge.num_matches = 100
        pose_graph.add_edge(i + 1, j + 1, edge)
    start = time.perf_counter()
    ok = pycolmap.run_rotation_averaging(pycolmap.RotationEstimatorOptions(), pose_graph, reconstruction, [])
    elapsed = time.perf_counter() - start
    R = []
    for i in range(n):
        image = reconstruction.images[i + 1]
        pose = image.cam_from_world() if callable(image.cam_from_world) else image.cam_from_world
        R.append(pose.rotation.matrix().T if ok and image.has_pose else np.full((3, 3), np.nan))
    return R, elapsed


# ---- measures, the same for every method ----

def chordal_cost(g, R):
    return float(sum(np.sum((R[i] @ quat_to_rot(q).as_matrix() - R[j]) ** 2) for (i, j), q in zip(g["edges"], g["relative"])))


def errors_to_truth(g, R):
    """Degrees, after the best gauge G (R_i ≈ G T_i): the chordal mean of R_i T_iᵀ."""
    T = [quat_to_rot(q).as_matrix() for q in g["truth"]]
    keep = [i for i in range(len(R)) if np.all(np.isfinite(R[i]))]
    G = Rotation.from_matrix([R[i] @ T[i].T for i in keep]).mean().as_matrix()
    return np.array([np.degrees(Rotation.from_matrix(R[i].T @ G @ T[i]).magnitude()) for i in keep]), len(R) - len(keep)


def edge_truth_errors(g):
    T = [quat_to_rot(q) for q in g["truth"]]
    return np.array([np.degrees((T[i].inv() * T[j]).inv().__mul__(quat_to_rot(q)).magnitude()) for (i, j), q in zip(g["edges"], g["relative"])])


def measures(g, R, seconds):
    out = {"seconds": seconds, "cost": chordal_cost(g, R)}
    if "truth" in g:
        errors, missing = errors_to_truth(g, R)
        out.update(median=float(np.median(errors)), mean=float(np.mean(errors)), missing=missing)
    return out


def anchors(request):
    out = []
    for g in request["graphs"]:
        row = {"name": g["name"], "methods": {}}
        if g["name"] == "sphere2500":
            methods = {"GTSAM chordal + LM": gtsam_chordal_lm, "GTSAM Shonan": gtsam_shonan,
                       "Theia Lagrange dual": theia_global("LAGRANGE_DUAL")}
        else:
            methods = {"Theia L1-IRLS": theia_robust, "Theia hybrid": theia_global("HYBRID"),
                       "COLMAP": colmap, "GTSAM Shonan": gtsam_shonan}
            if g["count"] <= 100 or g["name"].endswith("30% wrong"):
                methods["GTSAM GNC-TLS"] = gtsam_gnc_tls
        for name, method in methods.items():
            try:
                R, seconds = method(g)
                row["methods"][name] = measures(g, R, seconds)
            except Exception as e:  # an anchor that fails is reported, not hidden
                row["methods"][name] = {"error": str(e)[:200]}
        for name, result in request["kli"].get(g["name"], {}).items():
            R = [quat_to_rot(result["rotations"][4 * i:4 * i + 4]).as_matrix() for i in range(g["count"])]
            m = measures(g, R, result["seconds"])
            if "outliers" in result and "truth" in g:
                off = edge_truth_errors(g)
                flagged = np.array(result["outliers"], dtype=bool)
                m["far_flagged"] = float(flagged[off > 15].mean()) if (off > 15).any() else 1.0
                m["good_among_flagged"] = float((off[flagged] < 10).mean()) if flagged.any() else 0.0
            row["methods"][name] = m
        out.append(row)
    return out


# Ceres (under Theia) and GTSAM print progress tables on standard output: the C level's
# standard output goes to standard error, and the JSON to the real one.
answer = os.fdopen(os.dup(1), "w")
os.dup2(2, 1)
request = json.load(sys.stdin)
versions = {"gtsam": "4.3.0", "pycolmap": pycolmap.__version__, "pytheia": "1.2.1", "numpy": np.__version__}
if request["mode"] == "graphs":
    json.dump({"versions": versions, "graphs": graphs()}, answer)
else:
    json.dump({"versions": versions, "rows": anchors(request)}, answer)
answer.flush()
