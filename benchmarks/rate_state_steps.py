"""Where a rate-and-state point's time goes: Rosenbrock steps by phase and the cost of a step.

At the first regime of ``bench_rate_state.py`` (stick-slip-like, ``A = 0.5``): the steps of
the settling periods, of Newton's maps and the refinement together, of one plain period map
at ``rtol = 1e-7``, and the time of a plain step and of a step with the variational
equations (the minimum over 40 period maps, in this process).  Quoted in
docs/friction_laws.md, "Speed of the solver".

Run:  PYTHONPATH=src python benchmarks/rate_state_steps.py
"""

from __future__ import annotations

import time

import numpy as np

from bench_rate_state import LAW, REGIMES
from vibrofriction._kernels import rate_state as rs
from vibrofriction._kernels.phases import frame_offset
from vibrofriction.solver.points import point_table

RTOL = 1e-7


def main() -> None:
    _, system, law, V = REGIMES[0]
    p = point_table({**system, **LAW, **law, "v_inertial": V}).values[0]
    P = rs.point_parameters(p)
    start = rs.sliding_start(P, frame_offset(p[rs.T_A_X], p[rs.T_PHASE_X],
                                             p[rs.T_INPLANE_ON] == 0.0))
    work = rs._workspace()
    tw = work[6]
    log, lp = np.empty(1), np.zeros(2, np.int64)
    D, gmu, res = np.empty((4, 4)), np.empty(4), np.zeros(rs.N_RES)
    z, hbox, count = start.copy(), np.array([1e-3]), np.zeros(3, np.int64)
    for _ in range(rs.SETTLE):
        rs._map_mean(P, z, rs.LOOSE_RTOL, hbox, work, count, tw, log, lp)
    settle = int(count[0])
    count[:] = 0
    rs._newton(P, z, RTOL, np.array([hbox[0]]), work, count, tw, log, lp, D, gmu, res)
    newton = int(count[0])
    per_step = {}
    for name, tangent in (("plain", False), ("with the variational equations", True)):
        best = np.inf
        for _ in range(40):
            zz, cnt = z.copy(), np.zeros(3, np.int64)
            t0 = time.perf_counter()
            if tangent:
                rs._tangent_map(P, zz, RTOL, np.array([1e-3]), work, cnt, tw, log, lp, D, gmu)
            else:
                rs._map_mean(P, zz, RTOL, np.array([1e-3]), work, cnt, tw, log, lp)
            best = min(best, (time.perf_counter() - t0) / (cnt[0] + cnt[1]))
        per_step[name] = (best, int(cnt[0]))
    print(f"settling steps ({rs.SETTLE} periods at {rs.LOOSE_RTOL:g}): {settle}")
    print(f"Newton's maps and the refinement ({res[3]:.0f} maps, refined in Newton: "
          f"{bool(res[4])}): {newton} steps")
    for name, (best, steps) in per_step.items():
        print(f"a period map at rtol {RTOL:g}, {name}: {steps} steps, {1e6 * best:.2f} us a step")


if __name__ == "__main__":
    main()
