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

from ..solver import FLOAT_COLUMNS, NO_PHASE, PHASE_NAMES, STATUS_BY_CODE

__all__ = ["COORD_ATTRS", "STATUS_PENDING", "Variable", "point_variables", "row_variables",
           "signature"]

STATUS_PENDING = -128  # fill value of `status` and `final_phase`: not computed yet

_VEL_UNIT = "mu0 F_N0 / (m omega)"  # unit of the inertial velocity (docs/model.md)


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

COORD_ATTRS: dict[str, dict[str, Any]] = {
    "alpha": {"long_name": "system stiffness over inertia, k_x / (m omega^2)",
              "symbol": "alpha", "units": "1", "equation": "(20)"},
    "beta": {"long_name": "system plus contact stiffness over inertia, "
                          "(k_x + k_xc) / (m omega^2); inf = rigid contact",
             "symbol": "beta", "units": "1", "equation": "(20)"},
    "amplitude": {"long_name": "relative amplitude of the normal oscillation, du_z / u_z0",
                  "symbol": "a", "units": "1", "equation": "(1), (24)"},
    "zeta": {"long_name": "damping ratio of the pin, c_x / (2 sqrt(k_x m)) = 1/(2Q)",
             "symbol": "zeta", "units": "1", "equation": "docs/damping.md"},
    "eta_c": {"long_name": "loss factor of the contact at the drive frequency, "
                           "omega c_xc / k_xc",
              "symbol": "eta_c", "units": "1", "equation": "docs/damping.md"},
    "c_x": {"long_name": "pin dashpot parallel to k_x", "symbol": "c_x", "units": "N s m-1"},
    "c_xc": {"long_name": "tangential contact dashpot parallel to k_xc (Kelvin-Voigt)",
             "symbol": "c_x,c", "units": "N s m-1"},
    "vbar": {"long_name": "sliding velocity over the critical velocity, v0 / v0*",
             "symbol": "vbar", "units": "1", "equation": "(16)"},
    "v_inertial": {"long_name": "inertial sliding velocity, v0 m omega / (mu0 F_N0)",
                   "symbol": "v0 m omega / (mu0 F_N0)", "units": _VEL_UNIT,
                   "equation": "Fig. 6"},
    "v0": {"long_name": "sliding velocity of the drive", "symbol": "v0", "units": "m s-1"},
    "mass": {"long_name": "mass of the body", "symbol": "m", "units": "kg"},
    "k_x": {"long_name": "tangential stiffness of the system spring", "symbol": "k_x",
            "units": "N m-1"},
    "k_xc": {"long_name": "tangential contact stiffness; inf = rigid contact",
             "symbol": "k_x,c", "units": "N m-1"},
    "k_zc": {"long_name": "normal contact stiffness", "symbol": "k_z,c", "units": "N m-1"},
    "u_z0": {"long_name": "mean indentation", "symbol": "u_z0", "units": "m",
             "equation": "(1)"},
    "du_z": {"long_name": "amplitude of the normal oscillation", "symbol": "Delta u_z",
             "units": "m", "equation": "(1)"},
    "omega": {"long_name": "angular frequency of the normal oscillation", "symbol": "omega",
              "units": "rad s-1"},
    "mu0": {"long_name": "local (microscopic) coefficient of friction", "symbol": "mu0",
            "units": "1"},
    "direction": {"long_name": "direction of the velocity continuation: each point starts "
                               "from the final state of its predecessor in this direction",
                  "symbol": ""},
}

#: How the steady state was reached (solver columns; those the solver returns are stored).
_ORBIT_ATTRS: dict[str, dict[str, Any]] = {
    "multiplier": {"long_name": "modulus of the leading Floquet multiplier of the periodic "
                                "orbit (contraction per orbit period; nan if not periodic)",
                   "symbol": "|lambda|", "units": "1"},
    "settling_periods": {"long_name": "drive periods the motion from the initial state "
                                      "needs to come within error of the steady state",
                         "symbol": "", "units": "drive periods"},
    "window_min": {"long_name": "smallest mean of mu_ratio over the averaging windows "
                                "(averaged and not converged results; nan otherwise)",
                   "symbol": "", "units": "1"},
    "window_max": {"long_name": "largest mean of mu_ratio over the averaging windows "
                                "(averaged and not converged results; nan otherwise)",
                   "symbol": "", "units": "1"},
    "drift_rate": {"long_name": "change of the averaging windows' means per drive period where "
                                "the last three move one way (0 where they do not; nan with "
                                "fewer windows)",
                   "symbol": "", "units": "1 / drive period"},
}


