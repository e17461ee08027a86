"""The time histories :func:`vibrofriction.simulate` returns: a common part and one per solver.

:class:`History` holds what every history has (the 1-D solver's history is one);
:class:`PlaneHistory` adds the transverse components of the 2-D solver (``a_y > 0``),
:class:`CurvedHistory` the spring row of a curved tip (the method of dimensionality
reduction), :class:`RateStateHistory` the state and the local coefficient of rate-and-state
friction.  Each field is filled by the solver that returns the class.  This module
imports neither :mod:`.history` nor :mod:`.mdr_history`: both build on it.
"""

from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass, field, fields
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..params import Dimensionless, Physical
from ..schema import (
    CONTACT_STATE_NAMES,
    FIELD,
    HISTORY_FIELD,
    PARAMETER,
    PARTIAL,
    STATE_FIELDS,
    STATE_PREFIX,
)
from . import tables
from .energy import inplane_motion, transverse_motion
from .results import SectionState, state_columns
from .tables import Column, number

if TYPE_CHECKING:
    import pandas as pd
    import xarray as xr

__all__ = ["CurvedHistory", "Event", "History", "PlaneHistory", "RateStateHistory"]


@dataclass(frozen=True)
class Event:
    """A transition at drive time ``tau``.

    ``kind`` and the states before and after (names of
    :class:`~vibrofriction.schema.ContactState`).
    """

    tau: float
    kind: str
    before: str
    after: str


#: The fields of a history that are not sampled arrays (the events, the point, the state).
_NOT_SAMPLED = ("events", "system", "v_inertial", "final_state")
#: The names of a pair's components, and of :attr:`PlaneHistory.plane_state`'s.
_XY = ("x", "y")
_PLANE_STATE = ("y_x", "y_y", "v_x", "v_y", "e_x", "e_y")
#: The names a categorical column of a history may take, in order.
_HISTORY_CATEGORIES = {"phase": (*CONTACT_STATE_NAMES, PARTIAL),
                       "spring_state": CONTACT_STATE_NAMES,
                       "event_before": CONTACT_STATE_NAMES, "event_after": CONTACT_STATE_NAMES}


def _dims(name: str, values: np.ndarray) -> tuple[str, ...]:
    """The dimensions of a history's array ``name`` (by its name and shape)."""
    if name == "xi":
        return ("spring",)
    if name == "plane_state":
        return ("plane_component",)
    return ("sample", "spring" if name.startswith("spring_") else "component")[:values.ndim]


