"""Where a static coefficient above the kinetic one keeps a motion from sliding above V_c.

Continuous sliding exists for ``V > V_c`` whatever ``s_r`` (docs/friction_laws.md), and from
a state on the sliding orbit the motion slides for ever; from the named starts it may instead
settle on a stick-slip orbit.  For a few systems and ``s_r`` this scans ``V/V_c`` from 1.01 to
3 (step 0.01) and prints, for the sliding start and the rest, the smallest ``V/V_c`` from which
every point of the scan slides (``mu = 1``, no stick, no reverse slip), and the largest
``mu/mu0`` met above ``V_c`` (a stick-slip motion holding more than the kinetic force).

Run: ``.venv/bin/python benchmarks/static_kinetic_numbers.py`` (writes
benchmarks/results/static_kinetic_numbers.md).
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

import vibrofriction as vf
from vibrofriction import theory

HERE = Path(__file__).resolve().parent
FACTORS = np.round(np.arange(1.01, 3.0 + 1e-9, 0.01), 2)
SYSTEMS = [("elastic, undamped", 0.5, 2.0, 0.5, 0.0, 0.0),
           ("elastic, zeta = 0.05", 0.5, 2.0, 0.5, 0.05, 0.0),
           ("viscoelastic, eta_c = 0.2", 0.5, 2.0, 0.5, 0.0, 0.2),
           ("rigid, undamped", 0.2, math.inf, 0.7, 0.0, 0.0),
           ("rigid, zeta = 0.05", 0.5, math.inf, 0.5, 0.05, 0.0),
           ("elastic, jumping a = 1.3", 0.3, 5.0, 1.3, 0.02, 0.0)]
RATIOS = (1.1, 1.2, 1.5, 2.0)


def scan(alpha, beta, a, zeta, eta, sr, initial):
    """``(smallest V/V_c from which every point slides, largest mu above V_c, untrusted)``."""
    dim = vf.Dimensionless(alpha, beta, a, zeta=zeta, eta_c=eta, static_ratio=sr)
    vc = theory.static_kinetic_critical_velocity(alpha, beta, a, sr, zeta, eta)
    res = vf.friction_coefficient(dim, v_inertial=FACTORS * vc, initial=initial)
    slides = res.trusted & (res.mu_ratio == 1.0) & (res.stick_fraction == 0.0) \
        & (res.reverse_slip_fraction == 0.0)
    above = np.flatnonzero(~slides)
    reach = FACTORS[0] if not above.size else (
        FACTORS[above[-1] + 1] if above[-1] + 1 < FACTORS.size else math.inf)
    return reach, float(np.nanmax(res.mu_ratio)), int(np.sum(~res.trusted))


def main() -> None:
    lines = ["# Sliding above the critical velocity with a static coefficient", "",
             "Command: `.venv/bin/python benchmarks/static_kinetic_numbers.py`  ",
             f"Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}", "",
             "`V/V_c` scanned from 1.01 to 3 (step 0.01).  `reach`: the smallest `V/V_c` from "
             "which every point of the scan slides continuously from that start, trusted (`inf`: "
             "not within the scan); below it, down to `V_c`, a stick-slip motion coexists with the "
             "sliding orbit (which slides for ever from its own state).  `max mu`: the largest "
             "`mu/mu0` above `V_c` from that start.  `untrusted`: points of the scan not "
             "trusted (both starts): undamped, the motion near the neutral sliding orbit "
             "still sticks now and then after 20000 periods.", "",
             "| system | (alpha, beta, a) | s_r | reach (sliding) | max mu (sliding) | "
             "reach (rest) | max mu (rest) | untrusted |", "|---" * 8 + "|"]
    for label, alpha, beta, a, zeta, eta in SYSTEMS:
        for sr in RATIOS:
            rs = scan(alpha, beta, a, zeta, eta, sr, "sliding")
            rr = scan(alpha, beta, a, zeta, eta, sr, "rest")
            row = (f"| {label} | ({alpha:g}, {beta:g}, {a:g}) | {sr:g} | {rs[0]:g} | "
                   f"{rs[1]:.6f} | {rr[0]:g} | {rr[1]:.6f} | {rs[2] + rr[2]} |")
            print(row, flush=True)
            lines.append(row)
    (HERE / "results" / "static_kinetic_numbers.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
