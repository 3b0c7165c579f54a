#!/usr/bin/env python3
"""Reference PCHIP values for postproc's tests, computed once with scipy.

Run from this directory with scipy installed (`pip install scipy numpy`):

    python3 pchip_scipy.py > pchip_scipy.json

For each fixed 2-D path, the parameter s is the cumulative chord length of the nodes,
and x(s), y(s) are scipy.interpolate.PchipInterpolator(s, x) and (s, y). The JSON holds
the knots, the slopes at the nodes (first derivative at the knots), and values, first and
second derivatives at query parameters inside every piece. The Rust test
(tests/scipy.rs) compares postproc::Pchip against it to 1e-9 (relative to the magnitude
for the millimetre-scale set); it does not need Python.
"""

import json
import sys

import numpy as np
import scipy
from scipy.interpolate import PchipInterpolator

rng = np.random.default_rng(20260121)

DATASETS = {
    # Two nodes: scipy uses a straight line.
    "two_nodes": [[0.0, 0.0], [3.0, 4.0]],
    # Three nodes: both end slopes from the three-point formula.
    "three_nodes": [[0.0, 0.0], [1.0, 2.0], [3.0, 1.0]],
    # An RRT-like zigzag in cell units.
    "zigzag": [[0.5, 0.5], [3.2, 1.1], [4.0, 4.5], [7.5, 5.0], [8.0, 9.3],
               [12.1, 9.0], [13.0, 14.2], [17.7, 15.1]],
    # Monotone in both x and y (a staircase): no overshoot expected.
    "monotone_staircase": [[0.0, 0.0], [1.0, 0.2], [1.3, 2.0], [4.0, 2.1],
                           [4.2, 5.0], [9.0, 5.5], [9.1, 9.0]],
    # Axis-aligned legs with flat coordinates and extrema (zero slopes).
    "axis_aligned": [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [8.0, 4.0], [8.0, 0.0],
                     [12.0, 0.0]],
    # Sharp reversal to exercise the edge-case clamp 3 * m0.
    "edge_clamp": [[0.0, 0.0], [0.1, 1.0], [5.0, 0.5], [5.2, 3.0]],
    # Seed 000's scale: millimetres, about 6 m from start to goal.
    "seed000_mm": [[74.0, 1953.0], [580.0, 2210.0], [1250.0, 2950.0], [2100.0, 3010.0],
                   [2890.0, 2400.0], [3620.0, 1790.0], [4400.0, 1650.0], [5501.0, 1308.0]],
    # Twenty random nodes (seeded).
    "random20": np.cumsum(rng.uniform(-1.0, 3.0, size=(20, 2)), axis=0).tolist(),
}


def one(nodes):
    p = np.asarray(nodes, dtype=float)
    seg = np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1]))
    s = np.concatenate([[0.0], np.cumsum(seg)])
    fx = PchipInterpolator(s, p[:, 0])
    fy = PchipInterpolator(s, p[:, 1])
    # Seven interior points per piece (never the knots themselves).
    q = np.concatenate([s[k] + (s[k + 1] - s[k]) * np.linspace(0.05, 0.95, 7)
                        for k in range(len(s) - 1)])

    def xy(fa, fb, at, nu=0):
        return np.stack([fa(at, nu), fb(at, nu)], axis=1).tolist()

    return {
        "nodes": p.tolist(),
        "knots": s.tolist(),
        "slopes": xy(fx, fy, s, 1),
        "queries": q.tolist(),
        "values": xy(fx, fy, q),
        "d1": xy(fx, fy, q, 1),
        "d2": xy(fx, fy, q, 2),
    }


out = {
    "generator": "crates/postproc/tests/data/pchip_scipy.py",
    "scipy": scipy.__version__,
    "numpy": np.__version__,
    "datasets": {name: one(nodes) for name, nodes in DATASETS.items()},
}
json.dump(out, sys.stdout, indent=1)
sys.stdout.write("\n")
