"""The rate-and-state solver: a flat punch sliding along x with rate-and-state friction.

The local coefficient depends on the slip rate and a state (docs/friction_laws.md,
"Rate-and-state friction"), so no phase is linear: the motion is integrated by a
Rosenbrock scheme with error control (:mod:`vibrofriction._kernels.rate_state`), and the
steady state is found by Newton's method on the period map where the response locks to the
drive, else averaged.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ... import theory
from ..._kernels import codes
from ..._kernels.rate_state import rs_steady_state_many
from ...capabilities import CAPABILITIES, Refusal
from ...params import Dimensionless
from ...schema import METHOD_NAMES
from ..points import PointTable
from ..settings import SolverSettings
from .base import new_outputs
from .event import contact_columns

__all__ = ["RATE_STATE", "rate_state_arguments", "refuse_rate_state"]

_CODE = METHOD_NAMES.index("rate_state")


class RateStateMethod:
    """The rate-and-state solver (:data:`RATE_STATE`)."""

    capabilities = CAPABILITIES["rate_state"]

    def solve(self, points: PointTable, init_kind: int, init: NDArray[np.float64],
              settings: SolverSettings) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """Output rows of ``points`` (``V > 0``, from steady sliding); see :class:`~.base.Method`.

        Status :attr:`~vibrofriction.Status.PERIODIC` where Newton's method found an
        attracting orbit of the period map (its multiplier from the exact monodromy; its
        error: the integration's, measured by the change of the orbit's mean from ``rtol``
        to ``rtol/20``, plus the next Newton step's),
        :attr:`~vibrofriction.Status.AVERAGED` where the motion is not locked to the drive
        and the last three doubling windows' means agree within ``tol_mean`` (the error their
        range plus twice the change of the last period's mean at ``rtol/20``, the
        integration's), else not converged or failed (``nan``, ``inf``).
        """
        out_f, out_i = new_outputs(len(points))
        rs_steady_state_many(points.values, *rate_state_arguments(settings), out_f, out_i)
        _unforced_unstable(points, out_f, out_i)
        contact_columns(out_f, points["amplitude"], slice(None))
        out_i[:, codes.I_METHOD] = _CODE
        return out_f, out_i


def _unforced_unstable(points: PointTable, out_f: NDArray[np.float64],
                       out_i: NDArray[np.int64]) -> None:
    """Never a periodic answer where steady sliding without oscillation is unstable.

    Without any oscillation (``amplitude = a_x = 0``) the orbit Newton's method finds is
    steady sliding, whose stability is known exactly (the Hurwitz conditions of
    :func:`vibrofriction.theory.sliding_is_stable`).  The kernel's multiplier is the exact
    monodromy's (the variational equations along the period map) and decides this on its
    own (tests/solver/test_rate_state_multiplier.py runs the kernel without this guard);
    the guard stays as an independent cross-check: a row it contradicts is not converged
    (its ``mu_ratio`` the steady sliding it sits on, its error ``inf``), not periodic.
    Not with contact damping (``eta_c > 0``): the theory's polynomial has no contact
    dashpot, which damps, so there the kernel's multiplier decides alone.
    """
    rows = np.flatnonzero((points["amplitude"] == 0.0) & (points["a_x"] == 0.0)
                          & (points["eta_c"] == 0.0)
                          & (out_i[:, codes.I_STATUS] == codes.ST_PERIODIC))
    for i in rows:
        p = {k: float(points[k][i]) for k in ("alpha", "beta", "zeta", "v_inertial", "rs_a",
                                              "rs_b", "rs_d_c", "rs_v_ref")}
        if not theory.sliding_is_stable(p["alpha"], p["beta"], p["zeta"], p["v_inertial"],
                                        p["rs_a"], p["rs_b"], p["rs_d_c"], p["rs_v_ref"]):
            out_i[i, codes.I_STATUS] = codes.ST_NOT_CONVERGED
            out_f[i, codes.O_ERR] = np.inf
            out_i[i, codes.I_PERIOD] = 0


def rate_state_arguments(settings: SolverSettings) -> tuple[float, int, float]:
    """``(rtol, max_periods, tol_mean)`` of the rate-and-state kernels.

    ``settings`` resolved with the method's defaults (a setting it does not honour is refused).
    """
    RATE_STATE.capabilities.check_settings(settings)
    r = settings.resolved(RATE_STATE.capabilities.settings)
    return float(r["rtol"]), int(r["max_periods"]), float(r["tol_mean"])


def refuse_rate_state(system: Dimensionless, caller: str, what: str) -> None:
    """Refuse a rate-and-state ``system`` where the solver does not declare ``what``.

    ``caller`` (``"friction_gradient"``: the solver has no sensitivities) would otherwise run
    the Coulomb kernels on it.

    Raises
    ------
    Refusal
        Naming ``rs_a``.
    """
    if system.rs_a > 0.0:
        c = RATE_STATE.capabilities
        raise Refusal(f"{caller} does not cover rate-and-state friction: {c.title} ({c.takes}) "
                      f"has no {what}: got rs_a = {system.rs_a:g}", "rs_a")


RATE_STATE = RateStateMethod()
