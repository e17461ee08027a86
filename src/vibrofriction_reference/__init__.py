"""Independent reference integrators for the in-plane model (Mao et al. 2017, Part II).

A package of its own: it imports nothing from ``vibrofriction`` (checked by an
import-linter contract), so that agreeing with it means something.

Two peers of the exact event-driven solver, written from the model statement
alone (``docs/model.md``) and sharing no code with it, so that tests can
use them to check it and benchmarks can time it against them.

Scaled variables (docs/model.md): time ``tau = omega t``, body position ``x``,
contact force ``f`` in units of ``mu0 F_N0``, pulling velocity ``V``::

    x'' = alpha (V tau - x) - f            n(tau) = max(0, 1 + a cos tau)
    |f| <= n;  finite contact stiffness k = beta - alpha: f = k (x - x_c),
    x_c' = 0 while |f| < n (stick), |f| = n with sign(x_c') = sign(f) (slip),
    f = 0 in flight (n = 0), touchdown in stick with f = 0;
    rigid contact (beta = inf): stick means x' = 0.

    mu_ratio = mu_macro / mu0 = <f> / <n>         (paper eq. 25)

Both peers work with the drift removed, ``y = x - V tau``, so that nothing grows
over long runs.

* **Peer B**, :func:`return_mapping_mu` -- fixed-step explicit dynamics in numba.
  Finite contact stiffness: velocity Verlet for the body, and the contact force
  from a return mapping (elastic predictor / plastic corrector) of the Jenkins
  element at every step. Rigid contact: Moreau's midpoint time-stepping (the
  friction impulse of each step is chosen in ``[-n dt, n dt]`` so that the
  body stops if it can). Averages by the trapezoid rule (Verlet) or the
  midpoint rule (Moreau), matching where each scheme evaluates the force.
  :func:`return_mapping_periods` gives the same run's mean ``f`` and ``n`` over
  each averaged drive period (to see whether a run has settled).
* **Peer A**, :func:`solve_ivp_mu` -- what a Python user would write today:
  :func:`scipy.integrate.solve_ivp` phase by phase with terminal events for the
  stick/slip switches; lift-off and touchdown times are known in closed form
  and cut the time axis; quadrature state variables accumulate the integrals of
  ``f`` and ``n``.

Damping (``docs/damping.md``): every public function takes ``zeta`` (the pin's damping
ratio, ``gamma = 2 zeta sqrt(alpha)``) and ``eta_c`` (the contact's loss factor, ``c =
eta_c (beta - alpha)``), both 0 by default, where the undamped code runs unchanged::

    x'' = alpha (V tau - x) + gamma (V - x') - f,
    f = k e + c (x' - x_c'),  e = x - x_c       (Kelvin-Voigt element + slider)

stick ``x_c' = 0``; slip ``f = s n``, ``c e' = s n - k e``; flight ``f = 0``, ``c e' = -k
e``; a rigid contact ignores ``eta_c``.  Peer B (:mod:`.damped`) keeps Verlet with both
dashpots trapezoidal and a return mapping of the Kelvin-Voigt element with exact
relaxation: second order, stable for any ``zeta, eta_c`` (Moreau with the pin dashpot for
a rigid contact).  Peer A adds ``e`` to its state when ``eta_c > 0`` and the events
``|k e + c x'| = n`` (stick ends) and ``x_c' = 0`` (slip ends).  Measured in
``tests/reference/test_reference_damped.py``: the peers agree to 2e-9-2e-7 on ten damped points of
every regime, peer B's history closes the energy balance at second order.

The in-plane oscillation of issue 20 (a 2-D tangential plane, the substrate or the holder
oscillating along and across the sliding direction): :func:`inplane_run` and
:func:`inplane_mean` (:mod:`.inplane`, ``solve_ivp`` phase by phase with events, written
from the model statement of ``docs/inplane_reference.md``; a finite contact only).

The MDR contact of issue 21 (a row of springs on the 1-D profile of ``z = c r^n``, each
with its own Coulomb law): :func:`mdr_mean` and :func:`mdr_reference` (:mod:`.mdr`,
``docs/contact_geometry.md``), the latter with an error bar from two resolutions.

Two local friction laws beyond Coulomb's (:mod:`.friction_laws`; the pin dashpot ``zeta``,
no contact dashpot), each with an error bar from two runs:

* static friction above kinetic, ``sigma = static_ratio = mu_static/mu0 >= 1`` (a stuck
  contact holds while ``|f| <= sigma n``, then the force drops to ``n`` and slips until
  the slip velocity would reverse): :func:`static_kinetic_run` (the mean, the error bar
  from ``N`` and ``2 N`` steps, the per-period means), :func:`static_kinetic_mu` (one
  resolution) and :func:`static_kinetic_history`.  Fixed steps, second order: velocity
  Verlet with a return mapping that keeps a stuck/slipping flag (finite contact), Moreau
  time-stepping (rigid), the drop of the force placed inside its step.  ``sigma = 1`` is
  Coulomb's law, the model of the two peers above.  :func:`static_kinetic_events_run`
  (:mod:`.static_events`) is the same law phase by phase with ``solve_ivp``, every switch
  an event: no step to place a switch in, where grazing switches and rigid touch-downs
  leave the fixed steps an error that does not fall smoothly;
* rate-and-state friction (``a, b, d_c, v_ref``, the aging or the slip law, the
  Linker-Dieterich coupling ``alpha_ld``; an elastic or rigid contact, the contact's
  dashpot ``eta_c``): :func:`rate_state_run` (the mean over a window
  after a transient, the error bar from two tolerances, the per-period means),
  :func:`rate_state_history` and :func:`mu_steady_state`.  ``solve_ivp`` (LSODA with an
  analytic Jacobian, Radau where LSODA fails) arc by arc, cut near lift-off and touch-down,
  flights in closed form.

Neither peer detects a periodic orbit: each averages over a fixed window after a
fixed transient, from a stated initial state. Compare them (and the main
solver) at the same transient/average windows when checking discretisation
error, or with windows long enough that the steady state is reached.

Parameters are plain floats and are not validated as physical parameters (that is
the caller's task, e.g. ``vibrofriction.Dimensionless``); only what an integrator
cannot run without is refused, with a ValueError naming the parameter and its range.
"""

