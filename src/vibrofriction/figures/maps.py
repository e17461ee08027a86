r"""Beyond the paper: maps over the ``(alpha, beta)`` plane (log axes, ``beta > alpha``).

(a) The critical velocity of eq. (12) relative to the soft-system value of
eq. (13), ``v0*/v0*_soft = |beta - 1| / ((beta - alpha)|alpha - 1|)``: zero on the
contact resonance ``beta = 1`` (case III), infinite on the system resonance
``alpha = 1`` (case IV), ``-> 1`` in the soft corner (I) and
``-> 1/(beta - alpha)`` (eq. 14) along the stiff diagonal (II).
(b) ``mu/mu0`` from the solver at a fixed ``vbar`` and (c) at a fixed inertial
velocity ``V``, both at one amplitude.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from matplotlib import colors as mcolors

from .. import theory
from ..params import Case, classify
from . import style
from .checks import map_field, map_note
from .edges import cell_edges
from .recipe import Recipe, Rendered, Table
from .series import Curve, Series

__all__ = ["MAP_AMPLITUDE", "MAP_VBAR", "MAP_V_INERTIAL", "grid", "maps"]

MAP_AMPLITUDE = 0.5
MAP_VBAR = 0.5
MAP_V_INERTIAL = 0.25  # = a/2: half the soft critical velocity (eq. 13)
_ALPHA_RANGE = (1e-2, 1e2)
_BETA_RANGE = (1e-2, 1e3)
_CASE_CODE = {Case.GENERAL: 0, Case.SOFT: 1, Case.STIFF: 2, Case.RESONANT_CONTACT: 3,
              Case.RESONANT_SYSTEM: 4}


def grid(n_alpha: int, n_beta: int) -> tuple[np.ndarray, np.ndarray]:
    """Cell centres, log-spaced; even counts keep ``alpha = 1``, ``beta = 1`` off the grid."""
    alpha = np.geomspace(*_ALPHA_RANGE, n_alpha)
    beta = np.geomspace(*_BETA_RANGE, n_beta)
    if np.any(alpha == 1.0) or np.any(beta == 1.0):
        raise ValueError("the map grid must avoid alpha = 1 and beta = 1 (vbar undefined)")
    return alpha, beta


def _series(quick: bool) -> tuple[Series, ...]:
    alpha, beta = grid(*((16, 20) if quick else (48, 60)))
    A, B = np.meshgrid(alpha, beta)  # rows: beta
    valid = B > A
    out = []
    a = MAP_AMPLITUDE
    for i, b in enumerate(beta):
        al = alpha[valid[i]]
        if al.size == 0:
            continue
        c = np.asarray(theory.critical_inertial_velocity(al, b, a))
        for kind, V, vb in (("vbar", c * MAP_VBAR, np.full(al.size, MAP_VBAR)),
                            ("V", np.full(al.size, MAP_V_INERTIAL), MAP_V_INERTIAL / c)):
            # one series per (row, map) with varying alpha: carry alpha in meta
            for j, (alj, Vj, vbj) in enumerate(zip(al, V, vb, strict=True)):
                out.append(Series(f"{kind}:{i}:{j}", float(alj), float(b), a,
                                  np.array([Vj]), np.array([vbj]),
                                  {"map": kind, "row": i, "alpha": float(alj)}))
    return tuple(out)


def _decorate(ax, alpha: np.ndarray, beta: np.ndarray, cases: np.ndarray) -> None:
    lo, hi = min(_ALPHA_RANGE[0], _BETA_RANGE[0]), max(_ALPHA_RANGE[1], _BETA_RANGE[1])
    d = np.geomspace(lo, hi, 10)
    ax.fill_between(d, lo, d, color="0.85", lw=0, zorder=1)
    ax.plot(d, d, color="0.3", lw=0.6, zorder=3)
    ax.axvline(1.0, color=style.RESONANT, lw=1.0, zorder=3)
    ax.axhline(1.0, color=style.RESONANT, lw=1.0, zorder=3)
    # case regions (classify with its default thresholds) as outlines
    for code in (1, 2):
        ax.contour(alpha, beta, (cases == code).astype(float), levels=[0.5], colors="white",
                   linewidths=0.8, zorder=4)
    kw = {"fontsize": 7, "fontweight": "bold", "ha": "center", "va": "center", "zorder": 5}
    ax.text(0.03, 200.0, "I", color="white", **kw)
    ax.text(0.03, 0.045, "II", color="white", **kw)
    ax.text(20.0, 30.0, "II", color="white", **kw)
    ax.text(0.2, 1.0, "III", color=style.RESONANT,
            bbox={"fc": "white", "ec": "none", "pad": 0.5}, **kw)
    ax.text(1.0, 300.0, "IV", color=style.RESONANT,
            bbox={"fc": "white", "ec": "none", "pad": 0.5}, **kw)
    ax.text(20.0, 0.05, r"$\beta < \alpha$" "\n(no system)", color="0.35", fontsize=6,
            ha="center", va="center", zorder=5)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(*_ALPHA_RANGE)
    ax.set_ylim(*_BETA_RANGE)
    ax.set_xlabel(r"$\alpha = k_x/(m\omega^2)$")


@style.styled
def _draw(curves: Mapping[str, Curve], alpha: np.ndarray, beta: np.ndarray):
    fig = style.figure(style.PAGE, 2.75)
    axes = fig.subplots(1, 3, sharey=True)
    A, B = np.meshgrid(alpha, beta)
    valid = B > A
    cases = np.vectorize(lambda a, b: _CASE_CODE[classify(a, b)] if b > a else -1,
                         otypes=[int])(A, B)
    ratio = np.where(valid, np.asarray(theory.critical_inertial_velocity(
        A, np.where(valid, B, A + 1), 1.0)), np.nan)
    ea, eb = cell_edges(alpha, log=True, name="alpha"), cell_edges(beta, log=True, name="beta")
    m = axes[0].pcolormesh(ea, eb, np.ma.masked_invalid(ratio), shading="flat",
                           norm=mcolors.LogNorm(1e-2, 1e2), cmap="cividis", rasterized=True)
    cb = fig.colorbar(m, ax=axes[0], pad=0.02, shrink=0.9, extend="both")
    cb.set_label(r"$v_0^*/v^*_{0,soft}$ (eqs. 12, 13)", fontsize=6.5)
    cb.ax.tick_params(labelsize=6)
    axes[0].set_title(r"(a) critical velocity, eq. (12)", fontsize=7.5)
    for ax, kind, title in (
            (axes[1], "vbar", rf"(b) $\mu_{{\mathrm{{macro}}}}/\mu_0$ at $\bar v = {MAP_VBAR:g}$"),
            (axes[2], "V", rf"(c) $\mu_{{\mathrm{{macro}}}}/\mu_0$ at $V = {MAP_V_INERTIAL:g}$")):
        mu, ok = map_field(curves, kind, alpha, beta)
        mm = ax.pcolormesh(ea, eb, np.ma.masked_invalid(np.where(ok | ~valid, mu, np.nan)),
                           shading="flat", vmin=1 - MAP_AMPLITUDE, vmax=1.0, cmap="viridis",
                           rasterized=True)
        bad = valid & ~ok
        if np.any(bad):
            ax.plot(A[bad], B[bad], "x", color="red", ms=2.5, mew=0.6, zorder=6)
        ax.set_title(title + rf", $\Delta u_z/u_{{z,0}} = {MAP_AMPLITUDE:g}$", fontsize=7.5)
        cb = fig.colorbar(mm, ax=ax, pad=0.02, shrink=0.9)
        cb.ax.tick_params(labelsize=6)
        if kind == "V":
            cb.set_label(style.MU, fontsize=6.5)
    for ax in axes:
        _decorate(ax, alpha, beta, cases)
    axes[0].set_ylabel(r"$\beta = (k_x + k_{x,c})/(m\omega^2)$")
    return fig


def maps(quick: bool = False) -> Recipe:
    """Maps of the critical velocity and of mu/mu0 over the (alpha, beta) plane."""
    alpha, beta = grid(*((16, 20) if quick else (48, 60)))

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw(curves, alpha, beta)
        A, B = np.meshgrid(alpha, beta)
        valid = B > A
        mu_vbar, ok_vbar = map_field(curves, "vbar", alpha, beta)
        mu_V, ok_V = map_field(curves, "V", alpha, beta)
        ratio = np.asarray(theory.critical_inertial_velocity(A[valid], B[valid], 1.0))
        cases = [classify(a, b).value for a, b in zip(A[valid], B[valid], strict=True)]
        table = Table("Maps over (alpha, beta)", (
            f"amplitude a = {MAP_AMPLITUDE}; grid alpha in {_ALPHA_RANGE} ({alpha.size} log "
            f"points), beta in {_BETA_RANGE} ({beta.size} log points), beta > alpha only",
            "vstar_over_soft = v0*/v0*_soft = |beta-1|/((beta-alpha)|alpha-1|) (eqs. 12, 13)",
            f"mu_at_vbar = mu/mu0 at vbar = {MAP_VBAR}; mu_at_V = mu/mu0 at "
            f"v_inertial = {MAP_V_INERTIAL}; *_ok = converged and trusted",
            "case = classify(alpha, beta) with rtol = 0.05, ratio = 0.1"),
            {"alpha": A[valid], "beta": B[valid], "case": np.array(cases, dtype=object),
             "vstar_over_soft": ratio, "mu_at_vbar": mu_vbar[valid],
             "mu_at_vbar_ok": ok_vbar[valid].astype(int), "mu_at_V": mu_V[valid],
             "mu_at_V_ok": ok_V[valid].astype(int)})
        notes = map_note(curves, alpha, beta)
        return Rendered(fig, (table,), (), notes)

    return Recipe(
        name="maps_alpha_beta",
        title="Beyond the paper: maps over the (alpha, beta) plane",
        caption=("(a) Critical velocity of eq. (12) relative to the soft value of eq. (13), "
                 "$|\\beta - 1|/((\\beta - \\alpha)|\\alpha - 1|)$; (b) "
                 f"$\\mu_{{macro}}/\\mu_0$ at $\\bar v$ = {MAP_VBAR:g} and (c) at "
                 f"$V = v_0 m\\omega/(\\mu_0 F_{{N,0}})$ = {MAP_V_INERTIAL:g}, both for "
                 f"$\\Delta u_z/u_{{z,0}}$ = {MAP_AMPLITUDE:g}. Orange lines: the resonances "
                 "$\\beta = 1$ (III) and $\\alpha = 1$ (IV); white outlines: the soft (I) and "
                 "stiff (II) regions of `classify` (ratio 0.1); gray: $\\beta < \\alpha$, "
                 "excluded."),
        series=_series(quick), render=render)
