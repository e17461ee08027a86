"""The fit, from the guess to the result.

The problem checked and built, the search, the uncertainties and the verdict, in that order (the
package's docstring describes each).
"""

from __future__ import annotations

import math
import time
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from ...parallel import available_cores, mapper
from ...params import Physical
from ...solver import SolverSettings
from ..measurements import read_measurements
from .problem import (
    CONTACT_FIELDS,
    CONTACT_FITTABLE,
    RATE_STATE_BOUND,
    Contact,
    Problem,
    check_contact,
    check_law,
    contact_exponents,
    free_and_tied,
    search_bounds,
)
from .result import FitResult, judge
from .search import Stages, ln_of, local_fit, run_search
from .uncertainty import (
    determination,
    estimate_uncertainties,
    identifiability,
    jacobian_at,
    law_warnings,
    physical_params,
    profile_warnings,
)

#: The MDR solver's ``tol_trusted`` in a fit of a curved contact without ``settings``: the
#: row without springs answers it as it does the default 1e-5 (errors about 1e-7); where the
#: rows of springs answer (a static coefficient above the kinetic one, ``a = 1``) it is the
#: cheaper. An error of ``mu0 1e-4`` in the COF is a hundredth of a bench's noise
#: (docs/bench.md, "A curved contact").
CURVED_TOL = 1e-4
#: The 2-D solver's ``rtol`` in a fit whose every row has a transverse oscillation
#: (``du_y > 0``), without ``settings``: about twice as fast as its default 1e-10, with stated
#: errors of a few 1e-6 in ``mu/mu0``, a thousandth of a bench's noise (docs/bench.md,
#: "Measured friction curves: the table", across the sliding).
TRANSVERSE_RTOL = 1e-8
#: The global search's local starts and screened points without ``starts``, ``screen``: a
#: flat punch's, and a curved contact's or rate-and-state friction's (the MDR solver is ~30
#: times slower a point, the rate-and-state solver ~60 times).
SEARCH = (12, 512)
CURVED_SEARCH = (3, 32)

__all__ = ["CURVED_TOL", "TRANSVERSE_RTOL", "fit", "fit_settings"]


def fit_settings(guess: Physical, data: pd.DataFrame) -> SolverSettings | None:
    """The solver's settings of a fit given none.

    ``tol_trusted`` :data:`CURVED_TOL` for a curved contact, ``rtol``
    :data:`TRANSVERSE_RTOL` where every row has a transverse oscillation (``du_y > 0``: the
    2-D solver), else the defaults (None).
    """
    if guess.curved:
        return SolverSettings(tol_trusted=CURVED_TOL)
    if bool(np.all(data["du_y"].to_numpy() > 0.0)):
        return SolverSettings(rtol=TRANSVERSE_RTOL)
    return None


