"""The solvers behind :func:`~vibrofriction.solver.solve_points`, one module each.

Each method (:mod:`.event`, :mod:`.plane`, :mod:`.mdr`, :mod:`.rate_state`) implements the
protocol of :mod:`.base`: its :class:`~vibrofriction.capabilities.Capabilities` (declared in
:mod:`vibrofriction.capabilities`) and ``solve``.  :func:`choose` is
the one rule that picks the method of a point; :data:`METHODS` lists them by name, in the
order of :data:`vibrofriction.schema.METHOD_NAMES`.  A new solver is one new module here,
its declaration in :mod:`vibrofriction.capabilities`, one entry in :data:`METHODS`
and one branch of :func:`choose`.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ...capabilities import INITIAL_KINDS, Capabilities, Limit, Refusal, capability_table
from ...schema import METHOD_NAMES
from .base import Method
from .event import EVENT
from .mdr import MDR
from .plane import PLANE
from .rate_state import RATE_STATE

__all__ = ["INITIAL_KINDS", "METHODS", "Capabilities", "Limit", "Method", "Refusal",
           "capability_table",
           "choose", "method_of"]

#: Every method by name (:data:`vibrofriction.schema.METHOD_NAMES`, in that order).
METHODS: dict[str, Method] = {"event": EVENT, "plane": PLANE, "mdr": MDR,
                              "rate_state": RATE_STATE}
assert tuple(METHODS) == METHOD_NAMES


def choose(profile_exponent: ArrayLike, a_y: ArrayLike,
           rs_a: ArrayLike = 0.0) -> NDArray[np.int64]:
    """The index in :data:`METHODS` of the method of each point.

    A curved tip (finite ``profile_exponent``) the MDR solver, else a transverse oscillation
    (``a_y > 0``) the 2-D solver, else rate-and-state friction (``rs_a > 0``) the
    rate-and-state solver, else the 1-D event-driven solver.  (The MDR and the 2-D solver
    refuse ``rs_a > 0`` by their declared limits.)
    """
    curved = np.asarray(profile_exponent) != np.inf
    flat = np.where(np.asarray(rs_a) > 0.0, 3, 0)
    return np.where(curved, 2, np.where(np.asarray(a_y) > 0.0, 1, flat))


def method_of(profile_exponent: float, a_y: float, rs_a: float = 0.0) -> Method:
    """The method of one point: :func:`choose` on Python floats (the one-point path)."""
    if profile_exponent != math.inf:
        return MDR
    if a_y > 0.0:
        return PLANE
    return RATE_STATE if rs_a > 0.0 else EVENT
