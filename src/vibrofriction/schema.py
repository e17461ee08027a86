"""The vocabulary: every parameter of the model and every quantity the solver returns, once.

Each :class:`Field` carries its name, kind, unit, long name and the paper's equation
(Mao, Popov, Starcevic & Popov, *Friction* 2017, Part II); the kernels' output columns
(:data:`FLOAT_COLUMNS`, :data:`INT_COLUMNS`), :class:`~vibrofriction.FrictionResult`,
the sweep's variables, the figures' curves, ``vibrofriction mu --json`` and the
explorer's curves are derived from :data:`FIELDS`.  :class:`Status` is the one status
vocabulary: each member carries its kernel code, its name, whether it is converged
and its message.  :class:`ContactState` is the one vocabulary of contact states (stick,
slip+, slip-, flight) of every solver: the kernels' codes and the names of histories,
results, figures and the explorer.  :data:`PARAMETERS` is the model's description: each
:class:`Parameter` carries its name, model, unit, long name, symbol, equation, allowed
:class:`Range` and default; :func:`vibrofriction.validation.validated` checks values
against it, and :class:`~vibrofriction.Dimensionless`, :class:`~vibrofriction.Physical`,
the sweep's coordinates, ``vibrofriction mu --json`` and the explorer follow it.

Standard library only: the numba kernels import it (their column indices, status codes
and contact-state codes come from here, :mod:`vibrofriction._kernels.codes`).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

__all__ = ["CONTACT_STATE_NAMES", "CONVERGED_CODES", "FIELD", "FIELDS", "FLOAT_COLUMNS",
           "INT_COLUMNS", "LENGTH_UNIT", "METHOD_NAMES", "MODELS", "NO_STATE", "PARAMETER",
           "PARAMETERS", "PARTIAL", "POINT_COLUMNS", "RESULT_FIELDS", "STATE_FIELDS",
           "STATUS_BY_CODE", "VELOCITY_UNIT", "CHOICES", "Choice", "ContactState", "Field",
           "Parameter", "Range", "Status", "choice_names", "column_index", "parameter_names",
           "parameters", "point_index"]

#: Units of the scaled variables (docs/model.md).
VELOCITY_UNIT = "mu0 F_N0 / (m omega)"
LENGTH_UNIT = "mu0 F_N0 / (m omega^2)"
FORCE_UNIT = "mu0 F_N0"


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
          "tip's solver; the kernels' rows hold its index)", column=("int", 6), dtype="i1"),
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
                "no periodic orbit within the period bound; the running average over the "
                "last half of the run agrees with the half before within tol_mean")
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


# --------------------------------------------------------------------------- parameters
#: The models a parameter belongs to: the paper's dimensionless groups
#: (:class:`~vibrofriction.Dimensionless`), the SI set-up
#: (:class:`~vibrofriction.Physical`) and the sliding velocity (one of three forms).
MODELS = ("dimensionless", "physical", "velocity")


def _number(x: float) -> str:
    return f"{x:g}"


@dataclass(frozen=True)
class Range:
    """The values a parameter may take.

    Parameters
    ----------
    minimum : float or None, optional
        The lower bound, if any; exclusive when ``strict``.
    strict : bool, optional
        Whether ``minimum`` itself is refused.
    maximum : float or None, optional
        The upper bound (inclusive), if any.
    allow_inf : bool, optional
        Whether ``+inf`` is admitted (``nan`` never is).
    above : str, optional
        A parameter the value must exceed (``beta > alpha``), where ``inf`` is always
        allowed; ``minimum`` is what is checked when that parameter is not given.

    Examples
    --------
    >>> from vibrofriction.schema import Range
    >>> Range(0.0, strict=True).text()
    'finite and > 0'
    >>> Range(above="alpha").text(0.5)
    '> alpha (= 0.5) or math.inf'
    """

    minimum: float | None = None
    strict: bool = False
    maximum: float | None = None
    allow_inf: bool = False
    above: str = ""

    def text(self, above_value: float | None = None) -> str:
        """The range in words, as the validator's errors say it.

        ``"finite and > 0"``, ``"> 0 (math.inf allowed)"``, ``"> alpha or math.inf"`` (with
        ``above_value``, the value of the parameter named by ``above``: ``"> alpha (= 0.5) or
        math.inf"``).
        """
        if self.above:
            value = "" if above_value is None else f" (= {above_value!r})"
            return f"> {self.above}{value} or math.inf"
        lo, hi = self.minimum, self.maximum
        if lo is not None and hi is not None:
            text = f"in {'(' if self.strict else '['}{_number(lo)}, {_number(hi)}]"
        elif lo is not None:
            text = f"{'>' if self.strict else '>='} {_number(lo)}"
        else:
            return "a number (not nan)" if self.allow_inf else "finite"
        return f"{text} (math.inf allowed)" if self.allow_inf else f"finite and {text}"


POSITIVE = Range(0.0, strict=True)
NONNEGATIVE = Range(0.0)
FINITE = Range()  # any finite real (a phase, a signed velocity)


@dataclass(frozen=True)
class Parameter:
    """One parameter of the model: what it is, where it comes from, what it may be.

    Parameters
    ----------
    name : str
        The parameter's name, as the model dataclasses and the sweep spell it.
    model : str
        One of :data:`MODELS`.
    unit : str
        UDUNITS-style (``"1"``: dimensionless).
    long_name : str
        What it is, in words.
    symbol : str
        Its symbol in the paper.
    equation : str
        The paper's equation that introduces it.
    range : Range
        Its allowed values.
    default : float or None, optional
        Its value when it is not given (None: required, unless ``twin``).
    definition : str, optional
        The parameter in terms of others (``"k_x / (m omega^2)"``; empty for a primary
        one).
    also : tuple of str, optional
        The other models that share it (a phase is the same number in SI and scaled
        form).
    twin : str, optional
        The parameter whose value an *optional* one takes when it is None (its default):
        the pin's transverse ``k_y`` is ``k_x`` unless given (an axisymmetric pin). The
        twin comes before it in :data:`PARAMETERS`;
        :func:`vibrofriction.validation.validated` resolves a None to the twin's value,
        and the model dataclasses keep the None (so a copy with another ``k_x`` stays
        axisymmetric).

    Examples
    --------
    >>> from vibrofriction.schema import PARAMETER
    >>> alpha = PARAMETER["alpha"]
    >>> alpha.long_name, alpha.equation
    ('system stiffness over inertia, k_x / (m omega^2)', '(20)')
    >>> alpha.label
    'alpha = k_x / (m omega^2)'
    >>> alpha.range.text()
    'finite and > 0'
    """

    name: str
    model: str
    unit: str
    long_name: str
    symbol: str
    equation: str
    range: Range
    default: float | None = None
    definition: str = ""
    also: tuple[str, ...] = ()
    twin: str = ""

    @property
    def models(self) -> tuple[str, ...]:
        """Every model this parameter belongs to (``model`` first)."""
        return (self.model, *self.also)

    @property
    def label(self) -> str:
        """``symbol = definition`` (or ``symbol, unit``): a short caption for a form."""
        return (f"{self.symbol} = {self.definition}" if self.definition
                else f"{self.symbol} ({self.unit})")


def _p(name: str, model: str, unit: str, long_name: str, symbol: str, equation: str = "",
       range: Range = POSITIVE, default: float | None = None, definition: str = "",
       also: tuple[str, ...] = (), twin: str = "") -> Parameter:
    return Parameter(name, model, unit, long_name, symbol, equation, range, default,
                     definition, also, twin)


_D, _P, _V = MODELS

#: Every parameter of the model, in the order of the fields of
#: :class:`~vibrofriction.Dimensionless`, then :class:`~vibrofriction.Physical`, then
#: the velocities (``phase_x`` belongs to both and sits where both orders hold).  A new
#: parameter is one entry here (docs/model.md, "Adding a parameter"): the validator, the
#: sweep's coordinates, ``vibrofriction mu --json`` and the explorer follow.
PARAMETERS: tuple[Parameter, ...] = (
    _p("alpha", _D, "1", "system stiffness over inertia, k_x / (m omega^2)", "alpha", "(20)",
       definition="k_x / (m omega^2)"),
    _p("beta", _D, "1", "system plus contact stiffness over inertia, (k_x + k_xc) / "
       "(m omega^2); inf = rigid contact", "beta", "(20)",
       Range(0.0, strict=True, allow_inf=True, above="alpha"),
       definition="(k_x + k_xc) / (m omega^2)"),
    _p("amplitude", _D, "1", "relative amplitude of the normal oscillation, du_z / u_z0 "
       "(> 1: jumping)", "a", "(1), (24)", NONNEGATIVE, definition="du_z / u_z0"),
    _p("zeta", _D, "1", "damping ratio of the pin, c_x / (2 sqrt(k_x m)) = 1/(2Q)", "zeta",
       "docs/damping.md", NONNEGATIVE, 0.0, "c_x / (2 sqrt(k_x m))"),
    _p("eta_c", _D, "1", "loss factor of the contact at the drive frequency, "
       "omega c_xc / k_xc (ignored by a rigid contact)", "eta_c", "docs/damping.md",
       NONNEGATIVE, 0.0, "omega c_xc / k_xc"),
    _p("a_x", _D, "1", "amplitude of the longitudinal in-plane oscillation (along the "
       "sliding), du_x m omega^2 / (mu0 F_N0), also its velocity amplitude in units of "
       "the inertial velocity", "a_x", "docs/inplane.md", NONNEGATIVE, 0.0,
       "du_x m omega^2 / (mu0 F_N0)"),
    _p("mass", _P, "kg", "mass of the body", "m", "Fig. 1b"),
    _p("k_x", _P, "N m-1", "tangential stiffness of the system spring", "k_x", "Fig. 1b"),
    _p("k_xc", _P, "N m-1", "tangential contact stiffness; inf = rigid contact", "k_x,c",
       "Fig. 1b", Range(0.0, strict=True, allow_inf=True)),
    _p("k_zc", _P, "N m-1", "normal contact stiffness", "k_z,c", "(3)"),
    _p("u_z0", _P, "m", "mean indentation", "u_z0", "(1)"),
    _p("du_z", _P, "m", "amplitude of the normal oscillation", "Delta u_z", "(1)",
       NONNEGATIVE),
    _p("omega", _P, "rad s-1", "angular frequency of the normal oscillation", "omega", "(1)"),
    _p("mu0", _P, "1", "local (microscopic) coefficient of friction", "mu0", "Fig. 1b"),
    _p("c_x", _P, "N s m-1", "pin dashpot parallel to k_x", "c_x", "docs/damping.md",
       NONNEGATIVE, 0.0),
    _p("c_xc", _P, "N s m-1", "tangential contact dashpot parallel to k_xc (Kelvin-Voigt)",
       "c_x,c", "docs/damping.md", NONNEGATIVE, 0.0),
    _p("du_x", _P, "m", "amplitude of the longitudinal in-plane oscillation, du_x cos(omega t "
       "+ phase_x) (of the substrate or the holder: inplane_on)", "Delta u_x",
       "docs/inplane.md", NONNEGATIVE, 0.0),
    _p("phase_x", _D, "rad", "phase of the longitudinal in-plane oscillation relative to "
       "the normal one, a_x cos(tau + phase_x)", "phase_x", "docs/inplane.md", FINITE, 0.0,
       also=(_P,)),
    _p("a_y", _D, "1", "amplitude of the transverse in-plane oscillation (across the "
       "sliding), du_y m omega^2 / (mu0 F_N0) (the 2-D solver)", "a_y", "docs/inplane.md",
       NONNEGATIVE, 0.0, "du_y m omega^2 / (mu0 F_N0)"),
    _p("du_y", _P, "m", "amplitude of the transverse in-plane oscillation, du_y cos(omega t "
       "+ phase_y) (of the substrate or the holder: inplane_on)", "Delta u_y",
       "docs/inplane.md", NONNEGATIVE, 0.0),
    _p("phase_y", _D, "rad", "phase of the transverse in-plane oscillation relative to "
       "the normal one, a_y cos(tau + phase_y)", "phase_y", "docs/inplane.md", FINITE, 0.0,
       also=(_P,)),
    _p("alpha_y", _D, "1", "transverse stiffness of the pin over inertia, k_y / (m "
       "omega^2) (the 2-D solver); None: alpha (an axisymmetric pin)", "alpha_y",
       "docs/inplane.md", definition="k_y / (m omega^2)", twin="alpha"),
    _p("zeta_y", _D, "1", "transverse damping ratio of the pin, c_y / (2 sqrt(k_y m)) (the "
       "2-D solver); None: zeta", "zeta_y", "docs/inplane.md", NONNEGATIVE,
       definition="c_y / (2 sqrt(k_y m))", twin="zeta"),
    _p("k_y", _P, "N m-1", "transverse stiffness of the pin (across the sliding); None: "
       "k_x (an axisymmetric pin)", "k_y", "docs/inplane.md", twin="k_x"),
    _p("c_y", _P, "N s m-1", "transverse pin dashpot parallel to k_y; None: c_x", "c_y",
       "docs/inplane.md", NONNEGATIVE, twin="c_x"),
    _p("profile_exponent", _D, "1", "exponent n of the pin's axisymmetric tip z = c r^n "
       "(1 cone, 2 sphere; inf = the flat punch, the single spring of the seed): the "
       "contact by the method of dimensionality reduction", "n", "docs/contact_geometry.md",
       Range(0.0, strict=True, allow_inf=True), float("inf"), also=(_P,)),
    _p("vbar", _V, "1", "sliding velocity over the critical velocity, v0 / v0*", "vbar",
       "(16)", NONNEGATIVE, definition="v0 / v0*"),
    _p("v_inertial", _V, VELOCITY_UNIT, FIELD["v_inertial"].long_name, "V", "Fig. 6",
       FINITE, definition="v0 m omega / (mu0 F_N0)"),
    _p("v0", _V, "m s-1", "sliding velocity of the drive (signed: negative slides the other "
       "way)", "v0", "Fig. 1b", FINITE),
)

#: Every model parameter by name.
PARAMETER: dict[str, Parameter] = {p.name: p for p in PARAMETERS}
if len(PARAMETER) != len(PARAMETERS) or any(
        any(m not in MODELS for m in p.models)
        or any(other and other not in [q.name for q in PARAMETERS[:i]]
               for other in (p.range.above, p.twin))
        or (p.twin and (p.default is not None or PARAMETER[p.twin].models != p.models))
        for i, p in enumerate(PARAMETERS)):  # the validator checks in this order
    raise AssertionError("PARAMETERS: names must be unique, models known, a parameter that "
                         "must exceed another or defaults to its twin must come after it, "
                         "and an optional one has no default of its own and its twin's "
                         "models")


@dataclass(frozen=True)
class Choice:
    """A model input that is one of a few names, not a number (``inplane_on``).

    :func:`vibrofriction.validation.checked_choice` is its one check. The model
    dataclasses carry a choice as a field after their numeric parameters.

    Parameters
    ----------
    name : str
        The choice's name.
    model : str
        One of :data:`MODELS`.
    long_name : str
        What it chooses, in words.
    values : tuple of str
        The allowed names.
    default : str
        One of ``values``.
    also : tuple of str, optional
        The other models that share it.

    Examples
    --------
    >>> from vibrofriction.schema import CHOICES
    >>> CHOICES["inplane_on"].values, CHOICES["inplane_on"].default
    (('substrate', 'holder'), 'substrate')
    """

    name: str
    model: str
    long_name: str
    values: tuple[str, ...]
    default: str
    also: tuple[str, ...] = ()


#: The model's choices (names, not numbers), by name.
CHOICES: dict[str, Choice] = {
    "inplane_on": Choice("inplane_on", _D, "where the in-plane oscillation is imposed: the "
                         "substrate (the contact point sticks to it; slip is relative to "
                         "it) or the pin's holder (the pulled end of the system spring)",
                         ("substrate", "holder"), "substrate", also=(_P,)),
}


def choice_names(model: str) -> tuple[str, ...]:
    """The names of the :data:`CHOICES` of ``model``.

    Parameters
    ----------
    model : str
        One of :data:`MODELS`.

    Returns
    -------
    tuple of str
        The names, in the order of :data:`CHOICES`.

    Examples
    --------
    >>> from vibrofriction.schema import choice_names
    >>> choice_names("dimensionless")
    ('inplane_on',)
    """
    return tuple(c.name for c in CHOICES.values() if model in (c.model, *c.also))


def parameters(model: str) -> tuple[Parameter, ...]:
    """The parameters of ``model``, in the schema's order.

    Parameters
    ----------
    model : str
        One of :data:`MODELS`: ``"dimensionless"``, ``"physical"`` or ``"velocity"``.

    Returns
    -------
    tuple of Parameter
        The parameters of :data:`PARAMETERS` that belong to ``model``.

    Raises
    ------
    ValueError
        If ``model`` is not one of :data:`MODELS`.

    Examples
    --------
    >>> from vibrofriction.schema import parameters
    >>> [p.name for p in parameters("physical")][:5]
    ['mass', 'k_x', 'k_xc', 'k_zc', 'u_z0']
    """
    if model not in MODELS:
        raise ValueError(f"model must be one of {list(MODELS)}, got {model!r}")
    return tuple(p for p in PARAMETERS if model in p.models)


def parameter_names(model: str, *, optional: bool = True) -> tuple[str, ...]:
    """The names of :func:`parameters` of ``model``.

    Parameters
    ----------
    model : str
        One of :data:`MODELS`.
    optional : bool, optional
        False leaves out the optional ones that default to their twin
        (:attr:`Parameter.twin`: ``k_y``, ``alpha_y``, ...).

    Returns
    -------
    tuple of str
        The names, in the schema's order.

    Examples
    --------
    >>> from vibrofriction.schema import parameter_names
    >>> parameter_names("dimensionless", optional=False)
    ('alpha', 'beta', 'amplitude', 'zeta', 'eta_c', 'a_x', 'phase_x', 'a_y', 'phase_y',
     'profile_exponent')
    """
    return tuple(p.name for p in parameters(model) if optional or not p.twin)


#: The solvers, by the name a result records (``FrictionResult.method``); the kernels' rows
#: hold the index (:mod:`vibrofriction.solver.methods` declares what each one covers).
METHOD_NAMES: tuple[str, ...] = ("event", "plane", "mdr")

#: The columns of a table of points (:class:`vibrofriction.solver.points.PointTable`), in
#: order: the dimensionless model's parameters (the order of :data:`PARAMETERS`), the
#: inertial velocity, then each choice of the model as the index of its value in
#: :attr:`Choice.values`.  The kernels read a packed row of points by these indices
#: (:mod:`vibrofriction._kernels.codes`), as they write the output columns.
POINT_COLUMNS: tuple[str, ...] = (*parameter_names(_D), "v_inertial", *choice_names(_D))


def point_index(name: str) -> int:
    """The index of ``name`` in a row of a table of points (:data:`POINT_COLUMNS`)."""
    try:
        return POINT_COLUMNS.index(name)
    except ValueError:
        raise KeyError(f"{name!r} is not a column of a table of points: "
                       f"{list(POINT_COLUMNS)}") from None
