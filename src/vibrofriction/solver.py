r"""The macroscopic coefficient of friction and time histories (paper eqs. 21-25).

:func:`friction_coefficient` returns ``mu_macro / mu0 = <F_x>/<F_N>`` (eq. 25) in the
steady state, computed by the exact event-driven kernels of
:mod:`vibrofriction._kernels`; :func:`simulate` returns a densely sampled time
history (Fig. 2).  Velocities are given as ``vbar = v0/v0*`` (eq. 16), as the
inertial velocity ``v_inertial = v0 m omega/(mu0 F_N0)`` (the axis of Fig. 6, the
only one that exists in cases III and IV) or, for a :class:`Physical` system, as
``v0`` in m/s.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field, fields

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import theory
from ._kernels import codes
from ._kernels.integrate import N_SEG_COLUMNS, TWO_PI, initial_point, run_periods, sample
from ._kernels.steady import steady_state, steady_state_many
from .params import Dimensionless, Physical
from .validation import checked, checked_beta

__all__ = [
    "Event",
    "FrictionResult",
    "FrictionResults",
    "History",
    "SectionState",
    "SolverSettings",
    "Status",
    "describe",
    "friction_coefficient",
    "section_state",
    "simulate",
    "solve_points",
]

System = Dimensionless | Physical


class Status(enum.Enum):
    """How a steady-state result was obtained; ``.message`` says it for humans."""

    PERIODIC = "periodic"
    SLIDING = "continuous sliding"
    AVERAGED = "averaged"
    NOT_CONVERGED = "not converged"
    FAILED = "failed"
    STATIC = "static limit"

    @property
    def message(self) -> str:
        return _STATUS_MESSAGES[self]

    @property
    def ok(self) -> bool:
        return self in (Status.PERIODIC, Status.SLIDING, Status.AVERAGED, Status.STATIC)


_STATUS_MESSAGES = {
    Status.PERIODIC: "a periodic orbit was found on the Poincare section and averaged over "
    "exactly one of its periods",
    Status.SLIDING: "continuous forward sliding is proven: the contact point can never stop "
    "again (the free oscillation is smaller than v0 - v0*, eqs. 10-12), so mu = mu0 exactly",
    Status.AVERAGED: "no periodic orbit within the period bound; the running average over "
    "the last half of the run agrees with the half before within tol_mean",
    Status.NOT_CONVERGED: "max_periods was reached before a periodic orbit was found or the "
    "running average settled",
    Status.FAILED: "the event budget `max_events` was exhausted, or the integration could not "
    "advance, or more than 1000 transitions could only be decided within round-off (chatter "
    "along a tangency of the friction cone); the value is not reliable",
    Status.STATIC: "zero sliding velocity: the static limit of eq. (2), the limit of the "
    "steady state as v0 -> 0+",
}
STATUS_BY_CODE = {
    codes.ST_PERIODIC: Status.PERIODIC,
    codes.ST_AVERAGED: Status.AVERAGED,
    codes.ST_NOT_CONVERGED: Status.NOT_CONVERGED,
    codes.ST_FAILED: Status.FAILED,
    codes.ST_SLIDING: Status.SLIDING,
    codes.ST_STATIC: Status.STATIC,
}
NO_PHASE = codes.NO_PHASE  # phase code of a point without a section state (static limit)
PHASE_NAMES = codes.PHASE_NAMES  # phase names by code
_PHASE_CODE = {name: i for i, name in enumerate(codes.PHASE_NAMES)}


@dataclass(frozen=True)
class SolverSettings:
    """Accuracy and effort bounds of the steady-state search.

    Parameters
    ----------
    max_periods : give up (status ``NOT_CONVERGED``) after this many drive periods.
    min_periods : first checkpoint of the running average (doubling afterwards).
    tol_state : relative distance of section states that counts as periodic.
    tol_mean : agreement of successive averaging windows that counts as converged.
    max_events : event budget per point (status ``FAILED`` beyond).
    tol_trusted : a result is *trusted* when its status is a converged one and its
        ``error`` (an estimate of ``|mu_ratio - exact|``) is at most this; the one
        definition used by the figures, the report, the sweep and the command line.
    """

    max_periods: int = 20000
    min_periods: int = 64
    tol_state: float = 1e-10
    tol_mean: float = 1e-7
    max_events: int = 20_000_000
    tol_trusted: float = 1e-5

    def __post_init__(self) -> None:
        if not (isinstance(self.max_periods, int | np.integer) and self.max_periods >= 1):
            raise ValueError(f"max_periods must be an integer >= 1, got {self.max_periods!r}")
        if not (isinstance(self.min_periods, int | np.integer) and self.min_periods >= 1):
            raise ValueError(f"min_periods must be an integer >= 1, got {self.min_periods!r}")
        for name in ("tol_state", "tol_mean", "tol_trusted"):
            v = getattr(self, name)
            if not (math.isfinite(v) and 0.0 < v < 1.0):
                raise ValueError(f"{name} must be in (0, 1), got {v!r}")
        if not (isinstance(self.max_events, int | np.integer) and self.max_events >= 1):
            raise ValueError(f"max_events must be an integer >= 1, got {self.max_events!r}")

    def trusted(self, status: ArrayLike, error: ArrayLike) -> NDArray[np.bool_]:
        """Which results to trust: a converged status and ``error <= tol_trusted``.

        ``status`` holds integer codes (:data:`STATUS_BY_CODE`) or :class:`Status`
        members.  This is the package's one notion of a trusted result.
        """
        st = np.asarray(status)
        if st.dtype == object:
            ok = np.vectorize(lambda x: x.ok, otypes=[bool])(st) if st.size else st.astype(bool)
        else:
            ok = np.isin(st, _CONVERGED_CODES)
        err = np.nan_to_num(np.asarray(error, dtype=float), nan=np.inf)
        return ok & (err <= self.tol_trusted)


_DEFAULT_SETTINGS = SolverSettings()
_CONVERGED_CODES = [c for c, st in STATUS_BY_CODE.items() if st.ok]


@dataclass(frozen=True)
class SectionState:
    """A state on the Poincare section ``tau = 2 pi k`` in the scaled variables.

    ``y = x - V tau`` is the body displacement without the drift (unit
    ``mu0 F_N0/(m omega^2)``), ``x_dot`` the body velocity (unit ``mu0 F_N0/(m omega)``),
    ``f`` the tangential contact force (unit ``mu0 F_N0``), ``phase`` one of
    ``stick``, ``slip+``, ``slip-``, and ``e`` the elongation of the contact spring
    (unit of ``y``; ``nan``: derived from ``f``, which needs ``f = k e + c x_dot`` to
    determine it, i.e. not in slip on a viscoelastic contact).
    """

    y: float
    x_dot: float
    f: float
    phase: str
    e: float = math.nan

    def __post_init__(self) -> None:
        if self.phase not in ("stick", "slip+", "slip-"):
            raise ValueError(f"phase must be 'stick', 'slip+' or 'slip-', got {self.phase!r}")
        for name in ("y", "x_dot", "f"):
            if not math.isfinite(getattr(self, name)):
                raise ValueError(f"{name} must be finite, got {getattr(self, name)!r}")

    def elongation(self, system: Dimensionless) -> float:
        """``e``, or where it is not given, the one ``f`` implies for ``system``."""
        if math.isfinite(self.e):
            return self.e
        k = system.beta - system.alpha
        if math.isinf(k):
            return 0.0
        if self.phase == "stick":
            return (self.f - system.eta_c * k * self.x_dot) / k
        if system.eta_c > 0.0:
            raise ValueError("a SectionState in slip on a viscoelastic contact (eta_c > 0) "
                             "needs its elongation e")
        return self.f / k


@dataclass(frozen=True)
class FrictionResult:
    """The steady state at one point (paper eq. 25) and how it was obtained.

    ``mu_ratio`` is ``mu_macro/mu0``; ``error`` an estimate of ``|mu_ratio - exact|``
    (docs/solver.md explains how it is obtained for each status; ``inf`` when
    nothing is known); ``trusted`` whether the status is a converged one and
    ``error <= settings.tol_trusted``; ``period`` the orbit's period in drive
    periods (0 when not periodic); ``periods`` and ``events`` the work done; the
    fractions are of time in the averaging window; ``multiplier`` the modulus of
    the orbit's leading Floquet multiplier (how fast the motion approaches it per
    ``period`` drive periods; nan when not periodic); ``settling_periods`` the drive
    periods the motion from the initial state needs to come within ``error`` of the
    answer; ``window_min``/``window_max`` the range of the averaging windows'
    means (averaged and not converged results) and ``drift_rate`` their change per
    drive period where the last three move one way (0 where they do not, nan with
    fewer windows); ``final_state`` the last section state (a start for continuation).
    """

    mu_ratio: float
    status: Status
    error: float
    trusted: bool
    period: int
    periods: int
    events: int
    stick_fraction: float
    slip_fraction: float
    reverse_slip_fraction: float
    flight_fraction: float
    multiplier: float
    settling_periods: float
    window_min: float
    window_max: float
    drift_rate: float
    final_state: SectionState | None
    system: Dimensionless
    v_inertial: float

    @property
    def message(self) -> str:
        """How the result was obtained and what it is worth, in words."""
        return describe(self)

    @property
    def success(self) -> bool:
        return self.status.ok

    @property
    def vbar(self) -> float:
        """``v0/v0*``, or nan where ``v0*`` is zero or infinite (cases III, IV)."""
        try:
            return float(self.system.inertial_to_vbar(self.v_inertial))
        except ValueError:
            return math.nan


#: Drive periods beyond which the approach to a periodic orbit counts as slow.
SLOW_SETTLING = 1000


def describe(r: FrictionResult) -> str:
    """The message of a result: status, how it was obtained, and its caveats."""
    head = r.status.value + (f" (period {r.period})" if r.status is Status.PERIODIC else "")
    parts = [f"{head}: {r.status.message}", f"error estimate {r.error:.2g}"
             + ("" if r.trusted else " (not trusted)")]
    if r.status is Status.PERIODIC and math.isfinite(r.settling_periods) \
            and r.settling_periods > SLOW_SETTLING:
        parts.append(
            f"the orbit is reached slowly: leading Floquet multiplier {r.multiplier:.6g}, so "
            f"the motion from the initial state needs about {r.settling_periods:.3g} drive "
            "periods to come within the error of this value; a measurement over fewer "
            "periods sees the transient")
    if r.status is Status.PERIODIC and math.isnan(r.settling_periods):
        parts.append(
            f"the orbit is neutrally stable (leading Floquet multiplier {r.multiplier:.9g}): "
            "the motion from the initial state need not approach it, and a transient (e.g. "
            "rare sticks of an undamped free oscillation) can persist for many periods; "
            "the error includes how far the motion's mean over periods 512-1024 is from it")
    if r.status in (Status.AVERAGED, Status.NOT_CONVERGED) and math.isfinite(r.window_min):
        parts.append(f"window means range from {r.window_min:.6g} to {r.window_max:.6g}")
    if r.status is Status.NOT_CONVERGED:
        if math.isfinite(r.drift_rate) and r.drift_rate != 0.0:
            how = (f"the window means drift one way ({r.drift_rate:+.2g} per period): a slow "
                   "transient still on its way to a steady state (near beta = 1 such drifts "
                   "last 1e4-1e6 periods, docs/modulation.md)")
        else:
            how = "the window means do not move one way"
        parts.append(f"mu_ratio is nan: the motion has not settled and a window mean is not "
                     f"the long-time average; {how}: raise max_periods")
    return "; ".join(parts)


@dataclass(frozen=True)
class FrictionResults:
    """Results over an array of velocities: the fields of :class:`FrictionResult` as arrays."""

    mu_ratio: NDArray[np.float64]
    status: NDArray[np.object_]
    error: NDArray[np.float64]
    trusted: NDArray[np.bool_]
    period: NDArray[np.int64]
    periods: NDArray[np.int64]
    events: NDArray[np.int64]
    stick_fraction: NDArray[np.float64]
    slip_fraction: NDArray[np.float64]
    reverse_slip_fraction: NDArray[np.float64]
    flight_fraction: NDArray[np.float64]
    multiplier: NDArray[np.float64]
    settling_periods: NDArray[np.float64]
    window_min: NDArray[np.float64]
    window_max: NDArray[np.float64]
    drift_rate: NDArray[np.float64]
    final_state: NDArray[np.object_]
    system: Dimensionless
    v_inertial: NDArray[np.float64]

    @property
    def shape(self) -> tuple[int, ...]:
        return self.mu_ratio.shape

    def __len__(self) -> int:
        return len(self.mu_ratio)

    def __getitem__(self, index: int | tuple[int, ...]) -> FrictionResult:
        out = {}
        for f in fields(self):
            v = getattr(self, f.name)
            if f.name != "system":
                v = v[index]
                v = v.item() if isinstance(v, np.generic) else v
            out[f.name] = v
        return FrictionResult(**out)

    def __iter__(self):
        for i in np.ndindex(self.shape):
            yield self[i]

    @property
    def success(self) -> NDArray[np.bool_]:
        return np.vectorize(lambda s: s.ok, otypes=[bool])(self.status)


@dataclass(frozen=True)
class Event:
    """A transition at drive time ``tau``: ``kind`` and the phases before and after."""

    tau: float
    kind: str
    before: str
    after: str


@dataclass(frozen=True)
class History:
    """A time history sampled from the closed forms (Fig. 2).

    All quantities are scaled (docs/model.md): ``tau = omega t``; ``x`` body position and
    ``x_dot`` its velocity (units ``mu0 F_N0/(m omega^2)`` and ``mu0 F_N0/(m omega)``);
    ``f`` the tangential contact force and ``n`` the ``mu0``-scaled normal force, both
    in units of ``mu0 F_N0``; ``phase`` the phase name at each sample; ``events``
    every transition with its exact time.  Sample times include every event time
    (on both sides), so phase boundaries are sharp.  ``e`` is the elongation of the
    contact spring; ``work_input`` the work done by the pulled end since the start and
    ``dissipated_pin``, ``dissipated_contact``, ``dissipated_friction`` the energy
    dissipated by the pin dashpot, the contact dashpot and friction (unit
    ``(mu0 F_N0)^2/(m omega^2)``; Gauss-Legendre quadrature of the closed forms, relative
    accuracy ~1e-10), so that ``work_input - sum(dissipated) = stored_energy() -
    stored_energy()[0]`` (docs/damping.md).
    """

    tau: NDArray[np.float64]
    x: NDArray[np.float64]
    x_dot: NDArray[np.float64]
    f: NDArray[np.float64]
    n: NDArray[np.float64]
    phase: NDArray[np.str_]
    events: tuple[Event, ...]
    system: Dimensionless
    v_inertial: float
    e: NDArray[np.float64]
    work_input: NDArray[np.float64]
    dissipated_pin: NDArray[np.float64]
    dissipated_contact: NDArray[np.float64]
    dissipated_friction: NDArray[np.float64]
    final_state: SectionState | None = field(default=None)

    def stored_energy(self) -> NDArray[np.float64]:
        """Kinetic and elastic energy ``x'^2/2 + alpha (V tau - x)^2/2 + k e^2/2``."""
        d = self.system
        y = self.x - self.v_inertial * self.tau
        out = 0.5 * self.x_dot**2 + 0.5 * d.alpha * y**2
        if not d.is_rigid:
            out = out + 0.5 * (d.beta - d.alpha) * self.e**2
        return out

    def time(self, physical: Physical) -> NDArray[np.float64]:
        """Sample times in seconds for a physical system (``t = tau/omega``)."""
        return self.tau / physical.omega


