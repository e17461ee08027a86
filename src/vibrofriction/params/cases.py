"""The velocity ``vbar = v0/v0*`` (eq. 16) and the limiting cases I-IV (Section 3).

``vbar`` against the inertial velocity ``V``, and the cases' classification.
"""

from __future__ import annotations

import enum
import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibrofriction import theory
from vibrofriction.schema import NONNEGATIVE
from vibrofriction.validation import as_float_or_array, checked, validated

from .fields import FloatOrArray, valid_array


# --------------------------------------------------------------------------- vbar <-> V
def _undefined_vbar(alpha: NDArray[np.float64], amplitude: NDArray[np.float64],
                    factor: NDArray[np.float64],
                    curved: NDArray[np.bool_] | bool = False) -> str | None:
    """Why ``vbar`` does not exist at the first point where it does not, or None."""
    bad = (factor == 0.0) | np.isinf(factor)
    if not np.any(bad):
        return None
    al, am, c, b, cu = (np.atleast_1d(x)
                        for x in np.broadcast_arrays(alpha, amplitude, factor, bad, curved))
    i = int(np.flatnonzero(b)[0])
    if cu[i] and am[i] != 0.0:
        # theory.profile_critical_velocity: inf undamped at alpha = k^2, every harmonic k of
        # the curved tip's normal force
        return (f"a curved tip at alpha = {al[i]:g}: v0* is "
                + ("infinite (undamped, alpha = k^2 for a harmonic k of its normal force)"
                   if math.isinf(c[i]) else "zero"))
    if math.isinf(c[i]):
        return f"alpha == 1 (case IV): v0* is infinite (alpha = {al[i]:g})"
    if am[i] == 0.0:
        return "amplitude == 0: v0* is zero"
    return "beta == 1 (case III): v0* is zero"


def critical_for_vbar(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                       zeta: ArrayLike = 0.0, eta_c: ArrayLike = 0.0,
                       profile_exponent: ArrayLike = math.inf) -> NDArray[np.float64]:
    """``V_c = V/vbar`` (eqs. 12, 16, 20; damped: docs/damping.md) elementwise.

    A curved tip (finite ``profile_exponent``, the MDR contact): its critical velocity of
    continuous sliding, :func:`~vibrofriction.theory.profile_critical_velocity`
    (docs/contact_geometry.md; derived without contact damping: ``eta_c > 0`` is refused).
    ValueError where ``vbar`` is undefined.
    """
    al, am = validated({"alpha": alpha, "amplitude": amplitude}).values()
    c = np.asarray(theory.critical_inertial_velocity(al, beta, am, zeta, eta_c), dtype=float)
    curved = np.isfinite(np.asarray(profile_exponent, dtype=float))
    if np.any(curved):
        if np.any(curved & (np.asarray(eta_c, dtype=float) > 0.0)):
            raise ValueError("vbar of a curved tip is derived without contact damping "
                             "(eta_c > 0; docs/contact_geometry.md): use the inertial "
                             "velocity v_inertial instead")
        tip = np.asarray(theory.profile_critical_velocity(al, beta, am, profile_exponent,
                                                          zeta), dtype=float)
        c = np.where(curved, tip, c)
    why = _undefined_vbar(al, am, c, curved)
    if why is not None:
        raise ValueError(f"vbar is undefined for {why}; use the inertial velocity "
                         "v_inertial instead")
    return c


def vbar_to_inertial(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                     vbar: ArrayLike, zeta: ArrayLike = 0.0,
                     eta_c: ArrayLike = 0.0,
                     profile_exponent: ArrayLike = math.inf) -> FloatOrArray:
    """Inertial velocity ``V = v0 m omega/(mu0 F_N0) = c vbar`` (eqs. 12, 16), elementwise.

    The one conversion from ``vbar = v0/v0*`` to ``V`` in the package.

    Parameters
    ----------
    alpha, beta, amplitude : array_like
        The system's groups (eq. 20).
    vbar : array_like
        ``v0/v0*``, ``>= 0``.
    zeta, eta_c : array_like, optional
        The damping of the pin and of the contact (docs/damping.md).
    profile_exponent : array_like, optional
        ``n`` of a curved tip ``z = c r^n`` (the MDR contact): ``c`` is then its critical
        velocity, :func:`~vibrofriction.theory.profile_critical_velocity`; ``inf`` (the
        default) a flat punch.

    Returns
    -------
    float or ndarray
        ``V``, of the inputs' broadcast shape.

    Raises
    ------
    ValueError
        Where ``vbar`` is undefined (``alpha = 1``, ``beta = 1`` or ``a = 0``; a curved tip
        at an undamped ``alpha = k^2``, or with ``eta_c > 0``) or negative.

    Examples
    --------
    >>> from vibrofriction.params import vbar_to_inertial
    >>> vbar_to_inertial(0.5, 2.0, 0.5, [0.3, 1.0])  # c = a|beta - 1|/((beta - alpha)|alpha - 1|)
    array([0.2       , 0.66666667])
    """
    v = valid_array("vbar", vbar)
    return as_float_or_array(critical_for_vbar(alpha, beta, amplitude, zeta, eta_c,
                                               profile_exponent) * v)


