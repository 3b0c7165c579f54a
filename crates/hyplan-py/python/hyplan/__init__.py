"""hyplan: 2-D path planning for mobile robots, the Rust planners of hyplan from NumPy.

Coordinates are in the map's input frame, as on ``hyplan plan``: world units with y up
for maps made with ``GridMap.from_array`` and ROS YAML maps; cells with y counted down
from the top row for pictures and MovingAI ``.map`` files.
"""

from . import bench, scenario
from ._hyplan import (
    GridMap,
    PlanResult,
    Sim,
    plan,
    planner_info,
    planner_params,
    planners,
    smooth,
    transfer_time,
)


class NoPathError(RuntimeError):
    """No path was found; ``.result`` is the ``PlanResult`` with the run's statistics
    (nodes, iterations, time) and ``.result.no_path`` says why."""

    def __init__(self, message, result):
        super().__init__(message)
        self.result = result

    @property
    def kind(self):
        """``"disconnected"``, ``"exhausted"``, ``"budget"`` or ``"invalid"``."""
        return self.result.no_path["kind"]


__all__ = [
    "GridMap",
    "NoPathError",
    "PlanResult",
    "Sim",
    "bench",
    "plan",
    "planner_info",
    "planner_params",
    "planners",
    "scenario",
    "smooth",
    "transfer_time",
]
