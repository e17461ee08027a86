r"""Contact stiffnesses from the contact's geometry and materials (docs/bench.md).

The model's contact is linear: ``F_N = k_zc u_z`` and ``F_c = k_xc (u_x - u_xc)``. An
experimenter knows a geometry and materials instead; this module gives the two
stiffnesses (the tangent stiffnesses at the mean normal load for a curved contact):

* **flat punch** of radius ``R`` (a cylindrical pin end, fully in contact):
  ``k_z = 2 E* R``, ``k_x = 8 G* R``;
* **sphere** of radius ``R`` under the load ``F_N`` (Hertz; Mindlin for the
  tangential stiffness before any micro-slip): contact radius
  ``a = (3 F_N R / (4 E*))^{1/3}``, ``k_z = 2 E* a``, ``k_x = 8 G* a``;

with the effective moduli of the two bodies (Johnson, *Contact Mechanics*, ch. 7)

.. math:: \frac{1}{E^*} = \frac{1 - \nu_1^2}{E_1} + \frac{1 - \nu_2^2}{E_2},\qquad
          \frac{1}{G^*} = \frac{2 - \nu_1}{G_1} + \frac{2 - \nu_2}{G_2},\quad
          G_i = \frac{E_i}{2(1 + \nu_i)}.

For two bodies of the same material the ratio ``k_x/k_z = 2(1 - nu)/(2 - nu)``
depends on Poisson's ratio only (0.8 at ``nu = 1/3``), the Mindlin ratio the paper uses.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .validation import checked

__all__ = ["FlatPunch", "Material", "Sphere", "effective_modulus", "effective_shear_modulus",
           "rigid"]


@dataclass(frozen=True)
class Material:
    """Young's modulus ``E`` (Pa; ``math.inf`` for a rigid body) and Poisson's ratio
    ``nu`` (``-1 < nu < 0.5``)."""

    E: float
    nu: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "E", float(checked("E", self.E, minimum=0.0, strict=True,
                                                    allow_inf=True)))
        nu = float(self.nu)
        if not (-1.0 < nu < 0.5):
            raise ValueError(f"nu must be in (-1, 0.5), got {self.nu!r}")
        object.__setattr__(self, "nu", nu)

    @property
    def G(self) -> float:
        """Shear modulus ``E / (2 (1 + nu))``, Pa."""
        return self.E / (2.0 * (1.0 + self.nu))


def effective_modulus(a: Material, b: Material) -> float:
    """``E*`` of the pair (Pa)."""
    inv = (1.0 - a.nu**2) / a.E + (1.0 - b.nu**2) / b.E
    if inv == 0.0:
        raise ValueError("both bodies are rigid: the contact has no compliance")
    return 1.0 / inv


def effective_shear_modulus(a: Material, b: Material) -> float:
    """``G*`` of the pair for the tangential stiffness (Pa)."""
    inv = (2.0 - a.nu) / a.G + (2.0 - b.nu) / b.G
    if inv == 0.0:
        raise ValueError("both bodies are rigid: the contact has no compliance")
    return 1.0 / inv


@dataclass(frozen=True)
class _Circular:
    """A circular contact of radius ``a``: ``k_z = 2 E* a``, ``k_x = 8 G* a``."""

    radius: float
    pin: Material
    counterface: Material

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", float(checked("radius", self.radius, minimum=0.0,
                                                         strict=True)))

    def contact_radius(self, normal_load: float) -> float:
        raise NotImplementedError

    def stiffness(self, normal_load: float) -> tuple[float, float]:
        """``(k_zc, k_xc)`` in N/m at ``normal_load`` (the tangent stiffnesses)."""
        a = self.contact_radius(normal_load)
        return (2.0 * effective_modulus(self.pin, self.counterface) * a,
                8.0 * effective_shear_modulus(self.pin, self.counterface) * a)


@dataclass(frozen=True)
class FlatPunch(_Circular):
    """A flat circular pin end of radius ``radius`` (m) on the counterface: the contact
    radius is the punch's at any load."""

    def contact_radius(self, normal_load: float) -> float:
        checked("normal_load", normal_load, minimum=0.0, strict=True)
        return self.radius


@dataclass(frozen=True)
class Sphere(_Circular):
    """A spherical pin end of radius ``radius`` (m): Hertz and Mindlin at the load."""

    def contact_radius(self, normal_load: float) -> float:
        """Hertz: ``a = (3 F_N R / (4 E*))^{1/3}``, m."""
        load = float(checked("normal_load", normal_load, minimum=0.0, strict=True))
        e_star = effective_modulus(self.pin, self.counterface)
        return (3.0 * load * self.radius / (4.0 * e_star)) ** (1.0 / 3.0)


def rigid() -> Material:
    """A rigid body (``E = inf``)."""
    return Material(math.inf, 0.0)
