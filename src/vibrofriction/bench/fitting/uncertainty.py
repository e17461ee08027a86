"""The fit's uncertainties (:mod:`.procedure`).

Profile-likelihood intervals (a lower chi-square met on the way is fitted from), the parameters in
physical units with their intervals and correlations, and what the data do not identify.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import lmfit
import numpy as np
from numpy.typing import NDArray

from .problem import LAW_FITTABLE, Problem
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
    interval ends, the lower point if the profiles met one again, and the profiles' shape
    (:func:`_profiles`).
    """
    free = problem.free
    with stages.timed("profiles") as row:
        dists, lower, row["evaluations"], shape = _profiles(problem, out, minima, bounds, map_,
                                                            progress)
    if lower is None:
        return out, minima, dists, None, shape
    old, old_best = out, ln_of(out, free)
    with stages.timed("local") as row:
        out, more, row["evaluations"] = local_fit(problem, [lower[1]], bounds, map_)
    minima = sorted(minima + more, key=lambda r: r[0])
    new_best = ln_of(out, free)
    inside = all(old_best[j] - dists[n][0] <= new_best[j] <= old_best[j] + dists[n][1]
                 for j, n in enumerate(free))
    if inside and old.chisqr - out.chisqr <= RESTART_PROFILES * _s2(problem, out):
        # the old level set holds the new one (and its minimum): its intervals, re-centred
        return out, minima, _recentre(dists, free, old_best, ln_of(out, free)), None, shape
    with stages.timed("profiles") as row:
        dists, lower, row["evaluations"], shape = _profiles(problem, out, minima, bounds, map_,
                                                            progress)
    return out, minima, dists, lower, shape


def _profiles(problem: Problem, out, minima, bounds, map_, progress: bool):
    """The profile-likelihood distances ``(below, above)`` in ``ln`` of each free parameter.

    The profile-likelihood distances ``(below, above)`` in ``ln`` of each free
    parameter from the best fit (:mod:`.procedure`), in parallel over parameters and
    sides; from every other local minimum within the level as well, on the side away from
    the best fit (the profile of one valley cannot see across the ridge to the next); the
    point of lowest chi-square a profile met, if lower than the fit's; the profiles'
    curves and the jumps of the model they crossed.
    """
    from tqdm.auto import tqdm

    best = ln_of(out, problem.free)
    chi = float(out.chisqr)
    level = PROFILE_LEVEL * _s2(problem, out)
    covar = out.covar
    others = _other_valleys(best, chi, minima, level, bounds)
    tasks = []
    for j, n in enumerate(problem.free):
        se = out.params[n].stderr
        step = float(np.clip(2.2 * se, MIN_STEP, MAX_STEP)) if (
            se is not None and np.isfinite(se) and se > 0) else FIRST_STEP
        slope = _conditional_slope(covar, j, len(best))
        alternatives = [x for _, x in others]
        tasks += [(problem, best, best, bounds, j, side, step, slope, level, chi, alternatives)
                  for side in (-1.0, 1.0)]
        for _, x in others:  # the far side of another valley, measured from the best fit
            side = 1.0 if x[j] >= best[j] else -1.0
            tasks.append((problem, x, best, bounds, j, side, step, slope, level, chi,
                          [best]))
    with tqdm(total=len(tasks), desc="fit: profile intervals", disable=not progress) as bar:
        found = []
        for r in map_(_profile_side, tasks):
            found.append(r)
            bar.update(1)
    dists = {n: [0.0, 0.0] for n in problem.free}
    curves: dict[str, list[tuple[float, float]]] = {n: [] for n in problem.free}
    jumps: dict[str, list[float]] = {n: [] for n in problem.free}
    for task, r in zip(tasks, found, strict=True):
        centre, j, side = task[1], task[4], task[5]
        n = problem.free[j]
        reach = side * (centre[j] - best[j]) + r.distance
        k = 0 if side < 0 else 1
        dists[n][k] = max(dists[n][k], reach)
        curves[n] += [(float(centre[j] + side * d), float(c)) for d, c in r.curve]
        jumps[n] += [float(centre[j] + side * d) for d in r.jumps]
    dists_t = {n: (d[0], d[1]) for n, d in dists.items()}
    for chi_k, x in minima:  # another valley within the level widens the interval to it
        if chi_k - chi <= level:
            dists_t = _reach(dists_t, problem.free, best, x)
    lower = min((r.lower for r in found if r.lower is not None), key=lambda r: r[0],
                default=None)
    shape = {"curves": {n: sorted(set(c)) for n, c in curves.items()},
             "jumps": {n: sorted(set(v)) for n, v in jumps.items()}, "level": level,
             "chisqr": chi, "best": {n: float(best[j]) for j, n in enumerate(problem.free)}}
    return dists_t, lower, sum(r.nfev for r in found), shape


