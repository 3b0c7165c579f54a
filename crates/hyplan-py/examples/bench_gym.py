"""Steps per second of hyplan/Nav-v0 and of hyplan.Sim on one core.

    python crates/hyplan-py/examples/bench_gym.py [--steps N] [--repeats R]

A step is one control period (0.1 s of scenario 3: 20 ticks, four 720-beam scans with
noise). Prints the median and the range over the repeats, on CPU time of this process
(one thread: the machine's other core may be busy) and on wall time.
"""

import argparse
import statistics
import time

import numpy as np


def rate(step, reset, steps):
    reset()
    c0, w0 = time.process_time(), time.perf_counter()
    for _ in range(steps):
        if step():
            reset()
    c, w = time.process_time() - c0, time.perf_counter() - w0
    return steps / c, steps / w


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=5000)
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args()

    import gymnasium

    import hyplan
    import hyplan.gym

    env = gymnasium.make("hyplan/Nav-v0")
    # A slow turn: the robot circles in the hall (no contact, no goal) for the whole run.
    action = np.array([0.3, 0.2], np.float32)

    def env_step():
        _, _, terminated, truncated, _ = env.step(action)
        return terminated or truncated

    sim = hyplan.Sim.from_ron(hyplan._hyplan._builtin_scenario(hyplan.gym.DEFAULT_SCENARIO), seed=1)

    def sim_step():
        return sim.step(0.3, 0.2)["timed_out"]

    cases = [
        ("gymnasium.make('hyplan/Nav-v0').step", env_step, lambda: env.reset(seed=1)),
        ("hyplan.Sim.step (observation dict, tracker on)", sim_step, lambda: sim.reset(seed=1)),
    ]
    for name, step, reset in cases:
        rates = [rate(step, reset, args.steps) for _ in range(args.repeats)]
        cpu = sorted(r[0] for r in rates)
        wall = sorted(r[1] for r in rates)
        print(
            f"{name}: {statistics.median(cpu):,.0f} steps/s on CPU time "
            f"({cpu[0]:,.0f}-{cpu[-1]:,.0f}), {statistics.median(wall):,.0f} on wall time "
            f"({wall[0]:,.0f}-{wall[-1]:,.0f}); {args.repeats} x {args.steps} steps"
        )


if __name__ == "__main__":
    main()
