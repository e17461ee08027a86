r"""Beyond the paper: stick, slip and lift-off across a sphere over one period (issue 21).

Fig. 19: the time history of a sphere's contact (:func:`vibrofriction.simulate` with
``profile_exponent = 2``: the MDR row of springs recorded at the sample times, on its
periodic orbit), one drive period: above, the friction force ``sum f_i`` and ``mu0`` times
the normal force ``sum n_i``; below, the space-time picture of the contact, the radius
``r/a0`` (both sides of the axis) against time, coloured by each ring's state (stick,
forward slip, reverse slip, flight: out of contact), with the contact radius of the imposed
indentation and the stick radius. Left a sphere that does not jump (``a = 0.5``), right
one that does (``a = 1.5``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
from matplotlib import patheffects
from matplotlib.colors import ListedColormap
from matplotlib.patches import Patch

from .. import theory
from ..params import Dimensionless
from ..schema import ContactState
from ..solver import CurvedHistory, simulate
from ..solver.engine import solve_points
from ..solver.mdr import mdr_friction, mdr_row
from . import style
from .recipe import Check, Recipe, Rendered, Table
from .series import Curve

__all__ = ["FIG19_AMPLITUDES", "FIG19_POINT", "FIG19_SPRINGS", "fig19", "sphere_histories"]

#: ``(alpha, beta, V, zeta)`` of Fig. 19: the soft-ish system of docs/contact_geometry.md.
FIG19_POINT = (0.5, 2.0, 0.3, 0.0)
#: The indentation amplitudes ``a = dd/d0``: no jumping, and jumping.
FIG19_AMPLITUDES = (0.5, 1.5)
FIG19_SPRINGS = 200
_SAMPLES = 720
#: Colour of each contact state, by code (``CurvedHistory.spring_state``).
_STATE_COLORS = {ContactState.STICK: "#3182bd", ContactState.SLIP_POS: "#fdae6b",
                 ContactState.SLIP_NEG: "#e6550d", ContactState.FLIGHT: "#d9d9d9"}
_COLORS = tuple(_STATE_COLORS[s] for s in ContactState)
_NAMES = tuple(s.long_name for s in ContactState)


def sphere_histories() -> dict[float, CurvedHistory]:
    """One period of the periodic orbit of each amplitude of Fig. 19 (sphere, ``n = 2``)."""
    alpha, beta, V, zeta = FIG19_POINT
    out = {}
    for a in FIG19_AMPLITUDES:
        h = simulate(Dimensionless(alpha, beta, a, zeta=zeta, profile_exponent=2.0),
                     v_inertial=V, periods=1, samples_per_period=_SAMPLES,
                     initial="steady", springs=FIG19_SPRINGS)
        assert isinstance(h, CurvedHistory)  # a curved tip's history
        out[a] = h
    return out


def _draw(hs: Mapping[float, CurvedHistory]):
    fig = style.figure(style.PAGE, 4.6)
    axes = fig.subplots(2, len(hs), sharex=True, height_ratios=(1.0, 2.2))
    cmap = ListedColormap(_COLORS)
    for k, (a, h) in enumerate(hs.items()):
        top, bot = axes[0, k], axes[1, k]
        t = h.tau / (2.0 * math.pi)
        top.axhline(0.0, color="0.6", lw=0.4)
        top.plot(t, h.n, color="#1f77b4", lw=1.2, label=r"$\mu_0 F_N$")
        top.plot(t, h.f, color="#2ca02c", lw=1.1, ls="--", label=r"$F_x$ (friction)")
        top.set_title(rf"({'ab'[k]}) $a = \Delta d/d_0$ = {a:g}"
                      + (" (jumping)" if a > 1 else ""), fontsize=7.5)
        top.legend(loc="upper center", fontsize=6, ncol=2, handlelength=1.6)
        top.set_ylim(min(-0.1, 1.1 * float(h.f.min())), 1.25 * float(h.n.max()))
        # the picture: rows are the springs mirrored about the axis, columns the samples
        state = h.spring_state[:-1].T
        image = np.vstack([state[::-1], state])
        r_max = float(h.xi[-1] + h.xi[0])
        bot.imshow(image, cmap=cmap, vmin=-0.5, vmax=len(_COLORS) - 0.5, aspect="auto",
                   interpolation="nearest", origin="lower",
                   extent=(0.0, 1.0, -r_max, r_max))
        contact_r = np.where(h.contact_radius > 0, h.contact_radius, np.nan)
        stick_r = np.where(h.stick_radius > 0, h.stick_radius, np.nan)
        outline = [patheffects.Stroke(linewidth=2.0, foreground="k"), patheffects.Normal()]
        for sgn in (1.0, -1.0):
            bot.plot(t, sgn * contact_r, color="k", lw=0.9,
                     label="contact radius" if sgn > 0 else None)
            bot.plot(t, sgn * stick_r, color="w", lw=0.9, ls=(0, (2.5, 1.2)),
                     path_effects=outline, label="stick radius" if sgn > 0 else None)
        bot.set_ylim(-r_max, r_max)
        bot.set_xlim(0.0, 1.0)
        bot.set_xlabel(r"time $\omega t/2\pi$ (drive periods)")
    axes[0, 0].set_ylabel(r"force / $\mu_0 F_{N,0}$")
    axes[1, 0].set_ylabel(r"radius $r/a_0$")
    handles = [Patch(color=c, label=n) for c, n in zip(_COLORS, _NAMES, strict=True)]
    line_handles, line_labels = axes[1, 0].get_legend_handles_labels()
    fig.legend(handles + line_handles, _NAMES + tuple(line_labels), loc="outside lower center",
               ncol=6, fontsize=6.5, handlelength=2.0, columnspacing=1.0)
    alpha, beta, V, zeta = FIG19_POINT
    fig.suptitle(rf"Sphere ($n = 2$) by MDR, {FIG19_SPRINGS} springs, periodic orbit: "
                 rf"$\alpha$ = {alpha:g}, $\beta$ = {beta:g}, $V$ = {V:g}, undamped",
                 fontsize=7.5)
    return fig


@style.styled
def _render(_: Mapping[str, Curve]) -> Rendered:
    hs = sphere_histories()
    fig = _draw(hs)
    alpha, beta, V, zeta = FIG19_POINT
    cols: dict[str, list] = {k: [] for k in (
        "amplitude", "tau", "f", "n", "stick_radius", "contact_radius",
        "stick_area_fraction", "slip_area_fraction", "open_area_fraction")}
    checks = []
    notes = []
    for a, h in hs.items():
        T = h.tau.size
        cols["amplitude"].append(np.full(T, a))
        for k in list(cols)[1:]:
            cols[k].append(getattr(h, k))
        mu = h.impulse[-1, 0] / h.normal_impulse[-1]
        row = mdr_row(alpha, beta, a, V, 2.0, FIG19_SPRINGS, zeta)
        checks.append(Check(
            "int F_x / int F_N over the period = the periodic orbit's mu_ratio of the same "
            "row (mdr_row)", f"a = {a:g}", abs(mu - row["mu_ratio"]), "round-off",
            f"the history's row of {FIG19_SPRINGS} springs"))
        # the rows' bar counts two differences, as the MDR solver's rows do (one alone
        # can be short: 9.4e-7 off for a bar of 8.3e-7 at a = 0.5)
        rows = mdr_friction(alpha, beta, a, V, 2.0, zeta, n_springs=FIG19_SPRINGS)
        prev = mdr_friction(alpha, beta, a, V, 2.0, zeta, n_springs=FIG19_SPRINGS // 2)
        point = solve_points(alpha, beta, a, V, zeta, profile_exponent=2.0)
        bar = rows["error"] + prev["error"] + float(point["error"])
        checks.append(Check(
            f"the rows of {FIG19_SPRINGS} and {2 * FIG19_SPRINGS} springs, extrapolated = "
            "solve_points' mu_ratio (the MDR solver: the row without springs)",
            f"a = {a:g}", abs(rows["mu_ratio"] - float(point["mu_ratio"])),
            f"error bar {bar:.2g}", f"the rows' differences from {FIG19_SPRINGS // 2} "
            "springs and the solver's error"))
        law = float(theory.profile_mean_normal_force(a, 2.0))
        checks.append(Check(
            "mean normal force = theory.profile_mean_normal_force", f"a = {a:g}",
            abs(h.normal_impulse[-1] / (2.0 * math.pi) - law), "one period",
            "the row's discretisation"))
        E = h.stored_energy()
        residual = h.work_input - h.dissipated_pin - h.dissipated_friction - (E - E[0])
        checks.append(Check(
            "energy balance: work input - dissipation - stored energy change",
            f"a = {a:g}, every sample", float(np.max(np.abs(residual))),
            f"work input {h.work_input[-1]:.4f} a period", "round-off"))
        frac = [float(np.mean(x[:-1])) for x in (h.stick_area_fraction,
                                                  h.slip_area_fraction,
                                                  h.open_area_fraction)]
        centre_open = float(np.mean(h.spring_state[:-1, 0] == ContactState.FLIGHT))
        notes.append(f"a = {a:g}: mu/mu0 = {mu:.4f}, <F_N>/F_N0 = "
                     f"{h.normal_impulse[-1] / (2 * math.pi):.4f}; stick, slip, open "
                     f"{frac[0]:.3f}, {frac[1]:.3f}, {frac[2]:.3f} of the disc "
                     f"(time means); largest stick radius "
                     f"{float(np.max(h.stick_radius)):.3f} a0; the centre out of contact "
                     f"{100 * centre_open:.1f} % of the period")
    table = Table("Fig. 19: stick, slip and lift-off across a sphere", (
        f"alpha={alpha}, beta={beta}, v_inertial={V}, zeta={zeta}, profile_exponent=2, "
        f"amplitude={FIG19_AMPLITUDES}, springs={FIG19_SPRINGS}, initial state: steady "
        "(the row's periodic orbit), one drive period",
        "tau = omega t; forces in units of mu0 F_N0 (f = sum f_i, n = sum n_i); radii in "
        "units of a0; area fractions of the disc of the largest contact radius",
    ), {k: np.concatenate(v) for k, v in cols.items()})
    return Rendered(fig, (table,), tuple(checks), "; ".join(notes) + ".")


def fig19() -> Recipe:
    """Fig. 19 recipe (no solver series: it simulates its histories itself)."""
    alpha, beta, V, _ = FIG19_POINT
    return Recipe(
        name="fig19_sphere_contact",
        title="Fig. 19 (beyond the paper): stick, slip and lift-off across a sphere",
        caption=(
            "One drive period of a sphere's periodic orbit by the method of dimensionality "
            f"reduction ({FIG19_SPRINGS} springs; $(\\alpha, \\beta, V)$ = "
            f"$({alpha}, {beta}, {V})$, undamped) at $a = \\Delta d/d_0$ = 0.5 (left) "
            "and 1.5 (right, jumping). Top: $\\mu_0$ times the normal force (blue) and "
            "the friction force (green, dashed), in units of $\\mu_0 F_{N,0}$. Bottom: "
            "each ring of the contact (radius $r/a_0$, both sides of the axis) against "
            "time, coloured by its state; black: the contact radius of the imposed "
            "indentation, white dashed: the stick radius (the outermost stuck ring). "
            "In (a) the contact sticks as a whole when its slip stops (every slipping "
            "ring has the same slip velocity); a ring of reverse slip then enters from "
            "the edge (Cattaneo-Mindlin) and grows inwards, and the outer rings leave the "
            "contact while the centre holds. In (b) the whole contact opens for part of "
            "the period (the centre for 27 % of it), and the rings touching down stick."),
        series=(),
        render=_render,
    )
