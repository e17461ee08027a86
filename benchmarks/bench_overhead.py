"""Python overhead of one call of ``friction_coefficient``, a 200-point curve, and a system built.

Each case is timed three ways, the repeats interleaved so that a busy machine slows
all three alike:

* the whole call;
* the compiled kernel alone on the same point (``vibrofriction._kernels.steady.
  steady_state``, called as the solver calls it but with no Python around it), so that
  the overhead is the difference of the two medians;
* the whole call with the kernels stubbed (``Python alone``): the solver's kernel entries
  replaced by a function that writes the rows the real kernel wrote for that point,
  which measures the Python around the kernel without the kernel's noise (numba's
  argument dispatch is not in it; the stub's own call, about 0.5 us, is).

The system's construction (``Dimensionless(0.5, 2, 0.5)``, its parameters validated) is
timed as a whole, as a script that builds one system a point pays it.

Medians of 7 repeats of 200 calls (single points) or 1 call (the curve), warm, in a
fresh process; each number is the median of ``--rounds`` (3) such processes.  With
``--baseline REV`` the same measurement is run on that revision's ``src`` (exported by
``git archive`` to a temporary directory; its numba cache is compiled there first) and
on the working tree, the two in turn.  Appends a section to ``results/overhead.md``
with the commit(s), date and machine.

Run: ``python benchmarks/bench_overhead.py [--baseline REV] [--rounds N]``.
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).resolve().parent / "results" / "overhead.md"
ROOT = Path(__file__).resolve().parent.parent
CASES = {"stick-slip orbit, vbar = 0.3": 0.3, "above v0*, vbar = 1.5": 1.5}
CURVE = "200-point curve, vbar 0.01-1.2"
BUILD = "the system built, Dimensionless(0.5, 2, 0.5)"
REPEATS = 7


def _interleaved_medians(loops: dict, inner: int) -> dict[str, float]:
    """Median seconds per call of each of ``loops`` (``loop(n)`` makes n calls), their
    repeats interleaved."""
    for loop in loops.values():
        loop(1)
    times: dict[str, list[float]] = {k: [] for k in loops}
    for _ in range(REPEATS):
        for k, loop in loops.items():
            t = time.perf_counter()
            loop(inner)
            times[k].append((time.perf_counter() - t) / inner)
    return {k: statistics.median(v) for k, v in times.items()}


def _loop(call):
    def loop(n: int) -> None:
        for _ in range(n):
            call()
    return loop


def _stub(real):
    """A stand-in for the kernel entry ``real`` that writes the rows ``real`` wrote at its
    first call (its last two array arguments are the output rows: a flag may follow)."""
    rows: dict[str, np.ndarray] = {}

    def stub(*args):
        of, oi = [a for a in args if isinstance(a, np.ndarray)][-2:]
        if not rows:
            real(*args)
            rows["f"], rows["i"] = of.copy(), oi.copy()
        of[...] = rows["f"]
        oi[...] = rows["i"]
    return stub


def measure() -> dict[str, dict[str, float]]:
    """Microseconds per call by case: ``whole``, ``kernel`` (single points) and ``python``."""
    import vibrofriction as vf
    from vibrofriction._kernels.steady import steady_state
    from vibrofriction.solver import engine
    from vibrofriction.solver.settings import DEFAULT_SETTINGS

    try:  # the method protocol: the batch kernel is called by the event method
        from vibrofriction.solver.methods import event
        from vibrofriction.solver.methods.event import event_arguments
    except ImportError:  # a tree before it (--baseline): the engine called it
        event = engine

        def event_arguments(settings):
            return settings.kernel_arguments()

    system = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)
    real_one, real_many = engine.steady_state, event.steady_state_many

    def stubbed(call):
        def loop(n: int) -> None:
            engine.steady_state, event.steady_state_many = stub_one, stub_many
            try:
                for _ in range(n):
                    call()
            finally:
                engine.steady_state, event.steady_state_many = real_one, real_many
        return loop

    out = {}
    for name, vbar in CASES.items():
        V = float(system.vbar_to_inertial(vbar))
        of = np.empty(len(vf.solver.FLOAT_COLUMNS))
        oi = np.empty(len(vf.solver.INT_COLUMNS), dtype=np.int64)
        args = (system.alpha, system.beta, system.amplitude, V, system.zeta, system.eta_c,
                system.a_x, system.phase_x, True, system.static_ratio, 0, 0.0, 0.0, 0.0, 0,
                *event_arguments(DEFAULT_SETTINGS), of, oi)
        stub_one, stub_many = _stub(real_one), _stub(real_many)
        t = _interleaved_medians({
            "whole": _loop(lambda v=vbar: vf.friction_coefficient(system, vbar=v)),
            "kernel": _loop(lambda a=args: steady_state(*a)),
            "python": stubbed(lambda v=vbar: vf.friction_coefficient(system, vbar=v)),
        }, inner=200)
        out[name] = {k: v * 1e6 for k, v in t.items()}
    grid = np.linspace(0.01, 1.2, 200)
    stub_one, stub_many = _stub(real_one), _stub(real_many)
    t = _interleaved_medians({
        "whole": _loop(lambda: vf.friction_coefficient(system, vbar=grid)),
        "python": stubbed(lambda: vf.friction_coefficient(system, vbar=grid)),
    }, inner=1)
    out[CURVE] = {k: v * 1e6 for k, v in t.items()}
    t = _interleaved_medians({"whole": _loop(lambda: vf.Dimensionless(0.5, 2.0, 0.5))},
                             inner=200)
    out[BUILD] = {k: v * 1e6 for k, v in t.items()}
    return out


def _git(*args: str) -> str:
    return subprocess.run(["git", *args], capture_output=True, text=True, cwd=ROOT,
                          check=True).stdout.strip()


def _measure_in(src: Path) -> dict[str, dict[str, float]]:
    """:func:`measure` in a fresh process importing ``vibrofriction`` from ``src``."""
    env = {**os.environ, "PYTHONPATH": str(src)}
    run = subprocess.run([sys.executable, __file__, "--measure-only"], env=env, check=True,
                         capture_output=True, text=True)
    return json.loads(run.stdout.splitlines()[-1])


def _rows(label: str, t: dict[str, dict[str, float]]) -> list[str]:
    rows = []
    for name in CASES:
        w, k, p = t[name]["whole"], t[name]["kernel"], t[name]["python"]
        rows.append(f"| {label} | {name} | {w:.1f} | {k:.1f} | {w - k:.1f} | {p:.1f} |")
    w, p = t[CURVE]["whole"], t[CURVE]["python"]
    rows.append(f"| {label} | {CURVE} | {w:.0f} | | | {p:.0f} |")
    if BUILD in t:
        rows.append(f"| {label} | {BUILD} | {t[BUILD]['whole']:.1f} | | | |")
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", metavar="REV",
                        help="also measure this git revision's src, side by side")
    parser.add_argument("--rounds", type=int, default=3,
                        help="measurements of each tree, in turn; their median is reported")
    parser.add_argument("--measure-only", action="store_true", help=argparse.SUPPRESS)
    opts = parser.parse_args()
    if opts.measure_only:
        print(json.dumps(measure()))
        return
    commit = _git("rev-parse", "--short", "HEAD")
    dirty = " (with uncommitted changes)" if _git("status", "--porcelain", "src") else ""
    trees = {commit: ROOT / "src"}
    with tempfile.TemporaryDirectory() as tmp:
        if opts.baseline:
            base = _git("rev-parse", "--short", opts.baseline)
            archive = subprocess.run(["git", "archive", base, "src"], cwd=ROOT, check=True,
                                     capture_output=True).stdout
            subprocess.run(["tar", "-x", "-C", tmp], input=archive, check=True)
            _measure_in(Path(tmp) / "src")  # compiles its numba cache
            trees = {base: Path(tmp) / "src", **trees}
        runs: dict[str, list] = {label: [] for label in trees}
        for _ in range(opts.rounds):  # the trees in turn, so that load hits both
            for label, src in trees.items():
                runs[label].append(_measure_in(src))
    rows = []
    for label, measured in runs.items():
        rows += _rows(label, {case: {k: statistics.median(m[case][k] for m in measured)
                                     for k in measured[0][case]} for case in measured[0]})
    date = datetime.date.today().isoformat()
    against = f" against {base}" if opts.baseline else ""
    command = "python benchmarks/bench_overhead.py" + (
        f" --baseline {opts.baseline}" if opts.baseline else "") + (
        f" --rounds {opts.rounds}" if opts.rounds != 3 else "")
    section = (
        f"\n## {commit}{dirty}{against}\n\n"
        f"`{command}` on {date}; {platform.processor() or platform.machine()}, Python "
        f"{platform.python_version()}, {os.cpu_count()} cores; alpha = 0.5, beta = 2, "
        f"a = 0.5; medians of {REPEATS} interleaved repeats of 200 warm calls (the curve: "
        f"of 1 call) in a fresh process, then the median of {opts.rounds} such "
        "measurements of each tree, taken in turn.\n\n"
        "| commit | case | whole call (us) | kernel alone (us) | overhead (us) | "
        "Python alone, kernel stubbed (us) |\n|---|---|---|---|---|---|\n"
        + "\n".join(rows) + "\n")
    with RESULTS.open("a") as f:
        f.write(section)
    print(section)


if __name__ == "__main__":
    main()
