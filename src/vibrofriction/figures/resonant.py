r"""Fig. 6 (the resonant case IV) and the model's prediction for the experiment (Figs. 8-9).

Case IV: ``alpha = 1`` (drive at the natural frequency of the pin) on a rigid
contact (``beta = inf``), as in the paper's analysis (eqs. 27-32).  ``vbar`` does
not exist (``v0* = inf``); the velocity axis is ``V = v0 m omega/(mu0 F_N0)``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from .. import theory
from . import style
from .checks import (
    fig6_checks,
    fig6_note,
    prediction_note,
    resonant_velocity_amplitude,  # re-exported: moved to .checks
)
from .recipe import Recipe, Rendered, curve_table
from .series import Curve, Series

__all__ = [
    "FIG6_AMPLITUDES",
    "FIG6_V_MAX",
    "EXPERIMENT",
    "EXPERIMENT_AMPLITUDES_UM",
    "fig6",
    "fig8_9",
    "resonant_velocity_amplitude",
]

FIG6_AMPLITUDES: tuple[float, ...] = (0.2, 0.5, 0.8, 1.0, 1.5, 2.0)
FIG6_V_MAX = 12.0
#: Velocities at which the plateau itself is measured (far beyond the figure's range).
_PLATEAU_V = (50.0, 200.0)

#: The paper's experiment (Section 7) as far as it is stated -- pin natural frequency
#: about 800 Hz, driven at resonance -- plus the assumptions needed for a prediction.
EXPERIMENT: dict[str, float] = {
    "f_hz": 800.0,      # stated: natural frequency of the pin = drive frequency
    "mass": 0.01,       # assumed modal mass of the pin, kg
    "F_N0": 1.0,        # assumed mean normal force, N
    "mu0": 0.3,         # assumed local coefficient of friction
    "u_z0": 10e-6,      # assumed mean indentation, m
}
#: Oscillation amplitudes of Fig. 9 (stated), micrometres.
EXPERIMENT_AMPLITUDES_UM: tuple[float, ...] = (1.3, 5.4, 8.2, 60.0)
_U_Z0_ALTERNATIVES_UM = (5.0, 10.0, 30.0)


# --------------------------------------------------------------------------- Fig. 6
def _fig6_series(quick: bool) -> tuple[Series, ...]:
    n = 61 if quick else 301
    V = np.linspace(0.0, FIG6_V_MAX, n)
    out = [Series(f"a={a:g}", 1.0, math.inf, a, V, np.full(n, np.nan), {"role": "curve"})
           for a in FIG6_AMPLITUDES]
    out += [Series(f"plateau,a={a:g}", 1.0, math.inf, a, np.array(_PLATEAU_V),
                   np.full(len(_PLATEAU_V), np.nan), {"role": "plateau"})
            for a in FIG6_AMPLITUDES]
    return tuple(out)


@style.styled
def _draw_fig6(curves: Mapping[str, Curve]):
    fig = style.figure(style.COLUMN, 3.4)
    ax = fig.add_subplot()
    for a in FIG6_AMPLITUDES:
        c = curves[f"a={a:g}"]
        color = "black" if a <= 1.0 else "0.55"
        ax.plot(c.v_inertial, c.trusted_mu, color=color, lw=1.1)
        style.mark_untrusted(ax, c.v_inertial, c, style.THEORY, ms=2.5)
        exact = float(theory.resonant_plateau_exact(a))
        approx = 1.0 - a / 2.0
        ax.axhline(exact, color=style.THEORY, lw=0.6, ls=(0, (1, 1.5)))
        if approx > 0:
            ax.plot([FIG6_V_MAX * 0.72, FIG6_V_MAX], [approx, approx], color=style.THEORY,
                    lw=0.8, ls="--")
        ax.plot([0], [float(theory.static_mu_ratio(a))], "o", ms=3, color=color, clip_on=False,
                zorder=5)
        ax.text(FIG6_V_MAX * 0.985, exact + 0.01, f"{a:g}", ha="right", va="bottom",
                fontsize=6, color=color)
    ax.set_xlim(0, FIG6_V_MAX)
    ax.set_ylim(-0.02, 1.0)
    ax.set_xlabel(style.V_INERTIAL)
    ax.set_ylabel(style.MU)
    from matplotlib.lines import Line2D
    fig.legend(handles=[
        Line2D([], [], color="black", lw=1.1, label=r"numerics, $\Delta F_N/F_{N,0}\leq 1$"),
        Line2D([], [], color="0.55", lw=1.1, label=r"numerics, jumping ($>1$)"),
        Line2D([], [], color="black", marker="o", ls="none", ms=3,
               label="static value, eq. (2)"),
        Line2D([], [], color=style.THEORY, lw=0.8, ls="--",
               label=r"$1 - \Delta F_N/(2F_{N,0})$, eq. (32)"),
        Line2D([], [], color=style.THEORY, lw=0.6, ls=(0, (1, 1.5)),
               label=r"plateau, exact $\tau^*$ (and $\langle F_N\rangle$)")],
        loc="outside lower center", fontsize=6, ncol=2, columnspacing=0.8, handlelength=2.2)
    ax.set_title(r"case IV: $\alpha = 1$, $\beta = \infty$; labels: $\Delta F_N/F_{N,0}$",
                 fontsize=7)
    return fig


def fig6(quick: bool = False) -> Recipe:
    """Fig. 6: case IV, mu/mu0 against V for non-jumping and jumping amplitudes."""

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_fig6(curves)
        table = curve_table("Fig. 6: resonant case IV", curves, (
            "alpha = 1, beta = inf (rigid contact); amplitudes a = dF_N/F_N0 = "
            f"{FIG6_AMPLITUDES}",
            "velocity axis v_inertial = v0 m omega/(mu0 F_N0) (vbar does not exist: nan)",
            "series 'plateau,a=...' are the points at V = 50, 200 used to measure the plateau",
            "plateau_eq32 = 1 - a/2 (paper); plateau_approx = same approximation with loss "
            "of contact and <F_N> for a > 1; plateau_exact = 1 - (2/pi)(tau* + a sin tau*)/<n> "
            "with the exact root tau* of the energy balance (first eq. 32)"),
            extra=lambda c: {
                "plateau_eq32": np.full(c.series.size, 1.0 - c.series.amplitude / 2.0),
                "plateau_approx": np.full(c.series.size,
                                          float(theory.resonant_plateau(c.series.amplitude))),
                "plateau_exact": np.full(c.series.size, float(theory.resonant_plateau_exact(
                    c.series.amplitude)))})
        checks = fig6_checks(curves, FIG6_AMPLITUDES, _PLATEAU_V[-1], FIG6_V_MAX)
        notes = fig6_note(curves, FIG6_AMPLITUDES, _PLATEAU_V[-1])
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig06_resonant",
        title="Fig. 6: the resonant case IV",
        caption=("$\\mu_{macro}/\\mu_0$ against $v_0 m\\omega/(\\mu_0 F_{N,0})$ in case IV "
                 "($\\alpha = 1$, rigid contact) for $\\Delta F_N/F_{N,0}$ = "
                 + ", ".join(f"{a:g}" for a in FIG6_AMPLITUDES) + " (black: non-jumping, "
                 "gray: jumping). Dots: static values (eq. 2); red dashed: the paper's "
                 "plateau $1 - \\Delta F_N/(2F_{N,0})$; red dotted: the plateau with the exact "
                 "reverse-slip window $\\tau^*$ and, for jumping, the mean normal force."),
        series=_fig6_series(quick), render=render)


# --------------------------------------------------------------------------- Figs. 8-9
def _experiment_units() -> tuple[float, float]:
    """``(omega, velocity unit mu0 F_N0/(m omega))`` of the assumed experiment."""
    omega = 2.0 * math.pi * EXPERIMENT["f_hz"]
    unit = EXPERIMENT["mu0"] * EXPERIMENT["F_N0"] / (EXPERIMENT["mass"] * omega)
    return omega, unit


def _v0_grid(quick: bool) -> np.ndarray:
    return np.linspace(0.0, 0.3, 41 if quick else 151)


def _fig89_series(quick: bool) -> tuple[Series, ...]:
    _, unit = _experiment_units()
    v0 = _v0_grid(quick)
    out = []
    for du in EXPERIMENT_AMPLITUDES_UM:
        a = du * 1e-6 / EXPERIMENT["u_z0"]
        out.append(Series(f"du_z={du:g}um", 1.0, math.inf, a, v0 / unit,
                          np.full(v0.size, np.nan), {"v0": v0, "du_z_um": du}))
    return tuple(out)


@style.styled
def _draw_fig89(curves: Mapping[str, Curve]):
    fig = style.figure(style.PAGE, 3.0)
    ax, bx = fig.subplots(1, 2, width_ratios=[1.25, 1.0])
    mu0 = EXPERIMENT["mu0"]
    colors = style.sequence_colors(len(EXPERIMENT_AMPLITUDES_UM), "viridis", 0.0, 0.8)
    for du, col in zip(EXPERIMENT_AMPLITUDES_UM, colors, strict=True):
        c = curves[f"du_z={du:g}um"]
        a = c.series.amplitude
        v0 = c.series.meta["v0"]
        ax.plot(v0, mu0 * c.trusted_mu, color=col, lw=1.1,
                label=rf"({EXPERIMENT_AMPLITUDES_UM.index(du) + 1}) $\Delta u_z = {du:g}$ $\mu$m"
                      rf" ($a = {a:.2f}$)")
        style.mark_untrusted(ax, v0, c, style.THEORY, scale=mu0, ms=2.5)
    ax.set_xlim(0, float(_v0_grid(False)[-1]))
    ax.set_ylim(-0.008, mu0 * 1.05)
    ax.axhline(mu0, color="0.6", lw=0.5, ls=":")
    ax.text(0.299, mu0 * 1.0, r"$\mu_0$", ha="right", va="bottom", fontsize=6.5, color="0.4")
    ax.set_xlabel(r"$v_0$ (m/s)")
    ax.set_ylabel(r"COF $\mu_{\mathrm{macro}}$")
    if any(not c.trusted.all() for c in curves.values()):
        ax.plot([], [], "o", ms=2.5, mfc="none", mec=style.THEORY, label="not trusted")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, fontsize=6)
    ax.set_title("(a) PREDICTION for the experiment of Figs. 8-9 (data not available)",
                 fontsize=7)
    du_grid = np.linspace(0.0, 70.0, 701)
    for uz, ls in zip(_U_Z0_ALTERNATIVES_UM, (":", "-", "--"), strict=True):
        amps = du_grid / uz
        bx.plot(du_grid, mu0 * np.asarray(theory.resonant_plateau_exact(amps)), color="black",
                lw=0.9,
                ls=ls, label=rf"$u_{{z,0}} = {uz:g}$ $\mu$m")
    for d, col in zip(EXPERIMENT_AMPLITUDES_UM, colors, strict=True):
        a = d * 1e-6 / EXPERIMENT["u_z0"]
        bx.plot([d], [mu0 * float(theory.resonant_plateau_exact(a))], "o", color=col, ms=4)
    bx.set_xlabel(r"$\Delta u_z$ ($\mu$m)")
    bx.set_ylabel(r"plateau COF (large $v_0$)")
    bx.set_ylim(0, mu0 * 1.05)
    bx.set_xlim(0, 70)
    bx.legend(loc="upper right", fontsize=6)
    bx.set_title(r"(b) plateau vs. amplitude for assumed $u_{z,0}$", fontsize=7)
    return fig


def fig8_9(quick: bool = False) -> Recipe:
    """Figs. 8-9: the experiment's data are not available; the model's case IV prediction."""
    omega, unit = _experiment_units()
    e = EXPERIMENT
    params = (
        "PREDICTION, not data: the measured points of Fig. 9 are not in the paper's text",
        f"stated: drive at the pin's natural frequency {e['f_hz']:g} Hz (case IV, alpha = 1); "
        f"amplitudes du_z = {EXPERIMENT_AMPLITUDES_UM} um",
        f"assumed: rigid contact (beta = inf), modal mass m = {e['mass']} kg, "
        f"F_N0 = {e['F_N0']} N, mu0 = {e['mu0']}, u_z0 = {e['u_z0'] * 1e6:g} um "
        "(so a = du_z/u_z0)",
        f"velocity unit mu0 F_N0/(m omega) = {unit:.6g} m/s (omega = {omega:.6g} rad/s)",
    )

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_fig89(curves)
        table = curve_table("Figs. 8-9: model prediction for the resonant experiment", curves,
                            params, x=lambda c: {"v0_m_per_s": c.series.meta["v0"]},
                            extra=lambda c: {"cof": e["mu0"] * c.mu_ratio})
        notes = prediction_note(e["mu0"], e["u_z0"], EXPERIMENT_AMPLITUDES_UM, unit)
        return Rendered(fig, (table,), (), notes)

    return Recipe(
        name="fig08_09_prediction",
        title="Figs. 8-9: the experiment (data not available) -- model prediction",
        caption=("**Prediction, not measurement.** (a) COF against sliding velocity in the "
                 "resonant case IV for the four oscillation amplitudes of Fig. 9 (1.3, 5.4, "
                 "8.2, 60 $\\mu$m), assuming a rigid contact, $m$ = 0.01 kg, $F_{N,0}$ = 1 N, "
                 "$\\mu_0$ = 0.3, $u_{z,0}$ = 10 $\\mu$m and $f$ = 800 Hz. (b) The plateau COF "
                 "(exact $\\tau^*$) against the amplitude for three assumed mean indentations; "
                 "dots: the four amplitudes at $u_{z,0}$ = 10 $\\mu$m."),
        series=_fig89_series(quick), render=render, parameters=params)
