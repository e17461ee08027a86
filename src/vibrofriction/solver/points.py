"""A table of points: every parameter of the dimensionless model, one row a point.

:class:`PointTable` is what the methods (:mod:`vibrofriction.solver.methods`) solve: its
columns are :data:`vibrofriction.schema.POINT_COLUMNS` (the dimensionless parameters in
the schema's order, the inertial velocity ``V`` and the choice ``inplane_on`` as the index
of its value), broadcast together and validated once, packed in one C-contiguous float
array that the kernels read by the schema's indices (:mod:`vibrofriction._kernels.codes`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..params import Dimensionless
from ..schema import CHOICES, PARAMETER, POINT_COLUMNS, point_index
from ..validation import checked_choice, validated

__all__ = ["PointTable", "point_table", "table_of"]

_CHOICE_NAMES = tuple(CHOICES)
_NUMBERS = tuple(n for n in POINT_COLUMNS if n not in CHOICES)


@dataclass(frozen=True)
class PointTable:
    """Points of the dimensionless model, one row each (``POINT_COLUMNS``).

    Parameters
    ----------
    values : numpy.ndarray
        ``(n, len(POINT_COLUMNS))`` floats, C-contiguous: row ``i`` is point ``i``; a
        choice's column holds the index of its value in ``Choice.values``.
    shape : tuple of int
        The broadcast shape of the inputs (``n`` is its product).
    """

    values: NDArray[np.float64]
    shape: tuple[int, ...]

    def __len__(self) -> int:
        """The number of points ``n``."""
        return self.values.shape[0]

    def __getitem__(self, name: str) -> NDArray[np.float64]:
        """The column ``name`` (a view)."""
        return self.values[:, point_index(name)]

    def take(self, rows: NDArray[np.intp]) -> PointTable:
        """The table of the points ``rows`` (increasing indices), flat.

        Where ``rows`` is every point, the same rows without a copy (a table is never
        written to).
        """
        n = len(rows)
        if n == len(self) and (n == 0 or (rows[0] == 0 and rows[-1] == n - 1)):
            return self if len(self.shape) == 1 else PointTable(self.values, (n,))
        return PointTable(np.ascontiguousarray(self.values[rows]), (len(rows),))

    def with_column(self, name: str, values: ArrayLike) -> PointTable:
        """A copy with the column ``name`` replaced."""
        out = self.values.copy()
        out[:, point_index(name)] = values
        return PointTable(out, self.shape)

    def choice(self, name: str, i: int) -> str:
        """The value of the choice ``name`` at point ``i``."""
        return CHOICES[name].values[int(self.values[i, point_index(name)])]

    def groups(self, name: str, rows: NDArray[np.intp]) -> list[tuple[str, NDArray[np.intp]]]:
        """The points ``rows`` by the value of the choice ``name``: ``(value, their rows)``."""
        codes = self[name][rows]
        return [(v, rows[codes == k]) for k, v in enumerate(CHOICES[name].values)
                if np.any(codes == k)]

    def system(self, i: int) -> Dimensionless:
        """Point ``i`` as a :class:`~vibrofriction.Dimensionless` system."""
        row = self.values[i]
        kw: dict[str, Any] = {n: float(row[point_index(n)]) for n in _NUMBERS
                              if n != "v_inertial"}
        kw.update({n: self.choice(n, i) for n in _CHOICE_NAMES})
        return Dimensionless(**kw)


def point_table(parameters: Mapping[str, ArrayLike | str | None]) -> PointTable:
    """Broadcast, validate and pack points of the dimensionless model.

    Parameters
    ----------
    parameters : mapping
        Values of the columns :data:`~vibrofriction.schema.POINT_COLUMNS` by name
        (arrays broadcast together; a choice a name or an array of names); a missing
        parameter takes its schema default, an optional one (``alpha_y``, ``zeta_y``)
        given as None its twin's values.  ``alpha``, ``beta``, ``amplitude`` and
        ``v_inertial`` are required.

    Returns
    -------
    PointTable
        The validated points; ``ValueError`` names the first parameter out of its range
        (:func:`vibrofriction.validation.validated`).
    """
    unknown = set(parameters) - set(POINT_COLUMNS)
    if unknown:
        raise TypeError(f"unknown parameter(s) {sorted(unknown)}: a point has "
                        f"{list(POINT_COLUMNS)}")
    given: dict[str, Any] = {}
    for name in _NUMBERS:
        value = parameters.get(name)
        if value is None:
            p = PARAMETER[name]
            if p.twin:
                value = given[p.twin]
            elif p.default is not None:
                value = p.default
            else:
                raise TypeError(f"{name} is required")
        given[name] = value
    codes = {name: _choice_codes(name, parameters.get(name, CHOICES[name].default))
             for name in _CHOICE_NAMES}
    # each value as given (a default a plain number, checked at once): a broadcast repeats
    # values, it adds none
    numbers = validated(given)
    columns = {**numbers, **codes}
    shape = np.broadcast_shapes(*(x.shape for x in columns.values()))
    values = np.empty((*shape, len(POINT_COLUMNS)))
    for name, x in columns.items():
        values[..., point_index(name)] = x
    values = values.reshape(math.prod(shape), len(POINT_COLUMNS))
    return PointTable(values, shape)


def _choice_codes(name: str, value: Any) -> NDArray[np.float64]:
    """The indices of the values of the choice ``name`` (one name or an array of names)."""
    allowed = CHOICES[name].values
    if isinstance(value, str):
        return np.asarray(float(allowed.index(checked_choice(name, value))))
    names = np.asarray(value, dtype=object)
    out = np.empty(names.shape)
    for i, v in enumerate(names.flat):
        out.flat[i] = allowed.index(checked_choice(name, str(v)))
    return out


def table_of(system: Dimensionless, v_inertial: ArrayLike) -> PointTable:
    """The points of ``system`` at the inertial velocities ``v_inertial``.

    The system was validated when it was made (it is frozen): only the velocities are
    checked here, the rest of each row is the system's.
    """
    V = validated({"v_inertial": v_inertial})["v_inertial"]
    row = np.empty(len(POINT_COLUMNS))
    for name in _NUMBERS:
        value = getattr(system, name) if name != "v_inertial" else math.nan
        if value is None:  # an optional parameter: its twin's value
            value = getattr(system, PARAMETER[name].twin)
        row[point_index(name)] = value
    for name in _CHOICE_NAMES:
        row[point_index(name)] = CHOICES[name].values.index(getattr(system, name))
    values = np.empty((V.size, len(POINT_COLUMNS)))
    values[:] = row
    values[:, point_index("v_inertial")] = V.ravel()
    return PointTable(values, V.shape)
