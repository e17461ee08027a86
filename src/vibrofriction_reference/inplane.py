"""Reference integrator of the in-plane oscillation model (issue 20): a 2-D tangential plane.

Written from the model statement (``docs/model.md``, ``docs/damping.md`` and the in-plane
brief of issue 20), independently of ``vibrofriction`` (an import-linter contract forbids
any import from it) and of the 1-D peers of this package (it shares only the plain
argument checks of :mod:`.model`).  Method: :func:`scipy.integrate.solve_ivp` (DOP853,
tight tolerances) phase by phase, with terminal events at the stick/slip switches and the
time axis cut at every drive period, lift-off and touch-down.  Chosen to be simple and
obviously right, not fast (tens of ms per drive period in Python).

Scaled variables (``tau = omega t``, forces in ``mu0 F_N0``, lengths in ``mu0 F_N0 /
(m omega^2)``), body position ``u = (u_x, u_y)``, drift removed ``y = u - (V tau, 0)``,
body velocity ``v = u'``, ``n = max(0, 1 + a cos tau)``::

    X = a_x cos(tau + phase_x),  Y = a_y cos(tau + phase_y)      (the in-plane oscillation)
    holder:    h = (V tau + X, Y), substrate velocity v_s = 0
    substrate: h = (V tau, 0),     substrate velocity v_s = (X', Y')
    v_x' = alpha   (h_x - u_x) + gamma_x (h_x' - v_x) - f_x,  gamma_x = 2 zeta sqrt(alpha)
    v_y' = alpha_y (h_y - u_y) + gamma_y (h_y' - v_y) - f_y,  gamma_y = 2 zeta_y sqrt(alpha_y)
    f = k e + c e',  e = u - u_c,  k = beta - alpha,  c = eta_c k,  |f| <= n

with ``u_c`` the contact point.  Stick: ``u_c' = v_s``.  Slip: ``f = n w/|w|`` with ``w =
u_c' - v_s`` the slip velocity (the force on the body, ``-f``, opposes it).  Flight (``n =
0``): ``f = 0``.

**Jenkins contact** (``eta_c = 0``): stick ``e' = v - v_s``, ``f = k e``, until ``|k e|``
reaches ``n``.  Slip: ``f = n d`` with ``d`` a unit vector (the state holds ``d``, not
``e``, so that the direction survives ``n -> 0``); from ``f = k e`` and ``e' = v - v_s -
lam d`` (``lam = |w| >= 0``)::

    d' = (k / n) (w_b - (d . w_b) d),   lam = d . w_b - n' / k,   w_b = v - v_s

(the direction turns towards the body's velocity relative to the substrate); slip ends
when ``lam`` falls to 0 (then stick, ``e = n d / k``).  Flight: ``e = 0``.  Touch-down:
``e = 0``; stick if ``n' >= k |w_b|`` (the cone opens faster than the spring loads), else
slip along ``w_b``.  ``d'`` is stiff where ``n`` is small; for ``a > 1`` each contact arc
is shortened by ``delta = 1e-7`` at both ends (flight there), which moves ``<f>`` by about
``a delta^2``, far below the tolerances.  With one component (``a_y = 0``) ``d = (+-1, 0)``
and this is the 1-D Jenkins element of ``docs/model.md``.

**Kelvin-Voigt contact** (``eta_c > 0``): with ``F = k e + c (v - v_s)`` (the force if the
contact point moved with the substrate) the phase is a function of the state: stick while
``|F| <= n`` (``f = F``, ``e' = v - v_s``); else slip along ``F``: ``f = n F/|F|``, ``lam =
(|F| - n) / c``, ``e' = v - v_s - lam F/|F|``; flight ``c e' = -k e``.  Events at ``|F| =
n`` split the run where the right-hand side has a kink.

**Not covered**: a rigid contact (``beta = inf``; use a large finite ``beta``) and the
grazing amplitude ``a = 1`` with a 2-D Jenkins contact (``d'`` singular where ``n``
touches 0).  Pairs of close roots of an event function inside one step (a stick or slip
much shorter than a step) can be missed; the step is capped at a quarter of the fastest
natural period to make this unlikely.

Energy (``E = |v|^2/2 + alpha (h_x - u_x)^2/2 + alpha_y (h_y - u_y)^2/2 + k |e|^2/2``)::

    E' = P_in - D',   P_in = F_pin . h' - f . v_s,   F_pin = alpha (h - u) + gamma (h' - v)
    D' = gamma_x (h_x' - v_x)^2 + gamma_y (h_y' - v_y)^2 + c |e'|^2 + n lam   (each >= 0)

``P_in`` is the power of the holder and of the substrate; both integrals are state
variables, so a run reports the energy balance per period.

Initial states: ``"sliding"`` with ``s = sign(V)``: ``y = (-s/alpha, 0)``, ``v = (V, 0)``,
``e = (s/k, 0)`` (``f = (s, 0)`` if it sticks; with ``c > 0`` the phase follows from ``F``);
for ``V > 0`` this is the 1-D peers' sliding state, and for ``V = 0`` it is ``"rest"``:
``y = v = e = 0``.  An explicit start is a tuple ``(y_x, v_x, e_x)`` (laboratory frame,
transverse components 0): e.g. a body at rest held by a preload ``F``, ``(-F/alpha, 0,
F/k)`` (the phase follows from the state as at any start).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from .model import TWO_PI, check_count, check_damping, check_parameters, initial_code

__all__ = ["InplaneMean", "InplaneRun", "inplane_mean", "inplane_run"]

_STICK, _SLIP, _FLIGHT = 0, 1, 2
_DELTA = 1e-7
"""Jenkins contact, ``a > 1``: each contact arc is shortened by this at both ends."""
_MARGIN = 1e-12
"""At a switch the new phase starts this (relative) distance inside its domain."""
_VIOLATION = 1e-8
"""A step end this far outside its phase's domain (``n - |f|`` in stick, the slip speed in
slip) means an event was missed: RuntimeError."""
_N_STATE = 11
# state: 0,1 y; 2,3 v; 4,5 e (or d in Jenkins slip); 6 I_fx; 7 I_fy; 8 I_n; 9 W_in; 10 D


@dataclass(frozen=True)
class InplaneRun:
    """One run of :func:`inplane_run`: means over the averaging window and per period.

    ``mu_ratio = mean_fx / mean_n``, ``lateral_ratio = mean_fy / mean_n``.  ``period_fx``,
    ``period_fy``, ``period_n`` are the means over each averaged drive period.
    ``stick_fraction``, ``slip_fraction``, ``flight_fraction``: shares of the window's
    time.  ``energy_residual[j]``: over averaged period ``j``, ``|E_end - E_start - W_in +
    D| / max(W_in, D, 1e-300)`` (0 up to the integration error); ``period_work``,
    ``period_dissipation`` the two integrals per period (``D >= 0`` per period).
    ``max_force_excess``: the largest ``|f| - n`` over every step end and event (``<= 0``
    up to round-off).  Counters as :class:`PeerRun`.  ``final_state`` is ``(tau, u_x, u_y,
    v_x, v_y, f_x, f_y)``.
    """

    mu_ratio: float
    lateral_ratio: float
    mean_fx: float
    mean_fy: float
    mean_n: float
    stick_fraction: float
    slip_fraction: float
    flight_fraction: float
    period_fx: np.ndarray
    period_fy: np.ndarray
    period_n: np.ndarray
    period_work: np.ndarray
    period_dissipation: np.ndarray
    energy_residual: np.ndarray
    max_force_excess: float
    n_events: int
    n_solve_ivp: int
    nfev: int
    final_state: tuple[float, ...]


@dataclass(frozen=True)
class InplaneMean:
    """Steady-state means of :func:`inplane_mean` with error estimates.

    ``mu_ratio = <f_x>/<n>`` and ``lateral_ratio = <f_y>/<n>`` over the averaging window;
    ``mu_error``, ``lateral_error`` estimate ``|value - steady-state value|``: the sum of
    the window's spread (the larger of the difference between the means over its two
    halves and three standard errors of the means of ten blocks) and the integration
    error (the difference from a run at ``1000 rtol``, ``1000 atol``, if asked).  Time
    fractions of stick, slip and flight over the window; ``run`` the accurate run.
    """

    mu_ratio: float
    mu_error: float
    lateral_ratio: float
    lateral_error: float
    stick_fraction: float
    slip_fraction: float
    flight_fraction: float
    run: InplaneRun


class _Model:
    """Forcing, right-hand sides, events and phase rules of one parameter point."""

    def __init__(self, alpha, beta, a, V, zeta, eta_c, a_x, phase_x, a_y, phase_y,
                 alpha_y, zeta_y, inplane_on):
        self.alpha, self.a, self.V = alpha, a, V
        self.alpha_y = alpha_y
        self.gx = 2.0 * zeta * math.sqrt(alpha)
        self.gy = 2.0 * zeta_y * math.sqrt(alpha_y)
        self.k = beta - alpha
        self.c = eta_c * self.k
        self.viscous = self.c > 0.0
        self.a_x, self.px, self.a_y, self.py = a_x, phase_x, a_y, phase_y
        self.holder = inplane_on == "holder"

    # -- forcing ---------------------------------------------------------------
    def n(self, t):
        return 1.0 + self.a * math.cos(t)

    def dn(self, t):
        return -self.a * math.sin(t)

    def inplane(self, t):
        """``(X, Y, X', Y')`` at ``t``."""
        cx, sx = math.cos(t + self.px), math.sin(t + self.px)
        cy, sy = math.cos(t + self.py), math.sin(t + self.py)
        return self.a_x * cx, self.a_y * cy, -self.a_x * sx, -self.a_y * sy

    def drive(self, t):
        """``(h_x - V tau, h_y, h_x', h_y', v_sx, v_sy)``."""
        X, Y, Xd, Yd = self.inplane(t)
        if self.holder:
            return X, Y, self.V + Xd, Yd, 0.0, 0.0
        return 0.0, 0.0, self.V, 0.0, Xd, Yd

    # -- forces ----------------------------------------------------------------
    def contact_force(self, phase, t, z):
        """The contact forces and rates of a state in a phase.

        ``(f_x, f_y, e'_x, e'_y, lam)`` of the state ``z`` in ``phase`` (``lam`` the slip
        speed; ``e'`` is 0 in Jenkins slip, where the state holds ``d``).
        """
        _, _, _, _, vsx, vsy = self.drive(t)
        wx, wy = z[2] - vsx, z[3] - vsy
        k, c = self.k, self.c
        if phase == _FLIGHT:
            if self.viscous:
                return 0.0, 0.0, -k * z[4] / c, -k * z[5] / c, 0.0
            return 0.0, 0.0, 0.0, 0.0, 0.0
        n = self.n(t)
        if not self.viscous:
            if phase == _STICK:
                return k * z[4], k * z[5], wx, wy, 0.0
            dn_ = math.hypot(z[4], z[5])
            dx, dy = z[4] / dn_, z[5] / dn_
            lam = dx * wx + dy * wy - self.dn(t) / k
            return n * dx, n * dy, 0.0, 0.0, lam
        Fx, Fy = k * z[4] + c * wx, k * z[5] + c * wy
        if phase == _STICK:
            return Fx, Fy, wx, wy, 0.0
        F = math.hypot(Fx, Fy)
        lam = (F - n) / c
        return n * Fx / F, n * Fy / F, wx - lam * Fx / F, wy - lam * Fy / F, lam

    def rhs(self, phase):
        al, aly, gx, gy, V = self.alpha, self.alpha_y, self.gx, self.gy, self.V
        jenkins_slip = phase == _SLIP and not self.viscous

        def fun(t, z):
            hx, hy, hdx, hdy, vsx, vsy = self.drive(t)
            fx, fy, ex, ey, lam = self.contact_force(phase, t, z)
            px, py = gx * (hdx - z[2]), gy * (hdy - z[3])
            Fpx, Fpy = al * (hx - z[0]) + px, aly * (hy - z[1]) + py
            if jenkins_slip:  # the direction d turns towards the relative body velocity
                n = self.n(t)
                wx, wy = z[2] - vsx, z[3] - vsy
                dn_ = math.hypot(z[4], z[5])
                dx, dy = z[4] / dn_, z[5] / dn_
                p = dx * wx + dy * wy
                r = self.k / n if n > 0.0 else 0.0
                ex, ey = r * (wx - p * dx), r * (wy - p * dy)
            n_here = self.n(t) if phase != _FLIGHT else 0.0
            diss = gx * (hdx - z[2]) ** 2 + gy * (hdy - z[3]) ** 2 + n_here * lam
            if self.viscous:
                diss += self.c * ((ex * ex + ey * ey) if phase != _STICK
                                  else ((z[2] - vsx) ** 2 + (z[3] - vsy) ** 2))
            return np.array([
                z[2] - V, z[3], Fpx - fx, Fpy - fy, ex, ey, fx, fy, n_here,
                Fpx * hdx + Fpy * hdy - fx * vsx - fy * vsy, diss])

        return fun

    def energy(self, phase, t, z):
        """Stored energy ``E`` of the state (see the module docstring)."""
        hx, hy, _, _, _, _ = self.drive(t)
        if phase == _SLIP and not self.viscous:
            ee = (self.n(t) / self.k) ** 2
        elif phase == _FLIGHT and not self.viscous:
            ee = 0.0
        else:
            ee = z[4] ** 2 + z[5] ** 2
        return 0.5 * (z[2] ** 2 + z[3] ** 2 + self.alpha * (hx - z[0]) ** 2
                      + self.alpha_y * (hy - z[1]) ** 2 + self.k * ee)

    # -- events ------------------------------------------------------------------
    def events(self, phase):
        """Terminal events (falling through 0) that end ``phase``."""
        if phase == _FLIGHT:
            return []
        k, c = self.k, self.c
        if phase == _STICK:
            if self.viscous:
                def g(t, z):
                    _, _, _, _, vsx, vsy = self.drive(t)
                    return self.n(t) - math.hypot(k * z[4] + c * (z[2] - vsx),
                                                  k * z[5] + c * (z[3] - vsy))
            else:
                def g(t, z):
                    return self.n(t) - k * math.hypot(z[4], z[5])
        else:
            def g(t, z):
                return self.contact_force(_SLIP, t, z)[4]
        # solve_ivp reads these attributes of an event function
        g.terminal = True  # type: ignore[attr-defined]
        g.direction = -1.0  # type: ignore[attr-defined]
        return [g]

    # -- phase rules ---------------------------------------------------------------
    def _jenkins_to_slip(self, t, z):
        z = z.copy()
        e = math.hypot(z[4], z[5])
        z[4], z[5] = z[4] / e, z[5] / e
        return z

    def _jenkins_to_stick(self, t, z):
        z = z.copy()
        d = math.hypot(z[4], z[5])
        s = self.n(t) / (self.k * d) * (1.0 - _MARGIN)
        z[4], z[5] = z[4] * s, z[5] * s
        return z

    def entry(self, t, z):
        """The phase of a contact state with no history (start of the run)."""
        n = self.n(t)
        _, _, _, _, vsx, vsy = self.drive(t)
        if self.viscous:
            F = math.hypot(self.k * z[4] + self.c * (z[2] - vsx),
                           self.k * z[5] + self.c * (z[3] - vsy))
            return (_STICK if F <= n else _SLIP), z
        fe = self.k * math.hypot(z[4], z[5])
        if fe < n or fe == 0.0:
            return _STICK, z
        zs = self._jenkins_to_slip(t, z)
        if self.contact_force(_SLIP, t, zs)[4] > 0.0:
            return _SLIP, zs
        return _STICK, z

    def touchdown(self, t, z):
        """Contact begins at ``t`` after a flight."""
        _, _, _, _, vsx, vsy = self.drive(t)
        wx, wy = z[2] - vsx, z[3] - vsy
        if self.viscous:
            F = math.hypot(self.k * z[4] + self.c * wx, self.k * z[5] + self.c * wy)
            return (_STICK if F <= self.n(t) else _SLIP), z
        z = z.copy()
        w = math.hypot(wx, wy)
        if self.dn(t) >= self.k * w:
            z[4] = z[5] = 0.0
            return _STICK, z
        z[4], z[5] = wx / w, wy / w
        return _SLIP, z

    def lift_off(self, phase, z):
        z = z.copy()
        if not self.viscous:
            z[4] = z[5] = 0.0
        return _FLIGHT, z

    def _viscous_to(self, t, z, size):
        """``e`` moved along ``F`` so that ``|F| = size`` (a change of order ``1e-12 n/k``)."""
        z = z.copy()
        _, _, _, _, vsx, vsy = self.drive(t)
        Fx = self.k * z[4] + self.c * (z[2] - vsx)
        Fy = self.k * z[5] + self.c * (z[3] - vsy)
        F = math.hypot(Fx, Fy)
        z[4] += (size - F) * Fx / (F * self.k)
        z[5] += (size - F) * Fy / (F * self.k)
        return z

    def switch(self, phase, t, z):
        """The phase after the terminal event of ``phase`` at ``t``.

        The new phase starts strictly inside its domain (``|F|`` or ``|k e|`` a relative
        ``_MARGIN`` away from ``n``): an event function that started at a round-off zero
        on the wrong side would miss its next root if that fell in the first step (a
        stick across a force reversal shorter than one step).
        """
        n = self.n(t)
        if phase == _STICK:
            if self.viscous:
                return _SLIP, self._viscous_to(t, z, n * (1.0 + _MARGIN))
            return _SLIP, self._jenkins_to_slip(t, z)
        if self.viscous:
            return _STICK, self._viscous_to(t, z, n * (1.0 - _MARGIN))
        return _STICK, self._jenkins_to_stick(t, z)


def _stick_load(model: _Model, t: float, z: np.ndarray) -> float:
    """``|f|`` in stick (the load the cone must carry)."""
    fx, fy = model.contact_force(_STICK, t, z)[:2]
    return math.hypot(fx, fy)


def _initial(initial, model: _Model) -> np.ndarray:
    z = np.zeros(_N_STATE)
    if isinstance(initial, tuple):  # an explicit state (y_x, v_x, e_x) at tau = 0
        if len(initial) != 3 or not all(math.isfinite(float(v)) for v in initial):
            raise ValueError(f"an explicit initial state is (y_x, v_x, e_x), finite; got "
                             f"{initial!r}")
        z[0], z[2], z[4] = (float(v) for v in initial)
        return z
    if initial_code(initial) == 0 and model.V != 0.0:
        s = math.copysign(1.0, model.V)
        z[0], z[2], z[4] = -s / model.alpha, model.V, s / model.k
    return z


def _period_end(t: float) -> bool:
    """Whether the cut end ``t`` is a drive period's end (``2 pi k``, as :func:`_cuts` forms it).

    Relative to ``k``: ``2 pi k`` formed in floats is ``k`` times ``2 pi`` only to about ``k``
    roundings (from about 8000 periods on beyond 1e-12; the other cut ends, a lift-off
    or a touch-down, lie at least ``delta`` inside a period).
    """
    k = t / TWO_PI
    return abs(k - round(k)) < 1e-12 * max(1.0, k)


def _cuts(a: float, periods: int, delta: float) -> list[tuple[float, float, bool]]:
    """Segments ``(t0, t1, in_contact)`` cut at every period, lift-off and touch-down."""
    out = []
    theta = math.acos(-1.0 / a) if a > 1.0 else None
    for j in range(periods):
        t0 = TWO_PI * j
        if theta is None:
            out.append((t0, t0 + TWO_PI, True))
            continue
        up, down = t0 + theta - delta, t0 + TWO_PI - theta + delta
        out += [(t0, up, True), (up, down, False), (down, t0 + TWO_PI, True)]
    return out


def _check_inplane(a_x, phase_x, a_y, phase_y, alpha, alpha_y, zeta, zeta_y, inplane_on):
    vals = {}
    for name, v in (("a_x", a_x), ("a_y", a_y)):
        v = float(v)
        if not (v >= 0.0 and math.isfinite(v)):
            raise ValueError(f"{name} must be in [0, inf) (finite and >= 0), got {v}")
        vals[name] = v
    for name, v in (("phase_x", phase_x), ("phase_y", phase_y)):
        if not math.isfinite(float(v)):
            raise ValueError(f"{name} must be a finite number, got {v}")
    alpha_y = alpha if alpha_y is None else float(alpha_y)
    if not (alpha_y > 0.0 and math.isfinite(alpha_y)):
        raise ValueError(f"alpha_y must be in (0, inf) (finite and > 0), got {alpha_y}")
    zeta_y = zeta if zeta_y is None else float(zeta_y)
    if not (zeta_y >= 0.0 and math.isfinite(zeta_y)):
        raise ValueError(f"zeta_y must be in [0, inf) (finite and >= 0), got {zeta_y}")
    if inplane_on not in ("substrate", "holder"):
        raise ValueError(f"inplane_on must be 'substrate' or 'holder', got {inplane_on!r}")
    return vals["a_x"], float(phase_x), vals["a_y"], float(phase_y), alpha_y, zeta_y


def inplane_run(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    transient_periods: int = 100,
    average_periods: int = 20,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    *,
    zeta: float = 0.0,
    eta_c: float = 0.0,
    a_x: float = 0.0,
    phase_x: float = 0.0,
    a_y: float = 0.0,
    phase_y: float = 0.0,
    alpha_y: float | None = None,
    zeta_y: float | None = None,
    inplane_on: str = "substrate",
    initial: int | str | tuple[float, float, float] = "sliding",
    max_events_per_period: int = 200,
    steps_per_fastest_period: float = 4.0,
) -> InplaneRun:
    """Integrate the in-plane model phase by phase and average it.

    Integrate the in-plane model (module docstring) over ``transient_periods +
    average_periods`` drive periods with DOP853 (``rtol``, ``atol``) phase by phase and
    average over the last ``average_periods``.

    ``alpha_y``, ``zeta_y`` default to ``alpha``, ``zeta``.  ``beta`` must be finite
    (a rigid contact is not covered), ``a = 1`` with ``eta_c = 0`` and ``a_y > 0`` is
    refused.  A step end outside its phase's domain (stick with ``|f| > n``, slip with a
    negative slip speed) by more than 1e-8 raises RuntimeError (an event was missed: two
    switches inside one step).  More than ``max_events_per_period`` stick/slip switches in
    one period raise RuntimeError (chatter).  The step is capped at
    ``1/steps_per_fastest_period`` of the fastest natural period (``2 pi / max(1,
    sqrt(alpha), sqrt(alpha_y), sqrt(beta))``).
    """
    alpha, beta, a, V = check_parameters(alpha, beta, amplitude, V)
    zeta, eta_c = check_damping(zeta, eta_c)
    a_x, phase_x, a_y, phase_y, alpha_y, zeta_y = _check_inplane(
        a_x, phase_x, a_y, phase_y, alpha, alpha_y, zeta, zeta_y, inplane_on)
    if math.isinf(beta):
        raise ValueError("beta must be finite: the in-plane reference does not cover a "
                         "rigid contact (use a large finite beta)")
    if a == 1.0 and eta_c == 0.0 and a_y > 0.0:
        raise ValueError("amplitude = 1 (grazing) with eta_c = 0 and a_y > 0 is not covered")
    transient_periods = check_count("transient_periods", transient_periods, 0)
    average_periods = check_count("average_periods", average_periods, 1)
    model = _Model(alpha, beta, a, V, zeta, eta_c, a_x, phase_x, a_y, phase_y, alpha_y,
                   zeta_y, inplane_on)
    periods = transient_periods + average_periods
    w = max(1.0, math.sqrt(alpha), math.sqrt(alpha_y), math.sqrt(beta))
    max_step = TWO_PI / (steps_per_fastest_period * w)
    delta = 0.0 if model.viscous else _DELTA

    z = _initial(initial, model)
    phase, z = model.entry(0.0, z)
    counters = {"events": 0, "calls": 0, "nfev": 0}
    excess = -math.inf
    time_in = [0.0, 0.0, 0.0]
    period_marks = [(z[6:11].copy(), model.energy(phase, 0.0, z))]
    events_in_period, period_index = 0, 0
    for t0, t1, contact in _cuts(a, periods, delta):
        # the drive period the cut begins in (t0 % TWO_PI == 0 fails from period 11 on:
        # k 2 pi is not a float multiple of TWO_PI there)
        k = math.floor(t0 / TWO_PI + 1e-9)
        if k != period_index:
            events_in_period, period_index = 0, k
        if not contact:
            phase, z = model.lift_off(phase, z)
        elif phase == _FLIGHT:
            phase, z = model.touchdown(t0, z)
        t = t0
        while t < t1:
            sol = solve_ivp(model.rhs(phase), (t, t1), z, method="DOP853", rtol=rtol,
                            atol=atol, events=model.events(phase), max_step=max_step)
            if not sol.success:
                raise RuntimeError(f"solve_ivp failed at tau={t:.9g}: {sol.message}")
            counters["calls"] += 1
            counters["nfev"] += sol.nfev
            if phase != _FLIGHT:
                for j in range(sol.y.shape[1]):
                    fx, fy, _, _, lam = model.contact_force(phase, sol.t[j], sol.y[:, j])
                    excess = max(excess, math.hypot(fx, fy) - model.n(sol.t[j]))
                    if phase == _STICK:
                        g = (model.n(sol.t[j]) - _stick_load(model, sol.t[j], sol.y[:, j]))
                    else:
                        g = lam
                    if g < -_VIOLATION:
                        raise RuntimeError(
                            f"missed event: {'stick' if phase == _STICK else 'slip'} "
                            f"outside its domain by {-g:.3g} at tau={sol.t[j]:.9g} (two "
                            "switches inside one step?); lower steps_per_fastest_period's "
                            "step cap or rtol")
            if sol.status == 1:
                t_new = float(sol.t_events[0][0])
                z = sol.y_events[0][0].copy()
            else:
                t_new, z = t1, sol.y[:, -1].copy()
            if t0 >= TWO_PI * transient_periods:
                time_in[phase] += t_new - t
            t = t_new
            if sol.status == 1:
                counters["events"] += 1
                events_in_period += 1
                if events_in_period > max_events_per_period:
                    raise RuntimeError(
                        f"chattering: more than {max_events_per_period} stick/slip events "
                        f"in the drive period at tau={t:.9g}")
                phase, z = model.switch(phase, t, z)
        if _period_end(t1):
            period_marks.append((z[6:11].copy(), model.energy(phase, t1, z)))

    ints = np.array([m[0] for m in period_marks])
    energies = np.array([m[1] for m in period_marks])
    per = np.diff(ints, axis=0)[transient_periods:] / TWO_PI
    dE = np.diff(energies)[transient_periods:]
    work, diss = per[:, 3] * TWO_PI, per[:, 4] * TWO_PI
    residual = np.abs(dE - work + diss) / np.maximum(np.maximum(np.abs(work), diss), 1e-300)
    mean_fx, mean_fy, mean_n = (float(np.mean(per[:, i])) for i in range(3))
    span = TWO_PI * average_periods
    fx, fy, _, _, _ = model.contact_force(phase, TWO_PI * periods, z)
    final = (TWO_PI * periods, float(z[0]) + V * TWO_PI * periods, float(z[1]),
             float(z[2]), float(z[3]), float(fx), float(fy))
    return InplaneRun(
        mean_fx / mean_n, mean_fy / mean_n, mean_fx, mean_fy, mean_n,
        time_in[_STICK] / span, time_in[_SLIP] / span, time_in[_FLIGHT] / span,
        per[:, 0], per[:, 1], per[:, 2], work, diss, residual, float(excess),
        counters["events"], counters["calls"], counters["nfev"], final)


def _spread(values: np.ndarray, weights: np.ndarray) -> float:
    """Window spread of a ratio of means.

    Halves' difference or 3 standard errors of ten blocks, whichever is larger (0 for fewer than 2
    periods).
    """
    m = len(values)
    if m < 2:
        return 0.0
    h = m // 2
    halves = abs(values[:h].sum() / weights[:h].sum() - values[h:].sum() / weights[h:].sum())
    nb = min(10, m)
    blocks = [b.sum() / wb.sum() for b, wb in zip(np.array_split(values, nb),
                                                   np.array_split(weights, nb), strict=True)]
    return max(halves, 3.0 * float(np.std(blocks, ddof=1)) / math.sqrt(nb))


def inplane_mean(
    alpha: float,
    beta: float,
    amplitude: float,
    V: float,
    transient_periods: int = 100,
    average_periods: int = 40,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    *,
    tolerance_check: bool = True,
    **model,
) -> InplaneMean:
    """The steady-state friction ratios of the in-plane model, with error estimates.

    Steady-state ``<f_x>/<n>`` and ``<f_y>/<n>`` with error estimates (see
    :class:`InplaneMean`) from :func:`inplane_run`; ``model`` are its keywords (``zeta,
    eta_c, a_x, phase_x, a_y, phase_y, alpha_y, zeta_y, inplane_on, initial``).
    ``tolerance_check`` adds a second run at 1000 times looser tolerances (about a third
    of the cost) whose difference is added to the errors.
    """
    run = inplane_run(alpha, beta, amplitude, V, transient_periods, average_periods, rtol,
                      atol, **model)
    mu_err = _spread(run.period_fx, run.period_n)
    lat_err = _spread(run.period_fy, run.period_n)
    if tolerance_check:
        loose = inplane_run(alpha, beta, amplitude, V, transient_periods, average_periods,
                            1e3 * rtol, 1e3 * atol, **model)
        mu_err += abs(loose.mu_ratio - run.mu_ratio)
        lat_err += abs(loose.lateral_ratio - run.lateral_ratio)
    return InplaneMean(run.mu_ratio, mu_err, run.lateral_ratio, lat_err, run.stick_fraction,
                       run.slip_fraction, run.flight_fraction, run)
