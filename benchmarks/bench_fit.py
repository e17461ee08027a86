"""Time of a fit to 60 measured points (3 amplitudes x 20 velocities), stage by stage.

Two calls, on the same synthetic data set (the pin of tests/bench/test_fit.py: 800 Hz, Q = 50,
k_xc = 1.5e7 N/m, 20 N; noise 0.003 in the COF) from the same poor guess:

* ``free = mu0, mass, k_xc, u_z0`` with the default constraints (``k_x`` follows
  ``mass`` through the natural frequency, ``k_zc`` follows ``u_z0``): four varied;
* five varied parameters (``natural_frequency=False``).

Each is run once on each of four data sets (noise seeds): the time depends on the data
(a first round of the global search that ends not clearly good is followed by a second).

Each fit is run with each local Jacobian of ``--jacobian`` (``exact``: the steady
state's sensitivities; ``differences``: lmfit's), interleaved per data set so that the
machine's load hits them alike.

Run:  python benchmarks/bench_fit.py [--data-seeds 11,12,13,14] [--workers 2]
      [--jacobian exact,differences] [--calls 4,5]
Writes benchmarks/results/fit.md: this run on top, the runs before it below.
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import statistics
import subprocess
import time
from pathlib import Path

import numpy as np
import pandas as pd

import vibrofriction as vf
from vibrofriction.bench import synthetic_measurements

HERE = Path(__file__).resolve().parent
TRUE = vf.from_bench(natural_frequency_hz=800.0, mass=0.01, quality_factor=50.0,
                              normal_load=20.0, k_zc=2e7, k_xc=1.5e7, drive_frequency_hz=1000.0,
                              du_z=0.5e-6, mu0=0.3)
# a poor guess: mu0 +20 %, the modal mass +30 %, k_xc +47 %, u_z0 +25 % (the load kept);
# the pin's measured quality factor kept (Q = 50), as an experimenter who measured it would
GUESS = TRUE.with_(mu0=0.36, mass=0.013, k_x=TRUE.k_x * 1.3, k_xc=2.2e7, u_z0=TRUE.u_z0 * 1.25,
                   k_zc=TRUE.k_zc / 1.25).with_damping(quality_factor=TRUE.quality_factor)
FREE = ["mu0", "mass", "k_x", "k_xc", "u_z0"]
CALLS = {  # the first keeps the measured natural frequency; the second guesses k_x -10 % too
    "4 varied (k_x follows mass)": (GUESS, {"natural_frequency": True,
                                            "free": [n for n in FREE if n != "k_x"]}),
    "5 varied (natural frequency released)": (
        GUESS.with_(k_x=TRUE.k_x * 1.2).with_damping(quality_factor=TRUE.quality_factor),
        {"natural_frequency": False})}


def data(rng: np.random.Generator) -> pd.DataFrame:
    return synthetic_measurements(TRUE, (0.3e-6, 0.6e-6, 0.9e-6), np.geomspace(1e-3, 0.2, 20),
                                  0.003, rng)


def _label(variant: str) -> str:
    return f"{variant} Jacobian"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data-seeds", default="11,12,13,14",
                    help="noise seeds of the data sets, one fit of each per call")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--jacobian", default="exact",
                    help="the local stages' Jacobians compared, interleaved per data set")
    ap.add_argument("--calls", default="4,5", help="the calls timed, by their varied count")
    args = ap.parse_args()
    calls = {k: v for k, v in CALLS.items() if k[0] in args.calls.split(",")}
    variants = args.jacobian.split(",")
    seeds = [int(x) for x in args.data_seeds.split(",")]
    tables = {k: data(np.random.default_rng(k)) for k in seeds}
    vf.fit(tables[seeds[0]].head(6), TRUE, free=["mu0"], global_stage=False,
           progress=False)  # warm-up
    load = os.getloadavg()[0]
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=Path(vf.__file__).parent,
                            capture_output=True, text=True).stdout.strip()
    lines = [f"# Fit time ({datetime.date.today()}, {platform.processor() or platform.machine()},"
             f" {os.cpu_count()} cores, workers={args.workers}, commit {commit})", "",
             "`python benchmarks/bench_fit.py`: 60 points (3 amplitudes x 20 velocities, noise "
             "0.003), the pin of tests/bench/test_fit.py, from a poor guess; one fit per data set "
             f"(noise seeds {', '.join(map(str, seeds))}).", "",
             "| call | median time | max | per data set (s) | verdict (p) | "
             "global stages |", "|---|---|---|---|---|---|"]
    detail = []
    truth = ", ".join(f"{n} {getattr(TRUE, n):.4g}" for n in FREE)
    for name, (guess, kwargs) in calls.items():
        times = {v: [] for v in variants}
        verdicts = {v: [] for v in variants}
        stages = {v: [] for v in variants}
        for k in seeds:
            for v in variants:
                t = time.perf_counter()
                res = vf.fit(tables[k], guess, **{"free": FREE, **kwargs},
                             workers=args.workers, progress=False, jacobian=v)
                times[v].append(time.perf_counter() - t)
                verdicts[v].append(f"{res.quality} ({res.p_value:.2g})")
                stages[v].append(sum(r["stage"] == "global" for r in res.extra["stages"]))
                print(f"{name}, {_label(v)}, data {k}: {times[v][-1]:.1f} s, "
                      f"{verdicts[v][-1]}", flush=True)
                detail.append(f"* {name}, {_label(v)}, data {k}: " + "; ".join(
                    f"{r['stage']} {r['seconds']:.1f} s ({r['evaluations']})"
                    for r in res.extra["stages"]))
                detail.append("  " + "; ".join(
                    f"{n} {res.params[n].value:.4g} [{lo:.4g}, {hi:.4g}]"
                    for n, (lo, hi) in res.intervals.items()))
        for v in variants:
            t = times[v]
            lines.append(f"| {name}, {_label(v)} | {statistics.median(t):.1f} s | "
                         f"{max(t):.1f} s | {', '.join(f'{x:.1f}' for x in t)} | "
                         f"{', '.join(verdicts[v])} | "
                         f"{', '.join(map(str, stages[v]))} |")
    lines[2] += (
        f" Load average {load:.1f} at the start, {os.getloadavg()[0]:.1f} at the end.")
    lines += ["", "Stages (seconds, model evaluations) and the 95.4 % intervals "
              f"(truth: {truth}):", "", *detail, ""]
    out = HERE / "results" / "fit.md"
    before = out.read_text().replace("# ", "## Before: ", 1) if out.exists() else ""
    out.write_text("\n".join(lines) + ("\n" + before if before else ""))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
