"""Figures of the bench: a fit against its data, its profiles, a design's map (docs/bench.md).

Pure drawing on :class:`~vibrofriction.bench.FitResult` and
:class:`~vibrofriction.bench.DesignResult`; each returns a ``matplotlib.figure.Figure``.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import LogLocator, NullFormatter

from ..bench import DesignResult, FitResult
from . import style

__all__ = ["plot_design", "plot_fit", "plot_profiles"]


@style.styled
def plot_fit(result: FitResult) -> Figure:
    """Data with error bars, the fitted curves per (amplitude, frequency) and the residuals.

    The title gives the free parameters, the verdict and the reduced chi-square.
    """
    fig = style.figure(6.0, 5.0)
    ax, axr = fig.subplots(2, 1, sharex=True, height_ratios=(3, 1))
    inplane_columns = ("du_x", "phase_x", "du_y", "phase_y")
    data = result.data.assign(**{c: result.data.get(c, 0.0) for c in inplane_columns})
    signed = bool((data["v0"] <= 0.0).any())  # an in-plane oscillation: both directions
    for k, ((du, om, dx, ph, dy, py), g) in enumerate(data.groupby(
            ["du_z", "omega", *inplane_columns], sort=True)):
        color = f"C{k % 10}"
        lo, hi = g["v0"].min(), g["v0"].max()
        v = (np.linspace(lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo), 240) if signed
             else np.geomspace(max(lo, 1e-9) / 1.5, hi * 1.5, 120))
        if dy > 0:  # the 2-D solver: not at v0 = 0, and slow (minutes) very near it
            v = v[np.abs(v) >= 0.5 * np.abs(g["v0"]).min()]
        inplane = f", du_x = {dx * 1e6:.3g} um at {ph:.3g} rad" if dx > 0 else ""
        inplane += f", du_y = {dy * 1e6:.3g} um at {py:.3g} rad" if dy > 0 else ""
        ax.plot(v, result.predict(v, np.full(v.size, du), np.full(v.size, om), du_x=dx,
                                  phase_x=ph, du_y=dy, phase_y=py), color=color, lw=1.2,
                label=f"du_z = {du * 1e6:.3g} um, f = {om / (2 * math.pi):.4g} Hz{inplane}")
        yerr = g["sigma"] if np.all(np.isfinite(g["sigma"])) else None
        ax.errorbar(g["v0"], g["cof"], yerr=yerr, fmt="o", ms=3, color=color, capsize=2)
        res = g["cof"] - result.predict(g["v0"].to_numpy(), g["du_z"].to_numpy(),
                                        g["omega"].to_numpy(), du_x=g["du_x"].to_numpy(),
                                        phase_x=g["phase_x"].to_numpy(),
                                        du_y=g["du_y"].to_numpy(),
                                        phase_y=g["phase_y"].to_numpy())
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
def plot_profiles(result: FitResult, truth: dict[str, float] | None = None) -> Figure:
    """The profile chi-square of each free parameter, its level and its 95 % interval.

    Every refit the profiles made (the others refitted, the parameter held; points, not a
    line: the profiles from two valleys are two curves), the rise above
    the fit's chi-square against the parameter, the level that bounds the interval, the
    interval (shaded; the search range when not determined), the fit and, where given, the
    ``truth``; the jumps of the model at an interval's end in red.
    """
    shape = result.extra.get("profiles")
    if not shape:
        raise ValueError("this fit has no profiles to show (a fit loaded from JSON keeps none: "
                         "plot the result vf.fit returned)")
    free = list(result.free)
    cols = min(len(free), 3)
    rows = math.ceil(len(free) / cols)
    fig = style.figure(3.0 * cols, 2.5 * rows)
    axes = np.atleast_1d(fig.subplots(rows, cols, squeeze=False)).ravel()
    level, chi = shape["level"], shape["chisqr"]
    for ax, name in zip(axes, free, strict=False):
        curve = np.array(shape["curves"][name]) if shape["curves"][name] else np.zeros((0, 2))
        best = result.params[name].value
        if curve.size:
            x, rise = np.exp(curve[:, 0]), curve[:, 1] - chi
            order = np.argsort(x)
            ax.plot(x[order], rise[order], ".", color="C0", ms=4,
                    label="profile refits")
        lo, hi = result.intervals.get(name, (math.nan, math.nan))
        status = result.determination.get(name, "")
        ax.axvspan(lo if math.isfinite(lo) else ax.get_xlim()[0],
                   hi if math.isfinite(hi) else ax.get_xlim()[1], color="C2", alpha=0.15,
                   label="95 % interval")
        ax.axhline(level, color="k", lw=0.8, ls="--", label=f"level {level:.3g}")
        ax.axvline(best, color="C1", lw=1.0, label="fit")
        if truth and name in truth:
            ax.axvline(truth[name], color="C3", lw=1.0, ls=":", label="truth")
        for j in shape["jumps"][name]:
            ax.plot([math.exp(j)], [level], "v", color="C3", ms=6)
        shown = [v for v in (*(np.exp(curve[:, 0]) if curve.size else ()), lo, hi, best)
                 if math.isfinite(v) and v > 0]
        if max(shown) / min(shown) > 5.0:  # decades: a log axis, labels at 1, 2, 5
            ax.set_xscale("log")
            ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
            ax.xaxis.set_minor_formatter(NullFormatter())
        ax.tick_params(axis="x", labelsize="x-small")
        ax.set_ylim(-0.05 * 3 * level, 3 * level)
        ax.set_xlabel(name)
        ax.set_title(status, fontsize="small")
    axes[0].set_ylabel("chi-square rise")
    axes[0].legend(fontsize="x-small", loc="upper left")
    for ax in axes[len(free):]:
        ax.set_visible(False)
    return fig


@style.styled
def plot_design(result: DesignResult) -> Figure:
    """A design's map: the COF over the actuator's range.

    The COF over the actuator's range (white: untrusted or beyond the velocity
    limit), the optimum and the pin's resonance.  An in-plane design: the signed COF
    over ``(phase_x, du_x)`` at the chosen frequency and ``du_z``, and over
    ``(omega, du_z)`` at the map's ``du_x`` and ``phase_x`` nearest the optimum.
    """
    if result.inplane:
        return _plot_design_inplane(result)
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


def _signed_mesh(ax, x, y, cof, label):
    """A signed COF in RdBu_r centred on 0 (blue: the oscillation pushes)."""
    from matplotlib.colors import TwoSlopeNorm

    finite = cof[np.isfinite(cof)]
    span = max(float(np.max(np.abs(finite))) if finite.size else 1.0, 1e-12)
    mesh = ax.pcolormesh(x, y, cof, shading="nearest", cmap="RdBu_r",
                         norm=TwoSlopeNorm(0.0, -span, span))
    ax.figure.colorbar(mesh, ax=ax, label=label)
    if finite.size and finite.min() < 0.0 < finite.max():
        ax.contour(x, y, cof, levels=[0.0], colors="k", linewidths=0.8)


def _adding_phase(system) -> float | None:
    """The phase that cancels the in-plane oscillation's effect, or None.

    ``theory.inplane_cancellation(...).phase_x + pi`` (mod 2 pi) of the chosen
    oscillation, where its closed form applies (``a <= 1``), else None.
    """
    from .. import theory

    d = system.to_dimensionless()
    try:
        c = theory.inplane_cancellation(d.alpha, d.beta, d.amplitude, d.zeta, d.eta_c,
                                        d.inplane_on)
    except ValueError:
        return None
    phase = float(c.phase_x)
    return (phase + math.pi) % (2 * math.pi) if math.isfinite(phase) else None


def _plot_design_inplane(result: DesignResult) -> Figure:
    fig = style.figure(10.0, 4.8)
    left, right = fig.subplots(1, 2)
    s = result.system
    goal = "largest drive force" if result.goal == "drive" else "smallest |COF|"
    star = dict(color="gold", marker="*", ms=14, mec="k", ls="none",
                label=f"optimum ({goal}): COF {result.cof:.4g}")
    label = "COF (signed; white: untrusted or beyond the limit; black line: 0)"
    pm = result.phase_map
    if pm is not None and pm["du_x"].size == 1:
        cof = np.where(pm["feasible"].values & pm["trusted"].values, pm["cof"].values, np.nan)
        left.plot(pm["phase_x"].values, cof[0], color="C0", label="COF (trusted)")
        left.plot([s.phase_x], [result.cof], **star)
        left.axhline(0.0, color="0.5", lw=0.6)
        left.set_xlabel("phase_x (rad)")
        left.set_ylabel(f"COF at du_x = {s.du_x * 1e6:.3g} um")
    elif pm is not None:
        cof = np.where(pm["feasible"].values & pm["trusted"].values, pm["cof"].values, np.nan)
        _signed_mesh(left, pm["phase_x"].values, pm["du_x"].values * 1e6, cof, label)
        left.set_title(f"at f = {s.omega / (2 * math.pi):.5g} Hz, du_z = {s.du_z * 1e6:.3g} um",
                       fontsize=8)
    else:
        left.text(0.5, 0.5, "phase or du_x fixed:\nno (phase_x, du_x) map",
                  ha="center", va="center", transform=left.transAxes)
    adding = _adding_phase(s)
    if adding is not None:
        left.axvline(adding, color="0.3", lw=0.8, ls=":",
                     label="theory: adding phase (largest V_c)")
    if pm is None or pm["du_x"].size > 1:
        left.plot([s.phase_x], [s.du_x * 1e6], **star)
        left.set_xlabel("phase_x (rad)")
        left.set_ylabel("in-plane amplitude du_x (um)")
    left.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2,
                frameon=False)  # below the axes: the map stays visible
    m = result.map
    ix = int(np.argmin(np.abs(m["du_x"].values - s.du_x)))
    ip = int(np.argmin(np.abs(np.angle(np.exp(1j * (m["phase_x"].values - s.phase_x))))))
    sl = m.isel(du_x=ix, phase_x=ip)
    sl = sl.isel(du_z=sl["du_z"].values > 0)
    if sl["du_z"].size * sl["omega"].size == 1:
        right.text(0.5, 0.8, "frequency and du_z fixed", ha="center", va="center",
                   transform=right.transAxes)
    elif sl["du_z"].size:
        cof = np.where(sl["feasible"].values & sl["trusted"].values, sl["cof"].values, np.nan)
        _signed_mesh(right, sl["omega"].values / (2 * math.pi), sl["du_z"].values * 1e6, cof.T,
                     label)
        if sl["du_z"].values.max() > 10 * sl["du_z"].values.min():
            right.set_yscale("log")
    right.plot([s.omega / (2 * math.pi)], [s.du_z * 1e6], **star)
    if m["omega"].values.max() > 10 * m["omega"].values.min():
        right.set_xscale("log")
    for axis in (right.xaxis, right.yaxis):
        axis.set_minor_formatter(NullFormatter())
    right.set_xlabel("drive frequency (Hz)")
    right.set_ylabel("normal amplitude du_z (um)")
    right.set_title(f"map at du_x = {m['du_x'].values[ix] * 1e6:.3g} um, phase_x = "
                    f"{m['phase_x'].values[ip]:.3g} rad (nearest the optimum)", fontsize=8)
    fig.suptitle(f"{result.goal} design at v0 = {result.v0:g} m/s ({s.inplane_on}); "
                 f"{result.n_untrusted} untrusted map points", fontsize=9)
    return fig
