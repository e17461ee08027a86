r"""Beyond the paper: the damped model (pin dashpot ``zeta = 1/(2Q)``, docs/damping.md).

* Fig. 11: the resonant case IV (``alpha = 1``, rigid contact) with pin damping.  Without
  damping ``mu/mu0`` tends to the plateau of eq. (32) and never reaches 1; any damping
  bounds the resonant velocity amplitude, so the curve rises to ``mu0``, reached
  exactly at ``V_c = a/(2 zeta)``.
* Fig. 12: Fig. 10's law of friction in m/s with a realistic pin (``Q = 50``): only the
  resonant system changes.
* Fig. 13: Fig. 5's series of ``beta`` through the contact resonance, undamped and with
  a small damping ``zeta = 0.01``: the slow drifts that did not settle disappear.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace

import numpy as np

from .. import theory
from ..params import Dimensionless, Physical
from . import style
from .damped_checks import damped_beta_series_checks, damped_case_iv_checks, damped_law_checks
from .dimensional import PIN, SYSTEMS, physical_system
from .recipe import Recipe, Rendered, curve_table
from .series import Curve, Series, series_at_vbar, series_of_physical
from .velocity import FIG5_BETAS_ABOVE, FIG5_BETAS_BELOW

__all__ = [
    "CASE_IV_AMPLITUDE",
    "CASE_IV_ZETAS",
    "FIG13_ZETA",
    "QUALITY_FACTOR",
    "damped_case_iv",
    "damped_fig5",
    "damped_fig10",
    "damped_system",
]

#: Fig. 11: case IV at this amplitude, for these pin damping ratios (Q = 1/(2 zeta)).
CASE_IV_AMPLITUDE = 0.5
CASE_IV_ZETAS: tuple[float, ...] = (0.0, 0.005, 0.02, 0.05)
#: Fig. 12: the quality factor of the pin (a steel pin on a tribometer: tens to hundreds).
QUALITY_FACTOR = 50.0
#: Fig. 13: the small pin damping compared with the undamped Fig. 5.
FIG13_ZETA = 0.01

_V_RANGE = (0.01, 80.0)          # Fig. 11, inertial velocity, log-spaced
_V0_RANGE = (1e-4, 6.0)          # Fig. 12, m/s, log-spaced (damped resonant v0* ~ 3 m/s)
#: Multiples of V_c added to the grid of each damped curve of Fig. 11 (sharp corner).
_AROUND_VC = (0.9, 0.95, 0.98, 0.99, 1.0, 1.01, 1.02, 1.05)


def _damping_columns(c: Curve) -> dict[str, np.ndarray]:
    n = c.series.size
    return {"zeta": np.full(n, c.series.zeta), "eta_c": np.full(n, c.series.eta_c)}


def _q_text(zeta: float) -> str:
    return r"$Q = \infty$" if zeta == 0 else rf"$Q = {1 / (2 * zeta):g}$"


# --------------------------------------------------------------------------- Fig. 11
def _case_iv_vc(zeta: float) -> float:
    return Dimensionless(1.0, math.inf, CASE_IV_AMPLITUDE, zeta=zeta).critical_inertial_velocity()


def _case_iv_series(quick: bool) -> tuple[Series, ...]:
    n = 41 if quick else 201
    base = np.geomspace(*_V_RANGE, n)
    out = []
    for z in CASE_IV_ZETAS:
        vc = _case_iv_vc(z)
        V = base
        if math.isfinite(vc):
            V = np.unique(np.concatenate([base, vc * np.array(_AROUND_VC)]))
        out.append(Series(f"zeta={z:g}", 1.0, math.inf, CASE_IV_AMPLITUDE, V,
                          np.full(V.size, np.nan), {"v_c": vc}, zeta=z))
    return tuple(out)


def _case_iv_colors() -> list:
    return ["black", *style.sequence_colors(len(CASE_IV_ZETAS) - 1, "plasma", 0.15, 0.75)]


@style.styled
def _draw_case_iv(curves: Mapping[str, Curve]):
    fig = style.figure(style.COLUMN, 3.0)
    ax = fig.add_subplot()
    a = CASE_IV_AMPLITUDE
    plateau = float(theory.resonant_plateau_exact(a))
    ax.axhline(plateau, color=style.THEORY, lw=0.7, ls="--", zorder=1)
    ax.text(_V_RANGE[0] * 1.15, plateau + 0.008, f"undamped plateau {plateau:.3f} (eq. 32)",
            fontsize=6, color=style.THEORY, va="bottom")
    ax.axhline(1.0, color="0.6", lw=0.5, ls=":", zorder=1)
    for z, col in zip(CASE_IV_ZETAS, _case_iv_colors(), strict=True):
        c = curves[f"zeta={z:g}"]
        label = (rf"$\zeta = {z:g}$ ({_q_text(z)})" if z > 0 else
                 r"$\zeta = 0$ (undamped)")
        ax.plot(c.v_inertial, c.trusted_mu, color=col, lw=1.1, label=label, zorder=3)
        style.mark_untrusted(ax, c.v_inertial, c, col, ms=2.5)
        if z > 0:  # the rise law: energy balance with the dashpot (docs/damping.md),
            # drawn where its ansatz (an oscillation large against V) can hold
            V = c.v_inertial[c.v_inertial >= 0.1 * c.series.meta["v_c"]]
            ax.plot(V, theory.resonant_damped_mu_ratio(V, a, z), color="black", lw=0.6,
                    ls=(0, (1, 1.5)), zorder=4)
        vc = c.series.meta["v_c"]
        if math.isfinite(vc):
            ax.axvline(vc, color=col, lw=0.6, ls=(0, (2, 2)), zorder=2)
            ax.text(vc, 0.512, rf"$V_c$ = {vc:g}", rotation=90, ha="right", va="bottom",
                    fontsize=5.5, color=col)
    ax.set_xscale("log")
    ax.set_xlim(*_V_RANGE)
    ax.set_ylim(0.5, 1.03)
    ax.set_xlabel(r"$V = v_0 m\omega/(\mu_0 F_{N,0})$")
    ax.set_ylabel(style.MU)
    ax.set_title(rf"case IV damped: $\alpha = 1$, $\beta = \infty$, "
                 rf"$\Delta F_N/F_{{N,0}} = {a:g}$; $V_c = a/(2\zeta)$", fontsize=7)
    from matplotlib.lines import Line2D
    handles, _ = ax.get_legend_handles_labels()
    handles.append(Line2D([], [], color="black", lw=0.6, ls=(0, (1, 1.5)),
                          label="rise law (energy balance with damping)"))
    ax.legend(handles=handles, loc="upper left", fontsize=6, handlelength=1.8)
    return fig


def damped_case_iv(quick: bool = False) -> Recipe:
    """Fig. 11: case IV with pin damping; the plateau becomes a rise to mu0 at V_c."""
    params = (f"alpha = 1, beta = inf (rigid contact), a = {CASE_IV_AMPLITUDE}; pin damping "
              f"zeta = {CASE_IV_ZETAS} (Q = 1/(2 zeta)), eta_c = 0",
              "velocity axis v_inertial = v0 m omega/(mu0 F_N0) (vbar does not exist: nan)",
              "v_c = critical inertial velocity a/(2 zeta) (inf undamped); "
              "plateau_exact = undamped case IV plateau (first eq. 32, exact tau*)")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_case_iv(curves)
        plateau = float(theory.resonant_plateau_exact(CASE_IV_AMPLITUDE))
        table = curve_table("Fig. 11: damped case IV", curves, params, extra=lambda c: {
            **_damping_columns(c), "v_c": np.full(c.series.size, c.series.meta["v_c"]),
            "plateau_exact": np.full(c.series.size, plateau)})
        checks, notes = damped_case_iv_checks(curves)
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig11_damped_case_iv",
        title="Fig. 11 (beyond the paper): the resonant case IV with a damped pin",
        caption=("$\\mu_{macro}/\\mu_0$ against $V = v_0 m\\omega/(\\mu_0 F_{N,0})$ (log "
                 "scale) in case IV ($\\alpha = 1$, rigid contact, $\\Delta F_N/F_{N,0}$ = "
                 f"{CASE_IV_AMPLITUDE:g}) for the pin damping ratios $\\zeta$ = "
                 + ", ".join(f"{z:g}" for z in CASE_IV_ZETAS) + " ($Q = 1/(2\\zeta)$). Red "
                 "dashed: the undamped plateau (exact, eq. 32); dashed verticals: the damped "
                 "critical velocities $V_c = a/(2\\zeta)$, above which $\\mu = \\mu_0$; black "
                 "dotted: the rise law from the energy balance with the dashpot "
                 "(docs/damping.md), drawn from $0.1 V_c$. At $V = 0$ "
                 "(off the log axis) every curve starts at the static value "
                 f"{1 - CASE_IV_AMPLITUDE:g} (eq. 2)."),
        series=_case_iv_series(quick), render=render, parameters=params)


# --------------------------------------------------------------------------- Fig. 12
def damped_system(name: str) -> Physical:
    """A system of Fig. 10 with a damped pin.

    The system ``name`` of Fig. 10 (:data:`.dimensional.SYSTEMS`) with a pin of quality
    factor :data:`QUALITY_FACTOR`.
    """
    return physical_system(name).with_damping(quality_factor=QUALITY_FACTOR)


def _law_series(quick: bool) -> tuple[Series, ...]:
    n = 40 if quick else 240
    v0 = np.concatenate([[0.0], np.geomspace(*_V0_RANGE, n)])
    out = []
    for name, (f, _, _) in SYSTEMS.items():
        for key, phys in ((name, damped_system(name)),
                          (f"undamped:{name}", physical_system(name))):
            out.append(series_of_physical(key, phys, v0, frequency_hz=f, system=name))
    return tuple(out)


@style.styled
def _draw_law(curves: Mapping[str, Curve]):
    from matplotlib.lines import Line2D

    fig = style.figure(style.COLUMN, 3.1)
    ax = fig.add_subplot()
    mu0 = PIN["mu0"]
    a = PIN["a"]
    handles = []
    for name, (f, _, color) in SYSTEMS.items():
        u = curves[f"undamped:{name}"]
        c = curves[name]
        v0 = c.series.meta["v0"]
        m = v0 > 0
        ax.plot(v0[m], mu0 * u.trusted_mu[m], color="0.55", lw=0.6, zorder=2)
        style.mark_untrusted(ax, v0[m], u, "0.55", scale=mu0, ms=2.0, where=m)
        ax.plot(v0[m], mu0 * c.trusted_mu[m], color=color, lw=1.1, zorder=3)
        style.mark_untrusted(ax, v0[m], c, color, scale=mu0, ms=2.5, where=m)
        phys = damped_system(name)
        vstar = phys.critical_velocity()
        if math.isfinite(vstar):
            ax.plot([vstar], [mu0 * 1.035], "v", color=color, ms=4, clip_on=False)
        handles.append(Line2D([], [], color=color, lw=1.1,
                              label=f"{name}: {f / 1000:g} kHz, " + r"$v_0^*$ = "
                              + f"{vstar:.3g} m/s"))
    handles.append(Line2D([], [], color="0.55", lw=0.6, label=r"undamped pin ($Q = \infty$)"))
    ax.axhline(mu0 * (1 - a), color="0.5", lw=0.6, ls=":")
    ax.axhline(mu0, color="0.5", lw=0.6, ls=":")
    ax.axhline(mu0 * float(theory.resonant_plateau_exact(a)), color=style.THEORY, lw=0.5,
               ls="--")
    ax.text(_V0_RANGE[0] * 1.2, mu0 * (1 - a) - 0.004, r"static: $\mu_0(1 - \Delta F_N/F_{N,0})$",
            fontsize=6, va="top", color="0.35")
    ax.text(_V0_RANGE[1] * 0.9, mu0 * float(theory.resonant_plateau_exact(a)) - 0.004,
            "undamped plateau (IV)", fontsize=6, ha="right", va="top", color=style.THEORY)
    ax.set_xscale("log")
    ax.set_xlim(*_V0_RANGE)
    ax.set_ylim(mu0 * (1 - a) - 0.03, mu0 * 1.07)
    ax.set_xlabel(r"sliding velocity $v_0$ (m/s)")
    ax.set_ylabel(r"COF $\mu_{\mathrm{macro}}$ ($\mu_0 = 0.3$)")
    ax.set_title(rf"Fig. 10 with a damped pin, $Q = {QUALITY_FACTOR:g}$ "
                 rf"($\zeta = {1 / (2 * QUALITY_FACTOR):g}$); triangles: $v_0^*$", fontsize=7)
    fig.legend(handles=handles, loc="outside lower center", fontsize=5.8, ncol=1,
               handlelength=1.8)
    return fig


def damped_fig10(quick: bool = False) -> Recipe:
    """Fig. 12: Fig. 10's law of friction with a pin of quality factor Q = 50."""
    p = PIN
    params = tuple(
        f"{name}: " + ", ".join(f"{k} = {getattr(damped_system(name), k):.6g}" for k in
                                ("mass", "k_x", "c_x", "k_xc", "k_zc", "u_z0", "du_z", "omega",
                                 "mu0"))
        + f" (SI units; drive {SYSTEMS[name][0]:g} Hz)" for name in SYSTEMS) + (
        f"pin quality factor Q = {QUALITY_FACTOR:g} (c_x = 2 zeta sqrt(k_x m), zeta = 1/(2Q)); "
        "series 'undamped:...' are the same systems with c_x = 0 (Fig. 10)",
        "cof = mu0 * mu_ratio; v0_m_per_s = sliding velocity")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_law(curves)
        table = curve_table("Fig. 12: law of friction with a damped pin", curves, params,
                            x=lambda c: {"v0_m_per_s": c.series.meta["v0"]},
                            extra=lambda c: {**_damping_columns(c),
                                             "cof": p["mu0"] * c.mu_ratio})
        checks, notes = damped_law_checks(
            {name: curves[name] for name in SYSTEMS},
            {name: curves[f"undamped:{name}"] for name in SYSTEMS},
            {name: (physical_system(name), damped_system(name)) for name in SYSTEMS},
            resonant="resonant (IV)")
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig12_damped_law",
        title="Fig. 12 (beyond the paper): the law of friction with a damped pin",
        caption=("Fig. 10 (COF against $v_0$, log scale; same pin, contacts and drive "
                 f"frequencies) with a pin of quality factor $Q$ = {QUALITY_FACTOR:g} "
                 f"($\\zeta$ = {1 / (2 * QUALITY_FACTOR):g}); thin gray: the undamped curves "
                 "of Fig. 10. Triangles: the damped critical velocities. Damping hardly "
                 "changes the stiff, soft and in-between systems; the resonant one no "
                 "longer stays on its plateau but reaches $\\mu_0$ at a finite $v_0^*$."),
        series=_law_series(quick), render=render, parameters=params)


