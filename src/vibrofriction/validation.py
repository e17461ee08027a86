"""The one parameter validator of the package.

Every public entry point (parameters, closed forms, solver, sweep grids, figures)
checks its inputs through :func:`checked` and :func:`checked_beta`, so that a bad
value is refused with the same sentence everywhere: the parameter's name, the
allowed range and the first offending value.  The model's parameters are checked by
:func:`validated`, against their ranges in :data:`vibrofriction.schema.PARAMETERS`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .schema import CHOICES, PARAMETER, PARAMETERS, Range

__all__ = ["as_float_or_array", "checked", "checked_beta", "checked_choice", "checked_count",
           "checked_number", "range_text", "refuse_non_numbers", "validated"]

FloatOrArray = float | NDArray[np.float64]


def range_text(minimum: float | None = None, strict: bool = False,
               maximum: float | None = None, allow_inf: bool = False) -> str:
    """The allowed range in words, as the validator's errors say it.

    Parameters
    ----------
    minimum, strict, maximum, allow_inf : optional
        The range, as the fields of the same names of
        :class:`~vibrofriction.schema.Range` give it.

    Returns
    -------
    str
        The range's sentence (:meth:`vibrofriction.schema.Range.text`).

    Examples
    --------
    >>> from vibrofriction.validation import range_text
    >>> range_text(0.0, strict=True)
    'finite and > 0'
    >>> range_text(0.0, maximum=1.0)
    'finite and in [0, 1]'
    """
    return Range(minimum, strict, maximum, allow_inf).text()


def _plain(value: object) -> float | None:
    """``value`` as a float where it is one plain number, else None: the validator's shortcut.

    A plain number is a ``float`` or an ``int``, not a bool nor a numpy scalar (those take
    the array path).
    """
    if isinstance(value, float | int) and type(value) in (float, int):
        return float(value)
    return None


def _floats(name: str, value: ArrayLike) -> NDArray[np.float64]:
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number or an array of numbers, "
                         f"got {value!r}") from None


#: The dtype kinds of real numbers: signed and unsigned integers, floats (not bool, str, ...).
_REAL_KINDS = "iuf"


def _not_a_number(value: object) -> tuple[object] | None:
    """The first element of ``value`` that is no real number (a string, a bool, ...), if any.

    As a 1-tuple (the element may be None); None where every element is a real number, or
    where ``value`` is of a kind the float conversion judges itself.
    """
    if isinstance(value, str | bytes | bool | np.bool_):
        return (value,)
    if isinstance(value, np.ndarray | np.generic):
        kind = value.dtype.kind
        if kind in _REAL_KINDS or value.size == 0:
            return None
        flat = np.ravel(value)
        if kind != "O":
            return (flat[0],)
        value = flat.tolist()
    if isinstance(value, list | tuple):
        for v in value:
            bad = _not_a_number(v)
            if bad is not None:
                return bad
    return None


def refuse_non_numbers(name: str, value: object, allowed: Range) -> None:
    """ValueError naming ``name`` and its range where ``value`` holds a string or a bool.

    ``float("1.0")`` and ``float(True)`` are numbers to numpy; a model parameter given as
    either is more likely a mistake (a value read from a file, a flag) than meant.
    :func:`validated` runs it on every parameter (and a sweep's grid before it builds its
    axes); a text typed by a user is parsed first (:func:`checked` parses one).

    Parameters
    ----------
    name : str
        The parameter's name, for the error message.
    value : object
        The value given: a number, an array or a (nested) list of them.
    allowed : Range
        Its allowed values, named in the error message.

    Raises
    ------
    ValueError
        Where ``value`` holds a string, bytes or a bool.

    Examples
    --------
    >>> from vibrofriction.schema import FINITE
    >>> from vibrofriction.validation import refuse_non_numbers
    >>> refuse_non_numbers("phase_x", "1.0", FINITE)
    Traceback (most recent call last):
    ...
    ValueError: phase_x must be a real number or an array of them (finite), not a str: got '1.0'
    """
    if value.__class__ is float or value.__class__ is int:  # the common case, at once
        return
    bad = _not_a_number(value)
    if bad is not None:
        raise ValueError(f"{name} must be a real number or an array of them "
                         f"({allowed.text()}), not a {type(bad[0]).__name__}: got {value!r}")


def checked(name: str, value: ArrayLike, *, minimum: float | None = None,
            strict: bool = False, maximum: float | None = None,
            allow_inf: bool = False) -> NDArray[np.float64]:
    """Check a number or an array against a range.

    Parameters
    ----------
    name : str
        The parameter's name, for the error message.
    value : array_like
        The number(s) to check.
    minimum, strict, maximum, allow_inf : optional
        The range, as the fields of the same names of
        :class:`~vibrofriction.schema.Range` give it: ``minimum`` is exclusive when
        ``strict``, ``maximum`` inclusive, ``allow_inf`` admits ``+inf`` (a rigid
        contact, ``beta = inf``) but never ``nan``.

    Returns
    -------
    numpy.ndarray
        ``value`` as a float array (0-d for a scalar).

    Raises
    ------
    ValueError
        Naming ``name``, the allowed range and the first bad value.

    Examples
    --------
    >>> from vibrofriction.validation import checked
    >>> checked("alpha", [1.0, 2.0], minimum=0.0, strict=True)
    array([1., 2.])
    >>> checked("alpha", [1.0, -2.0], minimum=0.0, strict=True)
    Traceback (most recent call last):
    ...
    ValueError: alpha must be finite and > 0, got -2.0
    """
    x = _plain(value)
    if x is not None:  # one plain number: at once
        if not (math.isnan(x) or (math.isinf(x) and not allow_inf)
                or (minimum is not None and (x <= minimum if strict else x < minimum))
                or (maximum is not None and x > maximum)):
            return np.asarray(x)
    arr = _floats(name, value)  # (a bad plain number too: the message below)
    bad = np.isnan(arr)
    if not allow_inf:
        bad |= np.isinf(arr)
    with np.errstate(invalid="ignore"):
        if minimum is not None:
            bad |= (arr <= minimum) if strict else (arr < minimum)
        if maximum is not None:
            bad |= arr > maximum
    if np.any(bad):
        first = float(np.atleast_1d(arr)[np.atleast_1d(bad)][0])
        raise ValueError(
            f"{name} must be {range_text(minimum, strict, maximum, allow_inf)}, got {first!r}")
    return arr


def _in_range(name: str, value: ArrayLike, r: Range) -> NDArray[np.float64]:
    """:func:`checked` against the range ``r`` (its ``above`` aside)."""
    return checked(name, value, minimum=r.minimum, strict=r.strict, maximum=r.maximum,
                   allow_inf=r.allow_inf)


def _checked_above(name: str, value: ArrayLike, other: str,
                   other_value: ArrayLike) -> NDArray[np.float64]:
    """Check that a value exceeds another, elementwise.

    ``value`` as a float array, or ValueError unless ``value > other_value`` (``inf``
    allowed; ``nan`` never), elementwise.
    """
    x = _plain(value)
    if x is not None and np.ndim(other_value) == 0 and x > float(np.asarray(other_value)):
        return np.asarray(x)  # one plain number above a number: at once
    low = np.asarray(other_value, dtype=float)
    arr = _floats(name, value)
    with np.errstate(invalid="ignore"):
        bad = ~(arr > low)  # also nan
    if np.any(bad):
        low_b, arr_b, bad_b = np.broadcast_arrays(low, arr, bad)
        raise ValueError(f"{name} must be "
                         f"{Range(above=other).text(float(low_b[bad_b][0]))}, "
                         f"got {float(arr_b[bad_b][0])!r}")
    return arr


def checked_beta(alpha: ArrayLike, beta: ArrayLike) -> NDArray[np.float64]:
    """Check ``beta > alpha`` elementwise (``beta = inf`` allowed).

    Parameters
    ----------
    alpha, beta : array_like
        The dimensionless stiffnesses of the pin and of the contact (eq. 7).

    Returns
    -------
    numpy.ndarray
        ``beta`` as a float array.

    Raises
    ------
    ValueError
        Unless ``beta > alpha`` wherever they are compared (``nan`` never passes).

    Examples
    --------
    >>> from vibrofriction.validation import checked_beta
    >>> checked_beta(1.0, [10.0, float("inf")])
    array([10., inf])
    >>> checked_beta(1.0, 0.5)
    Traceback (most recent call last):
    ...
    ValueError: beta must be > alpha (= 1.0) or math.inf, got 0.5
    """
    return _checked_above("beta", beta, "alpha", alpha)


def validated(values: Mapping[str, ArrayLike], *,
              ranges: Mapping[str, Range] | None = None) -> dict[str, NDArray[np.float64]]:
    """The one check of the model's parameters.

    Each of ``values`` is checked against its schema :class:`~vibrofriction.schema.Range`.
    Checked in the schema's order, so the first bad one named is the first in the
    schema; a parameter that must exceed another (``beta > alpha``) is compared with
    it elementwise where both are given, and against its own ``minimum`` otherwise.
    ``ranges`` replaces the schema's range of some parameters, for a closed form whose
    domain is not the model's (``amplitude <= 1``: no jumping).  An optional parameter
    (``Parameter.twin``: ``k_y``, ``alpha_y``, ...) given as None takes its twin's value,
    which must be given too.

    Parameters
    ----------
    values : mapping of str to array_like
        Scalars or arrays by the names of :data:`~vibrofriction.schema.PARAMETERS`.
    ranges : mapping of str to Range, optional
        Ranges that replace the schema's for some parameters.

    Returns
    -------
    dict of str to numpy.ndarray
        The values as float arrays, in the order given.

    Raises
    ------
    ValueError
        Naming the parameter, its range and the first bad value; a string or a bool (a
        numeric string such as ``"1.0"`` too: not a number); or naming an unknown parameter.

    Examples
    --------
    >>> from vibrofriction.validation import validated
    >>> validated({"alpha": 1.0, "beta": [10.0, 100.0]})
    {'alpha': array(1.), 'beta': array([ 10., 100.])}
    >>> validated({"alpha": 1.0, "beta": 0.5})
    Traceback (most recent call last):
    ...
    ValueError: beta must be > alpha (= 1.0) or math.inf, got 0.5
    """
    unknown = [n for n in values if n not in PARAMETER]
    if unknown:
        raise ValueError(f"unknown model parameter(s) {unknown}; known: {list(PARAMETER)}")
    ranges = ranges or {}
    out: dict[str, NDArray[np.float64]] = {}
    for p in PARAMETERS:
        if p.name not in values:
            continue
        if p.twin and values[p.name] is None:  # optional: its twin's value
            if p.twin not in out:
                raise ValueError(f"{p.name} = None means the value of {p.twin}: give "
                                 f"{p.twin} too, or a value of {p.name}")
            out[p.name] = out[p.twin]
            continue
        r = ranges.get(p.name, p.range)
        refuse_non_numbers(p.name, values[p.name], r)
        if r.above and r.above in out:
            out[p.name] = _checked_above(p.name, values[p.name], r.above, out[r.above])
        else:
            out[p.name] = _in_range(p.name, values[p.name], r)
    _check_friction_law(out)
    return {n: out[n] for n in values}


#: Pairs of the friction law's parameters that cannot go together: ``(name, other, bad,
#: why)``, refused where ``bad(value, other's value)`` (the first offending value named).
_FRICTION_PAIRS: tuple[tuple[str, str, Any, str], ...] = (
    ("rs_b", "rs_a", lambda b, a: (b > 0.0) & (a == 0.0),
     "rs_b > 0 needs rs_a > 0 (rs_a = 0 is Coulomb friction)"),
    ("rs_alpha_ld", "rs_a", lambda al, a: (al > 0.0) & (a == 0.0),
     "rs_alpha_ld > 0 needs rs_a > 0 (rs_a = 0 is Coulomb friction)"),
    ("rs_alpha_ld", "rs_b", lambda al, b: (al > 0.0) & (b == 0.0),
     "rs_alpha_ld > 0 needs rs_b > 0 (the state's response to the normal force is "
     "alpha_ld/b)"),
    ("rs_alpha_ld", "amplitude", lambda al, am: (al > 0.0) & (am >= 1.0),
     "rs_alpha_ld > 0 needs amplitude < 1 (the response -(alpha_ld/b) theta n'/n diverges "
     "where the normal force reaches 0)"),
    ("static_ratio", "rs_a", lambda s, a: (s != 1.0) & (a > 0.0),
     "static_ratio > 1 is a law of Coulomb friction: it needs rs_a = 0"),
)


def _check_friction_law(out: Mapping[str, NDArray[np.float64]]) -> None:
    """Refuse the friction law's parameters that cannot go together (both given)."""
    for name, other, bad, why in _FRICTION_PAIRS:
        if name in out and other in out:
            if out[name].ndim == 0 and out[other].ndim == 0 \
                    and not bad(float(out[name]), float(out[other])):
                continue  # two numbers that go together: at once
            x, y = np.broadcast_arrays(out[name], out[other])
            hit = bad(x, y)
            if np.any(hit):
                i = np.flatnonzero(hit)[0]
                raise ValueError(f"{why}: got {name} = {float(x.flat[i]):g} with {other} = "
                                 f"{float(y.flat[i]):g}")


