"""Curved tips at a stated error of at most 1e-7: the row without springs against the rows.

At the ten regimes of ``bench_ratios.py`` (the two jumping ones since the continuum covers
``a > 1``), for a cone, a sphere and ``n = 4``: the time per point of ``solve_points`` with
``tol_trusted = 1e-7`` (the MDR solver then answers with the row without springs,
:mod:`vibrofriction.solver.mdr_continuum`) against the flat point at the same
``(alpha, beta, a, V, zeta, a_x)``, and the spring rows asked for the same tolerance
(within ``rows_alone()``: rows doubled up to 5120 springs); the
stated errors and statuses after the times; medians of the ratios at the end.

    PYTHONPATH=src python benchmarks/bench_mdr_tol.py [--tol TOL] [--continuum] [--write]

``--tol`` another ``tol_trusted`` (``1e-5``, the default one, compares the two solvers where a
user who sets nothing gets them); the MDR solver answers with the row without springs at
every tolerance wherever it covers the point (``--continuum``, which made it do so above a
threshold that no longer exists, is kept for the commands of earlier runs); ``--write``
appends the run to benchmarks/results/mdr_tol.md.
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import time
from pathlib import Path

import numpy as np

from bench_ratios import REGIMES
from sections import append_run
from vibrofriction.schema import Status
from vibrofriction.solver import SolverSettings, mdr, solve_points
from vibrofriction.solver.mdr import rows_alone

TOL = 1e-7
EXPONENTS = (1.0, 2.0, 4.0)
REPEATS = 3
COPIES = 4
FLAT_COPIES = 32  # as bench_ratios.py: the flat point's cost without the call's overhead
CURVED_COPIES = FLAT_COPIES  # the row without springs likewise (the rows: COPIES, slow)
RESULTS = Path(__file__).parent / "results" / "mdr_tol.md"


def _timed(settings: SolverSettings | None = None, copies: int = COPIES,
           **kw) -> tuple[float, dict]:
    kw = {k: np.full(copies, v) for k, v in kw.items()}
    out = solve_points(**kw, settings=settings)
    times = []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        out = solve_points(**kw, settings=settings)
        times.append((time.perf_counter() - t0) / copies)
    return statistics.median(times), {k: v[0] for k, v in out.items()}


def _answer(out: dict) -> str:
    return f"{float(out['error']):.1e} ({Status.from_code(int(out['status'])).value})"


def bench(tol: float = TOL) -> list[str]:
    tight = SolverSettings(tol_trusted=tol)
    lines = ["| regime | flat ms | " + " | ".join(f"n = {n:g}: ms, ratio, error"
                                                  for n in EXPONENTS)
             + " | " + " | ".join(f"n = {n:g}, rows: ms, ratio, error" for n in EXPONENTS)
             + " |", "|" + "---|" * (2 + 2 * len(EXPONENTS))]
    ratios, row_ratios, errors = [], [], []
    for label, alpha, beta, a, V, zeta, a_x in REGIMES:
        base = {"alpha": alpha, "beta": beta, "amplitude": a, "v_inertial": V, "zeta": zeta,
                "a_x": a_x}
        t_flat, _ = _timed(copies=FLAT_COPIES, **base)
        cells = [label, f"{1e3 * t_flat:.3f}"]
        for n in EXPONENTS:
            t, out = _timed(tight, copies=CURVED_COPIES, **base, profile_exponent=n)
            ratios.append(t / t_flat)
            errors.append(float(out["error"]))
            cells.append(f"{1e3 * t:.2f}, {t / t_flat:.0f}x, {_answer(out)}")
        with rows_alone():
            for n in EXPONENTS:
                t, out = _timed(tight, **base, profile_exponent=n)
                row_ratios.append(t / t_flat)
                cells.append(f"{1e3 * t:.1f}, {t / t_flat:.0f}x, {_answer(out)}")
        line = "| " + " | ".join(cells) + " |"
        print(line, flush=True)
        lines.append(line)
    within = sum(e <= tol for e in errors)
    best = sum(e <= TOL for e in errors)
    lines += ["", f"Median ratio to the flat point at `tol_trusted = {tol:g}`: the row without "
              f"springs **{statistics.median(ratios):.0f}x** ({min(ratios):.0f}x to "
              f"{max(ratios):.0f}x over {len(ratios)} points, {within} with a stated error "
              f"<= {tol:g}, {best} <= {TOL:g}); the spring rows "
              f"{statistics.median(row_ratios):.0f}x ({min(row_ratios):.0f}x to "
              f"{max(row_ratios):.0f}x)."]
    print(lines[-1])
    return lines


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--tol", type=float, default=TOL, help="tol_trusted (default %(default)g)")
    ap.add_argument("--continuum", action="store_true",
                    help="the row without springs at every tolerance")
    ap.add_argument("--write", action="store_true", help=f"append to {RESULTS}")
    args = ap.parse_args()
    if args.continuum:
        mdr.CONTINUUM_TOL = math.inf
    lines = bench(args.tol)
    if args.write:
        flag = ("" if args.tol == TOL else f" --tol {args.tol:g}") \
            + (" --continuum" if args.continuum else "")
        append_run(RESULTS, "Curved tips at a stated error <= 1e-7: the row without springs",
                   f"PYTHONPATH=src python benchmarks/bench_mdr_tol.py{flag} --write",
                   f"load average {os.getloadavg()[0]:.1f} at the end; each time per point, the "
                   f"median of {REPEATS} calls of `solve_points` on {CURVED_COPIES} copies "
                   f"(the flat point and the row without springs; the rows of springs on "
                   f"{COPIES}), the kernels warm; the stated error and status after each "
                   "time.", lines)


if __name__ == "__main__":
    main()
