r"""Beyond the paper: the longitudinal in-plane oscillation (issue 20, docs/inplane.md).

The system is the issue's pin ``(alpha, beta, a) = (0.5, 2, 0.5)`` with a substrate
oscillation ``a_x = du_x m omega^2/(mu0 F_N0)`` along the sliding direction (the
vibration-velocity amplitude in units of the inertial velocity), velocities signed
(``V < 0`` slides backward; the solver's mirror).

* Fig. 14: the directions of oscillation for one pin, ``mu/mu0`` against ``V``: normal
  only, longitudinal only and combined at three phases, with the critical velocities of
  continuous sliding (:func:`theory.inplane_critical_velocity`) and the rigid body's
  kinematic law (:func:`theory.kinematic_mu_longitudinal`).
* Fig. 15: the combined drive over ``(phase_x, V)``: where friction is reduced, where the
  drive pushes (the mean force against the motion's sign: an actuator) and the boundary
  of continuous sliding ``|V| = V_c(phase_x)``.
* Fig. 16: the drive's characteristic against the phase: the blocking forces
  ``mu(V -> 0+-)`` beside the static band of the stuck contact
  (:func:`theory.inplane_static_mu_ratio`) and the idle velocity (``mu = 0``).

The transverse (2-D) oscillation is not in the solver and not drawn.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import brentq

from .. import theory
from ..solver import solve_points
from . import style
from .recipe import Check, Recipe, Rendered, curve_table, max_deviation
from .series import Curve, Series

__all__ = [
    "A_X",
    "DAMPING",
    "DRIVE_AMPLITUDES",
    "SYSTEM",
    "V_BLOCK",
    "blocking_forces",
    "idle_velocities",
    "inplane_directions",
    "inplane_drive",
    "inplane_map",
]

#: The issue's pin ``(alpha, beta, a)`` and its substrate amplitude ``a_x``.
SYSTEM: tuple[float, float, float] = (0.5, 2.0, 0.5)
A_X = 0.5
#: The damped variant of the issue: pin ``zeta`` and contact ``eta_c``.
DAMPING: tuple[float, float] = (0.05, 0.1)
#: Fig. 15 and 16: the issue's amplitude and a larger one at which the drive appears.
DRIVE_AMPLITUDES: tuple[float, ...] = (0.5, 1.0)
#: Fig. 16: the blocking force is ``mu`` at ``V = +-V_BLOCK[0]``; ``V_BLOCK[1]`` checks
#: its convergence in ``V``.
V_BLOCK: tuple[float, float] = (1e-5, 1e-4)
_FIG14_PHASES: tuple[tuple[str, float], ...] = (("0", 0.0), (r"\pi/2", math.pi / 2),
                                                (r"\pi", math.pi))
_AROUND_VC = (0.97, 0.99, 1.01, 1.03)
_SLIDING_BEYOND = 1.001   # continuous sliding is checked at |V| > this * V_c


def _tex(x: float) -> str:
    """``1e-05`` as ``10^{-5}`` for mathtext (a power of ten)."""
    return f"10^{{{round(math.log10(x))}}}"


def _vc(a: float, a_x: float, phase: float | NDArray, zeta: float = 0.0, eta_c: float = 0.0
        ) -> float | NDArray:
    """Critical velocity of forward continuous sliding (docs/inplane.md, section 2)."""
    return theory.inplane_critical_velocity(SYSTEM[0], SYSTEM[1], a, a_x, phase, zeta, eta_c)


def _vc_pair(a: float, a_x: float, phase: float, zeta: float = 0.0, eta_c: float = 0.0
             ) -> tuple[float, float]:
    """``(V_c forward, V_c backward)``: backward sliding needs ``|V| > V_c(phase + pi)``."""
    return (float(_vc(a, a_x, phase, zeta, eta_c)),
            float(_vc(a, a_x, phase + math.pi, zeta, eta_c)))


def _inplane_columns(c: Curve) -> dict[str, NDArray]:
    s = c.series
    n = s.size
    return {"zeta": np.full(n, s.zeta), "eta_c": np.full(n, s.eta_c), "a_x": np.full(n, s.a_x),
            "phase_x": np.full(n, s.phase_x),
            "inplane_on": np.full(n, s.inplane_on, dtype=object)}


def _mark_untrusted(ax, x: NDArray, c: Curve, color, ms: float = 2.5) -> None:
    """Untrusted points as open circles at their (signed) value, or a bar over the range
    of their last windows' means when they did not settle."""
    bad = ~np.asarray(c.trusted)
    mu = c.mu_ratio
    valued = bad & np.isfinite(mu)
    if np.any(valued):
        ax.plot(x[valued], mu[valued], "o", ms=ms, mfc="none", mec=color, mew=0.5)
    ranged = bad & ~np.isfinite(mu) & np.isfinite(c.window_min)
    if np.any(ranged):
        ax.vlines(x[ranged], c.window_min[ranged], c.window_max[ranged], colors=color, lw=0.6)


