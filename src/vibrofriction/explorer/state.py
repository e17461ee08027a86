"""The explorer's state: the inputs as one value, its URL form and the system it describes.

Every range check is the library's own: :meth:`State.system` builds a
:class:`~vibrofriction.Dimensionless` or :func:`~vibrofriction.bench.from_bench`, and a
bad value is the ``ValueError`` they raise (docs/explorer.md).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

import vibrofriction as vf
from vibrofriction.capabilities import CAPABILITIES, FRICTION_LAWS, friction_laws
from vibrofriction.schema import CHOICES, PARAMETER, parameter_names
from vibrofriction.validation import checked, checked_choice

__all__ = ["AXES", "BENCH", "BENCH_LAW", "DIMENSIONLESS", "FIELDS", "LAWS", "LAW_DISABLED",
           "LAW_FIELDS", "LAW_POINTS", "MDR_POINTS", "MDR_REFUSED", "PROFILE", "PROFILES", "Field",
           "State", "law_solver", "parse_number", "profile_of"]

MODES = ("dimensionless", "bench")
#: velocity axes: the keyword of ``friction_coefficient`` and the axis label
AXES = {"vbar": ("vbar", "vbar = v0/v0*"),
        "V": ("v_inertial", "V = v0 m omega/(mu0 F_N0)"),
        "v0": ("v0", "v0 (m/s)")}


def _default(name: str) -> float:
    """The schema's default of a parameter that has one."""
    default = PARAMETER[name].default
    assert default is not None, name
    return default


@dataclass(frozen=True)
class Field:
    """One numeric input: its name (the library's), label, slider range and scale."""

    name: str
    label: str
    low: float
    high: float
    log: bool = True
    allow_inf: bool = False


def _model_field(name: str, low: float, high: float, log: bool = True,
                 label: str = "") -> Field:
    """The input of a model parameter.

    Its label (unless given) and whether ``inf`` is allowed from the schema
    (:data:`vibrofriction.schema.PARAMETERS`); the slider range and scale are the explorer's choice.
    """
    p = PARAMETER[name]
    return Field(name, label or p.label, low, high, log, allow_inf=p.range.allow_inf)


#: the sliders of the dimensionless model (ranges: UI choices, not the model's limits)
_SLIDERS = {"alpha": (1e-3, 1e2, True), "beta": (1e-3, 1e4, True),
           "amplitude": (0.0, 3.0, False), "zeta": (0.0, 0.2, False),
           "eta_c": (0.0, 1.0, False), "a_x": (0.0, 5.0, False),
           "phase_x": (0.0, 6.283185307179586, False), "a_y": (0.0, 5.0, False),
           "phase_y": (0.0, 6.283185307179586, False)}
#: the tip's profile is offered by a selector of its own (:data:`PROFILES`, :data:`PROFILE`)
#: over the MDR solver (docs/contact_geometry.md), the friction law's inputs by the law's
#: selector (:data:`LAWS`, :data:`LAW_FIELDS`); the pin across (alpha_y, zeta_y) is
#: axisymmetric here
_NOT_OFFERED = ("profile_exponent", "static_ratio", "rs_a", "rs_b", "rs_d_c", "rs_v_ref",
                "rs_alpha_ld")
DIMENSIONLESS = tuple(_model_field(n, *_SLIDERS[n])
                      for n in parameter_names("dimensionless", optional=False)
                      if n not in _NOT_OFFERED)
#: the profile selector's named tips and their exponent ``n`` of ``z = c r^n``; any other
#: exponent is the power law (its own input, :data:`PROFILE`)
PROFILES = {"flat": math.inf, "sphere": 2.0, "cone": 1.0}
#: the exponent of the power law (slider range: a UI choice; the library takes any n > 0)
PROFILE = _model_field("profile_exponent", 0.25, 20.0,
                       label="exponent n of the tip z = c r^n (power law)")
#: the inputs the MDR solver refuses whatever their value (its declared limits, whole):
#: reset to 0 and disabled,
#: with the library's refusal shown next to them (docs/explorer.md); it takes the
#: longitudinal in-plane oscillation ``a_x`` at ``V != 0`` (not at ``V = 0``:
#: :meth:`State.velocities` leaves that point out)
MDR_REFUSED = tuple(lim.parameter for lim in CAPABILITIES["mdr"].limits
                    if lim.whole and lim.parameter not in _NOT_OFFERED)
#: the most points of a curve of a curved tip (the MDR solver: ~30 ms a point, up to a few
#: tenths of a second near the onset of sliding)
MDR_POINTS = 40


