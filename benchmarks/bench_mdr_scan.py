"""CPU time of the MDR solver (``mdr_friction``, tol 1e-5) at ``bench_mdr.py``'s points:
this tree's scan, which misses no root (at its default sub-steps a period and at 1024),
against a commit's fixed scan (default ``1153fe4``, the last with the fixed scan at 1024
sub-steps), each in its own process, the three alternated over ``ROUNDS`` rounds; each
point's time the median of ``REPEATS`` calls (``time.process_time``: the shared
machine's other processes count less). Writes benchmarks/results/mdr_scan.md.

    PYTHONPATH=src python benchmarks/bench_mdr_scan.py [commit]
"""

import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROUNDS = 3
REPEATS = 11
HERE = Path(__file__).resolve().parent
ROOT = HERE.parent

# run in each process: the points' medians as JSON (argv: repeats, sub-steps or 0)
CHILD = """
import contextlib, json, statistics, sys, time
sys.path.insert(0, {bench!r})
from bench_mdr import POINTS, STIFF_CONTACT
import vibrofriction.solver.mdr as S
if int(sys.argv[2]):
    _row = S.mdr_row
    S.mdr_row = lambda *a, **k: _row(*a, **{{**k, "substeps": int(sys.argv[2])}})
S.mdr_friction(0.5, 2.0, 0.5, 0.3, 2.0)
out = []
for al, be, a, V, z, n in [*POINTS, STIFF_CONTACT]:
    ts = []
    for _ in range(int(sys.argv[1])):
        t0 = time.process_time()
        with getattr(S, "rows_alone", contextlib.nullcontext)():  # (the rows: their scan)
            r = S.mdr_friction(al, be, a, V, n, zeta=z, tol=1e-5)
        ts.append(time.process_time() - t0)
    out.append((statistics.median(ts), r["mu_ratio"], r["error"]))
print(json.dumps(out))
"""


def run(src: str, substeps: int) -> list:
    env = {**os.environ, "PYTHONPATH": src}
    code = CHILD.format(bench=str(HERE))
    res = subprocess.run([sys.executable, "-c", code, str(REPEATS), str(substeps)],
                         env=env, capture_output=True, text=True, check=True)
    return json.loads(res.stdout)


def main() -> None:
    commit = sys.argv[1] if len(sys.argv) > 1 else "1153fe4"
    here = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                          text=True, cwd=ROOT).stdout.strip()
    import vibrofriction.solver.mdr as mdr

    with tempfile.TemporaryDirectory() as tmp:
        archive = subprocess.run(["git", "archive", commit, "src"], capture_output=True,
                                 cwd=ROOT, check=True).stdout
        subprocess.run(["tar", "x", "-C", tmp], input=archive, check=True)
        old_src = str(Path(tmp) / "src")
        new_src = str(ROOT / "src")
        runs: dict[str, list] = {"fixed": [], "rigorous": [], "rigorous 1024": []}
        for _ in range(ROUNDS):
            runs["fixed"].append(run(old_src, 0))
            runs["rigorous"].append(run(new_src, 0))
            runs["rigorous 1024"].append(run(new_src, 1024))
    names = list(runs)
    npts = len(runs["fixed"][0])
    med = {k: [statistics.median(r[i][0] for r in v) for i in range(npts)]
           for k, v in runs.items()}
    from bench_mdr import POINTS, STIFF_CONTACT

    lines = ["# The MDR scan that misses no root: CPU time", "",
             f"`PYTHONPATH=src python benchmarks/bench_mdr_scan.py {commit}`, "
             f"{datetime.date.today()}, commit {here}, {platform.machine()} (shared 2-core "
             f"machine: another process ran beside it; CPU time, each point the median of "
             f"{REPEATS} calls, then the median of {ROUNDS} rounds, the three versions "
             f"alternated). `fixed`: commit {commit}'s scan of fixed sub-steps (1024 a "
             f"period); `rigorous`: this tree's at its {mdr.SUBSTEPS} sub-steps a period; "
             f"`rigorous 1024`: at 1024.", "",
             "| alpha, beta, a, V, zeta, n | " + " | ".join(f"{k} ms" for k in names)
             + " | mu_ratio fixed - rigorous | error fixed - rigorous |",
             "| --- | " + " | ".join("---" for _ in names) + " | --- | --- |"]
    for i, p in enumerate([*POINTS, STIFF_CONTACT]):
        dmu = runs["fixed"][0][i][1] - runs["rigorous"][0][i][1]
        derr = runs["fixed"][0][i][2] - runs["rigorous"][0][i][2]
        lines.append(f"| {', '.join(f'{x:.4g}' for x in p)} | "
                     + " | ".join(f"{1e3 * med[k][i]:.2f}" for k in names)
                     + f" | {dmu:.1e} | {derr:.1e} |")
    six = {k: statistics.median(v[:-1]) for k, v in med.items()}
    lines += ["", "Median over the six regimes (the last row, the stiff contact, outside): "
              + ", ".join(f"{k} {1e3 * six[k]:.2f} ms" for k in names)
              + f"; rigorous/fixed {six['rigorous'] / six['fixed']:.2f}x, rigorous 1024/"
              f"fixed {six['rigorous 1024'] / six['fixed']:.2f}x.", ""]
    text = "\n".join(lines)
    (HERE / "results" / "mdr_scan.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
