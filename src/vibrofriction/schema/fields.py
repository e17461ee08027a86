"""The quantities a steady-state result holds, its statuses and the contact states.

See :mod:`vibrofriction.schema`; standard library only.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

__all__ = ["CONTACT_STATE_NAMES", "CONVERGED_CODES", "ContactState", "ENERGY_UNIT", "FIELD",
           "FIELDS", "FLOAT_COLUMNS", "FORCE_UNIT", "Field", "INT_COLUMNS", "LENGTH_UNIT",
           "NO_STATE", "PARTIAL", "RESULT_FIELDS", "STATE_FIELDS", "STATE_PREFIX", "STATUS_BY_CODE",
           "Status", "VELOCITY_UNIT", "cf_attrs", "column_index"]

#: Units of the scaled variables (docs/model.md).
VELOCITY_UNIT = "mu0 F_N0 / (m omega)"
LENGTH_UNIT = "mu0 F_N0 / (m omega^2)"
FORCE_UNIT = "mu0 F_N0"
ENERGY_UNIT = "(mu0 F_N0)^2 / (m omega^2)"


@dataclass(frozen=True)
class Field:
    """One quantity of a steady-state result.

    Parameters
    ----------
    name : str
        The field's name.
    kind : str
        Its Python type in a :class:`~vibrofriction.FrictionResult`: ``"float"``,
        ``"int"``, ``"bool"`` or ``"object"``.
    unit : str
        UDUNITS-style (``"1"``: dimensionless).
    long_name : str
        What it is, in words.
    equation : str, optional
        The paper's equation that defines it, if any.
    symbol : str, optional
        Its symbol in the paper.
    column : tuple of (str, int) or None, optional
        Its place ``("float" | "int", index)`` in the kernels' output rows (None:
        computed in Python).
    role : str, optional
        ``"result"`` (a field of ``FrictionResult``), ``"state"`` (a component of its
        ``final_state``) or ``"kernel"`` (bookkeeping of the kernels only).
    dtype : str, optional
        The numpy dtype an atlas stores it in.

    Examples
    --------
    >>> from vibrofriction.schema import FIELD
    >>> field = FIELD["mu_ratio"]
    >>> field.kind, field.unit, field.column
    ('float', '1', ('float', 0))
    >>> field.long_name
    'macroscopic coefficient of friction over the local one in the steady state, <F_x>/(mu0 <F_N>)'
    """

    name: str
    kind: str
    unit: str
    long_name: str
    equation: str = ""
    symbol: str = ""
    column: tuple[str, int] | None = None
    role: str = "result"
    dtype: str = ""

    def attrs(self, prefix: str = "") -> dict[str, str]:
        """The field's CF-style attributes, as an xarray variable carries them.

        Parameters
        ----------
        prefix : str, optional
            Words put before the long name (``"final state ...: "``).

        Returns
        -------
        dict of str to str
            ``long_name``, ``symbol``, ``units`` and, where the field has one, ``equation``.

        Examples
        --------
        >>> from vibrofriction.schema import FIELD
        >>> FIELD["period"].attrs()["units"]
        'drive periods'
        """
        return cf_attrs(prefix + self.long_name, self.symbol, self.unit, self.equation)


def cf_attrs(long_name: str, symbol: str, unit: str, equation: str = "") -> dict[str, str]:
    """CF-style attributes of a quantity: its long name, symbol, units and equation.

    The one place where the schema's descriptions become the attributes of a labelled array
    (a sweep's atlas, a result's or a history's ``to_xarray()``); ``equation`` only where
    given.

    Examples
    --------
    >>> from vibrofriction.schema import cf_attrs
    >>> cf_attrs("drive time", "tau", "1")
    {'long_name': 'drive time', 'symbol': 'tau', 'units': '1'}
    """
    attrs = {"long_name": long_name, "symbol": symbol, "units": unit}
    if equation:
        attrs["equation"] = equation
    return attrs


# --------------------------------------------------------------------------- contact states
class ContactState(enum.IntEnum):
    """The state of a contact.

    Of the single contact point (the flat punch, in 1-D and 2-D) or of one spring of a
    curved tip's row (the method of dimensionality reduction).
    The value is the kernels' code (stored in atlases and CSVs as the result's ``phase``,
    and in ``CurvedHistory.spring_state``); :attr:`label` the name of the state
    (``History.phase``, ``SectionState.phase``, :class:`~vibrofriction.Event`) and
    :attr:`long_name` the words of figure legends.  ``FLIGHT`` is out of contact: the
    point jumps, or a spring of the row is off the substrate.
    """

    STICK = 0  # the contact point moves with the substrate
    SLIP_POS = 1  # it slides forwards, in +x (the drive's direction): f = +mu0 F_N
    SLIP_NEG = 2  # it slides backwards, in -x: f = -mu0 F_N
    FLIGHT = 3  # out of contact: no force

    @property
    def label(self) -> str:
        """The state's name: ``"stick"``, ``"slip+"``, ``"slip-"``, ``"flight"``."""
        return CONTACT_STATE_NAMES[self.value]

    @property
    def long_name(self) -> str:
        """Words for a legend.

        ``"stick"``, ``"forward slip"``, ``"reverse slip"`` or ``"flight"``.
        """
        return _STATE_LONG_NAMES[self.value]

    @classmethod
    def from_label(cls, name: str) -> ContactState:
        """The member named ``name`` (:attr:`label`); ValueError for an unknown name."""
        try:
            return cls(CONTACT_STATE_NAMES.index(name))
        except ValueError:
            raise ValueError(f"unknown contact state {name!r}; known: "
                             f"{list(CONTACT_STATE_NAMES)}") from None


