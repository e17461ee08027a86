"""The row without springs at soft pins sliding slowly, where the body creeps for long.

24 random points for each of the seeds 5 and 6: ``alpha`` 10^-2..10^-0.5, ``beta - alpha``
10^-0.5..10^1.5, ``a`` 0.1..0.9, ``V`` 10^-2.5..10^-1, ``n`` in {1, 2, 3}, undamped, no
drive; each asked of :func:`~vibrofriction.solver.mdr_continuum.continuum_friction` at
``tol_trusted = 1e-7`` as the MDR solver asks it. Prints each point's status, periods,
``mu_ratio``, stated error and time, and per seed the periods in all and the failures.
``|<y>|/(2 pi V)`` with ``<y> = -0.6/alpha`` (a typical ``mu <F_N>``) after each point
gives the order of the periods its spring takes to load while the body creeps.

    PYTHONPATH=src python benchmarks/mdr_continuum_creep.py [--write]

``--write`` appends the run to benchmarks/results/mdr_continuum_creep.md.
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import numpy as np

from vibrofriction.solver.mdr_continuum import continuum_friction

RESULTS = Path(__file__).parent / "results" / "mdr_continuum_creep.md"
SEEDS = (5, 6)
COUNT = 24
TOL = 1e-7


def run(seed: int) -> list[str]:
    rng = np.random.default_rng(seed)
    lines = [f"| seed {seed}: alpha, beta, a, V, n | status | periods | mu_ratio | error | "
             "ms | creep ~ periods |", "|---|---|---|---|---|---|---|"]
    periods = failed = 0
    for _ in range(COUNT):
        al = 10 ** rng.uniform(-2, -0.5)
        be = al + 10 ** rng.uniform(-0.5, 1.5)
        a, V = rng.uniform(0.1, 0.9), 10 ** rng.uniform(-2.5, -1)
        n = float(rng.choice([1, 2, 3]))
        t0 = time.perf_counter()
        r = continuum_friction(al, be, a, V, n, 0.0, 0.0, 0.0, (0.0, 0.0), TOL)
        ms = 1e3 * (time.perf_counter() - t0)
        periods += r["periods"]
        failed += r["status"] != "periodic"
        lines.append(f"| {al:.3f}, {be:.2f}, {a:.2f}, {V:.4f}, {n:g} | {r['status']} | "
                     f"{r['periods']} | {r['mu_ratio']:.9f} | {r['error']:.1e} | {ms:.1f} | "
                     f"{0.6 / (al * 2 * math.pi * V):.0f} |")
        print(lines[-1], flush=True)
    lines += ["", f"Seed {seed}: {periods} periods in all, {failed} of {COUNT} not periodic.",
              ""]
    print(lines[-2])
    return lines


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--write", action="store_true")
    opts = ap.parse_args()
    continuum_friction(0.5, 2.0, 0.5, 0.3, 2.0, 0.0, 0.0, 0.0, (0.0, 0.0), TOL)  # (warm)
    lines = [line for seed in SEEDS for line in run(seed)]
    if opts.write:
        from sections import append_run

        append_run(RESULTS, "The row without springs at soft, slowly sliding pins",
                   "PYTHONPATH=src python benchmarks/mdr_continuum_creep.py --write",
                   f"tol_trusted = {TOL:g}; each point solved once, the kernels warm.", lines)


if __name__ == "__main__":
    main()
