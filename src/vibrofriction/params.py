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

__all__ = ["Case", "Dimensionless", "Physical", "classify"]

FloatOrArray = float | NDArray[np.float64]


# --------------------------------------------------------------------------- validation
def _positive(name: str, value: Any) -> float:
    x = float(value)
    if not (math.isfinite(x) and x > 0.0):
        raise ValueError(f"{name} must be finite and > 0, got {x!r}")
    return x


def _nonnegative(name: str, value: Any) -> float:
    x = float(value)
    if not (math.isfinite(x) and x >= 0.0):
        raise ValueError(f"{name} must be finite and >= 0, got {x!r}")
    return x


def _beta(alpha: float, value: Any) -> float:
    x = float(value)
    if not (x > alpha):  # also rejects nan
        raise ValueError(f"beta must be > alpha (= {alpha!r}) or math.inf, got {x!r}")
    return x


def _velocity(name: str, value: ArrayLike) -> NDArray[np.float64]:
    arr = np.asarray(value, dtype=float)
    bad = ~(np.isfinite(arr) & (arr >= 0.0))
    if np.any(bad):
        first = float(np.atleast_1d(arr)[np.atleast_1d(bad)][0])
        raise ValueError(f"{name} must be finite and >= 0, got {first!r}")
    return arr


def _out(x: ArrayLike) -> FloatOrArray:
    arr = np.asarray(x, dtype=float)
    return float(arr) if arr.ndim == 0 else arr


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
    beta = _beta(alpha, beta)
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
        object.__setattr__(self, "beta", _beta(alpha, self.beta))
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

    def _checked_factor(self) -> float:
        c = self.inertial_per_vbar
        if c == 0.0 or math.isinf(c):
            if math.isinf(c):
                why = "alpha == 1 (case IV): v0* is infinite"
            elif self.amplitude == 0.0:
                why = "amplitude == 0: v0* is zero"
            else:
                why = "beta == 1 (case III): v0* is zero"
            raise ValueError(
                f"vbar is undefined for {why}; use the inertial velocity v_inertial instead"
            )
        return c

    def vbar_to_inertial(self, vbar: ArrayLike) -> FloatOrArray:
        """Inertial velocity ``V = c vbar`` (eqs. 12, 16); ValueError where vbar is undefined."""
        v = _velocity("vbar", vbar)
        return _out(self._checked_factor() * v)

    def inertial_to_vbar(self, v_inertial: ArrayLike) -> FloatOrArray:
        """``vbar = V / c`` (eqs. 12, 16); ValueError where ``vbar`` is undefined."""
        V = _velocity("v_inertial", v_inertial)
        return _out(V / self._checked_factor())


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
        k_xc = float(self.k_xc)
        if not k_xc > 0.0:
            raise ValueError(f"k_xc must be > 0 (math.inf allowed), got {k_xc!r}")
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
        return _out(_velocity("v0", v0) / self._velocity_unit())

    def inertial_to_v0(self, v_inertial: ArrayLike) -> FloatOrArray:
        """``v0 = V mu0 F_N0 / (m omega)``, m/s."""
        return _out(_velocity("v_inertial", v_inertial) * self._velocity_unit())

    def v0_to_vbar(self, v0: ArrayLike) -> FloatOrArray:
        """``vbar = v0 / v0*`` (eq. 16); ValueError where ``v0*`` is 0 or infinite."""
        v = _velocity("v0", v0)
        return self.to_dimensionless().inertial_to_vbar(v / self._velocity_unit())

    def vbar_to_v0(self, vbar: ArrayLike) -> FloatOrArray:
        """``v0 = vbar v0*`` (eq. 16), m/s; ValueError where ``v0*`` is 0 or infinite."""
        V = np.asarray(self.to_dimensionless().vbar_to_inertial(vbar))
        return _out(V * self._velocity_unit())
