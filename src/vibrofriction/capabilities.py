"""What each solver covers, declared once (standard library and the schema only).

Four solvers stand behind :func:`~vibrofriction.solver.solve_points`: the 1-D
event-driven solver (``event``), the 2-D solver (``plane``), the MDR solver of curved
tips (``mdr``) and the rate-and-state solver of a flat punch (``rate_state``).  Each
one's :class:`Capabilities` say which points it is chosen for, the parameters it uses, the
points it refuses (:class:`Limit`), the initial states, settings (with its own defaults),
outputs, sensitivities and histories it covers.  The solvers
(:mod:`vibrofriction.solver.methods`) check points against them, and the refusal
messages, the command line's help, the explorer's disabled controls and the table "what
each solver covers" (docs/solver.md, :func:`capability_table`) are made from them.  This
module imports no numpy and no kernel, so that the command line's ``--help`` can read it.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

__all__ = ["CAPABILITIES", "EVENT", "FRICTION_LAWS", "INITIAL_KINDS", "MDR", "PLANE",
           "RATE_STATE", "Capabilities", "Limit", "Refusal", "capability_table", "friction_laws",
           "refused_by"]

#: The kinds of initial state, by the kernels' code: steady sliding, rest, a section state.
INITIAL_KINDS = ("sliding", "rest", "section state")


class Refusal(ValueError):
    """A point, initial state or setting a method does not cover.

    ``parameter`` names the input refused: a parameter, ``"initial"`` or
    ``"settings.<field>"``.
    """

    def __init__(self, message: str, parameter: str) -> None:
        super().__init__(message)
        self.parameter = parameter


@dataclass(frozen=True)
class Limit:
    """Points a method does not cover: ``what`` in words, named by ``parameter``.

    ``refuses(points)`` is True at the points refused (a boolean array over a
    :class:`~vibrofriction.solver.points.PointTable`); ``whole``:
    every value of ``parameter`` but its default is refused (a control to disable).
    """

    parameter: str
    what: str
    refuses: Callable[[Any], Any]
    whole: bool = False


@dataclass(frozen=True)
class Capabilities:
    """What a method covers, declared once.

    Parameters
    ----------
    name : str
        Its name in :data:`~vibrofriction.schema.METHOD_NAMES` (a result's ``method``).
    title : str
        What it is, for messages: ``"the MDR solver"``.
    takes : str
        The points it is chosen for, in words (:func:`vibrofriction.solver.methods.choose`).
    parameters : tuple of str
        The parameters it uses; the others do not change its results.
    limits : tuple of Limit
        The points it is chosen for but does not cover (refused with ``ValueError``).
    initial : tuple of str
        The initial states it starts from (:data:`INITIAL_KINDS`); the others are refused
        at ``V != 0``.
    settings : mapping
        The :class:`~vibrofriction.solver.SolverSettings` fields it honours, with its own
        default of each (a field set and not honoured is refused).
    outputs : tuple of str
        The output columns it computes (the others are nan, or 0 for an integer column).
    sensitivities : bool
        :func:`~vibrofriction.solver.friction_gradient` covers its points.
    histories : bool
        :func:`~vibrofriction.solver.simulate` covers its points.
    velocities : str
        How it treats ``V`` (the sign, ``V = 0``), in words.
    """

    name: str
    title: str
    takes: str
    parameters: tuple[str, ...]
    limits: tuple[Limit, ...]
    initial: tuple[str, ...]
    settings: Mapping[str, float | int]
    outputs: tuple[str, ...]
    sensitivities: bool
    histories: bool
    velocities: str
    notes: tuple[str, ...] = field(default=())

    def check(self, points: Any, init_kind: int, settings: Any) -> None:
        """Refuse the first point of ``points`` (all chosen for this method) it does not cover.

        Raises
        ------
        Refusal
            Naming the parameter and its value, the initial state or the setting.
        """
        for limit in self.limits:
            bad = limit.refuses(points)
            if bad.any():
                i = int(bad.argmax())
                raise Refusal(f"{self.title} ({self.takes}) does not take {limit.what}: "
                              f"got {limit.parameter} = {_number(points[limit.parameter][i])}",
                              limit.parameter)
        kind = INITIAL_KINDS[init_kind]
        if kind not in self.initial and (points["v_inertial"] != 0.0).any():
            raise Refusal(f"initial = {kind}: {self.title} ({self.takes}) starts from "
                          f"{' or '.join(self.initial)} only", "initial")
        self.check_settings(settings)

    def check_settings(self, settings: Any) -> None:
        """Refuse a field of ``settings`` that was set (not None) and is not honoured here.

        Raises
        ------
        Refusal
            Naming the first such field.
        """
        unknown = [k for k in settings.chosen() if k not in self.settings]
        if unknown:
            raise Refusal(f"settings.{unknown[0]} = {getattr(settings, unknown[0])} is not "
                          f"honoured by {self.title} ({self.takes}), which takes "
                          f"{', '.join(self.settings)} and tol_trusted: leave it None "
                          "(each method's default)", f"settings.{unknown[0]}")


def _number(x: float) -> str:
    """A number as a user writes it (``inf``, ``0.5``)."""
    return "inf" if math.isinf(x) and x > 0 else f"{float(x):g}"



_ALL_FLOAT = ("mu_ratio", "error", "work", "stick_fraction", "slip_fraction",
              "reverse_slip_fraction", "flight_fraction", "multiplier", "settling_periods",
              "window_min", "window_max", "drift_rate", "lateral_ratio", "mean_normal_ratio",
              "stick_area_fraction", "slip_area_fraction", "open_area_fraction",
              "sliding_mu_ratio", "y", "x_dot", "f", "e")


EVENT = Capabilities(
    name="event",
    title="the 1-D event-driven solver",
    takes="a flat punch, profile_exponent = inf, without a transverse oscillation, a_y = 0",
    parameters=("alpha", "beta", "amplitude", "zeta", "eta_c", "a_x", "phase_x",
                "v_inertial", "inplane_on", "static_ratio"),
    limits=(
        Limit("static_ratio", "a static coefficient above the kinetic one at v_inertial = 0 "
              "(its static limit depends on the dynamics of the slips: give a velocity != 0)",
              lambda p: (p["static_ratio"] != 1.0) & (p["v_inertial"] == 0.0)),
    ),
    initial=INITIAL_KINDS,
    settings={"max_periods": 20_000, "min_periods": 64, "tol_state": 1e-10,
              "tol_mean": 1e-7, "max_events": 20_000_000},
    outputs=(*_ALL_FLOAT, "status", "period", "periods", "events", "phase",
             "degenerate"),
    sensitivities=True,
    histories=True,
    velocities="every V: V < 0 by the mirror x -> -x; V = 0 the static limit (eq. 2), "
               "or with a_x > 0 integrated from rest (HELD where the contact can "
               "stick through whole cycles)",
)

PLANE = Capabilities(
    name="plane",
    title="the 2-D solver",
    takes="a flat punch, profile_exponent = inf, with a transverse oscillation, a_y > 0",
    parameters=("alpha", "beta", "amplitude", "zeta", "eta_c", "a_x", "phase_x", "a_y",
                "phase_y", "alpha_y", "zeta_y", "static_ratio", "v_inertial", "inplane_on"),
    limits=(
        Limit("beta", "a rigid contact (beta = inf; use a large finite beta)",
              lambda p: p["beta"] == math.inf),
        Limit("amplitude", "grazing (amplitude = 1) with eta_c = 0",
              lambda p: (p["amplitude"] == 1.0) & (p["eta_c"] == 0.0)),
        Limit("rs_a", "rate-and-state friction (rs_a > 0)", lambda p: p["rs_a"] > 0.0,
              whole=True),
    ),
    initial=INITIAL_KINDS,
    settings={"max_periods": 20000, "max_events_per_period": 10_000, "rtol": 1e-10},
    outputs=("mu_ratio", "error", "work", "stick_fraction", "slip_fraction",
             "reverse_slip_fraction", "flight_fraction", "multiplier",
             "settling_periods", "window_min", "window_max", "drift_rate",
             "lateral_ratio", "mean_normal_ratio", "stick_area_fraction",
             "slip_area_fraction", "open_area_fraction", "sliding_mu_ratio", "y", "x_dot",
             "f", "e", "status", "period", "periods", "events", "phase", "degenerate"),
    sensitivities=False,
    histories=True,
    velocities="every V: V < 0 by the mirror x -> -x; V = 0 by plain iteration of the "
               "period map (HELD where a stuck contact can hold a region of mean forces)",
)

MDR = Capabilities(
    name="mdr",
    title="the MDR solver",
    takes="a curved tip, profile_exponent finite",
    parameters=("alpha", "beta", "amplitude", "zeta", "a_x", "phase_x",
                "profile_exponent", "static_ratio", "v_inertial", "inplane_on"),
    limits=(
        Limit("beta", "a rigid contact (beta = inf)", lambda p: p["beta"] == math.inf),
        Limit("eta_c", "contact damping (eta_c > 0)", lambda p: p["eta_c"] > 0.0,
              whole=True),
        Limit("a_y", "a transverse in-plane oscillation (a_y > 0)",
              lambda p: p["a_y"] > 0.0, whole=True),
        Limit("a_x", "a longitudinal in-plane oscillation at v_inertial = 0 (springs "
              "that stick through whole cycles keep the elongation of the start, so "
              "the steady state depends on it; give a velocity != 0)",
              lambda p: (p["a_x"] > 0.0) & (p["v_inertial"] == 0.0)),
        Limit("static_ratio", "a static coefficient above the kinetic one at v_inertial = 0 "
              "(its static limit depends on the dynamics of the slips: give a velocity != 0)",
              lambda p: (p["static_ratio"] != 1.0) & (p["v_inertial"] == 0.0)),
        Limit("rs_a", "rate-and-state friction (rs_a > 0)", lambda p: p["rs_a"] > 0.0,
              whole=True),
    ),
    initial=("sliding",),
    settings={"max_periods": 4000, "tol_state": 1e-11},
    outputs=("mu_ratio", "error", "status", "period", "periods", "events",
             "lateral_ratio", "mean_normal_ratio", "stick_area_fraction",
             "slip_area_fraction", "open_area_fraction", "sliding_mu_ratio", "phase"),
    sensitivities=False,
    histories=True,
    velocities="every V: V < 0 by the mirror x -> -x; V = 0 the static limit of the "
               "tip (theory.profile_static_mu_ratio)",
    notes=("a point with 0 < amplitude < 1 or amplitude > 1, v_inertial != 0 and "
           "static_ratio = 1 is solved by the row without springs (no discretisation of "
           "the contact), at every tol_trusted; it ends its search at tol_state where given "
           "(at the tightest 1e-9 of its section state), else at 0.3 tol_trusted within "
           "[1e-9, 1e-7]",
           "elsewhere, where the row without springs fails, or where n_springs is given, "
           "rows of springs are refined until their error is at most tol_trusted"),
)

RATE_STATE = Capabilities(
    name="rate_state",
    title="the rate-and-state solver",
    takes="a flat punch, profile_exponent = inf, without a transverse oscillation, a_y = 0, "
          "with rate-and-state friction, rs_a > 0",
    parameters=("alpha", "beta", "amplitude", "zeta", "eta_c", "a_x", "phase_x", "v_inertial",
                "inplane_on", "rs_a", "rs_b", "rs_d_c", "rs_v_ref", "rs_alpha_ld", "rs_law"),
    limits=(
        Limit("v_inertial", "zero velocity (v_inertial = 0: the contact creeps, there is no "
              "static limit)", lambda p: p["v_inertial"] == 0.0),
    ),
    initial=("sliding",),
    settings={"rtol": 1e-7, "max_periods": 4000, "tol_mean": 1e-6},
    outputs=("mu_ratio", "error", "status", "period", "periods", "events", "work",
             "flight_fraction", "multiplier", "settling_periods", "window_min", "window_max",
             "lateral_ratio", "mean_normal_ratio", "open_area_fraction", "sliding_mu_ratio",
             "y", "x_dot", "f", "e", "phase"),
    sensitivities=False,
    histories=True,
    velocities="V > 0; V < 0 by the mirror x -> -x; V = 0 refused (the contact creeps)",
    notes=("error: twice the change of the orbit's mean from rtol to rtol/20 plus the next "
           "Newton step's; averaged results: the range of the last three windows' means plus "
           "twice the change of the last period's mean at rtol/20",),
)

#: Every solver's declaration by name (:data:`vibrofriction.schema.METHOD_NAMES`, in order).
CAPABILITIES: dict[str, Capabilities] = {"event": EVENT, "plane": PLANE, "mdr": MDR,
                                         "rate_state": RATE_STATE}


def refused_by(parameter: str) -> list[Capabilities]:
    """The solvers that refuse every value of ``parameter`` but its default.

    A :class:`Limit` with ``whole`` set; the command line names them in the help.
    """
    return [c for c in CAPABILITIES.values()
            if any(lim.whole and lim.parameter == parameter for lim in c.limits)]


def capability_table() -> str:
    """What each solver covers, as a Markdown table (docs/solver.md includes it)."""
    caps = list(CAPABILITIES.values())
    rows = [
        ("chosen for", [c.takes for c in caps]),
        ("parameters used", [", ".join(f"`{p}`" for p in c.parameters) for c in caps]),
        ("refuses", ["; ".join(f"{lim.what} (`{lim.parameter}`)" for lim in c.limits)
                     or "nothing" for c in caps]),
        ("velocities", [c.velocities for c in caps]),
        ("initial states", [", ".join(c.initial) for c in caps]),
        ("settings honoured (default)",
         [", ".join(f"`{k}` ({v:,})" if isinstance(v, int) else f"`{k}` ({v:g})"
                    for k, v in c.settings.items()) + ", `tol_trusted`"
          for c in caps]),
        ("outputs (the rest nan)", [_outputs(c) for c in caps]),
        ("local friction laws", [", ".join(friction_laws(c)) for c in caps]),
        ("sensitivities", ["yes" if c.sensitivities else "no" for c in caps]),
        ("time histories", ["yes" if c.histories else "no" for c in caps]),
    ]
    head = "| | " + " | ".join(f"{c.title} (`{c.name}`)" for c in caps) + " |\n"
    head += "|---" * (len(caps) + 1) + "|\n"
    return head + "".join(f"| {k} | " + " | ".join(v) + " |\n" for k, v in rows)


#: The local friction laws and the parameter that switches each on (Coulomb's always holds).
FRICTION_LAWS = {"static above kinetic": "static_ratio", "rate-and-state": "rs_a"}


def friction_laws(c: Capabilities) -> list[str]:
    """The local friction laws ``c`` covers: Coulomb's, and each whose parameter it uses."""
    refused = {lim.parameter for lim in c.limits if lim.whole}
    # the rate-and-state solver is chosen for rs_a > 0 only (Coulomb goes to the others)
    coulomb = [] if c.name == "rate_state" else ["Coulomb"]
    return [*coulomb, *(law for law, p in FRICTION_LAWS.items()
                        if p in c.parameters and p not in refused)]


def _outputs(c: Capabilities) -> str:
    """The outputs of ``c``, or those of every method less the ones it leaves out."""
    every = {n for m in CAPABILITIES.values() for n in m.outputs}
    missing = sorted(every - set(c.outputs))
    return "all" if not missing else "all but " + ", ".join(f"`{n}`" for n in missing)
