"""The explorer's sentences.

The curve's status and readout, a picked point's values and a curved tip's static value and critical
velocity.
"""

from __future__ import annotations

import math
from html import escape

import numpy as np

from . import compute
from .state import (
    State,
)

__all__ = ["curved_side_text", "flat_side_text", "mount_note", "point_text", "readout_text",
           "status_text", "vbar_refusal", "with_more"]


def with_more(short: str, more: str = "") -> str:
    """A short line, and the details behind a "more" toggle (HTML; both escaped).

    The side panel shows the line; ``more`` opens with a click (an HTML ``details``).
    """
    if not more:
        return escape(short)
    return (f"<span>{escape(short)}</span><details class=\"vf-more\"><summary>more</summary>"
            f"<div>{escape(more)}</div></details>")


def vbar_refusal(state: State) -> str:
    """The library's message refusing the axis ``vbar`` for the state's tip and drive.

    ``""`` where ``vbar`` is defined: without an in-plane oscillation, for a flat punch or a
    curved tip (its critical velocity of continuous sliding) without contact damping.  The
    tip, the in-plane amplitudes and ``eta_c`` are the state's; the groups a regular point
    (the resonances that leave ``vbar`` undefined are the axis's message, not a switch).
    """
    import vibrofriction as vf

    try:
        vf.Dimensionless(0.5, 2.0, 0.5, eta_c=state.eta_c, a_x=state.a_x, a_y=state.a_y,
                         profile_exponent=state.profile_exponent).vbar_to_inertial(1.0)
    except ValueError as exc:
        return str(exc)
    return ""


def mount_note(state: State) -> str:
    """Why the mount (substrate or holder) changes nothing here, or ``""`` where it matters.

    With neither ``a_x`` nor ``a_y`` the mount has nothing to move.  Otherwise the two
    mounts are the same drive where the in-plane force on the pin is the same
    (docs/inplane.md, "The exact solver"; the 2-D model of its section 6 alike): in the
    substrate's frame it is ``(1 - alpha) X - gamma X'`` on the substrate and ``alpha X +
    gamma X'`` on the holder, equal for every ``X`` iff ``alpha = 1/2`` and ``gamma = 2 zeta
    sqrt(alpha) = 0``; the contact (its damping ``eta_c`` included) sees the same relative
    motion in both.  Only a point held at ``V = 0`` (stuck through whole cycles, its value
    set by where it starts, not trusted) can differ.
    """
    if state.mode != "dimensionless":
        return ""
    if state.a_x == 0.0 and state.a_y == 0.0:
        return with_more("no in-plane oscillation (a_x = a_y = 0): the mount changes nothing",
                         "The mount says where the in-plane oscillation is imposed; without "
                         "one both choices are the same system.")
    if state.alpha == 0.5 and state.zeta == 0.0:
        return with_more(
            "at alpha = 1/2 without pin damping (zeta = 0) both mounts are the same drive: "
            "the same curve",
            "In the substrate's frame the in-plane oscillation X acts on the pin as the force "
            "(1 - alpha) X - gamma X' on the substrate and alpha X + gamma X' on the holder "
            "(gamma = 2 zeta sqrt(alpha)); they are equal for every X only at alpha = 1/2, "
            "zeta = 0. The contact, with its damping eta_c, sees the same relative motion in "
            "both (docs/inplane.md). Only a point held at V = 0, whose value depends on its "
            "start (not trusted), can differ.")
    return ""