# --------------------------------------------------------------------------- helpers
def _dimensionless(system: System) -> Dimensionless:
    if isinstance(system, Physical):
        return system.to_dimensionless()
    if isinstance(system, Dimensionless):
        return system
    raise TypeError(f"system must be a Dimensionless or Physical, got {type(system).__name__}")


def _inertial_velocity(system: System, vbar, v_inertial, v0) -> NDArray[np.float64]:
    given = [name for name, v in (("vbar", vbar), ("v_inertial", v_inertial), ("v0", v0))
             if v is not None]
    if len(given) != 1:
        raise ValueError(f"give exactly one of vbar, v_inertial, v0 (got {given or 'none'})")
    dim = _dimensionless(system)
    if v_inertial.__class__ is float and vbar is None and v0 is None:  # the common fast path
        if not (math.isfinite(v_inertial) and v_inertial >= 0.0):
            raise ValueError(f"v_inertial must be finite and >= 0, got {v_inertial!r}")
        return np.asarray(v_inertial)
    if v0 is not None:
        if not isinstance(system, Physical):
            raise ValueError("v0 (m/s) needs a Physical system; use vbar or v_inertial")
        return np.asarray(system.v0_to_inertial(v0), dtype=float)
    if vbar is not None:
        return np.asarray(dim.vbar_to_inertial(vbar), dtype=float)
    arr = np.asarray(v_inertial, dtype=float)
    bad = ~(np.isfinite(arr) & (arr >= 0.0))
    if np.any(bad):
        first = float(np.atleast_1d(arr)[np.atleast_1d(bad)][0])
        raise ValueError(f"v_inertial must be finite and >= 0, got {first!r}")
    return arr