# --------------------------------------------------------------------------- Fig. 13
def _beta_series(quick: bool) -> tuple[Series, ...]:
    n = 31 if quick else 301
    vb = np.linspace(0.0, 1.2, n)
    out = []
    for b in FIG5_BETAS_BELOW + FIG5_BETAS_ABOVE:
        # the UNDAMPED v0* converts vbar to V for both: the curves share their velocities
        s = series_at_vbar(f"beta={b:g}", 0.01, b, 1.0, vb,
                           side="below" if b < 1 else "above")
        out += [s, replace(s, key=f"beta={b:g},zeta={FIG13_ZETA:g}", zeta=FIG13_ZETA)]
    return tuple(out)


@style.styled
def _draw_beta(curves: Mapping[str, Curve]):
    from matplotlib.lines import Line2D

    fig = style.figure(style.PAGE, 3.3)
    axes = fig.subplots(1, 2, sharey=True)
    for ax, betas, lab, where in ((axes[0], FIG5_BETAS_BELOW, "a", r"$\beta < 1$"),
                                  (axes[1], FIG5_BETAS_ABOVE, "b", r"$\beta > 1$")):
        colors = style.sequence_colors(len(betas), "viridis" if lab == "a" else "plasma")
        handles = []
        for b, col in zip(betas, colors, strict=True):
            u = curves[f"beta={b:g}"]
            d = curves[f"beta={b:g},zeta={FIG13_ZETA:g}"]
            ax.plot(u.vbar, u.trusted_mu, color=col, lw=0.7, ls=(0, (3, 2)), alpha=0.9)
            style.mark_untrusted(ax, u.vbar, u, col)
            ax.plot(d.vbar, d.trusted_mu, color=col, lw=1.0)
            style.mark_untrusted(ax, d.vbar, d, col)
            handles.append(Line2D([], [], color=col, lw=1.0, label=rf"$\beta = {b:g}$"))
        ax.set_xlim(0, 1.2)
        ax.set_ylim(-0.02, 1.05)
        ax.set_xlabel(r"$\bar v = v_0/v_0^*$ (undamped $v_0^*$)")
        ax.set_title(rf"({lab}) $\alpha = 0.01$, $\Delta u_z/u_{{z,0}} = 1$, {where}",
                     fontsize=7.5)
        ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=3,
                  fontsize=6, handlelength=1.8, columnspacing=1.0)
    axes[0].set_ylabel(style.MU)
    fig.legend(handles=[
        Line2D([], [], color="0.3", lw=1.0, label=rf"damped, $\zeta = {FIG13_ZETA:g}$"),
        Line2D([], [], color="0.3", lw=0.7, ls=(0, (3, 2)), label="undamped (Fig. 5)"),
        Line2D([], [], color="0.3", marker="|", ls="none", ms=5,
               label="not settled: range of window means"),
        Line2D([], [], color="0.3", marker="o", ls="none", ms=2.5, mfc="none", mew=0.5,
               label="converged, error too large")],
        loc="outside lower center", ncol=4, fontsize=6, handlelength=2.2)
    return fig


