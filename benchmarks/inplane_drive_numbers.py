"""Issue 20's drive numbers for the system (alpha, beta, a) = (0.5, 2, 0.5) with a
substrate oscillation a_x = du_x m omega^2/(mu0 F_N0) = 0.5 at phase_x = pi/2: the mean
force mu_ratio = <F_x>/(mu0 <F_N>) against the signed velocity V (the exact solver, V < 0
by the mirror), its limits V -> 0+ and 0- (the blocking force) beside the static band of
the stuck contact (theory.inplane_static_mu_ratio), the idle velocity (where the mean
force changes sign, if anywhere but V = 0) and the critical velocity of continuous
sliding (theory.inplane_critical_velocity); undamped and with zeta = 0.05, eta_c = 0.1.
At V = 0 itself (docs/inplane.md, "v0 = 0"): the mean force from rest and from preloads
(a body at rest, spring and contact carrying F), with its status (held or not), against
a_x with the damping, beside the stuck band.

Run:  python benchmarks/inplane_drive_numbers.py   (about 10 s; writes
benchmarks/results/inplane_drive.md; with ``--print`` it prints the same text and writes
nothing: tests/docs/test_quoted_numbers.py compares it with the committed file)
"""

from __future__ import annotations

import datetime
import math
import platform
import subprocess
import sys
from pathlib import Path

import numpy as np

from vibrofriction import Dimensionless, friction_coefficient, theory
from vibrofriction.solver import SectionState, solve_points

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
    lines += zero_velocity()
    text = "\n".join(lines)
    if "--print" not in sys.argv[1:]:
        (HERE / "results" / "inplane_drive.md").write_text(text)
    print(text)


PRELOADS = (0.0, 0.25, 0.5, 0.9, -0.25)
ZERO_AX = (0.25, 0.5, 1.0, 1.25, 1.5, 2.0, 3.0)


def _at_rest(dim: Dimensionless, force: float) -> SectionState:
    """A body at rest held by the preload ``force`` (spring and contact carry it)."""
    k = dim.beta - dim.alpha
    return SectionState(-force / dim.alpha, 0.0, force, "stick", force / k)


def zero_velocity() -> list[str]:
    """V = 0: the mean force from rest and from preloads, held or not, against a_x."""
    zeta, eta_c = DAMPING[1]
    lines = [f"## V = 0, zeta = {zeta}, eta_c = {eta_c}", "",
             "Mean force at V = 0 from a body at rest held by the preload F (F = 0: the "
             "rest, also what \"sliding\" means at V = 0), its status and stick fraction; "
             "the stuck band of theory.inplane_static_mu_ratio (nan: none, the contact "
             "slips in every cycle).", "",
             "| a_x | band upper / lower | " + " | ".join(f"F = {f:+g}" for f in PRELOADS)
             + " |", "|---|---|" + "---|" * len(PRELOADS)]
    for a_x in ZERO_AX:
        dim = Dimensionless(*SYSTEM, zeta, eta_c, a_x, PHASE_X)
        band = theory.inplane_static_mu_ratio(*SYSTEM, a_x, PHASE_X, zeta=zeta, eta_c=eta_c)
        cells = []
        for force in PRELOADS:
            r = friction_coefficient(dim, v_inertial=0.0, initial=_at_rest(dim, force))
            cells.append(f"{r.mu_ratio:+.6f} {r.status.value} ({r.error:.0e}, stick "
                         f"{r.stick_fraction:.3f})")
        lines.append(f"| {a_x:g} | {band.upper:+.4f} / {band.lower:+.4f} | "
                     + " | ".join(cells) + " |")
    lines.append("")
    return lines


if __name__ == "__main__":
    main()
