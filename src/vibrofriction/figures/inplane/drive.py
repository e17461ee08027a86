"""Fig. 16: the drive's characteristic against the phase.

The blocking forces and the idle velocity.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import brentq

from ... import theory
from ...solver import solve_points
from .. import style
from ..recipe import Check, Recipe, Rendered, curve_table, max_deviation
from ..series import Curve, Series
from .common import (
    DAMPING,
    DRIVE_AMPLITUDES,
    SYSTEM,
    V_BLOCK,
    critical_v,
    inplane_columns,
    sliding_check,
    tex,
)


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
    vmax = 1.05 * float(np.max(critical_v(SYSTEM[2], a_x, np.linspace(0, 2 * math.pi, 361))))
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
    """Every ``V != 0`` at which the curve's ``mu`` changes sign.

    Every ``V != 0`` at which the curve's ``mu`` changes sign, refined by Brent's method
    on the solver (:func:`solve_points`); empty where ``mu`` has the sign of ``V``
    everywhere on the grid.  A bracket with an untrusted end is skipped.
    """
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
    """Per ``(a_x, zeta)``.

    Phases, blocking forces at both V_BLOCK, static band, idle velocities (list per phase), and
    the solver's mu at the idle velocities.
    """
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
            vc_up = critical_v(SYSTEM[2], a_x, ph, zeta, d["eta_c"])
            vc_dn = critical_v(SYSTEM[2], a_x, ph + math.pi, zeta, d["eta_c"])
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
        Line2D([], [], color="0.3", lw=1.2, label=rf"$\mu(V = +{tex(V_BLOCK[0])})$ (solver)"),
        Line2D([], [], color="0.3", lw=1.2, ls=(0, (4, 1.5)),
               label=rf"$\mu(V = -{tex(V_BLOCK[0])})$ (solver)"),
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
        checks.append(sliding_check(d["rows"], where))
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
            return {**inplane_columns(c), "static_upper": np.full(n, float(band.upper)),
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
                 f"blocking forces, $\\mu$ at $V = \\pm {tex(V_BLOCK[0])}$ (solid: forward, "
                 "dashed: backward), over the static band of the stuck contact (theory, "
                 "black dotted). Bottom: the idle velocity, where the mean force "
                 "vanishes (Brent's method on the solver), with the critical velocities of "
                 "continuous sliding (thin dashed). Where both blocking forces share a sign "
                 "the oscillation drives the body (actuator); where they differ in size "
                 "only, it is a ratchet."),
        series=_drive_series(quick), render=render, parameters=params)
