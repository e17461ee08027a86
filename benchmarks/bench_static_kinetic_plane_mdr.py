"""Cost of a static coefficient above the kinetic one in the 2-D solver and the MDR row.

Side by side in one run: each point of :data:`PLANE` (a transverse oscillation, Jenkins and
Kelvin-Voigt contacts, jumping, all three drives on the holder) and of :data:`MDR` (sphere,
cone, jumping sphere) is solved by ``solve_points`` at ``static_ratio = 1`` and at
:data:`S` alternately, :data:`REPEATS` times each (after one warm-up call of each); the
table gives the medians of the wall times, their ratio, and each answer (``mu_ratio``,
status, stated error, events).  The law's target for the 1-D solver: a static-above-kinetic
point at most 1.5 times a Coulomb point at the same parameters (median over regimes).
Second table: the MDR row's convergence in the number of springs ``N`` at the sphere
point, ``s = 1`` and ``s = 1.3`` (each row from the sliding start, ``mdr_row``), against
the row of 2560 springs.

    PYTHONPATH=src python benchmarks/bench_static_kinetic_plane_mdr.py [--write]

``--write`` appends its run to benchmarks/results/static_kinetic_plane_mdr.md.
"""

from __future__ import annotations

import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from vibrofriction.schema import Status
from vibrofriction.solver import solve_points
from vibrofriction.solver.mdr import mdr_row

S = 1.3
REPEATS = 9
RESULTS = Path(__file__).parent / "results" / "static_kinetic_plane_mdr.md"
# (label, keywords of solve_points)
PLANE = [
    ("2-D, Jenkins", dict(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.3, zeta=0.05,
                          a_y=0.5, phase_y=1.0)),
    ("2-D, Kelvin-Voigt", dict(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.3,
                               zeta=0.05, eta_c=0.1, a_y=0.5, phase_y=1.0)),
    ("2-D, jumping Jenkins", dict(alpha=0.5, beta=4.0, amplitude=1.5, v_inertial=0.3,
                                  zeta=0.1, a_y=0.5, phase_y=0.5)),
    ("2-D, all three, holder", dict(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.4,
                                    zeta=0.05, eta_c=0.1, a_x=0.5, phase_x=1.57, a_y=0.5,
                                    phase_y=3.0, inplane_on="holder")),
]
MDR = [
    ("MDR, sphere", dict(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.3, zeta=0.1,
                         profile_exponent=2.0)),
    ("MDR, cone", dict(alpha=1.0, beta=3.0, amplitude=0.7, v_inertial=0.5, zeta=0.1,
                       profile_exponent=1.0)),
    ("MDR, jumping sphere", dict(alpha=0.5, beta=2.0, amplitude=1.5, v_inertial=0.3,
                                 zeta=0.1, profile_exponent=2.0)),
]


def _timed(kw: dict, s: float) -> tuple[float, dict]:
    t = time.perf_counter()
    r = solve_points(**kw, static_ratio=s)
    return time.perf_counter() - t, r


def measure() -> list[tuple]:
    """``(label, t1, ts, ratio, r1, rs)`` per point, medians over :data:`REPEATS`."""
    rows = []
    for label, kw in PLANE + MDR:
        _timed(kw, 1.0)
        _timed(kw, S)
        t1, ts = [], []
        for _ in range(REPEATS):  # alternately, so that the machine's load falls on both
            dt, r1 = _timed(kw, 1.0)
            t1.append(dt)
            dt, rs = _timed(kw, S)
            ts.append(dt)
        m1, ms = statistics.median(t1), statistics.median(ts)
        rows.append((label, m1, ms, ms / m1, r1, rs))
    return rows


def _answer(r: dict) -> str:
    st = Status.from_code(int(r["status"])).value
    return (f"{float(r['mu_ratio']):.8f} ({st}, error {float(r['error']):.1e}, "
            f"{int(r['events'])} events)")


def table(rows: list[tuple]) -> str:
    head = ["| point | s = 1: ms | s = 1.3: ms | ratio | s = 1: mu_ratio | s = 1.3: mu_ratio |",
            "|---|---|---|---|---|---|"]
    body = [f"| {lab} | {1e3 * t1:.1f} | {1e3 * ts:.1f} | {q:.2f} | {_answer(r1)} | "
            f"{_answer(rs)} |" for lab, t1, ts, q, r1, rs in rows]
    ratios = [r[3] for r in rows]
    plane = statistics.median([r[3] for r in rows[:len(PLANE)]])
    mdr = statistics.median([r[3] for r in rows[len(PLANE):]])
    tail = [f"\nMedian ratio (s = {S} over s = 1): 2-D {plane:.2f}, MDR {mdr:.2f}, all "
            f"{statistics.median(ratios):.2f}."]
    return "\n".join(head + body + tail)


ROWS = (40, 80, 160, 240, 280, 320, 400, 480, 560, 640, 1280)


def convergence() -> str:
    """The MDR sphere's row means against ``N`` at ``s = 1`` and ``S``."""
    kw = MDR[0][1]
    args = (kw["alpha"], kw["beta"], kw["amplitude"], kw["v_inertial"],
            kw["profile_exponent"])
    lines = [f"| N | s = 1: mu_ratio - mu(2560) | s = {S}: mu_ratio - mu(2560) |",
             "|---|---|---|"]
    cols = []
    for s in (1.0, S):
        ref = mdr_row(*args, 2560, kw["zeta"], static_ratio=s)["mu_ratio"]
        cols.append([mdr_row(*args, n, kw["zeta"], static_ratio=s)["mu_ratio"] - ref
                     for n in ROWS])
    lines += [f"| {n} | {a:+.2e} | {b:+.2e} |" for n, a, b in zip(ROWS, *cols, strict=True)]
    return "\n".join(lines)


def main() -> None:
    rows = measure()
    text = table(rows) + "\n\nThe MDR row's convergence in N (sphere point):\n\n" \
        + convergence()
    print(text)
    if "--write" in sys.argv:
        rev = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                             text=True, check=False).stdout.strip()
        head = "# A static coefficient above the kinetic one: 2-D solver and MDR row\n\n"
        if RESULTS.exists():  # a new section below the earlier runs
            head = RESULTS.read_text().rstrip("\n") + "\n\n## A later run\n\n"
        RESULTS.write_text(
            head + f"`python benchmarks/bench_static_kinetic_plane_mdr.py --write`, "
            f"{time.strftime('%Y-%m-%d')}, commit {rev}, Python {platform.python_version()}, "
            f"numpy {np.__version__}; wall times, medians of {REPEATS} calls of "
            "`solve_points` on one point, the two laws alternately in the same run, on a "
            "2-core machine shared with other sessions.\n\n" + text + "\n")


if __name__ == "__main__":
    main()
