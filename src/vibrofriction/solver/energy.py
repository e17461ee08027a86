"""The energy balance of a time history (docs/damping.md): work input and dissipation.

Power input by the pulled end (and an oscillating substrate) and dissipated by the pin
dashpot, the contact dashpot and friction, integrated by Gauss-Legendre quadrature of the
closed forms between samples.  All in the laboratory frame: the kernels' state relative
to an oscillating substrate is shifted back (:func:`inplane_motion`).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._kernels import codes
from .._kernels.integrate import sample
from .._kernels.phases import ETA_ELASTIC
from ..params import Dimensionless

__all__ = ["ENERGY_NAMES", "dissipation", "inplane_motion", "kernel_point", "transverse_motion"]

#: The cumulative energies of a :class:`~vibrofriction.History`, in order.
ENERGY_NAMES = ("work_input", "dissipated_pin", "dissipated_contact", "dissipated_friction")

_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(6)


def kernel_point(dim: Dimensionless, V: float
                 ) -> tuple[float, float, float, float, float, float, float, float, bool, float]:
    """The kernels' point arguments of a system at velocity ``V``.

    ``(alpha, beta, a, V, zeta, eta_c, a_x, phase_x, on_substrate, static_ratio)``.
    """
    return (dim.alpha, dim.beta, dim.amplitude, float(V), dim.zeta, dim.eta_c, dim.a_x,
            dim.phase_x, dim.inplane_on == "substrate", dim.static_ratio)


def inplane_motion(dim: Dimensionless, tau: NDArray[np.float64]
                   ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``(X, X')``: the longitudinal in-plane oscillation and its velocity at ``tau``.

    ``a_x cos(tau + phase_x)`` (docs/inplane.md), of the substrate or of the holder.
    """
    return _harmonic(dim.a_x, dim.phase_x, tau)


