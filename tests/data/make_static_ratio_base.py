"""Outputs of the 1-D solver before the static coefficient (``static_ratio``) existed.

Run on the code of ``main`` *before* the kernels took ``static_ratio`` (commit 3a25862):
``PYTHONPATH=src python tests/data/make_static_ratio_base.py``.  It writes
``static_ratio_base.json``: at 40 random points of every regime (finite elastic, viscous
and rigid contact, pin damping, jumping, a longitudinal in-plane oscillation on the
substrate or the holder, the sliding and the rest start) every output column of
``solve_points`` (the batch kernel) and of ``friction_coefficient`` (the scalar fast
path), as hexadecimal floats, and a digest of the bytes of ``simulate``'s arrays at 8 of
them.  ``tests/solver/test_static_kinetic.py`` checks that ``static_ratio = 1`` gives
these bit for bit.
"""

from __future__ import annotations

import hashlib
import json
import math
from pathlib import Path

import numpy as np

import vibrofriction as vf
from vibrofriction.schema import FLOAT_COLUMNS, INT_COLUMNS
from vibrofriction.solver import solve_points

OUT = Path(__file__).with_name("static_ratio_base.json")
N_POINTS = 40
N_HISTORIES = 8
HISTORY_FIELDS = ("tau", "x", "x_dot", "f", "n", "e", "work_input", "dissipated_pin",
                  "dissipated_contact", "dissipated_friction")


def points(seed: int = 34) -> list[dict]:
    """Random points cycling through the regimes (the same list on every run)."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(N_POINTS):
        contact = ("elastic", "viscous", "rigid")[i % 3]
        alpha = float(rng.uniform(0.05, 2.5))
        beta = math.inf if contact == "rigid" else alpha + float(rng.uniform(0.4, 15.0))
        jumping = i % 4 == 1
        a = float(rng.uniform(1.05, 1.6)) if jumping else float(rng.uniform(0.0, 0.95))
        if i % 10 == 9:
            a = 0.0
        p = {"alpha": alpha, "beta": beta, "amplitude": a,
             "v_inertial": float(rng.uniform(0.02, 0.5)),
             "zeta": float(rng.uniform(0.01, 0.3)) if i % 2 == 0 else 0.0,
             "eta_c": float(rng.uniform(0.05, 0.6)) if contact == "viscous" else 0.0,
             "a_x": float(rng.uniform(0.05, 0.5)) if i % 5 == 3 else 0.0,
             "phase_x": float(rng.uniform(0.0, 2 * math.pi)),
             "inplane_on": "holder" if i % 10 == 8 else "substrate",
             "initial": "rest" if i % 3 == 1 else "sliding"}
        out.append(p)
    return out


def _hex(x: float) -> str:
    return float(x).hex()


def run_point(p: dict) -> dict:
    kw = {k: v for k, v in p.items() if k not in ("initial", "inplane_on")}
    cols = solve_points(**kw, inplane_on=p["inplane_on"], initial=p["initial"])
    # sliding_mu_ratio came later (mu_ss(V)/mu0 of the point, 1 for Coulomb): not stored
    batch = {k: _hex(cols[k]) for k in FLOAT_COLUMNS if k != "sliding_mu_ratio"}
    batch.update({k: int(cols[k]) for k in INT_COLUMNS})
    dim = vf.Dimensionless(p["alpha"], p["beta"], p["amplitude"], zeta=p["zeta"],
                           eta_c=p["eta_c"], a_x=p["a_x"], phase_x=p["phase_x"],
                           inplane_on=p["inplane_on"])
    r = vf.friction_coefficient(dim, v_inertial=p["v_inertial"], initial=p["initial"])
    fs = r.final_state
    scalar = {"mu_ratio": _hex(r.mu_ratio), "error": _hex(r.error), "status": r.status.value,
              "events": int(r.events), "periods": int(r.periods),
              "final": None if fs is None else [_hex(fs.y), _hex(fs.x_dot), _hex(fs.f),
                                                fs.phase]}
    return {"batch": batch, "scalar": scalar}


def history_digest(p: dict) -> str:
    dim = vf.Dimensionless(p["alpha"], p["beta"], p["amplitude"], zeta=p["zeta"],
                           eta_c=p["eta_c"], a_x=p["a_x"], phase_x=p["phase_x"],
                           inplane_on=p["inplane_on"])
    h = vf.simulate(dim, v_inertial=p["v_inertial"], periods=3.0, samples_per_period=64,
                    initial=p["initial"])
    d = hashlib.sha256()
    for name in HISTORY_FIELDS:
        d.update(np.ascontiguousarray(getattr(h, name), dtype=float).tobytes())
    d.update(repr([(e.tau, e.kind, e.before, e.after) for e in h.events]).encode())
    return d.hexdigest()


def main() -> None:
    pts = points()
    rows = [run_point(p) for p in pts]
    hist = [history_digest(p) for p in pts[:N_HISTORIES]]
    OUT.write_text(json.dumps({"points": pts, "results": rows, "histories": hist},
                              indent=1) + "\n")
    print(f"wrote {OUT} ({len(rows)} points, {len(hist)} histories)")


if __name__ == "__main__":
    main()
