"""A pin in SI units
=================

A pin on a tribometer, in SI units: the coefficient of friction against sliding speed.

The pin (modal mass 10 g on a 2.5e5 N/m holder: natural frequency 796 Hz) presses on
the disk through a contact of stiffness 4e5 N/m tangentially and 5e5 N/m normally,
with a mean indentation of 1 um (0.5 N). A shaker oscillates the indentation by
0.5 um (a = 0.5) at 600 Hz. The local coefficient of friction is 0.3.

Run:  python examples/pin_si_units.py [output directory]
"""

# %%
# The pin
# -------
# A :class:`vibrofriction.Physical` holds the bench's numbers in SI units. From them the
# package derives the paper's dimensionless parameters: :math:`\alpha` (holder stiffness
# against the drive's inertia), :math:`\beta` (holder and contact together),
# :math:`a = \Delta u_z/u_{z0}` and the case of the paper the pin falls into.

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

import vibrofriction as vf

OUT = Path(sys.argv[1] if len(sys.argv) > 1 else "example_output")  # where the figure goes
OUT.mkdir(parents=True, exist_ok=True)

PIN = vf.Physical(mass=0.01, k_x=2.5e5, k_xc=4e5, k_zc=5e5, u_z0=1e-6, du_z=5e-7,
                  omega=2 * math.pi * 600, mu0=0.3)
print(f"pin: f0 = {PIN.natural_frequency() / (2 * math.pi):.0f} Hz, drive 600 Hz, "
      f"a = {PIN.du_z / PIN.u_z0:g}, case {PIN.to_dimensionless().case.value}")

# %%
# The critical velocity
# ---------------------
# Above the critical velocity :math:`v_0^*` of eq. (12) the contact slides all the time
# and the oscillation no longer lowers the friction: the curve ends there. It sets the
# range of sliding speeds worth computing.

v_star = PIN.critical_velocity()  # eq. (12), m/s
print(f"v0* = {1e3 * v_star:.3f} mm/s")

# %%
# The friction curve
# ------------------
# :func:`vibrofriction.friction_coefficient` solves the steady state at each speed
# exactly (event to event, no time steps) and returns :math:`\mu/\mu_0` with a status and
# an error estimate per point. A point is *trusted* when its error is below the
# tolerance; every result says so, and the figure marks any other point.

v0 = np.linspace(0.0, 1.4 * v_star, 57)
res = vf.friction_coefficient(PIN, v0=v0)
cof = PIN.mu0 * res.mu_ratio

print(f"{'v0 (mm/s)':>10} {'COF':>8} {'error':>8}  status")
for i in range(0, v0.size, 8):
    r = res[i]
    print(f"{1e3 * v0[i]:10.4f} {cof[i]:8.5f} {PIN.mu0 * r.error:8.1e}  "
          f"{r.status.value}{'' if r.trusted else '  (not trusted)'}")

# %%
# At rest the friction is :math:`\mu_0 (1 - a)` (eq. 2): the pin sticks until the pulling
# force reaches the smallest friction limit of the cycle. It rises to :math:`\mu_0` at
# :math:`v_0^*`.

fig = Figure(figsize=(5.0, 3.4), layout="constrained")
ax = fig.add_subplot()
ok = res.trusted
ax.plot(1e3 * v0[ok], cof[ok], "o-", ms=3, lw=1, label="exact solver (trusted)")
if np.any(~ok):
    ax.plot(1e3 * v0[~ok], cof[~ok], "o", mfc="none", label="not trusted")
ax.axvline(1e3 * v_star, color="0.4", ls="--", lw=0.8)
ax.text(1e3 * v_star, 0.1, r" $v_0^*$ (eq. 12)", color="0.3")
ax.axhline(PIN.mu0, color="0.7", lw=0.8)
ax.set(xlabel=r"sliding velocity $v_0$ (mm/s)", ylabel="coefficient of friction",
       title="Pin at 796 Hz, normal oscillation 600 Hz, a = 0.5", ylim=(0, 0.32))
ax.legend(loc="lower left", frameon=False)
fig.savefig(OUT / "pin_si_units.png", dpi=150)
print("wrote pin_si_units.png")
