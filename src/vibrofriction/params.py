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
import functools
import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibrofriction import theory
from vibrofriction.schema import NONNEGATIVE, PARAMETER, parameter_names
from vibrofriction.validation import as_float_or_array, checked, checked_choice, validated

__all__ = ["Case", "Dimensionless", "Physical", "System", "classify", "dimensionless",
           "inertial_to_vbar", "inertial_velocity", "pin_damping",
           "vbar_to_inertial"]

FloatOrArray = float | NDArray[np.float64]

# --------------------------------------------------------------------------- validation
def _valid(name: str, value: Any) -> float:
    """One model parameter as a float, checked against its schema range."""
    return float(validated({name: value})[name])


def _valid_array(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """One model parameter as a float array, checked against its schema range."""
    return validated({name: value})[name]


def _validate_fields(obj: Any, model: str) -> None:
    """Check the fields of a frozen model dataclass against the schema's ranges
    (:func:`~vibrofriction.validation.validated`) and store them as floats; an optional
    field (``Parameter.twin``) left None stays None (its twin's value, whatever that is)."""
    given = {name: getattr(obj, name) for name in parameter_names(model)}
    values = validated({n: v for n, v in given.items() if v is not None
                        or not PARAMETER[n].twin})
    for name, value in values.items():
        object.__setattr__(obj, name, float(value))


def pin_damping(k_x: float, mass: float, *, zeta: float | None = None,
                quality_factor: float | None = None) -> float:
    """The pin dashpot ``c_x`` (N s/m) from its damping ratio or its quality factor.

    ``c_x = 2 zeta sqrt(k_x m)`` with ``zeta = 1/(2Q)``: ``Q`` is what an impact test
    gives (the free decay of the pin with the contact open, paper Fig. 8b).  Exactly
    one of ``zeta`` (``>= 0``) and ``quality_factor`` (``> 0``, ``inf`` undamped).
    """
    if (zeta is None) == (quality_factor is None):
        raise ValueError("give exactly one of zeta and quality_factor")
    k_x = _valid("k_x", k_x)
    mass = _valid("mass", mass)
    if zeta is None:
        assert quality_factor is not None  # exactly one of them is given
        q = float(checked("quality_factor", quality_factor, minimum=0.0, strict=True,
                          allow_inf=True))
        zeta = 0.0 if math.isinf(q) else 1.0 / (2.0 * q)
    return 2.0 * _valid("zeta", zeta) * math.sqrt(k_x * mass)


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


def _critical_for_vbar(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                       zeta: ArrayLike = 0.0, eta_c: ArrayLike = 0.0) -> NDArray[np.float64]:
    """``V_c = V/vbar`` (eqs. 12, 16, 20; damped: docs/damping.md) elementwise;
    ValueError where ``vbar`` is undefined."""
    al, am = validated({"alpha": alpha, "amplitude": amplitude}).values()
    c = np.asarray(theory.critical_inertial_velocity(al, beta, am, zeta, eta_c), dtype=float)
    why = _undefined_vbar(al, am, c)
    if why is not None:
        raise ValueError(f"vbar is undefined for {why}; use the inertial velocity "
                         "v_inertial instead")
    return c


def vbar_to_inertial(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                     vbar: ArrayLike, zeta: ArrayLike = 0.0,
                     eta_c: ArrayLike = 0.0) -> FloatOrArray:
    """Inertial velocity ``V = v0 m omega/(mu0 F_N0) = c vbar`` (eqs. 12, 16), elementwise.

    The one conversion from ``vbar = v0/v0*`` to ``V`` in the package.  ValueError where
    ``vbar`` is undefined (``alpha = 1``, ``beta = 1`` or ``a = 0``) or negative.
    """
    v = _valid_array("vbar", vbar)
    return as_float_or_array(_critical_for_vbar(alpha, beta, amplitude, zeta, eta_c) * v)


def inertial_to_vbar(alpha: ArrayLike, beta: ArrayLike, amplitude: ArrayLike,
                     v_inertial: ArrayLike, zeta: ArrayLike = 0.0,
                     eta_c: ArrayLike = 0.0) -> FloatOrArray:
    """``vbar = V / c`` (eqs. 12, 16), elementwise: the inverse of :func:`vbar_to_inertial`.

    ``vbar`` is defined for ``V >= 0`` only (a backward velocity has no ``vbar``)."""
    V = validated({"v_inertial": v_inertial}, ranges={"v_inertial": NONNEGATIVE})["v_inertial"]
    return as_float_or_array(V / _critical_for_vbar(alpha, beta, amplitude, zeta, eta_c))


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
    zeta : float
        Damping ratio of the pin, ``c_x / (2 sqrt(k_x m))`` (``= 1/(2Q)`` of its free
        decay with the contact open), finite and >= 0 (docs/damping.md).
    eta_c : float
        Loss factor of the contact, ``omega c_xc / k_xc`` (the loss tangent of the
        tangential contact at the drive frequency), finite and >= 0; ignored by a
        rigid contact.
    a_x : float
        Amplitude of the longitudinal in-plane oscillation ``a_x cos(tau + phase_x)``,
        ``du_x m omega^2 / (mu0 F_N0)`` (also its velocity amplitude ``omega du_x`` in
        units of the inertial velocity), finite and >= 0 (docs/inplane.md).
    phase_x : float
        Its phase relative to the normal oscillation, radians, finite.
    a_y : float
        Amplitude of the transverse in-plane oscillation ``a_y cos(tau + phase_y)``
        (across the sliding), ``du_y m omega^2 / (mu0 F_N0)``, finite and >= 0; ``a_y > 0``
        is computed by the 2-D solver (docs/inplane.md, "The 2-D solver").
    phase_y : float
        Its phase relative to the normal oscillation, radians, finite.
    alpha_y, zeta_y : float or None
        The pin across the sliding (the 2-D solver, ``a_y > 0``): ``k_y / (m omega^2)``
        (finite and > 0) and ``c_y / (2 sqrt(k_y m))`` (finite and >= 0); None (default)
        is ``alpha``, ``zeta``: an axisymmetric pin (:attr:`pin_y`).  Without a transverse
        oscillation they have no effect (the body never moves across).
    profile_exponent : float
        Exponent ``n`` of the pin's axisymmetric tip ``z = c r^n`` (``1`` a cone, ``2`` a
        sphere), ``> 0``; ``math.inf`` (default) is the flat punch, the seed's single
        spring.  A finite ``n`` is the scaled MDR contact of docs/contact_geometry.md
        (``beta`` with the fully stuck contact's ``k_xc0 = 2 G* a0``, ``a = dd/d0``,
        velocities with ``F_N0 = F(d0)``), computed by the MDR solver.
    inplane_on : str
        ``"substrate"`` (default: the contact point sticks to the oscillating substrate,
        slip is relative to it) or ``"holder"`` (the pulled end of the system spring and
        dashpot oscillates; the substrate is at rest).
    """

    alpha: float
    beta: float
    amplitude: float
    zeta: float = 0.0
    eta_c: float = 0.0
    a_x: float = 0.0
    phase_x: float = 0.0
    a_y: float = 0.0
    phase_y: float = 0.0
    alpha_y: float | None = None
    zeta_y: float | None = None
    profile_exponent: float = math.inf
    inplane_on: str = "substrate"

    def __post_init__(self) -> None:
        _validate_fields(self, "dimensionless")
        checked_choice("inplane_on", self.inplane_on)

    @property
    def pin_y(self) -> tuple[float, float]:
        """``(alpha_y, zeta_y)`` with None resolved to ``alpha``, ``zeta``: the pin across
        the sliding."""
        return (self.alpha if self.alpha_y is None else self.alpha_y,
                self.zeta if self.zeta_y is None else self.zeta_y)

    @property
    def damped(self) -> bool:
        """``True`` if the pin or the contact has a dashpot."""
        return self.zeta > 0.0 or (self.eta_c > 0.0 and not self.is_rigid)

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
    def curved(self) -> bool:
        """``True`` for a curved tip (finite ``profile_exponent``: the MDR contact)."""
        return self.profile_exponent != math.inf

    def _check_flat(self, what: str) -> None:
        if self.curved:
            raise ValueError(f"{what} is not wired for a curved profile yet "
                             f"(profile_exponent = {self.profile_exponent!r}; its critical "
                             "velocity is critical_inertial_velocity(), "
                             "docs/contact_geometry.md): use the inertial velocity v_inertial")

    def critical_inertial_velocity(self) -> float:
        """``V_c``, the inertial velocity of continuous forward sliding (eq. 12 with
        damping; with a longitudinal in-plane oscillation, the combined drive's).

        Normal oscillation only, it is the velocity at ``vbar = 1``, undamped ``a|beta -
        1| / ((beta - alpha)|alpha - 1|)``: ``inf`` in case IV (``alpha = 1``), ``0`` in
        case III (``beta = 1``); damping makes both finite and positive
        (``theory.critical_inertial_velocity``, docs/damping.md).  With ``a_x > 0`` it is
        ``theory.inplane_critical_velocity`` (docs/inplane.md); backward sliding needs
        ``|V|`` above the same expression at ``phase_x + pi``.  With a transverse
        oscillation (``a_y > 0``) ``inf``: the friction force turns with the slip
        velocity and is below ``mu0`` at every velocity (the kinematic law,
        docs/inplane.md section 1).  A curved profile (finite ``profile_exponent``, MDR):
        ``theory.profile_critical_velocity`` (the total normal force is not harmonic;
        docs/contact_geometry.md), refused with ``eta_c``, ``a_x`` or ``a_y`` > 0.
        """
        if self.curved:
            for name, value in (("eta_c", self.eta_c), ("a_x", self.a_x), ("a_y", self.a_y)):
                if value > 0.0:
                    raise ValueError(f"the critical velocity of a curved profile is derived "
                                     f"without {name} (got {name} = {value!r}; "
                                     "docs/contact_geometry.md)")
            return float(theory.profile_critical_velocity(
                self.alpha, self.beta, self.amplitude, self.profile_exponent, self.zeta))
        if self.a_y > 0.0:
            return math.inf
        return float(theory.critical_inertial_velocity(
            self.alpha, self.beta, self.amplitude, self.zeta, self.eta_c, self.a_x,
            self.phase_x, self.inplane_on))

    @functools.cached_property
    def _vbar_unit(self) -> float:
        """``V_c`` where ``vbar`` exists (computed once per system: the fields are frozen
        and validated); ValueError where it does not (not cached), and with an in-plane
        oscillation, whose velocities are signed and have no ``vbar`` (eq. 16 scales
        by the normal oscillation's ``v0*`` only)."""
        self._check_vbar_inplane()
        return float(_critical_for_vbar(self.alpha, self.beta, self.amplitude, self.zeta,
                                        self.eta_c))

    def _check_vbar_inplane(self) -> None:
        self._check_flat("vbar (v0/v0* of eq. 16)")
        if self.a_x > 0.0 or self.a_y > 0.0:
            raise ValueError(f"vbar (v0/v0* of eq. 16) is not defined with an in-plane "
                             f"oscillation (a_x = {self.a_x!r}, a_y = {self.a_y!r}); use the "
                             "inertial velocity v_inertial (signed) instead")

    def vbar_to_inertial(self, vbar: ArrayLike) -> FloatOrArray:
        """Inertial velocity ``V = V_c vbar`` (eqs. 12, 16); ValueError where vbar is undefined."""
        return as_float_or_array(self._vbar_unit * _valid_array("vbar", vbar))

    def inertial_to_vbar(self, v_inertial: ArrayLike) -> FloatOrArray:
        """``vbar = V / V_c`` (eqs. 12, 16); ValueError where ``vbar`` is undefined."""
        self._check_vbar_inplane()
        return inertial_to_vbar(self.alpha, self.beta, self.amplitude, v_inertial, self.zeta,
                                self.eta_c)


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
    c_x : float
        Pin dashpot parallel to ``k_x``, N s/m, ``>= 0`` (:func:`pin_damping` gives it
        from a damping ratio or quality factor; :meth:`with_damping`).
    c_xc : float
        Tangential contact dashpot parallel to ``k_xc`` (Kelvin-Voigt), N s/m, ``>= 0``.
    du_x : float
        Amplitude of the longitudinal in-plane oscillation ``du_x cos(omega t + phase_x)``,
        m, ``>= 0`` (docs/inplane.md).
    phase_x : float
        Its phase relative to the normal oscillation, radians, finite.
    du_y : float
        Amplitude of the transverse in-plane oscillation ``du_y cos(omega t + phase_y)``
        (across the sliding), m, ``>= 0``.
    phase_y : float
        Its phase relative to the normal oscillation, radians, finite.
    k_y, c_y : float or None
        The pin's stiffness (N/m, finite and > 0) and dashpot (N s/m, >= 0) across the
        sliding; None (default) is ``k_x``, ``c_x``: an axisymmetric pin (:attr:`pin_y`).
        They act only with a transverse oscillation (``du_y > 0``).
    profile_exponent : float
        Exponent ``n`` of the tip ``z = c r^n``; ``math.inf`` (default): the linear contact
        of the fields above (a flat punch, or a curved tip linearised at its load).  A
        finite ``n`` is the MDR contact (docs/contact_geometry.md): ``u_z0`` is the mean
        indentation ``d0``, ``k_zc = 2 E* a0`` and ``k_xc = 2 G* a0`` the tangent normal
        and the fully stuck tangential stiffness at ``d0`` (contact radius ``a0``), and the
        mean-indentation load is ``F_N0 = F(d0) = k_zc u_z0 n/(n + 1)``
        (:func:`~vibrofriction.bench.from_bench` with ``contact_model="mdr"`` builds it).
    inplane_on : str
        Where both components are imposed: ``"substrate"`` (default) or ``"holder"`` (the pulled end
        of ``k_x`` and ``c_x``).
    """

    mass: float
    k_x: float
    k_xc: float
    k_zc: float
    u_z0: float
    du_z: float
    omega: float
    mu0: float
    c_x: float = 0.0
    c_xc: float = 0.0
    du_x: float = 0.0
    phase_x: float = 0.0
    du_y: float = 0.0
    phase_y: float = 0.0
    k_y: float | None = None
    c_y: float | None = None
    profile_exponent: float = math.inf
    inplane_on: str = "substrate"

    #: How :func:`~vibrofriction.bench.from_bench` set ``u_z0`` from its load (not a field:
    #: the model is the imposed indentation about ``u_z0`` either way, and a copy made by
    #: :meth:`with_` is ``"indentation"`` again): ``"indentation"`` (``F(u_z0)`` is the load) or
    #: ``"dead_weight"`` (:attr:`mean_normal_force` is the load).
    normal_control: ClassVar[str] = "indentation"

    def __post_init__(self) -> None:
        _validate_fields(self, "physical")
        checked_choice("inplane_on", self.inplane_on)

    @property
    def pin_y(self) -> tuple[float, float]:
        """``(k_y, c_y)`` with None resolved to ``k_x``, ``c_x``: the pin across the
        sliding."""
        return (self.k_x if self.k_y is None else self.k_y,
                self.c_x if self.c_y is None else self.c_y)

    def with_(self, **changes: Any) -> Physical:
        """A copy with some fields replaced (validated again)."""
        return dataclasses.replace(self, **changes)

    @property
    def curved(self) -> bool:
        """``True`` for a curved tip (finite ``profile_exponent``: the MDR contact)."""
        return self.profile_exponent != math.inf

    @property
    def F_N0(self) -> float:
        """Normal force at the mean indentation, N: ``k_zc u_z0`` (eq. 3; the mean force
        without jumping); for a curved MDR contact ``F(d0) = k_zc u_z0 n/(n + 1)``."""
        if self.curved:
            n = self.profile_exponent
            return self.k_zc * self.u_z0 * n / (n + 1.0)
        return self.k_zc * self.u_z0

    @property
    def mean_normal_force(self) -> float:
        """Mean normal force over the cycle, N: ``F_N0 <F(u_z0 + du_z cos)>/F(u_z0)``,
        ``F_N0`` times :func:`~vibrofriction.theory.profile_mean_normal_force` of
        ``a = du_z/u_z0`` (a linear contact: :func:`~vibrofriction.theory.mean_normal_force`,
        ``F_N0`` unless it jumps); the load of a dead weight
        (:func:`~vibrofriction.bench.from_bench`)."""
        a = self.du_z / self.u_z0
        return self.F_N0 * float(theory.profile_mean_normal_force(a, self.profile_exponent))

    @property
    def dF_N(self) -> float:
        """Amplitude of the normal force ``k_zc du_z``, N (eq. 3); ValueError for a curved
        MDR contact, whose normal force is not harmonic."""
        self._check_flat("dF_N (the amplitude of a harmonic normal force)")
        return self.k_zc * self.du_z

    def _check_flat(self, what: str) -> None:
        if self.curved:
            raise ValueError(f"{what} is not available for a curved MDR contact yet "
                             f"(profile_exponent = {self.profile_exponent!r}, "
                             "docs/contact_geometry.md)")

    def natural_frequency(self) -> float:
        """``omega_0 = sqrt(k_x / m)`` of the body on the system spring, rad/s."""
        return math.sqrt(self.k_x / self.mass)

    @property
    def zeta(self) -> float:
        """Damping ratio of the pin, ``c_x / (2 sqrt(k_x m))``."""
        return self.c_x / (2.0 * math.sqrt(self.k_x * self.mass))

    @property
    def quality_factor(self) -> float:
        """Quality factor ``Q = 1/(2 zeta)`` of the pin's free decay (``inf`` undamped)."""
        return math.inf if self.c_x == 0.0 else 1.0 / (2.0 * self.zeta)

    @property
    def eta_c(self) -> float:
        """Loss factor of the contact at the drive frequency, ``omega c_xc / k_xc``."""
        return float(self.groups(self.du_z, self.omega)[4])

    def with_damping(self, *, zeta: float | None = None, quality_factor: float | None = None,
                     eta_c: float | None = None) -> Physical:
        """A copy with the pin's damping given as a ratio or a quality factor (not both)
        and/or the contact's loss factor at ``omega``."""
        changes: dict[str, float] = {}
        if zeta is not None or quality_factor is not None:
            changes["c_x"] = pin_damping(self.k_x, self.mass, zeta=zeta,
                                         quality_factor=quality_factor)
        if eta_c is not None:
            eta = _valid("eta_c", eta_c)
            changes["c_xc"] = 0.0 if math.isinf(self.k_xc) else eta * self.k_xc / self.omega
        return self.with_(**changes)

    def to_dimensionless(self) -> Dimensionless:
        """``alpha``, ``beta`` (eq. 20), ``a = du_z/u_z0``, ``zeta``, ``eta_c``, the
        in-plane oscillation ``a_x`` (:meth:`inplane_amplitude`), ``phase_x``, ``a_y``,
        ``phase_y``, ``inplane_on``, and the transverse pin ``alpha_y``, ``zeta_y``
        (:meth:`transverse_groups`; None for an axisymmetric pin)."""
        alpha, beta, a, zeta, eta_c = self.groups(self.du_z, self.omega)
        alpha_y, zeta_y = self.transverse_groups(self.omega)
        return Dimensionless(alpha=float(alpha), beta=float(beta), amplitude=float(a),
                             zeta=float(zeta), eta_c=float(eta_c),
                             a_x=float(self.inplane_amplitude(self.du_x, self.omega)),
                             phase_x=self.phase_x,
                             a_y=float(self.inplane_amplitude(self.du_y, self.omega)),
                             phase_y=self.phase_y,
                             alpha_y=None if alpha_y is None else float(alpha_y),
                             zeta_y=None if zeta_y is None else float(zeta_y),
                             profile_exponent=self.profile_exponent,
                             inplane_on=self.inplane_on)

    def transverse_groups(self, omega: ArrayLike) -> tuple[NDArray[np.float64] | None, ...]:
        """``(alpha_y, zeta_y) = (k_y / (m omega^2), c_y / (2 sqrt(k_y m)))`` at ``omega``
        (rad/s), elementwise; each None where this pin leaves it to its twin: ``alpha_y``
        where ``k_y`` is None, ``zeta_y`` where ``k_y`` and ``c_y`` both are (with ``k_y``
        given, ``c_y = c_x`` has another damping ratio than ``zeta``)."""
        omega = np.asarray(omega, dtype=float)
        k_y, c_y = self.pin_y
        alpha_y = None if self.k_y is None else k_y / (self.mass * omega**2)
        zeta_y = None if self.k_y is None and self.c_y is None else np.full(
            np.shape(omega), c_y / (2.0 * math.sqrt(k_y * self.mass)))
        return alpha_y, zeta_y

    def point_arguments(self, v0: ArrayLike, du_z: ArrayLike, omega: ArrayLike,
                        du_x: ArrayLike = 0.0, phase_x: ArrayLike = 0.0,
                        du_y: ArrayLike = 0.0, phase_y: ArrayLike = 0.0
                        ) -> tuple[FloatOrArray | None, ...]:
        """``(alpha, beta, a, V, zeta, eta_c, a_x, phase_x, a_y, phase_y, alpha_y,
        zeta_y)`` of this pin at each point ``(v0, du_z, omega, du_x, phase_x, du_y,
        phase_y)`` (SI), elementwise: the arguments of
        :func:`~vibrofriction.solver.solve_points` for a measured table or a design's map
        (the pin's own ``du_z``, ``omega``, ``du_x``, ``phase_x``, ``du_y``, ``phase_y``
        are not used; its ``k_y``, ``c_y`` are: ``alpha_y``, ``zeta_y`` None for an
        axisymmetric pin, :meth:`transverse_groups`).  A curved MDR contact's are those of
        its scaled model (``a = du_z/d0``, velocities in units of ``mu0 F(d0)/(m omega)``):
        pass them with ``profile_exponent`` to ``solve_points``."""
        alpha, beta, a, zeta, eta = self.groups(du_z, omega)
        a_x = self.inplane_amplitude(du_x, omega)
        a_y = self.inplane_amplitude(du_y, omega)
        phase = np.broadcast_to(np.asarray(phase_x, dtype=float), np.shape(a_x))
        phase_y = np.broadcast_to(np.asarray(phase_y, dtype=float), np.shape(a_y))
        return (alpha, beta, a, self.v0_to_inertial(v0, omega), zeta, eta, a_x, phase, a_y,
                phase_y, *self.transverse_groups(omega))

    def inplane_amplitude(self, du_x: ArrayLike, omega: ArrayLike) -> NDArray[np.float64]:
        """``a_x = du_x m omega^2 / (mu0 F_N0)`` (docs/inplane.md) of an in-plane amplitude
        ``du_x`` (m) at ``omega`` (rad/s), elementwise: the in-plane amplitude in units of
        the length ``mu0 F_N0/(m omega^2)``, and equally ``omega du_x`` in units of the
        inertial velocity ``mu0 F_N0/(m omega)``; the one conversion from SI."""
        du_x = np.asarray(du_x, dtype=float)
        return du_x * self.mass * np.asarray(omega, dtype=float) ** 2 / (self.mu0 * self.F_N0)

    def groups(self, du_z: ArrayLike, omega: ArrayLike) -> tuple[NDArray[np.float64], ...]:
        """``(alpha, beta, a, zeta, eta_c)`` (eq. 20, docs/damping.md) of this pin driven at
        ``omega`` (rad/s) with amplitude ``du_z`` (m), elementwise: the one conversion
        from SI, for one point or a measured table."""
        du_z = np.asarray(du_z, dtype=float)
        omega = np.asarray(omega, dtype=float)
        stiffness = self.mass * omega**2
        eta_c = np.zeros_like(omega) if math.isinf(self.k_xc) else omega * self.c_xc / self.k_xc
        return (self.k_x / stiffness, (self.k_x + self.k_xc) / stiffness, du_z / self.u_z0,
                np.full(np.shape(omega), self.zeta), eta_c)

    def critical_velocity(self) -> float:
        """``v0*`` of eq. (12) with damping, m/s (``theory.critical_velocity``): above it
        the contact slides forward continuously.

        Undamped: ``inf`` if ``k_x = m omega^2`` (case IV), 0 if ``k_x + k_xc = m omega^2``
        (case III) or ``du_z = 0``; ``k_xc = inf`` gives ``mu0 omega du_z k_zc /
        |k_x - m omega^2 + i omega c_x|``.  With a longitudinal in-plane oscillation
        (``du_x > 0``) the combined drive's (``theory.inplane_critical_velocity`` in m/s,
        docs/inplane.md).  A curved MDR contact: ``theory.profile_critical_velocity`` in
        m/s (docs/contact_geometry.md; not with contact damping or an in-plane oscillation).
        """
        if self.curved or self.du_x > 0.0 or self.du_y > 0.0:
            return float(self.to_dimensionless().critical_inertial_velocity()
                         * self.velocity_unit())
        return float(theory.critical_velocity(self.mu0, self.omega, self.du_z, self.k_zc,
                                              self.k_xc, self.k_x, self.mass, self.c_x,
                                              self.c_xc))

    def velocity_unit(self, omega: ArrayLike | None = None) -> FloatOrArray:
        """The unit of the inertial velocity, ``mu0 F_N0 / (m omega)`` in m/s (Fig. 6), at
        this pin's ``omega`` or, elementwise, at other drive frequencies ``omega`` (rad/s)."""
        omega = self.omega if omega is None else _valid_array("omega", omega)
        return as_float_or_array(self.mu0 * self.F_N0 / (self.mass * omega))

    def v0_to_inertial(self, v0: ArrayLike, omega: ArrayLike | None = None) -> FloatOrArray:
        """``V = v0 m omega / (mu0 F_N0)``, the velocity axis of Fig. 6 (at this pin's
        ``omega`` or, elementwise, at other drive frequencies ``omega``, rad/s)."""
        return as_float_or_array(_valid_array("v0", v0) / self.velocity_unit(omega))

    def inertial_to_v0(self, v_inertial: ArrayLike) -> FloatOrArray:
        """``v0 = V mu0 F_N0 / (m omega)``, m/s."""
        return as_float_or_array(_valid_array("v_inertial", v_inertial)
                                 * self.velocity_unit())

    def v0_to_vbar(self, v0: ArrayLike) -> FloatOrArray:
        """``vbar = v0 / v0*`` (eq. 16), ``v0 >= 0``; ValueError where ``v0*`` is 0 or
        infinite (a backward velocity has no ``vbar``)."""
        v0 = validated({"v0": v0}, ranges={"v0": NONNEGATIVE})["v0"]
        return self.to_dimensionless().inertial_to_vbar(self.v0_to_inertial(v0))

    def vbar_to_v0(self, vbar: ArrayLike) -> FloatOrArray:
        """``v0 = vbar v0*`` (eq. 16), m/s; ValueError where ``v0*`` is 0 or infinite."""
        return self.inertial_to_v0(self.to_dimensionless().vbar_to_inertial(vbar))


# --------------------------------------------------------------------------- the one conversion
System = Dimensionless | Physical


def dimensionless(system: System) -> Dimensionless:
    """The :class:`Dimensionless` groups of ``system`` (eq. 20; itself if it is one)."""
    if isinstance(system, Physical):
        return system.to_dimensionless()
    if isinstance(system, Dimensionless):
        return system
    raise TypeError(f"system must be a Dimensionless or Physical, got {type(system).__name__}")


#: Scalar types of a velocity that :func:`inertial_velocity` converts without numpy.
_FLOATS = (float, np.float64)


def inertial_velocity(system: System, vbar: ArrayLike | None = None, *,
                      v_inertial: ArrayLike | None = None,
                      v0: ArrayLike | None = None) -> FloatOrArray:
    """The inertial velocity ``V = v0 m omega/(mu0 F_N0)`` (Fig. 6) from exactly one of
    ``vbar = v0/v0*`` (eq. 16), ``v_inertial`` itself, or ``v0`` in m/s (a
    :class:`Physical` system only), elementwise: the package's one decision of which
    velocity was given.  ValueError naming the parameter where it is invalid (negative,
    not finite) or undefined (``vbar`` in cases III and IV: :meth:`Dimensionless.
    critical_inertial_velocity` is 0 or inf there).
    """
    # the common fast path; mypy sees no float in ArrayLike (only complex), hence the ignore
    if type(v_inertial) is float and vbar is None and v0 is None:  # type: ignore[unreachable]
        if not math.isfinite(v_inertial):  # type: ignore[unreachable]
            _valid("v_inertial", v_inertial)  # raises the schema's sentence
        return v_inertial
    if vbar.__class__ in _FLOATS and v_inertial is None and v0 is None \
            and system.__class__ is Dimensionless and math.isfinite(vbar) and vbar >= 0.0:
        return float(system._vbar_unit * vbar)  # = vbar_to_inertial's product, bit for bit
    given = [name for name, v in (("vbar", vbar), ("v_inertial", v_inertial), ("v0", v0))
             if v is not None]
    if len(given) != 1:
        raise ValueError("give exactly one velocity: vbar (v0/v0*), v_inertial "
                         f"(v0 m omega/(mu0 F_N0)) or v0 (m/s); got "
                         f"{' and '.join(given) or 'none'}")
    if v0 is not None:
        if not isinstance(system, Physical):
            dimensionless(system)  # a TypeError for what is no system at all
            raise ValueError("v0 (m/s) needs a Physical system; use vbar or v_inertial")
        return system.v0_to_inertial(v0)
    if vbar is not None:
        return dimensionless(system).vbar_to_inertial(vbar)
    dimensionless(system)
    assert v_inertial is not None  # the one velocity given
    return as_float_or_array(_valid_array("v_inertial", v_inertial))

