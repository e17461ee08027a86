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
poor after the first starts (chi-square probability below :data:`~.result.POOR_P`)
runs a second global stage with another seed.  Parameters are fitted as logarithms (all
are positive and span decades).  A row the model cannot evaluate (no trusted value of
the solver) costs more than any honest misfit of that row could
(:meth:`.problem.Problem.penalty`).

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
``points - free`` degrees of freedom): below :data:`~.result.POOR_P`, or when a
profile met a lower chi-square twice, the fit is not a description of the data within
``sigma`` (a wrong valley, a wrong model, a wrong constraint or an understated
``sigma``: the fit cannot tell which), ``res.quality`` says so, the report says so
first, and the intervals are the whole search range (the profile intervals, scaled by
``s^2``, are kept in ``res.extra["profile_intervals"]``).  An unweighted fit cannot be
judged.

A guess with a local friction law (``mu_static``, or ``friction=RateAndState(...)``) carries it
through every evaluation, and ``free`` may name the law's ``mu_static``, ``a``, ``b``, ``d_c``
(:data:`~.problem.LAW_FITTABLE`; :func:`.procedure.fit`, docs/bench.md "Fitting a friction
law"): their Jacobian columns are the solver's differences, and what the data cannot tell of
them is said by name (:func:`.uncertainty.law_warnings`: ``a - b`` from steady sliding).

The parts, each in its module, in the order :func:`fit` (:mod:`.procedure`) runs them: the problem
(:mod:`.problem`: the parameters in ``ln``, the constraints, the residuals and their
penalty, :func:`predict_cof`), the search (:mod:`.search`: the global stage and the
local starts), the uncertainties (:mod:`.uncertainty`: the profiles, what the data
do not identify) and the result (:mod:`.result`: :class:`FitResult` and its
verdict).
"""

from .problem import CONTACT_FITTABLE, FITTABLE, predict_cof, synthetic_measurements
from .procedure import CURVED_TOL, TRANSVERSE_RTOL, fit
from .result import FitResult

__all__ = ["CONTACT_FITTABLE", "CURVED_TOL", "FITTABLE", "FitResult", "TRANSVERSE_RTOL", "fit",
           "predict_cof", "synthetic_measurements"]
