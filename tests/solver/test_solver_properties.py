"""Property tests over random valid parameters: no crash, no hang, honest status."""

import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import vibrofriction as vf

log_alpha = st.floats(-3.0, 2.5)
log_k = st.floats(-3.0, 3.0)
amplitude = st.floats(0.0, 2.5)
vfrac = st.floats(0.0, 3.0)

BUDGET = vf.SolverSettings(max_periods=3000)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(la=log_alpha, lk=log_k, rigid=st.booleans(), a=amplitude, v=vfrac)
def test_random_points_are_honest(la, lk, rigid, a, v):
    alpha = 10.0**la
    beta = math.inf if rigid else alpha + 10.0**lk
    s = vf.Dimensionless(alpha, beta, a)
    # velocity relative to v0* where it exists, else an inertial velocity
    V = v * (s.critical_inertial_velocity() if 0 < s.critical_inertial_velocity() < 1e6
             else 1.0)
    r = vf.friction_coefficient(s, v_inertial=V, settings=BUDGET)
    assert r.status in tuple(vf.Status)
    if r.status in (vf.Status.FAILED, vf.Status.NOT_CONVERGED):
        # allowed only with an honest status, no value and no claimed accuracy
        assert not r.trusted and r.error == math.inf
        assert r.status is vf.Status.FAILED or math.isnan(r.mu_ratio)
        return
    assert math.isfinite(r.mu_ratio)
    assert r.mu_ratio <= 1.0 + 1e-9 + r.error
    assert r.mu_ratio >= -1.0 - 1e-9
    if r.status is vf.Status.PERIODIC:
        assert r.period >= 1 and 0.0 < r.error
        assert math.isnan(r.multiplier) or r.multiplier >= 0.0  # nan: no single chart
        # the error is what the orbit's verification says; trust follows from it alone
        # (its calibration is tested in tests/reference/test_differential.py and test_trust.py)
    assert r.trusted == (r.success and r.error <= BUDGET.tol_trusted)
    if r.status in (vf.Status.PERIODIC, vf.Status.AVERAGED, vf.Status.SLIDING):
        total = r.stick_fraction + r.slip_fraction + r.flight_fraction
        assert abs(total - 1.0) < 1e-9
        assert (r.flight_fraction > 0) <= (a > 1)
    if r.status is vf.Status.SLIDING:
        assert r.mu_ratio == 1.0
    if V == 0:
        assert r.status is vf.Status.STATIC


@settings(max_examples=40, deadline=None)
@given(la=st.floats(-2.0, 1.5), lk=st.floats(-2.0, 2.5), a=st.floats(0.05, 2.0),
       vbar=st.floats(0.05, 0.95))
def test_random_histories_stay_in_the_friction_cone(la, lk, a, vbar):
    alpha = 10.0**la
    beta = alpha + 10.0**lk
    if abs(alpha - 1) < 1e-3 or abs(beta - 1) < 1e-3:
        return
    s = vf.Dimensionless(alpha, beta, a)
    h = vf.simulate(s, vbar=vbar, periods=3, samples_per_period=200)
    assert np.all(np.abs(h.f) <= h.n * (1 + 1e-12) + 1e-12)
    times = [e.tau for e in h.events]
    assert times == sorted(times)
