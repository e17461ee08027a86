"""The reference integrators of the two local friction laws beyond Coulomb's.

Law 1 (static above kinetic, :func:`static_kinetic_run`, fixed steps):
(a) at ``sigma = 1`` it is Coulomb's law: it agrees with both Coulomb peers (finite and
    rigid contact, damping, jumping) within its error bar;
(b) it converges at second order in the step (fitted slope), and its error bar (two
    resolutions) bounds its actual error;
(c) ``A = 0``, undamped rigid contact, from rest: the saw-tooth derived by hand below.

Law 2 (rate-and-state, :func:`rate_state_run`, ``solve_ivp``):
(d) at ``A = 0`` with stable sliding it returns to ``mu_ss(V)`` from a perturbed state,
    under the aging and the slip law alike (the same steady state); a stiff finite contact
    approaches the rigid one; LSODA and Radau agree within their bars;
(e) the Coulomb limit ``a, b -> 0`` approaches the Coulomb peers, at first order in ``a``;
(f) the energy balance of a steady period closes on a history;
(g) parameters it cannot run with are refused.
"""

import math

import numpy as np
import pytest

from vibrofriction_reference import (
    mu_steady_state,
    rate_state_history,
    rate_state_run,
    return_mapping_mu,
    solve_ivp_mu,
    static_kinetic_history,
    static_kinetic_mu,
    static_kinetic_run,
)

# --- (a) sigma = 1 is Coulomb's law -------------------------------------------------------

# (alpha, beta, A, V), zeta, initial: finite and rigid contact, damped, jumping
COULOMB_POINTS = [
    ((0.5, 2.0, 0.5, 0.3), 0.0, "sliding"),
    ((0.5, 2.0, 1.5, 1.0), 0.0, "sliding"),
    ((0.5, 2.0, 0.5, 0.3), 0.2, "rest"),
    ((1.0, math.inf, 0.5, 3.0), 0.0, "sliding"),
    ((0.5, math.inf, 1.5, 0.5), 0.0, "rest"),
    ((0.5, math.inf, 0.8, 0.5), 0.2, "sliding"),
]


@pytest.mark.parametrize("p, zeta, initial", COULOMB_POINTS)
def test_law1_at_sigma_one_agrees_with_the_coulomb_peers(p, zeta, initial):
    run = static_kinetic_run(*p, 1.0, zeta=zeta, transient_periods=20, average_periods=10,
                             initial=initial)
    assert 0.0 < run.error < 2e-4
    peer_a = solve_ivp_mu(*p, 20, 10, initial=initial, zeta=zeta)  # accurate to ~rtol
    assert abs(run.mu_ratio - peer_a) <= run.error + 1e-7
    # peer B with its own bar (two resolutions)
    b_fine = return_mapping_mu(*p, 800, 20, 10, initial=initial, zeta=zeta)
    b_coarse = return_mapping_mu(*p, 400, 20, 10, initial=initial, zeta=zeta)
    assert abs(run.mu_ratio - b_fine) <= run.error + abs(b_fine - b_coarse) + 1e-9
    # the per-period means (the undamped jumping point is still drifting by 1e-3: same
    # windows for every peer) add up to the run's
    assert run.period_f.shape == run.period_n.shape == (10,)
    assert run.period_f.sum() / run.period_n.sum() == pytest.approx(run.mu_ratio, rel=1e-12)


def test_law1_static_friction_raises_the_mean_where_the_contact_sticks():
    """A point that sticks part of each period: sigma > 1 changes the answer (so (b) and
    (c) test more than Coulomb's law)."""
    p = (0.5, 2.0, 0.5, 0.3)
    coulomb = static_kinetic_mu(*p, 1.0, transient_periods=20, average_periods=10)
    static = static_kinetic_mu(*p, 1.5, transient_periods=20, average_periods=10)
    assert static - coulomb > 0.01


# --- (b) second order -----------------------------------------------------------------------

ORDER_POINTS = [
    ((0.5, 2.0, 0.5, 0.3), 1.5, 0.0),
    ((0.5, 2.0, 1.5, 1.0), 1.3, 0.0),  # jumping
    ((1.0, math.inf, 0.5, 3.0), 1.5, 0.0),
    ((0.5, math.inf, 0.8, 0.5), 1.4, 0.2),
]


