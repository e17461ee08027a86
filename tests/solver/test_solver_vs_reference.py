"""Agreement with an independent fixed-step integrator (return-mapping Jenkins element).

The reference (:mod:`vibrofriction_reference`) shares no code with the kernels: velocity
Verlet for the body, an elastic-predictor / plastic-corrector step for the contact,
Moreau time-stepping for a rigid contact.  Its error falls with the step, so agreement
is asserted at the reference's own accuracy and the error must shrink as it is refined.
"""

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction_reference import return_mapping_mu

# (alpha, beta, amplitude, vbar) spread over every regime; vbar None: case III/IV,
# then the last entry is v_inertial.
POINTS = [
    (0.5, 2.0, 0.5, 0.3), (0.5, 2.0, 0.5, 0.7), (0.5, 2.0, 0.5, 0.95),
    (0.01, 0.02, 0.5, 0.5), (0.01, 0.02, 1.0, 0.3), (0.01, 0.02, 0.2, 0.8),
    (0.01, 400.01, 0.5, 0.5), (0.01, 400.01, 1.0, 0.2),
    (0.5, 2.0, 1.0, 0.5), (0.5, 2.0, 1.5, 0.5), (0.5, 2.0, 1.5, 0.2),
    (0.01, 400.01, 1.5, 0.5),
    (2.0, 5.0, 0.8, 0.4), (4.0, 4.5, 0.5, 0.6), (0.2, 0.9, 0.7, 0.5),
    (0.3, 1.6, 0.5, 0.4), (0.05, 50.0, 0.6, 0.3),
    (0.01, math.inf, 0.5, 0.5), (0.1, math.inf, 1.5, 0.5), (3.0, math.inf, 0.7, 0.6),
    (1.0, math.inf, 0.5, None, 3.0), (1.0, math.inf, 1.5, None, 1.0),
    (1.0, 2.0, 0.5, None, 1.0), (0.3, 1.0, 0.8, None, 0.5),
]


def _velocity(p):
    s = vf.Dimensionless(*p[:3])
    return s, (float(s.vbar_to_inertial(p[3])) if p[3] is not None else p[4])


@pytest.mark.parametrize("p", POINTS, ids=lambda p: "-".join(f"{x:g}" for x in p if x is not None))
@pytest.mark.slow
def test_exact_solver_agrees_with_fixed_step_reference(p):
    s, V = _velocity(p)
    r = vf.friction_coefficient(s, v_inertial=V)
    assert r.success, r.message
    # Moreau's scheme (rigid contact) is first order: give it more steps
    steps = 6400 if s.is_rigid else 1600
    ref = return_mapping_mu(s.alpha, s.beta, s.amplitude, V, steps_per_period=steps,
                            transient_periods=300, average_periods=60)
    assert ref == pytest.approx(r.mu_ratio, abs=3e-5)


@pytest.mark.parametrize("p", [POINTS[0], POINTS[3], POINTS[9], POINTS[17]])
def test_reference_error_shrinks_towards_the_exact_value(p):
    """Convergence of the fixed-step scheme towards our value (order >= 1)."""
    s, V = _velocity(p)
    exact = vf.friction_coefficient(s, v_inertial=V).mu_ratio
    errs = [abs(return_mapping_mu(s.alpha, s.beta, s.amplitude, V, steps_per_period=n,
                                  transient_periods=300, average_periods=60) - exact)
            for n in (200, 800, 3200)]
    assert errs[2] < errs[0] / 8
    order = np.log(errs[0] / errs[2]) / np.log(16)
    assert order > 0.75
