"""hyplan.Sim (seed 004's robot driven from Python) and hyplan.gym.NavEnv (hyplan/Nav-v0)."""

import math
import os
import time

import numpy as np
import pytest

import hyplan
from conftest import ROOT, ticks_during

SCENARIO3 = ROOT / "scenarios" / "sim" / "3-person.ron"

HALL = {
    "name": "hall",
    "world": {
        "size": [6.0, 3.0],
        "shapes": [{"Box": {"center": [4.5, 1.5], "size": [0.4, 0.4]}}],
    },
    "start": [0.5, 1.5],
    "goal": [5.5, 1.5],
}


def test_sim_drives_a_scenario_file_and_observes():
    sim = hyplan.Sim(SCENARIO3, seed=1)
    first = sim.observation()
    assert first["t"] == 0.0
    assert first["ranges"].dtype == np.float32 and first["ranges"].shape == (720,)
    assert first["goal_distance"] == pytest.approx(11.0)
    assert sim.period == pytest.approx(0.1)
    for _ in range(50):
        o = sim.step(0.3, 0.0)
    assert o["t"] == pytest.approx(5.0)
    # 0.3 m/s reached at the robot's acceleration: nearly 1.5 m in 5 s.
    assert 1.3 < o["pose"][0] - 3.0 < 1.5
    assert o["goal_distance"] == pytest.approx(14.0 - o["pose"][0], abs=1e-9)
    assert o["velocity"][0] == pytest.approx(0.3)
    assert not o["contacts"]["static"] and o["contacts"]["people"] == []
    assert o["clearance"] > 1.0
    # The walls of the 22 m hall are all within the 60 m range: every beam hits.
    assert np.all(np.isfinite(o["ranges"])) and o["ranges"].min() > 0.1
    assert o["people"].shape == (1, 3)


def test_sim_from_a_dict_and_contacts():
    sim = hyplan.Sim(HALL, seed=3)
    assert sim.name == "hall" and sim.goal == (5.5, 1.5)
    hit = None
    for k in range(200):
        o = sim.step(0.3, 0.0)
        if o["contacts"]["static"]:
            hit = k
            break
    # The box's near face is at x = 4.3: the body (radius 0.178) meets it near x = 4.12.
    assert hit is not None, "drove through the box without a contact"
    assert o["clearance"] < 0.0
    assert 4.1 < o["pose"][0] < 4.2


def test_sim_is_deterministic_under_its_seed_and_resets():
    a, b, c = hyplan.Sim(SCENARIO3, seed=5), hyplan.Sim(SCENARIO3, seed=5), hyplan.Sim(SCENARIO3, seed=6)
    for k in range(30):
        oa, ob, oc = (s.step(0.2, 0.3 * math.sin(k / 5)) for s in (a, b, c))
    assert np.array_equal(oa["ranges"], ob["ranges"])
    assert np.array_equal(oa["pose"], ob["pose"])
    assert not np.array_equal(oa["ranges"], oc["ranges"])
    start = a.reset()
    assert start["t"] == 0.0 and np.allclose(start["pose"], [3.0, 5.5, 0.0])
    again = [a.step(0.2, 0.3 * math.sin(k / 5))["ranges"] for k in range(30)][-1]
    assert np.array_equal(again, ob["ranges"])
    assert a.reset(seed=6)["t"] == 0.0 and a.seed == 6


def test_sim_tracks_the_crossing_person():
    sim = hyplan.Sim(SCENARIO3, seed=1)
    seen = 0
    for _ in range(250):
        o = sim.step(0.3, 0.0)
        seen = max(seen, len(o["tracked"]))
    assert o["tracked"].shape[1] == 5
    assert seen >= 1, "the tracker never followed the person crossing in front"
    quiet = hyplan.Sim(SCENARIO3, seed=1, track_people=False)
    for _ in range(250):
        assert len(quiet.step(0.3, 0.0)["tracked"]) == 0


def test_sim_run_is_the_built_in_stack_and_releases_the_gil():
    sim = hyplan.Sim(SCENARIO3, seed=0)
    out, during = ticks_during(sim.run)
    assert out["reached"] and out["contacts_at_fault"] == 0
    assert out["track"].shape[1] == 6 and out["track"][-1, 0] == pytest.approx(out["end_time"], abs=0.03)
    assert during > 100, f"the counter thread ran {during} times during the run"


