"""The sphere fit of tests/bench/test_fit_mdr.py timed: is it under a minute?

The fit with ``contact_model="mdr"`` (``free = mu0, radius, mass``, a guess 1.3x off in
each, ``workers=2``) on the held-out table made by the independent spring-row reference
(``tests/data/mdr_bench.csv``), run ``--runs`` times in one process (the first compiles
nothing: the kernels load from the disk cache): wall time, chi-square, evaluations,
verdict, and whether every interval holds the truth. ``fit_mdr_numbers.py`` gives the
whole record (stages, intervals, the linearised sphere, the design).

Run: ``PYTHONPATH=src python benchmarks/fit_mdr_time.py [--runs N] [--write]``
(``--write`` appends the runs to benchmarks/results/fit_mdr.md).
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT / "tests" / "bench"))
RESULTS = ROOT / "benchmarks" / "results" / "fit_mdr.md"
FREE = ("mu0", "radius", "mass")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=2)
    ap.add_argument("--write", action="store_true")
    opts = ap.parse_args()
    import test_fit_mdr as t

    rows = []
    for _ in range(opts.runs):
        t0 = time.perf_counter()
        res = t._fit("mdr")
        wall = time.perf_counter() - t0
        inside = all(res.intervals[n][0] <= t.T[n] <= res.intervals[n][1] for n in FREE)
        rows.append(f"| {wall:.1f} s | {res.chisqr:.3f} | {res.nfev} | {res.quality} | "
                    f"{'yes' if inside else 'NO'} |")
        print(rows[-1], flush=True)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=ROOT).stdout.strip()
    load = os.getloadavg()[0]
    lines = [
        "",
        f"## The sphere fit timed at {commit}, "
        f"{datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC",
        "",
        f"`PYTHONPATH=src python benchmarks/fit_mdr_time.py --runs {opts.runs}` on "
        f"{platform.machine()}, {os.cpu_count()} cores; load average {load:.1f} at the end. "
        "The fit of section 2 (`free = mu0, radius, mass`, 1.3x off, `workers=2`), run "
        "after run in one process.",
        "",
        "| wall | chi-square | evaluations | verdict | every interval holds the truth |",
        "|---:|---:|---:|---|---|",
        *rows,
    ]
    if opts.write:
        with RESULTS.open("a") as fh:
            fh.write("\n".join(lines) + "\n")
        print(f"-> {RESULTS}")
    else:
        print("\n".join(lines))


if __name__ == "__main__":
    main()
