"""The bindings' own cost per `hyplan.plan` call: the call's wall time minus the planner's
own time (`r.time_s`), over 1000 calls on a small map."""
import statistics
import time

import numpy as np
import pytest

import hyplan

CALLS = 1000
# Measured 0.01-0.03 ms (2-core shared machine, median over 1000 calls; README,
# "Measurements"); the bindings used to cost 0.1-0.14 ms on the 100 x 100 map and
# 0.25 ms on the 200 x 200 one, the quarter-cell post-processing of smooth="none".
BOUND_S = 0.1e-3


def wall_map(n):
    occ = np.zeros((n, n), bool)
    occ[n // 10 : n * 9 // 10, n // 2] = True  # one wall across the straight line
    return hyplan.GridMap.from_array(occ)


@pytest.mark.skipif(getattr(hyplan._hyplan, "_debug_build", False),
                    reason="timings of a debug build (maturin develop without --release)")
@pytest.mark.parametrize("n,planner", [(100, "rrt-connect"), (100, "astar"),
                                       (200, "rrt-connect")])
def test_overhead_per_call_is_under_a_tenth_of_a_millisecond(n, planner):
    m = wall_map(n)
    start, goal = (0.05 * n, 0.5 * n), (0.95 * n, 0.5 * n)
    for s in range(50):  # warm-up: caches, allocator
        hyplan.plan(m, start, goal, planner=planner, seed=s)
    overhead = []
    for s in range(CALLS):
        t0 = time.perf_counter()
        r = hyplan.plan(m, start, goal, planner=planner, seed=s)
        wall = time.perf_counter() - t0
        assert r.solved
        overhead.append(wall - r.time_s)
    med = statistics.median(overhead)  # the machine is noisy: the median, not the mean
    print(f"{n} x {n} {planner}: overhead per call, median of {CALLS}: {med * 1e3:.4f} ms")
    assert med <= BOUND_S, (
        f"{n} x {n} {planner}: median overhead {med * 1e3:.4f} ms per call "
        f"> {BOUND_S * 1e3} ms"
    )