def flat_side_text(curve: dict, state: State) -> str:
    """The case, the static value (or the stuck band) and the critical velocity (HTML).

    One short line; the case's description and the details behind "more".
    """
    crit, band = curve["critical"], curve["band"]
    if curve.get("law", "coulomb") != "coulomb":
        critical = (f"critical velocity ({state.axis}) {crit:.4g} (Coulomb's)"
                    if math.isfinite(crit) else "no critical velocity")
        short = f"case {curve['case']}; {curve['law_text']}: no static value; {critical}"
        more = ("V = 0 is left out of the curve: the 1-D solver has no static limit of a "
                "static coefficient (its value at rest depends on the slips), and "
                "rate-and-state friction creeps at every force. " + (
                    "The critical velocity of continuous sliding is Coulomb's (eq. 12): "
                    "a sliding contact never sticks again. " if curve["law"] == "static" else
                    "Eq. (12) is Coulomb's; the dashed line is steady sliding without "
                    "oscillation, mu_ss(v0)/mu0 (docs/friction_laws.md). "))
        return with_more(short, f"{more}{curve['case_text']}")
    if curve["a_y"] > 0:
        short = f"case {curve['case']}; no static value, no critical velocity"
        more = ("A transverse oscillation: no closed-form static value and no critical "
                "velocity (the slip keeps turning).")
    else:
        first = (f"static value {curve['static']:.4g}" if band is None else
                 f"stuck band {band[0]:.4g} (V -> 0+), {band[1]:.4g} (V -> 0-): {band[2]}")
        short = f"case {curve['case']}; {first}; critical velocity ({state.axis}) {crit:.4g}"
        more = ("The blocking forces of the closed-form stuck band (docs/inplane.md "
                "section 3). " if band is not None else
                "The static value is the limit v0 -> 0+ (eq. 2). ")
        if curve["jumping"]:
            more += "a > 1: eq. (12) is not the onset of sliding. "
    return with_more(short, f"{more}{curve['case_text']}")


def curved_side_text(curve: dict, state: State) -> str:
    """The case and the curved tip's values beside the curve (HTML: short, then "more").

    The static value (none with ``a_x > 0``: it is the limit without the in-plane oscillation),
    the mean normal force, the critical velocity of continuous sliding (or the library's reason
    for none), and why ``V = 0`` is left out where it is.
    """
    static = (f"static value {curve['static']:.4g}" if math.isfinite(curve["static"]) else
              "no static value")
    static_why = ("the smallest normal force over the mean" if math.isfinite(curve["static"])
                  else "a curved tip's is that without the in-plane oscillation"
                  if curve["a_x"] > 0 else "the curve starts at V < 0")
    crit = curve["critical"]
    critical = (f"critical velocity ({state.axis}) {crit:.4g}" if math.isfinite(crit) else
                "no critical velocity")
    critical_why = ("continuous sliding above it: mu = mu0" if math.isfinite(crit) else
                    curve["critical_note"] or "it is not finite")
    short = f"case {curve['case']}; {curve['profile']} (MDR): {static}; {critical}"
    more = (f"The {static} ({static_why}); the mean normal force <F_N>/F_N0 = "
            f"{curve['mean_normal']:.5g}; the {critical} ({critical_why}). "
            f"{curve['case_text']}")
    if curve["rest_note"]:
        short += "; V = 0 left out of the curve"
        more += f" {curve['rest_note']}."
    return with_more(short, more)


def status_text(state: State) -> str:
    """What is being computed, shown while the curve is under way."""
    if state.curved:
        return (f"computing {state.curve_points} points by the MDR solver "
                f"({compute.profile_text(state.profile_exponent)}: a few ms a point, more "
                "near the onset of sliding)...")
    if state.friction == "rate_state" and not state.curved:
        return (f"computing {state.curve_points} points by the rate-and-state solver (~10 ms a "
                "point; the first curve after an install compiles its kernels, about a "
                "minute)...")
    return f"computing {state.curve_points} points..."


def point_text(curve: dict, i: int) -> str:
    """The results of the curve's point ``i``.

    ``mu/mu0`` (or the COF), its status, the mean normal force ``<F_N>/F_N0`` and the fractions
    of the contact disc in stick, slip and out of contact over the period (the flat punch: its
    time fractions; a solver without stick and slip phases, rate-and-state friction whose
    contact creeps, says so).
    """
    def value(name: str, fmt: str) -> str:
        v = float(np.asarray(curve[name], dtype=float)[i])
        return format(v, fmt) if math.isfinite(v) else "none"  # e.g. the static limit

    trusted = bool(np.asarray(curve["trusted"])[i])
    stick, slip = value('stick_area_fraction', '.3f'), value('slip_area_fraction', '.3f')
    creeps = "method" in curve and curve["method"][i] == "rate_state"  # never sticks
    phases = ("stick and slip not separated by this solver" if creeps else
              f"stick {stick}, slip {slip}")
    return (f"{curve['y_label']} = {value('y', '.6g')} ({curve['status'][i]}"
            f"{'' if trusted else ', not trusted'}), <F_N>/F_N0 = "
            f"{value('mean_normal_ratio', '.5g')}, contact over the period: {phases}, "
            f"out of contact {value('open_area_fraction', '.3f')}")


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