#: At most this many other local minima within the level are profiled (the lowest).
OTHER_VALLEYS = 1


def _other_valleys(best: NDArray, chi: float, minima, level: float, bounds):
    """The local minima within ``level`` of ``chi`` that are distinct from ``best``."""
    lo, hi = np.array(bounds, dtype=float).T
    width = np.where(hi > lo, hi - lo, 1.0)
    out: list[tuple[float, NDArray]] = []
    for chi_k, x in minima:
        if chi_k - chi > level:
            continue
        if all(np.max(np.abs(x - y) / width) > 0.02 for y in [best, *(o[1] for o in out)]):
            out.append((chi_k, np.asarray(x, dtype=float)))
        if len(out) == OTHER_VALLEYS:
            break
    return out


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


@dataclass
class _Side:
    """One side of a profile: its distance, the lowest point met, its evaluations, its curve.

    ``curve``: ``(distance, chi-square)`` of every refit; ``jumps``: the distances where
    the profile chi-square jumps (the model's discontinuities: a row's stick-slip pattern,
    contact loss or status changes) by more than the level between refits closer than
    :data:`JUMP_WIDTH`.
    """

    distance: float
    lower: tuple[float, NDArray] | None
    nfev: int
    curve: list[tuple[float, float]]
    jumps: list[float]


#: The first step of a profile (``ln``) without a standard error, and the clip of
#: ``2.2 stderr`` otherwise: a (nearly) singular covariance gives a standard error of
#: 1e-14 that is no scale of the profile.
FIRST_STEP = 0.05
MIN_STEP = 2e-3
MAX_STEP = 0.3
#: After the profile first rises past the level faster than a parabola, it looks this
#: many doublings further (within the search range; one after a parabola's rise) for a
#: point back below it: past a jump of the model or a ridge, the profile may come down
#: again.
LOOKAHEAD = 2
#: The relative precision of an interval's end (Brent's method on the profile).
BRENT_RTOL = 0.05
#: A bracket narrower than this (in ``ln``, plus a tenth of its distance) across which the
#: profile rises by more than the level is a jump of the model, not a slope (a parabola
#: rises by a fifth of the level there).
JUMP_WIDTH = 1e-3


