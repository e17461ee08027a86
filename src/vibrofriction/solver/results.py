"""What the solver returns: section states and steady-state results (paper eq. 25).

The fields of :class:`FrictionResult` and :class:`FrictionResults` are those of
:data:`vibrofriction.schema.RESULT_FIELDS`, in that order, with their units and meanings
(the docstrings below are generated from it); :func:`results_from_columns` builds them
from the kernels' named output columns, :func:`result_from_rows` one point's from the
kernels' rows (the scalar fast path: no dictionary, no dataclass ``__init__``).
"""

from __future__ import annotations

import math
import operator
from collections import Counter
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, fields
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from .._kernels import codes
from ..params import Dimensionless
from ..schema import (
    FIELD,
    FLOAT_COLUMNS,
    INT_COLUMNS,
    METHOD_NAMES,
    PARAMETER,
    RESULT_FIELDS,
    STATE_FIELDS,
    STATE_PREFIX,
    Field,
    Status,
    column_index,
)
from .settings import SolverSettings, converged
from .tables import (
    Column,
    dataframe,
    dataset,
    number,
    system_coords,
    system_text,
    table_attrs,
    vbar_of,
)

if TYPE_CHECKING:
    import pandas as pd
    import xarray as xr

__all__ = ["SLOW_SETTLING", "FrictionResult", "FrictionResults", "SectionState", "describe",
           "result_from_columns", "result_from_rows", "results_from_columns",
           "section_state"]

PHASE_CODE = {name: i for i, name in enumerate(codes.PHASE_NAMES)}


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
        """Check the phase's name and that ``y``, ``x_dot`` and ``f`` are finite."""
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


assert tuple(f.name for f in STATE_FIELDS) == tuple(f.name for f in fields(SectionState))


def _frozen(cls: type, values: dict[str, Any]) -> Any:
    """An instance of the frozen dataclass ``cls`` with the fields ``values``, unchecked.

    ``values`` holds all the fields, in field order; ``__init__`` is not run: for values already
    checked, as the solver's are; the same object ``cls(**values)`` would be, a few microseconds
    sooner.
    """
    obj: Any = object.__new__(cls)
    obj.__dict__.update(values)
    return obj


#: The phases a section state can be in, by code.
_SECTION_PHASES = {c: codes.PHASE_NAMES[c] for c in (codes.STICK, codes.SLIP_POS, codes.SLIP_NEG)}


def section_state(y: float, x_dot: float, f: float, phase: int, e: float) -> SectionState | None:
    """The :class:`SectionState` of a solver row, or None where there is none (static).

    Parameters
    ----------
    y, x_dot, f : float
        The section state's position, velocity and contact force (laboratory frame).
    phase : int
        The kernels' phase code (``phase`` of :data:`~vibrofriction.schema.INT_COLUMNS`).
    e : float
        The contact spring's elongation.

    Returns
    -------
    SectionState or None
        None where the phase has no section state or a value is not finite.
    """
    name = _SECTION_PHASES.get(phase)
    if name is None or not (math.isfinite(y) and math.isfinite(x_dot) and math.isfinite(f)):
        return None
    # what SectionState.__post_init__ checks holds: finite y, x_dot, f and a named phase
    state = object.__new__(SectionState)
    state.__dict__.update(y=float(y), x_dot=float(x_dot), f=float(f), phase=name, e=float(e))
    return state


# --------------------------------------------------------------------------- the results
# the fields are written out below, so that type checkers and editors see them; they are
# checked against the schema's (names, order and kinds) where the classes are defined
_SCALAR = {"float": "float", "int": "int", "bool": "bool", "str": "str"}
_OBJECT = {"status": "Status", "final_state": "SectionState | None", "system": "Dimensionless"}
_ARRAY = {"float": "NDArray[np.float64]", "int": "NDArray[np.int64]",
          "bool": "NDArray[np.bool_]", "str": "NDArray[np.str_]"}


def _check_fields(cls: type, expected: dict[str, str]) -> None:
    """The annotations of ``cls`` are ``expected``: the schema's fields, in order."""
    if list(cls.__annotations__.items()) != list(expected.items()):
        raise TypeError(f"{cls.__name__}'s fields differ from schema.RESULT_FIELDS")


