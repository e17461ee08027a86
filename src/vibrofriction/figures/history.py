"""Fig. 2: time history of the normal force ``mu0 F_N`` and the tangential contact force.

During slip the tangential force equals ``mu0 F_N``; during stick it is smaller.
Stick begins when the velocity of the contact point vanishes (``t1``) and ends
when the tangential force reaches ``mu0 F_N`` (``t2``) (paper, Section 3).

:func:`plot_history` draws any :func:`~vibrofriction.simulate` history the same way, with
the local coefficient below and, for rate-and-state friction, the state ``theta``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from ..params import Dimensionless
from ..schema import ContactState
from ..solver import History, RateStateHistory, simulate
from . import style
from .checks import history_mu_ratio, history_note, history_transitions
from .recipe import Recipe, Rendered, Table
from .series import Curve

__all__ = ["FIG2_POINT", "fig2", "plot_history"]

#: The stick-slip point shown: ``(alpha, beta, a, vbar)`` -- a general (not limiting)
#: system whose steady state has one stick and one slip phase per period.
FIG2_POINT = (0.3, 3.0, 0.8, 0.5)
_PERIODS = 4
#: The window shown, in drive periods: it starts in slip so that, as in the paper,
#: ``t1`` is the beginning of a stick phase.
_WINDOW = (0.5, 2.75)


def _shade_phases(ax, tau_p, phase) -> None:
    """Shade the runs of stick, reverse slip and flight.

    Shade every maximal run of samples in stick, reverse slip or flight (forward slip,
    the ordinary sliding, stays unshaded).
    """
    labelled = set()
    start = 0
    for i in range(1, len(phase) + 1):
        if i == len(phase) or phase[i] != phase[start]:
            name = str(phase[start])
            color = style.PHASE_COLORS.get(name, "none")
            if color != "none" and name != "slip+":
                label = None if name in labelled else ContactState.from_label(name).long_name
                labelled.add(name)
                ax.axvspan(tau_p[start], tau_p[i - 1], color=color, alpha=0.6, lw=0,
                           label=label, zorder=0)
            start = i


@style.styled
def _render(_: Mapping[str, Curve]) -> Rendered:
    alpha, beta, a, vbar = FIG2_POINT
    system = Dimensionless(alpha, beta, a)
    h = simulate(system, vbar=vbar, periods=_PERIODS, samples_per_period=600, initial="steady")
    t = h.tau / (2.0 * math.pi)
    mean_f = history_mu_ratio(h)

    fig = style.figure(style.COLUMN, 2.5)
    ax = fig.add_subplot()
    w = (t >= _WINDOW[0]) & (t <= _WINDOW[1])
    _shade_phases(ax, t[w], h.phase[w])
    ax.axhline(0.0, color="0.5", lw=0.4)
    ax.plot(t[w], h.n[w], color="#1f77b4", lw=1.3, label=r"$\mu_0 F_N$")
    ax.plot(t[w], h.f[w], color="#2ca02c", lw=1.1, ls="--",
            label=r"$k_{x,c}(u_x - u_{x,c})$")
    transitions = history_transitions(h, _WINDOW)
    ymax = 1.0 + a
    for k, e in enumerate(transitions, start=1):
        x = e.tau / (2.0 * math.pi)
        ax.axvline(x, color="0.3", lw=0.5, ls=":")
        ax.text(x, ymax * 1.03, f"$t_{k}$", ha="center", va="bottom", fontsize=7)
    ax.set_xlim(*_WINDOW)
    ax.set_ylim(min(-0.05, float(h.f[w].min()) * 1.1), ymax * 1.14)
    ax.set_xlabel(r"time $\omega t/2\pi$ (drive periods)")
    ax.set_ylabel(r"force / $\mu_0 F_{N,0}$")
    fig.legend(loc="outside upper center", ncol=3, fontsize=6.5, handlelength=1.8,
               columnspacing=1.2)
    ax.set_title(rf"$\alpha={alpha:g}$, $\beta={beta:g}$, "
                 rf"$\Delta u_z/u_{{z,0}}={a:g}$, $\bar v={vbar:g}$:  "
                 rf"$\mu_{{\mathrm{{macro}}}}/\mu_0={mean_f:.3f}$", fontsize=7, pad=3)

    table = Table("Fig. 2: time history in the steady state", (
        f"alpha={alpha}, beta={beta}, amplitude={a}, vbar={vbar}, "
        f"v_inertial={h.v_inertial!r}, initial state: steady (periodic orbit)",
        "tau = omega t; forces in units of mu0 F_N0: n = mu0 F_N/(mu0 F_N0), "
        "f = contact-spring force; x, x_dot in units mu0 F_N0/(m omega^2), mu0 F_N0/(m omega)",
        "events: " + "; ".join(f"{e.kind} at tau={e.tau:.6f}" for e in h.events),
    ), {"tau": h.tau, "n": h.n, "f": h.f, "x": h.x, "x_dot": h.x_dot,
        "phase": np.asarray(h.phase, dtype=object)})
    notes = history_note(h, FIG2_POINT, _WINDOW)
    return Rendered(fig, (table,), (), notes)


def fig2() -> Recipe:
    """Fig. 2 recipe (no solver series: it simulates one history itself)."""
    alpha, beta, a, vbar = FIG2_POINT
    return Recipe(
        name="fig02_history",
        title="Fig. 2: forces over time in a stick-slip steady state",
        caption=(
            "Normal force times the local coefficient of friction, $\\mu_0 F_N$ (blue), "
            "and the tangential force of the contact spring (green, dashed), in units of "
            "$\\mu_0 F_{N,0}$, over 2.25 drive periods of the steady state at "
            "$(\\alpha, \\beta, \\Delta u_z/u_{z,0}, \\bar v)$ = "
            f"$({alpha}, {beta}, {a}, {vbar})$. "
            "Stick phases are shaded; $t_k$ mark the transitions. In slip the two "
            "forces coincide, in stick the tangential force stays below $\\mu_0 F_N$."),
        series=(),
        render=_render,
    )


def plot_history(h: History):
    """A history's forces, its local coefficient and, with rate-and-state friction, ``theta``.

    Top: ``n`` and ``f`` (units ``mu0 F_N0``), stick, reverse slip and flight shaded, the
    events marked. Below: the local coefficient ``f/n`` (over ``mu0``; none in flight), with
    the kinetic ``+-1`` (and ``+-static_ratio``) or, for rate-and-state friction, steady
    sliding's ``+-mu_ss(V)/mu_star`` dashed. A :class:`~vibrofriction.RateStateHistory` adds
    ``theta`` on a log scale, with steady sliding's ``d_c/|V|`` dashed.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from ..theory import steady_mu_ratio

    rs = h if isinstance(h, RateStateHistory) else None
    d = h.system
    t = h.tau / (2.0 * math.pi)
    panels = 3 if rs is not None else 2
    fig = style.figure(style.COLUMN, 1.25 * panels + 0.6)
    axes = fig.subplots(panels, 1, sharex=True)
    ax = axes[0]
    _shade_phases(ax, t, h.phase)
    ax.axhline(0.0, color="0.5", lw=0.4)
    ax.plot(t, h.n, color="#1f77b4", lw=1.2, label=r"$n = F_N/F_{N,0}$")
    ax.plot(t, h.f, color="#2ca02c", lw=1.1, label=r"$f = F_x/(\mu_0 F_{N,0})$")
    for e in h.events:
        ax.axvline(e.tau / (2.0 * math.pi), color="0.3", lw=0.4, ls=":")
    ax.set_ylabel(r"force / $\mu_0 F_{N,0}$")
    ax.legend(fontsize=6, loc="upper right", ncol=2)
    with np.errstate(divide="ignore", invalid="ignore"):
        mu = rs.local_mu if rs is not None else np.where(h.n > 0.0, h.f / h.n, np.nan)
    ax = axes[1]
    ax.plot(t, mu, color="#1f77b4", lw=1.1)
    if rs is not None:
        level = abs(float(steady_mu_ratio(abs(h.v_inertial), d.rs_a, d.rs_b, d.rs_d_c,
                                          d.rs_v_ref)))
        label = rf"steady sliding $\pm{level:.4g}$"
    else:
        level, label = d.static_ratio, r"$\pm\mu_s/\mu_0$" if d.static_ratio > 1.0 \
            else r"kinetic $\pm 1$"
    for sign in (1.0, -1.0):
        ax.axhline(sign * level, color="#d62728", lw=0.8, ls="--",
                   label=label if sign > 0 else None)
    ax.set_ylabel(r"$f/n$ (over $\mu_0$)")
    ax.legend(fontsize=6, loc="lower right")
    if rs is not None:
        ax = axes[2]
        ax.semilogy(t, rs.theta, color="#6a3d9a", lw=1.1)
        ax.axhline(d.rs_d_c / abs(h.v_inertial), color="#d62728", lw=0.8, ls="--",
                   label=r"steady sliding $d_c/V$")
        ax.set_ylabel(r"$\theta$ ($1/\omega$)")
        ax.legend(fontsize=6, loc="lower right")
    axes[-1].set_xlabel(r"time $\omega t/2\pi$ (drive periods)")
    axes[-1].set_xlim(float(t[0]), float(t[-1]))
    law = (f"\nrate-and-state ({d.rs_law} law): a={d.rs_a:g}, b={d.rs_b:g}, d_c={d.rs_d_c:g}, "
           f"v_ref={d.rs_v_ref:g}" if rs is not None else
           f", static_ratio={d.static_ratio:g}" if d.static_ratio > 1.0 else "")
    axes[0].set_title(f"alpha={d.alpha:g}, beta={d.beta:g}, amplitude={d.amplitude:g}, "
                      f"V={h.v_inertial:g}{law}", fontsize=6, pad=3)
    return fig
