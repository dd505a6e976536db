"""SciPy's RotationSpline through the keys the JavaScript bench sends (bench/spline.mjs).

Reads JSON from stdin: a list of {"keys": [[w, x, y, z], ...], "times": [...], "at": [...]} and
writes to stdout, for each set in order, the spline's quaternions at "at" as little-endian
float64 [w, x, y, z] (scalar first, as kli's), signs as SciPy returns them.
"""
import json
import sys

import numpy as np
from scipy.spatial.transform import Rotation, RotationSpline

out = sys.stdout.buffer
for case in json.load(sys.stdin):
    keys = np.array(case["keys"], dtype=float)
    spline = RotationSpline(case["times"], Rotation.from_quat(keys[:, [1, 2, 3, 0]]))
    xyzw = spline(np.array(case["at"], dtype=float)).as_quat()
    out.write(np.ascontiguousarray(xyzw[:, [3, 0, 1, 2]], dtype="<f8").tobytes())