def _sliding_check(curves: Sequence[Curve], where: str) -> Check:
    """``mu = sign(V)`` beyond the critical velocities (continuous sliding)."""
    dev, labels = [], []
    for c in curves:
        s = c.series
        up, down = _vc_pair(s.amplitude, s.a_x, s.phase_x, s.zeta, s.eta_c)
        V = s.v_inertial
        sel = (V > _SLIDING_BEYOND * up) | (V < -_SLIDING_BEYOND * down)
        dev += list(np.abs(c.mu_ratio[sel] - np.sign(V[sel])))
        labels += [f"{s.key}, V = {v:.4g}" for v in V[sel]]
    d, at = max_deviation(np.array(dev), np.zeros(len(dev)), labels)
    return Check("continuous sliding: mu/mu0 = sign(V) for V > V_c(phase_x) and "
                 "V < -V_c(phase_x + pi)", where + f" ({len(dev)} points beyond "
                 f"{_SLIDING_BEYOND:g} V_c)", d, at,
                 "V_c from theory.inplane_critical_velocity; the solver proves the sliding "
                 "orbit (status continuous sliding, mu = 1 exactly)" if d == 0 else
                 "V_c from theory.inplane_critical_velocity")


def _below_check(curves: Sequence[Curve], where: str, below: float = 0.99) -> Check:
    """Just below ``V_c`` the contact must stick or reverse: ``|mu| < 1``; the smallest
    margin ``1 - |mu|`` there (it closes quadratically at ``V_c``)."""
    margin, at = math.inf, "no points"
    n = 0
    for c in curves:
        s = c.series
        up, down = _vc_pair(s.amplitude, s.a_x, s.phase_x, s.zeta, s.eta_c)
        V = s.v_inertial
        sel = ((V > 0) & (V < below * up)) | ((V < 0) & (V > -below * down))
        n += int(sel.sum())
        if np.any(sel):
            i = np.flatnonzero(sel)[np.nanargmax(np.abs(c.mu_ratio[sel]))]
            if 1 - abs(c.mu_ratio[i]) < margin:
                margin, at = float(1 - abs(c.mu_ratio[i])), f"{s.key}, V = {V[i]:.4g}"
    return Check(f"no continuous sliding below {below:g} V_c: smallest 1 - |mu/mu0|",
                 where + f" ({n} points)", margin, at,
                 "positive: below V_c the contact sticks or reverses, as the closed form says"
                 if margin > 0 else "NOT positive: continuous sliding below V_c")


# --------------------------------------------------------------------------- Fig. 14
def _fig14_grid(quick: bool, up: float, down: float) -> NDArray:
    n = 28 if quick else 140
    base = np.concatenate([np.geomspace(1e-4, 0.02, 6 if quick else 12),
                           np.linspace(0.02, 1.4, n)])
    pos = np.concatenate([base, [k * up for k in _AROUND_VC if up > 0]])
    neg = np.concatenate([base, [k * down for k in _AROUND_VC if down > 0]])
    return np.unique(np.concatenate([-neg, pos]))


