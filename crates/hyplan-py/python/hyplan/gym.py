"""A Gymnasium environment of seed 004's robot: ``hyplan.gym.NavEnv``, registered as
``hyplan/Nav-v0`` when this module is imported.

.. code-block:: python

    import gymnasium
    import hyplan.gym  # registers hyplan/Nav-v0

    env = gymnasium.make("hyplan/Nav-v0")
    obs, info = env.reset(seed=1)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

The robot drives a scenario of ``hyplan sim`` (by default seed 004's scenario 3: a 22 x
22 m hall where a person walks across the 11 m route) from its start toward its goal.

**Step.** One control period of the scenario (0.1 s by default). The laser fires at its
own rate meanwhile (40 Hz: four scans a step), people walk, the robot reaches the command
at its own accelerations. No map is built and no planner runs.

**Action.** ``Box([0, -omega_max], [v_max, omega_max])``, float32: forward speed (m/s,
the robot drives forward only, as its 180-degree laser looks forward) and turn rate
(rad/s, positive left). Values outside are clipped.

**Observation.** A ``Dict``, every entry float32:

- ``scan``: ``(beams,)`` the latest scan's ranges (m), in ``[0, range_max]``: a beam that
  met nothing within range reads ``range_max``, one closer than the shortest range
  reads 0;
- ``goal``: ``(2,)`` the goal's distance (m) and bearing (rad, from the heading, in
  ``[-pi, pi]``);
- ``velocity``: ``(2,)`` the command in force, ``v`` and ``omega``.

**Reward.** The progress toward the goal this step (m; negative when moving away), minus
0.01 per step; plus 1 when the goal is reached; minus 1 on a contact (the body overlapping
a wall, a piece of furniture or a person on any laser tick of the step).

**Termination.** The goal reached (within the scenario's goal tolerance, 0.3 m) or a
contact. **Truncation:** the scenario's time limit (120 s: 1,200 steps).

``info`` is empty; ``env.unwrapped.sim.observation()`` is the simulator's own observation
(``hyplan.Sim.step``'s dict: pose, REP 117 ranges, true people, contacts, clearance). The
people tracker does not run (the observation has no tracks).
"""

from __future__ import annotations

import math
from typing import Any, Optional

import numpy as np

try:
    import gymnasium
    from gymnasium import spaces
except ImportError as e:  # pragma: no cover - the message is the point
    raise ImportError(
        "hyplan.gym needs Gymnasium: pip install 'hyplan[gym]' (or pip install gymnasium)"
    ) from e

from ._hyplan import Sim, _builtin_scenario

#: The scenario ``hyplan/Nav-v0`` drives: seed 004's scenario 3 (``scenarios/sim/3-person.ron``).
DEFAULT_SCENARIO = "004-nav-3-person"

STEP_COST = 0.01
GOAL_REWARD = 1.0
CONTACT_PENALTY = 1.0


class NavEnv(gymnasium.Env):
    """Seed 004's robot driving a scenario of ``hyplan sim`` toward its goal.

    ``scenario``: a scenario file (RON) or dict of ``hyplan sim``, or None for the
    default. ``seed`` passed to ``reset`` seeds the laser noise. See the module's doc for
    the spaces, reward and termination.
    """

    metadata = {"render_modes": []}

    def __init__(self, scenario: Any = None, render_mode: Optional[str] = None):
        if render_mode is not None:
            raise ValueError(f"render_mode {render_mode!r}: NavEnv does not render")
        if scenario is None:
            self._sim = Sim.from_ron(_builtin_scenario(DEFAULT_SCENARIO), track_people=False)
        else:
            self._sim = Sim(scenario, track_people=False)
        laser = self._sim.laser
        robot = self._sim.robot
        self._range_max = np.float32(laser["range_max"])
        self._v_max = robot["v_max"]
        self._omega_max = robot["omega_max"]
        f32 = np.float32
        self.action_space = spaces.Box(
            low=np.array([0.0, -self._omega_max], dtype=f32),
            high=np.array([self._v_max, self._omega_max], dtype=f32),
            dtype=f32,
        )
        self.observation_space = spaces.Dict(
            {
                "scan": spaces.Box(0.0, self._range_max, (laser["beams"],), dtype=f32),
                "goal": spaces.Box(
                    low=np.array([0.0, -math.pi], dtype=f32),
                    high=np.array([np.inf, math.pi], dtype=f32),
                    dtype=f32,
                ),
                "velocity": spaces.Box(
                    low=np.array([0.0, -self._omega_max], dtype=f32),
                    high=np.array([self._v_max, self._omega_max], dtype=f32),
                    dtype=f32,
                ),
            }
        )
        self._distance = 0.0

    @property
    def sim(self) -> Sim:
        """The simulator underneath: ``env.unwrapped.sim.observation()`` is the full
        observation of ``hyplan.Sim.step`` (pose, REP 117 ranges, people, contacts)."""
        return self._sim

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        super().reset(seed=seed)
        if seed is None:
            seed = int(self.np_random.integers(0, 2**63 - 1))
        self._sim.reset(seed=seed)
        scan, goal, velocity, self._distance, _, _, _ = self._sim._observe_gym()
        return {"scan": scan, "goal": goal, "velocity": velocity}, {}

    def step(self, action):
        # The action is clipped to the box in Rust, with the step.
        scan, goal, velocity, d, contact, reached, timed_out = self._sim._step_gym(action)
        reward = self._distance - d - STEP_COST
        self._distance = d
        if reached:
            reward += GOAL_REWARD
        if contact:
            reward -= CONTACT_PENALTY
        terminated = reached or contact
        obs = {"scan": scan, "goal": goal, "velocity": velocity}
        return obs, reward, terminated, timed_out and not terminated, {}


gymnasium.register(id="hyplan/Nav-v0", entry_point="hyplan.gym:NavEnv")

__all__ = ["DEFAULT_SCENARIO", "NavEnv"]
