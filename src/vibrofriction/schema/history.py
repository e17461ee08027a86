"""The quantities of a time history (:class:`~vibrofriction.History` and its subclasses).

See :mod:`vibrofriction.schema`; standard library only. Each sampled array of a history is
one :class:`~vibrofriction.schema.Field` here, with its unit and meaning (role
``"history"``); a quantity that is also a result's (the body velocity, the contact force, the
contact spring's elongation) is the result's field. ``to_xarray()`` and ``to_dataframe()`` of a
history take their attributes from :data:`HISTORY_FIELD`, as do its events (``event_*``).
"""

from __future__ import annotations

from dataclasses import replace

from .fields import (
    ENERGY_UNIT,
    FIELD,
    FORCE_UNIT,
    LENGTH_UNIT,
    PARTIAL,
    VELOCITY_UNIT,
    Field,
)

__all__ = ["HISTORY_FIELD", "HISTORY_FIELDS", "RADIUS_UNIT"]

#: The unit of a curved tip's positions along its profile: the contact radius at the mean
#: indentation (docs/contact_geometry.md).
RADIUS_UNIT = "a0"


def _h(name: str, kind: str, unit: str, long_name: str, symbol: str = "") -> Field:
    return Field(name, kind, unit, long_name, symbol=symbol, role="history")


def _of_result(name: str) -> Field:
    """A result's field (a component of the section state) as a history's sampled one."""
    return replace(FIELD[name], column=None, role="history", dtype="")


def _area(name: str, what: str) -> Field:
    return _h(name, "float", "1", f"fraction of the disc of the largest contact radius {what} "
              "at the sample (area-weighted)")


def _energy(name: str, long_name: str) -> Field:
    return _h(name, "float", ENERGY_UNIT, long_name + " since tau = 0 (docs/damping.md)")


#: Every sampled quantity of a history, in the order of the classes' fields (:class:`History`,
#: then :class:`PlaneHistory`'s, then :class:`CurvedHistory`'s own, then
#: :class:`RateStateHistory`'s), then its events'.
HISTORY_FIELDS: tuple[Field, ...] = (
    _h("tau", "float", "1", "drive time, omega t (sample times include every event's, on "
       "both sides)", "tau"),
    _h("x", "float", LENGTH_UNIT, "body position (laboratory frame)", "x"),
    _of_result("x_dot"),
    _of_result("f"),
    _h("n", "float", FORCE_UNIT, "normal contact force times mu0 (the friction limit: "
       "|f| <= n), n = F_N / F_N0", "n"),
    _h("phase", "str", "1", "state of the contact (ContactState: stick, slip+, slip-, "
       f"flight; a curved tip's '{PARTIAL}' where its springs in contact differ)"),
    _of_result("e"),
    _energy("work_input", "work done by the pulled end (and an oscillating substrate or "
            "holder)"),
    _energy("dissipated_pin", "energy dissipated by the pin's dashpot"),
    _energy("dissipated_contact", "energy dissipated by the contact's dashpot"),
    _energy("dissipated_friction", "energy dissipated by friction"),
    # the 2-D solver's (PlaneHistory)
    _h("u_y", "float", LENGTH_UNIT, "body position across the sliding", "u_y"),
    _h("u_y_dot", "float", VELOCITY_UNIT, "body velocity across the sliding", "u_y'"),
    _h("f_y", "float", FORCE_UNIT, "transverse contact force", "f_y"),
    _h("e_y", "float", LENGTH_UNIT, "transverse elongation of the contact spring", "e_y"),
    _h("slip_velocity", "float", VELOCITY_UNIT, "velocity of the contact point relative to "
       "the substrate, (x, y) components (0 in stick)"),
    _h("impulse", "float", FORCE_UNIT, "integral of the contact force over tau since tau = 0, "
       "(x, y) components"),
    _h("plane_state", "float", "", "state (y_x, y_y, v_x, v_y, e_x, e_y) at tau = 2 pi "
       f"floor(periods), positions in {LENGTH_UNIT}, velocities in {VELOCITY_UNIT}"),
    # a curved tip's (CurvedHistory)
    _h("xi", "float", RADIUS_UNIT, "position of each spring of the row along the profile "
       "(cell midpoints)", "xi"),
    _h("spring_state", "str", "1", "state of each spring of the row (ContactState: stick, "
       "slip+, slip-, flight = out of contact)"),
    _h("spring_f", "float", FORCE_UNIT, "tangential force of each spring of the row", "f_i"),
    _h("stick_radius", "float", RADIUS_UNIT, "position of the outermost stuck spring (0 if "
       "none)"),
    _h("contact_radius", "float", RADIUS_UNIT, "contact radius of the imposed indentation, "
       "max(0, 1 + a cos tau)^(1/n)"),
    _area("stick_area_fraction", "in stick"),
    _area("slip_area_fraction", "in slip, either way"),
    _area("open_area_fraction", "out of contact"),
    _h("normal_impulse", "float", FORCE_UNIT, "integral of n over tau since tau = 0"),
    # rate-and-state friction's (RateStateHistory; slip_velocity and impulse above)
    _h("theta", "float", "1 / omega", "state variable of rate-and-state friction (a time; "
       "theta/omega in seconds)", "theta"),
    _h("local_mu", "float", "1", "local coefficient of friction f/n, over mu0 = mu_star "
       "(nan in flight)", "mu/mu_star"),
    # the transitions (History.events), one entry each
    _h("event_tau", "float", "1", "drive time of each transition, omega t", "tau"),
    _h("event_kind", "str", "1", "kind of each transition (stick, slip, lift-off, "
       "touchdown, ...)"),
    _h("event_before", "str", "1", "state of the contact before each transition "
       "(ContactState)"),
    _h("event_after", "str", "1", "state of the contact after each transition "
       "(ContactState)"),
)

#: Every sampled quantity of a history by name.
HISTORY_FIELD: dict[str, Field] = {f.name: f for f in HISTORY_FIELDS}
if len(HISTORY_FIELD) != len(HISTORY_FIELDS):
    raise AssertionError("HISTORY_FIELDS: names must be unique")
