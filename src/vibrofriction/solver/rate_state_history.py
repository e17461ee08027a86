"""The time history of rate-and-state friction (docs/friction_laws.md, "Time histories").

The kernel :func:`vibrofriction._kernels.rate_state_history.rs_history` integrates the
rate-and-state solver's equations with its Rosenbrock steps to every sample time;
:func:`rate_state_history` turns the rows into a :class:`~vibrofriction.RateStateHistory`.
:func:`vibrofriction.simulate` routes a system with ``rs_a > 0`` here.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from .._kernels import codes
from .._kernels import rate_state as _rs
from .._kernels import rate_state_history as _rh
from ..capabilities import Refusal
from ..params import Dimensionless
from ..schema import Status
from .energy import inplane_motion
from .history_types import Event, RateStateHistory
from .methods.base import new_outputs
from .methods.rate_state import RATE_STATE, _unforced_unstable, rate_state_arguments
from .points import table_of
from .results import section_state
from .settings import DEFAULT_SETTINGS, SolverSettings

__all__ = ["rate_state_history"]

TWO_PI = 2.0 * math.pi


def _segments(p: NDArray[np.float64], tau_end: float
              ) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """The boundaries and modes of the contact and flight segments on ``[0, tau_end]``."""
    c_off, c_on = _rh.rs_cuts(p)
    if c_off >= TWO_PI:  # never a flight
        return np.array([0.0, tau_end]), np.array([_rs.CONTACT])
    cuts = [0.0]
    k = 0
    while True:
        for c in (c_off, c_on):
            t = TWO_PI * k + c
            if t >= tau_end:
                cuts.append(tau_end)
                modes = [_rs.CONTACT if j % 2 == 0 else _rs.FLIGHT
                         for j in range(len(cuts) - 1)]
                return np.asarray(cuts), np.asarray(modes, dtype=np.int64)
            cuts.append(t)
        k += 1


def _start(dim: Dimensionless, p: NDArray[np.float64], initial: object,
           settings: SolverSettings) -> NDArray[np.float64]:
    """The kernels' state at ``tau = 0`` from ``initial`` (``"sliding"`` or ``"steady"``)."""
    if not (isinstance(initial, str) and initial in ("sliding", "steady")):
        raise Refusal(f"a rate-and-state history starts from initial='sliding' or 'steady' "
                      f"(a section state has no theta), got {initial!r}", "initial")
    rtol, max_periods, tol_mean = rate_state_arguments(settings)
    out_f, out_i = new_outputs(1)
    z = _rh.rs_start(p, initial == "steady", rtol, max_periods, tol_mean, out_f[0], out_i[0])
    if initial == "steady":
        _unforced_unstable(table_of(dim, p[codes.T_V]), out_f, out_i)
        status = int(out_i[0, codes.I_STATUS])
        error = float(out_f[0, codes.O_ERR])
        if not settings.trusted(status, error):
            raise ValueError(f"initial='steady': no trusted steady state at this point "
                             f"(status {Status.from_code(status).value}, error {error:.3g})")
    return z


def _cumulative(tau: NDArray[np.float64], p: NDArray[np.float64]) -> NDArray[np.float64]:
    """The trapezoidal rule's running integral of the samples ``p`` over ``tau``."""
    return np.concatenate([[0.0], np.cumsum(0.5 * (p[1:] + p[:-1]) * np.diff(tau))])


