"""Cost of a static coefficient above the kinetic one against Coulomb friction, side by side.

The benchmark's regimes (``bench_solver.POINTS``) plus damped, viscoelastic and rigid
points, each solved with Coulomb friction (``static_ratio = 1``) and with
``static_ratio = 1.3`` and ``2`` at the same parameters, alternately in one process
(``friction_coefficient``, the scalar path): median wall time per point and the ratio per
regime; the target is a median ratio of at most 1.5.

Run: ``.venv/bin/python benchmarks/bench_static_kinetic.py`` (appends its run to
benchmarks/results/static_kinetic.md, the earlier runs kept).  ``--quick``: fewer repeats.
"""

from __future__ import annotations

import os
import platform
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

import vibrofriction as vf  # noqa: E402
from bench_solver import POINTS, _median_time  # noqa: E402

HERE = Path(__file__).resolve().parent
QUICK = "--quick" in sys.argv
RATIOS = (1.3, 2.0)
# (label, alpha, beta, a, vbar, V, zeta, eta_c) beyond bench_solver's regimes
EXTRA = [("damped stick-slip", 0.5, 2.0, 0.5, 0.5, None, 0.05, 0.0),
         ("viscoelastic contact", 0.5, 2.0, 0.5, 0.5, None, 0.0, 0.2),
         ("rigid, damped, a = 0.8", 0.3, float("inf"), 0.8, 0.5, None, 0.05, 0.0),
         ("jumping, damped", 0.3, 5.0, 1.3, 0.5, None, 0.02, 0.0)]


def rows() -> list[dict]:
    out = []
    points = [(*p, 0.0, 0.0) for p in POINTS] + EXTRA
    for label, alpha, beta, a, vbar, v_in, zeta, eta in points:
        base = vf.Dimensionless(alpha, beta, a, zeta, eta)
        V = float(base.vbar_to_inertial(vbar)) if vbar is not None else v_in
        systems = [vf.Dimensionless(alpha, beta, a, zeta, eta, static_ratio=s)
                   for s in (1.0, *RATIOS)]
        for s in systems:  # compile and warm up
            vf.friction_coefficient(s, v_inertial=V)
        res = [[], [], []]
        for _ in range(3 if QUICK else 9):  # alternate, so that drifts hit both alike
            for i, s in enumerate(systems):
                res[i].append(_median_time(
                    lambda s=s, V=V: vf.friction_coefficient(s, v_inertial=V),
                    3 if QUICK else 7, 2.0))
        times = [statistics.median(t for t, _ in r) for r in res]
        results = [r[-1][1] for r in res]
        row = {"point": label, "V": V, "zeta": zeta, "eta_c": eta,
               "coulomb_ms": times[0] * 1e3,
               "coulomb": results[0]}
        for sr, t, r in zip(RATIOS, times[1:], results[1:], strict=True):
            row[sr] = (t * 1e3, t / times[0], r)
        out.append(row)
        print(f"{label:24s} coulomb {times[0] * 1e3:7.3f} ms "
              + " ".join(f"s_r={sr}: {row[sr][0]:7.3f} ms ({row[sr][1]:.2f}x, "
                         f"mu {row[sr][2].mu_ratio:.6f} {row[sr][2].status.value})"
                         for sr in RATIOS), flush=True)
    return out


def report(table: list[dict]) -> str:
    lines = ["# A static coefficient above the kinetic one: cost against Coulomb friction", "",
             "Command: `.venv/bin/python benchmarks/bench_static_kinetic.py`  ",
             f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python "
             f"{platform.python_version()}, numpy {np.__version__}; one process, one core.  ",
             f"Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}", "",
             "Median wall time per steady-state point of `friction_coefficient` (the scalar "
             "path), Coulomb friction and `static_ratio` = 1.3, 2 at the same parameters, "
             "timed alternately in one run.", "",
             "| point | V | zeta | eta_c | Coulomb (ms) | mu/mu0 | "
             + " | ".join(f"s_r = {sr} (ms) | ratio | mu/mu0 | status" for sr in RATIOS)
             + " |",
             "|---" * (6 + 4 * len(RATIOS)) + "|"]
    for row in table:
        c = row["coulomb"]
        cells = [row["point"], f"{row['V']:.4g}", f"{row['zeta']:g}", f"{row['eta_c']:g}",
                 f"{row['coulomb_ms']:.3f}", f"{c.mu_ratio:.6f}"]
        for sr in RATIOS:
            t, ratio, r = row[sr]
            cells += [f"{t:.3f}", f"{ratio:.2f}", f"{r.mu_ratio:.6f}", r.status.value]
        lines.append("| " + " | ".join(cells) + " |")
    lines.append("")
    for row in table:
        for sr in RATIOS:
            r = row[sr][2]
            if r.status.value == "not converged":
                lines.append(f"* {row['point']}, `static_ratio = {sr}`: the motion does not lock "
                             f"to the drive within {r.periods} periods (its window means "
                             f"{r.window_min:.7f} ... {r.window_max:.7f}): not converged, the "
                             "time is the whole budget.")
    for sr in RATIOS:
        ratios = [row[sr][1] for row in table]
        lines.append(f"* `static_ratio = {sr}`: median ratio over the {len(ratios)} regimes "
                     f"**{statistics.median(ratios):.2f}** (range {min(ratios):.2f} - "
                     f"{max(ratios):.2f}); target at most 1.5.")
    return "\n".join(lines) + "\n"


def main() -> None:
    table = rows()
    text = report(table)
    if not QUICK:  # a new section below the earlier runs (the file's title once)
        path = HERE / "results" / "static_kinetic.md"
        if path.exists():
            _, body = text.split("\n", 1)
            text = path.read_text().rstrip("\n") + "\n\n## A later run\n" + body
        path.write_text(text)
    print(text)


if __name__ == "__main__":
    main()