def _field_doc(f: Field) -> str:
    where = f"; eq. {f.equation}" if f.equation.startswith("(") else ""
    unit = f" [{f.unit}]" if f.unit not in ("", "1") else ""
    text = f.long_name.replace("|", "\\|")  # |x| is a substitution in reST
    return f"* ``{f.name}``{unit}: {text}{where}"


_FIELDS_DOC = "\n".join(_field_doc(f) for f in RESULT_FIELDS)


@dataclass(frozen=True, repr=False)
class FrictionResult:  # noqa: D101 (the docstring is __doc__ below: it lists the fields)
    mu_ratio: float
    status: Status
    error: float
    trusted: bool
    period: int
    periods: int
    events: int
    method: str
    work: float
    stick_fraction: float
    slip_fraction: float
    reverse_slip_fraction: float
    flight_fraction: float
    multiplier: float
    settling_periods: float
    window_min: float
    window_max: float
    drift_rate: float
    lateral_ratio: float
    mean_normal_ratio: float
    stick_area_fraction: float
    slip_area_fraction: float
    open_area_fraction: float
    sliding_mu_ratio: float
    final_state: SectionState | None
    system: Dimensionless
    v_inertial: float
    __doc__ = f"""The steady state at one point (paper eq. 25) and how it was obtained.

    Its fields are :data:`vibrofriction.schema.RESULT_FIELDS`; docs/solver.md explains
    how ``error`` is obtained for each status.

{_FIELDS_DOC}
    """

    @property
    def message(self) -> str:
        """How the result was obtained and what it is worth, in words."""
        return describe(self)

    @property
    def success(self) -> bool:
        """Whether the status is a converged one (:attr:`Status.ok`)."""
        return self.status.ok

    @property
    def vbar(self) -> float:
        """``v0/v0*``, or nan where ``v0*`` is zero or infinite (cases III, IV)."""
        try:
            return float(self.system.inertial_to_vbar(self.v_inertial))
        except ValueError:
            return math.nan

    def as_dict(self) -> dict[str, Any]:
        """Every field by name (:data:`~vibrofriction.schema.RESULT_FIELDS`).

        ``status`` as its name, ``final_state`` and ``system`` as dicts (None: no section
        state).
        """
        out = {}
        for f in RESULT_FIELDS:
            v = getattr(self, f.name)
            if isinstance(v, Status):
                v = v.value
            elif v is not None and f.kind == "object":
                v = {g.name: getattr(v, g.name) for g in fields(v)}
            out[f.name] = v
        return out

    def to_dict(self) -> dict[str, Any]:
        """The result as one row of a table: :meth:`FrictionResults.to_dataframe`'s columns.

        Returns
        -------
        dict of str to object
            ``v_inertial`` and ``vbar`` (nan where ``v0*`` is zero or infinite), every field
            of :data:`~vibrofriction.schema.RESULT_FIELDS` but ``final_state`` and ``system``
            (``status`` as its name), and the final section state's components as
            ``final_y``, ``final_x_dot``, ``final_f``, ``final_phase`` (``"none"``: no
            section state) and ``final_e``; Python scalars. Unlike :meth:`as_dict`, flat:
            the system's parameters are in ``system``.

        Examples
        --------
        >>> import vibrofriction as vf
        >>> r = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5), vbar=0.3)
        >>> row = r.to_dict()
        >>> row["status"], row["final_phase"], row["vbar"]
        ('periodic', 'stick', 0.3)
        """
        row: dict[str, Any] = {"v_inertial": self.v_inertial, "vbar": self.vbar}
        for f in _TABLE_FIELDS:
            v = getattr(self, f.name)
            row[f.name] = v.value if isinstance(v, Status) else v
        row.update({k: v[0] for k, v in state_columns([self.final_state]).items()})
        return row

    def __repr__(self) -> str:
        """A few lines: ``mu_ratio`` with its error, the status, the method, the point."""
        s = self.final_state
        state = "none (static limit)" if s is None else (
            f"{s.phase} at y = {number(s.y)}, x' = {number(s.x_dot)}, f = {number(s.f)}")
        period = f", period {self.period}" if self.status is Status.PERIODIC else ""
        return "\n".join((
            f"FrictionResult: mu_ratio = {self.mu_ratio:.10g} +- {number(self.error)} "
            f"({self.status.value}{period}; {'' if self.trusted else 'not '}trusted), "
            f"method {self.method}",
            f"  at v_inertial = {number(self.v_inertial)} (vbar = {number(self.vbar)}); "
            f"{system_text(self.system)}",
            f"  time in stick {number(self.stick_fraction)}, slip+ {number(self.slip_fraction)},"
            f" slip- {number(self.reverse_slip_fraction)}, flight "
            f"{number(self.flight_fraction)}; {self.events} events in {self.periods} "
            f"period{'' if self.periods == 1 else 's'}",
            f"  final section state: {state}",
            "  .message says how it was obtained; .to_dict() gives it as a row"))