def _profile_side(task) -> _Side:
    """How far parameter ``j`` can move on ``side`` before the profile chi-square rises.

    How far parameter ``j`` can move on ``side`` (in ``ln``) from ``centre`` before the
    profile chi-square (the others refitted) exceeds the best fit's by ``target``:
    doubling steps to a bracket, :data:`LOOKAHEAD` more to see whether it comes down again,
    then Brent's method; ``inf`` if it never rises within the search range.  Each refit
    starts from the refit next to it on the centre's side, moved along ``slope`` (the
    valley's direction at the best fit); one that lands above the level is repeated from
    the refit next to it on the far side (a refit from either side can stop in a kink's
    dip that the other passes); where a
    refit of the doubling steps rises steeply above the level it is repeated from the
    ``alternatives`` (the best fit, the other valleys) with the parameter held, and the
    lowest wins: a refit that cannot descend across a jump of the model does not end the
    interval.
    """
    from scipy.optimize import brentq

    (problem, centre, best, bounds, j, side, step, slope, target, chi_best,
     alternatives) = task
    limit = bounds[j][1] - centre[j] if side > 0 else centre[j] - bounds[j][0]
    spent = [0]
    lowest: list[tuple[float, NDArray]] = []  # the lowest point met below the best fit
    rises = {0.0: 0.0 if np.array_equal(centre, best) else float(problem.cost(centre)) - chi_best}
    points = {0.0: centre.copy()}  # the refit at each distance
    lo, hi = np.array(bounds).T

    def refit(x0: NDArray, budget: float = 1.0) -> tuple[NDArray, float]:
        x0 = np.clip(x0, lo, hi)
        if len(centre) == 1:
            spent[0] += 1
            return x0, problem.cost(x0)
        out = least_squares(problem, x0, bounds, hold=j, budget_factor=budget)
        spent[0] += int(out.nfev)
        return ln_of(out, problem.free), float(out.chisqr)

    def steep(d: float, r: float) -> bool:
        """A rise past the level faster than a parabola's from the refit inside ``d``."""
        inner = max(k for k in rises if k < d)
        return r > target + max(rises[inner], 0.0) * (d / inner if inner > 0 else 1.0) ** 2

    def rise(d: float, explore: bool = False, budget: float = 1.0) -> float:
        if d in rises:
            return rises[d]
        held = centre[j] + side * d
        inner = max(k for k in points if k < d)  # the refit on the way from the centre
        x = points[inner] + side * (d - inner) * slope
        x[j] = held
        x, chi = refit(x, budget)
        outer = [k for k in points if k > d]
        if chi - chi_best > target and outer:  # above the level: also from the far side
            k = min(outer)
            y0 = points[k] - side * (k - d) * slope
            y0[j] = held
            y, c = refit(y0, budget)
            if c < chi:
                x, chi = y, c
        if explore and steep(d, chi - chi_best):  # another start, across what stopped it
            for alt in alternatives + [centre]:
                y0 = np.array(alt, dtype=float)
                y0[j] = held
                y, c = refit(y0)
                if c < chi:
                    x, chi = y, c
        points[d] = x
        if chi < chi_best - 1e-6 * max(chi_best, 1.0) and (not lowest or chi < lowest[0][0]):
            lowest[:] = [(chi, x)]
        rises[d] = chi - chi_best
        return rises[d]

    def root(d: float, explore: bool = False, budget: float = 1.0) -> float:
        r = rise(d, explore, budget)  # root: ~linear in d on a parabola
        return math.copysign(math.sqrt(abs(r)), r) - math.sqrt(target)

    def done(distance: float, jumps: list[float]) -> _Side:
        curve = sorted((d, chi_best + r) for d, r in rises.items())
        return _Side(distance, lowest[0] if lowest else None, spent[0], curve, jumps)

    inner, d = 0.0, min(step, limit)
    while True:
        while root(d, explore=True) <= 0.0:
            if d >= limit:
                return done(math.inf, [])
            inner, d = d, min(2.0 * d, limit)
        # does the profile come down again further out? Two doublings past a steep rise,
        # one past a parabola's, each refit on half the budget (it need only come down)
        ahead, back = d, None
        for _ in range(LOOKAHEAD if steep(d, rises[d]) else 1):
            if ahead >= limit:
                break
            ahead = min(2.0 * ahead, limit)
            if root(ahead, explore=True, budget=0.5) <= 0.0:
                back = ahead
                break
        if back is None:
            break
        inner, d = back, min(2.0 * back, limit)
        if inner >= limit:
            return done(math.inf, [])
    end = float(brentq(root, inner, d, xtol=1e-5, rtol=BRENT_RTOL, disp=False))
    # a bracket that closed on a jump: the far side's refits (from every start) decide
    near = [x for x in rises if x <= end]
    far = [x for x in rises if x > end]
    jumps = []
    if near and far and min(far) - max(near) < JUMP_WIDTH + 0.1 * end and (
            rises[min(far)] - rises[max(near)] > target):
        jumps.append(end)
    return done(end, jumps)


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
                   "the global minimum; widen the global search (starts, screen)")
    return out


