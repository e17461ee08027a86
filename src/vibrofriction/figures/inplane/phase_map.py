"""Fig. 15: the combined drive over ``(phase_x, V)``.

Reduction, drive and the boundary of continuous sliding.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
from numpy.typing import NDArray

from .. import style
from ..recipe import Check, Recipe, Rendered, curve_table, max_deviation
from ..series import Curve, Series
from .common import (
    DAMPING,
    DRIVE_AMPLITUDES,
    SYSTEM,
    below_check,
    critical_v,
    critical_v_pair,
    inplane_columns,
    sliding_check,
)


# --------------------------------------------------------------------------- Fig. 15
def _map_grid(quick: bool, a_x: float) -> tuple[NDArray, NDArray, float]:
    """The phases and the signed velocities of a map panel, and ``V_max``.

    Phases (``0..2 pi``, an even number of steps: ``phase + pi`` is on the grid) and the
    signed velocities (cell centres, symmetric, no 0) of a map panel; ``V_max``.
    """
    zeta, eta_c = DAMPING
    n_phase = 24 if quick else 96
    n_v = 15 if quick else 80
    phases = np.linspace(0.0, 2 * math.pi, n_phase + 1)
    vmax = 1.1 * float(np.max(critical_v(SYSTEM[2], a_x, np.linspace(0, 2 * math.pi, 361), zeta,
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
        ax.plot(ph, critical_v(a, a_x, ph, zeta, eta_c), color="black", lw=1.0, ls="--")
        ax.plot(ph, -critical_v(a, a_x, ph + math.pi, zeta, eta_c), color="black", lw=1.0, ls="--")
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
        checks += [sliding_check(rows, where), below_check(rows, where)]
        # |mu| reaches 1 at the first grid velocity beyond V_c
        V = rows[0].series.v_inertial
        dv = float(V[1] - V[0])
        worst, at = 0.0, "every row"
        for c in rows:
            up, down = critical_v_pair(a, a_x, c.series.phase_x, zeta, eta_c)
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
            up, down = critical_v_pair(a, s.a_x, s.phase_x, zeta, eta_c)
            return {**inplane_columns(c), "v_c_forward": np.full(n, up),
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
