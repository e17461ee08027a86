"""Designing the oscillation: the frequency and amplitude that minimise friction (docs/bench.md).

``design(pin, v0=..., omega=(lo, hi), du_z=(lo, hi), max_velocity_amplitude=None)``
solves the model on a map over the actuator's range (logarithmic in both, the pin's
natural frequency and the contact resonance ``sqrt((k_x + k_xc)/m)`` added to the
frequencies when they lie inside, because the resonant optimum can be sharp), takes
the lowest trusted point of the map that respects the velocity limit
``omega * du_z <= max_velocity_amplitude``, and refines it by Nelder-Mead in
``(ln omega, ln du_z)`` inside the limits.  The map is returned, so that the optimum
can be seen to be the global one within the limits and not a local dip.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd
import xarray as xr

from .fitting import predict_cof
from .params import Physical
from .validation import checked

__all__ = ["DesignResult", "design"]

#: Relative changes of the drive frequency in the sensitivity table.
FREQUENCY_CHANGES = (-0.05, -0.01, 0.01, 0.05)
#: Relative change of each pin parameter in the sensitivity table.
PARAMETER_CHANGE = 0.10
PIN_PARAMETERS = ("mass", "k_x", "k_xc", "k_zc", "c_x", "mu0")


@dataclass
class DesignResult:
    """The chosen oscillation and what it is worth.

    ``system``: the pin at the chosen ``omega`` and ``du_z``; ``cof`` and ``mu_ratio``
    there; ``map``: the labelled Dataset over ``(omega, du_z)`` (``cof``, ``mu_ratio``,
    ``trusted``, ``feasible``) with the optimum in its attributes; ``sensitivity``: the
    COF when the frequency is off by +-1, +-5 % and when each pin parameter is off by
    +-10 % (a DataFrame).
    """

    system: Physical
    v0: float
    cof: float
    mu_ratio: float
    map: xr.Dataset
    sensitivity: pd.DataFrame

    def plot(self):
        """The map of the COF over the actuator's range with the optimum (a Figure)."""
        from matplotlib.figure import Figure

        fig = Figure(figsize=(5.6, 4.2), layout="constrained")
        ax = fig.add_subplot()
        m = self.map
        f_hz = m["omega"].values / (2 * math.pi)
        cof = np.where(m["feasible"].values & m["trusted"].values, m["cof"].values, np.nan)
        mesh = ax.pcolormesh(f_hz, m["du_z"].values * 1e6, cof.T, shading="nearest",
                             cmap="viridis")
        fig.colorbar(mesh, ax=ax, label="COF")
        ax.plot([self.system.omega / (2 * math.pi)], [self.system.du_z * 1e6], "r*", ms=12,
                label=f"optimum: COF {self.cof:.4g}")
        f_n = math.sqrt(self.system.k_x / self.system.mass) / (2 * math.pi)
        ax.axvline(f_n, color="w", lw=0.8, ls="--", label=f"pin resonance {f_n:.4g} Hz")
        from matplotlib.ticker import NullFormatter

        ax.set_xscale("log")
        ax.set_yscale("log")
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_minor_formatter(NullFormatter())
        ax.set_xlabel("drive frequency (Hz)")
        ax.set_ylabel("amplitude du_z (um)")
        ax.set_title(f"COF at v0 = {self.v0:g} m/s over the actuator's range", fontsize=8)
        ax.legend(fontsize=7, loc="lower left")
        return fig

    def report(self) -> str:
        s = self.system
        lines = [f"optimum at v0 = {self.v0:g} m/s: f = {s.omega / (2 * math.pi):.6g} Hz, "
                 f"du_z = {s.du_z:.4g} m (velocity amplitude {s.omega * s.du_z:.4g} m/s): "
                 f"COF {self.cof:.5g} (mu/mu0 = {self.mu_ratio:.5g})",
                 "sensitivity (COF):"]
        for _, row in self.sensitivity.iterrows():
            lines.append(f"  {row['change']:>28s}: {row['cof']:.5g}")
        return "\n".join(lines)