#: the friction-law selector: its value (the URL's ``friction``) and the law's name in the
#: solvers' declarations (:data:`vibrofriction.capabilities.FRICTION_LAWS`, the capability table)
LAWS = {"coulomb": "Coulomb", "static": "static above kinetic", "rate_state": "rate-and-state"}
assert set(LAWS.values()) == {"Coulomb", *FRICTION_LAWS}
#: the inputs of each law (dimensionless, the model's units; docs/friction_laws.md), slider
#: ranges a UI choice
LAW_FIELDS = {
    "static": (_model_field("static_ratio", 1.0, 3.0, log=False),),
    "rate_state": (_model_field("rs_a", 1e-3, 0.5), _model_field("rs_b", 0.0, 0.5, log=False),
                   _model_field("rs_d_c", 1e-4, 10.0), _model_field("rs_v_ref", 1e-4, 10.0),
                   _model_field("rs_alpha_ld", 0.0, 0.5, log=False)),
}
#: the same laws on the bench, in SI (``vf.Physical(mu_static=..., friction=vf.RateAndState(
#: a, b, d_c [m], v_ref [m/s], alpha_ld))``): d_c typed in um, v_ref in mm/s
BENCH_LAW = {
    "static": (Field("mu_static", "mu_static (static coefficient, >= mu0)", 0.01, 3.0),),
    "rate_state": (Field("friction_a", "a (direct effect)", 1e-4, 0.2),
                   Field("friction_b", "b (evolution effect)", 0.0, 0.2, log=False),
                   Field("friction_d_c_um", "d_c (critical slip distance, um)", 1e-3, 1e3),
                   Field("friction_v_ref_mm_s", "v_ref (reference velocity, mm/s)", 1e-4,
                         1e4),
                   Field("friction_alpha_ld", "alpha_ld (Linker-Dieterich)", 0.0, 0.2,
                         log=False)),
}
#: the most points of a rate-and-state curve (~5-10 ms a point, more near stick-slip)
LAW_POINTS = 40


def law_solver(law: str) -> str:
    """The solver of a flat punch without a transverse oscillation under ``law``.

    Its name in :data:`~vibrofriction.capabilities.CAPABILITIES`: the first, in their order,
    whose declaration covers the law and is chosen for a flat punch sliding along x.
    """
    return "rate_state" if law == "rate_state" else "event"


def _law_disabled(law: str) -> tuple[str, ...]:
    """The offered inputs disabled under ``law``, from the declarations.

    Those its solver refuses whatever their value (``whole``), and the transverse oscillation
    (``a_y``, ``phase_y``) where the 2-D solver does not cover the law.
    """
    own = CAPABILITIES[law_solver(law)]
    names = [lim.parameter for lim in own.limits if lim.whole]
    if LAWS[law] not in friction_laws(CAPABILITIES["plane"]):
        names += ["a_y", "phase_y"]
    return tuple(n for n in names if n in _SLIDERS)


#: the inputs each law disables (reset to 0, the reason beside them; docs/explorer.md)
LAW_DISABLED = {law: _law_disabled(law) for law in LAWS}


def profile_of(exponent: float) -> str:
    """The selector's name of a tip exponent: ``flat``, ``sphere``, ``cone`` or ``power``."""
    return next((k for k, n in PROFILES.items() if n == exponent), "power")


BENCH = (
    Field("natural_frequency_hz", "pin natural frequency (Hz)", 10.0, 1e5),
    _model_field("mass", 1e-4, 10.0, label="pin modal mass (kg)"),
    Field("quality_factor", "pin quality factor Q", 1.0, 1e4, allow_inf=True),
    Field("normal_load", "normal load F_N0 (N)", 0.01, 1e4),
    _model_field("k_zc", 1e4, 1e10, label="normal contact stiffness k_zc (N/m)"),
    _model_field("k_xc", 1e4, 1e10, label="tangential contact stiffness k_xc (N/m)"),
    Field("drive_frequency_hz", "drive frequency (Hz)", 10.0, 1e5),
    Field("du_z_um", "oscillation amplitude du_z (um)", 1e-3, 100.0),
    _model_field("mu0", 0.01, 2.0, label="mu0 (local coefficient of friction)"),
    Field("bench_eta_c", "eta_c (contact loss factor)", 0.0, 1.0, log=False),
)
VELOCITY = (
    Field("v_min", "velocity from (V, v0: signed)", -1e3, 1e3, log=False, allow_inf=False),
    Field("v_max", "velocity to", 1e-6, 1e3),
)
LAW_INPUTS = tuple(f for fields in (*LAW_FIELDS.values(), *BENCH_LAW.values())
                   for f in fields)
FIELDS = {f.name: f for f in (*DIMENSIONLESS, PROFILE, *BENCH, *VELOCITY, *LAW_INPUTS)}


