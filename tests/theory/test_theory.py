"""Closed forms of the paper (vibrofriction.theory): limits, invariants, quadrature."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from vibrofriction import theory

TWO_PI = 2.0 * math.pi


def n_of(tau: float, a: float) -> float:
    """Scaled normal force with loss of contact."""
    return max(0.0, 1.0 + a * math.cos(tau))


def period_mean(func, breakpoints=()) -> float:
    """Mean over one period [-pi, pi] by adaptive quadrature."""
    pts = sorted(p for p in breakpoints if -math.pi < p < math.pi)
    value, _ = quad(func, -math.pi, math.pi, points=pts or None, limit=200,
                    epsabs=1e-13, epsrel=1e-13)
    return value / TWO_PI


# --------------------------------------------------------------------------- eq. (2)
def test_static_mu_ratio_eq2() -> None:
    assert theory.static_mu_ratio(0.0) == 1.0
    assert theory.static_mu_ratio(0.5) == 0.5
    assert theory.static_mu_ratio(1.0) == 0.0
    assert theory.static_mu_ratio(3.0) == 0.0
    got = theory.static_mu_ratio(np.array([0.2, 0.999, 1.0001]))
    np.testing.assert_allclose(got, [0.8, 0.001, 0.0], atol=1e-15)
    assert isinstance(theory.static_mu_ratio(0.3), float)


@pytest.mark.parametrize("bad", [-0.1, math.nan, math.inf])
def test_static_mu_ratio_rejects(bad: float) -> None:
    with pytest.raises(ValueError, match=r"amplitude must be finite and >= 0, got"):
        theory.static_mu_ratio([0.5, bad])


# --------------------------------------------------------------------------- eqs. (12)-(14)
M, W, MU0, KZC, DUZ = 0.05, 2.0 * math.pi * 800.0, 0.3, 2.0e6, 1.0e-6
MW2 = M * W**2


def test_critical_velocity_by_hand() -> None:
    k_x, k_xc = 0.3 * MW2, 2.0 * MW2
    expected = MU0 * W * DUZ * KZC / k_xc * abs(k_xc + k_x - MW2) / abs(k_x - MW2)
    got = theory.critical_velocity(MU0, W, DUZ, KZC, k_xc, k_x, M)
    assert got == pytest.approx(expected, rel=1e-14)


def test_soft_limit_eq13() -> None:
    """(13) is (12) for k_x -> 0 and k_xc -> inf."""
    exact = theory.critical_velocity_soft(MU0, KZC * DUZ, M, W)
    assert exact == pytest.approx(MU0 * KZC * DUZ / (M * W))
    errors = []
    for eps in (1e-2, 1e-4, 1e-6):
        v = theory.critical_velocity(MU0, W, DUZ, KZC, MW2 / eps, eps * MW2, M)
        errors.append(abs(v / exact - 1.0))
    assert errors[-1] < 1e-5
    assert errors[0] > errors[1] > errors[2]
    # exactly the limit at k_x = 0, k_xc = inf
    assert theory.critical_velocity(MU0, W, DUZ, KZC, math.inf, 0.0, M) == pytest.approx(exact)


@pytest.mark.parametrize("k_x_over_mw2", [0.01, 0.5, 3.0, 100.0])
def test_stiff_limit_eq14(k_x_over_mw2: float) -> None:
    """(14) is (12) for k_xc << |k_x - m omega^2|."""
    k_x = k_x_over_mw2 * MW2
    gap = abs(k_x - MW2)
    for eps in (1e-3, 1e-6):
        k_xc = eps * gap
        v12 = theory.critical_velocity(MU0, W, DUZ, KZC, k_xc, k_x, M)
        v14 = theory.critical_velocity_stiff(MU0, W, DUZ, KZC, k_xc)
        assert v12 == pytest.approx(v14, rel=2 * eps)


def test_critical_velocity_special_points() -> None:
    # case IV: infinite; case III: zero; no oscillation: zero
    assert theory.critical_velocity(MU0, W, DUZ, KZC, MW2, MW2, M) == math.inf
    assert theory.critical_velocity(MU0, W, DUZ, KZC, 0.25 * MW2, 0.75 * MW2, M) == 0.0
    assert theory.critical_velocity(MU0, W, 0.0, KZC, MW2, MW2, M) == 0.0
    # rigid contact: mu0 omega du_z k_zc / |k_x - m omega^2|
    rigid = theory.critical_velocity(MU0, W, DUZ, KZC, math.inf, 3.0 * MW2, M)
    assert rigid == pytest.approx(MU0 * W * DUZ * KZC / (2.0 * MW2), rel=1e-14)
    # vectorised over k_xc
    v = theory.critical_velocity(MU0, W, DUZ, KZC, np.array([1.0, 1e3, math.inf]) * MW2,
                                 0.5 * MW2, M)
    assert v.shape == (3,)
    assert v[2] == pytest.approx(MU0 * W * DUZ * KZC / (0.5 * MW2), rel=1e-14)


def test_critical_velocity_rejects() -> None:
    with pytest.raises(ValueError, match=r"k_xc must be > 0 \(math.inf allowed\), got 0.0"):
        theory.critical_velocity(MU0, W, DUZ, KZC, 0.0, MW2, M)
    with pytest.raises(ValueError, match=r"mass must be finite and > 0, got -1.0"):
        theory.critical_velocity(MU0, W, DUZ, KZC, MW2, MW2, -1.0)


def test_critical_inertial_velocity_matches_eq12() -> None:
    """c * mu0 F_N0 / (m omega) is v0* of eq. (12)."""
    u_z0 = 4.0 * DUZ
    unit = MU0 * KZC * u_z0 / (M * W)
    for k_x, k_xc in [(0.3, 2.0), (2.0, 0.01), (0.01, 400.0), (5.0, math.inf)]:
        alpha, beta = k_x, k_x + k_xc
        c = theory.critical_inertial_velocity(alpha, beta, DUZ / u_z0)
        v = theory.critical_velocity(MU0, W, DUZ, KZC, k_xc * MW2, k_x * MW2, M)
        assert c * unit == pytest.approx(v, rel=1e-12)


def test_critical_inertial_velocity_limits() -> None:
    a = 0.7
    assert theory.critical_inertial_velocity(0.5, math.inf, a) == pytest.approx(a / 0.5)
    assert theory.critical_inertial_velocity(0.5, 1e12, a) == pytest.approx(a / 0.5, rel=1e-11)
    assert theory.critical_inertial_velocity(1e-9, 1e9, a) == pytest.approx(a, rel=1e-8)  # eq. (13)
    assert theory.critical_inertial_velocity(1.0, 2.0, a) == math.inf
    assert theory.critical_inertial_velocity(0.5, 1.0, a) == 0.0
    assert theory.critical_inertial_velocity(1.0, 2.0, 0.0) == 0.0
    with pytest.raises(ValueError, match=r"beta must be > alpha \(= 0.5\) or math.inf, got 0.3"):
        theory.critical_inertial_velocity(0.5, 0.3, a)
    with pytest.raises(ValueError, match="beta must be > alpha"):
        theory.critical_inertial_velocity(0.5, math.nan, a)


# --------------------------------------------------------------------------- eqs. (7)-(10)
STEADY_CASES = [(0.01, 0.02, 0.5), (0.01, 400.01, 1.0), (0.3, 0.9, 0.8), (2.5, 7.0, 0.2),
                (0.5, 1.0, 0.4), (0.7, math.inf, 0.6), (1.4, 1.5, 1.0)]


@pytest.mark.parametrize(("alpha", "beta", "a"), STEADY_CASES)
def test_steady_sliding_solves_slip_ode(alpha: float, beta: float, a: float) -> None:
    """x'' + alpha x = alpha V tau - (1 + a cos tau), x' = dx/dtau, x_c' = x' - f'/(beta-alpha)."""
    V, h = 1.7, 1e-4
    tau = np.linspace(0.0, TWO_PI, 41)

    def x(t):
        return V * t + theory.steady_sliding(t, alpha, beta, a, V).y

    s = theory.steady_sliding(tau, alpha, beta, a, V)
    xpp = (x(tau + h) - 2 * x(tau) + x(tau - h)) / h**2
    residual = xpp + alpha * x(tau) - (alpha * V * tau - (1.0 + a * np.cos(tau)))
    scale = 1.0 + a / abs(1.0 - alpha)
    assert np.max(np.abs(residual)) < 1e-5 * scale * max(1.0, alpha)
    xp = (x(tau + h) - x(tau - h)) / (2 * h)
    np.testing.assert_allclose(s.velocity, xp, atol=1e-7 * scale)
    if math.isinf(beta):
        np.testing.assert_array_equal(s.contact_velocity, s.velocity)
    else:
        fp = -a * np.sin(tau)  # f = n(tau) in slip
        np.testing.assert_allclose(s.contact_velocity, s.velocity - fp / (beta - alpha),
                                   atol=1e-12 * scale)


def test_steady_sliding_matches_dimensional_eq10() -> None:
    """Scaled x_c' times mu0 F_N0/(m omega) is eq. (10) as printed."""
    k_x, k_xc, u_z0, v0 = 0.4 * MW2, 3.0 * MW2, 2.0e-6, 0.02
    t = np.linspace(0.0, 3.0 / 800.0, 17)
    paper = v0 - KZC / k_xc * (k_xc + k_x - MW2) / (MW2 - k_x) * MU0 * W * DUZ * np.sin(W * t)
    paper_body = v0 - MU0 * KZC * DUZ / (MW2 - k_x) * W * np.sin(W * t)  # eq. (8)
    unit = MU0 * KZC * u_z0 / (M * W)
    s = theory.steady_sliding(W * t, k_x / MW2, (k_x + k_xc) / MW2, DUZ / u_z0, v0 / unit)
    np.testing.assert_allclose(np.asarray(s.contact_velocity) * unit, paper, rtol=1e-12)
    np.testing.assert_allclose(np.asarray(s.velocity) * unit, paper_body, rtol=1e-12)