def _initial(initial, n: int, systems) -> tuple[int, NDArray[np.float64]]:
    """Kernel start ``(kind, rows (y, x', e, phase))``; ``systems(i)`` is point i's system."""
    init = np.zeros((n, 4))
    if isinstance(initial, SectionState):
        init[:] = (initial.y, initial.x_dot, initial.elongation(systems(0)),
                   _PHASE_CODE[initial.phase])
        return 2, init
    if isinstance(initial, np.ndarray) and initial.dtype == object:
        for i, s in enumerate(initial.ravel()):
            init[i] = (s.y, s.x_dot, s.elongation(systems(i)), _PHASE_CODE[s.phase])
        return 2, init
    if initial == "sliding":
        return 0, init
    if initial == "rest":
        return 1, init
    raise ValueError(f"initial must be 'sliding', 'rest' or a SectionState, got {initial!r}")


def section_state(y: float, xd: float, f: float, phase: int, e: float) -> SectionState | None:
    """The :class:`SectionState` of a solver row, or None where there is none (static)."""
    if not (math.isfinite(y) and math.isfinite(xd) and math.isfinite(f)) \
            or phase not in (codes.STICK, codes.SLIP_POS, codes.SLIP_NEG):
        return None
    return SectionState(float(y), float(xd), float(f), codes.PHASE_NAMES[int(phase)], float(e))