#: The names of the contact states, by code (:attr:`ContactState.label`).
CONTACT_STATE_NAMES: tuple[str, ...] = ("stick", "slip+", "slip-", "flight")
_STATE_LONG_NAMES = ("stick", "forward slip", "reverse slip", "flight")
#: The code of no state: a static point has no section state, and a kernel's entry into
#: a phase with no phase to avoid.
NO_STATE = -1
#: The name of a curved tip's contact whose springs in contact are not all in one state
#: (stick and slip at once: partial slip), in ``CurvedHistory.phase``; never a code.
PARTIAL = "partial"
if [m.label for m in ContactState] != list(CONTACT_STATE_NAMES) or len(_STATE_LONG_NAMES) != \
        len(CONTACT_STATE_NAMES) or [m.value for m in ContactState] != \
        list(range(len(ContactState))):
    raise AssertionError("ContactState: codes 0..n-1, one name and one long name each")


def _fraction(state: ContactState, index: int) -> Field:
    name = {ContactState.STICK: "stick_fraction", ContactState.SLIP_POS: "slip_fraction",
            ContactState.SLIP_NEG: "reverse_slip_fraction",
            ContactState.FLIGHT: "flight_fraction"}[state]
    return Field(name, "float", "1", f"fraction of time in {state.long_name} (averaging "
                 "window)", column=("float", index), dtype="f8")


