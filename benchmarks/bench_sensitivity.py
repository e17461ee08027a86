"""Cost of the steady state's parameter sensitivities against a plain solve.

On the 60 points of the fit benchmark's data (benchmarks/bench_fit.py, data seed 11, the
guess's parameters) and on the seeded random points of tests/solver/test_sensitivity.py, times
(medians of repeats, interleaved): ``solve_points`` alone; ``solve_gradients`` with all
eight parameters, order 4 (the default); and with order 2 and only the five parameters the
fit moves (what the fit's Jacobian calls).  The ratio to the plain solve is the cost of a
gradient in solves; a forward-difference Jacobian of ``n`` parameters costs ``n``.

Run:  python benchmarks/bench_sensitivity.py [--repeats 15]
Writes benchmarks/results/sensitivity.md.
"""

from __future__ import annotations

import argparse
import datetime
import math
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from vibrofriction.bench.fitting.problem import Problem
from vibrofriction.solver import solve_points
from vibrofriction.solver.sensitivity import solve_gradients

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "tests"))
sys.path.insert(0, str(HERE.parent / "tests" / "solver"))
import test_sensitivity  # noqa: E402

import bench_fit  # noqa: E402

FIT_MOVES = ("alpha", "beta", "amplitude", "v_inertial", "zeta")


def _sets() -> dict[str, tuple[dict, str]]:
    d = bench_fit.data(np.random.default_rng(11))
    pr = Problem(bench_fit.GUESS, tuple(bench_fit.FREE), False, True, True, d)
    ln = np.array([math.log(getattr(bench_fit.GUESS, n)) for n in bench_fit.FREE])
    names = ("alpha", "beta", "amplitude", "v_inertial", "zeta", "eta_c", "a_x", "phase_x")
    fit_pts = dict(zip(names, pr.points(ln)[1:], strict=True))
    out = {"fit benchmark, 60 points": (fit_pts, "substrate")}
    cases = [c for c in test_sensitivity._cases() if c[2] == "substrate"]
    out[f"random test points on the substrate, {len(cases)}"] = (
        {k: np.array([c[1][k] for c in cases]) for k in names}, "substrate")
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=15)
    args = ap.parse_args()
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=HERE).stdout.strip()
    ways = {
        "solve_points": lambda p, on: solve_points(**p, inplane_on=on),
        "gradient, 8 parameters, order 4": lambda p, on: solve_gradients(**p, inplane_on=on),
        "gradient, the fit's 5, order 2": lambda p, on: solve_gradients(
            **p, inplane_on=on, order=2, parameters=FIT_MOVES),
    }
    lines = [f"# Cost of a gradient ({datetime.date.today()}, commit {commit}, "
             f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores)", "",
             f"`python benchmarks/bench_sensitivity.py --repeats {args.repeats}`: medians of "
             f"{args.repeats} interleaved repeats, warm, one process.", "",
             "| points | " + " | ".join(ways) + " |", "|---|" + "---|" * len(ways)]
    for name, (pts, on) in _sets().items():
        for f in ways.values():
            f(pts, on)  # warm-up, compile
        times = {k: [] for k in ways}
        for _ in range(args.repeats):
            for k, f in ways.items():
                t = time.perf_counter()
                f(pts, on)
                times[k].append(time.perf_counter() - t)
        med = {k: statistics.median(v) for k, v in times.items()}
        base = med["solve_points"]
        lines.append(f"| {name} | " + " | ".join(
            f"{1e3 * m:.1f} ms ({m / base:.1f}x)" for m in med.values()) + " |")
    out = HERE / "results" / "sensitivity.md"
    out.write_text("\n".join(lines) + "\n")
    print(out.read_text())


if __name__ == "__main__":
    main()
