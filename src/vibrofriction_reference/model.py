"""What both reference integrators share: initial states, the normal force, contact angles.

Written from the model statement (``docs/model.md``), independently of the
``vibrofriction`` package (an import-linter contract forbids any import from it).
Parameters are plain floats; checking physical parameters is the caller's task
(the tests build every point from ``vibrofriction.Dimensionless``), and only what
an integrator cannot run without is refused here: :func:`check_parameters` for the
model, :func:`check_damping` for the dashpots (``zeta``, the pin's damping ratio, and
``eta_c``, the contact's loss factor: finite and ``>= 0``; ``docs/damping.md``).
"""

from __future__ import annotations

import math

from numba import njit

__all__ = ["INITIAL_REST", "INITIAL_SLIDING", "TWO_PI", "check_count", "check_damping",
           "check_parameters",
           "check_windows", "contact_angle", "initial_code", "normal", "steps_per_drive_period"]

INITIAL_SLIDING = 0
"""Initial state ``tau = 0, x = -1/alpha, x' = V, f = 1`` (sliding before the oscillation)."""
INITIAL_REST = 1
"""Initial state ``tau = 0, x = 0, x' = 0, f = 0``."""

TWO_PI = 2.0 * math.pi


def initial_code(initial) -> int:
    """0 (sliding) or 1 (rest) from a name or a code."""
    if isinstance(initial, str):
        codes = {"sliding": INITIAL_SLIDING, "rest": INITIAL_REST}
        if initial not in codes:
            raise ValueError(f"initial must be 'sliding' or 'rest', got {initial!r}")
        return codes[initial]
    code = int(initial)
    if code not in (INITIAL_SLIDING, INITIAL_REST):
        raise ValueError(f"initial must be 0 (sliding) or 1 (rest), got {initial!r}")
    return code


def check_parameters(alpha, beta, amplitude, V) -> tuple[float, float, float, float]:
    """Plain floats, or ValueError where the integrators cannot run (the least they need).

    This is not the package's parameter validation (``vibrofriction.Dimensionless``
    does that for the caller); it refuses only what would make the integrators
    meaningless: ``1/alpha`` in the initial state, a negative contact stiffness
    ``beta - alpha``, ``arccos(-1/a)`` and non-finite inputs.
    """
    alpha, beta, amplitude, V = float(alpha), float(beta), float(amplitude), float(V)
    if not (alpha > 0.0 and math.isfinite(alpha)):
        raise ValueError(f"alpha must be in (0, inf) (finite and > 0), got {alpha}")
    if not beta > alpha:
        raise ValueError(
            f"beta must be in (alpha, inf] (> alpha = {alpha}, math.inf for a rigid "
            f"contact), got beta={beta}")
    if not (amplitude >= 0.0 and math.isfinite(amplitude)):
        raise ValueError(f"amplitude must be in [0, inf) (finite and >= 0), got {amplitude}")
    if not math.isfinite(V):
        raise ValueError(f"V must be a finite number, got {V}")
    return alpha, beta, amplitude, V


def check_damping(zeta, eta_c) -> tuple[float, float]:
    """The damping ratio and the loss factor, checked.

    The pin's damping ratio and the contact's loss factor as floats, or ValueError
    naming the one that is negative or not finite.
    """
    out = []
    for name, value in (("zeta", zeta), ("eta_c", eta_c)):
        value = float(value)
        if not (value >= 0.0 and math.isfinite(value)):
            raise ValueError(f"{name} must be in [0, inf) (finite and >= 0), got {value}")
        out.append(value)
    return out[0], out[1]


def check_count(name: str, value, minimum: int) -> int:
    """``value`` as a whole number ``>= minimum``.

    ``value`` as an int, or ValueError naming ``name`` unless it is a whole number
    ``>= minimum``.
    """
    try:
        count = int(value)
    except (TypeError, ValueError, OverflowError):
        count = None
    if count is None or count != value or count < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")
    return count


def check_windows(transient_periods, average_periods) -> tuple[int, int]:
    """The transient and averaging windows as whole numbers of drive periods."""
    return (check_count("transient_periods", transient_periods, 0),
            check_count("average_periods", average_periods, 1))


def steps_per_drive_period(alpha: float, beta: float, steps_per_period: float) -> int:
    """Number of fixed steps per drive period ``2 pi`` used by :func:`return_mapping_mu`.

    ``steps_per_period`` steps per period of the fastest of the drive (frequency 1),
    the slip oscillation (``sqrt(alpha)``) and, for a finite contact, the stick
    oscillation (``sqrt(beta)``), rounded up to a whole number per drive period
    (at least 4). ``steps_per_period`` must be a finite number > 0.
    """
    steps_per_period = float(steps_per_period)
    if not (steps_per_period > 0.0 and math.isfinite(steps_per_period)):
        raise ValueError(
            f"steps_per_period must be in (0, inf) (finite and > 0), got {steps_per_period}")
    w = max(1.0, math.sqrt(alpha))
    if math.isfinite(beta):
        w = max(w, math.sqrt(beta))
    return max(4, int(math.ceil(steps_per_period * w - 1e-9)))


@njit(cache=True)
def normal(tau, a):
    """``n = max(0, 1 + a cos tau)``."""
    n = 1.0 + a * math.cos(tau)
    return n if n > 0.0 else 0.0


@njit(cache=True)
def contact_angle(a):
    """``theta = arccos(-1/a)`` (``a >= 1``): in contact while ``|tau mod 2 pi| < theta``.

    Lift-off at ``2 pi j + theta``, touch-down at ``2 pi (j + 1) - theta``.
    """
    return math.acos(-1.0 / a)
