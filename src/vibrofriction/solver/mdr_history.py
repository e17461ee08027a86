"""The time history of a curved tip: the MDR spring row sampled (docs/contact_geometry.md).

The event-driven kernel :func:`vibrofriction._kernels.mdr.run_periods` records the row at
the sample times from its closed forms (not interpolated): the body, every spring's
tangential force and state, and the integrals of the forces and of the powers since the
start. :func:`mdr_history` turns that into a :class:`~vibrofriction.CurvedHistory`;
:func:`vibrofriction.simulate` routes a curved profile here.  The springs' states are the
package's contact states (:class:`~vibrofriction.schema.ContactState`).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from .._kernels import mdr as _mdr
from .._kernels.codes import FLIGHT, PHASE_NAMES, SLIP_NEG, SLIP_POS, STICK
from .._kernels.phases import frame_offset, inplane_forcing
from ..capabilities import CAPABILITIES
from ..params import Dimensionless
from ..schema import PARTIAL
from .history_types import CurvedHistory
from .mdr import SUBSTEPS, _check, _start, mdr_row
from .settings import DEFAULT_SETTINGS, SolverSettings

__all__ = ["SPRINGS", "mdr_history", "spring_row"]

#: The default number of springs of a curved history (``simulate(..., springs=...)``).
SPRINGS = 160


def spring_row(amplitude: float, profile_exponent: float, springs: int
               ) -> tuple[NDArray[np.float64], NDArray[np.float64], float, NDArray[np.float64]]:
    """``(xi, g, w, area)`` of a row.

    The springs' positions (cell midpoints on ``(0, (1 + a)^(1/n)]``, unit ``a0``), their gaps
    ``xi^n``, the normal weight ``w = dxi (n + 1)/n`` (the flat punch's ``dxi``) and each
    spring's share of the disc of the largest contact radius.
    """
    g, w, dxi, _, _, area = _mdr.row_geometry(float(amplitude), float(profile_exponent),
                                              int(springs))
    return (np.arange(int(springs)) + 0.5) * dxi, g, float(w), area


def _summary_phase(state: NDArray[np.int8]) -> NDArray[np.str_]:
    """One name a sample.

    ``"flight"`` (no spring in contact), ``"stick"``, ``"slip+"`` or ``"slip-"`` where every
    spring in contact is in that state, else ``"partial"``.
    """
    touching = state != FLIGHT
    width = max(len(name) for name in (*PHASE_NAMES, PARTIAL))
    out = np.full(state.shape[0], PARTIAL, dtype=f"<U{width}")
    out[~touching.any(axis=1)] = PHASE_NAMES[FLIGHT]
    for code in (STICK, SLIP_POS, SLIP_NEG):
        out[touching.any(axis=1) & np.all((state == code) | ~touching, axis=1)] = \
            PHASE_NAMES[code]
    return out


def _initial_row(dim: Dimensionless, initial: object, Va: float, a_x: float, phase_x: float,
                 M: int, settings: SolverSettings
                 ) -> tuple[float, float, NDArray[np.int64], NDArray[np.float64]]:
    """The section state ``(y, y', st, e)`` :func:`mdr_history` starts from.

    Its ``initial``; ``Va = |V|``, ``phase_x`` that of the mirrored point where ``V < 0``;
    ``"steady"`` searches the orbit with the MDR solver's resolved ``settings``.
    """
    alpha, beta, a, n_exp, zeta = (dim.alpha, dim.beta, dim.amplitude, dim.profile_exponent,
                                   dim.zeta)
    on_substrate = dim.inplane_on == "substrate"
    if isinstance(initial, str) and initial == "sliding":
        y, yd, st, e = _start(alpha, a, n_exp, M, None,
                              frame_offset(a_x, phase_x, on_substrate))
        # the solver's start leaves the springs beyond the mean contact radius out of
        # contact until their touch-down late in the first period (its steady state is
        # the same); in contact at tau = 0 (g_i < 1 + a), they slip forwards too
        g = _mdr.row_geometry(a, n_exp, M)[0]
        st[(st == FLIGHT) & (1.0 + a - g > 0.0)] = SLIP_POS
    elif isinstance(initial, str) and initial == "steady":
        rs = settings.resolved(CAPABILITIES["mdr"].settings)
        r = mdr_row(alpha, beta, a, Va, n_exp, M, zeta, a_x=a_x, phase_x=phase_x,
                    inplane_on=dim.inplane_on, state_tol=float(rs["tol_state"]),
                    max_periods=int(rs["max_periods"]), static_ratio=dim.static_ratio)
        if r["status"] == "not converged":
            raise ValueError(f"initial='steady': the row of {M} springs did not converge "
                             f"at this point (after {r['periods']} periods)")
        y, yd, st, e = r["final_state"]
        st, e = st.copy(), e.copy()
    else:
        raise ValueError(f"a curved profile starts from initial='sliding' or 'steady' "
                         f"(the MDR row takes no section state), got {initial!r}")
    return y, yd, st, e


def _row_columns(sts: NDArray[np.int8], tau: NDArray[np.float64], a: float, n_exp: float,
                 M: int) -> tuple[NDArray[np.float64], ...]:
    """The row columns of a history: ``(xi, stick_area, slip_area, stick_radius, contact_radius)``.

    From the springs' states ``sts`` at the phases ``tau``.
    """
    xi, g, w, area = spring_row(a, n_exp, M)
    stick = sts == STICK
    slip = (sts == SLIP_POS) | (sts == SLIP_NEG)
    stick_area = stick.astype(float) @ area
    slip_area = slip.astype(float) @ area
    stick_radius = np.where(stick.any(axis=1), np.max(np.where(stick, xi, 0.0), axis=1), 0.0)
    depth = np.maximum(0.0, 1.0 + a * np.cos(tau))
    contact_radius = np.where(depth > 0.0, 1.0, 0.0) if math.isinf(n_exp) \
        else depth ** (1.0 / n_exp)
    return xi, stick_area, slip_area, stick_radius, contact_radius


def mdr_history(dim: Dimensionless, V: float, periods: float, samples_per_period: int,
                initial: object = "sliding", springs: int = SPRINGS,
                settings: SolverSettings = DEFAULT_SETTINGS) -> CurvedHistory:
    """The history of a row of ``springs`` springs over ``periods`` drive periods.

    Sampled on the uniform grid of ``samples_per_period`` a period (``tau = 0`` to ``2 pi periods``,
    both included), from the closed forms.

    ``initial``: ``"sliding"`` (the MDR solver's start: every loaded spring slipping
    forwards at its limit ``n_i(0)``, the pin stretched by the load at ``d0``: ``y =
    -sum w max(0, 1 - g_i)/alpha``, ``x' = V``; the flat punch's
    ``SectionState(-1/alpha, V, 1 + a, "slip+")``; unlike the solver's, the springs in
    contact at ``tau = 0`` beyond the mean contact radius, ``1 <= g_i < 1 + a``, slip
    too) or ``"steady"`` (the final section state of
    :func:`~vibrofriction.solver.mdr.mdr_row` with the same springs: a periodic orbit, or
    the row's attractor after its averaging window; ValueError where it did not converge).
    ``V < 0`` is the mirror image of ``-V`` (with ``phase_x + pi``). A longitudinal
    in-plane oscillation (``a_x``, ``phase_x``, ``inplane_on``; ``V != 0``) as the MDR
    solver's: ``x``, ``x_dot`` in the laboratory frame, the energies with the
    laboratory's definitions (:mod:`vibrofriction.solver.energy`). Any
    ``profile_exponent``, ``math.inf`` included (the flat punch as a row: each spring
    carries the same share).
    """
    M = int(springs)
    if M < 1:
        raise ValueError(f"springs must be an integer >= 1, got {springs!r}")
    alpha, beta, a, n_exp, zeta = (dim.alpha, dim.beta, dim.amplitude, dim.profile_exponent,
                                   dim.zeta)
    sign = -1.0 if V < 0.0 else 1.0
    Va = abs(V)
    # V < 0: the point (-V, phase_x + pi) mirrored, as solve_points
    a_x, phase_x = dim.a_x, dim.phase_x + (math.pi if V < 0.0 else 0.0)
    on_substrate = dim.inplane_on == "substrate"
    _check(alpha, beta, a, Va, n_exp, zeta, a_x, phase_x, dim.inplane_on)
    gamma = 2.0 * zeta * math.sqrt(alpha)
    hc, hs = inplane_forcing(alpha, gamma, a_x, phase_x, on_substrate)
    ip = np.array([a_x * math.cos(phase_x), a_x * math.sin(phase_x),
                   0.0 if on_substrate else 1.0])
    y, yd, st, e = _initial_row(dim, initial, Va, a_x, phase_x, M, settings)
    tau_end = 2.0 * math.pi * periods
    tau = np.linspace(0.0, tau_end, int(round(samples_per_period * periods)) + 1)
    T = tau.size
    body = np.empty((T, _mdr.N_REC))
    fs = np.empty((T, M))
    sts = np.empty((T, M), dtype=np.int8)
    whole = int(math.ceil(periods - 1e-12))
    *_, events, _, _ = _mdr.run_periods(
        alpha, beta, a, Va, gamma, n_exp, M, SUBSTEPS, whole, whole, 0.0, float(y),
        float(yd), st, e, hc, hs, (tau, body, fs, sts, ip), dim.static_ratio)
    if events < 0:
        raise RuntimeError(f"the MDR row of {M} springs made no progress (more than "
                           f"{200 * M + 1000} segments in a period)")
    xi, stick_area, slip_area, stick_radius, contact_radius = _row_columns(sts, tau, a,
                                                                           n_exp, M)
    if sign < 0.0:  # the mirror image: x -> -x, the slip directions swapped
        sts = np.where(sts == SLIP_POS, SLIP_NEG,
                       np.where(sts == SLIP_NEG, SLIP_POS, sts)).astype(np.int8)
    y_s, yd_s = body[:, _mdr.R_Y], body[:, _mdr.R_YD] + Va
    if on_substrate and a_x > 0.0:  # from the substrate's frame to the laboratory's
        y_s = y_s + ip[0] * np.cos(tau) - ip[1] * np.sin(tau)
        yd_s = yd_s - ip[0] * np.sin(tau) - ip[1] * np.cos(tau)
    y_s, yd_s = sign * y_s, sign * yd_s
    f = sign * body[:, _mdr.R_F]
    impulse = np.zeros((T, 2))
    impulse[:, 0] = sign * body[:, _mdr.R_IF]
    return CurvedHistory(
        tau=tau, x=y_s + V * tau, x_dot=yd_s, f=f, n=body[:, _mdr.R_N].copy(),
        phase=_summary_phase(sts), events=(), system=dim, v_inertial=float(V),
        e=f / (beta - alpha), work_input=body[:, _mdr.R_WIN].copy(),
        dissipated_pin=body[:, _mdr.R_DPIN].copy(), dissipated_contact=np.zeros(T),
        dissipated_friction=body[:, _mdr.R_DFRIC].copy(), final_state=None,
        impulse=impulse, xi=xi, spring_state=sts, spring_f=sign * fs,
        stick_radius=stick_radius, contact_radius=contact_radius,
        stick_area_fraction=stick_area, slip_area_fraction=slip_area,
        open_area_fraction=1.0 - stick_area - slip_area,
        normal_impulse=body[:, _mdr.R_IN].copy())
