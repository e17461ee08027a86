"""The fit's uncertainties (:mod:`.procedure`).

Profile-likelihood intervals (a lower chi-square met on the way is fitted from), the parameters in
physical units with their intervals and correlations, and what the data do not identify.
"""

from __future__ import annotations

import math

import lmfit
import numpy as np
from numpy.typing import NDArray

from .problem import Problem
from .search import Stages, least_squares, ln_of, local_fit

#: Correlations beyond this in modulus are reported as a warning.
STRONG_CORRELATION = 0.98
#: Relative singular value below which a direction of the Jacobian counts as flat.
FLAT = 1e-4
#: The rise of the profile chi-square (in units of ``s^2``) that bounds the reported
#: intervals: 4, two standard errors of a Gaussian (95.4 %).
PROFILE_LEVEL = 4.0
#: A profile that meets a chi-square lower than the fit's by more than this (in units of
#: ``s^2``) makes the fit start again from there and the profiles be run again; a
#: smaller drop keeps the intervals found, which hold the new level set (it lies within
#: the old one), re-centred on the new best fit.
RESTART_PROFILES = 0.5


def estimate_uncertainties(problem: Problem, out, minima, bounds, map_, stages: Stages,
                   progress: bool):
    """The profile intervals about ``out`` (:mod:`.procedure`).

    A lower chi-square met on the way is fitted from.  The fit, the minima, the distances of the
    interval ends and the lower point if the profiles met one again.
    """
    free = problem.free
    with stages.timed("profiles") as row:
        dists, lower, row["evaluations"] = _profiles(problem, out, minima, bounds, map_,
                                                     progress)
    if lower is None:
        return out, minima, dists, None
    old, old_best = out, ln_of(out, free)
    with stages.timed("local") as row:
        out, more, row["evaluations"] = local_fit(problem, [lower[1]], bounds, map_)
    minima = sorted(minima + more, key=lambda r: r[0])
    if old.chisqr - out.chisqr <= RESTART_PROFILES * _s2(problem, out):
        # the old level set holds the new one: its intervals, re-centred
        return out, minima, _recentre(dists, free, old_best, ln_of(out, free)), None
    with stages.timed("profiles") as row:
        dists, lower, row["evaluations"] = _profiles(problem, out, minima, bounds, map_,
                                                     progress)
    return out, minima, dists, lower


def _profiles(problem: Problem, out, minima, bounds, map_, progress: bool):
    """The profile-likelihood distances ``(below, above)`` in ``ln`` of each free parameter.

    The profile-likelihood distances ``(below, above)`` in ``ln`` of each free
    parameter from the best fit (:mod:`.procedure`), in parallel over parameters and
    sides, widened to reach the other local ``minima`` within the level; and the point
    of lowest chi-square a profile met, if lower than the fit's.
    """
    from tqdm.auto import tqdm

    best = ln_of(out, problem.free)
    chi = float(out.chisqr)
    level = PROFILE_LEVEL * _s2(problem, out)
    covar = out.covar
    tasks = []
    for j, n in enumerate(problem.free):
        se = out.params[n].stderr
        step = 2.2 * se if se is not None and np.isfinite(se) and se > 0 else 0.05
        slope = _conditional_slope(covar, j, len(best))
        tasks += [(problem, best, bounds, j, side, step, slope, level, chi)
                  for side in (-1.0, 1.0)]
    with tqdm(total=len(tasks), desc="fit: profile intervals", disable=not progress) as bar:
        found = []
        for r in map_(_profile_side, tasks):
            found.append(r)
            bar.update(1)
    dists = {n: (found[2 * j][0], found[2 * j + 1][0]) for j, n in enumerate(problem.free)}
    for chi_k, x in minima:  # another valley within the level widens the interval to it
        if chi_k - chi <= level:
            dists = _reach(dists, problem.free, best, x)
    lower = min((r[1] for r in found if r[1] is not None), key=lambda r: r[0], default=None)
    return dists, lower, sum(r[2] for r in found)


