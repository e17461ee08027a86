"""The local friction law of rate-and-state friction: :class:`RateAndState` (docs/friction_laws.md).

The package's default local law is Coulomb's, ``|f| <= mu0 n``, with a static coefficient
``mu_static >= mu0`` optional (:class:`~vibrofriction.Physical`, ``static_ratio`` of
:class:`~vibrofriction.Dimensionless`).  :class:`RateAndState` replaces it with
rate-and-state friction, regularised at zero slip rate (Rice & Ben-Zion 1996; Lapusta et
al. 2000)::

    f = n mu(w', theta),
    mu = a asinh( w'/(2 v_ref) exp((mu_star + b ln(theta v_ref / d_c)) / a) ),

``w'`` the slip velocity of the contact point, ``theta`` the state (a time) evolving by the
aging or the slip law, plus the Linker-Dieterich response to the normal force,
``theta' += -(alpha_ld / b) theta n'/n``.  ``mu_star`` is the package's ``mu0``.
"""

from __future__ import annotations

from dataclasses import dataclass

from vibrofriction import theory
from vibrofriction.schema import CHOICES, PARAMETER, POSITIVE
from vibrofriction.validation import checked_number

__all__ = ["RateAndState"]


@dataclass(frozen=True)
class RateAndState:
    """Rate-and-state friction: its parameters, in SI units or in the model's.

    Passed to :class:`~vibrofriction.Physical` (``friction=``) its lengths and velocities
    are SI: ``d_c`` in m, ``v_ref`` in m/s, and ``a``, ``b``, ``alpha_ld`` are plain
    coefficients (``mu_star`` is the system's ``mu0``).  In the dimensionless model
    (:meth:`vibrofriction.Dimensionless.with_friction`, the ``rs_*`` fields) the same law
    is in the model's units: ``a``, ``b``, ``alpha_ld`` over ``mu_star``, ``d_c`` in units of
    the inertial length ``mu_star F_N0 / (m omega^2)``, ``v_ref`` in units of the inertial
    velocity ``mu_star F_N0 / (m omega)`` (:meth:`scaled`).

    Parameters
    ----------
    a : float
        The direct effect, ``> 0``.
    b : float
        The evolution effect, ``>= 0`` (``b > a``: steady sliding weakens with velocity).
    d_c : float
        The critical slip distance, ``> 0``.
    v_ref : float
        The reference velocity, ``> 0``.
    alpha_ld : float, optional
        The Linker-Dieterich coefficient, ``>= 0`` (default 0: the state does not respond
        to the normal force); ``> 0`` needs ``b > 0``.
    law : str, optional
        The state's evolution law: ``"aging"`` (default) or ``"slip"``.

    Raises
    ------
    ValueError
        A parameter out of its range, an unknown ``law``, or ``alpha_ld > 0`` with ``b = 0``.

    Examples
    --------
    >>> import vibrofriction as vf
    >>> law = vf.RateAndState(a=0.01, b=0.015, d_c=1e-6, v_ref=1e-3)
    >>> round(law.steady_mu(1e-3, mu_star=0.6), 12)  # a asinh(e^(mu_star/a)/2) at v_ref
    0.6
    >>> vf.RateAndState(a=0.0, b=0.01, d_c=1e-6, v_ref=1e-3)
    Traceback (most recent call last):
    ...
    ValueError: a must be finite and > 0, got 0.0
    """

    a: float
    b: float
    d_c: float
    v_ref: float
    alpha_ld: float = 0.0
    law: str = "aging"

    def __post_init__(self) -> None:
        """Check every parameter, and that the coupling has a ``b`` to divide by."""
        for name, key in (("a", "rs_a"), ("b", "rs_b"), ("d_c", "rs_d_c"),
                          ("v_ref", "rs_v_ref"), ("alpha_ld", "rs_alpha_ld")):
            # a > 0 here: the model's rs_a = 0 is Coulomb friction, not a law
            allowed = POSITIVE if name == "a" else PARAMETER[key].range
            object.__setattr__(self, name, checked_number(name, getattr(self, name), allowed))
        if self.law not in CHOICES["rs_law"].values:
            raise ValueError(f"law must be one of {', '.join(map(repr, CHOICES['rs_law'].values))}"
                             f", got {self.law!r}")
        if self.alpha_ld > 0.0 and self.b == 0.0:
            raise ValueError(f"alpha_ld = {self.alpha_ld:g} > 0 needs b > 0 (the state's "
                             "response to the normal force is alpha_ld/b), got b = 0")

    def steady_mu(self, v: float, mu_star: float = 1.0) -> float:
        """``mu_ss(v) = a asinh( v/(2 v_ref) exp((mu_star + b ln(v_ref/v))/a) )``, ``v > 0``.

        The coefficient of steady sliding at the slip velocity ``v`` (``theta = d_c/v``), in
        the units of ``a``, ``b`` and ``mu_star`` (``mu_star = 1``: the model's units).
        """
        # the model's law (theory.steady_mu_ratio) with a, b over mu_star: the one formula
        return mu_star * float(theory.steady_mu_ratio(v, self.a / mu_star, self.b / mu_star,
                                                      self.d_c, self.v_ref))

    def scaled(self, mu_star: float, F_N0: float, mass: float, omega: float) -> RateAndState:
        """The same law in the model's units, from SI (the one conversion).

        ``a``, ``b``, ``alpha_ld`` over ``mu_star``; ``d_c`` over the inertial length ``mu_star
        F_N0/(m omega^2)``; ``v_ref`` over the inertial velocity ``mu_star F_N0/(m omega)``.
        """
        length = mu_star * F_N0 / (mass * omega**2)
        return RateAndState(a=self.a / mu_star, b=self.b / mu_star, d_c=self.d_c / length,
                            v_ref=self.v_ref / (length * omega),
                            alpha_ld=self.alpha_ld / mu_star, law=self.law)

    def scaled_fields(self) -> dict[str, float | str]:
        """The fields of :class:`~vibrofriction.Dimensionless` of this law (already scaled)."""
        return {"rs_a": self.a, "rs_b": self.b, "rs_d_c": self.d_c, "rs_v_ref": self.v_ref,
                "rs_alpha_ld": self.alpha_ld, "rs_law": self.law}


assert CHOICES["rs_law"].default == RateAndState.law