def checked_number(name: str, value: object, allowed: Range) -> float:
    """Check that ``value`` is one real number in the range ``allowed`` (a solver's setting).

    Parameters
    ----------
    name : str
        The setting's name, for the error message.
    value : object
        The value given.
    allowed : Range
        Its allowed values.

    Returns
    -------
    float
        ``value`` as a float.

    Raises
    ------
    ValueError
        In one sentence naming ``name`` and its range: a value out of range, nan, an array, a
        string or a bool.

    Examples
    --------
    >>> from vibrofriction.schema import POSITIVE
    >>> from vibrofriction.validation import checked_number
    >>> checked_number("tol", 1e-5, POSITIVE)
    1e-05
    >>> checked_number("tol", -1.0, POSITIVE)
    Traceback (most recent call last):
    ...
    ValueError: tol must be finite and > 0, got -1.0
    """
    refuse_non_numbers(name, value, allowed)
    # any object: checked() converts it to floats or says that it is not a number
    arr = _in_range(name, value, allowed)  # type: ignore[arg-type]
    if arr.ndim:
        raise ValueError(f"{name} must be one number ({allowed.text()}), got {value!r}")
    return float(arr)


def checked_count(name: str, value: object, minimum: int = 1) -> int:
    """Check that ``value`` is a whole number ``>= minimum`` (an integral float such as 3.0 too).

    Parameters
    ----------
    name, value : str, object
        The count's name (for the error message) and its value.
    minimum : int, optional
        The smallest count allowed.

    Returns
    -------
    int
        ``value`` as an int.

    Raises
    ------
    ValueError
        In one sentence naming ``name``: not a whole number (2.7, nan, a string, a bool),
        or below ``minimum``.

    Examples
    --------
    >>> from vibrofriction.validation import checked_count
    >>> checked_count("n_springs", 3.0)
    3
    >>> checked_count("n_springs", 2.7)
    Traceback (most recent call last):
    ...
    ValueError: n_springs must be a whole number >= 1 (such as 3 or 3.0), got 2.7
    """
    count = None
    if isinstance(value, int | float | np.integer | np.floating) \
            and not isinstance(value, bool | np.bool_) and float(value).is_integer():
        count = int(value)
    if count is None or count < minimum:
        raise ValueError(f"{name} must be a whole number >= {minimum} (such as {minimum + 2} "
                         f"or {minimum + 2}.0), got {value!r}")
    return count


