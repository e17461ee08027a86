"""Validation messages: the library's ValueError, placed next to the input it names."""

from __future__ import annotations

import math
import re
from collections.abc import Mapping

from vibrofriction.capabilities import Refusal

from .state import FIELDS, LAW_DISABLED, MDR_REFUSED, State, parse_number

__all__ = ["GENERAL", "LAW", "curved_refusal", "field_of", "law_refusal", "law_taken",
           "read_inputs"]

#: the key of a message that names no single input (shown above the inputs)
GENERAL = "general"
#: the key of a message about the friction law itself (shown under its selector)
LAW = "friction"
# names the library uses for an input the explorer shows under another name
_ALIASES = {"du_z": "du_z_um", "dF_N": "du_z_um", "k_x": "mass",
            "vbar": "v_max", "v_inertial": "v_max", "v0": "v_max"}
# the bench's names of the rate-and-state law's inputs (vf.RateAndState's, in SI)
_BENCH_ALIASES = {"eta_c": "bench_eta_c", "a": "friction_a", "b": "friction_b",
                  "d_c": "friction_d_c_um", "v_ref": "friction_v_ref_mm_s",
                  "alpha_ld": "friction_alpha_ld"}
_FIRST_WORD = re.compile(r"^\s*([A-Za-z_][A-Za-z_0-9]*)")


def field_of(message: str, mode: str = "dimensionless") -> str:
    """The input a library message is about (its first word), or :data:`GENERAL`."""
    m = _FIRST_WORD.match(message)
    word = m.group(1) if m else ""
    if mode == "bench" and word in _BENCH_ALIASES:
        return _BENCH_ALIASES[word]
    if word in ("rs_law", "static_ratio") and "rs_a" in message:  # the laws' pairs
        return LAW
    if "v0* is" in message or "v0 (m/s) needs" in message or \
            (word == "vbar" and "curved tip" in message):
        return "axis"
    word = _ALIASES.get(word, word)
    return word if word in FIELDS else GENERAL


def read_inputs(texts: Mapping[str, str], base: State) -> tuple[State | None, dict[str, str]]:
    """The typed ``texts`` over ``base``.

    The state and no message, or None and a message per offending input (parsing, then the library's
    validators through :meth:`State.system` and :meth:`State.velocities`).
    """
    values: dict[str, float] = {}
    problems: dict[str, str] = {}
    for name, text in texts.items():
        try:
            values[name] = parse_number(name, text)
        except ValueError as exc:
            problems[name] = str(exc)
    if problems:
        return None, problems
    state = base.with_(**values)
    try:
        system = state.system()
        state.velocities()
        _check_axis(state, system)
        if state.curved:
            _check_curved(state)
        elif state.friction != "coulomb":
            _check_law(state, system)
    except Refusal as exc:  # a solver's declared limit names the input
        return None, {exc.parameter if exc.parameter in FIELDS else GENERAL: str(exc)}
    except (ValueError, TypeError) as exc:
        return None, {field_of(str(exc), state.mode): str(exc)}
    return state, {}


def _check_axis(state: State, system) -> None:
    """Check that the chosen velocity axis exists for this system.

    The chosen velocity axis exists for this system (the library's conversion says why
    not: ``vbar`` in the resonant cases, ``v0`` without a bench).
    """
    import vibrofriction as vf

    if state.axis == "vbar":
        dim = system.to_dimensionless() if isinstance(system, vf.Physical) else system
        dim.vbar_to_inertial(1.0)
    elif state.axis == "v0" and not isinstance(system, vf.Physical):
        raise ValueError("v0 (m/s) needs a Physical system: choose the bench inputs, "
                         "or the axis vbar or V")


def _check_curved(state: State) -> None:
    """The library's refusal of what the MDR solver does not take yet.

    The library's refusal of what the MDR solver does not take yet (``beta = inf``,
    ``eta_c``, ``a_y``): ``solve_points`` at ``V = 0``, the static limit, which validates
    the point as any other and computes nothing.  ``a_x`` is taken at ``V != 0`` (and
    refused at ``V = 0``, which the curve leaves out: :attr:`State.rest_refused`), so the
    check is without it (``Dimensionless`` has validated it).
    """
    from vibrofriction.solver import solve_points

    solve_points(state.alpha, state.beta, state.amplitude, 0.0, state.zeta, state.eta_c,
                 0.0, state.phase_x, state.a_y, state.phase_y,
                 profile_exponent=state.profile_exponent, inplane_on=state.inplane_on)


def _check_law(state: State, system) -> None:
    """The library's refusal of what the law's solver does not take (its declared limits).

    The state's point, at ``V = 1`` (``V = 0`` is left out of the curve:
    :attr:`State.rest_refused`), checked against the declaration of the solver that takes it;
    nothing is computed.
    """
    import vibrofriction as vf
    from vibrofriction.capabilities import CAPABILITIES
    from vibrofriction.solver.methods import choose
    from vibrofriction.solver.points import table_of
    from vibrofriction.solver.settings import DEFAULT_SETTINGS

    dim = system.to_dimensionless() if isinstance(system, vf.Physical) else system
    table = table_of(dim, 1.0)
    name = list(CAPABILITIES)[int(choose(dim.profile_exponent, dim.a_y, dim.rs_a))]
    CAPABILITIES[name].check(table, 0, DEFAULT_SETTINGS)


def law_refusal(state: State, name: str, value: float) -> str:
    """The library's message refusing ``name = value`` under the state's friction law.

    ``""`` where it is accepted; the other inputs the law disables at 0.
    """
    others = {n: 0.0 for n in LAW_DISABLED[state.friction]}
    probe = state.with_(mode="dimensionless", profile_exponent=math.inf,
                        **{**others, name: value})
    try:
        _check_law(probe, probe.system())
    except ValueError as exc:
        return str(exc)
    return ""


def law_taken(state: State) -> str:
    """Why a curved tip does not take the state's friction law (the library's refusal).

    ``""`` for Coulomb friction, a flat punch, or where the MDR solver's declaration covers
    the law.
    """
    if state.friction == "coulomb" or not state.curved:
        return ""
    beta = state.beta if math.isfinite(state.beta) else state.alpha + 1.0
    probe = state.with_(**{n: 0.0 for n in MDR_REFUSED}, beta=beta)
    try:
        _check_law(probe, probe.system())
    except ValueError as exc:
        return str(exc)
    return ""


def curved_refusal(state: State, name: str, value: float) -> str:
    """The library's message refusing ``name = value`` with a curved tip.

    The library's message refusing ``name = value`` with the state's curved tip (the
    other refused inputs at 0 and a finite ``beta``, so the message is about ``name``);
    ``""`` where it is accepted.
    """
    others = {n: 0.0 for n in MDR_REFUSED}
    beta = state.beta if math.isfinite(state.beta) else state.alpha + 1.0
    try:
        _check_curved(state.with_(**{**others, "beta": beta, name: value}))
    except ValueError as exc:
        return str(exc)
    return ""
