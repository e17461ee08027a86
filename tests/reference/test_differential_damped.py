"""The damped exact solver against the independent damped reference integrator.

24 points over every regime (contact closed, grazing, jumping; alpha = 1, beta = 1,
rigid; pin damping from 0.005 to over-damped, contact loss factors up to 1), each
compared with peer B of :mod:`vibrofriction_reference` (fixed-step, both dashpots, its
own code) through the harness of ``tests/reference_points.py``, which bounds the
reference's own error by three resolutions, the halves of the window and later windows.
"""

import math

import pytest

import vibrofriction as vf
from reference_points import reference_mu

# (alpha, beta, a, V, zeta, eta_c, regime)
POINTS = [
    (0.5, 2.0, 0.5, 0.3, 0.02, 0.0, "general, pin dashpot"),
    (0.5, 2.0, 0.5, 0.3, 0.0, 0.2, "general, viscoelastic contact"),
    (0.5, 2.0, 0.5, 0.3, 0.05, 0.5, "general, both"),
    (0.5, 2.0, 1.0, 0.2, 0.02, 0.1, "grazing a = 1"),
    (0.3, 2.0, 1.5, 0.4, 0.05, 0.0, "jumping, pin dashpot"),
    (0.3, 2.0, 1.5, 0.4, 0.02, 0.3, "jumping, both"),
    (1.0, 5.3, 0.5, 1.0, 0.02, 0.1, "case IV, finite contact"),
    (1.0, math.inf, 0.5, 3.0, 0.02, 0.0, "case IV, rigid"),
    (1.0, math.inf, 0.5, 10.0, 0.005, 0.0, "case IV, rigid, light damping"),
    (0.2, 1.0, 0.5, 0.05, 0.01, 0.1, "case III"),
    (0.2, 1.0, 1.5, 0.1, 0.02, 0.0, "case III, jumping"),
    (0.01, math.inf, 0.5, 0.3, 0.1, 0.0, "rigid contact"),
    (0.5, math.inf, 1.5, 0.5, 0.05, 0.0, "rigid, jumping"),
    (0.5, 2.0, 0.5, 0.3, 1.5, 0.0, "over-damped pin"),
    (0.5, 2.0, 0.8, 0.3, 1.0, 0.0, "critically damped pin"),
    (0.3, 4.0, 1.2, 0.5, 2.0, 1.0, "over-damped, jumping"),
    (0.01, 0.02, 0.5, 0.25, 0.05, 0.1, "stiff system II"),
    (0.01, 400.01, 1.0, 0.5, 0.01, 0.05, "soft system I"),
    (0.01, 400.01, 0.5, 0.3, 0.0, 1.0, "soft, over-damped contact"),
    (2.0, 10.0, 0.8, 0.2, 0.05, 0.2, "alpha > 1"),
    (3.0, 10.0, 0.8, 0.1, 1.2, 0.0, "alpha > 1, over-damped pin"),
    (0.2, 0.9, 0.7, 0.03, 0.02, 0.05, "near beta = 1"),
    (0.5, 3.0, 0.9, 0.3, 0.0, 1.0, "loss factor 1"),
    (2.0, math.inf, 1.2, 0.2, 0.3, 0.0, "rigid, alpha > 1, jumping"),
]


@pytest.mark.parametrize("p", POINTS, ids=[p[-1] for p in POINTS])
@pytest.mark.slow
def test_damped_solver_agrees_with_the_damped_reference(p):
    alpha, beta, a, V, zeta, eta, _ = p
    r = vf.friction_coefficient(vf.Dimensionless(alpha, beta, a, zeta, eta), v_inertial=V)
    assert r.trusted, r.message
    ref, err = reference_mu(alpha, beta, a, V, zeta=zeta, eta_c=eta)
    assert math.isfinite(err), "the reference cannot bound its own error here"
    assert abs(r.mu_ratio - ref) <= r.error + err, (r.mu_ratio, ref, err)