def damped_fig5(quick: bool = False) -> Recipe:
    """Fig. 13: Fig. 5's beta series undamped and with a small pin damping."""
    params = ("alpha = 0.01, amplitude = 1.0, eta_c = 0; each beta undamped (zeta = 0) and "
              f"with pin damping zeta = {FIG13_ZETA:g} (Q = {1 / (2 * FIG13_ZETA):g})",
              f"beta below 1: {FIG5_BETAS_BELOW}; above 1: {FIG5_BETAS_ABOVE}",
              "vbar = v0/v0* with the UNDAMPED v0* (eq. 12) for both curves of a beta, "
              "so they share their velocities v_inertial")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_beta(curves)
        table = curve_table("Fig. 13: Fig. 5 with a small pin damping", curves, params,
                            extra=lambda c: _damping_columns(c))
        checks, notes = damped_beta_series_checks(curves)
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig13_damped_beta_series",
        title="Fig. 13 (beyond the paper): Fig. 5 with a small pin damping",
        caption=("$\\mu_{macro}/\\mu_0$ against $\\bar v$ (with the undamped $v_0^*$) for "
                 "$\\alpha = 0.01$, $\\Delta u_z/u_{z,0} = 1$ and the $\\beta$ of Fig. 5, "
                 f"with pin damping $\\zeta$ = {FIG13_ZETA:g} (solid) and undamped (dashed, "
                 "as Fig. 5). Vertical bars and open circles: points the solver does not "
                 "trust (undamped: slow drifts that did not settle)."),
        series=_beta_series(quick), render=render, parameters=params)
