"""Time per steady-state point and error: the exact solver against its peers, side by side.

Peers (``benchmarks/peers.py``): A, ``scipy.integrate.solve_ivp`` with events; B, a
numba fixed-step return-mapping integrator at 400 steps per fastest period.  The
converged reference of each point is the exact solver with ``tol_state = 1e-13``;
independently, peer B at 12800 steps per period is shown to agree with it.

Run:  ``.venv/bin/python benchmarks/bench_solver.py``  (writes benchmarks/results/solver.md
and solver.json).  Times are medians over repeats in one process; machines are noisy,
so read ratios, not absolute numbers.
"""

from __future__ import annotations

import json
import math
import os
import platform
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

import vibrofriction as vf  # noqa: E402
from peers import peer_a, peer_b, warm_up  # noqa: E402

HERE = Path(__file__).resolve().parent
QUICK = "--quick" in sys.argv

# (label, alpha, beta, amplitude, vbar or None, v_inertial if vbar is None)
POINTS = [
    ("general stick-slip", 0.5, 2.0, 0.5, 0.5, None),
    ("stiff system II", 0.01, 0.02, 0.5, 0.5, None),
    ("soft system I", 0.01, 400.01, 0.5, 0.5, None),
    ("grazing a = 1", 0.5, 2.0, 1.0, 0.5, None),
    ("jumping a = 1.5", 0.5, 2.0, 1.5, 0.5, None),
    ("alpha > 1", 2.0, 5.0, 0.8, 0.4, None),
    ("rigid contact", 0.01, math.inf, 0.5, 0.5, None),
    ("resonant IV, rigid", 1.0, math.inf, 0.5, None, 3.0),
    ("resonant IV, beta = 2", 1.0, 2.0, 0.5, None, 1.0),
    ("near beta = 1", 0.2, 0.9, 0.7, 0.5, None),
]
TIGHT = vf.SolverSettings(tol_state=1e-13)


def _median_time(fn, repeats: int, budget: float) -> tuple[float, object]:
    times, out = [], None
    t_start = time.perf_counter()
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
        if time.perf_counter() - t_start > budget:
            break
    return statistics.median(times), out


def main() -> None:
    warm_up()
    vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5), vbar=0.5)  # compile/load
    rows = []
    for label, alpha, beta, a, vbar, v_in in POINTS:
        s = vf.Dimensionless(alpha, beta, a)
        V = float(s.vbar_to_inertial(vbar)) if vbar is not None else v_in
        ref = vf.friction_coefficient(s, v_inertial=V, settings=TIGHT).mu_ratio
        t_ours, r = _median_time(lambda s=s, V=V: vf.friction_coefficient(s, v_inertial=V),
                                 50 if not QUICK else 5, 5.0)
        t_b, mu_b = _median_time(lambda p=(alpha, beta, a, V): peer_b(*p), 7 if not QUICK else 1,
                                 20.0)
        fine = peer_b(alpha, beta, a, V, steps_per_period=12800 if not QUICK else 3200)
        if QUICK:
            t_a, mu_a = _median_time(lambda p=(alpha, beta, a, V): peer_a(*p, 20, 5), 1, 60.0)
        else:
            t_a, mu_a = _median_time(lambda p=(alpha, beta, a, V): peer_a(*p), 1, 60.0)
        row = {
            "point": label, "alpha": alpha, "beta": beta, "amplitude": a, "vbar": vbar,
            "v_inertial": V, "reference": ref,
            "ours_s": t_ours, "ours_err": abs(r.mu_ratio - ref), "ours_status": r.status.value,
            "ours_periods": r.periods, "ours_stated_error": r.error,
            "peer_b_s": t_b, "peer_b_err": abs(mu_b - ref),
            "peer_a_s": t_a, "peer_a_err": abs(mu_a - ref),
            "peer_b_fine_diff": abs(fine - ref),
        }
        rows.append(row)
        print(f"{label:24s} ours {t_ours * 1e3:8.3f} ms err {row['ours_err']:.1e} | "
              f"B {t_b * 1e3:8.2f} ms err {row['peer_b_err']:.1e} | "
              f"A {t_a * 1e3:9.1f} ms err {row['peer_a_err']:.1e} | "
              f"B-fine vs ref {row['peer_b_fine_diff']:.1e}", flush=True)
    write(rows)


def _fmt_err(e: float) -> str:
    return "0" if e == 0 else f"{e:.1e}"


def write(rows: list[dict]) -> None:
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    name = "solver_quick" if QUICK else "solver"
    (out / f"{name}.json").write_text(json.dumps(rows, indent=1))
    floor = 1e-16  # our error is often exactly 0 against the tight run
    sp_b = [r["peer_b_s"] / r["ours_s"] for r in rows]
    sp_a = [r["peer_a_s"] / r["ours_s"] for r in rows]
    acc_b = [r["peer_b_err"] / max(r["ours_err"], floor) for r in rows]
    lines = [
        "# Solver benchmark: exact event-driven solver vs peers",
        "",
        f"Command: `.venv/bin/python benchmarks/bench_solver.py{' --quick' if QUICK else ''}`  ",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python "
        f"{platform.python_version()}, numpy {np.__version__}; one process, one core.  ",
        f"Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}",
        "",
        "Time: median wall time per steady-state point (ours: 50 repeats, B: 7, A: 1).",
        "Error: |mu/mu0 - reference|, reference = exact solver with tol_state = 1e-13. ",
        "Independent check: peer B at 12800 steps per fastest period vs that reference "
        "(the reference is not just our own answer: a different method converges to it).",
        "",
        "| point | alpha | beta | a | vbar / V | ours (ms) | ours err | status | "
        "B 400 steps (ms) | B err | A solve_ivp (ms) | A err | B/ours time | A/ours time "
        "| B err / ours err | B@12800 vs ref |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r, sb, sa, ab in zip(rows, sp_b, sp_a, acc_b, strict=True):
        vel = f"{r['vbar']:g}" if r["vbar"] is not None else f"V={r['v_inertial']:g}"
        lines.append(
            f"| {r['point']} | {r['alpha']:g} | {r['beta']:g} | {r['amplitude']:g} | {vel} | "
            f"{r['ours_s'] * 1e3:.3f} | {_fmt_err(r['ours_err'])} | {r['ours_status']} | "
            f"{r['peer_b_s'] * 1e3:.2f} | {_fmt_err(r['peer_b_err'])} | "
            f"{r['peer_a_s'] * 1e3:.0f} | {_fmt_err(r['peer_a_err'])} | {sb:.0f}x | {sa:.0f}x | "
            f"{ab:.1e} | {_fmt_err(r['peer_b_fine_diff'])} |")
    lines += [
        "",
        f"Median speed-up over peer B: **{statistics.median(sp_b):.0f}x** "
        f"(min {min(sp_b):.0f}x); over peer A: **{statistics.median(sp_a):.0f}x** "
        f"(min {min(sp_a):.0f}x).  ",
        f"Median accuracy ratio (B error / our error, our error floored at 1e-16): "
        f"{statistics.median(acc_b):.1e} (min {min(acc_b):.1e}).",
    ]
    (out / f"{name}.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines[-3:]))


if __name__ == "__main__":
    main()
