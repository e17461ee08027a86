"""The normal oscillation alone.

The map over ``(omega, du_z)`` and its best points refined by Nelder-Mead.
"""

from __future__ import annotations

import math

import numpy as np

from ...params import Physical
from ...validation import checked
from .evaluation import (
    checked_range,
    log_step,
    map_axes_2d,
    map_dataset,
    map_status,
    sensitivity_table,
    solve_design,
    untrusted_near,
)
from .result import DesignResult


def _refine(pin, v0, settings, starts, limits, steps):
    """Nelder-Mead in ``(ln omega, ln du_z)`` from each start.

    Nelder-Mead in ``(ln omega, ln du_z)`` from each start, inside the limits, on
    trusted values only.  Returns the lowest ``(omega, du_z, cof)`` found (the starts
    included), the untrusted evaluations rejected in all and by the winning run.
    """
    from scipy.optimize import minimize

    (w_lo, w_hi), (d_lo, d_hi), vmax = limits
    best = min(starts, key=lambda s: s[2])
    rejected = {"all": 0, "run": 0}

    def objective(x):
        w, d = math.exp(x[0]), math.exp(x[1])
        if not (w_lo <= w <= w_hi and d_lo <= d <= d_hi and w * d <= vmax):
            return math.inf
        c = float(solve_design(pin, v0, w, d, settings)["cof"])
        if math.isnan(c):
            rejected["run"] += 1
            return math.inf
        return c

    best_rejected = 0
    for w, d, _ in starts:
        if d == 0.0:  # no logarithm; the point itself is a candidate as it stands
            continue
        x0 = np.log([w, d])
        simplex = np.array([x0, x0 + [steps[0], 0.0], x0 + [0.0, -steps[1]]])
        rejected["run"] = 0
        with np.errstate(invalid="ignore"):  # inf - inf in the simplex's spread
            res = minimize(objective, x0, method="Nelder-Mead",
                           options={"xatol": 1e-7, "fatol": 1e-10, "maxfev": 150,
                                    "initial_simplex": simplex})
        rejected["all"] += rejected["run"]
        if res.fun < best[2]:
            best = (math.exp(res.x[0]), math.exp(res.x[1]), float(res.fun))
            best_rejected = rejected["run"]
    return best, rejected["all"], best_rejected


def design_normal(pin: Physical, *, v0, omega, du_z, max_velocity_amplitude, n_omega,
                   n_du_z, starts, settings) -> DesignResult:
    """The normal oscillation alone.

    The map over ``(omega, du_z)``, its lowest trusted points refined, the status of the
    optimum.
    """
    v0 = float(checked("v0", v0, minimum=0.0, strict=True))
    w_range = checked_range("omega", omega)
    d_range = checked_range("du_z", du_z, allow_zero=True)
    vmax = math.inf if max_velocity_amplitude is None else float(checked(
        "max_velocity_amplitude", max_velocity_amplitude, minimum=0.0, strict=True))
    if w_range[0] * d_range[0] > vmax:
        raise ValueError(f"no oscillation in range respects max_velocity_amplitude = {vmax:g} "
                         f"m/s: the smallest omega * du_z is {w_range[0] * d_range[0]:g}")
    ws, ds = map_axes_2d(pin, w_range, d_range, n_omega, n_du_z)
    W, D = np.meshgrid(ws, ds, indexing="ij")
    sol = solve_design(pin, v0, W, D, settings)
    feasible = W * D <= vmax * (1 + 1e-12)
    candidates = np.where(feasible & sol["trusted"], sol["cof"], np.inf)
    order = np.argsort(candidates, axis=None)[:starts]
    picked = [k for k in order if np.isfinite(candidates.flat[k])]
    if not picked:
        raise ValueError(f"no trusted point of the map respects the limits "
                         f"({int((feasible & ~sol['trusted']).sum())} untrusted within them)")
    (w_opt, d_opt, c_opt), n_rejected, rejected_run = _refine(
        pin, v0, settings, [(W.flat[k], D.flat[k], candidates.flat[k]) for k in picked],
        (w_range, d_range, vmax), (log_step(ws), log_step(ds)))
    at_opt = solve_design(pin, v0, w_opt, d_opt, settings)
    untrusted = feasible & ~sol["trusted"]
    near = untrusted_near(untrusted, ws, ds, w_opt, d_opt)
    status, message = map_status(untrusted, feasible, near, n_rejected, rejected_run)
    chosen = pin.with_(omega=w_opt, du_z=d_opt)
    dmap = map_dataset(ws, ds, sol, feasible, attrs={
        "v0": v0, "optimum_omega": w_opt, "optimum_du_z": d_opt, "optimum_cof": c_opt,
        "max_velocity_amplitude": vmax, "status": status, "n_untrusted": int(untrusted.sum()),
        "n_untrusted_near": near, "n_rejected": n_rejected})
    return DesignResult(system=chosen, v0=v0, cof=c_opt, mu_ratio=c_opt / pin.mu0,
                        error=float(at_opt["error"]), map=dmap,
                        sensitivity=sensitivity_table(chosen, v0, settings), status=status,
                        message=message, n_untrusted=int(untrusted.sum()),
                        n_untrusted_near=near, n_rejected=n_rejected)
