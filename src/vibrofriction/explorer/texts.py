"""The explorer's sentences.

The curve's status and readout, a picked point's values and a curved tip's static value and critical
velocity.
"""

from __future__ import annotations

import math

import numpy as np

from . import compute
from .state import (
    State,
)

__all__ = ["curved_side_text", "point_text", "readout_text", "status_text"]


def vbar_refusal(state: State) -> str:
    """The library's message refusing the axis ``vbar`` for the state's curved tip."""
    import vibrofriction as vf

    try:
        vf.Dimensionless(0.5, 2.0, 0.5, profile_exponent=state.profile_exponent
                         ).vbar_to_inertial(1.0)
    except ValueError as exc:
        return str(exc)
    return "vbar is not available for this tip"


def curved_side_text(curve: dict, state: State) -> str:
    """The case and the curved tip's values beside the curve.

    The static value (none with ``a_x > 0``: it is the limit without the in-plane oscillation),
    the mean normal force, the critical velocity of continuous sliding (or the library's reason
    for none), and why ``V = 0`` is left out where it is.
    """
    static = (f"static value {curve['static']:.4g} (the smallest normal force over the "
              "mean)" if math.isfinite(curve["static"]) else
              "no static value (a curved tip's is that without the in-plane oscillation)"
              if curve["a_x"] > 0 else "no static value (the curve starts at V < 0)")
    crit = curve["critical"]
    critical = (f"critical velocity ({state.axis}) {crit:.4g} (continuous sliding above "
                "it: mu = mu0)" if math.isfinite(crit) else
                f"no critical velocity: {curve['critical_note']}" if curve["critical_note"]
                else "no finite critical velocity")
    text = (f"**case {curve['case']}**: {curve['case_text']}\n\n"
            f"**{curve['profile']}** (MDR): {static}; mean normal force "
            f"<F_N>/F_N0 = {curve['mean_normal']:.5g}; {critical}")
    if curve["rest_note"]:
        text += f"\n\n**{curve['rest_note']}**"
    return text


def status_text(state: State) -> str:
    """What is being computed, shown while the curve is under way."""
    if state.curved:
        return (f"computing {state.curve_points} points by the MDR solver "
                f"({compute.profile_text(state.profile_exponent)}: ~30 ms a point, up to "
                "a few tenths near the onset of sliding)...")
    return f"computing {state.curve_points} points..."


def point_text(curve: dict, i: int) -> str:
    """The results of the curve's point ``i``.

    ``mu/mu0`` (or the COF), its status, the mean normal force ``<F_N>/F_N0`` and the fractions
    of the contact disc in stick, slip and out of contact over the period (the flat punch: its
    time fractions).
    """
    def value(name: str, fmt: str) -> str:
        v = float(np.asarray(curve[name], dtype=float)[i])
        return format(v, fmt) if math.isfinite(v) else "none"  # e.g. the static limit

    trusted = bool(np.asarray(curve["trusted"])[i])
    return (f"{curve['y_label']} = {value('y', '.6g')} ({curve['status'][i]}"
            f"{'' if trusted else ', not trusted'}), <F_N>/F_N0 = "
            f"{value('mean_normal_ratio', '.5g')}, contact over the period: stick "
            f"{value('stick_area_fraction', '.3f')}, slip "
            f"{value('slip_area_fraction', '.3f')}, out of contact "
            f"{value('open_area_fraction', '.3f')}")


def readout_text(curve: dict) -> str:
    """The curve's summary.

    The mean over its trusted points only (an untrusted value is no answer), how many of the
    points are trusted, and the time it took.
    """
    y, ok = np.asarray(curve["y"], dtype=float), np.asarray(curve["trusted"], dtype=bool)
    n_ok = int(np.count_nonzero(ok))
    took = f"computed in {curve['seconds']:.2f} s"
    if n_ok == 0:
        return f"no trusted point of {y.size}: no mean; {took}"
    return (f"mean {curve['y_label']} = {np.mean(y[ok]):.6f} over the {n_ok} trusted of "
            f"{y.size} points; {took}")
