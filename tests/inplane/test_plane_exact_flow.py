"""The 2-D solver's exact flows of its linear phases (stick and flight).

In stick and in flight the 2-D model is linear with constant coefficients, driven by
``cos t`` and ``sin t``: :func:`vibrofriction._kernels.plane.linear_flows` takes the
matrix exponential of the augmented system once per point, and ``segment`` steps those
phases with it where a whole step is safe.  Checked here against what shares none of it:
the model's equations written out afresh below and integrated by SciPy's DOP853 at
``rtol = 1e-13``, SciPy's ``expm``, dense sampling of a cubic, and the whole solver at a
tolerance a hundred times finer.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.linalg import expm

from plane_regimes import REGIMES
from vibrofriction._kernels import plane


def _random_point(rng):
    """``(P, parameters)`` of a random point: soft to stiff pins and contacts, Jenkins and
    Kelvin-Voigt, damped or not, substrate or holder mount, both in-plane drives."""
    al = 10 ** rng.uniform(-1.5, 1)
    be = al + 10 ** rng.uniform(-1, 2)
    p = dict(alpha=al, beta=be, a=rng.uniform(0, 2.5), V=rng.uniform(-1, 2),
             zeta=float(rng.choice([0.0, 0.05, 0.5])), eta=float(rng.choice([0.0, 0.1, 1.0])),
             a_x=float(rng.choice([0.0, 0.5])), phase_x=rng.uniform(0, 6.3),
             a_y=10 ** rng.uniform(-2, 0.5), phase_y=rng.uniform(0, 6.3),
             alpha_y=al * float(rng.choice([1.0, 2.0])), zeta_y=float(rng.choice([0.0, 0.1])),
             substrate=bool(rng.integers(2)))
    P = plane.parameters(p["alpha"], p["beta"], p["a"], p["V"], p["zeta"], p["eta"],
                         p["a_x"], p["phase_x"], p["a_y"], p["phase_y"], p["alpha_y"],
                         p["zeta_y"], p["substrate"], 1.0)
    return P, p


def _field(p, stick):
    """The right-hand side of stick (else flight) from the model's equations (docs/inplane.md),
    written here independently of the kernel: ``z = (y_x, y_y, v_x, v_y, e_x, e_y, int f_x,
    int f_y)``."""
    k = p["beta"] - p["alpha"]
    c = p["eta"] * k
    g = 2 * p["zeta"] * math.sqrt(p["alpha"])
    gy = 2 * p["zeta_y"] * math.sqrt(p["alpha_y"])

    def f(t, z):
        X, Y = p["a_x"] * math.cos(t + p["phase_x"]), p["a_y"] * math.cos(t + p["phase_y"])
        dX, dY = -p["a_x"] * math.sin(t + p["phase_x"]), -p["a_y"] * math.sin(t + p["phase_y"])
        if p["substrate"]:  # the substrate moves: the contact point's reference
            D, hd, vs = (0.0, 0.0), (p["V"], 0.0), (dX, dY)
        else:  # the holder moves: the spring's and dashpot's far end
            D, hd, vs = (X, Y), (p["V"] + dX, dY), (0.0, 0.0)
        w = (z[2] - vs[0], z[3] - vs[1])
        if stick:
            fc = (k * z[4] + c * w[0], k * z[5] + c * w[1])
            de = w
        else:
            fc = (0.0, 0.0)
            de = (-k * z[4] / c, -k * z[5] / c) if c > 0 else (0.0, 0.0)
        return [z[2] - p["V"], z[3],
                p["alpha"] * (D[0] - z[0]) + g * (hd[0] - z[2]) - fc[0],
                p["alpha_y"] * (D[1] - z[1]) + gy * (hd[1] - z[3]) - fc[1],
                de[0], de[1], fc[0], fc[1]]
    return f


def _flow_matrix(P, offset):
    return P[offset:offset + plane.N_L * plane.N_L].reshape(plane.N_L, plane.N_L)


@pytest.mark.parametrize("stick", [True, False], ids=["stick", "flight"])
def test_the_exact_flow_is_the_model_s_motion(stick):
    """One step ``H`` of the exact flow from random states, times and points against
    DOP853 at ``rtol = 1e-13`` of the equations written out afresh: within ``1e-10`` of the
    state's size (the reference's own accuracy), the force integrals included."""
    rng = np.random.default_rng(11 if stick else 12)
    worst = 0.0
    for _ in range(60):
        P, p = _random_point(rng)
        Phi = _flow_matrix(P, plane.P_PHI_STICK if stick else plane.P_PHI_FLIGHT)
        H = P[plane.P_H]
        assert H == pytest.approx(0.5 * plane.max_step(P))
        z0 = rng.normal(size=plane.N_Z)
        if not stick and p["eta"] == 0.0:
            z0[4:6] = 0.0  # a Jenkins contact has no elongation in flight
        t0 = rng.uniform(0, 2 * math.pi)
        w = np.concatenate([z0, [math.cos(t0), math.sin(t0), 1.0]])
        exact = (Phi @ w)[:plane.N_Z]
        ref = solve_ivp(_field(p, stick), (t0, t0 + H), z0, method="DOP853", rtol=1e-13,
                        atol=1e-13).y[:, -1]
        scale = 1.0 + np.max(np.abs(ref))
        worst = max(worst, np.max(np.abs(exact - ref)) / scale)
        # the cosine and sine carried along are the drive's at t0 + H
        assert (Phi @ w)[plane.N_Z:] == pytest.approx(
            [math.cos(t0 + H), math.sin(t0 + H), 1.0], abs=1e-13)
    assert worst < 1e-10, worst


def _force_along(F, z, dz, t, s):
    """The force rows at ``t + s`` on the motion's tangent line (first order in ``s``
    suffices for the rate at ``t``)."""
    zs = z + s * np.asarray(dz)
    return F @ np.concatenate([zs, [math.cos(t + s), math.sin(t + s), 1.0]])


def test_the_stick_force_rows_and_their_rates():
    """``F w`` is the stuck contact's force (``k e + c (v - v_s)``, written out) and ``F A
    w`` its rate, the force's central difference along the motion."""
    rng = np.random.default_rng(13)
    for _ in range(40):
        P, p = _random_point(rng)
        k = p["beta"] - p["alpha"]
        c = p["eta"] * k
        F = P[plane.P_F_STICK:plane.P_FA_STICK].reshape(2, plane.N_L)
        FA = P[plane.P_FA_STICK:plane.P_PHI_FLIGHT].reshape(2, plane.N_L)
        z = rng.normal(size=plane.N_Z)
        t = rng.uniform(0, 2 * math.pi)
        w = np.concatenate([z, [math.cos(t), math.sin(t), 1.0]])
        field = _field(p, True)
        dz = field(t, z)
        vs = np.zeros(2)
        if p["substrate"]:
            vs = -np.array([p["a_x"] * math.sin(t + p["phase_x"]),
                            p["a_y"] * math.sin(t + p["phase_y"])])
        force = k * z[4:6] + c * (z[2:4] - vs)
        np.testing.assert_allclose(F @ w, force, rtol=1e-12, atol=1e-12)
        d = 1e-6
        rate = (_force_along(F, z, dz, t, d) - _force_along(F, z, dz, t, -d)) / (2 * d)
        np.testing.assert_allclose(FA @ w, rate, rtol=1e-6, atol=1e-6 * (1 + np.abs(rate).max()))


