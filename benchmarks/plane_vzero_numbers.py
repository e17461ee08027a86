"""The numbers of docs/inplane.md on the 2-D solver at ``v0 = 0`` and near it (issue 20).

    PYTHONPATH=src python benchmarks/plane_vzero_numbers.py    # writes results/plane_vzero.md
    PYTHONPATH=src python benchmarks/plane_vzero_numbers.py --slow-only --repeats 1 --print

Part 1: the ``V = 0`` points of ``tests/data/plane_vzero_reference.json`` (the reference's
values are read from it, not recomputed) solved from rest and from a preload of half the
friction limit along ``x``: status, ``mu_ratio``, ``lateral_ratio``, stated error, the
difference from the reference from the same start, the stuck region's ``x`` extent
(``theory.plane_static_region``) and the median time of ``--repeats`` solves.  Part 2:
the slow points near ``V = 0`` (the fit's ``v0 = -1.4e-4 m/s`` of the transverse bench
and ``fuzz_plane.py``'s slowest point): status, values, error, periods and the median
time.  ``--slow-only --print`` runs part 2 alone and prints it, which also runs on the
code before this change (``git archive <commit> src`` and ``PYTHONPATH`` at it): the
"before" column of docs/inplane.md.  A 2-core machine shared with other sessions: times
are medians and noisy.
"""

from __future__ import annotations

import argparse
import json
import math
import platform
import subprocess
import time
from datetime import UTC, datetime
from pathlib import Path

import numpy as np

from vibrofriction.solver import solve_points

try:  # absent before this change (part 2 runs on the old code too)
    from vibrofriction import theory
    from vibrofriction.solver import SectionState
except ImportError:  # pragma: no cover
    theory = None

HERE = Path(__file__).resolve().parent
DATA = HERE.parent / "tests" / "data" / "plane_vzero_reference.json"
RESULTS = HERE / "results" / "plane_vzero.md"
PI = math.pi
STATUS = {0: "periodic", 1: "averaged", 2: "not converged", 3: "failed", 5: "held"}

#: (label, alpha, beta, a, V, zeta, eta_c, a_x, phase_x, a_y, phase_y, alpha_y, zeta_y)
SLOW = [
    ("transverse bench, v0 = -1.4e-4 m/s", 0.64, 0.64 + 3e6 / (0.02 * (2 * PI * 1e3) ** 2),
     0.6, -1.4e-4 * 0.02 * 2 * PI * 1e3 / 6.0, 0.01, 0.0, 0.0, 0.0,
     3e-6 * 0.02 * (2 * PI * 1e3) ** 2 / 6.0, 0.0, 0.6 * 0.64, 0.01 / math.sqrt(0.6)),
    ("transverse bench, phase_y = pi/2", 0.64, 0.64 + 3e6 / (0.02 * (2 * PI * 1e3) ** 2),
     0.6, -1.4e-4 * 0.02 * 2 * PI * 1e3 / 6.0, 0.01, 0.0, 0.0, 0.0,
     3e-6 * 0.02 * (2 * PI * 1e3) ** 2 / 6.0, PI / 2, 0.6 * 0.64, 0.01 / math.sqrt(0.6)),
    ("fuzz_plane slowest (undamped)", 0.15197844544689837, 4.644902947034958,
     0.8605751934496317, 0.0015949771032228717, 0.0, 0.0, 0.0, 0.1729660560039444,
     0.038576975875694114, 5.125650963518721, 0.15197844544689837, 0.0),
]


def _timed(repeats: int, f):
    times, out = [], None
    for _ in range(repeats):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return out, float(np.median(times))


def _slow_rows(repeats: int) -> list[str]:
    rows = ["| point | V | status | mu_ratio | lateral_ratio | error | periods | median time |",
            "|---|---|---|---|---|---|---|---|"]
    for label, *p in SLOW:
        o, t = _timed(repeats, lambda p=p: solve_points(*p[:10], alpha_y=p[10],
                                                        zeta_y=p[11]))
        rows.append(f"| {label} | {p[3]:.6g} | {STATUS.get(int(o['status']), o['status'])} | "
                    f"{float(o['mu_ratio']):+.9f} | {float(o['lateral_ratio']):+.9f} | "
                    f"{float(o['error']):.2g} | {int(o['periods'])} | {t:.3g} s |")
    return rows


