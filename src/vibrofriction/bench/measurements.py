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
du_x      amplitude of the longitudinal in-plane oscillation     m, mm, um, nm
          (optional, docs/inplane.md)
phase_x   its phase relative to the normal one (optional)        rad, deg
du_y      amplitude of the transverse in-plane oscillation       m, mm, um, nm
          (optional; the 2-D solver, docs/inplane.md)
phase_y   its phase relative to the normal one (optional)        rad, deg
========  =====================================================  ==================

A unit is written in brackets after the name (``v0 [mm/s]``, ``du_z [um]``, ``omega
[Hz]``); without one the column is in the first unit of its row (SI).  Values are
converted to SI (``omega`` to rad/s, ``phase_x``, ``phase_y`` to rad).  Every value must be
finite; ``du_z``, ``du_x`` and ``du_y`` ``>= 0``, ``omega`` and ``sigma`` ``> 0``; ``v0 >= 0``
and ``cof >= 0`` unless the table has a ``du_x`` or ``du_y`` column (an in-plane
oscillation makes both signed: sliding backward, a drive).  Names match regardless of case
(``Sigma``, ``V0 [mm/s]``); other columns are ignored, unless a name is close to a known
one (``sigm``, ``du-z``: a misspelling, an error naming both).  A missing column, an
unknown unit or a bad value is a ``ValueError`` naming the column and, for a value, the
row (the line of a CSV file as an editor numbers it: comment lines and blank lines
count).
"""

from __future__ import annotations

import difflib
import io
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
    "du_x": {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "nm": 1e-9},
    "phase_x": {"rad": 1.0, "deg": math.pi / 180.0},
    "du_y": {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "nm": 1e-9},
    "phase_y": {"rad": 1.0, "deg": math.pi / 180.0},
}
#: The optional columns and their value where a table has none.
_OPTIONAL = {"sigma": math.nan, "du_x": 0.0, "phase_x": 0.0, "du_y": 0.0, "phase_y": 0.0}
_REQUIRED = ("v0", "cof", "du_z", "omega")
_MINIMUM = {"v0": (0.0, False), "cof": (0.0, False), "du_z": (0.0, False),
            "omega": (0.0, True), "sigma": (0.0, True), "du_x": (0.0, False),
            "phase_x": (-math.inf, True), "du_y": (0.0, False), "phase_y": (-math.inf, True)}
#: Columns that are signed where the table has an in-plane oscillation (a ``du_x`` or
#: ``du_y`` column).
_SIGNED_INPLANE = ("v0", "cof")
#: How close (difflib's ratio) an unknown column's name may come to a known one.
_MISSPELLING_CUTOFF = 0.75
_HEADER = re.compile(r"^\s*([^\[(]*?)\s*(?:[\[(]\s*([^\])]*)\s*[\])])?\s*$")


def _parse_header(name: object) -> tuple[str, str | None]:
    m = _HEADER.match(str(name))
    if not m:
        return str(name).strip(), None
    return m.group(1), (m.group(2).strip() if m.group(2) is not None else None)


def _read_csv(source: str | os.PathLike) -> tuple[pd.DataFrame, list[int]]:
    """The table of a CSV file and, per row, its line in the file.

    Lines are 1-based, every line counted: comments, blank lines and the header.
    """
    where = os.fspath(source)
    try:
        with open(source, encoding="utf-8-sig", newline="") as fh:
            text = fh.read()
    except FileNotFoundError:
        raise ValueError(f"no measurement file {where!r}") from None
    except UnicodeDecodeError as e:
        raise ValueError(f"{where!r} is not UTF-8 text ({e.reason} at byte {e.start})") from None
    records = [i for i, line in enumerate(re.split(r"\r\n|\r|\n", text), start=1)
               if line.split("#", 1)[0].strip()]
    try:
        frame = pd.read_csv(io.StringIO(text), comment="#", skipinitialspace=True)
    except pd.errors.EmptyDataError:
        raise ValueError(f"{where!r} holds no table") from None
    lines = records[1:] if len(records) == len(frame) + 1 else []  # else: quoted newlines
    return frame, lines


def _columns(frame: pd.DataFrame, where: str) -> dict[str, tuple[object, str | None]]:
    """The known columns of ``frame`` (matched regardless of case) with their header and unit.

    A name close to a known one but not it is an error.
    """
    columns: dict[str, tuple[object, str | None]] = {}
    for raw in frame.columns:
        name, unit = _parse_header(raw)
        key = name.lower()
        if key in COLUMNS:
            if key in columns:
                raise ValueError(f"column {key!r} appears twice in {where} "
                                 f"({columns[key][0]!r} and {raw!r})")
            columns[key] = (raw, unit)
            continue
        close = difflib.get_close_matches(key, COLUMNS, n=1, cutoff=_MISSPELLING_CUTOFF)
        if close:
            raise ValueError(f"column {raw!r} of {where} is not a measurement column but "
                             f"close to {close[0]!r}: rename it to {close[0]!r} or to a "
                             f"name unlike {list(COLUMNS)} (such columns are ignored)")
    missing = [c for c in _REQUIRED if c not in columns]
    if missing:
        raise ValueError(f"{where} lacks the column(s) {missing}; a measurement table has "
                         f"{list(_REQUIRED)} and optionally {list(_OPTIONAL)} "
                         "(docs/bench.md)")
    return columns


def read_measurements(source: str | os.PathLike | pd.DataFrame) -> pd.DataFrame:
    """A measured table (CSV path or DataFrame) as a DataFrame in SI units, checked.

    Parameters
    ----------
    source : str, os.PathLike or pandas.DataFrame
        A CSV file or a table (docs/bench.md: the columns, their units in the headers).

    Returns
    -------
    pandas.DataFrame
        The columns ``v0`` (m/s), ``cof``, ``du_z`` (m), ``omega`` (rad/s), ``sigma`` (nan
        where not given), ``du_x``, ``du_y`` (m) and ``phase_x``, ``phase_y`` (rad; 0 where
        not given), in the order of the input rows.

    Raises
    ------
    ValueError
        A missing or unreadable file, a missing, repeated or unknown column, an unknown
        unit, or a value that is not a finite number in its range (naming the column and
        the row).
    """
    if isinstance(source, pd.DataFrame):
        frame, lines, where = source, None, "the DataFrame"
    else:
        (frame, lines), where = _read_csv(source), os.fspath(source)
    columns = _columns(frame, where)
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
        if name in _SIGNED_INPLANE and ("du_x" in columns or "du_y" in columns):
            low, strict = -math.inf, True
        bad = ~np.isfinite(values) | ((values <= low) if strict else (values < low))
        if np.any(bad):
            i = int(np.flatnonzero(bad)[0])
            row = (f"row {frame.index[i]!r}" if lines is None else
                   f"line {lines[i]}" if lines else f"data row {i + 1}")
            rule = "" if math.isinf(low) else f" > {low:g}" if strict else f" >= {low:g}"
            value = frame[raw].iloc[i]
            value = repr(value) if isinstance(value, str) else str(value)
            raise ValueError(f"column {name!r}, {row}: {value} is not a finite number{rule}")
        out[name] = values * units[key]
    for name, missing in _OPTIONAL.items():
        if name not in out:
            out[name] = np.full(len(frame), missing)
    return pd.DataFrame({c: out[c] for c in (*_REQUIRED, *_OPTIONAL)})
