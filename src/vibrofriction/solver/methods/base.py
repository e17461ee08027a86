"""The method protocol: what a solver declares it covers, and how it is called.

A method is a module of this package that defines one :class:`Method`: its
:class:`Capabilities` (the points it is chosen for, the parameters it uses, the points it
refuses, the initial states, settings, outputs, sensitivities and histories it covers)
and ``solve(points, init_kind, init, settings)`` that writes the schema's output columns
and :class:`~vibrofriction.schema.Status` codes.  Every refusal message, the command
line's notes, the explorer's disabled controls and the table "what each solver covers"
(docs/solver.md) are made from these declarations: one place.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ...schema import FLOAT_COLUMNS, INT_COLUMNS
from ..points import PointTable
from ..settings import SolverSettings

__all__ = ["INITIAL_KINDS", "Capabilities", "Limit", "Method", "Refusal", "new_outputs"]

#: The kinds of initial state, by the kernels' code: steady sliding, rest, a section state.
INITIAL_KINDS = ("sliding", "rest", "section state")


class Refusal(ValueError):
    """A point, initial state or setting a method does not cover; ``parameter`` names the
    input refused (a parameter, ``"initial"`` or ``"settings.<field>"``)."""

    def __init__(self, message: str, parameter: str) -> None:
        super().__init__(message)
        self.parameter = parameter


@dataclass(frozen=True)
class Limit:
    """Points a method does not cover: ``what`` in words, named by ``parameter``.

    ``refuses(points)`` is True at the points refused (a :class:`PointTable`); ``whole``:
    every value of ``parameter`` but its default is refused (a control to disable).
    """

    parameter: str
    what: str
    refuses: Callable[[PointTable], NDArray[np.bool_]]
    whole: bool = False


@dataclass(frozen=True)
class Capabilities:
    """What a method covers, declared once.

    Parameters
    ----------
    name : str
        Its name in :data:`~vibrofriction.schema.METHOD_NAMES` (a result's ``method``).
    title : str
        What it is, for messages: ``"the MDR solver"``.
    takes : str
        The points it is chosen for, in words (:func:`vibrofriction.solver.methods.choose`).
    parameters : tuple of str
        The parameters it uses; the others do not change its results.
    limits : tuple of Limit
        The points it is chosen for but does not cover (refused with ``ValueError``).
    initial : tuple of str
        The initial states it starts from (:data:`INITIAL_KINDS`); the others are refused
        at ``V != 0``.
    settings : mapping
        The :class:`~vibrofriction.solver.SolverSettings` fields it honours, with its own
        default of each (a field set and not honoured is refused).
    outputs : tuple of str
        The output columns it computes (the others are nan, or 0 for an integer column).
    sensitivities : bool
        :func:`~vibrofriction.solver.friction_gradient` covers its points.
    histories : bool
        :func:`~vibrofriction.solver.simulate` covers its points.
    velocities : str
        How it treats ``V`` (the sign, ``V = 0``), in words.
    """

    name: str
    title: str
    takes: str
    parameters: tuple[str, ...]
    limits: tuple[Limit, ...]
    initial: tuple[str, ...]
    settings: Mapping[str, float | int]
    outputs: tuple[str, ...]
    sensitivities: bool
    histories: bool
    velocities: str
    notes: tuple[str, ...] = field(default=())

    def check(self, points: PointTable, init_kind: int, settings: SolverSettings) -> None:
        """``ValueError`` for the first point of ``points`` (all chosen for this method)
        that it does not cover, naming the parameter and its value, or the setting."""
        for limit in self.limits:
            bad = limit.refuses(points)
            if np.any(bad):
                i = int(np.flatnonzero(bad)[0])
                raise Refusal(f"{self.title} ({self.takes}) does not take {limit.what}: "
                              f"got {limit.parameter} = {_number(points[limit.parameter][i])}",
                              limit.parameter)
        kind = INITIAL_KINDS[init_kind]
        if kind not in self.initial and np.any(points["v_inertial"] != 0.0):
            raise Refusal(f"initial = {kind}: {self.title} ({self.takes}) starts from "
                          f"{' or '.join(self.initial)} only", "initial")
        self.check_settings(settings)

    def check_settings(self, settings: SolverSettings) -> None:
        """``ValueError`` naming the first field of ``settings`` that was set (not None) and
        that this method does not honour."""
        unknown = [k for k in settings.chosen() if k not in self.settings]
        if unknown:
            raise Refusal(f"settings.{unknown[0]} = {getattr(settings, unknown[0])} is not "
                          f"honoured by {self.title} ({self.takes}), which takes "
                          f"{', '.join(self.settings)} and tol_trusted: leave it None "
                          "(each method's default)", f"settings.{unknown[0]}")


def _number(x: float) -> str:
    """A number as a user writes it (``inf``, ``0.5``)."""
    return "inf" if math.isinf(x) and x > 0 else f"{float(x):g}"


def new_outputs(n: int) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Output rows of ``n`` points: floats nan, integers 0."""
    return (np.full((n, len(FLOAT_COLUMNS)), np.nan),
            np.zeros((n, len(INT_COLUMNS)), dtype=np.int64))


class Method(Protocol):
    """A solver: its declared :class:`Capabilities` and its ``solve``."""

    capabilities: Capabilities

    def solve(self, points: PointTable, init_kind: int, init: NDArray[np.float64],
              settings: SolverSettings) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """Output rows (:data:`~vibrofriction.schema.FLOAT_COLUMNS`, ``INT_COLUMNS``) of
        ``points`` (``V >= 0``: ``V < 0`` is mirrored by the caller), started from
        ``init_kind`` (:data:`INITIAL_KINDS`) and the rows ``init`` ``(y, x', e, phase)``."""
        ...
