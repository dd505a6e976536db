# SciPy's chordal mean of the quaternions in a binary file (float64, [w, x, y, z] rows), timed:
# Rotation.from_quat(q).mean(), as a user would call it. Input (stdin, JSON): { path, n, rounds }.
# Output (stdout, JSON): the median time in ms and the mean as [w, x, y, z].
import json, sys, time
import numpy as np
from scipy.spatial.transform import Rotation

job = json.load(sys.stdin)
wxyz = np.fromfile(job["path"], dtype="<f8").reshape(job["n"], 4)
xyzw = np.ascontiguousarray(wxyz[:, [1, 2, 3, 0]])
times, mean = [], None
for _ in range(job["rounds"]):
    start = time.perf_counter()
    mean = Rotation.from_quat(xyzw).mean().as_quat()
    times.append((time.perf_counter() - start) * 1000)
times.sort()
x, y, z, w = mean
json.dump({"ms": times[len(times) // 2], "mean": [w, x, y, z]}, sys.stdout)
