"""Make the held-out bench data sets of tests/bench/test_fit_friction_laws.py with the reference.

The friction coefficients come from ``vibrofriction_reference.friction_laws`` (a fixed-step
scheme for the static coefficient, ``scipy.integrate.solve_ivp`` for rate-and-state friction:
no code shared with the solvers being fitted), not from ``vibrofriction``: a fit to these data
tests the fit of a friction law against a model it did not make.  The SI -> dimensionless
conversion is written out here (eq. 20, Fig. 6, docs/friction_laws.md), also without the
package.

Four tables, each with Gaussian noise of standard deviation ``sigma`` (seeded) added to
``mu0 * mu_ratio``, and a JSON beside it with the truth (the fields of ``vf.Physical``, the law
in SI units), the noise, the seed and the reference's largest error bar in the COF (its two
resolutions' difference, or the difference of the averaging window's halves where larger):

* ``static_bench``: a static coefficient 1.3 times the kinetic one, two amplitudes x 8
  velocities (the slow rows stick for part of the cycle), ``static_kinetic_run``;
* ``rate_state_bench``: rate-and-state friction (aging law, ``a = 0.006``, ``b = 0.003``,
  ``d_c = 2 um``, ``v_ref = 10 mm/s``, ``mu_star = 0.3``), two amplitudes x 6 velocities,
  ``rate_state_run``;
* ``rate_state_steady``: the same law without oscillation (``du_z = 0``), 10 velocities:
  steady sliding, ``mu_steady_state`` (what a bench measures without the shaker);
* ``rate_state_dc``: the law of ``rate_state_bench`` with the Linker-Dieterich response to the
  normal load (``alpha_ld = 0.3``), two amplitudes (0.15 and 0.25 um) x 7 velocities from
  1 mm/s to 50 mm/s, noise 0.001: the velocities span ``omega d_c = 12.6 mm/s`` (``v0/omega``
  from d_c/13 to 4 d_c), so the slow rows see a state that cannot follow the oscillating load and
  the fast rows one that relaxes over ``d_c/v0`` within the period; this determines ``d_c``
  (``d_c`` halved or doubled moves the rows above 10 mm/s by 0.5-6e-3 in the COF, the
  chi-square at the truth by +90 and +115; without the load's term, ``alpha_ld = 0``, by
  < 0.4e-3, below the noise). Rows at 0.1 m/s, and ``d_c`` below ~1 um at the fast rows, are
  where the package's solver does not trust its value: left out.

Run (about 1 min on one core):  python tests/data/make_friction_law_bench.py [name ...]
(the named tables only; all by default).
"""

from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path

import numpy as np

from vibrofriction_reference.friction_laws import (
    mu_steady_state,
    rate_state_run,
    static_kinetic_run,
)

HERE = Path(__file__).resolve().parent
#: The pin: 800 Hz, 10 g, Q = 50, 20 N on a flat contact (k_zc = 2e7, k_xc = 1.5e7 N/m),
#: driven at 1 kHz; mu0 = 0.3 (the kinetic coefficient, and mu_star of rate-and-state).
OMEGA = 2.0 * math.pi * 1000.0
MASS = 0.01
K_X = MASS * (2.0 * math.pi * 800.0) ** 2
PIN = {"mass": MASS, "k_x": K_X, "k_xc": 1.5e7, "k_zc": 2e7, "u_z0": 1e-6, "du_z": 0.5e-6,
       "omega": OMEGA, "mu0": 0.3, "c_x": 2.0 * math.sqrt(K_X * MASS) / (2.0 * 50.0)}
STATIC = {**PIN, "mu_static": 0.39}
LAW = {"a": 0.006, "b": 0.003, "d_c": 2e-6, "v_ref": 1e-2, "alpha_ld": 0.0, "law": "aging"}
LAW_LD = {**LAW, "alpha_ld": 0.3}


def groups(p: dict, du_z: float, v0: float) -> tuple[float, ...]:
    """``alpha, beta`` (eq. 20), ``A = du_z/u_z0``, ``V = v0 m omega/(mu0 F_N0)`` (Fig. 6),
    ``zeta = c_x/(2 sqrt(k_x m))``."""
    stiffness = p["mass"] * p["omega"] ** 2
    V = v0 * p["mass"] * p["omega"] / (p["mu0"] * p["k_zc"] * p["u_z0"])
    return (p["k_x"] / stiffness, (p["k_x"] + p["k_xc"]) / stiffness, du_z / p["u_z0"], V,
            p["c_x"] / (2.0 * math.sqrt(p["k_x"] * p["mass"])))


def scaled_law(p: dict, law: dict) -> tuple[float, float, float, float, float]:
    """``a, b`` over ``mu_star``, ``d_c`` over ``mu_star F_N0/(m omega^2)``, ``v_ref`` over
    ``mu_star F_N0/(m omega)``, ``alpha_ld`` over ``mu_star`` (docs/friction_laws.md)."""
    length = p["mu0"] * p["k_zc"] * p["u_z0"] / (p["mass"] * p["omega"] ** 2)
    return (law["a"] / p["mu0"], law["b"] / p["mu0"], law["d_c"] / length,
            law["v_ref"] / (length * p["omega"]), law["alpha_ld"] / p["mu0"])