def fit(data: pd.DataFrame | str | Path, guess: Physical, free: list[str] | tuple[str, ...] = (
        "mu0", "mass", "k_xc", "u_z0"), *, natural_frequency: bool = True,
        normal_load: bool = True, quality_factor: bool = True, span: float = 10.0,
        global_stage: bool = True, starts: int | None = None, screen: int | None = None,
        seed: int = 0,
        workers: int = 1, progress: bool = True,
        settings: SolverSettings | None = None, jacobian: str = "exact",
        contact: Contact | None = None) -> FitResult:
    """Fit the fields ``free`` of ``guess`` to a measured table (module docstring).

    ``data``: a table of :func:`~vibrofriction.bench.read_measurements` (or its
    path).  ``natural_frequency``, ``normal_load``, ``quality_factor``: the constraints
    (module docstring); a parameter in ``free`` that one of them would hold is refused,
    naming the keyword that releases it.  ``span``: each free parameter is searched
    within a factor ``span`` of the guess (``mu0`` as well).  ``global_stage``: the global
    search (:func:`.search.run_search`: a Sobol screen of ``screen`` points of the search box
    on every other row of a table of 20 rows or more, least squares from its ``starts`` best
    distinct points, then basin hops from the best minimum; defaults :data:`SEARCH`,
    :data:`CURVED_SEARCH` for a curved contact; ``seed`` seeds it); without it, least squares
    from the guess alone.  ``workers``: processes for the global
    search, the local starts and the profiles (``-1``: every core), from the package's one
    pool (:mod:`vibrofriction.parallel`, forkserver workers that die with their parent):
    a script that fits with ``workers != 1`` runs the fit under
    ``if __name__ == "__main__":``.
    ``jacobian``: the local least squares' Jacobian, ``"exact"`` (the sensitivities of
    the steady state, :meth:`Problem.jacobian`; differences of the solver only at the
    rows that have none) or ``"differences"`` (lmfit's differences of the residuals).
    ``contact``: the geometry the guess was built from (``vf.from_bench(contact=...,
    contact_model=...)``, checked): its ``radius`` and its pair's ``E_star``
    (:data:`CONTACT_FITTABLE`) may then be free, one of them (module docstring, "A curved
    contact"); ``k_zc``, ``k_xc``, ``u_z0`` follow them at the guess's load.  A curved
    (MDR) guess is solved by the MDR solver (``tol_trusted`` :data:`CURVED_TOL` unless
    ``settings`` say otherwise) and differenced (``jacobian="exact"`` takes the solver's
    differences at every row). Data whose every row has a transverse oscillation (``du_y >
    0``: the 2-D solver) are solved at ``rtol`` :data:`TRANSVERSE_RTOL` unless ``settings``
    say otherwise.
    **A local friction law** (docs/bench.md, "Fitting a friction law") is carried by the
    guess through every evaluation (and into ``res.system``): ``mu_static`` (a guess with
    ``mu_static > mu0``) may then be free, searched as ``ln(mu_static/mu0)`` within
    ``[max(0, ln(r/span)), ln(r span)]`` (``r`` the guess's ratio: never below the kinetic
    ``mu0``; its interval is the ratio's times the fitted ``mu0``; a held ``mu_static``
    keeps its value while ``mu0`` moves), and so may the rate-and-state ``a``, ``b``,
    ``d_c`` (m) of a guess with ``friction=RateAndState(...)``; each refused by name
    without its law in the guess.  The Jacobian of a column that moves the law (``mu_static``,
    or ``mu0`` under a held ``mu_static``) is the solver's central differences (the
    sensitivities do not differentiate the static coefficient); under rate-and-state
    friction every column is (the rate-and-state solver has no sensitivities; step
    :data:`~.problem.RATE_STATE_STEP` in ``ln``), and the search is the short one of a
    curved contact (:data:`CURVED_SEARCH`).  What the data determine of each law's
    parameters is checked (:func:`.uncertainty.law_warnings`): ``a`` and ``b`` apart only
    where the data hold more than steady sliding (``a - b`` otherwise, named), ``d_c`` only
    through the dynamics, ``mu_static`` only at rows where the contact sticks.
    ``res.extra["stages"]`` says where the time went; ``res.quality`` whether the fit
    describes the data.
    """
    t0 = time.perf_counter()
    data = read_measurements(data)
    free, tied = free_and_tied(tuple(free), natural_frequency, normal_load, quality_factor,
                                len(data))
    check_contact(guess, contact, free)
    check_law(guess, free)
    if settings is None:
        settings = fit_settings(guess, data)
    search = CURVED_SEARCH if guess.curved or guess.friction is not None else SEARCH
    starts = search[0] if starts is None else _count("starts", starts)
    screen = search[1] if screen is None else _count("screen", screen)
    for n in free:
        if n in CONTACT_FITTABLE:  # k_zc, k_xc, u_z0 follow it: ln y = p ln x + const
            assert contact is not None  # a contact parameter without contact= is refused
            for k, p in contact_exponents(contact, n, guess.F_N0, guess.curved).items():
                if k in CONTACT_FIELDS and abs(p) > 1e-9:
                    tied[k] = (n, p)
    if jacobian not in ("exact", "differences"):
        raise ValueError(f"jacobian must be 'exact' or 'differences', got {jacobian!r}")
    problem = Problem(guess, free, natural_frequency, normal_load, quality_factor, data,
                       settings, jacobian_kind=jacobian, contact=contact)
    bounds = search_bounds(problem, span)
    if "mu0" in free:
        problem.mu0_max = math.exp(bounds[free.index("mu0")][1])
    problem.ratio_max = (RATE_STATE_BOUND if guess.friction is not None else
                         math.exp(bounds[free.index("mu_static")][1]) if "mu_static" in free
                         else guess.static_ratio)
    x0 = np.array([math.log(problem.start(n)) for n in free])
    workers = workers if workers >= 1 else available_cores()
    stages = Stages()
    with mapper(workers) as map_:
        if global_stage:
            out, minima = run_search(problem, bounds, x0, map_, stages, screen, starts, seed,
                                     progress, workers)
        else:
            with stages.timed("local") as row:
                out, minima, row["evaluations"] = local_fit(problem, [x0], bounds, map_)
        out, minima, dists, lower, shape = estimate_uncertainties(problem, out, minima, bounds,
                                                                  map_, stages, progress)
    res = _result(problem, out, bounds, tied, dists, lower)
    res.extra["profiles"] = shape
    res.nfev, res.seconds = stages.nfev, time.perf_counter() - t0
    res.extra.update(local_minima=[float(m[0]) for m in minima], stages=stages.rows)
    return res


