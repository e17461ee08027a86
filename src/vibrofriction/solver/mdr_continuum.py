"""The MDR row without springs (the continuum limit): docs/contact_geometry.md.

:mod:`vibrofriction._kernels.mdr_continuum` integrates one period of the body driven by the
continuous row, the profile kept as a few pieces, exact in ``xi``; this module finds the
periodic orbit.  Its section is ``tau = pi`` (mod ``2 pi``), the smallest indentation: every
point that touched down in the last loading has left there (``a < 1``), so the profile is a
few affine pieces over the core ``xi <= (1 - a)^(1/n)`` and the section state is the vector
``(y, y', the pieces' ends, their levels relative to u)``.  Anderson's mixing of the last
``DEPTH`` period maps of that vector (restarted when the pieces' kinds change, or where a
mixed step's residual grows) finds the orbit in about ten to twenty-five periods where the
plain iteration takes hundreds (``tests/mdr/test_mdr_continuum.py``'s points); a last
period at a hundredth of the tolerance gives ``mu_ratio``, and its difference from the
period before, plus the section state's tolerance, is the stated error.
"""

from __future__ import annotations

import math

import numpy as np

from .. import theory
from .._kernels import mdr_continuum as mc

__all__ = ["continuum_covers", "mdr_continuum"]

RTOL = 1e-8  # the period maps' tolerance (Dormand-Prince, relative)
FINE = 1e-2  # the last period's tolerance: this times RTOL
DEPTH = 5  # period maps mixed
STATE_TOL = 1e-9  # the section state's change that ends the search
GROWTH = 2.0  # a mixed step whose residual grows by this restarts the mixing
HISTORY = 20000  # rows of the history of u


def continuum_covers(amplitude: float, V: float, static_ratio: float) -> bool:
    """Whether the continuum covers a point: ``0 < a < 1``, ``V > 0``, Coulomb friction."""
    return 0.0 < amplitude < 1.0 and V > 0.0 and static_ratio == 1.0


def _vector(z: np.ndarray, PC: np.ndarray, npc: int, u: float) -> np.ndarray:
    x = np.empty(2 + 2 * npc)
    x[0], x[1] = z[0], z[1]
    x[2::2] = PC[:npc, mc.X1]
    x[3::2] = PC[:npc, mc.VAL] - u
    return x


def _set_vector(x: np.ndarray, z: np.ndarray, PC: np.ndarray, npc: int, u: float,
                n: float) -> None:
    z[0], z[1] = x[0], x[1]
    ends = np.minimum(np.maximum.accumulate(np.maximum(x[2::2], 0.0)), PC[npc - 1, mc.X1])
    ends[-1] = PC[npc - 1, mc.X1]  # the contact's edge at the section is fixed
    PC[:npc, mc.X1] = ends
    PC[:npc, mc.X1P] = ends ** (n + 1.0)
    PC[1:npc, mc.X0] = ends[:-1]
    PC[1:npc, mc.X0P] = PC[:npc - 1, mc.X1P]
    PC[:npc, mc.VAL] = x[3::2] + u


