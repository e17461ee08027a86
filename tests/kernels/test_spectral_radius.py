"""The Floquet multiplier in closed form against LAPACK's eigenvalues.

:func:`vibrofriction._kernels.newton.spectral_radius` takes the largest modulus of the roots
of the characteristic polynomial of a 2 x 2 or 3 x 3 matrix, and leaves clustered
eigenvalues (where those roots lose accuracy) to LAPACK.  ``numpy.linalg.eigvals`` is the
independent reference here, on random matrices of every kind the solver's Jacobians take:
real eigenvalues, complex pairs, eigenvalues clustered near 1 (a nearly neutral orbit),
non-normal matrices, and scales from 1e-3 to 10.
"""

from __future__ import annotations

import numpy as np
import pytest

from vibrofriction._kernels.newton import spectral_radius


def _matrix(rng: np.random.Generator, nd: int, kind: int) -> np.ndarray:
    J = rng.normal(size=(nd, nd)) * 10.0 ** rng.uniform(-3, 1)
    Q = rng.normal(size=(nd, nd))
    if kind == 1:  # eigenvalues clustered just below 1
        J = Q @ np.diag(1.0 - 10.0 ** rng.uniform(-9, -1, size=nd)) @ np.linalg.inv(Q)
    elif kind == 2:  # a complex pair of modulus r, and a real eigenvalue
        th, r = rng.uniform(0.0, np.pi), rng.uniform(0.01, 1.2)
        B = np.eye(nd) * rng.uniform(-1.0, 1.0)
        B[:2, :2] = r * np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
        J = Q @ B @ np.linalg.inv(Q)
    elif kind == 3:  # a double eigenvalue (a Jordan block)
        B = np.diag(np.full(nd, rng.uniform(0.1, 1.0)))
        B[0, 1] = 1.0
        J = Q @ B @ np.linalg.inv(Q)
    return J


@pytest.mark.parametrize("nd", [2, 3])
@pytest.mark.parametrize("kind", [0, 1, 2, 3])
def test_spectral_radius_is_lapacks(nd, kind):
    rng = np.random.default_rng(100 * nd + kind)
    for _ in range(500):
        J = _matrix(rng, nd, kind)
        values, vectors = np.linalg.eig(J)
        ref = np.max(np.abs(values))
        # LAPACK's own error is about eps times the eigenvector basis's condition
        cond = np.linalg.cond(vectors) if kind != 3 else 1e8
        got = spectral_radius(np.ascontiguousarray(J), nd)
        assert abs(got - ref) <= 1e-11 * max(1.0, ref) * max(1.0, cond), (J, got, ref)


def test_spectral_radius_of_special_matrices():
    eye = np.eye(3)
    assert spectral_radius(eye, 3) == pytest.approx(1.0, abs=1e-15)  # a triple root
    assert spectral_radius(0.0 * eye, 3) == 0.0
    rot = np.array([[0.0, -0.5, 0.0], [0.5, 0.0, 0.0], [0.0, 0.0, 0.1]])
    assert spectral_radius(rot, 3) == pytest.approx(0.5, rel=1e-15)  # a complex pair
    assert spectral_radius(rot, 2) == pytest.approx(0.5, rel=1e-15)
    assert spectral_radius(np.array([[-0.7, 0, 0], [0, 0, 0], [0, 0, 0.0]]), 1) == 0.7
    nan = np.full((3, 3), np.nan)
    assert spectral_radius(nan, 3) == np.inf