def _energies(dim: Dimensionless, V: float, tau: NDArray[np.float64],
              z: NDArray[np.float64], f: NDArray[np.float64]
              ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``(work_input, dissipated_pin)`` of the mirrored point's rows (``V >= 0``).

    Without an in-plane oscillation the body's equation ``x'' = alpha (V tau - x) + gamma
    (V - x') - f`` gives the pulled end's work ``V int (x'' + f) = V (x' - x'(0) + F)``, and
    the dashpot's is the quadrature ``G``; with one, the trapezoidal rule over the samples
    (the definitions of :func:`vibrofriction.solver.energy.dissipation`).
    """
    y, v, F, G = (z[:, j] for j in (_rs.Z_Y, _rs.Z_V, _rs.Z_F, _rs.Z_G))
    if dim.a_x == 0.0:
        return V * (v - v[0] + F), G.copy()
    gamma = 2.0 * dim.zeta * math.sqrt(dim.alpha)
    X, Xd = inplane_motion(dim, tau)
    if dim.inplane_on == "substrate":  # the kernels' frame moves with the substrate
        rel = V - v - Xd
        p_in = V * (-dim.alpha * (y + X) + gamma * rel) - f * Xd
    else:
        rel = V + Xd - v
        p_in = (V + Xd) * (dim.alpha * (X - y) + gamma * rel)
    return _cumulative(tau, p_in), _cumulative(tau, gamma * rel**2)


def _elongation(dim: Dimensionless, tau: NDArray[np.float64], z: NDArray[np.float64],
                w: NDArray[np.float64], n: NDArray[np.float64], contact: NDArray[np.bool_]
                ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``(e, dissipated_contact)`` of the mirrored point's rows (kernels' variables).

    ``e = f/k`` (0 for a rigid contact); with the contact's dashpot ``c = eta_c k``, ``e =
    (f - c (x' - w'))/k`` in contact and the kernels' ``z[Z_M]`` in flight (``k e + c e' =
    0``), and its dissipation ``int c e'^2`` by the trapezoidal rule over the samples
    (``e' = x' - w'`` in contact, ``-e/eta_c`` in flight).
    """
    k = dim.beta - dim.alpha
    m, v = z[:, _rs.Z_M], z[:, _rs.Z_V]
    if not (dim.eta_c > 0.0 and math.isfinite(k)):
        return np.where(contact, n * m / k, 0.0), np.zeros_like(tau)
    c = dim.eta_c * k
    slip = np.where(contact, v - np.where(contact, w, 0.0), 0.0)
    e = np.where(contact, (n * m - c * slip) / k, m)
    e_dot = np.where(contact, slip, -m / dim.eta_c)
    return e, _cumulative(tau, c * e_dot**2)


def rate_state_history(dim: Dimensionless, V: float, periods: float, samples_per_period: int,
                       initial: object = "sliding",
                       settings: SolverSettings | None = None) -> RateStateHistory:
    """The history of a rate-and-state system over ``periods`` drive periods.

    Sampled on the uniform grid of ``samples_per_period`` a period and at the sections
    ``tau = 2 pi k``, and at each lift-off and touch-down on both sides.  ``initial``
    ``"sliding"`` (the solver's start: steady sliding at ``V`` before the oscillation) or
    ``"steady"`` (the last section state of the solver's steady state, where trusted, with
    its ``theta``).  ``V < 0`` is the mirror image of ``-V`` (``phase_x + pi``).
    """
    settings = settings or DEFAULT_SETTINGS
    RATE_STATE.capabilities.check(table_of(dim, V), 0, settings)
    sign = -1.0 if V < 0.0 else 1.0
    mirror = replace(dim, phase_x=dim.phase_x + math.pi) if V < 0.0 else dim
    Va = abs(V)
    p = table_of(mirror, Va).values[0]
    z0 = _start(mirror, p, initial, settings)
    rtol = rate_state_arguments(settings)[0]
    tau_end = TWO_PI * periods
    whole_done = int(math.floor(periods + 1e-12))
    grid = np.unique(np.concatenate([
        np.linspace(0.0, tau_end, int(round(samples_per_period * periods)) + 1),
        TWO_PI * np.arange(1, whole_done + 1)]))
    seg_t, seg_mode = _segments(p, tau_end)
    out = np.empty((grid.size + 2 * seg_mode.size, _rh.N_R))
    m = _rh.rs_history(p, z0, seg_t, seg_mode, grid, rtol, out)
    if m < 0:
        raise RuntimeError("the rate-and-state history failed: a Rosenbrock step fell below "
                           "its smallest size or a period took more than its most steps")
    out = out[:m]
    tau = out[:, _rh.R_TAU]
    z = out[:, _rh.R_Z:_rh.R_Z + _rs.NZ]
    mode = out[:, _rh.R_MODE].astype(int)
    contact = mode == _rs.CONTACT
    w = sign * out[:, _rh.R_W]
    n = np.maximum(0.0, 1.0 + dim.amplitude * np.cos(tau))
    mu = np.where(contact, sign * z[:, _rs.Z_M], np.nan)
    f = np.where(contact, n * sign * z[:, _rs.Z_M], 0.0)
    ph = np.where(contact, np.where(w >= 0.0, codes.SLIP_POS, codes.SLIP_NEG), codes.FLIGHT)
    names = np.asarray(codes.PHASE_NAMES, dtype=str)
    changes = np.flatnonzero(mode[1:] != mode[:-1])
    events = tuple(Event(float(tau[j]), codes.EVENT_NAMES[
        codes.EV_LIFTOFF if contact[j] else codes.EV_TOUCHDOWN],
        str(names[ph[j]]), str(names[ph[j + 1]])) for j in changes)
    work, pin = _energies(mirror, Va, tau, z, sign * f)
    e_k, contact_loss = _elongation(dim, tau, z, out[:, _rh.R_W], n, contact)
    e = sign * e_k
    y, v = sign * z[:, _rs.Z_Y], sign * z[:, _rs.Z_V]
    if dim.a_x > 0.0 and dim.inplane_on == "substrate":  # back to the laboratory frame
        X, Xd = inplane_motion(dim, tau)
        y, v = y + X, v + Xd
    zeros = np.zeros_like(tau)
    r = int(np.flatnonzero(np.isclose(tau, TWO_PI * whole_done, rtol=0.0, atol=1e-12))[-1])
    final = section_state(y[r], v[r], f[r], int(ph[r]), float(e[r]))
    return RateStateHistory(
        tau=tau, x=y + V * tau, x_dot=v, f=f, n=n, phase=names[ph], events=events,
        system=dim, v_inertial=float(V), e=e, work_input=work,
        dissipated_pin=pin, dissipated_contact=contact_loss,
        dissipated_friction=z[:, _rs.Z_D].copy(), final_state=final,
        theta=np.exp(z[:, _rs.Z_L]), local_mu=mu,
        slip_velocity=np.stack([w, zeros], axis=1),
        impulse=np.stack([sign * z[:, _rs.Z_F], zeros], axis=1))
