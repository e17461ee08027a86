"""The command line's options in one table, made from the schema.

Every model parameter of :data:`vibrofriction.schema.PARAMETERS` becomes an option whose
flag, metavar, help text (long name, unit, allowed range, default, equation) and check
come from its :class:`~vibrofriction.schema.Parameter`; the model's choices
(:data:`~vibrofriction.schema.CHOICES`) likewise.  The options that are not parameters
of the model (``--out``, ``--workers``, ...) are rows of the same :class:`Opt` table,
written by hand in the command modules; what each solver does not take is said from
:mod:`vibrofriction.capabilities`.  Standard library, the schema and the capabilities
only: this module is imported for ``vibrofriction --help``.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from typing import Any

from ..capabilities import CAPABILITIES, refused_by
from ..schema import CHOICES, PARAMETER, PARAMETERS, Parameter, Range

FLOAT = "FLOAT"
FLOATS = "FLOAT[,FLOAT...]"
INT = "INT"

#: The kinds of value an option takes: one number, a comma list of numbers, a sweep
#: axis (a number, a comma list or start:stop:num[:log]), an integer, a name from
#: ``choices``, free text (a path, a dim=value pair) or nothing (an on/off flag).
KINDS = ("float", "list", "axis", "int", "choice", "text", "flag")


@dataclass(frozen=True)
class Opt:
    """One option (or positional argument) of a command.

    ``name`` is the keyword it becomes (the schema's name for a model parameter);
    ``requires`` the options of which at least one must be given (and not all zero)
    with this one, so that it is never silently ignored; ``parameter`` the schema's
    description, whose range every value is checked against.
    """

    name: str
    help: str
    kind: str = "float"
    default: Any = None
    metavar: str = ""
    choices: tuple[str, ...] = ()
    requires: tuple[str, ...] = ()
    parameter: Parameter | None = None
    positional: bool = False
    repeat: bool = False  # may be given more than once (a list of the values)
    negatable: bool = True  # a flag with a --no- form
    flags: tuple[str, ...] = ()  # the option strings, when not the one made from name
    range: Range | None = None  # the allowed values of an option that is no parameter
    required: bool = False
    group: str = ""  # the heading it is listed under in --help ("" : options)

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"option {self.name}: kind must be one of {', '.join(KINDS)}")

    @property
    def allowed(self) -> Range | None:
        """The range each value is checked against (the schema's for a parameter)."""
        return self.parameter.range if self.parameter is not None else self.range

    @property
    def flag(self) -> str:
        """``--k-xc`` for ``k_xc`` (or the first of ``flags``)."""
        return self.flags[0] if self.flags else "--" + self.name.replace("_", "-")

    @property
    def takes_value(self) -> bool:
        return self.kind != "flag" and not self.positional

    def full_help(self) -> str:
        """The help text with what it needs and its default."""
        parts = [self.help + (" (required)" if self.required else "")]
        if self.requires:
            parts.append("needs " + " or ".join(flag(r) for r in self.requires))
        if self.default is not None and self.kind not in ("flag",):
            parts.append(f"default {plain(self.default)}")
        return "; ".join(p for p in parts if p)


def flag(name: str) -> str:
    """The command-line flag of a keyword name: ``phase_x`` -> ``--phase-x``."""
    return "--" + name.replace("_", "-")


def plain(value: Any) -> str:
    """A value as a user writes it: ``0.5``, ``inf``, ``1e-06`` (never a Python repr)."""
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, float | int):
        return f"{value:g}"
    try:  # a numpy scalar
        return f"{float(value):g}"
    except (TypeError, ValueError):
        return str(value)


def unit_words(unit: str) -> str:
    """A UDUNITS unit as people write it: ``N m-1`` -> ``N/m``, ``1`` -> ``""``."""
    if unit == "1":
        return ""
    tokens = unit.split()
    if not all(re.fullmatch(r"[A-Za-z]+(-1)?", t) for t in tokens):
        return unit  # not a product of units and inverse units: keep as written
    up = [t for t in tokens if not t.endswith("-1")]
    down = [t[:-2] for t in tokens if t.endswith("-1")]
    return " ".join(up) + ("/" + " ".join(down) if down else "")


def range_words(rng: Range) -> str:
    """The allowed values in the schema's words, with ``inf`` for ``math.inf``.

    ``finite and > 0``, ``> 0 (inf allowed)``, ``> alpha or inf``.
    """
    return rng.text().replace("math.inf", "inf")


def check_value(opt_flag: str, rng: Range, value: float,
                above: tuple[str, float] | None = None, name: str = "") -> None:
    """ValueError in one line if ``value`` is outside ``rng``.

    ValueError in one line naming the option (and the parameter ``name``) and its
    allowed values if ``value`` is outside ``rng`` (``above``: the flag and value of the
    parameter it must exceed).
    """
    ok = not math.isnan(value)
    if ok and math.isinf(value):
        ok = value > 0 and rng.allow_inf
    elif ok:
        if rng.minimum is not None:
            ok = value > rng.minimum if rng.strict else value >= rng.minimum
        if ok and rng.maximum is not None:
            ok = value <= rng.maximum
        if ok and rng.above and above is not None:
            ok = value > above[1]
    if not ok:
        allowed = range_words(rng)
        if rng.above and above is not None:
            allowed = f"> {above[0]} (= {above[1]:g}) or inf"
        named = f" ({name})" if name and flag(name) == opt_flag and "_" in name else ""
        raise ValueError(f"{opt_flag}{named} must be {allowed}, got {value:g}")


#: The headings of the schema's models in ``--help``.
GROUPS = {"dimensionless": "the dimensionless system (and both kinds)",
          "physical": "a physical set-up (SI units)",
          "velocity": "the sliding velocity"}


def _equation(eq: str) -> str:
    return f"eq. {eq}" if eq.startswith("(") else eq


def parameter_option(name: str, kind: str = "float", note: str = "",
                     requires: tuple[str, ...] = ()) -> Opt:
    """The option of the schema's parameter ``name``.

    Help from its long name, unit, range, default (or twin) and equation; ``note`` is what the
    command adds.
    """
    p = PARAMETER[name]
    unit = unit_words(p.unit)
    words = [p.long_name + (f" [{unit}]" if unit else ""), range_words(p.range)]
    if p.twin:
        words.append(f"default: {flag(p.twin)}")
    if note:
        words.append(note)
    words += [f"not taken by {c.title} ({c.takes})" for c in refused_by(name)]
    if p.equation:
        words.append(_equation(p.equation))
    metavar = {"float": FLOAT, "list": FLOATS, "axis": FLOATS}[kind]
    return Opt(name, "; ".join(words), kind=kind, metavar=metavar,
               default=None if p.default is None else p.default, requires=requires,
               parameter=p, group=GROUPS[p.model])


def choice_option(name: str, requires: tuple[str, ...] = ()) -> Opt:
    """The option of the schema's choice ``name`` (``inplane_on``)."""
    c = CHOICES[name]
    return Opt(name, c.long_name, kind="choice", choices=c.values, default=c.default,
               metavar="{" + ",".join(c.values) + "}", requires=requires,
               group=GROUPS[c.model])


def with_(opt: Opt, **changes: Any) -> Opt:
    """A copy of a row with some fields changed."""
    return replace(opt, **changes)


def by_name(options: Sequence[Opt]) -> dict[str, Opt]:
    return {o.name: o for o in options}


#: The options that mean something only with another: at least one of these must be
#: given (nonzero), else the option is refused rather than silently ignored.
REQUIRES: dict[str, tuple[str, ...]] = {
    "phase_x": ("a_x", "du_x"),
    "phase_y": ("a_y", "du_y"),
    "alpha_y": ("a_y",),
    "zeta_y": ("a_y",),
    "k_y": ("du_y",),
    "c_y": ("du_y",),
    "inplane_on": ("a_x", "a_y", "du_x", "du_y"),
    **dict.fromkeys(("rs_b", "rs_d_c", "rs_v_ref", "rs_alpha_ld", "rs_law"),
                    ("rs_a", "friction_a")),
    **dict.fromkeys(("friction_b", "friction_d_c", "friction_v_ref", "friction_alpha_ld"),
                    ("friction_a",)),
}

#: Rate-and-state friction of a physical set-up (``Physical(friction=RateAndState(...))``):
#: its coefficients as they are, ``d_c`` in m and ``v_ref`` in m/s; ``--rs-law`` chooses the
#: state's law in both kinds of system.
FRICTION_SI = tuple(
    Opt(f"friction_{name}", f"rate-and-state friction of a physical set-up: {words}",
        metavar=FLOAT, range=rng, requires=REQUIRES.get(f"friction_{name}", ()),
        group=GROUPS["physical"])
    for name, words, rng in (
        ("a", "the direct effect a (mu_star = --mu0; with --friction-d-c, --friction-v-ref)",
         Range(0.0, strict=True)),
        ("b", "the evolution effect b (default 0)", Range(0.0)),
        ("d_c", "the critical slip distance d_c [m]", Range(0.0, strict=True)),
        ("v_ref", "the reference slip velocity v_ref [m s-1]", Range(0.0, strict=True)),
        ("alpha_ld", "the Linker-Dieterich coefficient alpha (default 0)", Range(0.0))))


def model_options(kinds: dict[str, str], notes: dict[str, str] | None = None,
                  skip: Iterable[str] = ()) -> tuple[Opt, ...]:
    """An option for every parameter of the schema and every choice, except ``skip``.

    An option for every parameter of the schema (in its order; ``kinds``: the kind of
    value of some of them, ``"float"`` otherwise) and every choice, except ``skip``.
    """
    notes = notes or {}
    skip = set(skip)
    out = [parameter_option(p.name, kinds.get(p.name, "float"), notes.get(p.name, ""),
                            REQUIRES.get(p.name, ()))
           for p in PARAMETERS if p.name not in skip]
    out += [choice_option(c, REQUIRES.get(c, ())) for c in CHOICES if c not in skip]
    return tuple(out)


#: Solver settings shared by ``mu`` and ``sweep`` (their defaults are those of
#: ``SolverSettings``, which a test checks; the solver is not imported for ``--help``;
#: None: each solver's own).
INITIAL = Opt("initial", "initial state", kind="choice", choices=("sliding", "rest"),
              default="sliding", metavar="{sliding,rest}")
MAX_PERIODS = Opt("max_periods", "give up after this many drive periods (default: each "
                  "solver's own: " + ", ".join(
                      f"{c.settings['max_periods']:,} for {c.title}"
                      for c in CAPABILITIES.values() if "max_periods" in c.settings) + ")",
                  kind="int", default=None, metavar=INT, range=Range(1.0))
TOL_TRUSTED = Opt("tol_trusted", "largest error estimate of a trusted point (the others "
                  "give exit code 3)", default=1e-5, metavar=FLOAT, range=Range(0.0, strict=True))