def _recentre(dists, free: tuple[str, ...], old: NDArray, new: NDArray):
    """Distances from ``old`` as distances from ``new``: the same intervals."""
    return {n: (max(dists[n][0] + new[j] - old[j], 0.0), max(dists[n][1] + old[j] - new[j], 0.0))
            for j, n in enumerate(free)}


def _s2(problem: Problem, out) -> float:
    """The scale ``s^2`` of the profile level.

    The reduced chi-square, at least 1 when the residuals are weighted by the measured
    ``sigma``.
    """
    return max(float(out.redchi), 1.0) if problem.weighted else float(out.redchi)


def _reach(dists, free: tuple[str, ...], best: NDArray, x: NDArray):
    """The distances ``dists`` from ``best`` widened so that each interval holds ``x``."""
    out = {}
    for j, n in enumerate(free):
        below, above = dists[n]
        out[n] = (max(below, best[j] - x[j]), max(above, x[j] - best[j]))
    return out


def _conditional_slope(covar, j: int, size: int) -> NDArray[np.float64]:
    """How the others move with parameter ``j`` along the valley, to first order.

    Column ``j`` of the covariance over its diagonal entry (zeros without a covariance).  Only a
    starting point for the profile's refits.
    """
    if covar is None or np.shape(covar) != (size, size) or not covar[j, j] > 0:
        return np.zeros(size)
    slope = np.asarray(covar[:, j], dtype=float) / covar[j, j]
    return np.where(np.isfinite(slope), slope, 0.0)


def _profile_side(task) -> tuple[float, tuple[float, NDArray] | None, int]:
    """How far parameter ``j`` can move on ``side`` before the profile chi-square rises.

    How far parameter ``j`` can move on ``side`` (in ``ln``) before the profile
    chi-square (the others refitted) has risen by ``target``: doubling steps to a
    bracket, then Brent's method; ``inf`` if it never does within the search range.
    Each refit starts from the previous one moved along ``slope`` (the valley's
    direction at the best fit); a distance already refitted is not refitted again.
    """
    from scipy.optimize import brentq

    problem, best, bounds, j, side, step, slope, target, chi_best = task
    limit = bounds[j][1] - best[j] if side > 0 else best[j] - bounds[j][0]
    state = {"x": best.copy(), "d": 0.0, "nfev": 0, "lower": None}
    rises = {0.0: 0.0}

    def rise(d: float) -> float:
        if d in rises:
            return rises[d]
        x = state["x"] + side * (d - state["d"]) * slope
        x[j] = best[j] + side * d
        lo, hi = np.array(bounds).T
        x = np.clip(x, lo, hi)
        if len(best) == 1:
            chi, state["nfev"] = problem.cost(x), state["nfev"] + 1
        else:
            out = least_squares(problem, x, bounds, hold=j)
            x, chi = ln_of(out, problem.free), float(out.chisqr)
            state["nfev"] += int(out.nfev)
        state["x"], state["d"] = x, d
        if chi < chi_best - 1e-6 * max(chi_best, 1.0) and (
                state["lower"] is None or chi < state["lower"][0]):
            state["lower"] = (chi, x)
        rises[d] = chi - chi_best
        return rises[d]

    def root(d: float) -> float:  # nearly linear in d where the profile is a parabola
        r = rise(d)
        return math.copysign(math.sqrt(abs(r)), r) - math.sqrt(target)

    inner, d = 0.0, min(step, limit)
    while root(d) <= 0.0:
        if d >= limit:
            return math.inf, state["lower"], state["nfev"]
        inner, d = d, min(2.0 * d, limit)
    d = brentq(root, inner, d, xtol=1e-5, rtol=0.03, disp=False)
    return float(d), state["lower"], state["nfev"]