def mdr_continuum(alpha: float, beta: float, amplitude: float, V: float,
                  profile_exponent: float, zeta: float = 0.0, hc: float = 0.0,
                  hs: float = 0.0, offset: tuple[float, float] = (0.0, 0.0),
                  max_periods: int = 200, rtol: float = RTOL) -> dict:
    """The periodic orbit of the continuum MDR row (``0 < a < 1``, ``V > 0``, Coulomb).

    ``hc``, ``hs``: the in-plane force ``hc cos tau + hs sin tau`` on the body, ``offset``
    the start's frame offset (:func:`vibrofriction._kernels.phases.frame_offset`), as for
    :func:`vibrofriction.solver.mdr.mdr_row`.  Returns ``mu_ratio``, ``error``, ``status``
    (``"periodic"``, or ``"failed"`` with the reason in ``reason``), ``periods`` and the
    time-averaged area fractions in stick, slip and out of contact.
    """
    a, n = float(amplitude), float(profile_exponent)
    k = beta - alpha
    c = (n + 1.0) / n / k
    gamma = 2.0 * zeta * math.sqrt(alpha)
    prm = np.array([alpha, gamma, k, c, n, a, V, hc, hs])
    PC = np.zeros((mc.MAX_PIECES + 1, mc.N_PC))
    out = np.zeros_like(PC)
    HS = np.zeros((HISTORY, mc.N_HS))
    K = np.zeros((7, mc.N_Z))
    cnt = np.zeros(4, dtype=np.int64)
    y0 = -(1.0 + a) ** (1.0 + 1.0 / n) / alpha - offset[0]
    z = np.zeros(mc.N_Z)
    z[0], z[1] = y0, -offset[1]
    npc, nh = mc.start(prm, z[0], z[1], PC, HS)
    fail = dict(mu_ratio=math.nan, error=math.inf, status="failed", periods=0,
                stick_area_fraction=math.nan, slip_area_fraction=math.nan,
                open_area_fraction=math.nan, events_per_period=0)
    npc, nh, h = mc.period(prm, 0.0, z, PC, npc, HS, nh, rtol, 0.01 * rtol, 0.5, 0.1, K,
                           out, cnt, 1)
    if npc < 0:
        return dict(fail, reason=f"kernel code {npc}")
    nh = mc.compact(HS, nh, PC, npc)
    t = math.pi
    xs: list[np.ndarray] = []
    gs: list[np.ndarray] = []
    W = math.nan
    last = math.inf
    for m in range(max_periods):
        u = z[0] + V * t
        x = _vector(z, PC, npc, u)
        kinds = PC[:npc, mc.KIND].copy()
        z2 = z.copy()
        npc2, nh2, h = mc.period(prm, t, z2, PC, npc, HS, nh, rtol, 0.01 * rtol, 0.5, h, K,
                                 out, cnt, 2)
        if npc2 < 0:
            return dict(fail, reason=f"kernel code {npc2}", periods=m + 1)
        nh2 = mc.compact(HS, nh2, PC, npc2)
        t += 2.0 * math.pi
        g = _vector(z2, PC, npc2, z2[0] + V * t)
        z[:] = z2
        npc, nh = npc2, nh2
        if npc2 != kinds.size or np.any(PC[:npc2, mc.KIND] != kinds):
            xs, gs = [], []  # the pieces' kinds changed: a new start
            last = math.inf
            continue
        f = g - x
        res = float(np.max(np.abs(f) / (1.0 + np.abs(x))))
        if res < STATE_TOL:
            W = z2[3]
            break
        if res > GROWTH * last:  # the mixing went astray: start again from here
            xs, gs = [], []
        last = res
        xs.append(x)
        gs.append(g)
        # at most as many differences as the vector has components
        keep = min(DEPTH, x.size + 1)
        xs, gs = xs[-keep:], gs[-keep:]
        if len(xs) >= 2:
            F = np.array([gg - xx for gg, xx in zip(gs, xs, strict=True)]).T
            G = np.array(gs).T
            gam, *_ = np.linalg.lstsq(np.diff(F, axis=1), f, rcond=None)
            xn = g - np.diff(G, axis=1) @ gam
            if np.all(np.isfinite(xn)):
                _set_vector(xn, z, PC, npc, xn[0] + V * t, n)
                HS[nh - 1, mc.HU] = xn[0] + V * t
                HS[nh - 1, mc.HD] = xn[1] + V
    else:
        return dict(fail, reason="no periodic orbit within max_periods", periods=max_periods)
    # the last period at a hundredth of the tolerance: mu and its error
    z2 = z.copy()
    ev0 = cnt[2]
    npc2, nh2, h = mc.period(prm, t, z2, PC, npc, HS, nh, FINE * rtol, 0.01 * FINE * rtol,
                             0.5, h, K, out, cnt, 2)
    if npc2 < 0:
        return dict(fail, reason=f"kernel code {npc2}", periods=m + 2)
    nint = 2.0 * math.pi * float(theory.profile_mean_normal_force(a, n))
    mu = z2[3] / nint
    err = abs(z2[3] - W) / nint + STATE_TOL
    area = 2.0 * math.pi * (1.0 + a) ** (2.0 / n)
    stick, slip = z2[4] / area, z2[5] / area
    return dict(mu_ratio=float(mu), error=float(err), status="periodic", periods=m + 2,
                stick_area_fraction=float(stick), slip_area_fraction=float(slip),
                open_area_fraction=float(1.0 - stick - slip),
                events_per_period=int(cnt[2] - ev0), reason="")