def point_variables(velocity: str) -> tuple[Variable, ...]:
    """Variables with one value per grid point; ``velocity`` is the swept velocity's name."""
    out = [
        Variable("mu_ratio", "f8", np.nan, {
            "long_name": "macroscopic coefficient of friction over the local one in the "
                         "steady state, <F_x>/(mu0 <F_N>)",
            "symbol": "mu_macro / mu0", "units": "1", "equation": "(25)"}, "mu_ratio"),
        Variable("status", "i1", STATUS_PENDING, {
            "long_name": "how the steady state was obtained",
            "flag_values": [STATUS_PENDING, *_STATUS_CODES],
            "flag_meanings": " ".join(
                ["not_computed", *(_flag_words(STATUS_BY_CODE[c].value) for c in _STATUS_CODES)]),
            "comment": " | ".join(f"{STATUS_BY_CODE[c].value}: {STATUS_BY_CODE[c].message}"
                                  for c in _STATUS_CODES)}, "status"),
        Variable("error", "f8", np.nan, {
            "long_name": "estimated absolute error of mu_ratio, |mu_ratio - exact|",
            "symbol": "", "units": "1"}, "error"),
        Variable("trusted", "bool", False, {
            "long_name": "the result is trusted: converged status and error <= tol_trusted",
            "comment": "converged status: periodic, averaged, continuous sliding or static "
                       "limit; tol_trusted is the Dataset attribute solver_tol_trusted "
                       "(SolverSettings.tol_trusted); False where not computed yet",
            "flag_values": [0, 1], "flag_meanings": "not_trusted trusted"}, "trusted"),
        Variable("period", "i4", -1, {
            "long_name": "period of the steady orbit in drive periods (0 = not periodic)",
            "symbol": "", "units": "1"}, "period"),
        Variable("periods", "i4", -1, {
            "long_name": "drive periods integrated", "symbol": "", "units": "1"}, "periods"),
        Variable("events", "i8", -1, {
            "long_name": "phase transitions integrated (stick, slip, lift-off, touchdown)",
            "symbol": "", "units": "1"}, "events"),
        Variable("stick_fraction", "f8", np.nan, {
            "long_name": "fraction of time the contact sticks (averaging window)",
            "symbol": "", "units": "1"}, "stick_fraction"),
        Variable("slip_fraction", "f8", np.nan, {
            "long_name": "fraction of time the contact slips forward (averaging window)",
            "symbol": "", "units": "1"}, "slip_fraction"),
        Variable("reverse_slip_fraction", "f8", np.nan, {
            "long_name": "fraction of time the contact slips backward (averaging window)",
            "symbol": "", "units": "1"}, "reverse_slip_fraction"),
        Variable("flight_fraction", "f8", np.nan, {
            "long_name": "fraction of time without contact, jumping (averaging window)",
            "symbol": "", "units": "1"}, "flight_fraction"),
    ]
    out += [Variable(name, "f8", np.nan, dict(attrs), name)
            for name, attrs in _ORBIT_ATTRS.items() if name in FLOAT_COLUMNS]
    if velocity != "v_inertial":
        out.append(Variable("v_inertial", "f8", np.nan, dict(COORD_ATTRS["v_inertial"])))
    out += [
        Variable("final_y", "f8", np.nan, {
            "long_name": "final state on the Poincare section tau = 2 pi k: body "
                         "displacement without the drift, y = x - V tau",
            "symbol": "y", "units": "mu0 F_N0 / (m omega^2)"}, "y"),
        Variable("final_x_dot", "f8", np.nan, {
            "long_name": "final state on the Poincare section: body velocity",
            "symbol": "x'", "units": _VEL_UNIT}, "x_dot"),
        Variable("final_f", "f8", np.nan, {
            "long_name": "final state on the Poincare section: tangential contact force",
            "symbol": "f", "units": "mu0 F_N0"}, "f"),
        Variable("final_e", "f8", np.nan, {
            "long_name": "final state on the Poincare section: elongation of the contact "
                         "spring, x - x_c (0 for a rigid contact)",
            "symbol": "e", "units": "mu0 F_N0 / (m omega^2)"}, "e"),
        Variable("final_phase", "i1", STATUS_PENDING, {
            "long_name": "final state on the Poincare section: phase of the contact",
            "flag_values": [STATUS_PENDING, NO_PHASE, *range(len(PHASE_NAMES))],
            "flag_meanings": " ".join(["not_computed", "no_state",
                                       *(_flag_words(p) for p in PHASE_NAMES)])}, "phase"),
    ]
    return tuple(out)


def row_variables(kind: str) -> tuple[Variable, ...]:
    """Variables of the non-velocity parameters only (one value per curve)."""
    if kind == "dimensionless":
        return (Variable("critical_velocity", "f8", np.nan, {
            "long_name": "critical velocity v0* in inertial units (V at vbar = 1), damped; "
                         "undamped inf in case IV (alpha = 1), 0 in case III (beta = 1); "
                         "0 at amplitude 0",
            "symbol": "v0* m omega / (mu0 F_N0)", "units": _VEL_UNIT,
            "equation": "(12)"}),)
    return (
        Variable("critical_velocity", "f8", np.nan, {
            "long_name": "critical velocity above which the contact slides continuously; "
                         "inf at k_x = m omega^2 (case IV), 0 at k_x + k_xc = m omega^2 "
                         "(case III)",
            "symbol": "v0*", "units": "m s-1", "equation": "(12)"}),
        Variable("alpha", "f8", np.nan, dict(COORD_ATTRS["alpha"])),
        Variable("beta", "f8", np.nan, dict(COORD_ATTRS["beta"])),
        Variable("amplitude", "f8", np.nan, dict(COORD_ATTRS["amplitude"])),
        Variable("zeta", "f8", np.nan, dict(COORD_ATTRS["zeta"])),
        Variable("eta_c", "f8", np.nan, dict(COORD_ATTRS["eta_c"])),
    )


def signature(kind: str, velocity: str) -> dict[str, list]:
    """``{name: [dtype, fill]}`` of every variable: part of a store's signature."""
    def fill(v: Variable):
        return None if isinstance(v.fill, float) and np.isnan(v.fill) else np.asarray(
            v.fill).item()

    return {v.name: [v.dtype, fill(v)]
            for v in (*point_variables(velocity), *row_variables(kind))}
