"""Physics checks of the figures' data: pure functions from solved curves to numbers.

Each returns :class:`~.recipe.Check` records (or the numbers and sentences behind
them) for the report's table, its notes and ``deviations.csv``; nothing here draws
or imports matplotlib.  The drawing modules (:mod:`.history`, :mod:`.velocity`,
:mod:`.resonant`, :mod:`.dimensional`, :mod:`.maps`) call these (the damped figures'
checks are :mod:`.damped_checks`) from their recipes
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

__all__ = ["closed_form", "fig4_checks", "fig5_checks", "fig6_checks", "fig6_note",
           "fig10_checks", "fit_soft_exponent", "history_mu_ratio", "history_note",
           "history_transitions", "jumping_note", "map_field", "map_note", "matrix_checks",
           "monotonicity", "prediction_note", "resonant_velocity_amplitude", "status_note"]


def matrix_checks(curves: Mapping[str, Curve], amplitude: float, fig: str,
                  v_max_case_iii: float) -> list[Check]:
    """Figs. 3 and 7: case III, eq. (12), the case IV plateau and monotonicity.

    Figs. 3 and 7: case III (mu = mu0), eq. (12) (mu = mu0 exactly above v0*, below
    under it), the case IV plateau at finite beta against the rigid-contact one (eq. 32)
    and the monotonicity the caption of Fig. 3 states.
    """
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
    """Fig. 7: where ``mu/mu0`` first reaches 1 (within 1e-9) on each panel drawn against ``vbar``.

    With loss of contact eq. (12) no longer marks that onset.
    """
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
    """Fig. 4: eqs. (26) and (27) on the stiff and soft curves, and monotonicity.

    Fig. 4: eq. (26) on the stiff curves, eq. (27) corrected and as printed on the soft
    ones, monotonicity of the soft curves and the best-fitting exponent of eq. (27).

    ``systems`` maps ``"stiff"`` and ``"soft"`` to their ``(alpha, beta)``.
    """
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
    """Fig. 5: corrected eq. (27) as the upper envelope above beta = 1, and monotonicity.

    Fig. 5: corrected eq. (27) as the upper envelope above beta = 1, monotonicity, and
    (as sentences) where the plateau at mu0 begins near the resonance.
    """
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
    """Fig. 6 (case IV, ``alpha = 1``, ``beta = inf``).

    The plateau against ``1 - a/2`` (last eq. 32) and against
    :func:`~vibrofriction.theory.resonant_plateau` (small ``tau*``) and
    ``resonant_plateau_exact`` (exact root of the energy balance, first eq. 32); the distance of
    the drawn curves from it at their right edge ``v_max``; and ``v0/dv`` (eq. 32) from the
    simulated body velocity at ``V = plateau_v``.

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
    """Figs. 8-9: the predicted plateau COF for each amplitude, in words.

    Figs. 8-9: the predicted plateau COF ``mu0 * resonant_plateau_exact(du_z/u_z0)``
    (first eq. 32) for each amplitude (micrometres), in words.
    """
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
    """Fig. 10: eq. (12) in m/s per system, and a note on its limits.

    Fig. 10: eq. (12) in m/s (trusted COF = mu0 at every ``v0 >= v0*``) per system, and a
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
    """``(mu/mu0, trusted)`` on the ``(beta, alpha)`` grid of one map.

    ``(mu/mu0, trusted)`` on the ``(beta, alpha)`` grid of one map (``kind`` = ``"vbar"``
    or ``"V"``), from one-point curves carrying ``meta`` ``map``, ``row`` and ``alpha``;
    nan and False where no curve lies.
    """
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
    """``mu/mu0`` of a sampled history.

    The time average of ``f`` over that of ``n`` (eq. 25, trapezoidal rule over the samples).
    """
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
