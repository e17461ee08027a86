"""Rows of the MDR solver (vibrofriction.solver.mdr.mdr_row) by plain iteration of the period
map against Anderson mixing: status, mu_ratio, periods and time per row, at the benchmark's
regimes and the stiff contact of docs/contact_geometry.md; then mdr_friction. Appends to
benchmarks/results/mdr_acceleration.md. At a commit whose mdr_row has no ``accelerate``
(the first version, 7a5e0ac), the plain column is that version's; name the code's
commit as the argument when ``src`` is another checkout.

    PYTHONPATH=src python benchmarks/mdr_acceleration.py
    PYTHONPATH=/tmp/old/src python benchmarks/mdr_acceleration.py 7a5e0ac
"""

import datetime
import inspect
import platform
import subprocess
import sys
import time
from pathlib import Path

from vibrofriction.solver.mdr import mdr_friction, mdr_row, rows_alone

POINTS = [  # (alpha, beta, a, V, zeta, n): bench_mdr.py's six and its stiff contact
    (0.5, 2.0, 0.5, 0.3, 0.0, 2.0), (0.5, 2.0, 1.5, 0.3, 0.0, 2.0),
    (1.0, 3.0, 0.7, 0.5, 0.1, 1.0), (0.1, 0.5, 0.5, 0.05, 0.0, 3.0),
    (2.0, 6.0, 0.8, 0.5, 0.0, 1.0), (0.05, 0.1, 1.3, 2.0, 0.5, 1.0),
    (0.64, 35.81106201466738, 0.5058099397428091, 0.314, 0.0, 2.0)]
ROWS = (20, 40, 80, 160, 320)


def main() -> None:
    mdr_row(0.5, 2.0, 0.5, 0.3, 2.0, 10)  # compile
    has_acc = "accelerate" in inspect.signature(mdr_row).parameters
    modes = (False, True) if has_acc else (None,)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    if len(sys.argv) > 1:
        commit = f"{sys.argv[1]} (the code; the script at {commit})"
    lines = ["", "## Period map: plain iteration against Anderson mixing", "",
             f"`PYTHONPATH=src python benchmarks/mdr_acceleration.py`, {datetime.date.today()}, "
             f"commit {commit}, {platform.machine()} (shared 2-core machine).", "",
             "| alpha, beta, a, V, zeta, n | N | plain: status, mu, periods, ms | "
             "Anderson: status, mu, periods, ms |", "| --- | --- | --- | --- |"]
    for al, be, a, V, z, n in POINTS:
        for N in ROWS:
            cells = []
            for acc in modes:
                kw = {} if acc is None else {"accelerate": acc}
                t = time.perf_counter()
                r = mdr_row(al, be, a, V, n, N, z, **kw)
                t = time.perf_counter() - t
                cells.append(f"{r['status']}, {r['mu_ratio']:.9f}, {r['periods']}, "
                             f"{1e3 * t:.1f}")
            lines.append(f"| {al:.4g}, {be:.4g}, {a:.4g}, {V}, {z}, {n} | {N} | "
                         + " | ".join(cells) + " |")
        t = time.perf_counter()
        with rows_alone():  # (the rows of springs, as the columns above)
            r = mdr_friction(al, be, a, V, n, zeta=z)
        t = time.perf_counter() - t
        lines.append(f"| (mdr_friction) | {r['rows']} | {r['status']}, "
                     f"{r['mu_ratio']:.9f} +- {r['error']:.1e}, {1e3 * t:.1f} ms | |")
    text = "\n".join(lines) + "\n"
    out = Path(__file__).parent / "results" / "mdr_acceleration.md"
    with out.open("a") as fh:
        fh.write(text)
    print(text)


if __name__ == "__main__":
    main()
