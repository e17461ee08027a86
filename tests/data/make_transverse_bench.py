"""Make the held-out transverse bench data of tests/bench/test_fit_transverse.py with the reference.

Friction coefficients under normal + transverse oscillation (on the substrate), with a
pin that is not axisymmetric (``k_y != k_x``), from
``vibrofriction_reference.inplane.inplane_mean`` (solve_ivp DOP853, shares no code with
the solver being fitted), not from ``vibrofriction``; the SI -> dimensionless conversion
is written out here from docs/model.md and docs/inplane.md ("The pin across the
sliding"), also without the package.  Gaussian noise of standard deviation ``SIGMA``
(seeded) is added to ``mu0 * mu_ratio``; the reference's largest error bar is written to
the JSON with the truth.  Small on purpose: the 2-D reference takes seconds a point.

Run (about 1 min on one core):  python tests/data/make_transverse_bench.py
Writes tests/data/transverse_bench.csv and tests/data/transverse_bench.json.
"""

from __future__ import annotations

import math

import numpy as np
from make_inplane_bench import make
from make_reference_bench import TRUTH as PIN

#: The truth: the pin of make_reference_bench.py (800 Hz, 20 g, Q = 50, soft contact,
#: 20 N, 1 kHz), softer across the sliding (k_y = 0.6 k_x, c_y = c_x), with a 3 um
#: transverse oscillation of the substrate (a_y about 0.4).
TRUTH = {**PIN, "du_y": 3e-6, "k_y": 0.6 * PIN["k_x"], "c_y": PIN["c_x"],
         "inplane_on": "substrate"}
PHASES = (0.0, math.pi / 2)
VELOCITIES = np.array([-0.03, 0.005, 0.015, 0.03, 0.06])
SIGMA = 0.003
SEED = 21


def groups(p: dict, v0: float, phase_y: float) -> dict[str, float]:
    """The reference's arguments: ``alpha, beta`` (eq. 20), ``a = du_z/u_z0``, ``V = v0 m
    omega/(mu0 F_N0)``, ``zeta``, ``eta_c``, ``a_y = du_y m omega^2/(mu0 F_N0)``, and the
    pin across: ``alpha_y = k_y/(m omega^2)``, ``zeta_y = c_y/(2 sqrt(k_y m))``."""
    stiffness = p["mass"] * p["omega"] ** 2
    force = p["mu0"] * p["k_zc"] * p["u_z0"]
    return {"alpha": p["k_x"] / stiffness, "beta": (p["k_x"] + p["k_xc"]) / stiffness,
            "amplitude": p["du_z"] / p["u_z0"], "V": v0 * p["mass"] * p["omega"] / force,
            "zeta": p["c_x"] / (2.0 * math.sqrt(p["k_x"] * p["mass"])),
            "eta_c": p["omega"] * p["c_xc"] / p["k_xc"],
            "a_y": p["du_y"] * stiffness / force, "phase_y": phase_y,
            "alpha_y": p["k_y"] / stiffness,
            "zeta_y": p["c_y"] / (2.0 * math.sqrt(p["k_y"] * p["mass"]))}


def main() -> None:
    make("transverse_bench", TRUTH, groups, PHASES, VELOCITIES, SIGMA, SEED,
         ("du_y", "phase_y"), "transverse")


if __name__ == "__main__":
    main()