# --------------------------------------------------------------------------- public API
#: Columns of :func:`solve_points` (and of the kernels' output rows), in order.
FLOAT_COLUMNS = ("mu_ratio", "error", "stick_fraction", "slip_fraction",
                 "reverse_slip_fraction", "flight_fraction", "y", "x_dot", "f", "multiplier",
                 "settling_periods", "window_min", "window_max", "drift_rate", "e")
INT_COLUMNS = ("status", "period", "periods", "events", "phase", "degenerate")


def solve_points(
    alpha: ArrayLike,
    beta: ArrayLike,
    amplitude: ArrayLike,
    v_inertial: ArrayLike,
    zeta: ArrayLike = 0.0,
    eta_c: ArrayLike = 0.0,
    *,
    initial: str | SectionState | NDArray[np.object_] = "sliding",
    settings: SolverSettings | None = None,
) -> dict[str, NDArray]:
    """Steady states at arbitrary points, one compiled loop: the batch engine.

    The six parameters broadcast together; validation is the caller's duty beyond
    what is checked here (finite, ``alpha > 0``, ``beta > alpha``, ``a >= 0``,
    ``V >= 0``, ``zeta >= 0``, ``eta_c >= 0``).  Returns arrays of that shape:
    ``mu_ratio``, ``error``, the four time fractions, ``status`` (integer codes, see
    :data:`STATUS_BY_CODE`; ``-1`` = static limit at ``V = 0``), ``period``,
    ``periods``, ``events`` and the final section state ``y``, ``x_dot``, ``f``, ``e``,
    ``phase`` (phase code).  Results are bitwise reproducible:
    each point depends only on its own parameters.
    """
    settings = settings or SolverSettings()
    al, be, am, V, ze, et = np.broadcast_arrays(*(
        np.asarray(x, dtype=float) for x in (alpha, beta, amplitude, v_inertial, zeta, eta_c)))
    shape = V.shape
    al, be, am, V, ze, et = (np.ascontiguousarray(x.ravel()) for x in (al, be, am, V, ze, et))
    checked("alpha", al, minimum=0.0, strict=True)
    checked_beta(al, be)
    checked("amplitude", am, minimum=0.0)
    checked("v_inertial", V, minimum=0.0)
    checked("zeta", ze, minimum=0.0)
    checked("eta_c", et, minimum=0.0)
    n = V.size
    kind, init = _initial(initial, n, lambda i: Dimensionless(al[i], be[i], am[i], ze[i], et[i]))
    out_f = np.full((n, len(FLOAT_COLUMNS)), np.nan)
    out_i = np.zeros((n, len(INT_COLUMNS)), dtype=np.int64)
    moving = V > 0.0
    idx = np.flatnonzero(moving)
    if idx.size:
        of = np.full((idx.size, len(FLOAT_COLUMNS)), np.nan)
        oi = np.zeros((idx.size, len(INT_COLUMNS)), dtype=np.int64)
        steady_state_many(al[idx], be[idx], am[idx], V[idx], ze[idx], et[idx], kind,
                          np.ascontiguousarray(init[idx]), *_kernel_settings(settings), of, oi)
        out_f[idx] = of
        out_i[idx] = oi
    _static_limit(am[~moving], out_f, out_i, ~moving)
    out = {k: out_f[:, j].reshape(shape) for j, k in enumerate(FLOAT_COLUMNS)}
    out.update({k: out_i[:, j].reshape(shape) for j, k in enumerate(INT_COLUMNS)})
    out["trusted"] = settings.trusted(out["status"], out["error"])
    return out


