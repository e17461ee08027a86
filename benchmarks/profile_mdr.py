"""Where the MDR solver's time goes, per row: the rows of 20 to 640 springs of one point,
each started from the previous row's final state (as ``mdr_friction`` does), their periods,
events a period and CPU time a period (the least of 5 calls; ``time.process_time``, so
the shared machine's other processes count less), with the scan's sub-steps at the solver's
(``solver.mdr.SUBSTEPS``, 64 a period; 1024 up to commit 1153fe4, the sections of the
results file before it) and at 1024 (the difference: the scan's share). Appends to
benchmarks/results/mdr_profile.md.

    PYTHONPATH=src python benchmarks/profile_mdr.py [alpha beta a V zeta n]
"""

import datetime
import platform
import subprocess
import sys
import time
from pathlib import Path

import vibrofriction.solver.mdr as mdr

POINT = (1.0, 3.0, 0.7, 0.5, 0.1, 1.0)  # (alpha, beta, a, V, zeta, n): the bench's damped cone
OTHER = 1024  # the sub-steps a period compared with the solver's


def rows(point: tuple, substeps: int) -> list[tuple]:
    al, be, a, V, z, n = point
    mdr.mdr_row(al, be, a, V, n, 20, z, substeps=substeps)  # compile
    out, warm = [], None
    for M in (20, 40, 80, 160, 320, 640):
        ts = []
        for _ in range(5):
            t0 = time.process_time()
            r = mdr.mdr_row(al, be, a, V, n, M, z, warm=warm, substeps=substeps)
            ts.append(time.process_time() - t0)
        warm = r["final_state"]
        out.append((M, r["periods"], r["events_per_period"], min(ts)))
    return out


def main() -> None:
    point = tuple(float(x) for x in sys.argv[1:7]) if len(sys.argv) > 6 else POINT
    fine, coarse = rows(point, mdr.SUBSTEPS), rows(point, OTHER)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    lines = ["", f"## Rows of {point} (alpha, beta, a, V, zeta, n)", "",
             f"`PYTHONPATH=src python benchmarks/profile_mdr.py`, {datetime.date.today()}, "
             f"commit {commit}, {platform.machine()} (shared 2-core machine; CPU time).", "",
             "| springs | periods | events a period | ms a row | us a period | "
             f"us a period, {OTHER} sub-steps |", "| --- | --- | --- | --- | --- | --- |"]
    for (M, p, ev, t), (_, p2, _, t2) in zip(fine, coarse, strict=True):
        lines.append(f"| {M} | {p} | {ev} | {1e3 * t:.2f} | {1e6 * t / p:.0f} | "
                     f"{1e6 * t2 / p2:.0f} |")
    lines += ["", f"Total over the rows: {1e3 * sum(r[3] for r in fine):.1f} ms "
              f"({1e3 * sum(r[3] for r in coarse):.1f} ms with {OTHER} sub-steps).", ""]
    text = "\n".join(lines)
    out = Path(__file__).parent / "results" / "mdr_profile.md"
    if not out.exists():
        out.write_text("# Where the MDR solver's time goes (benchmarks/profile_mdr.py)\n")
    with out.open("a") as fh:
        fh.write(text)
    print(text)


if __name__ == "__main__":
    main()
