"""Physics of the steady state: exact limits, invariants, event conditions, energy."""

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory

# A spread of regimes used by several tests: (alpha, beta, amplitude, vbar or None).
# vbar None means the velocity is given as v_inertial (cases III and IV).
REGIMES = [
    (0.5, 2.0, 0.5),  # general
    (0.01, 0.02, 0.5),  # stiff system, case II
    (0.01, 400.01, 0.5),  # soft system, case I
    (0.5, 2.0, 1.0),  # grazing contact
    (0.5, 2.0, 1.5),  # jumping
    (2.0, 5.0, 0.8),  # alpha > 1
    (0.01, math.inf, 0.5),  # rigid contact
    (0.2, 0.9, 0.7),  # below the contact resonance
]


def _contact_velocity(h, k):
    """Contact-point velocity in slip, x' - f'/k with f = s n (eq. 10)."""
    s = np.where(h.phase == "slip+", 1.0, np.where(h.phase == "slip-", -1.0, 0.0))
    a = h.system.amplitude
    return h.x_dot + s * a * np.sin(h.tau) / k


@pytest.mark.parametrize("alpha,beta,a", [r for r in REGIMES if r[1] != 0.9 and r[2] <= 1])
@pytest.mark.parametrize("vbar", [1.05, 1.5, 3.0])
def test_continuous_sliding_above_critical_velocity_gives_exactly_one(alpha, beta, a, vbar):
    """Eqs. (10)-(12), for a contact that never opens (jumping: tests/solver/test_trust.py)."""
    r = vf.friction_coefficient(vf.Dimensionless(alpha, beta, a), vbar=vbar)
    assert r.trusted
    assert r.mu_ratio == pytest.approx(1.0, abs=1e-12)
    # rare grazing sticks of the undamped free oscillation may remain (docs/solver.md)
    assert r.stick_fraction < 1e-6


@pytest.mark.parametrize("a", [0.0, 0.2, 0.5, 0.9, 1.0, 1.5])
def test_static_limit(a):
    """vbar -> 0: mu/mu0 -> 1 - a (a < 1), 0 (a >= 1) (eq. 2); V = 0 is that limit."""
    s = vf.Dimensionless(0.5, 2.0, a)
    assert vf.friction_coefficient(s, v_inertial=0.0).mu_ratio == theory.static_mu_ratio(a)
    assert vf.friction_coefficient(s, v_inertial=0.0).status is vf.Status.STATIC
    if a == 0:
        return
    small = vf.friction_coefficient(s, vbar=np.array([1e-4, 1e-3]))
    assert np.all(small.success)
    assert np.all(np.abs(small.mu_ratio - theory.static_mu_ratio(a)) < 30 * small.v_inertial)


@pytest.mark.parametrize("alpha,beta,a", [(0.5, 2.0, 0.5), (0.01, 0.02, 0.5),
                                          (0.01, 400.01, 0.8), (2.0, 5.0, 0.8),
                                          (0.2, 0.9, 0.7)])
def test_stick_just_below_critical_velocity_and_not_above(alpha, beta, a):
    """Eq. (12): the contact point stops (sticks) iff v0 < v0*."""
    s = vf.Dimensionless(alpha, beta, a)
    below = vf.friction_coefficient(s, vbar=0.97)
    above = vf.friction_coefficient(s, vbar=1.03)
    assert below.success and above.success
    assert below.stick_fraction > 0 and below.mu_ratio < 1.0
    # above v0*: mu0 within the stated error.  From the sliding start a free oscillation
    # at sqrt(alpha) is left over; it is undamped in slip, so rare grazing sticks can
    # recur while its amplitude decays to v0 - v0* (then the average is 'averaged').
    assert abs(above.mu_ratio - 1.0) <= max(above.error, 1e-12)
    assert above.stick_fraction < 1e-2


def test_resonant_contact_case_iii_gives_one_at_all_velocities():
    s = vf.Dimensionless(0.3, 1.0, 0.8)
    r = vf.friction_coefficient(s, v_inertial=np.array([0.01, 0.1, 0.5, 2.0, 10.0]))
    assert np.all(r.success)
    np.testing.assert_allclose(r.mu_ratio, 1.0, atol=1e-9)


def test_resonant_system_case_iv_reaches_the_exact_plateau():
    """alpha = 1, rigid contact: the plateau is the energy balance of eqs. (32)."""
    for a in (0.2, 0.5, 1.0):
        r = vf.friction_coefficient(vf.Dimensionless(1.0, math.inf, a), v_inertial=60.0)
        assert r.success
        assert r.mu_ratio == pytest.approx(theory.resonant_plateau_exact(a), abs=2e-4)
        assert r.mu_ratio == pytest.approx(1 - a / 2, abs=0.02)


@pytest.mark.parametrize("delta", [1e-9, -1e-9, 1e-7])
def test_alpha_within_1e9_of_one_is_continuous(delta):
    """The 1/(alpha - 1) of the slip closed form cancels analytically."""
    V = np.array([0.5, 2.0, 8.0])
    for beta in (2.0, math.inf):
        ref = vf.friction_coefficient(vf.Dimensionless(1.0, beta, 0.5), v_inertial=V)
        near = vf.friction_coefficient(vf.Dimensionless(1.0 + delta, beta, 0.5), v_inertial=V)
        assert np.all(near.success)
        np.testing.assert_allclose(near.mu_ratio, ref.mu_ratio, atol=50 * abs(delta) + 1e-10)