#: Every quantity, in the order of :class:`~vibrofriction.FrictionResult` (results
#: first, then the components of the final section state, then kernel bookkeeping).
FIELDS: tuple[Field, ...] = (
    Field("mu_ratio", "float", "1", "macroscopic coefficient of friction over the local "
          "one in the steady state, <F_x>/(mu0 <F_N>)", "(25)", "mu_macro / mu0",
          ("float", 0), dtype="f8"),
    Field("status", "object", "1", "how the steady state was obtained (Status; the kernels "
          "return its code)", column=("int", 0), dtype="i1"),
    Field("error", "float", "1", "estimated absolute error of mu_ratio, |mu_ratio - exact| "
          "(inf: nothing is known)", "docs/solver.md", column=("float", 1), dtype="f8"),
    Field("trusted", "bool", "1", "the result is trusted: converged status and error <= "
          "tol_trusted (SolverSettings)", dtype="bool"),
    Field("period", "int", "drive periods", "period of the steady orbit (0 = not periodic)",
          column=("int", 1), dtype="i4"),
    Field("periods", "int", "drive periods", "drive periods integrated", column=("int", 2),
          dtype="i4"),
    Field("events", "int", "1", "phase transitions integrated (stick, slip, lift-off, "
          "touchdown)", column=("int", 3), dtype="i8"),
    Field("method", "str", "1", "the solver that computed the result (METHOD_NAMES: "
          "'event' the 1-D event-driven solver, 'plane' the 2-D solver, 'mdr' the curved "
          "tip's solver, 'rate_state' the rate-and-state solver; the kernels' rows hold its "
          "index)", column=("int", 6), dtype="i1"),
    Field("work", "float", "drive periods", "drive periods integrated in all, Newton's period "
          "maps, verification and averaging included", column=("float", 15), dtype="f8"),
    _fraction(ContactState.STICK, 2),
    _fraction(ContactState.SLIP_POS, 3),
    _fraction(ContactState.SLIP_NEG, 4),
    _fraction(ContactState.FLIGHT, 5),
    Field("multiplier", "float", "1", "modulus of the leading Floquet multiplier of the "
          "periodic orbit (contraction per orbit period; nan if not periodic)",
          symbol="|lambda|", column=("float", 9), dtype="f8"),
    Field("settling_periods", "float", "drive periods", "drive periods the motion from the "
          "initial state needs to come within error of the steady state",
          column=("float", 10), dtype="f8"),
    Field("window_min", "float", "1", "smallest mean of mu_ratio over the averaging windows "
          "(averaged and not converged results; nan otherwise)", column=("float", 11),
          dtype="f8"),
    Field("window_max", "float", "1", "largest mean of mu_ratio over the averaging windows "
          "(averaged and not converged results; nan otherwise)", column=("float", 12),
          dtype="f8"),
    Field("drift_rate", "float", "1 / drive period", "change of the averaging windows' means "
          "per drive period where the last three move one way (0 where they do not; nan "
          "with fewer windows)", column=("float", 13), dtype="f8"),
    Field("lateral_ratio", "float", "1", "mean transverse force over the mean normal one, "
          "<F_y>/(mu0 <F_N>) (0 without a transverse oscillation, a_y = 0)",
          "docs/inplane.md", "<F_y> / (mu0 <F_N>)", ("float", 16), dtype="f8"),
    Field("mean_normal_ratio", "float", "1", "mean normal force over the cycle over the "
          "normal force at the mean indentation, <F_N>/F_N0 (the closed form of the imposed "
          "indentation: 1 for a flat punch without jumping)", "docs/contact_geometry.md",
          "<F_N> / F_N0", ("float", 17), dtype="f8"),
    Field("stick_area_fraction", "float", "1", "time-averaged fraction of the contact disc "
          "(of the largest contact radius of the cycle; the flat punch's face) in stick "
          "(the flat punch: stick_fraction)", "docs/contact_geometry.md",
          column=("float", 18), dtype="f8"),
    Field("slip_area_fraction", "float", "1", "time-averaged fraction of the contact disc "
          "in slip, either way (the flat punch: slip_fraction + reverse_slip_fraction)",
          "docs/contact_geometry.md", column=("float", 19), dtype="f8"),
    Field("open_area_fraction", "float", "1", "time-averaged fraction of the contact disc "
          "out of contact (the flat punch: flight_fraction)", "docs/contact_geometry.md",
          column=("float", 20), dtype="f8"),
    Field("sliding_mu_ratio", "float", "1", "the coefficient of steady sliding at the same "
          "velocity without oscillation over the local one, mu_ss(v0)/mu0 (1 for Coulomb "
          "friction; rate-and-state friction: docs/friction_laws.md), so that the reduction "
          "by the oscillation is mu_ratio/sliding_mu_ratio", "docs/friction_laws.md",
          "mu_ss(v0) / mu0", ("float", 21), dtype="f8"),
    Field("final_state", "object", "", "the last state on the Poincare section tau = 2 pi k "
          "(SectionState: y, x_dot, f, phase, e; None for the static limit)"),
    Field("system", "object", "", "the dimensionless system (Dimensionless: the parameters "
          "of the dimensionless model, PARAMETERS)", "(20), (24)"),
    Field("v_inertial", "float", VELOCITY_UNIT, "inertial sliding velocity, "
          "v0 m omega / (mu0 F_N0)", "Fig. 6", "v0 m omega / (mu0 F_N0)", dtype="f8"),
    # the final section state, in the order of SectionState
    Field("y", "float", LENGTH_UNIT, "body displacement without the drift, y = x - V tau",
          symbol="y", column=("float", 6), role="state", dtype="f8"),
    Field("x_dot", "float", VELOCITY_UNIT, "body velocity", symbol="x'",
          column=("float", 7), role="state", dtype="f8"),
    Field("f", "float", FORCE_UNIT, "tangential contact force", symbol="f",
          column=("float", 8), role="state", dtype="f8"),
    Field("phase", "int", "1", "state of the contact (ContactState: stick 0, slip+ 1, "
          "slip- 2, flight 3; -1: no state)", column=("int", 4), role="state", dtype="i1"),
    Field("e", "float", LENGTH_UNIT, "elongation of the contact spring, x - x_c (0 for a "
          "rigid contact)", symbol="e", column=("float", 14), role="state", dtype="f8"),
    Field("degenerate", "int", "1", "transitions decided only within round-off (chatter "
          "along a tangency of the friction cone)", column=("int", 5), role="kernel",
          dtype="i8"),
)

#: Every field by name.
FIELD: dict[str, Field] = {f.name: f for f in FIELDS}
RESULT_FIELDS: tuple[Field, ...] = tuple(f for f in FIELDS if f.role == "result")
STATE_FIELDS: tuple[Field, ...] = tuple(f for f in FIELDS if f.role == "state")
#: The words before the long name of a component of the final section state stored on its
#: own (``final_y``, ``final_x_dot``, ...: a sweep's atlas, ``FrictionResults.to_xarray()``).
STATE_PREFIX = "final state on the Poincare section tau = 2 pi k: "


