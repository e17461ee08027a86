"""The rate-and-state solver with contact damping (``eta_c > 0``: a dashpot ``c = eta_c k``
in parallel with the contact spring, ``f = k e + c (x' - w') = n mu(w', theta)``).

Checked against what does not come from the damped mode: the undamped solver as
``eta_c -> 0`` (another mode of the kernel), the energy balance of a history (the
dissipations by their own definitions), the scalar equation the start's and the
touch-down's ``m`` solve, and the continuity of the elongation through lift-off and
touch-down.  The Jacobian of the period map against central differences is in
tests/solver/test_rate_state_multiplier.py, the agreement with the independent reference in
tests/reference/test_differential_rate_state.py.
"""

from __future__ import annotations

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction._kernels import rate_state as rs
from vibrofriction.schema import Status

POINTS = [dict(alpha=0.5, beta=2.0, amplitude=0.5, rs_a=0.02, rs_b=0.01, rs_d_c=0.02,
               rs_v_ref=1.0),
          dict(alpha=0.5, beta=2.0, amplitude=1.3, zeta=0.1, rs_a=0.02, rs_b=0.01,
               rs_d_c=0.02, rs_v_ref=1.0, rs_law="slip")]  # jumping


@pytest.mark.parametrize("point", POINTS, ids=["contact", "jumping"])
def test_damped_tends_to_the_undamped_solver(point: dict) -> None:
    """``eta_c -> 0``: the damped answers tend to the undamped solver's at first order
    (measured, rtol 1e-9: ``(mu - mu_0)/eta_c`` = 1.3615, 1.3797, 1.3814 at ``eta_c`` =
    1e-2, 1e-3, 1e-4; jumping 0.8193, 0.8308, 0.8320)."""
    settings = vf.SolverSettings(rtol=1e-9)

    def mu(eta_c: float) -> float:
        r = vf.friction_coefficient(vf.Dimensionless(eta_c=eta_c, **point), v_inertial=0.5,
                                    settings=settings)
        assert r.status is Status.PERIODIC
        return r.mu_ratio

    undamped = mu(0.0)
    slopes = [(mu(eta) - undamped) / eta for eta in (1e-3, 1e-4)]
    assert slopes[0] > 0.1
    assert slopes[1] == pytest.approx(slopes[0], rel=0.02)


@pytest.mark.parametrize("point", POINTS, ids=["contact", "jumping"])
def test_damped_history_energy_balance(point: dict) -> None:
    """A damped history from the start: the pulled end's work equals the change of the
    energy (kinetic, the pin's and the contact's springs, ``k e^2/2``) plus the pin's,
    the contact dashpot's and the friction's dissipations, to the trapezoidal rule's error;
    the elongation is continuous through each lift-off and touch-down (two rows at one
    time), and relaxes in flight."""
    s = vf.Dimensionless(eta_c=0.2, **point)
    h = vf.simulate(s, v_inertial=0.5, periods=2, samples_per_period=2000)
    k = s.beta - s.alpha
    y = h.x - 0.5 * h.tau
    energy = 0.5 * h.x_dot**2 + 0.5 * s.alpha * y**2 + 0.5 * k * h.e**2
    balance = (h.work_input - (energy - energy[0]) - h.dissipated_pin - h.dissipated_contact
               - h.dissipated_friction)
    assert h.dissipated_contact[-1] > 0.01 * h.work_input[-1]
    # measured 2.2e-7 and 1.8e-6 (the work 5.3 and 3.3): the trapezoidal rule's error
    assert np.abs(balance).max() <= 1e-5 * h.work_input[-1]
    twins = np.flatnonzero(np.diff(h.tau) == 0.0)
    assert len(twins) == len(h.events)  # each event: the rows before and after
    for j in twins:
        assert h.e[j + 1] == pytest.approx(h.e[j], rel=1e-9, abs=1e-12)
    if point["amplitude"] > 1.0:
        flight = h.phase == "flight"
        assert flight.any() and np.all(h.f[flight] == 0.0)


def test_damped_start_solves_the_scalar_equation() -> None:
    """The start: steady sliding with ``e = mu_ss/k`` and ``x' = V`` continuous at ``tau =
    0``; the force there ``n m`` with ``n(0) m + c w'(m) = k e + c V``, between ``mu_ss`` and
    ``n(0) mu_ss`` (the load jumps, the dashpot takes part of it)."""
    V, A, eta = 0.5, 0.5, 0.2
    P = rs.make_parameters(0.5, 2.0, A, V, 0.0, 0.0, 0.0, True, 0.02, 0.01, 0.02, 1.0, 0.0,
                           0.0, eta)
    z = rs.sliding_start(P, np.zeros(2))
    mu_ss = float(theory.steady_mu_ratio(V, 0.02, 0.01, 0.02, 1.0))
    c = eta * (2.0 - 0.5)  # eta_c k
    w = rs._slip_rate(P, z[rs.Z_M], z[rs.Z_L])[0]
    assert (1.0 + A) * z[rs.Z_M] + c * w == pytest.approx(mu_ss + c * V, rel=1e-13)
    assert z[rs.Z_V] == V and z[rs.Z_Y] == pytest.approx(-mu_ss / 0.5, rel=1e-14)
    assert mu_ss < (1.0 + A) * z[rs.Z_M] < (1.0 + A) * mu_ss
    assert w < V


def test_damped_steady_sliding_at_zero_amplitude() -> None:
    """``A = 0``, stable sliding: ``mu_ss(V)`` within the stated error, periodic (the
    solver's Hurwitz guard, whose polynomial has no contact dashpot, stays out of it)."""
    s = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.0, eta_c=0.1, rs_a=0.02,
                         rs_b=0.01, rs_d_c=0.02, rs_v_ref=1.0)
    r = vf.friction_coefficient(s, v_inertial=0.5)
    assert r.status is Status.PERIODIC
    assert abs(r.mu_ratio - float(theory.steady_mu_ratio(0.5, 0.02, 0.01, 0.02, 1.0))) \
        <= r.error
    assert 0.0 < r.multiplier < 1.0