@pytest.mark.parametrize(("alpha", "beta", "a"), [c for c in STEADY_CASES if c[1] != 1.0])
def test_contact_velocity_threshold_is_vbar_one(alpha: float, beta: float, a: float) -> None:
    """x_c' > 0 for vbar > 1, min exactly 0 at vbar = 1 (eqs. 11-12)."""
    c = theory.critical_inertial_velocity(alpha, beta, a)
    tau = np.concatenate([np.linspace(0.0, TWO_PI, 2001), [0.5 * math.pi, 1.5 * math.pi]])
    at_one = np.asarray(theory.steady_sliding(tau, alpha, beta, a, c).contact_velocity)
    assert np.min(at_one) == pytest.approx(0.0, abs=1e-12 * c)
    assert np.min(at_one) >= -1e-12 * c
    above = theory.steady_sliding(tau, alpha, beta, a, 1.001 * c).contact_velocity
    assert np.min(above) > 0.0
    below = theory.steady_sliding(tau, alpha, beta, a, 0.999 * c).contact_velocity
    assert np.min(below) < 0.0


def test_steady_sliding_domain() -> None:
    with pytest.raises(ValueError, match="alpha must differ from 1"):
        theory.steady_sliding(0.0, 1.0, 2.0, 0.5, 1.0)
    with pytest.raises(ValueError, match=r"amplitude must be finite and in \[0, 1\], got 1.5"):
        theory.steady_sliding(0.0, 0.5, 2.0, 1.5, 1.0)
    with pytest.raises(ValueError, match=r"alpha must be finite and > 0, got 0.0"):
        theory.steady_sliding(0.0, 0.0, 2.0, 0.5, 1.0)
    s = theory.steady_sliding(0.3, 0.5, 2.0, 0.5, 1.0)
    assert all(isinstance(v, float) for v in s)


