"""The fit's search (:mod:`.procedure`).

The global search: a space-filling screen of the search box, Levenberg-Marquardt from its best
distinct points, a basin hopping from the best minimum, and a second round when the fit is not
clearly good; where the time went (:class:`Stages`).
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

import lmfit
import numpy as np
from numpy.typing import NDArray

from .problem import MDR_STEP, Problem
from .result import DOUBTFUL_P, chi_square_p

#: Model evaluations per varied parameter (plus one) that a local least-squares run may
#: spend: a start that crawls along a kinked valley does not win.
LOCAL_BUDGET = 60
#: Tasks per process of the screen of the global search (:meth:`Problem.costs`): the
#: cost of a point varies tenfold, so a few interleaved tasks each even the load out.
CHUNKS = 4


@dataclass
class Stages:
    """Where the fit spent its time: a row per stage (name, seconds, model evaluations)."""

    rows: list[dict[str, Any]] = field(default_factory=list)

    @contextmanager
    def timed(self, name: str) -> Iterator[dict[str, Any]]:
        """Time the stage ``name``: its row, whose ``evaluations`` the caller sets."""
        row = {"stage": name, "seconds": 0.0, "evaluations": 0}
        self.rows.append(row)
        t = time.perf_counter()
        yield row
        row["seconds"] = time.perf_counter() - t

    @property
    def nfev(self) -> int:
        """The model evaluations of every stage."""
        return sum(r["evaluations"] for r in self.rows)


def run_search(problem: Problem, bounds, x0: NDArray, map_, stages: Stages, screen: int,
               starts: int, seed: int, progress: bool, cores: int):
    """Local least squares from many space-filling starts, then hops from the best.

    A scrambled Sobol sample of ``screen`` points of the search box (and the guess) is scored
    on the coarse table (:meth:`Problem.coarse`, a generation at once, :meth:`Problem.costs`);
    least squares on every row run from the ``starts`` best of them that are distinct (no two
    within :data:`DISTINCT` of the box's width in every parameter).  Then a basin hopping
    (:func:`_hop`): least squares from random neighbours of the best minimum, round after
    round, until a few rounds find nothing lower.  A fit still not clearly good
    (:func:`_poor`) samples again (another seed).  The best fit and the local minima reached
    (chi-square, point), lowest first.
    """
    out: Any = None
    minima: list[Any] = []
    coarse = problem.coarse()
    rng = np.random.default_rng(seed)
    for attempt in range(2):
        with stages.timed("global") as row:
            sample = _sobol(bounds, screen, seed + attempt)
            if attempt == 0:
                sample = np.vstack([x0, sample])
            cost = coarse.costs(sample.T, map_=map_, chunks=CHUNKS * cores)
            row["evaluations"] = len(sample)
        chosen = _spread(sample, cost, bounds, starts, [m[1] for m in minima])
        with stages.timed("local") as row:
            found, more, row["evaluations"] = local_fit(problem, chosen, bounds, map_,
                                                        progress=progress)
        minima = sorted(minima + more, key=lambda r: r[0])
        if out is None or found.chisqr < out.chisqr:
            out = found
        with stages.timed("hops") as row:
            out, more, row["evaluations"] = _hop(problem, out, bounds, map_, rng, cores,
                                                 calm=1 if problem.differenced else CALM)
        minima = sorted(minima + more, key=lambda r: r[0])
        if not _poor(problem, out.chisqr):
            break
    return out, minima


#: The basin hopping's steps in ``ln`` (a normal deviate of this scale in every parameter,
#: half the hops at each), the hops of a round per process (at least two a round), and the
#: rounds without a minimum lower by more than :data:`GAIN` (an eighth of the profiles'
#: level: a smaller gain moves no interval's end much) after which it stops, at most
#: :data:`HOP_ROUNDS` rounds.
HOP_SCALES = (0.1, 0.3)
HOPS_PER_CORE = 1
CALM = 2
GAIN = 0.5
HOP_ROUNDS = 12
#: A hop's least squares start next to a minimum: half the budget of a start from afar.
HOP_BUDGET = 0.5


def _hop(problem: Problem, out, bounds, map_, rng: np.random.Generator, cores: int,
         calm: int = 2):
    """Basin hopping from the minimum ``out``: the best fit, the minima met, the evaluations.

    Each round runs least squares from ``HOPS_PER_CORE`` random neighbours per process of the
    best minimum so far (steps :data:`HOP_SCALES` in ``ln``); a lower minimum becomes the
    centre of the next round; it stops after ``calm`` rounds without one (:data:`CALM`; one
    for a curved contact, whose evaluations are ~30 times dearer).  The chi-square of noisy
    data has shallow valleys beside the deepest (the stick-slip pattern of a row changes): a
    hop reaches a neighbour that a descent cannot.
    """
    lo, hi = np.array(bounds, dtype=float).T
    minima: list[Any] = []
    spent, quiet = 0, 0
    count = max(HOPS_PER_CORE * cores, 2)
    for _ in range(HOP_ROUNDS):
        centre = ln_of(out, problem.free)
        scales = np.resize(np.asarray(HOP_SCALES), count)[:, None]
        hops = np.clip(centre + scales * rng.standard_normal((count, centre.size)), lo, hi)
        found, more, nfev = local_fit(problem, list(hops), bounds, map_, budget=HOP_BUDGET)
        minima += more
        spent += nfev
        if found.chisqr < out.chisqr - GAIN:
            out, quiet = found, 0
        else:
            if found.chisqr < out.chisqr:
                out = found
            quiet += 1
            if quiet == calm:
                break
    return out, sorted(minima, key=lambda r: r[0]), spent


#: Two starts of the multi-start stage are distinct when they differ by more than this
#: fraction of the search box's width in some parameter.
DISTINCT = 0.08


def _sobol(bounds, n: int, seed: int) -> NDArray[np.float64]:
    """``n`` points of a scrambled Sobol sequence in the box ``bounds`` (rows)."""
    from scipy.stats import qmc

    lo, hi = np.array(bounds, dtype=float).T
    m = max(int(np.ceil(np.log2(max(n, 2)))), 1)
    sample = qmc.Sobol(len(bounds), scramble=True, seed=seed).random_base2(m)[:n]
    return lo + sample * (hi - lo)


def _spread(sample: NDArray, cost: NDArray, bounds, count: int, taken) -> list[NDArray]:
    """The ``count`` lowest-cost points of ``sample`` that are distinct from each other.

    And from the points already ``taken`` (the minima of an earlier round).
    """
    lo, hi = np.array(bounds, dtype=float).T
    width = np.where(hi > lo, hi - lo, 1.0)
    chosen: list[NDArray] = []
    near = [np.asarray(t, dtype=float) for t in taken]
    for i in np.argsort(np.where(np.isfinite(cost), cost, np.inf), kind="stable"):
        x = sample[i]
        if all(np.max(np.abs(x - y) / width) > DISTINCT for y in chosen + near):
            chosen.append(x)
        if len(chosen) == count:
            break
    return chosen


def _poor(problem: Problem, chisqr: float) -> bool:
    """A weighted fit that is not clearly good.

    Its chi-square has a probability below :data:`DOUBTFUL_P` (a wrong valley is one
    explanation, so another is looked for).
    """
    return problem.weighted and chi_square_p(problem, chisqr) < DOUBTFUL_P


def ln_of(out, free: tuple[str, ...]) -> NDArray[np.float64]:
    """The values of the free parameters (``ln``) of an lmfit result ``out``."""
    return np.array([out.params[n].value for n in free])


def least_squares(problem: Problem, x0: NDArray, bounds, hold: int | None = None,
                  budget_factor: float = 1.0):
    """Levenberg-Marquardt (lmfit) over ``ln`` of the free parameters from ``x0``.

    ``hold``: the index of a parameter kept at its value in ``x0`` (a profile).
    """
    params = lmfit.Parameters()
    for i, (n, x, (lo, hi)) in enumerate(zip(problem.free, x0, bounds, strict=True)):
        params.add(n, value=float(np.clip(x, lo, hi)), min=lo, max=hi, vary=i != hold)

    def residual(p):
        return problem.residual(np.array([p[n].value for n in problem.free]))

    loose = {"ftol": 1e-6, "xtol": 1e-6} if hold is not None else {}  # chi^2 to ~1e-4
    if hold is not None and problem.differenced:  # the MDR's value is only within 1e-4
        loose = {"ftol": 1e-4, "xtol": 1e-4}  # anyway; a rate-and-state evaluation is dear
    nvary = len(problem.free) - (hold is not None)
    # a start that crawls along a kinked valley for thousands of evaluations does not win:
    # the budget is LOCAL_BUDGET evaluations per varied parameter
    budget = int(LOCAL_BUDGET * budget_factor) * (nvary + 1)

    def leastsq(p, max_nfev, **jacobian_options):
        return lmfit.minimize(residual, p, method="leastsq",
                              scale_covar=not problem.weighted, max_nfev=max_nfev,
                              **loose, **jacobian_options)

    def differences(p, max_nfev):
        # a curved contact's value moves in steps of its error bar: lmfit's step
        # sqrt(epsfcn) |x| must be far larger than the default's 1e-4
        return leastsq(p, max_nfev, epsfcn=MDR_STEP**2 if problem.curved else 1e-8)

    if problem.jacobian_kind == "differences":
        return differences(params, budget)
    # the exact Jacobian (:meth:`Problem.jacobian`); it counts as nvary evaluations of
    # the budget, as the differences it replaces did
    vary = np.array([i != hold for i in range(len(problem.free))])
    spent = {"jacobians": 0}

    def jacobian(p):
        spent["jacobians"] += 1
        return problem.jacobian(np.array([p[n].value for n in problem.free]), vary)

    def over_budget(p, it, resid, *args, **kws):
        return it + nvary * spent["jacobians"] > budget

    fast = leastsq(params, budget, Dfun=jacobian, col_deriv=0, iter_cb=over_budget)
    if problem.differenced:  # its Jacobian is already the solver's differences
        fast.nfev = int(fast.nfev) + 2 * nvary * spent["jacobians"]
        if not hasattr(fast, "chisqr"):  # stopped by the budget: lmfit leaves no statistics
            r = problem.residual(ln_of(fast, problem.free))
            fast.chisqr = float(r @ r)
            fast.redchi = fast.chisqr / max(r.size - nvary, 1)
            fast.covar = None
        return fast
    # then lmfit's differences from there: the model bends on scales below their step
    # (stick-slip patterns that change), where the exact local slope can stop at a
    # kink's small dip that differences of that step see through (a profile of a
    # 5-parameter fit stopped 1.9 higher in chi-square); near the minimum this costs a
    # few evaluations, and the covariance is the differences' as before
    left = max(budget - int(fast.nfev) - nvary * spent["jacobians"], 2 * (nvary + 1))
    out = differences(fast.params, left)
    out.nfev += int(fast.nfev) + nvary * spent["jacobians"]
    return out


@dataclass
class _Fit:
    """What the fit keeps of an lmfit run (picklable, so that a worker can send it)."""

    params: lmfit.Parameters
    chisqr: float
    redchi: float
    covar: NDArray | None
    nfev: int

    @classmethod
    def of(cls, out) -> _Fit:
        covar = getattr(out, "covar", None)
        return cls(out.params, float(out.chisqr), float(out.redchi),
                   None if covar is None else np.array(covar), int(out.nfev))


def _polish(task) -> _Fit:
    problem, x0, bounds, budget = task
    return _Fit.of(least_squares(problem, x0, bounds, budget_factor=budget))


def local_fit(problem: Problem, starts: list[NDArray], bounds, map_, progress: bool = False,
              budget: float = 1.0):
    """Least squares from every start (in parallel), each within ``budget`` of the budget.

    The lowest chi-square, the chi-squares and points reached from each start, and the count of
    model evaluations.
    """
    from tqdm.auto import tqdm

    found = []
    with tqdm(total=len(starts), desc="fit: local starts",
              disable=not progress or len(starts) < 3) as bar:
        for r in map_(_polish, [(problem, x, bounds, budget) for x in starts]):
            found.append(r)
            bar.update(1)
    minima = sorted(((r.chisqr, ln_of(r, problem.free)) for r in found), key=lambda r: r[0])
    return min(found, key=lambda r: r.chisqr), minima, sum(r.nfev for r in found)
