"""Axisymmetric profiles ``z = c r^n`` by the method of dimensionality reduction."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..validation import as_float_or_array, checked
from .materials import Material, effective_modulus, effective_shear_modulus, mdr_shear_modulus

__all__ = ["Cone", "FlatPunch", "PowerLaw", "Sphere", "mdr_kappa"]


def mdr_kappa(exponent: float) -> float:
    """The MDR factor ``kappa_n`` of the profile ``z = c r^n``.

    ``kappa_n = sqrt(pi) Gamma(n/2 + 1)/Gamma(n/2 + 1/2)``: the 1-D profile of the method
    of dimensionality reduction is ``g(x) = kappa_n c |x|^n`` (docs/contact_geometry.md).

    Parameters
    ----------
    exponent : float
        The profile's exponent ``n > 0`` (``math.inf``: the flat punch).

    Returns
    -------
    float
        ``kappa_n``: 2 for a sphere (``n = 2``), ``pi/2`` for a cone (``n = 1``),
        ``inf`` for ``n = inf``.

    Examples
    --------
    >>> from vibrofriction.contact import mdr_kappa
    >>> mdr_kappa(2.0), mdr_kappa(1.0)
    (2.0000000000000004, 1.5707963267948963)
    """
    n = float(checked("exponent", exponent, minimum=0.0, strict=True, allow_inf=True))
    if math.isinf(n):
        return math.inf
    return math.exp(0.5 * math.log(math.pi) + math.lgamma(0.5 * n + 1.0)
                    - math.lgamma(0.5 * n + 0.5))


class _MDR:
    """The MDR of an axisymmetric profile ``z = c r^n`` (SI units throughout).

    Subclasses give ``exponent`` (``n``), ``coefficient`` (``c``, m^(1-n)), ``pin`` and
    ``counterface``; the flat punch overrides what its limit ``n -> inf`` changes.
    """

    pin: Material
    counterface: Material

    @property
    def exponent(self) -> float:
        raise NotImplementedError

    @property
    def coefficient(self) -> float:
        raise NotImplementedError

    @property
    def kappa(self) -> float:
        """``kappa_n`` of :func:`mdr_kappa`."""
        return mdr_kappa(self.exponent)

    @property
    def e_star(self) -> float:
        """``E*`` of the pair, Pa (:func:`effective_modulus`)."""
        return effective_modulus(self.pin, self.counterface)

    @property
    def g_star(self) -> float:
        """``G*_mdr`` of the pair, Pa (:func:`mdr_shear_modulus`)."""
        return mdr_shear_modulus(self.pin, self.counterface)

    def profile_1d(self, x: ArrayLike) -> float | NDArray[np.float64]:
        """The MDR profile ``g(x) = kappa_n c |x|^n``.

        Parameters
        ----------
        x : array_like
            Positions along the 1-D row, m.

        Returns
        -------
        float or numpy.ndarray
            ``g(x)``, m.
        """
        x = np.abs(checked("x", x))
        return as_float_or_array(self.kappa * self.coefficient * x**self.exponent)

    def radius_at(self, indentation: ArrayLike) -> float | NDArray[np.float64]:
        """The contact radius ``a(d) = (d/(kappa_n c))^{1/n}`` (``g(a) = d``).

        Parameters
        ----------
        indentation : array_like
            ``d``, m.

        Returns
        -------
        float or numpy.ndarray
            ``a``, m; 0 for ``d <= 0``.
        """
        d = checked("indentation", indentation)
        dp = np.maximum(d, 0.0)
        return as_float_or_array((dp / (self.kappa * self.coefficient)) ** (1.0 / self.exponent))

    def normal_force(self, indentation: ArrayLike) -> float | NDArray[np.float64]:
        """The normal force ``F(d) = 2 E* int_0^a (d - g) dx = 2 E* d a n/(n + 1)``.

        Parameters
        ----------
        indentation : array_like
            ``d``, m.

        Returns
        -------
        float or numpy.ndarray
            ``F``, N; 0 for ``d <= 0``.
        """
        d = np.maximum(checked("indentation", indentation), 0.0)
        n = self.exponent
        a = np.asarray(self.radius_at(d))
        return as_float_or_array(2.0 * self.e_star * d * a * n / (n + 1.0))

    def indentation(self, normal_load: ArrayLike) -> float | NDArray[np.float64]:
        """The indentation ``d(F)`` at a normal load: the inverse of :meth:`normal_force`.

        ``d = (F (n + 1)/(2 n E*))^{n/(n+1)} (kappa_n c)^{1/(n+1)}``.

        Parameters
        ----------
        normal_load : array_like
            ``F >= 0``, N.

        Returns
        -------
        float or numpy.ndarray
            ``d``, m.
        """
        F = checked("normal_load", normal_load, minimum=0.0)
        n = self.exponent
        base = F * (n + 1.0) / (2.0 * n * self.e_star)
        return as_float_or_array(base ** (n / (n + 1.0))
                                 * (self.kappa * self.coefficient) ** (1.0 / (n + 1.0)))

    def normal_stiffness(self, indentation: ArrayLike) -> float | NDArray[np.float64]:
        """The normal stiffness ``dF/dd = 2 E* a(d)``.

        Parameters
        ----------
        indentation : array_like
            ``d``, m.

        Returns
        -------
        float or numpy.ndarray
            N/m.
        """
        return as_float_or_array(2.0 * self.e_star * np.asarray(self.radius_at(indentation)))

    def tangential_stiffness(self, indentation: ArrayLike) -> float | NDArray[np.float64]:
        """The tangential stiffness of the fully stuck contact, ``2 G*_mdr a(d)``.

        Parameters
        ----------
        indentation : array_like
            ``d``, m.

        Returns
        -------
        float or numpy.ndarray
            N/m.
        """
        return as_float_or_array(2.0 * self.g_star * np.asarray(self.radius_at(indentation)))


@dataclass(frozen=True)
class _Circular(_MDR):
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
        """The contact's normal and tangential stiffness at a normal load.

        ``k_zc = 2 E* a`` and ``k_xc = 8 G* a`` (Mindlin) at the contact radius ``a``.

        Parameters
        ----------
        normal_load : float
            ``F_N > 0``, N.

        Returns
        -------
        tuple of (float, float)
            ``(k_zc, k_xc)``, N/m: the tangent stiffnesses.
        """
        a = self.contact_radius(normal_load)
        return (2.0 * effective_modulus(self.pin, self.counterface) * a,
                8.0 * effective_shear_modulus(self.pin, self.counterface) * a)


@dataclass(frozen=True)
class FlatPunch(_Circular):
    """A flat circular pin end on the counterface.

    The contact radius is the punch's at any load: ``k_zc = 2 E* R``, ``k_xc = 8 G* R``.

    Parameters
    ----------
    radius : float
        The punch's radius ``R``, m.
    pin, counterface : Material
        The two bodies.

    Examples
    --------
    >>> from vibrofriction.contact import FlatPunch, Material
    >>> steel = Material(E=210e9, nu=0.3)
    >>> k_zc, k_xc = FlatPunch(radius=1e-3, pin=steel, counterface=steel).stiffness(10.0)
    >>> k_zc, k_xc  # N/m
    (230769230.76..., 190045248.86...)
    >>> k_xc / k_zc  # 2 (1 - nu)/(2 - nu), the Mindlin ratio
    0.8235294117647...
    """

    def contact_radius(self, normal_load: float) -> float:
        """The punch's radius ``radius`` (m), at any ``normal_load > 0`` (N)."""
        checked("normal_load", normal_load, minimum=0.0, strict=True)
        return self.radius

    @property
    def exponent(self) -> float:
        """``inf``: the limit ``n -> inf`` of ``z = (r/A)^n h``."""
        return math.inf

    @property
    def coefficient(self) -> float:
        """Not defined for the limit; the flat punch's methods do without it."""
        raise AttributeError("a flat punch has no coefficient c (the limit n -> inf)")

    @property
    def kappa(self) -> float:
        """``inf``: a flat punch has no finite MDR factor."""
        return math.inf

    def profile_1d(self, x: ArrayLike) -> float | NDArray[np.float64]:
        """``g(x) = 0`` for ``|x| <= A``, ``inf`` beyond."""
        x = np.abs(checked("x", x))
        return as_float_or_array(np.where(x <= self.radius, 0.0, np.inf))

    def radius_at(self, indentation: ArrayLike) -> float | NDArray[np.float64]:
        """``A`` for ``d > 0``, 0 otherwise."""
        d = checked("indentation", indentation)
        return as_float_or_array(np.where(d > 0.0, self.radius, 0.0))

    def normal_force(self, indentation: ArrayLike) -> float | NDArray[np.float64]:
        """``F = 2 E* A max(0, d)``."""
        d = np.maximum(checked("indentation", indentation), 0.0)
        return as_float_or_array(2.0 * self.e_star * self.radius * d)

    def indentation(self, normal_load: ArrayLike) -> float | NDArray[np.float64]:
        """``d = F/(2 E* A)``."""
        F = checked("normal_load", normal_load, minimum=0.0)
        return as_float_or_array(F / (2.0 * self.e_star * self.radius))


