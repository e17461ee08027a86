"""The rate-and-state kernel's Floquet multiplier: the exact monodromy of the period map.

The multiplier comes from the variational equations integrated with the state
(``_kernels.rate_state._tangent_map``).  It is checked against what does not come from the
kernel: the roots of the characteristic polynomial of steady sliding (``theory.rate_state``:
the growth per period ``exp(2 pi max Re s)``) without oscillation, central differences of
the period map at a much tighter tolerance, and the growth of a perturbation of the orbit.
The kernel is called directly (``rs_steady_state``), without the solver's guard
``_unforced_unstable``: it must be right on its own.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction._kernels import rate_state as rs
from vibrofriction.schema import FLOAT_COLUMNS, INT_COLUMNS, Status, column_index
from vibrofriction.solver import solve_points
from vibrofriction.theory import rate_state as trs

# the defect's point: a slow growth (exp(2 pi Re s) = 1.0326) the finite-difference and
# Broyden Jacobian read as 0.968
DEFECT = {"alpha": 0.2, "beta": 10.0, "zeta": 0.0, "v": 0.7924465962305569, "a": 0.03,
          "b": 0.05, "d_c": 1.0, "v_ref": 1.0}
STATUS, MULT = column_index("status"), column_index("multiplier")


def _params(alpha: float, beta: float, A: float, V: float, zeta: float, a: float, b: float,
            dc: float, vref: float, ald: float = 0.0, law: float = 0.0,
            eta_c: float = 0.0) -> np.ndarray:
    return rs.make_parameters(alpha, beta, A, V, zeta, 0.0, 0.0, True, a, b, dc, vref, ald,
                              law, eta_c)


def _kernel(P: np.ndarray, rtol: float = 1e-8, max_periods: int = 300) -> tuple[int, float]:
    """``(status code, multiplier)`` of the kernel from steady sliding, no guard."""
    z = rs.sliding_start(P, np.zeros(2))
    of = np.empty(len(FLOAT_COLUMNS))
    oi = np.empty(len(INT_COLUMNS), np.int64)
    rs.rs_steady_state(P, z, rtol, max_periods, 1e-6, np.zeros(2), of, oi)
    return int(oi[STATUS]), float(of[MULT])


def _growth(alpha: float, beta: float, zeta: float, V: float, a: float, b: float, dc: float,
            vref: float) -> float:
    s = trs.sliding_eigenvalues(alpha, beta, zeta, V, a, b, dc, vref)
    return math.exp(2.0 * math.pi * float(np.max(s.real)))


def _random_points(n: int, seed: int) -> list[tuple]:
    """Points without oscillation, weakening and strengthening, both laws, damping; the
    ones within 1e-3 of neutral left out (their verdict is the tolerance's)."""
    rng = np.random.default_rng(seed)
    out: list[tuple] = []
    while len(out) < n:
        alpha = 10 ** rng.uniform(-1.0, 0.5)
        beta = alpha + 10 ** rng.uniform(0.0, 1.3)
        zeta = float(rng.choice([0.0, 0.05]))
        V = 10 ** rng.uniform(-1.0, 0.3)
        a = 10 ** rng.uniform(-2.0, -1.3)
        b = a * rng.uniform(0.3, 2.5)
        dc = 10 ** rng.uniform(-1.0, 0.3)
        law = float(rng.integers(2))
        g = _growth(alpha, beta, zeta, V, a, b, dc, 1.0)
        if abs(g - 1.0) > 1e-3:
            out.append((alpha, beta, zeta, V, a, b, dc, law, g))
    return out


def test_defect_point_is_not_periodic_without_the_guard() -> None:
    """The kernel alone: at the defect's point steady sliding is unstable (growth 1.0326),
    so the answer is not periodic, and Newton's orbit there has the theory's multiplier."""
    d = DEFECT
    g = _growth(d["alpha"], d["beta"], d["zeta"], d["v"], d["a"], d["b"], d["d_c"], d["v_ref"])
    assert g == pytest.approx(1.0326, abs=1e-4)
    P = _params(d["alpha"], d["beta"], 0.0, d["v"], d["zeta"], d["a"], d["b"], d["d_c"],
                d["v_ref"])
    status, _ = _kernel(P, rtol=1e-7, max_periods=600)
    assert status != Status.PERIODIC.code
    # Newton's method from the start (which is the orbit): the exact multiplier
    z = rs.sliding_start(P, np.zeros(2))
    res = np.zeros(rs.N_RES)
    found = rs._newton(P, z, 1e-7, np.array([1e-3]), rs._workspace(), np.zeros(3, np.int64),
                       rs._tangent_workspace(), np.empty(1), np.zeros(2, np.int64),
                       np.empty((4, 4)), np.empty(4), res)
    assert found
    assert res[2] == pytest.approx(g, abs=1e-4)


@pytest.mark.parametrize("point", _random_points(10, 34))
def test_multiplier_is_the_hurwitz_growth(point: tuple) -> None:
    """Without oscillation, over random stable and unstable points: a stable one is
    periodic with the multiplier ``exp(2 pi max Re s)`` of the characteristic roots; an
    unstable one is never periodic (the kernel alone)."""
    alpha, beta, zeta, V, a, b, dc, law, g = point
    P = _params(alpha, beta, 0.0, V, zeta, a, b, dc, 1.0, 0.0, law)
    status, mult = _kernel(P)
    if g < 1.0:
        assert status == Status.PERIODIC.code
        assert mult == pytest.approx(g, abs=2e-5)
    else:
        assert status != Status.PERIODIC.code


def test_points_cover_both_verdicts() -> None:
    """The random points of the test above include stable and unstable sliding."""
    growths = [p[-1] for p in _random_points(10, 34)]
    assert min(growths) < 1.0 < max(growths)


@pytest.mark.parametrize("amplitude", [0.02, 0.05])
def test_small_amplitude_at_the_defect_point_is_never_periodic(amplitude: float) -> None:
    """A small normal oscillation at the defect's parameters: the orbit Newton's method
    finds near steady sliding keeps about the unforced multiplier (it grows), and the
    solver does not call the point periodic (no guard exists with an oscillation)."""
    d = DEFECT
    g = _growth(d["alpha"], d["beta"], d["zeta"], d["v"], d["a"], d["b"], d["d_c"], d["v_ref"])
    P = _params(d["alpha"], d["beta"], amplitude, d["v"], d["zeta"], d["a"], d["b"],
                d["d_c"], d["v_ref"])
    z = rs.sliding_start(P, np.zeros(2))
    res = np.zeros(rs.N_RES)
    assert rs._newton(P, z, 1e-8, np.array([1e-3]), rs._workspace(), np.zeros(3, np.int64),
                      rs._tangent_workspace(), np.empty(1), np.zeros(2, np.int64),
                      np.empty((4, 4)), np.empty(4), res)
    assert abs(res[2] - g) < 0.01 and res[2] > 1.0
    out = solve_points(d["alpha"], d["beta"], amplitude, d["v"], rs_a=d["a"], rs_b=d["b"],
                       rs_d_c=d["d_c"], rs_v_ref=d["v_ref"])
    assert int(out["status"]) != Status.PERIODIC.code


def _central_jacobian(P: np.ndarray, z0: np.ndarray) -> np.ndarray:
    """The period map's Jacobian by central differences of adaptive maps at rtol 1e-12."""
    work, tw = rs._workspace(), rs._tangent_workspace()
    count, log, lp = np.zeros(3, np.int64), np.empty(1), np.zeros(2, np.int64)
    wv, s = rs._weights(P, z0)
    D = np.empty((4, 4))
    for j in range(4):
        dj = 1e-5 * s / wv[j]
        zp, zq = z0.copy(), z0.copy()
        zp[j] += dj
        zq[j] -= dj
        for zz in (zp, zq):
            assert rs._map_mean(P, zz, 1e-12, np.array([1e-4]), work, count, tw, log, lp)[0]
        D[:, j] = (zp[:4] - zq[:4]) / (2.0 * dj)
    return D


@pytest.mark.parametrize("point", [
    # alpha, beta, A, V, zeta, a, b, d_c, v_ref, alpha_ld, law
    (0.5, 2.0, 0.5, 0.5, 0.0, 0.01, 0.005, 0.01, 1.0, 0.0, 0.0),
    (0.5, 2.0, 0.7, 0.3, 0.1, 0.02, 0.03, 0.05, 0.5, 0.0, 1.0),
    (0.5, 2.0, 1.5, 0.5, 0.0, 0.01, 0.005, 0.01, 1.0, 0.0, 0.0),  # jumping
    (0.5, 2.0, 1.3, 0.8, 0.1, 0.02, 0.01, 0.02, 1.0, 0.0, 1.0),  # jumping, slip law
    (0.2, 3.0, 0.6, 1.0, 0.0, 0.01, 0.008, 0.01, 1.0, 0.3, 0.0),  # Linker-Dieterich
    # a rigid contact (its own mode: x' slaved to m; measured 1.7e-8 to 1.9e-7 relative)
    (0.5, math.inf, 0.5, 0.5, 0.0, 0.05, 0.03, 0.05, 1.0, 0.0, 0.0),
    (0.5, math.inf, 0.7, 0.3, 0.1, 0.05, 0.06, 0.05, 0.5, 0.0, 1.0),  # weakening, damped
    (0.5, math.inf, 1.3, 0.8, 0.1, 0.05, 0.03, 0.05, 1.0, 0.0, 1.0),  # jumping, slip law
    (0.2, math.inf, 0.6, 1.0, 0.0, 0.05, 0.04, 0.05, 1.0, 0.3, 0.0),  # Linker-Dieterich
    # contact damping (eta_c, the last; measured 2.6e-9 to 3.2e-9 relative)
    (0.5, 2.0, 0.5, 0.5, 0.0, 0.02, 0.01, 0.02, 1.0, 0.0, 0.0, 0.1),
    (0.5, 2.0, 1.3, 0.5, 0.1, 0.02, 0.01, 0.02, 1.0, 0.0, 1.0, 0.3),  # jumping, slip law
    (0.2, 3.0, 0.6, 1.0, 0.0, 0.02, 0.015, 0.02, 1.0, 0.3, 0.0, 0.05),  # Linker-Dieterich
])
def test_monodromy_against_central_differences(point: tuple) -> None:
    """With an oscillation (contact, lift-off and touch-down, the coupling), finite and
    rigid contact: the tangent's Jacobian of the period map at the orbit is the central
    differences' of tight maps, and so are the multipliers (Newton's method after the
    solver's settling periods).  A rigid contact's section velocity is slaved to ``m``:
    its column is zero in both.  With contact damping, the flight's elongation and the
    resets of lift-off and touch-down (the scalar equation of ``m``) included."""
    P = _params(*point)
    z = rs.sliding_start(P, np.zeros(2))
    for _ in range(rs.SETTLE):
        assert rs.rs_period(P, z, 1e-9, np.array([1e-3]), rs._workspace(),
                            np.zeros(3, np.int64))
    D, gmu, res = np.empty((4, 4)), np.empty(4), np.zeros(rs.N_RES)
    assert rs._newton(P, z, 1e-9, np.array([1e-3]), rs._workspace(), np.zeros(3, np.int64),
                      rs._tangent_workspace(), np.empty(1), np.zeros(2, np.int64), D, gmu,
                      res)
    Dc = _central_jacobian(P, z)
    assert np.abs(D - Dc).max() <= 1e-5 * np.abs(Dc).max()
    if math.isinf(point[1]):
        assert np.all(D[:, rs.Z_V] == 0.0) and np.all(Dc[:, rs.Z_V] == 0.0)
    rho = float(np.max(np.abs(np.linalg.eigvals(Dc))))
    assert res[2] == pytest.approx(rho, abs=1e-6)


def test_linker_dieterich_orbit_grows() -> None:
    """An undamped pin with the Linker-Dieterich coupling: the orbit's multiplier is
    1.0016 (a slow growth, which the finite-difference and Broyden Jacobian read as 0.997
    and called periodic); a perturbation of the orbit grows over the periods as the
    multiplier says, and the solver does not call the point periodic."""
    P = _params(0.2, 3.0, 0.6, 1.0, 0.0, 0.01, 0.008, 0.01, 1.0, 0.3, 0.0)
    z = rs.sliding_start(P, np.zeros(2))
    res = np.zeros(rs.N_RES)
    assert rs._newton(P, z, 1e-9, np.array([1e-3]), rs._workspace(), np.zeros(3, np.int64),
                      rs._tangent_workspace(), np.empty(1), np.zeros(2, np.int64),
                      np.empty((4, 4)), np.empty(4), res)
    assert res[2] == pytest.approx(1.00159, abs=1e-5)
    work, tw = rs._workspace(), rs._tangent_workspace()
    count, log, lp = np.zeros(3, np.int64), np.empty(1), np.zeros(2, np.int64)
    wv, _ = rs._weights(P, z)
    zp, zr = z.copy(), z.copy()
    zp[rs.Z_V] += 1e-6
    d0 = rs._distance(wv, zp, zr)
    for _ in range(1500):
        for zz in (zp, zr):
            assert rs._map_mean(P, zz, 1e-11, np.array([1e-4]), work, count, tw, log, lp)[0]
    assert rs._distance(wv, zp, zr) > 3.0 * d0  # 1.0016^1500 = 11, less the rotation's phase
    s = vf.Dimensionless(alpha=0.2, beta=3.0, amplitude=0.6, rs_a=0.01, rs_b=0.008,
                         rs_d_c=0.01, rs_v_ref=1.0, rs_alpha_ld=0.3)
    r = vf.friction_coefficient(s, v_inertial=1.0, settings=vf.SolverSettings(max_periods=300))
    assert r.status is not Status.PERIODIC
