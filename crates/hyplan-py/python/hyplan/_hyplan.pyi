"""Type stubs of the native module (re-exported by ``hyplan``)."""

from os import PathLike
from typing import Any, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, "PathLike[str]"]

class GridMap:
    """An occupancy grid with zones (0 free, 1 high-risk, 2 forbidden). Immutable."""

    @staticmethod
    def from_array(
        occupied: npt.ArrayLike,
        resolution: float = 1.0,
        origin: Tuple[float, float] = (0.0, 0.0),
    ) -> "GridMap":
        """A map from ``occupied[row, col]`` (row 0 on top); a bool array is read in
        place, the zones are its one copy. Coordinates: world units, y up."""
    @staticmethod
    def load(
        path: _Path,
        threshold: int = 100,
        safety_radius: Optional[float] = None,
        invert: bool = False,
        unknown_free: bool = False,
        max_cells: int = 100_000_000,
    ) -> "GridMap":
        """Loads a picture, a ROS ``.yaml`` or a MovingAI ``.map`` as ``hyplan plan``."""
    def with_safety_band(self, radius: float) -> "GridMap":
        """The same map with a high-risk band of ``radius`` (input units)."""
    def avoiding_risk(self) -> "GridMap":
        """The same map with the high-risk band blocked too."""
    @property
    def zones(self) -> npt.NDArray[np.uint8]:
        """Read-only view ``[row, col]`` (row 0 on top) of the zones, no copy."""
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def resolution(self) -> float: ...
    @property
    def origin(self) -> Tuple[float, float]: ...
    @property
    def frame(self) -> str:
        """``"world"`` (y up), ``"cells"`` (y down from the top row) or ``"map"``."""
    @property
    def avoids_risk(self) -> bool: ...

class PlanResult:
    """One plan's outcome."""

    planner: str
    seed: int
    solved: bool
    path: npt.NDArray[np.float64]
    length: float
    time_s: float
    nodes: int
    iterations: int
    collision_checks: int
    smoothed: Optional[npt.NDArray[np.float64]]
    turns: Optional[int]
    transfer_time_s: Optional[float]
    no_path: Optional[dict]

def plan(
    map: GridMap,
    start: Tuple[float, float],
    goal: Tuple[float, float],
    planner: str = "rrt-connect",
    seed: int = 0,
    *,
    run: int = 0,
    step: Optional[float] = None,
    goal_bias: float = 0.05,
    goal_radius: float = 0.0,
    max_iter: Optional[int] = None,
    time_limit: Optional[float] = None,
    smooth: str = "none",
    vmax: Optional[float] = None,
    wmax: Optional[float] = None,
    amax: Optional[float] = None,
    **params: Any,
) -> PlanResult:
    """Plans as ``hyplan plan --seed seed`` run ``run``; raises ``ValueError`` for bad
    input and ``hyplan.NoPathError`` (with ``.result``) when no path is found."""

def smooth(
    path: npt.ArrayLike, map: GridMap, method: str = "pchip"
) -> npt.NDArray[np.float64]:
    """The checked smoothed curve of ``path``, in the map's input frame."""

def transfer_time(path: npt.ArrayLike, vmax: float, wmax: float, amax: float) -> float:
    """Rest-to-rest time (s) to follow the polyline ``path``."""

def run_scenario(path: _Path, runs: Optional[int] = None) -> list: ...
def planners() -> list[str]:
    """The planner names ``plan`` accepts."""

def planner_params(name: str) -> list[Tuple[str, str]]:
    """``(key, default)`` pairs (RON text) of a planner."""

def planner_info(name: str) -> dict:
    """A planner's help line, capabilities (``family``, ``grid_only``, ``uses_risk``,
    ``has_step``, ``wants_default_step``, ``goal_bias``, ``own_goal_radius``,
    ``deterministic``) and ``params``: dicts of ``name``, ``type``, ``default`` (RON text)
    and ``doc``."""

class Sim:
    """Seed 004's robot in a scenario of ``hyplan sim``, driven one control period at a
    time. ``step`` returns a dict: ``t``, ``pose`` ``[x, y, phi]``, ``velocity`` ``[v,
    omega]``, ``ranges`` (float32, REP 117), ``tracked`` ``(K, 5)`` ``x, y, vx, vy,
    radius``, ``people`` ``(M, 3)`` ``x, y, radius``, ``contacts`` ``{"static": bool,
    "people": [int]}``, ``clearance``, ``goal_distance``, ``goal_bearing``, ``reached``,
    ``timed_out``."""

    def __init__(
        self,
        scenario: Union[_Path, dict],
        seed: int = 0,
        track_people: bool = True,
        crowd: Optional[float] = None,
    ) -> None:
        """``crowd``: people per 100 m^2 added to the scenario's map, as ``hyplan sim
        --crowd`` adds them (drawn from ``seed``)."""
    @staticmethod
    def from_ron(
        text: str, seed: int = 0, track_people: bool = True, crowd: Optional[float] = None
    ) -> "Sim": ...
    def reset(self, seed: Optional[int] = None) -> dict:
        """Back to the start (with a new seed if given); the first observation."""
    def step(self, v: float, omega: float) -> dict:
        """One control period commanding ``v`` (m/s) and ``omega`` (rad/s)."""
    def observation(self) -> dict: ...
    def run(self) -> dict:
        """The built-in stack from the start, as ``hyplan sim``: ``summary.json`` as a
        dict, with ``track`` ``(N, 6)``: ``t, x, y, phi, v, omega``."""
    @property
    def period(self) -> float: ...
    @property
    def name(self) -> str: ...
    @property
    def seed(self) -> int: ...
    @property
    def goal(self) -> Tuple[float, float]: ...
    @property
    def time_limit(self) -> float: ...
    @property
    def laser(self) -> dict:
        """``beams``, ``angle_min``, ``angle_increment``, ``range_min``, ``range_max``,
        ``rate_hz``."""
    @property
    def robot(self) -> dict:
        """``body_radius``, ``v_max``, ``omega_max``, ``acc_v``, ``acc_omega``."""

def _builtin_scenario(name: str) -> str: ...