def _range(name: str, value) -> tuple[float, float]:
    try:
        lo, hi = (float(x) for x in value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a pair (low, high), got {value!r}") from None
    checked(name, np.array([lo, hi]), minimum=0.0, strict=True)
    if not lo <= hi:
        raise ValueError(f"{name}: low {lo!r} > high {hi!r}")
    return lo, hi


def _cof(pin: Physical, v0: float, omega, du_z) -> np.ndarray:
    omega, du_z = np.broadcast_arrays(np.asarray(omega, float), np.asarray(du_z, float))
    return predict_cof(pin, np.full(omega.shape, v0), du_z, omega)


def design(pin: Physical, *, v0: float, omega: tuple[float, float],
           du_z: tuple[float, float], max_velocity_amplitude: float | None = None,
           n_omega: int = 161, n_du_z: int = 41, starts: int = 8) -> DesignResult:
    """The oscillation (``omega`` in rad/s, ``du_z`` in m, within the given ranges and
    ``omega du_z <= max_velocity_amplitude``) that minimises the COF of ``pin`` at the
    sliding velocity ``v0`` (m/s); ``pin``'s own ``omega``, ``du_z`` are not used."""
    from scipy.optimize import minimize

    v0 = float(checked("v0", v0, minimum=0.0, strict=True))
    w_lo, w_hi = _range("omega", omega)
    d_lo, d_hi = _range("du_z", du_z)
    vmax = math.inf if max_velocity_amplitude is None else float(checked(
        "max_velocity_amplitude", max_velocity_amplitude, minimum=0.0, strict=True))
    if w_lo * d_lo > vmax:
        raise ValueError(f"no oscillation in range respects max_velocity_amplitude = {vmax:g} "
                         f"m/s: the smallest omega * du_z is {w_lo * d_lo:g}")
    ws = np.geomspace(w_lo, w_hi, n_omega)
    resonances = [math.sqrt(pin.k_x / pin.mass)]
    if math.isfinite(pin.k_xc):
        resonances.append(math.sqrt((pin.k_x + pin.k_xc) / pin.mass))
    ws = np.unique(np.concatenate([ws, [w for w in resonances if w_lo <= w <= w_hi]]))
    ds = np.geomspace(d_lo, d_hi, n_du_z)
    W, D = np.meshgrid(ws, ds, indexing="ij")
    alpha, beta, a, zeta, eta = pin.groups(D, W)
    from .solver import solve_points

    out = solve_points(alpha, beta, a, pin.v0_to_inertial(v0, W), zeta, eta)
    cof = pin.mu0 * out["mu_ratio"]
    feasible = W * D <= vmax * (1 + 1e-12)
    candidates = np.where(feasible & out["trusted"], cof, np.inf)
    order = np.argsort(candidates, axis=None)[:starts]
    if not np.isfinite(candidates.flat[order[0]]):
        raise ValueError("no trusted point of the map respects the limits")

    def objective(x):
        w, d = math.exp(x[0]), math.exp(x[1])
        if not (w_lo <= w <= w_hi and d_lo <= d <= d_hi and w * d <= vmax):
            return math.inf
        return float(_cof(pin, v0, w, d))

    # refine from the best map points (the landscape is jagged where the stick-slip
    # pattern changes): Nelder-Mead inside the limits from each, keep the lowest
    w_opt, d_opt, c_opt = float(W.flat[order[0]]), float(D.flat[order[0]]), \
        float(candidates.flat[order[0]])
    step = math.log(ws[1] / ws[0]) if ws.size > 1 else 0.1
    for k in order:
        if not np.isfinite(candidates.flat[k]):
            break
        x0 = np.log([W.flat[k], D.flat[k]])
        simplex = np.array([x0, x0 + [step, 0.0], x0 + [0.0, -step]])
        best = minimize(objective, x0, method="Nelder-Mead",
                        options={"xatol": 1e-7, "fatol": 1e-10, "maxfev": 150,
                                 "initial_simplex": simplex})
        if best.fun < c_opt:
            w_opt, d_opt, c_opt = math.exp(best.x[0]), math.exp(best.x[1]), float(best.fun)
    chosen = pin.with_(omega=w_opt, du_z=d_opt)
    dmap = xr.Dataset(
        {"cof": (("omega", "du_z"), cof, {"long_name": "coefficient of friction mu0 mu/mu0"}),
         "mu_ratio": (("omega", "du_z"), out["mu_ratio"], {"long_name": "mu_macro/mu0"}),
         "trusted": (("omega", "du_z"), out["trusted"]),
         "feasible": (("omega", "du_z"), feasible,
                      {"long_name": "omega du_z <= max_velocity_amplitude"})},
        coords={"omega": ("omega", ws, {"units": "rad s-1"}),
                "du_z": ("du_z", ds, {"units": "m"})},
        attrs={"v0": v0, "optimum_omega": w_opt, "optimum_du_z": d_opt, "optimum_cof": c_opt,
               "max_velocity_amplitude": vmax})
    return DesignResult(system=chosen, v0=v0, cof=c_opt, mu_ratio=c_opt / pin.mu0, map=dmap,
                        sensitivity=_sensitivity(chosen, v0))


def _sensitivity(chosen: Physical, v0: float) -> pd.DataFrame:
    rows = [("optimum", float(_cof(chosen, v0, chosen.omega, chosen.du_z)))]
    for c in FREQUENCY_CHANGES:
        w = chosen.omega * (1 + c)
        rows.append((f"frequency {100 * c:+.0f} %", float(_cof(chosen, v0, w, chosen.du_z))))
    for name in PIN_PARAMETERS:
        base = getattr(chosen, name)
        if base == 0.0 or not math.isfinite(base):
            continue
        for sign in (-1, 1):
            p = chosen.with_(**{name: base * (1 + sign * PARAMETER_CHANGE)})
            rows.append((f"{name} {sign * 100 * PARAMETER_CHANGE:+.0f} %",
                         float(_cof(p, v0, p.omega, p.du_z))))
    return pd.DataFrame(rows, columns=["change", "cof"])