def transverse_motion(dim: Dimensionless, tau: NDArray[np.float64]
                      ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``(Y, Y')``: the transverse oscillation and its velocity at ``tau``.

    ``a_y cos(tau + phase_y)`` (docs/inplane.md), of the substrate or of the holder.
    """
    return _harmonic(dim.a_y, dim.phase_y, tau)


def _harmonic(amplitude: float, phase: float, tau: NDArray[np.float64]
              ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    arg = np.asarray(tau, dtype=float) + phase
    return amplitude * np.cos(arg), -amplitude * np.sin(arg)


def _elongation_rate(dim: Dimensionless, cols: NDArray[np.float64],
                     tau: NDArray[np.float64]) -> NDArray[np.float64]:
    """``e'`` of the contact spring at the samples (stick: the body velocity)."""
    xd, f, ph, e = (cols[:, j] for j in (codes.SMP_XD, codes.SMP_F, codes.SMP_PHASE,
                                          codes.SMP_E))
    k = dim.beta - dim.alpha
    stick = ph == codes.STICK
    if math.isinf(k):  # rigid contact: the contact point moves with the body in stick
        e_dot = np.zeros_like(xd)
    elif dim.eta_c > 0.0:  # f = k e + c e' in contact, 0 = k e + c e' in flight
        e_dot = (f - k * e) / (dim.eta_c * k)
    else:  # slip on an elastic contact: e = s n / k
        s = np.where(ph == codes.SLIP_POS, 1.0, np.where(ph == codes.SLIP_NEG, -1.0, 0.0))
        e_dot = -s * dim.amplitude * np.sin(tau) / k
    return np.where(stick, xd, e_dot)


def _rates(dim: Dimensionless, V: float, cols: NDArray[np.float64],
           tau: NDArray[np.float64]) -> NDArray[np.float64]:
    """Power input by the pulled end and dissipated by the dashpots and friction.

    The pin dashpot, the contact dashpot and friction (docs/damping.md, energy balance), from
    sampled columns (the kernels' frame).  With an in-plane oscillation (docs/inplane.md): on the
    substrate the body's laboratory position and velocity are ``y + X``, ``x' + X'`` and the
    substrate works ``-f X'`` on the contact; on the holder the pulled end moves at ``V + X'`` and
    the pin's spring and dashpot act on ``V tau + X - x``.  Friction dissipates ``f`` times the slip
    velocity relative to the substrate, ``x' - e'`` in the kernels' frame.
    """
    y, xd, f = cols[:, codes.SMP_Y], cols[:, codes.SMP_XD], cols[:, codes.SMP_F]
    gamma = 2.0 * dim.zeta * math.sqrt(dim.alpha)
    k = dim.beta - dim.alpha
    c = 0.0 if math.isinf(k) else dim.eta_c * k
    e_dot = _elongation_rate(dim, cols, tau)
    friction = f * (xd - e_dot)
    if dim.a_x == 0.0:
        return np.stack([V * (-dim.alpha * y - gamma * (xd - V)), gamma * (xd - V) ** 2,
                         c * e_dot**2, friction])
    X, Xd = inplane_motion(dim, tau)
    if dim.inplane_on == "substrate":
        pin = -dim.alpha * (y + X) + gamma * (V - xd - Xd)  # the pin's force on the body
        return np.stack([V * pin - f * Xd, gamma * (V - xd - Xd) ** 2, c * e_dot**2,
                         friction])
    pin = dim.alpha * (X - y) + gamma * (V + Xd - xd)
    return np.stack([(V + Xd) * pin, gamma * (V + Xd - xd) ** 2, c * e_dot**2, friction])


def _quadrature_nodes(taus: NDArray[np.float64], w_max: float):
    """Gauss nodes between successive samples: ``(nodes, owner interval, piece width)``.

    Each interval is cut into pieces shorter than a quarter of the fastest free period.
    """
    h = np.diff(taus)
    pieces = np.maximum(1, np.ceil(h * w_max / (0.5 * math.pi))).astype(int)
    owner = np.repeat(np.arange(h.size), pieces)
    first = np.repeat(np.cumsum(pieces) - pieces, pieces)
    width = np.repeat(h / pieces, pieces)
    start = np.repeat(taus[:-1], pieces) + (np.arange(owner.size) - first) * width
    nodes = (start[:, None] + 0.5 * width[:, None] * (_GAUSS_X[None, :] + 1.0)).ravel()
    return nodes, owner, width


def dissipation(seg: NDArray[np.float64], m: int, dim: Dimensionless, V: float,
                taus: NDArray[np.float64]) -> dict[str, Any]:
    """Cumulative work and dissipated energies (:data:`ENERGY_NAMES`) at ``taus``.

    Gauss-Legendre quadrature of the closed forms between successive samples (no event lies
    inside one), relative accuracy ~1e-10.
    """
    w_max = max(1.0, math.sqrt(dim.alpha), 0.0 if dim.is_rigid else math.sqrt(dim.beta))
    nodes, owner, width = _quadrature_nodes(taus, w_max)
    cols = np.empty((nodes.size, codes.N_SMP_COLUMNS))
    sample(seg, m, *kernel_point(dim, V), nodes, cols)
    rates = _rates(dim, V, cols, nodes).reshape(len(ENERGY_NAMES), -1, _GAUSS_X.size)
    per_piece = 0.5 * width * (rates * _GAUSS_W).sum(axis=2)
    n = taus.size - 1
    per_interval = np.stack([np.bincount(owner, p, minlength=n) for p in per_piece])
    cum = np.concatenate([np.zeros((len(ENERGY_NAMES), 1)), np.cumsum(per_interval, axis=1)],
                         axis=1)
    cum[ENERGY_NAMES.index("dissipated_friction")] += _jumps(seg, m, dim, taus)
    return dict(zip(ENERGY_NAMES, cum, strict=True))


def _jumps(seg: NDArray[np.float64], m: int, dim: Dimensionless,
           taus: NDArray[np.float64]) -> NDArray[np.float64] | float:
    """The energy friction dissipates in the jumps of an elastic contact, cumulative at ``taus``.

    With a static coefficient above the kinetic one (docs/friction_laws.md) the massless
    contact point of an elastic contact jumps where the contact breaks loose: ``e`` drops
    from ``s s_r n/k`` to ``s n/k`` at once, and the spring's energy
    ``(k/2)(e_before^2 - e_after^2) = k e_after^2 (s_r^2 - 1)/2`` goes into the slider.  A
    rigid or viscoelastic contact does not jump (its dissipation is in the rates).  Each jump
    counts from its event time on (the samples there are the state after it).
    """
    k = dim.beta - dim.alpha
    if dim.static_ratio == 1.0 or math.isinf(k) or dim.eta_c >= ETA_ELASTIC:
        return 0.0
    rows = np.flatnonzero(seg[1:m, codes.SEG_EVENT] == codes.EV_STICK_TO_SLIP) + 1
    if not rows.size:
        return 0.0
    e_after = seg[rows, codes.SEG_E]
    energy = 0.5 * k * e_after**2 * (dim.static_ratio**2 - 1.0)
    at = np.searchsorted(seg[rows, codes.SEG_TAU], taus, side="right")
    return np.concatenate([[0.0], np.cumsum(energy)])[at]
