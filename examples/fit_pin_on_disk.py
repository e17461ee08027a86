"""Fit a pin-on-disk data set
==========================

Fit a (synthetic) pin-on-disk data set at three oscillation amplitudes.

The data are made from a known pin (800 Hz, Q = 50, a steel sphere of 3 mm on steel at
20 N, driven at 1 kHz) plus measurement noise of 0.003 in the COF; the experimenter knows
the natural frequency, Q, the load and the drive, and fits mu0, the modal mass (with
k_x tied to it by the natural frequency) and the tangential contact stiffness.

Run:  python examples/fit_pin_on_disk.py [output directory]
"""

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

STEEL = Material(E=210e9, nu=0.3)
TRUE = vf.from_bench(natural_frequency_hz=800, mass=0.01, quality_factor=50,
                              normal_load=20.0, contact=Sphere(3e-3, STEEL, STEEL),
                              drive_frequency_hz=1000, dF_N=10.0, mu0=0.3)
AMPLITUDES_UM = (0.2, 0.4, 0.8)


def measured(rng: np.random.Generator) -> pd.DataFrame:
    """The table as a bench would write it: velocities in mm/s, amplitudes in um, Hz."""
    t = synthetic_measurements(TRUE, [du * 1e-6 for du in AMPLITUDES_UM],
                               np.geomspace(1e-3, 0.3, 20), 3e-3, rng)
    return pd.DataFrame({"v0 [mm/s]": t.v0 * 1e3, "cof": t.cof,
                         "du_z [um]": (t.du_z * 1e6).round(6),
                         "omega [Hz]": (t.omega / (2 * math.pi)).round(6), "sigma": t.sigma})


def main(out_dir: str | Path = "example_output") -> dict[str, float]:
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    csv = out / "bench_measurements.csv"
    measured(np.random.default_rng(7)).to_csv(csv, index=False)
    guess = vf.from_bench(natural_frequency_hz=800, mass=0.02, quality_factor=50,
                                   normal_load=20.0, k_zc=TRUE.k_zc, k_xc=TRUE.k_xc / 3,
                                   drive_frequency_hz=1000, dF_N=10.0, mu0=0.4)
    res = vf.fit(vf.read_measurements(csv), guess, free=["mu0", "mass", "k_xc"],
                 progress=False)
    print(res.report())
    plot_fit(res).savefig(out / "fit_pin_on_disk.png", dpi=150)
    res.to_json(out / "fit_pin_on_disk.json")
    return {n: (res.params[n].value, res.params[n].stderr) for n in ("mu0", "mass", "k_xc")}


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "example_output")
