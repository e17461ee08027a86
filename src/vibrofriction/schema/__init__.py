"""The vocabulary: every parameter of the model and every quantity the solver returns, once.

Each :class:`Field` carries its name, kind, unit, long name and the paper's equation
(Mao, Popov, Starcevic & Popov, *Friction* 2017, Part II); the kernels' output columns
(:data:`FLOAT_COLUMNS`, :data:`INT_COLUMNS`), :class:`~vibrofriction.FrictionResult`,
the sweep's variables, the figures' curves, ``vibrofriction mu --json`` and the
explorer's curves are derived from :data:`FIELDS`.  :class:`Status` is the one status
vocabulary: each member carries its kernel code, its name, whether it is converged
and its message.  :class:`ContactState` is the one vocabulary of contact states (stick,
slip+, slip-, flight) of every solver: the kernels' codes and the names of histories,
results, figures and the explorer.  :data:`PARAMETERS` is the model's description: each
:class:`Parameter` carries its name, model, unit, long name, symbol, equation, allowed
:class:`Range` and default; :func:`vibrofriction.validation.validated` checks values
against it, and :class:`~vibrofriction.Dimensionless`, :class:`~vibrofriction.Physical`,
the sweep's coordinates, ``vibrofriction mu --json`` and the explorer follow it.

Standard library only: the numba kernels import it (their column indices, status codes
and contact-state codes come from here, :mod:`vibrofriction._kernels.codes`).
"""

from __future__ import annotations

from .fields import (
    CONTACT_STATE_NAMES,
    CONVERGED_CODES,
    ENERGY_UNIT,
    FIELD,
    FIELDS,
    FLOAT_COLUMNS,
    FORCE_UNIT,
    INT_COLUMNS,
    LENGTH_UNIT,
    NO_STATE,
    PARTIAL,
    RESULT_FIELDS,
    STATE_FIELDS,
    STATE_PREFIX,
    STATUS_BY_CODE,
    VELOCITY_UNIT,
    ContactState,
    Field,
    Status,
    cf_attrs,
    column_index,
)
from .history import HISTORY_FIELD, HISTORY_FIELDS, RADIUS_UNIT
from .parameters import (
    CHOICES,
    FINITE,
    METHOD_NAMES,
    MODELS,
    NONNEGATIVE,
    PARAMETER,
    PARAMETERS,
    POINT_COLUMNS,
    POSITIVE,
    Choice,
    Parameter,
    Range,
    choice_names,
    parameter_names,
    parameters,
    point_index,
)

__all__ = ["CHOICES", "CONTACT_STATE_NAMES", "CONVERGED_CODES", "Choice", "ContactState",
           "ENERGY_UNIT", "FIELD", "FIELDS", "FINITE", "FLOAT_COLUMNS", "FORCE_UNIT", "Field",
           "HISTORY_FIELD", "HISTORY_FIELDS", "INT_COLUMNS", "LENGTH_UNIT", "METHOD_NAMES",
           "MODELS", "NONNEGATIVE", "NO_STATE", "PARAMETER", "PARAMETERS", "PARTIAL",
           "POINT_COLUMNS", "POSITIVE", "Parameter", "RADIUS_UNIT", "RESULT_FIELDS", "Range",
           "STATE_FIELDS", "STATE_PREFIX", "STATUS_BY_CODE", "Status", "VELOCITY_UNIT", "cf_attrs",
           "choice_names", "column_index", "parameter_names", "parameters", "point_index"]