def physical_params(out, free: tuple[str, ...], values: dict[str, float],
                     tied: dict[str, tuple[str, float]],
                     dists: dict[str, tuple[float, float]]):
    """The fitted parameters in physical units with their intervals and correlations.

    The fitted parameters in physical units (``values``: the system's fields and the
    free contact parameters) with their 95.4 % profile intervals and ``stderr`` half the
    interval's longer side; the correlations of the least-squares covariance.  A
    parameter tied to a free one by a constraint or a contact geometry, ``ln x = p ln y +
    const``, gets the mapped interval of its source.
    """
    params, intervals = lmfit.Parameters(), {}
    for n in [*free, *tied]:
        source, sign = tied.get(n, (n, 1.0))
        below, above = (abs(sign) * d for d in dists[source])
        if sign < 0:
            below, above = above, below
        value = values[n]
        lo = value * math.exp(-below) if math.isfinite(below) else -math.inf
        hi = value * math.exp(above) if math.isfinite(above) else math.inf
        params.add(n, value=value, vary=False)
        params[n].stderr = max(value - lo, hi - value) / 2.0
        params[n].correl = dict(out.params[n].correl or {}) if n in free else {}
        intervals[n] = (lo, hi)
    return params, intervals


def profile_warnings(free: tuple[str, ...], dists, tied, lower) -> list[str]:
    """One sentence per open side of an interval, and one for a lower minimum.

    One sentence per side of an interval the data do not close within the search
    range, and one if the fit's minimum is still not the lowest found.
    """
    out = []
    for n in free:
        for side, d in zip(("below", "above"), dists[n], strict=True):
            if not np.isfinite(d):
                also = [t for t, (src, _) in tied.items() if src == n]
                out.append(f"{n}{' (and ' + ', '.join(also) + ')' if also else ''} is not "
                           f"bounded {side} by these data within the search range: its "
                           f"profile chi-square never rises by {PROFILE_LEVEL:g} s^2")
    if lower is not None:
        out.append("a profile met a lower chi-square than the fit twice: the fit is not at "
                   "the global minimum; widen the global stage (maxiter, popsize)")
    return out


def identifiability(out, problem: Problem, ln: NDArray, bounds) -> list[str]:
    """One sentence per parameter the data do not identify.

    At a bound, in a flat direction of the Jacobian, strongly correlated with another; and one
    if the least-squares covariance is singular (no correlations).
    """
    warnings = []
    free = problem.free
    for n, x, (lo, hi) in zip(free, ln, bounds, strict=True):
        if min(x - lo, hi - x) < 1e-3:
            warnings.append(f"{n} is at the bound of its search range ({math.exp(lo):.3g} .. "
                            f"{math.exp(hi):.3g}): the data push it out; widen span or fix it")
    jac = _jacobian(problem, ln)
    if jac is not None and len(free) > 1:
        u, sv, vt = np.linalg.svd(jac, full_matrices=False)
        if sv[0] > 0:
            for k in np.flatnonzero(sv / sv[0] < FLAT):
                names = [free[j] for j in np.argsort(-np.abs(vt[k]))[:2]]
                warnings.append(
                    f"{' and '.join(names)} are not identified by these data: changing them "
                    f"together along a flat direction leaves the fit unchanged (relative "
                    f"singular value {sv[k] / sv[0]:.1e}); fix one or add data")
    for i, a in enumerate(free):
        for b in free[i + 1:]:
            r = (out.params[a].correl or {}).get(b)
            if r is not None and abs(r) > STRONG_CORRELATION:
                warnings.append(f"{a} and {b} are strongly correlated (r = {r:+.3f}): the data "
                                f"constrain a combination of them, not each")
    if out.covar is None:
        warnings.append(f"the least-squares covariance of {', '.join(free)} is singular: "
                        "no correlations (the intervals come from the profiles)")
    return warnings


def _jacobian(problem: Problem, ln: NDArray, step: float = 1e-4) -> NDArray | None:
    """Central differences of the residuals in ``ln`` (columns: free parameters).

    A curved contact's are :meth:`Problem.jacobian`'s (the MDR solver's value moves in steps of
    its error bar: a step of 1e-4 would difference those).
    """
    if problem.curved:
        jac = problem.jacobian(ln)
        return jac if np.all(np.isfinite(jac)) else None
    cols = []
    for j in range(len(ln)):
        e = np.zeros_like(ln)
        e[j] = step
        cols.append((problem.residual(ln + e) - problem.residual(ln - e)) / (2 * step))
    jac = np.array(cols).T
    return jac if np.all(np.isfinite(jac)) else None
