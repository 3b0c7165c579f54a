"""Bindings overhead: wall time of hyplan.plan minus the Rust planner's own time (r.time_s).

Small maps (100 x 100 and 200 x 200, one wall): 1000 calls per planner, median and 90th
percentile of the per-call overhead. Large map (1000 x 1000, one wall): 7 calls per planner, the overhead as a
share of the planner's time. `python examples/bench_overhead.py [CALLS]`
"""
import statistics
import sys
import time

import numpy as np

import hyplan


def wall_map(n):
    occ = np.zeros((n, n), bool)
    occ[n // 10 : n * 9 // 10, n // 2] = True
    return hyplan.GridMap.from_array(occ)


def calls(m, start, goal, planner, count, **kw):
    """(wall s, planner s) of `count` calls, seeds 0..count-1."""
    rows = []
    for s in range(count):
        t0 = time.perf_counter()
        r = hyplan.plan(m, start, goal, planner=planner, seed=s, **kw)
        w = time.perf_counter() - t0
        rows.append((w, r.time_s))
    return rows


def small(n, count):
    m = wall_map(n)
    start, goal = (0.05 * n, 0.5 * n), (0.95 * n, 0.5 * n)
    for planner in ["rrt-connect", "astar"]:
        calls(m, start, goal, planner, 50)  # warm-up
        rows = calls(m, start, goal, planner, count)
        ov = sorted(w - t for w, t in rows)
        med = statistics.median(ov)
        p90 = ov[int(0.9 * len(ov))]
        wall = statistics.median(w for w, _ in rows)
        rust = statistics.median(t for _, t in rows)
        print(f"{n} x {n}, {count} calls, {planner}: python wall {wall*1e3:.3f} ms, "
              f"rust planner {rust*1e3:.3f} ms, overhead per call median "
              f"{med*1e3:.4f} ms (p90 {p90*1e3:.4f} ms)")


def large():
    n = 1000
    m = wall_map(n)
    for planner in ["astar", "rrt-connect"]:
        rows = calls(m, (10, 500), (990, 500), planner, 7, max_iter=10**9)
        wall = statistics.median(w for w, _ in rows)
        rust = statistics.median(t for _, t in rows)
        ov = statistics.median(w - t for w, t in rows)
        pct = statistics.median((w - t) / t for w, t in rows)
        print(f"{n} x {n}, 7 calls, {planner}: python wall {wall*1e3:.2f} ms, rust planner "
              f"{rust*1e3:.2f} ms, overhead {ov*1e3:.3f} ms ({pct*100:.2f} %)")


if __name__ == "__main__":
    for n in (100, 200):
        small(n, int(sys.argv[1]) if len(sys.argv) > 1 else 1000)
    large()
