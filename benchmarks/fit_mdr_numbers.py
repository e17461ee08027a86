"""The numbers of docs/bench.md, "Fit and design with a curved contact", regenerated.

The held-out MDR bench table (tests/data/mdr_bench.csv, .json: a steel sphere of radius
3 mm on steel, 20 N, an 800 Hz pin of 20 g with Q = 50, driven at 1 kHz, mu0 = 0.3;
two indentation amplitudes x 9 velocities, noise 0.003, made by the independent spring-row
reference ``vibrofriction_reference.mdr``), and the calls of tests/bench/test_fit_mdr.py:

1. chi-square of the MDR model and of the linearised sphere at the truth (no fit);
2. the fit with ``contact_model="mdr"``, ``free = mu0, radius, mass``, from a guess 1.3x
   off in each (``contact=`` the guess's sphere, ``workers=2``, the curved defaults:
   ``tol_trusted`` 1e-4, a global stage of 20 generations of 8 x 3 members, 2 local
   starts): verdict, intervals (do they hold the truth?), time by stage;
3. the same fit with the linearised sphere (``contact_model="linearised"``);
4. the design of the MDR pin (the test's call), its optimum re-evaluated by the reference;
5. the MDR solver's tolerance: the 18 rows at the truth and at the 1.3x-off guess with
   ``tol_trusted`` 1e-5 (the default) and 1e-4 (the fit's ``CURVED_TOL``): CPU seconds
   (median of 3) and chi-square.

Run: ``python benchmarks/fit_mdr_numbers.py > benchmarks/results/fit_mdr.md`` (minutes
on 2 cores; the machine's load is printed, timings move with it); ``--only 5`` runs
section 5 alone (``> benchmarks/results/fit_mdr_tol.md``).
"""

from __future__ import annotations

import argparse
import datetime
import math
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT / "tests" / "bench"))


def tolerance() -> None:
    """Section 5: the 18 rows at the truth and the guess, tol_trusted 1e-5 and 1e-4."""
    import numpy as np
    import test_fit_mdr as t

    from vibrofriction.bench import predict_cof
    from vibrofriction.solver import SolverSettings

    data = t._data()
    cols = [data[c].to_numpy() for c in ("v0", "du_z", "omega")]
    print("## 5. The MDR solver's tolerance on the 18 rows\n")
    print("| system | tol_trusted | CPU s (median of 3) | chi-square |\n|---|---|---|---|")
    guess = t._pin(radius=t.T["radius"] * t.OFF, mass=t.T["mass"] / t.OFF,
                   mu0=t.T["mu0"] * t.OFF)
    predict_cof(guess, *cols)  # compile
    for label, pin in (("truth", t._pin()), ("guess 1.3x off", guess)):
        for tol in (1e-5, 1e-4):
            times = []
            for _ in range(3):
                c0 = time.process_time()
                cof = predict_cof(pin, *cols, SolverSettings(tol_trusted=tol))
                times.append(time.process_time() - c0)
            r = (cof - data["cof"].to_numpy()) / data["sigma"].to_numpy()
            print(f"| {label} | {tol:g} | {float(np.median(times)):.3f} | {float(r @ r):.3f} |")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--only", choices=["5"], default=None)
    args = parser.parse_args()
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=ROOT).stdout.strip()
    print(f"# MDR fit and design numbers\n\n`python benchmarks/fit_mdr_numbers.py"
          f"{' --only ' + args.only if args.only else ''}`, "
          f"{datetime.date.today()}, commit {commit}, {platform.platform()}, "
          f"{os.cpu_count()} cores, load average at start {os.getloadavg()[0]:.1f}\n")
    if args.only == "5":
        tolerance()
        return
    import test_fit_mdr as t  # the test's set-up: data, truth, guess, the reference call

    from vibrofriction_reference.mdr import mdr_reference

    print("## 1. At the truth (no fit)\n")
    mdr, lin = t._chisq(t._pin()), t._chisq(t._pin(model="linearised"))
    print(f"chi-square of 18 points: MDR {mdr:.2f}, linearised {lin:.1f}\n")
    for n, model in ((2, "mdr"), (3, "linearised")):
        print(f"## {n}. Fit, contact_model={model!r}, free = mu0, radius, mass, from 1.3x off\n")
        res = t._fit(model)
        print("```\n" + res.report() + "\n```\n")
        truth = {"mu0": t.T["mu0"], "radius": t.T["radius"], "mass": t.T["mass"],
                 "k_zc": t._pin(model=model).k_zc}
        for name, value in truth.items():
            lo, hi = res.intervals[name]
            print(f"* {name}: fitted {res.params[name].value:.6g}, interval [{lo:.5g}, "
                  f"{hi:.5g}] ({100 * (hi - lo) / res.params[name].value:.1f} % wide), truth "
                  f"{value:.6g}: {'inside' if lo <= value <= hi else 'OUTSIDE'}")
        stages = ", ".join(f"{r['stage']} {r['seconds']:.1f} s ({r['evaluations']} "
                           "evaluations)" for r in res.extra["stages"])
        print(f"* {res.seconds:.1f} s wall with workers=2: {stages}; load average now "
              f"{os.getloadavg()[0]:.1f}\n")
    print("## 4. Design of the MDR pin, re-evaluated by the reference\n")
    pin = t._pin()
    t0 = time.perf_counter()
    import vibrofriction as vf
    res = vf.design(pin, v0=0.01, omega=(2 * math.pi * 500, 2 * math.pi * 2000),
                    du_z=(0.1e-6, 1.5e-6), max_velocity_amplitude=0.012, n_omega=9,
                    n_du_z=5, starts=2)
    seconds = time.perf_counter() - t0
    s = res.system
    g = t._bench_module().groups({**t.T, "drive_frequency_hz": s.omega / (2 * math.pi)},
                                 s.du_z, 0.01)
    ref = mdr_reference(g["alpha"], g["beta"], g["amplitude"], g["V"], 2.0, zeta=g["zeta"],
                        transient_periods=300, average_periods=20)
    mu0 = t.T["mu0"]
    print("```\n" + res.report() + "\n```\n")
    print(f"* {seconds:.1f} s; optimum f = {s.omega / (2 * math.pi):.5g} Hz, du_z = "
          f"{s.du_z:.4g} m: COF {res.cof:.6f} (solver error {mu0 * res.error:.1e}); the "
          f"reference {mu0 * ref.mu_ratio:.6f} (+- {mu0 * ref.mu_error:.1e}); difference "
          f"{res.cof - mu0 * ref.mu_ratio:+.1e}\n")
    tolerance()


if __name__ == "__main__":
    main()
