r"""Beyond the paper: the longitudinal in-plane oscillation (issue 20, docs/inplane.md).

The system is the issue's pin ``(alpha, beta, a) = (0.5, 2, 0.5)`` with a substrate
oscillation ``a_x = du_x m omega^2/(mu0 F_N0)`` along the sliding direction (the
vibration-velocity amplitude in units of the inertial velocity), velocities signed
(``V < 0`` slides backward; the solver's mirror).

* Fig. 14: the directions of oscillation for one pin, ``mu/mu0`` against ``V``: normal
  only, longitudinal only and combined at three phases, with the critical velocities of
  continuous sliding (:func:`theory.inplane_critical_velocity`) and the rigid body's
  kinematic law (:func:`theory.kinematic_mu_longitudinal`).
* Fig. 15: the combined drive over ``(phase_x, V)``: where friction is reduced, where the
  drive pushes (the mean force against the motion's sign: an actuator) and the boundary
  of continuous sliding ``|V| = V_c(phase_x)``.
* Fig. 16: the drive's characteristic against the phase: the blocking forces
  ``mu(V -> 0+-)`` beside the static band of the stuck contact
  (:func:`theory.inplane_static_mu_ratio`) and the idle velocity (``mu = 0``).

The transverse (2-D) oscillation is not in the solver and not drawn.
"""

from __future__ import annotations

from .common import A_X, DAMPING, DRIVE_AMPLITUDES, SYSTEM, V_BLOCK
from .directions import inplane_directions
from .drive import blocking_forces, idle_velocities, inplane_drive
from .phase_map import inplane_map

__all__ = [
    "A_X",
    "DAMPING",
    "DRIVE_AMPLITUDES",
    "SYSTEM",
    "V_BLOCK",
    "blocking_forces",
    "idle_velocities",
    "inplane_directions",
    "inplane_drive",
    "inplane_map",
]