@dataclass(frozen=True)
class Sphere(_Circular):
    """A spherical pin end: Hertz and Mindlin at the load.

    The contact radius ``a = (3 F_N R/(4 E*))^{1/3}`` follows the load; ``k_zc = 2 E* a``,
    ``k_xc = 8 G* a``.

    Parameters
    ----------
    radius : float
        The sphere's radius ``R``, m.
    pin, counterface : Material
        The two bodies.

    Examples
    --------
    A steel ball of radius 5 mm on steel under 10 N: a contact of 69 um radius.

    >>> from vibrofriction.contact import Material, Sphere
    >>> steel = Material(E=210e9, nu=0.3)
    >>> ball = Sphere(radius=5e-3, pin=steel, counterface=steel)
    >>> ball.contact_radius(10.0)  # m
    6.87534433537...e-05
    >>> ball.stiffness(10.0)  # (k_zc, k_xc), N/m
    (15866179.23..., 13066265.25...)
    """

    def contact_radius(self, normal_load: float) -> float:
        """Hertz: ``a = (3 F_N R / (4 E*))^{1/3}``, m."""
        load = float(checked("normal_load", normal_load, minimum=0.0, strict=True))
        e_star = effective_modulus(self.pin, self.counterface)
        return (3.0 * load * self.radius / (4.0 * e_star)) ** (1.0 / 3.0)

    @property
    def exponent(self) -> float:
        """The exponent ``n = 2`` of a paraboloid (Hertz)."""
        return 2.0

    @property
    def coefficient(self) -> float:
        """``c = 1/(2R)``, 1/m."""
        return 0.5 / self.radius


