"""Make the 2-D (transverse) reference cache of tests/inplane/test_plane_solver.py (issue 20).

Each point of :data:`POINTS` (a transverse oscillation ``a_y > 0``: transverse only
``a = 0``, combined normal + transverse, normal + longitudinal + transverse, substrate
and holder, damped, Jenkins and Kelvin-Voigt contacts, jumping ``a > 1``, several phases,
``V < 0``; a pin that is not axisymmetric, ``alpha_y != alpha`` and ``zeta_y != zeta``, at
the points of :data:`ANISOTROPIC`) is integrated by the independent reference
``vibrofriction_reference.inplane_mean`` (solve_ivp DOP853, shares no code with the
solver) from the sliding start, with its error bars on ``mu_ratio`` and
``lateral_ratio`` (window spread plus the difference from a run at 1000 times looser
tolerances).  The solver is not run here.

Run (several minutes on one core):  python tests/data/make_plane_reference.py
Writes tests/data/plane_reference.json.
"""

from __future__ import annotations

import json
import math
import platform
import subprocess
import time
from pathlib import Path

from vibrofriction_reference import inplane_mean

HERE = Path(__file__).resolve().parent
PI = math.pi
TRANSIENT, AVERAGE = 150, 40

# (label, alpha, beta, a, V, zeta, eta_c, a_x, phase_x, a_y, phase_y, inplane_on)
POINTS = [
    ("transverse only substrate", 0.5, 2.0, 0.0, 0.3, 0.05, 0.0, 0.0, 0.0, 0.8, 0.0,
     "substrate"),
    ("transverse only holder viscous", 2.0, 8.0, 0.0, 0.4, 0.1, 0.1, 0.0, 0.0, 1.0, 0.0,
     "holder"),
    ("normal + transverse viscous", 0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.0, 0.0, 0.5, 1.0,
     "substrate"),
    ("normal + transverse Jenkins", 0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0, 0.0, 0.5, 1.0,
     "substrate"),
    ("normal + transverse Jenkins, phase + pi", 0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0, 0.0, 0.5,
     1.0 + PI, "substrate"),
    ("normal + transverse holder", 0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0, 0.0, 0.5, 2.5,
     "holder"),
    ("all three substrate", 0.5, 2.0, 0.5, 0.4, 0.05, 0.1, 0.5, PI / 2, 0.5, 0.0,
     "substrate"),
    ("all three holder", 0.5, 2.0, 0.5, 0.4, 0.05, 0.1, 0.5, PI / 2, 0.5, 3.0, "holder"),
    ("jumping viscous substrate", 0.5, 4.0, 1.5, 0.3, 0.1, 0.2, 0.0, 0.0, 0.5, 0.5,
     "substrate"),
    ("jumping viscous holder", 2.0, 10.0, 1.3, 0.5, 0.05, 0.1, 0.3, 0.7, 0.4, 2.0, "holder"),
    ("jumping Jenkins substrate", 0.5, 4.0, 1.5, 0.3, 0.1, 0.0, 0.0, 0.0, 0.5, 0.5,
     "substrate"),
    ("lightly damped stick-slip", 0.3, 3.0, 0.7, 0.2, 0.01, 0.0, 0.0, 0.0, 0.3, 4.0,
     "substrate"),
    ("stiff system", 5.0, 50.0, 0.6, 0.5, 0.05, 0.05, 0.0, 0.0, 0.6, 1.2, "substrate"),
    ("soft heavy holder", 0.05, 1.5, 0.8, 0.1, 0.1, 0.0, 0.0, 0.0, 0.3, 5.0, "holder"),
    ("over-damped pin", 0.4, 2.0, 0.6, 0.3, 1.5, 0.0, 0.3, 1.2, 0.6, 2.0, "substrate"),
    ("backward all three", 0.5, 2.0, 0.5, -0.3, 0.05, 0.1, 0.5, 1.0, 0.5, 1.0, "substrate"),
]
# the pin across the sliding its own (issue 20: k_y, c_y): the same columns, then alpha_y,
# zeta_y (the points above have None: alpha, zeta)
ANISOTROPIC = [
    ("anisotropic transverse only", 0.5, 2.0, 0.0, 0.3, 0.05, 0.0, 0.0, 0.0, 0.8, 0.0,
     "substrate", 1.5, 0.2),
    ("anisotropic soft across, Jenkins", 0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0, 0.0, 0.5, 1.0,
     "substrate", 0.2, 0.02),
    ("anisotropic all three holder", 0.5, 2.0, 0.5, 0.4, 0.05, 0.1, 0.5, PI / 2, 0.5, 3.0,
     "holder", 2.0, 0.1),
    ("anisotropic jumping viscous", 0.5, 4.0, 1.5, 0.3, 0.1, 0.2, 0.0, 0.0, 0.5, 0.5,
     "substrate", 3.0, 0.3),
    ("anisotropic resonant across", 0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.0, 0.0, 0.3, 2.0,
     "substrate", 1.0, 0.05),
    ("anisotropic backward holder", 0.5, 2.0, 0.5, -0.3, 0.05, 0.1, 0.3, 1.0, 0.4, 1.0,
     "holder", 0.8, 0.01),
]
POINTS += ANISOTROPIC
KEYS = ("label", "alpha", "beta", "amplitude", "v_inertial", "zeta", "eta_c", "a_x",
        "phase_x", "a_y", "phase_y", "inplane_on", "alpha_y", "zeta_y")


def main() -> None:
    rows = []
    for p in POINTS:
        d = dict(zip(KEYS, (*p, None, None)[:len(KEYS)], strict=True))
        t0 = time.perf_counter()
        r = inplane_mean(d["alpha"], d["beta"], d["amplitude"], d["v_inertial"], TRANSIENT,
                         AVERAGE, **{k: d[k] for k in KEYS[5:]})
        d.update(mu_ref=r.mu_ratio, err_ref=r.mu_error, lat_ref=r.lateral_ratio,
                 lat_err_ref=r.lateral_error, stick_fraction=r.stick_fraction,
                 slip_fraction=r.slip_fraction, flight_fraction=r.flight_fraction,
                 max_force_excess=r.run.max_force_excess,
                 seconds=round(time.perf_counter() - t0, 2))
        print(f"{d['label']:40s} mu {r.mu_ratio:+.10f} +- {r.mu_error:.1e}  lat "
              f"{r.lateral_ratio:+.10f} +- {r.lateral_error:.1e}  {d['seconds']} s",
              flush=True)
        rows.append(d)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=HERE).stdout.strip()
    meta = {"script": "tests/data/make_plane_reference.py", "commit": commit,
            "date": time.strftime("%Y-%m-%d"), "machine": platform.platform(),
            "transient_periods": TRANSIENT, "average_periods": AVERAGE,
            "initial": "sliding"}
    (HERE / "plane_reference.json").write_text(json.dumps({"meta": meta, "points": rows},
                                                          indent=1) + "\n")


if __name__ == "__main__":
    main()