_check_fields(FrictionResult, {f.name: _OBJECT.get(f.name) or _SCALAR[f.kind]
                               for f in RESULT_FIELDS})


@dataclass(frozen=True, repr=False)
class FrictionResults:  # noqa: D101 (the docstring is __doc__ below, as FrictionResult's)
    mu_ratio: NDArray[np.float64]
    status: NDArray[np.object_]
    error: NDArray[np.float64]
    trusted: NDArray[np.bool_]
    period: NDArray[np.int64]
    periods: NDArray[np.int64]
    events: NDArray[np.int64]
    method: NDArray[np.str_]
    work: NDArray[np.float64]
    stick_fraction: NDArray[np.float64]
    slip_fraction: NDArray[np.float64]
    reverse_slip_fraction: NDArray[np.float64]
    flight_fraction: NDArray[np.float64]
    multiplier: NDArray[np.float64]
    settling_periods: NDArray[np.float64]
    window_min: NDArray[np.float64]
    window_max: NDArray[np.float64]
    drift_rate: NDArray[np.float64]
    lateral_ratio: NDArray[np.float64]
    mean_normal_ratio: NDArray[np.float64]
    stick_area_fraction: NDArray[np.float64]
    slip_area_fraction: NDArray[np.float64]
    open_area_fraction: NDArray[np.float64]
    sliding_mu_ratio: NDArray[np.float64]
    final_state: NDArray[np.object_]
    system: Dimensionless
    v_inertial: NDArray[np.float64]
    __doc__ = """Results over an array of velocities.

    The fields of :class:`FrictionResult` as arrays of one shape (``system`` is shared);
    indexing gives one :class:`FrictionResult`, iteration each in turn.
    """

    @property
    def shape(self) -> tuple[int, ...]:
        """The shape of the velocities (and of every array field)."""
        return self.mu_ratio.shape

    def __len__(self) -> int:
        """The length of the first axis."""
        return len(self.mu_ratio)

    def __getitem__(self, index: int | tuple[int, ...]) -> FrictionResult:
        """The :class:`FrictionResult` at ``index``."""
        out = {}
        for f in RESULT_FIELDS:
            v = getattr(self, f.name)
            if f.name != "system":
                v = v[index]
                v = v.item() if isinstance(v, np.generic) else v
            out[f.name] = v
        return _frozen(FrictionResult, out)  # the fields of a result already built

    def __iter__(self) -> Iterator[FrictionResult]:
        """Each point's :class:`FrictionResult`, in C order over every axis."""
        for i in np.ndindex(self.shape):
            yield self[i]

    @property
    def success(self) -> NDArray[np.bool_]:
        """Which statuses are converged, elementwise (:func:`converged`)."""
        return converged(self.status)

    @property
    def vbar(self) -> NDArray[np.float64]:
        """``v0/v0*`` of every point, nan where ``v0*`` is zero or infinite (cases III, IV)."""
        return vbar_of(self.system, self.v_inertial)

    def _dims(self) -> tuple[str, ...]:
        """The names of the points' dimensions: ``point``, or ``point_0``, ``point_1``, ..."""
        n = self.mu_ratio.ndim
        return ("point",) if n == 1 else tuple(f"point_{i}" for i in range(n))

    def _columns(self) -> list[Column]:
        """Every array as a :class:`~vibrofriction.solver.tables.Column`, the schema's attrs."""
        dims = self._dims()
        out = [Column("v_inertial", dims, self.v_inertial, FIELD["v_inertial"].attrs(),
                      coord=True),
               Column("vbar", dims, self.vbar, PARAMETER["vbar"].attrs(), coord=True),
               *system_coords(self.system)]
        for f in _TABLE_FIELDS:
            values = getattr(self, f.name)
            if f.name == "status":
                values = np.vectorize(lambda s: s.value, otypes=[object])(values)
            out.append(Column(f.name, dims, np.asarray(values), f.attrs(),
                              _CATEGORIES.get(f.name, ())))
        flat = state_columns(self.final_state.reshape(-1).tolist())
        for g in STATE_FIELDS:
            name = f"final_{g.name}"
            out.append(Column(name, dims, np.asarray(flat[name]).reshape(self.shape),
                              g.attrs(STATE_PREFIX), _CATEGORIES.get(name, ())))
        return out

    def _attrs(self) -> dict[str, Any]:
        return table_attrs("steady-state results (FrictionResults)", self.system)

    def to_xarray(self) -> xr.Dataset:
        """The results as an :class:`xarray.Dataset`, labelled and described.

        Returns
        -------
        xarray.Dataset
            Dimensions ``point`` (or ``point_0``, ``point_1``, ... for several axes); the
            coordinates ``v_inertial`` and ``vbar`` along them, and the system's
            parameters as scalar coordinates; a data variable per field of
            :data:`~vibrofriction.schema.RESULT_FIELDS` (``status`` and ``method`` as names)
            and the final section state's components as ``final_y``, ..., ``final_phase``.
            Each variable's ``attrs`` hold its ``units``, ``long_name``, ``symbol`` and
            equation from :mod:`vibrofriction.schema`, as a sweep's atlas does.

        Examples
        --------
        >>> import vibrofriction as vf
        >>> rs = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5), vbar=[0.3])
        >>> ds = rs.to_xarray()
        >>> ds.mu_ratio.dims, ds.period.attrs["units"], str(ds.status[0].values)
        (('point',), 'drive periods', 'periodic')
        """
        return dataset(self._columns(), self._attrs())

    def to_dataframe(self) -> pd.DataFrame:
        """The results as a :class:`pandas.DataFrame`, one row per point.

        Returns
        -------
        pandas.DataFrame
            The columns of :meth:`FrictionResult.to_dict` (``status``, ``method`` and
            ``final_phase`` as :class:`pandas.Categorical` of their names); indexed by
            ``point`` (a :class:`pandas.MultiIndex` over ``point_0``, ``point_1``, ... for
            several axes, in C order). ``DataFrame.attrs["units"]`` holds each column's unit
            (:mod:`vibrofriction.schema`); the system's parameters are in ``system``.

        Examples
        --------
        >>> import vibrofriction as vf
        >>> table = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5),
        ...                                 vbar=[0.3]).to_dataframe()
        >>> table.shape, list(table.columns[:4]), str(table.status.dtype)
        ((1, 31), ['v_inertial', 'vbar', 'mu_ratio', 'status'], 'category')
        """
        return dataframe(self._columns(), self._dims(), self._attrs())

    def __repr__(self) -> str:
        """A few lines: the shape, the status counts, the range of trusted ``mu_ratio``."""
        flat_status = [s.value for s in self.status.reshape(-1)]
        counts = Counter(flat_status)
        trusted = self.trusted & np.isfinite(self.mu_ratio)
        mu = self.mu_ratio[trusted]
        span = f"from {mu.min():.6g} to {mu.max():.6g}" if mu.size else "none"
        errors = self.error[np.isfinite(self.error)]
        largest = number(float(np.max(self.error))) if self.error.size else "none"
        if errors.size < self.error.size:
            largest += f" ({self.error.size - errors.size} unbounded)"
        methods = Counter(self.method.reshape(-1).tolist())
        vbar = self.vbar
        vbar_text = f", vbar {number(np.nanmin(vbar))} to {number(np.nanmax(vbar))}" \
            if np.isfinite(vbar).any() else ""
        return "\n".join((
            f"FrictionResults: {self.mu_ratio.size} points, shape {self.shape}; "
            f"{system_text(self.system)}",
            f"  v_inertial {number(np.min(self.v_inertial))} to "
            f"{number(np.max(self.v_inertial))}{vbar_text}",
            "  status: " + ", ".join(f"{s.value} {counts[s.value]}" for s in Status
                                     if counts[s.value]),
            f"  trusted {int(np.sum(self.trusted))} of {self.trusted.size}; mu_ratio of the "
            f"trusted {span}; largest error {largest}",
            "  method: " + ", ".join(f"{m} {n}" for m, n in methods.items()),
            "  one point: [i]; each field an array (.mu_ratio, .status, ...); as a table: "
            ".to_dataframe()"))


