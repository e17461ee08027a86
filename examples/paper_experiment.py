"""The paper's experiment as a prediction
======================================

The paper's experiment (Section 7, Figs. 8-9) as a prediction, with stated assumptions.

Stated by the paper: a pin of about 800 Hz natural frequency driven at that resonance
(case IV), oscillation amplitudes 1.3, 5.4, 8.2 and 60 um. Assumed here (not stated):
modal mass 0.01 kg, mean normal force 1 N, mu0 = 0.3, mean indentation 10 um (so the
amplitudes are a = 0.13 ... 6), a quality factor Q = 50, a rigid tangential contact. The
prediction is the COF against the sliding velocity for each amplitude; with Q = 50 the
friction reduction ends at v0* = mu0 omega du_z k_zc / (omega c_x) (eq. 12 damped, rigid).

Run:  python examples/paper_experiment.py [output directory]
"""

# %%
# The bench, from what an experimenter knows
# ------------------------------------------
# :func:`vibrofriction.from_bench` builds the pin from a bench's quantities: its natural
# frequency, modal mass and quality factor, the load and the drive. The contact is
# rigid tangentially (``k_xc = inf``) and its normal stiffness turns the assumed mean
# indentation of 10 um into the load.

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

import vibrofriction as vf

OUT = Path(sys.argv[1] if len(sys.argv) > 1 else "example_output")
OUT.mkdir(parents=True, exist_ok=True)

AMPLITUDES_UM = (1.3, 5.4, 8.2, 60.0)
U_Z0 = 10e-6


def pin(du_z: float) -> vf.Physical:
    """The assumed pin, oscillated by ``du_z`` (m) at its resonance."""
    return vf.from_bench(natural_frequency_hz=800, mass=0.01, quality_factor=50,
                         normal_load=1.0, k_zc=1.0 / U_Z0, k_xc=math.inf,
                         drive_frequency_hz=800, du_z=du_z, mu0=0.3)


# %%
# The critical velocities
# -----------------------
# At resonance an undamped pin would have no critical velocity at all (case IV). With
# damping it is finite, :math:`v_0^* \propto \Delta u_z/\zeta` (eq. 12 with the pin's
# dashpot): the larger the amplitude, the further the friction reduction reaches.

for du in AMPLITUDES_UM:
    v_star = pin(du * 1e-6).critical_velocity()
    print(f"du_z = {du:4g} um (a = {du / 10:g}): v0* = {v_star:.3g} m/s")

# %%
# The prediction
# --------------
# One friction curve per amplitude, over four decades of sliding speed. Amplitudes
# above :math:`a = 1` lift the pin off the disk for part of each cycle (jumping), which
# the solver follows exactly.

v0 = np.geomspace(1e-4, 1.0, 60)
fig = Figure(figsize=(5.2, 3.4), layout="constrained")
ax = fig.add_subplot()
cof_at_1cm_s = {}
for du in AMPLITUDES_UM:
    p = pin(du * 1e-6)
    r = vf.friction_coefficient(p, v0=v0)
    ok = r.trusted
    ax.plot(v0[ok], p.mu0 * r.mu_ratio[ok], lw=1.2, label=f"{du:g} um (a = {du / 10:g})")
    ax.plot(v0[~ok], p.mu0 * r.mu_ratio[~ok], "o", mfc="none", ms=3)  # untrusted points
    cof_at_1cm_s[du] = float(p.mu0 * r.mu_ratio[np.argmin(abs(v0 - 0.01))])
    print(f"{du:4g} um: COF {cof_at_1cm_s[du]:.4f} at 1 cm/s, "
          f"{int(ok.sum())} of {ok.size} points trusted")

ax.set_xscale("log")
ax.set_xlabel("sliding velocity v0 (m/s)")
ax.set_ylabel("COF (mu0 = 0.3 assumed)")
ax.set_title("prediction for the paper's experiment (800 Hz pin at resonance, Q = 50 "
             "assumed)", fontsize=7)
ax.legend(fontsize=7)
fig.savefig(OUT / "paper_experiment.png", dpi=150)