def checked_choice(name: str, value: object) -> str:
    """Check that ``value`` is an allowed name of the choice ``name``.

    Parameters
    ----------
    name : str
        A choice of :data:`~vibrofriction.schema.CHOICES` (``"inplane_on"``).
    value : object
        The name given.

    Returns
    -------
    str
        ``value``, unchanged.

    Raises
    ------
    ValueError
        Naming the choice and its allowed names, unless ``value`` is one of them.

    Examples
    --------
    >>> from vibrofriction.validation import checked_choice
    >>> checked_choice("inplane_on", "substrate")
    'substrate'
    """
    allowed = CHOICES[name].values
    if not (isinstance(value, str) and value in allowed):
        raise ValueError(f"{name} must be one of {', '.join(map(repr, allowed))}, "
                         f"got {value!r}")
    return value


def as_float_or_array(x: ArrayLike) -> FloatOrArray:
    """A Python float for a scalar, else a float array.

    Parameters
    ----------
    x : array_like
        A number or an array of numbers.

    Returns
    -------
    float or numpy.ndarray
        ``float(x)`` for a 0-d input, else ``x`` as a float array.

    Examples
    --------
    >>> from vibrofriction.validation import as_float_or_array
    >>> as_float_or_array(2)
    2.0
    >>> as_float_or_array([1, 2])
    array([1., 2.])
    """
    arr = np.asarray(x, dtype=float)
    return float(arr) if arr.ndim == 0 else arr
