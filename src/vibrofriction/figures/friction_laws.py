r"""Beyond the paper: local friction laws other than Coulomb's (docs/friction_laws.md).

* Fig. 20: ``mu/mu0`` against the velocity under a normal oscillation at one pin for
  Coulomb friction, a static coefficient above the kinetic one and two rate-and-state laws
  (velocity strengthening and weakening), each beside its steady sliding without
  oscillation, so that the reduction by the oscillation reads directly.
* Fig. 21: a normal-load modulation without loss of contact, as in Bureau, Baumberger &
  Caroli (Phys. Rev. E 62, 6810, 2000): the mean friction of a rate-and-state interface
  (with and without the Linker-Dieterich response of the state to the normal force)
  against the modulation amplitude and against the drive frequency, the Coulomb model
  beside it; a :class:`~vibrofriction.Physical` pin converted to the model at every
  frequency.
* Fig. 22: velocity weakening on a soft pin: over ``(V, amplitude)``, where the response
  locks to the drive and where it is self-excited stick-slip, against the stability of
  steady sliding without oscillation (:func:`vibrofriction.theory.sliding_is_stable`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import numpy as np
from matplotlib import colors as mcolors
from numpy.typing import NDArray

from .. import theory
from ..params import Dimensionless, Physical, RateAndState
from ..schema import STATUS_BY_CODE, Status
from ..solver import SolverSettings
from . import style
from .edges import cell_edges
from .recipe import Check, Recipe, Rendered, curve_table, max_deviation
from .series import Curve, Series, series_of_physical

__all__ = [
    "BUREAU_AMPLITUDE",
    "BUREAU_FREQUENCY_HZ",
    "BUREAU_LD",
    "BUREAU_V0",
    "LAWS",
    "LAWS_PIN",
    "WEAKENING_LAW",
    "WEAKENING_PIN",
    "WEAKENING_SETTINGS",
    "bureau_pin",
    "friction_laws",
    "load_modulation",
    "steady_mu",
    "weakening_map",
]

#: The friction-law fields of a :class:`~.series.Series` written into the tables.
_LAW_COLUMNS = ("static_ratio", "rs_a", "rs_b", "rs_d_c", "rs_v_ref", "rs_alpha_ld")


def steady_mu(series: Series, v: NDArray | float) -> NDArray[np.float64]:
    """``mu_ss(v)/mu0``: steady sliding at ``v`` without oscillation under the series' law.

    Rate-and-state friction (``rs_a > 0``): :func:`vibrofriction.theory.steady_mu_ratio`;
    Coulomb friction, with or without a static coefficient above the kinetic one: 1 (a
    sliding contact carries the kinetic force).
    """
    v = np.asarray(v, dtype=float)
    if series.rs_a > 0.0:
        return np.asarray(theory.steady_mu_ratio(v, series.rs_a, series.rs_b, series.rs_d_c,
                                                 series.rs_v_ref), dtype=float)
    return np.ones(v.shape)


def _law_columns(c: Curve) -> dict[str, NDArray]:
    s = c.series
    n = s.size
    out: dict[str, NDArray] = {k: np.full(n, float(getattr(s, k))) for k in _LAW_COLUMNS}
    out["rs_law"] = np.full(n, s.rs_law if s.rs_a > 0 else "", dtype=object)
    return out


def _status_names(c: Curve) -> NDArray[np.object_]:
    return np.array([STATUS_BY_CODE[int(t)].value for t in c.status], dtype=object)


def _finish(fig: Any, handles: list, ncol: int, title: str) -> Any:
    """The figure's legend below its panels and its title: the figure."""
    fig.legend(handles=handles, loc="outside lower center", ncol=ncol, fontsize=6,
               handlelength=2.0)
    fig.suptitle(title, fontsize=7)
    return fig


# --------------------------------------------------------------------------- Fig. 20
#: Fig. 20: the pin (a stiff system, case II, finite contact) and the normal amplitude.
LAWS_PIN: dict[str, float] = {"alpha": 5.0, "beta": 20.0, "amplitude": 0.5}
#: Fig. 20: the laws, by series key: a label, a colour and their fields (model units: ``a``,
#: ``b`` over ``mu_star = mu0``, ``d_c`` in inertial lengths, ``v_ref`` in inertial velocities).
LAWS: dict[str, tuple[str, str, dict[str, Any]]] = {
    "coulomb": ("Coulomb", "black", {}),
    "static": (r"static above kinetic, $\mu_s/\mu_0 = 1.3$", "#1f77b4",
               {"static_ratio": 1.3}),
    "rs_strengthening": ("rate-and-state, strengthening ($a > b$)", "#2ca02c",
                         {"rs_a": 0.05, "rs_b": 0.03, "rs_d_c": 1.0, "rs_v_ref": 1.0}),
    "rs_weakening": ("rate-and-state, weakening ($b > a$)", "#d62728",
                     {"rs_a": 0.03, "rs_b": 0.05, "rs_d_c": 1.0, "rs_v_ref": 1.0}),
}
_LAWS_V = (0.01, 2.0)   # inertial velocity, log-spaced
#: Fig. 20's check: the points at ``V >= _HIGH_V`` (about 6 Coulomb critical velocities).
_HIGH_V = 1.0


def _laws_vc() -> float:
    p = LAWS_PIN
    return Dimensionless(p["alpha"], p["beta"], p["amplitude"]).critical_inertial_velocity()