def pinned(free: tuple[str, ...], ln: NDArray, bounds) -> list[str]:
    """The free parameters the fit leaves at a bound of their search range (within 1e-3)."""
    return [n for n, x, (lo, hi) in zip(free, ln, bounds, strict=True)
            if min(x - lo, hi - x) < 1e-3]


def identifiability(out, problem: Problem, ln: NDArray, bounds,
                    jac: NDArray | None = None) -> list[str]:
    """One sentence per parameter the data do not identify.

    At a bound, in a flat direction of the Jacobian (``jac``: :func:`jacobian_at`, computed
    when not given), strongly correlated with another; and one if the least-squares
    covariance is singular (no correlations).
    """
    warnings = []
    free = problem.free
    for n in pinned(free, ln, bounds):
        lo, hi = bounds[free.index(n)]
        what = "mu_static/mu0 " if n == "mu_static" else ""  # its coordinate is the ratio's
        warnings.append(f"{n} is at the bound of its search range ({what}{math.exp(lo):.3g} .. "
                        f"{math.exp(hi):.3g}): the data push it out; widen span or fix it")
    jac = jacobian_at(problem, ln) if jac is None else jac
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


def jacobian_at(problem: Problem, ln: NDArray, step: float = 1e-4) -> NDArray | None:
    """Central differences of the residuals in ``ln`` (columns: free parameters).

    A curved contact's and rate-and-state friction's are :meth:`Problem.jacobian`'s (the MDR
    solver's value moves in steps of its error bar: a step of 1e-4 would difference those; the
    rate-and-state solver's error, ~1e-7, wants a longer step than 1e-4 too).
    """
    if problem.differenced:
        jac = problem.jacobian(ln)
        return jac if np.all(np.isfinite(jac)) else None
    cols = []
    for j in range(len(ln)):
        e = np.zeros_like(ln)
        e[j] = step
        cols.append((problem.residual(ln + e) - problem.residual(ln - e)) / (2 * step))
    jac = np.array(cols).T
    return jac if np.all(np.isfinite(jac)) else None


#: A direction of the Jacobian whose relative singular value is below this is weak: a
#: parameter that the profiles leave open is reported with the combination along it that
#: the data do hold.
WEAK = 1e-2


def determination(out, problem: Problem, ln: NDArray, bounds, dists,
                  jac: NDArray | None = None) -> tuple[dict[str, str], dict[str, str]]:
    """What the data hold of each free parameter, and the combination they hold instead.

    ``determined`` (both ends of its interval closed), ``bounded below`` or ``bounded
    above`` (one end closed), ``not determined`` (neither, or the fit pins it, or a
    strongly correlated neighbour, at the bound of the search range: its interval is then the
    search range's, not the data's).  For a parameter not determined, the combination of it
    and its partner along the weakest direction of the Jacobian (``jac``: :func:`jacobian_at`,
    computed when needed and not given) that the data fix (e.g. ``k_x/mass``), where the
    Jacobian shows one.
    """
    free = problem.free
    at_bound = pinned(free, ln, bounds)
    status: dict[str, str] = {}
    for n in free:
        below, above = (math.isfinite(d) for d in dists[n])
        correl = out.params[n].correl or {}
        leaning = [m for m in at_bound
                   if m != n and abs(correl.get(m, 0.0)) > STRONG_CORRELATION]
        if n in at_bound or leaning or not (below or above):
            status[n] = "not determined"
        else:
            status[n] = ("determined" if below and above else
                         "bounded below" if below else "bounded above")
    combos = {}
    if jac is None and any(v != "determined" for v in status.values()):
        jac = jacobian_at(problem, ln)
    if jac is not None and len(free) > 1:
        _, sv, vt = np.linalg.svd(jac, full_matrices=False)
        weak = [k for k in np.argsort(sv) if sv[0] > 0 and sv[k] / sv[0] < WEAK]
        for n in (m for m in free if status[m] != "determined"):
            j = free.index(n)
            for k in weak:
                v = vt[k]
                if abs(v[j]) < 0.3:
                    continue
                partner = max((i for i in range(len(free)) if i != j), key=lambda i: abs(v[i]))
                if abs(v[partner]) < 0.3 * abs(v[j]):
                    continue
                combos[n] = _combination(n, free[partner], -v[j] / v[partner])
                break
    return status, combos