def _columns(kind: str) -> tuple[str, ...]:
    cols = sorted((f.column[1], f.name) for f in FIELDS if f.column and f.column[0] == kind)
    if [i for i, _ in cols] != list(range(len(cols))):
        raise AssertionError(f"the {kind} kernel columns are not 0..n-1: {cols}")
    return tuple(name for _, name in cols)


#: The kernels' output rows, in order (``solve_points`` returns these and ``trusted``).
FLOAT_COLUMNS: tuple[str, ...] = _columns("float")
INT_COLUMNS: tuple[str, ...] = _columns("int")


def column_index(name: str) -> int:
    """The index of ``name`` in its kernel output row.

    Parameters
    ----------
    name : str
        A field of :data:`FIELD` that the kernels return.

    Returns
    -------
    int
        Its index in :data:`FLOAT_COLUMNS` or :data:`INT_COLUMNS`.

    Raises
    ------
    KeyError
        If ``name`` is no field, or is computed in Python (no kernel column).

    Examples
    --------
    >>> from vibrofriction.schema import FLOAT_COLUMNS, column_index
    >>> column_index("mu_ratio")
    0
    >>> FLOAT_COLUMNS[0]
    'mu_ratio'
    """
    col = FIELD[name].column
    if col is None:
        raise KeyError(f"{name!r} is not a kernel column")
    return col[1]


class Status(enum.Enum):
    """How a steady-state result was obtained.

    ``.value`` its name, ``.code`` the kernels' code, ``.ok`` whether it is converged, ``.message``
    what it means for humans.
    """

    code: int
    ok: bool
    message: str

    PERIODIC = ("periodic", 0, True,
                "a periodic orbit was found on the Poincare section and averaged over "
                "exactly one of its periods")
    SLIDING = ("continuous sliding", 4, True,
               "continuous forward sliding is proven, so mu = mu0 exactly: the contact "
               "point can never stop again (the free oscillation is smaller than v0 - v0*, "
               "eqs. 10-12), or the contact point of the sliding orbit (of steady sliding "
               "without oscillation, a = 0) never stops, so that the energy of the motion "
               "about that orbit bounds the work of the friction deficit from any start, "
               "sticks of the transient included (docs/solver.md)")
    AVERAGED = ("averaged", 1, True,
                "no periodic orbit within the period bound; the means of the running "
                "average's last windows agree within tol_mean (the event and rate-and-state "
                "solvers: the last three doubling windows, the motion not near a periodic "
                "orbit; the 2-D solver: the thirds of a fixed window, no error where it lies "
                "on an orbit not shown to attract; the curved-tip solver: the halves of a "
                "fixed window)")
    NOT_CONVERGED = ("not converged", 2, False,
                     "max_periods was reached before a periodic orbit was found or the "
                     "running average settled")
    FAILED = ("failed", 3, False,
              "the event budget `max_events` was exhausted, or the integration could not "
              "advance, or more than 1000 transitions could only be decided within "
              "round-off (chatter along a tangency of the friction cone); the value is "
              "not reliable")
    HELD = ("held", 5, False,
            "v0 = 0 and the contact can stick through whole cycles: any mean force in the "
            "stuck band (with a transverse oscillation, the stuck region of mean forces in "
            "the plane) is a steady state, so the value is that of the preload the body "
            "started with, not a property of the system (docs/inplane.md, 'v0 = 0')")
    STATIC = ("static limit", -1, True,
              "zero sliding velocity: the static limit of eq. (2), the limit of the steady "
              "state as v0 -> 0+")

    def __new__(cls, value: str, code: int, ok: bool, message: str) -> Status:
        """A member with its code, whether it converged and its message."""
        member = object.__new__(cls)
        member._value_ = value
        member.code = code
        member.ok = ok  # converged: the value is a steady-state answer
        member.message = message
        return member

    @classmethod
    def from_code(cls, code: int) -> Status:
        """The member of a kernel status code; ValueError for an unknown code."""
        try:
            return STATUS_BY_CODE[int(code)]
        except KeyError:
            raise ValueError(f"unknown status code {code!r}; known: "
                             f"{sorted(STATUS_BY_CODE)}") from None


#: Members by kernel code, in code order (non-negative codes first, then ``STATIC``).
STATUS_BY_CODE: dict[int, Status] = {
    s.code: s for s in sorted(Status, key=lambda s: (s.code < 0, s.code))}
#: The codes of converged statuses (``Status.ok``).
CONVERGED_CODES: tuple[int, ...] = tuple(c for c, s in STATUS_BY_CODE.items() if s.ok)
