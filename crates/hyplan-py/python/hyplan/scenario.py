"""Scenario files (RON) run as the harness runs them."""

from os import PathLike
from typing import Optional, Union

from ._hyplan import run_scenario as _run


def run(path: Union[str, PathLike], runs: Optional[int] = None) -> list:
    """Runs every planner of the scenario at ``path`` (``runs`` per planner, default the
    scenario's own) and returns one dict per run: the harness's ``RunMetrics`` fields
    (``run``, ``seed``, ``success``, ``time_s``, ``length``, ``nodes``, ``turns``,
    ``explored``, ...) plus ``planner``, the planner's label."""
    return _run(path, runs)
