"""The solvers behind :func:`~vibrofriction.solver.solve_points`, one module each.

Each method (:mod:`.event`, :mod:`.plane`, :mod:`.mdr`) implements the protocol of
:mod:`.base`: its declared :class:`~.base.Capabilities` and ``solve``.  :func:`choose` is
the one rule that picks the method of a point; :data:`METHODS` lists them by name, in the
order of :data:`vibrofriction.schema.METHOD_NAMES`.  A new solver is one new module here,
one entry in :data:`METHODS` and one branch of :func:`choose`.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ...schema import METHOD_NAMES
from .base import INITIAL_KINDS, Capabilities, Limit, Method, Refusal
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
    """The index in :data:`METHODS` of the method of each point: a curved tip (finite
    ``profile_exponent``) the MDR solver, else a transverse oscillation (``a_y > 0``) the
    2-D solver, else the 1-D event-driven solver."""
    curved = np.asarray(profile_exponent) != np.inf
    return np.where(curved, 2, np.where(np.asarray(a_y) > 0.0, 1, 0))


def method_of(profile_exponent: float, a_y: float) -> Method:
    """The method of one point: :func:`choose` on Python floats (the one-point path)."""
    if profile_exponent != math.inf:
        return MDR
    return PLANE if a_y > 0.0 else EVENT


def capability_table() -> str:
    """What each solver covers, as a Markdown table (docs/solver.md includes it)."""
    caps = [m.capabilities for m in METHODS.values()]
    rows = [
        ("chosen for", [c.takes for c in caps]),
        ("parameters used", [", ".join(f"`{p}`" for p in c.parameters) for c in caps]),
        ("refuses", ["; ".join(f"{lim.what} (`{lim.parameter}`)" for lim in c.limits)
                     or "nothing" for c in caps]),
        ("velocities", [c.velocities for c in caps]),
        ("initial states", [", ".join(c.initial) for c in caps]),
        ("settings honoured (default)",
         [", ".join(f"`{k}` ({v:,})" if isinstance(v, int) else f"`{k}` ({v:g})"
                    for k, v in c.settings.items()) + ", `tol_trusted`"
          for c in caps]),
        ("outputs (the rest nan)", [_outputs(c) for c in caps]),
        ("sensitivities", ["yes" if c.sensitivities else "no" for c in caps]),
        ("time histories", ["yes" if c.histories else "no" for c in caps]),
    ]
    head = "| | " + " | ".join(f"{c.title} (`{c.name}`)" for c in caps) + " |\n"
    head += "|---" * (len(caps) + 1) + "|\n"
    return head + "".join(f"| {k} | " + " | ".join(v) + " |\n" for k, v in rows)


def _outputs(c: Capabilities) -> str:
    """The outputs of ``c``, or those of every method less the ones it leaves out."""
    every = {n for m in METHODS.values() for n in m.capabilities.outputs}
    missing = sorted(every - set(c.outputs))
    return "all" if not missing else "all but " + ", ".join(f"`{n}`" for n in missing)
