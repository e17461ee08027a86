"""Design the oscillation for a pin
================================

Design the oscillation for a pin: which frequency and amplitude lower friction most at
the operating speed, within the shaker's range and velocity limit, and how sensitive
the optimum is.

Run:  python examples/design_oscillation.py [output directory]
"""

# %%
# The pin
# -------
# A steel sphere of 3 mm radius on steel, loaded with 20 N: :mod:`vibrofriction.contact`
# turns the Hertz contact into the contact stiffnesses the model needs. The pin's
# natural frequency and quality factor are what a tap test gives.

from __future__ import annotations

import math
import sys
from pathlib import Path

import vibrofriction as vf
from vibrofriction.contact import Material, Sphere
from vibrofriction.figures import plot_design

OUT = Path(sys.argv[1] if len(sys.argv) > 1 else "example_output")
OUT.mkdir(parents=True, exist_ok=True)

STEEL = Material(E=210e9, nu=0.3)
PIN = vf.from_bench(natural_frequency_hz=800, mass=0.01, quality_factor=50,
                    normal_load=20.0, contact=Sphere(3e-3, STEEL, STEEL),
                    drive_frequency_hz=1000, dF_N=10.0, mu0=0.3)

# %%
# The search
# ----------
# :func:`vibrofriction.design` looks for the drive frequency and normal amplitude that
# give the lowest friction at the operating speed (5 cm/s), within the shaker's range
# (200 Hz to 5 kHz, 0.05 to 0.5 um) and a limit on the vibration's velocity amplitude
# :math:`\omega \Delta u_z` of 1 cm/s. Its report states the optimum, which constraint
# holds it there and how sensitive the friction is to each setting.

res = vf.design(PIN, v0=0.05, omega=(2 * math.pi * 200, 2 * math.pi * 5000),
                du_z=(0.05e-6, 0.5e-6), max_velocity_amplitude=0.01)
print(res.report())

# %%
# The map of the search, with the optimum and the velocity limit:

plot_design(res).savefig(OUT / "design_oscillation.png", dpi=150)
frequency_hz = res.system.omega / (2 * math.pi)
print(f"optimum: {frequency_hz:.0f} Hz, du_z = {1e6 * res.system.du_z:.3f} um, "
      f"COF {res.cof:.4f}")