def _laws_series(quick: bool) -> tuple[Series, ...]:
    V = np.geomspace(*_LAWS_V, 9 if quick else 61)
    p = LAWS_PIN
    return tuple(Series(key, p["alpha"], p["beta"], p["amplitude"], V, np.full(V.size, np.nan),
                        {"law": label}, **fields)
                 for key, (label, _, fields) in LAWS.items())


@style.styled
def _draw_laws(curves: Mapping[str, Curve]):
    from matplotlib.lines import Line2D

    fig = style.figure(style.PAGE, 3.0)
    ax, ax2 = fig.subplots(1, 2)
    fine = np.geomspace(*_LAWS_V, 200)
    for key, (label, color, _) in LAWS.items():
        c = curves[key]
        V = c.v_inertial
        ss = steady_mu(c.series, V)
        ax.plot(fine, steady_mu(c.series, fine), color=color, lw=0.6, ls=(0, (4, 2)), zorder=2)
        ax.plot(V, c.trusted_mu, color=color, lw=1.1, marker="o", ms=1.8, zorder=3,
                label=label)
        style.mark_untrusted(ax, V, c, color, ms=2.5, clip=(0.0, 2.0))
        ax2.plot(V, c.trusted_mu / ss, color=color, lw=1.1, marker="o", ms=1.8, zorder=3)
    vc = _laws_vc()
    a = LAWS_PIN["amplitude"]
    for axis in (ax, ax2):
        axis.axvline(vc, color="0.5", lw=0.6, ls=":")
        axis.set_xscale("log")
        axis.set_xlim(*_LAWS_V)
        axis.set_xlabel(r"$V = v_0 m\omega/(\mu_0 F_{N,0})$")
    ax.text(vc * 1.08, 1 - a + 0.01, rf"Coulomb $V_c$ = {vc:.3g}", rotation=90, fontsize=6,
            color="0.35", va="bottom")
    ax.axhline(1 - a, color="0.6", lw=0.5, ls=":")
    ax.set_ylabel(style.MU)
    ax.set_title(r"(a) under the oscillation (solid); steady sliding without it (dashed)",
                 fontsize=7)
    ax2.axhline(1.0, color="0.6", lw=0.5, ls=":")
    ax2.set_ylabel(r"$\mu_{\mathrm{macro}}/\mu_{ss}(v_0)$")
    ax2.set_title("(b) the reduction by the oscillation", fontsize=7)
    p = LAWS_PIN
    handles, _ = ax.get_legend_handles_labels()
    handles.append(Line2D([], [], color="0.3", lw=0.6, ls=(0, (4, 2)),
                          label=r"steady sliding without oscillation, $\mu_{ss}(v_0)$"))
    return _finish(fig, handles, 3, rf"$\alpha = {p['alpha']:g}$, $\beta = {p['beta']:g}$, "
                   rf"$\Delta F_N/F_{{N,0}} = {a:g}$; rate-and-state: $d_c = 1$, "
                   r"$v_{ref} = 1$ (model units), aging law")


def _laws_checks(curves: Mapping[str, Curve]) -> list[Check]:
    checks = []
    for key, (label, _, _) in LAWS.items():
        c = curves[key]
        high = (c.v_inertial >= _HIGH_V) & c.trusted
        V = c.v_inertial[high]
        d, at = max_deviation(c.mu_ratio[high], steady_mu(c.series, V),
                              [f"V = {v:.3g}" for v in V])
        n_high = int(np.sum(c.v_inertial >= _HIGH_V))
        checks.append(Check(
            f"{label}: mu -> mu_ss(V) at high velocity (steady sliding without oscillation)",
            f"the {int(high.sum())} trusted of {n_high} points at V >= {_HIGH_V:g} "
            f"(Coulomb V_c = {_laws_vc():.3g})", d, at,
            "exact above V_c (the contact slides throughout, at the kinetic force)"
            if c.series.rs_a == 0 else
            "the slip velocity's and the state's fluctuations about V vanish as V grows"))
    return checks


