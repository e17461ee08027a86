"""Issue 20's drive numbers for the system (alpha, beta, a) = (0.5, 2, 0.5) with a
substrate oscillation a_x = du_x m omega^2/(mu0 F_N0) = 0.5 at phase_x = pi/2: the mean
force mu_ratio = <F_x>/(mu0 <F_N>) against the signed velocity V (the exact solver, V < 0
by the mirror), its limits V -> 0+ and 0- (the blocking force) beside the static band of
the stuck contact (theory.inplane_static_mu_ratio), the idle velocity (where the mean
force changes sign, if anywhere but V = 0) and the critical velocity of continuous
sliding (theory.inplane_critical_velocity); undamped and with zeta = 0.05, eta_c = 0.1.

Run:  python benchmarks/inplane_drive_numbers.py   (about 10 s; writes
benchmarks/results/inplane_drive.md)
"""

from __future__ import annotations

import datetime
import math
import platform
import subprocess
from pathlib import Path

import numpy as np

from vibrofriction import theory
from vibrofriction.solver import solve_points

HERE = Path(__file__).resolve().parent
SYSTEM = (0.5, 2.0, 0.5)
A_X, PHASE_X = 0.5, math.pi / 2
DAMPING = ((0.0, 0.0), (0.05, 0.1))
NO_IDLE = "none (the mean force changes sign only at V = 0: no drive)"
SPEEDS = (1e-5, 1e-4, 1e-3, 1e-2, 0.05, 0.1, 0.3, 0.6, 0.8)


def main() -> None:
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=HERE).stdout.strip()
    lines = ["# The drive of (alpha, beta, a) = (0.5, 2, 0.5), a_x = 0.5 at phase_x = pi/2 "
             "(benchmarks/inplane_drive_numbers.py)", "",
             f"{datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC, commit {commit}, "
             f"{platform.machine()}; substrate oscillation; exact solver, default settings.", ""]
    for zeta, eta_c in DAMPING:
        band = theory.inplane_static_mu_ratio(*SYSTEM, A_X, PHASE_X, zeta=zeta, eta_c=eta_c)
        vc_up = theory.inplane_critical_velocity(*SYSTEM, A_X, PHASE_X, zeta=zeta, eta_c=eta_c)
        vc_down = theory.inplane_critical_velocity(*SYSTEM, A_X, PHASE_X + math.pi,
                                                   zeta=zeta, eta_c=eta_c)
        V = np.array([-v for v in SPEEDS[::-1]] + list(SPEEDS))
        out = solve_points(*SYSTEM, V, zeta, eta_c, A_X, PHASE_X)
        mu, err, trusted = out["mu_ratio"], out["error"], out["trusted"]
        sign = np.sign(mu)
        idle = [f"{V[i]:.3g}..{V[i + 1]:.3g}" for i in range(len(V) - 1)
                if sign[i] != sign[i + 1] and not (V[i] < 0 < V[i + 1])]
        lines += [f"## zeta = {zeta}, eta_c = {eta_c}", "",
                  f"* blocking force (the limits V -> 0+ and 0-): {mu[len(SPEEDS)]:+.6f} and "
                  f"{mu[len(SPEEDS) - 1]:+.6f} at V = +-{SPEEDS[0]:g}; the static band of the "
                  f"stuck contact {band.upper:+.6f} / {band.lower:+.6f}",
                  "* idle velocity: " + (", ".join(idle) if idle else NO_IDLE),
                  f"* critical velocity of continuous sliding: {vc_up:.6f} forward, "
                  f"{vc_down:.6f} backward", "",
                  "| V | mu_ratio | error | trusted |", "|---|---|---|---|"]
        lines += [f"| {v:+.3g} | {m:+.10f} | {e:.1e} | {bool(t)} |"
                  for v, m, e, t in zip(V, mu, err, trusted, strict=True)]
        lines.append("")
    text = "\n".join(lines)
    (HERE / "results" / "inplane_drive.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
