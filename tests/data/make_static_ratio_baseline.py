"""Make the outputs of the 2-D solver and the MDR row before they took ``static_ratio``.

``tests/inplane/test_static_kinetic_plane.py`` and ``tests/mdr/test_static_kinetic_mdr.py``
check that ``static_ratio = 1`` (the default) gives these outputs bit for bit: every output
column of 20 random 2-D points (``solve_points`` with ``a_y > 0``: Kelvin-Voigt and
Jenkins contacts, jumping, in-plane oscillation along the sliding, substrate and holder,
``V < 0``), 20 random MDR rows of 20 springs (``mdr_row``), three MDR points of the solver
(``solve_points`` with a finite ``profile_exponent``) and the SHA-256 of the arrays of two
2-D and one curved history (``simulate``).

Run on the code before the change (it was: the commit ``3a25862`` of the branch's base):
    PYTHONPATH=src python tests/data/make_static_ratio_baseline.py
Writes tests/data/static_ratio_baseline.json.
"""

from __future__ import annotations

import hashlib
import json
import math
from pathlib import Path

import numpy as np

import vibrofriction as vf
from vibrofriction.solver import solve_points
from vibrofriction.solver.mdr import mdr_row

HERE = Path(__file__).resolve().parent
SEED = 34


def plane_points(rng: np.random.Generator, count: int) -> list[dict]:
    """Random valid 2-D points (``a_y > 0``)."""
    out = []
    for j in range(count):
        alpha = float(rng.uniform(0.1, 5.0))
        a = float(rng.choice([rng.uniform(0.0, 0.95), rng.uniform(1.05, 1.6)]))
        out.append(dict(
            alpha=alpha, beta=alpha * float(rng.uniform(1.5, 10.0)), amplitude=a,
            v_inertial=float(rng.choice([-1.0, 1.0]) * rng.uniform(0.05, 1.0)),
            zeta=float(rng.uniform(0.0, 0.5)),
            eta_c=0.0 if j % 2 == 0 else float(rng.uniform(0.02, 0.3)),
            a_x=float(rng.choice([0.0, rng.uniform(0.0, 1.0)])),
            phase_x=float(rng.uniform(0.0, 2 * math.pi)), a_y=float(rng.uniform(0.1, 1.5)),
            phase_y=float(rng.uniform(0.0, 2 * math.pi)),
            inplane_on=str(rng.choice(["substrate", "holder"]))))
    return out


def mdr_points(rng: np.random.Generator, count: int) -> list[dict]:
    """Random valid MDR rows (``V > 0``, no contact damping)."""
    out = []
    for _ in range(count):
        alpha = float(rng.uniform(0.1, 5.0))
        out.append(dict(
            alpha=alpha, beta=alpha * float(rng.uniform(1.5, 10.0)),
            amplitude=float(rng.uniform(0.0, 1.6)), V=float(rng.uniform(0.05, 1.0)),
            profile_exponent=float(rng.choice([math.inf, rng.uniform(0.7, 4.0)])),
            zeta=float(rng.uniform(0.0, 0.5)),
            a_x=float(rng.choice([0.0, rng.uniform(0.0, 1.0)])),
            phase_x=float(rng.uniform(0.0, 2 * math.pi)),
            inplane_on=str(rng.choice(["substrate", "holder"]))))
    return out


MDR_SOLVER = [dict(alpha=0.5, beta=2.0, amplitude=0.5, v_inertial=0.3, zeta=0.1,
                   profile_exponent=2.0),
              dict(alpha=1.0, beta=4.0, amplitude=1.3, v_inertial=-0.4, zeta=0.05,
                   profile_exponent=1.5),
              dict(alpha=0.3, beta=3.0, amplitude=0.8, v_inertial=0.2, zeta=0.2,
                   profile_exponent=3.0, a_x=0.4, phase_x=1.0)]
HISTORIES = [
    dict(system=dict(alpha=0.5, beta=2.0, amplitude=0.5, zeta=0.05, a_y=0.5, phase_y=1.0),
         v_inertial=0.3, periods=2.0, initial="sliding"),
    dict(system=dict(alpha=0.5, beta=4.0, amplitude=1.5, zeta=0.1, eta_c=0.2, a_y=0.5,
                     phase_y=0.5, a_x=0.3, inplane_on="holder"),
         v_inertial=0.3, periods=2.0, initial="steady"),
    dict(system=dict(alpha=0.5, beta=2.0, amplitude=0.7, zeta=0.1, profile_exponent=2.0),
         v_inertial=0.3, periods=2.0, initial="sliding"),
]
HISTORY_FIELDS = ("tau", "x", "x_dot", "f", "n", "e", "work_input", "dissipated_pin",
                  "dissipated_contact", "dissipated_friction", "impulse")


def digest(h: object) -> str:
    """SHA-256 of a history's arrays (:data:`HISTORY_FIELDS`)."""
    d = hashlib.sha256()
    for name in HISTORY_FIELDS:
        d.update(np.ascontiguousarray(getattr(h, name), dtype=float).tobytes())
    return d.hexdigest()


def plane_outputs(points: list[dict]) -> dict[str, list]:
    """Every output column of :func:`vf.solve_points` at the 2-D points."""
    cols = {k: np.array([p[k] for p in points]) for k in points[0] if k != "inplane_on"}
    out: dict[str, list] = {}
    for on in ("substrate", "holder"):
        idx = [i for i, p in enumerate(points) if p["inplane_on"] == on]
        r = solve_points(**{k: v[idx] for k, v in cols.items()}, inplane_on=on)
        for k, v in r.items():
            out.setdefault(k, [None] * len(points))
            for j, i in enumerate(idx):
                out[k][i] = np.asarray(v)[j].item()
    return out


def mdr_outputs(points: list[dict]) -> list[dict]:
    """``mu_ratio``, the fractions, periods, events, final state of each row of 20 springs."""
    out = []
    for p in points:
        r = mdr_row(p["alpha"], p["beta"], p["amplitude"], p["V"], p["profile_exponent"], 20,
                    p["zeta"], a_x=p["a_x"], phase_x=p["phase_x"], inplane_on=p["inplane_on"])
        y, yd, st, e = r["final_state"]
        out.append(dict(mu_ratio=r["mu_ratio"], error=r["error"], status=r["status"],
                        periods=r["periods"], events=r["events_per_period"],
                        max_excess=r["max_excess"],
                        fractions=[r["stick_area_fraction"], r["slip_area_fraction"],
                                   r["open_area_fraction"]],
                        y=y, yd=yd, st=[int(s) for s in st], e=[float(x) for x in e]))
    return out


def main() -> None:
    rng = np.random.default_rng(SEED)
    plane = plane_points(rng, 20)
    mdr = mdr_points(rng, 20)
    solver = []
    for p in MDR_SOLVER:
        r = solve_points(**p)
        solver.append({k: np.asarray(v).item() for k, v in r.items()})
    hist = []
    for h in HISTORIES:
        sim = vf.simulate(vf.Dimensionless(**h["system"]), v_inertial=h["v_inertial"],
                          periods=h["periods"], initial=h["initial"])
        hist.append(digest(sim))
    data = dict(plane_points=plane, plane_outputs=plane_outputs(plane), mdr_points=mdr,
                mdr_outputs=mdr_outputs(mdr), mdr_solver_points=MDR_SOLVER,
                mdr_solver_outputs=solver, histories=HISTORIES, history_sha256=hist)
    (HERE / "static_ratio_baseline.json").write_text(json.dumps(data, indent=1) + "\n")


if __name__ == "__main__":
    main()
