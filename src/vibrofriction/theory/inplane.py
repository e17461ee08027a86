"""In-plane oscillations.

Kinematic friction, the critical velocity, cancellation, the static region and the regimes
(docs/inplane.md).
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..schema import CHOICES
from ..validation import as_float_or_array, checked, checked_choice, validated
from .domains import SOFT_LIMIT, FloatOrArray

# --------------------------------------------------------------------------- in-plane
#: Where the in-plane oscillation is imposed (docs/inplane.md).
INPLANE_ON = CHOICES["inplane_on"].values


def checked_inplane_on(inplane_on: str) -> str:
    """``inplane_on`` if it is ``"substrate"`` or ``"holder"``, else a ValueError."""
    return checked_choice("inplane_on", inplane_on)


def kinematic_mu_longitudinal(v: ArrayLike, a_x: ArrayLike) -> FloatOrArray:
    r"""Kinematic law of a rigid body, oscillation along the sliding direction (docs/inplane.md).

    The body moves at the constant velocity ``v`` against a substrate whose velocity
    is ``-a_x sin(theta)``; friction ``-sign(v + a_x sin theta)`` averages to

    .. math:: \frac{\mu}{\mu_0} = \frac{2}{\pi}\arcsin\frac{v}{a_x}, \quad |v| < a_x,

    and ``sign(v)`` for ``|v| >= a_x``.  Any unit, as long as ``v`` and ``a_x`` (the
    vibration-velocity amplitude ``omega du_x``) share it; ``v`` is signed.
    """
    v = checked("v", v)
    a_x = checked("a_x", a_x, minimum=0.0)
    v, a_x = np.broadcast_arrays(v, a_x)
    r = np.array(np.sign(v), dtype=float)
    np.divide(v, a_x, out=r, where=np.abs(v) < a_x)
    return as_float_or_array(2.0 / np.pi * np.arcsin(np.clip(r, -1.0, 1.0)))


def kinematic_mu_transverse(v: ArrayLike, a_y: ArrayLike) -> FloatOrArray:
    r"""Kinematic law of a rigid body, oscillation across the sliding direction.

    The slip velocity is ``(v, a_y sin theta)``; isotropic friction opposes it, so its
    component along the sliding is ``v/sqrt(v^2 + a_y^2 sin^2 theta)``, whose mean is

    .. math:: \frac{\mu}{\mu_0} = \frac{2}{\pi}\frac{K(m)}{\sqrt{1 + \epsilon^2}}, \quad
              \epsilon = \frac{a_y}{v}, \quad m = \frac{\epsilon^2}{1 + \epsilon^2},

    ``K(m) = int_0^{pi/2} (1 - m sin^2)^{-1/2}`` with the parameter ``m``
    (``scipy.special.ellipk``).  No critical velocity: ``mu < mu0`` at every ``v``;
    ``-> 1 - eps^2/4`` for large ``v``, ``(2/pi)(|v|/a_y) ln(4 a_y/|v|)`` for small.
    """
    from scipy.special import ellipk

    v = checked("v", v)
    a_y = checked("a_y", a_y, minimum=0.0)
    v, a_y = np.broadcast_arrays(v, a_y)
    av = np.abs(v)
    # m = a_y^2/(v^2 + a_y^2), 1/sqrt(1 + eps^2) = |v|/sqrt(v^2 + a_y^2), with 0/0 -> 0
    norm = np.hypot(av, a_y)
    m = np.zeros(v.shape)
    np.divide(a_y**2, norm**2, out=m, where=norm > 0)
    scale = np.zeros(v.shape)
    np.divide(av, norm, out=scale, where=norm > 0)
    with np.errstate(invalid="ignore"):
        law = 2.0 / np.pi * ellipk(np.minimum(m, 1.0)) * scale
    law = np.where(av == 0.0, 0.0, law)  # K(1) = inf times 0
    return as_float_or_array(np.sign(v) * law)


def _inplane_factors(alpha: NDArray[np.float64], beta: NDArray[np.float64],
                     zeta: NDArray[np.float64], eta: NDArray[np.float64], on: str):
    """``P``, the slip compliance, the contact impedance and the in-plane forcing.

    ``P``, the contact's slip compliance ``1/(k(1 + i eta_c))``, the contact impedance ``k + i c``
    (0 for rigid: then unused) and the in-plane forcing ``G`` times ``P`` (substrate: ``-P``;
    holder: ``alpha + i gamma``).
    """
    gamma = 2.0 * zeta * np.sqrt(alpha)
    p = (alpha - 1.0) + 1j * gamma
    rigid = np.isinf(beta)
    k = np.where(rigid, 1.0, beta - alpha)
    eta = np.where(rigid, 0.0, eta)
    slip_compliance = np.where(rigid, 0.0, 1.0 / (k * (1.0 + 1j * eta)))
    impedance = k * (1.0 + 1j * eta)
    gp = -p if on == "substrate" else alpha + 1j * gamma
    return p, slip_compliance, impedance, gp, rigid


def _inplane_inputs(alpha, beta, amplitude, a_x, phase_x, zeta, eta_c, inplane_on
                    ) -> tuple[Any, ...]:
    """The validated inputs of the in-plane closed forms.

    ``(on_substrate, alpha, beta, a, zeta, eta_c, a_x, phase_x)``, checked against the schema's
    ranges (``alpha`` as in the soft limit).
    """
    on = checked_inplane_on(inplane_on)
    values = validated({"alpha": alpha, "beta": beta, "amplitude": amplitude, "zeta": zeta,
                        "eta_c": eta_c, "a_x": a_x, "phase_x": phase_x},
                       ranges={"alpha": SOFT_LIMIT})
    return (on, *values.values())


def inplane_critical_velocity(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                              a_x: ArrayLike, phase_x: ArrayLike, zeta: ArrayLike = 0.0,
                              eta_c: ArrayLike = 0.0,
                              inplane_on: str = "substrate") -> FloatOrArray:
    r"""Critical inertial velocity of continuous sliding, normal + longitudinal oscillation.

    In permanent forward slip (``f = n = 1 + a cos tau``, ``a <= 1``) the contact
    point's slip velocity relative to the substrate is ``V`` plus a harmonic
    (docs/inplane.md),

    .. math:: w = V - \mathrm{Re}\big(i e^{i\tau}\,[a B - a_x G e^{i\phi_x}]\big),\quad
              B = \frac1P + \frac{1}{k(1 + i\eta_c)},\quad P = \alpha - 1 + i\gamma,

    ``G = -1`` (substrate) or ``(alpha + i gamma)/P`` (holder), ``gamma = 2 zeta
    sqrt(alpha)``, ``k = beta - alpha``.  It never reaches 0 iff ``V >= V_c`` with

    .. math:: V_c = |a B - a_x G e^{i\phi_x}|.

    ``a_x = 0`` gives :func:`critical_inertial_velocity`.  For ``V < 0`` (backward
    sliding) the condition is ``|V| >= V_c(phase_x + pi)``.  ``inf`` at an undamped
    resonance ``alpha = 1`` unless the holder's forcing cancels the normal one there.
    """
    on, alpha, beta, a, zeta, eta, a_x, phase = _inplane_inputs(
        alpha, beta, amplitude, a_x, phase_x, zeta, eta_c, inplane_on)
    # the names keep their ArrayLike annotations; _inplane_inputs made them float arrays
    p, slip_compliance, _, gp, _ = _inplane_factors(alpha, beta, zeta, eta, on)  # type: ignore[arg-type]
    # a B - a_x G e^{i phi} = N / P + a / (k (1 + i eta_c)), N = a - a_x (G P) e^{i phi}
    num = a - a_x * gp * np.exp(1j * phase)
    num, p, rest = np.broadcast_arrays(num, p, a * slip_compliance)
    resonant = np.zeros(num.shape, dtype=complex)
    np.divide(num, p, out=resonant, where=p != 0)
    total = np.abs(resonant + rest)
    total = np.where((p == 0) & (num != 0), np.inf, total)
    return as_float_or_array(total)


class Cancellation(NamedTuple):
    """Where the normal and longitudinal oscillations cancel in the sliding velocity."""

    #: ``phase_x`` in ``[0, 2 pi)`` at which ``V_c`` is smallest, ``| a|B| - a_x|G| |``;
    #: they add (``V_c = a|B| + a_x|G|``) at ``phase_x + pi``.
    phase_x: FloatOrArray
    #: The ``a_x = a|B|/|G|`` at which ``V_c = 0`` there (``mu = mu0`` at every ``V > 0``).
    a_x: FloatOrArray


def inplane_cancellation(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                         zeta: ArrayLike = 0.0, eta_c: ArrayLike = 0.0,
                         inplane_on: str = "substrate") -> Cancellation:
    r"""Phase and amplitude at which the longitudinal oscillation cancels the normal one.

    ``V_c^2 = a^2|B|^2 + a_x^2|G|^2 - 2 a a_x |B||G| cos(phase_x - arg B + arg G)``
    (:func:`inplane_critical_velocity`), so the phase of cancellation is
    ``arg B - arg G`` (mod ``2 pi``) and ``V_c`` vanishes there for ``a_x = a|B|/|G|``.
    Undamped, ``B`` and ``G`` are real: the phase is 0 or ``pi``.  At an undamped
    resonance (``P = 0``) ``B`` and ``G`` are both infinite and their ratio ``1/(alpha +
    i gamma)`` (holder) sets the phase; the substrate cannot cancel it (``a_x = inf``).
    """
    on = checked_inplane_on(inplane_on)
    alpha, beta, a, zeta, eta = validated(
        {"alpha": alpha, "beta": beta, "amplitude": amplitude, "zeta": zeta, "eta_c": eta_c},
        ranges={"alpha": SOFT_LIMIT}).values()
    # the names keep their ArrayLike annotations; _inplane_inputs made them float arrays
    p, slip_compliance, _, gp, _ = _inplane_factors(alpha, beta, zeta, eta, on)  # type: ignore[arg-type]
    # B/G = (1 + P/(k(1 + i eta_c))) / (G P): finite also at P = 0
    bp = 1.0 + p * slip_compliance
    ratio = np.full(np.broadcast(bp, gp).shape, np.inf, dtype=complex)
    np.divide(bp, gp, out=ratio, where=gp != 0)
    phase = np.mod(np.angle(ratio), 2.0 * np.pi)
    amp = a * np.abs(ratio)
    amp = np.where(np.isinf(np.abs(ratio)) & (a == 0), 0.0, amp)
    return Cancellation(as_float_or_array(phase), as_float_or_array(amp))


class InplaneStatic(NamedTuple):
    """Range of mean forces a stuck contact can hold (``mu/mu0``, ``V -> 0+`` and ``0-``)."""

    #: ``mu(V -> 0+)/mu0 = 1 - |a + Q|``: the largest mean force of a permanent stick.
    upper: FloatOrArray
    #: ``mu(V -> 0-)/mu0 = -(1 - |a - Q|)``: the most negative one.
    lower: FloatOrArray


def inplane_static_mu_ratio(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                            a_x: ArrayLike, phase_x: ArrayLike, zeta: ArrayLike = 0.0,
                            eta_c: ArrayLike = 0.0,
                            inplane_on: str = "substrate") -> InplaneStatic:
    r"""Static friction under normal + longitudinal oscillation, compliant contact.

    With the contact stuck through the whole cycle the system is linear: the contact
    force is ``F + Re(F^ e^{i tau})``, ``F`` the mean (the measured friction force),
    ``F^ = -Q``, ``Q = a_x T e^{i phase_x}`` with (docs/inplane.md)

    .. math:: T = \frac{(k + i c)\,P}{P + k + i c}\ \text{(substrate)},\qquad
              T = -\frac{(k + i c)(\alpha + i\gamma)}{P + k + i c}\ \text{(holder)},

    ``c = eta_c k``, ``P = alpha - 1 + i gamma``; rigid contact: ``T = P`` or
    ``-(alpha + i gamma)``.  ``|f| <= n`` through the cycle iff
    ``-1 + |a - Q| <= F <= 1 - |a + Q|``; the body creeping at ``V -> 0+`` raises ``F``
    to the upper bound, so ``mu(0+)/mu0 = 1 - |a + Q|`` and ``mu(0-)/mu0 =
    -(1 - |a - Q|)``.  Quasi-statically (``alpha, beta -> 0``: a heavy body) ``T = k``
    and a pure in-plane oscillation gives ``1 - k a_x`` (the intrinsic length
    ``1/k``, i.e. ``mu0 F_N0/k_xc``).  ``nan`` where no permanent stick exists
    (``|a + Q| + |a - Q| > 2``, or ``a > 1``): the contact slips in every cycle.
    Valid where the stuck orbit is the attractor (damping; the solver is the judge).
    """
    on, alpha, beta, a, zeta, eta, a_x, phase = _inplane_inputs(
        alpha, beta, amplitude, a_x, phase_x, zeta, eta_c, inplane_on)
    # the names keep their ArrayLike annotations; _inplane_inputs made them float arrays
    p, _, impedance, gp, rigid = _inplane_factors(alpha, beta, zeta, eta, on)  # type: ignore[arg-type]
    # T = -(k + i c) G P / (P + k + i c); rigid: -G P
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(rigid, -gp, -impedance * gp / (p + impedance))
    with np.errstate(invalid="ignore"):  # T = inf at an undamped beta = 1
        q = np.where(a_x == 0.0, 0.0, a_x * t * np.exp(1j * phase))
        plus, minus = np.abs(a + q), np.abs(a - q)
    ok = (plus + minus <= 2.0) & (a <= 1.0)
    upper = np.where(ok, 1.0 - plus, np.nan)
    lower = np.where(ok, minus - 1.0, np.nan)
    return InplaneStatic(as_float_or_array(upper), as_float_or_array(lower))


class PlaneStatic(NamedTuple):
    """The region of mean forces ``(F_x, F_y)/(mu0 F_N0)`` a stuck contact can hold.

    Stuck through whole cycles under normal + in-plane oscillation in both directions
    (:func:`plane_static_region`), given by its extent; ``nan`` where it is empty.
    """

    #: The largest and the smallest ``F_x`` of the region (held ``mu_ratio`` values).
    x_upper: FloatOrArray
    x_lower: FloatOrArray
    #: The largest and the smallest ``F_y`` (held ``lateral_ratio`` values).
    y_upper: FloatOrArray
    y_lower: FloatOrArray


#: Samples of the drive period on which :func:`plane_static_region` imposes the cone.
PLANE_STATIC_SAMPLES = 4096


def _axis_range(qa: NDArray[np.float64], qb: NDArray[np.float64],
                n: NDArray[np.float64]) -> tuple[float, float]:
    """The extent along ``a`` of ``{F: |F - (qa_j, qb_j)| <= n_j for all j}`` (a convex set).

    At fixed ``F_a`` the feasible ``F_b`` is an intersection of intervals, of concave width
    ``h(F_a) = min hi_j - max lo_j``; its maximum by golden section, the ends where ``h = 0`` by
    bisection.  ``(nan, nan)`` where the set is empty.
    """
    lo_dom, hi_dom = float(np.max(qa - n)), float(np.min(qa + n))
    if lo_dom > hi_dom:
        return math.nan, math.nan

    def width(x: float) -> float:
        r = np.sqrt(np.maximum(n * n - (x - qa) ** 2, 0.0))
        return float(np.min(qb + r) - np.max(qb - r))

    g = (math.sqrt(5.0) - 1.0) / 2.0
    a, b = lo_dom, hi_dom
    c, d = b - g * (b - a), a + g * (b - a)
    wc, wd = width(c), width(d)
    for _ in range(100):
        if b - a <= 1e-15 * (1.0 + abs(a) + abs(b)):
            break
        if wc >= wd:
            b, d, wd = d, c, wc
            c = b - g * (b - a)
            wc = width(c)
        else:
            a, c, wc = c, d, wd
            d = a + g * (b - a)
            wd = width(d)
    top = 0.5 * (a + b)
    if width(top) < 0.0:
        return math.nan, math.nan

    def edge(inside: float, outside: float) -> float:
        for _ in range(100):
            mid = 0.5 * (inside + outside)
            if mid in (inside, outside):
                break
            if width(mid) >= 0.0:
                inside = mid
            else:
                outside = mid
        return inside

    return edge(top, lo_dom) if width(lo_dom) < 0.0 else lo_dom, \
        edge(top, hi_dom) if width(hi_dom) < 0.0 else hi_dom


def plane_static_region(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                        a_x: ArrayLike, phase_x: ArrayLike, a_y: ArrayLike,
                        phase_y: ArrayLike, zeta: ArrayLike = 0.0, eta_c: ArrayLike = 0.0,
                        inplane_on: str = "substrate", alpha_y: ArrayLike | None = None,
                        zeta_y: ArrayLike | None = None) -> PlaneStatic:
    r"""Static friction under normal + in-plane oscillation in both directions.

    The region of mean forces a contact stuck through the whole cycle can hold.

    In stick the contact point moves with the substrate and the two directions decouple
    (the pin's springs act along their axes, the contact spring is isotropic): each
    component of the contact force is that of :func:`inplane_static_mu_ratio`, ``F_x -
    Re(Q_x e^{i tau})`` and ``F_y - Re(Q_y e^{i tau})`` with ``Q_x = a_x T e^{i
    phase_x}`` and ``Q_y = a_y T_y e^{i phase_y}`` (``T_y`` of the pin across,
    ``alpha_y``, ``zeta_y``; None: ``alpha``, ``zeta``).  The stick holds through the
    cycle iff ``|F - q(tau)| <= n(tau) = 1 + a cos tau`` for every ``tau``: ``F`` in the
    intersection of the disks of radius ``n`` about the ellipse ``q``, a convex set.  Its
    extent is computed on :data:`PLANE_STATIC_SAMPLES` equally spaced phases (an outer
    approximation, to about ``1e-6``).  With ``a_y = 0`` the ``x`` extent is the band of
    :func:`inplane_static_mu_ratio`.  ``nan`` where the region is empty (or ``a > 1``):
    the contact slips in every cycle.
    """
    on, al, be, am, ze, et, ax, px = _inplane_inputs(alpha, beta, amplitude, a_x, phase_x,
                                                     zeta, eta_c, inplane_on)
    aly = al if alpha_y is None else np.asarray(alpha_y, dtype=float)
    zey = ze if zeta_y is None else np.asarray(zeta_y, dtype=float)
    al, be, am, ze, et, ax, px, ay, py, aly, zey = np.broadcast_arrays(
        al, be, am, ze, et, ax, px, np.asarray(a_y, dtype=float),
        np.asarray(phase_y, dtype=float), aly, zey)
    tau = np.linspace(0.0, 2.0 * np.pi, PLANE_STATIC_SAMPLES, endpoint=False)
    e = np.exp(1j * tau)
    out = np.full((4,) + al.shape, np.nan)
    for i in np.ndindex(al.shape):
        if am[i] > 1.0:
            continue
        q = []
        # the contact (k = beta - alpha, c = eta_c k) is shared: across, beta_y = k + alpha_y
        for amp, ph, a_, b_, z_ in ((ax[i], px[i], al[i], be[i], ze[i]),
                                    (ay[i], py[i], aly[i], be[i] - al[i] + aly[i], zey[i])):
            p, _, impedance, gp, rigid = _inplane_factors(
                np.asarray(a_), np.asarray(b_), np.asarray(z_), np.asarray(et[i]), on)
            with np.errstate(divide="ignore", invalid="ignore"):
                t = complex(-gp if rigid else -impedance * gp / (p + impedance))
            q.append(np.zeros_like(tau) if amp == 0.0 else np.real(amp * t * np.exp(1j * ph) * e))
        n = 1.0 + am[i] * np.cos(tau)
        out[(1, *i)], out[(0, *i)] = _axis_range(q[0], q[1], n)
        out[(3, *i)], out[(2, *i)] = _axis_range(q[1], q[0], n)
    return PlaneStatic(*(as_float_or_array(x) for x in out))


#: The regimes of :func:`inplane_regime`, in the order of their codes 0, 1, 2 (-1: the
#: contact slips in every cycle, no closed form).
INPLANE_REGIMES = ("reduction", "ratchet", "actuator")


def inplane_regime(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                   a_x: ArrayLike, phase_x: ArrayLike, zeta: ArrayLike = 0.0,
                   eta_c: ArrayLike = 0.0, inplane_on: str = "substrate",
                   rtol: float = 1e-9) -> NDArray[np.int8]:
    r"""The regime of the combined drive near ``V = 0``.

    From the static band of :func:`inplane_static_mu_ratio` (``upper = mu(0+)/mu0``, ``lower =
    mu(0-)/mu0``):

    * ``0`` **friction reduction**: ``lower < 0 < upper`` and ``upper = -lower`` (within
      ``rtol``): the oscillation lowers static friction equally both ways;
    * ``1`` **ratchet**: ``lower < 0 < upper``, ``upper != -lower``: a preferred
      direction, but a held body needs no force (0 is in the band);
    * ``2`` **actuator**: the band excludes 0 (``upper < 0`` or ``lower > 0``): the
      oscillation pushes; a held body carries a force, and the free body moves (at its
      idle velocity, where ``mu(V) = 0``);
    * ``-1``: no permanent stick (the contact slips in every cycle); the solver's
      ``mu(V -> 0+-)`` decide (docs/inplane.md, section 3).
    """
    upper, lower = (np.asarray(x, dtype=float) for x in inplane_static_mu_ratio(
        alpha, beta, amplitude, a_x, phase_x, zeta, eta_c, inplane_on))
    out = np.full(upper.shape, -1, dtype=np.int8)
    held = np.isfinite(upper)
    out[held & ((upper < 0.0) | (lower > 0.0))] = 2
    inside = held & (upper >= 0.0) & (lower <= 0.0)
    symmetric = np.abs(upper + lower) <= rtol * np.maximum(np.abs(upper), np.abs(lower))
    out[inside & symmetric] = 0
    out[inside & ~symmetric] = 1
    return out
