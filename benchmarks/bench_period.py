"""The cost of one drive period of the 1-D exact kernels, plain and with the tangent (issue 19).

Points: the 49 held-out points of ``bench_heldout.points()`` and the stiff point of
``results/stiff.md`` (alpha 0.01, beta 1e6, zeta 0.001, a 0.5, vbar 0.1; hundreds of
micro-slip events per period).  Per point, from the section state after ``WARM`` periods
from steady sliding, ``period_map`` (plain) and ``period_map_tangent`` integrate ``P``
periods in one kernel call; the time per period is the median over ``REPEATS`` calls
divided by ``P``.  Each tree (``--tree DIR``, its ``src`` first on ``PYTHONPATH``) is timed
in its own subprocess; the trees alternate, ``ROUNDS`` rounds, and each point's time is
the median over the rounds.  The workers also return the end state and event count so
that the trees can be compared for equality.

Run:  ``.venv/bin/python benchmarks/bench_period.py --tree /path/old --tree . [--note TEXT]``
(the first tree is "before", the last "after"; default: this tree alone).  Writes
``results/period.md`` (``--no-write``: print only).  Run nothing heavy alongside.
"""

from __future__ import annotations

import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPORT = HERE / "results" / "period.md"
WARM = 30  # periods from steady sliding before the timed state
P = 10  # periods per timed kernel call
REPEATS = 15
ROUNDS = 3
STIFF = ("stiff corner", 0.01, 1e6, 0.5, 0.1, 0.001, 0.0)  # vbar, not V
MAX_EVENTS = 10**7


def points() -> list[tuple[str, float, float, float, float, float, float]]:
    """``(name, alpha, beta, a, V, zeta, eta_c)``: the held-out points and the stiff one."""
    sys.path.insert(0, str(HERE))
    import vibrofriction as vf
    from bench_heldout import points as heldout

    out = list(heldout())
    name, alpha, beta, a, vbar, zeta, eta = STIFF
    V = float(vf.Dimensionless(alpha, beta, a, zeta=zeta).vbar_to_inertial(vbar))
    out.append((name, alpha, beta, a, V, zeta, eta))
    return out


def worker(pts: list) -> list[dict]:
    """Time one tree (the one on ``sys.path``) at ``pts``."""
    import numpy as np

    from vibrofriction._kernels.integrate import initial_point
    from vibrofriction._kernels.period import period_map
    from vibrofriction._kernels.phases import make_model
    from vibrofriction._kernels.tangent import period_map_tangent

    rows = []
    for _, alpha, beta, a, V, zeta, eta in pts:
        M = make_model(alpha, beta, a, V, zeta, eta, 0.0, 0.0, False)
        y, xd, e, ph, _ = initial_point(0, alpha, beta, a, V, zeta, eta, 0.0, 0.0, False)
        y, xd, e, ph, ev0, deg0, _ = period_map(y, xd, e, ph, WARM, M, MAX_EVENTS)
        J = np.zeros((3, 3))
        G = np.zeros(3)
        acc = np.zeros(6)
        plain = []
        tangent = []
        for _ in range(REPEATS):
            t0 = time.perf_counter()
            r = period_map(y, xd, e, ph, P, M, MAX_EVENTS)
            plain.append((time.perf_counter() - t0) / P)
            t0 = time.perf_counter()
            rt = period_map_tangent(y, xd, e, ph, P, M, MAX_EVENTS, J, G, acc)
            tangent.append((time.perf_counter() - t0) / P)
        rows.append({"plain": statistics.median(plain), "tangent": statistics.median(tangent),
                     "events": int(r[4]) / P, "state": [float(v) for v in r[:3]],
                     "phase": int(r[3]), "degenerate": int(r[5]),
                     "tangent_state": [float(v) for v in rt[:3]],
                     "J": [float(v) for v in J.ravel()], "G": [float(v) for v in G],
                     "int_f": float(acc[0])})
    return rows


def run_tree(tree: Path, pts: list) -> list[dict]:
    env = dict(os.environ, PYTHONPATH=str(tree / "src"))
    out = subprocess.run([sys.executable, __file__, "--worker"], input=json.dumps(pts),
                         capture_output=True, text=True, env=env, check=True)
    return json.loads(out.stdout)


def _commit(tree: Path) -> str:
    out = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                         text=True, cwd=tree)
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no", "src"],
                           capture_output=True, text=True, cwd=tree).stdout.strip()
    return (out.stdout.strip() or "unknown") + ("+dirty" if dirty else "")


def _rel(x: float, y: float) -> float:
    return abs(x - y) / max(abs(x), abs(y), 1e-300)


