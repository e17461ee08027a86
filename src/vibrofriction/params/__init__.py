r"""Parameters of the model: dimensionless groups, SI parameters and the cases I-IV.

Mao, Popov, Starcevic & Popov, *Friction* (2017), Part II: eq. (20) defines
``alpha = k_x/(m omega^2)`` and ``beta = (k_x + k_xc)/(m omega^2)``; eq. (12)
the critical velocity ``v0*``; eq. (16) ``vbar = v0/v0*``; Section 3 the
limiting cases I-IV. Velocities are also given as the *inertial velocity*
``V = v0 m omega / (mu0 F_N0)`` (axis of Fig. 6), which stays finite where
``vbar`` does not (cases III and IV).
"""

from __future__ import annotations

from .cases import Case, classify, inertial_to_vbar, vbar_to_inertial
from .conversion import System, dimensionless, inertial_velocity
from .dimensionless import Dimensionless
from .friction import RateAndState
from .physical import Physical, pin_damping

__all__ = ["Case", "Dimensionless", "Physical", "RateAndState", "System", "classify",
           "dimensionless", "inertial_to_vbar", "inertial_velocity", "pin_damping",
           "vbar_to_inertial"]