# --------------------------------------------------------------------------- eqs. (26), (27)
LAWS = [theory.mu_ratio_stiff, theory.mu_ratio_soft]
AMPS = [0.2, 0.4, 0.6, 0.8, 1.0]  # Fig. 4


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("a", AMPS)
def test_laws_end_points_and_monotone(law, a: float) -> None:
    assert law(0.0, a) == pytest.approx(theory.static_mu_ratio(a), abs=1e-15)
    assert law(1.0, a) == 1.0
    assert law(np.array([1.0, 1.5, 1e6, math.inf]), a).tolist() == [1.0] * 4
    v = np.linspace(0.0, 1.0, 2001)
    mu = law(v, a)
    assert np.all(np.diff(mu) > 0.0)  # strictly increasing below vbar = 1
    assert np.all(mu <= 1.0)
    assert law(1.0 - 1e-12, a) == pytest.approx(1.0, abs=1e-10)  # continuous at vbar = 1


def test_soft_law_slope_and_exponent() -> None:
    """Eq. (27) with p = 1.2 is monotone (slope 0.964 a at vbar = 1); p > 6.5 would not be."""
    c = math.sqrt(4 * math.pi / 9)
    a, h = 0.6, 1e-7
    slope = (theory.mu_ratio_soft(1 - h, a) - theory.mu_ratio_soft(1 - 2 * h, a)) / h
    assert slope == pytest.approx(a * (c + (1 - c) * 1.2), rel=1e-5)
    assert a * (c + (1 - c) * 1.2) == pytest.approx(0.9637 * a, rel=1e-4)
    v = np.linspace(0.0, 1.0, 2001)
    assert np.any(np.diff(theory.mu_ratio_soft(v, a, exponent=8.0)) < 0.0)
    assert np.all(np.diff(theory.mu_ratio_soft(v, a, exponent=6.0)) > 0.0)
    # stiff law joins 1 with zero slope
    stiff_slope = (theory.mu_ratio_stiff(1.0, a) - theory.mu_ratio_stiff(1 - h, a)) / h
    assert abs(stiff_slope) < 1e-5


