r"""Fitting measured friction curves with the model (docs/bench.md).

``fit(data, guess, free=[...])`` adjusts the named fields of a :class:`Physical` guess
so that ``mu0 * mu_ratio`` (eq. 25, exact solver, trusted values only) matches the
measured ``cof`` at each row's ``(v0, du_z, omega)``.  The other fields stay at the
guess's values; the experimenter's knowns can be imposed as constraints (each on by
default, each stated in the report):

* ``natural_frequency``: ``k_x = m (2 pi f_n)^2`` with ``f_n`` of the guess (an impact
  test measures it): with ``mass`` free, ``k_x`` follows it (and the other way round);
* ``normal_load``: ``k_zc u_z0 = F_N0`` of the guess (the applied load): with ``k_zc``
  free, ``u_z0`` follows it (and the other way round);
* ``quality_factor``: the pin's damping ratio ``zeta`` of the guess is kept, so
  ``c_x = 2 zeta sqrt(k_x m)`` follows the pin.

A parameter named in ``free`` is fitted: naming both members of a constraint's pair
(``mass`` and ``k_x``; ``k_zc`` and ``u_z0``; ``c_x`` under ``quality_factor``) is refused
with the keyword that releases it.

The objective has kinks where the stick-slip pattern changes, so a local least-squares
fit from a poor start can stop in the wrong valley: a global stage (differential
evolution over ``ln`` of the free parameters, within a factor ``span`` of the guess,
on every other row of the table: half the cost per generation) comes first, then
Levenberg-Marquardt with lmfit on every row from its best point and from the next best
distinct members of its population (the lowest chi-square wins), with the exact Jacobian
of the residuals (the steady state's sensitivities, docs/solver.md "Parameter
sensitivities"; the solver's differences at the rows that have none), then lmfit's
differences from where it stops (the model's kinks).  A weighted fit still
poor after the first starts (chi-square probability below :data:`~.fit_result.POOR_P`)
runs a second global stage with another seed.  Parameters are fitted as logarithms (all
are positive and span decades).  A row the model cannot evaluate (no trusted value of
the solver) costs more than any honest misfit of that row could
(:meth:`.fit_problem._Problem.penalty`).

Uncertainties are profile-likelihood intervals, not the curvature at the minimum: the
kinks make the chi-square surface far from a parabola on the scale of the errors.  For
each free parameter and each side, the parameter is held and the others refitted until
the chi-square has risen by ``4 s^2`` (``s^2`` the reduced chi-square, at least 1 when
``sigma`` is given): the 95.4 % interval ``res.intervals[name]``, asymmetric in general;
``stderr`` is half its longer side, so that ``value +- 2 stderr`` holds the whole
interval.  A side the profile never closes within the search range is unbounded
(``-inf`` or ``inf``).  Correlations come from the covariance of the least-squares
stage.  Another local minimum (from the other starts) within the level widens the
interval to reach it, and a profile that finds a lower chi-square than the fit restarts
the fit from there (and the profiles, if the drop exceeds ``s^2/2``; a smaller one keeps
the intervals, which then hold the true ones: the new level set lies inside the old).

A weighted fit is judged by the probability of its chi-square (``res.p_value``, with
``points - free`` degrees of freedom): below :data:`~.fit_result.POOR_P`, or when a
profile met a lower chi-square twice, the fit is not a description of the data within
``sigma`` (a wrong valley, a wrong model, a wrong constraint or an understated
``sigma``: the fit cannot tell which), ``res.quality`` says so, the report says so
first, and the intervals are the whole search range (the profile intervals, scaled by
``s^2``, are kept in ``res.extra["profile_intervals"]``).  An unweighted fit cannot be
judged.

The parts, each in its module, in the order :func:`fit` runs them: the problem
(:mod:`.fit_problem`: the parameters in ``ln``, the constraints, the residuals and their
penalty, :func:`predict_cof`), the search (:mod:`.fit_search`: the global stage and the
local starts), the uncertainties (:mod:`.fit_uncertainty`: the profiles, what the data
do not identify) and the result (:mod:`.fit_result`: :class:`FitResult` and its
verdict).
"""

