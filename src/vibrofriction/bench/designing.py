"""Designing the oscillation: the frequency and amplitude that minimise friction (docs/bench.md).

``design(pin, v0=..., omega=(lo, hi), du_z=(lo, hi), max_velocity_amplitude=None)``
solves the model (``COF = mu0 mu/mu0``, eq. 25) on a map over the actuator's range
(logarithmic in both, the pin's natural frequency and the contact resonance
``sqrt((k_x + k_xc)/m)`` added to the frequencies when they lie inside, because the
resonant optimum can be sharp), takes the lowest trusted points of the map that respect
the velocity limit ``omega * du_z <= max_velocity_amplitude``, and refines them by
Nelder-Mead in ``(ln omega, ln du_z)`` inside the limits.

Only trusted values are used (``SolverSettings.trusted``): an untrusted point of the
map is no candidate, an untrusted evaluation of the refinement is rejected, and an
untrusted row of the sensitivity table has no value.  The result counts them and says
in its ``status`` whether untrusted points lie next to the optimum (where a lower value
could hide).  The map is returned, so that the optimum can be seen to be the global one
within the limits and not a local dip.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd
import xarray as xr

from ..params import Physical
from ..solver import SolverSettings, solve_points
from ..validation import checked

__all__ = ["DESIGN_STATUSES", "DesignResult", "design"]

#: Relative changes of the drive frequency in the sensitivity table.
FREQUENCY_CHANGES = (-0.05, -0.01, 0.01, 0.05)
#: Relative change of each pin parameter in the sensitivity table.
PARAMETER_CHANGE = 0.10
PIN_PARAMETERS = ("mass", "k_x", "k_xc", "k_zc", "c_x", "mu0")
#: With ``du_z = (0, hi)`` the map's amplitudes are 0 and ``hi`` down to this fraction of it.
ZERO_AMPLITUDE_FLOOR = 1e-2
#: ``DesignResult.status``: what the optimum rests on.
DESIGN_STATUSES = {
    "trusted": "every point of the map within the limits is trusted",
    "untrusted_in_map": "the map has untrusted points within the limits, none next to the "
                        "optimum",
    "untrusted_near_optimum": "untrusted points lie next to the optimum: a lower value may "
                              "hide among them",
}


@dataclass
class DesignResult:
    """The chosen oscillation and what it is worth.

    ``system``: the pin at the chosen ``omega`` and ``du_z``; ``cof`` and ``mu_ratio``
    there (always a trusted value) and the solver's ``error`` estimate of ``mu_ratio``;
    ``map``: the labelled Dataset over ``(omega, du_z)`` (``cof``, nan where not
    trusted, ``mu_ratio``, ``error``, ``trusted``, ``feasible``) with the optimum and the
    counts in its attributes; ``sensitivity``: the COF when the frequency is off by +-1,
    +-5 % and when each pin parameter is off by +-10 % (a DataFrame with ``change``,
    ``cof``, nan where untrusted, and ``trusted``).

    ``n_untrusted``: untrusted map points within the limits; ``n_untrusted_near``: those
    next to the optimum (its map cell's neighbours); ``n_rejected``: untrusted
    evaluations the refinement rejected (all starts); ``status``: a key of
    :data:`DESIGN_STATUSES`, ``message`` says it with the counts.
    """

    system: Physical
    v0: float
    cof: float
    mu_ratio: float
    error: float
    map: xr.Dataset
    sensitivity: pd.DataFrame
    status: str
    message: str
    n_untrusted: int
    n_untrusted_near: int
    n_rejected: int

    @property
    def trusted(self) -> bool:
        """Whether every point of the map within the limits is trusted (status ``trusted``)."""
        return self.status == "trusted"

    def report(self) -> str:
        s = self.system
        lines = [f"optimum at v0 = {self.v0:g} m/s: f = {s.omega / (2 * math.pi):.6g} Hz, "
                 f"du_z = {s.du_z:.4g} m (velocity amplitude {s.omega * s.du_z:.4g} m/s): "
                 f"COF {self.cof:.5g} (mu/mu0 = {self.mu_ratio:.5g}, solver error "
                 f"{self.error:.1e})",
                 f"status: {self.status}: {self.message}",
                 "sensitivity (COF):"]
        for _, row in self.sensitivity.iterrows():
            value = f"{row['cof']:.5g}" if row["trusted"] else "untrusted (no value)"
            lines.append(f"  {row['change']:>28s}: {value}")
        return "\n".join(lines)


def _range(name: str, value, *, allow_zero: bool = False) -> tuple[float, float]:
    try:
        lo, hi = (float(x) for x in value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a pair (low, high), got {value!r}") from None
    checked(name, np.array([lo, hi]), minimum=0.0, strict=not allow_zero)
    if not lo <= hi:
        raise ValueError(f"{name}: low {lo!r} > high {hi!r}")
    return lo, hi


def _solve(pin: Physical, v0: float, omega, du_z,
           settings: SolverSettings | None) -> dict[str, np.ndarray]:
    """``cof`` (nan where not trusted), ``mu_ratio``, ``error`` and ``trusted`` of ``pin``
    driven at ``omega`` (rad/s) with ``du_z`` (m), at the sliding velocity ``v0`` (m/s)."""
    omega, du_z = np.broadcast_arrays(np.asarray(omega, float), np.asarray(du_z, float))
    alpha, beta, a, zeta, eta = pin.groups(du_z, omega)
    out = solve_points(alpha, beta, a, pin.v0_to_inertial(v0, omega), zeta, eta,
                       settings=settings)
    trusted = out["trusted"]
    return {"cof": np.where(trusted, pin.mu0 * out["mu_ratio"], np.nan),
            "mu_ratio": out["mu_ratio"], "error": out["error"], "trusted": trusted}


def _axes(pin: Physical, w_range, d_range, n_omega: int, n_du_z: int):
    """The map's frequencies (with the resonances inside) and amplitudes (0 included
    when the range starts there), logarithmic."""
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


def _log_step(axis: np.ndarray) -> float:
    positive = axis[axis > 0]
    return math.log(positive[1] / positive[0]) if positive.size > 1 else 0.1


def _refine(pin, v0, settings, starts, limits, steps):
    """Nelder-Mead in ``(ln omega, ln du_z)`` from each start, inside the limits, on
    trusted values only.  Returns the lowest ``(omega, du_z, cof)`` found (the starts
    included), the untrusted evaluations rejected in all and by the winning run."""
    from scipy.optimize import minimize

    (w_lo, w_hi), (d_lo, d_hi), vmax = limits
    best = min(starts, key=lambda s: s[2])
    rejected = {"all": 0, "run": 0}

    def objective(x):
        w, d = math.exp(x[0]), math.exp(x[1])
        if not (w_lo <= w <= w_hi and d_lo <= d <= d_hi and w * d <= vmax):
            return math.inf
        c = float(_solve(pin, v0, w, d, settings)["cof"])
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


def design(pin: Physical, *, v0: float, omega: tuple[float, float],
           du_z: tuple[float, float], max_velocity_amplitude: float | None = None,
           n_omega: int = 161, n_du_z: int = 41, starts: int = 8,
           settings: SolverSettings | None = None) -> DesignResult:
    """The oscillation (``omega`` in rad/s, ``du_z`` in m, within the given ranges and
    ``omega du_z <= max_velocity_amplitude``) that minimises the COF of ``pin`` (eq. 25)
    at the sliding velocity ``v0`` (m/s); ``pin``'s own ``omega``, ``du_z`` are not used.

    ``du_z`` may start at 0 (no oscillation, ``COF = mu0``); the map then holds 0 and
    logarithmic amplitudes from ``ZERO_AMPLITUDE_FLOOR * high``.  ``settings``: the
    solver's (its ``tol_trusted`` decides which values are used).  Raises ValueError
    when no trusted point of the map respects the limits.
    """
    pin.require_normal_only("the design")
    v0 = float(checked("v0", v0, minimum=0.0, strict=True))
    w_range = _range("omega", omega)
    d_range = _range("du_z", du_z, allow_zero=True)
    vmax = math.inf if max_velocity_amplitude is None else float(checked(
        "max_velocity_amplitude", max_velocity_amplitude, minimum=0.0, strict=True))
    if w_range[0] * d_range[0] > vmax:
        raise ValueError(f"no oscillation in range respects max_velocity_amplitude = {vmax:g} "
                         f"m/s: the smallest omega * du_z is {w_range[0] * d_range[0]:g}")
    ws, ds = _axes(pin, w_range, d_range, n_omega, n_du_z)
    W, D = np.meshgrid(ws, ds, indexing="ij")
    sol = _solve(pin, v0, W, D, settings)
    feasible = W * D <= vmax * (1 + 1e-12)
    candidates = np.where(feasible & sol["trusted"], sol["cof"], np.inf)
    order = np.argsort(candidates, axis=None)[:starts]
    order = [k for k in order if np.isfinite(candidates.flat[k])]
    if not order:
        raise ValueError(f"no trusted point of the map respects the limits "
                         f"({int((feasible & ~sol['trusted']).sum())} untrusted within them)")
    (w_opt, d_opt, c_opt), n_rejected, rejected_run = _refine(
        pin, v0, settings, [(W.flat[k], D.flat[k], candidates.flat[k]) for k in order],
        (w_range, d_range, vmax), (_log_step(ws), _log_step(ds)))
    at_opt = _solve(pin, v0, w_opt, d_opt, settings)
    untrusted = feasible & ~sol["trusted"]
    near = _untrusted_near(untrusted, ws, ds, w_opt, d_opt)
    status, message = _status(untrusted, feasible, near, n_rejected, rejected_run)
    chosen = pin.with_(omega=w_opt, du_z=d_opt)
    dmap = _dataset(ws, ds, sol, feasible, attrs={
        "v0": v0, "optimum_omega": w_opt, "optimum_du_z": d_opt, "optimum_cof": c_opt,
        "max_velocity_amplitude": vmax, "status": status, "n_untrusted": int(untrusted.sum()),
        "n_untrusted_near": near, "n_rejected": n_rejected})
    return DesignResult(system=chosen, v0=v0, cof=c_opt, mu_ratio=c_opt / pin.mu0,
                        error=float(at_opt["error"]), map=dmap,
                        sensitivity=_sensitivity(chosen, v0, settings), status=status,
                        message=message, n_untrusted=int(untrusted.sum()),
                        n_untrusted_near=near, n_rejected=n_rejected)


def _untrusted_near(untrusted: np.ndarray, ws, ds, w_opt: float, d_opt: float) -> int:
    """Untrusted map points among the neighbours of the map point nearest the optimum."""
    i = int(np.argmin(np.abs(np.log(ws / w_opt))))
    with np.errstate(divide="ignore"):
        j = int(np.argmin(np.abs(ds - d_opt) if d_opt == 0.0 else
                          np.abs(np.log(np.where(ds > 0.0, ds, 0.0) / d_opt))))
    return int(untrusted[max(i - 1, 0):i + 2, max(j - 1, 0):j + 2].sum())


def _status(untrusted: np.ndarray, feasible: np.ndarray, near: int, n_rejected: int,
            rejected_run: int) -> tuple[str, str]:
    """The key of :data:`DESIGN_STATUSES` and its message with the counts."""
    status = ("untrusted_near_optimum" if near or rejected_run else
              "untrusted_in_map" if untrusted.any() else "trusted")
    return status, (f"{DESIGN_STATUSES[status]} ({int(untrusted.sum())} of "
                    f"{int(feasible.sum())} map points within the limits untrusted, {near} "
                    f"next to the optimum; {n_rejected} untrusted evaluations rejected by the "
                    f"refinement, {rejected_run} in the run that found the optimum)")


def _dataset(ws, ds, sol, feasible, attrs) -> xr.Dataset:
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


def _sensitivity(chosen: Physical, v0: float, settings: SolverSettings | None) -> pd.DataFrame:
    """The COF at the optimum, with the frequency off by ``FREQUENCY_CHANGES`` and each
    pin parameter off by ``PARAMETER_CHANGE`` (nan and ``trusted`` False where the
    solver does not trust its value)."""
    cases = [("optimum", chosen, chosen.omega)]
    cases += [(f"frequency {100 * c:+.0f} %", chosen, chosen.omega * (1 + c))
              for c in FREQUENCY_CHANGES]
    for name in PIN_PARAMETERS:
        base = getattr(chosen, name)
        if base == 0.0 or not math.isfinite(base):
            continue
        for sign in (-1, 1):
            p = chosen.with_(**{name: base * (1 + sign * PARAMETER_CHANGE)})
            cases.append((f"{name} {sign * 100 * PARAMETER_CHANGE:+.0f} %", p, p.omega))
    rows = []
    for label, pin, w in cases:
        sol = _solve(pin, v0, w, pin.du_z, settings)
        rows.append((label, float(sol["cof"]), bool(sol["trusted"])))
    return pd.DataFrame(rows, columns=["change", "cof", "trusted"])