def friction_laws(quick: bool = False) -> Recipe:
    """Fig. 20: mu/mu0 against V for four local friction laws at one pin."""
    p = LAWS_PIN
    params = (
        f"alpha = {p['alpha']:g}, beta = {p['beta']:g}, amplitude = {p['amplitude']:g}, "
        "zeta = eta_c = 0; initial state: steady sliding, the oscillation switched on at t = 0",
        *(f"{key}: {label}: " + (", ".join(f"{k} = {v!r}" for k, v in fields.items())
                                 or "static_ratio = 1, rs_a = 0")
          for key, (label, _, fields) in LAWS.items()),
        "rate-and-state in model units (a, b over mu_star = mu0; d_c in inertial lengths "
        "mu0 F_N0/(m omega^2); v_ref in inertial velocities), aging law",
        "steady_mu_ratio = mu_ss(v0)/mu0 of steady sliding without oscillation "
        "(theory.steady_mu_ratio; 1 for Coulomb friction); reduction = mu_ratio / "
        "steady_mu_ratio")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_laws(curves)

        def extra(c: Curve) -> dict[str, NDArray]:
            ss = steady_mu(c.series, c.v_inertial)
            return {**_law_columns(c), "steady_mu_ratio": ss, "reduction": c.mu_ratio / ss}

        table = curve_table("Fig. 20: the local friction laws under a normal oscillation",
                            curves, params, extra=extra)
        return Rendered(fig, (table,), tuple(_laws_checks(curves)), "")

    return Recipe(
        name="fig20_friction_laws",
        title="Fig. 20 (beyond the paper): local friction laws under a normal oscillation",
        caption=(
            "(a) $\\mu_{macro}/\\mu_0$ against $V = v_0 m\\omega/(\\mu_0 F_{N,0})$ (log "
            f"scale) at one pin ($\\alpha$ = {p['alpha']:g}, $\\beta$ = {p['beta']:g}, no "
            f"damping) under the normal oscillation $\\Delta F_N/F_{{N,0}}$ = "
            f"{p['amplitude']:g}, for four local laws: Coulomb ($\\mu_0$), a static "
            "coefficient 1.3 times the kinetic one, and rate-and-state friction (aging law, "
            "$d_c$ = 1 inertial length, $v_{ref}$ = 1 inertial velocity; $\\mu_0 = \\mu_*$) "
            "strengthening "
            "($a$ = 0.05, $b$ = 0.03) and weakening ($a$ = 0.03, $b$ = 0.05), $a$, $b$ over "
            "$\\mu_* = \\mu_0$. Dashed: each law's steady sliding without oscillation, "
            "$\\mu_{ss}(v_0)/\\mu_0$ (1 for both Coulomb laws). (b) The ratio of the two: "
            "the reduction by the oscillation. Dotted vertical: the Coulomb critical "
            "velocity $V_c$ (eq. 12); open circles and bars: points the solver does not "
            "trust."),
        series=_laws_series(quick), render=render, parameters=params)


# --------------------------------------------------------------------------- Fig. 21
#: Fig. 21: the sliding velocity (m/s), the frequency of the amplitude sweep (Hz), the
#: amplitude of the frequency sweep and the Linker-Dieterich coefficient (absolute).
BUREAU_V0 = 20e-6
BUREAU_FREQUENCY_HZ = 100.0
BUREAU_AMPLITUDE = 0.3
BUREAU_LD = 0.2
#: The rate-and-state law of the interface (SI: d_c in m, v_ref in m/s), mu_star = 0.5.
_BUREAU_MU = 0.5
_BUREAU_LAW = RateAndState(a=0.01, b=0.014, d_c=0.5e-6, v_ref=10e-6)
_BUREAU_F_RANGE = (0.3, 300.0)   # Hz, log-spaced
#: The three models of Fig. 21: label, colour, Linker-Dieterich alpha (None: Coulomb).
_BUREAU_MODELS: dict[str, tuple[str, str, float | None]] = {
    "coulomb": (r"Coulomb, $\mu_0 = \mu_*$", "black", None),
    "rs": (r"rate-and-state, $\alpha_{LD} = 0$", "#1f77b4", 0.0),
    "rs_ld": (rf"rate-and-state, $\alpha_{{LD}} = {BUREAU_LD:g}$", "#d62728", BUREAU_LD),
}


def bureau_pin(model: str = "rs", frequency_hz: float = BUREAU_FREQUENCY_HZ,
               amplitude: float = BUREAU_AMPLITUDE) -> Physical:
    """Fig. 21's pin in SI units with the law ``model`` (``"coulomb"``, ``"rs"``, ``"rs_ld"``).

    A 20 g pin with a natural frequency of 1 kHz and a quality factor of 20, pressed with
    10 N on a contact of normal stiffness 2e7 N/m (tangential 1.6e7 N/m), driven at
    ``frequency_hz`` with the relative normal amplitude ``amplitude``; rate-and-state
    friction ``a = 0.01``, ``b = 0.014``, ``d_c = 0.5 um``, ``v_ref = 10 um/s``, ``mu_star =
    0.5``, aging law, with the Linker-Dieterich coefficient of ``model``.
    """
    alpha_ld = _BUREAU_MODELS[model][2]
    friction = None if alpha_ld is None else replace(_BUREAU_LAW, alpha_ld=alpha_ld)
    mass, f_n, F_N0, k_zc = 0.02, 1000.0, 10.0, 2.0e7
    u_z0 = F_N0 / k_zc
    pin = Physical(mass=mass, k_x=mass * (2 * math.pi * f_n) ** 2, k_xc=k_zc / 1.25,
                   k_zc=k_zc, u_z0=u_z0, du_z=amplitude * u_z0,
                   omega=2 * math.pi * frequency_hz, mu0=_BUREAU_MU, friction=friction)
    return pin.with_damping(quality_factor=20.0)


def _bureau_grids(quick: bool) -> tuple[NDArray, NDArray]:
    amplitudes = np.linspace(0.0, 0.9, 4 if quick else 19)
    frequencies = np.geomspace(*_BUREAU_F_RANGE, 5 if quick else 31)
    return amplitudes, frequencies


def _bureau_series(quick: bool) -> tuple[Series, ...]:
    amplitudes, frequencies = _bureau_grids(quick)
    out = []
    for model in _BUREAU_MODELS:
        for a in amplitudes:
            out.append(series_of_physical(f"{model}:a={a:g}", bureau_pin(model, amplitude=a),
                                          [BUREAU_V0], sweep="amplitude", model=model,
                                          amplitude=float(a),
                                          frequency_hz=BUREAU_FREQUENCY_HZ))
        for f in frequencies:
            out.append(series_of_physical(f"{model}:f={f:.6g}", bureau_pin(model, f),
                                          [BUREAU_V0], sweep="frequency", model=model,
                                          amplitude=BUREAU_AMPLITUDE, frequency_hz=float(f)))
    return tuple(out)