def _kernel_settings(settings: SolverSettings) -> tuple:
    return (int(settings.max_periods), int(settings.min_periods), float(settings.tol_state),
            float(settings.tol_mean), int(settings.max_events))


def _static_limit(amplitude: NDArray[np.float64], out_f: NDArray[np.float64],
                  out_i: NDArray[np.int64], rows: NDArray[np.bool_]) -> None:
    """Fill the rows of zero-velocity points with the static limit, eq. (2)."""
    if not np.any(rows):
        return
    col = {k: j for j, k in enumerate(FLOAT_COLUMNS)}
    contact = amplitude < 1.0
    out_f[rows, col["mu_ratio"]] = theory.static_mu_ratio(amplitude)
    out_f[rows, col["error"]] = 0.0
    out_f[rows, col["stick_fraction"]] = np.where(contact, 1.0, np.nan)
    for k in ("slip_fraction", "reverse_slip_fraction", "flight_fraction"):
        out_f[rows, col[k]] = np.where(contact, 0.0, np.nan)
    out_i[rows, INT_COLUMNS.index("status")] = codes.ST_STATIC
    out_i[rows, INT_COLUMNS.index("phase")] = codes.NO_PHASE


def friction_coefficient(
    system: System,
    vbar: ArrayLike | None = None,
    *,
    v_inertial: ArrayLike | None = None,
    v0: ArrayLike | None = None,
    initial: str | SectionState = "sliding",
    settings: SolverSettings | None = None,
) -> FrictionResult | FrictionResults:
    """Macroscopic coefficient of friction ``mu_macro/mu0`` in the steady state (eq. 25).

    Parameters
    ----------
    system : a :class:`Dimensionless` ``(alpha, beta, amplitude)`` (eq. 20) or a
        :class:`Physical` system in SI units.
    vbar, v_inertial, v0 : the sliding velocity, exactly one of: ``v0/v0*`` (eq. 16),
        ``v0 m omega/(mu0 F_N0)`` (Fig. 6; required in cases III and IV), or m/s
        (Physical systems only).  Scalars give a :class:`FrictionResult`, arrays a
        :class:`FrictionResults` of the same shape.
    initial : ``"sliding"`` (default: steady sliding before the oscillation is switched
        on at ``tau = 0``, docs/model.md), ``"rest"``, or a :class:`SectionState` (e.g. the
        ``final_state`` of another result, for continuation).  Coexisting attractors
        make the initial state part of the result's definition.
    settings : accuracy and effort bounds (:class:`SolverSettings`).
    """
    dim = _dimensionless(system)
    V = _inertial_velocity(system, vbar, v_inertial, v0)
    scalar = V.ndim == 0
    shape = V.shape
    if scalar and V > 0.0:
        # one point: call the scalar kernel directly (no array bookkeeping)
        settings = settings or _DEFAULT_SETTINGS
        kind, init = _initial(initial, 1, lambda i: dim)
        of = np.empty(len(FLOAT_COLUMNS))
        oi = np.empty(len(INT_COLUMNS), dtype=np.int64)
        steady_state(dim.alpha, dim.beta, dim.amplitude, float(V), dim.zeta, dim.eta_c, kind,
                     init[0, 0], init[0, 1], init[0, 2], int(init[0, 3]),
                     *_kernel_settings(settings), of, oi)
        cols = dict(zip(FLOAT_COLUMNS, of.tolist(), strict=True))
        cols.update(zip(INT_COLUMNS, oi.tolist(), strict=True))
        cols["trusted"] = bool(settings.trusted(oi[0], of[1]))
        return _result(cols, dim, float(V))
    cols = solve_points(dim.alpha, dim.beta, dim.amplitude, V, dim.zeta, dim.eta_c,
                        initial=initial, settings=settings)
    if scalar:
        return _result({k: v[()].item() for k, v in cols.items()}, dim, float(V))
    status = np.vectorize(STATUS_BY_CODE.__getitem__, otypes=[object])(cols["status"])
    states = np.empty(V.size, dtype=object)
    flat = {k: v.ravel() for k, v in cols.items()}
    for i in range(V.size):
        states[i] = section_state(flat["y"][i], flat["x_dot"][i], flat["f"][i],
                                  int(flat["phase"][i]), flat["e"][i])
    return FrictionResults(
        status=status, final_state=states.reshape(shape), system=dim,
        v_inertial=V.astype(float), **{k: cols[k] for k in _RESULT_COLUMNS})