_check_fields(FrictionResults, {f.name: "Dimensionless" if f.name == "system" else
                                _ARRAY.get(f.kind, "NDArray[np.object_]")
                                for f in RESULT_FIELDS})


#: The fields of a row of a table (:meth:`FrictionResult.to_dict`), besides the velocities
#: and the final section state's components.
_TABLE_FIELDS = tuple(f for f in RESULT_FIELDS
                      if f.name not in ("final_state", "system", "v_inertial"))
#: The names a categorical column may take, in order.
_CATEGORIES = {"status": tuple(s.value for s in Status), "method": METHOD_NAMES,
               "final_phase": (*_SECTION_PHASES.values(), "none")}


def state_columns(states: Iterable[SectionState | None]) -> dict[str, list[Any]]:
    """The components of section states as ``final_*`` columns (nan, ``"none"``: no state)."""
    out: dict[str, list[Any]] = {f"final_{g.name}": [] for g in STATE_FIELDS}
    for s in states:
        for g in STATE_FIELDS:
            none = "none" if g.name == "phase" else math.nan
            out[f"final_{g.name}"].append(none if s is None else getattr(s, g.name))
    return out


#: Drive periods beyond which the approach to a periodic orbit counts as slow.
SLOW_SETTLING = 1000


def describe(r: FrictionResult) -> str:
    """The message of a result: status, how it was obtained, and its caveats.

    Parameters
    ----------
    r : FrictionResult
        The result.

    Returns
    -------
    str
        One line: the status and what it means, the error estimate, and the caveats
        (slow or neutral settling, and the like) where they apply.
    """
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
    if r.status is Status.SLIDING and math.isnan(r.settling_periods):
        parts.append(
            "the sliding orbit's contact point never stops, which proves the long-time "
            "average from any start; the motion from the initial state was not seen to "
            "stop sticking within 16 periods (no settling time): a measurement over a "
            "finite time can read slightly less than mu0")
    if r.status is Status.PERIODIC and math.isnan(r.settling_periods):
        parts.append(
            f"the orbit is neutrally stable (leading Floquet multiplier {r.multiplier:.9g}): "
            "the motion from the initial state need not approach it, and a transient (e.g. "
            "rare sticks of an undamped free oscillation) can persist for many periods; "
            "the error includes how far the motion's mean over periods 512-1024 is from it")
    if r.status is Status.FAILED and r.system.rs_b > r.system.rs_a > 0.0:
        parts.append(
            "with velocity-weakening rate-and-state friction (rs_b > rs_a) this can be the "
            "slip rate diverging in finite time: the massless contact point slipping "
            "unstably on its own spring (the quasi-static instability of a law without "
            "inertia, docs/friction_laws.md)")
    if r.status in (Status.AVERAGED, Status.NOT_CONVERGED, Status.HELD) \
            and math.isfinite(r.window_min):
        # enough digits to tell the two apart (two beyond the first that differs)
        span = abs(r.window_max - r.window_min) / max(abs(r.window_max), 1e-300)
        digits = min(15, max(6, 2 - math.floor(math.log10(span)))) if span > 0 else 6
        parts.append(f"window means range from {r.window_min:.{digits}g} to "
                     f"{r.window_max:.{digits}g}")
    if r.status is Status.NOT_CONVERGED:
        parts.append(_not_converged_note(r.drift_rate))
    return "; ".join(parts)


