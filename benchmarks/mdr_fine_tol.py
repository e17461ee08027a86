"""The MDR solver asked for a stated error of 1e-7: is it reached, what does it cost, does it hold?

At the regimes of ``benchmarks/bench_ratios.py`` (stiff, soft, resonant, damped, jumping, with
a longitudinal drive; 10 of them) and three tips (a cone, a sphere, ``n = 4``), the point is
solved by ``solve_points`` at ``tol_trusted`` 1e-5 (the default) and 1e-7, each time the
median of 3 calls; its rows, stated error and status are given. The 1e-7 answer is then
checked against the same solver's far finer answer: rows doubled on to 20480 springs
(``solver.mdr.MAX_SPRINGS`` raised for that run only) until a stated error of 1e-9 or that
row; the check is ``|mu(1e-7) - mu(fine)| <= error(1e-7) + error(fine)``. This is the
solver's own convergence, not the independent reference (whose fine cache has bars of
about 1e-6: ``tests/data/mdr_fine_reference.json``).

    PYTHONPATH=src python benchmarks/mdr_fine_tol.py [--write] [--cusp]

``--write`` appends to benchmarks/results/mdr_fine_tol.md. ``--cusp``: instead, the
explorer's 40-point curves of tips with a cusp (``n < 1``, whose rows converge slowly) at
the default ``tol_trusted``, with the rows capped at 640 springs (the cap before 5120) and
at 5120: the time of ``explorer.compute.curve`` in one process and the points trusted.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import vibrofriction.solver.mdr as mdr
from bench_ratios import EXPONENTS, REGIMES
from sections import append_run
from vibrofriction import SolverSettings
from vibrofriction.schema import Status
from vibrofriction.solver import solve_points

RESULTS = Path(__file__).parent / "results" / "mdr_fine_tol.md"
FINE_SPRINGS = 20480


def _solve(kw: dict, tol: float, repeats: int = 3) -> tuple[float, dict]:
    settings = SolverSettings(tol_trusted=tol)
    out = solve_points(**kw, settings=settings)
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = solve_points(**kw, settings=settings)
        times.append(time.perf_counter() - t0)
    return (statistics.median(times) if times else float("nan")), out


def table() -> list[str]:
    lines = ["| regime | n | 1e-5: ms, error | 1e-7: ms, error, status | fine: error | "
             "\\|mu(1e-7) - mu(fine)\\| | holds |", "|---|---|---|---|---|---|---|"]
    reached, holds, ratios = 0, 0, []
    rows = 0
    for label, alpha, beta, a, V, zeta, a_x in REGIMES:
        for n in EXPONENTS:
            kw = {"alpha": alpha, "beta": beta, "amplitude": a, "v_inertial": V, "zeta": zeta,
                  "a_x": a_x, "profile_exponent": n}
            t5, r5 = _solve(kw, 1e-5)
            t7, r7 = _solve(kw, 1e-7)
            cap = mdr.MAX_SPRINGS
            mdr.MAX_SPRINGS = FINE_SPRINGS
            try:
                _, rf = _solve(kw, 1e-9, repeats=0)
            finally:
                mdr.MAX_SPRINGS = cap
            e7, ef = float(r7["error"]), float(rf["error"])
            diff = abs(float(r7["mu_ratio"]) - float(rf["mu_ratio"]))
            ok = diff <= e7 + ef
            rows += 1
            reached += bool(r7["trusted"])
            holds += ok
            ratios.append(t7 / t5)
            status = Status.from_code(int(r7["status"])).value
            line = (f"| {label} | {n:g} | {1e3 * t5:.1f}, {float(r5['error']):.1e} | "
                    f"{1e3 * t7:.1f}, {e7:.1e}, {status}"
                    f"{'' if r7['trusted'] else ' (not trusted)'} | {ef:.1e} | {diff:.1e} | "
                    f"{'yes' if ok else 'NO'} |")
            print(line, flush=True)
            lines.append(line)
    lines += ["", f"{reached} of {rows} points trusted at `tol_trusted = 1e-7`; the answer "
              f"within its stated error and the fine answer's at {holds} of {rows}; the "
              f"time at 1e-7 over the time at 1e-5: median {statistics.median(ratios):.1f}x "
              f"({min(ratios):.1f}x to {max(ratios):.1f}x)."]
    print(lines[-1])
    return lines


CUSPS = ({"profile_exponent": 0.7}, {"profile_exponent": 0.7, "amplitude": 1.5},
         {"profile_exponent": 0.5, "zeta": 0.1})


def cusp() -> list[str]:
    import dataclasses

    import numpy as np

    from vibrofriction.explorer.compute import curve
    from vibrofriction.explorer.state import State

    lines = ["| tip (explorer state) | springs at most | s a curve | points trusted |",
             "|---|---|---|---|"]
    cap = mdr.MAX_SPRINGS
    try:
        for kw in CUSPS:
            state = dataclasses.replace(State(), **kw)
            for springs in (640, cap):
                mdr.MAX_SPRINGS = springs
                curve(state)
                t0 = time.perf_counter()
                c = curve(state)
                seconds = time.perf_counter() - t0
                trusted = int(np.sum(np.asarray(c["trusted"]) == True))  # noqa: E712
                line = (f"| {kw} | {springs} | {seconds:.2f} | {trusted} of {len(c['x'])} |")
                print(line, flush=True)
                lines.append(line)
    finally:
        mdr.MAX_SPRINGS = cap
    return lines


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--write", action="store_true", help=f"append to {RESULTS}")
    ap.add_argument("--cusp", action="store_true", help="the explorer's curves of cusps")
    args = ap.parse_args()
    lines = cusp() if args.cusp else table()
    if args.write:
        append_run(RESULTS, "The MDR solver asked for a stated error of 1e-7",
                   "PYTHONPATH=src python benchmarks/mdr_fine_tol.py --write"
                   f"{' --cusp' if args.cusp else ''}",
                   "times the median of 3 calls of `solve_points` on the point.", lines)


if __name__ == "__main__":
    main()
