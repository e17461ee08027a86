"""The model's parameters and choices, the solvers' names and a table of points' columns.

See :mod:`vibrofriction.schema`; standard library only.
"""

from __future__ import annotations

from dataclasses import dataclass

from .fields import FIELD, VELOCITY_UNIT, cf_attrs

__all__ = ["CHOICES", "Choice", "FINITE", "METHOD_NAMES", "MODELS", "NONNEGATIVE", "PARAMETER",
           "PARAMETERS", "POINT_COLUMNS", "POSITIVE", "Parameter", "Range",
           "choice_names", "parameter_names", "parameters", "point_index"]

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

    def attrs(self) -> dict[str, str]:
        """The parameter's CF-style attributes (:func:`~vibrofriction.schema.cf_attrs`).

        Examples
        --------
        >>> from vibrofriction.schema import PARAMETER
        >>> PARAMETER["k_x"].attrs()["units"]
        'N m-1'
        """
        return cf_attrs(self.long_name, self.symbol, self.unit, self.equation)

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
    _p("mu_static", _P, "1", "static coefficient of friction: a stuck contact holds while "
       "|f| <= mu_static n, then its force drops to mu0 n (mu0 the kinetic one; >= mu0); "
       "None: mu0 (Coulomb friction)", "mu_s", "docs/friction_laws.md", twin="mu0"),
    _p("static_ratio", _D, "1", "static over kinetic coefficient of friction, mu_static / mu0 "
       "(>= 1; 1: Coulomb friction)", "mu_s/mu0", "docs/friction_laws.md", Range(1.0), 1.0,
       "mu_static / mu0"),
    _p("rs_a", _D, "1", "direct effect a of rate-and-state friction over mu_star (mu_star = "
       "mu0; 0: Coulomb friction, no rate-and-state law)", "a/mu_star",
       "docs/friction_laws.md", NONNEGATIVE, 0.0, "a / mu_star"),
    _p("rs_b", _D, "1", "evolution effect b of rate-and-state friction over mu_star (b > a: "
       "velocity weakening)", "b/mu_star", "docs/friction_laws.md", NONNEGATIVE, 0.0,
       "b / mu_star"),
    _p("rs_d_c", _D, "1", "critical slip distance d_c of rate-and-state friction in units of "
       "the inertial length mu_star F_N0 / (m omega^2)", "d_c", "docs/friction_laws.md",
       POSITIVE, 1.0, "d_c m omega^2 / (mu_star F_N0)"),
    _p("rs_v_ref", _D, "1", "reference slip velocity v_ref of rate-and-state friction in units "
       "of the inertial velocity mu_star F_N0 / (m omega)", "v_ref", "docs/friction_laws.md",
       POSITIVE, 1.0, "v_ref m omega / (mu_star F_N0)"),
    _p("rs_alpha_ld", _D, "1", "Linker-Dieterich coefficient alpha of the state's response to "
       "the normal force over mu_star (0: no normal-stress memory)", "alpha_LD/mu_star",
       "docs/friction_laws.md", NONNEGATIVE, 0.0, "alpha_LD / mu_star"),
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
    "rs_law": Choice("rs_law", _D, "the evolution law of the state of rate-and-state "
                     "friction (rs_a > 0): aging, theta' = 1 - |w'| theta / d_c, or slip, "
                     "theta' = -(|w'| theta / d_c) ln(|w'| theta / d_c)",
                     ("aging", "slip"), "aging"),
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
    ('inplane_on', 'rs_law')
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
     'profile_exponent', 'static_ratio', 'rs_a', 'rs_b', 'rs_d_c', 'rs_v_ref', 'rs_alpha_ld')
    """
    return tuple(p.name for p in parameters(model) if optional or not p.twin)


#: The solvers, by the name a result records (``FrictionResult.method``); the kernels' rows
#: hold the index (:mod:`vibrofriction.solver.methods` declares what each one covers).
METHOD_NAMES: tuple[str, ...] = ("event", "plane", "mdr", "rate_state")

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
