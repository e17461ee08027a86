"""The rate-and-state solver against the event solver's Coulomb point, side by side.

For each regime the median wall time of ``REPEATS`` one-point calls of
``friction_coefficient`` with rate-and-state friction and without (Coulomb, the same
``alpha, beta, amplitude, zeta, a_x`` and ``V``), alternated in one run; then a 200-point
rate-and-state curve in one process and on two worker processes of the package's pool
(warm: started and loaded before the clock). Appends to benchmarks/results/rate_state.md.

    PYTHONPATH=src python benchmarks/bench_rate_state.py
"""

from __future__ import annotations

import datetime
import platform
import statistics
import subprocess
import time
from pathlib import Path

import numpy as np

import vibrofriction as vf
from vibrofriction.parallel import process_pool
from vibrofriction.solver import solve_points

LAW = {"rs_a": 0.01, "rs_b": 0.005, "rs_d_c": 0.01, "rs_v_ref": 1.0}
REGIMES = [  # (name, system parameters, law changes, V)
    ("stick-slip-like, a = 0.5", {"alpha": 0.5, "beta": 2.0, "amplitude": 0.5}, {}, 0.5),
    ("near grazing, a = 0.9", {"alpha": 0.5, "beta": 2.0, "amplitude": 0.9}, {}, 0.5),
    ("jumping, a = 1.5", {"alpha": 0.5, "beta": 2.0, "amplitude": 1.5}, {}, 0.5),
    ("slip law, weakening", {"alpha": 0.5, "beta": 2.0, "amplitude": 0.7},
     {"rs_law": "slip", "rs_b": 0.015}, 0.3),
    # damped: without the pin's dashpot this orbit grows slowly (multiplier 1.0016) and the
    # response is averaged over thousands of periods
    ("Linker-Dieterich, damped", {"alpha": 0.2, "beta": 3.0, "amplitude": 0.6, "zeta": 0.1},
     {"rs_b": 0.008, "rs_alpha_ld": 0.3}, 1.0),
    ("damped, stiff", {"alpha": 2.0, "beta": 5.0, "amplitude": 0.4, "zeta": 0.05}, {}, 0.4),
    ("in-plane drive", {"alpha": 0.5, "beta": 2.0, "amplitude": 0.3, "a_x": 0.2}, {}, 0.5),
]
REPEATS = 7
CURVE = np.linspace(0.05, 2.0, 200)
CURVE_SYSTEM = {"alpha": 0.5, "beta": 2.0, "amplitude": 0.5, **LAW}


def _half(velocities: np.ndarray) -> np.ndarray:
    """The curve's ``mu_ratio`` at ``velocities`` (a worker's task)."""
    return np.asarray(solve_points(**CURVE_SYSTEM, v_inertial=velocities)["mu_ratio"])


def _warm() -> None:
    solve_points(**CURVE_SYSTEM, v_inertial=0.5)


def main() -> None:
    rows, ratios = [], []
    for name, system, law, V in REGIMES:
        rs_system = vf.Dimensionless(**system, **{**LAW, **law})
        coulomb = vf.Dimensionless(**system)
        vf.friction_coefficient(rs_system, v_inertial=V)  # compile, load
        vf.friction_coefficient(coulomb, v_inertial=V)
        t_rs, t_c = [], []
        for _ in range(REPEATS):
            t0 = time.perf_counter()
            r = vf.friction_coefficient(rs_system, v_inertial=V)
            t1 = time.perf_counter()
            c = vf.friction_coefficient(coulomb, v_inertial=V)
            t2 = time.perf_counter()
            t_rs.append(t1 - t0)
            t_c.append(t2 - t1)
        m_rs, m_c = statistics.median(t_rs), statistics.median(t_c)
        ratios.append(m_rs / m_c)
        rows.append(f"| {name} | {r.mu_ratio:.8f} +- {r.error:.1e} ({r.status.value}, "
                    f"{r.work:.0f} periods) | {1e3 * m_rs:.2f} | {c.mu_ratio:.8f} | "
                    f"{1e3 * m_c:.3f} | {m_rs / m_c:.0f}x |")
    _warm()
    t0 = time.perf_counter()
    serial = _half(CURVE)
    t_serial = time.perf_counter() - t0
    with process_pool(2, _warm) as pool:
        list(pool.map(_half, np.array_split(CURVE[:4], 2)))  # workers started and loaded
        t0 = time.perf_counter()
        parts = list(pool.map(_half, np.array_split(CURVE, 2)))
        t_pool = time.perf_counter() - t0
    same = np.array_equal(np.concatenate(parts), serial, equal_nan=True)
    out = solve_points(**CURVE_SYSTEM, v_inertial=CURVE)
    statuses = {vf.Status.from_code(int(s)).value: int(n)
                for s, n in zip(*np.unique(out["status"], return_counts=True), strict=True)}
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    text = "\n".join([
        "",
        "## The rate-and-state solver against a Coulomb point",
        "",
        f"`PYTHONPATH=src python benchmarks/bench_rate_state.py`, {datetime.date.today()}, "
        f"commit {commit}, {platform.machine()} (a 2-core machine shared with other jobs: "
        f"timings noisy). Each time is the median of {REPEATS} one-point calls of "
        "`friction_coefficient`, rate-and-state and Coulomb alternated; the law is "
        f"{LAW} unless the row says otherwise; the solver's defaults (rtol 1e-7).",
        "",
        "| regime | rate-and-state mu_ratio +- error (status, work) | time (ms) | "
        "Coulomb mu_ratio | time (ms) | ratio |",
        "|---|---|---|---|---|---|",
        *rows,
        "",
        f"Median ratio over the regimes: **{statistics.median(ratios):.0f}x** (target: at most "
        "20x).",
        "",
        f"A 200-point rate-and-state curve (`v_inertial` 0.05 to 2, {CURVE_SYSTEM}): "
        f"**{t_serial:.2f} s** in one process, **{t_pool:.2f} s** on two worker processes "
        f"(warm pool; target: under 1 s on 2 cores); the same values both ways: {same}; "
        f"statuses {statuses}.",
        "",
    ])
    path = Path(__file__).parent / "results" / "rate_state.md"
    if not path.exists():
        path.write_text("# Rate-and-state solver benchmark\n")
    with path.open("a") as fh:
        fh.write(text)
    print(text)


if __name__ == "__main__":
    main()
