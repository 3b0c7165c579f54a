"""The ROS maps the hyplan CLI writes, read by an independent decoder (Pillow) and Nav2's rules.

`hyplan map --out X.pgm` / `--yaml X.yaml` (a three-zone map), `hyplan explore` and
`hyplan sim` (the robot's built map, `map.yaml` + `map.pgm`) must write binary PGM (`P5`)
that Pillow opens in mode "L", with a YAML whose mode and thresholds make Nav2's
`loadMapFromFile` give back the cells hyplan meant:

- occ = (255 - v) / 255 (negate 0); occupied if occ > occupied_thresh, free if
  occ < free_thresh, else unknown (trinary) or a graded cost (scale).

What the cells are compared with, each stated independently of the PGM writers:
- the zone map: the zones recomputed here from the input picture (decoded by Pillow) by
  seed 000's rule as hyplan documents it (obstacle: Rec. 709 luma < 100; high-risk: within
  20 cells, dx^2 + dy^2 <= 400, of an obstacle cell; safe otherwise), cell by cell, and the
  counts `hyplan map --json` prints;
- the built maps: the map drawn cell by cell in the run's SVG figure (free and occupied
  cells as rectangles, unknown ones left out), and for `hyplan explore` the counts it
  prints (`built map: ... free, ... occupied, ... unknown`).

Needs Pillow and NumPy; a missing one fails the run (no silent skip).
"""

import base64
import io
import json
import re
import subprocess
from pathlib import Path

import numpy as np
from PIL import Image

from conftest import ROOT

ROOM_PICTURE = ROOT / "scenarios" / "maps" / "room_960x640.png"
SAFETY_RADIUS = 20  # hyplan map's default for pictures (seed 000)

FREE, OCCUPIED, UNKNOWN = 0, 1, 2


def run(*args, codes=(0,)):
    out = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=900)
    assert out.returncode in codes, (args, out.returncode, out.stderr)
    return out


def read_yaml(path):
    """The flat `key: value` YAML hyplan writes (no nesting), values as strings."""
    meta = {}
    for line in Path(path).read_text().splitlines():
        key, _, value = line.partition(":")
        meta[key.strip()] = value.strip()
    return meta


def open_pgm(path):
    """Pillow's decoding of a PGM that must be binary (P5) and 8-bit grey."""
    with open(path, "rb") as f:
        assert f.read(2) == b"P5", f"{path}: not a binary PGM"
    im = Image.open(path)
    assert im.format == "PPM", im.format  # Pillow's netpbm plug-in
    assert im.mode == "L", im.mode
    return np.asarray(im, dtype=np.uint8)  # rows top first


def nav2_classes(grey, occupied_thresh, free_thresh, negate=False):
    """Nav2's loadMapFromFile, trinary mode: FREE / OCCUPIED / UNKNOWN per pixel."""
    shade = grey.astype(np.float64) / 255.0
    occ = shade if negate else 1.0 - shade
    out = np.full(grey.shape, UNKNOWN, dtype=np.uint8)
    out[occ < free_thresh] = FREE
    out[occ > occupied_thresh] = OCCUPIED
    return out


def ros_map(yaml, mode):
    """The image of a ROS map YAML, checked to be in `mode` with map_saver's settings, and
    its cells by Nav2's trinary rule (rows top first)."""
    meta = read_yaml(yaml)
    assert meta["mode"] == mode, meta
    assert meta["negate"] == "0", meta
    occ_t, free_t = float(meta["occupied_thresh"]), float(meta["free_thresh"])
    assert (occ_t, free_t) == (0.65, 0.196), meta
    grey = open_pgm(Path(yaml).parent / meta["image"])
    return meta, grey, nav2_classes(grey, occ_t, free_t)


def seed000_zones(picture):
    """The zones of `picture` recomputed from hyplan's documented rule, rows top first."""
    rgb = np.asarray(Image.open(picture).convert("RGB"), dtype=np.int64)
    luma = (2126 * rgb[..., 0] + 7152 * rgb[..., 1] + 722 * rgb[..., 2] + 5000) // 10000
    obstacle = luma < 100
    r = SAFETY_RADIUS
    h, w = obstacle.shape
    padded = np.zeros((h + 2 * r, w + 2 * r), dtype=bool)
    padded[r : r + h, r : r + w] = obstacle
    near = np.zeros_like(obstacle)
    for dy in range(-r, r + 1):
        for dx in range(-r, r + 1):
            if dx * dx + dy * dy <= r * r:
                near |= padded[r + dy : r + dy + h, r + dx : r + dx + w]
    zones = np.full(obstacle.shape, FREE, dtype=np.uint8)
    zones[near] = UNKNOWN  # high-risk: Nav2's trinary rule must read it as unknown
    zones[obstacle] = OCCUPIED
    return zones


