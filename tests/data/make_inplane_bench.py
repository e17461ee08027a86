"""Make the held-out in-plane bench data of tests/inplane/test_inplane_api.py with the reference.

Friction coefficients under normal + longitudinal oscillation (on the substrate) from
``vibrofriction_reference.inplane.inplane_mean`` (solve_ivp DOP853, shares no code with
the solver being fitted), not from ``vibrofriction``; the SI -> dimensionless conversion
is written out here from docs/model.md and docs/inplane.md, also without the package.
Gaussian noise of standard deviation ``SIGMA`` (seeded) is added to ``mu0 * mu_ratio``;
the reference's largest error bar is written to the JSON with the truth.

Run (about 1-2 min on one core):  python tests/data/make_inplane_bench.py
Writes tests/data/inplane_bench.csv and tests/data/inplane_bench.json.
"""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np
from make_reference_bench import OMEGA
from make_reference_bench import TRUTH as PIN

from vibrofriction_reference.inplane import inplane_mean

HERE = Path(__file__).resolve().parent
#: The truth: the pin of make_reference_bench.py (800 Hz, 20 g, Q = 50, soft contact,
#: 20 N, 1 kHz), with a 4 um longitudinal oscillation of the substrate (a_x about 0.53).
TRUTH = {**PIN, "du_x": 4e-6, "phase_x": 0.0, "inplane_on": "substrate"}
PHASES = (0.0, math.pi / 2)
VELOCITIES = np.array([-0.08, -0.05, -0.03, -0.015, -0.005, 0.005, 0.015, 0.03, 0.05, 0.08])
SIGMA = 0.003
SEED = 20


def groups(p: dict, v0: float, phase_x: float) -> dict[str, float]:
    """The reference's arguments: ``alpha, beta`` (eq. 20), ``a = du_z/u_z0``, ``V = v0 m
    omega/(mu0 F_N0)``, ``zeta``, ``eta_c``, ``a_x = du_x m omega^2/(mu0 F_N0)``."""
    stiffness = p["mass"] * p["omega"] ** 2
    force = p["mu0"] * p["k_zc"] * p["u_z0"]
    return {"alpha": p["k_x"] / stiffness, "beta": (p["k_x"] + p["k_xc"]) / stiffness,
            "amplitude": p["du_z"] / p["u_z0"], "V": v0 * p["mass"] * p["omega"] / force,
            "zeta": p["c_x"] / (2.0 * math.sqrt(p["k_x"] * p["mass"])),
            "eta_c": p["omega"] * p["c_xc"] / p["k_xc"],
            "a_x": p["du_x"] * stiffness / force, "phase_x": phase_x}


def make(stem: str, truth: dict, groups, phases, velocities: np.ndarray, sigma: float,
         seed: int, columns: tuple[str, str], what: str) -> None:
    """Write ``tests/data/<stem>.csv`` (rows ``v0, cof, du_z, omega, sigma`` and the in-plane
    ``columns``: amplitude and phase) and ``<stem>.json`` (the truth, the reference's largest
    error bar): ``mu0 * mu_ratio`` of ``inplane_mean`` at ``groups(truth, v0, phase)`` for
    every phase and velocity, plus seeded Gaussian noise of standard deviation ``sigma``."""
    t0 = time.perf_counter()
    rng = np.random.default_rng(seed)
    rows, err = [], 0.0
    for phase in phases:
        for v in velocities:
            g = groups(truth, float(v), phase)
            r = inplane_mean(g.pop("alpha"), g.pop("beta"), g.pop("amplitude"), g.pop("V"),
                             transient_periods=150, inplane_on=truth["inplane_on"], **g)
            err = max(err, r.mu_error)
            rows.append((float(v), truth["mu0"] * r.mu_ratio, phase))
            print(f"v0 {v:+.3f} {columns[1]} {phase:.3f}: cof {rows[-1][1]:+.10f} "
                  f"(+- {truth['mu0'] * r.mu_error:.1e})", flush=True)
    noise = rng.normal(0.0, sigma, len(rows))
    lines = [f"# held-out {what} bench data made by vibrofriction_reference.inplane; truth "
             f"and error bar in {stem}.json; made by tests/data/make_{stem}.py",
             "v0,cof,du_z,omega,sigma," + ",".join(columns)]
    lines += [",".join(f"{float(x):.17g}" for x in (v, cof + n, truth["du_z"], OMEGA, sigma,
                                                   truth[columns[0]], ph))
              for (v, cof, ph), n in zip(rows, noise, strict=True)]
    (HERE / f"{stem}.csv").write_text("\n".join(lines) + "\n")
    meta = {"truth": truth, "sigma": sigma, "seed": seed, "phases": list(phases),
            "velocities": velocities.tolist(), "reference": "inplane_mean (solve_ivp DOP853)",
            "reference_error_bar_cof": truth["mu0"] * err,
            "seconds": round(time.perf_counter() - t0, 1)}
    (HERE / f"{stem}.json").write_text(json.dumps(meta, indent=1) + "\n")
    print(json.dumps(meta, indent=1))


def main() -> None:
    make("inplane_bench", TRUTH, groups, PHASES, VELOCITIES, SIGMA, SEED, ("du_x", "phase_x"),
         "in-plane")


if __name__ == "__main__":
    main()
