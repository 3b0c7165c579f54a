import json
import subprocess

import numpy as np
import pytest

import hyplan
from conftest import ROOT, maze, ticks_during, write_pgm

START_CELL = (5.0, 5.0)  # x, y counted down from the top row (the CLI's picture frame)
GOAL_CELL = (74.0, 74.0)


def cli_plan(hyplan_bin, pgm, planner, seed, *extra, start=START_CELL, goal=GOAL_CELL):
    out = subprocess.run(
        [hyplan_bin, "plan", "--map", str(pgm), "--safety-radius", "0", "--json",
         "--planner", planner, "--seed", str(seed),
         "--start", "%g,%g" % start, "--goal", "%g,%g" % goal, *extra],
        capture_output=True, text=True,
    )
    assert out.returncode in (0, 3), out.stderr
    return json.loads(out.stdout.splitlines()[0])


@pytest.mark.parametrize("planner", hyplan.planners())
def test_every_planner_solves_the_maze_as_the_cli(tmp_path, hyplan_bin, planner):
    occ = maze()
    start, goal = START_CELL, GOAL_CELL
    if planner == "ga-pchip":
        # The genetic planner needs minutes on the maze: one wall instead.
        occ = np.zeros((50, 60), bool)
        occ[10:40, 30] = True
        start, goal = (5.0, 25.0), (55.0, 25.0)
    h = occ.shape[0]
    pgm = tmp_path / "maze.pgm"
    write_pgm(pgm, occ)
    rec = cli_plan(hyplan_bin, pgm, planner, 7, start=start, goal=goal)
    assert rec["solved"], rec

    # The NumPy map: world frame, y up, so the CLI's y (down from the top) is h - y.
    m = hyplan.GridMap.from_array(occ)
    r = hyplan.plan(m, (start[0], h - start[1]), (goal[0], h - goal[1]),
                    planner=planner, seed=7)
    assert r.solved
    assert r.nodes == rec["nodes"]
    assert r.iterations == rec["iterations"]
    assert r.collision_checks == rec["collision_checks"]
    assert r.length == pytest.approx(rec["length"], rel=1e-12)
    assert r.turns == rec["turns"]  # smooth="none": counted on the plan's nodes
    cli_path = np.array(rec["path"])
    assert r.path.shape == cli_path.shape
    np.testing.assert_allclose(r.path[:, 0], cli_path[:, 0], atol=1e-9)
    np.testing.assert_allclose(r.path[:, 1], h - cli_path[:, 1], atol=1e-9)

    # The same picture loaded by the bindings: the CLI's own frame, the same numbers.
    lm = hyplan.GridMap.load(pgm, safety_radius=0)
    assert lm.frame == "cells"
    r2 = hyplan.plan(lm, start, goal, planner=planner, seed=7)
    np.testing.assert_allclose(r2.path, cli_path, atol=1e-9)
    assert r2.turns == rec["turns"]


@pytest.mark.parametrize("planner", ["rrt-connect", "astar", "rrt-astar-bt"])
def test_unsmoothed_turns_and_transfer_time_match_the_cli(tmp_path, hyplan_bin, planner):
    # smooth="none" takes a short cut past the quarter-cell samples; a polyline plan
    # (rrt-connect, astar) and a curve plan (rrt-astar-bt) give the CLI's figures.
    occ = maze()
    pgm = tmp_path / "maze.pgm"
    write_pgm(pgm, occ)
    m = hyplan.GridMap.load(pgm, safety_radius=0)
    for seed in (3, 4):
        rec = cli_plan(hyplan_bin, pgm, planner, seed, "--vmax", "2", "--wmax", "1.5",
                       "--amax", "0.5")
        r = hyplan.plan(m, START_CELL, GOAL_CELL, planner=planner, seed=seed, vmax=2,
                        wmax=1.5, amax=0.5)
        np.testing.assert_allclose(r.path, np.array(rec["path"]), atol=1e-9)
        assert r.turns == rec["turns"]
        assert r.transfer_time_s == pytest.approx(rec["transfer_time_s"], rel=1e-12)
        assert r.smoothed is None
        plain = hyplan.plan(m, START_CELL, GOAL_CELL, planner=planner, seed=seed)
        assert plain.turns == rec["turns"] and plain.transfer_time_s is None


