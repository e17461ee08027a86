"""The cost of a continuation sweep: each point starts from its predecessor's final state.

A grid of 20 ``alpha`` x 2 amplitudes x 50 ``vbar`` (flat punch, ``beta = 2``), walked up
and then down in velocity (4000 solves), in one process (``workers=1``): the time a point
and a digest of every variable of the dataset, so that two trees can be checked to give
the same dataset bit for bit.  ``--tree DIR`` runs the same measurement with the source
tree ``DIR`` (its ``src`` first on the path, in a subprocess) right after, side by side.

    PYTHONPATH=src python benchmarks/bench_continuation.py [--tree OLD] [--write]

``--write`` appends the run to benchmarks/results/continuation.md (earlier runs stay).
"""

from __future__ import annotations

import hashlib
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).parent / "results" / "continuation.md"
REPEATS = 3


def measure() -> str:
    """``us a point (median of REPEATS), digest`` of this process's tree."""
    from vibrofriction.sweep import sweep

    grid = dict(alpha=np.linspace(0.05, 0.9, 20), beta=2.0, amplitude=[0.3, 0.6],
                vbar=np.linspace(0.05, 1.2, 50), continuation=True, workers=1,
                progress=False)
    sweep(**{**grid, "alpha": [0.3], "amplitude": 0.5})  # load the kernels
    times = []
    for _ in range(REPEATS):
        t = time.perf_counter()
        ds = sweep(**grid)
        times.append(time.perf_counter() - t)
    digest = hashlib.sha256()
    for name in sorted(ds.data_vars):
        digest.update(np.ascontiguousarray(ds[name].values).tobytes())
    return f"{statistics.median(times) / ds.mu_ratio.size * 1e6:.0f} {digest.hexdigest()[:16]}"


def main() -> None:
    if "--measure" in sys.argv:
        print(measure())
        return
    trees = [("this tree", str(Path(__file__).resolve().parents[1]))]
    if "--tree" in sys.argv:
        trees.append(("--tree", sys.argv[sys.argv.index("--tree") + 1]))
    lines = ["| tree | us a point | dataset digest |", "|---|---|---|"]
    for label, tree in trees:
        env = {**os.environ, "PYTHONPATH": f"{tree}/src"}
        out = subprocess.run([sys.executable, __file__, "--measure"], env=env, check=True,
                             capture_output=True, text=True).stdout.split()
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=tree,
                                capture_output=True, text=True).stdout.strip()
        lines.append(f"| {label} ({commit}) | {out[0]} | `{out[1]}` |")
    print("\n".join(lines))
    if "--write" in sys.argv:
        sys.path.insert(0, str(Path(__file__).parent))
        from sections import append_run

        append_run(RESULTS, "Continuation sweeps: the cost a point",
                   " ".join(["PYTHONPATH=src python benchmarks/bench_continuation.py",
                             *sys.argv[1:]]),
                   f"4000 solves (20 alpha x 2 amplitudes x 50 vbar, up and down), one "
                   f"process; the median of {REPEATS} sweeps, the trees one after the other.",
                   lines)


if __name__ == "__main__":
    main()
