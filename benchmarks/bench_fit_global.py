"""The fit's global stage, two ways side by side: one pool task per population member
(the call of scipy's ``workers=map``, as before 2026-11-26) against a whole generation
per call (``vectorized=True``, :meth:`Problem.costs`, the fit's way since).

Same data (bench_fit.py's, noise seed 11), same coarse problem, same seed, deferred
updating in both, so the two walk the same population: the script checks that the best
cost is bitwise the same, then reports the wall time of each, in interleaved rounds.

Run:  python benchmarks/bench_fit_global.py [--generations 60] [--rounds 2]
Prints a Markdown table (recorded in benchmarks/results/fit.md).
"""

from __future__ import annotations

import argparse
import statistics
import time
from functools import partial

import numpy as np
from scipy.optimize import differential_evolution

from bench_fit import CALLS, FREE, data
from vibrofriction.bench.fitting.problem import Problem, search_bounds
from vibrofriction.bench.fitting.search import CHUNKS
from vibrofriction.parallel import mapper


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--generations", type=int, default=60)
    ap.add_argument("--rounds", type=int, default=2)
    args = ap.parse_args()
    guess, kwargs = CALLS["4 varied (k_x follows mass)"]
    free = tuple(n for n in FREE if n != "k_x")
    problem = Problem(guess, free, True, True, True, data(np.random.default_rng(11)))
    bounds, coarse = search_bounds(problem, 10.0), problem.coarse()
    x0 = np.log([getattr(guess, n) for n in free])
    common = dict(maxiter=args.generations, popsize=12, seed=0, polish=False, init="sobol",
                  x0=x0, tol=0.0, updating="deferred")
    times: dict[str, list[float]] = {"one task per member": [], "a generation per call": []}
    best = set()
    with mapper(2) as map_:
        map_(coarse.cost, [x0, x0])  # the workers warm
        for _ in range(args.rounds):
            for name in times:
                t = time.perf_counter()
                if name == "one task per member":
                    de = differential_evolution(coarse.cost, bounds, workers=map_, **common)
                else:
                    de = differential_evolution(
                        partial(coarse.costs, map_=map_, chunks=CHUNKS * 2), bounds,
                        vectorized=True, **common)
                times[name].append(time.perf_counter() - t)
                best.add(float(de.fun))
    assert len(best) == 1, f"the two ways walked different populations: {best}"
    print(f"{args.generations} generations of 64 members on 30 rows, 2 processes, "
          f"{args.rounds} interleaved rounds (best cost {best.pop():.6g} in every run)\n")
    print("| call | median wall (s) | runs (s) |\n|---|---:|---|")
    for name, t in times.items():
        print(f"| {name} | {statistics.median(t):.1f} | "
              f"{', '.join(f'{x:.1f}' for x in t)} |")
    ratio = statistics.median(times["one task per member"]) / statistics.median(
        times["a generation per call"])
    print(f"\nspeed-up {ratio:.2f}x")


if __name__ == "__main__":
    main()
