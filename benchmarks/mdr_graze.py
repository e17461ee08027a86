"""Where the curved tip's fine orbit needs maps a hundred times finer: the graze measures.

The row without springs states its error as the difference of two orbits, the coarse
maps' and the fine maps'. Just below the critical velocity ``V_c`` maps ten times finer
can keep the coarse orbit with less stick, and the difference then understates the
error; maps a hundred times finer do not (benchmarks/mdr_near_critical.py). The kernel
measures how closely the last coarse map grazes (``period``'s ``gz``): the smallest
``|P'|`` or ``|N'|`` where one turns back from 0, over ``V + c a`` (the depth), and the
shortest time between two sign changes of the same edge's velocity (a brief stick or
slip). The solver takes the hundredfold maps where the depth is below ``GRAZE_DEPTH`` or
the time below ``GRAZE_TIME`` (``solver/mdr_continuum.py``), and at every jumping point
(``a > 1``: its brief stick ends at the flight, where the measures stop;
``mdr_near_critical.py --jumping``), the tenfold ones elsewhere.

This script measures both sides of those thresholds:

* the near-critical systems of ``mdr_near_critical.py`` (``--seeds``, at 0.9995 and 0.9999
  ``V_c``, ``tol`` 1e-5 and 1e-8), each solved with the fine maps at a tenth and at a
  hundredth everywhere, against the rows of 640 springs: the graze measures of the
  points where a tenth falls short (``|mu - mu_rows|`` above the two stated errors);
* the 30 points of ``mdr_continuum_periods.py`` (the regimes of ``bench_ratios.py``) and
  the 80 of ``mdr_continuum_calibration.py``, at ``tol`` 1e-7: their graze measures, and
  how many take the hundredfold maps (by the thresholds, or jumping).

    PYTHONPATH=src python benchmarks/mdr_graze.py [--seeds S ...] [--write]

``--write`` appends the run to benchmarks/results/mdr_graze.md.
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

from mdr_continuum_calibration import DRAWS, points
from mdr_continuum_periods import _points
from mdr_near_critical import SPRINGS, systems
from sections import append_run
from vibrofriction import theory
from vibrofriction._kernels import mdr_continuum as mc
from vibrofriction.solver import mdr_continuum as smc
from vibrofriction.solver.mdr import mdr_friction

RESULTS = Path(__file__).parent / "results" / "mdr_graze.md"
SEEDS = tuple(range(5, 25))
FRACTIONS = (0.9999, 0.9995)
TOLS = (1e-5, 1e-8)

_last: dict[str, tuple[float, float]] = {}
_steady = mc.steady


def _recorded(*args):
    """``mc.steady``, its last coarse map's graze measures kept (``res[7:9]``)."""
    out = _steady(*args)
    _last["g"] = (float(args[-1][7]), float(args[-1][8]))
    return out


def _fine_everywhere(fine: float) -> None:
    smc.FINE = smc.FINE_GRAZE = fine


def near_critical(seeds) -> tuple[list[tuple], int]:
    """``(seed, system, V/V_c, tol, ratio at a tenth, ratio at a hundredth, depth, time)``
    of every compared point, and the count of points compared."""
    out = []
    for seed in seeds:
        for alpha, beta, a, n, zeta in systems(seed):
            vc = theory.profile_critical_velocity(alpha, beta, a, n, zeta)
            for f in FRACTIONS:
                V = f * vc
                ref = mdr_friction(alpha, beta, a, V, n, zeta, n_springs=SPRINGS)
                if ref["status"] != "periodic" or not ref["error"] <= 1e-8:
                    continue
                for tol in TOLS:
                    ratios = []
                    for fine in (0.1, 0.01):
                        _fine_everywhere(fine)
                        _last.clear()
                        r = mdr_friction(alpha, beta, a, V, n, zeta, tol=tol)
                        ratios.append(abs(r["mu_ratio"] - ref["mu_ratio"])
                                      / (r["error"] + ref["error"])
                                      if r["status"] == "periodic" else math.nan)
                    g = _last.get("g", (math.nan, math.nan))
                    out.append((seed, (alpha, beta, a, n, zeta), f, tol, *ratios, *g))
    return out, len(out)


