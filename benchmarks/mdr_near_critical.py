"""The curved tip's stated error just below the critical velocity, against rows of springs.

Just below the critical velocity of continuous sliding ``V_c`` the springs stick briefly
once or twice a period, and whether a stick begins turns on a small dip of the band's edge
velocity below zero. At random systems (two seeds of 30: ``alpha`` 10^-2..10, ``beta -
alpha`` 10^-1..10^2, ``a`` 0.1..0.95, ``n`` in {1, 1.5, 2, 3, 5}, ``zeta`` in {0, 0.05,
0.3}; the draws of the scans by hand at 0.95..0.999 ``V_c``) at ``0.9995`` and ``0.9999``
``V_c``, the MDR solver at its defaults (:func:`~vibrofriction.solver.mdr.mdr_friction`,
``tol = 1e-5``, or ``--tol``: the row without springs) is compared with the rows of 640
and 1280 springs (an independent solver; a point whose rows state more than 1e-8 is not
compared). Short:
``|mu - mu_rows|`` above the two stated errors.

    PYTHONPATH=src python benchmarks/mdr_near_critical.py [--seeds S ...] [--tol TOL]
        [--fractions F ...] [--jumping] [--recheck N] [--write] [--note TEXT]

``--seeds`` other seeds (points the defaults' were not chosen on); ``--tol`` the solver's
``tol`` (``tol_trusted``) instead of its default; ``--fractions`` other ``V/V_c``;
``--jumping``: the systems' ``a`` from 1.05 to 2.5 (a jumping indenter), not 0.1 to 0.95;
``--recheck N``: each short point compared again with the rows of ``N`` and ``2 N``
springs (the 640 springs' own error can be understated: at ``tol`` 1e-8 and 0.95 V_c one
stated 3.5e-9 and was 1.1e-7 off); ``--write`` appends the
run to benchmarks/results/mdr_near_critical.md (``--note``: a line that says which tree
ran, e.g. one on ``PYTHONPATH`` other than the checkout's).
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import numpy as np

from sections import append_run
from vibrofriction import theory
from vibrofriction.solver.mdr import mdr_friction

RESULTS = Path(__file__).parent / "results" / "mdr_near_critical.md"
SEEDS = (5, 6)
SYSTEMS = 30
FRACTIONS = (0.9999, 0.9995)
SPRINGS = 640


def systems(seed: int, jumping: bool = False) -> list[tuple[float, float, float, float,
                                                             float]]:
    """The seed's systems ``(alpha, beta, a, n, zeta)`` with a finite ``V_c > 0`` (jumping:
    ``a`` 1.05..2.5)."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(SYSTEMS):
        alpha = 10 ** rng.uniform(-2, 1)
        beta = alpha + 10 ** rng.uniform(-1, 2)
        a = rng.uniform(*((1.05, 2.5) if jumping else (0.1, 0.95)))
        n = float(rng.choice([1, 1.5, 2, 3, 5]))
        zeta = float(rng.choice([0, 0.05, 0.3]))
        vc = theory.profile_critical_velocity(alpha, beta, a, n, zeta)
        if math.isfinite(vc) and vc > 0:
            out.append((alpha, beta, a, n, zeta))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--write", action="store_true")
    ap.add_argument("--note", default="")
    ap.add_argument("--seeds", type=int, nargs="+", default=list(SEEDS))
    ap.add_argument("--tol", type=float, default=None)
    ap.add_argument("--fractions", type=float, nargs="+", default=list(FRACTIONS))
    ap.add_argument("--recheck", type=int, default=0)
    ap.add_argument("--jumping", action="store_true")
    opts = ap.parse_args()
    t0 = time.perf_counter()
    compared = short = skipped = short_again = 0
    worst = worst_again = 0.0
    again = f"; over the errors with {opts.recheck} springs" if opts.recheck else ""
    rows = ["| seed | alpha, beta, a, n, zeta | V/V_c | mu +- error | rows | stick area "
            f"(rows) | \\|difference\\| / errors{again} |",
            "|---|---|---|---|---|---|---|"]
    for seed in opts.seeds:
        for alpha, beta, a, n, zeta in systems(seed, opts.jumping):
            vc = theory.profile_critical_velocity(alpha, beta, a, n, zeta)
            for f in opts.fractions:
                V = f * vc
                ref = mdr_friction(alpha, beta, a, V, n, zeta, n_springs=SPRINGS)
                r = mdr_friction(alpha, beta, a, V, n, zeta,
                                 **({} if opts.tol is None else {"tol": opts.tol}))
                if ref["status"] != "periodic" or not ref["error"] <= 1e-8 \
                        or r["status"] != "periodic":
                    skipped += 1
                    continue
                compared += 1
                ratio = abs(r["mu_ratio"] - ref["mu_ratio"]) / (r["error"] + ref["error"])
                worst = max(worst, ratio)
                if ratio > 1.0:
                    short += 1
                    cell = f"{ratio:.2f}"
                    if opts.recheck:
                        fine = mdr_friction(alpha, beta, a, V, n, zeta,
                                            n_springs=opts.recheck)
                        r2 = abs(r["mu_ratio"] - fine["mu_ratio"]) / (r["error"]
                                                                     + fine["error"])
                        worst_again = max(worst_again, r2)
                        short_again += r2 > 1.0
                        cell += f"; {r2:.2f}"
                    rows.append(
                        f"| {seed} | {alpha:.4g}, {beta:.4g}, {a:.4g}, {n:g}, {zeta:g} | {f} | "
                        f"{r['mu_ratio']:.10f} +- {r['error']:.1e} | {ref['mu_ratio']:.10f} | "
                        f"{r['stick_area_fraction']:.4f} ({ref['stick_area_fraction']:.4f}) | "
                        f"{cell} |")
                    print(rows[-1], flush=True)
    summary = (f"{compared} points compared ({skipped} not: the rows or the solver not "
               f"periodic, or the rows' error above 1e-8); {short} short, the largest "
               f"difference over the errors {worst:.2f}"
               + (f"; of the short, {short_again} also short against the rows of "
                  f"{opts.recheck} and {2 * opts.recheck} springs (the largest difference "
                  f"over the errors {worst_again:.2f})" if opts.recheck else "")
               + f"; {time.perf_counter() - t0:.0f} s.")
    print(summary)
    if opts.write:
        lines = ([opts.note, ""] if opts.note else []) + [summary]
        if short:
            lines += ["", *rows]
        seeds = "" if opts.seeds == list(SEEDS) else " --seeds " + " ".join(map(str, opts.seeds))
        seeds += "" if opts.tol is None else f" --tol {opts.tol:g}"
        if opts.fractions != list(FRACTIONS):
            seeds += " --fractions " + " ".join(map(str, opts.fractions))
        seeds += f" --recheck {opts.recheck}" if opts.recheck else ""
        seeds += " --jumping" if opts.jumping else ""
        append_run(RESULTS, "Curved tips just below the critical velocity, against rows of "
                   "springs", f"PYTHONPATH=src python benchmarks/mdr_near_critical.py{seeds} "
                   "--write", f"seeds {tuple(opts.seeds)}, {SYSTEMS} systems each, at "
                   f"{tuple(opts.fractions)} V_c; the rows of {SPRINGS} and {2 * SPRINGS} "
                   "springs as the "
                   "reference.", lines)


if __name__ == "__main__":
    main()
