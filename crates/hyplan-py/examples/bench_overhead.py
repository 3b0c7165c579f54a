"""Bindings overhead: wall time of hyplan.plan vs the Rust planner's own time on 1000 x 1000."""
import time, statistics, numpy as np, hyplan
n = 1000
occ = np.zeros((n, n), bool); occ[100:900, 500] = True
m = hyplan.GridMap.from_array(occ)
for planner in ["astar", "rrt-connect"]:
    rows = []
    for s in range(7):
        t0 = time.perf_counter(); r = hyplan.plan(m, (10, 500), (990, 500), planner=planner, seed=s, max_iter=10**9); w = time.perf_counter() - t0
        rows.append((w, r.time_s))
    wall = statistics.median(w for w, _ in rows); rust = statistics.median(t for _, t in rows)
    ov = statistics.median((w - t) / t for w, t in rows)
    print(f"{planner}: python wall {wall*1e3:.2f} ms, rust planner {rust*1e3:.2f} ms, median overhead {ov*100:.2f} %")