def test_large_beta_is_close_to_the_rigid_contact():
    """Within 5e-3 for beta >= 100, but not monotonically: the contact vibration at
    sqrt(beta) excited at each slip -> stick is undamped in this model and ends only
    through micro-slips, so beta -> inf is a singular limit (see docs/solver.md)."""
    rigid = vf.friction_coefficient(vf.Dimensionless(0.5, math.inf, 0.5), v_inertial=0.3)
    for beta in (1e2, 1e3, 1e4):
        r = vf.friction_coefficient(vf.Dimensionless(0.5, beta, 0.5), v_inertial=0.3)
        assert r.success
        assert abs(r.mu_ratio - rigid.mu_ratio) < 5e-3


@pytest.mark.parametrize("alpha,beta,a", REGIMES)
def test_friction_never_exceeds_the_cone_along_a_history(alpha, beta, a):
    s = vf.Dimensionless(alpha, beta, a)
    h = vf.simulate(s, vbar=0.4, periods=4, samples_per_period=500, initial="steady")
    assert np.all(np.abs(h.f) <= h.n + 1e-12 * (1 + h.n))
    assert np.all(h.n >= 0)
    assert np.all(h.f[h.phase == "flight"] == 0.0)


@pytest.mark.parametrize("alpha,beta,a", [r for r in REGIMES if not math.isinf(r[1])])
def test_event_conditions_hold_at_the_reported_event_times(alpha, beta, a):
    s = vf.Dimensionless(alpha, beta, a)
    h = vf.simulate(s, vbar=0.5, periods=6, initial="steady")
    assert h.events, "a stick-slip point must have events"
    k = beta - alpha
    idx = {ev.tau: i for i, ev in enumerate(h.events)}
    assert len(idx) == len(h.events)
    for ev in h.events:
        i = int(np.searchsorted(h.tau, ev.tau))  # sample exactly at the event
        assert h.tau[i] == ev.tau
        if ev.kind == "stick->slip":
            assert abs(h.f[i]) == pytest.approx(h.n[i], abs=1e-12)
        elif ev.kind == "slip->stick":
            # the sample before the event is still in slip: contact velocity ~ 0 there
            sj = 1.0 if ev.before == "slip+" else -1.0
            vc = h.x_dot[i - 1] + sj * a * math.sin(h.tau[i - 1]) / k
            assert abs(vc) < 1e-9 * (1 + abs(h.x_dot[i - 1]))
            assert abs(h.x_dot[i] + sj * a * math.sin(h.tau[i]) / k) < 1e-12 * (1 + k)
        elif ev.kind in ("lift-off", "touchdown"):
            assert math.cos(ev.tau) == pytest.approx(-1.0 / a, abs=1e-12)


@pytest.mark.parametrize("alpha,beta,a,vbar", [(0.5, 2.0, 0.5, 0.3), (0.01, 0.02, 0.8, 0.5),
                                               (2.0, 5.0, 0.8, 0.4), (0.5, 2.0, 1.5, 0.5),
                                               (0.01, 400.01, 0.5, 0.5)])
def test_energy_balance_over_a_steady_period(alpha, beta, a, vbar):
    """Work of the pulling spring = frictional dissipation over one steady period.

    Power in: alpha (V tau - x) V; dissipation: f x_c' (x_c' = 0 in stick, f = s n in
    slip).  Over a periodic orbit the stored energy returns, so <f> V = <f x_c'>.
    """
    s = vf.Dimensionless(alpha, beta, a)
    r = vf.friction_coefficient(s, vbar=vbar)
    assert r.status is vf.Status.PERIODIC
    p = r.period
    h = vf.simulate(s, vbar=vbar, periods=p, samples_per_period=40000, initial=r.final_state)
    V = h.v_inertial
    work_in = np.trapezoid(alpha * (V * h.tau - h.x), h.tau) * V
    slipping = (h.phase == "slip+") | (h.phase == "slip-")
    vc = np.where(slipping, _contact_velocity(h, beta - alpha), 0.0)
    dissipated = np.trapezoid(h.f * vc, h.tau)
    assert dissipated > 0
    assert work_in == pytest.approx(dissipated, rel=2e-5)
    # and the averaged friction is that of the result
    mu = np.trapezoid(h.f, h.tau) / np.trapezoid(h.n, h.tau)
    assert mu == pytest.approx(r.mu_ratio, abs=2e-6)


def test_continuation_from_a_final_state_reproduces_the_orbit(general_system):
    r = vf.friction_coefficient(general_system, vbar=0.4)
    again = vf.friction_coefficient(general_system, vbar=0.4, initial=r.final_state)
    assert again.status is vf.Status.PERIODIC
    assert again.periods <= r.period + 1
    assert again.mu_ratio == pytest.approx(r.mu_ratio, abs=1e-12)


def test_rest_and_sliding_starts_agree_where_the_attractor_is_unique(general_system):
    a = vf.friction_coefficient(general_system, vbar=0.5)
    b = vf.friction_coefficient(general_system, vbar=0.5, initial="rest")
    assert a.mu_ratio == pytest.approx(b.mu_ratio, abs=1e-9)


def test_periodic_results_state_honest_errors(general_system):
    c = vf.friction_coefficient(general_system, vbar=np.linspace(0.05, 0.95, 19))
    for r in c:
        assert r.status in (vf.Status.PERIODIC, vf.Status.AVERAGED)
        assert 0 <= r.error < 1e-6
        assert r.stick_fraction + r.slip_fraction + r.flight_fraction == pytest.approx(1.0)


def test_not_converged_is_reported_not_hidden():
    """alpha within 1e-9 of 1 at a vbar: v0* ~ 1e9, a resonance still building up."""
    s = vf.Dimensionless(1 - 1e-9, 2.0, 0.5)
    r = vf.friction_coefficient(s, vbar=0.5, settings=vf.SolverSettings(max_periods=300))
    assert r.status is vf.Status.NOT_CONVERGED
    assert not r.success
    assert "max_periods" in r.message
