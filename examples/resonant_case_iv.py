"""Case IV: a pin driven at its resonance
======================================

Case IV: the pin driven at its own resonance (alpha = 1, rigid contact).

The critical velocity of eq. (12) is infinite there, so friction stays below mu0 at
every sliding speed and tends to a plateau. The exact plateau follows from the
energy balance of the resonant oscillation (theory.resonant_plateau_exact); the
paper's small-amplitude law 1 - a/2 is drawn for comparison.

Run:  python examples/resonant_case_iv.py [output directory]
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

import vibrofriction as vf
from vibrofriction import theory

AMPLITUDES = (0.2, 0.5, 1.0)


def main(out_dir: str | Path = "example_output") -> dict[str, float]:
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    V = np.geomspace(0.05, 40.0, 60)  # inertial velocity v0 m omega / (mu0 F_N0)
    fig = Figure(figsize=(5.0, 3.4), layout="constrained")
    ax = fig.add_subplot()
    last = {}
    for a, color in zip(AMPLITUDES, ("C0", "C1", "C2"), strict=True):
        res = vf.friction_coefficient(vf.Dimensionless(1.0, math.inf, a), v_inertial=V)
        ok = res.trusted
        ax.plot(V[ok], res.mu_ratio[ok], color=color, lw=1.2, label=f"a = {a:g}")
        ax.plot(V[~ok], res.mu_ratio[~ok], "o", mfc="none", color=color)
        plateau = float(theory.resonant_plateau_exact(a))
        ax.axhline(plateau, color=color, ls="--", lw=0.8)
        ax.axhline(1 - a / 2, color=color, ls=":", lw=0.8)
        last[a] = float(res.mu_ratio[-1])
        print(f"a = {a:g}: mu/mu0 at V = {V[-1]:g} is {res.mu_ratio[-1]:.5f}; exact plateau "
              f"{plateau:.5f}; paper's 1 - a/2 = {1 - a / 2:.3f}")
    ax.set_xscale("log")
    ax.set(xlabel=r"inertial velocity $v_0 m\omega/(\mu_0 F_{N,0})$",
           ylabel=r"$\mu_{macro}/\mu_0$", ylim=(0, 1.05),
           title="Case IV: dashed exact plateau, dotted 1 - a/2")
    ax.legend(frameon=False, loc="lower left")
    path = out / "resonant_case_iv.png"
    fig.savefig(path, dpi=150)
    print(f"wrote {path}")
    return {"mu_at_largest_V_a0.5": last[0.5]}


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "example_output")
