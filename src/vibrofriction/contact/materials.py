"""Materials of the pin and the counter-body, and their effective moduli (SI units)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..validation import checked

__all__ = ["Material", "effective_modulus", "effective_shear_modulus", "mdr_shear_modulus", "rigid"]


@dataclass(frozen=True)
class Material:
    """The elastic constants of one body.

    Parameters
    ----------
    E : float
        Young's modulus, Pa (``math.inf`` for a rigid body, see :func:`rigid`).
    nu : float
        Poisson's ratio, ``-1 < nu < 0.5``.

    Raises
    ------
    ValueError
        If ``E`` is not positive or ``nu`` is outside ``(-1, 0.5)``.

    Examples
    --------
    >>> from vibrofriction.contact import Material
    >>> steel = Material(E=210e9, nu=0.3)
    >>> steel.G  # shear modulus E/(2 (1 + nu)), Pa
    80769230769.23...
    """

    E: float
    nu: float

    def __post_init__(self) -> None:
        """Check ``E >= 0`` and ``-1 < nu < 0.5``."""
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
    """The effective (contact) modulus ``E*`` of two bodies.

    ``1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2`` (Johnson, *Contact Mechanics*, ch. 7).

    Parameters
    ----------
    a, b : Material
        The two bodies (the pin and the counterface); at most one may be rigid.

    Returns
    -------
    float
        ``E*``, Pa.

    Raises
    ------
    ValueError
        If both bodies are rigid.

    Examples
    --------
    >>> from vibrofriction.contact import Material, effective_modulus, rigid
    >>> steel = Material(E=210e9, nu=0.3)
    >>> effective_modulus(steel, steel)  # E/(2 (1 - nu^2))
    115384615384.6...
    >>> effective_modulus(steel, rigid())  # E/(1 - nu^2)
    230769230769.2...
    """
    inv = (1.0 - a.nu**2) / a.E + (1.0 - b.nu**2) / b.E
    if inv == 0.0:
        raise ValueError("both bodies are rigid: the contact has no compliance")
    return 1.0 / inv


def effective_shear_modulus(a: Material, b: Material) -> float:
    """The effective shear modulus ``G*`` of two bodies (Mindlin).

    ``1/G* = (2 - nu_1)/G_1 + (2 - nu_2)/G_2``: a stuck circular contact of radius ``a``
    has the tangential stiffness ``8 G* a``.

    Parameters
    ----------
    a, b : Material
        The two bodies; at most one may be rigid.

    Returns
    -------
    float
        ``G*``, Pa.

    Raises
    ------
    ValueError
        If both bodies are rigid.

    Examples
    --------
    >>> from vibrofriction.contact import Material, effective_shear_modulus
    >>> steel = Material(E=210e9, nu=0.3)
    >>> effective_shear_modulus(steel, steel)
    23755656108.59...
    """
    inv = (2.0 - a.nu) / a.G + (2.0 - b.nu) / b.G
    if inv == 0.0:
        raise ValueError("both bodies are rigid: the contact has no compliance")
    return 1.0 / inv


def mdr_shear_modulus(a: Material, b: Material) -> float:
    """The shear modulus ``G*_mdr`` of the MDR springs.

    ``1/G*_mdr = sum (2 - nu_i)/(4 G_i)``, i.e. ``4 *`` :func:`effective_shear_modulus`: the
    fully stuck contact of radius ``a`` has the tangential stiffness ``2 G*_mdr a``
    (``= 8 G* a``, Mindlin).

    Parameters
    ----------
    a, b : Material
        The two bodies; at most one may be rigid.

    Returns
    -------
    float
        ``G*_mdr``, Pa.

    Examples
    --------
    >>> from vibrofriction.contact import Material, mdr_shear_modulus
    >>> steel = Material(E=210e9, nu=0.3)
    >>> mdr_shear_modulus(steel, steel)  # 4 G*
    95022624434.38...
    """
    return 4.0 * effective_shear_modulus(a, b)


def rigid() -> Material:
    """A rigid body.

    Returns
    -------
    Material
        ``E = inf`` (and ``nu = 0``, which then does not matter).

    Examples
    --------
    >>> from vibrofriction.contact import rigid
    >>> rigid()
    Material(E=inf, nu=0.0)
    """
    return Material(math.inf, 0.0)
