r"""Figs. 3, 4, 5 and 7: ``mu_macro/mu0`` against the velocity ``vbar = v0/v0*``.

* Figs. 3 (a = 0.5, 1.0) and 7 (a = 1.5): a matrix of small panels over
  ``(alpha, beta)`` spanning the stiff diagonal (case II), the soft corner
  (case I) and the resonance lines ``beta = 1`` (III) and ``alpha = 1`` (IV).
  On the resonance lines ``vbar`` does not exist (``v0*`` is 0 or infinite), so
  those panels use the inertial velocity ``V = v0 m omega/(mu0 F_N0)`` and say so.
* Fig. 4: the stiff and soft limits against eqs. (26) and (27).
* Fig. 5: ``alpha = 0.01``, ``a = 1`` and a series of ``beta`` through ``beta = 1``.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from .. import theory
from ..params import Case, classify
from . import style
from .checks import (
    closed_form,
    fig4_checks,
    fig5_checks,
    jumping_note,
    matrix_checks,
    status_note,
)
from .recipe import Recipe, Rendered, curve_table
from .series import Curve, Series, series_at_vbar

__all__ = [
    "MATRIX_ALPHAS",
    "MATRIX_BETAS",
    "MATRIX_POINTS",
    "FIG4_SYSTEMS",
    "FIG4_AMPLITUDES",
    "FIG5_BETAS_BELOW",
    "FIG5_BETAS_ABOVE",
    "fig3",
    "fig4",
    "fig5",
    "fig7",
    "matrix",
]

#: Columns (``alpha``) and rows (``beta``, bottom to top) of the matrix of Figs. 3, 7.
#: The diagonal panels ``(0.01, 0.02)``, ``(0.2, 0.22)``, ``(5, 5.3)``, ``(380, 400)``
#: are stiff (case II: ``beta - alpha <= 0.1 |alpha - 1|``); ``(0.01, 400)`` is the
#: soft corner (case I); ``beta = 1`` is case III and ``alpha = 1`` case IV.
MATRIX_ALPHAS: tuple[float, ...] = (0.01, 0.2, 1.0, 5.0, 380.0)
MATRIX_BETAS: tuple[float, ...] = (0.02, 0.22, 1.0, 5.3, 400.0)
#: The paper's points: A (stiff, small alpha), B (soft corner), C (stiff, large alpha).
#: A -> B crosses case III (beta = 1), C -> B crosses case IV (alpha = 1).
MATRIX_POINTS: dict[str, tuple[float, float]] = {
    "A": (0.01, 0.02), "B": (0.01, 400.0), "C": (380.0, 400.0)}

FIG4_SYSTEMS: dict[str, tuple[float, float]] = {"stiff": (0.01, 0.02), "soft": (0.01, 400.01)}
FIG4_AMPLITUDES: tuple[float, ...] = (0.2, 0.4, 0.6, 0.8, 1.0)
FIG5_BETAS_BELOW: tuple[float, ...] = (0.02, 0.1, 0.5, 0.8, 0.91, 0.99)
FIG5_BETAS_ABOVE: tuple[float, ...] = (1.01, 1.1, 2.0, 10.0, 100.0, 400.0)

#: Inertial-velocity range of the resonant panels (beta = 1 and alpha = 1).
_V_MAX_CASE_III = 2.0
_V_MAX_CASE_IV = 10.0
#: Inertial velocities at which the case IV plateau is measured (not drawn).
_PLATEAU_V = (100.0, 1000.0)


def _key(alpha: float, beta: float, amplitude: float) -> str:
    return f"alpha={alpha:g},beta={beta:g},a={amplitude:g}"


def _fmt(x: float) -> str:
    return f"{x:g}"


# --------------------------------------------------------------------------- matrix
def matrix_series(amplitude: float, vbar_max: float, n: int) -> tuple[Series, ...]:
    """Series of the (alpha, beta) matrix at one amplitude."""
    out = []
    vb = np.linspace(0.0, vbar_max, n)
    for beta in MATRIX_BETAS:
        for alpha in MATRIX_ALPHAS:
            if not beta > alpha:
                continue
            key = _key(alpha, beta, amplitude)
            if beta == 1.0 or alpha == 1.0:
                vmax = _V_MAX_CASE_III if beta == 1.0 else _V_MAX_CASE_IV
                V = np.linspace(0.0, vmax, n)
                out.append(Series(key, alpha, beta, amplitude, V, np.full(n, np.nan),
                                  {"axis": "v_inertial"}))
                if alpha == 1.0:  # the plateau itself, far beyond the panel
                    out.append(Series(f"plateau:{key}", alpha, beta, amplitude,
                                      np.array(_PLATEAU_V), np.full(len(_PLATEAU_V), np.nan),
                                      {"axis": "plateau"}))
            else:
                out.append(series_at_vbar(key, alpha, beta, amplitude, vb, axis="vbar"))
    return tuple(out)


def _case_label(alpha: float, beta: float) -> str:
    case = classify(alpha, beta)
    return "" if case is Case.GENERAL else case.value


def _matrix_panel(ax, c: Curve, alpha: float, beta: float, amplitude: float,
                  vbar_max: float, static: float) -> None:
    """One panel of the matrix.

    The curve, its untrusted points, the static value, the case, the named point and, on the
    resonance lines, the axis ``V`` in orange.
    """
    resonant = c.series.meta.get("axis") == "v_inertial"
    x = c.v_inertial if resonant else c.vbar
    ax.plot(x, c.trusted_mu, color=style.NUMERIC, lw=0.9)
    if np.any(~c.trusted):
        style.mark_untrusted(ax, x, c, style.THEORY)
    ax.axhline(static, color="0.6", lw=0.5, ls=":")
    ax.set_ylim(-0.03, 1.08)
    ax.set_yticks([0, 0.5, 1])
    ax.tick_params(labelsize=5.5, length=2, pad=1.5)
    if resonant:
        for side in ax.spines.values():
            side.set_color(style.RESONANT)
            side.set_linewidth(1.0)
        vmax = float(x[-1])
        ax.set_xlim(0, vmax)
        ax.set_xticks([0, vmax / 2, vmax])
        ax.set_xticklabels([_fmt(0), _fmt(vmax / 2), _fmt(vmax)])
        ax.text(0.97, 0.05, r"vs $V$", transform=ax.transAxes, ha="right",
                va="bottom", fontsize=5.5, color=style.RESONANT)
        if alpha == 1.0:
            plateau = float(theory.resonant_plateau_exact(amplitude))
            ax.axhline(plateau, color=style.THEORY, lw=0.6, ls="--")
    else:
        ax.set_xlim(0, vbar_max)
        ax.set_xticks([0, 0.5, 1.0] + ([1.5] if vbar_max >= 1.5 else []))
        ax.axvline(1.0, color="0.75", lw=0.5)
    case = _case_label(alpha, beta)
    if case:
        ax.text(0.97, 0.17 if resonant else 0.05, case, transform=ax.transAxes,
                ha="right", va="bottom", fontsize=6, color="0.35")
    for name, (pa, pb) in MATRIX_POINTS.items():
        if (pa, pb) == (alpha, beta):
            ax.text(0.05, 0.93, name, transform=ax.transAxes, ha="left", va="top",
                    fontsize=8, fontweight="bold", color="#1f5fa8")


@style.styled
def _draw_matrix(curves: Mapping[str, Curve], amplitude: float, vbar_max: float,
                 label: str):
    na, nb = len(MATRIX_ALPHAS), len(MATRIX_BETAS)
    fig = style.figure(style.PAGE, 6.2)
    grid = fig.add_gridspec(nb, na, hspace=0.08, wspace=0.08)
    static = float(theory.static_mu_ratio(amplitude))
    for i, beta in enumerate(MATRIX_BETAS):
        row = nb - 1 - i  # beta increases upwards
        for j, alpha in enumerate(MATRIX_ALPHAS):
            if not beta > alpha:
                if alpha == 1.0 and beta == 1.0:
                    ax = fig.add_subplot(grid[row, j])
                    ax.set_axis_off()
                    ax.text(0.5, 0.5, r"$\alpha=\beta=1$" "\n" r"excluded ($\beta>\alpha$)",
                            ha="center", va="center", fontsize=6, color="0.4",
                            transform=ax.transAxes)
                continue
            ax = fig.add_subplot(grid[row, j])
            _matrix_panel(ax, curves[_key(alpha, beta, amplitude)], alpha, beta, amplitude,
                          vbar_max, static)
            if j > 0:
                ax.set_yticklabels([])
            if i == nb - 1 or (beta == MATRIX_BETAS[-1]):
                ax.set_title(rf"$\alpha = {alpha:g}$", fontsize=7, pad=2)
            if j == 0:
                ax.set_ylabel(rf"$\beta = {beta:g}$", fontsize=7)
    fig.supxlabel(r"$\bar v = v_0/v_0^*$   (orange panels, on the resonance lines "
                  r"$\beta = 1$ and $\alpha = 1$: $V = v_0 m\omega/(\mu_0 F_{N,0})$)",
                  fontsize=7.5)
    fig.supylabel(style.MU + r"  (rows: $\beta$, columns: $\alpha$)", fontsize=7.5)
    fig.suptitle(rf"{label}  $\Delta u_z/u_{{z,0}} = {amplitude:g}$", fontsize=8, x=0.08,
                 ha="left")
    # a key in the empty lower-right triangle
    ax = fig.add_subplot(grid[nb - 2:, na - 2:])
    ax.set_axis_off()
    ax.text(0.5, 0.5,
            "no panels below the diagonal:\n" r"$\beta > \alpha$ since $k_{x,c} > 0$" "\n\n"
            "I soft, II stiff, III $\\beta=1$, IV $\\alpha=1$\n"
            "dotted: static value, eq. (2)\n"
            "red dashed: case IV plateau (exact)\n"
            "red circles / bars: not trusted",
            ha="center", va="center", fontsize=6, color="0.3", transform=ax.transAxes)
    return fig


def matrix(name: str, amplitude: float, label: str, title: str, quick: bool) -> Recipe:
    """The (alpha, beta) matrix of ``mu/mu0`` curves at one amplitude (Figs. 3, 7)."""
    vbar_max = 1.2 if amplitude <= 1.0 else 1.6
    n = 41 if quick else 161
    series = matrix_series(amplitude, vbar_max, n)

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_matrix(curves, amplitude, vbar_max, label)
        params = (f"amplitude a = du_z/u_z0 = {amplitude}",
                  f"alpha columns {MATRIX_ALPHAS}, beta rows {MATRIX_BETAS} (beta > alpha only)",
                  "vbar = v0/v0* (eq. 16, v0* of eq. 12); on beta = 1 and alpha = 1 vbar does "
                  "not exist (nan) and v_inertial = v0 m omega/(mu0 F_N0) is the axis",
                  "initial state: steady sliding before the oscillation is switched on")
        table = curve_table(f"{title}: mu/mu0 over the (alpha, beta) matrix", curves, params)
        checks = matrix_checks(curves, amplitude, name, _V_MAX_CASE_III)
        notes = status_note(curves)
        if amplitude > 1.0:
            notes += jumping_note(curves, vbar_max)
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(name=name, title=title, caption="", series=series, render=render)


def fig3(quick: bool = False) -> list[Recipe]:
    """Figs. 3a (a = 0.5) and 3b (a = 1.0)."""
    out = []
    for amp, lab in ((0.5, "a"), (1.0, "b")):
        r = matrix(f"fig03{lab}_matrix", amp, f"({lab})", f"Fig. 3{lab}", quick)
        out.append(_with_caption(r, (
            f"$\\mu_{{macro}}/\\mu_0$ against $\\bar v$ for $\\Delta u_z/u_{{z,0}} = {amp:g}$ "
            "over a matrix of $(\\alpha, \\beta)$: columns $\\alpha$ = "
            + ", ".join(_fmt(a) for a in MATRIX_ALPHAS) + "; rows $\\beta$ = "
            + ", ".join(_fmt(b) for b in MATRIX_BETAS) + " (bottom to top). "
            "Stiff systems (II) lie on the diagonal, the soft corner (I) top left; "
            "orange panels lie on the resonance lines $\\beta = 1$ (III) and $\\alpha = 1$ "
            "(IV), where $\\bar v$ does not exist and the axis is "
            "$V = v_0 m\\omega/(\\mu_0 F_{N,0})$. A $\\to$ B crosses case III, "
            "C $\\to$ B crosses case IV.")))
    return out


def fig7(quick: bool = False) -> Recipe:
    """Fig. 7: the matrix for the jumping amplitude a = 1.5."""
    r = matrix("fig07_matrix_jumping", 1.5, "Fig. 7:", "Fig. 7", quick)
    return _with_caption(r, (
        "The matrix of Fig. 3 for the jumping amplitude $\\Delta u_z/u_{z,0} = 1.5$ "
        "(the contact opens for part of each period). Same layout and axes as Fig. 3, "
        "$\\bar v$ up to 1.6."))


def _with_caption(r: Recipe, caption: str) -> Recipe:
    from dataclasses import replace
    return replace(r, caption=caption)


# --------------------------------------------------------------------------- Fig. 4
def _fig4_series(quick: bool) -> tuple[Series, ...]:
    n = 31 if quick else 121
    vb = np.linspace(0.0, 1.2, n)
    return tuple(series_at_vbar(f"{name},a={a:g}", al, be, a, vb, system=name)
                 for name, (al, be) in FIG4_SYSTEMS.items() for a in FIG4_AMPLITUDES)


@style.styled
def _draw_fig4(curves: Mapping[str, Curve]):
    from matplotlib.lines import Line2D

    fig = style.figure(style.PAGE, 2.8)
    axes = fig.subplots(1, 2, sharey=True)
    vfine = np.linspace(0.0, 1.2, 601)
    for ax, (name, (al, be)), lab in zip(axes, FIG4_SYSTEMS.items(), "ab", strict=True):
        for a in FIG4_AMPLITUDES:
            c = curves[f"{name},a={a:g}"]
            if name == "soft":
                ax.plot(vfine, closed_form(name, vfine, a, printed=True), color=style.THEORY,
                        lw=0.6, ls=":")
            ax.plot(vfine, closed_form(name, vfine, a), color=style.THEORY, lw=1.0)
            ax.plot(c.vbar, c.trusted_mu, color=style.NUMERIC, lw=0.5)
            step = max(1, c.series.size // 40)
            ax.plot(c.vbar[::step], c.trusted_mu[::step], "x", color=style.NUMERIC, ms=3,
                    mew=0.6)
        ax.set_xlim(0, 1.2)
        ax.set_ylim(-0.02, 1.05)
        ax.set_xlabel(style.VBAR)
        case = "II, stiff" if name == "stiff" else "I, soft"
        ax.set_title(rf"({lab}) $(\alpha, \beta) = ({al:g}, {be:g})$ (case {case})",
                     fontsize=7.5)
        ax.set_yticks(np.linspace(0, 1, 6))
        ax.tick_params(right=False)
        ax2 = ax.secondary_yaxis("right")
        ax2.set_yticks([1.0 - a for a in FIG4_AMPLITUDES])
        ax2.set_yticklabels([f"{a:g}" for a in FIG4_AMPLITUDES])
        ax2.tick_params(labelsize=6, length=2)
        if lab == "b":
            ax2.set_ylabel(r"$\Delta u_z/u_{z,0}$ (at its static value)", fontsize=6.5)
    axes[0].set_ylabel(style.MU)
    num = Line2D([], [], color=style.NUMERIC, marker="x", lw=0.5, ms=3,
                 label="numerics (exact solver)")
    axes[0].legend(handles=[num, Line2D([], [], color=style.THEORY, lw=1.0,
                                        label="eq. (26)")], loc="lower right")
    axes[1].legend(handles=[num,
                            Line2D([], [], color=style.THEORY, lw=1.0,
                                   label=r"eq. (27), $\sqrt{4\pi\bar v/9}$ (corrected)"),
                            Line2D([], [], color=style.THEORY, lw=0.6, ls=":",
                                   label=r"eq. (27) as printed, $\sqrt{4\pi/9}\,\bar v$")],
                   loc="lower right")
    return fig


def fig4(quick: bool = False) -> Recipe:
    """Fig. 4: stiff (0.01, 0.02) and soft (0.01, 400.01) systems against eqs. (26), (27)."""

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_fig4(curves)

        def extra(c: Curve):
            name = c.series.meta["system"]
            nan = np.full(c.series.size, np.nan)
            if name == "stiff":
                return {"eq26": closed_form(name, c.vbar, c.series.amplitude),
                        "eq27_corrected": nan, "eq27_printed": nan}
            return {"eq26": nan,
                    "eq27_corrected": closed_form(name, c.vbar, c.series.amplitude),
                    "eq27_printed": closed_form(name, c.vbar, c.series.amplitude,
                                                 printed=True)}

        table = curve_table("Fig. 4: stiff and soft limits against eqs. (26), (27)", curves, (
            "(a) stiff: alpha=0.01, beta=0.02; (b) soft: alpha=0.01, beta=400.01",
            f"amplitudes {FIG4_AMPLITUDES}; vbar = v0/v0* with v0* of eq. (12)",
            "eq26 = 1 - a[3/4 (vbar-1)^2 + 1/4 (vbar-1)^4] (vbar < 1), 1 above",
            "eq27_corrected = (1-a) + a[sqrt(4 pi vbar/9) + (1 - sqrt(4pi/9)) vbar^1.2]; "
            "eq27_printed = (1-a) + a[sqrt(4pi/9) vbar + (1 - sqrt(4pi/9)) vbar^1.2]; "
            "1 for vbar >= 1",
        ), extra=extra)
        checks = fig4_checks(curves, FIG4_SYSTEMS)
        notes = status_note(curves)
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig04_limits",
        title="Fig. 4: stiff and soft limits against the closed forms",
        caption=("$\\mu_{macro}/\\mu_0$ against $\\bar v$ for (a) the stiff system "
                 "$(\\alpha, \\beta) = (0.01, 0.02)$ with eq. (26) and (b) the soft system "
                 "$(0.01, 400.01)$ with eq. (27), for $\\Delta u_z/u_{z,0}$ = 0.2, 0.4, 0.6, "
                 "0.8, 1.0 (top to bottom; right axis). Black crosses and lines: numerics; red: "
                 "closed forms. In (b) the solid red line is eq. (27) with $\\bar v$ under "
                 "the square root (derived in docs/theory.md), the dotted one eq. (27) as "
                 "transcribed."),
        series=_fig4_series(quick), render=render)


# --------------------------------------------------------------------------- Fig. 5
def _fig5_series(quick: bool) -> tuple[Series, ...]:
    n = 61 if quick else 301
    vb = np.linspace(0.0, 1.2, n)
    return tuple(series_at_vbar(f"beta={b:g}", 0.01, b, 1.0, vb,
                                side="below" if b < 1 else "above")
                 for b in FIG5_BETAS_BELOW + FIG5_BETAS_ABOVE)


@style.styled
def _draw_fig5(curves: Mapping[str, Curve]):
    fig = style.figure(style.PAGE, 3.2)
    axes = fig.subplots(1, 2, sharey=True)
    vfine = np.linspace(0, 1.2, 601)
    for ax, betas, lab, where in ((axes[0], FIG5_BETAS_BELOW, "a", r"$\beta < 1$"),
                                  (axes[1], FIG5_BETAS_ABOVE, "b", r"$\beta > 1$")):
        colors = style.sequence_colors(len(betas), "viridis" if lab == "a" else "plasma")
        for b, col in zip(betas, colors, strict=True):
            c = curves[f"beta={b:g}"]
            ax.plot(c.vbar, c.trusted_mu, color=col, lw=0.8, label=rf"$\beta = {b:g}$")
            style.mark_untrusted(ax, c.vbar, c, col)
        if lab == "b":
            ax.plot(vfine, theory.mu_ratio_soft_corrected(vfine, 1.0), color="black", lw=0.8,
                    ls="--", label="soft limit, eq. (27) corrected")
        ax.set_xlim(0, 1.2)
        ax.set_ylim(-0.02, 1.05)
        ax.set_xlabel(style.VBAR)
        ax.set_title(rf"({lab}) $\alpha = 0.01$, $\Delta u_z/u_{{z,0}} = 1$, {where}",
                     fontsize=7.5)
        if lab == "b":
            ax.plot([], [], "|", ms=5, color="0.3",
                    label="not settled: range of window means")
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=4, fontsize=6,
                  handlelength=1.5, columnspacing=1.0)
    axes[0].set_ylabel(style.MU)
    return fig


def fig5(quick: bool = False) -> Recipe:
    """Fig. 5: alpha = 0.01, a = 1, beta through the contact resonance beta = 1."""

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_fig5(curves)
        table = curve_table("Fig. 5: alpha = 0.01, a = 1, a series of beta", curves, (
            "alpha = 0.01, amplitude = 1.0",
            f"beta below 1: {FIG5_BETAS_BELOW}; above 1: {FIG5_BETAS_ABOVE}",
            "vbar = v0/v0*, v0* of eq. (12)",
            "soft_limit_eq27 = eq. (27) at a = 1 for comparison"),
            extra=lambda c: {"soft_limit_eq27": np.asarray(
                theory.mu_ratio_soft_corrected(c.vbar, 1.0))})
        checks, plateau = fig5_checks(curves, FIG5_BETAS_BELOW, FIG5_BETAS_ABOVE)
        notes = (status_note(curves) + " The plateau near mu0 grows towards small vbar "
                 "near the resonance: " + "; ".join(plateau) + ".")
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig05_beta_series",
        title="Fig. 5: from the stiff to the soft system across the contact resonance",
        caption=("$\\mu_{macro}/\\mu_0$ against $\\bar v$ for $\\alpha = 0.01$, "
                 "$\\Delta u_z/u_{z,0} = 1$ and (a) $\\beta$ = "
                 + ", ".join(_fmt(b) for b in FIG5_BETAS_BELOW) + " (below the resonance "
                 "$\\beta = 1$), (b) $\\beta$ = " + ", ".join(_fmt(b) for b in FIG5_BETAS_ABOVE)
                 + " (above), with the soft limit eq. (27) dashed. Vertical bars: points whose "
                 "motion did not settle within the period budget (the range of the last "
                 "window means; a slow drift to an orbit, docs/solver.md)."),
        series=_fig5_series(quick), render=render)