@pytest.mark.parametrize("p, sigma, zeta", ORDER_POINTS)
def test_law1_converges_at_second_order(p, sigma, zeta):
    kw = {"zeta": zeta, "transient_periods": 20, "average_periods": 10}
    ref = static_kinetic_mu(*p, sigma, steps_per_period=12800, **kw)
    steps = np.array([100, 200, 400, 800])
    errors = np.array([abs(static_kinetic_mu(*p, sigma, steps_per_period=s, **kw) - ref)
                       for s in steps])
    slope = -np.polyfit(np.log(steps), np.log(errors), 1)[0]
    # measured: 1.96-2.08 (errors 1e-4 to 1.5e-6 at 100 to 800 steps)
    assert 1.7 < slope < 2.5, (slope, errors)
    # the bar of the two-resolution run bounds the finer run's error
    run = static_kinetic_run(*p, sigma, steps_per_period=200, **kw)
    assert abs(run.mu_ratio - ref) <= run.error


# --- (c) the saw-tooth --------------------------------------------------------------------


@pytest.mark.parametrize("sigma", [1.5, 2.5])
def test_law1_rigid_sawtooth_without_oscillation(sigma):
    """``A = 0``, ``zeta = 0``, rigid contact, from rest (``x = x' = 0``), ``n = 1``.

    Stuck, the holding force ``alpha (V tau - x) = alpha V tau`` grows until it reaches
    ``sigma`` at ``tau_1 = sigma/(alpha V)``.  Slip with ``f = 1``: ``xi = alpha (V tau -
    x) - 1`` obeys ``xi'' = -alpha xi`` from ``xi = sigma - 1``, ``xi' = alpha V``, so
    ``xi = R cos(phi - delta)``, ``phi = sqrt(alpha) (tau - tau_1)``, ``tan delta = V
    sqrt(alpha) / (sigma - 1)``, and ``x' = V + R sin(phi - delta) / sqrt(alpha)`` is
    positive until ``phi = pi + 2 delta``, where ``xi = -(sigma - 1)``: the body stops with
    the holding force ``2 - sigma``, within ``sigma`` (for every ``sigma >= 1``), and
    sticks.  It grows again at the rate ``alpha V`` to ``sigma`` after ``2 (sigma -
    1)/(alpha V)``, and the cycle repeats with the period ``T = 2 (sigma - 1)/(alpha V) +
    (pi + 2 delta)/sqrt(alpha)``.  Over a cycle the stuck force is linear from ``2 -
    sigma`` to ``sigma`` (mean 1) and the slipping force is 1: the mean of ``f`` is 1.
    """
    alpha, V = 0.5, 0.2
    h = static_kinetic_history(alpha, math.inf, 0.0, V, sigma, periods=20,
                               steps_per_period=2000, initial="rest")
    dt = 2 * math.pi / h.steps_per_drive_period
    delta = math.atan2(V * math.sqrt(alpha), sigma - 1.0)
    period = 2 * (sigma - 1) / (alpha * V) + (math.pi + 2 * delta) / math.sqrt(alpha)
    stuck = h.state == 0
    starts = np.nonzero(stuck[:-1] & ~stuck[1:])[0]  # last stuck step before a slip
    stops = np.nonzero(~stuck[:-1] & stuck[1:])[0] + 1  # the step that stops the body
    assert len(starts) >= 3 and len(stops) >= 2
    assert h.tau[starts[0]] == pytest.approx(sigma / (alpha * V), abs=dt)
    np.testing.assert_allclose(np.diff(h.tau[starts]), period, atol=2 * dt)
    # the force (a step's mean): sigma just before a slip, 2 - sigma once the body stops
    # (the holding force grows by alpha V dt over a step), 1 in slip
    np.testing.assert_allclose(h.f[starts], sigma, atol=2 * alpha * V * dt)
    np.testing.assert_allclose(h.f[stops + 1], 2 - sigma, atol=3 * alpha * V * dt)
    slipping = (h.state == 1) & (np.roll(h.state, 1) == 1)
    np.testing.assert_allclose(h.f[slipping], 1.0, atol=1e-12)
    assert np.all(h.xdot >= -1e-12)
    for i0, i1 in zip(starts[:-1], starts[1:], strict=True):
        assert np.mean(h.f[i0 + 1:i1 + 1]) == pytest.approx(1.0, abs=1e-3)


