"""The in-plane figures' pin, amplitudes and damping, and the helpers the three share.

Critical velocities, the in-plane columns of a curve, untrusted marks, sliding checks.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from ... import theory
from ..recipe import Check, max_deviation
from ..series import Curve

#: The issue's pin ``(alpha, beta, a)`` and its substrate amplitude ``a_x``.
SYSTEM: tuple[float, float, float] = (0.5, 2.0, 0.5)


A_X = 0.5


#: The damped variant of the issue: pin ``zeta`` and contact ``eta_c``.
DAMPING: tuple[float, float] = (0.05, 0.1)


#: Fig. 15 and 16: the issue's amplitude and a larger one at which the drive appears.
DRIVE_AMPLITUDES: tuple[float, ...] = (0.5, 1.0)


#: Fig. 16: the blocking force is ``mu`` at ``V = +-V_BLOCK[0]``; ``V_BLOCK[1]`` checks
#: its convergence in ``V``.
V_BLOCK: tuple[float, float] = (1e-5, 1e-4)


FIG14_PHASES: tuple[tuple[str, float], ...] = (("0", 0.0), (r"\pi/2", math.pi / 2),
                                                (r"\pi", math.pi))


AROUND_VC = (0.97, 0.99, 1.01, 1.03)


_SLIDING_BEYOND = 1.001   # continuous sliding is checked at |V| > this * V_c


def tex(x: float) -> str:
    """``1e-05`` as ``10^{-5}`` for mathtext (a power of ten)."""
    return f"10^{{{round(math.log10(x))}}}"


def critical_v(a: float, a_x: float, phase: float | NDArray, zeta: float = 0.0, eta_c: float = 0.0
        ) -> float | NDArray:
    """Critical velocity of forward continuous sliding (docs/inplane.md, section 2)."""
    return theory.inplane_critical_velocity(SYSTEM[0], SYSTEM[1], a, a_x, phase, zeta, eta_c)


def critical_v_pair(a: float, a_x: float, phase: float, zeta: float = 0.0, eta_c: float = 0.0
             ) -> tuple[float, float]:
    """``(V_c forward, V_c backward)``: backward sliding needs ``|V| > V_c(phase + pi)``."""
    return (float(critical_v(a, a_x, phase, zeta, eta_c)),
            float(critical_v(a, a_x, phase + math.pi, zeta, eta_c)))


def inplane_columns(c: Curve) -> dict[str, NDArray]:
    """The curve's damping and in-plane parameters as columns of its length."""
    s = c.series
    n = s.size
    return {"zeta": np.full(n, s.zeta), "eta_c": np.full(n, s.eta_c), "a_x": np.full(n, s.a_x),
            "phase_x": np.full(n, s.phase_x),
            "inplane_on": np.full(n, s.inplane_on, dtype=object)}


def mark_untrusted(ax, x: NDArray, c: Curve, color, ms: float = 2.5) -> None:
    """Untrusted points as open circles, or as a bar where they did not settle.

    Untrusted points as open circles at their (signed) value, or a bar over the range
    of their last windows' means when they did not settle.
    """
    bad = ~np.asarray(c.trusted)
    mu = c.mu_ratio
    valued = bad & np.isfinite(mu)
    if np.any(valued):
        ax.plot(x[valued], mu[valued], "o", ms=ms, mfc="none", mec=color, mew=0.5)
    ranged = bad & ~np.isfinite(mu) & np.isfinite(c.window_min)
    if np.any(ranged):
        ax.vlines(x[ranged], c.window_min[ranged], c.window_max[ranged], colors=color, lw=0.6)


def sliding_check(curves: Sequence[Curve], where: str) -> Check:
    """``mu = sign(V)`` beyond the critical velocities (continuous sliding)."""
    dev, labels = [], []
    for c in curves:
        s = c.series
        up, down = critical_v_pair(s.amplitude, s.a_x, s.phase_x, s.zeta, s.eta_c)
        V = s.v_inertial
        sel = (V > _SLIDING_BEYOND * up) | (V < -_SLIDING_BEYOND * down)
        dev += list(np.abs(c.mu_ratio[sel] - np.sign(V[sel])))
        labels += [f"{s.key}, V = {v:.4g}" for v in V[sel]]
    d, at = max_deviation(np.array(dev), np.zeros(len(dev)), labels)
    return Check("continuous sliding: mu/mu0 = sign(V) for V > V_c(phase_x) and "
                 "V < -V_c(phase_x + pi)", where + f" ({len(dev)} points beyond "
                 f"{_SLIDING_BEYOND:g} V_c)", d, at,
                 "V_c from theory.inplane_critical_velocity; the solver proves the sliding "
                 "orbit (status continuous sliding, mu = 1 exactly)" if d == 0 else
                 "V_c from theory.inplane_critical_velocity")


def below_check(curves: Sequence[Curve], where: str, below: float = 0.99) -> Check:
    """Just below ``V_c`` the contact must stick or reverse.

    ``|mu| < 1``; the smallest margin ``1 - |mu|`` there (it closes quadratically at ``V_c``).
    """
    margin, at = math.inf, "no points"
    n = 0
    for c in curves:
        s = c.series
        up, down = critical_v_pair(s.amplitude, s.a_x, s.phase_x, s.zeta, s.eta_c)
        V = s.v_inertial
        sel = ((V > 0) & (V < below * up)) | ((V < 0) & (V > -below * down))
        n += int(sel.sum())
        if np.any(sel):
            i = np.flatnonzero(sel)[np.nanargmax(np.abs(c.mu_ratio[sel]))]
            if 1 - abs(c.mu_ratio[i]) < margin:
                margin, at = float(1 - abs(c.mu_ratio[i])), f"{s.key}, V = {V[i]:.4g}"
    return Check(f"no continuous sliding below {below:g} V_c: smallest 1 - |mu/mu0|",
                 where + f" ({n} points)", margin, at,
                 "positive: below V_c the contact sticks or reverses, as the closed form says"
                 if margin > 0 else "NOT positive: continuous sliding below V_c")
