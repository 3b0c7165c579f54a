import os
import shutil
import threading
import time
from pathlib import Path

import numpy as np
import pytest

CRATE = Path(__file__).resolve().parents[1]
ROOT = CRATE.parents[1]


def maze(n=80):
    """A deterministic maze: vertical walls with gaps alternately at the top and bottom."""
    occ = np.zeros((n, n), dtype=bool)
    occ[0, :] = occ[-1, :] = occ[:, 0] = occ[:, -1] = True
    for k, x in enumerate(range(n // 4, n - 1, n // 4)):
        occ[:, x : x + 2] = True
        if k % 2 == 0:
            occ[2:12, x : x + 2] = False  # gap near the top row
        else:
            occ[n - 12 : n - 2, x : x + 2] = False
    return occ


def write_pgm(path, occ):
    h, w = occ.shape
    pix = np.where(occ, 0, 255).astype(np.uint8)
    with open(path, "wb") as f:
        f.write(b"P5\n%d %d\n255\n" % (w, h))
        f.write(pix.tobytes())


@pytest.fixture(scope="session")
def hyplan_bin():
    """The CLI: $HYPLAN_BIN, else the workspace's target/{release,debug}/hyplan."""
    env = os.environ.get("HYPLAN_BIN")
    if env:
        return env
    for prof in ("release", "debug"):
        p = ROOT / "target" / prof / "hyplan"
        if p.exists():
            return str(p)
    found = shutil.which("hyplan")
    if found:
        return found
    pytest.fail("no hyplan CLI: build it (cargo build -p hyplan) or set HYPLAN_BIN")


def ticks_during(call):
    """``call()``'s result and how many times a Python thread counted meanwhile: many
    counts if (and only if) the call runs without the GIL."""
    ticks = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks[0] += 1

    t = threading.Thread(target=count)
    t.start()
    time.sleep(0.05)
    before = ticks[0]
    out = call()
    during = ticks[0] - before
    stop.set()
    t.join()
    return out, during
