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
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from ..params import Physical
from ..solver import SolverSettings, solve_points
from ..validation import checked, checked_choice

__all__ = ["DESIGN_STATUSES", "GOALS", "VELOCITY_RULES", "DesignResult", "design"]

#: A curved (MDR) pin's map (the MDR solver, ~30 ms a point): this many frequencies and
#: normal amplitudes by default, and this many refinements from its lowest points.
CURVED_MAP = (25, 9)
CURVED_STARTS = 3
#: Relative changes of the drive frequency in the sensitivity table.
FREQUENCY_CHANGES = (-0.05, -0.01, 0.01, 0.05)
#: Changes of the in-plane phase (rad) in the sensitivity table of an in-plane design.
PHASE_CHANGES = (-0.1, 0.1)
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
    goal: str = "friction"
    velocity_rule: str = "combined"
    directions: pd.DataFrame | None = None
    phase_map: xr.Dataset | None = None
    blocking: tuple[float, float] | None = None
    blocking_trusted: bool | None = None
    idle_velocity: float | None = None
    idle_message: str = ""

    @property
    def trusted(self) -> bool:
        """Whether every point of the map within the limits is trusted (status ``trusted``)."""
        return self.status == "trusted"

    @property
    def inplane(self) -> bool:
        """Whether the design was allowed an in-plane oscillation (``du_x`` given)."""
        return "du_x" in self.map.dims

    @property
    def drive_ratio(self) -> float:
        """The drive force at ``v0`` in units of ``mu0 <F_N>``: ``-mu_ratio``, positive
        where the oscillation pushes the slider forward against a load."""
        return -self.mu_ratio

    def report(self) -> str:
        s = self.system
        if not self.inplane:
            lines = [f"optimum at v0 = {self.v0:g} m/s: f = {s.omega / (2 * math.pi):.6g} Hz, "
                     f"du_z = {s.du_z:.4g} m (velocity amplitude {s.omega * s.du_z:.4g} "
                     f"m/s): COF {self.cof:.5g} (mu/mu0 = {self.mu_ratio:.5g}, solver error "
                     f"{self.error:.1e})"]
        else:
            what = ("largest drive force" if self.goal == "drive" else
                    "smallest friction force |COF|")
            across = (f", du_y = {s.du_y:.4g} m, phase_y = {s.phase_y:.4f} rad (across the "
                      f"sliding)" if s.du_y > 0.0 else "")
            lines = [f"{what} at v0 = {self.v0:g} m/s ({s.inplane_on}): f = "
                     f"{s.omega / (2 * math.pi):.6g} Hz, du_z = {s.du_z:.4g} m, du_x = "
                     f"{s.du_x:.4g} m, phase_x = {s.phase_x:.4f} rad{across} (combined "
                     f"velocity amplitude "
                     f"{s.omega * math.hypot(s.du_z, s.du_x, s.du_y):.4g} m/s): COF "
                     f"{self.cof:.5g} (mu/mu0 = {self.mu_ratio:.5g}, solver error "
                     f"{self.error:.1e})"]
            if self.goal == "drive":
                lines.append(f"drive force at v0: {self.drive_ratio:.5g} mu0 <F_N>")
                if self.blocking is not None:
                    flag = "" if self.blocking_trusted else " (UNTRUSTED)"
                    lines.append(f"blocking force: mu/mu0 = {self.blocking[0]:+.5g} at V -> 0+, "
                                 f"{self.blocking[1]:+.5g} at V -> 0-{flag}")
                lines.append(f"idle velocity: {self.idle_message}")
        lines += [f"status: {self.status}: {self.message}"]
        if self.directions is not None:
            lines.append("which direction (best within the same limits):")
            for _, row in self.directions.iterrows():
                inplane = (f"du_y = {row['du_y']:.3g} m, phase_y = {row['phase_y']:.3f}"
                           if row.get("du_y", 0.0) > 0.0 else
                           f"du_x = {row['du_x']:.3g} m, phase_x = {row['phase_x']:.3f}")
                value = ("not allowed by the ranges" if not np.isfinite(row["cof"]) else
                         f"COF {row['cof']:.5g} at f = {row['omega'] / (2 * math.pi):.5g} Hz, "
                         f"du_z = {row['du_z']:.3g} m, {inplane}")
                lines.append(f"  {row['direction']:>18s}: {value}")
        lines.append("sensitivity (COF):")
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