class _Loaded(_MDR):
    """A profile whose contact radius follows the load (the MDR throughout)."""

    def contact_radius(self, normal_load: float) -> float:
        """The contact radius at a normal load.

        Parameters
        ----------
        normal_load : float
            ``F > 0``, N.

        Returns
        -------
        float
            ``a``, m.
        """
        load = float(checked("normal_load", normal_load, minimum=0.0, strict=True))
        return float(self.radius_at(self.indentation(load)))

    def stiffness(self, normal_load: float) -> tuple[float, float]:
        """The contact's normal and tangential stiffness at a normal load.

        ``k_zc = 2 E* a`` (the tangent normal stiffness) and ``k_xc = 2 G*_mdr a`` (the
        fully stuck tangential one) at the contact radius ``a``.

        Parameters
        ----------
        normal_load : float
            ``F_N > 0``, N.

        Returns
        -------
        tuple of (float, float)
            ``(k_zc, k_xc)``, N/m.
        """
        a = self.contact_radius(normal_load)
        return 2.0 * self.e_star * a, 2.0 * self.g_star * a


@dataclass(frozen=True)
class PowerLaw(_Loaded):
    """An axisymmetric tip ``z = c r^n`` (the MDR, docs/contact_geometry.md).

    Parameters
    ----------
    c : float
        The coefficient, ``c > 0``, in m^(1-n).
    n : float
        The exponent, ``0 < n < inf`` (1: a cone, 2: a paraboloid, as :class:`Sphere`).
    pin, counterface : Material
        The two bodies.

    Examples
    --------
    ``n = 2`` with ``c = 1/(2R)`` is the sphere of radius ``R``: here ``R = 5`` mm.

    >>> from vibrofriction.contact import Material, PowerLaw
    >>> steel = Material(E=210e9, nu=0.3)
    >>> tip = PowerLaw(c=100.0, n=2.0, pin=steel, counterface=steel)
    >>> tip.contact_radius(10.0)  # m
    6.87534433537...e-05
    >>> tip.stiffness(10.0)  # (k_zc, k_xc), N/m
    (15866179.23..., 13066265.25...)
    """

    c: float
    n: float
    pin: Material
    counterface: Material

    def __post_init__(self) -> None:
        """Check ``c > 0`` and ``n > 0``."""
        object.__setattr__(self, "c", float(checked("c", self.c, minimum=0.0, strict=True)))
        object.__setattr__(self, "n", float(checked("n", self.n, minimum=0.0, strict=True)))

    @property
    def exponent(self) -> float:
        """The exponent ``n`` of ``z = c r^n``."""
        return self.n

    @property
    def coefficient(self) -> float:
        """The coefficient ``c`` of ``z = c r^n`` (m^(1-n))."""
        return self.c


