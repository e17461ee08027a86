"""The least a 2-D point can cost against the flat point, from the 2-D solver's own periods.

The 2-D solver (transverse oscillation, ``a_y = 0.5``) integrates the period map with
Runge-Kutta; the flat punch's event-driven solver integrates a drive period in closed form.
At each regime of ``bench_ratios.REGIMES`` this script times, side by side in one run:

* the flat point and the 2-D point as ``bench_ratios.py`` does (``solve_points`` on 32
  copies, per point);
* one period map of the 2-D solver from its own periodic orbit at the tolerances it uses:
  ``1e-10`` (``rtol``, the answer), ``1e-8`` (``100 rtol``: the error estimate, and the
  rough Newton stage with its difference Jacobian) and ``1e-6`` (the transient); and with
  the tangent carried along at ``1e-8`` (Newton's rough stage) and ``1e-6`` (the
  transient's last period before the early attempt, whose tangent is Newton's first
  Jacobian);
* the transient's length from the sliding start (periods until the map moves the state by
  less than ``1e-4``, at most 8, where the solver first tries Newton's method; 20 before
  2026-11-30), as the solver runs it.

From these, three floors of a 2-D answer in units of the flat point:

* **orbit given**: its orbit known exactly, a 2-D answer still integrates one period at
  ``rtol`` (its means) and one at ``100 rtol`` (its stated error);
* **+ multiplier**: and the Jacobian whose spectral radius is the orbit's multiplier (the
  status, the settling): by forward differences, six more periods at ``1e-8``; by the
  tangent carried along (``plane.period_map_tangent``), one period at ``1e-8`` with it;
* **+ transient**: and, for an isolated point started from steady sliding, the transient
  that brings the state to where Newton's method converges (with the tangent's Jacobian).

    PYTHONPATH=src python benchmarks/plane_floor.py [--write]

``--write`` appends the table, with the commit, date and machine, to
benchmarks/results/plane_floor.md (the earlier runs stay above).
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
from pathlib import Path

import numpy as np

from bench_ratios import A_Y, REGIMES, _timed
from sections import append_run
from vibrofriction._kernels import plane as pl

RESULTS = Path(__file__).parent / "results" / "plane_floor.md"
REPEATS = 21
TOLERANCES = (1e-10, 1e-8, 1e-6)


def _orbit(alpha, beta, a, V, zeta, a_x):
    """The parameter vector and the 2-D solver's orbit ``(s, phase)`` at a point."""
    out_f, out_i, s_out = np.zeros(40), np.zeros(20, np.int64), np.zeros(pl.N_S + 1)
    pl.plane_steady_section(alpha, beta, a, V, zeta, 0.0, a_x, 0.0, A_Y, 0.0, alpha, zeta,
                            True, 0, 0.0, 0.0, 0.0, 1e-10, 100_000, 1000, out_f, out_i, s_out)
    P = pl.parameters(alpha, beta, a, V, zeta, 0.0, a_x, 0.0, A_Y, 0.0, alpha, zeta, True, 1.0)
    return P, s_out


def _period_time(P, s_out, tol: float, tangent: bool = False) -> float:
    """Seconds of one period map at ``tol`` from the orbit (median of :data:`REPEATS`),
    with the tangent carried along where ``tangent``."""
    hmax = pl.max_step(P)
    s, s1, acc = s_out[:pl.N_S].copy(), np.empty(pl.N_S), np.zeros(4)
    J = np.zeros((pl.N_S, pl.N_S))
    times = []
    for _ in range(REPEATS):
        W = np.zeros((pl.N_W, pl.N_Z))
        W[pl.W_MODE, 0] = s_out[pl.N_S]
        cnt = np.zeros(pl.N_C, np.int64)
        t0 = time.perf_counter()
        if tangent:
            ok, _ = pl.period_map_tangent(P, s, s1, tol, tol, hmax, W, acc, cnt, 1000, J)
        else:
            ok, _, _ = pl.period_map(P, s, s1, tol, tol, hmax, W, acc, cnt, 1000)
        times.append(time.perf_counter() - t0)
        assert ok
    return statistics.median(times)


