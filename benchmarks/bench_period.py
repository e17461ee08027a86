"""The cost of one drive period of the 1-D exact kernels, plain and with the tangent (issue 19).

Points: the 49 held-out points of ``bench_heldout.points()`` and the stiff point of
``results/stiff.md`` (alpha 0.01, beta 1e6, zeta 0.001, a 0.5, vbar 0.1; hundreds of
micro-slip events per period).  Per point, from the section state after ``WARM`` periods
from steady sliding, ``period_map`` (plain) and ``period_map_tangent`` integrate ``P``
periods in one kernel call; a point's time per period is the median over ``REPEATS`` calls
divided by ``P``.  Each tree (``--tree DIR``, its ``src`` first on ``PYTHONPATH``) is timed
in its own worker process, new every round; the trees alternate point by point (their order
reversed every other round), ``ROUNDS`` rounds, and each point's time is the median over the
rounds.  The
workers also return the end state, Jacobian and event count, to compare the trees.

Run:  ``.venv/bin/python benchmarks/bench_period.py --tree OLD --tree NEW [--note TEXT]``
(the first tree is "before", the last "after"; default: this tree alone).  Appends a
section to ``results/period.md`` (``--no-write``: print only).  Run nothing heavy
alongside; the load average is recorded.
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
REPEATS = 9
ROUNDS = 15
STIFF = ("stiff corner", 0.01, 1e6, 0.5, 0.1, 0.001, 0.0)  # vbar, not V
MAX_EVENTS = 10**7
# wall-clock and CPU time (process_time: less disturbed by other processes on a loaded machine)
KINDS = ("plain", "tangent", "plain_cpu", "tangent_cpu")


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


def worker() -> None:
    """Serve timings of the tree on ``sys.path``: reads the points (one JSON line), prepares
    each (compiles, warms up), then answers each point index it reads with one JSON line."""
    import numpy as np

    from vibrofriction._kernels.integrate import initial_point
    from vibrofriction._kernels.period import period_map
    from vibrofriction._kernels.phases import make_model
    from vibrofriction._kernels.tangent import period_map_tangent

    starts = []
    for _, alpha, beta, a, V, zeta, eta in json.loads(sys.stdin.readline()):
        M = make_model(alpha, beta, a, V, zeta, eta, 0.0, 0.0, False)
        y, xd, e, ph, _ = initial_point(0, alpha, beta, a, V, zeta, eta, 0.0, 0.0, False, 1.0)
        y, xd, e, ph, _, _, _ = period_map(y, xd, e, ph, WARM, M, MAX_EVENTS)
        starts.append((M, y, xd, e, ph))
    J = np.zeros((3, 3))
    G = np.zeros(3)
    acc = np.zeros(6)
    period_map_tangent(*starts[0][1:], 1, starts[0][0], MAX_EVENTS, J, G, acc)  # compile
    print("ready", flush=True)
    for line in sys.stdin:
        M, y, xd, e, ph = starts[int(line)]
        times: dict[str, list[float]] = {k: [] for k in KINDS}
        for _ in range(REPEATS):
            t0, c0 = time.perf_counter(), time.process_time()
            r = period_map(y, xd, e, ph, P, M, MAX_EVENTS)
            t1, c1 = time.perf_counter(), time.process_time()
            rt = period_map_tangent(y, xd, e, ph, P, M, MAX_EVENTS, J, G, acc)
            t2, c2 = time.perf_counter(), time.process_time()
            for k, v in zip(KINDS, (t1 - t0, t2 - t1, c1 - c0, c2 - c1), strict=True):
                times[k].append(v / P)
        print(json.dumps({**{k: statistics.median(v) for k, v in times.items()},
                          "events": int(r[4]) / P, "state": [float(v) for v in r[:3]],
                          "phase": int(r[3]), "degenerate": int(r[5]),
                          "tangent_state": [float(v) for v in rt[:3]],
                          "J": [float(v) for v in J.ravel()], "G": [float(v) for v in G],
                          "int_f": float(acc[0])}), flush=True)


class Worker:
    """A worker process timing one tree (its ``src`` first on ``PYTHONPATH``)."""

    def __init__(self, tree: Path, pts: list) -> None:
        env = dict(os.environ, PYTHONPATH=str(tree / "src"))
        self.proc = subprocess.Popen([sys.executable, __file__, "--worker"], env=env,
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        self._send(json.dumps(pts))

    def _send(self, line: str) -> None:
        assert self.proc.stdin is not None
        self.proc.stdin.write(line + "\n")
        self.proc.stdin.flush()

    def _read(self) -> str:
        assert self.proc.stdout is not None
        return self.proc.stdout.readline()

    def ready(self) -> None:
        if self._read().strip() != "ready":
            raise RuntimeError("worker failed")

    def time(self, j: int) -> dict:
        self._send(str(j))
        return json.loads(self._read())

    def close(self) -> None:
        assert self.proc.stdin is not None
        self.proc.stdin.close()
        self.proc.wait()


def _commit(tree: Path) -> str:
    out = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                         text=True, cwd=tree)
    if out.returncode != 0:
        return "not a git checkout"
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no", "src"],
                           capture_output=True, text=True, cwd=tree).stdout.strip()
    return out.stdout.strip() + ("+dirty" if dirty else "")


def main() -> None:
    trees = [Path(sys.argv[i + 1]).resolve() for i, a in enumerate(sys.argv) if a == "--tree"]
    trees = trees or [HERE.parent]
    note = sys.argv[sys.argv.index("--note") + 1] if "--note" in sys.argv else ""
    pts = points()
    load0 = os.getloadavg()[0]
    # runs[i][round][point]; new worker processes every round: the speed of compiled code
    # varies from process to process (where it is loaded), by up to 2x on this machine
    runs: list[list[list[dict]]] = [[[{} for _ in pts] for _ in range(ROUNDS)] for _ in trees]
    for rnd in range(ROUNDS):
        workers = [Worker(tree, pts) for tree in trees]
        for w in workers:
            w.ready()
        order = list(range(len(trees)))[::(-1 if rnd % 2 else 1)]
        for j in range(len(pts)):
            for i in order:
                runs[i][rnd][j] = workers[i].time(j)
        for w in workers:
            w.close()
        print(f"round {rnd + 1}/{ROUNDS} done", flush=True)
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
             f"{platform.python_version()}; load average {load0:.2f} before the timings, "
             f"{load1:.2f} after.\n",
             f"Per point: median over {REPEATS} kernel calls of {P} periods each, from the "
             f"section state after {WARM} periods; then the median over {ROUNDS} rounds "
             "(trees alternating point by point, each in its own process, new every "
             "round).  us per drive period, wall-clock and CPU time (`time.process_time`).\n",
             "| | " + " | ".join(f"{c}: plain | tangent" for c in cols) + " |",
             "|---|" + "---|---|" * len(trees)]
    for label, idx in (("held-out, median over 49 points", held), ("stiff corner", [stiff])):
        for clock, sfx in (("wall", ""), ("CPU", "_cpu")):
            cells = []
            for i in range(len(trees)):
                cells += [f"{1e6 * statistics.median(med(i, j, 'plain' + sfx) for j in idx):.2f}",
                          f"{1e6 * statistics.median(med(i, j, 'tangent' + sfx) for j in idx):.2f}"]
            lines.append(f"| {label}, {clock} | " + " | ".join(cells) + " |")
    if len(trees) > 1:
        first, last = 0, len(trees) - 1
        lines.append("")
        for label, idx in (("held-out", held), ("stiff corner", [stiff])):
            for kind in KINDS:
                ratios = [med(first, j, kind) / med(last, j, kind) for j in idx]
                lines.append(f"- {label}, {kind}: before/after, median of the per-point ratios "
                             f"**{statistics.median(ratios):.2f}x** (min {min(ratios):.2f}, "
                             f"max {max(ratios):.2f})")
        a, b = runs[first][0], runs[last][0]
        dstate = max(abs(x - y) / (1.0 + abs(x)) for j in range(len(pts))
                     for x, y in zip(a[j]["state"] + a[j]["tangent_state"] + [a[j]["int_f"]],
                                     b[j]["state"] + b[j]["tangent_state"] + [b[j]["int_f"]],
                                     strict=True))
        dJ = max(abs(x - y) / (1.0 + abs(x)) for j in range(len(pts))
                 for x, y in zip(a[j]["J"] + a[j]["G"], b[j]["J"] + b[j]["G"], strict=True))
        dev = sum(a[j]["events"] != b[j]["events"] or a[j]["phase"] != b[j]["phase"]
                  for j in range(len(pts)))
        lines.append(f"\nEquality ({WARM} + {P} periods, each tree from steady sliding): max "
                     f"|d|/(1 + |x|) of the state and int f {dstate:.1e}, of J and G "
                     f"{dJ:.1e}; points whose event count or phase differ: {dev}.")
    lines.append("\nPer point, wall-clock:\n")
    lines.append("| point (alpha, beta, a, V) | events/period | "
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
        worker()
    else:
        main()
