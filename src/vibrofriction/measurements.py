"""Measured friction curves: one table format, read and checked in one place (docs/bench.md).

A measurement table has one row per measured point and the columns

========  =====================================================  ==================
column    meaning                                                units accepted
========  =====================================================  ==================
v0        sliding velocity                                       m/s, mm/s, um/s
cof       measured coefficient of friction, ``<F_x>/<F_N>``      1 (dimensionless)
du_z      amplitude of the normal oscillation (indentation)      m, mm, um, nm
omega     drive frequency                                        rad/s, Hz
sigma     standard deviation of ``cof`` (optional)               1
========  =====================================================  ==================

A unit is written in brackets after the name (``v0 [mm/s]``, ``du_z [um]``, ``omega
[Hz]``); without one the column is in the first unit of its row (SI).  Values are
converted to SI (``omega`` to rad/s).  Every value must be finite; ``v0`` and ``du_z``
``>= 0``, ``omega`` and ``sigma`` ``> 0``, ``cof >= 0``.  A missing column, an unknown
unit or a bad value is a ``ValueError`` naming the column and, for a value, the row
(the line of a CSV file, counting the header as line 1).
"""

from __future__ import annotations

import math
import os
import re

import numpy as np
import pandas as pd

__all__ = ["COLUMNS", "read_measurements"]

#: Accepted units per column: factor to SI (omega: to rad/s).
COLUMNS: dict[str, dict[str, float]] = {
    "v0": {"m/s": 1.0, "mm/s": 1e-3, "um/s": 1e-6, "µm/s": 1e-6},
    "cof": {"1": 1.0, "": 1.0, "-": 1.0},
    "du_z": {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "nm": 1e-9},
    "omega": {"rad/s": 1.0, "hz": 2.0 * math.pi},
    "sigma": {"1": 1.0, "": 1.0, "-": 1.0},
}
_REQUIRED = ("v0", "cof", "du_z", "omega")
_MINIMUM = {"v0": (0.0, False), "cof": (0.0, False), "du_z": (0.0, False),
            "omega": (0.0, True), "sigma": (0.0, True)}
_HEADER = re.compile(r"^\s*([A-Za-z_0-9]+)\s*(?:[\[(]\s*([^\])]*)\s*[\])])?\s*$")


def _parse_header(name: object) -> tuple[str, str | None]:
    m = _HEADER.match(str(name))
    if not m:
        return str(name).strip(), None
    return m.group(1), (m.group(2).strip() if m.group(2) is not None else None)


def read_measurements(source: str | os.PathLike | pd.DataFrame) -> pd.DataFrame:
    """A measured table (CSV path or DataFrame) as a DataFrame in SI units, checked.

    Returns the columns ``v0`` (m/s), ``cof``, ``du_z`` (m), ``omega`` (rad/s) and
    ``sigma`` (nan where not given), in the order of the input rows.
    """
    from_file = not isinstance(source, pd.DataFrame)
    if from_file:
        try:
            frame = pd.read_csv(source, comment="#", skipinitialspace=True)
        except FileNotFoundError:
            raise ValueError(f"no measurement file {os.fspath(source)!r}") from None
        except pd.errors.EmptyDataError:
            raise ValueError(f"{os.fspath(source)!r} holds no table") from None
        where = os.fspath(source)
    else:
        frame = source
        where = "the DataFrame"
    columns: dict[str, tuple[object, str | None]] = {}
    for raw in frame.columns:
        name, unit = _parse_header(raw)
        if name in COLUMNS:
            if name in columns:
                raise ValueError(f"column {name!r} appears twice in {where}")
            columns[name] = (raw, unit)
    missing = [c for c in _REQUIRED if c not in columns]
    if missing:
        raise ValueError(f"{where} lacks the column(s) {missing}; a measurement table has "
                         f"{list(_REQUIRED)} and optionally 'sigma' (docs/bench.md)")
    if len(frame) == 0:
        raise ValueError(f"{where} has no rows")
    out = {}
    for name, (raw, unit) in columns.items():
        units = COLUMNS[name]
        key = (unit or next(iter(units))).lower()
        if key not in units:
            raise ValueError(f"column {name!r}: unit {unit!r} is not one of "
                             f"{[u for u in units if u]}")
        values = pd.to_numeric(frame[raw], errors="coerce").to_numpy(dtype=float)
        low, strict = _MINIMUM[name]
        bad = ~np.isfinite(values) | ((values <= low) if strict else (values < low))
        if np.any(bad):
            i = int(np.flatnonzero(bad)[0])
            row = f"line {i + 2}" if from_file else f"row {frame.index[i]!r}"
            rule = f"> {low:g}" if strict else f">= {low:g}"
            raise ValueError(f"column {name!r}, {row}: {frame[raw].iloc[i]!r} is not a finite "
                             f"number {rule}")
        out[name] = values * units[key]
    if "sigma" not in out:
        out["sigma"] = np.full(len(frame), np.nan)
    return pd.DataFrame({c: out[c] for c in (*_REQUIRED, "sigma")})