def _not_converged_note(drift_rate: float) -> str:
    if math.isfinite(drift_rate) and drift_rate != 0.0:
        how = (f"the window means drift one way ({drift_rate:+.2g} per period): a slow "
               "transient still on its way to a steady state (near beta = 1 such drifts "
               "last 1e4-1e6 periods, docs/modulation.md)")
    else:
        how = "the window means do not move one way"
    return (f"mu_ratio is nan: the motion has not settled and a window mean is not the "
            f"long-time average; {how}: raise max_periods")


# --------------------------------------------------------------------------- from columns
#: Result fields copied from the columns as they are (the rest are built below).
_PLAIN = tuple(f.name for f in RESULT_FIELDS
               if f.name not in ("status", "method", "final_state", "system", "v_inertial"))


def result_from_columns(cols: Mapping[str, Any], system: Dimensionless,
                        v_inertial: float) -> FrictionResult:
    """One point's :class:`FrictionResult` from its named columns.

    Python scalars: the kernels' :data:`~vibrofriction.schema.FLOAT_COLUMNS`, ``INT_COLUMNS`` and
    ``trusted``.
    """
    return FrictionResult(
        status=Status.from_code(cols["status"]), method=METHOD_NAMES[cols["method"]],
        final_state=section_state(*(cols[f.name] for f in STATE_FIELDS)),
        system=system, v_inertial=v_inertial, **{k: cols[k] for k in _PLAIN})