def _fig14_series(quick: bool) -> tuple[Series, ...]:
    al, be, a = SYSTEM
    out = []
    for key, amp, a_x, phase, label in (
            ("normal", a, 0.0, 0.0, "normal only"),
            ("longitudinal", 0.0, A_X, 0.0, "longitudinal only"),
            *((f"combined,phase_x={p:.6g}", a, A_X, p, rf"combined, $\varphi_x = {lab}$")
              for lab, p in _FIG14_PHASES)):
        up, down = _vc_pair(amp, a_x, phase)
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
            **{f"combined,phase_x={p:.6g}": c for (_, p), c in zip(_FIG14_PHASES, cs,
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
        _mark_untrusted(ax, V, c, col)
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
    checks = [_sliding_check(list(along.values()), where),
              _below_check(list(along.values()), where)]
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
            return {**_inplane_columns(c),
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


# --------------------------------------------------------------------------- Fig. 15
def _map_grid(quick: bool, a_x: float) -> tuple[NDArray, NDArray, float]:
    """Phases (``0..2 pi``, an even number of steps: ``phase + pi`` is on the grid) and the
    signed velocities (cell centres, symmetric, no 0) of a map panel; ``V_max``."""
    zeta, eta_c = DAMPING
    n_phase = 24 if quick else 96
    n_v = 15 if quick else 80
    phases = np.linspace(0.0, 2 * math.pi, n_phase + 1)
    vmax = 1.1 * float(np.max(_vc(SYSTEM[2], a_x, np.linspace(0, 2 * math.pi, 361), zeta,
                                  eta_c)))
    dv = vmax / n_v
    half = (np.arange(n_v) + 0.5) * dv
    return phases, np.concatenate([-half[::-1], half]), vmax


def _map_series(quick: bool) -> tuple[Series, ...]:
    al, be, a = SYSTEM
    zeta, eta_c = DAMPING
    out = []
    for a_x in DRIVE_AMPLITUDES:
        phases, V, vmax = _map_grid(quick, a_x)
        for j, p in enumerate(phases):
            out.append(Series(f"a_x={a_x:g},phase={j}", al, be, a, V, np.full(V.size, np.nan),
                              {"a_x": a_x, "row": j, "v_max": vmax}, zeta=zeta, eta_c=eta_c,
                              a_x=a_x, phase_x=float(p)))
    return tuple(out)


def _map_rows(curves: Mapping[str, Curve], a_x: float) -> list[Curve]:
    rows = [c for c in curves.values() if c.series.meta["a_x"] == a_x]
    return sorted(rows, key=lambda c: c.series.meta["row"])


def _edges(x: NDArray) -> NDArray:
    mid = 0.5 * (x[1:] + x[:-1])
    return np.concatenate([[x[0] - (mid[0] - x[0])], mid, [x[-1] + (x[-1] - mid[-1])]])


@style.styled
def _draw_map(curves: Mapping[str, Curve]):
    import matplotlib as mpl
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    zeta, eta_c = DAMPING
    a = SYSTEM[2]
    fig = style.figure(style.PAGE, 3.5)
    axes = fig.subplots(1, len(DRIVE_AMPLITUDES), sharey=False)
    cmap = mpl.colormaps["RdBu_r"].with_extremes(bad="0.55")
    mesh = None
    for k, (ax, a_x) in enumerate(zip(axes, DRIVE_AMPLITUDES, strict=True)):
        rows = _map_rows(curves, a_x)
        phases = np.array([c.series.phase_x for c in rows])
        V = rows[0].series.v_inertial
        mu = np.array([c.trusted_mu for c in rows])            # (phase, V); untrusted: nan
        mesh = ax.pcolormesh(_edges(phases), _edges(V), mu.T, cmap=cmap, vmin=-1, vmax=1,
                             shading="flat", rasterized=True)
        push = np.isfinite(mu) & (np.sign(mu) * np.sign(V)[None, :] < 0)
        if np.any(push):  # hatch the cells where the drive pushes
            ax.pcolor(_edges(phases), _edges(V), np.ma.masked_where(~push.T, push.T * 1.0),
                      hatch="////", facecolor="none", edgecolor="black", lw=0.0)
        for side in (V > 0, V < 0):  # mu = 0 away from V = 0: the idle velocity
            m = mu[:, side]
            if np.nanmin(m) < 0 < np.nanmax(m):
                ax.contour(phases, V[side], m.T, levels=[0.0], colors="black",
                           linewidths=0.8)
        ph = np.linspace(0, 2 * math.pi, 361)
        ax.plot(ph, _vc(a, a_x, ph, zeta, eta_c), color="black", lw=1.0, ls="--")
        ax.plot(ph, -_vc(a, a_x, ph + math.pi, zeta, eta_c), color="black", lw=1.0, ls="--")
        vmax = rows[0].series.meta["v_max"]
        ax.set_xlim(0, 2 * math.pi)
        ax.set_ylim(-vmax, vmax)
        ax.set_xticks(np.arange(5) * math.pi / 2,
                      ["0", r"$\pi/2$", r"$\pi$", r"$3\pi/2$", r"$2\pi$"])
        ax.set_xlabel(r"phase $\varphi_x$ of the longitudinal oscillation")
        ax.set_title(rf"({'ab'[k]}) $a_x = {a_x:g}$", fontsize=7.5)
        ax.axhline(0, color="0.3", lw=0.4)
    axes[0].set_ylabel(r"$V = v_0 m\omega/(\mu_0 F_{N,0})$")
    assert mesh is not None  # one panel per amplitude was drawn
    cb = fig.colorbar(mesh, ax=axes, shrink=0.9, pad=0.02)
    cb.set_label(style.MU)
    al, be, _ = SYSTEM
    fig.suptitle(rf"combined drive: $\alpha = {al:g}$, $\beta = {be:g}$, "
                 rf"$\Delta F_N/F_{{N,0}} = {a:g}$, $\zeta = {zeta:g}$, "
                 rf"$\eta_c = {eta_c:g}$, substrate", fontsize=7.5)
    fig.legend(handles=[
        Line2D([], [], color="black", lw=1.0, ls="--",
               label=r"$V = V_c(\varphi_x)$, $-V_c(\varphi_x + \pi)$: continuous sliding "
                     r"beyond ($\mu = \pm\mu_0$, theory)"),
        Patch(facecolor="white", edgecolor="black", hatch="////", lw=0.6,
              label=r"drive (actuator): $\mu$ against the sign of $V$ (solver)"),
        Line2D([], [], color="black", lw=0.8, label=r"idle velocity: $\mu = 0$ at "
                                                     r"$V \neq 0$ (solver, interpolated)"),
        Patch(facecolor="0.55", label="untrusted point (masked)")],
        loc="outside lower center", ncol=2, fontsize=6)
    return fig


def _map_checks(curves: Mapping[str, Curve]) -> tuple[list[Check], str]:
    zeta, eta_c = DAMPING
    a = SYSTEM[2]
    checks = []
    counts = []
    for a_x in DRIVE_AMPLITUDES:
        rows = _map_rows(curves, a_x)
        where = f"Fig. 15, a_x = {a_x:g}, zeta = {zeta}, eta_c = {eta_c}"
        checks += [_sliding_check(rows, where), _below_check(rows, where)]
        # |mu| reaches 1 at the first grid velocity beyond V_c
        V = rows[0].series.v_inertial
        dv = float(V[1] - V[0])
        worst, at = 0.0, "every row"
        for c in rows:
            up, down = _vc_pair(a, a_x, c.series.phase_x, zeta, eta_c)
            for side, vc in ((1, up), (-1, down)):
                m = (side * V > 0)
                full = m & (np.abs(c.mu_ratio - side) < 1e-9)
                first = float(np.min(side * V[full])) if np.any(full) else math.inf
                gap = first - vc
                if abs(gap) > abs(worst):
                    worst, at = gap, f"phase_x = {c.series.phase_x:.4f}, side {side:+d}"
        checks.append(Check("|mu/mu0| reaches 1 at |V| = V_c: (first |V| with |mu| = 1) - V_c",
                            where + f", grid step dV = {dv:.4g}", abs(worst), at,
                            "within one grid step dV when the deviation is in [0, dV)"
                            + ("" if 0 <= worst < dv else "; NOT within one step")))
        # mirror symmetry over the whole map: phase + pi is on the grid, V symmetric
        n = len(rows) - 1
        pairs, labels = [], []
        for j in range(n):
            jm = (j + n // 2) % n
            pairs.append(rows[j].mu_ratio + rows[jm].mu_ratio[::-1])
            labels += [f"phase_x = {rows[j].series.phase_x:.4f}, V = {v:.4g}" for v in V]
        d, at = max_deviation(np.concatenate(pairs), np.zeros(len(labels)), labels)
        checks.append(Check("mirror symmetry mu(V; phase_x) = -mu(-V; phase_x + pi)", where
                            + f" (every point, {len(labels)} pairs)", d, at,
                            "the solver computes V < 0 as the mirror (phase_x + pi)"))
        mu = np.array([c.mu_ratio for c in rows])
        push = int(np.sum(np.sign(mu) * np.sign(V)[None, :] < 0))
        bad = int(sum(np.sum(~c.trusted) for c in rows))
        counts.append(f"a_x = {a_x:g}: {push} of {mu.size} points drive (mu against the "
                      f"sign of V), {bad} untrusted (masked)")
    return checks, "Fig. 15: " + "; ".join(counts) + "."


def inplane_map(quick: bool = False) -> Recipe:
    """Fig. 15: mu/mu0 over (phase_x, V) for the combined drive, regimes marked."""
    al, be, a = SYSTEM
    zeta, eta_c = DAMPING
    params = (f"alpha = {al}, beta = {be}, amplitude = {a}, zeta = {zeta}, eta_c = {eta_c}, "
              f"substrate oscillation a_x = {DRIVE_AMPLITUDES} at phase_x on [0, 2 pi]",
              "v_inertial signed (cell centres of the map); v_c_forward = V_c(phase_x), "
              "v_c_backward = V_c(phase_x + pi) (theory.inplane_critical_velocity)")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_map(curves)

        def extra(c: Curve) -> dict[str, NDArray]:
            n = c.series.size
            s = c.series
            up, down = _vc_pair(a, s.a_x, s.phase_x, zeta, eta_c)
            return {**_inplane_columns(c), "v_c_forward": np.full(n, up),
                    "v_c_backward": np.full(n, down)}

        table = curve_table("Fig. 15: the combined drive over (phase_x, V)", curves, params,
                            extra=extra)
        checks, notes = _map_checks(curves)
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig15_inplane_map",
        title="Fig. 15 (beyond the paper): the combined drive over phase and velocity",
        caption=("$\\mu_{macro}/\\mu_0$ (colour) over the phase $\\varphi_x$ of the "
                 "longitudinal substrate oscillation and the signed $V$, for the pin "
                 f"$(\\alpha, \\beta) = ({al:g}, {be:g})$, $\\Delta F_N/F_{{N,0}} = {a:g}$, "
                 f"$\\zeta = {zeta:g}$, $\\eta_c = {eta_c:g}$, and $a_x$ = "
                 + ", ".join(f"{x:g}" for x in DRIVE_AMPLITUDES) + ". Red above and blue "
                 "below $V = 0$: friction, reduced below $\\mu_0$ inside the dashed lines "
                 "$V = V_c(\\varphi_x)$ and $V = -V_c(\\varphi_x + \\pi)$ (theory), "
                 "continuous sliding ($\\mu = \\pm\\mu_0$) beyond them. Hatched: the drive "
                 "pushes (the mean force has the sign opposite to $V$: an actuator); its "
                 "edge is the idle velocity. Asymmetry between $V$ and $-V$ at one phase "
                 "is the ratchet. Untrusted points would be masked in gray."),
        series=_map_series(quick), render=render, parameters=params)


# --------------------------------------------------------------------------- Fig. 16
def _drive_cases() -> list[tuple[float, float, float]]:
    """``(a_x, zeta, eta_c)`` of Fig. 16: each amplitude undamped and damped."""
    return [(a_x, z, e) for a_x in DRIVE_AMPLITUDES for z, e in ((0.0, 0.0), DAMPING)]


def _drive_key(a_x: float, zeta: float, j: int) -> str:
    return f"a_x={a_x:g},zeta={zeta:g},phase={j}"


def _drive_phases(quick: bool) -> NDArray:
    return np.linspace(0.0, 2 * math.pi, (12 if quick else 72) + 1)


def _drive_velocities(quick: bool, a_x: float) -> NDArray:
    """``+-V_BLOCK`` and a grid up to beyond the largest ``V_c`` (the sign changes)."""
    vmax = 1.05 * float(np.max(_vc(SYSTEM[2], a_x, np.linspace(0, 2 * math.pi, 361))))
    grid = np.geomspace(1e-3, vmax, 14 if quick else 50)
    pos = np.unique(np.concatenate([V_BLOCK, grid]))
    return np.concatenate([-pos[::-1], pos])


def _drive_series(quick: bool) -> tuple[Series, ...]:
    al, be, a = SYSTEM
    out = []
    for a_x, zeta, eta_c in _drive_cases():
        V = _drive_velocities(quick, a_x)
        for j, p in enumerate(_drive_phases(quick)):
            out.append(Series(_drive_key(a_x, zeta, j), al, be, a, V, np.full(V.size, np.nan),
                              {"row": j}, zeta=zeta, eta_c=eta_c, a_x=a_x, phase_x=float(p)))
    return tuple(out)


def _drive_rows(curves: Mapping[str, Curve], a_x: float, zeta: float) -> list[Curve]:
    rows = [c for c in curves.values()
            if c.series.a_x == a_x and c.series.zeta == zeta]
    return sorted(rows, key=lambda c: c.series.meta["row"])


def blocking_forces(c: Curve, v: float = V_BLOCK[0]) -> tuple[float, float]:
    """``(mu(+v), mu(-v))`` of a drive curve (``v`` on its grid): the blocking forces."""
    V = c.series.v_inertial
    return (float(c.mu_ratio[np.flatnonzero(V == v)[0]]),
            float(c.mu_ratio[np.flatnonzero(V == -v)[0]]))


def idle_velocities(c: Curve, *, xtol: float = 1e-7) -> list[float]:
    """Every ``V != 0`` at which the curve's ``mu`` changes sign, refined by Brent's method
    on the solver (:func:`solve_points`); empty where ``mu`` has the sign of ``V``
    everywhere on the grid.  A bracket with an untrusted end is skipped."""
    s = c.series
    V, mu, ok = s.v_inertial, c.mu_ratio, c.trusted

    def f(v: float) -> float:
        return float(solve_points(s.alpha, s.beta, s.amplitude, v, s.zeta, s.eta_c, s.a_x,
                                  s.phase_x, inplane_on=s.inplane_on)["mu_ratio"])

    roots = []
    for i in range(V.size - 1):
        if V[i] < 0 < V[i + 1] or not (ok[i] and ok[i + 1]):
            continue
        if mu[i] == 0.0:
            roots.append(float(V[i]))
        elif mu[i] * mu[i + 1] < 0:
            roots.append(float(brentq(f, V[i], V[i + 1], xtol=xtol)))
    return roots


def _drive_data(curves: Mapping[str, Curve]) -> dict[tuple[float, float], dict]:
    """Per ``(a_x, zeta)``: phases, blocking forces at both V_BLOCK, static band, idle
    velocities (list per phase), and the solver's mu at the idle velocities."""
    data = {}
    for a_x, zeta, eta_c in _drive_cases():
        rows = _drive_rows(curves, a_x, zeta)
        ph = np.array([c.series.phase_x for c in rows])
        b0 = np.array([blocking_forces(c, V_BLOCK[0]) for c in rows])
        b1 = np.array([blocking_forces(c, V_BLOCK[1]) for c in rows])
        band = theory.inplane_static_mu_ratio(*SYSTEM, a_x, ph, zeta, eta_c)
        idle = [idle_velocities(c) for c in rows]
        data[(a_x, zeta)] = {"phase": ph, "block": b0, "block_coarse": b1,
                             "upper": np.asarray(band.upper), "lower": np.asarray(band.lower),
                             "idle": idle, "eta_c": eta_c, "rows": rows}
    return data


@style.styled
def _draw_drive(data: Mapping[tuple[float, float], dict]):
    from matplotlib.lines import Line2D

    fig = style.figure(style.PAGE, 4.6)
    axes = fig.subplots(2, len(DRIVE_AMPLITUDES), sharex=True, sharey="row")
    colors = {0.0: "#1f77b4", DAMPING[0]: "#e08a00"}
    for k, a_x in enumerate(DRIVE_AMPLITUDES):
        top, bot = axes[0, k], axes[1, k]
        any_idle = False
        for zeta, col in colors.items():
            d = data[(a_x, zeta)]
            ph = d["phase"]
            top.plot(ph, d["block"][:, 0], color=col, lw=1.2)
            top.plot(ph, d["block"][:, 1], color=col, lw=1.2, ls=(0, (4, 1.5)))
            top.plot(ph, d["upper"], color="black", lw=0.5, ls=(0, (1, 1)))
            top.plot(ph, d["lower"], color="black", lw=0.5, ls=(0, (1, 1)))
            xs = [p for p, r in zip(ph, d["idle"], strict=True) for _ in r]
            ys = [v for r in d["idle"] for v in r]
            if ys:
                any_idle = True
                bot.plot(xs, ys, "o", color=col, ms=1.6)
                # a line through phases that have exactly one root
                one = np.array([r[0] if len(r) == 1 else np.nan for r in d["idle"]])
                bot.plot(ph, one, color=col, lw=0.9)
            vc_up = _vc(SYSTEM[2], a_x, ph, zeta, d["eta_c"])
            vc_dn = _vc(SYSTEM[2], a_x, ph + math.pi, zeta, d["eta_c"])
            bot.plot(ph, vc_up, color=col, lw=0.5, ls=(0, (2, 2)))
            bot.plot(ph, -vc_dn, color=col, lw=0.5, ls=(0, (2, 2)))
        if not any_idle:
            bot.text(math.pi, 0.0, "no idle velocity at any phase:\n"
                     r"$\mu$ has the sign of $V$ everywhere", ha="center", va="center",
                     fontsize=6.5, bbox={"fc": "white", "ec": "0.7", "lw": 0.5})
        top.axhline(0, color="0.6", lw=0.4)
        bot.axhline(0, color="0.6", lw=0.4)
        top.set_title(rf"({'ab'[k]}) $a_x = {a_x:g}$", fontsize=7.5)
        bot.set_xlim(0, 2 * math.pi)
        bot.set_xticks(np.arange(5) * math.pi / 2,
                       ["0", r"$\pi/2$", r"$\pi$", r"$3\pi/2$", r"$2\pi$"])
        bot.set_xlabel(r"phase $\varphi_x$")
    axes[0, 0].set_ylabel("blocking force\n" + r"$\mu(V \to 0^\pm)/\mu_0$")
    axes[1, 0].set_ylabel(r"idle velocity $V_0$ ($\mu = 0$)" + "\n"
                          + r"in $\mu_0 F_{N,0}/(m\omega)$")
    al, be, a = SYSTEM
    fig.suptitle(rf"drive characteristic: $\alpha = {al:g}$, $\beta = {be:g}$, "
                 rf"$\Delta F_N/F_{{N,0}} = {a:g}$, substrate oscillation", fontsize=7.5)
    zeta, eta_c = DAMPING
    fig.legend(handles=[
        Line2D([], [], color=colors[0.0], lw=1.2, label="undamped"),
        Line2D([], [], color=colors[zeta], lw=1.2,
               label=rf"$\zeta = {zeta:g}$, $\eta_c = {eta_c:g}$"),
        Line2D([], [], color="0.3", lw=1.2, label=rf"$\mu(V = +{_tex(V_BLOCK[0])})$ (solver)"),
        Line2D([], [], color="0.3", lw=1.2, ls=(0, (4, 1.5)),
               label=rf"$\mu(V = -{_tex(V_BLOCK[0])})$ (solver)"),
        Line2D([], [], color="black", lw=0.5, ls=(0, (1, 1)),
               label="edges of the static band of the stuck contact (theory)"),
        Line2D([], [], color="0.3", lw=0.5, ls=(0, (2, 2)),
               label=r"$V_c(\varphi_x)$, $-V_c(\varphi_x + \pi)$ (theory)")],
        loc="outside lower center", ncol=3, fontsize=6)
    return fig


def _drive_checks(data: Mapping[tuple[float, float], dict]) -> tuple[list[Check], str]:
    checks = []
    notes = []
    for (a_x, zeta), d in data.items():
        where = f"Fig. 16, a_x = {a_x:g}, zeta = {zeta:g}, eta_c = {d['eta_c']:g}"
        ph = d["phase"]
        labels = [f"phase_x = {p:.4f}" for p in ph]
        ref = np.column_stack([d["upper"], d["lower"]])
        has = np.all(np.isfinite(ref), axis=1)
        dev, at = max_deviation(d["block"][has].ravel(), ref[has].ravel(),
                                [lab for lab, h in zip(labels, has, strict=True) if h
                                 for _ in (0, 1)])
        checks.append(Check(
            "blocking force mu(V -> 0+-) = static band (theory.inplane_static_mu_ratio)",
            where + f", V = +-{V_BLOCK[0]:g}, {int(has.sum())} of {ph.size} phases",
            dev, at, "the band exists (a permanent stick) at every phase" if has.all() else
            f"no band (the contact slips in every cycle) at {int((~has).sum())} phases: "
            "not compared there"))
        conv, at = max_deviation(d["block"].ravel(), d["block_coarse"].ravel(),
                                 [lab for lab in labels for _ in (0, 1)])
        checks.append(_sliding_check(d["rows"], where))
        checks.append(Check(f"convergence in V: |mu(+-{V_BLOCK[1]:g}) - mu(+-{V_BLOCK[0]:g})|",
                            where, conv, at, "the blocking force moves by this much over "
                            "a decade of V (linear creep)"))
        n = ph.size - 1
        mirror = [d["block"][j, 0] + d["block"][(j + n // 2) % n, 1] for j in range(n)]
        dev, at = max_deviation(np.array(mirror), np.zeros(n), labels[:n])
        checks.append(Check("mirror symmetry mu(0+; phase_x) = -mu(0-; phase_x + pi)",
                            where, dev, at, "each side solved"))
        # the drive exists (an idle velocity) exactly where both limits share a sign
        mism, where_m = 0, "none"
        res = []
        for j, r in enumerate(d["idle"]):
            drive = d["block"][j, 0] * d["block"][j, 1] > 0
            if bool(r) != bool(drive):
                mism += 1
                where_m = labels[j]
            if r:
                c = d["rows"][j]
                s = c.series
                res += [abs(float(solve_points(s.alpha, s.beta, s.amplitude, v, s.zeta,
                                               s.eta_c, s.a_x, s.phase_x)["mu_ratio"]))
                        for v in r]
        checks.append(Check("an idle velocity exists iff mu(0+) and mu(0-) share a sign "
                            "(count of phases where not)", where, float(mism), where_m,
                            "the sign changes of mu on the velocity grid; more than one root "
                            "on a side would show as extra points"))
        if res:
            checks.append(Check("|mu/mu0| at the idle velocities (Brent on the solver)",
                                where, max(res), "largest", "xtol 1e-7 in V"))
        n_idle = sum(1 for r in d["idle"] if r)
        multi = sum(1 for r in d["idle"] if len(r) > 1)
        notes.append(f"{where}: idle velocity at {n_idle} of {ph.size} phases"
                     + (f" ({multi} with more than one)" if multi else ""))
    return checks, "; ".join(notes) + "."


def inplane_drive(quick: bool = False) -> Recipe:
    """Fig. 16: blocking forces and idle velocity of the drive against the phase."""
    al, be, a = SYSTEM
    zeta, eta_c = DAMPING
    params = (f"alpha = {al}, beta = {be}, amplitude = {a}, substrate oscillation a_x = "
              f"{DRIVE_AMPLITUDES}; undamped and zeta = {zeta}, eta_c = {eta_c}",
              f"blocking forces: mu at V = +-{V_BLOCK[0]:g} (and +-{V_BLOCK[1]:g} for "
              "convergence); static band: theory.inplane_static_mu_ratio",
              "idle_velocities: the roots V != 0 of mu(V) = 0 of the row's curve (Brent's "
              "method on the solver, xtol 1e-7), 'none' where mu has the sign of V")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        data = _drive_data(curves)
        fig = _draw_drive(data)
        idle = {c.series.key: r for d in data.values()
                for c, r in zip(d["rows"], d["idle"], strict=True)}

        def extra(c: Curve) -> dict[str, NDArray]:
            s = c.series
            n = s.size
            band = theory.inplane_static_mu_ratio(*SYSTEM, s.a_x, s.phase_x, s.zeta, s.eta_c)
            return {**_inplane_columns(c), "static_upper": np.full(n, float(band.upper)),
                    "static_lower": np.full(n, float(band.lower)),
                    "idle_velocities": np.full(n, " ".join(f"{v:.8g}" for v in idle[s.key])
                                               or "none", dtype=object)}

        table = curve_table("Fig. 16: the drive's characteristic against phase_x", curves,
                            params, extra=extra)
        checks, notes = _drive_checks(data)
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig16_inplane_drive",
        title="Fig. 16 (beyond the paper): blocking force and idle velocity of the drive",
        caption=("The drive's characteristic against the phase $\\varphi_x$ of the "
                 f"longitudinal substrate oscillation, pin $(\\alpha, \\beta) = ({al:g}, "
                 f"{be:g})$, $\\Delta F_N/F_{{N,0}} = {a:g}$, $a_x$ = "
                 + ", ".join(f"{x:g}" for x in DRIVE_AMPLITUDES) + f", undamped (blue) and "
                 f"with $\\zeta = {zeta:g}$, $\\eta_c = {eta_c:g}$ (orange). Top: the "
                 f"blocking forces, $\\mu$ at $V = \\pm {_tex(V_BLOCK[0])}$ (solid: forward, "
                 "dashed: backward), over the static band of the stuck contact (theory, "
                 "black dotted). Bottom: the idle velocity, where the mean force "
                 "vanishes (Brent's method on the solver), with the critical velocities of "
                 "continuous sliding (thin dashed). Where both blocking forces share a sign "
                 "the oscillation drives the body (actuator); where they differ in size "
                 "only, it is a ratchet."),
        series=_drive_series(quick), render=render, parameters=params)
