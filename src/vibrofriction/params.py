r"""Parameters of the model: dimensionless groups, SI parameters and the cases I-IV.

Mao, Popov, Starcevic & Popov, *Friction* (2017), Part II: eq. (20) defines
``alpha = k_x/(m omega^2)`` and ``beta = (k_x + k_xc)/(m omega^2)``; eq. (12)
the critical velocity ``v0*``; eq. (16) ``vbar = v0/v0*``; Section 3 the
limiting cases I-IV. Velocities are also given as the *inertial velocity*
``V = v0 m omega / (mu0 F_N0)`` (axis of Fig. 6), which stays finite where
``vbar`` does not (cases III and IV).
"""

from __future__ import annotations

import dataclasses
import enum
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibrofriction import theory
from vibrofriction.validation import as_float_or_array, checked, checked_beta

__all__ = ["Case", "Dimensionless", "Physical", "classify", "inertial_to_vbar",
           "vbar_factor", "vbar_to_inertial"]

FloatOrArray = float | NDArray[np.float64]


# --------------------------------------------------------------------------- validation
def _positive(name: str, value: Any) -> float:
    return float(checked(name, value, minimum=0.0, strict=True))


def _nonnegative(name: str, value: Any) -> float:
    return float(checked(name, value, minimum=0.0))


# --------------------------------------------------------------------------- vbar <-> V
def _undefined_vbar(alpha: NDArray[np.float64], amplitude: NDArray[np.float64],
                    factor: NDArray[np.float64]) -> str | None:
    """Why ``vbar`` does not exist at the first point where it does not, or None."""
    bad = (factor == 0.0) | np.isinf(factor)
    if not np.any(bad):
        return None
    al, am, c, b = (np.atleast_1d(x) for x in np.broadcast_arrays(alpha, amplitude, factor, bad))
    i = int(np.flatnonzero(b)[0])
    if math.isinf(c[i]):
        return f"alpha == 1 (case IV): v0* is infinite (alpha = {al[i]!r})"
    if am[i] == 0.0:
        return "amplitude == 0: v0* is zero"
    return "beta == 1 (case III): v0* is zero"


def vbar_factor(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike) -> NDArray[np.float64]:
    """``c = V/vbar`` (eqs. 12, 16, 20) elementwise; ValueError where ``vbar`` is undefined."""
    al = checked("alpha", alpha, minimum=0.0, strict=True)
    am = checked("amplitude", amplitude, minimum=0.0)
    c = np.asarray(theory.inertial_per_vbar(al, beta, am), dtype=float)
    why = _undefined_vbar(al, am, c)
    if why is not None:
        raise ValueError(f"vbar is undefined for {why}; use the inertial velocity "
                         "v_inertial instead")
    return c


def vbar_to_inertial(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                     vbar: ArrayLike) -> FloatOrArray:
    """Inertial velocity ``V = v0 m omega/(mu0 F_N0) = c vbar`` (eqs. 12, 16), elementwise.

    The one conversion from ``vbar = v0/v0*`` to ``V`` in the package.  ValueError where
    ``vbar`` is undefined (``alpha = 1``, ``beta = 1`` or ``a = 0``) or negative.
    """
    v = checked("vbar", vbar, minimum=0.0)
    return as_float_or_array(vbar_factor(alpha, beta, amplitude) * v)


def inertial_to_vbar(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                     v_inertial: ArrayLike) -> FloatOrArray:
    """``vbar = V / c`` (eqs. 12, 16), elementwise: the inverse of :func:`vbar_to_inertial`."""
    V = checked("v_inertial", v_inertial, minimum=0.0)
    return as_float_or_array(V / vbar_factor(alpha, beta, amplitude))


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
    alpha = _positive("alpha", alpha)
    beta = float(checked_beta(alpha, beta))
    rtol = _nonnegative("rtol", rtol)
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


# --------------------------------------------------------------------------- dimensionless
@dataclass(frozen=True)
class Dimensionless:
    r"""The paper's dimensionless parameters, eqs. (20) and (24).

    Parameters
    ----------
    alpha : float
        ``k_x / (m omega^2)``, finite and > 0.
    beta : float
        ``(k_x + k_xc) / (m omega^2)``, > ``alpha``; ``math.inf`` is a rigid contact.
    amplitude : float
        ``a = du_z / u_z0 = dF_N / F_N0``, finite and >= 0; ``a > 1`` is jumping.
    """

    alpha: float
    beta: float
    amplitude: float

    def __post_init__(self) -> None:
        alpha = _positive("alpha", self.alpha)
        object.__setattr__(self, "alpha", alpha)
        object.__setattr__(self, "beta", float(checked_beta(alpha, self.beta)))
        object.__setattr__(self, "amplitude", _nonnegative("amplitude", self.amplitude))

    @property
    def case(self) -> Case:
        """The limiting case, ``classify(alpha, beta)`` with default thresholds."""
        return classify(self.alpha, self.beta)

    @property
    def is_rigid(self) -> bool:
        """``True`` for a rigid contact, ``beta = inf``."""
        return math.isinf(self.beta)

    @property
    def jumping(self) -> bool:
        """``True`` if the contact opens once per period, ``a > 1``."""
        return self.amplitude > 1.0

    @property
    def inertial_per_vbar(self) -> float:
        """``c`` with ``V = c vbar``: ``a|beta - 1| / ((beta - alpha)|alpha - 1|)``, eq. (12).

        ``inf`` in case IV (``alpha = 1``), ``0`` in case III (``beta = 1``) or if ``a = 0``.
        """
        return float(theory.inertial_per_vbar(self.alpha, self.beta, self.amplitude))

    def critical_inertial_velocity(self) -> float:
        """Inertial velocity ``V*`` at ``vbar = 1`` (eq. 12 over ``mu0 F_N0/(m omega)``)."""
        return self.inertial_per_vbar

    def vbar_to_inertial(self, vbar: ArrayLike) -> FloatOrArray:
        """Inertial velocity ``V = c vbar`` (eqs. 12, 16); ValueError where vbar is undefined."""
        return vbar_to_inertial(self.alpha, self.beta, self.amplitude, vbar)

    def inertial_to_vbar(self, v_inertial: ArrayLike) -> FloatOrArray:
        """``vbar = V / c`` (eqs. 12, 16); ValueError where ``vbar`` is undefined."""
        return inertial_to_vbar(self.alpha, self.beta, self.amplitude, v_inertial)