def _count(name: str, value: object) -> int:
    """``value`` as a count of at least 1 (ValueError naming ``name`` otherwise)."""
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < 1:
        raise ValueError(f"{name} must be a whole number >= 1, got {value!r}")
    return int(value)


def _result(problem: Problem, out, bounds, tied, dists, lower) -> FitResult:
    """The :class:`FitResult` of the best fit ``out``.

    Its verdict (a poor one widens the intervals to the search range), parameters, intervals and
    warnings.
    """
    free = problem.free
    ln = ln_of(out, free)
    _, outside, untrusted = problem.evaluate(ln)
    penalised = {"untrusted": untrusted, "outside the model's domain": outside}
    quality, p_value = judge(problem, float(out.chisqr), lower, outside + untrusted)
    extra: dict[str, Any] = {}
    system = problem.system(ln)
    named = problem.named(ln)
    result_params, intervals = physical_params(out, free, named, tied, dists)
    extra["at_lowest_minimum"] = lower is None
    if quality == "poor":
        extra["profile_intervals"] = intervals
        search = {n: (ln[j] - bounds[j][0], bounds[j][1] - ln[j]) for j, n in enumerate(free)}
        result_params, intervals = physical_params(out, free, named, tied, search)
    jac = jacobian_at(problem, ln)  # one Jacobian for what the data hold and the warnings
    status, combos = determination(out, problem, ln, bounds, dists, jac)
    law_notes, law_combos = law_warnings(problem, ln, jac)
    if quality == "poor":  # a model that does not fit the data determines nothing of them
        status, combos = dict.fromkeys(free, "not determined"), {}
    else:  # a and b apart are not what the data hold, whatever the profiles
        combos.update(law_combos)
        status.update(dict.fromkeys(law_combos, "not determined"))
    for n, st in status.items():  # no standard error from the covariance of a loose parameter
        if st == "not determined" and n in result_params:
            result_params[n].stderr = None
    warnings = identifiability(out, problem, ln, bounds, jac)
    warnings += law_notes
    warnings += profile_warnings(free, dists, tied, lower)
    return FitResult(params=result_params, system=system, data=problem.data, free=free,
                     constraints={"natural_frequency": problem.natural_frequency,
                                  "normal_load": problem.normal_load,
                                  "quality_factor": problem.quality_factor},
                     warnings=warnings, chisqr=float(out.chisqr), redchi=float(out.redchi),
                     nfev=0, seconds=0.0, weighted=problem.weighted, guess=problem.guess,
                     intervals=intervals, extra=extra, quality=quality, p_value=p_value,
                     penalised=penalised, determination=status, combinations=combos)
