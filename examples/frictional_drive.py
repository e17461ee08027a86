"""A frictional drive: in-plane and normal oscillation at a phase
================================================================

An oscillation of the disk in the sliding direction together with the normal
oscillation, shifted by a phase: depending on that phase the pair lowers friction
equally both ways, favours one direction (a ratchet), or pushes the slider (an
actuator, a frictional drive).

The pin of the in-plane pages, in the paper's parameters: alpha = 0.5, beta = 2,
a = 0.5, with pin and contact damping (zeta = 0.05, eta_c = 0.1); the substrate
oscillates in the contact plane with amplitude a_x = 1 (in units of the inertial
velocity, the vibration's velocity amplitude) at the phase phase_x ahead of the normal
oscillation.

Run:  python examples/frictional_drive.py [output directory]
"""

# %%
# The system
# ----------
# The in-plane oscillation is two more keywords of the system: its amplitude ``a_x``
# and its phase ``phase_x``. Velocities are signed now: :math:`V < 0` slides backwards,
# and :math:`\mu/\mu_0` is signed with it (negative: the friction force points
# forwards).

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure
from scipy.optimize import brentq

import vibrofriction as vf
from vibrofriction import theory

OUT = Path(sys.argv[1] if len(sys.argv) > 1 else "example_output")
OUT.mkdir(parents=True, exist_ok=True)

PIN = dict(alpha=0.5, beta=2.0, amplitude=0.5, zeta=0.05, eta_c=0.1)
A_X = 1.0


def system(phase_x: float) -> vf.Dimensionless:
    return vf.Dimensionless(**PIN, a_x=A_X, phase_x=phase_x)


# %%
# Near rest: the stuck band
# -------------------------
# With the contact stuck through the whole cycle the system is linear, and the mean
# friction force :math:`F` a stuck slider can carry lies in a band,
# ``lower`` :math:`\le F/(\mu_0 F_{N0}) \le` ``upper``
# (:func:`vibrofriction.theory.inplane_static_mu_ratio`). The band says what the drive
# does (:func:`vibrofriction.theory.inplane_regime`): it contains 0 symmetrically
# (friction reduction), asymmetrically (a ratchet), or not at all: then the oscillation
# pushes the slider (an actuator).

phases = np.linspace(0.0, 2 * math.pi, 145)
band = theory.inplane_static_mu_ratio(**PIN, a_x=A_X, phase_x=phases)
regime = theory.inplane_regime(**PIN, a_x=A_X, phase_x=phases)
names = {0: "friction reduction", 1: "ratchet", 2: "actuator", -1: "slips every cycle"}
for phi in (0.0, math.pi / 2, math.pi):
    i = int(np.argmin(abs(phases - phi)))
    print(f"phase_x = {phi:.3f}: band [{band.lower[i]:+.4f}, {band.upper[i]:+.4f}], "
          f"{names[int(regime[i])]}")

# %%
# The exact solver near rest
# --------------------------
# A slider pulled very slowly forwards (:math:`V = 10^{-4}`) settles at the band's upper
# edge, pulled backwards at its lower edge: the solver's :math:`\mu(V \to 0^\pm)` at a
# dozen phases checks the closed form.

check = np.linspace(0.0, 2 * math.pi, 12, endpoint=False)
creep = np.array([vf.friction_coefficient(system(phi), v_inertial=[-1e-4, 1e-4]).mu_ratio
                  for phi in check])
closed = theory.inplane_static_mu_ratio(**PIN, a_x=A_X, phase_x=check)
print("largest difference from the band's edges:",
      f"{np.max(abs(creep - np.column_stack([closed.lower, closed.upper]))):.1e}")

# %%
# The whole curve, and the drive's idle velocity
# ----------------------------------------------
# Over the full range of speeds the friction curve is no longer odd in :math:`V`. In the
# actuator regime (:math:`\varphi_x = 0` here) it crosses zero away from :math:`V = 0`:
# a free slider (no pulling force) moves on its own at that *idle velocity*, found here
# by a root search on the solver. Above the combined critical velocity
# (:func:`vibrofriction.theory.inplane_critical_velocity`) the contact slides all the time
# and :math:`\mu = \mu_0`.

V = np.concatenate([-np.geomspace(2.0, 1e-3, 30), np.geomspace(1e-3, 2.0, 30)])
curves = {phi: vf.friction_coefficient(system(phi), v_inertial=V)
          for phi in (0.0, math.pi / 2, math.pi)}
idle = brentq(lambda v: vf.friction_coefficient(system(0.0), v_inertial=v).mu_ratio,
              -0.5, -1e-4, xtol=1e-6)
v_c = float(theory.inplane_critical_velocity(**PIN, a_x=A_X, phase_x=0.0))
print(f"phase_x = 0: idle velocity V = {idle:.4f}; critical velocity {v_c:.4f}")

# %%
# Left: the band against the phase (shaded where it excludes 0: the actuator) with the
# solver's creeping points. Right: the curves at three phases; the idle velocity is the
# circle on the axis
# (the speed axis is logarithmic on both sides, linear within :math:`|V| < 0.01`).

fig = Figure(figsize=(8.0, 3.4), layout="constrained")
left, right = fig.subplots(1, 2)
left.fill_between(phases, band.lower, band.upper, color="C0", alpha=0.25,
                  label="stuck band (closed form)")
left.fill_between(phases, -1, 1, where=regime == 2, color="C3", alpha=0.08, lw=0,
                  label="actuator: 0 outside the band")
left.plot(check, creep[:, 1], "k^", ms=4, label=r"solver, $V = +10^{-4}$")
left.plot(check, creep[:, 0], "kv", ms=4, label=r"solver, $V = -10^{-4}$")
left.axhline(0, color="0.5", lw=0.6)
left.set(xlabel=r"phase $\varphi_x$ (rad)", ylabel=r"$\mu/\mu_0$ near rest",
         xlim=(0, 2 * math.pi), ylim=(-1, 1), title="what the drive does near rest")
left.legend(fontsize=7, loc="lower left", frameon=False)
for (phi, res), color in zip(curves.items(), ("C3", "C0", "C2"), strict=True):
    ok = res.trusted
    right.plot(V[ok], res.mu_ratio[ok], ".-", ms=3, lw=1, color=color,
               label=rf"$\varphi_x$ = {phi:.2f}")
    right.plot(V[~ok], res.mu_ratio[~ok], "o", mfc="none", color=color)  # untrusted
right.plot([idle], [0.0], "o", mfc="none", mec="C3", ms=8)
right.annotate("idle velocity", (idle, 0.0), (-1.5, 0.4), fontsize=8,
               arrowprops=dict(arrowstyle="->", lw=0.6))
right.axhline(0, color="0.5", lw=0.6)
right.set_xscale("symlog", linthresh=0.01)  # linear within |V| < 0.01, where it jumps
right.set(xlabel=r"inertial velocity $V$ (signed)", ylabel=r"$\mu/\mu_0$",
          title=rf"friction curves, $a$ = 0.5, $a_x$ = {A_X:g}")
right.legend(fontsize=7, loc="lower right", frameon=False)
fig.savefig(OUT / "frictional_drive.png", dpi=150)
print("wrote frictional_drive.png")
