"""Load the TurtleBot3 world (a ROS map_server map), plan with three planners, plot them.

Run from the crate directory after `pip install . matplotlib`:
    python examples/ros_three_planners.py
writes examples/ros_three_planners.png.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import hyplan  # noqa: E402

HERE = Path(__file__).resolve().parent
MAP = HERE.parents[2] / "data" / "ros_maps" / "turtlebot3_world" / "map.yaml"

m = hyplan.GridMap.load(MAP)  # metres, y up (the map's own frame)
start, goal = (-1.8, -0.5), (1.8, 0.5)
(x0, y0), res = m.origin, m.resolution
extent = (x0, x0 + m.width * res, y0, y0 + m.height * res)

fig, ax = plt.subplots(figsize=(6, 6))
ax.imshow(m.zones, cmap="Greys", vmin=0, vmax=2, extent=extent, interpolation="nearest")
for planner, colour in [("rrt-connect", "tab:blue"), ("astar", "tab:orange"),
                        ("theta-star", "tab:green")]:
    r = hyplan.plan(m, start, goal, planner=planner, seed=1, max_iter=10**7)
    label = f"{planner}: {r.length:.2f} m, {r.time_s * 1e3:.1f} ms"
    print(label)
    ax.plot(r.path[:, 0], r.path[:, 1], color=colour, lw=2, label=label)
ax.plot(*start, "o", color="red")
ax.plot(*goal, "*", color="red", ms=12)
ax.set_xlim(-2.6, 2.6)
ax.set_ylim(-2.6, 2.6)
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.set_title("TurtleBot3 world: three hyplan planners")
ax.legend(loc="lower left", fontsize=8)
fig.tight_layout()
fig.savefig(HERE / "ros_three_planners.png", dpi=80)
