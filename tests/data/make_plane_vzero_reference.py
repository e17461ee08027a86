"""Make the ``v0 = 0`` 2-D reference cache of tests/inplane/test_plane_vzero.py (issue 20).

Each point of :data:`POINTS` (a transverse oscillation ``a_y > 0`` at ``V = 0``: contacts
that slip in every cycle, transverse only and combined with a longitudinal one, jumping
on the holder, a Jenkins contact; and held ones, where a stuck contact can carry a region
of mean forces) is integrated by the independent reference
``vibrofriction_reference.inplane_mean`` (solve_ivp DOP853, shares no code with the
solver) from two starts: the rest, and a body at rest held by a preload of half the
friction limit along ``x`` (spring and contact each carrying it); and two slowly sliding
points near ``V = 0`` (:data:`CREEPING`, from the sliding start, a long transient).  The
solver is not run.

Run (a few minutes on one core):  python tests/data/make_plane_vzero_reference.py
Writes tests/data/plane_vzero_reference.json.
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
PRELOAD = 0.5

# (label, alpha, beta, a, zeta, eta_c, a_x, phase_x, a_y, phase_y, inplane_on, alpha_y,
#  zeta_y)
POINTS = [
    ("slips, transverse only", 0.5, 2.0, 0.5, 0.05, 0.1, 0.0, 0.0, 2.0, PI / 2, "substrate",
     None, None),
    ("slips, all three", 0.5, 2.0, 0.5, 0.05, 0.1, 2.0, PI / 2, 1.0, 0.5, "substrate",
     None, None),
    ("slips, jumping holder", 0.5, 2.0, 2.5, 0.05, 0.1, 0.5, 2.0, 0.5, 1.0, "holder", None,
     None),
    ("slips, Jenkins", 0.5, 2.0, 0.5, 0.05, 0.0, 1.5, 1.0, 1.5, 0.5, "substrate", None,
     None),
    ("held, transverse only", 0.5, 2.0, 0.5, 0.05, 0.1, 0.0, 0.0, 0.5, PI / 2, "substrate",
     None, None),
    ("held, all three", 0.5, 2.0, 0.5, 0.05, 0.1, 0.5, PI / 2, 0.3, 0.5, "substrate", None,
     None),
    ("held, holder, anisotropic", 0.5, 2.0, 0.5, 0.05, 0.1, 1.0, 0.3, 0.3, 1.0, "holder",
     0.8, 0.1),
]
# near V = 0 (issue 20's slow points): creeping, from the sliding start, a long transient
# (the motion settles with multipliers 0.985, 0.99); the columns of POINTS, then V
CREEPING_TRANSIENT = 3000
CREEPING = [
    ("creeping, transverse bench", 0.64, 0.64 + 3e6 / (0.02 * (2 * PI * 1e3) ** 2), 0.6,
     0.01, 0.0, 0.0, 0.0, 3e-6 * 0.02 * (2 * PI * 1e3) ** 2 / 6.0, 0.0, "substrate",
     0.6 * 0.64, 0.01 / math.sqrt(0.6), -1.4e-4 * 0.02 * 2 * PI * 1e3 / 6.0),
    ("creeping, undamped (fuzz_plane)", 0.15197844544689837, 4.644902947034958,
     0.8605751934496317, 0.0, 0.0, 0.0, 0.1729660560039444, 0.038576975875694114,
     5.125650963518721, "substrate", None, None, 0.0015949771032228717),
]
KEYS = ("label", "alpha", "beta", "amplitude", "zeta", "eta_c", "a_x", "phase_x", "a_y",
        "phase_y", "inplane_on", "alpha_y", "zeta_y")


def preload_start(alpha: float, beta: float, force: float) -> tuple[float, float, float]:
    """A body at rest held by ``force`` along ``x``: ``(y_x, v_x, e_x)``."""
    return -force / alpha, 0.0, force / (beta - alpha)


def main() -> None:
    rows = []
    for p in POINTS:
        d = dict(zip(KEYS, p, strict=True))
        for name, start in (("rest", "rest"),
                            ("preload", preload_start(d["alpha"], d["beta"], PRELOAD))):
            t0 = time.perf_counter()
            r = inplane_mean(d["alpha"], d["beta"], d["amplitude"], 0.0, TRANSIENT, AVERAGE,
                             initial=start, **{k: d[k] for k in KEYS[4:]})
            d[name] = dict(mu_ref=r.mu_ratio, err_ref=r.mu_error, lat_ref=r.lateral_ratio,
                           lat_err_ref=r.lateral_error, stick_fraction=r.stick_fraction,
                           slip_fraction=r.slip_fraction,
                           flight_fraction=r.flight_fraction,
                           seconds=round(time.perf_counter() - t0, 2))
            print(f"{d['label']:28s} {name:8s} mu {r.mu_ratio:+.10f} +- {r.mu_error:.1e}  "
                  f"lat {r.lateral_ratio:+.10f} +- {r.lateral_error:.1e}  stick "
                  f"{r.stick_fraction:.6f}  {d[name]['seconds']} s", flush=True)
        rows.append(d)
    creeping = []
    for p in CREEPING:
        d = dict(zip((*KEYS, "v_inertial"), p, strict=True))
        t0 = time.perf_counter()
        # max_events_per_period: the data were made when the reference's per-period
        # counter was reset only where ``t0 % TWO_PI == 0.0`` (false from period 11 on, so
        # its default of 200 capped the whole run's events; fixed since, by the period's
        # index); kept so that the script makes the same data
        r = inplane_mean(d["alpha"], d["beta"], d["amplitude"], d["v_inertial"],
                         CREEPING_TRANSIENT, AVERAGE, max_events_per_period=10**6,
                         **{k: d[k] for k in KEYS[4:]})
        d.update(mu_ref=r.mu_ratio, err_ref=r.mu_error, lat_ref=r.lateral_ratio,
                 lat_err_ref=r.lateral_error, stick_fraction=r.stick_fraction,
                 seconds=round(time.perf_counter() - t0, 2))
        print(f"{d['label']:28s} sliding  mu {r.mu_ratio:+.10f} +- {r.mu_error:.1e}  "
              f"lat {r.lateral_ratio:+.10f} +- {r.lateral_error:.1e}  {d['seconds']} s",
              flush=True)
        creeping.append(d)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=HERE).stdout.strip()
    meta = {"script": "tests/data/make_plane_vzero_reference.py", "commit": commit,
            "date": time.strftime("%Y-%m-%d"), "machine": platform.platform(),
            "transient_periods": TRANSIENT, "average_periods": AVERAGE,
            "preload": PRELOAD, "creeping_transient_periods": CREEPING_TRANSIENT}
    (HERE / "plane_vzero_reference.json").write_text(
        json.dumps({"meta": meta, "points": rows, "creeping": creeping}, indent=1) + "\n")


if __name__ == "__main__":
    main()
