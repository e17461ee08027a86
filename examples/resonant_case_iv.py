"""Case IV: a pin driven at its resonance
======================================

Case IV: the pin driven at its own resonance (alpha = 1, rigid contact).

The critical velocity of eq. (12) is infinite there, so friction stays below mu0 at
every sliding speed and tends to a plateau. The exact plateau follows from the
energy balance of the resonant oscillation (theory.resonant_plateau_exact); the
paper's small-amplitude law 1 - a/2 is drawn for comparison.

Run:  python examples/resonant_case_iv.py [output directory]
"""

# %%
# The system, in the paper's parameters
# -------------------------------------
# :class:`vibrofriction.Dimensionless` takes :math:`(\alpha, \beta, a)` directly:
# :math:`\alpha = 1` puts the drive on the pin's resonance, :math:`\beta = \infty` makes
# the contact rigid. With :math:`v_0^*` infinite, :math:`\bar v = v_0/v_0^*` is no scale;
# the sliding speed is given as the inertial velocity
# :math:`V = v_0 m \omega/(\mu_0 F_{N0})` instead.

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

import vibrofriction as vf
from vibrofriction import theory

OUT = Path(sys.argv[1] if len(sys.argv) > 1 else "example_output")
OUT.mkdir(parents=True, exist_ok=True)

AMPLITUDES = (0.2, 0.5, 1.0)
V = np.geomspace(0.05, 40.0, 60)  # inertial velocity v0 m omega / (mu0 F_N0)

# %%
# Friction against speed, and the plateau it tends to
# ---------------------------------------------------
# For each amplitude the exact solver gives the curve; the closed forms give two
# plateaus: the exact one (:func:`vibrofriction.theory.resonant_plateau_exact`, from the
# energy balance of the resonant oscillation) and the paper's :math:`1 - a/2`. At the
# largest speed the curve should sit on the exact plateau.

fig = Figure(figsize=(5.0, 3.4), layout="constrained")
ax = fig.add_subplot()
mu_at_largest_V = {}
for a, color in zip(AMPLITUDES, ("C0", "C1", "C2"), strict=True):
    res = vf.friction_coefficient(vf.Dimensionless(1.0, math.inf, a), v_inertial=V)
    ok = res.trusted
    ax.plot(V[ok], res.mu_ratio[ok], color=color, lw=1.2, label=f"a = {a:g}")
    ax.plot(V[~ok], res.mu_ratio[~ok], "o", mfc="none", color=color)  # untrusted
    plateau = float(theory.resonant_plateau_exact(a))
    ax.axhline(plateau, color=color, ls="--", lw=0.8)
    ax.axhline(1 - a / 2, color=color, ls=":", lw=0.8)
    mu_at_largest_V[a] = float(res.mu_ratio[-1])
    print(f"a = {a:g}: mu/mu0 at V = {V[-1]:g} is {res.mu_ratio[-1]:.5f}; exact plateau "
          f"{plateau:.5f}; paper's 1 - a/2 = {1 - a / 2:.3f}")

# %%
# The paper's :math:`1 - a/2` is a small-amplitude law: it drifts from the exact plateau
# as :math:`a` grows.

ax.set_xscale("log")
ax.set(xlabel=r"inertial velocity $v_0 m\omega/(\mu_0 F_{N,0})$",
       ylabel=r"$\mu_{macro}/\mu_0$", ylim=(0, 1.05),
       title="Case IV: dashed exact plateau, dotted 1 - a/2")
ax.legend(frameon=False, loc="lower left")
fig.savefig(OUT / "resonant_case_iv.png", dpi=150)
print("wrote resonant_case_iv.png")