def test_repeated_calls_reuse_nothing_they_should_not():
    # `plan` keeps the configurations it made; the same call gives the same result, and a
    # change of parameter, flag or map (the default step follows the map's size) is seen.
    occ = maze()
    m = hyplan.GridMap.from_array(occ)
    big = hyplan.GridMap.from_array(np.pad(occ, ((0, 40), (0, 40))))
    args = (m, (5, 75), (74, 6))
    kw = dict(planner="rrt", seed=2, max_iterations=50000, goal_bias=0.1)
    a = hyplan.plan(*args, **kw)
    b = hyplan.plan(*args, **kw)
    assert a.nodes == b.nodes and a.iterations == b.iterations
    np.testing.assert_array_equal(a.path, b.path)
    c = hyplan.plan(*args, **{**kw, "step": 1.0})
    assert c.nodes != a.nodes
    d = hyplan.plan(*args, **{**kw, "goal_bias": 0.3})
    assert d.nodes != a.nodes
    with pytest.raises(hyplan.NoPathError) as e:
        hyplan.plan(*args, **{**kw, "max_iterations": 7})
    assert e.value.result.iterations == 7
    # The default step is 5 % of the map's diagonal: another map, another step.
    f = hyplan.plan(big, (5, 115), (74, 46), **kw)
    g = hyplan.plan(big, (5, 115), (74, 46), **{**kw, "step": 0.05 * np.hypot(120, 120)})
    assert f.nodes == g.nodes
    np.testing.assert_array_equal(f.path, g.path)
    h = hyplan.plan(*args, **{**kw, "step": 0.05 * np.hypot(80, 80)})
    np.testing.assert_array_equal(h.path, a.path)
    # A bad parameter is refused every time.
    for _ in range(2):
        with pytest.raises(ValueError, match="bogus"):
            hyplan.plan(*args, planner="rrt", bogus=1.0)


def test_flags_and_params_match_the_cli(tmp_path, hyplan_bin):
    occ = maze()
    pgm = tmp_path / "maze.pgm"
    write_pgm(pgm, occ)
    m = hyplan.GridMap.load(pgm, safety_radius=0)
    recs = subprocess.run(
        [hyplan_bin, "plan", "--map", str(pgm), "--safety-radius", "0", "--json",
         "--planner", "rrt:step=3.0", "--seed", "11", "--runs", "3", "--goal-bias", "0.2",
         "--smooth", "pchip", "--vmax", "1", "--wmax", "1", "--amax", "1",
         "--start", "5,5", "--goal", "74,74"], capture_output=True, text=True,
    ).stdout.splitlines()
    assert len(recs) == 3
    for run in range(3):
        rec = json.loads(recs[run])
        r = hyplan.plan(m, START_CELL, GOAL_CELL, planner="rrt", seed=11, run=run, step=3.0,
                        goal_bias=0.2, smooth="pchip", vmax=1, wmax=1, amax=1)
        assert r.seed == rec["seed"]
        assert r.nodes == rec["nodes"]
        np.testing.assert_allclose(r.path, np.array(rec["path"]), atol=1e-9)
        np.testing.assert_allclose(r.smoothed, np.array(rec["smoothed"]), atol=1e-9)
        assert r.transfer_time_s == pytest.approx(rec["transfer_time_s"], rel=1e-12)
        assert r.turns == rec["turns"]


def test_bad_input_raises_value_error():
    m = hyplan.GridMap.from_array(maze())
    with pytest.raises(ValueError, match="nope"):
        hyplan.plan(m, (5, 75), (74, 6), planner="nope")
    with pytest.raises(ValueError, match="bogus"):
        hyplan.plan(m, (5, 75), (74, 6), planner="rrt", bogus=1.0)
    with pytest.raises(ValueError, match="oops|max_iterations"):
        hyplan.plan(m, (5, 75), (74, 6), planner="rrt", max_iterations="oops")
    with pytest.raises(ValueError, match="start"):
        hyplan.plan(m, (0.5, 0.5), (74, 6))  # on the wall
    # Off the map: the message says where the map is.
    with pytest.raises(ValueError, match=r"outside the map \(the map spans x from 0 to 80 and y"):
        hyplan.plan(m, (500, 75), (74, 6))
    with pytest.raises(ValueError, match="goal_bias"):
        hyplan.plan(m, (5, 75), (74, 6), goal_bias=1.5)
    with pytest.raises(ValueError):
        hyplan.plan(m, (5, 75), (74, 6), vmax=1.0)
    with pytest.raises(ValueError):
        hyplan.GridMap.from_array(np.zeros((0, 3), bool))
    with pytest.raises(ValueError):
        hyplan.GridMap.from_array(np.zeros((3, 3), bool), resolution=-1)
    with pytest.raises(OSError):
        hyplan.GridMap.load("/nonexistent/map.yaml")


def test_params_set_fields_and_budget():
    m = hyplan.GridMap.from_array(maze())
    r = hyplan.plan(m, (5, 75), (74, 6), planner="rrt", step=2.0, max_iterations=100000)
    assert r.solved
    keys = dict(hyplan.planner_params("rrt"))
    assert "step" in keys and "budget.max_iterations" in keys


def test_planner_info_reads_the_registry():
    for name in hyplan.planners():
        info = hyplan.planner_info(name)
        assert info["name"] == name and info["help"]
        # The same parameters as planner_params, each with a type and a doc line.
        assert [(p["name"], p["default"]) for p in info["params"]] == hyplan.planner_params(name)
        assert all(p["type"] and p["doc"] for p in info["params"])
    assert hyplan.planner_info("astar")["deterministic"]
    assert hyplan.planner_info("safe-rrt-star")["uses_risk"]
    step = next(p for p in hyplan.planner_info("rrt:step=3")["params"] if p["name"] == "step")
    assert (step["type"], step["default"]) == ("f64", "3.0")
    with pytest.raises(ValueError):
        hyplan.planner_info("nope")