from __future__ import annotations

import math
import time
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from ..parallel import available_cores, mapper
from ..params import Physical
from ..solver import SolverSettings
from .fit_problem import (
    CONTACT_FIELDS,
    CONTACT_FITTABLE,
    FITTABLE,
    Contact,
    _bounds,
    _check_contact,
    _free_and_tied,
    _Problem,
    contact_exponents,
    predict_cof,
    synthetic_measurements,
)
from .fit_result import FitResult, _judge
from .fit_search import _ln, _local_fit, _search, _Stages
from .fit_uncertainty import _identifiability, _physical_params, _profile_warnings, _uncertainties
from .measurements import read_measurements

#: The MDR solver's ``tol_trusted`` in a fit of a curved contact without ``settings``:
#: three times faster than the default 1e-5, and its error (``mu0 1e-4`` in the COF) is
#: a hundredth of a bench's noise (docs/bench.md, "A curved contact").
CURVED_TOL = 1e-4
#: The global stage's ``maxiter`` and ``popsize`` without them: a flat punch's, and a
#: curved contact's (the MDR solver is ~30 times slower a point: a shorter stage).
GLOBAL_STAGE = (60, 12)
CURVED_GLOBAL_STAGE = (20, 8)

__all__ = ["CONTACT_FITTABLE", "CURVED_TOL", "FITTABLE", "FitResult", "fit", "predict_cof",
           "synthetic_measurements"]


def fit(data: pd.DataFrame | str | Path, guess: Physical, free: list[str] | tuple[str, ...] = (
        "mu0", "mass", "k_xc", "u_z0"), *, natural_frequency: bool = True,
        normal_load: bool = True, quality_factor: bool = True, span: float = 10.0,
        global_stage: bool = True, maxiter: int | None = None, popsize: int | None = None,
        seed: int = 0,
        workers: int = 1, progress: bool = True,
        settings: SolverSettings | None = None, jacobian: str = "exact",
        contact: Contact | None = None) -> FitResult:
    """Fit the fields ``free`` of ``guess`` to a measured table (module docstring).

    ``data``: a table of :func:`~vibrofriction.bench.read_measurements` (or its
    path).  ``natural_frequency``, ``normal_load``, ``quality_factor``: the constraints
    (module docstring); a parameter in ``free`` that one of them would hold is refused,
    naming the keyword that releases it.  ``span``: each free parameter is searched
    within a factor ``span`` of the guess (``mu0`` as well).  ``maxiter``, ``popsize``
    (default :data:`GLOBAL_STAGE`, :data:`CURVED_GLOBAL_STAGE` for a curved contact),
    ``seed``: the global stage (:func:`scipy.optimize.differential_evolution`, on every
    other row of a table of 20 rows or more).  ``workers``: processes for the global
    stage, the local starts and the profiles (``-1``: every core), from the package's one
    pool (:mod:`vibrofriction.parallel`, forkserver workers that die with their parent):
    a script that fits with ``workers != 1`` runs the fit under
    ``if __name__ == "__main__":``.
    ``jacobian``: the local least squares' Jacobian, ``"exact"`` (the sensitivities of
    the steady state, :meth:`_Problem.jacobian`; differences of the solver only at the
    rows that have none) or ``"differences"`` (lmfit's differences of the residuals).
    ``contact``: the geometry the guess was built from (``vf.from_bench(contact=...,
    contact_model=...)``, checked): its ``radius`` and its pair's ``E_star``
    (:data:`CONTACT_FITTABLE`) may then be free, one of them (module docstring, "A curved
    contact"); ``k_zc``, ``k_xc``, ``u_z0`` follow them at the guess's load.  A curved
    (MDR) guess is solved by the MDR solver (``tol_trusted`` :data:`CURVED_TOL` unless
    ``settings`` say otherwise) and differenced (``jacobian="exact"`` takes the solver's
    differences at every row).
    ``res.extra["stages"]`` says where the time went; ``res.quality`` whether the fit
    describes the data.
    """
    t0 = time.perf_counter()
    data = read_measurements(data)
    free, tied = _free_and_tied(tuple(free), natural_frequency, normal_load, quality_factor,
                                len(data))
    _check_contact(guess, contact, free)
    if guess.curved and settings is None:
        settings = SolverSettings(tol_trusted=CURVED_TOL)
    stage = CURVED_GLOBAL_STAGE if guess.curved else GLOBAL_STAGE
    maxiter = stage[0] if maxiter is None else maxiter
    popsize = stage[1] if popsize is None else popsize
    for n in free:
        if n in CONTACT_FITTABLE:  # k_zc, k_xc, u_z0 follow it: ln y = p ln x + const
            assert contact is not None  # a contact parameter without contact= is refused
            for k, p in contact_exponents(contact, n, guess.F_N0, guess.curved).items():
                if k in CONTACT_FIELDS and abs(p) > 1e-9:
                    tied[k] = (n, p)
    if jacobian not in ("exact", "differences"):
        raise ValueError(f"jacobian must be 'exact' or 'differences', got {jacobian!r}")
    problem = _Problem(guess, free, natural_frequency, normal_load, quality_factor, data,
                       settings, jacobian_kind=jacobian, contact=contact)
    bounds = _bounds(problem, span)
    if "mu0" in free:
        problem.mu0_max = math.exp(bounds[free.index("mu0")][1])
    x0 = np.array([math.log(problem.start(n)) for n in free])
    workers = workers if workers >= 1 else available_cores()
    stages = _Stages()
    with mapper(workers) as map_:
        if global_stage:
            out, minima = _search(problem, bounds, x0, map_ if workers != 1 else 1, map_,
                                  stages, maxiter, popsize, seed, progress, workers)
        else:
            with stages.timed("local") as row:
                out, minima, row["evaluations"] = _local_fit(problem, [x0], bounds, map_)
        out, minima, dists, lower = _uncertainties(problem, out, minima, bounds, map_,
                                                   stages, progress)
    res = _result(problem, out, bounds, tied, dists, lower)
    res.nfev, res.seconds = stages.nfev, time.perf_counter() - t0
    res.extra.update(local_minima=[float(m[0]) for m in minima], stages=stages.rows)
    return res