def _transient_periods(P) -> int:
    """The periods of the 2-D solver's transient from the sliding start before Newton's
    method is first tried (at most ``plane.TRANSIENT_EARLY``)."""
    W = np.zeros((pl.N_W, pl.N_Z))
    W[pl.W_MODE, 0] = pl.SLIP
    s = np.empty(pl.N_S)
    pl.start_state(P, 0, 0.0, 0.0, 0.0, s)
    periods, _ = pl._transient(P, s, 1e-10, pl.max_step(P), W, np.zeros(pl.N_C, np.int64),
                               1000, pl.TRANSIENT_EARLY)
    return int(periods)


def bench() -> list[str]:
    lines = ["| regime | flat ms | 2-D ms, ratio | period at 1e-10, 1e-8, 1e-6; with the "
             "tangent at 1e-8, 1e-6 (us) | transient periods | orbit given | + multiplier by "
             "differences | + multiplier by the tangent | + transient |",
             "|---|---|---|---|---|---|---|---|---|"]
    floors: dict[str, list[float]] = {"orbit": [], "diff": [], "mult": [], "trans": [],
                                      "ratio": []}
    for label, alpha, beta, a, V, zeta, a_x in REGIMES:
        base = {"alpha": alpha, "beta": beta, "amplitude": a, "v_inertial": V, "zeta": zeta,
                "a_x": a_x}
        t_flat, _ = _timed(**base)
        t_2d, _ = _timed(**base, a_y=A_Y)
        P, s_out = _orbit(alpha, beta, a, V, zeta, a_x)
        t10, t8, t6 = (_period_time(P, s_out, tol) for tol in TOLERANCES)
        t8_tangent = _period_time(P, s_out, 1e-8, tangent=True)
        t6_tangent = _period_time(P, s_out, 1e-6, tangent=True)
        n_tr = _transient_periods(P)
        orbit = (t10 + t8) / t_flat
        diff = orbit + 6 * t8 / t_flat
        mult = orbit + t8_tangent / t_flat
        trans = mult + n_tr * t6 / t_flat
        for k, v in zip(floors, (orbit, diff, mult, trans, t_2d / t_flat), strict=True):
            floors[k].append(v)
        line = (f"| {label} | {1e3 * t_flat:.3f} | {1e3 * t_2d:.2f}, {t_2d / t_flat:.0f}x | "
                f"{1e6 * t10:.0f}, {1e6 * t8:.0f}, {1e6 * t6:.0f}; {1e6 * t8_tangent:.0f}, "
                f"{1e6 * t6_tangent:.0f} | "
                f"{n_tr} | {orbit:.1f}x | {diff:.1f}x | {mult:.1f}x | {trans:.1f}x |")
        print(line, flush=True)
        lines.append(line)
    med = {k: statistics.median(v) for k, v in floors.items()}
    lines += ["", f"Medians over the {len(REGIMES)} regimes: the 2-D point as solved "
              f"**{med['ratio']:.0f}x** the flat point; its floors: orbit given "
              f"**{med['orbit']:.1f}x**, + multiplier by differences **{med['diff']:.1f}x** "
              f"or by the tangent **{med['mult']:.1f}x**, + transient **{med['trans']:.1f}x**."]
    print(lines[-1])
    return lines


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--write", action="store_true", help=f"append to {RESULTS}")
    args = ap.parse_args()
    lines = bench()
    if args.write:
        append_run(RESULTS, "The least a 2-D point can cost against a flat point",
                   "PYTHONPATH=src python benchmarks/plane_floor.py --write",
                   f"load average {os.getloadavg()[0]:.1f} at the end; flat and 2-D points "
                   "per point as bench_ratios.py (32 copies, median of 3 calls); a period "
                   f"map the median of {REPEATS} from the 2-D solver's orbit.", lines)


if __name__ == "__main__":
    main()
