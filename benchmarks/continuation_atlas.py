"""A flat-punch atlas with independent starts against the same atlas walked by continuation.

The grid is every ``--every``-th alpha and beta of the 10^6-point atlas of
``bench_sweep.py memory`` (alpha 100 log-spaced in [0.01, 0.5], beta 100 in [2, 200],
vbar 100 in [0, 1.2], a = 0.5; ``--every 5``: 40,000 points), swept in one process three
ways one after the other: independent starts from steady sliding (the default),
``continuation="up"`` (each velocity curve walked up, every point from its predecessor's
final state) and ``continuation="both"`` (up, then down).  For each: microseconds a
solve and the mean drive periods integrated (``work``).  Then the values:

* up against independent: the points where both are trusted and differ by more than the
  sum of their stated errors (another steady state reached: several coexist there);
* up against down: the same test, where the start matters: hysteresis (coexisting
  steady states), or a nearly neutral orbit (a multiplier within about 1e-6 of 1, an
  undamped system) near which the motion's mean depends on where it started.

    PYTHONPATH=src python benchmarks/continuation_atlas.py [--every 5] [--write]

``--write`` appends the run to benchmarks/results/continuation_atlas.md.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

from sections import append_run
from vibrofriction.sweep import sweep

RESULTS = Path(__file__).parent / "results" / "continuation_atlas.md"


def _differ(a, b) -> np.ndarray:
    """Both trusted and further apart than the sum of their stated errors."""
    return (a.trusted & b.trusted & (abs(a.mu_ratio - b.mu_ratio) > a.error + b.error)).values


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--every", type=int, default=5)
    parser.add_argument("--write", action="store_true")
    args = parser.parse_args()
    grid = dict(alpha=np.geomspace(0.01, 0.5, 100)[::args.every],
                beta=np.geomspace(2.0, 200.0, 100)[::args.every], amplitude=0.5,
                vbar=np.linspace(0.0, 1.2, 100), workers=1, progress=False)
    for c in (False, "up"):  # load the kernels
        sweep(**{**grid, "alpha": [0.1], "beta": [2.0]}, continuation=c)
    runs = {}
    lines = ["| start | solves | us a solve | mean work (periods) | trusted |",
             "|---|---:|---:|---:|---:|"]
    for label, c in (("independent (steady sliding)", False), ("continuation up", "up"),
                     ("continuation up and down", "both")):
        t = time.perf_counter()
        ds = sweep(**grid, continuation=c)
        seconds = time.perf_counter() - t
        runs[c] = ds
        lines.append(f"| {label} | {ds.mu_ratio.size} | {seconds / ds.mu_ratio.size * 1e6:.1f} "
                     f"| {float(ds.work.mean()):.2f} | {float(ds.trusted.mean()):.4f} |")
    indep, up, both = runs[False], runs["up"].sel(direction="up"), runs["both"]
    other = _differ(up, indep)
    hyst = _differ(both.sel(direction="up"), both.sel(direction="down"))
    n = indep.mu_ratio.size
    ratio = float(indep.work.mean() / up.work.mean())
    lines += ["", f"Up against independent starts: {int(other.sum())} of {n} points differ by "
              f"more than the two stated errors (both trusted); mean work {ratio:.2f} times "
              f"smaller.  Up against down: {int(hyst.sum())} points differ (the start matters: "
              f"hysteresis, or a nearly neutral orbit)."]
    for name, mask, a_run, b_run, labels in (
            ("up against independent", other, indep, up, ("independent", "up")),
            ("up against down", hyst, both.sel(direction="up"), both.sel(direction="down"),
             ("up", "down"))):
        if not mask.any():
            continue
        lines += ["", f"{name}, the points that differ:", "",
                  f"| alpha | beta | vbar | {labels[0]} | {labels[1]} | errors |",
                  "|---|---|---|---|---|---|"]
        idx = np.argwhere(mask)
        for i, j, k in idx[:12]:
            a, b = a_run.isel(alpha=i, beta=j, vbar=k), b_run.isel(alpha=i, beta=j, vbar=k)
            lines.append(f"| {float(a.alpha):.4g} | {float(a.beta):.4g} | {float(a.vbar):.4g} "
                         f"| {float(a.mu_ratio):.8f} | {float(b.mu_ratio):.8f} "
                         f"| {float(a.error):.1e}, {float(b.error):.1e} |")
        if len(idx) > 12:
            lines.append(f"\n({len(idx) - 12} more not listed)")
    print("\n".join(lines))
    if args.write:
        append_run(RESULTS, "A flat-punch atlas by continuation against independent starts",
                   " ".join(["PYTHONPATH=src python benchmarks/continuation_atlas.py",
                             *sys.argv[1:]]),
                   f"one process, the three sweeps of the same {n}-point grid one after the "
                   f"other.", lines)


if __name__ == "__main__":
    main()
