r"""Beyond the paper: how much the shape of the contact matters (issue 21).

The tip ``z = c r^n`` by the method of dimensionality reduction (the MDR solver,
:func:`vibrofriction.solver.mdr.mdr_friction`): flat punch (``n = inf``, the seed's
single spring), sphere (``n = 2``) and cone (``n = 1``).

* Fig. 17: ``mu/mu0`` against the velocity for flat, sphere and cone **at equal
  normal-force amplitude and equal dimensionless velocity**, in a stiff, a soft and a
  resonant system, the flat punch at ``a = 0.5`` (no jumping) and ``a = 1.5`` (jumping).
  The force of a curved tip is not harmonic, ``F/F_N0 = max(0, 1 + a cos tau)^(1 + 1/n)``,
  so at equal indentation amplitude ``a = dd/d0`` the force amplitudes differ; the
  normal-force amplitude is taken as half the peak-to-peak force over the mean force,
  ``A_F = (F_max - F_min)/(2 <F_N>)`` (:func:`force_amplitude`; ``a`` itself for a flat
  punch that does not jump), and each curved tip gets the ``a`` with the flat punch's
  ``A_F`` (:func:`equal_force_amplitude`). The velocity is in units of the mean normal
  force, ``v0 m omega/(mu0 <F_N>) = V/(<F_N>/F_N0)``, as ``mu/mu0 = <F_x>/(mu0 <F_N>)``
  is. Closed forms: the static value at ``V = 0`` (:func:`theory.profile_static_mu_ratio`)
  and, in the stiff system, the stiff law (:func:`theory.mu_ratio_stiff_profile`,
  :func:`theory.mu_ratio_stiff_flat`).
* Fig. 18: the linearised against the full sphere on one bench
  (``vf.from_bench(..., contact=Sphere(...))`` with ``contact_model="linearised"``
  and ``"mdr"``): the COF against ``v0`` in m/s at three indentation amplitudes, and the
  relative difference.

The stick/slip/lift-off picture of a sphere over one period (issue 21, item 5) is Fig. 19,
:mod:`.contact`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import brentq

from .. import theory
from ..contact import Material, Sphere
from ..params import Physical
from . import style
from .recipe import Check, Recipe, Rendered, curve_table, max_deviation
from .series import Curve, Series, series_of_physical

__all__ = [
    "BENCH",
    "BENCH_DU_Z",
    "FLAT_AMPLITUDES",
    "PROFILES",
    "SYSTEMS",
    "bench_physical",
    "equal_force_amplitude",
    "force_amplitude",
    "shape_dependence",
    "sphere_linearised",
    "stiff_law",
]

#: The systems ``(alpha, beta)``: stiff (case II, Fig. 4), soft (case I) and resonant
#: (case IV: the pin's resonance at the drive frequency); undamped.
SYSTEMS: dict[str, tuple[float, float]] = {"stiff": (0.01, 0.02), "soft": (0.01, 40.0),
                                           "resonant": (1.0, 3.0)}
#: The flat punch's indentation (= force) amplitudes: no jumping, jumping.
FLAT_AMPLITUDES: tuple[float, ...] = (0.5, 1.5)
#: ``(name, profile_exponent, colour)``.
PROFILES: tuple[tuple[str, float, str], ...] = (
    ("flat punch", math.inf, "black"), ("sphere", 2.0, "#1f77b4"), ("cone", 1.0, "#2ca02c"))
_RESONANT_XMAX = 3.0

#: Fig. 18's bench: the 3 mm steel sphere of docs/contact_geometry.md ("Using it").
_STEEL = Material(E=210e9, nu=0.3)
BENCH: dict[str, Any] = dict(natural_frequency_hz=800.0, mass=0.2, normal_load=20.0,
                                drive_frequency_hz=1000.0, mu0=0.3,
                                contact=Sphere(3e-3, _STEEL, _STEEL))
#: Its indentation amplitudes ``du_z`` (m): MDR ``a`` = 0.25, 0.51, 0.90 (linearised
#: 0.38, 0.76, 1.35: the linearised contact jumps at the last).
BENCH_DU_Z: tuple[float, ...] = (0.45e-6, 0.9e-6, 1.6e-6)


# --------------------------------------------------------------------------- amplitudes
def force_amplitude(amplitude: float, profile_exponent: float) -> float:
    """``A_F = (F_max - F_min)/(2 <F_N>)`` of the imposed indentation ``d0 (1 + a cos tau)``.

    ``F/F_N0 = max(0, 1 + a cos tau)^p``, ``p = 1 + 1/n`` (``a`` for a flat punch with ``a <= 1``).
    """
    p = 1.0 + 1.0 / profile_exponent
    a = float(amplitude)
    top, low = (1.0 + a) ** p, max(0.0, 1.0 - a) ** p
    return (top - low) / (2.0 * float(theory.profile_mean_normal_force(a, profile_exponent)))


def equal_force_amplitude(flat_amplitude: float, profile_exponent: float) -> float:
    """The indentation amplitude of the flat punch's force amplitude for a tip ``n``.

    The indentation amplitude ``a`` at which a tip of exponent ``n`` has the flat punch's
    normal-force amplitude :func:`force_amplitude` (Brent's method, to 1e-14).
    """
    if math.isinf(profile_exponent):
        return float(flat_amplitude)
    target = force_amplitude(flat_amplitude, math.inf)

    def f(a: float) -> float:
        return force_amplitude(a, profile_exponent) - target

    for lo, hi in ((1e-9, 1.0), (1.0, 50.0)):
        if f(lo) * f(hi) <= 0:
            return float(brentq(f, lo, hi, xtol=1e-14))
    raise ValueError(f"no amplitude of n = {profile_exponent} reaches A_F = {target}")


def stiff_law(v_inertial: NDArray, alpha: float, beta: float, amplitude: float,
              profile_exponent: float) -> NDArray:
    """The stiff-system law at the scaled velocities ``V``.

    ``vbar = (beta - alpha) V n/((n + 1) a)`` (``k V/a`` for the flat punch),
    docs/contact_geometry.md.
    """
    V = np.asarray(v_inertial, dtype=float)
    n = profile_exponent
    if math.isinf(n):
        return np.asarray(theory.mu_ratio_stiff_flat((beta - alpha) * V / amplitude, amplitude))
    vbar = (beta - alpha) * V * n / ((n + 1.0) * amplitude)
    return np.asarray(theory.mu_ratio_stiff_profile(vbar, amplitude, n))


# --------------------------------------------------------------------------- Fig. 17
def _key(system: str, flat_a: float, name: str) -> str:
    return f"{system},a_flat={flat_a:g},{name}"


def _xmax(system: str, flat_a: float) -> float:
    """The panel's range of ``v0 m omega/(mu0 <F_N>)``: beyond continuous sliding."""
    alpha, beta = SYSTEMS[system]
    if system == "resonant":
        return _RESONANT_XMAX
    if system == "stiff":   # continuous sliding at vbar = 1 for every profile
        vc = []
        for _, n, _ in PROFILES:
            a = equal_force_amplitude(flat_a, n)
            ratio = 1.0 if math.isinf(n) else (n + 1.0) / n
            vc.append(ratio * a / (beta - alpha)
                      / float(theory.profile_mean_normal_force(a, n)))
        return 1.2 * max(vc)
    return 2.0 * float(theory.critical_inertial_velocity(alpha, beta, flat_a))


def _shape_series(quick: bool) -> tuple[Series, ...]:
    out = []
    for system, (alpha, beta) in SYSTEMS.items():
        for flat_a in FLAT_AMPLITUDES:
            x = np.linspace(0.0, _xmax(system, flat_a), 6 if quick else 21)[1:]
            for name, n, _ in PROFILES:
                a = equal_force_amplitude(flat_a, n)
                mean = float(theory.profile_mean_normal_force(a, n))
                out.append(Series(_key(system, flat_a, name), alpha, beta, a, x * mean,
                                  np.full(x.size, np.nan),
                                  {"system": system, "flat_amplitude": flat_a,
                                   "profile": name, "v_mean": x, "mean_normal": mean},
                                  profile_exponent=n))
    return tuple(out)


@style.styled
def _draw_shape(curves: Mapping[str, Curve]):
    from matplotlib.lines import Line2D

    fig = style.figure(style.PAGE, 7.0)
    axes = fig.subplots(len(SYSTEMS), len(FLAT_AMPLITUDES), sharey=True)
    for i, (system, (alpha, beta)) in enumerate(SYSTEMS.items()):
        for j, flat_a in enumerate(FLAT_AMPLITUDES):
            ax = axes[i, j]
            for name, n, color in PROFILES:
                c = curves[_key(system, flat_a, name)]
                s = c.series
                x = np.asarray(s.meta["v_mean"])
                ax.plot(x, c.trusted_mu, "o-", color=color, lw=1.1, ms=2.2,
                        label=f"{name}, a = {s.amplitude:.3g}")
                if np.any(~c.trusted):
                    style.mark_untrusted(ax, x, c, color, ms=3.0)
                ax.plot([0.0], [float(theory.profile_static_mu_ratio(s.amplitude, n))], "D",
                        ms=4.5, mfc="none", mec=color, mew=0.8, clip_on=False)
                if system == "stiff":
                    xf = np.linspace(0.0, x[-1], 200)
                    ax.plot(xf, stiff_law(xf * s.meta["mean_normal"], alpha, beta,
                                          s.amplitude, n), color=color, lw=0.7, ls=(0, (1, 1)))
            ax.set_xlim(0.0, None)
            ax.set_ylim(-0.02, 1.05)
            ax.axhline(1.0, color="0.6", lw=0.4)
            ax.legend(loc="lower right", fontsize=6, handlelength=1.5)
            jump = "jumping flat punch" if flat_a > 1 else "no jumping"
            ax.set_title(rf"({'abcdef'[2 * i + j]}) {system}: $\alpha = {alpha:g}$, "
                         rf"$\beta = {beta:g}$; $A_F = {force_amplitude(flat_a, math.inf):.3g}$"
                         f" ({jump})", fontsize=7.5)
            if j == 0:
                ax.set_ylabel(style.MU)
            if i == len(SYSTEMS) - 1:
                ax.set_xlabel(r"$v_0\,m\omega/(\mu_0 \langle F_N\rangle)$")
    fig.legend(handles=[
        Line2D([], [], color="0.3", marker="o", ms=2.2, lw=1.1, label="MDR solver"),
        Line2D([], [], color="0.3", marker="o", ms=3, mfc="none", lw=0,
               label="not trusted (open)"),
        Line2D([], [], color="0.3", marker="D", ms=4.5, mfc="none", lw=0,
               label=r"static value $\mu(V \to 0)$ (theory)"),
        Line2D([], [], color="0.3", lw=0.7, ls=(0, (1, 1)), label="stiff law (theory)")],
        loc="outside lower center", ncol=4, fontsize=6.5)
    return fig


def _shape_checks(curves: Mapping[str, Curve]) -> tuple[list[Check], str]:
    cs = list(curves.values())
    checks = []
    vals, refs, labs = [], [], []
    for c in cs:
        s = c.series
        if s.meta["system"] != "stiff":
            continue
        ok = c.trusted & (s.v_inertial > 0)
        vals.append(c.mu_ratio[ok])
        refs.append(stiff_law(s.v_inertial[ok], s.alpha, s.beta, s.amplitude,
                              s.profile_exponent))
        labs += [f"{s.key}, V = {v:.4g}" for v in s.v_inertial[ok]]
    dev, at = max_deviation(np.concatenate(vals), np.concatenate(refs), labs)
    checks.append(Check("stiff system = stiff law (theory.mu_ratio_stiff_profile; flat: "
                        "mu_ratio_stiff_flat)", "stiff panels, trusted points, V > 0",
                        dev, at, "the distance falls like alpha (0.01 here)"))
    notes = "; ".join(
        f"A_F = {force_amplitude(fa, math.inf):.4g} (flat a = {fa:g}): "
        + ", ".join(f"{name} a = {equal_force_amplitude(fa, n):.4f}" for name, n, _ in PROFILES
                    if not math.isinf(n)) for fa in FLAT_AMPLITUDES)
    return checks, notes + "."


def shape_dependence(quick: bool = False) -> Recipe:
    """Fig. 17: flat, sphere and cone at equal normal-force amplitude, three systems."""
    params = (", ".join(f"{k}: alpha = {a}, beta = {b}" for k, (a, b) in SYSTEMS.items())
              + "; undamped",
              "profiles: " + ", ".join(f"{name} n = {n}" for name, n, _ in PROFILES)
              + "; the curved tips at the flat punch's A_F = (F_max - F_min)/(2 <F_N>), "
              f"flat a = {FLAT_AMPLITUDES}",
              "v_mean = v0 m omega/(mu0 <F_N>) = v_inertial/mean_normal (closed form); "
              "static: theory.profile_static_mu_ratio; stiff_law: theory.mu_ratio_stiff_"
              "profile (flat: mu_ratio_stiff_flat), stiff system only")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_shape(curves)

        def extra(c: Curve) -> dict[str, NDArray]:
            s = c.series
            k = s.size
            stiff = (stiff_law(s.v_inertial, s.alpha, s.beta, s.amplitude, s.profile_exponent)
                     if s.meta["system"] == "stiff" else np.full(k, np.nan))
            return {"profile_exponent": np.full(k, s.profile_exponent),
                    "flat_amplitude": np.full(k, s.meta["flat_amplitude"]),
                    "force_amplitude": np.full(k, force_amplitude(s.amplitude,
                                                                  s.profile_exponent)),
                    "mean_normal_ratio": c.mean_normal_ratio,
                    "static": np.full(k, float(theory.profile_static_mu_ratio(
                        s.amplitude, s.profile_exponent))),
                    "stiff_law": stiff}

        table = curve_table("Fig. 17: shape dependence at equal normal-force amplitude",
                            curves, params, x=lambda c: {"v_mean": c.series.meta["v_mean"]},
                            extra=extra)
        checks, notes = _shape_checks(curves)
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig17_shape",
        title="Fig. 17 (beyond the paper): how much the shape of the contact matters",
        caption=("$\\mu_{macro}/\\mu_0$ against the velocity in units of the mean normal "
                 "force, $v_0 m\\omega/(\\mu_0 \\langle F_N\\rangle)$, for a flat punch "
                 "(black), a sphere (blue) and a cone (green) by the method of "
                 "dimensionality reduction, at equal normal-force amplitude "
                 "$A_F = (F_{max} - F_{min})/(2\\langle F_N\\rangle)$: the flat punch at "
                 "$a = \\Delta d/d_0$ = 0.5 (left) and 1.5 (right, jumping), the curved tips "
                 "at the $a$ of equal $A_F$ (legend). Rows: the stiff system "
                 "(0.01, 0.02) with the stiff law (dotted), the soft system (0.01, 40) and "
                 "the resonant one (1, 3). Diamonds: the static value at $V = 0$ "
                 "(theory). At equal force amplitude the curved tips do not jump where the "
                 "flat punch does."),
        series=_shape_series(quick), render=render, parameters=params)