def typical() -> list[tuple[str, float, float, float]]:
    """``(label, a, depth, time)`` of the 30 regimes' and the 80 calibration points at
    1e-7."""
    out = []
    for lab, n, args in _points():
        _last.clear()
        smc.continuum_friction(*args, 1e-7)
        out.append((f"{lab}, n {n:g}", args[2], *_last.get("g", (math.nan, math.nan))))
    for seed, ar in DRAWS:
        for al, be, a, V, n, ze in points(seed, ar):
            _last.clear()
            smc.continuum_friction(al, be, a, V, n, ze, 0.0, 0.0, (0.0, 0.0), 1e-7)
            out.append((f"calibration seed {seed}", a,
                        *_last.get("g", (math.nan, math.nan))))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--write", action="store_true")
    ap.add_argument("--seeds", type=int, nargs="+", default=list(SEEDS))
    opts = ap.parse_args()
    t0 = time.perf_counter()
    depth_max, time_max = smc.GRAZE_DEPTH, smc.GRAZE_TIME
    mc.steady = _recorded
    fine, fine_graze = smc.FINE, smc.FINE_GRAZE
    try:
        rows, compared = near_critical(opts.seeds)
        _fine_everywhere(fine)
        smc.FINE_GRAZE = fine_graze
        usual = typical()
    finally:
        mc.steady = _steady
        smc.FINE, smc.FINE_GRAZE = fine, fine_graze

    def grazes(d: float, t: float) -> bool:
        return d < depth_max or t < time_max

    def finer(a: float, d: float, t: float) -> str:
        return "yes, jumping" if a > 1.0 else ("yes" if grazes(d, t) else "no")

    short = [r for r in rows if r[4] > 1.0]
    lines = [
        f"Near V_c: {compared} points compared (seeds {opts.seeds[0]}..{opts.seeds[-1]}, "
        f"{FRACTIONS} V_c, tol {TOLS}); with the fine maps at a tenth everywhere "
        f"{len(short)} fall short (worst {max((r[4] for r in short), default=0):.2f}), "
        f"at a hundredth {sum(r[5] > 1.0 for r in rows)} (worst "
        f"{max((r[5] for r in rows), default=0):.2f}).",
        f"Of the {len(short)} short at a tenth: the largest time "
        f"{max((r[7] for r in short), default=math.nan):.3g}, the largest finite depth "
        f"{max((r[6] for r in short if math.isfinite(r[6])), default=math.nan):.3g}; "
        f"{sum(not grazes(r[6], r[7]) for r in short)} not taken for grazing by the "
        f"thresholds (depth {depth_max:g}, time {time_max:g}). Of all {compared}: "
        f"{sum(grazes(r[6], r[7]) for r in rows)} taken for grazing.",
        "",
        f"Away from V_c (the 30 regimes and the 80 calibration points, tol 1e-7): "
        f"{sum(grazes(d, t) for _, _, d, t in usual)} of {len(usual)} taken for grazing "
        f"by the measures (the smallest depth {min(d for _, _, d, _ in usual):.3g}, the "
        f"smallest time {min(t for _, _, _, t in usual):.3g}); "
        f"{sum(a > 1.0 for _, a, _, _ in usual)} jumping, which take the hundredfold maps "
        "anyway.",
        "",
        "| point | a | depth | time | hundredfold maps |", "|---|---|---|---|---|",
        *(f"| {lab} | {a:.3g} | {d:.3g} | {t:.3g} | {finer(a, d, t)} |"
          for lab, a, d, t in usual),
        "",
        "The near-critical points short at a tenth:",
        "",
        "| seed | alpha, beta, a, n, zeta | V/V_c | tol | ratio at a tenth | at a hundredth "
        "| depth | time |", "|---|---|---|---|---|---|---|---|",
        *(f"| {s} | {', '.join(f'{x:.4g}' for x in p)} | {f} | {tol:g} | {r1:.2f} | "
          f"{r2:.2f} | {d:.3g} | {t:.3g} |" for s, p, f, tol, r1, r2, d, t in short),
        "", f"{time.perf_counter() - t0:.0f} s.",
    ]
    print("\n".join(lines))
    if opts.write:
        seeds = "" if opts.seeds == list(SEEDS) else " --seeds " + " ".join(map(str, opts.seeds))
        append_run(RESULTS, "The graze measures of the curved tip's coarse orbit",
                   f"PYTHONPATH=src python benchmarks/mdr_graze.py{seeds} --write",
                   f"the rows of {SPRINGS} springs as the reference near V_c.", lines)


if __name__ == "__main__":
    main()
