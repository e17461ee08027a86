"""The axes of a sweep: one parameter's values, parsed from numbers or text."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..schema import PARAMETER
from ..validation import refuse_non_numbers

__all__ = ["Axis", "make_axis", "parse_axis"]


@dataclass(frozen=True, eq=False)
class Axis:
    """One parameter of the grid: ``values`` is 1-D if swept, 0-d if held fixed."""

    name: str
    values: NDArray[np.float64]

    @property
    def swept(self) -> bool:
        return self.values.ndim == 1

    def __len__(self) -> int:
        return self.values.size


def make_axis(name: str, value: ArrayLike) -> Axis:
    if name in PARAMETER:  # "1.0" or True: refused as the model's parameters are
        refuse_non_numbers(name, value, PARAMETER[name].range)
    try:
        arr = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number or a 1-D list/array of numbers, "
                         f"got {value!r}") from None
    if arr.ndim > 1:
        raise ValueError(f"{name} must be a scalar (held fixed) or a 1-D array (swept), "
                         f"got an array of shape {arr.shape}")
    if arr.size == 0:
        raise ValueError(f"{name}: empty grid (no values given)")
    arr.setflags(write=False)
    return Axis(name, arr)


def parse_axis(text: str, name: str) -> float | NDArray[np.float64]:
    """A grid axis from text: ``start:stop:num[:log]``, a single value, or a comma list.

    ``0:1.2:121`` is ``numpy.linspace(0, 1.2, 121)``; ``1e-2:1e2:41:log`` is
    ``numpy.geomspace(1e-2, 1e2, 41)``; ``0.5`` is held fixed; ``0.25,0.5,1`` (or
    ``0.5,`` for a one-value axis) is swept.  ``inf`` is accepted (``beta``).

    Parameters
    ----------
    text : str
        The axis as the command line ``vibrofriction sweep`` takes it.
    name : str
        The parameter's name, for the error messages.

    Returns
    -------
    float or numpy.ndarray
        A float for a value held fixed, a 1-D array for a swept axis.

    Raises
    ------
    ValueError
        For text that is none of the three forms.

    Examples
    --------
    >>> from vibrofriction.sweep import parse_axis
    >>> parse_axis("0:1.2:4", "vbar")
    array([0. , 0.4, 0.8, 1.2])
    >>> parse_axis("1e-2:1e2:5:log", "alpha")
    array([1.e-02, 1.e-01, 1.e+00, 1.e+01, 1.e+02])
    >>> parse_axis("0.5", "amplitude")
    0.5
    """
    text = text.strip()
    if not text:
        raise ValueError(f"{name}: empty value")

    def number(t: str) -> float:
        try:
            return float(t)
        except ValueError:
            raise ValueError(f"{name}: {t.strip()!r} is not a number (in {text!r})") from None

    if ":" in text:
        parts = [p.strip() for p in text.split(":")]
        log = len(parts) == 4 and parts[3].lower() in ("log", "geom")
        if len(parts) not in (3, 4) or (len(parts) == 4 and not log):
            raise ValueError(f"{name}: a range is start:stop:num or start:stop:num:log, "
                             f"got {text!r}")
        start, stop = number(parts[0]), number(parts[1])
        try:
            num = int(parts[2])
        except ValueError:
            raise ValueError(f"{name}: the number of values in {text!r} must be an "
                             f"integer, got {parts[2]!r}") from None
        if num < 1:
            raise ValueError(f"{name}: empty grid (num = {num} in {text!r})")
        if not (math.isfinite(start) and math.isfinite(stop)):
            raise ValueError(f"{name}: range ends must be finite, got {text!r}")
        if log:
            if not (start > 0 and stop > 0):
                raise ValueError(f"{name}: a log range needs start, stop > 0, got {text!r}")
            return np.geomspace(start, stop, num)
        return np.linspace(start, stop, num)
    if "," in text:
        items = [t for t in text.split(",") if t.strip()]
        if not items:
            raise ValueError(f"{name}: empty grid (no values in {text!r})")
        return np.array([number(t) for t in items])
    return number(text)
