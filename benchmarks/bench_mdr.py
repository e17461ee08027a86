"""Median time per point of the MDR solver (vibrofriction.solver.mdr.mdr_friction, tol 1e-5)
and of the fixed-step reference (vibrofriction_reference.mdr.mdr_reference, default
resolutions) side by side in the same run; appends to benchmarks/results/mdr.md. Each
point's time is the median of ``REPEATS`` calls, solver and reference alternated (the
sections of the results file up to commit cd16773 timed one call each). The last point
(the bench's sphere with ``mass=0.01``, a lightly damped stiff contact) is reported on its
own line, outside the medians of the six regimes.

    PYTHONPATH=src python benchmarks/bench_mdr.py
"""

import datetime
import platform
import statistics
import subprocess
import time
from pathlib import Path

from vibrofriction.solver.mdr import mdr_friction, rows_alone
from vibrofriction_reference.mdr import mdr_reference

POINTS = [  # (alpha, beta, a, V, zeta, n)
    (0.5, 2.0, 0.5, 0.3, 0.0, 2.0), (0.5, 2.0, 1.5, 0.3, 0.0, 2.0),
    (1.0, 3.0, 0.7, 0.5, 0.1, 1.0), (0.1, 0.5, 0.5, 0.05, 0.0, 3.0),
    (2.0, 6.0, 0.8, 0.5, 0.0, 1.0), (0.05, 0.1, 1.3, 2.0, 0.5, 1.0)]
STIFF_CONTACT = (0.64, 35.81106201466738, 0.5058099397428091, 0.314, 0.0, 2.0)
REPEATS = 3


def main() -> None:
    mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0)  # compile
    mdr_reference(0.5, 2.0, 0.5, 0.3, 2.0, transient_periods=2, average_periods=1)
    rows, ts, tr = [], [], []
    for al, be, a, V, z, n in [*POINTS, STIFF_CONTACT]:
        s_t, r_t = [], []
        for _ in range(REPEATS):
            t0 = time.perf_counter()
            # the rows of springs (the row without springs: bench_mdr_tol.py)
            with rows_alone():
                r = mdr_friction(al, be, a, V, n, zeta=z, tol=1e-5)
            t1 = time.perf_counter()
            ref = mdr_reference(al, be, a, V, n, transient_periods=300, average_periods=20,
                                zeta=z)
            t2 = time.perf_counter()
            s_t.append(t1 - t0)
            r_t.append(t2 - t1)
        ts.append(statistics.median(s_t))
        tr.append(statistics.median(r_t))
        rows.append(f"| {al:.4g}, {be:.4g}, {a:.4g}, {V}, {z}, {n} | {r['mu_ratio']:.7f} "
                    f"+- {r['error']:.1e} ({r['status']}, rows {r['rows']}) | "
                    f"{1e3 * ts[-1]:.1f} | "
                    f"{ref.mu_ratio:.7f} +- {ref.mu_error:.1e} | {1e3 * tr[-1]:.0f} |")
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    ratios = [r / s for s, r in zip(ts[:-1], tr[:-1], strict=True)]
    text = "\n".join([
        "",
        "## MDR solver against the fixed-step reference",
        "",
        f"`PYTHONPATH=src python benchmarks/bench_mdr.py`, {datetime.date.today()}, commit "
        f"{commit}, {platform.machine()} (shared 2-core machine; timings noisy; each the "
        f"median of {REPEATS} calls, solver and reference alternated).",
        "",
        "| alpha, beta, a, V, zeta, n | solver mu +- error | ms | reference mu +- error | ms |",
        "| --- | --- | --- | --- | --- |", *rows, "",
        f"Median over the six regimes: solver {1e3 * statistics.median(ts[:-1]):.1f} ms, "
        f"reference {1e3 * statistics.median(tr[:-1]):.0f} ms per point; reference/solver "
        f"time per point: median {statistics.median(ratios):.1f}x, range "
        f"{min(ratios):.1f}x ... {max(ratios):.1f}x. Last row (stiff contact, outside the "
        f"medians): solver {1e3 * ts[-1]:.0f} ms, reference {1e3 * tr[-1]:.0f} ms.", ""])
    out = Path(__file__).parent / "results" / "mdr.md"
    with out.open("a") as fh:
        fh.write(text)
    print(text)


if __name__ == "__main__":
    main()