@pytest.mark.parametrize("law", LAWS)
def test_laws_refuse_jumping_and_bad_velocity(law) -> None:
    with pytest.raises(ValueError, match=r"amplitude must be finite and in \[0, 1\], got 1.5"):
        law(0.5, 1.5)
    with pytest.raises(ValueError, match=r"vbar must be >= 0 \(math.inf allowed\), got -1.0"):
        law(-1.0, 0.5)


# --------------------------------------------------------------------------- jumping
@pytest.mark.parametrize("a", [0.0, 0.5, 1.0, 1.0 + 1e-9, 1.2, 1.5, 3.0, 20.0])
def test_mean_normal_force_by_quadrature(a: float) -> None:
    breaks = [math.acos(-1 / a), -math.acos(-1 / a)] if a > 1 else []
    expected = period_mean(lambda t: n_of(t, a), breaks)
    assert theory.mean_normal_force(a) == pytest.approx(expected, rel=1e-11)
    assert theory.mean_normal_force_of(a) == pytest.approx(expected, rel=1e-11)


def test_mean_normal_force_shape() -> None:
    a = np.array([0.3, 1.0, 2.0, 1e8])
    n = theory.mean_normal_force(a)
    assert n[:2].tolist() == [1.0, 1.0]
    assert n[3] == pytest.approx(1e8 / math.pi, rel=1e-7)  # half-wave rectified cosine