_RESULT_COLUMNS = ("mu_ratio", "error", "trusted", "period", "periods", "events",
                   "stick_fraction", "slip_fraction", "reverse_slip_fraction",
                   "flight_fraction", "multiplier", "settling_periods", "window_min",
                   "window_max", "drift_rate")


def _result(cols: dict, dim: Dimensionless, V: float) -> FrictionResult:
    """One point's :class:`FrictionResult` from its columns (Python scalars)."""
    return FrictionResult(
        status=STATUS_BY_CODE[int(cols["status"])],
        final_state=section_state(cols["y"], cols["x_dot"], cols["f"], int(cols["phase"]),
                                  cols["e"]),
        system=dim, v_inertial=V, **{k: cols[k] for k in _RESULT_COLUMNS})


def simulate(
    system: System,
    vbar: float | None = None,
    *,
    v_inertial: float | None = None,
    v0: float | None = None,
    periods: float = 5.0,
    samples_per_period: int = 400,
    initial: str | SectionState = "sliding",
    settings: SolverSettings | None = None,
) -> History:
    """Time history over ``periods`` drive periods, sampled from the closed forms (Fig. 2).

    ``initial``: ``"sliding"``, ``"rest"``, a :class:`SectionState`, or ``"steady"``:
    the final section state of :func:`friction_coefficient` at the same point, so the
    history shows the steady state rather than the transient (ValueError where that
    result has no section state or is not trusted).  ``final_state`` is the state on
    the last Poincare section within the history, ``tau = 2 pi floor(periods)``.
    """
    dim = _dimensionless(system)
    V = _inertial_velocity(system, vbar, v_inertial, v0)
    if V.ndim != 0:
        raise ValueError("simulate takes one velocity, got an array")
    V = float(V)
    if not (math.isfinite(periods) and periods > 0):
        raise ValueError(f"periods must be finite and > 0, got {periods!r}")
    if not (isinstance(samples_per_period, int) and samples_per_period >= 2):
        raise ValueError(f"samples_per_period must be an integer >= 2, got {samples_per_period!r}")
    if isinstance(initial, str) and initial == "steady":
        steady = friction_coefficient(dim, v_inertial=V, settings=settings)
        if steady.final_state is None or not steady.trusted:
            raise ValueError(f"initial='steady': no trusted steady state at this point "
                             f"({steady.message})")
        initial = steady.final_state
    kind, init = _initial(initial, 1, lambda i: dim)
    if kind == 2:
        y, xd, e, ph, ed = init[0, 0], init[0, 1], init[0, 2], int(init[0, 3]), math.nan
    else:
        y, xd, e, ph, ed = initial_point(kind, *_parameters(dim, V))
    whole = int(math.ceil(periods))
    cap = 4096 * whole
    while True:
        seg = np.empty((cap, N_SEG_COLUMNS))
        m = run_periods(0.0, y, xd, e, ed, ph, *_parameters(dim, V), whole, cap, seg)
        if m > 0:
            break
        cap *= 4
    seg = seg[:m]
    tau_end = TWO_PI * periods
    grid = np.linspace(0.0, tau_end, int(round(samples_per_period * periods)) + 1)
    ev_rows = [j for j in range(1, m) if int(seg[j, 5]) != codes.EV_SECTION]
    ev_tau = seg[ev_rows, 0] if ev_rows else np.empty(0)
    ev_tau = ev_tau[ev_tau <= tau_end]
    # each event time twice: the end of one phase and the start of the next
    eps = 1e-12 * max(1.0, tau_end)
    taus = np.sort(np.concatenate([grid, ev_tau - eps, ev_tau]))
    taus = taus[(taus >= 0.0) & (taus <= tau_end)]
    out = np.empty((taus.size, 6))
    sample(seg, m, *_parameters(dim, V), taus, out)
    dissipated = _dissipation(seg, m, dim, V, taus)
    events = tuple(
        Event(float(seg[j, 0]), codes.EVENT_NAMES[int(seg[j, 5])],
              codes.PHASE_NAMES[int(seg[j - 1, 4])], codes.PHASE_NAMES[int(seg[j, 4])])
        for j in ev_rows if seg[j, 0] <= tau_end)
    whole_done = int(math.floor(periods + 1e-12))
    last = seg[np.flatnonzero(seg[:, 0] <= TWO_PI * whole_done * (1 + 1e-14))[-1]]
    return History(
        tau=taus, x=out[:, 0] + V * taus, x_dot=out[:, 1], f=out[:, 2], n=out[:, 3],
        phase=np.asarray(codes.PHASE_NAMES, dtype=str)[out[:, 4].astype(int)],
        events=events, system=dim, v_inertial=V, e=out[:, 5], **dissipated,
        final_state=section_state(last[1], last[2], last[3], int(last[4]), last[9]))