def test_no_path_error_carries_statistics():
    occ = maze()
    m = hyplan.GridMap.from_array(occ)
    with pytest.raises(hyplan.NoPathError) as e:
        hyplan.plan(m, (5, 75), (74, 6), planner="rrt", max_iter=5)
    assert e.value.kind == "budget"
    assert e.value.result.solved is False
    assert e.value.result.iterations == 5
    assert e.value.result.path.shape == (0, 2)
    # The spent budget is named, with the way to raise it.
    assert e.value.result.no_path["max_iterations"] == 5
    assert "the budget was 5 iterations" in str(e.value)
    assert "max_iter=N" in str(e.value)
    # Without max_iter the planner's rule applies: A* searches to the end and finds it.
    assert hyplan.plan(m, (5, 75), (74, 6), planner="astar").solved
    # A closed wall: proved disconnected before planning.
    occ2 = occ.copy()
    occ2[:, 20:22] = True
    with pytest.raises(hyplan.NoPathError) as e:
        hyplan.plan(hyplan.GridMap.from_array(occ2), (5, 75), (74, 6), planner="astar")
    assert e.value.kind == "disconnected"
    assert e.value.result.no_path["cause"] == "wall"


def test_zones_view_and_safety_band():
    occ = maze()
    m = hyplan.GridMap.from_array(occ, resolution=0.5, origin=(1.0, 2.0))
    z = m.zones
    assert z.dtype == np.uint8 and z.shape == occ.shape
    np.testing.assert_array_equal(z, occ.astype(np.uint8) * 2)
    assert not z.flags.writeable
    assert z.base is not None  # a view of the map's cells, not a copy
    with pytest.raises(ValueError):
        z[0, 0] = 1
    assert m.resolution == 0.5 and m.origin == (1.0, 2.0)
    b = m.with_safety_band(1.0)  # 2 cells at 0.5 per cell
    bz = b.zones
    np.testing.assert_array_equal(bz == 2, occ)
    # A free cell 2 cells from a wall is in the band, one 3 cells away is not.
    assert bz[40, 18] == 1 and bz[40, 17] == 0
    assert not b.avoids_risk and b.avoiding_risk().avoids_risk


def test_smooth_and_transfer_time():
    m = hyplan.GridMap.from_array(maze())
    r = hyplan.plan(m, (5, 75), (74, 6), planner="astar")
    c = hyplan.smooth(r.path, m, "pchip")
    assert c.shape[1] == 2 and len(c) >= 2
    np.testing.assert_allclose(c[0], r.path[0])
    np.testing.assert_allclose(c[-1], r.path[-1])
    # Two legs of 4 + 1 s and a quarter turn of 1 s (postproc's doc example).
    t = hyplan.transfer_time(np.array([[0.0, 0], [4, 0], [4, 4]]), 1.0, np.pi / 2, 1.0)
    assert t == pytest.approx(11.0, abs=1e-12)
    with pytest.raises(ValueError):
        hyplan.smooth(r.path, m, "spline-of-doom")
    with pytest.raises(ValueError):
        hyplan.transfer_time(np.zeros((3, 2)), -1.0, 1.0, 1.0)


def test_gil_is_released_while_planning():
    # A large open map and Dijkstra: long enough that a Python thread gets many turns
    # if (and only if) the plan runs without the GIL (5.8 million cells: about 0.1 s
    # since Dijkstra's open list became buckets; 1,200 x 1,200 took 0.03 s).
    n = 2400
    m = hyplan.GridMap.from_array(np.zeros((n, n), bool))
    r, during = ticks_during(
        lambda: hyplan.plan(m, (1, 1), (n - 1, n - 1), planner="dijkstra", max_iter=10**9)
    )
    assert r.solved
    assert r.time_s > 0.05, "plan too quick to tell"
    assert during > 1000, f"the counter thread ran {during} times during a {r.time_s:.3f} s plan"


def test_scenario_run_gives_harness_records():
    path = ROOT / "scenarios" / "001-grid100.ron"
    recs = hyplan.scenario.run(path, runs=2)
    again = hyplan.scenario.run(path, runs=2)
    assert len(recs) >= 2 and len(recs) % 2 == 0
    for a, b in zip(recs, again):
        assert a["planner"] == b["planner"] and a["seed"] == b["seed"]
        assert a["length"] == b["length"] or (a["length"] != a["length"])  # NaN unsolved
        for k in ("run", "success", "time_s", "nodes", "turns", "explored"):
            assert k in a
    with pytest.raises(OSError):
        hyplan.scenario.run("/nonexistent.ron")
