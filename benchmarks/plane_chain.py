"""A continuation of the 2-D solver against its independent points, side by side in one run.

Four transverse curves of 40 velocities (``V`` 0.05..1.5; stick-slip, jumping and damped, a
soft pin, a longitudinal drive too), each solved as a continuation
(:func:`vibrofriction.solver.engine.solve_chain`: each point from the orbit before it) and as
independent points (:func:`~vibrofriction.solver.engine.solve_table`, each from the sliding
start), the median of 3 calls each; the drive periods integrated, the points where the two
differ by more than their two stated errors, and the largest difference of the multipliers.

    PYTHONPATH=src python benchmarks/plane_chain.py [--write]

Run with another tree's ``src`` first on ``PYTHONPATH`` to time its continuation the same way
(before the chain of whole 2-D orbits, a 2-D point of a continuation started from the ``x``
components of the state before it, and ran the transient).  ``--write`` appends the run to
benchmarks/results/plane_chain.md.
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
from pathlib import Path

import numpy as np

import vibrofriction as vf
from bench_solver import _median_time
from sections import append_run
from vibrofriction.solver.engine import solve_chain, solve_table
from vibrofriction.solver.points import table_of
from vibrofriction.solver.settings import DEFAULT_SETTINGS

RESULTS = Path(__file__).parent / "results" / "plane_chain.md"
CURVES = [("stick-slip", vf.Dimensionless(0.5, 2.0, 0.5, a_y=0.5)),
          ("jumping, damped", vf.Dimensionless(0.5, 4.0, 1.5, 0.1, a_y=0.5)),
          ("soft pin", vf.Dimensionless(0.05, 20.0, 0.5, a_y=0.3)),
          ("longitudinal drive too", vf.Dimensionless(0.5, 2.0, 0.7, 0.05, a_x=0.3, a_y=0.5))]
V = np.linspace(0.05, 1.5, 40)
REPEATS = 3


def _timed(f):
    """The median of :data:`REPEATS` calls of ``f``, warm, and its result."""
    f()
    return _median_time(f, REPEATS, math.inf)


def bench() -> list[str]:
    lines = ["| curve (40 points) | continuation ms, periods | independent ms, periods | "
             "ratio | beyond the two errors | max multiplier difference |",
             "|---|---|---|---|---|---|"]
    ratios = []
    for label, system in CURVES:
        table = table_of(system, V)
        tc, c = _timed(lambda t=table: solve_chain(t, "sliding", DEFAULT_SETTINGS))
        ti, i = _timed(lambda t=table: solve_table(t, "sliding", DEFAULT_SETTINGS))
        beyond = int(np.sum(np.abs(c["mu_ratio"] - i["mu_ratio"]) > c["error"] + i["error"]))
        dmult = float(np.max(np.abs(c["multiplier"] - i["multiplier"])))
        ratios.append(ti / tc)
        line = (f"| {label} | {1e3 * tc:.1f}, {c['work'].sum():.0f} | {1e3 * ti:.1f}, "
                f"{i['work'].sum():.0f} | {ti / tc:.2f}x | {beyond} | {dmult:.1e} |")
        print(line, flush=True)
        lines.append(line)
    lines += ["", f"The continuation over the independent points: median "
              f"**{statistics.median(ratios):.2f}x** faster."]
    print(lines[-1])
    return lines


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--write", action="store_true", help=f"append to {RESULTS}")
    ap.add_argument("--note", default="", help="a line after the table")
    args = ap.parse_args()
    lines = bench()
    if args.note:
        lines += ["", args.note]
    if args.write:
        append_run(RESULTS, "A continuation of the 2-D solver against its independent points",
                   "PYTHONPATH=src python benchmarks/plane_chain.py --write",
                   f"load average {os.getloadavg()[0]:.1f} at the end; the median of "
                   f"{REPEATS} calls each, package {Path(vf.__file__).parent}.", lines)


if __name__ == "__main__":
    main()