@pytest.mark.parametrize("a", [1.0, 1.01, 1.5, 4.0])
def test_liftoff_phases(a: float) -> None:
    off, on = theory.liftoff_phases(a)
    assert 0.5 * math.pi < off <= math.pi <= on < 1.5 * math.pi
    for t in (off, on):
        assert 1 + a * math.cos(t) == pytest.approx(0.0, abs=1e-14)
    # n decreases through 0 at tau_off, increases at tau_on
    assert -a * math.sin(off) <= 1e-15 and -a * math.sin(on) >= -1e-15


def test_liftoff_without_jumping_is_nan() -> None:
    off, on = theory.liftoff_phases(np.array([0.0, 0.5, 2.0]))
    assert np.isnan(off[:2]).all() and np.isnan(on[:2]).all()
    assert off[2] == pytest.approx(2 * math.pi / 3)
    assert on[2] == pytest.approx(4 * math.pi / 3)


# --------------------------------------------------------------------------- case IV
def energy_balance(r: float, a: float) -> float:
    """<n cos tau sign(r - cos tau)> by quadrature (first eq. (32))."""
    ts = math.acos(r)
    breaks = [ts, -ts] + ([math.acos(-1 / a), -math.acos(-1 / a)] if a > 1 else [])
    return period_mean(lambda t: n_of(t, a) * math.cos(t) * math.copysign(1.0, r - math.cos(t)),
                       breaks)


RES_AMPS = [0.01, 0.2, 0.5, 1.0, 1.5, 3.0]


@pytest.mark.parametrize("a", RES_AMPS)
def test_resonant_velocity_ratio_solves_energy_balance(a: float) -> None:
    r = theory.resonant_velocity_ratio_exact(a)
    assert 0.0 < r < 1.0
    assert abs(energy_balance(r, a)) < 1e-12
    d = 1e-6
    assert energy_balance(r - d, a) < 0.0 < energy_balance(min(r + d, 1.0), a)


@pytest.mark.parametrize("a", RES_AMPS)
def test_resonant_plateau_exact_by_quadrature(a: float) -> None:
    r = theory.resonant_velocity_ratio_exact(a)
    ts = math.acos(r)
    breaks = [ts, -ts] + ([math.acos(-1 / a), -math.acos(-1 / a)] if a > 1 else [])
    num = period_mean(lambda t: n_of(t, a) * math.copysign(1.0, r - math.cos(t)), breaks)
    den = period_mean(lambda t: n_of(t, a), breaks)
    assert theory.resonant_plateau_exact(a) == pytest.approx(num / den, rel=1e-11)


def test_resonant_plateau_numbers() -> None:
    """Exact energy-balance plateau vs the paper's 1 - a/2 and vs the solver (case IV)."""
    from scipy.optimize import brentq

    for a in (0.2, 0.5, 1.0):
        # independent: root of the energy balance by quadrature, then the mean friction
        r = brentq(lambda x, a=a: energy_balance(x, a), 1e-9, 1 - 1e-12, xtol=1e-14)
        ts = math.acos(r)
        plateau = period_mean(lambda t, a=a, r=r: n_of(t, a) * math.copysign(1.0, r - math.cos(t)),
                              [ts, -ts]) / period_mean(lambda t, a=a: n_of(t, a))
        assert theory.resonant_plateau_exact(a) == pytest.approx(plateau, abs=1e-10)
        # the paper's small-amplitude law 1 - a/2 (eqs. 32) overestimates it
        assert theory.resonant_plateau(a) == 1.0 - a / 2
        assert plateau < 1.0 - a / 2
        # and the exact solver reaches it at a large inertial velocity (Fig. 6)
        import vibrofriction as vf
        res = vf.friction_coefficient(vf.Dimensionless(1.0, math.inf, a), v_inertial=30.0)
        assert res.trusted and abs(res.mu_ratio - plateau) < 2e-3


