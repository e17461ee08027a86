"""Make the held-out MDR bench data of tests/bench/test_fit_mdr.py with the spring-row reference.

Friction coefficients of a steel sphere on a steel flat under an imposed normal
oscillation (``contact_model="mdr"``, docs/contact_geometry.md) from
``vibrofriction_reference.mdr.mdr_reference`` (a fixed-step spring row that shares no
code with the MDR solver being fitted), not from ``vibrofriction``; the SI ->
dimensionless conversion (Hertz's sphere by the MDR, the effective moduli) is written
out here from docs/contact_geometry.md and docs/bench.md, also without the package.
Each point is the reference's finer row (200 springs, 400 steps a period) with its
error bar ``|fine - coarse|``; the largest is written to the JSON with the truth.
Gaussian noise of standard deviation ``SIGMA`` (seeded) is added to ``mu0 * mu_ratio``.

Run (about half a minute on one core):  python tests/data/make_mdr_bench.py
Writes tests/data/mdr_bench.csv and tests/data/mdr_bench.json.
"""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np

from vibrofriction_reference.mdr import mdr_reference

HERE = Path(__file__).resolve().parent
#: The truth: an 800 Hz pin of 20 g, Q = 50, with a steel sphere of radius 3 mm on a
#: steel flat (E = 210 GPa, nu = 0.3 both), 20 N at the mean indentation, 1 kHz drive.
E, NU = 210e9, 0.3
TRUTH = {"radius": 3e-3, "E": E, "nu": NU, "normal_load": 20.0, "natural_frequency_hz": 800.0,
         "mass": 0.02, "quality_factor": 50.0, "drive_frequency_hz": 1000.0, "mu0": 0.3}
AMPLITUDES = (0.6e-6, 1.2e-6)  # a = du_z/d0 = 0.34, 0.67 (linearised: 0.51, 1.01)
VELOCITIES = np.geomspace(1.5e-3, 0.12, 9)  # m/s: V = 0.031 ... 2.5
SIGMA = 0.003
SEED = 22
TRANSIENT, AVERAGE = 300, 20


def groups(p: dict, du_z: float, v0: float) -> dict[str, float]:
    """The reference's arguments.  Same material on both sides: ``1/E* = 2 (1 - nu^2)/E``,
    ``G = E/(2 (1 + nu))``, the MDR springs' ``1/G*_mdr = 2 (2 - nu)/(4 G)``; a sphere
    (``n = 2``) at the load ``F``: ``F = (4/3) E* sqrt(R) d0^(3/2)``, ``a0 = sqrt(R d0)``,
    ``k_xc0 = 2 G*_mdr a0``; ``alpha = k_x/(m omega^2)``, ``beta = (k_x + k_xc0)/(m
    omega^2)``, ``a = du_z/d0``, ``V = v0 m omega/(mu0 F)``, ``zeta = 1/(2 Q)``."""
    e_star = 1.0 / (2.0 * (1.0 - p["nu"] ** 2) / p["E"])
    g = p["E"] / (2.0 * (1.0 + p["nu"]))
    g_mdr = 1.0 / (2.0 * (2.0 - p["nu"]) / (4.0 * g))
    F, R = p["normal_load"], p["radius"]
    d0 = (3.0 * F / (4.0 * e_star * math.sqrt(R))) ** (2.0 / 3.0)
    k_xc = 2.0 * g_mdr * math.sqrt(R * d0)
    m, omega = p["mass"], 2.0 * math.pi * p["drive_frequency_hz"]
    k_x = m * (2.0 * math.pi * p["natural_frequency_hz"]) ** 2
    return {"alpha": k_x / (m * omega**2), "beta": (k_x + k_xc) / (m * omega**2),
            "amplitude": du_z / d0, "V": v0 * m * omega / (p["mu0"] * F),
            "zeta": 1.0 / (2.0 * p["quality_factor"])}


def main() -> None:
    t0 = time.perf_counter()
    rng = np.random.default_rng(SEED)
    omega = 2.0 * math.pi * TRUTH["drive_frequency_hz"]
    rows, err = [], 0.0
    for du in AMPLITUDES:
        for v in VELOCITIES:
            g = groups(TRUTH, du, float(v))
            r = mdr_reference(g["alpha"], g["beta"], g["amplitude"], g["V"], 2.0,
                              transient_periods=TRANSIENT, average_periods=AVERAGE,
                              zeta=g["zeta"])
            err = max(err, r.mu_error)
            rows.append((float(v), TRUTH["mu0"] * r.mu_ratio, du))
            print(f"du_z {du:.2e} v0 {v:.4f} (V {g['V']:.3f}, a {g['amplitude']:.3f}): "
                  f"cof {rows[-1][1]:.8f} (+- {TRUTH['mu0'] * r.mu_error:.1e})", flush=True)
    noise = rng.normal(0.0, SIGMA, len(rows))
    lines = ["# held-out MDR sphere bench data made by vibrofriction_reference.mdr; truth and "
             "error bar in mdr_bench.json; made by tests/data/make_mdr_bench.py",
             "v0,cof,du_z,omega,sigma"]
    lines += [",".join(f"{float(x):.17g}" for x in (v, cof + n, du, omega, SIGMA))
              for (v, cof, du), n in zip(rows, noise, strict=True)]
    (HERE / "mdr_bench.csv").write_text("\n".join(lines) + "\n")
    meta = {"truth": TRUTH, "sigma": SIGMA, "seed": SEED, "amplitudes": list(AMPLITUDES),
            "velocities": VELOCITIES.tolist(), "transient_periods": TRANSIENT,
            "average_periods": AVERAGE,
            "reference": "mdr_reference (spring rows (100, 200) and (200, 400))",
            "reference_error_bar_cof": TRUTH["mu0"] * err,
            "seconds": round(time.perf_counter() - t0, 1)}
    (HERE / "mdr_bench.json").write_text(json.dumps(meta, indent=1) + "\n")
    print(json.dumps(meta, indent=1))


if __name__ == "__main__":
    main()
