"""The in-plane and drive design.

The combined optimum, the best of each direction, the phase map and the drive characteristic.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from ...params import Physical
from ...solver import SolverSettings, solve_points
from ...validation import checked, checked_choice
from .evaluation import checked_range, map_status, sensitivity_table, solve_design
from .result import DesignResult
from .space import (
    AXES,
    BLOCKING_V,
    GOALS,
    PLANE_MAP,
    PLANE_STARTS,
    VELOCITY_RULES,
    Space,
    direction_row,
    objective_of,
    optimise,
    untrusted_near_nd,
)


def design_inplane(pin: Physical, *, v0, omega, du_z, du_x, phase_x, inplane_on, goal,
                    velocity_rule, vmax, n_omega, n_du_z, n_du_x, n_phase, starts,
                    settings, du_y=None, phase_y=None, n_du_y=4,
                    n_phase_y=4) -> DesignResult:
    """The in-plane and drive design: :func:`~vibrofriction.bench.design` with in-plane ranges."""
    v0, ranges, phase_x, phase_y, on, vmax = _inplane_inputs(
        pin, v0=v0, omega=omega, du_z=du_z, du_x=du_x, du_y=du_y, phase_x=phase_x,
        phase_y=phase_y, inplane_on=inplane_on, goal=goal, velocity_rule=velocity_rule,
        vmax=vmax, counts=(("n_omega", n_omega, 2), ("n_du_z", n_du_z, 2),
                           ("n_du_x", n_du_x, 2), ("n_phase", n_phase, 1),
                           ("starts", starts, 1), ("n_du_y", n_du_y, 2),
                           ("n_phase_y", n_phase_y, 1)))
    w_range, z_range, x_range, y_range = ranges
    space = Space(w_range, z_range, x_range, phase_x, vmax, velocity_rule)
    if not space.feasible(w_range[0], z_range[0], x_range[0]):
        raise ValueError(f"no oscillation in range respects max_velocity_amplitude = {vmax:g} "
                         f"m/s ({VELOCITY_RULES[velocity_rule]}): the smallest is "
                         f"{w_range[0] * math.hypot(z_range[0], x_range[0]):g}")
    sizes = (n_omega, n_du_z, n_du_x, n_phase)
    point, obj, grids, axes, sol, feasible, n_rejected, rejected_run = optimise(
        pin, v0, on, goal, space, sizes, starts, settings)
    # which direction: the best normal-only and longitudinal-only choices in the limits
    rows = [{"direction": "combined", "omega": point[0], "du_z": point[1], "du_x": point[2],
             "phase_x": point[3], "du_y": 0.0, "phase_y": 0.0, "cof": math.nan,
             "allowed": True}]
    rows += _direction_rows(pin, v0, on, goal, space, sizes, starts, settings)
    if y_range[1] > 0.0:  # across the sliding: the 2-D solver, a smaller map
        plane = Space(w_range, z_range, y_range, phase_y, vmax, velocity_rule, "y")
        rows += _transverse_rows(pin, v0, on, goal, plane,
                                 (n_omega, n_du_z, n_du_y, n_phase_y), starts, settings)
    choice = _best_choice(goal, rows, point, obj)
    point = choice[:4]
    # choice is (omega, du_z, du_x, phase_x, du_y, phase_y): mypy cannot count a star
    at_opt = solve_design(pin, v0, *choice[:2], settings, *choice[2:4], on, *choice[4:])  # type: ignore[call-arg]
    cof = float(at_opt["cof"])
    rows[0]["cof"] = cof
    directions = pd.DataFrame(rows)
    untrusted = feasible & ~sol["trusted"]
    near = untrusted_near_nd(untrusted, axes, point)
    status, message = map_status(untrusted, feasible, near, n_rejected, rejected_run)
    chosen = pin.with_(omega=point[0], du_z=point[1], du_x=point[2],
                       phase_x=point[3] if point[2] > 0.0 else 0.0, du_y=choice[4],
                       phase_y=choice[5] if choice[4] > 0.0 else 0.0, inplane_on=on)
    attrs = {"v0": v0, "goal": goal, "inplane_on": on, "velocity_rule": velocity_rule,
             "max_velocity_amplitude": vmax, "status": status,
             "n_untrusted": int(untrusted.sum()), "n_untrusted_near": near,
             "n_rejected": n_rejected, "optimum_cof": cof,
             **{f"optimum_{k}": v for k, v in zip((*AXES, "du_y", "phase_y"), choice,
                                                  strict=True)}}
    dmap = _dataset_nd(axes, sol, feasible, attrs)
    result = DesignResult(
        system=chosen, v0=v0, cof=cof, mu_ratio=cof / pin.mu0, error=float(at_opt["error"]),
        map=dmap, sensitivity=sensitivity_table(chosen, v0, settings), status=status,
        message=message, n_untrusted=int(untrusted.sum()), n_untrusted_near=near,
        n_rejected=n_rejected, goal=goal, velocity_rule=velocity_rule,
        directions=directions,
        phase_map=_phase_map(pin, v0, on, space, point, settings))
    if goal == "drive":
        _drive_characteristic(result, settings)
    return result


def _inplane_inputs(pin: Physical, *, v0, omega, du_z, du_x, du_y, phase_x, phase_y,
                    inplane_on, goal, velocity_rule, vmax, counts):
    """The in-plane design's inputs checked.

    ``(v0, (omega, du_z, du_x, du_y) ranges, phase_x, phase_y, inplane_on, vmax)``; ``counts``:
    ``(name, value, least)`` of each size of the map.
    """
    if goal not in GOALS:
        raise ValueError(f"goal must be one of {sorted(GOALS)}, got {goal!r}")
    if velocity_rule not in VELOCITY_RULES:
        raise ValueError(f"velocity_rule must be one of {sorted(VELOCITY_RULES)}, got "
                         f"{velocity_rule!r}")
    v0 = float(checked("v0", v0, minimum=0.0, strict=True))
    w_range = checked_range("omega", omega)
    z_range = checked_range("du_z", du_z, allow_zero=True)
    x_range = (0.0, 0.0) if du_x is None else checked_range("du_x", du_x, allow_zero=True)
    y_range = (0.0, 0.0) if du_y is None else checked_range("du_y", du_y, allow_zero=True)
    if y_range[1] > 0.0 and math.isinf(pin.k_xc):
        raise ValueError("a transverse design (du_y) needs a finite k_xc: the 2-D solver "
                         "does not cover a rigid contact")
    if phase_y is not None:
        phase_y = float(checked("phase_y", phase_y))
    if goal == "drive" and x_range[1] == 0.0:
        raise ValueError("goal='drive' needs an in-plane oscillation: give du_x=(low, high) "
                         "with high > 0 (a normal oscillation alone cannot drive: its mean "
                         "force has the sign of v0, the holder supplies all the energy the "
                         "contact dissipates)")
    if phase_x is not None:
        phase_x = float(checked("phase_x", phase_x))
    on = pin.inplane_on if inplane_on is None else checked_choice("inplane_on", inplane_on)
    vmax = math.inf if vmax is None else float(checked(
        "max_velocity_amplitude", vmax, minimum=0.0, strict=True))
    for name, n, least in counts:
        if int(n) != n or n < least:
            raise ValueError(f"{name} must be an integer >= {least}, got {n!r}")
    return v0, (w_range, z_range, x_range, y_range), phase_x, phase_y, on, vmax


def _direction_rows(pin, v0, on, goal, space: Space, sizes, starts, settings) -> list[dict]:
    """The best normal-only and longitudinal-only choices within the limits.

    Each where its range is not empty.
    """
    rows = []
    if space.du_z[1] > 0.0:
        rows.append(direction_row("normal only", pin, v0, on, goal,
                                   space.restricted(du_x=(0.0, 0.0)), sizes, starts,
                                   settings))
    if space.du_x[1] > 0.0:
        rows.append(direction_row("longitudinal only", pin, v0, on, goal,
                                   space.restricted(du_z=(0.0, 0.0), phase=0.0), sizes,
                                   starts, settings))
    return rows


def _transverse_rows(pin, v0, on, goal, plane: Space, sizes, starts,
                     settings) -> list[dict]:
    """The best normal + transverse and transverse-only choices, by the 2-D solver.

    The best normal + transverse and transverse-only choices, by the 2-D solver on a
    smaller map (:data:`PLANE_MAP`, :data:`PLANE_STARTS`); ``sizes``: ``(n_omega, n_du_z,
    n_du_y, n_phase_y)``.
    """
    n_omega, n_du_z, n_du_y, n_phase_y = sizes
    plane_sizes = (min(n_omega, PLANE_MAP[0]), min(n_du_z, PLANE_MAP[1]), n_du_y, n_phase_y)
    plane_starts = min(starts, PLANE_STARTS)
    rows = []
    if plane.du_z[1] > 0.0:
        rows.append(direction_row("normal + transverse", pin, v0, on, goal, plane,
                                   plane_sizes, plane_starts, settings))
    rows.append(direction_row("transverse only", pin, v0, on, goal,
                               plane.restricted(du_z=(0.0, 0.0), phase=0.0),
                               plane_sizes, plane_starts, settings))
    return rows


def _best_choice(goal: str, rows: list[dict], point, obj: float) -> tuple:
    """``(omega, du_z, du_x, phase_x, du_y, phase_y)`` of the best row.

    The combined optimum ``point`` unless a sub-design inside the allowed set did better
    (``rows[0]``, the combined row, takes the choice).
    """
    choice = (*point, 0.0, 0.0)  # (omega, du_z, du_x, phase_x, du_y, phase_y)
    for row in rows[1:]:  # a sub-design inside the allowed set that did better wins
        if row["allowed"] and np.isfinite(row["cof"]) and \
                float(objective_of(goal, np.array(row["cof"]))) < obj:
            choice = tuple(row[k] for k in (*AXES, "du_y", "phase_y"))
            obj = float(objective_of(goal, np.array(row["cof"])))
    rows[0].update(zip((*AXES, "du_y", "phase_y"), choice, strict=True))
    return choice


def _phase_map(pin, v0, on, space: Space, point, settings, n_phase: int = 73,
               n_du_x: int = 25) -> xr.Dataset | None:
    """The COF over ``(du_x, phase_x)`` at the chosen ``omega`` and ``du_z``.

    The COF over ``(du_x, phase_x)`` at the chosen ``omega`` and ``du_z`` (what
    :func:`~vibrofriction.figures.plot_design` shows) when the phase is free (one
    ``du_x`` when its range is a point).
    """
    if space.phase is not None or space.du_x[1] == 0.0:
        return None
    w, dz = point[0], point[1]
    dxs = np.linspace(space.du_x[0], space.du_x[1], n_du_x if space.du_x[0] < space.du_x[1]
                      else 1)
    phs = np.linspace(0.0, 2 * math.pi, n_phase)
    DX, PH = np.meshgrid(dxs, phs, indexing="ij")
    sol = solve_design(pin, v0, w, dz, settings, DX, PH, on)
    dims = ("du_x", "phase_x")
    return xr.Dataset(
        {"cof": (dims, sol["cof"]), "trusted": (dims, sol["trusted"]),
         "feasible": (dims, space.feasible(w, dz, DX))},
        coords={"du_x": ("du_x", dxs, {"units": "m"}),
                "phase_x": ("phase_x", phs, {"units": "rad"})},
        attrs={"omega": w, "du_z": dz, "v0": v0})


def _dataset_nd(axes, sol, feasible, attrs) -> xr.Dataset:
    return xr.Dataset(
        {"cof": (AXES, sol["cof"], {"long_name": "coefficient of friction mu0 mu/mu0 "
                                                  "(signed; nan where not trusted)"}),
         "mu_ratio": (AXES, sol["mu_ratio"], {"long_name": "mu_macro/mu0 as the solver "
                                                            "left it (trusted or not)"}),
         "error": (AXES, sol["error"], {"long_name": "estimate of |mu_ratio - exact|"}),
         "trusted": (AXES, sol["trusted"]),
         "feasible": (AXES, feasible, {"long_name": "within max_velocity_amplitude"})},
        coords={"omega": ("omega", axes[0], {"units": "rad s-1"}),
                "du_z": ("du_z", axes[1], {"units": "m"}),
                "du_x": ("du_x", axes[2], {"units": "m"}),
                "phase_x": ("phase_x", axes[3], {"units": "rad"})},
        attrs=attrs)


def _drive_characteristic(result: DesignResult, settings: SolverSettings | None) -> None:
    """The chosen oscillation's blocking force and idle velocity, in place.

    The chosen oscillation's blocking force (``mu`` at ``V = +-BLOCKING_V``) and idle
    velocity (the root of ``mu(V) = 0`` above ``v0``, Brent's method on the solver,
    bracketed by a scan up to ``1.01 V_c``, theory's critical velocity), in place.
    """
    from scipy.optimize import brentq

    from ... import theory

    s = result.system
    d = s.to_dimensionless()
    args = (d.alpha, d.beta, d.amplitude)
    tail: dict[str, Any] = dict(zeta=d.zeta, eta_c=d.eta_c, a_x=d.a_x, phase_x=d.phase_x,
                                inplane_on=d.inplane_on, settings=settings,
                                static_ratio=d.static_ratio)
    block = solve_points(*args, np.array([BLOCKING_V, -BLOCKING_V]), **tail)
    result.blocking = (float(block["mu_ratio"][0]), float(block["mu_ratio"][1]))
    result.blocking_trusted = bool(block["trusted"].all())
    V0 = float(s.v0_to_inertial(result.v0))
    if not result.mu_ratio < 0.0:
        result.idle_velocity = math.nan
        result.idle_message = (f"none: the chosen oscillation does not drive at v0 "
                               f"(mu/mu0 = {result.mu_ratio:+.4g} >= 0)")
        return
    Vc = float(theory.inplane_critical_velocity(*args, d.a_x, d.phase_x, d.zeta, d.eta_c,
                                                d.inplane_on))
    if not np.isfinite(Vc) or Vc <= V0:
        result.idle_velocity = math.nan
        result.idle_message = "not found (no finite critical velocity above v0 to bracket it)"
        return
    V = np.geomspace(V0, 1.01 * Vc, 24)
    scan = solve_points(*args, V, **tail)
    mu, ok = scan["mu_ratio"], scan["trusted"]
    untrusted = {"n": 0}

    def f(v):
        out = solve_points(*args, v, **tail)
        untrusted["n"] += int(not out["trusted"])
        return float(out["mu_ratio"])

    for i in range(V.size - 1):
        if mu[i] < 0.0 <= mu[i + 1]:
            if not (ok[i] and ok[i + 1]):
                result.idle_velocity = math.nan
                result.idle_message = (f"not found: the bracket {V[i]:.4g}..{V[i + 1]:.4g} "
                                       f"(inertial units) has an untrusted end")
                return
            root = brentq(f, V[i], V[i + 1], xtol=1e-9 * V[i + 1])
            result.idle_velocity = float(root * s.velocity_unit())
            flag = ("" if not untrusted["n"] else
                    f"; {untrusted['n']} untrusted evaluations in the root search")
            result.idle_message = (f"{result.idle_velocity:.5g} m/s (V = {root:.5g} in "
                                   f"inertial units; the drive pushes between v0 and it, "
                                   f"theory's V_c = {Vc:.5g}){flag}")
            return
    result.idle_velocity = math.nan
    result.idle_message = "not found between v0 and 1.01 V_c (no trusted sign change)"