def _solve(pin: Physical, v0: float, omega, du_z, settings: SolverSettings | None,
           du_x=0.0, phase_x=0.0, inplane_on: str = "substrate", du_y=0.0,
           phase_y=0.0) -> dict[str, np.ndarray]:
    """``cof`` (nan where not trusted), ``mu_ratio``, ``error`` and ``trusted`` of ``pin``
    driven at ``omega`` (rad/s) with ``du_z`` (m) and the in-plane ``du_x``, ``du_y`` (m),
    ``phase_x``, ``phase_y`` on ``inplane_on``, at the sliding velocity ``v0`` (m/s)
    (:meth:`Physical.point_arguments`, the fit's conversion too; ``du_y > 0``: the 2-D
    solver, with the pin's ``k_y``, ``c_y``)."""
    omega, du_z, du_x, phase_x, du_y, phase_y = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (omega, du_z, du_x, phase_x, du_y, phase_y)))
    args: tuple[Any, ...] = pin.point_arguments(v0, du_z, omega, du_x, phase_x, du_y, phase_y)
    out = solve_points(*args, profile_exponent=pin.profile_exponent,  # type: ignore[misc]
                       inplane_on=inplane_on,  # args: the 12 groups before profile_exponent
                       settings=settings)
    trusted = out["trusted"]
    return {"cof": np.where(trusted, pin.mu0 * out["mu_ratio"], np.nan),
            "mu_ratio": out["mu_ratio"], "error": out["error"], "trusted": out["trusted"]}


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
           du_x: tuple[float, float] | None = None, phase_x: float | None = None,
           inplane_on: str | None = None, goal: str = "friction",
           velocity_rule: str = "combined", n_omega: int | None = None,
           n_du_z: int | None = None, n_du_x: int = 9, n_phase: int = 16,
           starts: int | None = None,
           settings: SolverSettings | None = None, du_y: tuple[float, float] | None = None,
           phase_y: float | None = None, n_du_y: int = 4,
           n_phase_y: int = 4) -> DesignResult:
    """The oscillation (``omega`` in rad/s, ``du_z`` in m, within the given ranges and
    ``omega du_z <= max_velocity_amplitude``) that minimises the COF of ``pin`` (eq. 25)
    at the sliding velocity ``v0`` (m/s); ``pin``'s own oscillation (``omega``, ``du_z``,
    ``du_x``, ``phase_x``) is not used (a pin with ``du_x > 0`` needs ``du_x=``: refused
    rather than ignored).

    ``du_z`` may start at 0 (no oscillation, ``COF = mu0``); the map then holds 0 and
    logarithmic amplitudes from ``ZERO_AMPLITUDE_FLOOR * high``.  ``settings``: the
    solver's (its ``tol_trusted`` decides which values are used).  Raises ValueError
    when no trusted point of the map respects the limits.

    **In-plane** (docs/bench.md): ``du_x=(lo, hi)`` (m, may start at 0) allows the
    longitudinal oscillation ``du_x cos(omega t + phase_x)`` on ``inplane_on`` (default
    the pin's); ``phase_x=None`` optimises the phase over ``[0, 2 pi)`` (a grid of
    ``n_phase``, then refined), a number fixes it.  The velocity limit applies to
    ``omega sqrt(du_z^2 + du_x^2)`` (``velocity_rule="combined"``) or to each of
    ``omega du_z``, ``omega du_x`` (``"each"``).  ``goal="friction"`` minimises the force
    magnitude ``|COF|`` at ``v0`` (the oscillation may push: ``mu < 0``),
    ``goal="drive"`` maximises the drive force ``-mu(v0)`` and reports the blocking
    force and the idle velocity; it needs ``du_x`` (a normal oscillation alone cannot
    drive).  The map is 4-D (default ``41 x 9 x n_du_x x n_phase``); ``directions``
    gives the best normal-only and longitudinal-only choices within the same limits.

    **Transverse** (``goal="friction"``): ``du_y=(lo, hi)`` (m) allows the oscillation
    across the sliding ``du_y cos(omega t + phase_y)`` (``phase_y=None``: free) instead of
    the longitudinal one (one in-plane direction at a time; the velocity limit applies to
    ``omega sqrt(du_z^2 + du_y^2)``, resp. each).  It is designed by the 2-D solver with the
    pin's ``k_y``, ``c_y``, on a smaller map (at most :data:`PLANE_MAP` frequencies and
    normal amplitudes, ``n_du_y x n_phase_y``, :data:`PLANE_STARTS` refinements): the rows
    ``"normal + transverse"`` and ``"transverse only"`` of ``directions``; the chosen
    oscillation is the best row (``system.du_y > 0`` where a transverse one wins).  The
    4-D ``map`` stays the one over ``du_x``, ``phase_x`` (only ``du_x = 0`` without
    ``du_x``).

    **Curved contact** (a pin of ``vf.from_bench(contact=..., contact_model="mdr")``,
    docs/bench.md): the same normal-oscillation design by the MDR solver, on a smaller map
    by default (:data:`CURVED_MAP`, :data:`CURVED_STARTS` refinements; ``starts`` default 8
    otherwise); ``du_z`` is the amplitude of the imposed indentation.  Refused by name what
    the MDR solver does not take: ``du_x``, ``du_y``, ``goal="drive"`` and a contact
    dashpot (``c_xc > 0``).
    """
    if pin.curved:
        for name, given in (("du_x", du_x is not None), ("du_y", du_y is not None),
                            ("goal='drive'", goal != "friction"),
                            ("a contact dashpot c_xc > 0", pin.c_xc > 0.0)):
            if given:
                raise ValueError(f"a curved MDR pin (profile_exponent = "
                                 f"{pin.profile_exponent!r}) is designed by the MDR solver, "
                                 f"which does not take {name} yet: design the normal "
                                 f"oscillation alone")
        n_omega = CURVED_MAP[0] if n_omega is None else n_omega
        n_du_z = CURVED_MAP[1] if n_du_z is None else n_du_z
        starts = CURVED_STARTS if starts is None else starts
    starts = 8 if starts is None else starts
    if du_y is None and pin.du_y > 0.0:
        raise ValueError(f"the pin has a transverse oscillation (du_y = {pin.du_y!r} m), "
                         f"which the design would not use: give du_y=(low, high) to design "
                         f"it, or a pin with du_y = 0")
    if du_y is None and phase_y is not None:
        raise ValueError("phase_y needs a transverse oscillation: give du_y=(low, high)")
    if du_y is not None and goal != "friction":
        raise ValueError("goal='drive' does not take a transverse oscillation (du_y) yet: "
                         "design the drive with du_x")
    if du_x is None and pin.du_x > 0.0:
        raise ValueError(f"the pin has an in-plane oscillation (du_x = {pin.du_x!r} m), which "
                         f"the design would not use: give du_x=(low, high) to design it, or "
                         f"a pin with du_x = 0")
    if du_x is None and goal == "friction" and (phase_x, inplane_on) != (None, None) \
            and du_y is None:
        raise ValueError("phase_x and inplane_on need an in-plane oscillation: give "
                         "du_x=(low, high)")
    if du_x is None and phase_x is not None:
        raise ValueError("phase_x needs a longitudinal oscillation: give du_x=(low, high)")
    if du_x is not None or du_y is not None or goal != "friction":
        return _design_inplane(pin, v0=v0, omega=omega, du_z=du_z, du_x=du_x,
                               phase_x=phase_x, inplane_on=inplane_on, goal=goal,
                               velocity_rule=velocity_rule, vmax=max_velocity_amplitude,
                               n_omega=41 if n_omega is None else n_omega,
                               n_du_z=9 if n_du_z is None else n_du_z, n_du_x=n_du_x,
                               n_phase=n_phase, starts=starts, settings=settings,
                               du_y=du_y, phase_y=phase_y, n_du_y=n_du_y,
                               n_phase_y=n_phase_y)
    n_omega = 161 if n_omega is None else n_omega
    n_du_z = 41 if n_du_z is None else n_du_z
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
    picked = [k for k in order if np.isfinite(candidates.flat[k])]
    if not picked:
        raise ValueError(f"no trusted point of the map respects the limits "
                         f"({int((feasible & ~sol['trusted']).sum())} untrusted within them)")
    (w_opt, d_opt, c_opt), n_rejected, rejected_run = _refine(
        pin, v0, settings, [(W.flat[k], D.flat[k], candidates.flat[k]) for k in picked],
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
            p = chosen.with_(**{name: base * (1 + sign * PARAMETER_CHANGE)})
            cases.append((f"{name} {sign * 100 * PARAMETER_CHANGE:+.0f} %", p, p.omega))
    rows = []
    for label, pin, w in cases:
        sol = _solve(pin, v0, w, pin.du_z, settings, pin.du_x, pin.phase_x, pin.inplane_on,
                     pin.du_y, pin.phase_y)
        rows.append((label, float(sol["cof"]), bool(sol["trusted"])))
    return pd.DataFrame(rows, columns=["change", "cof", "trusted"])


# --------------------------------------------------------------------------------------
# In-plane design: normal + longitudinal oscillation, friction or drive (docs/bench.md)

#: ``velocity_rule``: what ``max_velocity_amplitude`` limits.
VELOCITY_RULES = {
    "combined": "omega sqrt(du_z^2 + du_x^2) (the peak speed of the contact's vibration at "
                "the worst phase, sqrt(2) times its rms speed at any phase)",
    "each": "omega du_z and omega du_x separately (two actuators, each with its limit)",
}
#: ``goal``: what the design optimises at ``v0``.
GOALS = {
    "friction": "the smallest friction force magnitude |COF| = mu0 |mu(v0)|",
    "drive": "the largest drive force -mu(v0) (forward, against a load, at v0 > 0)",
}
#: The blocking force is ``mu`` at ``V = +-BLOCKING_V`` (inertial units).
BLOCKING_V = 1e-5
_AXES = ("omega", "du_z", "du_x", "phase_x")
#: A transverse design's map (the 2-D solver, ~7 ms a point): at most this many
#: frequencies and normal amplitudes (then ``n_du_y x n_phase_y``).
PLANE_MAP = (9, 4)
#: ... and at most this many refinements from its lowest points.
PLANE_STARTS = 2


@dataclass
class _Space:
    """The allowed oscillations: ranges (SI), the phase (``None``: free), the limit;
    ``component`` the in-plane direction that ``du_x`` and ``phase`` stand for: ``"x"``
    (longitudinal) or ``"y"`` (transverse: ``du_y``, ``phase_y``)."""

    omega: tuple[float, float]
    du_z: tuple[float, float]
    du_x: tuple[float, float]
    phase: float | None
    vmax: float
    rule: str
    component: str = "x"

    def solve(self, pin, v0, w, dz, d, ph, on, settings) -> dict[str, np.ndarray]:
        """:func:`_solve` with the in-plane amplitude ``d`` and phase ``ph`` along
        ``component``."""
        if self.component == "y":
            return _solve(pin, v0, w, dz, settings, 0.0, 0.0, on, d, ph)
        return _solve(pin, v0, w, dz, settings, d, ph, on)

    def feasible(self, w, dz, dx) -> np.ndarray:
        w, dz, dx = (np.asarray(x, float) for x in (w, dz, dx))
        speed = w * (np.hypot(dz, dx) if self.rule == "combined" else np.maximum(dz, dx))
        return speed <= self.vmax * (1 + 1e-12)

    def inside(self, w, dz, dx) -> bool:
        return (self.omega[0] <= w <= self.omega[1] and self.du_z[0] <= dz <= self.du_z[1]
                and self.du_x[0] <= dx <= self.du_x[1] and bool(self.feasible(w, dz, dx)))

    def restricted(self, **ranges) -> _Space:
        return _Space(**{**self.__dict__, **ranges})


def _amplitudes(lo: float, hi: float, n: int) -> np.ndarray:
    if lo == hi:
        return np.array([lo])
    if lo == 0.0:
        return np.concatenate([[0.0], np.geomspace(ZERO_AMPLITUDE_FLOOR * hi, hi,
                                                   max(n - 1, 1))])
    return np.unique(np.geomspace(lo, hi, n))


def _map_axes(pin: Physical, space: _Space, n_omega: int, n_du_z: int, n_du_x: int,
              n_phase: int) -> list[np.ndarray]:
    ws = (np.array([space.omega[0]]) if space.omega[0] == space.omega[1] else
          _axes(pin, space.omega, (1.0, 1.0), n_omega, 1)[0])
    dxs = _amplitudes(*space.du_x, n_du_x)
    if space.phase is not None:
        phs = np.array([space.phase])
    elif dxs.max() == 0.0:
        phs = np.zeros(1)  # no in-plane oscillation: the phase means nothing
    else:
        phs = np.linspace(0.0, 2 * math.pi, n_phase, endpoint=False)
    return [ws, _amplitudes(*space.du_z, n_du_z), dxs, phs]


def _objective(goal: str, cof: np.ndarray) -> np.ndarray:
    """The value minimised: ``|COF|`` (friction) or ``COF`` (drive: ``-COF`` maximised)."""
    return np.abs(cof) if goal == "friction" else cof


def _solve_map(pin, v0, axes, on, settings, space: _Space):
    """The solver on the 4-D grid; points without in-plane amplitude are solved at the
    first phase only and copied (the phase means nothing there)."""
    grids = np.meshgrid(*axes, indexing="ij")
    need = (grids[2] > 0.0) | (np.arange(axes[3].size) == 0)[None, None, None, :]
    sol = {k: np.full(grids[0].shape, np.nan) for k in ("cof", "mu_ratio", "error")}
    sol["trusted"] = np.zeros(grids[0].shape, bool)
    w, dz, dx, ph = (g[need] for g in grids)
    part = space.solve(pin, v0, w, dz, dx, ph, on, settings)
    for k, v in part.items():
        sol[k][need] = v
        sol[k][:, :, axes[2] == 0.0, :] = sol[k][:, :, axes[2] == 0.0, :1]
    return grids, sol


def _refine_inplane(pin, v0, on, goal, settings, space: _Space, starts, steps):
    """Nelder-Mead from each start in the free coordinates (``ln omega``, ``ln du_z``,
    ``ln du_x`` where the start's value is > 0 and its range not a point; ``phase_x``
    when free), inside the limits, on trusted values only.  Returns the best
    ``(point, objective)`` (starts included), the rejected evaluations in all and in
    the winning run."""
    from scipy.optimize import minimize

    best = min(starts, key=lambda s: s[1])
    rejected = {"all": 0, "run": 0}
    best_rejected = 0
    for point, _ in starts:
        free = [i for i, (v, rng) in enumerate(zip(point[:3], (space.omega, space.du_z,
                                                                  space.du_x), strict=True))
                if v > 0.0 and rng[0] < rng[1]]
        if space.phase is None and point[2] > 0.0:
            free.append(3)
        if not free:
            continue

        def full(x, point=point, free=free):
            p = list(point)
            for i, xi in zip(free, x, strict=True):
                p[i] = xi % (2 * math.pi) if i == 3 else math.exp(xi)
            return p

        def objective(x, full=full):
            w, dz, dx, ph = full(x)
            if not space.inside(w, dz, dx):
                return math.inf
            c = float(space.solve(pin, v0, w, dz, dx, ph, on, settings)["cof"])
            if math.isnan(c):
                rejected["run"] += 1
                return math.inf
            return float(_objective(goal, np.array(c)))

        x0 = np.array([point[i] if i == 3 else math.log(point[i]) for i in free])
        simplex = [x0]
        for k, i in enumerate(free):  # step towards the inside: down in amplitude
            e = np.zeros(len(free))
            e[k] = steps[i] if i in (0, 3) else -steps[i]
            simplex.append(x0 + e)
        rejected["run"] = 0
        with np.errstate(invalid="ignore"):
            res = minimize(objective, x0, method="Nelder-Mead",
                           options={"xatol": 1e-7, "fatol": 1e-10,
                                    "maxfev": 60 + 60 * len(free),
                                    "initial_simplex": np.array(simplex)})
        rejected["all"] += rejected["run"]
        if res.fun < best[1]:
            best = (tuple(full(res.x)), float(res.fun))
            best_rejected = rejected["run"]
    return best, rejected["all"], best_rejected


def _optimise(pin, v0, on, goal, space: _Space, sizes, starts, settings):
    """Map and refinement over ``space``: ``(point, objective, grids, axes, sol,
    feasible, n_rejected, rejected_run)``; ValueError without a trusted feasible point."""
    axes = _map_axes(pin, space, *sizes)
    grids, sol = _solve_map(pin, v0, axes, on, settings, space)
    feasible = space.feasible(*grids[:3])
    value = np.where(feasible & sol["trusted"], _objective(goal, sol["cof"]), np.inf)
    order = [k for k in np.argsort(value, axis=None)[:starts] if np.isfinite(value.flat[k])]
    if not order:
        raise ValueError(f"no trusted point of the map respects the limits "
                         f"({int((feasible & ~sol['trusted']).sum())} untrusted within them)")
    steps = [_log_step(axes[0]), _log_step(axes[1]), _log_step(axes[2]),
             2 * math.pi / axes[3].size if axes[3].size > 1 else 0.2]
    (point, obj), n_rej, rej_run = _refine_inplane(
        pin, v0, on, goal, settings, space,
        [(tuple(float(g.flat[k]) for g in grids), float(value.flat[k])) for k in order],
        steps)
    return point, obj, grids, axes, sol, feasible, n_rej, rej_run


def _untrusted_near_nd(untrusted: np.ndarray, axes, point) -> int:
    """Untrusted map points among the neighbours of the map point nearest ``point``
    (amplitudes and frequency by ratio, the phase by its periodic distance)."""
    index = []
    for k, (ax, v) in enumerate(zip(axes, point, strict=True)):
        if k == 3:
            d = np.abs(np.angle(np.exp(1j * (ax - v))))
        elif v == 0.0 or not np.any(ax > 0):
            d = np.abs(ax - v)
        else:
            with np.errstate(divide="ignore"):
                d = np.abs(np.log(np.where(ax > 0.0, ax, 1e-300) / v))
        i = int(np.argmin(d))
        index.append(slice(max(i - 1, 0), i + 2))
    return int(untrusted[tuple(index)].sum())


def _direction_row(name, pin, v0, on, goal, space, sizes, starts, settings):
    """The best choice within ``space``: a row of ``directions`` (``du_x``, ``phase_x``,
    ``du_y``, ``phase_y``: the one along ``space.component`` set, the other 0)."""
    try:
        point, _, *_ = _optimise(pin, v0, on, goal, space, sizes, starts, settings)
    except ValueError:
        return {"direction": name, "omega": math.nan, "du_z": math.nan, "du_x": math.nan,
                "phase_x": math.nan, "du_y": math.nan, "phase_y": math.nan,
                "cof": math.nan, "allowed": False}
    cof = float(space.solve(pin, v0, *point, on, settings)["cof"])
    d, ph = point[2], point[3] if point[2] > 0.0 else 0.0
    inplane = ({"du_x": 0.0, "phase_x": 0.0, "du_y": d, "phase_y": ph}
               if space.component == "y" else
               {"du_x": d, "phase_x": point[3], "du_y": 0.0, "phase_y": 0.0})
    return {"direction": name, "omega": point[0], "du_z": point[1], **inplane, "cof": cof,
            "allowed": space.inside(*point[:3])}


def _design_inplane(pin: Physical, *, v0, omega, du_z, du_x, phase_x, inplane_on, goal,
                    velocity_rule, vmax, n_omega, n_du_z, n_du_x, n_phase, starts,
                    settings, du_y=None, phase_y=None, n_du_y=4,
                    n_phase_y=4) -> DesignResult:
    if goal not in GOALS:
        raise ValueError(f"goal must be one of {sorted(GOALS)}, got {goal!r}")
    if velocity_rule not in VELOCITY_RULES:
        raise ValueError(f"velocity_rule must be one of {sorted(VELOCITY_RULES)}, got "
                         f"{velocity_rule!r}")
    v0 = float(checked("v0", v0, minimum=0.0, strict=True))
    w_range = _range("omega", omega)
    z_range = _range("du_z", du_z, allow_zero=True)
    x_range = (0.0, 0.0) if du_x is None else _range("du_x", du_x, allow_zero=True)
    y_range = (0.0, 0.0) if du_y is None else _range("du_y", du_y, allow_zero=True)
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
    for name, n, least in (("n_omega", n_omega, 2), ("n_du_z", n_du_z, 2),
                           ("n_du_x", n_du_x, 2), ("n_phase", n_phase, 1),
                           ("starts", starts, 1), ("n_du_y", n_du_y, 2),
                           ("n_phase_y", n_phase_y, 1)):
        if int(n) != n or n < least:
            raise ValueError(f"{name} must be an integer >= {least}, got {n!r}")
    space = _Space(w_range, z_range, x_range, phase_x, vmax, velocity_rule)
    if not space.feasible(w_range[0], z_range[0], x_range[0]):
        raise ValueError(f"no oscillation in range respects max_velocity_amplitude = {vmax:g} "
                         f"m/s ({VELOCITY_RULES[velocity_rule]}): the smallest is "
                         f"{w_range[0] * math.hypot(z_range[0], x_range[0]):g}")
    sizes = (n_omega, n_du_z, n_du_x, n_phase)
    point, obj, grids, axes, sol, feasible, n_rejected, rejected_run = _optimise(
        pin, v0, on, goal, space, sizes, starts, settings)
    # which direction: the best normal-only and longitudinal-only choices in the limits
    rows = [{"direction": "combined", "omega": point[0], "du_z": point[1], "du_x": point[2],
             "phase_x": point[3], "du_y": 0.0, "phase_y": 0.0, "cof": math.nan,
             "allowed": True}]
    if z_range[1] > 0.0:
        rows.append(_direction_row("normal only", pin, v0, on, goal,
                                   space.restricted(du_x=(0.0, 0.0)), sizes, starts,
                                   settings))
    if x_range[1] > 0.0:
        rows.append(_direction_row("longitudinal only", pin, v0, on, goal,
                                   space.restricted(du_z=(0.0, 0.0), phase=0.0), sizes,
                                   starts, settings))
    if y_range[1] > 0.0:  # across the sliding: the 2-D solver, a smaller map
        plane = _Space(w_range, z_range, y_range, phase_y, vmax, velocity_rule, "y")
        plane_sizes = (min(n_omega, PLANE_MAP[0]), min(n_du_z, PLANE_MAP[1]), n_du_y,
                       n_phase_y)
        plane_starts = min(starts, PLANE_STARTS)
        if z_range[1] > 0.0:
            rows.append(_direction_row("normal + transverse", pin, v0, on, goal, plane,
                                       plane_sizes, plane_starts, settings))
        rows.append(_direction_row("transverse only", pin, v0, on, goal,
                                   plane.restricted(du_z=(0.0, 0.0), phase=0.0),
                                   plane_sizes, plane_starts, settings))
    choice = (*point, 0.0, 0.0)  # (omega, du_z, du_x, phase_x, du_y, phase_y)
    for row in rows[1:]:  # a sub-design inside the allowed set that did better wins
        if row["allowed"] and np.isfinite(row["cof"]) and \
                float(_objective(goal, np.array(row["cof"]))) < obj:
            choice = tuple(row[k] for k in (*_AXES, "du_y", "phase_y"))
            obj = float(_objective(goal, np.array(row["cof"])))
    point = choice[:4]
    rows[0].update(zip((*_AXES, "du_y", "phase_y"), choice, strict=True))
    # choice is (omega, du_z, du_x, phase_x, du_y, phase_y): mypy cannot count a star
    at_opt = _solve(pin, v0, *choice[:2], settings, *choice[2:4], on, *choice[4:])  # type: ignore[call-arg]
    cof = float(at_opt["cof"])
    rows[0]["cof"] = cof
    directions = pd.DataFrame(rows)
    untrusted = feasible & ~sol["trusted"]
    near = _untrusted_near_nd(untrusted, axes, point)
    status, message = _status(untrusted, feasible, near, n_rejected, rejected_run)
    chosen = pin.with_(omega=point[0], du_z=point[1], du_x=point[2],
                       phase_x=point[3] if point[2] > 0.0 else 0.0, du_y=choice[4],
                       phase_y=choice[5] if choice[4] > 0.0 else 0.0, inplane_on=on)
    attrs = {"v0": v0, "goal": goal, "inplane_on": on, "velocity_rule": velocity_rule,
             "max_velocity_amplitude": vmax, "status": status,
             "n_untrusted": int(untrusted.sum()), "n_untrusted_near": near,
             "n_rejected": n_rejected, "optimum_cof": cof,
             **{f"optimum_{k}": v for k, v in zip((*_AXES, "du_y", "phase_y"), choice,
                                                  strict=True)}}
    dmap = _dataset_nd(axes, sol, feasible, attrs)
    result = DesignResult(
        system=chosen, v0=v0, cof=cof, mu_ratio=cof / pin.mu0, error=float(at_opt["error"]),
        map=dmap, sensitivity=_sensitivity(chosen, v0, settings), status=status,
        message=message, n_untrusted=int(untrusted.sum()), n_untrusted_near=near,
        n_rejected=n_rejected, goal=goal, velocity_rule=velocity_rule,
        directions=directions,
        phase_map=_phase_map(pin, v0, on, space, point, settings))
    if goal == "drive":
        _drive_characteristic(result, settings)
    return result


def _phase_map(pin, v0, on, space: _Space, point, settings, n_phase: int = 73,
               n_du_x: int = 25) -> xr.Dataset | None:
    """The COF over ``(du_x, phase_x)`` at the chosen ``omega`` and ``du_z`` (what
    :func:`~vibrofriction.figures.plot_design` shows) when the phase is free (one
    ``du_x`` when its range is a point)."""
    if space.phase is not None or space.du_x[1] == 0.0:
        return None
    w, dz = point[0], point[1]
    dxs = np.linspace(space.du_x[0], space.du_x[1], n_du_x if space.du_x[0] < space.du_x[1]
                      else 1)
    phs = np.linspace(0.0, 2 * math.pi, n_phase)
    DX, PH = np.meshgrid(dxs, phs, indexing="ij")
    sol = _solve(pin, v0, w, dz, settings, DX, PH, on)
    dims = ("du_x", "phase_x")
    return xr.Dataset(
        {"cof": (dims, sol["cof"]), "trusted": (dims, sol["trusted"]),
         "feasible": (dims, space.feasible(w, dz, DX))},
        coords={"du_x": ("du_x", dxs, {"units": "m"}),
                "phase_x": ("phase_x", phs, {"units": "rad"})},
        attrs={"omega": w, "du_z": dz, "v0": v0})


def _dataset_nd(axes, sol, feasible, attrs) -> xr.Dataset:
    return xr.Dataset(
        {"cof": (_AXES, sol["cof"], {"long_name": "coefficient of friction mu0 mu/mu0 "
                                                  "(signed; nan where not trusted)"}),
         "mu_ratio": (_AXES, sol["mu_ratio"], {"long_name": "mu_macro/mu0 as the solver "
                                                            "left it (trusted or not)"}),
         "error": (_AXES, sol["error"], {"long_name": "estimate of |mu_ratio - exact|"}),
         "trusted": (_AXES, sol["trusted"]),
         "feasible": (_AXES, feasible, {"long_name": "within max_velocity_amplitude"})},
        coords={"omega": ("omega", axes[0], {"units": "rad s-1"}),
                "du_z": ("du_z", axes[1], {"units": "m"}),
                "du_x": ("du_x", axes[2], {"units": "m"}),
                "phase_x": ("phase_x", axes[3], {"units": "rad"})},
        attrs=attrs)


def _drive_characteristic(result: DesignResult, settings: SolverSettings | None) -> None:
    """The chosen oscillation's blocking force (``mu`` at ``V = +-BLOCKING_V``) and idle
    velocity (the root of ``mu(V) = 0`` above ``v0``, Brent's method on the solver,
    bracketed by a scan up to ``1.01 V_c``, theory's critical velocity), in place."""
    from scipy.optimize import brentq

    from .. import theory

    s = result.system
    d = s.to_dimensionless()
    args = (d.alpha, d.beta, d.amplitude)
    tail: dict[str, Any] = dict(zeta=d.zeta, eta_c=d.eta_c, a_x=d.a_x, phase_x=d.phase_x,
                                inplane_on=d.inplane_on, settings=settings)
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
