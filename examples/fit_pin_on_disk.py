"""Fit a pin-on-disk data set
==========================

Fit a (synthetic) pin-on-disk data set at three oscillation amplitudes.

The data are made from a known pin (800 Hz, Q = 50, a steel sphere of 3 mm on steel at
20 N, driven at 1 kHz) plus measurement noise of 0.003 in the COF; the experimenter knows
the natural frequency, Q, the load and the drive, and fits mu0, the modal mass (with
k_x tied to it by the natural frequency) and the tangential contact stiffness.

Run:  python examples/fit_pin_on_disk.py [output directory]
"""

# %%
# The pin behind the data
# -----------------------
# A known pin makes the data, so the fit can be judged: the values it finds should be
# within a few standard errors of these.

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pandas as pd

import vibrofriction as vf
from vibrofriction.bench import synthetic_measurements
from vibrofriction.contact import Material, Sphere
from vibrofriction.figures import plot_fit

OUT = Path(sys.argv[1] if len(sys.argv) > 1 else "example_output")
OUT.mkdir(parents=True, exist_ok=True)

STEEL = Material(E=210e9, nu=0.3)
TRUE = vf.from_bench(natural_frequency_hz=800, mass=0.01, quality_factor=50,
                     normal_load=20.0, contact=Sphere(3e-3, STEEL, STEEL),
                     drive_frequency_hz=1000, dF_N=10.0, mu0=0.3)
AMPLITUDES_UM = (0.2, 0.4, 0.8)

# %%
# A bench's table
# ---------------
# 20 sliding speeds at each of three amplitudes, with noise of 0.003 in the COF, written
# as a bench would write it: velocities in mm/s, amplitudes in um, frequencies in Hz,
# the units in the column names. :func:`vibrofriction.read_measurements` reads such a
# file and converts the units.

t = synthetic_measurements(TRUE, [du * 1e-6 for du in AMPLITUDES_UM],
                           np.geomspace(1e-3, 0.3, 20), 3e-3, np.random.default_rng(7))
table = pd.DataFrame({"v0 [mm/s]": t.v0 * 1e3, "cof": t.cof,
                      "du_z [um]": (t.du_z * 1e6).round(6),
                      "omega [Hz]": (t.omega / (2 * math.pi)).round(6), "sigma": t.sigma})
csv = OUT / "bench_measurements.csv"
table.to_csv(csv, index=False)
print(table.head())

# %%
# The fit
# -------
# The first guess is off by a factor 2 in the mass, 3 in the contact stiffness and
# 0.1 in :math:`\mu_0`. :func:`vibrofriction.fit` varies the three free parameters
# (the others stay as the bench gives them) and reports the values with their standard
# errors and a verdict on the fit's quality.

guess = vf.from_bench(natural_frequency_hz=800, mass=0.02, quality_factor=50,
                      normal_load=20.0, k_zc=TRUE.k_zc, k_xc=TRUE.k_xc / 3,
                      drive_frequency_hz=1000, dF_N=10.0, mu0=0.4)
res = vf.fit(vf.read_measurements(csv), guess, free=["mu0", "mass", "k_xc"],
             progress=False)
print(res.report())

# %%
# The data with the fitted curves, and the result saved as JSON for later:

plot_fit(res).savefig(OUT / "fit_pin_on_disk.png", dpi=150)
res.to_json(OUT / "fit_pin_on_disk.json")
fitted = {n: (res.params[n].value, res.params[n].stderr) for n in ("mu0", "mass", "k_xc")}
for name, (value, stderr) in fitted.items():
    print(f"{name}: {value:.4g} +- {stderr:.2g} (true {getattr(TRUE, name):.4g})")
