r"""The macroscopic coefficient of friction and time histories (paper eqs. 21-25).

:func:`friction_coefficient` returns ``mu_macro / mu0 = <F_x>/<F_N>`` (eq. 25) in the
steady state, computed by the exact event-driven kernels of
:mod:`vibrofriction._kernels`; :func:`simulate` returns a densely sampled time
history (Fig. 2).  Velocities are given as ``vbar = v0/v0*`` (eq. 16), as the
inertial velocity ``v_inertial = v0 m omega/(mu0 F_N0)`` (the axis of Fig. 6, the
only one that exists in cases III and IV) or, for a :class:`Physical` system, as
``v0`` in m/s (:func:`vibrofriction.params.inertial_velocity`).

Modules: :mod:`.settings` (accuracy bounds, what is trusted), :mod:`.results` (what is
returned; its fields are :mod:`vibrofriction.schema`'s), :mod:`.engine` (the batch
engine), :mod:`.history` (time histories: :func:`simulate`; their types :class:`History`,
:class:`PlaneHistory`, :class:`CurvedHistory`, :class:`RateStateHistory` in
:mod:`.history_types`), :mod:`.energy` (their energy balance) and
:mod:`.sensitivity` (``d mu_ratio / d theta`` of the steady state: :func:`friction_gradient`,
:func:`solve_gradients`).
"""

from .._kernels.codes import NO_PHASE, PHASE_NAMES
from ..schema import FLOAT_COLUMNS, INT_COLUMNS, STATUS_BY_CODE, Status
from .engine import friction_coefficient, solve_points
from .history import CurvedHistory, Event, History, PlaneHistory, RateStateHistory, simulate
from .results import (
    SLOW_SETTLING,
    FrictionResult,
    FrictionResults,
    SectionState,
    describe,
    section_state,
)
from .sensitivity import SENSITIVE, Sensitivities, friction_gradient, solve_gradients
from .settings import SolverSettings, converged

__all__ = [
    "FLOAT_COLUMNS",
    "INT_COLUMNS",
    "SENSITIVE",
    "NO_PHASE",
    "PHASE_NAMES",
    "SLOW_SETTLING",
    "STATUS_BY_CODE",
    "CurvedHistory",
    "Event",
    "FrictionResult",
    "FrictionResults",
    "History",
    "PlaneHistory",
    "RateStateHistory",
    "SectionState",
    "Sensitivities",
    "SolverSettings",
    "Status",
    "converged",
    "describe",
    "friction_coefficient",
    "friction_gradient",
    "section_state",
    "simulate",
    "solve_gradients",
    "solve_points",
]
