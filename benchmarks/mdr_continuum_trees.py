"""The row without springs' time over the 30 points of ``mdr_continuum_periods.py``, two trees
side by side.

Each round runs one fresh process per tree, in turn (its ``src`` first on ``PYTHONPATH``):
the 30 points (the regimes of ``bench_ratios.py`` for a cone, a sphere and ``n = 4``) at
``tol_trusted = 1e-7`` through :func:`~vibrofriction.solver.mdr_continuum.continuum_friction`,
once to warm up, then the sum over the points of the median of 5 calls. On a shared
machine whose speed drifts by half from minute to minute, the pair of a round is measured
under about the same load: the median of the rounds' ratios and the ratio of the two
smallest sums are reported.

    PYTHONPATH=src python benchmarks/mdr_continuum_trees.py OLD_SRC NEW_SRC [--rounds N]
        [--write]

``--write`` appends the run to benchmarks/results/mdr_continuum_periods.md.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

from sections import append_run

RESULTS = Path(__file__).parent / "results" / "mdr_continuum_periods.md"
TOL = 1e-7
REPEATS = 5


def _measure() -> None:
    """Print the sum over the points of the median time of a call, in ms."""
    from mdr_continuum_periods import _points
    from vibrofriction.solver.mdr_continuum import continuum_friction

    points = _points()
    for _, _, args in points:
        continuum_friction(*args, TOL)
    total = 0.0
    for _, _, args in points:
        ts = []
        for _ in range(REPEATS):
            t = time.perf_counter()
            continuum_friction(*args, TOL)
            ts.append(time.perf_counter() - t)
        total += statistics.median(ts)
    print(f"{1e3 * total:.3f}")


def _run(src: str) -> float:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([src, str(Path(__file__).parent)]))
    out = subprocess.run([sys.executable, __file__, "--measure"], env=env, check=True,
                         capture_output=True, text=True).stdout
    return float(out.split()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("trees", nargs="*", help="the old and the new tree's src")
    ap.add_argument("--rounds", type=int, default=6)
    ap.add_argument("--write", action="store_true")
    ap.add_argument("--measure", action="store_true", help=argparse.SUPPRESS)
    opts = ap.parse_args()
    if opts.measure:
        _measure()
        return
    old, new = opts.trees
    pairs = []
    for _ in range(opts.rounds):
        pairs.append((_run(old), _run(new)))
        print(f"{pairs[-1][0]:.1f} ms, {pairs[-1][1]:.1f} ms", flush=True)
    lines = ["| round | old (ms) | new (ms) | new / old |", "|---|---|---|---|",
             *(f"| {i + 1} | {a:.1f} | {b:.1f} | {b / a:.3f} |"
               for i, (a, b) in enumerate(pairs)), "",
             f"Median of the rounds' ratios {statistics.median(b / a for a, b in pairs):.3f}; "
             f"the smallest sums {min(a for a, _ in pairs):.1f} ms (old) and "
             f"{min(b for _, b in pairs):.1f} ms (new), ratio "
             f"{min(b for _, b in pairs) / min(a for a, _ in pairs):.3f}."]
    print(lines[-1])
    if opts.write:
        append_run(RESULTS, "The row without springs: periods by stage, and from a perfect "
                   "start of the body", f"python benchmarks/mdr_continuum_trees.py {old} {new}"
                   f" --rounds {opts.rounds} --write",
                   f"the 30 points at tol_trusted = {TOL:g}, the sum of each point's median "
                   f"of {REPEATS} warm calls, the two trees in turn in fresh processes.",
                   lines)


if __name__ == "__main__":
    main()