def test_zone_maps_open_in_pillow_and_keep_their_zones(tmp_path, hyplan_bin):
    out_pgm = tmp_path / "zones.pgm"
    yaml = tmp_path / "zones_ros.yaml"
    rec = json.loads(
        run(hyplan_bin, "map", ROOM_PICTURE, "--out", out_pgm, "--yaml", yaml, "--json").stdout
    )
    expected = seed000_zones(ROOM_PICTURE)
    counts = {FREE: rec["free"], OCCUPIED: rec["forbidden"], UNKNOWN: rec["risk"]}
    assert all(n > 0 for n in counts.values()), rec
    for k, n in counts.items():
        assert int((expected == k).sum()) == n, (k, n)

    # --out X.pgm: the zone picture as grey levels.
    grey = open_pgm(out_pgm)
    assert grey.shape == (640, 960)
    np.testing.assert_array_equal(nav2_classes(grey, 0.65, 0.196), expected)

    # --yaml: the ROS pair, scale mode; high-risk cells lie strictly between the thresholds.
    meta, grey, cells = ros_map(yaml, "scale")
    assert float(meta["resolution"]) == 1.0
    assert meta["origin"] == "[0.0, 0.0, 0.0]"
    assert grey.shape == (640, 960)
    np.testing.assert_array_equal(cells, expected)
    assert set(np.unique(grey)) <= {0, 128, 254}, np.unique(grey)
    # Our own loader reads the pair back to the same counts.
    back = json.loads(run(hyplan_bin, "map", yaml, "--json").stdout)
    assert (back["free"], back["risk"], back["forbidden"]) == (rec["free"], rec["risk"], rec["forbidden"])


def svg_cells(svg, meta, shape):
    """The built map as the run's SVG figure draws it: an embedded PNG of one pixel per
    cell, rows top first, free #fff, occupied #222, unknown any other colour."""
    text = Path(svg).read_text()
    found = re.search(r'<image [^>]*href="data:image/png;base64,([^"]+)"', text)
    assert found, f"{svg}: no map image"
    pixels = np.asarray(Image.open(io.BytesIO(base64.b64decode(found.group(1)))).convert("RGB"))
    assert pixels.shape[:2] == shape, (svg, pixels.shape, shape)
    cells = np.full(shape, UNKNOWN, dtype=np.uint8)
    cells[(pixels == (0xFF, 0xFF, 0xFF)).all(axis=2)] = FREE
    cells[(pixels == (0x22, 0x22, 0x22)).all(axis=2)] = OCCUPIED
    assert (cells != UNKNOWN).any(), f"{svg}: no map cells drawn"
    return cells


# The room the CLI tests explore (crates/hyplan/tests/sim.rs reads the same file).
ROOM = ROOT / "crates" / "hyplan" / "tests" / "data" / "room.ron"


def check_built_map(out_dir, figure, shape):
    meta, grey, cells = ros_map(out_dir / "map.yaml", "trinary")
    assert meta["image"] == "map.pgm"
    assert grey.shape == shape
    assert set(np.unique(grey)) <= {0, 205, 254}, np.unique(grey)
    drawn = svg_cells(figure, meta, shape)
    np.testing.assert_array_equal(cells, drawn)
    assert all((cells == k).any() for k in (FREE, OCCUPIED, UNKNOWN))
    return cells


def test_explored_map_is_map_savers_trinary(tmp_path, hyplan_bin):
    out_dir = tmp_path / "explore"
    out = run(hyplan_bin, "explore", ROOM, "--eta", "2", "--seed", "4", "--out", out_dir,
              codes=(0, 1))
    # The final snapshot (largest time) draws the final map.
    snaps = sorted(out_dir.glob("explore-*s.svg"), key=lambda p: float(p.stem[8:-1]))
    assert snaps, list(out_dir.iterdir())
    cells = check_built_map(out_dir, snaps[-1], (80, 120))
    m = re.search(r"built map: (\d+) x (\d+) cells of ([\d.]+) m: (\d+) free, (\d+) occupied, "
                  r"(\d+) unknown", out.stdout)
    assert m, out.stdout
    w, h, free, occupied, unknown = (int(m.group(k)) for k in (1, 2, 4, 5, 6))
    assert (h, w) == cells.shape
    assert (free, occupied, unknown) == tuple(int((cells == k).sum()) for k in (FREE, OCCUPIED, UNKNOWN))


HALL = """SimScenario(
    name: "hall",
    world: (size: (6.0, 3.0), shapes: [Box(center: (3.0, 0.6), size: (0.6, 1.2))]),
    people: [(path: [(4.5, 2.8), (4.5, 0.2)], speed: 0.3, start: 4.0)],
    start: (0.5, 1.5), goal: (5.5, 1.5),
    time_limit: 60.0,
)
"""


def test_sim_map_is_map_savers_trinary(tmp_path, hyplan_bin):
    scenario = tmp_path / "hall.ron"
    scenario.write_text(HALL)
    out_dir = tmp_path / "sim"
    run(hyplan_bin, "sim", scenario, "--seed", "3", "--out", out_dir)
    check_built_map(out_dir, out_dir / "trajectory.svg", (60, 120))
