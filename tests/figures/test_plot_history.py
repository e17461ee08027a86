"""``figures.plot_history``: a history's forces, its local coefficient and, with
rate-and-state friction, the state theta (the arrays drawn are the history's)."""

from __future__ import annotations

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction.figures import plot_history

RS = dict(rs_a=0.03, rs_b=0.01, rs_d_c=0.02, rs_v_ref=0.2)


def test_a_rate_and_state_history_shows_theta_and_the_local_coefficient() -> None:
    h = vf.simulate(vf.Dimensionless(0.5, 2.0, 1.3, **RS), v_inertial=0.5, periods=1)
    assert isinstance(h, vf.RateStateHistory)
    fig = plot_history(h)
    forces, local, state = fig.axes
    np.testing.assert_array_equal(local.lines[0].get_ydata(), h.local_mu)
    np.testing.assert_array_equal(state.lines[0].get_ydata(), h.theta)
    assert state.get_yscale() == "log"
    assert state.lines[1].get_ydata()[0] == pytest.approx(0.02 / 0.5)  # d_c/V
    mu_ss = float(theory.steady_mu_ratio(0.5, 0.03, 0.01, 0.02, 0.2))
    assert local.lines[1].get_ydata()[0] == pytest.approx(mu_ss)
    assert "rate-and-state (aging law)" in forces.get_title()


def test_a_coulomb_history_shows_its_coefficient_within_the_static_limit() -> None:
    h = vf.simulate(vf.Dimensionless(0.5, 2.0, 1.3, static_ratio=1.3), v_inertial=0.5,
                    periods=1)
    fig = plot_history(h)
    assert len(fig.axes) == 2
    mu = fig.axes[1].lines[0].get_ydata()
    assert np.all(np.isnan(mu[h.n == 0.0]))
    assert np.nanmax(np.abs(mu)) <= 1.3 + 1e-9 and fig.axes[1].lines[1].get_ydata()[0] == 1.3
