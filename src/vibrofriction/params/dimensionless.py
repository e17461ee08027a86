"""The dimensionless groups of the model (eq. 20): :class:`Dimensionless`."""

from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass

from numpy.typing import ArrayLike

from vibrofriction import theory
from vibrofriction.schema import CHOICES, PARAMETER
from vibrofriction.validation import as_float_or_array, checked_choice

from .cases import Case, classify, critical_for_vbar, inertial_to_vbar
from .fields import FloatOrArray, valid_array, validate_fields
from .friction import RateAndState


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
    static_ratio : float
        ``mu_static / mu0 >= 1``: a stuck contact holds while ``|f| <= static_ratio n`` and
        then slips at the kinetic ``mu0`` (default 1: Coulomb friction;
        docs/friction_laws.md).
    rs_a, rs_b, rs_d_c, rs_v_ref, rs_alpha_ld : float
        Rate-and-state friction in the model's units (docs/friction_laws.md): ``a``, ``b``
        and the Linker-Dieterich ``alpha`` over ``mu_star = mu0``, ``d_c`` in units of the
        inertial length ``mu_star F_N0 / (m omega^2)``, ``v_ref`` in units of the inertial
        velocity.  ``rs_a = 0`` (default) is Coulomb friction; :meth:`with_friction`
        sets them from a :class:`~vibrofriction.RateAndState` law.
    rs_law : str
        The state's evolution law, ``"aging"`` (default) or ``"slip"``.

    Raises
    ------
    ValueError
        A field out of its range (named, with the range), or an unknown ``inplane_on``.

    Examples
    --------
    >>> import vibrofriction as vf
    >>> system = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)
    >>> system.case
    <Case.GENERAL: 'general'>
    >>> system.critical_inertial_velocity()  # a|beta - 1|/((beta - alpha)|alpha - 1|)
    0.666666666666...
    >>> vf.Dimensionless(alpha=1.0, beta=0.5, amplitude=0.5)
    Traceback (most recent call last):
    ...
    ValueError: beta must be > alpha (= 1.0) or math.inf, got 0.5
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
    static_ratio: float = 1.0
    rs_a: float = 0.0
    rs_b: float = 0.0
    rs_d_c: float = 1.0
    rs_v_ref: float = 1.0
    rs_alpha_ld: float = 0.0
    inplane_on: str = "substrate"
    rs_law: str = "aging"

    def __post_init__(self) -> None:
        """Check every field against its range in the schema, and the choices."""
        validate_fields(self, "dimensionless")
        checked_choice("inplane_on", self.inplane_on)
        checked_choice("rs_law", self.rs_law)

    @property
    def friction(self) -> RateAndState | None:
        """The rate-and-state law in the model's units, or None (Coulomb: ``rs_a = 0``)."""
        if self.rs_a == 0.0:
            return None
        return RateAndState(a=self.rs_a, b=self.rs_b, d_c=self.rs_d_c, v_ref=self.rs_v_ref,
                            alpha_ld=self.rs_alpha_ld, law=self.rs_law)

    def with_friction(self, friction: RateAndState | None) -> Dimensionless:
        """A copy with the rate-and-state law ``friction`` (in the model's units; None: Coulomb)."""
        if friction is None:
            return dataclasses.replace(self, rs_law=CHOICES["rs_law"].default, **{  # type: ignore[arg-type]
                n: PARAMETER[n].default for n in ("rs_a", "rs_b", "rs_d_c", "rs_v_ref",
                                                  "rs_alpha_ld")})
        return dataclasses.replace(self, rs_a=friction.a, rs_b=friction.b, rs_d_c=friction.d_c,
                                   rs_v_ref=friction.v_ref, rs_alpha_ld=friction.alpha_ld,
                                   rs_law=friction.law)

    @property
    def pin_y(self) -> tuple[float, float]:
        """``(alpha_y, zeta_y)`` with None resolved to ``alpha``, ``zeta``.

        The pin across the sliding.
        """
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

    def critical_inertial_velocity(self) -> float:
        """``V_c``, the inertial velocity of continuous forward sliding (eq. 12 with damping).

        With a longitudinal in-plane oscillation, the combined drive's.

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
        """``V_c`` where ``vbar`` exists, computed once per system.

        The fields are frozen and validated.  ValueError where ``vbar`` does not exist (not cached),
        and with an in-plane oscillation, whose velocities are signed and have no ``vbar`` (eq. 16
        scales by the normal oscillation's ``v0*`` only).  A curved tip: its critical velocity
        (:meth:`critical_inertial_velocity`, ``theory.profile_critical_velocity``).
        """
        self._check_vbar_inplane()
        return float(critical_for_vbar(self.alpha, self.beta, self.amplitude, self.zeta,
                                        self.eta_c, self.profile_exponent))

    def _check_vbar_inplane(self) -> None:
        if self.a_x > 0.0 or self.a_y > 0.0:
            raise ValueError(f"vbar (v0/v0* of eq. 16) is not defined with an in-plane "
                             f"oscillation (a_x = {self.a_x!r}, a_y = {self.a_y!r}); use the "
                             "inertial velocity v_inertial (signed) instead")

    def vbar_to_inertial(self, vbar: ArrayLike) -> FloatOrArray:
        """Inertial velocity ``V = V_c vbar`` (eqs. 12, 16); ValueError where vbar is undefined."""
        return as_float_or_array(self._vbar_unit * valid_array("vbar", vbar))

    def inertial_to_vbar(self, v_inertial: ArrayLike) -> FloatOrArray:
        """``vbar = V / V_c`` (eqs. 12, 16); ValueError where ``vbar`` is undefined."""
        self._check_vbar_inplane()
        return inertial_to_vbar(self.alpha, self.beta, self.amplitude, v_inertial, self.zeta,
                                self.eta_c, self.profile_exponent)
