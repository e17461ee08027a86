"""The solvers behind :func:`~vibrofriction.solver.solve_points`, one module each.

Each method (:mod:`.event`, :mod:`.plane`, :mod:`.mdr`) implements the protocol of
:mod:`.base`: its :class:`~vibrofriction.capabilities.Capabilities` (declared in
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

__all__ = ["INITIAL_KINDS", "METHODS", "Capabilities", "Limit", "Method", "Refusal",
           "capability_table",
           "choose", "method_of"]

#: Every method by name (:data:`vibrofriction.schema.METHOD_NAMES`, in that order).
METHODS: dict[str, Method] = {"event": EVENT, "plane": PLANE, "mdr": MDR}
assert tuple(METHODS) == METHOD_NAMES


def choose(profile_exponent: ArrayLike, a_y: ArrayLike) -> NDArray[np.int64]:
    """The index in :data:`METHODS` of the method of each point.

    A curved tip (finite ``profile_exponent``) the MDR solver, else a transverse oscillation
    (``a_y > 0``) the 2-D solver, else the 1-D event-driven solver.
    """
    curved = np.asarray(profile_exponent) != np.inf
    return np.where(curved, 2, np.where(np.asarray(a_y) > 0.0, 1, 0))


def method_of(profile_exponent: float, a_y: float) -> Method:
    """The method of one point: :func:`choose` on Python floats (the one-point path)."""
    if profile_exponent != math.inf:
        return MDR
    return PLANE if a_y > 0.0 else EVENT