def parse_number(name: str, text: str | float) -> float:
    """A typed value as a float (``inf`` accepted), or the library's ValueError naming it."""
    if isinstance(text, str):
        text = text.strip()
    return float(checked(name, text, allow_inf=True))


@dataclass(frozen=True)
class State:
    """Every input of the explorer (defaults: the general system of the README)."""

    mode: str = "dimensionless"
    alpha: float = 0.5
    beta: float = 2.0
    amplitude: float = 0.5
    zeta: float = _default("zeta")
    eta_c: float = _default("eta_c")
    a_x: float = _default("a_x")
    phase_x: float = _default("phase_x")
    a_y: float = _default("a_y")
    phase_y: float = _default("phase_y")
    profile_exponent: float = _default("profile_exponent")
    inplane_on: str = CHOICES["inplane_on"].default
    friction: str = "coulomb"
    static_ratio: float = 1.3
    rs_a: float = 0.02
    rs_b: float = 0.01
    rs_d_c: float = 0.01
    rs_v_ref: float = 0.1
    rs_alpha_ld: float = 0.0
    rs_law: str = CHOICES["rs_law"].default
    natural_frequency_hz: float = 800.0
    mass: float = 0.01
    quality_factor: float = 50.0
    normal_load: float = 20.0
    k_zc: float = 2e7
    k_xc: float = 1.5e7
    drive_frequency_hz: float = 1000.0
    du_z_um: float = 0.5
    mu0: float = 0.3
    bench_eta_c: float = 0.0
    mu_static: float = 0.39
    friction_a: float = 0.006
    friction_b: float = 0.003
    friction_d_c_um: float = 1.0
    friction_v_ref_mm_s: float = 1.0
    friction_alpha_ld: float = 0.0
    axis: str = "vbar"
    v_min: float = 0.0
    v_max: float = 1.5
    log_x: bool = False
    points: int = 200

    def __post_init__(self) -> None:
        """Check the mode and the axis by name."""
        if self.mode not in MODES:
            raise ValueError(f"mode must be one of {list(MODES)}, got {self.mode!r}")
        if self.axis not in AXES:
            raise ValueError(f"axis must be one of {list(AXES)}, got {self.axis!r}")
        checked_choice("inplane_on", self.inplane_on)
        checked_choice("rs_law", self.rs_law)
        if self.friction not in LAWS:
            raise ValueError(f"friction must be one of {list(LAWS)}, got {self.friction!r}")

    # ------------------------------------------------------------------ system
    @property
    def curved(self) -> bool:
        """A curved tip (finite ``profile_exponent``) on the dimensionless inputs.

        The MDR solver computes the curve (the bench inputs are the linearised contact).
        """
        return self.mode == "dimensionless" and self.profile_exponent != math.inf

    @property
    def curve_points(self) -> int:
        """The points of the curve.

        ``points``, at most :data:`MDR_POINTS` for a curved tip and :data:`LAW_POINTS` for
        rate-and-state friction.
        """
        if self.curved:
            return min(self.points, MDR_POINTS)
        return min(self.points, LAW_POINTS) if self.friction == "rate_state" else self.points

    def law_fields(self) -> tuple[Field, ...]:
        """The inputs of the chosen friction law in the state's mode (none for Coulomb)."""
        return (BENCH_LAW if self.mode == "bench" else LAW_FIELDS).get(self.friction, ())

    def law_arguments(self) -> dict[str, Any]:
        """The chosen law as the library's keywords.

        Dimensionless: ``static_ratio`` or the ``rs_*`` fields; bench: ``mu_static`` or
        ``friction`` (a :class:`~vibrofriction.RateAndState` in SI); empty for Coulomb.
        """
        if self.friction == "coulomb":
            return {}
        if self.mode == "dimensionless":
            law = {f.name: getattr(self, f.name) for f in LAW_FIELDS[self.friction]}
            return law if self.friction == "static" else {**law, "rs_law": self.rs_law}
        if self.friction == "static":
            return {"mu_static": self.mu_static}
        return {"friction": vf.RateAndState(
            a=self.friction_a, b=self.friction_b, d_c=self.friction_d_c_um * 1e-6,
            v_ref=self.friction_v_ref_mm_s * 1e-3, alpha_ld=self.friction_alpha_ld,
            law=self.rs_law)}

    def system(self) -> vf.Dimensionless | vf.Physical:
        """The library's system for these inputs (its validators raise ValueError)."""
        if self.mode == "dimensionless":
            return vf.Dimensionless(**{f.name: getattr(self, f.name) for f in DIMENSIONLESS},
                                    profile_exponent=self.profile_exponent,
                                    inplane_on=self.inplane_on, **self.law_arguments())
        bench = vf.from_bench(**self.bench_arguments())
        law = self.law_arguments()
        return bench.with_(**law) if law else bench

    def bench_arguments(self) -> dict[str, Any]:
        """The keyword arguments of :func:`vibrofriction.bench.from_bench` (bench file's keys)."""
        return dict(natural_frequency_hz=self.natural_frequency_hz, mass=self.mass,
                    quality_factor=self.quality_factor, normal_load=self.normal_load,
                    k_zc=self.k_zc, k_xc=self.k_xc,
                    drive_frequency_hz=self.drive_frequency_hz, du_z=self.du_z_um * 1e-6,
                    mu0=self.mu0, eta_c=self.bench_eta_c)

    @property
    def rest_refused(self) -> bool:
        """Whether ``V = 0`` is no point of the curve.

        A curved tip with a longitudinal in-plane oscillation (``a_x > 0``), which the MDR solver
        refuses at rest; a friction law other than Coulomb's on a flat punch (the 1-D solver
        has no static limit of a static coefficient, the rate-and-state solver none at all:
        the contact creeps).
        """
        if self.curved:
            return self.a_x > 0.0
        return self.friction != "coulomb"

    def grid(self) -> np.ndarray:
        """The velocities of the curve on the chosen axis.

        The :attr:`curve_points` velocities from ``v_min`` to ``v_max`` on the chosen
        axis (``V`` and ``v0`` signed: negative slides the other way; ``vbar`` from 0).
        """
        lo = float(checked("v_min", self.v_min, minimum=0.0 if self.axis == "vbar" else None))
        hi = float(checked("v_max", self.v_max, minimum=lo, strict=True))
        if self.log_x:
            lo = float(checked("v_min", lo, minimum=0.0, strict=True))
            return np.geomspace(lo, hi, self.curve_points)
        return np.linspace(lo, hi, self.curve_points)

    def velocities(self) -> np.ndarray:
        """The velocities of the curve.

        The :meth:`grid`, without ``V = 0`` where it is refused (:attr:`rest_refused`; the page says
        so).
        """
        x = self.grid()
        return x[x != 0.0] if self.rest_refused else x

    def velocity_keyword(self) -> str:
        """``vbar``, ``v_inertial`` or ``v0``: the keyword of ``friction_coefficient``."""
        return AXES[self.axis][0]

    # ------------------------------------------------------------------ URL
    def to_query(self) -> dict[str, str]:
        """The inputs that differ from the defaults, as URL query parameters."""
        default = State()
        out = {}
        for f in dataclasses.fields(self):
            value = getattr(self, f.name)
            if value != getattr(default, f.name):
                out[f.name] = _text(value)
        return out

    @classmethod
    def from_query(cls, query: Mapping[str, str | bytes | list]) -> tuple[State, dict[str, str]]:
        """A state from URL query parameters, and the messages of those it could not read.

        A state from URL query parameters, and a message per parameter it could not read
        (those keep their defaults; unknown names are ignored).
        """
        values: dict[str, Any] = {}
        problems: dict[str, str] = {}
        names = {f.name: f for f in dataclasses.fields(cls)}
        for key, raw in query.items():
            if key not in names:
                continue
            if isinstance(raw, list):
                raw = raw[-1] if raw else ""
            text = raw.decode() if isinstance(raw, bytes) else str(raw)
            try:
                values[key] = _value(key, text)
            except ValueError as exc:
                problems[key] = str(exc)
        while True:  # each choice the state refuses by name keeps its default
            try:
                return cls(**values), problems
            except ValueError as exc:
                bad = next((n for n in ("mode", "inplane_on", "rs_law", "friction")
                            if str(exc).startswith(n)), "axis")
                if bad not in values:
                    raise
                problems[bad] = str(exc)
                values.pop(bad)

    def with_(self, **changes: Any) -> State:
        """A copy with some inputs replaced."""
        return dataclasses.replace(self, **changes)


def _text(value: object) -> str:
    """A value as typed or written in a URL: floats with round-trip precision."""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, float):
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        short = f"{value:g}"
        return short if float(short) == value else repr(value)
    return str(value)


def _value(name: str, text: str) -> object:
    if name in ("mode", "axis", "inplane_on", "friction", "rs_law"):
        return text
    if name == "log_x":
        return text.strip().lower() in ("1", "true", "yes", "on")
    if name == "points":
        n = int(parse_number(name, text))
        if not 2 <= n <= 2000:
            raise ValueError(f"points must be an integer in [2, 2000], got {text!r}")
        return n
    return parse_number(name, text)


def format_value(value: float) -> str:
    """A float as shown in a typed-entry box (round-trips exactly)."""
    return _text(float(value))
