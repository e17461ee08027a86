"""Make the in-plane reference cache of tests/inplane/test_inplane_solver.py (issue 20).

Each point of :data:`POINTS` (normal + longitudinal in-plane oscillation, every regime:
substrate and holder, several phases, stick-slip, jumping, grazing, damped, a stiff
viscous contact, near the resonances ``alpha = 1`` and ``beta = 1``, pure longitudinal
``a = 0``, ``V < 0``) is integrated by the independent reference
``vibrofriction_reference.inplane_mean`` (solve_ivp, shares no code with the solver), from
the sliding start, with its error bar (window spread plus the difference from a run at
1000 times looser tolerances; where that run is on another orbit, at tighter tolerances
checked against a run at a tenth of them, see ``POINTS``).  The solver is not run here.

Run (about 3 min on one core):  python tests/data/make_inplane_reference.py
Writes tests/data/inplane_reference.json.
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

# (label, alpha, beta, a, V, zeta, eta_c, a_x, phase_x, inplane_on[, rtol])
POINTS = [
    ("issue system substrate pi/2", 0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.5, PI / 2, "substrate"),
    ("issue system holder pi/2", 0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.5, PI / 2, "holder"),
    ("general substrate 0", 0.5, 2.0, 0.5, 0.4, 0.02, 0.0, 0.4, 0.0, "substrate"),
    ("general substrate pi", 0.5, 2.0, 0.5, 0.4, 0.02, 0.0, 0.4, PI, "substrate"),
    ("general holder 3pi/2", 0.5, 2.0, 0.5, 0.4, 0.02, 0.0, 0.4, 1.5 * PI, "holder"),
    ("general holder 1.0", 0.5, 2.0, 0.5, 0.2, 0.02, 0.05, 0.7, 1.0, "holder"),
    ("stick-slip slow substrate", 0.3, 3.0, 0.4, 0.05, 0.05, 0.0, 0.3, 2.0, "substrate"),
    ("stick-slip slow holder", 0.3, 3.0, 0.4, 0.05, 0.05, 0.0, 0.3, 2.0, "holder"),
    ("jumping substrate", 0.5, 2.0, 1.5, 0.3, 0.05, 0.0, 0.5, 0.7, "substrate"),
    ("jumping holder viscous", 0.5, 2.0, 1.5, 0.3, 0.05, 0.2, 0.5, 4.0, "holder"),
    ("grazing a = 1", 0.8, 3.0, 1.0, 0.3, 0.05, 0.0, 0.3, 2.5, "substrate"),
    ("over-damped pin", 0.4, 2.0, 0.6, 0.3, 1.5, 0.0, 0.5, 1.2, "holder"),
    ("viscous contact", 2.0, 5.0, 0.8, 0.3, 0.02, 0.5, 0.4, 5.0, "substrate"),
    ("stiff viscous contact", 2.0, 200.0, 0.5, 0.3, 0.05, 0.05, 0.3, 0.3, "substrate"),
    ("alpha > 1 holder", 3.0, 6.0, 0.5, 0.2, 0.1, 0.0, 0.5, 2.2, "holder"),
    ("near alpha = 1 substrate", 0.95, 3.0, 0.5, 0.5, 0.05, 0.0, 0.3, 0.5, "substrate"),
    ("alpha = 1 holder", 1.0, 3.0, 0.5, 0.5, 0.05, 0.0, 0.3, 2.0, "holder"),
    ("near beta = 1 substrate", 0.3, 1.05, 0.5, 0.1, 0.05, 0.0, 0.3, 1.0, "substrate"),
    ("near beta = 1 holder", 0.3, 1.05, 0.5, 0.1, 0.05, 0.1, 0.5, 3.0, "holder"),
    ("soft case I substrate", 0.05, 20.0, 0.5, 0.3, 0.2, 0.0, 1.0, 0.0, "substrate"),
    ("pure longitudinal substrate", 2.0, 10.0, 0.0, 0.2, 0.2, 0.0, 0.5, 0.0, "substrate"),
    ("pure longitudinal holder", 4.0, 20.0, 0.0, 0.3, 0.2, 0.0, 0.5, 0.0, "holder"),
    ("backward substrate", 0.5, 2.0, 0.5, -0.3, 0.05, 0.1, 0.5, PI / 2, "substrate"),
    ("backward holder", 0.5, 2.0, 0.5, -0.3, 0.05, 0.1, 0.5, PI / 2, "holder"),
    ("backward jumping", 0.5, 2.0, 1.3, -0.2, 0.05, 0.0, 0.4, 2.0, "substrate"),
    ("backward stick-slip", 0.3, 3.0, 0.4, -0.05, 0.05, 0.0, 0.3, 5.0, "holder"),
    ("backward near beta = 1", 0.3, 1.05, 0.5, -0.15, 0.05, 0.0, 0.3, 1.0, "substrate"),
    ("fast sliding substrate", 0.5, 2.0, 0.5, 1.2, 0.05, 0.0, 0.5, 2.0, "substrate"),
    ("large amplitude substrate", 0.5, 4.0, 0.3, 0.3, 0.1, 0.0, 2.0, 1.0, "substrate"),
    ("large amplitude holder", 0.5, 4.0, 0.3, 0.3, 0.1, 0.0, 2.0, 1.0, "holder"),
    # micro-slips in long sticks: at rtol 1e-10 the reference lands on a spurious period-5
    # orbit (mean 0.50596, its own bar 1e-2); at 1e-12 and 1e-13 on a period-1 orbit (mean
    # 0.5031654710225, the two runs within 1e-14)
    ("stiff system II holder", 0.05, 0.1, 0.5, 0.02, 0.2, 0.0, 0.2, 0.5, "holder", 1e-12),
    ("undamped substrate", 0.5, 2.0, 0.5, 0.3, 0.0, 0.0, 0.5, 2.0, "substrate"),
]
KEYS = ("label", "alpha", "beta", "amplitude", "v_inertial", "zeta", "eta_c", "a_x",
        "phase_x", "inplane_on")


def _reference(d: dict, rtol: float | None) -> tuple:
    """``(InplaneMean, error)``: at the default tolerances with their check against a run
    at 1000 times looser ones; with ``rtol`` given, at it and checked against a run at
    ``rtol / 10`` instead (where the looser run is not on the same orbit)."""
    args = (d["alpha"], d["beta"], d["amplitude"], d["v_inertial"], TRANSIENT, AVERAGE)
    model = {k: d[k] for k in ("zeta", "eta_c", "a_x", "phase_x", "inplane_on")}
    if rtol is None:
        r = inplane_mean(*args, **model)
        return r, r.mu_error
    r = inplane_mean(*args, rtol, 1e-2 * rtol, tolerance_check=False, **model)
    tight = inplane_mean(*args, 0.1 * rtol, 1e-3 * rtol, tolerance_check=False, **model)
    return r, r.mu_error + abs(tight.mu_ratio - r.mu_ratio)


def main() -> None:
    rows = []
    for p in POINTS:
        d = dict(zip(KEYS, p[:len(KEYS)], strict=True))
        rtol = p[len(KEYS)] if len(p) > len(KEYS) else None
        t0 = time.perf_counter()
        r, err = _reference(d, rtol)
        d.update(mu_ref=r.mu_ratio, err_ref=err, rtol=rtol, stick_fraction=r.stick_fraction,
                 flight_fraction=r.flight_fraction, max_force_excess=r.run.max_force_excess,
                 seconds=round(time.perf_counter() - t0, 2))
        print(f"{d['label']:32s} mu {r.mu_ratio:+.10f} +- {err:.1e}  "
              f"stick {r.stick_fraction:.3f}  {d['seconds']} s", flush=True)
        rows.append(d)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=HERE).stdout.strip()
    meta = {"script": "tests/data/make_inplane_reference.py", "commit": commit,
            "date": time.strftime("%Y-%m-%d"), "machine": platform.platform(),
            "transient_periods": TRANSIENT, "average_periods": AVERAGE,
            "initial": "sliding"}
    (HERE / "inplane_reference.json").write_text(json.dumps({"meta": meta, "points": rows},
                                                            indent=1) + "\n")


if __name__ == "__main__":
    main()
