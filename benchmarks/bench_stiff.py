"""The stiff corner (issue 19): ``beta`` up to 1e6 with the pin damped (``zeta >= 1e-3``),
every point under 10 ms.

A grid over ``alpha`` (1e-4 to 1e3), ``beta`` (1e4, 1e5, 1e6), ``vbar`` (0.1, 0.5, 0.9),
``a = 0.5``, ``zeta`` 1e-3 and 1e-2: the median of 3 timed calls per point (after a warm
call), the status, the work and whether the result is trusted; the slowest points and
the maximum.  Appends a section to benchmarks/results/stiff.md.

Run: ``.venv/bin/python benchmarks/bench_stiff.py`` (about a minute).
"""

from __future__ import annotations

import datetime
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

import vibrofriction as vf

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results" / "stiff.md"
ALPHAS = (1e-4, 1e-2, 1.0, 1e2, 1e3)
BETAS = (1e4, 1e5, 1e6)
VBARS = (0.1, 0.5, 0.9)
ZETAS = (1e-3, 1e-2)


def _commit() -> str:
    out = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                         text=True, cwd=HERE)
    return out.stdout.strip() or "unknown"


def main() -> None:
    rows = []
    for alpha in ALPHAS:
        for beta in BETAS:
            if beta <= 2 * alpha:
                continue
            for zeta in ZETAS:
                s = vf.Dimensionless(alpha, beta, 0.5, zeta=zeta)
                for vbar in VBARS:
                    r = vf.friction_coefficient(s, vbar=vbar)  # warm
                    t = []
                    for _ in range(3):
                        t0 = time.perf_counter()
                        r = vf.friction_coefficient(s, vbar=vbar)
                        t.append(time.perf_counter() - t0)
                    rows.append((alpha, beta, zeta, vbar, statistics.median(t), r))
                    print(f"alpha {alpha:g} beta {beta:g} zeta {zeta:g} vbar {vbar}: "
                          f"{1e3 * rows[-1][4]:.2f} ms {r.status.value} work {r.work:g}",
                          flush=True)
    times = [row[4] for row in rows]
    slow = sorted(rows, key=lambda row: -row[4])[:8]
    lines = [f"\n## commit {_commit()}, "
             f"{datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC\n",
             f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python "
             f"{platform.python_version()}; load average {os.getloadavg()[0]:.2f} at the end.  "
             f"{len(rows)} points (alpha {ALPHAS}, beta {BETAS} where beta > 2 alpha, "
             f"zeta {ZETAS}, vbar {VBARS}, a = 0.5).\n",
             f"Median {1e3 * statistics.median(times):.2f} ms, maximum "
             f"**{1e3 * max(times):.2f} ms**; points over 10 ms: "
             f"{sum(t > 0.010 for t in times)}; not trusted: "
             f"{sum(not row[5].trusted for row in rows)}.\n",
             "| alpha | beta | zeta | vbar | ms | status | work | events | trusted |",
             "|---|---|---|---|---|---|---|---|---|"]
    for alpha, beta, zeta, vbar, t, r in slow:
        lines.append(f"| {alpha:g} | {beta:g} | {zeta:g} | {vbar} | {1e3 * t:.2f} | "
                     f"{r.status.value} | {r.work:g} | {r.events} | {r.trusted} |")
    if not RESULTS.exists():
        RESULTS.write_text("# The stiff corner: beta up to 1e6, zeta >= 1e-3 "
                           "(benchmarks/bench_stiff.py)\n\nThe 8 slowest points per run.\n")
    with RESULTS.open("a") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())
