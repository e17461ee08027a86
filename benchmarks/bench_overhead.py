"""Python overhead of one call of ``friction_coefficient``, and a 200-point curve.

Each case is timed as the whole call and as the compiled kernel alone on the same point
(``vibrofriction._kernels.steady.steady_state``, the peer that has no Python around it),
so that the overhead is their difference; medians of 7 repeats of 200 calls, warm.
Writes ``results/overhead.md`` (appends a row per run, with the commit).

Run: ``python benchmarks/bench_overhead.py``.
"""

from __future__ import annotations

import platform
import statistics
import subprocess
import time
from pathlib import Path

import numpy as np

import vibrofriction as vf
from vibrofriction._kernels.steady import steady_state
from vibrofriction.solver.settings import DEFAULT_SETTINGS

RESULTS = Path(__file__).resolve().parent / "results" / "overhead.md"
CASES = {"stick-slip orbit, vbar = 0.3": 0.3, "above v0*, vbar = 1.5": 1.5}
SYSTEM = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)


def _median_seconds(call, repeats: int = 7, inner: int = 200) -> float:
    call()
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        for _ in range(inner):
            call()
        times.append((time.perf_counter() - t) / inner)
    return statistics.median(times)


def _kernel_call(vbar: float):
    V = float(SYSTEM.vbar_to_inertial(vbar))
    of = np.empty(len(vf.solver.FLOAT_COLUMNS))
    oi = np.empty(len(vf.solver.INT_COLUMNS), dtype=np.int64)
    args = (SYSTEM.alpha, SYSTEM.beta, SYSTEM.amplitude, V, SYSTEM.zeta, SYSTEM.eta_c, 0,
            0.0, 0.0, 0.0, 0, *DEFAULT_SETTINGS.kernel_arguments(), of, oi)
    return lambda: steady_state(*args)


def main() -> None:
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=Path(__file__).parent).stdout.strip()
    rows = []
    for name, vbar in CASES.items():
        whole = _median_seconds(lambda v=vbar: vf.friction_coefficient(SYSTEM, vbar=v))
        kernel = _median_seconds(_kernel_call(vbar))
        rows.append(f"| {commit} | {name} | {whole * 1e6:.1f} | {kernel * 1e6:.1f} | "
                    f"{(whole - kernel) * 1e6:.1f} |")
    grid = np.linspace(0.01, 1.2, 200)
    curve = _median_seconds(lambda: vf.friction_coefficient(SYSTEM, vbar=grid), inner=1)
    rows.append(f"| {commit} | 200-point curve, vbar 0.01-1.2 | {curve * 1e6:.0f} | | |")
    if not RESULTS.exists():
        RESULTS.write_text(
            "# Python overhead of friction_coefficient (benchmarks/bench_overhead.py)\n\n"
            f"alpha = 0.5, beta = 2, a = 0.5; medians of 7 x 200 warm calls; "
            f"{platform.processor() or platform.machine()}, Python "
            f"{platform.python_version()}.\n\n"
            "| commit | case | whole call (us) | kernel alone (us) | overhead (us) |\n"
            "|---|---|---|---|---|\n")
    with RESULTS.open("a") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
