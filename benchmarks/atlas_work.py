"""Where the work of a flat-punch atlas goes: drive periods by outcome, on a random sample.

The sample is drawn from the 10^6-point grid of ``benchmarks/bench_sweep.py memory`` (alpha
100 log-spaced in [0.01, 0.5], beta 100 in [2, 200], vbar 100 in [0, 1.2], a = 0.5): ``--n``
points (default 20000, seed 0), solved in one ``solve_points`` call from the default start.
The ``work`` column (drive periods integrated, a Newton map with its Jacobian counting one)
is split by outcome:

* periodic, Newton's first attempt (one period after the start) succeeded;
* periodic after Newton failed at least once (each failed attempt costs up to 12 maps; the
  motion runs on and Newton is tried again at periods 2, 3, 4, 6, 9, ...);
* continuous sliding (proven), split by whether the settling time was found within 16
  periods or is unknown (nan, all 16 integrated);
* the rest.

    PYTHONPATH=src python benchmarks/atlas_work.py [--n 20000] [--write]

``--write`` appends the table, with the commit, date and machine, to
benchmarks/results/atlas_work.md.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from sections import append_run
from vibrofriction.params.cases import vbar_to_inertial
from vibrofriction.schema import Status
from vibrofriction.solver import solve_points

RESULTS = Path(__file__).parent / "results" / "atlas_work.md"


def sample(n: int, seed: int = 0) -> dict[str, np.ndarray]:
    """``n`` points of the 10^6-point grid, drawn with replacement."""
    rng = np.random.default_rng(seed)
    alpha = rng.choice(np.geomspace(0.01, 0.5, 100), n)
    beta = rng.choice(np.geomspace(2.0, 200.0, 100), n)
    vbar = rng.choice(np.linspace(0.0, 1.2, 100), n)
    return {"alpha": alpha, "beta": beta, "amplitude": np.full(n, 0.5),
            "v_inertial": vbar_to_inertial(alpha, beta, 0.5, vbar)}


def table(n: int) -> list[str]:
    points = sample(n)
    solve_points(**{k: v[:10] for k, v in points.items()})  # load the kernels
    t0 = time.perf_counter()
    out = solve_points(**points)
    seconds = time.perf_counter() - t0
    work, status, k = out["work"], out["status"], out["periods"]
    periodic = status == Status.PERIODIC.code
    sliding = status == Status.SLIDING.code
    unknown = np.isnan(out["settling_periods"])
    groups = [
        ("periodic, Newton's first attempt", periodic & (k == 1)),
        ("periodic, after a failed attempt", periodic & (k > 1)),
        ("continuous sliding, settled within 16 periods", sliding & ~unknown),
        ("continuous sliding, settling unknown (16 periods)", sliding & unknown),
        ("other (V = 0, averaged, ...)", ~periodic & ~sliding),
    ]
    lines = [f"{n} points in {seconds:.2f} s ({1e6 * seconds / n:.0f} us a point, one process); "
             f"mean work {work.mean():.2f} drive periods a point, median "
             f"{np.median(work):.0f}.", "",
             "| outcome | points | share of points | mean work | median work | share of work |",
             "|---|---:|---:|---:|---:|---:|"]
    for label, m in groups:
        if not m.any():
            continue
        lines.append(f"| {label} | {m.sum()} | {m.mean():.1%} | {work[m].mean():.1f} | "
                     f"{np.median(work[m]):.0f} | {work[m].sum() / work.sum():.1%} |")
    return lines


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=20000)
    ap.add_argument("--write", action="store_true", help=f"append to {RESULTS}")
    args = ap.parse_args()
    lines = table(args.n)
    print("\n".join(lines))
    if args.write:
        append_run(RESULTS, "Where the work of a flat-punch atlas goes",
                   f"PYTHONPATH=src python benchmarks/atlas_work.py --n {args.n} --write",
                   "one process.", lines)


if __name__ == "__main__":
    main()