def _bureau_steady() -> float:
    """``mu_ss(v0)/mu_star`` of Fig. 21's interface (the same in SI and in the model)."""
    return _BUREAU_LAW.steady_mu(BUREAU_V0, mu_star=_BUREAU_MU) / _BUREAU_MU


def _coulomb_frequency() -> float:
    """The drive frequency (Hz) at which the Coulomb model's critical velocity ``v0*`` is ``v0``.

    Below it the Coulomb contact slides throughout (``mu = mu0``); ``v0*`` grows with the
    frequency (bisection in ``ln f``).
    """
    lo, hi = math.log(1e-3), math.log(1e3)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if bureau_pin("coulomb", math.exp(mid)).critical_velocity() < BUREAU_V0:
            lo = mid
        else:
            hi = mid
    return math.exp(0.5 * (lo + hi))


def _ageing_frequency() -> float:
    """``v0/(2 pi d_c)`` in Hz: the drive frequency of one critical slip distance per second."""
    return BUREAU_V0 / (2 * math.pi * _BUREAU_LAW.d_c)


def _bureau_pick(curves: Mapping[str, Curve], model: str, sweep: str
                 ) -> tuple[NDArray, NDArray, NDArray, list[Curve]]:
    cs = [c for c in curves.values()
          if c.series.meta["model"] == model and c.series.meta["sweep"] == sweep]
    x = np.array([c.series.meta["amplitude" if sweep == "amplitude" else "frequency_hz"]
                  for c in cs])
    mu = np.array([float(c.trusted_mu[0]) for c in cs])
    order = np.argsort(x)
    return x[order], mu[order], np.array([bool(c.trusted[0]) for c in cs])[order], \
        [cs[i] for i in order]


@style.styled
def _draw_bureau(curves: Mapping[str, Curve]):
    from matplotlib.lines import Line2D

    fig = style.figure(style.PAGE, 3.0)
    ax_a, ax_f = fig.subplots(1, 2, sharey=True)
    ss = _bureau_steady()
    handles = []
    for model, (label, color, _) in _BUREAU_MODELS.items():
        for ax, sweep in ((ax_a, "amplitude"), (ax_f, "frequency")):
            x, mu, ok, cs = _bureau_pick(curves, model, sweep)
            ax.plot(x, mu, color=color, lw=1.1, marker="o", ms=2.0, zorder=3)
            bad = ~ok
            if np.any(bad):
                ax.plot(x[bad], [np.clip(float(c.mu_ratio[0]), 0, 2) if np.isfinite(
                    c.mu_ratio[0]) else np.nan for c, b in zip(cs, bad, strict=True) if b],
                    "o", ms=2.5, mfc="none", mec=color, mew=0.5, zorder=4)
        handles.append(Line2D([], [], color=color, lw=1.1, marker="o", ms=2.0, label=label))
    for ax in (ax_a, ax_f):
        ax.axhline(ss, color="#1f77b4", lw=0.6, ls=(0, (4, 2)), zorder=1)
        ax.axhline(1.0, color="0.5", lw=0.5, ls=":", zorder=1)
    ax_a.plot([0, 0.9], [1.0, 0.1], color="0.45", lw=0.7, ls=":", zorder=5)
    ax_f.axhline(1 - BUREAU_AMPLITUDE, color="0.45", lw=0.7, ls=":", zorder=5)
    ax_a.set_xlim(-0.02, 0.92)
    ax_a.set_xlabel(r"modulation amplitude $\Delta F_N/F_{N,0}$")
    ax_a.set_ylabel(r"mean friction $\langle F_x\rangle/(\mu_* \langle F_N\rangle)$")
    ax_a.set_title(f"(a) at {BUREAU_FREQUENCY_HZ:g} Hz", fontsize=7)
    ax_f.set_xscale("log")
    ax_f.set_xlim(_BUREAU_F_RANGE[0] / 1.2, _BUREAU_F_RANGE[1] * 1.2)
    fa = _ageing_frequency()
    ax_f.axvline(fa, color="0.5", lw=0.6, ls=(0, (2, 2)))
    ax_f.text(fa * 1.08, 0.32, r"$v_0/(2\pi d_c)$", fontsize=6, color="0.35", rotation=90)
    fc = _coulomb_frequency()
    ax_f.axvline(fc, color="black", lw=0.6, ls=(0, (1, 1.5)))
    ax_f.text(fc * 1.08, 0.32, r"Coulomb $v_0^* = v_0$", fontsize=6, color="black",
              rotation=90)
    ax_f.set_xlabel("drive frequency (Hz)")
    ax_f.set_title(rf"(b) at $\Delta F_N/F_{{N,0}} = {BUREAU_AMPLITUDE:g}$", fontsize=7)
    ax_a.set_ylim(0.0, 1.15)
    handles.append(Line2D([], [], color="#1f77b4", lw=0.6, ls=(0, (4, 2)),
                          label=r"rate-and-state steady sliding without modulation, "
                                r"$\mu_{ss}(v_0)/\mu_*$"))
    handles.append(Line2D([], [], color="0.45", lw=0.7, ls=":",
                          label=r"Coulomb static value $1 - \Delta F_N/F_{N,0}$ (eq. 2)"))
    return _finish(fig, handles, 2,
                   rf"normal-load modulation at $v_0$ = {BUREAU_V0 * 1e6:g} $\mu$m/s: "
                   r"$a$ = 0.01, $b$ = 0.014, $d_c$ = 0.5 $\mu$m, $v_{ref}$ = 10 $\mu$m/s, "
                   r"$\mu_*$ = 0.5; pin 1 kHz, $Q$ = 20")


