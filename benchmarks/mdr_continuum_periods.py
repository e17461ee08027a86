"""Where the row without springs' periods go, and what a perfect start of the body buys.

At the ten regimes of ``bench_ratios.py`` for a cone, a sphere and ``n = 4``, the row without
springs asked for ``tol_trusted = 1e-7`` (:func:`~vibrofriction.solver.mdr_continuum.
continuum_friction`: maps at ``3e-8``, the fine orbit's at ``3e-9`` (``FINE`` times
that; ``3e-10`` where the coarse orbit grazes, ``FINE_GRAZE``), the first ones at
``VROUGH``, then ``ROUGH``):

* the period maps and Dormand-Prince steps of each stage of the search, counted in a
  second process under ``NUMBA_DISABLE_JIT`` (the kernel's ``period`` wrapped): the
  transient (maps at ``VROUGH``, then at ``ROUGH``), the coarse orbit (at ``3e-8``) and
  the fine one (``3e-9``, or ``3e-10`` where it grazes) (a tree without ``VROUGH`` has
  one transient stage); a jumping point's search-distance maps count with the stage of
  their tolerance (the coarse one's, ``1e-6`` at the tightest: at ``1e-7``, the rough
  stage's); and, over all stages, the
  rejected steps, the steps cut at an event found in them (their end read from the dense
  output; before 06b7f3c taken again to it) and the segments (the stretches between turns
  of the band's edges);
* the periods from the default start (steady sliding, the body at rest at
  ``-(1 + a)^(1 + 1/n)/alpha``) and from a start with the body exactly on its orbit at
  ``tau = 0`` (``u``, ``u'`` read from the converged orbit's history), the profile
  started as always: what the best possible first guess of the body alone would buy;
* the search's floor: the steps of one coarse and one fine map from the converged orbit's
  whole section state (the body and the profile), what even a perfect first guess costs
  (counted in this process, compiled).

    PYTHONPATH=src python benchmarks/mdr_continuum_periods.py [--tol TOL] [--write]

``--tol`` another ``tol_trusted`` (the maps' tolerances as ``continuum_friction`` chooses
them, without its retry); ``--write`` appends the run to
benchmarks/results/mdr_continuum_periods.md.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

from bench_ratios import REGIMES

RESULTS = Path(__file__).parent / "results" / "mdr_continuum_periods.md"
TOL = 1e-7
OTHER = "rejected, events, segments"  # (a key of a point's counts beside its stages)
EXPONENTS = (1.0, 2.0, 4.0)


def _points() -> list[tuple[str, float, tuple]]:
    """``(regime, n, continuum_friction's arguments)`` of every point."""
    from vibrofriction._kernels.phases import frame_offset, inplane_forcing

    out = []
    for lab, al, be, a, V, ze, ax in REGIMES:
        hc, hs = inplane_forcing(al, 2.0 * ze * math.sqrt(al), ax, 0.0, False)
        off = frame_offset(ax, 0.0, False)
        for n in EXPONENTS:
            out.append((lab, n, (al, be, a, V, n, ze, hc, hs, off)))
    return out


def _map_tolerance() -> float:
    """The coarse maps' tolerance ``continuum_friction`` chooses at ``TOL`` (no retry)."""
    from vibrofriction.solver.mdr_continuum import first_tolerances

    return first_tolerances(TOL)[0]


def _stage_tolerances() -> tuple[tuple[str, float], ...]:
    """The maps' tolerance of each stage of the search at ``TOL`` (the rough stage counted
    with the coarse one where their tolerances are one, ``rough = coarse``)."""
    from vibrofriction._kernels import mdr_continuum as mc
    from vibrofriction.solver import mdr_continuum as smc

    rtol = _map_tolerance()
    first = (("very rough", max(rtol, mc.VROUGH)),) if hasattr(mc, "VROUGH") else ()
    rough = max(rtol, mc.ROUGH)
    middle = (("rough = coarse", rtol),) if rough == rtol else (("rough", rough),
                                                                 ("coarse", rtol))
    fine = (("fine", smc.FINE * rtol),)
    graze = getattr(smc, "FINE_GRAZE", smc.FINE)  # (the trees before the graze measures)
    if graze != smc.FINE:
        fine += (("fine, grazing", graze * rtol),)
    return first + middle + fine


def stages() -> None:
    """Print, as JSON, each point's maps and steps by stage (run under NUMBA_DISABLE_JIT)."""
    from vibrofriction._kernels import mdr_continuum as mc
    from vibrofriction.solver.mdr_continuum import continuum_friction

    period = mc.period
    log: list[tuple[float, int]] = []
    other = np.zeros(3, np.int64)  # the point's rejected steps, events and segments

    def counted(*args):  # (prm, t0, z, PC, npc, HS, nh, rtol, atol, hmax, h, K, out, cnt,
        rtol, cnt = args[7], args[13]  # ...): the trees before the graze record too
        before = cnt.copy()
        res = period(*args)
        log.append((rtol, int(cnt[0] + cnt[1] - before[0] - before[1])))
        other[:] += cnt[1:4] - before[1:4]
        return res

    mc.period = counted
    rows = []
    for _, _, args in _points():
        log.clear()
        other[:] = 0
        continuum_friction(*args, TOL)
        row = {name: [sum(1 for u, _ in log if u == t), sum(s for u, s in log if u == t)]
               for name, t in _stage_tolerances()}
        # (a retry with tighter maps, where the stated error missed TOL, would be left out)
        assert sum(m for m, _ in row.values()) == len(log), log
        row[OTHER] = [int(k) for k in other]
        rows.append(row)
    print(json.dumps(rows))


def _floor(prm: np.ndarray, rtol: float, z: np.ndarray, PC: np.ndarray, HS: np.ndarray,
           periods: int, res: np.ndarray) -> int:
    """The steps (accepted and rejected) of one coarse and one fine map from the converged
    orbit's whole section state (the body and the profile) left by ``steady``: what the
    search costs from a perfect first guess, its floor (the fine map at the tolerance the
    search chose from ``res``'s graze measures).
    """
    from vibrofriction._kernels import mdr_continuum as mc
    from vibrofriction.solver import mdr_continuum as smc

    t = math.pi + 2.0 * math.pi * periods  # (the last map's end)
    nh = int(np.nanargmax(HS[:, mc.HT])) + 1  # (the rows after it: before a compaction)
    assert abs(HS[nh - 1, mc.HT] - t) < 1e-9 * t
    a, n = prm[mc.P_A], prm[mc.P_N]
    npc = 0
    if a < 1.0:  # (a jumping indenter is in its flight at odd multiples of pi: no profile)
        rho = mc._rho(a, n, t)  # (the contact's edge: the last piece's end)
        npc = 1 + int(np.flatnonzero(np.abs(PC[:, mc.X1] - rho) <= 1e-12 * rho)[0])
    grazes = a > 1.0 or res[7] < smc.GRAZE_DEPTH or res[8] < smc.GRAZE_TIME
    steps = 0
    for tol in (rtol, (smc.FINE_GRAZE if grazes else smc.FINE) * rtol):
        cnt = np.zeros(4, np.int64)
        mc.period(prm, t, z.copy(), PC.copy(), npc, HS.copy(), nh, tol, 0.01 * tol, 0.5, 0.1,
                  np.zeros((8, mc.N_Z)), np.zeros_like(PC), cnt, np.full(6, np.nan), 2)
        steps += int(cnt[0] + cnt[1])
    return steps


def _orbit_start(args: tuple) -> tuple[float, float, float, int]:
    """The body's ``(y, y')`` on the converged orbit at ``tau = 0``, the default ``y`` and
    the search's floor (:func:`_floor`)."""
    from vibrofriction import theory
    from vibrofriction._kernels import mdr_continuum as mc
    from vibrofriction.solver import mdr_continuum as smc

    al, be, a, V, n, ze, hc, hs, off = args
    rtol = _map_tolerance()
    prm = smc._parameters(al, be, a, V, n, ze, hc, hs)
    PC = np.zeros((mc.MAX_PIECES + 1, mc.N_PC))
    HS = np.full((smc.HISTORY, mc.N_HS), np.nan)
    z = np.zeros(mc.N_Z)
    y0 = -(1.0 + a) ** (1.0 + 1.0 / n) / al
    z[0], z[1] = y0 - off[0], -off[1]
    npc, nh = mc.start(prm, z[0], z[1], PC, HS)
    y_sliding = -float(theory.profile_mean_normal_force(a, n)) / al
    fine = (smc.FINE, smc.FINE_GRAZE, smc.GRAZE_DEPTH, smc.GRAZE_TIME)
    res = np.zeros(9)
    code, periods, _ = mc.steady(prm, z, PC, npc, HS, nh, rtol, *fine, smc.DEPTH, rtol,
                                 smc.GROWTH, y_sliding, 200, np.zeros(4, np.int64), res)
    if code != 0:
        return math.nan, math.nan, y0, 0
    floor = _floor(prm, rtol, z, PC, HS, periods, res)
    # the last period runs from pi + 2 pi (periods - 1) to pi + 2 pi periods; its steps end
    # at every multiple of pi, so its history has a row at 2 pi periods
    t = 2.0 * math.pi * periods
    i = int(np.nanargmin(np.abs(HS[:, mc.HT] - t)))
    assert abs(HS[i, mc.HT] - t) < 1e-9 * t
    return HS[i, mc.HU] - V * t, HS[i, mc.HD] - V, y0, floor


def main() -> None:
    global TOL
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--write", action="store_true")
    ap.add_argument("--tol", type=float, default=TOL, help="tol_trusted (default %(default)g)")
    ap.add_argument("--stages", action="store_true", help=argparse.SUPPRESS)
    opts = ap.parse_args()
    TOL = opts.tol
    if opts.stages:
        stages()
        return
    from vibrofriction.solver.mdr_continuum import continuum_friction

    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    counted = json.loads(subprocess.run(
        [sys.executable, __file__, "--stages", "--tol", repr(TOL)], env=env, check=True,
        capture_output=True, text=True).stdout.splitlines()[-1])
    other = [st.pop(OTHER) for st in counted]
    names = list(counted[0])
    lines = ["| regime | n | " + " | ".join(f"{k}: maps, steps" for k in names)
             + " | periods | from the orbit's body state |",
             "|---|---|" + "---|" * len(names) + "---|---|"]
    total = {k: [0, 0] for k in names}
    before = after = floor = 0
    for (lab, n, args), st in zip(_points(), counted, strict=True):
        r0 = continuum_friction(*args, TOL)
        y, v, y0, f = _orbit_start(args)
        floor += f
        al, be, a, V, n_, ze, hc, hs, off = args
        r1 = continuum_friction(al, be, a, V, n_, ze, hc, hs, (y0 - y, -v), TOL)
        cells = {}
        for name, (maps, steps) in st.items():
            cells[name] = f"{maps}, {steps}" if maps else "-"
            total[name][0] += maps
            total[name][1] += steps
        before += r0["periods"]
        after += r1["periods"]
        lines.append(f"| {lab} | {n:g} | " + " | ".join(cells[k] for k in names)
                     + f" | {r0['periods']} | {r1['periods']} "
                     f"(mu {r1['mu_ratio'] - r0['mu_ratio']:+.1e} from the default's) |")
        print(lines[-1], flush=True)
    steps = sum(s for _, s in total.values())
    lines.append("")
    lines.append(
        "In all: " + "; ".join(f"{k} {m} maps, {s} steps ({100 * s / steps:.0f} %)"
                               for k, (m, s) in total.items())
        + f". Periods from the default start {before}, from the body on its orbit {after} "
        f"({100 * (before - after) / before:.0f} % fewer).")
    print(lines[-1])
    lines.append("")
    lines.append(
        f"From a perfect first guess (the converged orbit's whole section state, the body and "
        f"the profile) the search would still take one coarse and one fine map: {floor} "
        f"steps, {steps / floor:.1f} times fewer than the {steps} from the default start.")
    print(lines[-1])
    rejected, events, segments = (sum(o[i] for o in other) for i in range(3))
    from vibrofriction._kernels import mdr_continuum as mc

    # (the trees before the dense cut took the step again to the event: a step's cost)
    dense_cut = hasattr(mc, "_level_in_step")
    cut = ("were cut at an event found in them, their end read from the dense output (one "
           "evaluation of the right-hand side each, not a step)"
           if dense_cut else "more were taken again to an event found in them")
    # (a step evaluates the right-hand side six times: Dormand-Prince's first same as last)
    evals = 6 * steps + (1 if dense_cut else 6) * events
    lines.append("")
    lines.append(
        f"Of the {steps} steps, {rejected} were rejected ({100 * rejected / steps:.0f} %); "
        f"{events} {cut} ({100 * events / steps:.0f} % of the steps); {segments} segments, "
        f"{(steps - rejected) / segments:.1f} accepted steps each; {evals} evaluations of the "
        "right-hand side in all.")
    print(lines[-1])
    if opts.write:
        from sections import append_run

        flag = "" if TOL == 1e-7 else f" --tol {TOL:g}"
        append_run(RESULTS, "The row without springs: periods by stage, from a perfect start "
                   "of the body, and the floor of a perfect start",
                   f"PYTHONPATH=src python benchmarks/mdr_continuum_periods.py{flag} --write",
                   f"tol_trusted = {TOL:g}; maps and steps counted under NUMBA_DISABLE_JIT "
                   "(steps include the rejected ones).", lines)


if __name__ == "__main__":
    main()
