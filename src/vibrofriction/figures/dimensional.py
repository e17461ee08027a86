r"""Fig. 10: the law of friction in dimensional variables, COF against ``v0`` in m/s.

One tribometer pin -- modal mass 0.01 kg on a tangential stiffness that puts its
natural frequency at 800 Hz, as in the paper's experiment -- pressed with
``F_N0 = 20 N`` on the disk through a contact with ``k_xc = k_zc/1.25`` (the
Mindlin ratio for Poisson's ratio 1/3), ``a = dF_N/F_N0 = 0.5``, ``mu0 = 0.3``.
The drive frequency (and, for the soft system, the contact) moves the point
``(alpha, beta)`` (eq. 20) through the cases of Section 3:

* 40 kHz (ultrasonic), compliant contact: stiff system, case II;
* 4.5 kHz, stiff contact (``k_xc`` = 8e8 N/m): soft system, case I
  (``alpha << 1 << beta`` needs ``k_xc >> k_x``, here 3000 times);
* 8 kHz, compliant contact: in between (near the contact resonance ``beta = 1``);
* 800 Hz, compliant contact: drive at the pin's natural frequency, case IV.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from .. import theory
from ..params import Physical
from . import style
from .checks import fig10_checks
from .recipe import Recipe, Rendered, curve_table
from .series import Curve, Series, series_of_physical

__all__ = ["CONTACTS", "PIN", "SYSTEMS", "fig10", "physical_system"]

#: The pin shared by all systems (SI units) and the amplitude ratio, force, mu0.
PIN: dict[str, float] = {
    "mass": 0.01,                                        # kg, modal mass
    "k_x": 0.01 * (2.0 * math.pi * 800.0) ** 2,          # N/m: natural frequency 800 Hz
    "F_N0": 20.0,                                        # N, mean normal force
    "a": 0.5,                                            # du_z/u_z0 = dF_N/F_N0
    "mu0": 0.3,
}
#: Normal contact stiffnesses, N/m: a compliant contact (e.g. a steel sphere of a few mm
#: radius at 20 N) and a stiff one (a large flat contact).
CONTACTS: dict[str, float] = {"compliant": 5.0e7, "stiff": 1.0e9}
#: The four systems: drive frequency (Hz), contact, colour.
SYSTEMS: dict[str, tuple[float, str, str]] = {
    "stiff (II)": (40_000.0, "compliant", "black"),
    "soft (I)": (4_500.0, "stiff", "#1f77b4"),
    "in between": (8_000.0, "compliant", "#2ca02c"),
    "resonant (IV)": (800.0, "compliant", "#d62728"),
}
_V0_RANGE = (1e-4, 3.0)  # m/s, log-spaced


def physical_system(name: str) -> Physical:
    """The :class:`Physical` system ``name`` of :data:`SYSTEMS`."""
    frequency, contact, _ = SYSTEMS[name]
    p = PIN
    k_zc = CONTACTS[contact]
    u_z0 = p["F_N0"] / k_zc
    return Physical(mass=p["mass"], k_x=p["k_x"], k_xc=k_zc / 1.25, k_zc=k_zc, u_z0=u_z0,
                    du_z=p["a"] * u_z0, omega=2.0 * math.pi * frequency, mu0=p["mu0"])


def _series(quick: bool) -> tuple[Series, ...]:
    n = 40 if quick else 240
    v0 = np.concatenate([[0.0], np.geomspace(*_V0_RANGE, n)])
    out = []
    for name, (f, _, _) in SYSTEMS.items():
        out.append(series_of_physical(name, physical_system(name), v0, frequency_hz=f))
    return tuple(out)


@style.styled
def _draw(curves: Mapping[str, Curve]):
    fig = style.figure(style.COLUMN, 2.9)
    ax = fig.add_subplot()
    mu0 = PIN["mu0"]
    a = PIN["a"]
    for name, (f, _, color) in SYSTEMS.items():
        c = curves[name]
        v0 = c.series.meta["v0"]
        m = v0 > 0
        ok = c.trusted[m]
        phys = physical_system(name)
        dim = phys.to_dimensionless()
        label = (f"{name}: {f / 1000:g} kHz, " + rf"$\alpha$={dim.alpha:.2g}, "
                 + rf"$\beta$={dim.beta:.3g}")
        ax.plot(v0[m], mu0 * np.where(ok, c.mu_ratio[m], np.nan), color=color, lw=1.1,
                label=label)
        if np.any(~ok):
            style.mark_untrusted(ax, v0[m], c, color, scale=mu0, ms=2.5, where=m)
        vstar = phys.critical_velocity()
        if math.isfinite(vstar):
            ax.plot([vstar], [mu0 * 1.035], "v", color=color, ms=4, clip_on=False)
    ax.axhline(mu0 * (1 - a), color="0.5", lw=0.6, ls=":")
    ax.axhline(mu0, color="0.5", lw=0.6, ls=":")
    ax.axhline(mu0 * float(theory.resonant_plateau_exact(a)), color="#d62728", lw=0.5,
               ls="--")
    ax.text(_V0_RANGE[0] * 1.2, mu0 * (1 - a) - 0.004, r"static: $\mu_0(1 - \Delta F_N/F_{N,0})$",
            fontsize=6, va="top", color="0.35")
    ax.text(_V0_RANGE[0] * 1.2, mu0 * float(theory.resonant_plateau_exact(a)) + 0.003,
            "case IV plateau", fontsize=6, va="bottom", color="#d62728")
    ax.set_xscale("log")
    ax.set_xlim(*_V0_RANGE)
    ax.set_ylim(mu0 * (1 - a) - 0.03, mu0 * 1.07)
    ax.set_xlabel(r"sliding velocity $v_0$ (m/s)")
    ax.set_ylabel(r"COF $\mu_{\mathrm{macro}}$ ($\mu_0 = 0.3$)")
    fig.legend(loc="outside lower center", fontsize=5.8, ncol=1, handlelength=1.8)
    return fig


def fig10(quick: bool = False) -> Recipe:
    """Fig. 10: COF against v0 (m/s) for stiff, soft, in-between and resonant systems."""
    p = PIN
    params = tuple(
        f"{name}: " + ", ".join(f"{k} = {getattr(physical_system(name), k):.6g}" for k in
                                ("mass", "k_x", "k_xc", "k_zc", "u_z0", "du_z", "omega", "mu0"))
        + f" (SI units; drive {SYSTEMS[name][0]:g} Hz)" for name in SYSTEMS) + (
        "cof = mu0 * mu_ratio; v0_m_per_s = sliding velocity",)

    def render(curves: Mapping[str, Curve]) -> Rendered:
        fig = _draw(curves)
        table = curve_table("Fig. 10: law of friction in dimensional variables", curves, params,
                            x=lambda c: {"v0_m_per_s": c.series.meta["v0"]},
                            extra=lambda c: {"cof": p["mu0"] * c.mu_ratio})
        checks, notes = fig10_checks(
            curves, {name: (SYSTEMS[name][0], physical_system(name)) for name in SYSTEMS},
            soft="soft (I)", stiff="stiff (II)")
        return Rendered(fig, (table,), tuple(checks), notes)

    return Recipe(
        name="fig10_dimensional",
        title="Fig. 10: the law of friction in dimensional variables",
        caption=("COF against the sliding velocity (log scale) for one pin (modal mass "
                 "0.01 kg, natural frequency 800 Hz) pressed with $F_{N,0}$ = 20 N, "
                 "$\\Delta F_N/F_{N,0}$ = 0.5, $\\mu_0$ = 0.3, $k_{x,c} = k_{z,c}/1.25$: "
                 "40 kHz on a compliant contact ($k_{z,c}$ = 5e7 N/m; stiff system, II), "
                 "4.5 kHz on a stiff contact ($k_{z,c}$ = 1e9 N/m; soft system, I), 8 kHz "
                 "(compliant contact; in between) and 800 Hz (compliant contact; resonant, "
                 "IV). Triangles: critical velocities of eq. (12). All curves start at the "
                 "static value; only the resonant one never reaches $\\mu_0$."),
        series=_series(quick), render=render, parameters=params)
