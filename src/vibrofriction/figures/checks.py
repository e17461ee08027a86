"""Physics checks of the figures' data: pure functions from solved curves to numbers.

Each returns :class:`~.recipe.Check` records (or the numbers behind them) for the
report's table and ``deviations.csv``; nothing here draws.  The drawing modules
(:mod:`.velocity`, ...) call these from their recipes.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from .. import theory
from .recipe import Check, max_deviation
from .series import Curve, status_counts

__all__ = ["fit_soft_exponent", "matrix_checks", "monotonicity", "status_note"]


def matrix_checks(curves: Mapping[str, Curve], amplitude: float, fig: str,
                  v_max_case_iii: float) -> list[Check]:
    """Figs. 3 and 7: case III (mu = mu0), eq. (12) (mu = mu0 exactly above v0*, below
    under it) and the case IV plateau at finite beta against the rigid-contact one."""
    checks = []
    if amplitude <= 1.0:
        # case III: mu = mu0 at every V > 0
        dev, at = [], []
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
        above, above_at, below_max = [], [], -np.inf
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
    return checks


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