def test_expm_matches_scipy():
    """The kernel's scaling and squaring against SciPy's ``expm`` on random matrices of the
    augmented system's size, dense and with most entries 0 (as the stick and flight
    systems are: its terms use the nonzeros only), norms from 0.01 to 1000."""
    rng = np.random.default_rng(14)
    for scale in (0.01, 1.0, 30.0, 1000.0):
        for trial in range(10):
            A = rng.normal(size=(plane.N_L, plane.N_L))
            if trial % 2:
                A[rng.random(A.shape) < 0.8] = 0.0
            h = scale / np.abs(A).sum(axis=1).max()
            ref = expm(A * h)
            got = plane._expm(A, h)
            assert np.max(np.abs(got - ref)) <= 1e-12 * np.max(np.abs(ref)) * max(1.0, scale)


def test_the_cubic_dip_test_against_sampling():
    """:func:`plane._cubic_dips` says whether the cubic of Hermite through two positive
    ends falls to 0 inside, as dense sampling of the same cubic sees it (cases within
    1e-9 of grazing left out)."""
    rng = np.random.default_rng(15)
    s = np.linspace(0, 1, 20001)
    h00, h10 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s
    h01, h11 = -2 * s**3 + 3 * s**2, s**3 - s**2
    seen = {True: 0, False: 0}
    for _ in range(3000):
        g0, g1 = 10 ** rng.uniform(-3, 0, 2)
        d0, d1 = rng.normal(scale=3, size=2)
        cubic = g0 * h00 + d0 * h10 + g1 * h01 + d1 * h11
        if abs(cubic.min()) < 1e-9:
            continue
        dips = bool(cubic.min() <= 0.0)
        assert plane._cubic_dips(g0, d0, g1, d1) == dips, (g0, d0, g1, d1)
        seen[dips] += 1
    assert min(seen.values()) > 200


@pytest.mark.parametrize("p", REGIMES)
def test_the_solver_within_its_error_of_a_finer_solve(p):
    """The steady state at the default ``rtol = 1e-10`` within its stated error (and
    ``1e-12``) of the same solve at ``1e-12``, at the regimes of the tangent's tests (all but
    the stiff pin spend part of their period stuck or in flight, where the exact flows
    step)."""
    al, be, a, V, ze, eta, ax, ay, sub, sr = p
    rows = []
    for rtol in (1e-10, 1e-12):
        out_f, out_i = np.zeros(40), np.zeros(20, np.int64)
        plane.plane_steady_state(al, be, a, V, ze, eta, ax, 0.3, ay, 0.7, al, ze, sub, 0,
                                 0.0, 0.0, 0.0, rtol, 100_000, 1000, out_f, out_i, sr)
        rows.append(out_f.copy())
    fine, coarse = rows[1], rows[0]
    for col in (plane.O_MU, plane.O_LAT):
        assert abs(coarse[col] - fine[col]) <= coarse[plane.O_ERR] + 1e-12
