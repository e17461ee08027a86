"""Fig. 14: the directions of oscillation for one pin, ``mu/mu0`` against ``V``."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ... import theory
from .. import style
from ..recipe import Check, Recipe, Rendered, curve_table, max_deviation
from ..series import Curve, Series
from .common import (
    A_X,
    AROUND_VC,
    FIG14_PHASES,
    SYSTEM,
    below_check,
    critical_v_pair,
    inplane_columns,
    mark_untrusted,
    sliding_check,
)


# --------------------------------------------------------------------------- Fig. 14
def _fig14_grid(quick: bool, up: float, down: float) -> NDArray:
    n = 28 if quick else 140
    base = np.concatenate([np.geomspace(1e-4, 0.02, 6 if quick else 12),
                           np.linspace(0.02, 1.4, n)])
    pos = np.concatenate([base, [k * up for k in AROUND_VC if up > 0]])
    neg = np.concatenate([base, [k * down for k in AROUND_VC if down > 0]])
    return np.unique(np.concatenate([-neg, pos]))


def _fig14_series(quick: bool) -> tuple[Series, ...]:
    al, be, a = SYSTEM
    out = []
    for key, amp, a_x, phase, label in (
            ("normal", a, 0.0, 0.0, "normal only"),
            ("longitudinal", 0.0, A_X, 0.0, "longitudinal only"),
            *((f"combined,phase_x={p:.6g}", a, A_X, p, rf"combined, $\varphi_x = {lab}$")
              for lab, p in FIG14_PHASES)):
        up, down = critical_v_pair(amp, a_x, phase)
        V = _fig14_grid(quick, up, down)
        out.append(Series(key, al, be, amp, V, np.full(V.size, np.nan),
                          {"label": label, "v_c_forward": up, "v_c_backward": down},
                          a_x=a_x, phase_x=phase))
    # across the sliding (the 2-D solver): no critical velocity, the slip keeps turning
    V = _fig14_grid(quick, 0.0, 0.0)
    out.append(Series("transverse", al, be, 0.0, V, np.full(V.size, np.nan),
                      {"label": "transverse only", "v_c_forward": math.inf,
                       "v_c_backward": math.inf}, a_y=A_X))
    return tuple(out)


def _fig14_colors() -> dict[str, Any]:
    cs = style.sequence_colors(3, "plasma", 0.1, 0.75)
    return {"normal": "black", "longitudinal": "#2ca02c", "transverse": "#17becf",
            **{f"combined,phase_x={p:.6g}": c for (_, p), c in zip(FIG14_PHASES, cs,
                                                                   strict=True)}}


@style.styled
def _draw_directions(curves: Mapping[str, Curve]):
    from matplotlib.lines import Line2D

    fig = style.figure(style.PAGE, 3.6)
    ax = fig.add_subplot()
    colors = _fig14_colors()
    handles = []
    for key, c in curves.items():
        s = c.series
        col = colors[key]
        V = s.v_inertial
        ax.plot(V, c.trusted_mu, color=col, lw=1.1, zorder=3)
        mark_untrusted(ax, V, c, col)
        if s.a_y > 0:  # no critical velocity across the sliding
            handles.append(Line2D([], [], color=col, lw=1.1,
                                  label=s.meta["label"] + r" (no $V_c$: 2-D solver)"))
            continue
        for vc in (s.meta["v_c_forward"], -s.meta["v_c_backward"]):
            ax.axvline(vc, color=col, lw=0.6, ls=(0, (2, 2)), zorder=2)
        handles.append(Line2D([], [], color=col, lw=1.1, label=s.meta["label"]
                              + rf" ($V_c$ = {s.meta['v_c_forward']:.3f} forward, "
                                rf"{s.meta['v_c_backward']:.3f} backward)"))
    v = np.linspace(-1.4, 1.4, 561)
    ax.plot(v, theory.kinematic_mu_longitudinal(v, A_X), color=style.THEORY, lw=0.6,
            ls=(0, (1, 1.2)), zorder=4)
    handles.append(Line2D([], [], color=style.THEORY, lw=0.6, ls=(0, (1, 1.2)),
                          label=r"rigid body, longitudinal only: $(2/\pi)\arcsin(V/a_x)$"))
    ax.plot(v, theory.kinematic_mu_transverse(v, A_X), color=colors["transverse"], lw=0.6,
            ls=(0, (1, 1.2)), zorder=4)
    handles.append(Line2D([], [], color=colors["transverse"], lw=0.6, ls=(0, (1, 1.2)),
                          label=r"rigid body, transverse only: $(2/\pi)K(m)/\sqrt{1+\epsilon^2}$"))
    handles.append(Line2D([], [], color="0.3", lw=0.6, ls=(0, (2, 2)),
                          label=r"$V_c$ of continuous sliding (theory), $\pm$"))
    ax.axhline(0, color="0.7", lw=0.4, zorder=1)
    ax.axvline(0, color="0.7", lw=0.4, zorder=1)
    ax.set_xlim(-1.4, 1.4)
    ax.set_ylim(-1.05, 1.05)
    ax.set_xlabel(r"$V = v_0 m\omega/(\mu_0 F_{N,0})$ (signed)")
    ax.set_ylabel(style.MU)
    al, be, a = SYSTEM
    fig.suptitle(rf"$\alpha = {al:g}$, $\beta = {be:g}$ (undamped, elastic contact), "
                 rf"substrate: normal $\Delta F_N/F_{{N,0}} = {a:g}$, longitudinal "
                 rf"$a_x = {A_X:g}$, transverse $a_y = {A_X:g}$", fontsize=7.5)
    fig.legend(handles=handles, loc="outside right center", fontsize=6, handlelength=2.0)
    return fig


def _directions_checks(curves: Mapping[str, Curve]) -> tuple[list[Check], str]:
    al, be, a = SYSTEM
    where = f"Fig. 14, (alpha, beta, a) = {SYSTEM}, a_x = {A_X}"
    along = {k: c for k, c in curves.items() if c.series.a_y == 0}
    checks = [sliding_check(list(along.values()), where),
              below_check(list(along.values()), where)]
    tra = curves["transverse"]
    ok = tra.trusted
    checks.append(Check("transverse only: never continuous sliding, largest |mu/mu0|",
                        where + f", a = 0, a_y = {A_X} ({int(ok.sum())} trusted points)",
                        float(np.max(np.abs(tra.mu_ratio[ok]))), "",
                        "below 1: the slip keeps turning (theory: no critical velocity)"))
    d, at = max_deviation(tra.lateral_ratio[ok], np.zeros(int(ok.sum())),
                          [f"V = {v:.4g}" for v in tra.series.v_inertial[ok]])
    checks.append(Check("transverse only: mean lateral force 0 (a = 0: the half-period "
                        "shift is the mirror y -> -y)", where, d, at,
                        "the 2-D solver's lateral_ratio at every trusted point"))
    # mirror symmetry: the phase-0 and phase-pi curves share one symmetric grid
    c0, cp = curves[f"combined,phase_x={0.0:.6g}"], curves[f"combined,phase_x={math.pi:.6g}"]
    V0, Vp = c0.series.v_inertial, cp.series.v_inertial
    if not np.array_equal(V0, -Vp[::-1]):
        raise AssertionError("Fig. 14: the phase-0 and phase-pi grids are not mirrors")
    d, at = max_deviation(c0.mu_ratio, -cp.mu_ratio[::-1], [f"V = {v:.4g}" for v in V0])
    checks.append(Check("mirror symmetry mu(V; phase_x) = -mu(-V; phase_x + pi)",
                        where + f", phase_x = 0 against pi ({V0.size} pairs, each solved)",
                        d, at, "the solver computes V < 0 as the mirror (phase_x + pi)"))
    # blocking forces against the static band of the stuck contact
    vals, refs, labels = [], [], []
    for key, c in along.items():
        s = c.series
        band = theory.inplane_static_mu_ratio(al, be, s.amplitude, s.a_x, s.phase_x)
        V = s.v_inertial
        for i, ref in ((int(np.argmin(np.where(V > 0, V, np.inf))), band.upper),
                       (int(np.argmax(np.where(V < 0, V, -np.inf))), band.lower)):
            vals.append(c.mu_ratio[i])
            refs.append(float(ref))
            labels.append(f"{key}, V = {V[i]:.1e}")
    d, at = max_deviation(np.array(vals), np.array(refs), labels)
    checks.append(Check("blocking force mu(V -> 0+-) = static band (1 - |a + Q|, "
                        "-(1 - |a - Q|))", where + ", at V = +-1e-4", d, at,
                        "theory.inplane_static_mu_ratio; the distance is the creep at "
                        "V = 1e-4, about 5 V"))
    lon = curves["longitudinal"]
    V = lon.series.v_inertial
    law = np.asarray(theory.kinematic_mu_longitudinal(V, A_X))
    d, at = max_deviation(lon.mu_ratio, law, [f"V = {v:.4g}" for v in V])
    checks.append(Check("kinematic law (2/pi) arcsin(V/a_x), longitudinal only",
                        where + ", a = 0", d, at,
                        f"not expected to hold here: the law is the rigid body's limit "
                        f"|alpha - 1| a_x >> 1 and k a_x >> 1 (here {abs(al - 1) * A_X:g} and "
                        f"{(be - al) * A_X:g}); drawn for orientation; its critical velocity "
                        f"a_x is exact (V_c = a_x for a = 0, substrate)"))
    notes = (f"Fig. 14: untrusted points {sum(int(np.sum(~c.trusted)) for c in curves.values())}"
             f" of {sum(c.series.size for c in curves.values())}.")
    return checks, notes


def inplane_directions(quick: bool = False) -> Recipe:
    """Fig. 14: normal, longitudinal and combined oscillation of one pin, mu against V."""
    al, be, a = SYSTEM
    params = (f"alpha = {al}, beta = {be}, zeta = 0, eta_c = 0, substrate oscillation "
              "(inplane_on = substrate)",
              f"normal: amplitude = {a}, a_x = 0; longitudinal: amplitude = 0, a_x = {A_X}; "
              f"combined: amplitude = {a}, a_x = {A_X}, phase_x = 0, pi/2, pi; "
              f"transverse: amplitude = 0, a_y = {A_X} (the 2-D solver)",
              "v_inertial = v0 m omega/(mu0 F_N0), signed (V < 0: backward sliding); "
              "kinematic = (2/pi) arcsin(V/a_x) (rigid body, longitudinal only) or "
              "(2/pi) K(m)/sqrt(1 + eps^2) (transverse only); "
              "v_c_forward = V_c(phase_x), v_c_backward = V_c(phase_x + pi) "
              "(theory.inplane_critical_velocity)")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_directions(curves)

        def extra(c: Curve) -> dict[str, NDArray]:
            n = c.series.size
            return {**inplane_columns(c),
                    "kinematic": np.asarray(
                        theory.kinematic_mu_longitudinal(c.v_inertial, c.series.a_x)
                        if c.series.a_x > 0 else
                        theory.kinematic_mu_transverse(c.v_inertial, c.series.a_y)
                        if c.series.a_y > 0 else np.full(n, np.nan)),
                    "v_c_forward": np.full(n, c.series.meta["v_c_forward"]),
                    "v_c_backward": np.full(n, c.series.meta["v_c_backward"])}

        table = curve_table("Fig. 14: directions of oscillation", curves, params, extra=extra)
        checks, notes = _directions_checks(curves)
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig14_inplane_directions",
        title="Fig. 14 (beyond the paper): normal, longitudinal and combined oscillation",
        caption=("$\\mu_{macro}/\\mu_0$ against the signed $V = v_0 m\\omega/(\\mu_0 "
                 f"F_{{N,0}})$ for the pin $(\\alpha, \\beta) = ({al:g}, {be:g})$ (undamped, "
                 f"elastic contact) with a normal oscillation $\\Delta F_N/F_{{N,0}} = {a:g}$ "
                 f"only, a longitudinal substrate oscillation $a_x = {A_X:g}$ "
                 "(velocity amplitude in units of $\\mu_0 F_{N,0}/(m\\omega)$) only, and both "
                 "at the phases $\\varphi_x$ = 0, $\\pi/2$, $\\pi$, and a transverse "
                 f"oscillation $a_y = {A_X:g}$ only (the 2-D solver). Dashed verticals: the "
                 "critical velocities of continuous sliding $V_c(\\varphi_x)$ and "
                 "$-V_c(\\varphi_x + \\pi)$ (theory); dotted: the rigid body's kinematic "
                 "laws (red along, cyan across), which this soft pin does not reach: its "
                 "contact spring takes up most of the transverse motion ($k a_y < 1$). "
                 "At $V \\to 0^\\pm$ the curves tend to the static band of the stuck "
                 "contact (Fig. 16)."),
        series=_fig14_series(quick), render=render, parameters=params)