@pytest.mark.parametrize("a", [1e-4, 1e-3, 1e-2, 0.05, 0.1, 0.2])
def test_resonant_small_amplitude_limit(a: float) -> None:
    """The paper's approximations are the small-a limits of the exact balance."""
    exact = theory.resonant_plateau_exact(a)
    # series of the balance: tau* = pi a/4 - pi a^2/4 + (pi/4 + pi^3/384) a^3 + ..., so
    # mu/mu0 = 1 - a/2 - (pi^2/192) a^3 + O(a^4): the paper's 1 - a/2 is exact to O(a^2)
    third = math.pi**2 / 192 * a**3
    assert abs(exact - (1 - a / 2 + -third)) < 0.5 * a**4 + 1e-15
    assert abs(exact - (1 - a / 2)) < 1.01 * third
    r_exact = theory.resonant_velocity_ratio_exact(a)
    r_paper = theory.resonant_velocity_ratio(a)
    assert abs(r_paper - r_exact) < 0.05 * a**3
    ts = theory.resonant_tau_star(r_exact)
    assert ts == pytest.approx(math.pi * a / (4 * (1 + a)), rel=0.2 * a)
    assert theory.resonant_tau_star(r_exact, approximate=True) == pytest.approx(ts, rel=0.1 * a)


def test_resonant_jumping_continuity_and_limit() -> None:
    for func in (theory.resonant_plateau, theory.resonant_plateau_exact,
                 theory.resonant_velocity_ratio, theory.resonant_velocity_ratio_exact):
        assert func(1.0 + 1e-10) == pytest.approx(func(1.0), abs=1e-6)
    assert theory.resonant_plateau(1e9) == pytest.approx(1 - math.pi / 4, abs=1e-6)
    a = np.linspace(0.0, 10.0, 101)
    p = theory.resonant_plateau_exact(a)
    assert np.all(np.diff(p) < 0.0) and np.all(p > 0.0)
    assert theory.resonant_plateau_exact(0.0) == 1.0
    assert theory.resonant_velocity_ratio_exact(0.0) == 1.0


def test_resonant_tau_star_domain() -> None:
    assert theory.resonant_tau_star(1.0) == 0.0
    assert theory.resonant_tau_star(0.0) == pytest.approx(math.pi / 2)
    assert theory.resonant_tau_star(0.98, approximate=True) == pytest.approx(0.2)
    with pytest.raises(ValueError, match=r"v_ratio must be finite and in \[-1, 1\], got 1.5"):
        theory.resonant_tau_star(1.5)


# --------------------------------------------------------------------------- vectorisation
@settings(max_examples=40, deadline=None)
@given(
    alpha=st.floats(0.01, 10.0),
    gap=st.floats(1e-3, 1e3),
    a=st.floats(0.0, 1.0),
    vbar=st.floats(1.0, 5.0),
)
def test_steady_sliding_contact_never_reverses_above_critical(
    alpha: float, gap: float, a: float, vbar: float
) -> None:
    if abs(alpha - 1.0) < 1e-6 or abs(alpha + gap - 1.0) < 1e-9:
        return
    c = theory.critical_inertial_velocity(alpha, alpha + gap, a)
    tau = np.linspace(0.0, TWO_PI, 257)
    s = theory.steady_sliding(tau, alpha, alpha + gap, a, vbar * c)
    assert np.min(s.contact_velocity) >= -1e-9 * max(c, 1.0)


def test_array_in_array_out() -> None:
    a = np.array([[0.1, 0.5], [1.0, 2.0]])
    for func in (theory.static_mu_ratio, theory.mean_normal_force, theory.resonant_plateau,
                 theory.resonant_plateau_exact, theory.resonant_velocity_ratio,
                 theory.resonant_velocity_ratio_exact):
        out = func(a)
        assert isinstance(out, np.ndarray) and out.shape == a.shape
        assert func(a[1, 1]) == pytest.approx(out[1, 1], rel=1e-15)