# --- (d) law 2 without oscillation ----------------------------------------------------------

RS = {"a": 0.02, "b": 0.01, "d_c": 0.01, "v_ref": 0.01}  # b < a: velocity strengthening


@pytest.mark.parametrize("beta", [5.0, math.inf])
def test_law2_without_oscillation_returns_to_steady_sliding_under_both_laws(beta):
    alpha, V = 2.0, 0.3  # a stiff pin
    mu_ss = mu_steady_state(V, RS["a"], RS["b"], RS["v_ref"])
    assert mu_ss == pytest.approx(1.0 + (RS["a"] - RS["b"]) * math.log(V / RS["v_ref"]),
                                  abs=1e-6)
    means = {}
    for law in ("aging", "slip"):
        theta0 = 100 * RS["d_c"] / V
        run = rate_state_run(alpha, beta, 0.0, V, **RS, law=law, zeta=0.2, theta0=theta0,
                             transient_periods=10, average_periods=3)
        # started off the steady state (theta a hundred times too large) ...
        early = rate_state_run(alpha, beta, 0.0, V, **RS, law=law, zeta=0.2, theta0=theta0,
                               transient_periods=0, average_periods=1)
        assert abs(early.mu_ratio - mu_ss) > 1e-4  # measured 6.5e-4, 7.0e-4
        # ... it returns to it
        assert abs(run.mu_ratio - mu_ss) <= run.error + 1e-8
        means[law] = run.mu_ratio
    assert means["aging"] == pytest.approx(means["slip"], abs=2e-8)


def test_law2_stiff_finite_contact_approaches_the_rigid_one():
    """Two formulations (``e`` in the state, or ``w = x`` with ``f = n mu(x')``) agree as
    ``k -> inf``, the gap falling like ``1/k`` (measured 4.6e-5 at 1e3, 5.3e-6 at 1e4)."""
    p = (0.5, 0.8, 0.3, 0.05, 0.025, 0.01, 0.01)
    kw = {"zeta": 0.2, "transient_periods": 10, "average_periods": 3}
    rigid = rate_state_run(p[0], math.inf, *p[1:], **kw)
    gaps = [abs(rate_state_run(p[0], beta, *p[1:], **kw).mu_ratio - rigid.mu_ratio)
            for beta in (1e3, 1e4)]
    assert gaps[0] < 1e-4
    assert 5 < gaps[0] / gaps[1] < 20


@pytest.mark.parametrize("beta, A", [(2.0, 0.5), (2.0, 1.5)])
def test_law2_lsoda_and_radau_agree_within_their_bars(beta, A):
    kw = {"zeta": 0.2, "transient_periods": 3, "average_periods": 2, "law": "slip"}
    args = (0.5, beta, A, 0.3, 0.05, 0.025, 0.01, 0.01)
    lsoda = rate_state_run(*args, **kw)
    radau = rate_state_run(*args, method="Radau", **kw)
    assert lsoda.error < 1e-5 and radau.error < 1e-5
    assert abs(lsoda.mu_ratio - radau.mu_ratio) <= lsoda.error + radau.error


# --- (e) the Coulomb limit ------------------------------------------------------------------


def test_law2_coulomb_limit_is_first_order_in_a():
    p, zeta = (0.5, 2.0, 0.5, 0.3), 0.2
    coulomb = solve_ivp_mu(*p, 30, 10, zeta=zeta)
    a_values = np.array([1e-2, 3e-3, 1e-3])
    gaps = []
    for a in a_values:
        run = rate_state_run(*p, a, a / 2, 0.01, 1e-3, zeta=zeta, transient_periods=30,
                             average_periods=10)
        assert run.error < 1e-5
        gaps.append(run.mu_ratio - coulomb)
    gaps = np.array(gaps)
    # measured: gaps 0.0207, 0.0063, 0.0021 (about 2 a), slope 0.99
    assert np.all(gaps > 0) and np.all(np.diff(gaps) < 0)
    slope = np.polyfit(np.log(a_values), np.log(gaps), 1)[0]
    assert 0.85 < slope < 1.15, (slope, gaps)
    assert gaps[-1] < 0.005


