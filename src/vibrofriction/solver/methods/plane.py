"""The 2-D solver: a flat punch with a transverse in-plane oscillation (docs/inplane.md).

The contact point moves in the plane; slip has a direction, so the phases are not linear
ODEs and the motion is integrated by an embedded Runge-Kutta scheme with located events
(:mod:`vibrofriction._kernels.plane`), the steady state found by Newton on the period map.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ... import theory
from ..._kernels import codes
from ..._kernels.plane import plane_steady_chain, plane_steady_state_many
from ...capabilities import CAPABILITIES
from ...schema import METHOD_NAMES, Status, column_index
from ..points import PointTable
from ..settings import SolverSettings
from .base import new_outputs
from .event import contact_columns, holds

__all__ = ["PLANE", "plane_arguments", "plane_held"]

_CODE = METHOD_NAMES.index("plane")


class PlaneMethod:
    """The 2-D solver (:data:`PLANE`)."""

    capabilities = CAPABILITIES["plane"]

    def solve(self, points: PointTable, init_kind: int, init: NDArray[np.float64],
              settings: SolverSettings) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """Output rows of ``points`` (``V >= 0``); see :class:`~.base.Method`."""
        out_f, out_i = new_outputs(len(points))
        plane_steady_state_many(points.values, init_kind, np.ascontiguousarray(init),
                                *plane_arguments(settings), out_f, out_i)
        contact_columns(out_f, points["amplitude"], slice(None))
        idx = np.flatnonzero(points["v_inertial"] == 0.0)
        for on, rows in points.groups("inplane_on", idx):
            p = points.take(rows)
            mark = plane_held(out_i[rows, codes.I_STATUS],
                              out_f[rows, column_index("stick_fraction")], p, on)
            out_i[rows[mark], codes.I_STATUS] = Status.HELD.code
        out_i[:, codes.I_METHOD] = _CODE
        return out_f, out_i

    def solve_chain(self, points: PointTable, init_kind: int, init: NDArray[np.float64],
                    link: NDArray[np.int8], settings: SolverSettings
                    ) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """:meth:`solve` of points in turn, each started as ``link`` says.

        A continuation in one compiled loop (``link[i]``: ``LINK_OWN`` from ``init_kind``
        and ``init[i]``, ``LINK_PREVIOUS`` from the whole final section state of point
        ``i - 1`` where that is a periodic orbit, its transverse components and phase too,
        Newton's method from it at once; ``LINK_GIVEN`` from the state ``init[i]``).  Every
        point has ``V > 0``.
        """
        if not np.all(points["v_inertial"] > 0.0):
            raise ValueError("a chain of 2-D points needs every v_inertial > 0")
        out_f, out_i = new_outputs(len(points))
        plane_steady_chain(points.values, init_kind, np.ascontiguousarray(init), link,
                           *plane_arguments(settings), out_f, out_i)
        contact_columns(out_f, points["amplitude"], slice(None))
        out_i[:, codes.I_METHOD] = _CODE
        return out_f, out_i


def plane_arguments(settings: SolverSettings) -> tuple[float, int, int]:
    """``(rtol, max_periods, max_events_per_period)`` of the 2-D kernels.

    ``settings`` resolved with the method's defaults.
    """
    PLANE.capabilities.check_settings(settings)
    r = settings.resolved(PLANE.capabilities.settings)
    return float(r["rtol"]), int(r["max_periods"]), int(r["max_events_per_period"])


def plane_held(status: NDArray[np.int64], stick_fraction: NDArray[np.float64],
               points: PointTable, inplane_on: str) -> NDArray[np.bool_]:
    """Which ``V = 0`` 2-D points (kernel ``status``, ``stick_fraction``) are held.

    The region of mean forces a stuck contact can hold is not empty
    (:func:`theory.plane_static_region`: a motion from outside it approaches its edge with slips
    that die out, as in 1-D), or the motion stuck through its whole averaging window or orbit.
    ``points`` all have ``inplane_on``.  With ``static_ratio = s > 1`` the stick holds while
    ``|F - q(tau)| <= s n(tau)``, i.e. ``|F/s - q(tau)/s| <= n(tau)``: the region at the
    in-plane amplitudes divided by ``s``, scaled by ``s`` (empty where that one is).
    """
    p = points
    s = p["static_ratio"]
    region = theory.plane_static_region(p["alpha"], p["beta"], p["amplitude"], p["a_x"] / s,
                                        p["phase_x"], p["a_y"] / s, p["phase_y"], p["zeta"],
                                        p["eta_c"], inplane_on, p["alpha_y"], p["zeta_y"])
    return holds(status, stick_fraction, np.isfinite(np.atleast_1d(region.x_upper)))


PLANE = PlaneMethod()
