"""Make the held-out bench data set of tests/bench/test_fit.py with the independent reference.

The friction coefficients come from ``vibrofriction_reference.return_mapping_mu`` (peer
B, fixed-step, shares no code with the solver being fitted), not from
``vibrofriction``: a fit to these data tests the fit against a model it did not make.
The SI -> dimensionless conversion is written out here from the paper (eq. 20, Fig. 6,
docs/damping.md), also without the package.

Each point is computed at two resolutions (400 and 800 steps per period; 300 and 600
transient periods); the larger difference is the reference's error bar, written to the
JSON beside the table with the truth, the noise ``sigma`` and the seed.  Gaussian noise
of standard deviation ``SIGMA`` (seeded) is added to ``mu0 * mu_ratio``.

Run (about 1-2 min on one core):  python tests/data/make_reference_bench.py
Writes tests/data/reference_bench.csv and tests/data/reference_bench.json.
"""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np

from vibrofriction_reference import return_mapping_mu

HERE = Path(__file__).resolve().parent
#: The truth: an 800 Hz pin of 20 g, Q = 50, on a soft contact, 20 N, driven at 1 kHz.
OMEGA = 2.0 * math.pi * 1000.0
MASS = 0.02
K_X = MASS * (2.0 * math.pi * 800.0) ** 2
TRUTH = {"mass": MASS, "k_x": K_X, "k_xc": 3e6, "k_zc": 2e7, "u_z0": 1e-6, "du_z": 0.6e-6,
         "omega": OMEGA, "mu0": 0.3, "c_x": 2.0 * math.sqrt(K_X * MASS) / (2.0 * 50.0),
         "c_xc": 0.0}
AMPLITUDES = (0.3e-6, 0.6e-6, 1.2e-6)  # a = 0.3, 0.6, 1.2 (the last one jumps)
VELOCITIES = np.geomspace(1e-3, 0.2, 16)  # m/s
SIGMA = 0.003
SEED = 18


def groups(p: dict, du_z: float, v0: float) -> tuple[float, ...]:
    """``alpha, beta`` (eq. 20), ``a = du_z/u_z0``, ``V = v0 m omega / (mu0 F_N0)``
    (Fig. 6), ``zeta = c_x / (2 sqrt(k_x m))``, ``eta_c = omega c_xc / k_xc``."""
    stiffness = p["mass"] * p["omega"] ** 2
    V = v0 * p["mass"] * p["omega"] / (p["mu0"] * p["k_zc"] * p["u_z0"])
    return (p["k_x"] / stiffness, (p["k_x"] + p["k_xc"]) / stiffness, du_z / p["u_z0"], V,
            p["c_x"] / (2.0 * math.sqrt(p["k_x"] * p["mass"])),
            p["omega"] * p["c_xc"] / p["k_xc"])


def reference_mu(p: dict, du_z: float, v0: float,
                 transients: tuple[int, int] = (300, 600)) -> tuple[float, float]:
    """``mu_ratio`` by peer B and its error bar (two resolutions, 400 and 800 steps a period,
    after ``transients`` periods each)."""
    alpha, beta, a, V, zeta, eta_c = groups(p, du_z, v0)
    coarse, fine = (return_mapping_mu(alpha, beta, a, V, steps_per_period=n,
                                      transient_periods=t, average_periods=60, zeta=zeta,
                                      eta_c=eta_c)
                    for n, t in zip((400, 800), transients, strict=True))
    return fine, abs(fine - coarse)


def main() -> None:
    t0 = time.perf_counter()
    rng = np.random.default_rng(SEED)
    rows, err = [], 0.0
    for du in AMPLITUDES:
        for v in VELOCITIES:
            mu, e = reference_mu(TRUTH, du, float(v))
            err = max(err, e)
            rows.append((float(v), TRUTH["mu0"] * mu, du))
    noise = rng.normal(0.0, SIGMA, len(rows))
    lines = ["# held-out bench data made by vibrofriction_reference (peer B); truth and "
             "error bar in reference_bench.json; made by tests/data/make_reference_bench.py",
             "v0,cof,du_z,omega,sigma"]
    lines += [",".join(f"{float(x):.17g}" for x in (v, cof + n, du, OMEGA, SIGMA))
              for (v, cof, du), n in zip(rows, noise, strict=True)]
    (HERE / "reference_bench.csv").write_text("\n".join(lines) + "\n")
    meta = {"truth": TRUTH, "sigma": SIGMA, "seed": SEED, "amplitudes": list(AMPLITUDES),
            "velocities": VELOCITIES.tolist(), "reference": "return_mapping_mu (peer B)",
            "reference_error_bar_cof": TRUTH["mu0"] * err,
            "seconds": round(time.perf_counter() - t0, 1)}
    (HERE / "reference_bench.json").write_text(json.dumps(meta, indent=1) + "\n")
    print(f"{len(rows)} points, reference error bar {TRUTH['mu0'] * err:.2e} in the COF, "
          f"{meta['seconds']} s")


if __name__ == "__main__":
    main()
