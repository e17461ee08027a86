"""Differential tests of the continuation: a walk in velocity against the reference.

A continuation starts each point from its neighbour's orbit, Newton's method at once and
from an orbit extrapolated along ``V`` (:func:`vibrofriction.solver.engine.solve_chain`):
another start than the independent points of ``test_differential.py``. For a seeded random
point of every regime (``tests/reference_points.py``; damped too where the regime allows),
the walk ``V/2 -> V`` in 7 steps ends at the point, and its value there must be trusted
and within its stated error plus the reference's bar of the independent fixed-step
reference (which shares no code with the solver).  The 2-D solver's chain, whose points
start from whole 2-D orbits, walks the same way to the cached points of the 2-D reference.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from reference_points import REGIMES, random_points, reference_mu
from vibrofriction.solver import SolverSettings
from vibrofriction.solver.engine import solve_chain
from vibrofriction.solver.points import point_table

SEED = 3535
CASES = [(regime, damped) for regime in REGIMES
         for damped in ((False, True) if regime in ("general", "alpha_gt_1",
                                                      "jumping_above_vstar") else (False,))]


@pytest.mark.slow
@pytest.mark.parametrize(("regime", "damped"), CASES)
def test_a_walk_up_to_a_point_agrees_with_the_reference(regime, damped):
    alpha, beta, a, V = random_points(SEED + 1, 2, regime)[1]
    zeta, eta_c = (0.03, 0.1) if damped else (0.0, 0.0)
    vs = V * np.linspace(0.5, 1.0, 7)
    points = {"alpha": np.full(7, alpha), "beta": np.full(7, beta), "amplitude": np.full(7, a),
              "v_inertial": vs, "zeta": np.full(7, zeta), "eta_c": np.full(7, eta_c)}
    walk = solve_chain(point_table(points), "sliding", SolverSettings())
    assert walk["trusted"][-1], (walk["status"][-1], walk["error"][-1])
    mu, err = float(walk["mu_ratio"][-1]), float(walk["error"][-1])
    mu_ref, err_ref = reference_mu(alpha, beta, a, V, zeta=zeta, eta_c=eta_c)
    if math.isinf(err_ref):
        pytest.skip("the reference cannot bound itself here")
    assert abs(mu - mu_ref) <= max(err, 1e-9) + err_ref, (mu, mu_ref, err, err_ref)


PLANE_POINTS = [p for p in json.loads((Path(__file__).parents[1] / "data" /
                                       "plane_reference.json").read_text())["points"]
                if p["v_inertial"] > 0.0]
#: agreement within this many times the combined bars, as tests/inplane/test_plane_solver.py
PLANE_SAFETY = 3.0


@pytest.mark.parametrize("p", PLANE_POINTS, ids=[p["label"] for p in PLANE_POINTS])
def test_a_transverse_walk_up_to_a_point_agrees_with_the_reference(p):
    """The 2-D solver's chain (each point from the whole orbit before it, Newton at once)
    at the cached points of the independent 2-D reference (``solve_ivp``, no shared code;
    tests/data/make_plane_reference.py), reached by the walk ``V/2 -> V`` in 7 steps."""
    vs = p["v_inertial"] * np.linspace(0.5, 1.0, 7)
    fixed = {k: p[k] for k in ("alpha", "beta", "amplitude", "zeta", "eta_c", "a_x",
                               "phase_x", "a_y", "phase_y", "alpha_y", "zeta_y")
             if p[k] is not None}
    points = point_table({"v_inertial": vs, "inplane_on": np.full(7, p["inplane_on"]),
                          **{k: np.full(7, float(v)) for k, v in fixed.items()}})
    walk = solve_chain(points, "sliding", SolverSettings())
    assert walk["trusted"][-1], (walk["status"][-1], walk["error"][-1])
    err = float(walk["error"][-1])
    assert abs(walk["mu_ratio"][-1] - p["mu_ref"]) <= PLANE_SAFETY * (err + p["err_ref"])
    assert abs(walk["lateral_ratio"][-1] - p["lat_ref"]) <= PLANE_SAFETY * (
        err + p["lat_err_ref"]) + 1e-12