@dataclass(frozen=True, repr=False)
class History:
    """A time history sampled from the closed forms (Fig. 2).

    All quantities are scaled (docs/model.md): ``tau = omega t``; ``x`` body position and
    ``x_dot`` its velocity (units ``mu0 F_N0/(m omega^2)`` and ``mu0 F_N0/(m omega)``);
    ``f`` the tangential contact force and ``n`` the ``mu0``-scaled normal force, both
    in units of ``mu0 F_N0``; ``phase`` the state of the contact at each sample (a name
    of :class:`~vibrofriction.schema.ContactState`: ``"stick"``, ``"slip+"``,
    ``"slip-"``, ``"flight"``); ``events`` every transition with its exact time.  Sample
    times include every event time (on both sides), so phase boundaries are sharp.
    ``e`` is the elongation of the contact spring; ``work_input`` the work done by the
    pulled end since the start and ``dissipated_pin``, ``dissipated_contact``,
    ``dissipated_friction`` the energy dissipated by the pin dashpot, the contact dashpot
    and friction (unit ``(mu0 F_N0)^2/(m omega^2)``; Gauss-Legendre quadrature of the
    closed forms, relative accuracy ~1e-10), so that ``work_input - sum(dissipated) =
    stored_energy() - stored_energy()[0]`` (docs/damping.md).  With a longitudinal
    in-plane oscillation (docs/inplane.md) ``x``, ``x_dot`` are in the laboratory frame
    and ``work_input`` includes the work of the oscillating substrate on the contact (or
    is that of the oscillating holder).  ``final_state`` is the state on the last
    Poincare section within the history, ``tau = 2 pi floor(periods)`` (the start for
    less than a period); None only for a curved tip (:class:`CurvedHistory`, whose state
    is its springs').

    The 1-D solver returns this class; the 2-D solver a :class:`PlaneHistory`, a curved
    tip a :class:`CurvedHistory`, rate-and-state friction a :class:`RateStateHistory`, each
    with the fields of its solver.
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

    @property
    def is_curved(self) -> bool:
        """Whether this is a curved tip's history (a :class:`CurvedHistory`)."""
        return isinstance(self, CurvedHistory)

    @property
    def is_rate_state(self) -> bool:
        """Whether this is a rate-and-state history (a :class:`RateStateHistory`)."""
        return isinstance(self, RateStateHistory)

    @property
    def is_plane(self) -> bool:
        """Whether this is a 2-D history (a :class:`PlaneHistory`)."""
        return isinstance(self, PlaneHistory)

    def _pin_energy(self) -> NDArray[np.float64]:
        """The pin's energy ``x'^2/2 + alpha (V tau - x)^2/2``.

        With an oscillating holder the pin's spring is stretched by ``V tau + X - x``.
        """
        d = self.system
        y = self.x - self.v_inertial * self.tau
        if d.a_x > 0.0 and d.inplane_on == "holder":
            y = y - inplane_motion(d, self.tau)[0]
        return 0.5 * self.x_dot**2 + 0.5 * d.alpha * y**2

    def stored_energy(self) -> NDArray[np.float64]:
        """Kinetic and elastic energy ``x'^2/2 + alpha (V tau - x)^2/2 + k e^2/2``.

        With an oscillating holder the pin's spring is stretched by ``V tau + X - x``; in 2-D the
        transverse terms are added, the pin's spring across ``alpha_y``; a curved tip's row has
        ``sum f_i^2/(2 k_i)``, ``k_i = (beta - alpha) dxi``, for ``k e^2/2``.
        """
        d = self.system
        out = self._pin_energy()
        if not d.is_rigid:
            out = out + 0.5 * (d.beta - d.alpha) * self.e**2
        return out

    def contact_point(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """The contact point's position relative to the substrate, ``(x_c, y_c)``.

        The body's minus the contact spring's elongation minus the substrate's in-plane
        displacement (none where the holder oscillates); ``y_c`` is 0 but in 2-D. ``x_c``
        advances by ``V`` per unit ``tau`` on average (the body slides over the substrate):
        ``x_c - V tau`` is periodic in a periodic steady state.
        """
        d = self.system
        xc = self.x - self.e
        if d.inplane_on == "substrate" and d.a_x > 0.0:
            xc = xc - inplane_motion(d, self.tau)[0]
        return xc, np.zeros_like(xc)

    def time(self, physical: Physical) -> NDArray[np.float64]:
        """Sample times in seconds for a physical system (``t = tau/omega``)."""
        return self.tau / physical.omega

    def _kind(self) -> str:
        """Which solver's history this is, in words."""
        return "the 1-D solver"

    def _columns(self) -> list[Column]:
        """Every array as a :class:`~vibrofriction.solver.tables.Column`, the schema's attrs."""
        out = [Column("v_inertial", (), np.asarray(self.v_inertial),
                      FIELD["v_inertial"].attrs(), coord=True),
               Column("vbar", (), tables.vbar_of(self.system, np.asarray(self.v_inertial)),
                      PARAMETER["vbar"].attrs(), coord=True),
               *tables.system_coords(self.system)]
        for f in fields(self):
            if f.name in _NOT_SAMPLED:
                continue
            values = np.asarray(getattr(self, f.name))
            if f.name == "spring_state":
                values = np.asarray(CONTACT_STATE_NAMES)[values]
            out.append(Column(f.name, _dims(f.name, values), values,
                              HISTORY_FIELD[f.name].attrs(),
                              _HISTORY_CATEGORIES.get(f.name, ()), f.name in ("tau", "xi")))
        dims = {d for c in out for d in c.dims}
        if "component" in dims:
            out.append(Column("component", ("component",), np.asarray(_XY),
                              {"long_name": "component in the plane: x along the sliding, "
                               "y across"}, coord=True))
        if "plane_component" in dims:
            out.append(Column("plane_component", ("plane_component",),
                              np.asarray(_PLANE_STATE), {"long_name": "component of the "
                              "2-D section state"}, coord=True))
        events = {"event_tau": [e.tau for e in self.events],
                  "event_kind": [e.kind for e in self.events],
                  "event_before": [e.before for e in self.events],
                  "event_after": [e.after for e in self.events]}
        out += [Column(k, ("event",), np.asarray(v, dtype=float if k == "event_tau" else str),
                       HISTORY_FIELD[k].attrs(), _HISTORY_CATEGORIES.get(k, ()))
                for k, v in events.items() if self.events]  # a curved tip's: none
        if self.final_state is not None:
            out += [Column(f"final_{g.name}", (), np.asarray(v[0]), g.attrs(STATE_PREFIX))
                    for g, v in zip(STATE_FIELDS,
                                    state_columns([self.final_state]).values(), strict=True)]
        return out

    def _attrs(self) -> dict[str, Any]:
        return tables.table_attrs(f"time history ({type(self).__name__}, {self._kind()})",
                           self.system)

    def to_xarray(self) -> xr.Dataset:
        """The history as an :class:`xarray.Dataset`, labelled and described.

        Returns
        -------
        xarray.Dataset
            Dimension ``sample`` (``tau`` its coordinate), ``component`` (``x``, ``y``: of
            ``slip_velocity`` and ``impulse``), ``spring`` (a curved tip's row: ``xi`` its
            coordinate), ``plane_component`` (``plane_state``) and ``event`` (``event_tau``,
            ``event_kind``, ``event_before``, ``event_after``); the velocity and the system's
            parameters as scalar coordinates; the final section state as ``final_y``, ...
            Each variable's ``attrs`` hold its ``units`` and ``long_name`` from
            :data:`vibrofriction.schema.HISTORY_FIELDS`; states are names, not codes.

        Examples
        --------
        >>> import vibrofriction as vf
        >>> h = vf.simulate(vf.Dimensionless(0.5, 2.0, 0.5), vbar=0.3, periods=1)
        >>> ds = h.to_xarray()
        >>> ds.x.dims, ds.x.attrs["units"], str(ds.phase.values[0])
        (('sample',), 'mu0 F_N0 / (m omega^2)', 'stick')
        """
        return tables.dataset(self._columns(), self._attrs())

    def to_dataframe(self) -> pd.DataFrame:
        """The sampled arrays as a :class:`pandas.DataFrame`, one row per sample.

        Returns
        -------
        pandas.DataFrame
            Indexed by ``sample``; a column per array with one value per sample (``tau``
            first; ``phase`` a :class:`pandas.Categorical` of the states' names), and the
            components of ``slip_velocity`` and ``impulse`` as ``slip_velocity_x``, ...
            A curved tip's per-spring arrays, the events and the final state are in
            :meth:`to_xarray`. ``DataFrame.attrs["units"]`` holds each column's unit.

        Examples
        --------
        >>> import vibrofriction as vf
        >>> h = vf.simulate(vf.Dimensionless(0.5, 2.0, 0.5), vbar=0.3, periods=1)
        >>> df = h.to_dataframe()
        >>> len(df) == h.tau.size, list(df.columns[:3]), df.attrs["units"]["f"]
        (True, ['tau', 'x', 'x_dot'], 'mu0 F_N0')
        """
        per_sample = []
        for c in self._columns():
            if c.dims == ("sample", "component"):
                per_sample += [Column(f"{c.name}_{xy}", ("sample",), c.values[:, i],
                                      {**c.attrs, "long_name": f"{xy} component: "
                                       f"{c.attrs['long_name']}"})
                               for i, xy in enumerate(_XY)]
            else:
                per_sample.append(c)
        return tables.dataframe(per_sample, ("sample",), self._attrs())

    def __repr__(self) -> str:
        """A few lines: the span in drive periods, the samples, the events, the columns."""
        span = float(self.tau[-1] - self.tau[0]) if self.tau.size else 0.0
        names = [f.name for f in fields(self) if f.name not in _NOT_SAMPLED]
        periods = span / (2.0 * math.pi)
        head = (f"{type(self).__name__} ({self._kind()}): tau {number(float(self.tau[0]))} "
                f"to {number(float(self.tau[-1]))} ({number(periods)} drive "
                f"period{'' if periods == 1.0 else 's'}), {self.tau.size} samples, "
                f"{len(self.events)} events")
        vbar = float(tables.vbar_of(self.system, np.asarray(self.v_inertial)))
        wrap = textwrap.TextWrapper(100, initial_indent="  ", subsequent_indent="    ").wrap
        return "\n".join((
            *textwrap.wrap(head, 100, subsequent_indent="    "),
            *wrap(f"at v_inertial = {number(self.v_inertial)} (vbar = {number(vbar)}); "
                  f"{tables.system_text(self.system)}"),
            *wrap("arrays: " + ", ".join(names)),
            "  as a table: .to_dataframe(), .to_xarray()"))


@dataclass(frozen=True, kw_only=True, repr=False)
class PlaneHistory(History):
    """A history with a transverse oscillation (``a_y > 0``, the 2-D solver).

    :class:`History` and the transverse components (docs/inplane.md section 6).

    ``u_y`` and ``u_y_dot`` the body's transverse position and velocity, ``f_y`` the
    transverse contact force, ``e_y`` the transverse elongation, ``slip_velocity`` (shape
    ``(N, 2)``) the contact point's velocity relative to the substrate (0 in stick: in
    slip its direction is the slip's, and ``(f, f_y)`` is parallel to it), ``impulse``
    (shape ``(N, 2)``) the integrals of ``(f, f_y)`` since ``tau = 0`` (to the
    integrator's tolerance), and ``plane_state`` the 6 components ``(y_x, y_y, v_x, v_y,
    e_x, e_y)`` of the state at ``tau = 2 pi floor(periods)`` (a start for another 2-D
    history; ``final_state`` keeps its x components).  There ``phase`` is ``"slip+"`` or
    ``"slip-"`` by the sign of ``f`` (as the 2-D solver's ``slip_fraction``), and the
    energies are the trapezoidal rule over the samples (second order in the sample
    spacing, not the 1-D histories' 1e-10).
    """

    u_y: NDArray[np.float64]
    u_y_dot: NDArray[np.float64]
    f_y: NDArray[np.float64]
    e_y: NDArray[np.float64]
    slip_velocity: NDArray[np.float64]
    impulse: NDArray[np.float64]
    plane_state: NDArray[np.float64]

    def _kind(self) -> str:
        return "the 2-D solver"

    def stored_energy(self) -> NDArray[np.float64]:
        """:meth:`History.stored_energy` with the transverse terms (pin across ``alpha_y``)."""
        d = self.system
        yy = self.u_y - (transverse_motion(d, self.tau)[0]
                         if d.inplane_on == "holder" else 0.0)
        out = super().stored_energy() + 0.5 * self.u_y_dot**2 + 0.5 * d.pin_y[0] * yy**2
        return out + 0.5 * (d.beta - d.alpha) * self.e_y**2

    def contact_point(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """:meth:`History.contact_point` with the transverse component ``y_c``."""
        xc, _ = super().contact_point()
        yc = self.u_y - self.e_y
        if self.system.inplane_on == "substrate":
            yc = yc - transverse_motion(self.system, self.tau)[0]
        return xc, yc


@dataclass(frozen=True, kw_only=True, repr=False)
class CurvedHistory(History):
    """A curved tip's history (finite ``profile_exponent``: the MDR row of ``M`` springs).

    :class:`History` and the contact fields (docs/contact_geometry.md "The history").

    ``f = sum f_i`` and ``n = sum n_i`` (units ``mu0 F_N0``: ``n`` is ``F_N/F_N0``), ``e
    = f/(beta - alpha)`` (the springs' elongation weighted by stiffness; the flat punch's
    ``e``), ``phase`` ``"stick"``, ``"slip+"``, ``"slip-"`` where every spring in contact
    is in that state, ``"flight"`` where none is in contact, else ``"partial"``
    (:data:`~vibrofriction.schema.PARTIAL`), no ``events`` (the springs' states hold
    them), no ``final_state``, ``dissipated_contact`` 0, and: ``impulse`` ``(int f, 0)``
    (exact, shape ``(N, 2)``), ``xi`` (shape ``(M,)``) the springs' positions along the
    profile (cell midpoints, unit ``a0``, the contact radius at the mean indentation),
    ``spring_state`` (``(N, M)``, int8) each spring's state at each sample (the codes of
    :class:`~vibrofriction.schema.ContactState`: 0 stick, 1 slip forwards, 2 slip
    backwards, 3 flight, out of contact), ``spring_f`` (``(N, M)``) each spring's
    tangential force (``|f_i| <= n_i``, :meth:`spring_normal`), ``stick_radius``
    (``(N,)``) the position of the outermost stuck spring (0 if none),
    ``contact_radius`` (``(N,)``) the imposed indentation's ``max(0, 1 + a cos
    tau)^(1/n)``, ``stick_area_fraction``, ``slip_area_fraction``,
    ``open_area_fraction`` (``(N,)``) the shares of the disc of the largest contact radius
    (area-weighted as the steady state's), and ``normal_impulse`` (``(N,)``) the exact
    integral of ``n`` since ``tau = 0``.
    """

    impulse: NDArray[np.float64]
    xi: NDArray[np.float64]
    spring_state: NDArray[np.int8]
    spring_f: NDArray[np.float64]
    stick_radius: NDArray[np.float64]
    contact_radius: NDArray[np.float64]
    stick_area_fraction: NDArray[np.float64]
    slip_area_fraction: NDArray[np.float64]
    open_area_fraction: NDArray[np.float64]
    normal_impulse: NDArray[np.float64]

    def _kind(self) -> str:
        return f"a curved tip: a row of {self.xi.size} springs"

    def spring_normal(self) -> NDArray[np.float64]:
        """Each spring's normal force ``n_i = w max(0, 1 + a cos tau - xi_i^n)``.

        ``w = dxi (n + 1)/n`` (the flat punch's ``dxi``); shape ``(N, M)``, unit ``mu0 F_N0``.
        """
        n_exp = self.system.profile_exponent
        dxi = 2.0 * float(self.xi[0])
        flat = math.isinf(n_exp)
        w = dxi if flat else dxi * (n_exp + 1.0) / n_exp
        g = np.zeros_like(self.xi) if flat else self.xi ** n_exp
        depth = 1.0 + self.system.amplitude * np.cos(self.tau)
        return w * np.maximum(0.0, depth[:, None] - g[None, :])

    def stored_energy(self) -> NDArray[np.float64]:
        """:meth:`History.stored_energy` with the row's springs, ``sum f_i^2/(2 k_i)``."""
        d = self.system
        k = (d.beta - d.alpha) * 2.0 * float(self.xi[0])  # the row: sum f_i^2/(2 k dxi)
        return self._pin_energy() + 0.5 * np.sum(self.spring_f**2, axis=1) / k


@dataclass(frozen=True, kw_only=True, repr=False)
class RateStateHistory(History):
    """A history with rate-and-state friction (``rs_a > 0``, the rate-and-state solver).

    :class:`History` and the friction law's fields (docs/friction_laws.md, "Time
    histories").  Integrated by the solver's Rosenbrock method (RODAS4, error control at
    ``settings.rtol``), each step ending at the next sample time where it would pass it:
    every sample is an integrated state, to the integrator's tolerance, not an interpolation.

    ``theta`` the state variable (a time, unit ``1/omega``: ``theta/omega`` in seconds for a
    :class:`~vibrofriction.Physical` system); ``local_mu`` the local coefficient ``f/n`` as a
    fraction of ``mu_star`` (``mu0``: ``f`` and ``n`` are in ``mu_star F_N0``), nan in flight;
    ``slip_velocity`` (shape ``(N, 2)``, the y component 0) the slip velocity ``w'`` of the
    contact point relative to the substrate, nan in flight; ``impulse`` (shape ``(N, 2)``)
    ``(int f, 0)`` since ``tau = 0`` (the integrator's quadrature).  The contact always slips:
    ``phase`` is ``"slip+"`` or ``"slip-"`` by the sign of ``w'``, ``"flight"`` out of
    contact; ``events`` are the lift-offs and touch-downs, at the phases where the
    integrator cuts the contact (``n = 1e-9``, within ``1e-9/|n'|`` of ``cos tau =
    -1/amplitude``), each on both sides.  ``dissipated_friction`` is ``int f w'`` and, without
    an in-plane oscillation, ``dissipated_pin`` and ``work_input`` are the integrator's
    quadratures too (``work_input = V (x' - x'(0) + int f)``, from the body's equation of
    motion), exact to the tolerance; with one (``a_x > 0``) the pin's dissipation and the
    work are the trapezoidal rule over the samples (second order in the sample spacing).
    ``dissipated_contact`` is 0 (the contact is elastic).
    """

    theta: NDArray[np.float64]
    local_mu: NDArray[np.float64]
    slip_velocity: NDArray[np.float64]
    impulse: NDArray[np.float64]

    def _kind(self) -> str:
        return "the rate-and-state solver"
