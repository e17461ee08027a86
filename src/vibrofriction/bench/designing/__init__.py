"""Designing the oscillation: the frequency and amplitude that minimise friction (docs/bench.md).

``design(pin, v0=..., omega=(lo, hi), du_z=(lo, hi), max_velocity_amplitude=None)``
solves the model (``COF = mu0 mu/mu0``, eq. 25) on a map over the actuator's range
(logarithmic in both, the pin's natural frequency and the contact resonance
``sqrt((k_x + k_xc)/m)`` added to the frequencies when they lie inside, because the
resonant optimum can be sharp), takes the lowest trusted points of the map that respect
the velocity limit ``omega * du_z <= max_velocity_amplitude``, and refines them by
Nelder-Mead in ``(ln omega, ln du_z)`` inside the limits.

Only trusted values are used (``SolverSettings.trusted``): an untrusted point of the
map is no candidate, an untrusted evaluation of the refinement is rejected, and an
untrusted row of the sensitivity table has no value.  The result counts them and says
in its ``status`` whether untrusted points lie next to the optimum (where a lower value
could hide).  The map is returned, so that the optimum can be seen to be the global one
within the limits and not a local dip.
"""

from __future__ import annotations

from .choosing import design
from .result import DESIGN_STATUSES, DesignResult
from .space import GOALS, VELOCITY_RULES

__all__ = ["DESIGN_STATUSES", "GOALS", "VELOCITY_RULES", "DesignResult", "design"]
