from . import bench as bench
from . import scenario as scenario
from ._hyplan import (
    GridMap as GridMap,
    PlanResult as PlanResult,
    Sim as Sim,
    plan as plan,
    planner_info as planner_info,
    planner_params as planner_params,
    planners as planners,
    smooth as smooth,
    transfer_time as transfer_time,
)

class NoPathError(RuntimeError):
    result: PlanResult
    def __init__(self, message: str, result: PlanResult) -> None: ...
    @property
    def kind(self) -> str: ...