def _result(problem: _Problem, out, bounds, tied, dists, lower) -> FitResult:
    """The :class:`FitResult` of the best fit ``out``: its verdict (a poor one widens the
    intervals to the search range), parameters, intervals and warnings."""
    free = problem.free
    ln = _ln(out, free)
    _, outside, untrusted = problem.evaluate(ln)
    penalised = {"untrusted": untrusted, "outside the model's domain": outside}
    quality, p_value = _judge(problem, float(out.chisqr), lower, outside + untrusted)
    extra: dict[str, Any] = {}
    system = problem.system(ln)
    named = problem.named(ln)
    result_params, intervals = _physical_params(out, free, named, tied, dists)
    extra["at_lowest_minimum"] = lower is None
    if quality == "poor":
        extra["profile_intervals"] = intervals
        search = {n: (ln[j] - bounds[j][0], bounds[j][1] - ln[j]) for j, n in enumerate(free)}
        result_params, intervals = _physical_params(out, free, named, tied, search)
    warnings = _identifiability(out, problem, ln, bounds)
    warnings += _profile_warnings(free, dists, tied, lower)
    return FitResult(params=result_params, system=system, data=problem.data, free=free,
                     constraints={"natural_frequency": problem.natural_frequency,
                                  "normal_load": problem.normal_load,
                                  "quality_factor": problem.quality_factor},
                     warnings=warnings, chisqr=float(out.chisqr), redchi=float(out.redchi),
                     nfev=0, seconds=0.0, weighted=problem.weighted, guess=problem.guess,
                     intervals=intervals, extra=extra, quality=quality, p_value=p_value,
                     penalised=penalised)
