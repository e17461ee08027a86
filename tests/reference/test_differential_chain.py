"""Differential tests of the continuation: a walk in velocity against the reference.

A continuation starts each point from its neighbour's orbit, Newton's method at once and
from an orbit extrapolated along ``V`` (:func:`vibrofriction.solver.engine.solve_chain`):
another start than the independent points of ``test_differential.py``. For a seeded random
point of every regime (``tests/reference_points.py``; damped too where the regime allows),
the walk ``V/2 -> V`` in 7 steps ends at the point, and its value there must be trusted
and within its stated error plus the reference's bar of the independent fixed-step
reference (which shares no code with the solver).
"""

from __future__ import annotations

import math

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