def inertial_to_vbar(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                     v_inertial: ArrayLike, zeta: ArrayLike = 0.0,
                     eta_c: ArrayLike = 0.0,
                     profile_exponent: ArrayLike = math.inf) -> FloatOrArray:
    """``vbar = V / c`` (eqs. 12, 16), elementwise: the inverse of :func:`vbar_to_inertial`.

    ``vbar`` is defined for ``V >= 0`` only (a backward velocity has no ``vbar``).

    Parameters
    ----------
    alpha, beta, amplitude, zeta, eta_c, profile_exponent : array_like
        The system, as for :func:`vbar_to_inertial`.
    v_inertial : array_like
        ``V``, ``>= 0``.

    Returns
    -------
    float or ndarray
        ``vbar``, of the inputs' broadcast shape.

    Raises
    ------
    ValueError
        Where ``vbar`` is undefined (as in :func:`vbar_to_inertial`) or ``V < 0``.

    Examples
    --------
    >>> from vibrofriction.params import inertial_to_vbar
    >>> inertial_to_vbar(0.5, 2.0, 0.5, 0.2)
    0.3...
    """
    V = validated({"v_inertial": v_inertial}, ranges={"v_inertial": NONNEGATIVE})["v_inertial"]
    return as_float_or_array(V / critical_for_vbar(alpha, beta, amplitude, zeta, eta_c,
                                                   profile_exponent))


# --------------------------------------------------------------------------- cases
class Case(enum.Enum):
    """The limiting cases of Section 3 (eqs. 13, 14 and the resonances)."""

    SOFT = "I"
    STIFF = "II"
    RESONANT_CONTACT = "III"
    RESONANT_SYSTEM = "IV"
    GENERAL = "general"

    @property
    def description(self) -> str:
        """One sentence saying what the case is and what the paper predicts."""
        return _CASE_DESCRIPTIONS[self]


_CASE_DESCRIPTIONS = {
    Case.SOFT: (
        "Case I, soft system on a stiff contact (alpha << 1 << beta): "
        "v0* = mu0 dF_N/(m omega), eq. (13); friction law of Teidelt et al., eq. (27)."
    ),
    Case.STIFF: (
        "Case II, stiff system (k_xc << |k_x - m omega^2|, i.e. beta - alpha << |alpha - 1|): "
        "v0* = mu0 omega du_z k_zc/k_xc, eq. (14); semi-empirical law of Part I, eq. (26)."
    ),
    Case.RESONANT_CONTACT: (
        "Case III, contact resonance (beta ~ 1): v0* ~ 0, the contact slides at all "
        "velocities and mu = mu0."
    ),
    Case.RESONANT_SYSTEM: (
        "Case IV, system resonance (alpha ~ 1): v0* is infinite and mu/mu0 tends to a "
        "plateau below 1 (about 1 - a/2) at large velocity."
    ),
    Case.GENERAL: (
        "General case: none of the limits I-IV applies; v0* is given by eq. (12)."
    ),
}


def classify(alpha: float, beta: float, rtol: float = 0.05, ratio: float = 0.1) -> Case:
    """Limiting case of Section 3 to which ``(alpha, beta)`` belongs.

    Tested in this order (the first match wins):

    1. ``RESONANT_SYSTEM`` (IV) if ``|alpha - 1| <= rtol``;
    2. ``RESONANT_CONTACT`` (III) if ``|beta - 1| <= rtol``;
    3. ``STIFF`` (II) if ``beta - alpha <= ratio * |alpha - 1|`` (eq. 14's condition
       ``k_xc << |k_x - m omega^2|``);
    4. ``SOFT`` (I) if ``alpha <= ratio`` and ``beta >= 1/ratio`` (``k_x << m omega^2 << k_xc``);
    5. ``GENERAL`` otherwise.

    The resonances come first because near them the ratios in (12) are what
    matter. The paper's points: ``(0.01, 0.02)`` is II, ``(0.01, 400.01)`` is I
    (Section 5 of the paper calls ``(0.01, 0.02)`` "case I" and Section 7 speaks of
    "the case I of a stiff system": both swap the labels of Section 3).

    Parameters
    ----------
    alpha, beta : float
        Eq. (20); ``alpha > 0``, ``beta > alpha`` (``math.inf`` for a rigid contact).
    rtol : float
        Half-width of the resonance bands, ``>= 0``.
    ratio : float
        What "much smaller" means, in ``(0, 1)``.
    """
    alpha, beta = (float(x) for x in validated({"alpha": alpha, "beta": beta}).values())
    rtol = float(checked("rtol", rtol, minimum=0.0))
    ratio = float(ratio)
    if not 0.0 < ratio < 1.0:
        raise ValueError(f"ratio must be in (0, 1), got {ratio!r}")
    if abs(alpha - 1.0) <= rtol:
        return Case.RESONANT_SYSTEM
    if abs(beta - 1.0) <= rtol:
        return Case.RESONANT_CONTACT
    if beta - alpha <= ratio * abs(alpha - 1.0):
        return Case.STIFF
    if alpha <= ratio and beta >= 1.0 / ratio:
        return Case.SOFT
    return Case.GENERAL
