"""Random points of the row without springs against the spring rows.

80 points drawn with a fixed seed (11) over ``0 < a < 1``: alpha 1e-2..10, beta - alpha
0.03..100, a 0.05..0.95, V 1e-2..3, zeta in {0, 0.01, 0.1, 0.5}, n in {0.7, 1, 1.5, 2, 3,
5}, a longitudinal drive a_x in {0, 0, 0.5} (random phase, substrate or holder); then 40
jumping points (``a`` 1.05..3, seed 12, the rest alike). Each is solved by the continuum
(:func:`vibrofriction.solver.mdr_continuum.mdr_continuum`) and by the spring rows
(:func:`vibrofriction.solver.mdr.mdr_friction` at ``tol = 1e-6``, rows doubled and
extrapolated). Prints and records the statuses, how many agree within the two stated
errors (and the largest difference over them), the stated errors and periods of the
continuum, and the time per point of both (medians). Then the MDR solver at
``tol = 1e-7`` (which asks the continuum) against the rows at ``1e-7``, at 60 jumping
points (``a`` 1.02..3.5, seed 41) and 30 barely jumping ones (``a`` 1.0005..1.05, seed
42); then the continuum against the independent reference refined to bars of at most 2e-6
(tests/data/mdr_fine_reference.json, the points it covers).

    PYTHONPATH=src python benchmarks/mdr_continuum_fuzz.py [--write]

``--write`` appends the run to benchmarks/results/mdr_continuum_fuzz.md.
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections import Counter
from pathlib import Path

import numpy as np

from sections import append_run
from vibrofriction._kernels.phases import frame_offset, inplane_forcing
from vibrofriction.solver.mdr import mdr_friction, rows_alone
from vibrofriction.solver.mdr_continuum import mdr_continuum

RESULTS = Path(__file__).parent / "results" / "mdr_continuum_fuzz.md"
N = 80


def _points(seed: int = 11, count: int = N, a_range: tuple = (0.05, 0.95)) -> list[tuple]:
    rng = np.random.default_rng(seed)
    pts = []
    for _ in range(count):
        al = 10 ** rng.uniform(-2, 1)
        be = al + 10 ** rng.uniform(-1.5, 2)
        pts.append((al, be, rng.uniform(*a_range), 10 ** rng.uniform(-2, 0.5),
                    float(rng.choice([0, 0.01, 0.1, 0.5])),
                    float(rng.choice([0.7, 1, 1.5, 2, 3, 5])),
                    float(rng.choice([0, 0, 0.5])), rng.uniform(0, 6.3),
                    str(rng.choice(["substrate", "holder"]))))
    return pts


N_JUMPING = 40


def run(points: list[tuple], title: str) -> list[str]:
    statuses: Counter = Counter()
    agree, ratios, errs, periods, t_c, t_r, worst = 0, [], [], [], [], [], ""
    failed: list[str] = []
    for al, be, a, V, ze, n, ax, px, on in points:
        sub = on == "substrate"
        hc, hs = inplane_forcing(al, 2 * ze * np.sqrt(al), ax, px, sub)
        t0 = time.perf_counter()
        c = mdr_continuum(al, be, a, V, n, ze, hc, hs, frame_offset(ax, px, sub))
        t1 = time.perf_counter()
        with rows_alone():  # (the default is the continuum)
            r = mdr_friction(al, be, a, V, n, zeta=ze, tol=1e-6, a_x=ax, phase_x=px,
                             inplane_on=on)
        t2 = time.perf_counter()
        statuses[(c["status"], r["status"])] += 1
        if c["status"] != "periodic":
            failed.append(f"alpha {al:.3g}, beta {be:.3g}, a {a:.3g}, V {V:.3g}, zeta {ze:g}, "
                          f"n {n:g}, a_x {ax:g} ({on}): {c['reason']} after {c['periods']} "
                          "periods")
        t_c.append(t1 - t0)
        t_r.append(t2 - t1)
        if c["status"] != "periodic" or r["status"] != "periodic":
            continue
        q = abs(c["mu_ratio"] - r["mu_ratio"]) / (c["error"] + r["error"])
        agree += q <= 1.0
        if not ratios or q > max(ratios):
            worst = (f"alpha {al:.3g}, beta {be:.3g}, a {a:.3g}, V {V:.3g}, zeta {ze:g}, "
                     f"n {n:g}, a_x {ax:g} ({on})")
        ratios.append(q)
        errs.append(c["error"])
        periods.append(c["periods"])
    both = sum(v for k, v in statuses.items() if k == ("periodic", "periodic"))
    lines = [
        "", f"| {title} | |", "|---|---|",
        "| statuses (continuum, rows): count | " + ", ".join(
            f"{k[0]}/{k[1]}: {v}" for k, v in sorted(statuses.items())) + " |",
        f"| within the two stated errors | {agree} of {both} (largest difference over them "
        f"{max(ratios):.2f}, median {statistics.median(ratios):.3f}) |",
        f"| the worst point | {worst} |",
        f"| continuum: stated error, median and largest | {statistics.median(errs):.1e}, "
        f"{max(errs):.1e} |",
        f"| continuum: periods, median and largest | {statistics.median(periods):.0f}, "
        f"{max(periods)} |",
        f"| time per point, median (continuum, rows at tol 1e-6) | "
        f"{1e3 * statistics.median(t_c):.1f} ms, {1e3 * statistics.median(t_r):.1f} ms |",
        *(f"| not periodic (continuum) | {f} |" for f in failed),
    ]
    for line in lines:
        print(line)
    return lines


def routed(seed: int, count: int, a_range: tuple[float, float], title: str) -> list[str]:
    """``mdr_friction`` at ``tol = 1e-7`` (the continuum) against the rows at ``1e-7``."""
    q, by_rows = [], 0
    for al, be, a, V, ze, n, ax, px, on in _points(seed, count, a_range):
        c = mdr_friction(al, be, a, V, n, zeta=ze, tol=1e-7, a_x=ax, phase_x=px, inplane_on=on)
        with rows_alone():
            r = mdr_friction(al, be, a, V, n, zeta=ze, tol=1e-7, a_x=ax, phase_x=px,
                             inplane_on=on)
        by_rows += c["rows"] != ()
        if c["status"] == r["status"] == "periodic":
            q.append(abs(c["mu_ratio"] - r["mu_ratio"]) / (c["error"] + r["error"]))
    lines = ["", f"| {title} | |", "|---|---|",
             f"| within the two stated errors | {sum(x <= 1.0 for x in q)} of {len(q)} "
             f"(largest difference over them {max(q):.2f}, median "
             f"{statistics.median(q):.3f}) |",
             f"| answered by the rows (the continuum failed) | {by_rows} of {count} |"]
    for line in lines:
        print(line)
    return lines


def against_reference() -> list[str]:
    """The continuum at the independent fine reference's points it covers (``a < 1`` and
    jumping apart).
    """
    import json

    path = Path(__file__).parents[1] / "tests" / "data" / "mdr_fine_reference.json"
    pts = [p for p in json.loads(path.read_text())["points"]
           if 0.0 < p["amplitude"] != 1.0 and p["v_inertial"] > 0.0]
    lines = ["", "| against the independent fine reference | a < 1 | a > 1 |", "|---|---|---|"]
    cells: dict[str, list[str]] = {"points covered": [],
                                   "within the reference's bar plus the stated error": [],
                                   "stated error, largest": []}
    for jumping in (False, True):
        q, errs = _reference_ratios([p for p in pts if (p["amplitude"] > 1.0) == jumping])
        cells["points covered"].append(str(len(q)))
        cells["within the reference's bar plus the stated error"].append(
            f"{sum(x <= 1.0 for x in q)} of {len(q)} (largest difference over them "
            f"{max(q):.2f}, median {statistics.median(q):.2f})")
        cells["stated error, largest"].append(f"{max(errs):.1e}")
    lines += [f"| {k} | " + " | ".join(v) + " |" for k, v in cells.items()]
    for line in lines:
        print(line)
    return lines


def _reference_ratios(pts: list[dict]) -> tuple[list[float], list[float]]:
    q, errs = [], []
    for p in pts:
        sub = p["inplane_on"] == "substrate"
        al, ze = p["alpha"], p["zeta"]
        hc, hs = inplane_forcing(al, 2 * ze * np.sqrt(al), p["a_x"], p["phase_x"], sub)
        c = mdr_continuum(al, p["beta"], p["amplitude"], p["v_inertial"],
                          p["profile_exponent"], ze, hc, hs,
                          frame_offset(p["a_x"], p["phase_x"], sub))
        q.append(abs(c["mu_ratio"] - p["mu_ref"]) / (p["err_ref"] + c["error"]))
        errs.append(c["error"])
    return q, errs


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--write", action="store_true", help=f"append to {RESULTS}")
    args = ap.parse_args()
    lines = (run(_points(), f"{N} points, 0 < a < 1")
             + run(_points(12, N_JUMPING, (1.05, 3.0)), f"{N_JUMPING} jumping points, a > 1")
             + routed(41, 60, (1.02, 3.5), "the MDR solver at tol 1e-7 against the rows at "
                      "1e-7: 60 jumping points, a 1.02..3.5")
             + routed(42, 30, (1.0005, 1.05), "the same: 30 barely jumping points, a "
                      "1.0005..1.05")
             + against_reference())
    if args.write:
        append_run(RESULTS, f"{N} + {N_JUMPING} random points: the row without springs "
                   "against the rows",
                   "PYTHONPATH=src python benchmarks/mdr_continuum_fuzz.py --write",
                   "seeds 11 and 12; each point solved alone, once (the medians: the first point's "
                   "times also load or compile the kernels).", lines)


if __name__ == "__main__":
    main()
