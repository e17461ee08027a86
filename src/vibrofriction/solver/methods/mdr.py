"""The MDR solver: a curved tip as a row of springs (docs/contact_geometry.md).

The method of dimensionality reduction maps an axisymmetric tip ``z = c r^n`` onto a row of
independent springs, each with its own stick, slip and loss of contact.  Where it covers the
point, the row's continuum limit is solved directly
(:mod:`vibrofriction.solver.mdr_continuum`); elsewhere rows of ``N`` and ``2N`` springs are
solved exactly and extrapolated in ``N`` (:func:`vibrofriction.solver.mdr.mdr_friction`).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ... import theory
from ..._kernels import codes
from ...capabilities import CAPABILITIES
from ...schema import METHOD_NAMES, Status, column_index
from ..mdr import mdr_friction
from ..points import PointTable
from ..settings import SolverSettings
from .base import new_outputs

__all__ = ["MDR"]

_CODE = METHOD_NAMES.index("mdr")
#: The package's status of each status of :func:`~vibrofriction.solver.mdr.mdr_friction`.
_MDR_STATUS = {"periodic": Status.PERIODIC, "averaged": Status.AVERAGED,
               "not converged": Status.NOT_CONVERGED, "continuous sliding": Status.SLIDING}


class MdrMethod:
    """The MDR solver of curved tips (:data:`MDR`)."""

    capabilities = CAPABILITIES["mdr"]

    def solve(self, points: PointTable, init_kind: int, init: NDArray[np.float64],
              settings: SolverSettings) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """Output rows of ``points`` (``V >= 0``), point by point; see :class:`~.base.Method`.

        Status: MDR ``"periodic"`` (the section state of the row without springs, or of
        the finer row, repeats after one period) is :attr:`Status.PERIODIC` (period 1),
        ``"averaged"`` :attr:`Status.AVERAGED`, ``"continuous sliding"`` (the row without
        springs, proven) :attr:`Status.SLIDING`, ``"not converged"``
        :attr:`Status.NOT_CONVERGED` (``mu_ratio`` nan, ``error`` inf) or, where a row made
        no progress (infinite error), :attr:`Status.FAILED`.  ``error`` is the solver's:
        the row without springs' (its orbits' difference at two tolerances plus its
        search's tolerance), or the difference of the rows of ``N`` and ``2N`` springs
        (the contact's discretisation) plus the orbits' errors.  ``periods`` and
        ``events`` are the solving row's (its periods, the events of its last period);
        ``work``, the time fractions of the single contact point, the Floquet and window
        columns and the final section state are nan.
        """
        r = settings.resolved(self.capabilities.settings)
        out_f, out_i = new_outputs(len(points))
        c = column_index
        out_f[:, c("lateral_ratio")] = 0.0
        out_i[:, codes.I_PHASE] = codes.NO_PHASE
        out_i[:, codes.I_METHOD] = _CODE
        for i in range(len(points)):
            am, pe, V = (float(points[k][i]) for k in ("amplitude", "profile_exponent",
                                                        "v_inertial"))
            out_f[i, c("mean_normal_ratio")] = theory.profile_mean_normal_force(am, pe)
            if V == 0.0:  # static_ratio = 1 here (the declared limits)
                out_f[i, c("mu_ratio")] = theory.profile_static_mu_ratio(am, pe)
                out_f[i, c("error")] = 0.0
                out_f[i, c("work")] = 0.0
                out_i[i, c("status")] = Status.STATIC.code
                continue
            m = mdr_friction(points["alpha"][i], points["beta"][i], am, V, pe,
                             zeta=points["zeta"][i], tol=settings.tol_trusted,
                             a_x=points["a_x"][i], phase_x=points["phase_x"][i],
                             inplane_on=points.choice("inplane_on", i),
                             # (None: the rows' default, the row without springs' for
                             # tol_trusted)
                             state_tol=settings.tol_state,
                             max_periods=int(r["max_periods"]),
                             static_ratio=float(points["static_ratio"][i]))
            status = _MDR_STATUS[m["status"]]
            mu, err = m["mu_ratio"], m["error"]
            if status is Status.NOT_CONVERGED:
                if not math.isfinite(err):
                    status = Status.FAILED
                mu, err = math.nan, math.inf
            out_f[i, c("mu_ratio")] = mu
            out_f[i, c("error")] = err
            for k in ("stick_area_fraction", "slip_area_fraction", "open_area_fraction"):
                out_f[i, c(k)] = m[k]
            out_i[i, c("status")] = status.code
            out_i[i, c("period")] = 1 if status is Status.PERIODIC else 0
            out_i[i, c("periods")] = m["periods"]
            out_i[i, c("events")] = m["events_per_period"]
        return out_f, out_i


MDR = MdrMethod()
