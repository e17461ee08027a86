"""Jumping (``a > 1``): the lift-off phases and the mean normal force."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._kernels.integrate import liftoff_phases as _kernel_liftoff_phases
from ..validation import as_float_or_array
from .domains import FloatOrArray, valid_array


# --------------------------------------------------------------------------- jumping
class Liftoff(NamedTuple):
    """Phases ``tau`` in ``[0, 2 pi)`` where contact is lost and regained."""

    tau_off: FloatOrArray
    tau_on: FloatOrArray


#: The kernels' lift-off angle (the one place it is computed), over arrays.
_liftoff_angles = np.vectorize(_kernel_liftoff_phases, otypes=[float, float])


def contact_half_angle(a: NDArray[np.float64]) -> NDArray[np.float64]:
    """``theta = arccos(-1/a)`` for ``a > 1``, ``pi`` otherwise: contact while ``|tau| < theta``."""
    return np.where(a > 1.0, _liftoff_angles(a)[0], np.pi)


def mean_normal_force(amplitude: ArrayLike) -> FloatOrArray:
    r"""Mean scaled normal force ``<n> = <max(0, 1 + a cos tau)> = <F_N>/F_N0``.

    For ``a <= 1`` the contact never opens and ``<n> = 1``. For ``a > 1`` it is
    closed for ``|tau| < theta = arccos(-1/a)``, so

    .. math:: \langle n\rangle = \frac{1}{2\pi}\int_{-\theta}^{\theta}(1 + a\cos\tau)\,d\tau
              = \frac{\theta + a\sin\theta}{\pi}, \quad \sin\theta = \sqrt{1 - a^{-2}},

    which is the denominator of eq. (25) for a jumping body.
    """
    a = valid_array("amplitude", amplitude)
    theta = contact_half_angle(a)
    return as_float_or_array(np.where(a > 1.0, (theta + a * np.sin(theta)) / np.pi, 1.0))


def mean_normal_force_of(a: float) -> float:
    """:func:`mean_normal_force` of one valid amplitude, in plain floats.

    The one-point fast path of the solver, where numpy's overhead would be most of the call.
    """
    if a <= 1.0:
        return 1.0
    theta = math.acos(-1.0 / a)
    return (theta + a * math.sin(theta)) / math.pi


def liftoff_phases(amplitude: ArrayLike) -> Liftoff:
    r"""Phases of loss of contact and touchdown, where ``1 + a cos tau = 0``.

    ``tau_off = arccos(-1/a)`` (in ``(pi/2, pi]``) and ``tau_on = 2 pi - tau_off``
    for ``a >= 1``; ``a = 1`` gives the grazing point ``(pi, pi)``; ``nan`` for
    ``a < 1`` (no loss of contact).
    """
    a = valid_array("amplitude", amplitude)
    off = np.where(a >= 1.0, _liftoff_angles(a)[0], np.nan)
    return Liftoff(as_float_or_array(off), as_float_or_array(2.0 * np.pi - off))
