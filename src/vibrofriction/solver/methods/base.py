"""The method protocol: what a solver declares it covers, and how it is called.

A method is a module of this package that defines one :class:`Method`: its
:class:`~vibrofriction.capabilities.Capabilities` (declared in
:mod:`vibrofriction.capabilities`, which the command line reads without importing the
solver) and ``solve(points, init_kind, init, settings)`` that writes the schema's output
columns and :class:`~vibrofriction.schema.Status` codes.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ...capabilities import INITIAL_KINDS, Capabilities, Limit, Refusal
from ...schema import FLOAT_COLUMNS, INT_COLUMNS
from ..points import PointTable
from ..settings import SolverSettings

__all__ = ["INITIAL_KINDS", "Capabilities", "Limit", "Method", "Refusal", "new_outputs"]

def new_outputs(n: int) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Output rows of ``n`` points: floats nan, integers 0."""
    return (np.full((n, len(FLOAT_COLUMNS)), np.nan),
            np.zeros((n, len(INT_COLUMNS)), dtype=np.int64))


class Method(Protocol):
    """A solver: its declared :class:`Capabilities` and its ``solve``."""

    capabilities: Capabilities

    def solve(self, points: PointTable, init_kind: int, init: NDArray[np.float64],
              settings: SolverSettings) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """Output rows (:data:`~vibrofriction.schema.FLOAT_COLUMNS`, ``INT_COLUMNS``) of ``points``.

        ``V >= 0`` (``V < 0`` is mirrored by the caller), started from ``init_kind``
        (:data:`INITIAL_KINDS`) and the rows ``init`` ``(y, x', e, phase)``.
        """
        ...
