r"""The batch engine: steady states at arbitrary points (paper eqs. 21-25).

:func:`solve_points` runs the exact event-driven kernels of :mod:`vibrofriction._kernels`
over arrays of points in one compiled loop and returns their named output columns
(:data:`vibrofriction.schema.FLOAT_COLUMNS`, ``INT_COLUMNS``); :func:`friction_coefficient`
wraps them as :class:`FrictionResult` objects for a system and its velocities.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import cast, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import theory
from .._kernels import codes
from .._kernels.plane import plane_steady_state_many
from .._kernels.steady import steady_state, steady_state_many
from ..params import Dimensionless, System, dimensionless, inertial_velocity
from ..schema import FLOAT_COLUMNS, INT_COLUMNS, Status, column_index
from ..validation import checked_choice, validated
from .results import (
    PHASE_CODE,
    FrictionResult,
    FrictionResults,
    SectionState,
    result_from_columns,
    result_from_rows,
    results_from_columns,
)
from .settings import DEFAULT_SETTINGS, SolverSettings

__all__ = ["friction_coefficient", "solve_points"]

Initial = str | SectionState


def initial_rows(initial: Initial | NDArray[np.object_], n: int,
                 systems: Callable[[int], Dimensionless]) -> tuple[int, NDArray[np.float64]]:
    """Kernel start ``(kind, rows (y, x', e, phase))``; ``systems(i)`` is point i's system."""
    init = np.zeros((n, 4))
    if isinstance(initial, SectionState):
        init[:] = (initial.y, initial.x_dot, initial.elongation(systems(0)),
                   PHASE_CODE[initial.phase])
        return 2, init
    if isinstance(initial, np.ndarray) and initial.dtype == object:
        for i, s in enumerate(initial.ravel()):
            init[i] = (s.y, s.x_dot, s.elongation(systems(i)), PHASE_CODE[s.phase])
        return 2, init
    if initial == "sliding":
        return 0, init
    if initial == "rest":
        return 1, init
    raise ValueError(f"initial must be 'sliding', 'rest' or a SectionState, got {initial!r}")


#: A ``V = 0`` motion that sticks this fraction of its averaging window is held
#: (:func:`_held`): all of it, no slip and no flight.
HELD_STICK = 1.0

#: The final-state columns that change sign under the mirror ``x -> -x``.
_SIGNED = ("mu_ratio", "y", "x_dot", "f", "e", "drift_rate")
_MIRROR_PHASE = {codes.SLIP_POS: codes.SLIP_NEG, codes.SLIP_NEG: codes.SLIP_POS}


def _mirror_rows(init: NDArray[np.float64], rows: NDArray[np.bool_]) -> None:
    """Mirror explicit start rows ``(y, x', e, phase)`` in place (``x -> -x``)."""
    init[rows, :3] = -init[rows, :3]
    ph = init[rows, 3].copy()
    for a, b in _MIRROR_PHASE.items():
        ph[init[rows, 3] == a] = b
    init[rows, 3] = ph


def _mirror_outputs(out_f: NDArray[np.float64], out_i: NDArray[np.int64],
                    rows: NDArray[np.bool_]) -> None:
    """The results of the mirrored problem as those of the given one: the signed columns
    negated, the window range negated and swapped, slip+ and slip- swapped in the final
    phase.  ``reverse_slip_fraction`` (slip against the sliding direction) is unchanged."""
    for k in _SIGNED:
        j = column_index(k)
        out_f[rows, j] = -out_f[rows, j]
    lo, hi = column_index("window_min"), column_index("window_max")
    out_f[rows, lo], out_f[rows, hi] = -out_f[rows, hi], -out_f[rows, lo]
    jp = column_index("phase")
    ph = out_i[rows, jp]
    out_i[rows, jp] = np.where(ph == codes.SLIP_POS, codes.SLIP_NEG,
                               np.where(ph == codes.SLIP_NEG, codes.SLIP_POS, ph))


def solve_points(
    alpha: ArrayLike,
    beta: ArrayLike,
    amplitude: ArrayLike,
    v_inertial: ArrayLike,
    zeta: ArrayLike = 0.0,
    eta_c: ArrayLike = 0.0,
    a_x: ArrayLike = 0.0,
    phase_x: ArrayLike = 0.0,
    a_y: ArrayLike = 0.0,
    phase_y: ArrayLike = 0.0,
    alpha_y: ArrayLike | None = None,
    zeta_y: ArrayLike | None = None,
    profile_exponent: ArrayLike = math.inf,
    *,
    inplane_on: str = "substrate",
    initial: Initial | NDArray[np.object_] = "sliding",
    settings: SolverSettings | None = None,
) -> dict[str, NDArray]:
    """Steady states at arbitrary points, one compiled loop: the batch engine.

    The thirteen parameters broadcast together and are validated against their ranges in
    :data:`vibrofriction.schema.PARAMETERS` (``alpha > 0``, ``beta > alpha``, ``a >= 0``,
    ``zeta >= 0``, ``eta_c >= 0``, ``a_x, a_y >= 0``; ``V`` and the phases any finite
    real; finite but ``beta``); ``inplane_on`` is ``"substrate"`` or ``"holder"`` for all
    of them (docs/inplane.md).  ``V < 0`` is solved by the mirror ``x -> -x``: the point
    ``(-V, phase_x + pi)`` (its ``n`` unchanged, ``h -> -h``) with ``mu_ratio`` and the
    signed state negated (an explicit initial state is mirrored on the way in).  ``V = 0``
    is the static limit without in-plane oscillation; with it (``a_x > 0``) it is
    integrated (``"sliding"`` is the rest there), and where the contact can stick
    through whole cycles (:func:`_held`) the status is :attr:`Status.HELD` (not trusted:
    the value is the preload the start implies, docs/inplane.md).  Returns arrays of that
    shape named by :data:`~vibrofriction.schema.FLOAT_COLUMNS` and ``INT_COLUMNS``
    (``status`` as :attr:`Status.code`; ``y``, ``x_dot``, ``f``, ``e``, ``phase`` the final
    section state, in the laboratory frame) and ``trusted``.  Results are bitwise reproducible: each
    point depends only on its own parameters.

    A transverse oscillation (``a_y > 0``) is solved by the 2-D solver
    (:mod:`vibrofriction._kernels.plane`, docs/inplane.md "The 2-D solver"; a finite
    ``beta``, and not ``a = 1`` with ``eta_c = 0``: ValueError otherwise);
    ``lateral_ratio = <F_y>/(mu0 <F_N>)`` is its mean transverse force (0 for the others).
    At ``V = 0`` it iterates the period map without Newton (``"sliding"`` is the rest),
    and where a stuck contact can hold a region of mean forces (:func:`plane_held`) the
    status is :attr:`Status.HELD`.

    ``alpha_y``, ``zeta_y`` are the pin across the sliding (None: ``alpha``, ``zeta``, an
    axisymmetric pin); only the 2-D points use them: without a transverse oscillation the
    body never moves across, and the 1-D solver's results do not depend on them.

    A curved tip (finite ``profile_exponent``) is solved point by point by the MDR solver
    (:func:`vibrofriction.solver.mdr.mdr_friction` with ``tol = settings.tol_trusted``;
    :func:`_mdr_rows`): milliseconds to a tenth of a second a point, from the
    ``"sliding"`` start only, with a longitudinal in-plane oscillation (``a_x``,
    ``phase_x``, ``inplane_on``) at ``V != 0``, and not yet with ``eta_c > 0``,
    ``a_y > 0``, ``beta = inf`` or ``a_x > 0`` at ``V = 0`` (ValueError naming them).
    ``mean_normal_ratio`` (the closed form of the imposed indentation) and the area
    fractions ``stick_area_fraction``,
    ``slip_area_fraction``, ``open_area_fraction`` are given at every point.
    """
    settings = settings or DEFAULT_SETTINGS
    on_substrate = checked_choice("inplane_on", inplane_on) == "substrate"
    al, be, am, V, ze, et, ax, px, ay, py, aly, zey, pe = np.broadcast_arrays(*(
        np.asarray(x, dtype=float)
        for x in (alpha, beta, amplitude, v_inertial, zeta, eta_c, a_x, phase_x, a_y,
                  phase_y, alpha if alpha_y is None else alpha_y,
                  zeta if zeta_y is None else zeta_y, profile_exponent)))
    shape = V.shape
    al, be, am, V, ze, et, ax, px, ay, py, aly, zey, pe = (
        np.ascontiguousarray(x.ravel()) for x in (al, be, am, V, ze, et, ax, px, ay, py, aly,
                                                  zey, pe))
    validated({"alpha": al, "beta": be, "amplitude": am, "v_inertial": V, "zeta": ze,
               "eta_c": et, "a_x": ax, "phase_x": px, "a_y": ay, "phase_y": py,
               "alpha_y": aly, "zeta_y": zey, "profile_exponent": pe})
    curved = pe != math.inf
    if np.any(curved):
        _check_curved(curved, al, be, am, V, ze, et, ax, ay, pe, initial)
    plane = ay > 0.0
    if np.any(plane):
        _check_plane(be[plane], am[plane], et[plane], V[plane])
    n = V.size
    kind, init = initial_rows(initial, n,
                              lambda i: Dimensionless(al[i], be[i], am[i], ze[i], et[i],
                                                      ax[i], px[i], ay[i], py[i],
                                                      inplane_on=inplane_on))
    backward = V < 0.0
    if np.any(backward):  # the mirror x -> -x
        V = np.where(backward, -V, V)
        px = np.where(backward, px + math.pi, px)
        if kind == 2:
            _mirror_rows(init, backward)
    out_f = np.full((n, len(FLOAT_COLUMNS)), np.nan)
    out_i = np.zeros((n, len(INT_COLUMNS)), dtype=np.int64)
    # V = 0 with an in-plane oscillation is integrated like any moving point; "sliding"
    # has no direction there and is the rest, as in the reference (docs/inplane.md)
    at_zero = (V == 0.0) & (ax > 0.0) & ~plane & ~curved
    for rows, k in ((plane, kind), ((V > 0.0) & ~plane & ~curved, kind),
                    (at_zero, 1 if kind == 0 else kind)):
        idx = np.flatnonzero(rows)
        if not idx.size:
            continue
        of = np.full((idx.size, len(FLOAT_COLUMNS)), np.nan)
        oi = np.zeros((idx.size, len(INT_COLUMNS)), dtype=np.int64)
        if rows is plane:
            plane_steady_state_many(al[idx], be[idx], am[idx], V[idx], ze[idx], et[idx],
                                    ax[idx], px[idx], ay[idx], py[idx], aly[idx],
                                    zey[idx], np.full(idx.size, on_substrate), k,
                                    np.ascontiguousarray(init[idx]), PLANE_RTOL,
                                    settings.max_periods,
                                    min(settings.max_events, PLANE_EVENTS_PER_PERIOD), of, oi)
            out_f[idx] = of
            out_i[idx] = oi
            continue
        steady_state_many(al[idx], be[idx], am[idx], V[idx], ze[idx], et[idx], ax[idx],
                          px[idx], np.full(idx.size, on_substrate), k,
                          np.ascontiguousarray(init[idx]), *settings.kernel_arguments(), of, oi)
        out_f[idx] = of
        out_i[idx] = oi
    _contact_columns(out_f, am, ~curved)
    if np.any(curved):
        _mdr_rows(out_f, out_i, curved, al, be, am, V, ze, pe, settings, ax, px, inplane_on)
    if np.any(backward):
        _mirror_outputs(out_f, out_i, backward)
    _held(out_f, out_i, at_zero, al, be, am, ze, et, ax, px, inplane_on)
    _plane_held(out_f, out_i, plane & (V == 0.0), al, be, am, ze, et, ax, px, ay, py, aly,
                zey, inplane_on)
    static = (V == 0.0) & ~at_zero & ~curved & ~plane
    _static_limit(am[static], out_f, out_i, static)
    out = {k: out_f[:, j].reshape(shape) for j, k in enumerate(FLOAT_COLUMNS)}
    out.update({k: out_i[:, j].reshape(shape) for j, k in enumerate(INT_COLUMNS)})
    out["trusted"] = settings.trusted(out["status"], out["error"])
    return out


def _held(out_f: NDArray[np.float64], out_i: NDArray[np.int64], rows: NDArray[np.bool_],
          *point: NDArray[np.float64] | str) -> None:
    """Mark :attr:`Status.HELD` the ``V = 0`` rows ``rows`` where the contact can stick
    through whole cycles: a stuck band exists (``theory.inplane_static_mu_ratio``; a motion
    from outside it approaches its edge with slips that die out), or the motion stuck
    through its whole averaging window (no slip, no flight).  ``point`` is ``(alpha, beta,
    a, zeta, eta_c, a_x, phase_x, inplane_on)``.  ``mu_ratio`` and ``error`` stay those of
    the motion from the given start (nan and inf where it did not settle)."""
    idx = np.flatnonzero(rows)
    if not idx.size:
        return
    al, be, am, ze, et, ax, px, on = point
    band = theory.inplane_static_mu_ratio(al[idx], be[idx], am[idx], ax[idx], px[idx],
                                          ze[idx], et[idx], cast(str, on))
    st = out_i[idx, column_index("status")]
    stuck = out_f[idx, column_index("stick_fraction")] >= HELD_STICK
    mark = (np.isfinite(np.atleast_1d(band.upper)) | stuck) & np.isin(
        st, (Status.PERIODIC.code, Status.AVERAGED.code, Status.NOT_CONVERGED.code))
    out_i[idx[mark], column_index("status")] = Status.HELD.code


def plane_held(status: NDArray[np.int64], stick_fraction: NDArray[np.float64],
               *point: NDArray[np.float64] | str) -> NDArray[np.bool_]:
    """Which ``V = 0`` 2-D points (kernel ``status``, ``stick_fraction``) are held: the
    region of mean forces a stuck contact can hold is not empty
    (:func:`theory.plane_static_region`: a motion from outside it approaches its edge
    with slips that die out, as in 1-D), or the motion stuck through its whole averaging
    window or orbit.  ``point`` is ``(alpha, beta, a, zeta, eta_c, a_x, phase_x, a_y,
    phase_y, alpha_y, zeta_y, inplane_on)``."""
    al, be, am, ze, et, ax, px, ay, py, aly, zey, on = point
    region = theory.plane_static_region(al, be, am, ax, px, ay, py, ze, et, cast(str, on),
                                        aly, zey)
    return (np.isfinite(np.atleast_1d(region.x_upper)) | (stick_fraction >= HELD_STICK)) \
        & np.isin(status, (Status.PERIODIC.code, Status.AVERAGED.code,
                           Status.NOT_CONVERGED.code))


def _plane_held(out_f: NDArray[np.float64], out_i: NDArray[np.int64], rows: NDArray[np.bool_],
                al: NDArray[np.float64], be: NDArray[np.float64], am: NDArray[np.float64],
                ze: NDArray[np.float64], et: NDArray[np.float64], ax: NDArray[np.float64],
                px: NDArray[np.float64], ay: NDArray[np.float64], py: NDArray[np.float64],
                aly: NDArray[np.float64], zey: NDArray[np.float64], on: str) -> None:
    """Mark :attr:`Status.HELD` the ``V = 0`` 2-D rows ``rows`` that :func:`plane_held`
    finds held; ``mu_ratio``, ``lateral_ratio`` and ``error`` stay those of the motion
    from the given start."""
    idx = np.flatnonzero(rows)
    if not idx.size:
        return
    st = out_i[idx, column_index("status")]
    mark = plane_held(st, out_f[idx, column_index("stick_fraction")], al[idx], be[idx],
                      am[idx], ze[idx], et[idx], ax[idx], px[idx], ay[idx], py[idx],
                      aly[idx], zey[idx], on)
    out_i[idx[mark], column_index("status")] = Status.HELD.code


#: The Runge-Kutta tolerance of the 2-D solver (docs/inplane.md, "The 2-D solver").
PLANE_RTOL = 1e-10
#: Stick/slip switches per drive period beyond which a 2-D point fails (chatter).
PLANE_EVENTS_PER_PERIOD = 10_000


def _check_plane(beta: NDArray[np.float64], amplitude: NDArray[np.float64],
                 eta_c: NDArray[np.float64], V: NDArray[np.float64]) -> None:
    """ValueError for the 2-D points the 2-D solver does not cover (``V`` is not
    checked: every velocity, ``V = 0`` included, is computed)."""
    if np.any(np.isinf(beta)):
        raise ValueError("a transverse oscillation (a_y > 0) needs a finite beta: the 2-D "
                         "solver does not cover a rigid contact (use a large finite beta)")
    if np.any((amplitude == 1.0) & (eta_c == 0.0)):
        raise ValueError("a transverse oscillation (a_y > 0) with amplitude = 1 (grazing) "
                         "and eta_c = 0 is not covered by the 2-D solver")


def _static_limit(amplitude: NDArray[np.float64], out_f: NDArray[np.float64],
                  out_i: NDArray[np.int64], rows: NDArray[np.bool_]) -> None:
    """Fill the rows of zero-velocity points with the static limit, eq. (2)."""
    if not np.any(rows):
        return
    contact = amplitude < 1.0
    out_f[rows, column_index("mu_ratio")] = theory.static_mu_ratio(amplitude)
    out_f[rows, column_index("error")] = 0.0
    out_f[rows, column_index("work")] = 0.0  # nothing integrated
    out_f[rows, column_index("stick_fraction")] = np.where(contact, 1.0, np.nan)
    for k in ("slip_fraction", "reverse_slip_fraction", "flight_fraction"):
        out_f[rows, column_index(k)] = np.where(contact, 0.0, np.nan)
    out_f[rows, column_index("lateral_ratio")] = 0.0
    _contact_columns(out_f, amplitude, rows)
    out_i[rows, column_index("status")] = Status.STATIC.code
    out_i[rows, column_index("phase")] = codes.NO_PHASE


_N_FLOAT, _N_INT = len(FLOAT_COLUMNS), len(INT_COLUMNS)
_O_STICK, _O_SLIP, _O_REVERSE, _O_FLIGHT = (column_index(k) for k in (
    "stick_fraction", "slip_fraction", "reverse_slip_fraction", "flight_fraction"))
_O_NORMAL, _O_STICK_AREA, _O_SLIP_AREA, _O_OPEN_AREA = (column_index(k) for k in (
    "mean_normal_ratio", "stick_area_fraction", "slip_area_fraction", "open_area_fraction"))


def _contact_columns(out_f: NDArray[np.float64], amplitude: NDArray[np.float64],
                     rows: NDArray[np.bool_]) -> None:
    """The contact's columns of the flat-punch rows ``rows`` (``amplitude`` of those rows or
    of all): ``mean_normal_ratio`` by its closed form (:func:`theory.mean_normal_force`)
    and the area fractions, which for the one spring of a flat punch are its time
    fractions (slip either way)."""
    if not np.any(rows):
        return
    am = amplitude[rows] if amplitude.shape == rows.shape else amplitude
    out_f[rows, _O_NORMAL] = theory.mean_normal_force(am)
    out_f[rows, _O_STICK_AREA] = out_f[rows, _O_STICK]
    out_f[rows, _O_SLIP_AREA] = out_f[rows, _O_SLIP] + out_f[rows, _O_REVERSE]
    out_f[rows, _O_OPEN_AREA] = out_f[rows, _O_FLIGHT]


def _check_curved(curved: NDArray[np.bool_], al: NDArray[np.float64],
                  be: NDArray[np.float64], am: NDArray[np.float64], V: NDArray[np.float64],
                  ze: NDArray[np.float64], et: NDArray[np.float64], ax: NDArray[np.float64],
                  ay: NDArray[np.float64], pe: NDArray[np.float64], initial: object) -> None:
    """ValueError, naming the parameter and its first value, for the curved-profile points
    the MDR solver does not cover yet (docs/contact_geometry.md)."""
    for name, values, bad, what in (
            ("beta", be, np.isinf(be), "a rigid contact (beta = inf)"),
            ("eta_c", et, et > 0.0, "contact damping (eta_c > 0)"),
            ("a_y", ay, ay > 0.0, "a transverse in-plane oscillation (a_y > 0)")):
        hit = curved & bad
        if np.any(hit):
            i = int(np.flatnonzero(hit)[0])
            raise ValueError(f"a curved profile (profile_exponent = {float(pe[i])!r}) is "
                             f"computed by the MDR solver, which does not take {what} yet: "
                             f"got {name} = {float(values[i])!r}")
    hit = curved & (ax > 0.0) & (V == 0.0)
    if np.any(hit):
        i = int(np.flatnonzero(hit)[0])
        raise ValueError(f"a curved profile (profile_exponent = {float(pe[i])!r}) with a "
                         f"longitudinal in-plane oscillation (a_x = {float(ax[i])!r}) at "
                         "v_inertial = 0 is not covered by the MDR solver: springs that "
                         "stick through whole cycles keep the elongation of the start, so "
                         "the steady state depends on it; give a velocity != 0")
    if not (isinstance(initial, str) and initial == "sliding") \
            and np.any(curved & (V != 0.0)):
        raise ValueError(f"initial = {initial!r}: a curved profile (profile_exponent "
                         "finite) starts from steady sliding only (initial='sliding'); the "
                         "MDR solver takes no section state yet")


#: The package's status of each status of :func:`~vibrofriction.solver.mdr.mdr_friction`.
_MDR_STATUS = {"periodic": Status.PERIODIC, "averaged": Status.AVERAGED,
               "not converged": Status.NOT_CONVERGED}


def _mdr_rows(out_f: NDArray[np.float64], out_i: NDArray[np.int64], rows: NDArray[np.bool_],
              al: NDArray[np.float64], be: NDArray[np.float64], am: NDArray[np.float64],
              V: NDArray[np.float64], ze: NDArray[np.float64], pe: NDArray[np.float64],
              settings: SolverSettings, ax: NDArray[np.float64] | None = None,
              px: NDArray[np.float64] | None = None, inplane_on: str = "substrate") -> None:
    """Fill the rows of the curved-profile points (``V >= 0``: a backward point is mirrored
    by the caller, ``phase_x`` with it) by the MDR solver, with the longitudinal in-plane
    oscillation ``ax``, ``px`` (None: none) of ``inplane_on``, or at ``V = 0`` (without
    one: refused by :func:`_check_curved`) by the static limit
    :func:`theory.profile_static_mu_ratio`.

    Status: MDR ``"periodic"`` (the section state of the finer row repeats after one
    period) is :attr:`Status.PERIODIC` (period 1), ``"averaged"`` :attr:`Status.AVERAGED`,
    ``"not converged"`` :attr:`Status.NOT_CONVERGED` (``mu_ratio`` nan, ``error`` inf, as
    the kernels' own) or, where a row made no progress (infinite error),
    :attr:`Status.FAILED`.  ``error`` is the solver's: the difference of the rows of ``N``
    and ``2N`` springs (the contact's discretisation) plus the orbits' errors.
    ``periods`` and ``events`` are the finer row's (its periods, the events of its last
    period); ``work``, the time fractions of the single contact point, the Floquet and
    window columns and the final section state are nan (no such quantities for a row).
    """
    from .mdr import mdr_friction

    c = column_index
    for i in np.flatnonzero(rows):
        out_f[i] = np.nan  # work, the time fractions, Floquet, windows, final state
        out_i[i] = 0
        out_f[i, c("lateral_ratio")] = 0.0
        out_i[i, c("phase")] = codes.NO_PHASE
        out_f[i, _O_NORMAL] = theory.profile_mean_normal_force(am[i], pe[i])
        if V[i] == 0.0:
            out_f[i, c("mu_ratio")] = theory.profile_static_mu_ratio(am[i], pe[i])
            out_f[i, c("error")] = 0.0
            out_f[i, c("work")] = 0.0
            out_i[i, c("status")] = Status.STATIC.code
            continue
        r = mdr_friction(al[i], be[i], am[i], V[i], pe[i], zeta=ze[i],
                         tol=settings.tol_trusted, a_x=0.0 if ax is None else ax[i],
                         phase_x=0.0 if px is None else px[i], inplane_on=inplane_on)
        status = _MDR_STATUS[r["status"]]
        mu, err = r["mu_ratio"], r["error"]
        if status is Status.NOT_CONVERGED:
            if not math.isfinite(err):
                status = Status.FAILED
            mu, err = math.nan, math.inf
        out_f[i, c("mu_ratio")] = mu
        out_f[i, c("error")] = err
        out_f[i, _O_STICK_AREA] = r["stick_area_fraction"]
        out_f[i, _O_SLIP_AREA] = r["slip_area_fraction"]
        out_f[i, _O_OPEN_AREA] = r["open_area_fraction"]
        out_i[i, c("status")] = status.code
        out_i[i, c("period")] = 1 if status is Status.PERIODIC else 0
        out_i[i, c("periods")] = r["periods"]
        out_i[i, c("events")] = r["events_per_period"]
#: Kernel start of the named initial states: ``(kind, y, x', e, phase)``.
_NAMED_START = {"sliding": (0, 0.0, 0.0, 0.0, 0), "rest": (1, 0.0, 0.0, 0.0, 0)}


def _one_point(dim: Dimensionless, V: float, initial: Initial,
               settings: SolverSettings) -> FrictionResult:
    """One moving point by the scalar kernel directly (no array bookkeeping)."""
    start = _NAMED_START.get(initial) if initial.__class__ is str else None
    if start is None:
        kind, init = initial_rows(initial, 1, lambda i: dim)
        start = (kind, init[0, 0], init[0, 1], init[0, 2], int(init[0, 3]))
    of = np.empty(_N_FLOAT)
    oi = np.empty(_N_INT, dtype=np.int64)
    steady_state(dim.alpha, dim.beta, dim.amplitude, V, dim.zeta, dim.eta_c, dim.a_x,
                 dim.phase_x, dim.inplane_on == "substrate", *start,
                 *settings.kernel_arguments(), of, oi)
    f = of.tolist()  # the contact's columns (as _contact_columns), on Python floats
    f[_O_NORMAL] = theory.mean_normal_force_of(dim.amplitude)
    f[_O_STICK_AREA] = f[_O_STICK]
    f[_O_SLIP_AREA] = f[_O_SLIP] + f[_O_REVERSE]
    f[_O_OPEN_AREA] = f[_O_FLIGHT]
    return result_from_rows(f, oi.tolist(), dim, V, settings)


@overload
def friction_coefficient(system: System, vbar: float, *, v_inertial: None = None,
                         v0: None = None, initial: Initial = "sliding",
                         settings: SolverSettings | None = None) -> FrictionResult: ...
@overload
def friction_coefficient(system: System, vbar: None = None, *, v_inertial: float,
                         v0: None = None, initial: Initial = "sliding",
                         settings: SolverSettings | None = None) -> FrictionResult: ...
@overload
def friction_coefficient(system: System, vbar: None = None, *, v_inertial: None = None,
                         v0: float, initial: Initial = "sliding",
                         settings: SolverSettings | None = None) -> FrictionResult: ...
@overload
def friction_coefficient(system: System, vbar: ArrayLike | None = None, *,
                         v_inertial: ArrayLike | None = None, v0: ArrayLike | None = None,
                         initial: Initial = "sliding", settings: SolverSettings | None = None
                         ) -> FrictionResult | FrictionResults: ...
def friction_coefficient(
    system: System,
    vbar: ArrayLike | None = None,
    *,
    v_inertial: ArrayLike | None = None,
    v0: ArrayLike | None = None,
    initial: Initial = "sliding",
    settings: SolverSettings | None = None,
) -> FrictionResult | FrictionResults:
    """Macroscopic coefficient of friction ``mu_macro/mu0`` in the steady state (eq. 25).

    Parameters
    ----------
    system : a :class:`Dimensionless` ``(alpha, beta, amplitude)`` (eq. 20) or a
        :class:`Physical` system in SI units.
    vbar, v_inertial, v0 : the sliding velocity, exactly one of: ``v0/v0*`` (eq. 16),
        ``v0 m omega/(mu0 F_N0)`` (Fig. 6; required in cases III and IV), or m/s
        (Physical systems only); :func:`vibrofriction.params.inertial_velocity`.
        Scalars give a :class:`FrictionResult`, arrays a :class:`FrictionResults` of
        the same shape.
    initial : ``"sliding"`` (default: steady sliding before the oscillation is switched
        on at ``tau = 0``, docs/model.md; at ``V = 0`` the rest), ``"rest"``, or a
        :class:`SectionState` (e.g. the
        ``final_state`` of another result, for continuation).  Coexisting attractors
        make the initial state part of the result's definition.
    settings : accuracy and effort bounds (:class:`SolverSettings`).
    """
    dim = dimensionless(system)
    V = inertial_velocity(system, vbar, v_inertial=v_inertial, v0=v0)
    if V.__class__ is float and V > 0.0 and dim.a_y == 0.0 \
            and dim.profile_exponent == math.inf:  # one moving point, 1-D, flat punch
        return _one_point(dim, V, initial, settings or DEFAULT_SETTINGS)
    V = np.asarray(V, dtype=float)
    cols = solve_points(dim.alpha, dim.beta, dim.amplitude, V, dim.zeta, dim.eta_c,
                        dim.a_x, dim.phase_x, dim.a_y, dim.phase_y, *dim.pin_y,
                        dim.profile_exponent,
                        inplane_on=dim.inplane_on, initial=initial, settings=settings)
    if V.ndim == 0:
        return result_from_columns({k: v[()].item() for k, v in cols.items()}, dim, float(V))
    return results_from_columns(cols, dim, V)
