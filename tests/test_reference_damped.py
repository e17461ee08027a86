"""The damped reference integrator (peer B with dashpots, vibrofriction_reference.damped):
its own checks, and its convergence towards the exact solver as the step shrinks."""

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction_reference import return_mapping_history, return_mapping_mu


def test_zero_damping_takes_the_undamped_scheme_bit_for_bit():
    for beta in (2.0, math.inf):
        assert return_mapping_mu(0.5, beta, 0.5, 0.3, 400, 20, 10, zeta=0.0, eta_c=0.0) \
            == return_mapping_mu(0.5, beta, 0.5, 0.3, 400, 20, 10)


@pytest.mark.parametrize("name, value", [("zeta", -0.1), ("eta_c", math.nan),
                                         ("eta_c", -1.0), ("zeta", math.inf)])
def test_bad_damping_is_refused(name, value):
    with pytest.raises(ValueError, match=name):
        return_mapping_mu(0.5, 2.0, 0.5, 0.3, **{name: value})


@pytest.mark.parametrize("p, order", [((0.5, 2.0, 0.5, 0.3, 0.05, 0.0), 1.6),
                                      ((1.0, math.inf, 0.5, 3.0, 0.02, 0.0), 0.8),
                                      ((0.5, 2.0, 0.5, 0.3, 0.0, 0.2), 0.8),
                                      ((0.3, 2.0, 1.5, 0.4, 0.02, 0.3), 0.8)])
def test_reference_converges_to_the_exact_solver(p, order):
    """Errors against the exact solver at 400, 1600, 6400 steps per fastest period fall
    with an observed order of at least ``order`` (second order with the pin dashpot
    alone; first order for the return mapping of the Kelvin-Voigt contact and Moreau)."""
    al, be, a, V, zeta, eta = p
    exact = vf.friction_coefficient(vf.Dimensionless(al, be, a, zeta, eta), v_inertial=V)
    assert exact.trusted
    errors = [abs(return_mapping_mu(al, be, a, V, n, 200, 40, zeta=zeta, eta_c=eta)
                  - exact.mu_ratio) for n in (400, 1600, 6400)]
    observed = math.log(errors[0] / errors[2]) / math.log(16.0)
    assert observed >= order, errors
    assert errors[2] < 1e-4


def test_reference_history_balances_energy_with_both_dashpots():
    """Work of the pulled end = change of stored energy + dissipation, to the scheme's
    accuracy, on the reference's own history (trapezoid rule)."""
    al, be, a, V, zeta, eta = 0.5, 2.0, 0.5, 0.3, 0.05, 0.2
    h = return_mapping_history(al, be, a, V, periods=2, steps_per_period=3200, zeta=zeta,
                               eta_c=eta)
    k, c, gamma = be - al, eta * (be - al), 2 * zeta * math.sqrt(al)
    y = h.x - V * h.tau
    stored = 0.5 * h.xdot**2 + 0.5 * al * y**2 + 0.5 * k * h.e**2
    e_dot = np.gradient(h.e, h.tau)
    power_in = V * (-al * y - gamma * (h.xdot - V))
    loss = gamma * (h.xdot - V) ** 2 + c * e_dot**2 + h.f * (h.xdot - e_dot)
    balance = np.trapezoid(power_in - loss, h.tau) - (stored[-1] - stored[0])
    assert abs(balance) < 2e-3 * np.trapezoid(np.abs(power_in), h.tau)