def test_sim_places_a_crowd_on_a_map():
    house = ROOT / "scenarios" / "sim" / "nav-aws_small_house.ron"
    sim = hyplan.Sim(house, seed=2, crowd=4.0)
    first = sim.observation()
    # 4 per 100 m^2 of the 108 m^2 floor a person fits on, as `hyplan sim --crowd 4`.
    assert first["people"].shape == (4, 3)
    # The crowd robot's 270-degree scanner, at seed 004's angle between beams.
    assert sim.laser["angle_min"] == pytest.approx(-math.radians(135.0))
    again = hyplan.Sim(house, seed=2, crowd=4.0).observation()
    np.testing.assert_array_equal(first["people"], again["people"])
    with pytest.raises(ValueError, match="crowd = -1: density = -1: must be finite"):
        hyplan.Sim(house, crowd=-1.0)
    with pytest.raises(ValueError, match="no map"):
        hyplan.Sim(HALL, crowd=1.0)


def test_sim_errors_name_the_input():
    with pytest.raises(OSError, match="no-such.ron"):
        hyplan.Sim("no-such.ron")
    with pytest.raises(ValueError, match="colour"):
        hyplan.Sim({**HALL, "colour": "red"})
    with pytest.raises(ValueError, match="laser.beams"):
        hyplan.Sim({**HALL, "laser": {"beams": 0}})
    with pytest.raises(ValueError, match="finite"):
        hyplan.Sim(HALL).step(float("nan"), 0.0)
    with pytest.raises(ValueError, match="built in"):
        hyplan._hyplan._builtin_scenario("nope")


# CI (HYPLAN_REQUIRE_TOOLS=1) installs Gymnasium: there a missing one fails, not skips.
if os.environ.get("HYPLAN_REQUIRE_TOOLS") == "1":
    import gymnasium as gym
else:
    gym = pytest.importorskip("gymnasium")


def test_nav_env_passes_gymnasiums_check_env():
    import hyplan.gym
    from gymnasium.utils.env_checker import check_env

    env = hyplan.gym.NavEnv()
    check_env(env, skip_render_check=True)
    made = gym.make("hyplan/Nav-v0")
    assert isinstance(made.unwrapped, hyplan.gym.NavEnv)
    check_env(made.unwrapped, skip_render_check=True)


def test_nav_env_reaches_the_goal_with_a_simple_policy():
    import hyplan.gym

    env = gym.make("hyplan/Nav-v0")
    obs, info = env.reset(seed=1)
    assert obs["scan"].shape == (720,) and obs["goal"][0] == pytest.approx(11.0)
    total, steps = 0.0, 0
    while True:
        distance, bearing = obs["goal"]
        obs, reward, terminated, truncated, info = env.step(np.array([0.3, 1.5 * bearing], np.float32))
        total += reward
        steps += 1
        if terminated or truncated:
            break
    sim = env.unwrapped.sim.observation()
    assert terminated and not truncated and sim["reached"], sim
    # Progress (10.7 m) + goal bonus - 0.01 a step: the reward adds up.
    assert total == pytest.approx(11.0 - sim["goal_distance"] + 1.0 - 0.01 * steps, abs=1e-6)
    assert 350 < steps < 380  # 10.7 m at 0.3 m/s


def test_nav_env_terminates_on_contact_and_is_deterministic():
    import hyplan.gym

    env = hyplan.gym.NavEnv(HALL)
    runs = []
    for _ in range(2):
        obs, _ = env.reset(seed=9)
        scans = []
        while True:
            obs, reward, terminated, truncated, _ = env.step(np.array([0.3, 0.0], np.float32))
            scans.append(obs["scan"])
            if terminated or truncated:
                break
        runs.append(scans)
    assert terminated and reward < -0.9  # the contact's penalty
    assert len(runs[0]) == len(runs[1])
    assert all(np.array_equal(a, b) for a, b in zip(*runs))


@pytest.mark.skipif(getattr(hyplan._hyplan, "_debug_build", False), reason="timing needs a release build")
def test_nav_env_steps_per_second():
    """The issue's figure: steps per second of hyplan/Nav-v0 (gymnasium.make, laser at 40 Hz,
    720 beams), printed; asserted only against a floor a loaded CI machine keeps."""
    import hyplan.gym

    env = gym.make("hyplan/Nav-v0")
    env.reset(seed=1)
    action = np.array([0.3, 0.2], np.float32)
    n = 3000
    t0 = time.process_time()
    for _ in range(n):
        _, _, terminated, truncated, _ = env.step(action)
        if terminated or truncated:
            env.reset()
    rate = n / (time.process_time() - t0)
    print(f"hyplan/Nav-v0: {rate:,.0f} steps per second of CPU time")
    assert rate > 2000