# --- (f) energy --------------------------------------------------------------------------


def _trapezoid(y, x):
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(x)))


@pytest.mark.parametrize("beta, A, law", [(2.0, 0.5, "aging"), (math.inf, 0.8, "slip"),
                                           (2.0, 1.5, "slip")])
def test_law2_energy_balance_of_a_steady_period(beta, A, law):
    alpha, V, zeta = 0.5, 0.3, 0.2
    gamma = 2 * zeta * math.sqrt(alpha)
    h = rate_state_history(alpha, beta, A, V, 0.05, 0.025, 0.01, 0.01, law=law, zeta=zeta,
                           periods=12, points_per_period=4000)
    last = h.tau >= 10 * 2 * math.pi - 1e-9  # the last two periods
    tau, y, xd, e, f, w = (h.tau[last], h.y[last], h.xdot[last], h.e[last], h.f[last],
                           h.slip_rate[last])
    k = 0.0 if math.isinf(beta) else beta - alpha
    energy = 0.5 * xd**2 + 0.5 * alpha * y**2 + 0.5 * k * e**2
    work = _trapezoid((-alpha * y + gamma * (V - xd)) * V, tau)
    friction = _trapezoid(f * w, tau)
    pin = _trapezoid(gamma * (V - xd) ** 2, tau)
    assert friction > 0.1 * work > 0.0
    assert work - friction - pin == pytest.approx(energy[-1] - energy[0], abs=1e-5 * work)
    # the force is the friction law's: f = n mu(w', theta) where in contact
    contact = h.n[last] > 1e-3
    q = w / (2 * 0.01) * np.exp((1 + 0.025 * np.log(h.theta[last] * 0.01 / 0.01)) / 0.05)
    np.testing.assert_allclose(f[contact], (h.n[last] * 0.05 * np.arcsinh(q))[contact],
                               rtol=1e-6, atol=1e-9)


# --- (g) refused parameters -------------------------------------------------------------------


@pytest.mark.parametrize("kwargs, match", [
    ({"static_ratio": 0.9}, "static_ratio"),
    ({"static_ratio": math.nan}, "static_ratio"),
    ({"zeta": -1.0}, "zeta"),
])
def test_law1_refuses(kwargs, match):
    args = {"alpha": 0.5, "beta": 2.0, "amplitude": 0.5, "V": 0.3, **kwargs}
    with pytest.raises(ValueError, match=match):
        static_kinetic_run(**args)


@pytest.mark.parametrize("kwargs, match", [
    ({"a": 0.0}, "a must"),
    ({"b": -0.1}, "b must"),
    ({"d_c": math.inf}, "d_c must"),
    ({"law": "ageing"}, "law must"),
    ({"alpha_ld": 0.1, "amplitude": 1.5}, "alpha_ld"),
    ({"alpha_ld": 0.1, "b": 0.0}, "alpha_ld"),
    ({"method": "RK45"}, "method"),
    ({"theta0": 0.0}, "theta0"),
])
def test_law2_refuses(kwargs, match):
    args = {"alpha": 0.5, "beta": 2.0, "amplitude": 0.5, "V": 0.3, "a": 0.02, "b": 0.01,
            "d_c": 0.01, "v_ref": 0.01, **kwargs}
    with pytest.raises(ValueError, match=match):
        rate_state_run(**args, transient_periods=0, average_periods=1)


def test_law2_linker_dieterich_coupling_changes_the_mean():
    kw = {"zeta": 0.2, "transient_periods": 10, "average_periods": 3}
    plain = rate_state_run(0.5, 2.0, 0.5, 0.3, 0.02, 0.01, 0.01, 0.01, **kw)
    coupled = rate_state_run(0.5, 2.0, 0.5, 0.3, 0.02, 0.01, 0.01, 0.01, alpha_ld=0.2, **kw)
    assert abs(coupled.mu_ratio - plain.mu_ratio) > 10 * (coupled.error + plain.error)
