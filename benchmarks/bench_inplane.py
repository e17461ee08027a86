"""Cost of a point with and without a longitudinal in-plane oscillation (issue 20).

For each regime, the median time of one ``solve_points`` call on a single point (the
solver's whole work: transient, orbit, error), without in-plane oscillation and with
``a_x = 0.5`` at ``phase_x = pi/2`` on the substrate and on the holder, measured
interleaved in one process.  Run with any ``vibrofriction`` on the path (an older one
without in-plane oscillation measures the normal-only points only)::

    PYTHONPATH=src python benchmarks/bench_inplane.py [--kernel] [--json OUT]

``--kernel`` times the compiled kernel ``steady_state`` alone (no Python around it).

The issue allows an in-plane point at most 1.5 times a normal-only one (median).
"""

from __future__ import annotations

import inspect
import json
import math
import statistics
import sys
import time

import numpy as np

from vibrofriction._kernels.steady import steady_state
from vibrofriction.solver import FLOAT_COLUMNS, INT_COLUMNS, solve_points
from vibrofriction.solver.settings import DEFAULT_SETTINGS

# (label, alpha, beta, a, V, zeta, eta_c)
REGIMES = [
    ("general stick-slip", 0.5, 2.0, 0.5, 0.3, 0.0, 0.0),
    ("general damped", 0.5, 2.0, 0.5, 0.3, 0.05, 0.1),
    ("soft system I", 0.01, 400.01, 0.5, 0.2, 0.01, 0.0),
    ("stiff system II", 0.01, 0.02, 0.5, 0.01, 0.05, 0.0),
    ("jumping a = 1.5", 0.5, 2.0, 1.5, 0.3, 0.02, 0.0),
    ("alpha > 1", 2.0, 5.0, 0.8, 0.3, 0.02, 0.0),
    ("rigid", 0.5, math.inf, 0.5, 0.5, 0.02, 0.0),
    ("near beta = 1", 0.3, 1.05, 0.5, 0.1, 0.05, 0.0),
    ("undamped slow", 0.5, 2.0, 0.5, 0.05, 0.0, 0.0),
    ("alpha = 1 damped", 1.0, 3.0, 0.5, 0.5, 0.01, 0.0),
]
INPLANE = "a_x" in inspect.signature(solve_points).parameters
REPEATS, ROUNDS = 15, 5
KERNEL = "--kernel" in sys.argv


def _timer(args, kw):
    """``solve_points`` on one point, or with ``KERNEL`` the compiled kernel alone."""
    if KERNEL:
        of = np.empty(len(FLOAT_COLUMNS))
        oi = np.empty(len(INT_COLUMNS), dtype=np.int64)
        inplane = (*(args[6:] or (0.0, 0.0)), kw.get("inplane_on", "substrate") == "substrate")
        full = (*args[:6], *(inplane if INPLANE else ()), 0, 0.0, 0.0, 0.0, 0,
                *DEFAULT_SETTINGS.kernel_arguments(), of, oi)

        def call() -> None:
            steady_state(*full)
    else:
        def call() -> None:
            solve_points(*args, **kw)

    def run() -> float:
        t0 = time.perf_counter()
        for _ in range(REPEATS):
            call()
        return (time.perf_counter() - t0) / REPEATS
    return run


def main() -> None:
    out = {}
    for label, *p in REGIMES:
        cases = {"normal": _timer(p, {})}
        if INPLANE:
            cases["substrate"] = _timer(p + [0.5, math.pi / 2], {})
            cases["holder"] = _timer(p + [0.5, math.pi / 2], {"inplane_on": "holder"})
        for run in cases.values():
            run()  # compile, warm
        times = {k: [] for k in cases}
        for _ in range(ROUNDS):
            for k, run in cases.items():
                times[k].append(run())
        out[label] = {k: 1e6 * statistics.median(v) for k, v in times.items()}
        print(f"{label:20s} " + "  ".join(f"{k} {v:9.1f} us" for k, v in out[label].items()),
              flush=True)
    if "--json" in sys.argv:
        with open(sys.argv[sys.argv.index("--json") + 1], "w") as fh:
            json.dump(out, fh, indent=1)


if __name__ == "__main__":
    main()