def _parameters(dim: Dimensionless, V: float) -> tuple[float, ...]:
    """The kernels' point arguments ``(alpha, beta, a, V, zeta, eta_c)``."""
    return dim.alpha, dim.beta, dim.amplitude, float(V), dim.zeta, dim.eta_c


def _rates(dim: Dimensionless, V: float, cols: NDArray[np.float64],
           tau: NDArray[np.float64]) -> NDArray[np.float64]:
    """Power input by the pulled end and dissipated by the pin dashpot, the contact
    dashpot and friction (docs/damping.md, energy balance), from sampled columns."""
    y, xd, f, n, ph, e = cols.T
    gamma = 2.0 * dim.zeta * math.sqrt(dim.alpha)
    k = dim.beta - dim.alpha
    c = 0.0 if math.isinf(k) else dim.eta_c * k
    stick = ph == codes.STICK
    if math.isinf(k):
        e_dot = np.zeros_like(xd)
    elif c > 0.0:
        e_dot = (f - k * e) / c  # f = k e + c e' in contact, 0 = k e + c e' in flight
    else:
        s = np.where(ph == codes.SLIP_POS, 1.0, np.where(ph == codes.SLIP_NEG, -1.0, 0.0))
        e_dot = np.where(stick, xd, -s * dim.amplitude * np.sin(tau) / k)  # e = s n / k
    e_dot = np.where(stick, xd, e_dot)
    return np.stack([V * (-dim.alpha * y - gamma * (xd - V)), gamma * (xd - V) ** 2,
                     c * e_dot**2, f * (xd - e_dot)])


