"""The fields of the model dataclasses checked against the schema's ranges."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibrofriction.schema import PARAMETER, parameter_names
from vibrofriction.validation import validated

FloatOrArray = float | NDArray[np.float64]


# --------------------------------------------------------------------------- validation
def valid_float(name: str, value: Any) -> float:
    """One model parameter as a float, checked against its schema range."""
    return float(validated({name: value})[name])


def valid_array(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """One model parameter as a float array, checked against its schema range."""
    return validated({name: value})[name]


def validate_fields(obj: Any, model: str) -> None:
    """Check the fields of a frozen model dataclass and store them as floats.

    The schema's ranges (:func:`~vibrofriction.validation.validated`); an optional field
    (``Parameter.twin``) left None stays None (its twin's value, whatever that is).
    """
    given = {name: getattr(obj, name) for name in parameter_names(model)}
    values = validated({n: v for n, v in given.items() if v is not None
                        or not PARAMETER[n].twin})
    for name, value in values.items():
        object.__setattr__(obj, name, float(value))
