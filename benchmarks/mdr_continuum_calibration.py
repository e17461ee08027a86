"""The row without springs' stated error against runs with maps a thousand times tighter.

40 random points with ``0 < a < 1`` (seed 22) and 40 jumping ones (``a`` 1.05..3, seed 21):
alpha 10^-1.5..10, beta - alpha 0.1..30, V 10^-1.5..2, n in {1, 1.5, 2, 3, 5}, zeta in
{0, 0.05, 0.3}, no drive. Each is solved as the MDR solver asks the continuum at
``tol_trusted`` 1e-3, 1e-4, 1e-5 (the default), 1e-6, 1e-7 and 1e-8
(:func:`vibrofriction.solver.mdr_continuum.continuum_friction`) and once with maps at
``1e-11`` (:func:`~vibrofriction.solver.mdr_continuum.mdr_continuum`);
a calibration failure is a difference from the latter above the two stated errors (the
tight run's is mostly its search's: at a slowly attracting orbit it can be the larger).

    PYTHONPATH=src python benchmarks/mdr_continuum_calibration.py [--write]

``--write`` appends the run to benchmarks/results/mdr_continuum_calibration.md.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from sections import append_run
from vibrofriction.solver.mdr_continuum import continuum_friction, mdr_continuum

RESULTS = Path(__file__).parent / "results" / "mdr_continuum_calibration.md"
COUNT = 40
TOLS = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8)


#: the two draws: (seed, the range of a)
DRAWS = ((22, (0.1, 0.95)), (21, (1.05, 3.0)))


def points(seed: int, a_range: tuple[float, float]) -> list[tuple[float, ...]]:
    """The seed's ``COUNT`` points ``(alpha, beta, a, V, n, zeta)``."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(COUNT):
        al = 10 ** rng.uniform(-1.5, 1)
        be = al + 10 ** rng.uniform(-1, 1.5)
        a, V = rng.uniform(*a_range), 10 ** rng.uniform(-1.5, 0.3)
        n, ze = float(rng.choice([1, 1.5, 2, 3, 5])), float(rng.choice([0, 0.05, 0.3]))
        out.append((al, be, a, V, n, ze))
    return out


def run(seed: int, a_range: tuple[float, float], title: str) -> list[str]:
    ratios, errors, failed, bad, unsolved = [], [], 0, [], []
    for al, be, a, V, n, ze in points(seed, a_range):
        ref = mdr_continuum(al, be, a, V, n, ze, rtol=1e-11)
        for tol in TOLS:
            r = continuum_friction(al, be, a, V, n, ze, 0.0, 0.0, (0.0, 0.0), tol)
            if r["status"] != "periodic" or ref["status"] != "periodic":
                failed += 1
                if tol == TOLS[0]:
                    unsolved.append(f"alpha {al!r}, beta {be!r}, a {a!r}, V {V!r}, n {n:g}, "
                                    f"zeta {ze:g}: {r['reason'] or ref['reason']}")
                continue
            diff = abs(r["mu_ratio"] - ref["mu_ratio"])
            ratios.append(diff / (r["error"] + ref["error"]))
            errors.append(diff)
            if diff > r["error"] + ref["error"]:
                bad.append(f"alpha {al!r}, beta {be!r}, a {a!r}, V {V!r}, n {n:g}, "
                           f"zeta {ze:g}, tol {tol:g}: stated {r['error']:.1e} (tight run "
                           f"{ref['error']:.1e}), off by {diff:.1e}")
    lines = ["", f"| {title} | |", "|---|---|",
             f"| solved (both runs periodic) | {len(ratios)} of {len(ratios) + failed} |",
             f"| within the two stated errors | {len(ratios) - len(bad)} of {len(ratios)} "
             f"(largest difference over them {max(ratios):.2f}, median "
             f"{float(np.median(ratios)):.3f}) |",
             f"| difference from the tight run, largest | {max(errors):.1e} |",
             *(f"| short | {b} |" for b in bad),
             *(f"| no orbit (the rows answer) | {u} |" for u in unsolved)]
    for line in lines:
        print(line)
    return lines


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--write", action="store_true", help=f"append to {RESULTS}")
    args = ap.parse_args()
    (s0, r0), (s1, r1) = DRAWS
    lines = (run(s0, r0, f"{COUNT} points, 0 < a < 1, at tol {TOLS}")
             + run(s1, r1, f"{COUNT} jumping points, a > 1, at tol {TOLS}"))
    if args.write:
        append_run(RESULTS, "The row without springs' stated error against tighter runs",
                   "PYTHONPATH=src python benchmarks/mdr_continuum_calibration.py --write",
                   "seeds 22 and 21; the reference: the same point with maps at 1e-11.",
                   lines)


if __name__ == "__main__":
    main()
