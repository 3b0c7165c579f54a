"""A grid planner's calls on one map: the first prepares the search, the map keeps it,
and the later calls cost only their search (issue 31's short query).

    pip install ./crates/hyplan-py numpy
    python crates/hyplan-py/examples/kept_search.py [--size 2048] [--calls 5]

Rooms of 64 cells with a door in each wall; the query from (10.5, 11.5) to (13.5, 12.5),
each call timed with time.perf_counter around hyplan.plan.
"""

import argparse
import time

import numpy as np

import hyplan


def rooms(n: int) -> np.ndarray:
    """An n x n grid (1 = wall) with a wall every 64 cells and a door in each."""
    a = np.zeros((n, n), dtype=np.uint8)
    wall = np.ones(n, dtype=np.uint8)
    wall[32::64] = 0
    for k in range(64, n, 64):
        a[k, :] = wall
        a[:, k] = wall
    return a


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=2048)
    parser.add_argument("--calls", type=int, default=5)
    args = parser.parse_args()
    m = hyplan.GridMap.from_array(rooms(args.size))
    for planner in ["jps", "astar", "dijkstra"]:
        times = []
        for _ in range(args.calls):
            t = time.perf_counter()
            r = hyplan.plan(m, (10.5, 11.5), (13.5, 12.5), planner=planner)
            times.append((time.perf_counter() - t) * 1e3)
        print(f"{planner}: " + " / ".join(f"{x:.3f}" for x in times) + f" ms a call ({r.nodes} nodes)")


if __name__ == "__main__":
    main()
