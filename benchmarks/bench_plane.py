"""Cost and accuracy of the 2-D (transverse) in-plane solver (issue 20, item 2).

For each regime of :data:`REGIMES` (a transverse oscillation ``a_y > 0``, alone or with
the normal and the longitudinal ones, substrate and holder, Jenkins and Kelvin-Voigt
contacts, jumping, stiff and soft systems), the median time of one ``solve_points`` call
on a single point (the solver's whole work: transient, Newton, means, the error's second
solve), its stated ``error`` and status, and side by side in the same run the
independent reference ``vibrofriction_reference.inplane_mean`` (solve_ivp DOP853, 150 +
40 periods, its tolerance check included) once: its time, its error bars and the
difference of the two.  ``--order`` measures the order of the Runge-Kutta method at one
point: the mean's error against the number of steps per period as the tolerance falls.

    PYTHONPATH=src python benchmarks/bench_plane.py [--order] [--write]

``--write`` appends the run to benchmarks/results/plane.md (the earlier runs stay above).
The issue's target: a 2-D point with ``error <= 1e-6`` in a median of at most 20 ms over
the regimes.
"""

from __future__ import annotations

import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from sections import append_run
from vibrofriction._kernels import plane
from vibrofriction.schema import Status
from vibrofriction.solver import solve_points
from vibrofriction_reference import inplane_mean

# (label, alpha, beta, a, V, zeta, eta_c, a_x, phase_x, a_y, phase_y, inplane_on)
REGIMES = [
    ("transverse only", 0.5, 2.0, 0.0, 0.3, 0.05, 0.0, 0.0, 0.0, 0.8, 0.0, "substrate"),
    ("normal + transverse, K-V", 0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.0, 0.0, 0.5, 1.0,
     "substrate"),
    ("normal + transverse, Jenkins", 0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0, 0.0, 0.5, 1.0,
     "substrate"),
    ("holder", 0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0, 0.0, 0.5, 2.5, "holder"),
    ("all three", 0.5, 2.0, 0.5, 0.4, 0.05, 0.1, 0.5, math.pi / 2, 0.5, 0.0, "substrate"),
    ("jumping, K-V", 0.5, 4.0, 1.5, 0.3, 0.1, 0.2, 0.0, 0.0, 0.5, 0.5, "substrate"),
    ("jumping, Jenkins", 0.5, 4.0, 1.5, 0.3, 0.1, 0.0, 0.0, 0.0, 0.5, 0.5, "substrate"),
    ("lightly damped stick-slip", 0.3, 3.0, 0.7, 0.2, 0.01, 0.0, 0.0, 0.0, 0.3, 4.0,
     "substrate"),
    ("stiff system", 5.0, 50.0, 0.6, 0.5, 0.05, 0.05, 0.0, 0.0, 0.6, 1.2, "substrate"),
    ("soft heavy, holder", 0.05, 1.5, 0.8, 0.1, 0.1, 0.0, 0.0, 0.0, 0.3, 5.0, "holder"),
    ("alpha > 1", 2.0, 6.0, 0.5, 0.2, 0.1, 0.0, 0.3, 2.2, 0.4, 1.0, "holder"),
    ("backward", 0.5, 2.0, 0.5, -0.3, 0.05, 0.1, 0.5, 1.0, 0.5, 1.0, "substrate"),
]
REPEATS = 9
RESULTS = Path(__file__).parent / "results" / "plane.md"


def _solve(r):
    _, al, be, a, V, ze, et, ax, px, ay, py, on = r
    return solve_points(al, be, a, V, ze, et, ax, px, ay, py, inplane_on=on)