def _bureau_checks(curves: Mapping[str, Curve]) -> list[Check]:
    ss = _bureau_steady()
    checks = []
    zero = [c for c in curves.values()
            if c.series.meta["sweep"] == "amplitude" and c.series.amplitude == 0.0]
    ref = np.array([1.0 if c.series.meta["model"] == "coulomb" else ss for c in zero])
    mu = np.array([float(c.mu_ratio[0]) if c.trusted[0] else np.nan for c in zero])
    d, at = max_deviation(mu, ref, [c.series.meta["model"] for c in zero])
    checks.append(Check(
        "no modulation: mu = mu_ss(v0)/mu_star (rate-and-state), 1 (Coulomb)",
        f"amplitude 0 at {BUREAU_FREQUENCY_HZ:g} Hz, the three models "
        f"({int(np.isfinite(mu).sum())} trusted of {len(zero)})", d, at,
        f"mu_ss(v0)/mu_star = {ss:.6f}; the Linker-Dieterich term needs n' != 0"))
    static = [c for c in curves.values() if c.series.meta["model"] == "coulomb"
              and c.series.meta["sweep"] == "amplitude" and c.series.amplitude > 0.0]
    ratio = max(BUREAU_V0 / bureau_pin("coulomb", amplitude=c.series.amplitude)
                .critical_velocity() for c in static)
    d, at = max_deviation(np.array([float(c.trusted_mu[0]) for c in static]),
                          np.array([1.0 - c.series.amplitude for c in static]),
                          [f"amplitude {c.series.amplitude:g}" for c in static])
    checks.append(Check(
        "Coulomb model: the static value 1 - a (eq. 2) where v0 << v0*",
        f"the amplitude sweep at {BUREAU_FREQUENCY_HZ:g} Hz, a > 0 ({len(static)} points), "
        f"v0/v0* <= {ratio:.3g}", d, at,
        "the deviation vanishes as v0/v0* -> 0"))
    return checks


def load_modulation(quick: bool = False) -> Recipe:
    """Fig. 21: the mean friction under a normal-load modulation (Bureau et al. 2000)."""
    pin = bureau_pin()
    dim = pin.to_dimensionless()
    params = (
        f"pin (SI): mass = {pin.mass:g} kg, k_x = {pin.k_x:.6g} N/m (1 kHz), c_x = "
        f"{pin.c_x:.6g} N s/m (Q = 20), k_xc = {pin.k_xc:.6g} N/m, k_zc = {pin.k_zc:.6g} N/m, "
        f"F_N0 = {pin.F_N0:g} N, mu0 = mu_star = {_BUREAU_MU:g}; v0 = {BUREAU_V0:g} m/s",
        "rate-and-state (SI): " + ", ".join(f"{k} = {getattr(_BUREAU_LAW, k):g}"
                                            for k in ("a", "b", "d_c", "v_ref"))
        + f", aging law; alpha_ld = 0 (model 'rs') or {BUREAU_LD:g} (model 'rs_ld'); model "
        "'coulomb': mu0 = mu_star, no rate-and-state",
        f"amplitude sweep at {BUREAU_FREQUENCY_HZ:g} Hz; frequency sweep at amplitude "
        f"{BUREAU_AMPLITUDE:g} over {_BUREAU_F_RANGE} Hz; each point converted with "
        "Physical.to_dimensionless() at its omega",
        f"at {BUREAU_FREQUENCY_HZ:g} Hz: alpha = {dim.alpha:.6g}, beta = {dim.beta:.6g}, "
        f"zeta = {dim.zeta:.6g}, rs_a = {dim.rs_a:.6g}, rs_b = {dim.rs_b:.6g}, rs_d_c = "
        f"{dim.rs_d_c:.6g}, rs_v_ref = {dim.rs_v_ref:.6g}",
        f"steady_mu_ratio = mu_ss(v0)/mu_star = {_bureau_steady():.8g} (1 for Coulomb); "
        "mean friction = mu_ratio = <F_x>/(mu_star <F_N>)")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_bureau(curves)
        ss = _bureau_steady()

        def x(c: Curve) -> dict[str, NDArray]:
            m = c.series.meta
            return {"model": np.array([m["model"]], dtype=object),
                    "sweep": np.array([m["sweep"]], dtype=object),
                    "frequency_hz": np.array([m["frequency_hz"]]),
                    "v0_m_per_s": np.asarray(m["v0"], dtype=float)}

        def extra(c: Curve) -> dict[str, NDArray]:
            return {**_law_columns(c), "steady_mu_ratio": np.array(
                [1.0 if c.series.rs_a == 0 else ss])}

        table = curve_table("Fig. 21: mean friction under a normal-load modulation", curves,
                            params, extra=extra, x=x)
        return Rendered(fig, (table,), tuple(_bureau_checks(curves)), "")

    return Recipe(
        name="fig21_load_modulation",
        title="Fig. 21 (beyond the paper): a normal-load modulation without loss of contact",
        caption=(
            "Mean friction $\\langle F_x\\rangle/(\\mu_*\\langle F_N\\rangle)$ of a sliding "
            f"contact ($v_0$ = {BUREAU_V0 * 1e6:g} µm/s) whose normal load is modulated "
            "without loss of contact, as in Bureau, Baumberger & Caroli (Phys. Rev. E 2000): "
            f"(a) against the modulation amplitude at {BUREAU_FREQUENCY_HZ:g} Hz, (b) against "
            f"the drive frequency at the amplitude {BUREAU_AMPLITUDE:g}. One pin (20 g, "
            "natural frequency 1 kHz, $Q$ = 20, $F_{N,0}$ = 10 N, contact stiffnesses "
            "1.6e7 and 2e7 N/m) converted to the model at every frequency; rate-and-state "
            "friction $a$ = 0.01, $b$ = 0.014, $d_c$ = 0.5 µm, $v_{ref}$ = 10 µm/s, "
            "$\\mu_*$ = 0.5, aging law, without (blue) and with (red) the Linker-Dieterich "
            f"response of the state, $\\alpha_{{LD}}$ = {BUREAU_LD:g}; black: the Coulomb "
            "model with $\\mu_0 = \\mu_*$. Dashed: rate-and-state steady sliding without "
            "modulation; dotted: the Coulomb static value $1 - \\Delta F_N/F_{N,0}$ (eq. 2) "
            "and 1; dashed vertical: $v_0/(2\\pi d_c)$, the frequency at which one period "
            "slides one $d_c$. Open circles: points the solver does not trust."),
        series=_bureau_series(quick), render=render, parameters=params)


