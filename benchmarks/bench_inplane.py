"""Cost of a point with and without a longitudinal in-plane oscillation (issue 20).

For each regime, the median time of one ``solve_points`` call on a single point (the
solver's whole work: transient, orbit, error), without in-plane oscillation and with
``a_x = 0.5`` at ``phase_x = pi/2`` on the substrate and on the holder, measured
interleaved in one process.  Run with any ``vibrofriction`` on the path (an older one
without in-plane oscillation measures the normal-only points only)::

    PYTHONPATH=src python benchmarks/bench_inplane.py [--kernel] [--json OUT] [--record]

``--kernel`` times the compiled kernel ``steady_state`` alone (no Python around it).
``--record`` appends the table and the median ratios to benchmarks/results/inplane.md.
``--against OTHER/src`` times normal-only points of this kernel against another
checkout's (main's), alternately in one process: the robust way to see a few per cent.

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

from vibrofriction.schema import FLOAT_COLUMNS, INT_COLUMNS

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
INPLANE = "a_x" in inspect.signature(__import__("vibrofriction.solver.engine", fromlist=["x"])
                                     .solve_points).parameters
REPEATS, ROUNDS = 15, 5
KERNEL = "--kernel" in sys.argv


def _timer(args, kw):
    """``solve_points`` on one point, or with ``KERNEL`` the compiled kernel alone."""
    from vibrofriction._kernels.steady import steady_state
    from vibrofriction.solver import solve_points
    from vibrofriction.solver.methods.event import event_arguments
    from vibrofriction.solver.settings import DEFAULT_SETTINGS

    if KERNEL:
        of = np.empty(len(FLOAT_COLUMNS))
        oi = np.empty(len(INT_COLUMNS), dtype=np.int64)
        inplane = (*(args[6:] or (0.0, 0.0)), kw.get("inplane_on", "substrate") == "substrate",
                   1.0)  # and static_ratio
        full = (*args[:6], *(inplane if INPLANE else ()), 0, 0.0, 0.0, 0.0, 0,
                *event_arguments(DEFAULT_SETTINGS), of, oi)

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


def _old_package(src: str):
    """``steady_state`` and settings of another checkout's ``src/vibrofriction``, imported
    under the name ``vfold`` (a renamed copy in a temporary directory) beside this one."""
    import re
    import shutil
    import tempfile
    from pathlib import Path

    root = Path(tempfile.mkdtemp()) / "vfold"
    shutil.copytree(Path(src) / "vibrofriction", root,
                    ignore=shutil.ignore_patterns("*.nbi", "*.nbc", "__pycache__"))
    for f in root.rglob("*.py"):
        f.write_text(re.sub(r"\bvibrofriction\b(?!_)", "vfold", f.read_text()))
    sys.path.insert(0, str(root.parent))
    from vfold._kernels.steady import steady_state as old
    from vfold.solver.settings import DEFAULT_SETTINGS as old_settings
    return old, old_settings


def against(src: str) -> None:
    """Normal-only points: this kernel against the one of ``src`` (e.g. main's), called
    alternately in one process (10 calls each, 40 times per regime); the median ratio."""
    old, old_settings = _old_package(src)
    from vibrofriction._kernels.steady import steady_state  # after the other one
    from vibrofriction.solver.methods.event import event_arguments
    from vibrofriction.solver.settings import DEFAULT_SETTINGS

    of = np.empty(len(FLOAT_COLUMNS))
    oi = np.empty(len(INT_COLUMNS), dtype=np.int64)
    ratios = {}
    for label, *p in REGIMES:
        a_old = (*p, 0, 0.0, 0.0, 0.0, 0, *old_settings.kernel_arguments(), of, oi)
        a_new = (*p, 0.0, 0.0, True, 1.0, 0, 0.0, 0.0, 0.0, 0,
                 *event_arguments(DEFAULT_SETTINGS), of, oi)
        old(*a_old)
        steady_state(*a_new)
        r = []
        for _ in range(40):
            t0 = time.perf_counter()
            for _ in range(10):
                old(*a_old)
            t1 = time.perf_counter()
            for _ in range(10):
                steady_state(*a_new)
            r.append((time.perf_counter() - t1) / (t1 - t0))
        ratios[label] = statistics.median(r)
        print(f"{label:20s} this / other {ratios[label]:.3f}", flush=True)
    print(f"median over the regimes: {statistics.median(ratios.values()):.3f}")


def main() -> None:
    if "--against" in sys.argv:
        against(sys.argv[sys.argv.index("--against") + 1])
        return
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
    if INPLANE:
        ratios = {k: [out[lbl][k] / out[lbl]["normal"] for lbl in out]
                  for k in ("substrate", "holder")}
        lines = [f"| {lbl} | {t['normal']:.0f} | {t['substrate']:.0f} | {t['holder']:.0f} | "
                 f"{t['substrate'] / t['normal']:.2f} | {t['holder'] / t['normal']:.2f} |"
                 for lbl, t in out.items()]
        summary = (f"median ratio over the regimes: substrate "
                   f"{statistics.median(ratios['substrate']):.2f}, holder "
                   f"{statistics.median(ratios['holder']):.2f}")
        print(summary)
        if "--record" in sys.argv:
            _record(lines, summary)
    if "--json" in sys.argv:
        with open(sys.argv[sys.argv.index("--json") + 1], "w") as fh:
            json.dump(out, fh, indent=1)


def _record(lines: list[str], summary: str) -> None:
    """Append this run to benchmarks/results/inplane.md (date, commit, machine)."""
    import datetime
    import os
    import platform
    import subprocess
    from pathlib import Path

    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    load = os.getloadavg()[0]
    path = Path(__file__).resolve().parent / "results" / "inplane.md"
    head = ("# Cost of a 1-D in-plane point against a normal-only one (issue 20)\n\n"
            "`python benchmarks/bench_inplane.py --record`: per regime the median time of "
            "one `solve_points` call (whole work: transient, orbit, error) without "
            "in-plane oscillation and with `a_x = 0.5`, `phase_x = pi/2` on the substrate "
            "and on the holder, interleaved in one process; the issue allows 1.5x "
            "(median).\n" if not path.exists() else "")
    text = (f"{head}\n## {datetime.date.today()}, commit {commit}, {platform.machine()} "
            f"{os.cpu_count()} cores, load average {load:.1f} at the end\n\n"
            "| regime | normal (us) | substrate (us) | holder (us) | substrate / normal | "
            "holder / normal |\n|---|---:|---:|---:|---:|---:|\n" + "\n".join(lines)
            + f"\n\n{summary}\n")
    with path.open("a") as fh:
        fh.write(text)


if __name__ == "__main__":
    main()
