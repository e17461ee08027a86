"""Validation messages: the library's ValueError, placed next to the input it names."""

from __future__ import annotations

import math
import re
from collections.abc import Mapping

from vibrofriction.capabilities import Refusal

from .state import FIELDS, MDR_REFUSED, State, parse_number

__all__ = ["GENERAL", "curved_refusal", "field_of", "read_inputs"]

#: the key of a message that names no single input (shown above the inputs)
GENERAL = "general"
# names the library uses for an input the explorer shows under another name
_ALIASES = {"du_z": "du_z_um", "dF_N": "du_z_um", "k_x": "mass",
            "vbar": "v_max", "v_inertial": "v_max", "v0": "v_max"}
_FIRST_WORD = re.compile(r"^\s*([A-Za-z_][A-Za-z_0-9]*)")


def field_of(message: str, mode: str = "dimensionless") -> str:
    """The input a library message is about (its first word), or :data:`GENERAL`."""
    m = _FIRST_WORD.match(message)
    word = m.group(1) if m else ""
    if word == "eta_c" and mode == "bench":
        return "bench_eta_c"
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