# --------------------------------------------------------------------------- Fig. 22
#: Fig. 22: the soft pin (finite contact, no damping) and its weakening law (model units).
WEAKENING_PIN: dict[str, float] = {"alpha": 0.2, "beta": 10.0}
WEAKENING_LAW: dict[str, Any] = {"rs_a": 0.03, "rs_b": 0.05, "rs_d_c": 1.0, "rs_v_ref": 1.0,
                                 "rs_law": "aging"}
_MAP_V = (0.05, 5.0)         # inertial velocity, log-spaced
_MAP_A = (0.0, 0.9)          # normal amplitude, linear (no loss of contact)
#: Fig. 22's settings: a self-excited stick-slip's running mean settles as the inverse of
#: the periods averaged, so its mean is asked to 1e-4 (and trusted at that error) within the
#: solver's period bound; a locked orbit's error is that of Newton's method either way.
WEAKENING_SETTINGS = SolverSettings(tol_mean=1e-4, tol_trusted=1e-4)
#: The verdicts of the map (:func:`_verdict`): locked to the drive (or steady sliding),
#: self-excited, no periodic orbit and no settled mean, failed.
_LOCKED = (Status.PERIODIC, Status.SLIDING)
_VERDICTS = ("locked", "self-excited", "not settled", "failed")
_VERDICT_COLORS = ("#a6d96a", "#fdae61", "#fee08b", "0.6")
_VERDICT_NAMES = ("locked to the drive (periodic)", "self-excited, not locked (averaged)",
                  "no periodic orbit, mean not settled (not converged)", "failed")


def _map_grid(quick: bool) -> tuple[NDArray, NDArray]:
    return (np.geomspace(*_MAP_V, 5 if quick else 21),
            np.linspace(*_MAP_A, 3 if quick else 13))


def _map_series(quick: bool) -> tuple[Series, ...]:
    V, amplitudes = _map_grid(quick)
    p = WEAKENING_PIN
    return tuple(Series(f"a={a:g}", p["alpha"], p["beta"], float(a), V, np.full(V.size, np.nan),
                        {"row": i}, **WEAKENING_LAW) for i, a in enumerate(amplitudes))


def _verdict(c: Curve) -> NDArray[np.int64]:
    """The index in :data:`_VERDICTS` of each point's status.

    0 locked (periodic or continuous sliding), 1 self-excited (averaged), 2 not settled
    (not converged), 3 failed (any other status).
    """
    locked = np.isin(c.status, [s.code for s in _LOCKED])
    return np.select([locked, c.status == Status.AVERAGED.code,
                      c.status == Status.NOT_CONVERGED.code], [0, 1, 2], 3)


def _stable_at_rest(V: NDArray) -> NDArray[np.bool_]:
    """Whether steady sliding without oscillation is stable at each ``V`` (Hurwitz)."""
    p, law = WEAKENING_PIN, WEAKENING_LAW
    return np.array([theory.sliding_is_stable(p["alpha"], p["beta"], 0.0, float(v), law["rs_a"],
                                              law["rs_b"], law["rs_d_c"], law["rs_v_ref"])
                     for v in V])


def _onset_velocities() -> list[float]:
    """The velocities in the map's range where steady sliding's stability changes."""
    V = np.geomspace(*_MAP_V, 2001)
    stable = _stable_at_rest(V)
    return [float(math.sqrt(V[i] * V[i + 1])) for i in np.flatnonzero(np.diff(stable))]