def _combination(a: str, b: str, power: float) -> str:
    """``a b^power`` written as a ratio or product (``power`` rounded to a half if near one)."""
    half = round(2.0 * power) / 2.0
    p = half if abs(power - half) < 0.1 else round(power, 2)
    if p == -1.0:
        return f"{a}/{b}"
    if p == 1.0:
        return f"{a}*{b}"
    return f"{a}*{b}^{p:g}"


#: What a law's parameter needs of the data, said where its column of the Jacobian is flat.
LAW_NEEDS = {
    "mu_static": "the static coefficient acts only where the contact sticks: rows of slower "
                 "sliding or larger amplitude, where it sticks for part of the cycle",
    "d_c": "steady sliding does not depend on d_c: it needs rows where the state cannot follow "
           "the slip rate, the oscillation's period comparable to d_c/v0 (omega d_c/v0 near 1)",
    "a": "a moves the model only through the slip rate's response",
    "b": "b moves the model only through the state",
}


def law_warnings(problem: Problem, ln: NDArray, jac: NDArray | None
                 ) -> tuple[list[str], dict[str, str]]:
    """What the data cannot tell of a local friction law: sentences, and combinations held.

    From the Jacobian in ``ln`` at ``ln`` (``jac``, :func:`jacobian_at`): a free law parameter
    (``mu_static``, ``a``, ``b``, ``d_c``) whose column is flat (weighted: moving the
    chi-square by less than 1 over a factor ``e``; unweighted: below :data:`WEAK` of the
    largest column)
    gets a sentence saying what the data would need (:data:`LAW_NEEDS`); free ``a`` and ``b``
    whose only combination the data see is ``a - b`` (their derivative along ``da = db``,
    ``J_a/a + J_b/b``, below :data:`WEAK` of each alone: at constant load and steady
    sliding ``mu_ss = mu_star + (a - b) ln(v/v_ref)`` to within ``exp(-2 mu_star/a)``) get a
    sentence naming it and the combination ``"a - b"`` for both.
    """
    free = problem.free
    law = [n for n in free if n in LAW_FITTABLE]
    if jac is None or not law:
        return [], {}
    norms = np.linalg.norm(jac, axis=0)
    top = float(norms.max())
    out: list[str] = []
    combos: dict[str, str] = {}
    for n in law:
        # weighted: the chi-square's own scale (a jump of another column, where a row changes
        # its stick-slip pattern within the step, does not make this one look flat)
        flat = (norms[free.index(n)] < 1.0 if problem.weighted else
                top == 0.0 or (len(free) > 1 and norms[free.index(n)] < WEAK * top))
        if flat:
            out.append(f"{n} does not move the model at these rows (its chi-square changes by "
                       f"{norms[free.index(n)] ** 2:.2g} over a factor e): {LAW_NEEDS[n]}")
    if "a" in free and "b" in free:
        ja, jb = jac[:, free.index("a")], jac[:, free.index("b")]
        named = problem.named(ln)
        a, b = named["a"], named["b"]
        along = np.linalg.norm(ja / a + jb / b)
        alone = min(np.linalg.norm(ja / a), np.linalg.norm(jb / b))
        if alone > 0.0 and along < WEAK * alone:
            out.append(f"a and b are not separated by these data: they determine a - b only "
                       f"(a change of both by the same amount moves the model by "
                       f"{along / alone:.1e} of a change of one; steady sliding at constant "
                       "load gives mu_ss(v) = mu_star + (a - b) ln(v/v_ref)): fix one, or add "
                       "rows where the oscillation makes the slip rate vary within the cycle")
            combos.update(a="a - b", b="a - b")
    return out, combos
