"""A system's dimensionless groups and its inertial velocity, from any velocity given.

The one conversion: :class:`Dimensionless` groups of a system and the inertial velocity from
whichever velocity was given.

A system's :class:`Dimensionless` groups and the inertial velocity from whichever velocity was
given.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from vibrofriction.validation import as_float_or_array

from .dimensionless import Dimensionless
from .fields import FloatOrArray, valid_array, valid_float
from .physical import Physical

# --------------------------------------------------------------------------- the one conversion
System = Dimensionless | Physical


def dimensionless(system: System) -> Dimensionless:
    """The :class:`Dimensionless` groups of ``system`` (eq. 20; itself if it is one).

    Parameters
    ----------
    system : Dimensionless or Physical
        The system.

    Returns
    -------
    Dimensionless
        ``system`` itself, or :meth:`Physical.to_dimensionless` of it.

    Raises
    ------
    TypeError
        ``system`` is neither.
    """
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
    """The inertial velocity ``V = v0 m omega/(mu0 F_N0)`` (Fig. 6), elementwise.

    From exactly one of ``vbar = v0/v0*`` (eq. 16), ``v_inertial`` itself, or ``v0`` in m/s (a
    :class:`Physical` system only): the package's one decision of which velocity was given.

    Parameters
    ----------
    system : Dimensionless or Physical
        The system the velocity belongs to.
    vbar : float or array_like, optional
        ``v0/v0*`` (eq. 16), ``>= 0``.
    v_inertial : float or array_like, optional, keyword-only
        ``V`` itself (negative: backwards).
    v0 : float or array_like, optional, keyword-only
        The sliding velocity in m/s (a :class:`Physical` system only).

    Returns
    -------
    float or ndarray
        ``V``, of the given velocity's shape.

    Raises
    ------
    ValueError
        Not exactly one velocity given; a velocity invalid (negative ``vbar``, not finite;
        named) or undefined (``vbar`` in cases III and IV:
        :meth:`Dimensionless.critical_inertial_velocity` is 0 or inf there); ``v0`` of a
        :class:`Dimensionless` system.
    TypeError
        ``system`` is neither a :class:`Dimensionless` nor a :class:`Physical` system.

    Examples
    --------
    >>> import vibrofriction as vf
    >>> from vibrofriction.params import inertial_velocity
    >>> system = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)
    >>> inertial_velocity(system, vbar=0.3)  # 0.3 V_c, V_c = 2/3
    0.2...
    """
    # the common fast path; mypy sees no float in ArrayLike (only complex), hence the ignore
    if type(v_inertial) is float and vbar is None and v0 is None:  # type: ignore[unreachable]
        if not math.isfinite(v_inertial):  # type: ignore[unreachable]
            valid_float("v_inertial", v_inertial)  # raises the schema's sentence
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
    return as_float_or_array(valid_array("v_inertial", v_inertial))