def _column(f: Field) -> tuple[str, int]:
    """A kernel-column field's ``(kind, index)``."""
    assert f.column is not None, f.name
    return f.column


#: The fields built in Python, after the kernels' rows in :func:`result_from_rows`.
_BUILT = ("status", "trusted", "final_state", "system", "v_inertial", "method")
#: Where each result field is in ``floats + ints + [the _BUILT values]``, in field order.
_PICK = operator.itemgetter(*(
    _BUILT.index(f.name) + len(FLOAT_COLUMNS) + len(INT_COLUMNS) if f.name in _BUILT
    else (len(FLOAT_COLUMNS) if _column(f)[0] == "int" else 0) + _column(f)[1]
    for f in RESULT_FIELDS))
_RESULT_NAMES = tuple(f.name for f in RESULT_FIELDS)
_STATE_PICK = operator.itemgetter(*(
    (len(FLOAT_COLUMNS) if _column(f)[0] == "int" else 0) + _column(f)[1] for f in STATE_FIELDS))
_I_STATUS, _I_ERROR, _I_METHOD = (column_index(k) for k in ("status", "error", "method"))


def result_from_rows(floats: list[float], ints: list[int], system: Dimensionless,
                     v_inertial: float, settings: SolverSettings) -> FrictionResult:
    """One point's :class:`FrictionResult` from the kernels' output rows.

    The rows as lists, in the order of :data:`~vibrofriction.schema.FLOAT_COLUMNS` and
    ``INT_COLUMNS``: the same result as :func:`result_from_columns` of their named columns with
    ``trusted`` from ``settings``, built without a dictionary of columns or the dataclass's checks.
    """
    status = Status.from_code(ints[_I_STATUS])
    row: list[Any] = [*floats, *ints]
    row += (status, settings.trusted_one(status, floats[_I_ERROR]),
            section_state(*_STATE_PICK(row)), system, v_inertial, METHOD_NAMES[ints[_I_METHOD]])
    return _frozen(FrictionResult, dict(zip(_RESULT_NAMES, _PICK(row), strict=True)))


def results_from_columns(cols: Mapping[str, NDArray], system: Dimensionless,
                         v_inertial: NDArray[np.float64]) -> FrictionResults:
    """:class:`FrictionResults` from the named column arrays of :func:`solve_points`."""
    shape = v_inertial.shape
    status = np.empty(shape, dtype=object)
    states = np.empty(shape, dtype=object)
    # C order, as np.ndindex: point by point over Python scalars, not numpy ones
    status.ravel()[:] = [Status.from_code(c) for c in np.ravel(cols["status"]).tolist()]
    states.ravel()[:] = list(map(section_state, *(np.ravel(cols[f.name]).tolist()
                                                  for f in STATE_FIELDS)))
    method = np.asarray(METHOD_NAMES)[np.asarray(cols["method"])].reshape(shape)
    return FrictionResults(status=status, method=method, final_state=states, system=system,
                           v_inertial=v_inertial.astype(float), **{k: cols[k] for k in _PLAIN})
