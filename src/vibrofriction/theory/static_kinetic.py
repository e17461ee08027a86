r"""A static coefficient above the kinetic one: the critical velocity and the static limit.

Scaled as everywhere in :mod:`vibrofriction.theory` (forces in ``mu0 F_N0``, time
``tau = omega t``); ``s_r = mu_static/mu0 >= 1`` (``static_ratio``).  A stuck contact holds
while ``|f| <= s_r n``; at ``|f| = s_r n`` it slips and the force drops at once to the
kinetic ``s n``; a slip ends where its velocity would change sign (docs/friction_laws.md).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from ..validation import as_float_or_array
from .domains import NO_JUMPING, FloatOrArray, valid_array
from .sliding import critical_inertial_velocity

__all__ = ["QuasiStaticSlip", "static_kinetic_critical_velocity", "static_kinetic_slip",
           "static_kinetic_static_limit"]

#: How long a slip is followed (drive periods) before it is taken as never ending.
_SLIP_HORIZON = 200.0
_GRID = 64  # samples of the slip velocity per drive period (and per free period)


def static_kinetic_critical_velocity(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                                     static_ratio: ArrayLike, zeta: ArrayLike = 0.0,
                                     eta_c: ArrayLike = 0.0, a_x: ArrayLike = 0.0,
                                     phase_x: ArrayLike = 0.0,
                                     inplane_on: str = "substrate") -> FloatOrArray:
    r"""The critical velocity of continuous sliding with ``mu_static > mu0``: Coulomb's ``V_c``.

    Continuous sliding is a motion whose contact point never stops; in it the contact
    carries the kinetic force ``f = n`` throughout, so it obeys the same linear equation
    as with Coulomb friction, ``y'' + gamma y' + alpha y = -n`` (and ``eta_c e' + e = n/k``),
    whose bounded solutions are the periodic sliding orbit plus a free motion that damping
    removes and that, undamped, only lowers the smallest contact velocity.  The static
    coefficient never enters: continuous sliding exists iff the orbit's contact point never
    stops, ``V > V_c`` of :func:`~vibrofriction.theory.critical_inertial_velocity`, for every
    ``s_r``.  What changes is whether the motion reaches it: the proof that Coulomb sliding
    attracts every start uses ``|f| <= n``, which a stuck contact no longer obeys, so above
    ``V_c`` a stick-slip motion may coexist with sliding (docs/friction_laws.md).

    Parameters
    ----------
    alpha, beta, amplitude, zeta, eta_c, a_x, phase_x : array_like
        As for :func:`~vibrofriction.theory.critical_inertial_velocity`.
    static_ratio : array_like
        ``mu_static / mu0 >= 1`` (checked; it does not change the result).
    inplane_on : str
        Where a longitudinal in-plane oscillation acts.

    Returns
    -------
    float or numpy.ndarray
        ``V_c`` in units of ``mu0 F_N0/(m omega)``.
    """
    sr = valid_array("static_ratio", static_ratio)
    vc = np.asarray(critical_inertial_velocity(alpha, beta, amplitude, zeta, eta_c, a_x,
                                               phase_x, inplane_on), dtype=float)
    return as_float_or_array(np.broadcast_arrays(vc, sr)[0])


class QuasiStaticSlip(NamedTuple):
    """The slip of a body held by a rigid contact at ``V -> 0+`` (:func:`static_kinetic_slip`).

    ``duration``: the slip's length in ``tau`` (0: none); ``force_before``: the held force
    that starts it, ``s_r (1 - a)``; ``force_after``: the spring's force where it ends (nan
    where the body does not stick again: it slips back, or the slip does not end within
    200 drive periods).
    """

    duration: float
    force_before: float
    force_after: float


def _slip_scalar(alpha: float, a: float, sr: float, zeta: float) -> QuasiStaticSlip:
    """:func:`static_kinetic_slip` at one point (DOP853, the slip's end an event)."""
    from scipy.integrate import solve_ivp

    gamma = 2.0 * zeta * math.sqrt(alpha)
    f0 = sr * (1.0 - a)

    def rhs(t: float, z: np.ndarray) -> list[float]:  # X'' + gamma X' + alpha X = F0 - n
        return [z[1], f0 - (1.0 - a * math.cos(t)) - gamma * z[1] - alpha * z[0]]

    def turn(t: float, z: np.ndarray) -> float:
        return float(z[1])

    turn.terminal = True  # type: ignore[attr-defined]
    turn.direction = -1  # type: ignore[attr-defined]
    # the slip starts with X'' = (s_r - 1)(1 - a) >= 0; at s_r = 1 the body decelerates at once
    # (X' ~ -a t^3/6): no slip
    if f0 - (1.0 - a) <= 0.0:
        return QuasiStaticSlip(0.0, f0, f0)
    step = 2.0 * math.pi / (_GRID * max(1.0, math.sqrt(alpha)))
    sol = solve_ivp(rhs, (0.0, 2.0 * math.pi * _SLIP_HORIZON), [0.0, 0.0], method="DOP853",
                    rtol=1e-12, atol=1e-14, events=turn, max_step=step, first_step=1e-6)
    if not sol.t_events[0].size:
        return QuasiStaticSlip(math.inf, f0, math.nan)
    t_end = float(sol.t_events[0][0])
    x_end = float(sol.y_events[0][0][0])
    f_end = f0 - alpha * x_end
    # the body sticks again if the holding force stays within the static cone until the
    # next minimum of n, where the next slip starts: |f_end| <= s_r (1 - a)
    if f_end < -f0:
        return QuasiStaticSlip(t_end, f0, math.nan)
    return QuasiStaticSlip(t_end, f0, f_end)


def static_kinetic_slip(alpha: float, amplitude: float, static_ratio: float,
                        zeta: float = 0.0) -> QuasiStaticSlip:
    r"""The slip that breaks a rigid contact loose in the static limit ``V -> 0+``.

    Held by a rigid contact, the body sees the spring's force ``F`` grow at the rate
    ``alpha V`` while ``|F| <= s_r n``; as ``V -> 0`` it breaks loose where ``F`` first reaches
    ``s_r n``: at the minimum of ``n`` (``tau = pi``), with ``F = F_0 = s_r (1 - a)`` and the
    body at rest.  The force drops to ``n`` and the body, ``X`` from there, obeys

    .. math:: X'' + \gamma X' + \alpha X = F_0 - (1 - a \cos t), \qquad X(0) = X'(0) = 0,

    (``t = tau - pi``; the drive moves the spring by ``V t``, nothing in the limit) until
    ``X'`` returns to 0 at ``t_e``; it sticks again with ``F_e = F_0 - alpha X(t_e)`` if
    ``|F_e| <= s_r (1 - a)``.  At ``a = 0``: ``F_e = 1 - (s_r - 1) q``, ``q =
    exp(-pi zeta/sqrt(1 - zeta^2))`` (0 from ``zeta = 1``: the slip does not end).  At
    ``s_r = 1`` the body decelerates at once, ``F_e = F_0 = 1 - a`` (eq. 2).

    Parameters
    ----------
    alpha : float
        ``k_x/(m omega^2) > 0``.
    amplitude : float
        ``0 <= a <= 1``.
    static_ratio : float
        ``s_r >= 1``.
    zeta : float
        The pin's damping ratio.

    Returns
    -------
    QuasiStaticSlip
        The slip's duration and the forces before and after it.
    """
    v = {k: float(valid_array(k, x, NO_JUMPING if k == "amplitude" else None))
         for k, x in (("alpha", alpha), ("amplitude", amplitude),
                      ("static_ratio", static_ratio), ("zeta", zeta))}
    return _slip_scalar(v["alpha"], v["amplitude"], v["static_ratio"], v["zeta"])


def _limit_scalar(alpha: float, beta: float, a: float, sr: float, zeta: float) -> float:
    rigid = math.isinf(beta)
    if not rigid and a > 0.0:
        raise ValueError("static_kinetic_static_limit of a finite contact is derived at "
                         f"amplitude = 0 only, got amplitude = {a:g} (use beta = inf)")
    if a == 0.0 and zeta >= 1.0 and sr > 1.0:
        return 1.0  # the first slip never ends: the body slides on at V, f = n
    slip = _slip_scalar(alpha, a, sr, zeta)
    if not math.isfinite(slip.force_after):
        return math.nan
    f_stick = slip.force_after
    if not rigid:
        # the contact spring holds f = n = 1 after the slip, the pin's spring F_e: the stuck
        # body settles (damped) where both are equal, f_eq = (alpha 1 + k F_e)/beta, its
        # force swinging between 1 and 2 f_eq - 1 on the way (undamped: for ever, and the
        # next slip starts at the peak s_r with F = 1, a slip of zero length; the mean of
        # the two alternating stick phases is the same, see docs/friction_laws.md)
        k = beta - alpha
        f_stick = (alpha + k * slip.force_after) / beta
        if 2.0 * f_stick - 1.0 < -sr:
            return math.nan
    # quasi-static stick: f rises linearly from f_stick to s_r (1 - a), the slip's time is
    # nothing against it; <n> = 1 without jumping
    return 0.5 * (f_stick + slip.force_before)


def static_kinetic_static_limit(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                                static_ratio: ArrayLike, zeta: ArrayLike = 0.0
                                ) -> FloatOrArray:
    r"""The static limit ``mu(V -> 0+)/mu0`` with a static coefficient above the kinetic one.

    As ``V -> 0`` the motion is a quasi-static stick-slip cycle: a long stick in which the
    stuck force rises linearly (rate ``alpha k V/beta``) from its value after a slip,
    ``f_s``, to the static threshold ``s_r (1 - a)`` at a minimum of ``n``, and a slip of
    finite length (:func:`static_kinetic_slip`) whose time is nothing against the stick's.
    So

    .. math:: \frac{\mu}{\mu_0} \to \frac{f_s + s_r (1 - a)}{2}, \qquad \langle n \rangle = 1.

    Rigid contact (``beta = inf``), ``0 <= a <= 1``, any pin damping: ``f_s = F_e`` of
    :func:`static_kinetic_slip`.  At ``a = 0`` undamped this is the saw-tooth between
    ``2 - s_r`` and ``s_r``, mean 1 for every ``s_r`` (exactly 1 at every ``V``, the slip's
    force being the kinetic 1 too); damped, ``1 + (s_r - 1)(1 - q)/2``.  Finite elastic
    contact at ``a = 0``: after the slip the contact spring holds ``f = 1`` and the pin
    ``F_e``; the stuck body settles at ``f_s = (alpha + k F_e)/beta``, so undamped
    ``mu -> 1 + (s_r - 1) alpha/(2 beta)``.  At ``s_r = 1`` it is eq. (2), ``1 - a``.
    Pin damping ``zeta >= 1`` at ``a = 0``: the first slip never ends, 1.  nan where the
    cycle is not this one (the body slips back after a slip, or a stuck body's swing
    reaches ``-s_r``).

    Parameters
    ----------
    alpha, beta : array_like
        The stiffness ratios (``beta = inf``: rigid contact).
    amplitude : array_like
        ``0 <= a <= 1`` (``a = 0`` for a finite contact).
    static_ratio : array_like
        ``s_r = mu_static/mu0 >= 1``.
    zeta : array_like
        The pin's damping ratio (no contact dashpot: ``eta_c = 0``).

    Returns
    -------
    float or numpy.ndarray
        ``mu/mu0`` in the limit.

    Raises
    ------
    ValueError
        A parameter out of its range, or a finite contact with ``a > 0``.
    """
    v = {k: valid_array(k, x, NO_JUMPING if k == "amplitude" else None)
         for k, x in (("alpha", alpha), ("beta", beta), ("amplitude", amplitude),
                      ("static_ratio", static_ratio), ("zeta", zeta))}
    al, be, am, sr, ze = np.broadcast_arrays(v["alpha"], v["beta"], v["amplitude"],
                                             v["static_ratio"], v["zeta"])
    if np.any(be <= al):
        raise ValueError("beta must be > alpha")
    out = np.array([_limit_scalar(*map(float, p)) for p in zip(al.ravel(), be.ravel(),
                                                                am.ravel(), sr.ravel(),
                                                                ze.ravel(), strict=True)])
    return as_float_or_array(out.reshape(al.shape))
