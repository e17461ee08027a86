"""The 1-D event-driven solver: a flat punch sliding along x (paper eqs. 21-25).

Every phase (stick, slip either way, flight) is a linear ODE with a closed form; the
state is advanced from event to event and the steady state is a periodic orbit on the
Poincare section (:mod:`vibrofriction._kernels.steady`; docs/solver.md).  ``V = 0``
without an in-plane oscillation is the static limit, eq. (2); with one it is integrated,
and where the contact can stick through whole cycles the status is ``HELD``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ... import theory
from ..._kernels import codes
from ..._kernels.codes import LINK_OWN
from ..._kernels.steady import steady_state_many
from ...capabilities import CAPABILITIES
from ...schema import METHOD_NAMES, Status, column_index
from ..points import PointTable
from ..settings import SolverSettings
from .base import new_outputs

__all__ = ["EVENT", "HELD_STICK", "contact_columns", "event_arguments", "holds"]

#: A ``V = 0`` motion that sticks this fraction of its averaging window is held: all of
#: it, no slip and no flight.
HELD_STICK = 1.0

_CODE = METHOD_NAMES.index("event")
_O_STICK, _O_SLIP, _O_REVERSE, _O_FLIGHT = (column_index(k) for k in (
    "stick_fraction", "slip_fraction", "reverse_slip_fraction", "flight_fraction"))
_O_NORMAL, _O_STICK_AREA, _O_SLIP_AREA, _O_OPEN_AREA = (column_index(k) for k in (
    "mean_normal_ratio", "stick_area_fraction", "slip_area_fraction", "open_area_fraction"))


class EventMethod:
    """The 1-D event-driven solver (:data:`EVENT`)."""

    capabilities = CAPABILITIES["event"]

    def solve(self, points: PointTable, init_kind: int, init: NDArray[np.float64],
              settings: SolverSettings) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """Output rows of ``points`` (``V >= 0``); see :class:`~.base.Method`."""
        out_f, out_i = new_outputs(len(points))
        V, a_x = points["v_inertial"], points["a_x"]
        at_zero = (V == 0.0) & (a_x > 0.0)
        args = event_arguments(settings)
        # V = 0 with an in-plane oscillation is integrated like any moving point;
        # "sliding" has no direction there and is the rest (docs/inplane.md)
        for rows, kind in ((V > 0.0, init_kind),
                           (at_zero, 1 if init_kind == 0 else init_kind)):
            idx = np.flatnonzero(rows)
            if idx.size == len(points):  # every point: the rows written in place
                steady_state_many(points.values, kind, init, _own(len(points)), *args,
                                  out_f, out_i)
            elif idx.size:
                of, oi = new_outputs(idx.size)
                steady_state_many(points.take(idx).values, kind,
                                  np.ascontiguousarray(init[idx]), _own(idx.size), *args, of, oi)
                out_f[idx], out_i[idx] = of, oi
        am = points["amplitude"]
        contact_columns(out_f, am, slice(None))
        _held(out_f, out_i, points, np.flatnonzero(at_zero))
        _static_limit(am, out_f, out_i, (V == 0.0) & ~at_zero)
        out_i[:, codes.I_METHOD] = _CODE
        return out_f, out_i

    def solve_chain(self, points: PointTable, init_kind: int, init: NDArray[np.float64],
                    link: NDArray[np.int8], settings: SolverSettings
                    ) -> tuple[NDArray[np.float64], NDArray[np.int64], int]:
        """:meth:`solve` of points in turn, each started as ``link`` says.

        A continuation in one compiled loop (``link[i]``: ``LINK_OWN`` from ``init_kind``
        and ``init[i]``, ``LINK_PREVIOUS`` from the final section state of point ``i - 1``
        where that has one, ``LINK_GIVEN`` from the state ``init[i]``).  Every point has
        ``V > 0``, or ``V = 0`` without an in-plane oscillation (the static limit).
        Returns ``(out_f, out_i, m)``: the first ``m`` rows are solved (``m < n`` where a
        final state lacks its elongation, which the caller derives to go on).
        """
        V = points["v_inertial"]
        static = V == 0.0
        if not np.all((V > 0.0) | (static & (points["a_x"] == 0.0))):
            raise ValueError("a chain of points needs every v_inertial > 0, or 0 without "
                             "an in-plane oscillation")
        out_f, out_i = new_outputs(len(points))
        m = steady_state_many(points.values, init_kind, np.ascontiguousarray(init), link,
                              *event_arguments(settings), out_f, out_i)
        am = points["amplitude"]
        contact_columns(out_f, am, slice(None))
        _static_limit(am, out_f, out_i, static)
        out_i[:, codes.I_METHOD] = _CODE
        return out_f, out_i, int(m)


def _own(n: int) -> NDArray[np.int8]:
    """``link`` of ``n`` independent points: each from its own start."""
    return np.full(n, LINK_OWN, dtype=np.int8)


def event_arguments(settings: SolverSettings) -> tuple[int, int, float, float, int]:
    """``(max_periods, min_periods, tol_state, tol_mean, max_events)`` of the event kernels.

    ``settings`` resolved with the method's defaults (a setting it does not honour is refused).
    """
    try:  # the one-point path: one dictionary look-up
        return settings._derived["event"]  # type: ignore[attr-defined]
    except KeyError:
        return settings.derived("event", _event_arguments)


def _event_arguments(settings: SolverSettings) -> tuple[int, int, float, float, int]:
    EVENT.capabilities.check_settings(settings)
    r = settings.resolved(EVENT.capabilities.settings)
    return (int(r["max_periods"]), int(r["min_periods"]), float(r["tol_state"]),
            float(r["tol_mean"]), int(r["max_events"]))


def _held(out_f: NDArray[np.float64], out_i: NDArray[np.int64], points: PointTable,
          idx: NDArray[np.intp]) -> None:
    """Mark :attr:`Status.HELD` the ``V = 0`` rows ``idx`` where the contact sticks for good.

    Where the contact can stick through whole cycles: a stuck band exists
    (``theory.inplane_static_mu_ratio``; a motion from outside it approaches its edge with slips
    that die out), or the motion stuck through its whole averaging window (no slip, no flight).
    ``mu_ratio`` and ``error`` stay those of the motion from the given start (nan and inf where it
    did not settle).
    """
    for on, rows in points.groups("inplane_on", idx):
        p = points.take(rows)
        band = theory.inplane_static_mu_ratio(p["alpha"], p["beta"], p["amplitude"],
                                              p["a_x"], p["phase_x"], p["zeta"],
                                              p["eta_c"], on)
        mark = holds(out_i[rows, codes.I_STATUS], out_f[rows, _O_STICK],
                     np.isfinite(np.atleast_1d(band.upper)))
        out_i[rows[mark], codes.I_STATUS] = Status.HELD.code


def holds(status: NDArray[np.int64], stick_fraction: NDArray[np.float64],
          bounded: NDArray[np.bool_]) -> NDArray[np.bool_]:
    """Which ``V = 0`` points are held (the 1-D and the 2-D solver alike).

    A stuck region of mean forces exists (``bounded``) or the motion stuck through its
    whole window, and the search ended without failing.
    """
    return (bounded | (stick_fraction >= HELD_STICK)) & np.isin(
        status, (Status.PERIODIC.code, Status.AVERAGED.code, Status.NOT_CONVERGED.code))


def _static_limit(amplitude: NDArray[np.float64], out_f: NDArray[np.float64],
                  out_i: NDArray[np.int64], rows: NDArray[np.bool_]) -> None:
    """Fill the rows of zero-velocity points with the static limit, eq. (2)."""
    if not np.any(rows):
        return
    am = amplitude[rows]
    contact = am < 1.0
    out_f[rows, codes.O_MU] = theory.static_mu_ratio(am)
    out_f[rows, codes.O_ERR] = 0.0
    out_f[rows, codes.O_WORK] = 0.0  # nothing integrated
    out_f[rows, _O_STICK] = np.where(contact, 1.0, np.nan)
    for j in (_O_SLIP, _O_REVERSE, _O_FLIGHT):
        out_f[rows, j] = np.where(contact, 0.0, np.nan)
    out_f[rows, codes.O_LAT] = 0.0
    contact_columns(out_f, amplitude, rows)
    out_i[rows, codes.I_STATUS] = Status.STATIC.code
    out_i[rows, codes.I_PHASE] = codes.NO_PHASE


def contact_columns(out_f: NDArray[np.float64], amplitude: NDArray[np.float64],
                    rows: NDArray[np.bool_] | slice) -> None:
    """The contact's columns of the flat-punch rows ``rows`` (``amplitude`` of all rows).

    ``mean_normal_ratio`` by its closed form (:func:`theory.mean_normal_force`) and the area
    fractions, which for the one spring of a flat punch are its time fractions (slip either
    way).
    """
    if not isinstance(rows, slice) and not np.any(rows):
        return
    out_f[rows, _O_NORMAL] = theory.mean_normal_force(amplitude[rows])
    out_f[rows, _O_STICK_AREA] = out_f[rows, _O_STICK]
    out_f[rows, _O_SLIP_AREA] = out_f[rows, _O_SLIP] + out_f[rows, _O_REVERSE]
    out_f[rows, _O_OPEN_AREA] = out_f[rows, _O_FLIGHT]


EVENT = EventMethod()