# --------------------------------------------------------------------------- physical
@dataclass(frozen=True)
class Physical:
    r"""Parameters of the model in SI units (Fig. 1b).

    Parameters
    ----------
    mass : float
        Mass ``m`` of the body, kg.
    k_x : float
        Tangential stiffness of the system spring, N/m.
    k_xc : float
        Tangential contact stiffness, N/m; ``math.inf`` is a rigid contact.
    k_zc : float
        Normal contact stiffness, N/m.
    u_z0 : float
        Mean indentation, m (eq. 1).
    du_z : float
        Amplitude of the normal oscillation, m, ``>= 0`` (eq. 1).
    omega : float
        Angular frequency of the oscillation, rad/s.
    mu0 : float
        Local (microscopic) coefficient of friction.
    """

    mass: float
    k_x: float
    k_xc: float
    k_zc: float
    u_z0: float
    du_z: float
    omega: float
    mu0: float

    def __post_init__(self) -> None:
        for name in ("mass", "k_x", "k_zc", "u_z0", "omega", "mu0"):
            object.__setattr__(self, name, _positive(name, getattr(self, name)))
        k_xc = float(checked("k_xc", self.k_xc, minimum=0.0, strict=True, allow_inf=True))
        object.__setattr__(self, "k_xc", k_xc)
        object.__setattr__(self, "du_z", _nonnegative("du_z", self.du_z))

    def with_(self, **changes: float) -> Physical:
        """A copy with some fields replaced (validated again)."""
        return dataclasses.replace(self, **changes)

    @property
    def F_N0(self) -> float:
        """Mean normal force ``k_zc u_z0`` without jumping, N (eq. 3)."""
        return self.k_zc * self.u_z0

    @property
    def dF_N(self) -> float:
        """Amplitude of the normal force ``k_zc du_z``, N (eq. 3)."""
        return self.k_zc * self.du_z

    def natural_frequency(self) -> float:
        """``omega_0 = sqrt(k_x / m)`` of the body on the system spring, rad/s."""
        return math.sqrt(self.k_x / self.mass)

    def to_dimensionless(self) -> Dimensionless:
        """``alpha``, ``beta`` (eq. 20) and ``a = du_z/u_z0``."""
        stiffness = self.mass * self.omega**2
        return Dimensionless(
            alpha=self.k_x / stiffness,
            beta=(self.k_x + self.k_xc) / stiffness,
            amplitude=self.du_z / self.u_z0,
        )

    def critical_velocity(self) -> float:
        """``v0*`` of eq. (12), m/s.

        ``inf`` if ``k_x = m omega^2`` (case IV), 0 if ``k_x + k_xc = m omega^2`` (case III)
        or ``du_z = 0``; ``k_xc = inf`` gives ``mu0 omega du_z k_zc / |k_x - m omega^2|``.
        """
        return float(theory.critical_velocity(self.mu0, self.omega, self.du_z, self.k_zc,
                                              self.k_xc, self.k_x, self.mass))

    def _velocity_unit(self) -> float:
        return self.mu0 * self.F_N0 / (self.mass * self.omega)

    def v0_to_inertial(self, v0: ArrayLike) -> FloatOrArray:
        """``V = v0 m omega / (mu0 F_N0)``, the velocity axis of Fig. 6."""
        return as_float_or_array(checked("v0", v0, minimum=0.0) / self._velocity_unit())

    def inertial_to_v0(self, v_inertial: ArrayLike) -> FloatOrArray:
        """``v0 = V mu0 F_N0 / (m omega)``, m/s."""
        return as_float_or_array(checked("v_inertial", v_inertial, minimum=0.0)
                                 * self._velocity_unit())

    def v0_to_vbar(self, v0: ArrayLike) -> FloatOrArray:
        """``vbar = v0 / v0*`` (eq. 16); ValueError where ``v0*`` is 0 or infinite."""
        return self.to_dimensionless().inertial_to_vbar(self.v0_to_inertial(v0))

    def vbar_to_v0(self, vbar: ArrayLike) -> FloatOrArray:
        """``v0 = vbar v0*`` (eq. 16), m/s; ValueError where ``v0*`` is 0 or infinite."""
        return self.inertial_to_v0(self.to_dimensionless().vbar_to_inertial(vbar))