_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(6)


def _dissipation(seg: NDArray[np.float64], m: int, dim: Dimensionless, V: float,
                 taus: NDArray[np.float64]) -> dict[str, NDArray[np.float64]]:
    """Cumulative work and dissipated energies at ``taus``: Gauss-Legendre quadrature of
    the closed forms between successive samples (no event lies inside one), each cut
    into pieces shorter than a quarter of the fastest free period."""
    w_max = max(1.0, math.sqrt(dim.alpha), 0.0 if dim.is_rigid else math.sqrt(dim.beta))
    h = np.diff(taus)
    pieces = np.maximum(1, np.ceil(h * w_max / (0.5 * math.pi))).astype(int)
    owner = np.repeat(np.arange(h.size), pieces)
    start = np.repeat(taus[:-1], pieces) + (np.arange(owner.size)
                                            - np.repeat(np.cumsum(pieces) - pieces, pieces)) \
        * np.repeat(h / pieces, pieces)
    width = np.repeat(h / pieces, pieces)
    nodes = (start[:, None] + 0.5 * width[:, None] * (_GAUSS_X[None, :] + 1.0)).ravel()
    cols = np.empty((nodes.size, 6))
    sample(seg, m, *_parameters(dim, V), nodes, cols)
    rates = _rates(dim, V, cols, nodes).reshape(4, -1, _GAUSS_X.size)
    per_piece = 0.5 * width * (rates * _GAUSS_W).sum(axis=2)
    per_interval = np.zeros((4, h.size))
    for j in range(4):
        per_interval[j] = np.bincount(owner, per_piece[j], minlength=h.size)
    cum = np.concatenate([np.zeros((4, 1)), np.cumsum(per_interval, axis=1)], axis=1)
    return dict(zip(("work_input", "dissipated_pin", "dissipated_contact",
                     "dissipated_friction"), cum, strict=True))
