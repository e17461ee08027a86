"""The rate-and-state solver with a rigid contact (``beta = inf``: the contact point moves
with the body, ``f = n mu(x', theta)``).

Checked against what does not come from the kernel: the closed-form critical stiffness of a
rigid contact and the characteristic roots of steady sliding (``theory.rate_state``), the
steady-sliding coefficient ``mu_ss(V)``, the energy balance of the orbit, and the finite
contact's solutions (another mode of the kernel: ``k e`` the force, no slaved velocity) as
``beta`` grows.  The Jacobian of the period map against central differences is in
tests/solver/test_rate_state_multiplier.py, the agreement with the independent reference in
tests/reference/test_differential_rate_state.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction._kernels import rate_state as rs
from vibrofriction.schema import FLOAT_COLUMNS, INT_COLUMNS, Status, column_index
from vibrofriction.theory import rate_state as trs

STATUS, MU, ERR, MULT = (column_index(c) for c in ("status", "mu_ratio", "error",
                                                    "multiplier"))


def _params(alpha: float, A: float, V: float, zeta: float, a: float, b: float, dc: float,
            vref: float = 1.0, ald: float = 0.0, law: float = 0.0) -> np.ndarray:
    return rs.make_parameters(alpha, math.inf, A, V, zeta, 0.0, 0.0, True, a, b, dc, vref,
                              ald, law)


def _kernel(P: np.ndarray, rtol: float = 1e-8, max_periods: int = 600
            ) -> tuple[int, float, float, float]:
    """``(status code, mu_ratio, error, multiplier)`` of the kernel alone (no guard)."""
    z = rs.sliding_start(P, np.zeros(2))
    of = np.empty(len(FLOAT_COLUMNS))
    oi = np.empty(len(INT_COLUMNS), np.int64)
    rs.rs_steady_state(P, z, rtol, max_periods, 1e-3, np.zeros(2), of, oi)
    return int(oi[STATUS]), float(of[MU]), float(of[ERR]), float(of[MULT])


# V, a, b, d_c, gamma: weakening points whose critical stiffness is of order 1
CRITICAL = [(0.3, 0.02, 0.04, 0.3, 0.0), (0.2, 0.03, 0.05, 0.2, 0.02)]


@pytest.mark.parametrize("point", CRITICAL)
def test_closed_form_critical_stiffness(point: tuple) -> None:
    """``theory.critical_stiffness_rigid`` is the closed form ``(V^2 + V d_c gamma + a_e
    d_c)(b_e - a_e - V gamma)/(d_c^2 (a_e + V gamma))`` (written out here, with the slopes
    ``a tanh(mu_ss/a)``, ``b tanh(mu_ss/a)``) and the root of the cubic's Hurwitz margin
    (``theory.critical_stiffness``, bisection)."""
    V, a, b, dc, gamma = point
    mu = a * math.asinh(V / 2.0 * math.exp((1.0 + b * math.log(1.0 / V)) / a))
    a_e, b_e = a * math.tanh(mu / a), b * math.tanh(mu / a)
    by_hand = ((V * V + V * dc * gamma + a_e * dc) * (b_e - a_e - V * gamma)
               / (dc * dc * (a_e + V * gamma)))
    acr = float(trs.critical_stiffness_rigid(V, a, b, dc, 1.0, gamma))
    assert acr == pytest.approx(by_hand, rel=1e-12)
    assert trs.critical_stiffness(math.inf, gamma, V, a, b, dc, 1.0) == pytest.approx(
        acr, rel=1e-9)
    assert 0.3 < acr < 3.0


@pytest.mark.parametrize("factor", [1.3, 1.1, 0.9, 0.7])
@pytest.mark.parametrize("point", CRITICAL)
def test_rigid_critical_stiffness(point: tuple, factor: float) -> None:
    """Without oscillation, at ``factor`` times the rigid contact's critical stiffness (the
    pin dashpot ``gamma`` held): above it steady sliding is periodic with the theory's
    multiplier ``exp(2 pi max Re s)`` (the exact monodromy of the rigid mode); below it the
    kernel alone never says periodic (it leaves steady sliding: the kick acts through
    ``m``, the velocity being slaved to it), nor does the solver."""
    V, a, b, dc, gamma = point
    alpha = factor * float(trs.critical_stiffness_rigid(V, a, b, dc, 1.0, gamma))
    zeta = gamma / (2.0 * math.sqrt(alpha))
    growth = math.exp(2.0 * math.pi * max(
        trs.sliding_eigenvalues(alpha, math.inf, zeta, V, a, b, dc, 1.0).real))
    status, mu, err, mult = _kernel(_params(alpha, 0.0, V, zeta, a, b, dc))
    s = vf.Dimensionless(alpha=alpha, beta=math.inf, amplitude=0.0, zeta=zeta, rs_a=a,
                         rs_b=b, rs_d_c=dc, rs_v_ref=1.0)
    r = vf.friction_coefficient(s, v_inertial=V, settings=vf.SolverSettings(tol_mean=1e-3))
    if factor > 1.0:
        assert growth < 1.0
        assert status == Status.PERIODIC.code
        assert mult == pytest.approx(growth, abs=1e-5)
        assert abs(mu - float(theory.steady_mu_ratio(V, a, b, dc, 1.0))) <= err
        assert r.status is Status.PERIODIC
    else:
        assert growth > 1.0
        assert status != Status.PERIODIC.code
        assert r.status is not Status.PERIODIC


@pytest.mark.parametrize(("V", "law", "zeta"), [(0.05, "aging", 0.0), (0.5, "slip", 0.0),
                                                 (2.0, "aging", 0.1), (0.3, "slip", 0.2)])
def test_rigid_steady_sliding_at_zero_amplitude(V: float, law: str, zeta: float) -> None:
    """``A = 0``, stable sliding (strengthening, ``b < a``): the answer is ``mu_ss(V)`` of
    the theory within the stated error, periodic."""
    a, b, dc = 0.03, 0.02, 0.05
    s = vf.Dimensionless(alpha=0.5, beta=math.inf, amplitude=0.0, zeta=zeta, rs_a=a, rs_b=b,
                         rs_d_c=dc, rs_v_ref=1.0, rs_law=law)
    r = vf.friction_coefficient(s, v_inertial=V)
    mu_ss = float(theory.steady_mu_ratio(V, a, b, dc, 1.0))
    assert r.status is Status.PERIODIC
    assert abs(r.mu_ratio - mu_ss) <= r.error
    assert r.error < 1e-8


@pytest.mark.parametrize("point", [
    # alpha, A, V, zeta, a, b, d_c, law
    (0.5, 0.5, 0.5, 0.0, 0.05, 0.03, 0.05, "aging"),
    (0.5, 1.3, 0.5, 0.1, 0.05, 0.03, 0.05, "slip"),  # jumping
])
def test_finite_contact_converges_to_the_rigid_one(point: tuple) -> None:
    """As ``k = beta - alpha`` grows the finite contact's mean tends to the rigid one's
    at first order, like ``1/k`` (measured, rtol 1e-9: ``k (mu_k - mu_rigid)`` = 0.0178,
    0.0189, 0.0196 at ``k`` = 1e3, 1e4, 1e5 for the first point, an order 0.98 over the
    two decades; 0.581, 0.682, 0.744 jumping, an order 0.95: the touch-downs add a slower
    correction)."""
    alpha, A, V, zeta, a, b, dc, law = point
    settings = vf.SolverSettings(rtol=1e-9)

    def mu(beta: float) -> float:
        s = vf.Dimensionless(alpha=alpha, beta=beta, amplitude=A, zeta=zeta, rs_a=a, rs_b=b,
                             rs_d_c=dc, rs_v_ref=1.0, rs_law=law)
        r = vf.friction_coefficient(s, v_inertial=V, settings=settings)
        assert r.status is Status.PERIODIC
        return r.mu_ratio

    rigid = mu(math.inf)
    gaps = [mu(alpha + k) - rigid for k in (1e3, 1e4, 1e5)]
    assert gaps[0] * gaps[1] > 0.0 and gaps[1] * gaps[2] > 0.0  # one side, no crossing
    # each decade of k divides the gap by about ten: first order
    for g0, g1 in zip(gaps[:-1], gaps[1:], strict=True):
        assert 7.0 < g0 / g1 < 11.0
    order = math.log10(gaps[0] / gaps[2]) / 2.0
    assert 0.9 < order < 1.1


@pytest.mark.parametrize(("A", "law", "zeta"), [(0.5, 0.0, 0.0), (0.7, 1.0, 0.2),
                                                 (1.3, 0.0, 0.1)])
def test_rigid_energy_balance(A: float, law: float, zeta: float) -> None:
    """Over the rigid contact's periodic orbit the puller's work ``V int f`` is the
    friction's dissipation ``int f x'`` plus the dashpot's ``int gamma y'^2`` (jumping
    included: the body flies freely)."""
    V = 0.5
    P = _params(0.5, A, V, zeta, 0.05, 0.03, 0.05, law=law)
    z = rs.sliding_start(P, np.zeros(2))
    of = np.empty(len(FLOAT_COLUMNS))
    oi = np.empty(len(INT_COLUMNS), np.int64)
    rs.rs_steady_state(P, z, 1e-9, 2000, 1e-8, np.zeros(2), of, oi)
    assert int(oi[STATUS]) == Status.PERIODIC.code
    assert rs.rs_period(P, z, 1e-10, np.array([1e-3]), rs._workspace(), np.zeros(3, np.int64))
    drive, friction, dashpot = V * z[rs.Z_F], z[rs.Z_D], z[rs.Z_G]
    assert friction > 0.0 and (dashpot > 0.0) == (zeta > 0.0)
    assert abs(drive - friction - dashpot) <= 1e-7 * drive


def test_rigid_start_is_the_reference_one() -> None:
    """The start: steady sliding at ``V`` before the oscillation, the body's velocity
    continuous at ``tau = 0`` (``x' = V``, ``m = mu(V, d_c/V) = mu_ss(V)``, ``y =
    -mu_ss/alpha``); the force jumps to ``n(0) mu_ss``."""
    V, a, b, dc = 0.5, 0.05, 0.03, 0.05
    P = _params(0.5, 0.7, V, 0.0, a, b, dc)
    z = rs.sliding_start(P, np.zeros(2))
    mu_ss = float(theory.steady_mu_ratio(V, a, b, dc, 1.0))
    assert z[rs.Z_V] == V
    assert z[rs.Z_M] == pytest.approx(mu_ss, rel=1e-14)
    assert z[rs.Z_Y] == pytest.approx(-mu_ss / 0.5, rel=1e-14)
    assert z[rs.Z_L] == pytest.approx(math.log(dc / V), rel=1e-14)
    f, w = rs.contact_state(P, z)
    assert f == pytest.approx(1.7 * mu_ss, rel=1e-14)
    assert w == pytest.approx(V, rel=1e-12)


def test_rigid_history() -> None:
    """``vf.simulate`` carries the rigid contact: ``e = 0``, the slip rate is the body's
    velocity in contact, the force ``n m``, the events those of the closed-form cuts; its
    last section state is the steady state's when it starts there."""
    s = vf.Dimensionless(alpha=0.5, beta=math.inf, amplitude=1.3, zeta=0.1, rs_a=0.05,
                         rs_b=0.03, rs_d_c=0.05, rs_v_ref=1.0, rs_law="slip")
    h = vf.simulate(s, v_inertial=0.8, periods=2)
    assert np.all(h.e == 0.0)
    contact = np.isfinite(h.local_mu)
    assert contact.any() and (~contact).any()
    assert np.array_equal(h.slip_velocity[contact, 0], h.x_dot[contact])
    assert np.allclose(h.f[contact], h.n[contact] * h.local_mu[contact], rtol=1e-14)
    assert [e.kind for e in h.events] == ["lift-off", "touchdown"] * 2
    th = math.acos(-1.0 / 1.3)
    assert h.events[0].tau == pytest.approx(th, abs=1e-6)
    assert h.x_dot[0] == pytest.approx(0.8, rel=1e-14)  # w'(mu(V)): the start's velocity
    r = vf.friction_coefficient(s, v_inertial=0.8)
    steady = vf.simulate(s, v_inertial=0.8, periods=1, initial="steady")
    assert r.status is Status.PERIODIC
    assert steady.x_dot[-1] == pytest.approx(steady.x_dot[0], abs=1e-5)
    assert steady.impulse[-1, 0] / (2.0 * math.pi * r.mean_normal_ratio) == pytest.approx(
        r.mu_ratio, abs=1e-5)


