"""What the normal and the in-plane design share.

The solver at design points, the map's axes, the status of an optimum and the sensitivity table of
the chosen oscillation.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from ...params import Physical
from ...solver import SolverSettings, solve_points
from ...validation import checked
from .result import DESIGN_STATUSES

#: Relative changes of the drive frequency in the sensitivity table.
FREQUENCY_CHANGES = (-0.05, -0.01, 0.01, 0.05)


#: Changes of the in-plane phase (rad) in the sensitivity table of an in-plane design.
PHASE_CHANGES = (-0.1, 0.1)


#: Relative change of each pin parameter in the sensitivity table.
PARAMETER_CHANGE = 0.10


PIN_PARAMETERS = ("mass", "k_x", "k_xc", "k_zc", "c_x", "mu0")


#: With ``du_z = (0, hi)`` the map's amplitudes are 0 and ``hi`` down to this fraction of it.
ZERO_AMPLITUDE_FLOOR = 1e-2


def checked_range(name: str, value, *, allow_zero: bool = False) -> tuple[float, float]:
    """``(low, high)`` of a range given as a pair, both > 0 (>= 0 with ``allow_zero``)."""
    try:
        lo, hi = (float(x) for x in value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a pair (low, high), got {value!r}") from None
    checked(name, np.array([lo, hi]), minimum=0.0, strict=not allow_zero)
    if not lo <= hi:
        raise ValueError(f"{name}: low {lo!r} > high {hi!r}")
    return lo, hi


def solve_design(pin: Physical, v0: float, omega, du_z, settings: SolverSettings | None,
           du_x=0.0, phase_x=0.0, inplane_on: str = "substrate", du_y=0.0,
           phase_y=0.0) -> dict[str, np.ndarray]:
    """The COF and its trust of ``pin`` driven at design points.

    ``cof`` (nan where not trusted), ``mu_ratio``, ``error`` and ``trusted`` of ``pin``
    driven at ``omega`` (rad/s) with ``du_z`` (m) and the in-plane ``du_x``, ``du_y`` (m),
    ``phase_x``, ``phase_y`` on ``inplane_on``, at the sliding velocity ``v0`` (m/s)
    (:meth:`Physical.point_arguments`, the fit's conversion too; ``du_y > 0``: the 2-D
    solver, with the pin's ``k_y``, ``c_y``), with the pin's friction law at each ``omega``
    (:meth:`Physical.law_arguments`).
    """
    omega, du_z, du_x, phase_x, du_y, phase_y = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (omega, du_z, du_x, phase_x, du_y, phase_y)))
    args: tuple[Any, ...] = pin.point_arguments(v0, du_z, omega, du_x, phase_x, du_y, phase_y)
    out = solve_points(*args, profile_exponent=pin.profile_exponent,  # type: ignore[misc]
                       inplane_on=inplane_on,  # args: the 12 groups before profile_exponent
                       settings=settings, **pin.law_arguments(omega))
    trusted = out["trusted"]
    return {"cof": np.where(trusted, pin.mu0 * out["mu_ratio"], np.nan),
            "mu_ratio": out["mu_ratio"], "error": out["error"], "trusted": out["trusted"]}


def map_axes_2d(pin: Physical, w_range, d_range, n_omega: int, n_du_z: int):
    """The map's frequencies and amplitudes, logarithmic.

    The frequencies with the resonances inside, the amplitudes with 0 included when the range starts
    there.
    """
    (w_lo, w_hi), (d_lo, d_hi) = w_range, d_range
    ws = np.geomspace(w_lo, w_hi, n_omega)
    resonances = [math.sqrt(pin.k_x / pin.mass)]
    if math.isfinite(pin.k_xc):
        resonances.append(math.sqrt((pin.k_x + pin.k_xc) / pin.mass))
    ws = np.unique(np.concatenate([ws, [w for w in resonances if w_lo <= w <= w_hi]]))
    if d_hi == 0.0:
        ds = np.zeros(1)
    elif d_lo == 0.0:
        ds = np.concatenate([[0.0], np.geomspace(ZERO_AMPLITUDE_FLOOR * d_hi, d_hi,
                                                 max(n_du_z - 1, 1))])
    else:
        ds = np.unique(np.geomspace(d_lo, d_hi, n_du_z))
    return ws, ds


def log_step(axis: np.ndarray) -> float:
    """The logarithmic step of a map axis (its positive values), 0.1 for one value."""
    positive = axis[axis > 0]
    return math.log(positive[1] / positive[0]) if positive.size > 1 else 0.1


def untrusted_near(untrusted: np.ndarray, ws, ds, w_opt: float, d_opt: float) -> int:
    """Untrusted map points among the neighbours of the map point nearest the optimum."""
    i = int(np.argmin(np.abs(np.log(ws / w_opt))))
    with np.errstate(divide="ignore"):
        j = int(np.argmin(np.abs(ds - d_opt) if d_opt == 0.0 else
                          np.abs(np.log(np.where(ds > 0.0, ds, 0.0) / d_opt))))
    return int(untrusted[max(i - 1, 0):i + 2, max(j - 1, 0):j + 2].sum())


def map_status(untrusted: np.ndarray, feasible: np.ndarray, near: int, n_rejected: int,
            rejected_run: int) -> tuple[str, str]:
    """The key of :data:`DESIGN_STATUSES` and its message with the counts."""
    status = ("untrusted_near_optimum" if near or rejected_run else
              "untrusted_in_map" if untrusted.any() else "trusted")
    return status, (f"{DESIGN_STATUSES[status]} ({int(untrusted.sum())} of "
                    f"{int(feasible.sum())} map points within the limits untrusted, {near} "
                    f"next to the optimum; {n_rejected} untrusted evaluations rejected by the "
                    f"refinement, {rejected_run} in the run that found the optimum)")


def map_dataset(ws, ds, sol, feasible, attrs) -> xr.Dataset:
    """The map over ``(omega, du_z)`` as an xarray Dataset with named, described variables."""
    dims = ("omega", "du_z")
    return xr.Dataset(
        {"cof": (dims, sol["cof"], {"long_name": "coefficient of friction mu0 mu/mu0 "
                                                 "(nan where not trusted)"}),
         "mu_ratio": (dims, sol["mu_ratio"], {"long_name": "mu_macro/mu0 as the solver "
                                                           "left it (trusted or not)"}),
         "error": (dims, sol["error"], {"long_name": "estimate of |mu_ratio - exact|"}),
         "trusted": (dims, sol["trusted"]),
         "feasible": (dims, feasible, {"long_name": "omega du_z <= max_velocity_amplitude"})},
        coords={"omega": ("omega", ws, {"units": "rad s-1"}),
                "du_z": ("du_z", ds, {"units": "m"})},
        attrs=attrs)


def sensitivity_table(chosen: Physical, v0: float, settings: SolverSettings | None) -> pd.DataFrame:
    """The COF at the optimum and at its neighbours in frequency and pin parameters.

    The COF at the optimum, with the frequency off by ``FREQUENCY_CHANGES`` and each
    pin parameter off by ``PARAMETER_CHANGE`` (nan and ``trusted`` False where the
    solver does not trust its value), and so each parameter of its friction law
    (:func:`_law_cases`; ``mu0`` of a pin with a static coefficient moves ``mu_static`` with it).
    """
    cases = [("optimum", chosen, chosen.omega)]
    cases += [(f"frequency {100 * c:+.0f} %", chosen, chosen.omega * (1 + c))
              for c in FREQUENCY_CHANGES]
    if chosen.du_x > 0.0:
        cases += [(f"phase_x {c:+.2f} rad", chosen.with_(phase_x=chosen.phase_x + c),
                   chosen.omega) for c in PHASE_CHANGES]
    if chosen.du_y > 0.0 and chosen.du_z > 0.0:  # without a normal one it means nothing
        cases += [(f"phase_y {c:+.2f} rad", chosen.with_(phase_y=chosen.phase_y + c),
                   chosen.omega) for c in PHASE_CHANGES]
    for name in PIN_PARAMETERS:
        base = getattr(chosen, name)
        if base == 0.0 or not math.isfinite(base):
            continue
        for sign in (-1, 1):
            change = {name: base * (1 + sign * PARAMETER_CHANGE)}
            if name == "mu0" and chosen.mu_static is not None:  # the ratio kept: mu_static >= mu0
                change["mu_static"] = chosen.static_ratio * change["mu0"]
            p = chosen.with_(**change)
            cases.append((f"{name} {sign * 100 * PARAMETER_CHANGE:+.0f} %", p, p.omega))
    cases += _law_cases(chosen)
    rows = []
    for label, pin, w in cases:
        sol = solve_design(pin, v0, w, pin.du_z, settings, pin.du_x, pin.phase_x, pin.inplane_on,
                     pin.du_y, pin.phase_y)
        rows.append((label, float(sol["cof"]), bool(sol["trusted"])))
    return pd.DataFrame(rows, columns=["change", "cof", "trusted"])


def _law_cases(chosen: Physical) -> list[tuple[str, Physical, float]]:
    """The sensitivity table's rows of the friction law, each parameter off by ``PARAMETER_CHANGE``.

    ``mu_static`` (where it stays ``>= mu0``) of a static coefficient; ``a``, ``b``, ``d_c``,
    ``v_ref`` (where not 0) of rate-and-state friction.
    """
    out = []
    for sign in (-1, 1):
        factor = 1 + sign * PARAMETER_CHANGE
        label = f"{sign * 100 * PARAMETER_CHANGE:+.0f} %"
        if chosen.mu_static is not None and chosen.mu_static * factor >= chosen.mu0:
            out.append((f"mu_static {label}", chosen.with_(mu_static=chosen.mu_static * factor),
                        chosen.omega))
        law = chosen.friction
        if law is None:
            continue
        for name in ("a", "b", "d_c", "v_ref"):
            base = getattr(law, name)
            if base > 0.0:
                p = chosen.with_(friction=dataclasses.replace(law, **{name: base * factor}))
                out.append((f"{name} {label}", p, chosen.omega))
    return out
