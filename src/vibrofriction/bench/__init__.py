"""The bench: measured friction curves, the fit of the model to them, the design of the
oscillation (docs/bench.md).

* :mod:`.measurements`: the table of measured points (:func:`read_measurements`);
* :mod:`.fitting`: the model fitted with honest uncertainties (:func:`fit`,
  :class:`FitResult`, :func:`synthetic_measurements` to try a fit before measuring),
  its parts one job each: :mod:`.fit_problem` (parameters, constraints, residuals),
  :mod:`.fit_search` (global stage, local starts), :mod:`.fit_uncertainty` (profiles,
  identifiability), :mod:`.fit_result` (:class:`FitResult`, the verdict);
* :mod:`.designing`: the oscillation that lowers friction most within an actuator's
  limits (:func:`design`, :class:`DesignResult`).

The pin itself is described by :class:`vibrofriction.Physical` (``from_bench``,
``from_bench_file``) and its contact by :mod:`vibrofriction.contact`; the figures are
:func:`vibrofriction.figures.plot_fit` and :func:`vibrofriction.figures.plot_design`.
"""

from .designing import DesignResult, design
from .fitting import FITTABLE, FitResult, fit, predict_cof, synthetic_measurements
from .measurements import read_measurements

__all__ = ["FITTABLE", "DesignResult", "FitResult", "design", "fit", "predict_cof",
           "read_measurements", "synthetic_measurements"]