from .events import PeerRun, solve_ivp_mu, solve_ivp_run
from .fixed_step import (
    PeriodMeans,
    ReferenceHistory,
    return_mapping_history,
    return_mapping_mu,
    return_mapping_periods,
)
from .friction_laws import (
    RateStateHistory,
    RateStateRun,
    StaticKineticHistory,
    StaticKineticRun,
    mu_steady_state,
    rate_state_history,
    rate_state_run,
    static_kinetic_history,
    static_kinetic_mu,
    static_kinetic_run,
)
from .inplane import InplaneMean, InplaneRun, inplane_mean, inplane_run
from .mdr import MDRMean, MDRReference, mdr_mean, mdr_reference
from .model import INITIAL_REST, INITIAL_SLIDING, steps_per_drive_period
from .static_events import StaticEventsRun, static_kinetic_events_run

__all__ = [
    "INITIAL_REST",
    "INITIAL_SLIDING",
    "InplaneMean",
    "InplaneRun",
    "MDRMean",
    "MDRReference",
    "PeerRun",
    "PeriodMeans",
    "RateStateHistory",
    "RateStateRun",
    "ReferenceHistory",
    "StaticEventsRun",
    "StaticKineticHistory",
    "StaticKineticRun",
    "inplane_mean",
    "inplane_run",
    "mdr_mean",
    "mdr_reference",
    "mu_steady_state",
    "rate_state_history",
    "rate_state_run",
    "return_mapping_history",
    "return_mapping_mu",
    "return_mapping_periods",
    "solve_ivp_mu",
    "solve_ivp_run",
    "static_kinetic_events_run",
    "static_kinetic_history",
    "static_kinetic_mu",
    "static_kinetic_run",
    "steps_per_drive_period",
]