@dataclass(frozen=True)
class Cone(_Loaded):
    """A conical tip ``z = r cot(theta)`` of half-angle ``theta`` (from the axis).

    The power law ``n = 1`` with ``c = slope = cot(theta)``. Build it as
    ``Cone(slope, pin, counterface)`` or :meth:`from_half_angle`.

    Parameters
    ----------
    slope : float
        ``cot(theta)``, dimensionless, ``> 0``.
    pin, counterface : Material
        The two bodies.

    Examples
    --------
    >>> import math
    >>> from vibrofriction.contact import Cone, Material
    >>> steel = Material(E=210e9, nu=0.3)
    >>> cone = Cone.from_half_angle(math.radians(80.0), steel, steel)
    >>> cone.slope
    0.1763269807084...
    >>> cone.contact_radius(10.0)  # m, under 10 N
    1.7689140139...e-05
    """

    slope: float
    pin: Material
    counterface: Material

    def __post_init__(self) -> None:
        """Check ``slope > 0``."""
        object.__setattr__(self, "slope", float(checked("slope", self.slope, minimum=0.0,
                                                        strict=True)))

    @classmethod
    def from_half_angle(cls, half_angle: float, pin: Material, counterface: Material) -> Cone:
        """The cone of half-angle ``theta`` (radians, ``0 < theta < pi/2``)."""
        theta = float(checked("half_angle", half_angle))
        if not 0.0 < theta < math.pi / 2:
            raise ValueError(f"half_angle must be in (0, pi/2) radians, got {half_angle!r}")
        return cls(1.0 / math.tan(theta), pin, counterface)

    @property
    def exponent(self) -> float:
        """1."""
        return 1.0

    @property
    def coefficient(self) -> float:
        """``c = slope = cot(theta)``."""
        return self.slope

    @property
    def half_angle(self) -> float:
        """``theta = arctan(1/slope)``, radians."""
        return math.atan(1.0 / self.slope)
