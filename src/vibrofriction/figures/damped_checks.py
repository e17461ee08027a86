"""Physics checks of the damped figures' data (:mod:`.damped`).

Pure functions from solved curves to :class:`~.recipe.Check` records, as :mod:`.checks` for the
paper's figures: the onset of sliding, the damped case IV law and the series over ``beta``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from .. import theory
from ..params import Dimensionless, Physical
from .recipe import Check
from .series import Curve

__all__ = ["damped_beta_series_checks", "damped_case_iv_checks", "damped_law_checks",
           "damped_onset"]


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
    """Fig. 11 (case IV with pin damping ``zeta``).

    For each damped curve ``mu = mu0`` above ``1.02 V_c`` and ``mu < mu0`` below ``0.95 V_c``
    (``V_c = a/(2 zeta)`` on a rigid contact); for the undamped one the distance from the exact
    plateau (first eq. 32) at its largest ``V``.  The note says, per damped curve, at which
    ``V`` it first departs by more than ``tolerance`` from the undamped one (compared at their
    common ``V``).

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
    """Fig. 12 (Fig. 10 with a damped pin).

    Per system, the COF equals ``mu0`` above ``1.02 v0*`` (damped ``v0*``, m/s) and stays below
    it under ``0.95 v0*``; the largest change of the COF by the damping on the non-resonant
    systems (points trusted in both); and at the ``resonant`` system the undamped curve's
    distance from the case IV plateau (first eq. 32) at its largest ``v0``.

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
    """Fig. 13 (Fig. 5 undamped and with a small pin damping).

    The number of untrusted points of each (how many of them did not converge), and the largest
    ``|mu_damped - mu_undamped|`` over the points trusted in both, over all ``beta`` and away
    from the contact resonance (``|beta - 1| > near``); the note lists it per ``beta``.

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
