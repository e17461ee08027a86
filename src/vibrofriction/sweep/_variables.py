"""What an atlas holds: every variable with its dtype, fill value and CF-style attributes.

*Point* variables have one value per grid point (all dimensions); *row*
variables depend only on the non-velocity parameters (no ``direction``, no
velocity dimension).  The fill value of each is what a point not yet computed
reads as; ``status`` and ``final_phase`` use a code the solver never returns and
``trusted`` reads False, so an unfinished point is never mistaken for a result.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..schema import (
    FIELD,
    PARAMETERS,
    RESULT_FIELDS,
    STATE_FIELDS,
    STATE_PREFIX,
    STATUS_BY_CODE,
    VELOCITY_UNIT,
    Field,
    Status,
    parameter_names,
)
from ..solver import NO_PHASE, PHASE_NAMES

__all__ = ["COORD_ATTRS", "STATUS_PENDING", "Variable", "point_variables", "row_variables",
           "signature"]

STATUS_PENDING = -128  # fill value of `status` and `final_phase`: not computed yet

_VEL_UNIT = VELOCITY_UNIT  # unit of the inertial velocity (docs/model.md)


@dataclass(frozen=True)
class Variable:
    name: str
    dtype: str
    fill: float | int
    attrs: dict[str, Any] = field(default_factory=dict)
    source: str = ""  # key in solve_points' output (point variables)

    def empty(self, shape: tuple[int, ...]) -> np.ndarray:
        return np.full(shape, self.fill, dtype=self.dtype)


def _flag_words(text: str) -> str:
    return text.replace(" ", "_").replace("+", "_positive").replace("-", "_negative")


_STATUS_CODES = sorted(STATUS_BY_CODE)


#: The SI parameters of a physical sweep's rate-and-state law (``Physical.friction``).
_FRICTION_SI_ATTRS = {
    "friction_a": ("direct effect a of rate-and-state friction (mu_star = mu0)", "1", "a"),
    "friction_b": ("evolution effect b of rate-and-state friction", "1", "b"),
    "friction_d_c": ("critical slip distance of rate-and-state friction", "m", "d_c"),
    "friction_v_ref": ("reference slip velocity of rate-and-state friction", "m s-1",
                       "v_ref"),
    "friction_alpha_ld": ("Linker-Dieterich coefficient of rate-and-state friction", "1",
                          "alpha_LD"),
}

#: Attributes of every coordinate: the schema's parameters, a physical sweep's
#: rate-and-state law, and ``direction``.
COORD_ATTRS: dict[str, dict[str, Any]] = {
    **{p.name: p.attrs() for p in PARAMETERS},
    **{name: {"long_name": words, "units": units, "symbol": symbol,
              "equation": "docs/friction_laws.md"}
       for name, (words, units, symbol) in _FRICTION_SI_ATTRS.items()},
    "direction": {"long_name": "direction of the velocity continuation: each point starts "
                               "from the final state of its predecessor in this direction",
                  "symbol": ""},
}


def _status_attrs() -> dict[str, Any]:
    return {"long_name": FIELD["status"].long_name,
            "flag_values": [STATUS_PENDING, *_STATUS_CODES],
            "flag_meanings": " ".join(["not_computed", *(_flag_words(STATUS_BY_CODE[c].value)
                                                         for c in _STATUS_CODES)]),
            "comment": " | ".join(f"{STATUS_BY_CODE[c].value}: {STATUS_BY_CODE[c].message}"
                                  for c in _STATUS_CODES)}


def _trusted_attrs() -> dict[str, Any]:
    ok = [s.value for s in Status if s.ok]
    return {"long_name": FIELD["trusted"].long_name,
            "comment": f"converged status: {', '.join(ok[:-1])} or {ok[-1]}; tol_trusted is "
                       "the Dataset attribute solver_tol_trusted (SolverSettings.tol_trusted); "
                       "False where not computed yet",
            "flag_values": [0, 1], "flag_meanings": "not_trusted trusted"}


def _phase_attrs(prefix: str) -> dict[str, Any]:
    return {"long_name": prefix + FIELD["phase"].long_name,
            "flag_values": [STATUS_PENDING, NO_PHASE, *range(len(PHASE_NAMES))],
            "flag_meanings": " ".join(["not_computed", "no_state",
                                       *(_flag_words(p) for p in PHASE_NAMES)])}


def _fill(f: Field) -> float | int | bool:
    if f.name in ("status", "phase"):
        return STATUS_PENDING
    return {"f8": np.nan, "bool": False}.get(f.dtype, -1)


def point_variables(velocity: str) -> tuple[Variable, ...]:
    """Variables with one value per grid point (``velocity`` is the swept velocity's name).

    Every field of :data:`vibrofriction.schema.RESULT_FIELDS` stored under its name with its unit,
    long name and equation, ``v_inertial`` where another velocity is swept, and the final section
    state as ``final_*``.
    """
    special = {"status": _status_attrs, "trusted": _trusted_attrs}
    out = [Variable(f.name, f.dtype, _fill(f), special.get(f.name, f.attrs)(),
                    f.name)
           for f in RESULT_FIELDS if f.dtype and f.name != "v_inertial"]
    if velocity != "v_inertial":
        out.append(Variable("v_inertial", "f8", np.nan, dict(COORD_ATTRS["v_inertial"])))
    prefix = STATE_PREFIX
    out += [Variable(f"final_{f.name}", f.dtype, _fill(f),
                     _phase_attrs(prefix) if f.name == "phase" else f.attrs(prefix), f.name)
            for f in STATE_FIELDS]
    return tuple(out)


#: The critical velocity under the friction laws (docs/friction_laws.md).
_LAW_COMMENT = ("Coulomb friction's (eq. 12, mu0 the kinetic coefficient), also with a static "
                "coefficient above the kinetic one (static_ratio > 1: a sliding contact "
                "carries the kinetic force); nan for rate-and-state friction (rs_a > 0), "
                "for which eq. 12 does not hold")


def row_variables(kind: str) -> tuple[Variable, ...]:
    """Variables of the non-velocity parameters only (one value per curve)."""
    if kind == "dimensionless":
        return (Variable("critical_velocity", "f8", np.nan, {
            "long_name": "critical velocity of continuous forward sliding in inertial "
                         "units, damped (V at vbar = 1 without in-plane oscillation; with "
                         "one, the combined drive's, docs/inplane.md); undamped inf in case "
                         "IV (alpha = 1), 0 in case III (beta = 1); 0 at amplitude 0",
            "comment": _LAW_COMMENT,
            "symbol": "v0* m omega / (mu0 F_N0)", "units": _VEL_UNIT,
            "equation": "(12)"}),)
    return (
        Variable("critical_velocity", "f8", np.nan, {
            "long_name": "critical velocity above which the contact slides continuously "
                         "forward (with an in-plane oscillation, the combined drive's); inf "
                         "at k_x = m omega^2 (case IV), 0 at k_x + k_xc = m omega^2 (case "
                         "III)",
            "comment": _LAW_COMMENT,
            "symbol": "v0*", "units": "m s-1", "equation": "(12)"}),
        *(Variable(n, "f8", np.nan, dict(COORD_ATTRS[n]))
          for n in parameter_names("dimensionless", optional=False)  # from the SI ones
          if n not in parameter_names("physical")),  # phase_x: an SI parameter itself
    )


def signature(kind: str, velocity: str) -> dict[str, list]:
    """``{name: [dtype, fill]}`` of every variable: part of a store's signature."""
    def fill(v: Variable):
        return None if isinstance(v.fill, float) and np.isnan(v.fill) else np.asarray(
            v.fill).item()

    return {v.name: [v.dtype, fill(v)]
            for v in (*point_variables(velocity), *row_variables(kind))}
