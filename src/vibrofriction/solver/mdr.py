"""A first MDR steady-state solver (issue 21, item 1): docs/contact_geometry.md.

The event-driven kernel :mod:`vibrofriction._kernels.mdr` integrates a row of ``N`` springs
exactly (closed forms between events, events refined to round-off); this module iterates its
period map on the section ``tau = 2 pi k`` until the section state repeats, and extrapolates
in ``N`` (rows of ``N`` and ``2N`` springs, Richardson with order 2, the order measured in
docs/contact_geometry.md). The public ``Dimensionless(..., profile_exponent=...)`` API is a
later step; :func:`mdr_friction` is the entry point for now.
"""

from __future__ import annotations

import math

import numpy as np

from .._kernels.mdr import STICK, row_geometry, run_periods

__all__ = ["mdr_friction", "mdr_row"]

ORDER = 2.0  # the observed order of the row's convergence in N (irregular: see docs)
SUBSTEPS = 64
MAX_PERIODS = 4000
AVERAGE_WINDOW = 100


def _check(alpha: float, beta: float, amplitude: float, V: float, n_exp: float,
           zeta: float) -> None:
    for name, value in (("alpha", alpha), ("beta", beta), ("amplitude", amplitude), ("V", V),
                        ("zeta", zeta)):
        if not math.isfinite(value):
            raise ValueError(f"{name} must be a finite number, got {value}")
    if not alpha > 0.0:
        raise ValueError(f"alpha must be > 0, got {alpha}")
    if not beta > alpha:
        raise ValueError(f"beta must be > alpha (finite), got {beta}")
    if amplitude < 0.0 or zeta < 0.0:
        raise ValueError("amplitude and zeta must be >= 0")
    if V < 0.0:
        raise ValueError(f"V must be >= 0 (the mirror V -> -V is not wired yet), got {V}")
    if not (n_exp > 0.0):
        raise ValueError(f"profile_exponent must be in (0, inf], got {n_exp}")


def mdr_row(alpha: float, beta: float, amplitude: float, V: float, profile_exponent: float,
            n_springs: int, zeta: float = 0.0, state_tol: float = 1e-11,
            substeps: int = SUBSTEPS, max_periods: int = MAX_PERIODS) -> dict:
    """Steady state of one row of ``n_springs`` springs (no extrapolation in ``N``).

    Starts sliding (``y = -sum n_i(0)/alpha``, every spring slipping forwards) and iterates
    the period map until the section state repeats within ``state_tol``: status
    ``"periodic"`` (error: round-off, 1e-12); otherwise the mean over the last
    ``AVERAGE_WINDOW`` periods, its error the difference of the window's two halves:
    ``"averaged"`` (or ``"not converged"`` if the kernel made no progress).
    """
    M = int(n_springs)
    if M < 1:
        raise ValueError(f"n_springs must be >= 1, got {n_springs}")
    a, n_exp = float(amplitude), float(profile_exponent)
    g, w, _, _, _, _ = row_geometry(a, n_exp, M)
    st = np.full(M, 2, dtype=np.int64)
    st[w * (1.0 - g) <= 0.0] = 0
    e = np.zeros(M)
    y = -float(np.sum(w * np.maximum(0.0, 1.0 - g))) / alpha
    gamma = 2.0 * zeta * math.sqrt(alpha)
    periods, conv, pf, pn, frac, viol, events, _, _ = run_periods(
        alpha, beta, a, V, gamma, n_exp, M, substeps, 5, max_periods, state_tol, y, 0.0, st, e)
    if events < 0:
        status, mu, err = "not converged", float(pf[-1] / pn[-1]) if periods > 1 else math.nan, \
            math.inf
    elif conv:
        status, mu, err = "periodic", float(pf[-1] / pn[-1]), 1e-12
    else:
        win = min(AVERAGE_WINDOW, periods // 2)
        h = win // 2
        mu = float(np.sum(pf[-win:]) / np.sum(pn[-win:]))
        m1 = np.sum(pf[-win:-h]) / np.sum(pn[-win:-h])
        m2 = np.sum(pf[-h:]) / np.sum(pn[-h:])
        status, err = "averaged", float(abs(m1 - m2)) + 1e-12
    return dict(mu_ratio=mu, error=err, status=status, periods=int(periods),
                mean_normal_ratio=float(pn[-1] / (2.0 * math.pi)),
                stick_fraction=float(frac[0]), slip_fraction=float(frac[1]),
                out_of_contact_fraction=float(frac[2]), max_excess=float(viol),
                events_per_period=int(events), n_springs=M, final_status=st.copy(),
                final_stuck=int(np.sum(st == STICK)))


def mdr_friction(alpha: float, beta: float, amplitude: float, V: float,
                 profile_exponent: float, zeta: float = 0.0, n_springs: int | None = None,
                 tol: float = 1e-5) -> dict:
    """``mu_ratio = <F_x>/(mu0 <F_N>)`` of the scaled MDR model (docs/contact_geometry.md).

    Rows of ``N`` and ``2N`` springs (``N = n_springs``, or doubled from 20 up to 640
    until the error is ``<= tol``); the result is the Richardson extrapolation with order
    2, ``mu_2N + (mu_2N - mu_N)/3``, and its ``error`` is ``|mu_2N - mu_N|`` (three times
    the Richardson estimate: the convergence is irregular) plus both orbits' errors. The
    flat punch (``profile_exponent = inf``) is one spring, exactly. Also returned:
    ``mean_normal_ratio = <F_N>/F_N0`` (exact for the row of ``2N``), the time-averaged
    fractions of the disc of the largest contact radius in stick, slip and out of contact
    (of the finer row), ``status`` (``"periodic"``, ``"averaged"``, ``"not converged"``:
    the worse of the two rows) and ``order``.
    """
    alpha, beta, amplitude, V, n_exp, zeta = (float(x) for x in (
        alpha, beta, amplitude, V, profile_exponent, zeta))
    _check(alpha, beta, amplitude, V, n_exp, zeta)
    rank = {"periodic": 0, "averaged": 1, "not converged": 2}
    if math.isinf(n_exp):
        r = mdr_row(alpha, beta, amplitude, V, n_exp, 1, zeta)
        r.update(order=math.inf, rows=(1,))
        return r
    N = 20 if n_springs is None else int(n_springs)
    coarse = mdr_row(alpha, beta, amplitude, V, n_exp, N, zeta)
    while True:
        fine = mdr_row(alpha, beta, amplitude, V, n_exp, 2 * N, zeta)
        d = fine["mu_ratio"] - coarse["mu_ratio"]
        err = abs(d) + coarse["error"] + fine["error"]
        if n_springs is not None or err <= tol or 2 * N >= 640:
            break
        N *= 2
        coarse = fine
    out = dict(fine)
    out.update(mu_ratio=fine["mu_ratio"] + d / (2.0 ** ORDER - 1.0), error=err,
               status=max(coarse["status"], fine["status"], key=rank.get),
               order=ORDER, rows=(N, 2 * N), unextrapolated=fine["mu_ratio"])
    if out["status"] == "averaged" and err > tol:
        out["status"] = "not converged"
    return out
