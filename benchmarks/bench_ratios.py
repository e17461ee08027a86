"""What the physics added costs against the flat punch's 1-D point, side by side in one run.

At each regime of :data:`REGIMES` (the same ``alpha, beta, a, zeta, V``; stiff, soft,
resonant, damped, jumping, with a longitudinal drive) one ``solve_points`` call is timed
(median of :data:`REPEATS` calls, the kernels warm; each call solves the point
:data:`COPIES` times, as a curve or a fit solves many points a call, and the time is per
point: a one-point call adds the Python of a call, about 0.3-0.4 ms, to every method; 32
copies leave about 10 us of it a point) for:

* the flat punch (the 1-D event-driven solver): the base;
* curved tips by the MDR solver: a cone (``n = 1``), a sphere (``n = 2``), ``n = 4``;
* the same point with a transverse oscillation ``a_y = 0.5`` (the 2-D solver), and, as its
  1-D base, the flat point again (the base is the same call).

Each row gives the times, the ratios to the flat point and each answer's stated error and
status; the summary the medians of the ratios over the regimes (the issue's targets: at most
10x for a curved tip with a stated error of at most 1e-7, at most 10x for a 2-D point).

    PYTHONPATH=src python benchmarks/bench_ratios.py [--write]

``--write`` appends the tables, with the commit, date and machine, to
benchmarks/results/ratios.md (the earlier runs stay above).
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
from pathlib import Path

import numpy as np

from sections import append_run
from vibrofriction.schema import Status
from vibrofriction.solver import solve_points

# (label, alpha, beta, a, V, zeta, a_x)
REGIMES = [
    ("general stick-slip", 0.5, 2.0, 0.5, 0.3, 0.0, 0.0),
    ("soft pin, stiff contact", 0.05, 20.0, 0.5, 0.1, 0.0, 0.0),
    ("stiff pin", 5.0, 50.0, 0.6, 0.5, 0.0, 0.0),
    ("near resonance, alpha ~ 1", 0.95, 3.0, 0.4, 0.3, 0.0, 0.0),
    ("damped", 0.5, 2.0, 0.7, 0.3, 0.1, 0.0),
    ("lightly damped, slow", 0.3, 3.0, 0.7, 0.05, 0.01, 0.0),
    ("jumping, a > 1", 0.5, 4.0, 1.5, 0.3, 0.0, 0.0),
    ("jumping, damped", 0.5, 4.0, 1.5, 0.3, 0.1, 0.0),
    ("longitudinal drive", 0.5, 2.0, 0.5, 0.3, 0.05, 0.3),
    ("fast, near sliding", 0.5, 2.0, 0.5, 0.9, 0.0, 0.0),
]
EXPONENTS = (1.0, 2.0, 4.0)
A_Y = 0.5
REPEATS = 3
COPIES = 32
RESULTS = Path(__file__).parent / "results" / "ratios.md"


def _timed(**kw) -> tuple[float, dict]:
    """Seconds per point (median of :data:`REPEATS` calls of :data:`COPIES` copies) and the
    first copy's result."""
    kw = {k: np.full(COPIES, v) for k, v in kw.items()}
    out = solve_points(**kw)  # warm (compiled kernels load on the first call)
    times = []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        out = solve_points(**kw)
        times.append((time.perf_counter() - t0) / COPIES)
    return statistics.median(times), {k: v[0] for k, v in out.items()}


def _answer(out: dict) -> str:
    status = Status.from_code(int(out["status"])).value
    return f"{float(out['error']):.1e} ({status})"


def bench() -> list[str]:
    head = ("| regime | flat ms | " + " | ".join(f"n = {n:g}: ms, ratio, error" for n in EXPONENTS)
            + f" | 2-D (a_y = {A_Y}): ms, ratio, error |")
    lines = [head, "|" + "---|" * (3 + len(EXPONENTS))]
    curved_ratios, plane_ratios, curved_errors = [], [], []
    for label, alpha, beta, a, V, zeta, a_x in REGIMES:
        base = {"alpha": alpha, "beta": beta, "amplitude": a, "v_inertial": V, "zeta": zeta,
                "a_x": a_x}
        t_flat, flat = _timed(**base)
        cells = [label, f"{1e3 * t_flat:.3f} ({_answer(flat)})"]
        for n in EXPONENTS:
            t, out = _timed(**base, profile_exponent=n)
            curved_ratios.append(t / t_flat)
            curved_errors.append(float(out["error"]))
            cells.append(f"{1e3 * t:.2f}, {t / t_flat:.0f}x, {_answer(out)}")
        t, out = _timed(**base, a_y=A_Y)
        plane_ratios.append(t / t_flat)
        cells.append(f"{1e3 * t:.2f}, {t / t_flat:.0f}x, {_answer(out)}")
        line = "| " + " | ".join(cells) + " |"
        print(line, flush=True)
        lines.append(line)
    within = sum(e <= 1e-7 for e in curved_errors)
    lines += [
        "",
        f"Median ratio to the flat point: curved tips **{statistics.median(curved_ratios):.1f}x** "
        f"({min(curved_ratios):.0f}x to {max(curved_ratios):.0f}x over "
        f"{len(curved_ratios)} points; {within} of them with a stated error <= 1e-7), "
        f"2-D **{statistics.median(plane_ratios):.1f}x** ({min(plane_ratios):.0f}x to "
        f"{max(plane_ratios):.0f}x over {len(plane_ratios)}).",
    ]
    print(lines[-1])
    return lines


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--write", action="store_true", help=f"append to {RESULTS}")
    args = ap.parse_args()
    lines = bench()
    if args.write:
        append_run(RESULTS, "The cost of curved tips and of the 2-D solver against a flat point",
                   "PYTHONPATH=src python benchmarks/bench_ratios.py --write",
                   f"load average {os.getloadavg()[0]:.1f} at the end; each time per point, the "
                   f"median of {REPEATS} calls of `solve_points` on {COPIES} copies of the "
                   "point, the kernels warm; the stated error and status after each time.",
                   lines)


if __name__ == "__main__":
    main()