def test_slaved_coefficient_root_converges(monkeypatch):
    """The root of ``g(m) = s0 + s1 m + s2 w'(m, L)`` (:func:`rs._root_m`, the contact's
    coefficient where its velocity is slaved) to round-off against ``brentq``, and in
    Newton's few steps: a converged step lands on the bracket's end just moved, and must
    answer rather than bisect the bracket down."""
    from scipy.optimize import brentq

    P = _params(0.5, 0.5, 0.3, 0.0, 0.01, 0.015, 1e-3)
    slip_rate = rs._slip_rate.py_func
    calls = []

    def counted(P, m, L):
        calls.append(m)
        return slip_rate(P, m, L)

    monkeypatch.setattr(rs, "_slip_rate", counted)
    for s0, s1, s2, far, most in ((-1.2, 1.0, 1e-3, 2.0, 14), (1.1, -1.0, -1e-2, 2.0, 8),
                                  (-0.3, 1.0, 0.5, 1.0, 4)):
        calls.clear()
        m = rs._root_m.py_func(P, 0.0, s0, s1, s2, far)
        exact = brentq(lambda x, s0=s0, s1=s1, s2=s2: s0 + s1 * x + s2 * slip_rate(P, x, 0.0)[0],
                       0.0, far,
                       xtol=1e-15, rtol=1e-15)
        assert m == pytest.approx(exact, rel=1e-14, abs=1e-15)
        assert len(calls) <= most