# --------------------------------------------------------------------------- Fig. 18
def bench_physical(du_z: float, contact_model: str) -> Physical:
    """The bench of Fig. 18 at the indentation amplitude ``du_z`` (m).

    ``contact_model`` is ``"linearised"`` or ``"mdr"``.
    """
    from ..bench import from_bench

    return from_bench(**BENCH, du_z=du_z, contact_model=contact_model)


def _bench_v0(du_z: float, quick: bool) -> NDArray:
    vc = bench_physical(du_z, "linearised").critical_velocity()
    return np.linspace(0.0, 1.5 * vc, 6 if quick else 21)[1:]


def _bench_series(quick: bool) -> tuple[Series, ...]:
    out = []
    for k, du in enumerate(BENCH_DU_Z):
        v0 = _bench_v0(du, quick)
        for model in ("linearised", "mdr"):
            out.append(series_of_physical(f"du_z={du:g},{model}", bench_physical(du, model),
                                          v0, panel=k, model=model, du_z=du))
    return tuple(out)


def _rel_diff(curves: Mapping[str, Curve], du: float) -> NDArray:
    lin, mdr = curves[f"du_z={du:g},linearised"], curves[f"du_z={du:g},mdr"]
    ok = lin.trusted & mdr.trusted & (mdr.mu_ratio > 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(ok, (lin.mu_ratio - mdr.mu_ratio) / mdr.mu_ratio, np.nan)


@style.styled
def _draw_bench(curves: Mapping[str, Curve]):
    fig = style.figure(style.PAGE, 4.4)
    axes = fig.subplots(2, len(BENCH_DU_Z), sharex="col", height_ratios=(2.0, 1.0))
    mu0 = float(BENCH["mu0"])
    colors = {"linearised": "#d62728", "mdr": "#1f77b4"}
    for k, du in enumerate(BENCH_DU_Z):
        top, bot = axes[0, k], axes[1, k]
        for model, color in colors.items():
            c = curves[f"du_z={du:g},{model}"]
            v0 = np.asarray(c.series.meta["v0"]) * 1e3
            label = ("full sphere (MDR)" if model == "mdr" else "linearised sphere") + \
                f", a = {c.series.amplitude:.3g}"
            top.plot(v0, mu0 * c.trusted_mu, "o-", color=color, ms=2.2, lw=1.1, label=label)
            if np.any(~c.trusted):
                style.mark_untrusted(top, v0, c, color, scale=mu0, ms=3.0)
            static = (theory.profile_static_mu_ratio(c.series.amplitude, 2.0) if model == "mdr"
                      else theory.static_mu_ratio(c.series.amplitude))
            top.plot([0.0], [mu0 * float(static)], "D", ms=4.5, mfc="none", mec=color,
                     mew=0.8, clip_on=False)
        v0 = np.asarray(curves[f"du_z={du:g},mdr"].series.meta["v0"]) * 1e3
        bot.plot(v0, 100 * _rel_diff(curves, du), "o-", color="0.2", ms=2.2, lw=1.0)
        for band, ls in ((1, (0, (1, 1))), (5, (0, (4, 2)))):
            bot.axhline(band, color="0.5", lw=0.6, ls=ls)
            bot.axhline(-band, color="0.5", lw=0.6, ls=ls)
        bot.axhline(0, color="0.7", lw=0.4)
        top.set_ylim(-0.01, mu0 * 1.05)
        top.axhline(mu0, color="0.6", lw=0.4)
        top.legend(loc="lower right", fontsize=6, handlelength=1.5)
        top.set_title(rf"({'abc'[k]}) $\Delta u_z$ = {du * 1e6:g} $\mu$m", fontsize=7.5)
        bot.set_xlabel(r"$v_0$ (mm/s)")
        bot.set_xlim(0.0, None)
    axes[0, 0].set_ylabel(r"COF $\mu_{\mathrm{macro}}$")
    axes[1, 0].set_ylabel("linearised - MDR\n(% of MDR)")
    fig.suptitle("3 mm steel sphere at 20 N, 1 kHz drive, pin 800 Hz / 0.2 kg, "
                 r"$\mu_0$ = 0.3; dotted $\pm$1 %, dashed $\pm$5 %; diamonds: static "
                 "values (theory)", fontsize=7)
    return fig


def sphere_linearised(quick: bool = False) -> Recipe:
    """Fig. 18: the linearised against the full (MDR) sphere on one bench."""
    params = ("bench: natural_frequency_hz = 800, mass = 0.2, normal_load = 20, "
              "drive_frequency_hz = 1000, mu0 = 0.3, contact = Sphere(3e-3, steel, steel), "
              "steel E = 210e9, nu = 0.3",
              f"du_z = {BENCH_DU_Z} m, contact_model 'linearised' and 'mdr'; "
              "cof = mu0 * mu_ratio; v0 up to 1.5 the linearised critical velocity")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_bench(curves)
        table = curve_table("Fig. 18: linearised against full sphere", curves, params,
                            x=lambda c: {"v0_m_per_s": c.series.meta["v0"]},
                            extra=lambda c: {
                                "profile_exponent": np.full(c.series.size,
                                                            c.series.profile_exponent),
                                "cof": float(BENCH["mu0"]) * c.mu_ratio})
        checks: list[Check] = []
        notes = "; ".join(
            f"du_z = {du * 1e6:g} um: |linearised - MDR|/MDR up to "
            f"{100 * np.nanmax(np.abs(_rel_diff(curves, du))):.3g} %" for du in BENCH_DU_Z)
        return Rendered(fig, (table,), tuple(checks), notes + ".")  # no closed form at v0 > 0

    return Recipe(
        name="fig18_sphere_linearised",
        title="Fig. 18 (beyond the paper): the linearised against the full sphere",
        caption=("COF against the sliding velocity for a 3 mm steel sphere at 20 N on the "
                 "bench of docs/contact_geometry.md (pin 800 Hz, 0.2 kg; drive 1 kHz; "
                 "$\\mu_0$ = 0.3) at three indentation amplitudes $\\Delta u_z$: the "
                 "linearised contact (one spring with Hertz's and Mindlin's tangent "
                 "stiffnesses at the load; red) against the full sphere by the method of "
                 "dimensionality reduction (blue). The same $\\Delta u_z$ is 3/2 times the "
                 "amplitude $a$ for the linearised contact ($u_{z,0} = 2 d_0/3$). Bottom: "
                 "their relative difference, with bands of 1 % and 5 %."),
        series=_bench_series(quick), render=render, parameters=params)
