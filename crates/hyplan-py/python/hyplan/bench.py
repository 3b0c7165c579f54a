"""``hyplan bench`` sweeps from Python: on this machine, or one shard per task of a Dask
cluster, merged into the outputs of one run.

This module drives the ``hyplan`` command-line tool (the package's extension has no
benchmark of its own): :func:`run` runs ``hyplan bench --experiment FILE`` here, or cuts
the experiment into shards (``hyplan bench --shard K/N``, one Dask task each, one thread
each so that workers are the parallelism) and joins them with ``hyplan bench merge``.
Every value but the measured times is the same whatever the number of shards.

The CLI is found, in order: the ``hyplan_bin`` argument, the ``HYPLAN_BIN`` environment
variable, ``hyplan`` on ``PATH`` (``cargo install --path crates/hyplan`` puts it there).
With a cluster each worker finds it the same way on its own machine.

Example::

    from dask.distributed import Client, LocalCluster
    import hyplan.bench

    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as c:
        result = hyplan.bench.run("arena.ron", client=c, out="bench-arena")
    print(result.summary)
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Dict, List, Optional, Sequence, Union

__all__ = ["BenchError", "SweepResult", "find_cli", "run", "run_shard"]

PathArg = Union[str, "os.PathLike[str]"]

# Files of a finished shard's folder (crates/hyplan/src/cmd/bench/shard.rs).
_SHARD_FILES = ("shard.json", "records.ron")


class BenchError(RuntimeError):
    """The ``hyplan`` CLI failed: ``.code`` is its exit status (2: bad input, refused
    shards), ``.stderr`` what it said."""

    def __init__(self, command: Sequence[str], code: int, stderr: str):
        super().__init__(f"{' '.join(command)} exited {code}: {stderr.strip()}")
        self.command = list(command)
        self.code = code
        self.stderr = stderr


@dataclass
class SweepResult:
    """Where the outputs are and how the sweep ran."""

    out: Path
    """The output folder: runs.csv, runs.json, summary.md, the OMPL logs and charts."""
    shards: int
    """Shards run (1: an unsharded run)."""
    wall_s: float
    """Wall time of the whole sweep, merge included, s."""

    @property
    def summary(self) -> str:
        """``summary.md``: the tables of the runs."""
        return (self.out / "summary.md").read_text()

    def runs(self) -> dict:
        """``runs.json``, parsed (every run, the summary, the comparisons)."""
        import json

        return json.loads((self.out / "runs.json").read_text())


def find_cli(hyplan_bin: Optional[PathArg] = None) -> str:
    """The ``hyplan`` CLI: ``hyplan_bin``, else ``$HYPLAN_BIN``, else ``hyplan`` on PATH.

    Raises ``FileNotFoundError`` naming the three places when none is there."""
    for candidate in (hyplan_bin, os.environ.get("HYPLAN_BIN")):
        if candidate:
            path = Path(candidate)
            if not path.is_file():
                raise FileNotFoundError(f"hyplan CLI {path}: no such file")
            return str(path)
    found = shutil.which("hyplan")
    if found:
        return found
    raise FileNotFoundError(
        "no hyplan CLI: pass hyplan_bin=, set HYPLAN_BIN, or put `hyplan` on PATH "
        "(cargo install --path crates/hyplan)"
    )


def _call(command: List[str]) -> str:
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise BenchError(command, done.returncode, done.stderr)
    return done.stdout


def run_shard(
    experiment: PathArg,
    shard: int,
    shards: int,
    out: Optional[PathArg] = None,
    threads: Optional[int] = 1,
    hyplan_bin: Optional[PathArg] = None,
    args: Sequence[str] = (),
) -> Dict[str, bytes]:
    """Runs shard ``shard`` of ``shards`` (from 0) and returns its folder's files by name
    (what ``hyplan bench merge`` reads). Into ``out`` if given, else a temporary folder
    removed afterwards: the files travel back to the caller, so the shards need no file
    system in common. This is the task :func:`run` submits to a cluster."""
    command_base = [
        find_cli(hyplan_bin),
        "bench",
        "--experiment",
        os.fspath(experiment),
        "--shard",
        f"{shard}/{shards}",
    ]
    if threads:
        command_base += ["--threads", str(threads)]
    with tempfile.TemporaryDirectory(prefix="hyplan-shard-") as tmp:
        folder = Path(out) if out is not None else Path(tmp)
        _call(command_base + ["--out", str(folder), *args])
        return {name: (folder / name).read_bytes() for name in _SHARD_FILES}


def _write_shard(folder: Path, files: Dict[str, bytes]) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    # The manifest last, as the CLI writes it: a folder with a manifest is complete.
    for name in sorted(files, key=lambda n: n == "shard.json"):
        (folder / name).write_bytes(files[name])


def run(
    experiment: PathArg,
    client=None,
    shards: Optional[int] = None,
    out: PathArg = "bench-out",
    threads: Optional[int] = None,
    hyplan_bin: Optional[PathArg] = None,
    args: Sequence[str] = (),
) -> SweepResult:
    """Runs the experiment file ``experiment`` (RON, docs/bench.md) and writes its outputs
    into ``out``; returns a :class:`SweepResult`.

    - ``client=None, shards=None``: one ``hyplan bench`` here, on every core (or
      ``threads``).
    - ``client=None, shards=N``: the N shards one after the other here, then the merge
      (the sharded path without a cluster).
    - ``client``, a ``dask.distributed.Client``: one task per shard (``shards`` of them,
      by default one per worker thread), each ``hyplan bench --shard K/N --threads 1`` on
      its worker; their files come back to this process, into ``out/shards/K``, and
      ``hyplan bench merge`` writes the outputs here.

    ``args`` are more ``hyplan bench`` flags for every run (``["--runs", "100"]``).
    Raises :class:`BenchError` when the CLI fails (bad input, a shard refused)."""
    started = time.perf_counter()
    experiment = Path(experiment).resolve()
    out = Path(out)
    bin_here = find_cli(hyplan_bin)
    if client is None and shards is None:
        command = [bin_here, "bench", "--experiment", str(experiment), "--out", str(out)]
        if threads:
            command += ["--threads", str(threads)]
        _call(command + list(args))
        return SweepResult(out, 1, time.perf_counter() - started)
    if client is not None and shards is None:
        shards = max(1, sum(client.nthreads().values()))
    if not shards or shards < 1:
        raise ValueError(f"shards={shards}: must be at least 1")
    folders = [out / "shards" / str(k) for k in range(shards)]
    if client is None:
        for k, folder in enumerate(folders):
            run_shard(experiment, k, shards, folder, threads, bin_here, args)
    else:
        # The workers find their own CLI unless one was named here.
        futures = [
            client.submit(
                run_shard,
                str(experiment),
                k,
                shards,
                None,
                1,
                hyplan_bin,
                tuple(args),
                key=f"hyplan-shard-{k}-of-{shards}-{os.getpid()}-{time.time_ns()}",
                pure=False,
            )
            for k in range(shards)
        ]
        for folder, files in zip(folders, client.gather(futures)):
            _write_shard(folder, files)
    _call([bin_here, "bench", "merge", *map(str, folders), "--out", str(out)])
    return SweepResult(out, shards, time.perf_counter() - started)
