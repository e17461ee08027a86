"""The model in SI units (Fig. 1b): :class:`Physical`, and :func:`pin_damping`."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibrofriction import theory
from vibrofriction.schema import NONNEGATIVE
from vibrofriction.validation import as_float_or_array, checked, checked_choice, validated

from .dimensionless import Dimensionless
from .fields import FloatOrArray, valid_array, valid_float, validate_fields
from .friction import RateAndState


def pin_damping(k_x: float, mass: float, *, zeta: float | None = None,
                quality_factor: float | None = None) -> float:
    """The pin dashpot ``c_x`` (N s/m) from its damping ratio or its quality factor.

    ``c_x = 2 zeta sqrt(k_x m)`` with ``zeta = 1/(2Q)``: ``Q`` is what an impact test
    gives (the free decay of the pin with the contact open, paper Fig. 8b).

    Parameters
    ----------
    k_x : float
        The pin's stiffness, N/m.
    mass : float
        The body's mass, kg.
    zeta : float, optional, keyword-only
        The damping ratio, ``>= 0``.
    quality_factor : float, optional, keyword-only
        The quality factor ``Q``, ``> 0`` (``inf``: undamped); exactly one of ``zeta`` and
        ``quality_factor``.

    Returns
    -------
    float
        ``c_x``, N s/m.

    Raises
    ------
    ValueError
        Both or neither of ``zeta`` and ``quality_factor``, or a value out of its range.

    Examples
    --------
    >>> from vibrofriction.params import pin_damping
    >>> pin_damping(2.5e5, 0.01, quality_factor=50)  # sqrt(k_x m)/Q
    1.0
    """
    if (zeta is None) == (quality_factor is None):
        raise ValueError("give exactly one of zeta and quality_factor")
    k_x = valid_float("k_x", k_x)
    mass = valid_float("mass", mass)
    if zeta is None:
        assert quality_factor is not None  # exactly one of them is given
        q = float(checked("quality_factor", quality_factor, minimum=0.0, strict=True,
                          allow_inf=True))
        zeta = 0.0 if math.isinf(q) else 1.0 / (2.0 * q)
    return 2.0 * valid_float("zeta", zeta) * math.sqrt(k_x * mass)


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
    mu_static : float or None
        The static coefficient of friction, ``>= mu0``: a stuck contact holds while ``|f| <=
        mu_static n`` and then slips at the kinetic ``mu0``; None (default) is ``mu0``
        (Coulomb friction; docs/friction_laws.md).
    friction : RateAndState or None
        Rate-and-state friction in SI units (:class:`~vibrofriction.RateAndState`, with
        ``mu_star = mu0``); None (default) is Coulomb friction.

    Raises
    ------
    ValueError
        A field outside its range in SI units (named, with the range: e.g. a mass or a
        stiffness that is not > 0), or an ``inplane_on`` that is neither name.

    Examples
    --------
    >>> import vibrofriction as vf
    >>> pin = vf.Physical(mass=0.01, k_x=2.5e5, k_xc=2e5, k_zc=2.5e5, u_z0=4e-6,
    ...                   du_z=2e-6, omega=6283.0, mu0=0.3)
    >>> system = pin.to_dimensionless()  # eq. (20)
    >>> system.alpha, system.beta, system.amplitude
    (0.633294752172..., 1.139930553910..., 0.5)
    >>> pin.F_N0, pin.critical_velocity()  # N, and v0* in m/s (eq. 12)
    (1.0, 0.001798141031...)
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
    mu_static: float | None = None
    inplane_on: str = "substrate"
    friction: RateAndState | None = None

    #: How :func:`~vibrofriction.bench.from_bench` set ``u_z0`` from its load (not a field:
    #: the model is the imposed indentation about ``u_z0`` either way, and a copy made by
    #: :meth:`with_` is ``"indentation"`` again): ``"indentation"`` (``F(u_z0)`` is the load) or
    #: ``"dead_weight"`` (:attr:`mean_normal_force` is the load).
    normal_control: ClassVar[str] = "indentation"

    def __post_init__(self) -> None:
        """Check every field against its range in the schema, and ``inplane_on``."""
        validate_fields(self, "physical")
        checked_choice("inplane_on", self.inplane_on)
        if self.mu_static is not None and self.mu_static < self.mu0:
            raise ValueError(f"mu_static must be >= mu0 (= {self.mu0!r}; the static coefficient "
                             f"is at least the kinetic one), got {self.mu_static!r}")
        if self.friction is not None:
            if not isinstance(self.friction, RateAndState):
                raise TypeError("friction must be a vibrofriction.RateAndState or None, got "
                                f"{type(self.friction).__name__}")
            if self.mu_static is not None and self.mu_static != self.mu0:
                raise ValueError("mu_static is a law of Coulomb friction: give it without "
                                 f"friction= (got mu_static = {self.mu_static!r} with a "
                                 "rate-and-state law)")

    @property
    def static_ratio(self) -> float:
        """``mu_static / mu0`` (1 for Coulomb friction)."""
        return 1.0 if self.mu_static is None else self.mu_static / self.mu0

    def friction_fields(self, omega: float | None = None) -> dict[str, float | str]:
        """The friction law's fields of :class:`Dimensionless` at ``omega`` (this pin's if None).

        ``static_ratio`` and, with a rate-and-state law, ``rs_*`` (:meth:`RateAndState.scaled`).
        """
        fields: dict[str, float | str] = {"static_ratio": self.static_ratio}
        if self.friction is not None:
            fields.update(self.friction.scaled(self.mu0, self.F_N0, self.mass,
                                               self.omega if omega is None else omega
                                               ).scaled_fields())
        return fields

    def law_arguments(self, omega: ArrayLike) -> dict[str, Any]:
        """The friction law's arguments of :func:`~vibrofriction.solver.solve_points`, elementwise.

        ``static_ratio``, ``rs_a``, ``rs_b``, ``rs_d_c``, ``rs_v_ref``, ``rs_alpha_ld`` as arrays
        of the shape of ``omega`` (rad/s; the scaled ``rs_d_c``, ``rs_v_ref`` change with it) and
        ``rs_law``: :meth:`friction_fields` at each drive frequency (the one conversion), Coulomb
        friction's defaults of ``solve_points`` without a rate-and-state law.

        Examples
        --------
        >>> import vibrofriction as vf
        >>> pin = vf.Physical(mass=0.01, k_x=2.5e5, k_xc=2e5, k_zc=2.5e5, u_z0=4e-6,
        ...                   du_z=2e-6, omega=6283.0, mu0=0.3, mu_static=0.39)
        >>> pin.law_arguments([6283.0, 12566.0])["static_ratio"]
        array([1.3, 1.3])
        """
        omega = np.asarray(omega, dtype=float)
        shape = np.shape(omega)
        names = ("rs_a", "rs_b", "rs_d_c", "rs_v_ref", "rs_alpha_ld")
        out: dict[str, Any] = {"static_ratio": np.full(shape, self.static_ratio),
                               **{n: np.full(shape, 1.0 if n in ("rs_d_c", "rs_v_ref") else 0.0)
                                  for n in names}, "rs_law": "aging"}
        if self.friction is None:
            return out
        out["rs_law"] = self.friction.law
        for w in np.unique(omega):  # a measured table holds few drive frequencies
            fields = self.friction_fields(float(w))
            where = omega == w
            for n in names:
                out[n] = np.where(where, float(fields[n]), out[n])
        return out

    @property
    def pin_y(self) -> tuple[float, float]:
        """``(k_y, c_y)`` with None resolved to ``k_x``, ``c_x``: the pin across the sliding."""
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
        """Normal force at the mean indentation, N.

        ``k_zc u_z0`` (eq. 3; the mean force without jumping); for a curved MDR contact
        ``F(d0) = k_zc u_z0 n/(n + 1)``.
        """
        if self.curved:
            n = self.profile_exponent
            return self.k_zc * self.u_z0 * n / (n + 1.0)
        return self.k_zc * self.u_z0

    @property
    def mean_normal_force(self) -> float:
        """Mean normal force over the cycle, N.

        ``F_N0 <F(u_z0 + du_z cos)>/F(u_z0)``, ``F_N0`` times
        :func:`~vibrofriction.theory.profile_mean_normal_force` of ``a = du_z/u_z0`` (a
        linear contact: :func:`~vibrofriction.theory.mean_normal_force`, ``F_N0`` unless it
        jumps); the load of a dead weight (:func:`~vibrofriction.bench.from_bench`).
        """
        a = self.du_z / self.u_z0
        return self.F_N0 * float(theory.profile_mean_normal_force(a, self.profile_exponent))

    @property
    def dF_N(self) -> float:
        """Amplitude of the normal force ``k_zc du_z``, N (eq. 3).

        ValueError for a curved MDR contact, whose normal force is not harmonic.
        """
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
        """A copy with other damping of the pin and/or of the contact.

        The pin's damping given as a ratio or a quality factor (not both) and/or the contact's loss
        factor at ``omega``.
        """
        changes: dict[str, float] = {}
        if zeta is not None or quality_factor is not None:
            changes["c_x"] = pin_damping(self.k_x, self.mass, zeta=zeta,
                                         quality_factor=quality_factor)
        if eta_c is not None:
            eta = valid_float("eta_c", eta_c)
            changes["c_xc"] = 0.0 if math.isinf(self.k_xc) else eta * self.k_xc / self.omega
        return self.with_(**changes)

    def to_dimensionless(self) -> Dimensionless:
        """The pin's :class:`Dimensionless` system at its own drive.

        ``alpha``, ``beta`` (eq. 20), ``a = du_z/u_z0``, ``zeta``, ``eta_c``, the in-plane
        oscillation ``a_x`` (:meth:`inplane_amplitude`), ``phase_x``, ``a_y``, ``phase_y``,
        ``inplane_on``, the transverse pin ``alpha_y``, ``zeta_y`` (:meth:`transverse_groups`;
        None for an axisymmetric pin) and the friction law (:meth:`friction_fields`).
        """
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
                             inplane_on=self.inplane_on, **self.friction_fields())  # type: ignore[arg-type]

    def transverse_groups(self, omega: ArrayLike) -> tuple[NDArray[np.float64] | None, ...]:
        """``(alpha_y, zeta_y) = (k_y / (m omega^2), c_y / (2 sqrt(k_y m)))`` at ``omega``.

        ``omega`` in rad/s, elementwise; each None where this pin leaves it to its twin: ``alpha_y``
        where ``k_y`` is None, ``zeta_y`` where ``k_y`` and ``c_y`` both are (with ``k_y`` given,
        ``c_y = c_x`` has another damping ratio than ``zeta``).
        """
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
        """The arguments of :func:`~vibrofriction.solver.solve_points` at SI points, elementwise.

        ``(alpha, beta, a, V, zeta, eta_c, a_x, phase_x, a_y, phase_y, alpha_y, zeta_y)`` of this
        pin at each point ``(v0, du_z, omega, du_x, phase_x, du_y, phase_y)``, for a measured table
        or a design's map (the pin's own ``du_z``, ``omega``, ``du_x``, ``phase_x``, ``du_y``,
        ``phase_y`` are not used; its ``k_y``, ``c_y`` are: ``alpha_y``, ``zeta_y`` None for an
        axisymmetric pin, :meth:`transverse_groups`).  A curved MDR contact's are those of its
        scaled model (``a = du_z/d0``, velocities in units of ``mu0 F(d0)/(m omega)``): pass them
        with ``profile_exponent`` to ``solve_points``.
        """
        alpha, beta, a, zeta, eta = self.groups(du_z, omega)
        a_x = self.inplane_amplitude(du_x, omega)
        a_y = self.inplane_amplitude(du_y, omega)
        phase = np.broadcast_to(np.asarray(phase_x, dtype=float), np.shape(a_x))
        phase_y = np.broadcast_to(np.asarray(phase_y, dtype=float), np.shape(a_y))
        return (alpha, beta, a, self.v0_to_inertial(v0, omega), zeta, eta, a_x, phase, a_y,
                phase_y, *self.transverse_groups(omega))

    def inplane_amplitude(self, du_x: ArrayLike, omega: ArrayLike) -> NDArray[np.float64]:
        """``a_x = du_x m omega^2 / (mu0 F_N0)`` (docs/inplane.md), elementwise.

        Of an in-plane amplitude ``du_x`` (m) at ``omega`` (rad/s): the in-plane amplitude in units
        of the length ``mu0 F_N0/(m omega^2)``, and equally ``omega du_x`` in units of the inertial
        velocity ``mu0 F_N0/(m omega)``; the one conversion from SI.
        """
        du_x = np.asarray(du_x, dtype=float)
        return du_x * self.mass * np.asarray(omega, dtype=float) ** 2 / (self.mu0 * self.F_N0)

    def groups(self, du_z: ArrayLike, omega: ArrayLike) -> tuple[NDArray[np.float64], ...]:
        """``(alpha, beta, a, zeta, eta_c)`` (eq. 20, docs/damping.md) of this pin, elementwise.

        Driven at ``omega`` (rad/s) with amplitude ``du_z`` (m): the one conversion from SI, for one
        point or a measured table.
        """
        du_z = np.asarray(du_z, dtype=float)
        omega = np.asarray(omega, dtype=float)
        stiffness = self.mass * omega**2
        eta_c = np.zeros_like(omega) if math.isinf(self.k_xc) else omega * self.c_xc / self.k_xc
        return (self.k_x / stiffness, (self.k_x + self.k_xc) / stiffness, du_z / self.u_z0,
                np.full(np.shape(omega), self.zeta), eta_c)

    def critical_velocity(self) -> float:
        """``v0*`` of eq. (12) with damping, m/s (``theory.critical_velocity``).

        Above it the contact slides forward continuously.

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
        """The unit of the inertial velocity, ``mu0 F_N0 / (m omega)`` in m/s (Fig. 6).

        At this pin's ``omega`` or, elementwise, at other drive frequencies ``omega`` (rad/s).
        """
        omega = self.omega if omega is None else valid_array("omega", omega)
        return as_float_or_array(self.mu0 * self.F_N0 / (self.mass * omega))

    def v0_to_inertial(self, v0: ArrayLike, omega: ArrayLike | None = None) -> FloatOrArray:
        """``V = v0 m omega / (mu0 F_N0)``, the velocity axis of Fig. 6.

        At this pin's ``omega`` or, elementwise, at other drive frequencies ``omega`` (rad/s).
        """
        return as_float_or_array(valid_array("v0", v0) / self.velocity_unit(omega))

    def inertial_to_v0(self, v_inertial: ArrayLike) -> FloatOrArray:
        """``v0 = V mu0 F_N0 / (m omega)``, m/s."""
        return as_float_or_array(valid_array("v_inertial", v_inertial)
                                 * self.velocity_unit())

    def v0_to_vbar(self, v0: ArrayLike) -> FloatOrArray:
        """``vbar = v0 / v0*`` (eq. 16), ``v0 >= 0``.

        ValueError where ``v0*`` is 0 or infinite (a backward velocity has no ``vbar``).
        """
        v0 = validated({"v0": v0}, ranges={"v0": NONNEGATIVE})["v0"]
        return self.to_dimensionless().inertial_to_vbar(self.v0_to_inertial(v0))

    def vbar_to_v0(self, vbar: ArrayLike) -> FloatOrArray:
        """``v0 = vbar v0*`` (eq. 16), m/s; ValueError where ``v0*`` is 0 or infinite."""
        return self.inertial_to_v0(self.to_dimensionless().vbar_to_inertial(vbar))
