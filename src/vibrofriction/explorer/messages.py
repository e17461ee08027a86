"""Validation messages: the library's ValueError, placed next to the input it names."""

from __future__ import annotations

import re
from collections.abc import Mapping

from .state import FIELDS, State, parse_number

__all__ = ["GENERAL", "field_of", "read_inputs"]

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
    if "v0* is" in message or "v0 (m/s) needs" in message:
        return "axis"
    word = _ALIASES.get(word, word)
    return word if word in FIELDS else GENERAL


def read_inputs(texts: Mapping[str, str], base: State) -> tuple[State | None, dict[str, str]]:
    """The typed ``texts`` over ``base``: the state and no message, or None and a message
    per offending input (parsing, then the library's validators through
    :meth:`State.system` and :meth:`State.velocities`)."""
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
    except (ValueError, TypeError) as exc:
        return None, {field_of(str(exc), state.mode): str(exc)}
    return state, {}


def _check_axis(state: State, system) -> None:
    """The chosen velocity axis exists for this system (the library's conversion says why
    not: ``vbar`` in the resonant cases, ``v0`` without a bench)."""
    import vibrofriction as vf

    if state.axis == "vbar":
        dim = system.to_dimensionless() if isinstance(system, vf.Physical) else system
        dim.vbar_to_inertial(1.0)
    elif state.axis == "v0" and not isinstance(system, vf.Physical):
        raise ValueError("v0 (m/s) needs a Physical system: choose the bench inputs, "
                         "or the axis vbar or V")
