"""The entry point :func:`design`.

The refusals, and the choice between the normal and the in-plane design.
"""

from __future__ import annotations

from ...params import Physical
from ...solver import SolverSettings
from .inplane import design_inplane
from .normal import design_normal
from .result import DesignResult

#: A curved (MDR) pin's map (the MDR solver, ~30 ms a point): this many frequencies and
#: normal amplitudes by default, and this many refinements from its lowest points.
CURVED_MAP = (25, 9)


CURVED_STARTS = 3
#: A pin with rate-and-state friction (the rate-and-state solver, ~5 ms a point, ~60 times
#: the event solver): the curved pin's smaller map and refinements (:data:`CURVED_MAP`,
#: :data:`CURVED_STARTS`), the normal oscillation only.
RATE_STATE_MAP = CURVED_MAP
RATE_STATE_STARTS = CURVED_STARTS


def design(pin: Physical, *, v0: float, omega: tuple[float, float],
           du_z: tuple[float, float], max_velocity_amplitude: float | None = None,
           du_x: tuple[float, float] | None = None, phase_x: float | None = None,
           inplane_on: str | None = None, goal: str = "friction",
           velocity_rule: str = "combined", n_omega: int | None = None,
           n_du_z: int | None = None, n_du_x: int = 9, n_phase: int = 16,
           starts: int | None = None,
           settings: SolverSettings | None = None, du_y: tuple[float, float] | None = None,
           phase_y: float | None = None, n_du_y: int = 4,
           n_phase_y: int = 4) -> DesignResult:
    """The oscillation that minimises the COF of ``pin`` at the sliding velocity ``v0``.

    The oscillation (``omega`` in rad/s, ``du_z`` in m, within the given ranges and
    ``omega du_z <= max_velocity_amplitude``) that minimises the COF of ``pin`` (eq. 25)
    at the sliding velocity ``v0`` (m/s); ``pin``'s own oscillation (``omega``, ``du_z``,
    ``du_x``, ``phase_x``) is not used (a pin with ``du_x > 0`` needs ``du_x=``: refused
    rather than ignored).

    ``du_z`` may start at 0 (no oscillation, ``COF = mu0``); the map then holds 0 and
    logarithmic amplitudes from ``ZERO_AMPLITUDE_FLOOR * high``.  ``settings``: the
    solver's (its ``tol_trusted`` decides which values are used).  Raises ValueError
    when no trusted point of the map respects the limits.

    **In-plane** (docs/bench.md): ``du_x=(lo, hi)`` (m, may start at 0) allows the
    longitudinal oscillation ``du_x cos(omega t + phase_x)`` on ``inplane_on`` (default
    the pin's); ``phase_x=None`` optimises the phase over ``[0, 2 pi)`` (a grid of
    ``n_phase``, then refined), a number fixes it.  The velocity limit applies to
    ``omega sqrt(du_z^2 + du_x^2)`` (``velocity_rule="combined"``) or to each of
    ``omega du_z``, ``omega du_x`` (``"each"``).  ``goal="friction"`` minimises the force
    magnitude ``|COF|`` at ``v0`` (the oscillation may push: ``mu < 0``),
    ``goal="drive"`` maximises the drive force ``-mu(v0)`` and reports the blocking
    force and the idle velocity; it needs ``du_x`` (a normal oscillation alone cannot
    drive).  The map is 4-D (default ``41 x 9 x n_du_x x n_phase``); ``directions``
    gives the best normal-only and longitudinal-only choices within the same limits.

    **Transverse** (``goal="friction"``): ``du_y=(lo, hi)`` (m) allows the oscillation
    across the sliding ``du_y cos(omega t + phase_y)`` (``phase_y=None``: free) instead of
    the longitudinal one (one in-plane direction at a time; the velocity limit applies to
    ``omega sqrt(du_z^2 + du_y^2)``, resp. each).  It is designed by the 2-D solver with the
    pin's ``k_y``, ``c_y``, on a smaller map (at most :data:`PLANE_MAP` frequencies and
    normal amplitudes, ``n_du_y x n_phase_y``, :data:`PLANE_STARTS` refinements): the rows
    ``"normal + transverse"`` and ``"transverse only"`` of ``directions``; the chosen
    oscillation is the best row (``system.du_y > 0`` where a transverse one wins).  The
    4-D ``map`` stays the one over ``du_x``, ``phase_x`` (only ``du_x = 0`` without
    ``du_x``).

    **Curved contact** (a pin of ``vf.from_bench(contact=..., contact_model="mdr")``,
    docs/bench.md): the same normal-oscillation design by the MDR solver, on a smaller map
    by default (:data:`CURVED_MAP`, :data:`CURVED_STARTS` refinements; ``starts`` default 8
    otherwise); ``du_z`` is the amplitude of the imposed indentation.  Refused by name what
    the MDR solver does not take: ``du_x``, ``du_y``, ``goal="drive"`` and a contact
    dashpot (``c_xc > 0``).

    **A local friction law** (docs/bench.md, "Fitting a friction law") is carried to every
    evaluation: a static coefficient (``mu_static``) everywhere the solvers take it (the
    normal, in-plane and transverse designs and the drive); rate-and-state friction
    (``friction=``) in the normal design only, on the smaller map of a curved pin
    (:data:`RATE_STATE_MAP`, :data:`RATE_STATE_STARTS`: the rate-and-state solver is ~100
    times slower a point): ``du_x``, ``du_y`` and ``goal="drive"`` are refused by name.
    """
    if pin.friction is not None:
        _refuse_for_rate_state(pin, du_x=du_x, du_y=du_y, goal=goal)
        n_omega = RATE_STATE_MAP[0] if n_omega is None else n_omega
        n_du_z = RATE_STATE_MAP[1] if n_du_z is None else n_du_z
        starts = RATE_STATE_STARTS if starts is None else starts
    if pin.curved:
        _refuse_for_mdr(pin, du_x=du_x, du_y=du_y, goal=goal)
        n_omega = CURVED_MAP[0] if n_omega is None else n_omega
        n_du_z = CURVED_MAP[1] if n_du_z is None else n_du_z
        starts = CURVED_STARTS if starts is None else starts
    starts = 8 if starts is None else starts
    _refuse_unused(pin, du_x=du_x, du_y=du_y, phase_x=phase_x, phase_y=phase_y,
                   inplane_on=inplane_on, goal=goal)
    if du_x is not None or du_y is not None or goal != "friction":
        return design_inplane(pin, v0=v0, omega=omega, du_z=du_z, du_x=du_x,
                               phase_x=phase_x, inplane_on=inplane_on, goal=goal,
                               velocity_rule=velocity_rule, vmax=max_velocity_amplitude,
                               n_omega=41 if n_omega is None else n_omega,
                               n_du_z=9 if n_du_z is None else n_du_z, n_du_x=n_du_x,
                               n_phase=n_phase, starts=starts, settings=settings,
                               du_y=du_y, phase_y=phase_y, n_du_y=n_du_y,
                               n_phase_y=n_phase_y)
    return design_normal(pin, v0=v0, omega=omega, du_z=du_z,
                          max_velocity_amplitude=max_velocity_amplitude,
                          n_omega=161 if n_omega is None else n_omega,
                          n_du_z=41 if n_du_z is None else n_du_z, starts=starts,
                          settings=settings)