def bench() -> list[str]:
    _solve(REGIMES[0])  # compile
    lines = ["| regime | median ms | mu_ratio | lateral_ratio | error | status | reference s "
             "| reference bars (mu, lateral) | abs difference (mu, lateral) |",
             "|---|---|---|---|---|---|---|---|---|"]
    medians, ok = [], 0
    for r in REGIMES:
        times = []
        for _ in range(REPEATS):
            t0 = time.perf_counter()
            c = _solve(r)
            times.append(time.perf_counter() - t0)
        med = statistics.median(times) * 1e3
        medians.append(med)
        _, al, be, a, V, ze, et, ax, px, ay, py, on = r
        t0 = time.perf_counter()
        ref = inplane_mean(al, be, a, V, 150, 40, zeta=ze, eta_c=et, a_x=ax, phase_x=px,
                           a_y=ay, phase_y=py, inplane_on=on)
        tr = time.perf_counter() - t0
        mu, lat, err = float(c["mu_ratio"]), float(c["lateral_ratio"]), float(c["error"])
        ok += err <= 1e-6
        status = Status.from_code(int(c["status"])).value
        line = (f"| {r[0]} | {med:.1f} | {mu:+.10f} | {lat:+.10f} | {err:.1e} | "
                f"{status} | {tr:.1f} | {ref.mu_error:.1e}, {ref.lateral_error:.1e} | "
                f"{abs(mu - ref.mu_ratio):.1e}, {abs(lat - ref.lateral_ratio):.1e} |")
        print(line, flush=True)
        lines.append(line)
    lines += ["", f"Median over the {len(REGIMES)} regimes of the per-point medians: "
              f"**{statistics.median(medians):.1f} ms** (largest {max(medians):.1f} ms); "
              f"{ok} of {len(REGIMES)} points with error <= 1e-6."]
    print(lines[-1])
    return lines


def order() -> list[str]:
    """The mean's error against steps per period at one point (normal + transverse,
    Kelvin-Voigt contact): the Newton orbit at each tolerance, against ``rtol = 1e-14``,
    the step not capped (so that the tolerance alone sets it)."""
    al, be, a, V, ze, et, ay, py = 0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.5, 1.0
    P = plane.parameters(al, be, a, V, ze, et, 0.0, 0.0, ay, py, al, ze, True)
    hmax = 1.0  # the solver caps the step at 2 pi/(8 w); here the tolerance decides

    def orbit(rtol):
        W = np.zeros((plane.N_W, plane.N_Z))
        cnt = np.zeros(plane.N_C, np.int64)
        s = np.empty(plane.N_S)
        plane.start_state(P, 0, 0.0, 0.0, 0.0, s)
        J = np.zeros((plane.N_S, plane.N_S))
        info = np.zeros(4)
        assert plane.newton(P, s, np.empty(plane.N_S), False, rtol, rtol, hmax, W, cnt, 10000,
                            1e-13, max(1e-12, 100 * rtol), 30, J, info, False, plane.DIFF_STEP,
                            0.0, np.zeros(7), plane.CHORD_NEAR * 1e-13)
        out = np.zeros(7)
        before = cnt[plane.C_STEPS]
        plane.orbit_mean(P, s, rtol, rtol, hmax, W, cnt, 10000, out)
        return out[0], cnt[plane.C_STEPS] - before

    exact, _ = orbit(1e-14)
    lines = ["| rtol | steps per period | abs error of mu | local order |", "|---|---|---|---|"]
    prev = None
    for k in range(5, 13):
        rtol = 10.0 ** -k
        mu, steps = orbit(rtol)
        e = abs(mu - exact)
        p = "" if prev is None else f"{-math.log(e / prev[1]) / math.log(steps / prev[0]):.2f}"
        lines.append(f"| 1e-{k} | {steps} | {e:.2e} | {p} |")
        print(lines[-1], flush=True)
        prev = (steps, e)
    return lines


def main() -> None:
    rows = order() if "--order" in sys.argv else []
    table = bench()
    if "--write" not in sys.argv:
        return
    lines = []
    if rows:
        lines += ["### Order of the method", "",
                  "Normal + transverse, Kelvin-Voigt contact, `(alpha, beta, a, V, zeta, "
                  "eta_c, a_y, phase_y) = (0.5, 2, 0.5, 0.3, 0.05, 0.1, 0.5, 1.0)`: the "
                  "periodic orbit and its mean at each tolerance against `rtol = 1e-14`, "
                  "the step not capped; "
                  "local order = -d log(error) / d log(steps).", "", *rows, ""]
    command = " ".join(["PYTHONPATH=src python benchmarks/bench_plane.py", *sys.argv[1:]])
    append_run(RESULTS, "The 2-D (transverse) in-plane solver: speed and accuracy", command,
               f"medians of {REPEATS} calls of `solve_points` on one point, the reference "
               "once, in the same run.", lines + ["### Regimes", "", *table])


if __name__ == "__main__":
    main()