def _map_fields(curves: Mapping[str, Curve], quick: bool
                ) -> tuple[NDArray, NDArray, NDArray, NDArray, NDArray]:
    V, amplitudes = _map_grid(quick)
    verdict = np.full((amplitudes.size, V.size), 3)
    mu = np.full((amplitudes.size, V.size), np.nan)
    for c in curves.values():
        i = c.series.meta["row"]
        verdict[i] = _verdict(c)
        mu[i] = np.where(c.trusted, c.mu_ratio, np.nan)
    return V, amplitudes, verdict, mu, np.asarray(theory.steady_mu_ratio(
        V, WEAKENING_LAW["rs_a"], WEAKENING_LAW["rs_b"], WEAKENING_LAW["rs_d_c"],
        WEAKENING_LAW["rs_v_ref"]))


@style.styled
def _draw_map(curves: Mapping[str, Curve], quick: bool):
    from matplotlib.artist import Artist
    from matplotlib.patches import Patch

    V, amplitudes, verdict, mu, ss = _map_fields(curves, quick)
    fig = style.figure(style.PAGE, 3.1)
    ax, ax2 = fig.subplots(1, 2, sharey=True)
    ev = cell_edges(V, log=True, name="V")
    ea = cell_edges(amplitudes, log=False, name="amplitude")
    ea[0], ea[-1] = max(ea[0], 0.0), min(ea[-1], 1.0)  # no negative amplitude, no flight
    cmap = mcolors.ListedColormap(_VERDICT_COLORS)
    ax.pcolormesh(ev, ea, verdict, cmap=cmap,
                  norm=mcolors.BoundaryNorm(np.arange(len(_VERDICTS) + 1) - 0.5, len(_VERDICTS)),
                  shading="flat", rasterized=True)
    m = ax2.pcolormesh(ev, ea, np.ma.masked_invalid(mu / ss[None, :]), shading="flat",
                       cmap="viridis", rasterized=True)
    cb = fig.colorbar(m, ax=ax2, pad=0.02, shrink=0.9)
    cb.set_label(r"$\mu_{\mathrm{macro}}/\mu_{ss}(v_0)$", fontsize=6.5)
    cb.ax.tick_params(labelsize=6)
    p = WEAKENING_PIN
    vc_unit = Dimensionless(p["alpha"], p["beta"], 1.0).critical_inertial_velocity()
    fine = np.geomspace(*_MAP_V, 100)
    onsets = _onset_velocities()
    for axis in (ax, ax2):
        # the Coulomb critical velocity V_c(a) = a V_c(1): above it a Coulomb contact slides
        axis.plot(fine, fine / vc_unit, color="black", lw=0.7, ls=(0, (3, 1.5)))
        for v in onsets:
            axis.axvline(v, color="#7b3294", lw=0.9)
        axis.set_xscale("log")
        axis.set_xlim(ev[0], ev[-1])
        axis.set_ylim(ea[0], ea[-1])
        axis.set_xlabel(r"$V = v_0 m\omega/(\mu_0 F_{N,0})$")
    stable = _stable_at_rest(fine)
    # the theory's verdict at amplitude 0: a strip just below the axis, under the first row
    strip = ax.get_xaxis_transform()
    for where, color in ((stable, "#1a9641"), (~stable, "#d7191c")):
        ax.scatter(fine[where], np.full(where.sum(), -0.025), marker="s", s=3, color=color,
                   transform=strip, clip_on=False, zorder=5)
    ax.set_ylabel(r"normal amplitude $\Delta F_N/F_{N,0}$")
    ax.set_title("(a) the response: locked to the drive or self-excited", fontsize=7)
    ax2.set_title(r"(b) mean friction over steady sliding, $\mu_{macro}/\mu_{ss}$", fontsize=7)
    from matplotlib.lines import Line2D
    handles: list[Artist] = [Patch(color=col, label=name)
                             for col, name in zip(_VERDICT_COLORS, _VERDICT_NAMES, strict=True)]
    handles += [Line2D([], [], color="#7b3294", lw=0.9,
                       label="onset of instability of steady sliding without oscillation"),
                Line2D([], [], color="#1a9641", marker="s", ls="none", ms=2.5,
                       label="steady sliding stable (amplitude 0, theory; below the axis)"),
                Line2D([], [], color="#d7191c", marker="s", ls="none", ms=2.5,
                       label="steady sliding unstable (amplitude 0, theory; below the axis)"),
                Line2D([], [], color="black", lw=0.7, ls=(0, (3, 1.5)),
                       label=r"Coulomb $V_c(a)$: continuous sliding to its right")]
    law = WEAKENING_LAW
    return _finish(fig, handles, 2,
                   rf"velocity weakening on a soft pin: $\alpha = {p['alpha']:g}$, "
                   rf"$\beta = {p['beta']:g}$, $a = {law['rs_a']:g}$, $b = {law['rs_b']:g}$, "
                   rf"$d_c = {law['rs_d_c']:g}$, $v_{{ref}} = {law['rs_v_ref']:g}$ "
                   "(model units), aging law")


