"""Work per point in periods of its orbit: the baseline of issue 19 ("the limit of a point
is the cost of integrating its orbit a few times").

Over the benchmark's regimes (``bench_solver.POINTS``) undamped and with the dampings of
``bench_damped.DAMPINGS``: per point the status, the orbit's period ``p`` in drive periods
(``period`` for a periodic orbit; 1 for proven continuous sliding, whose orbit has the
drive's period; none for an averaged or unconverged result), ``work`` (drive periods
integrated in all: the main loop, Newton's period maps and difference Jacobians, the
Floquet estimate, the verification window and any long window; ``FrictionResult.work``)
and ``work / p``, the work in periods of the orbit; the median over points.

Run: ``.venv/bin/python benchmarks/bench_work.py`` (appends to
benchmarks/results/work.md, with the commit; a few seconds).
"""

from __future__ import annotations

import math
import platform
import statistics
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import vibrofriction as vf  # noqa: E402
from bench_damped import DAMPINGS  # noqa: E402
from bench_solver import POINTS  # noqa: E402

RESULTS = HERE / "results" / "work.md"


def orbit_period(r: vf.FrictionResult) -> float:
    """The orbit's period in drive periods: 1 for continuous sliding, nan without an orbit."""
    if r.status is vf.Status.PERIODIC:
        return float(r.period)
    return 1.0 if r.status is vf.Status.SLIDING else math.nan


def measure() -> list[dict]:
    rows = []
    for label, alpha, beta, a, vbar, v_in in POINTS:
        V = float(vf.Dimensionless(alpha, beta, a).vbar_to_inertial(vbar)) if vbar else v_in
        for zeta, eta in DAMPINGS:
            r = vf.friction_coefficient(vf.Dimensionless(alpha, beta, a, zeta, eta),
                                        v_inertial=V)
            p = orbit_period(r)
            rows.append({"point": label, "zeta": zeta, "eta_c": eta, "status": r.status.value,
                         "p": p, "periods": r.periods, "work": r.work,
                         "per_orbit": r.work / p})
    return rows


def _median(values: list[float]) -> float:
    values = [v for v in values if math.isfinite(v)]
    return statistics.median(values) if values else math.nan


def table(rows: list[dict], commit: str) -> str:
    lines = ["| point | zeta | eta_c | status | p | periods | work | work / p |",
             "|---|---|---|---|---|---|---|---|"]
    for w in rows:
        p = "" if math.isnan(w["p"]) else f"{w['p']:g}"
        per = "" if math.isnan(w["per_orbit"]) else f"{w['per_orbit']:.1f}"
        lines.append(f"| {w['point']} | {w['zeta']:g} | {w['eta_c']:g} | {w['status']} | "
                     f"{p} | {w['periods']} | {w['work']:g} | {per} |")
    undamped = [w for w in rows if w["zeta"] == 0.0 and w["eta_c"] == 0.0]
    works = [w["work"] for w in rows]
    lines += ["", "| commit | points | median work / p | median work (drive periods) | "
              "undamped: median work / p | points at most 5 | total work |",
              "|---|---|---|---|---|---|---|",
              f"| {commit} | {len(rows)} | {_median([w['per_orbit'] for w in rows]):.1f} | "
              f"{_median(works):.1f} | "
              f"{_median([w['per_orbit'] for w in undamped]):.1f} | "
              f"{sum(w <= 5 for w in works)} | {sum(works):g} |"]
    return "\n".join(lines)


def main() -> None:
    # the commit of the package measured (PYTHONPATH may point at another checkout)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=Path(vf.__file__).parent).stdout.strip()
    text = table(measure(), commit)
    if not RESULTS.exists():
        RESULTS.write_text(
            "# Work per point in periods of its orbit (benchmarks/bench_work.py)\n\n"
            "Issue 19's limit: a few periods of the orbit (a couple of Newton steps and the "
            "average); target: median at most 5.  `p`: the orbit's period in drive periods "
            "(1 for continuous sliding); `periods`: the main loop's; `work`: drive periods "
            "integrated in all (Newton's period maps and difference Jacobians, the Floquet "
            "estimate, verification and long windows included; not the closed-form sliding "
            f"orbit and certificate).  Python {platform.python_version()}.\n")
    with RESULTS.open("a") as f:
        f.write(f"\n## commit {commit}\n\n{text}\n")
    print(text)


if __name__ == "__main__":
    main()