def _zero_rows(repeats: int) -> list[str]:
    data = json.loads(DATA.read_text())
    pre = data["meta"]["preload"]
    rows = ["| point | start | status | mu_ratio | lateral_ratio | error | "
            "mu - ref | lat - ref | region x | median time |",
            "|---|---|---|---|---|---|---|---|---|---|"]
    slips: list[tuple[float, float, float]] = []  # |mu - ref|, |lat - ref|, error
    held: list[float] = []
    for p in data["points"]:
        region = theory.plane_static_region(p["alpha"], p["beta"], p["amplitude"],
                                            p["a_x"], p["phase_x"], p["a_y"], p["phase_y"],
                                            p["zeta"], p["eta_c"], p["inplane_on"],
                                            p["alpha_y"], p["zeta_y"])
        ext = ("none" if math.isnan(region.x_upper)
               else f"[{region.x_lower:+.4f}, {region.x_upper:+.4f}]")
        k = p["beta"] - p["alpha"]
        for name, start in (("rest", "rest"),
                            ("preload", SectionState(-pre / p["alpha"], 0.0, pre, "stick",
                                                     pre / k))):
            args = (p["alpha"], p["beta"], p["amplitude"], 0.0, p["zeta"], p["eta_c"],
                    p["a_x"], p["phase_x"], p["a_y"], p["phase_y"])
            o, t = _timed(repeats, lambda args=args, start=start, p=p: solve_points(
                *args, alpha_y=p["alpha_y"], zeta_y=p["zeta_y"], inplane_on=p["inplane_on"],
                initial=start))
            ref = p[name]
            dmu = abs(float(o["mu_ratio"]) - ref["mu_ref"])
            dlat = abs(float(o["lateral_ratio"]) - ref["lat_ref"])
            if int(o["status"]) != 5:
                slips.append((dmu, dlat, float(o["error"])))
            elif (p["label"], name) != ("held, holder, anisotropic", "preload"):
                held.append(max(dmu, dlat))  # that start has not settled in the reference
            rows.append(
                f"| {p['label']} | {name} | {STATUS[int(o['status'])]} | "
                f"{float(o['mu_ratio']):+.10f} | {float(o['lateral_ratio']):+.10f} | "
                f"{float(o['error']):.1g} | {float(o['mu_ratio']) - ref['mu_ref']:.1e} | "
                f"{float(o['lateral_ratio']) - ref['lat_ref']:.1e} | {ext} | "
                f"{t * 1e3:.0f} ms |")
    mu, lat, err = zip(*slips, strict=True)
    rows += ["", f"Where it slips: |mu - ref| at most {max(mu):.1e}, |lat - ref| at most "
             f"{max(lat):.1e}, stated errors {min(err):.0e} to {max(err):.0e}; held (but the "
             f"anisotropic pin's preloaded start): both within {max(held):.1e}."]
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--slow-only", action="store_true")
    ap.add_argument("--print", action="store_true", help="print, do not write the file")
    args = ap.parse_args()
    solve_points(0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0, 0.0, 0.5, 1.0)  # compile or load
    lines = []
    if not args.slow_only:
        lines += ["## v0 = 0, 2-D: against the reference from two starts", "",
                  *_zero_rows(args.repeats), ""]
    lines += ["## Near v0 = 0: the slow points", "", *_slow_rows(args.repeats), ""]
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=HERE).stdout.strip()
    head = [f"# 2-D solver at and near v0 = 0 ({datetime.now(UTC):%Y-%m-%d}, commit {commit}, "
            f"{platform.machine()} {platform.system()}, python {platform.python_version()})",
            "", "Made by `PYTHONPATH=src python benchmarks/plane_vzero_numbers.py` "
            f"(medians of {args.repeats} runs; a 2-core machine shared with other "
            "sessions).", ""]
    text = "\n".join(head + lines)
    if args.print:
        print(text)
    else:
        RESULTS.write_text(text)
        print(text)


if __name__ == "__main__":
    main()