def _map_checks(curves: Mapping[str, Curve], quick: bool) -> tuple[list[Check], str]:
    V, amplitudes, verdict, mu, ss = _map_fields(curves, quick)
    checks: list[Check] = []
    if amplitudes[0] != 0.0:
        return checks, ""
    stable = _stable_at_rest(V)
    row = verdict[0]
    # a claim against the theory: locked where sliding is unstable, or not locked (averaged,
    # not settled) where it is stable; a failed point claims nothing
    wrong = (stable & ((row == 1) | (row == 2))) | (~stable & (row == 0))
    failed = row == 3
    checks.append(Check(
        "amplitude 0: steady sliding (locked) where theory.sliding_is_stable, not locked "
        "(averaged or not settled) where not: the number of velocities where the solver's "
        "verdict contradicts the theory",
        f"the {V.size} velocities of the map's first row (amplitude 0)", float(wrong.sum()),
        ", ".join(f"V = {v:.3g} ({_VERDICTS[k]})" for v, k in zip(V[wrong], row[wrong],
                                                                   strict=True)) or "nowhere",
        "onset of instability at V = " + ", ".join(f"{v:.3g}" for v in _onset_velocities())
        + (f"; failed at V = {', '.join(f'{v:.3g}' for v in V[failed])}" if failed.any()
           else "")))
    keep = stable & np.isfinite(mu[0])
    d, at = max_deviation(mu[0][keep], ss[keep], [f"V = {v:.3g}" for v in V[keep]])
    checks.append(Check(
        "amplitude 0, stable steady sliding: mu = mu_ss(V)/mu_star",
        f"the {int(keep.sum())} trusted points of the first row where sliding is stable",
        d, at))
    n = [int(np.sum(verdict[1:] == k)) for k in range(len(_VERDICTS))]
    notes = ("Under the oscillation (amplitude > 0): " + ", ".join(
        f"{k} {name}" for k, name in zip(n, _VERDICTS, strict=True)) + " points.")
    return checks, notes


def weakening_map(quick: bool = False) -> Recipe:
    """Fig. 22: where the oscillation suppresses or creates stick-slip on a weakening contact."""
    p, law = WEAKENING_PIN, WEAKENING_LAW
    V, amplitudes = _map_grid(quick)
    params = (
        f"alpha = {p['alpha']:g}, beta = {p['beta']:g}, zeta = eta_c = 0; rate-and-state "
        + ", ".join(f"{k} = {v!r}" for k, v in law.items()) + " (model units)",
        f"grid: v_inertial in {_MAP_V} ({V.size} log points) x amplitude in {_MAP_A} "
        f"({amplitudes.size} points); initial state: steady sliding",
        f"solver settings: tol_mean = {WEAKENING_SETTINGS.tol_mean:g} (a self-excited "
        f"motion's mean), tol_trusted = {WEAKENING_SETTINGS.tol_trusted:g}; the others the "
        "rate-and-state solver's defaults",
        "verdict: locked = status periodic (or continuous sliding); self-excited = status "
        "averaged (no periodic orbit locked to the drive, the mean settled); not settled = "
        "status not converged (no periodic orbit within max_periods, the mean not settled); "
        "failed = any other status",
        "stable_at_rest = steady sliding without oscillation linearly stable "
        "(theory.sliding_is_stable); steady_mu_ratio = mu_ss(v0)/mu_star")

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw_map(curves, quick)
        checks, notes = _map_checks(curves, quick)

        def extra(c: Curve) -> dict[str, NDArray]:
            verdict = np.array(_VERDICTS, dtype=object)
            return {**_law_columns(c),
                    "verdict": verdict[_verdict(c)],
                    "stable_at_rest": _stable_at_rest(c.v_inertial).astype(int),
                    "steady_mu_ratio": steady_mu(c.series, c.v_inertial)}

        table = curve_table("Fig. 22: velocity weakening on a soft pin", curves, params,
                            extra=extra)
        return Rendered(fig, (table,), tuple(checks), notes)

    onsets = ", ".join(f"{v:.3g}" for v in _onset_velocities())
    return Recipe(
        name="fig22_weakening_map",
        title="Fig. 22 (beyond the paper): velocity weakening, where the oscillation "
              "suppresses and where it creates stick-slip",
        caption=(
            f"A velocity-weakening contact (rate-and-state, $a$ = {law['rs_a']:g}, $b$ = "
            f"{law['rs_b']:g} over $\\mu_*$, $d_c$ = {law['rs_d_c']:g} inertial length, "
            f"$v_{{ref}}$ = {law['rs_v_ref']:g} inertial velocity, aging law) on a soft pin "
            f"($\\alpha$ = {p['alpha']:g}, $\\beta$ = {p['beta']:g}, no damping), over the "
            "velocity $V = v_0 m\\omega/(\\mu_0 F_{N,0})$ (log) and the normal amplitude "
            "$\\Delta F_N/F_{N,0}$ (no loss of contact), started from steady sliding. (a) "
            "The solver's verdict: green, the response locks to the drive (status "
            "periodic); orange, self-excited stick-slip not locked to it (status averaged); "
            "yellow, no periodic orbit and a mean not settled within the solver's period "
            "bound (status not converged); gray, failed. Squares below the axis: at "
            "amplitude 0, the "
            "linear stability of steady sliding without oscillation "
            "(`theory.sliding_is_stable`: the characteristic quartic with the contact "
            "spring in series, Hurwitz), green stable, red "
            f"unstable; purple vertical: its onset at $V$ = {onsets}. Black dashed: the "
            "Coulomb critical velocity $V_c(a)$ (eq. 12), for reference. (b) The mean "
            "friction over steady sliding, $\\mu_{macro}/\\mu_{ss}(v_0)$, where trusted "
            "(white: not trusted). A self-excited motion's mean is asked to 1e-4 "
            "(`tol_mean`) and trusted at that error (`tol_trusted`), since its running mean "
            "settles only as the inverse of the periods averaged."),
        series=_map_series(quick), render=render, parameters=params,
        settings=WEAKENING_SETTINGS)

