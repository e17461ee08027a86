"""Closed forms beyond the paper (docs/damping.md): the exact law of the stiff limit and
the rise of case IV to mu0 with a damped pin, each against the solver and by hand."""

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import solver, theory


def _quasi_static_stiff(vbar: float, a: float, steps: int = 200_000) -> float:
    """Brute force of the stiff limit: the contact spring pulled at the constant rate
    k V = a vbar (stick) with |f| <= n, f = n in forward slip; periods 1-3 averaged."""
    dt = 2 * math.pi / steps
    f = 1.0
    sf = sn = 0.0
    for i in range(4 * steps):
        tau = (i + 1) * dt
        n = 1.0 + a * math.cos(tau)
        f = min(f + a * vbar * dt, n)  # stick until the cone, then slide with f = n
        if i >= steps:
            sf += f
            sn += n
    return sf / sn


@pytest.mark.parametrize("vbar, a", [(0.05, 1.0), (0.3, 0.5), (0.6, 0.8), (0.95, 0.3)])
def test_stiff_exact_law_matches_a_brute_force_quasi_static_contact(vbar, a):
    assert theory.mu_ratio_stiff_exact(vbar, a) == pytest.approx(
        _quasi_static_stiff(vbar, a), abs=2e-4)


def test_stiff_exact_law_limits_and_its_distance_to_eq26():
    vb = np.linspace(0.0, 1.0, 401)
    for a in (0.25, 0.5, 1.0):
        ex = theory.mu_ratio_stiff_exact(vb, a)
        assert ex[0] == pytest.approx(1.0 - a, abs=1e-12) and ex[-1] == 1.0
        assert np.all(np.diff(ex) >= -1e-12)
        dev = np.abs(ex - theory.mu_ratio_stiff(vb, a))
        # eq. (26) is a fit: off by at most 0.0144 a, near vbar = 0.1
        assert np.max(dev) == pytest.approx(0.0144 * a, rel=0.02)
        assert 0.08 <= vb[np.argmax(dev)] <= 0.13
    assert theory.mu_ratio_stiff_exact(1.3, 0.5) == 1.0


@pytest.mark.parametrize("a", [0.5, 1.0])
def test_solver_tends_to_the_stiff_exact_law(a):
    """At (alpha, beta) = (1e-4, 2e-4) the solver is within 1e-5 of the law; the distance
    shrinks like alpha (7e-4, 7e-5, 7e-6 at alpha = 1e-2, 1e-3, 1e-4 for a = 1)."""
    vb = np.array([0.1, 0.3, 0.5, 0.7, 0.9])
    V = vf.Dimensionless(1e-4, 2e-4, a).vbar_to_inertial(vb)
    out = solver.solve_points(1e-4, 2e-4, a, V)
    assert np.all(out["trusted"])
    np.testing.assert_allclose(out["mu_ratio"], theory.mu_ratio_stiff_exact(vb, a), atol=1e-5)


@pytest.mark.parametrize("a", [0.2, 0.5, 1.0, 1.5])
def test_case_iv_damped_rise_law_against_the_solver(a):
    """The energy balance with the dashpot: within 2e-3 for zeta = 0.005 (V >= 0.1 V_c),
    within 0.01 (zeta = 0.02) and 0.015 (0.05) where V >= 0.3 V_c (the ansatz needs a
    large V)."""
    for zeta, frac, tol in ((0.005, 0.1, 2e-3), (0.02, 0.3, 0.01), (0.05, 0.3, 0.015)):
        vc = float(theory.resonant._drive_work(np.asarray(a))) / (2 * math.pi * zeta)
        if a <= 1:
            assert vc == pytest.approx(vf.Dimensionless(1.0, math.inf, a, zeta)
                                       .critical_inertial_velocity(), rel=1e-12)
        V = vc * np.linspace(frac, 0.97, 6)
        num = solver.solve_points(1.0, math.inf, a, V, zeta)
        assert np.all(num["trusted"])
        np.testing.assert_allclose(num["mu_ratio"], theory.resonant_damped_mu_ratio(V, a, zeta),
                                   atol=tol)
    # no damping: the plateau; at and above V_c: mu0
    assert theory.resonant_damped_mu_ratio(1e6, a, 0.0) == pytest.approx(
        theory.resonant_plateau_exact(a), abs=1e-12)
    assert theory.resonant_damped_mu_ratio(1.01 * vc, a, 0.05) == 1.0


def test_case_iv_rise_depends_on_v_over_vc_only():
    x = np.linspace(0.05, 1.0, 20)
    for a in (0.3, 0.8):
        curves = [theory.resonant_damped_mu_ratio(x * a / (2 * z), a, z) for z in (0.01, 0.1)]
        np.testing.assert_allclose(curves[0], curves[1], atol=1e-12)
