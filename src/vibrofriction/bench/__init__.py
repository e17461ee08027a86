"""The bench: measured friction curves, the fit of the model, the design of the oscillation.

From measured friction curves to the model and back (docs/bench.md).

* :mod:`.measurements`: the table of measured points (:func:`read_measurements`);
* :mod:`.fitting`: the model fitted with honest uncertainties (:func:`fit`,
  :class:`FitResult`, :func:`synthetic_measurements` to try a fit before measuring), a
  package of parts one job each: :mod:`.fitting.problem` (parameters, constraints,
  residuals), :mod:`.fitting.search` (global stage, local starts),
  :mod:`.fitting.uncertainty` (profiles, identifiability), :mod:`.fitting.result`
  (:class:`FitResult`, the verdict) and :mod:`.fitting.procedure` (:func:`fit`, which
  runs them in that order);
* :mod:`.designing`: the oscillation that lowers friction most within an actuator's
  limits (:func:`design`, :class:`DesignResult`);
* :mod:`.setup`: the pin from what the experimenter knows (:func:`from_bench`,
  :func:`from_bench_file`, :func:`read_bench_file`), a :class:`vibrofriction.Physical`.

The pin's contact is described by :mod:`vibrofriction.contact`; the figures are
:func:`vibrofriction.figures.plot_fit` and :func:`vibrofriction.figures.plot_design`.
"""

from .designing import DesignResult, design
from .fitting import FITTABLE, FitResult, fit, predict_cof, synthetic_measurements
from .measurements import read_measurements
from .setup import from_bench, from_bench_file, read_bench_file

__all__ = ["FITTABLE", "DesignResult", "FitResult", "design", "fit", "from_bench",
           "from_bench_file", "predict_cof", "read_bench_file", "read_measurements",
           "synthetic_measurements"]