def settled(period_f: np.ndarray, period_n: np.ndarray) -> float:
    """``|<f>/<n>|`` of the averaging window's first half less its second's: what the transient
    left (the window is even: a period-2 orbit's halves are equal)."""
    h = len(period_f) // 2
    return abs(period_f[:h].sum() / period_n[:h].sum()
               - period_f[h:2 * h].sum() / period_n[h:2 * h].sum())


def static_table() -> tuple[list[tuple[float, float, float]], float]:
    rows, err = [], 0.0
    for du in (0.3e-6, 0.6e-6):
        for v in np.geomspace(1e-3, 0.2, 8):
            alpha, beta, A, V, zeta = groups(STATIC, du, float(v))
            r = static_kinetic_run(alpha, beta, A, V, STATIC["mu_static"] / STATIC["mu0"],
                                   zeta=zeta, steps_per_period=400, transient_periods=300,
                                   average_periods=60)
            err = max(err, r.error, settled(r.period_f, r.period_n))
            rows.append((float(v), STATIC["mu0"] * r.mu_ratio, du))
    return rows, STATIC["mu0"] * err


def _rate_state_rows(law: dict, amplitudes: tuple[float, ...], velocities: np.ndarray
                     ) -> tuple[list[tuple[float, float, float]], float]:
    rows, err = [], 0.0
    a, b, d_c, v_ref, alpha_ld = scaled_law(PIN, law)
    for du in amplitudes:
        for v in velocities:
            alpha, beta, A, V, zeta = groups(PIN, du, float(v))
            r = rate_state_run(alpha, beta, A, V, a, b, d_c, v_ref, alpha_ld=alpha_ld,
                               law=law["law"], zeta=zeta, transient_periods=60,
                               average_periods=20)
            err = max(err, r.error, settled(r.period_f, r.period_n))
            rows.append((float(v), PIN["mu0"] * r.mu_ratio, du))
    return rows, PIN["mu0"] * err


def rate_state_table() -> tuple[list[tuple[float, float, float]], float]:
    return _rate_state_rows(LAW, (0.25e-6, 0.5e-6), np.geomspace(2e-3, 0.2, 6))


def d_c_table() -> tuple[list[tuple[float, float, float]], float]:
    return _rate_state_rows(LAW_LD, (0.15e-6, 0.25e-6), np.geomspace(1e-3, 0.05, 7))


def steady_table() -> tuple[list[tuple[float, float, float]], float]:
    a, b, _, v_ref, _ = scaled_law(PIN, LAW)
    rows = []
    for v in np.geomspace(1e-3, 0.3, 10):
        V = groups(PIN, 0.0, float(v))[3]
        rows.append((float(v), PIN["mu0"] * mu_steady_state(V, a, b, v_ref), 0.0))
    return rows, 0.0


def write(name: str, rows, sigma: float, seed: int, truth: dict, reference: str,
          err: float, seconds: float) -> None:
    noise = np.random.default_rng(seed).normal(0.0, sigma, len(rows))
    lines = [f"# held-out bench data made by vibrofriction_reference ({reference}); truth in "
             f"{name}.json; made by tests/data/make_friction_law_bench.py",
             "v0,cof,du_z,omega,sigma"]
    lines += [",".join(f"{float(x):.17g}" for x in (v, cof + n, du, OMEGA, sigma))
              for (v, cof, du), n in zip(rows, noise, strict=True)]
    (HERE / f"{name}.csv").write_text("\n".join(lines) + "\n")
    meta = {"truth": truth, "sigma": sigma, "seed": seed, "reference": reference,
            "reference_error_bar_cof": err, "seconds": round(seconds, 1)}
    (HERE / f"{name}.json").write_text(json.dumps(meta, indent=1) + "\n")
    print(f"{name}: {len(rows)} points, reference error bar {err:.2e} in the COF, "
          f"{seconds:.1f} s")


def main() -> None:
    for name, make, sigma, seed, truth, reference in (
            ("static_bench", static_table, 0.003, 34, STATIC, "static_kinetic_run"),
            ("rate_state_bench", rate_state_table, 0.001, 35, {**PIN, "friction": LAW},
             "rate_state_run"),
            ("rate_state_steady", steady_table, 0.002, 36, {**PIN, "friction": LAW},
             "mu_steady_state"),
            ("rate_state_dc", d_c_table, 0.001, 37, {**PIN, "friction": LAW_LD},
             "rate_state_run")):
        if len(sys.argv) > 1 and name not in sys.argv[1:]:
            continue
        t0 = time.perf_counter()
        rows, err = make()
        write(name, rows, sigma, seed, truth, reference, err, time.perf_counter() - t0)


if __name__ == "__main__":
    main()
