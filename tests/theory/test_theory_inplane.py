"""Closed forms of the in-plane oscillation (docs/inplane.md), each checked against a
direct evaluation or an integration of its own ODE written here (scipy's solve_ivp):
no call to the package's kernels, which have no in-plane physics."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import minimize_scalar

from vibrofriction import theory

TWO_PI = 2.0 * math.pi


# ------------------------------------------------------------------ kinematic laws
@pytest.mark.parametrize("v, a_x", [(0.1, 1.0), (0.5, 1.0), (0.99, 1.0), (-0.3, 0.7),
                                    (2.0, 1.0), (-3.0, 1.0), (0.0, 1.0), (0.25, 4.0)])
def test_kinematic_longitudinal_is_the_mean_of_the_sign_of_the_slip_velocity(v, a_x):
    # the body at v, the substrate at -a_x sin(theta): friction opposes v + a_x sin(theta)
    def slip_sign(theta: float) -> float:
        return float(np.sign(v + a_x * math.sin(theta)))

    roots = []  # where the slip velocity changes sign: break points of the quadrature
    if abs(v) < a_x:
        roots = [math.asin(-v / a_x) % TWO_PI, (math.pi + math.asin(v / a_x)) % TWO_PI]
    mean = quad(slip_sign, 0.0, TWO_PI, points=roots or None, limit=200)[0] / TWO_PI
    assert theory.kinematic_mu_longitudinal(v, a_x) == pytest.approx(mean, abs=1e-10)


@pytest.mark.parametrize("v, a_y", [(0.05, 1.0), (0.3, 1.0), (1.0, 1.0), (3.0, 1.0),
                                    (-0.7, 2.0), (10.0, 0.5)])
def test_kinematic_transverse_is_the_mean_friction_along_the_sliding(v, a_y):
    # slip velocity (v, a_y sin theta): the component of -w/|w| along x, averaged
    mean = quad(lambda t: v / math.hypot(v, a_y * math.sin(t)), 0.0, TWO_PI,
                limit=200, epsabs=1e-13)[0] / TWO_PI
    assert theory.kinematic_mu_transverse(v, a_y) == pytest.approx(mean, abs=1e-10)


def test_kinematic_laws_limits():
    lon = theory.kinematic_mu_longitudinal(np.array([-1.0, 0.0, 1.0]), 0.0)
    assert list(lon) == [-1.0, 0.0, 1.0]  # no oscillation: Coulomb
    assert theory.kinematic_mu_transverse(2.0, 0.0) == 1.0
    assert theory.kinematic_mu_transverse(0.0, 1.0) == 0.0
    # large v: 1 - eps^2/4; small v: (2/pi) eps^-1 ln(4 eps)
    assert theory.kinematic_mu_transverse(100.0, 1.0) == pytest.approx(1 - 1e-4 / 4, abs=1e-8)
    small = theory.kinematic_mu_transverse(1e-4, 1.0)
    assert small == pytest.approx(2 / math.pi * 1e-4 * math.log(4e4), rel=1e-6)
    # no critical velocity across, one along
    assert theory.kinematic_mu_transverse(5.0, 1.0) < 1.0
    assert theory.kinematic_mu_longitudinal(1.0, 1.0) == 1.0
    with pytest.raises(ValueError, match="a_x must be"):
        theory.kinematic_mu_longitudinal(1.0, -1.0)


# ------------------------------------------------------------------ periodic orbits
def _periodic(rhs, dim: int) -> np.ndarray:
    """The periodic orbit's initial state of a linear 2 pi-periodic ODE, by shooting: the
    period map is affine, z(2 pi) = M z0 + b, so z0 = (I - M)^-1 b."""
    def period(z0):
        return solve_ivp(rhs, (0.0, TWO_PI), z0, method="DOP853", rtol=1e-12,
                         atol=1e-13).y[:, -1]

    b = period(np.zeros(dim))
    m = np.column_stack([period(np.eye(dim)[i]) - b for i in range(dim)])
    return np.linalg.solve(np.eye(dim) - m, b)


def _sampled(rhs, z0, out, samples: int = 2048):
    """``out(tau, z)`` on a uniform grid over one period of the orbit from ``z0``."""
    tau = np.linspace(0.0, TWO_PI, samples, endpoint=False)
    sol = solve_ivp(rhs, (0.0, TWO_PI), z0, method="DOP853", rtol=1e-12, atol=1e-13,
                    t_eval=tau)
    return tau, out(tau, sol.y)


def _harmonic(tau, g):
    """Complex amplitude ``C`` of ``g = mean + Re(C e^{i tau})`` and the residual."""
    c = 2.0 * np.mean(g * np.exp(-1j * tau))
    fit = np.mean(g) + np.real(c * np.exp(1j * tau))
    return c, float(np.max(np.abs(g - fit)))


def _slip_velocity_amplitude(alpha, beta, a, zeta, eta_c, a_x, phase, on, sign=1.0):
    """Integrate permanent slip (f = sign n; forward for sign = 1) to its periodic state
    and return the amplitude of the oscillating part of the slip velocity w - V, from its
    extreme value towards a reversal and from its first harmonic."""
    gamma = 2.0 * zeta * math.sqrt(alpha)
    k = beta - alpha
    rigid, relaxing = math.isinf(beta), (not math.isinf(beta)) and eta_c > 0

    def forcing(tau):  # the holder's pull on the body
        if on != "holder":
            return 0.0
        return (alpha * a_x * np.cos(tau + phase) - gamma * a_x * np.sin(tau + phase))

    def rhs(tau, z):
        n = sign * (1.0 + a * np.cos(tau))
        acc = -gamma * z[1] - alpha * z[0] - n + forcing(tau)
        if relaxing:
            return [z[1], acc, (n / k - z[2]) / eta_c]
        return [z[1], acc]

    dim = 3 if relaxing else 2
    z0 = _periodic(rhs, dim)

    def slip(tau, z):  # w - V = y' - e' - (substrate velocity)
        n = sign * (1.0 + a * np.cos(tau))
        if rigid:
            e_dot = 0.0
        elif relaxing:
            e_dot = (n / k - z[2]) / eta_c
        else:
            e_dot = -sign * a * np.sin(tau) / k
        sub = -a_x * np.sin(tau + phase) if on == "substrate" else 0.0
        return z[1] - e_dot - sub

    tau, w = _sampled(rhs, z0, slip)
    c, residual = _harmonic(tau, w)
    assert abs(np.mean(w)) < 1e-9 and residual < 1e-9  # V plus a pure harmonic
    return -float(np.min(sign * w)), abs(c)


CRITICAL_POINTS = [
    # alpha, beta, a, zeta, eta_c, a_x, phase_x, inplane_on
    (0.5, 2.0, 0.5, 0.0, 0.0, 0.5, math.pi / 2, "substrate"),
    (0.5, 2.0, 0.5, 0.0, 0.0, 0.5, math.pi / 2, "holder"),
    (0.2, 5.0, 0.8, 0.05, 0.0, 0.3, 1.0, "substrate"),
    (2.0, 3.5, 1.0, 0.1, 0.3, 0.7, 2.5, "substrate"),
    (2.0, 3.5, 1.0, 0.1, 0.3, 0.7, 2.5, "holder"),
    (0.01, 400.01, 0.5, 0.02, 0.1, 0.4, 4.0, "substrate"),
    (3.0, math.inf, 0.6, 0.2, 0.0, 0.25, 5.5, "holder"),
    (0.8, math.inf, 0.3, 0.0, 0.0, 1.2, 0.3, "substrate"),
    (0.2, 1.0, 0.5, 0.0, 0.2, 0.1, 3.0, "holder"),
    (1.0, 2.0, 0.5, 0.05, 0.0, 0.5, 0.7, "holder"),
]


@pytest.mark.parametrize("point", CRITICAL_POINTS)
def test_inplane_critical_velocity_is_the_amplitude_of_the_sliding_solution(point):
    alpha, beta, a, zeta, eta_c, a_x, phase, on = point
    low, amp = _slip_velocity_amplitude(alpha, beta, a, zeta, eta_c, a_x, phase, on)
    vc = theory.inplane_critical_velocity(alpha, beta, a, a_x, phase, zeta, eta_c, on)
    assert vc == pytest.approx(amp, rel=1e-8, abs=1e-10)
    assert vc == pytest.approx(low, rel=2e-6)  # the sampled minimum of the harmonic


@pytest.mark.parametrize("point", CRITICAL_POINTS[:6])
def test_backward_sliding_needs_the_critical_velocity_of_the_opposite_phase(point):
    alpha, beta, a, zeta, eta_c, a_x, phase, on = point
    low, amp = _slip_velocity_amplitude(alpha, beta, a, zeta, eta_c, a_x, phase, on, -1.0)
    vc = theory.inplane_critical_velocity(alpha, beta, a, a_x, phase + math.pi, zeta, eta_c,
                                          on)
    assert vc == pytest.approx(amp, rel=1e-8) and vc == pytest.approx(low, rel=2e-6)


def test_zero_inplane_amplitude_gives_the_normal_only_critical_velocity():
    rng = np.random.default_rng(20)
    alpha = rng.uniform(0.01, 5.0, 200)
    beta = alpha + rng.uniform(0.01, 10.0, 200)
    a, zeta, eta = rng.uniform(0, 1, 200), rng.uniform(0, 0.5, 200), rng.uniform(0, 1, 200)
    beta[:20] = np.inf
    zeta[20:40] = 0.0
    for on in theory.INPLANE_ON:
        got = theory.inplane_critical_velocity(alpha, beta, a, 0.0, rng.uniform(0, 7, 200),
                                               zeta, eta, on)
        np.testing.assert_allclose(got, theory.critical_inertial_velocity(alpha, beta, a,
                                                                          zeta, eta),
                                   rtol=1e-13, atol=1e-15)
    # and the resonance, the contact resonance, no oscillation at all
    assert theory.inplane_critical_velocity(1.0, 2.0, 0.5, 0.0, 0.0) == math.inf
    assert theory.inplane_critical_velocity(0.2, 1.0, 0.5, 0.0, 0.0) == 0.0
    assert theory.inplane_critical_velocity(0.2, 1.0, 0.0, 0.0, 1.0) == 0.0


@pytest.mark.parametrize("on", ["substrate", "holder"])
@pytest.mark.parametrize("system", [(0.5, 2.0, 0.5, 0.0, 0.0), (0.3, 4.0, 0.8, 0.1, 0.2),
                                    (2.0, 3.0, 0.6, 0.05, 0.5)])
@pytest.mark.slow
def test_the_cancelling_phase_minimises_the_integrated_amplitude(system, on):
    alpha, beta, a, zeta, eta_c = system
    cancel = theory.inplane_cancellation(alpha, beta, a, zeta, eta_c, on)
    a_x = 0.5 * cancel.a_x

    def amplitude(phase):
        return _slip_velocity_amplitude(alpha, beta, a, zeta, eta_c, a_x, phase, on)[1]

    best = minimize_scalar(amplitude, bracket=(cancel.phase_x - 0.3, cancel.phase_x + 0.3),
                           tol=1e-10)
    assert (best.x - cancel.phase_x + math.pi) % TWO_PI - math.pi == pytest.approx(0.0, abs=1e-4)
    vc0 = theory.critical_inertial_velocity(alpha, beta, a, zeta, eta_c)
    assert best.fun == pytest.approx(0.5 * vc0, rel=1e-7)  # |a|B| - a_x|G|| = a|B|/2
    worst = amplitude(cancel.phase_x + math.pi)
    assert worst == pytest.approx(1.5 * vc0, rel=1e-7)  # a|B| + a_x|G|
    # at the cancelling amplitude the sliding solution's slip velocity is constant: V_c = 0
    assert _slip_velocity_amplitude(alpha, beta, a, zeta, eta_c, cancel.a_x, cancel.phase_x,
                                    on)[1] < 1e-8


def test_undamped_cancellation_is_in_or_against_phase():
    # B, G real undamped: soft case I (alpha < 1 < beta) cancels at 0 on the substrate
    assert theory.inplane_cancellation(0.01, 400.01, 0.5).phase_x == 0.0
    assert theory.inplane_cancellation(2.0, 4.0, 0.5).phase_x == pytest.approx(math.pi)
    # holder, rigid contact: B = 1/P, G = alpha/P, phase 0, a_x = a/alpha
    c = theory.inplane_cancellation(3.0, math.inf, 0.6, inplane_on="holder")
    assert c.phase_x == 0.0 and c.a_x == pytest.approx(0.2)


# ------------------------------------------------------------------ static friction
def _quasi_static_static(q: float, a: float, phase: float, kv: float = 2e-5,
                         steps: int = 4000, periods: int = 3) -> float:
    """mu(V -> 0+) of a heavy body (fixed on the drive's time scale, creeping at V) on a
    contact spring k over a substrate moving as a_x cos(tau + phase): the play operator
    f = k(x - x_c), |f| <= n, x_c with the substrate in stick. q = k a_x, kv = k V.
    Starts at the top of the cone (above the stuck band, so the first cycle slips down to
    its upper edge, as a sliding start would); returns <f>/<n> over the last period."""
    dt = TWO_PI / steps
    f, sf, sn = 1.0 + a, 0.0, 0.0
    s_prev = q * math.cos(phase)
    for i in range(periods * steps):
        tau = (i + 1) * dt
        s = q * math.cos(tau + phase)  # k times the substrate position
        n = 1.0 + a * math.cos(tau)
        f = min(max(f + kv * dt - (s - s_prev), -n), n)  # stick, else slip at the cone
        s_prev = s
        if i >= (periods - 1) * steps:
            sf += f
            sn += n
    return sf / sn


@pytest.mark.parametrize("q, a, phase", [(0.3, 0.0, 0.0), (0.8, 0.0, 1.0), (0.3, 0.5, 0.0),
                                         (0.3, 0.5, math.pi), (0.4, 0.6, 2.0),
                                         (0.5, 0.4, 4.0)])
def test_quasi_static_static_friction_is_one_minus_the_cone_shift(q, a, phase):
    k = 1e-5  # heavy limit: alpha, beta -> 0, T -> k
    upper, lower = theory.inplane_static_mu_ratio(0.0, k, a, q / k, phase)
    assert upper == pytest.approx(1.0 - abs(a + q * np.exp(1j * phase)), abs=2e-5)
    assert upper == pytest.approx(_quasi_static_static(q, a, phase), abs=2e-4)  # O(k V)


def test_quasi_static_pure_inplane_oscillation_above_the_intrinsic_length():
    # k a_x > 1: the contact slips both ways every cycle, the loop is symmetric: mu(0+) -> 0
    assert abs(_quasi_static_static(1.5, 0.0, 0.0)) < 1e-4
    assert math.isnan(theory.inplane_static_mu_ratio(0.0, 1e-5, 0.0, 1.5e5, 0.0).upper)


@pytest.mark.parametrize("point", [
    (0.5, 2.0, 0.5, 0.0, 0.0, 0.5, math.pi / 2, "substrate"),
    (0.5, 2.0, 0.5, 0.1, 0.3, 0.2, 1.0, "substrate"),
    (2.0, 5.0, 0.3, 0.05, 0.0, 0.1, 2.0, "holder"),
    (0.1, 0.6, 0.4, 0.2, 0.5, 0.3, 5.0, "holder"),
    (3.0, math.inf, 0.2, 0.1, 0.0, 0.1, 0.5, "holder"),
    (0.3, math.inf, 0.2, 0.0, 0.0, 0.2, 3.5, "substrate"),
])
def test_static_bounds_are_those_of_the_integrated_stuck_orbit(point):
    alpha, beta, a, zeta, eta_c, a_x, phase, on = point
    gamma = 2.0 * zeta * math.sqrt(alpha)
    rigid = math.isinf(beta)
    k = 0.0 if rigid else beta - alpha
    c = eta_c * k

    def sub(tau):  # substrate position and velocity
        if on != "substrate":
            return 0.0, 0.0
        return a_x * np.cos(tau + phase), -a_x * np.sin(tau + phase)

    def hold(tau):
        if on != "holder":
            return 0.0, 0.0
        return a_x * np.cos(tau + phase), -a_x * np.sin(tau + phase)

    if rigid:  # the body moves with the contact point, i.e. with the substrate
        def contact_force(tau, _z):
            s, sd = sub(tau)
            h, hd = hold(tau)
            sdd = -(s if on == "substrate" else 0.0)
            return alpha * (h - s) + gamma * (hd - sd) - sdd
        tau = np.linspace(0.0, TWO_PI, 2048, endpoint=False)
        f = contact_force(tau, None)
    else:
        def rhs(tau, z):
            s, sd = sub(tau)
            h, hd = hold(tau)
            f = k * (z[0] - s) + c * (z[1] - sd)
            return [z[1], alpha * (h - z[0]) + gamma * (hd - z[1]) - f]

        def contact_force(tau, z):
            s, sd = sub(tau)
            return k * (z[0] - s) + c * (z[1] - sd)

        tau, f = _sampled(rhs, _periodic(rhs, 2), contact_force)
    f = f - np.mean(f)  # the mean is the holder's static pull F
    n = 1.0 + a * np.cos(tau)
    upper, lower = np.min(n - f), np.max(-n - f)  # |F + f| <= n throughout
    got = theory.inplane_static_mu_ratio(alpha, beta, a, a_x, phase, zeta, eta_c, on)
    assert got.upper == pytest.approx(upper, abs=2e-6)
    assert got.lower == pytest.approx(lower, abs=2e-6)


def test_static_reduces_to_eq2_and_refuses_where_no_stick_exists():
    a = np.linspace(0.0, 1.0, 11)
    got = theory.inplane_static_mu_ratio(0.5, 2.0, a, 0.0, 0.0, 0.1, 0.1, "holder")
    np.testing.assert_allclose(got.upper, theory.static_mu_ratio(a), atol=1e-15)
    np.testing.assert_allclose(got.lower, -np.asarray(theory.static_mu_ratio(a)), atol=1e-15)
    assert math.isnan(theory.inplane_static_mu_ratio(0.5, 2.0, 1.2, 0.0, 0.0).upper)
    # contact resonance without in-plane oscillation: still eq. (2)
    assert theory.inplane_static_mu_ratio(0.5, 1.0, 0.5, 0.0, 0.0).upper == 0.5
    with pytest.raises(ValueError, match="inplane_on"):
        theory.inplane_static_mu_ratio(0.5, 2.0, 0.5, 0.1, 0.0, inplane_on="disk")
