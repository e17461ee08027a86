r"""Closed-form results of Mao, Popov, Starcevic & Popov, *Friction* (2017), Part II.

Every analytic formula of the paper lives here, once, vectorised over numpy
arrays (scalars in give floats out). Equation numbers refer to the paper; the
transcription numbers all equations of the resonant case IV "(32)", and they
are told apart below by what they compute.

Scaled variables (see ``docs/model.md``): time ``tau = omega t``; force unit
``mu0 F_N0``; length unit ``mu0 F_N0 / (m omega^2)``; velocity unit
``mu0 F_N0 / (m omega)``, in which the pulling velocity is the *inertial
velocity* ``V = v0 m omega / (mu0 F_N0)`` (the axis of Fig. 6). The paper's
groups are ``alpha = k_x/(m omega^2)``, ``beta = (k_x + k_xc)/(m omega^2)``
(eq. 20), ``a = du_z/u_z0`` and ``vbar = v0/v0*`` (eq. 16).

Defects of the paper corrected or made explicit here:

* eq. (27): the exponent printed ``1,2`` is read as 1.2 (decimal comma);
* eqs. (26), (27) are stated for ``a <= 1`` only (Fig. 4); for ``a > 1`` they
  would give a negative static friction, contradicting eq. (2), so they refuse;
* eqs. (21), (23) print the scaled contact force as
  ``(u_z0/du_z + cos tau)(alpha - 1)/(beta - 1)``; with ``xi = u_x omega/v0*``
  and ``v0*`` of eq. (12) (which has absolute values) the factor is
  ``|alpha - 1|/|beta - 1|``. As printed it is negative for ``alpha < 1 < beta``
  (e.g. the soft case I), i.e. friction would push the slider forward;
* case IV with jumping (``a > 1``): the paper's ``1 - a/2`` neglects loss of
  contact (and is negative for ``a > 2``); ``resonant_plateau`` and
  ``resonant_plateau_exact`` use ``n = max(0, 1 + a cos tau)`` and the mean
  normal force ``<n>`` instead.
"""

from __future__ import annotations

from .domains import FloatOrArray as FloatOrArray
from .inplane import (
    INPLANE_ON,
    Cancellation,
    InplaneStatic,
    PlaneStatic,
    inplane_cancellation,
    inplane_critical_velocity,
    inplane_regime,
    inplane_static_mu_ratio,
    kinematic_mu_longitudinal,
    kinematic_mu_transverse,
    plane_static_region,
)
from .inplane import INPLANE_REGIMES as INPLANE_REGIMES
from .inplane import PLANE_STATIC_SAMPLES as PLANE_STATIC_SAMPLES
from .jumping import Liftoff, liftoff_phases, mean_normal_force
from .jumping import mean_normal_force_of as mean_normal_force_of
from .profile import (
    dead_weight_indentation,
    mu_ratio_stiff_flat,
    mu_ratio_stiff_profile,
    profile_critical_velocity,
    profile_mean_normal_force,
    profile_static_mu_ratio,
)
from .rate_state import (
    critical_stiffness,
    critical_stiffness_rigid,
    sliding_eigenvalues,
    sliding_is_stable,
    sliding_polynomial,
    steady_mu_ratio,
    steady_slopes,
)
from .resonant import (
    resonant_damped_mu_ratio,
    resonant_plateau,
    resonant_plateau_exact,
    resonant_tau_star,
    resonant_velocity_ratio,
    resonant_velocity_ratio_exact,
)
from .sliding import (
    SOFT_EXPONENT,
    SteadySliding,
    critical_inertial_velocity,
    critical_velocity,
    critical_velocity_soft,
    critical_velocity_stiff,
    mu_ratio_soft,
    mu_ratio_soft_corrected,
    mu_ratio_stiff,
    static_mu_ratio,
    steady_sliding,
)
from .static_kinetic import (
    QuasiStaticSlip,
    static_kinetic_critical_velocity,
    static_kinetic_slip,
    static_kinetic_static_limit,
)
from .stiff import mu_ratio_stiff_exact

__all__ = [
    "Cancellation",
    "INPLANE_ON",
    "InplaneStatic",
    "Liftoff",
    "PlaneStatic",
    "QuasiStaticSlip",
    "SOFT_EXPONENT",
    "SteadySliding",
    "critical_inertial_velocity",
    "critical_stiffness",
    "critical_stiffness_rigid",
    "critical_velocity",
    "critical_velocity_soft",
    "critical_velocity_stiff",
    "dead_weight_indentation",
    "inplane_cancellation",
    "inplane_critical_velocity",
    "inplane_regime",
    "inplane_static_mu_ratio",
    "kinematic_mu_longitudinal",
    "kinematic_mu_transverse",
    "liftoff_phases",
    "mean_normal_force",
    "mu_ratio_soft",
    "mu_ratio_soft_corrected",
    "mu_ratio_stiff",
    "mu_ratio_stiff_exact",
    "mu_ratio_stiff_flat",
    "mu_ratio_stiff_profile",
    "plane_static_region",
    "profile_critical_velocity",
    "profile_mean_normal_force",
    "profile_static_mu_ratio",
    "resonant_damped_mu_ratio",
    "resonant_plateau",
    "resonant_plateau_exact",
    "resonant_tau_star",
    "resonant_velocity_ratio",
    "resonant_velocity_ratio_exact",
    "sliding_eigenvalues",
    "sliding_is_stable",
    "sliding_polynomial",
    "static_kinetic_critical_velocity",
    "static_kinetic_slip",
    "static_kinetic_static_limit",
    "static_mu_ratio",
    "steady_mu_ratio",
    "steady_sliding",
    "steady_slopes",
]
