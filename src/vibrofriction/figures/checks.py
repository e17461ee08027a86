"""Physics checks of the figures' data: pure functions from solved curves to numbers.

Each returns :class:`~.recipe.Check` records (or the numbers and sentences behind
them) for the report's table, its notes and ``deviations.csv``; nothing here draws
or imports matplotlib.  The drawing modules (:mod:`.history`, :mod:`.velocity`,
:mod:`.resonant`, :mod:`.dimensional`, :mod:`.maps`) call these from their recipes
and pass in their own constants (amplitudes, systems, grids), so every check can be
fed hand-made curves in a test.  Monotonicity, the envelope of Fig. 5 and the
checks of Fig. 10 use only the points the solver trusts (``Curve.trusted``, from
:meth:`vibrofriction.SolverSettings.trusted`); the others compare every point that has
a value.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

from .. import theory
from ..params import Dimensionless, Physical
from ..solver import Event, History, simulate
from .recipe import Check, max_deviation
from .series import Curve, status_counts

__all__ = ["closed_form", "damped_beta_series_checks", "damped_case_iv_checks",
           "damped_law_checks", "damped_onset", "fig4_checks", "fig5_checks", "fig6_checks",
           "fig6_note", "fig10_checks", "fit_soft_exponent", "history_mu_ratio", "history_note",
           "history_transitions", "jumping_note", "map_field", "map_note", "matrix_checks",
           "monotonicity", "prediction_note", "resonant_velocity_amplitude", "status_note"]


def matrix_checks(curves: Mapping[str, Curve], amplitude: float, fig: str,
                  v_max_case_iii: float) -> list[Check]:
    """Figs. 3 and 7: case III (mu = mu0), eq. (12) (mu = mu0 exactly above v0*, below
    under it), the case IV plateau at finite beta against the rigid-contact one (eq. 32)
    and the monotonicity the caption of Fig. 3 states."""
    checks = []
    if amplitude <= 1.0:
        # case III: mu = mu0 at every V > 0
        dev: list[float] = []
        at: list[str] = []
        for c in curves.values():
            if c.series.beta == 1.0:
                m = c.v_inertial > 0
                dev.extend(np.abs(c.mu_ratio[m] - 1.0))
                at.extend(f"alpha={c.series.alpha:g}, V={v:.3g}" for v in c.v_inertial[m])
        d, where = max_deviation(np.array(dev), np.zeros(len(dev)), at)
        checks.append(Check("case III: mu = mu0 for all v0 > 0", f"{fig}: beta = 1, "
                            f"a = {amplitude:g}, V in (0, {v_max_case_iii:g}]", d, where,
                            "holds exactly (continuous sliding is proven)" if d == 0.0
                            else "holds to the stated accuracy"))
        # eq. (12): mu = 1 for vbar >= 1 and mu < 1 below
        above: list[float] = []
        above_at: list[str] = []
        below_max = -np.inf
        for c in curves.values():
            if c.series.meta.get("axis") != "vbar":
                continue
            vb = c.vbar
            m = vb >= 1.0
            above.extend(np.abs(c.mu_ratio[m] - 1.0))
            above_at.extend(f"({c.series.alpha:g}, {c.series.beta:g}), vbar={v:.3g}"
                            for v in vb[m])
            sub = (vb < 1.0) & (vb > 0)
            if np.any(sub):
                below_max = max(below_max, float(np.max(c.mu_ratio[sub])))
        d, where = max_deviation(np.array(above), np.zeros(len(above)), above_at)
        top = max(float(c.vbar.max()) for c in curves.values()
                  if c.series.meta.get("axis") == "vbar")
        checks.append(Check(
            "eq. (12): mu = mu0 exactly for vbar >= 1", f"{fig}: all non-resonant panels, "
            f"a = {amplitude:g}, vbar in [1, {top:.3g}]",
            d, where, f"and max mu/mu0 below vbar = 1 is {below_max:.6f} (< 1: the critical "
            "velocity is sharp)"))
    # case IV at finite beta against the rigid-contact plateau
    plateau = float(theory.resonant_plateau_exact(amplitude))
    for c in curves.values():
        if c.series.meta.get("axis") != "plateau":
            continue
        shown = curves[c.series.key.split(":", 1)[1]]
        v_edge, mu_edge = float(shown.v_inertial[-1]), float(shown.mu_ratio[-1])
        checks.append(Check(
            "case IV plateau (exact, rigid contact) at finite beta",
            f"{fig}: alpha = 1, beta = {c.series.beta:g}, a = {amplitude:g}, "
            f"V = {c.v_inertial[-1]:g}",
            abs(float(c.mu_ratio[-1]) - plateau), f"V={c.v_inertial[-1]:g}",
            f"numerics {c.mu_ratio[-1]:.5f} vs {plateau:.5f}; at V = {v_edge:g} (panel edge) "
            f"{mu_edge:.4f}: a finite contact stiffness delays the approach, not the level"))
    worst, where = monotonicity(curves)
    checks.append(Check("Fig. 3 caption: mu/mu0 increases monotonically with vbar",
                        f"{fig}: all panels, a = {amplitude:g}", worst, where,
                        "largest decrease between successive grid points"))
    return checks


def jumping_note(curves: Mapping[str, Curve], vbar_max: float) -> str:
    """Fig. 7: where ``mu/mu0`` first reaches 1 (within 1e-9) on each panel drawn
    against ``vbar``; with loss of contact eq. (12) no longer marks that onset."""
    first = []
    for c in curves.values():
        if c.series.meta.get("axis") != "vbar":
            continue
        ones = np.flatnonzero(np.abs(c.mu_ratio - 1.0) < 1e-9)
        v = c.vbar[ones[0]] if ones.size else math.nan
        first.append(f"({c.series.alpha:g}, {c.series.beta:g}): "
                     + (f"{v:.3g}" if ones.size else f"> {vbar_max:g}"))
    return (" Jumping: eq. (12) no longer marks the onset of continuous "
            "sliding; mu/mu0 first reaches 1 at vbar = " + "; ".join(first) + ".")


def monotonicity(curves: Mapping[str, Curve]) -> tuple[float, str]:
    """Largest decrease of mu/mu0 between successive velocities over all curves."""
    worst, where = 0.0, "none"
    for c in curves.values():
        if c.series.meta.get("axis") == "plateau":
            continue
        d = -np.diff(np.where(c.trusted, c.mu_ratio, np.nan))
        if d.size and not np.all(np.isnan(d)) and np.nanmax(d) > worst:
            i = int(np.nanargmax(d))
            worst = float(d[i])
            on_vbar = not np.all(np.isnan(c.vbar))
            x = c.vbar if on_vbar else c.v_inertial
            name = "vbar" if on_vbar else "V"
            where = (f"(alpha, beta) = ({c.series.alpha:g}, {c.series.beta:g}), "
                     f"{name} = {x[i]:.3g}..{x[i + 1]:.3g}")
    return worst, where


def status_note(curves: Mapping[str, Curve]) -> str:
    """How many points ended in each status, and where the untrusted ones are."""
    counts = status_counts(curves)
    total = sum(counts.values())
    bad = {k: v for k, v in counts.items()
           if k in ("not converged", "failed")}
    text = ", ".join(f"{v} {k}" for k, v in sorted(counts.items()))
    if bad:
        where = []
        for c in curves.values():
            nbad = int(np.sum(~c.trusted))
            if nbad:
                where.append(f"({c.series.alpha:g}, {c.series.beta:g}): {nbad}")
        text += " (not trustworthy: " + "; ".join(where) + ")"
    return f"{total} points: {text}."


def fit_soft_exponent(curves: Mapping[str, Curve]) -> tuple[float, float]:
    """Least-squares exponent p of corrected eq. (27) over the soft curves; its max deviation."""
    from scipy.optimize import minimize_scalar

    soft = [c for c in curves.values() if c.series.meta.get("system") == "soft"]

    def law(c: Curve, p: float):
        return np.asarray(theory.mu_ratio_soft_corrected(c.vbar, c.series.amplitude, p))

    def cost(p: float) -> float:
        return float(np.sum(np.concatenate([c.mu_ratio - law(c, p) for c in soft]) ** 2))

    p = float(minimize_scalar(cost, bounds=(0.5, 4.0), method="bounded").x)
    dev = max(float(np.max(np.abs(c.mu_ratio - law(c, p)))) for c in soft)
    return p, dev


def closed_form(name: str, vbar, amplitude: float, *, printed: bool = False):
    """Eq. (26) for the stiff system; eq. (27) corrected (or as printed) for the soft one."""
    if name == "stiff":
        return np.asarray(theory.mu_ratio_stiff(vbar, amplitude))
    if printed:
        return np.asarray(theory.mu_ratio_soft(vbar, amplitude))
    return np.asarray(theory.mu_ratio_soft_corrected(vbar, amplitude))


def fig4_checks(curves: Mapping[str, Curve],
                systems: Mapping[str, tuple[float, float]]) -> list[Check]:
    """Fig. 4: eq. (26) on the stiff curves, eq. (27) corrected and as printed on the soft
    ones, monotonicity of the soft curves and the best-fitting exponent of eq. (27).

    ``systems`` maps ``"stiff"`` and ``"soft"`` to their ``(alpha, beta)``."""
    checks = []
    for name, printed in (("stiff", False), ("soft", False), ("soft", True)):
        al, be = systems[name]
        cs = [c for c in curves.values() if c.series.meta["system"] == name]
        refs = [closed_form(name, c.vbar, c.series.amplitude, printed=printed)
                for c in cs]
        num = np.concatenate([c.mu_ratio for c in cs])
        labels = [f"a={c.series.amplitude:g}, vbar={v:.3g}" for c in cs for v in c.vbar]
        d, at = max_deviation(num, np.concatenate(refs), labels)
        rel = max(float(np.max(np.abs(c.mu_ratio - r))) / c.series.amplitude
                  for c, r in zip(cs, refs, strict=True))
        eq = {("stiff", False): "eq. (26), stiff law",
              ("soft", False): "eq. (27) corrected: sqrt(4 pi vbar/9), p = 1.2",
              ("soft", True): "eq. (27) as printed: sqrt(4 pi/9) vbar, p = 1.2"}[
                  (name, printed)]
        remark = (f"largest deviation / a = {rel:.3f}" if not printed else
                  "the printed law is wrong: it misses the sqrt(vbar) rise "
                  "at small velocity")
        checks.append(Check(eq, f"fig04: (alpha, beta) = ({al:g}, {be:g}), a = 0.2..1, "
                            f"vbar in [0, 1.2], {len(num)} points", d, at, remark))
    worst, where = monotonicity({k: c for k, c in curves.items()
                                  if c.series.meta["system"] == "soft"})
    checks.append(Check("Fig. 3 caption: mu/mu0 increases monotonically with vbar",
                        "fig04: soft system (0.01, 400.01), a = 0.2..1", worst, where,
                        "largest decrease between successive grid points: the 'fine "
                        "structure' of the soft curves"))
    p, dev = fit_soft_exponent(curves)
    checks.append(Check("eq. (27) corrected, exponent p fitted to the numerics",
                        "fig04 soft curves", dev, f"best p = {p:.3f}",
                        "p = 1.2 (the printed '1,2') is close to the best fit"))
    return checks


def fig5_checks(curves: Mapping[str, Curve], betas_below: tuple[float, ...],
                betas_above: tuple[float, ...]) -> tuple[list[Check], list[str]]:
    """Fig. 5: corrected eq. (27) as the upper envelope above beta = 1, monotonicity, and
    (as sentences) where the plateau at mu0 begins near the resonance."""
    checks = []
    # the upper envelope of the curves above beta = 1 tends to the soft limit
    for b in betas_above[2:]:
        c = curves[f"beta={b:g}"]
        ok = c.trusted
        excess = np.where(ok, c.mu_ratio - np.asarray(
            theory.mu_ratio_soft_corrected(c.vbar, 1.0)), np.nan)
        i = int(np.nanargmax(excess))
        j = int(np.nanargmax(np.abs(excess)))
        checks.append(Check(
            "eq. (27) corrected as upper envelope (Fig. 5b): max(numerics - eq. 27)",
            f"fig05: alpha = 0.01, beta = {b:g}, a = 1, vbar in [0, 1.2]",
            float(excess[i]), f"vbar={c.vbar[i]:.3g}",
            f"max |numerics - eq. 27| = {abs(excess[j]):.3f} at vbar = {c.vbar[j]:.3g}"))
    below, below_at = monotonicity({k: c for k, c in curves.items()
                                     if c.series.beta < 1.0})
    above, above_at = monotonicity({k: c for k, c in curves.items()
                                     if c.series.beta > 1.0})
    checks.append(Check("Fig. 3 caption: mu/mu0 increases monotonically with vbar",
                        "fig05: alpha = 0.01, a = 1, beta < 1", below, below_at,
                        "largest decrease between successive grid points"))
    checks.append(Check("Fig. 3 caption: mu/mu0 increases monotonically with vbar",
                        "fig05: alpha = 0.01, a = 1, beta > 1", above, above_at,
                        "largest decrease between successive grid points: the "
                        "'oscillating curves' of Section 5"))
    # plateau width near beta = 1 (Fig. 5a, beta = 0.91, 0.99)
    plateau = []
    for b in betas_below[-3:] + betas_above[:2]:
        c = curves[f"beta={b:g}"]
        ones = np.flatnonzero(c.trusted & (c.mu_ratio > 1.0 - 1e-9))
        near = np.flatnonzero(c.trusted & (c.mu_ratio > 0.99))
        plateau.append(f"beta = {b:g}: mu/mu0 > 0.99 from vbar = "
                       + (f"{c.vbar[near[0]]:.3g}" if near.size else "-")
                       + ", = 1 from " + (f"{c.vbar[ones[0]]:.3g}" if ones.size else "-"))
    return checks, plateau


# --------------------------------------------------------------------------- Fig. 6
def resonant_velocity_amplitude(amplitude: float, v_inertial: float) -> tuple[float, float]:
    """``(Delta v, phase)`` of the fundamental of the body velocity in the case IV steady state.

    Simulates ``alpha = 1``, ``beta = inf`` from the steady state and projects the
    body velocity of the last period on ``cos tau`` and ``sin tau``.  In the paper's
    frame (substrate moving, eq. 30) the body velocity is ``Delta v cos tau``; here
    the substrate is fixed, so ``x' = V - Delta v cos tau`` and the phase is ``pi``.
    """
    h = simulate(Dimensionless(1.0, math.inf, amplitude), v_inertial=v_inertial, periods=3,
                 samples_per_period=4000, initial="steady")
    m = h.tau >= h.tau[-1] - 2.0 * math.pi
    tau, xd = h.tau[m], h.x_dot[m]
    c = float(np.trapezoid(xd * np.cos(tau), tau)) / math.pi
    s = float(np.trapezoid(xd * np.sin(tau), tau)) / math.pi
    return math.hypot(c, s), math.atan2(s, c)


def _by_amplitude(curves: Mapping[str, Curve], role: str) -> dict[float, Curve]:
    return {c.series.amplitude: c for c in curves.values() if c.series.meta.get("role") == role}


def fig6_checks(curves: Mapping[str, Curve], amplitudes: Sequence[float],
                plateau_v: float, v_max: float,
                velocity_amplitudes: Sequence[float] = (0.2, 0.5, 1.0, 1.5)) -> list[Check]:
    """Fig. 6 (case IV, ``alpha = 1``, ``beta = inf``): the plateau against ``1 - a/2`` (last
    eq. 32) and against :func:`~vibrofriction.theory.resonant_plateau` (small ``tau*``) and
    ``resonant_plateau_exact`` (exact root of the energy balance, first eq. 32); the
    distance of the drawn curves from it at their right edge ``v_max``; and ``v0/dv``
    (eq. 32) from the simulated body velocity at ``V = plateau_v``.

    ``curves`` holds the drawn curves (``meta["role"] == "curve"``) and one series per
    amplitude ending at ``V = plateau_v`` (``meta["role"] == "plateau"``).
    """
    plateau = _by_amplitude(curves, "plateau")
    shown = _by_amplitude(curves, "curve")
    checks = []
    for label, func, amps in (
            ("1 - a/2 (last eq. 32)", lambda a: 1.0 - a / 2.0,
             [a for a in amplitudes if a <= 1.0]),
            ("1 - a/2 (last eq. 32) for jumping", lambda a: 1.0 - a / 2.0,
             [a for a in amplitudes if a > 1.0]),
            ("case IV plateau, small-tau* approximation with <F_N> (theory.resonant_plateau)",
             lambda a: float(theory.resonant_plateau(a)), list(amplitudes)),
            ("case IV plateau, exact tau* (theory.resonant_plateau_exact)",
             lambda a: float(theory.resonant_plateau_exact(a)), list(amplitudes))):
        devs = [(abs(float(plateau[a].mu_ratio[-1]) - func(a)), a) for a in amps]
        d, a = max(devs)
        checks.append(Check(label, "fig06: alpha = 1, beta = inf, a = "
                            + ", ".join(f"{x:g}" for x in amps)
                            + f", mu at V = {plateau_v:g}", d, f"a={a:g}", ""))
    # approach of the plateau within the figure's range
    dev_end = max(abs(float(shown[a].mu_ratio[-1]) - float(theory.resonant_plateau_exact(a)))
                  for a in amplitudes)
    checks.append(Check("Fig. 6: curves approach the plateau", f"fig06: V = {v_max:g} "
                        "(right edge of the figure)", dev_end, "largest over amplitudes",
                        "distance from the exact plateau at the edge of the plot"))
    # eq. (32): v0/dv
    rows = []
    for a in velocity_amplitudes:
        dv, phase = resonant_velocity_amplitude(a, plateau_v)
        rows.append((a, plateau_v / dv, phase))
    for label, func in (("v0/dv, paper's approximation (eq. 32)",
                         theory.resonant_velocity_ratio),
                        ("v0/dv, exact root of the energy balance (eq. 32)",
                         theory.resonant_velocity_ratio_exact)):
        d, a = max((abs(r - float(func(a))), a) for a, r, _ in rows)
        checks.append(Check(label, "alpha = 1, beta = inf, V = "
                            f"{plateau_v:g}, a = " + ", ".join(f"{x:g}" for x in
                                                               velocity_amplitudes)
                            + "; dv = fundamental of the simulated body velocity", d,
                            f"a={a:g}",
                            "phase of the body velocity: "
                            + ", ".join(f"{math.degrees(p):.1f} deg" for _, _, p in rows)
                            + " (ansatz eq. 30: 180 deg in this frame)"))
    return checks


def fig6_note(curves: Mapping[str, Curve], amplitudes: Sequence[float],
              plateau_v: float) -> str:
    """The measured plateau at ``V = plateau_v`` against eq. (32), and the status counts."""
    plateau = _by_amplitude(curves, "plateau")
    text = "; ".join(
        f"a = {a:g}: numerics {float(plateau[a].mu_ratio[-1]):.4f}, "
        f"exact {float(theory.resonant_plateau_exact(a)):.4f}, 1 - a/2 = {1 - a / 2:.4f}"
        for a in amplitudes)
    counts = status_counts(curves)
    return (f"Plateau at V = {plateau_v:g}: {text}. Status: "
            + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())) + ".")


def prediction_note(mu0: float, u_z0: float, amplitudes_um: Sequence[float],
                    velocity_unit: float) -> str:
    """Figs. 8-9: the predicted plateau COF ``mu0 * resonant_plateau_exact(du_z/u_z0)``
    (first eq. 32) for each amplitude (micrometres), in words."""
    plateaus = ", ".join(
        f"{du:g} um: {mu0 * float(theory.resonant_plateau_exact(du * 1e-6 / u_z0)):.3f}"
        for du in amplitudes_um)
    return ("The measured data of Fig. 9 are not given in the paper's text, so they "
            "cannot be reproduced. Shown instead is the model's prediction under the "
            "assumptions listed with the figure. Predicted plateau COF (mu0 = "
            f"{mu0}): {plateaus}. The curves are flat beyond about "
            f"{10 * velocity_unit:.2g} m/s (V = 10), consistent with the paper's observation "
            "of an approximately velocity-independent COF at resonance; the plateau level "
            "depends on the unknown mean indentation u_z0 (panel b).")


# --------------------------------------------------------------------------- Fig. 10
def fig10_checks(curves: Mapping[str, Curve], systems: Mapping[str, tuple[float, Physical]],
                 soft: str, stiff: str) -> tuple[list[Check], str]:
    """Fig. 10: eq. (12) in m/s (trusted COF = mu0 at every ``v0 >= v0*``) per system, and a
    note comparing eq. (12) with the limits eq. (13) (``soft``) and eq. (14) (``stiff``).

    ``systems`` maps each curve's key to ``(drive frequency in Hz, Physical)``; each
    curve carries its velocities in m/s as ``meta["v0"]``.
    """
    lines = []
    checks = []
    for name, (f, phys) in systems.items():
        dim = phys.to_dimensionless()
        vstar = phys.critical_velocity()
        c = curves[name]
        lines.append(f"{name} ({f:g} Hz): alpha = {dim.alpha:.4g}, beta = {dim.beta:.4g}, "
                     f"case {dim.case.value}, v0* = {vstar:.4g} m/s (eq. 12)")
        if math.isfinite(vstar):
            v0 = c.series.meta["v0"]
            m = (v0 >= vstar) & c.trusted
            d = float(np.max(np.abs(c.mu_ratio[m] - 1.0))) if np.any(m) else math.nan
            checks.append(Check("eq. (12) in m/s: COF = mu0 above v0*", f"fig10: {name}, "
                                f"v0 in [{vstar:.3g}, {v0[-1]:g}] m/s", d, "",
                                f"v0* = {vstar:.4g} m/s"))
    s, t = systems[soft][1], systems[stiff][1]
    v_soft = theory.critical_velocity_soft(s.mu0, s.dF_N, s.mass, s.omega)
    v_stiff = theory.critical_velocity_stiff(t.mu0, t.omega, t.du_z, t.k_zc, t.k_xc)
    lines.append(
        f"limits: soft eq. (13) mu0 dF_N/(m omega) = {v_soft:.4g} m/s vs eq. (12) "
        f"{s.critical_velocity():.4g}; stiff eq. (14) = {v_stiff:.4g} m/s vs eq. (12) "
        f"{t.critical_velocity():.4g}")
    return checks, "; ".join(lines) + "."


# --------------------------------------------------------------------------- maps
def map_field(curves: Mapping[str, Curve], kind: str, alpha: np.ndarray, beta: np.ndarray
              ) -> tuple[np.ndarray, np.ndarray]:
    """``(mu/mu0, trusted)`` on the ``(beta, alpha)`` grid of one map (``kind`` = ``"vbar"``
    or ``"V"``), from one-point curves carrying ``meta`` ``map``, ``row`` and ``alpha``;
    nan and False where no curve lies."""
    mu = np.full((beta.size, alpha.size), np.nan)
    ok = np.zeros_like(mu, dtype=bool)
    index = {a: j for j, a in enumerate(alpha)}
    for c in curves.values():
        s = c.series
        if s.meta["map"] != kind:
            continue
        i, j = int(s.meta["row"]), index[s.meta["alpha"]]
        mu[i, j] = c.mu_ratio[0]
        ok[i, j] = bool(c.trusted[0])
    return mu, ok


def map_note(curves: Mapping[str, Curve], alpha: np.ndarray, beta: np.ndarray) -> str:
    """Untrusted points per map and the range of ``mu/mu0`` over each map (``beta > alpha``)."""
    A, B = np.meshgrid(alpha, beta)
    valid = B > A
    mu_vbar, ok_vbar = map_field(curves, "vbar", alpha, beta)
    mu_V, ok_V = map_field(curves, "V", alpha, beta)
    n = int(valid.sum())
    return (f"{n} points per map; untrusted: {int((~ok_vbar[valid]).sum())} at fixed vbar, "
            f"{int((~ok_V[valid]).sum())} at fixed V (red crosses). At fixed vbar the "
            f"map varies between {np.nanmin(mu_vbar[valid]):.3f} and "
            f"{np.nanmax(mu_vbar[valid]):.3f}; at fixed V between "
            f"{np.nanmin(mu_V[valid]):.3f} and {np.nanmax(mu_V[valid]):.3f}.")


# --------------------------------------------------------------------------- Fig. 2
def history_transitions(h: History, window: tuple[float, float]) -> list[Event]:
    """Stick/slip transitions strictly inside ``window`` (in drive periods)."""
    return [e for e in h.events if e.kind in ("slip->stick", "stick->slip")
            and window[0] < e.tau / (2.0 * math.pi) < window[1]]


def history_mu_ratio(h: History) -> float:
    """``mu/mu0`` of a sampled history: the time average of ``f`` over that of ``n`` (eq. 25,
    trapezoidal rule over the samples)."""
    return float(np.trapezoid(h.f, h.tau) / np.trapezoid(h.n, h.tau))


def history_note(h: History, point: tuple[float, float, float, float],
                 window: tuple[float, float]) -> str:
    """Fig. 2 in words: transitions in the window shown, stick fraction, ``mu/mu0``."""
    stick = float(np.mean(h.phase == "stick"))
    return (f"Steady state at (alpha, beta, a, vbar) = {point}: "
            f"{len(history_transitions(h, window))} stick/slip transitions in the "
            f"{window[1] - window[0]:g} periods shown, "
            f"stick about {100 * stick:.0f}% of the time, mu/mu0 = {history_mu_ratio(h):.4f} "
            "(time average of the sampled history).")


# --------------------------------------------------------------------------- damped figures
def damped_onset(curve: Curve, above: float = 1.02, below: float = 0.95
                 ) -> tuple[float, float, float]:
    """``(V_c, max |mu/mu0 - 1| at V >= above V_c, max mu/mu0 at 0 < V <= below V_c)``.

    ``V_c`` is the damped critical inertial velocity of the curve's own system
    (``Dimensionless.critical_inertial_velocity`` with its ``zeta`` and ``eta_c``);
    every point with a value counts; nan where no point lies in a range.
    """
    s = curve.series
    vc = Dimensionless(s.alpha, s.beta, s.amplitude, s.zeta, s.eta_c
                       ).critical_inertial_velocity()
    V, mu = s.v_inertial, curve.mu_ratio
    has = np.isfinite(mu)
    hi = has & (V >= above * vc)
    lo = has & (V > 0) & (V <= below * vc)
    d = float(np.max(np.abs(mu[hi] - 1.0))) if np.any(hi) else math.nan
    m = float(np.max(mu[lo])) if np.any(lo) else math.nan
    return vc, d, m


def _zeta_label(zeta: float) -> str:
    return f"zeta = {zeta:g} (Q = {1.0 / (2.0 * zeta):g})" if zeta > 0 else "zeta = 0"


def _damped_curve_checks(c: Curve, a: float, undamped: Curve | None, tolerance: float
                         ) -> tuple[list[Check], str]:
    """The checks of one damped case IV curve and its sentence for the note."""
    z = c.series.zeta
    vc, d, m = damped_onset(c)
    n_hi = int(np.sum(c.v_inertial >= 1.02 * vc))
    where = f"fig11: alpha = 1, beta = inf, a = {a:g}, {_zeta_label(z)}"
    checks = [
        Check("damped case IV: mu = mu0 above V_c = a/(2 zeta)",
              f"{where}, V in [{1.02 * vc:.3g}, {c.v_inertial.max():.3g}] ({n_hi} points)",
              d, f"V_c = {vc:.4g}", "continuous sliding: the friction is mu0 again"),
        Check("damped case IV: max mu/mu0 below 0.95 V_c (must be < 1)",
              f"{where}, V in (0, {0.95 * vc:.3g}]", m, f"V_c = {vc:.4g}",
              "below 1: the critical velocity is sharp" if m < 1.0 else "NOT below 1")]
    law_v = c.v_inertial[(c.v_inertial >= 0.3 * vc) & (c.v_inertial <= 0.97 * vc)]
    if law_v.size:
        sel = np.isin(c.v_inertial, law_v)
        law = np.asarray(theory.resonant_damped_mu_ratio(law_v, a, z))
        dev = np.abs(c.mu_ratio[sel] - law)
        checks.append(Check(
            "damped case IV: rise law (theory.resonant_damped_mu_ratio)",
            f"{where}, 0.3 V_c <= V <= 0.97 V_c ({law_v.size} points)", float(np.max(dev)),
            f"V = {float(law_v[np.argmax(dev)]):.3g}",
            "the energy balance of eq. (32) with the dashpot; harmonic ansatz"))
    text = f"{_zeta_label(z)}: V_c = {vc:.4g}"
    if undamped is not None:
        _, iu, ic = np.intersect1d(undamped.v_inertial, c.v_inertial, return_indices=True)
        far = np.abs(c.mu_ratio[ic] - undamped.mu_ratio[iu]) > tolerance
        if np.any(far):
            v_off = float(c.v_inertial[ic][far].min())
            text += (f", departs by more than {tolerance:g} from the undamped curve at "
                     f"V = {v_off:.3g} ({v_off / vc:.2f} V_c)")
    return checks, text


def damped_case_iv_checks(curves: Mapping[str, Curve], tolerance: float = 0.01
                          ) -> tuple[list[Check], str]:
    """Fig. 11 (case IV with pin damping ``zeta``): for each damped curve ``mu = mu0`` above
    ``1.02 V_c`` and ``mu < mu0`` below ``0.95 V_c`` (``V_c = a/(2 zeta)`` on a rigid
    contact); for the undamped one the distance from the exact plateau (first eq. 32) at
    its largest ``V``.  The note says, per damped curve, at which ``V`` it first departs
    by more than ``tolerance`` from the undamped one (compared at their common ``V``).

    The curves share one system but ``zeta`` and are told apart by ``series.zeta``.
    """
    checks = []
    undamped = [c for c in curves.values() if c.series.zeta == 0.0]
    damped = sorted((c for c in curves.values() if c.series.zeta > 0.0),
                    key=lambda c: c.series.zeta)
    a = next(iter(curves.values())).series.amplitude
    plateau = float(theory.resonant_plateau_exact(a))
    sentences = []
    for c in damped:
        more, sentence = _damped_curve_checks(c, a, undamped[0] if undamped else None,
                                              tolerance)
        checks += more
        sentences.append(sentence)
    for u in undamped:
        i = int(np.argmax(u.v_inertial))
        checks.append(Check(
            "undamped case IV: plateau, exact tau* (theory.resonant_plateau_exact)",
            f"fig11: alpha = 1, beta = inf, a = {a:g}, zeta = 0, largest V",
            abs(float(u.mu_ratio[i]) - plateau), f"V = {u.v_inertial[i]:.3g}",
            f"numerics {float(u.mu_ratio[i]):.5f} vs {plateau:.5f}: never reaches mu0"))
    note = (f"Undamped, mu/mu0 tends to the plateau {plateau:.4f} (exact tau*, eq. 32) and "
            "never reaches 1 (V_c = inf). Pin damping bounds the resonant velocity "
            "amplitude: the plateau turns into a rise that reaches mu0 exactly at "
            "V_c = a/(2 zeta). " + "; ".join(sentences) + ".")
    return checks, note


def damped_law_checks(damped: Mapping[str, Curve], undamped: Mapping[str, Curve],
                      systems: Mapping[str, tuple[Physical, Physical]], resonant: str
                      ) -> tuple[list[Check], str]:
    """Fig. 12 (Fig. 10 with a damped pin): per system, the COF equals ``mu0`` above
    ``1.02 v0*`` (damped ``v0*``, m/s) and stays below it under ``0.95 v0*``; the largest
    change of the COF by the damping on the non-resonant systems (points trusted in
    both); and at the ``resonant`` system the undamped curve's distance from the case IV
    plateau (first eq. 32) at its largest ``v0``.

    ``damped`` and ``undamped`` hold the curves by system name, ``systems`` the
    ``(undamped, damped)`` :class:`Physical` of each; every curve carries its velocities
    in m/s as ``meta["v0"]``.
    """
    checks = []
    lines = []
    for name, (plain, phys) in systems.items():
        c = damped[name]
        mu0 = phys.mu0
        vstar = phys.critical_velocity()
        _, d, m = damped_onset(c)
        v0 = c.series.meta["v0"]
        checks.append(Check(
            f"damped eq. (12) in m/s (Q = {phys.quality_factor:g}): COF = mu0 above v0*",
            f"fig12: {name}, v0 in [{1.02 * vstar:.3g}, {v0[-1]:g}] m/s", mu0 * d, "",
            f"v0* = {vstar:.4g} m/s; max COF below 0.95 v0*: {mu0 * m:.4f} "
            f"(mu0 = {mu0:g})"))
        lines.append(f"{name}: v0* = {vstar:.4g} m/s (undamped "
                     f"{plain.critical_velocity():.4g})")
    worst, where = 0.0, "none"
    for name, (_, phys) in systems.items():
        if name == resonant:
            continue
        c, u = damped[name], undamped[name]
        both = c.trusted & u.trusted
        if np.any(both):
            diff = phys.mu0 * np.abs(c.mu_ratio[both] - u.mu_ratio[both])
            i = int(np.argmax(diff))
            if diff[i] > worst:
                worst = float(diff[i])
                where = f"{name}, v0 = {c.series.meta['v0'][both][i]:.3g} m/s"
    others = [n for n in systems if n != resonant]
    checks.append(Check(
        "damping away from resonance: max |COF damped - COF undamped|",
        "fig12: " + ", ".join(others) + " (points trusted in both)", worst, where,
        "the pin's damping matters only near its resonance"))
    plain, phys = systems[resonant]
    u = undamped[resonant]
    plateau = float(theory.resonant_plateau_exact(plain.to_dimensionless().amplitude))
    i = int(np.argmax(u.series.meta["v0"]))
    vstar = phys.critical_velocity()
    checks.append(Check(
        "undamped resonant system: COF stays on the case IV plateau (exact, eq. 32)",
        f"fig12: {resonant}, undamped, v0 = {u.series.meta['v0'][i]:g} m/s (largest)",
        plain.mu0 * abs(float(u.mu_ratio[i]) - plateau), "",
        f"COF {plain.mu0 * float(u.mu_ratio[i]):.4f} vs {plain.mu0 * plateau:.4f}; "
        f"damped it reaches mu0 at v0* = {vstar:.4g} m/s"))
    note = ("Critical velocities with the damped pin: " + "; ".join(lines) + ". Only the "
            f"resonant system changes: undamped it stays on the case IV plateau "
            f"{plain.mu0 * plateau:.3f}, damped it rises to mu0 at v0* = {vstar:.3g} m/s.")
    return checks, note


def damped_beta_series_checks(curves: Mapping[str, Curve], near: float = 0.15
                              ) -> tuple[list[Check], str]:
    """Fig. 13 (Fig. 5 undamped and with a small pin damping): the number of untrusted
    points of each (how many of them did not converge), and the largest
    ``|mu_damped - mu_undamped|`` over the points trusted in both, over all ``beta`` and
    away from the contact resonance (``|beta - 1| > near``); the note lists it per ``beta``.

    The two curves of one ``beta`` share their velocities and are told apart by
    ``series.zeta`` (0 for the undamped one).
    """
    pairs: dict[float, dict[bool, Curve]] = {}
    for c in curves.values():
        pairs.setdefault(c.series.beta, {})[c.series.zeta > 0.0] = c
    zeta = max(c.series.zeta for c in curves.values())
    untrusted: dict[bool, dict[float, int]] = {False: {}, True: {}}
    unsettled = {False: 0, True: 0}
    diffs: list[tuple[float, float, float]] = []   # (|difference|, beta, vbar)
    for beta in sorted(pairs):
        for is_damped, c in pairs[beta].items():
            untrusted[is_damped][beta] = int(np.sum(~c.trusted))
            unsettled[is_damped] += int(np.sum(~c.trusted & ~c.suspicious))
        u, d = pairs[beta][False], pairs[beta][True]
        both = u.trusted & d.trusted
        if np.any(both):
            diff = np.where(both, np.abs(d.mu_ratio - u.mu_ratio), -1.0)
            i = int(np.argmax(diff))
            diffs.append((float(diff[i]), beta, float(u.vbar[i])))
    total = {k: sum(v.values()) for k, v in untrusted.items()}
    checks = []
    for is_damped, label in ((False, "undamped"), (True, f"damped, zeta = {zeta:g}")):
        where = ", ".join(f"beta = {b:g}: {n}" for b, n in untrusted[is_damped].items()
                          if n) or "none"
        remark = (f"{unsettled[is_damped]} did not converge, "
                  f"{total[is_damped] - unsettled[is_damped]} converged with too large an "
                  "error")
        if is_damped:
            remark += ("; " + ("damping removes every untrusted point of the undamped curves"
                               if total[True] == 0 else "fewer than undamped"
                               if total[True] < total[False] else "NOT fewer than undamped"))
        checks.append(Check(f"untrusted points, {label}: count",
                            f"fig13: alpha = 0.01, a = 1, {len(pairs)} betas x "
                            f"{next(iter(curves.values())).series.size} points",
                            float(total[is_damped]), where, remark))
    for label, sel in (("all beta", diffs),
                       (f"|beta - 1| > {near:g}", [x for x in diffs if abs(x[1] - 1) > near])):
        if sel:
            largest, b, v = max(sel)
            checks.append(Check(
                f"effect of small damping (zeta = {zeta:g}): max |mu_damped - mu_undamped|",
                f"fig13: {label}, points trusted in both", largest,
                f"beta = {b:g}, vbar = {v:.3g}",
                ""))
    alpha = next(iter(curves.values())).series.alpha
    note = (f"Untrusted points: undamped {total[False]} ({unsettled[False]} not converged), "
            f"damped {total[True]} ({unsettled[True]} not converged). Largest "
            "|mu_damped - mu_undamped| per beta (points trusted in both): "
            + "; ".join(f"{b:g}: {d:.2g}" for d, b, _ in diffs)
            + f". The damping term 2 zeta sqrt(alpha) = {2 * zeta * math.sqrt(alpha):.2g} is "
            "small, but not against the distance |beta - 1| from the contact resonance: "
            "there the curves change strongly (continuously in zeta).")
    return checks, note