def main() -> None:
    trees = [Path(sys.argv[i + 1]).resolve() for i, a in enumerate(sys.argv) if a == "--tree"]
    trees = trees or [HERE.parent]
    note = sys.argv[sys.argv.index("--note") + 1] if "--note" in sys.argv else ""
    pts = points()
    load0 = os.getloadavg()[0]
    runs: list[list[list[dict]]] = [[] for _ in trees]
    for rnd in range(ROUNDS):
        for i, tree in enumerate(trees):  # alternate the trees, round by round
            runs[i].append(run_tree(tree, pts))
            print(f"round {rnd + 1}/{ROUNDS}: {tree} done", flush=True)
    load1 = os.getloadavg()[0]

    def med(i: int, j: int, kind: str) -> float:
        return statistics.median(r[j][kind] for r in runs[i])

    names = [f"{p[0]} {p[1]:.4g}, {p[2]:.4g}, {p[3]:.4g}, {p[4]:.4g}" for p in pts]
    held = range(len(pts) - 1)
    stiff = len(pts) - 1
    cols = [f"{tree.name} @ {_commit(tree)}" for tree in trees]
    lines = [f"\n## {datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC"
             + (f": {note}" if note else "") + "\n",
             f"Command: `{' '.join([Path(sys.executable).name, *sys.argv])}`  ",
             f"Trees: {', '.join(cols)}  ",
             f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python "
             f"{platform.python_version()}; load average {load0:.2f} before, {load1:.2f} "
             "after.\n",
             f"Per point: median over {REPEATS} kernel calls of {P} periods each, from the "
             f"section state after {WARM} periods; then the median over {ROUNDS} rounds "
             "(trees alternating, each in its own process).  us per drive period.\n",
             "| | " + " | ".join(f"{c}: plain | tangent" for c in cols) + " |",
             "|---|" + "---|---|" * len(trees)]
    for label, idx in (("held-out, median over 49 points", held), ("stiff corner", [stiff])):
        cells = []
        for i in range(len(trees)):
            cells += [f"{1e6 * statistics.median(med(i, j, 'plain') for j in idx):.2f}",
                      f"{1e6 * statistics.median(med(i, j, 'tangent') for j in idx):.2f}"]
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    if len(trees) > 1:
        first, last = 0, len(trees) - 1
        for label, idx in (("held-out", held), ("stiff corner", [stiff])):
            for kind in ("plain", "tangent"):
                ratios = [med(first, j, kind) / med(last, j, kind) for j in idx]
                lines.append(f"\n{label}, {kind}: before/after median ratio "
                             f"{statistics.median(ratios):.2f}x (per-point min "
                             f"{min(ratios):.2f}, max {max(ratios):.2f})")
        a, b = runs[first][0], runs[last][0]
        dstate = max(_rel(x, y) for j in range(len(pts))
                     for x, y in zip(a[j]["state"] + a[j]["tangent_state"] + [a[j]["int_f"]],
                                     b[j]["state"] + b[j]["tangent_state"] + [b[j]["int_f"]],
                                     strict=True))
        dJ = max(abs(x - y) / (1.0 + abs(x)) for j in range(len(pts))
                 for x, y in zip(a[j]["J"] + a[j]["G"], b[j]["J"] + b[j]["G"], strict=True))
        dev = sum(a[j]["events"] != b[j]["events"] or a[j]["phase"] != b[j]["phase"]
                  for j in range(len(pts)))
        lines.append(f"\nEquality after {P} periods (first round): max relative difference "
                     f"of the state and int f {dstate:.1e}; of J, G (|d|/(1+|J|)) {dJ:.1e}; "
                     f"points whose event count or phase differ: {dev}.")
    lines.append("\n| point (alpha, beta, a, V) | events/period | "
                 + " | ".join(f"{c} plain | tangent" for c in cols) + " |")
    lines.append("|---|---|" + "---|---|" * len(trees))
    for j, name in enumerate(names):
        cells = []
        for i in range(len(trees)):
            cells += [f"{1e6 * med(i, j, 'plain'):.2f}", f"{1e6 * med(i, j, 'tangent'):.2f}"]
        lines.append(f"| {name} | {runs[-1][0][j]['events']:g} | " + " | ".join(cells) + " |")
    text = "\n".join(lines) + "\n"
    print(text)
    if "--no-write" not in sys.argv:
        if not REPORT.exists():
            REPORT.write_text("# The cost of one drive period (benchmarks/bench_period.py)\n\n"
                              "us per drive period of the 1-D exact kernels, plain "
                              "(`period_map`) and with the exact Jacobian "
                              "(`period_map_tangent`); one section per run.\n")
        with REPORT.open("a") as fh:
            fh.write(text)


if __name__ == "__main__":
    if "--worker" in sys.argv:
        json.dump(worker(json.loads(sys.stdin.read())), sys.stdout)
    else:
        main()