def _refuse_for_rate_state(pin: Physical, *, du_x, du_y, goal) -> None:
    """ValueError naming what the design of a rate-and-state pin does not take."""
    for name, given in (("du_x", du_x is not None), ("du_y", du_y is not None),
                        ("goal='drive'", goal != "friction")):
        if given:
            raise ValueError(f"a pin with rate-and-state friction (friction = {pin.friction!r}) "
                             f"is designed for the normal oscillation only, not {name}: the "
                             "rate-and-state solver costs ~60 times the event solver a point "
                             "(an in-plane map of ~50 000 points) and does not take the "
                             "transverse oscillation nor a negative velocity")


def _refuse_for_mdr(pin: Physical, *, du_x, du_y, goal) -> None:
    """ValueError naming what the MDR solver does not take, for a curved pin."""
    for name, given in (("du_x", du_x is not None), ("du_y", du_y is not None),
                        ("goal='drive'", goal != "friction"),
                        ("a contact dashpot c_xc > 0", pin.c_xc > 0.0)):
        if given:
            raise ValueError(f"a curved MDR pin (profile_exponent = "
                             f"{pin.profile_exponent!r}) is designed by the MDR solver, "
                             f"which does not take {name} yet: design the normal "
                             f"oscillation alone")


def _refuse_unused(pin: Physical, *, du_x, du_y, phase_x, phase_y, inplane_on, goal) -> None:
    """ValueError where an oscillation of the pin or an option would not be used.

    The pin's own in-plane oscillation, or a phase or side given, that the design asked for would
    not use.
    """
    if du_y is None and pin.du_y > 0.0:
        raise ValueError(f"the pin has a transverse oscillation (du_y = {pin.du_y!r} m), "
                         f"which the design would not use: give du_y=(low, high) to design "
                         f"it, or a pin with du_y = 0")
    if du_y is None and phase_y is not None:
        raise ValueError("phase_y needs a transverse oscillation: give du_y=(low, high)")
    if du_y is not None and goal != "friction":
        raise ValueError("goal='drive' does not take a transverse oscillation (du_y) yet: "
                         "design the drive with du_x")
    if du_x is None and pin.du_x > 0.0:
        raise ValueError(f"the pin has an in-plane oscillation (du_x = {pin.du_x!r} m), which "
                         f"the design would not use: give du_x=(low, high) to design it, or "
                         f"a pin with du_x = 0")
    if du_x is None and goal == "friction" and (phase_x, inplane_on) != (None, None) \
            and du_y is None:
        raise ValueError("phase_x and inplane_on need an in-plane oscillation: give "
                         "du_x=(low, high)")
    if du_x is None and phase_x is not None:
        raise ValueError("phase_x needs a longitudinal oscillation: give du_x=(low, high)")
