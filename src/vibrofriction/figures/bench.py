"""Figures of the bench: a fit against its data, and a design's map (docs/bench.md).

Pure drawing on :class:`~vibrofriction.bench.FitResult` and
:class:`~vibrofriction.bench.DesignResult`; each returns a ``matplotlib.figure.Figure``.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import NullFormatter

from ..bench import DesignResult, FitResult
from . import style

__all__ = ["plot_design", "plot_fit"]


@style.styled
def plot_fit(result: FitResult) -> Figure:
    """Data with error bars, the fitted curves per (amplitude, frequency) and the
    residuals; the title gives the free parameters, the verdict and the reduced
    chi-square."""
    fig = style.figure(6.0, 5.0)
    ax, axr = fig.subplots(2, 1, sharex=True, height_ratios=(3, 1))
    data = result.data.assign(**{c: result.data.get(c, 0.0) for c in ("du_x", "phase_x")})
    signed = bool((data["v0"] <= 0.0).any())  # an in-plane oscillation: both directions
    for k, ((du, om, dx, ph), g) in enumerate(data.groupby(
            ["du_z", "omega", "du_x", "phase_x"], sort=True)):
        color = f"C{k % 10}"
        lo, hi = g["v0"].min(), g["v0"].max()
        v = (np.linspace(lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo), 240) if signed
             else np.geomspace(max(lo, 1e-9) / 1.5, hi * 1.5, 120))
        inplane = f", du_x = {dx * 1e6:.3g} um at {ph:.3g} rad" if dx > 0 else ""
        ax.plot(v, result.predict(v, np.full(v.size, du), np.full(v.size, om), du_x=dx,
                                  phase_x=ph), color=color, lw=1.2,
                label=f"du_z = {du * 1e6:.3g} um, f = {om / (2 * math.pi):.4g} Hz{inplane}")
        yerr = g["sigma"] if np.all(np.isfinite(g["sigma"])) else None
        ax.errorbar(g["v0"], g["cof"], yerr=yerr, fmt="o", ms=3, color=color, capsize=2)
        res = g["cof"] - result.predict(g["v0"].to_numpy(), g["du_z"].to_numpy(),
                                        g["omega"].to_numpy(), du_x=g["du_x"].to_numpy(),
                                        phase_x=g["phase_x"].to_numpy())
        axr.errorbar(g["v0"], res, yerr=yerr, fmt="o", ms=3, color=color, capsize=2)
    axr.axhline(0.0, color="0.5", lw=0.6)
    ax.set_xscale("linear" if signed else "log")
    ax.set_ylabel("COF")
    axr.set_ylabel("residual")
    axr.set_xlabel("sliding velocity v0 (m/s)")
    ax.legend(fontsize=7)
    verdict = "" if result.quality == "good" else f"{result.quality.upper()} FIT; "
    ax.set_title(f"fit: {', '.join(result.free)} free; {verdict}reduced chi-square "
                 f"{result.redchi:.3g}", fontsize=8)
    return fig


@style.styled
def plot_design(result: DesignResult) -> Figure:
    """The COF over the actuator's range (white: untrusted or beyond the velocity
    limit), the optimum and the pin's resonance."""
    fig = style.figure(5.6, 4.2)
    ax = fig.add_subplot()
    m = result.map
    f_hz = m["omega"].values / (2 * math.pi)
    m = m.isel(du_z=m["du_z"].values > 0)  # no oscillation (COF = mu0): off the log axis
    cof = np.where(m["feasible"].values & m["trusted"].values, m["cof"].values, np.nan)
    mesh = ax.pcolormesh(f_hz, m["du_z"].values * 1e6, cof.T, shading="nearest",
                         cmap="viridis")
    fig.colorbar(mesh, ax=ax, label="COF (white: untrusted or beyond the limit)")
    s = result.system
    ax.plot([s.omega / (2 * math.pi)], [s.du_z * 1e6], "r*", ms=12,
            label=f"optimum: COF {result.cof:.4g}")
    f_n = math.sqrt(s.k_x / s.mass) / (2 * math.pi)
    ax.axvline(f_n, color="w", lw=0.8, ls="--", label=f"pin resonance {f_n:.4g} Hz")
    ax.set_xscale("log")
    ax.set_yscale("log")
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("drive frequency (Hz)")
    ax.set_ylabel("amplitude du_z (um)")
    ax.set_title(f"COF at v0 = {result.v0:g} m/s over the actuator's range; "
                 f"{result.n_untrusted} untrusted", fontsize=8)
    ax.legend(fontsize=7, loc="lower left")
    return fig
