r"""Parameter sensitivities of a periodic steady state (issue 19).

A ``p``-periodic orbit is a fixed point ``z* = P(z*, theta)`` of the ``p``-period map on
the section, in the free coordinates of its phase there (:func:`.newton._free_dimension`),
with ``theta = (alpha, beta, a, V, zeta, eta_c, a_x, phase_x)``.  By the implicit function
theorem

    dz*/dtheta = (I - J)^{-1} P_theta,

``J`` the monodromy matrix (the exact Jacobian of the period map in the state,
:func:`.tangent.period_map_tangent`) and ``P_theta`` the map's explicit derivative at
fixed ``z*``.  The ratio ``mu = F/N`` (``F``, ``N`` the integrals of ``f`` and ``n`` over
the ``p`` periods, eq. 25) then moves by

    dmu/dtheta = (G . dz*/dtheta + F_theta - mu N_theta) / N,

``G`` the exact gradient of ``F`` in the state (:mod:`.tangent`).  The state part
(``J``, ``G``) is exact; the explicit parameter part ``P_theta``, ``F_theta`` is taken by
fourth-order central differences (``+-h``, ``+-2h``) of the exact period map at fixed
``z*`` (``h`` = ``rel`` times the parameter's scale, :func:`_step`); ``N`` does not
depend on the state and its derivative is closed form (``dN/da = 2 p sqrt(1 - 1/a^2)``
with lift-off, 0 without).  A difference is refused (``nan``, flag :data:`SF_KINK`)
where one of its four maps does not end in the same phase with the same number of
events as the map at ``theta`` (the parameter moves an event through a grazing), or a
transition is degenerate.
"""

import math

import numpy as np

from .integrate import to_kernel_frame
from .jit import jit
from .newton import NEUTRAL, _free_dimension, _solve_small, _unpack, spectral_radius
from .period import A_F, A_N, C_DEGENERATE, C_EVENTS, N_ACC, advance_period, pure_forward_slip
from .phases import ETA_ELASTIC, frame_offset, make_model
from .tangent import period_map_tangent

N_THETA = 8  # alpha, beta, a, V, zeta, eta_c, a_x, phase_x
T_ALPHA, T_BETA, T_A, T_V, T_ZETA, T_ETA, T_AX, T_PX = 0, 1, 2, 3, 4, 5, 6, 7
REL_STEP = 1e-6  # the central differences' step, relative to the parameter's scale
STENCIL = (-2.0, -1.0, 1.0, 2.0)  # order 4; order 2 takes the middle two

# flags (bits) of a point: the orbit's map is not differentiable (tangential event,
# degenerate transition, image in another phase), the orbit is neutral (I - J singular),
# some parameter's difference crosses an event grazing or a model switch
SF_OK, SF_NOT_SMOOTH, SF_NEUTRAL, SF_KINK, SF_FAILED = 0, 1, 2, 4, 8


@jit
def _step(theta, j, rel):
    """The difference step of parameter ``j``: ``rel`` times its scale (``k = beta -
    alpha`` for ``beta``; at least 1 for ``a``, ``zeta``, ``a_x``, ``phase_x``, whose
    effect is set on the scale 1 of the drive).
    """
    x = theta[j]
    if j == T_BETA:
        return rel * (theta[T_BETA] - theta[T_ALPHA])
    if j == T_A or j == T_ZETA or j == T_AX or j == T_PX:
        return rel * max(abs(x), 1.0)
    return rel * abs(x)


@jit
def _map_at(theta, on_substrate, sr, zf, ph, nd, p, max_events, acc):
    """The ``p``-period map at parameters ``theta`` from the free coordinates ``zf`` of
    phase ``ph``: ``(ok, start, image, phase, events)`` (``start``, ``image`` full
    ``(y, x', e)``; ``ok`` False where the integration stopped or a transition was
    degenerate), ``acc`` its accumulators.
    """
    M = make_model(theta[0], theta[1], theta[2], theta[3], theta[4], theta[5], theta[6],
                   theta[7], on_substrate, sr)
    y0, xd0, e0 = _unpack(zf, ph, M)
    z = np.array([y0, xd0, e0, float(ph), math.nan])
    acc[:] = 0.0
    count = np.zeros(3, np.int64)
    ok = True
    for _ in range(p):
        if not advance_period(z, acc, count, M, max_events):
            ok = False
            break
    start = np.array([y0, xd0, e0])
    return (ok and count[C_DEGENERATE] == 0, start, z[:3].copy(), int(z[3]),
            count[C_EVENTS])


@jit
def _difference(f, h, order):
    """The central difference of ``f`` at the offsets :data:`STENCIL` times ``h``: of
    order 4, or of order 2 from the middle two.
    """
    if order == 2:
        return (f[2] - f[1]) / (2.0 * h)
    return (8.0 * (f[2] - f[1]) - (f[3] - f[0])) / (12.0 * h)


@jit
def _normal_rate(a, p):
    """``dN/da`` of ``N = p int n`` over a period (``n = 1 + a cos tau`` in contact):
    0 without lift-off (``a <= 1``), ``2 p sqrt(1 - 1/a^2)`` with it (``n = 0`` at
    the ends of the contact, so they do not contribute).
    """
    if a <= 1.0:
        return 0.0
    return 2.0 * p * math.sqrt(1.0 - 1.0 / (a * a))


@jit
def orbit_sensitivity(alpha, beta, a, V, zeta, eta, a_x, phase_x, on_substrate, y, xd, e,
                      ph, p, max_events, rel, order, want, dmu, dz, sr=1.0):
    """Sensitivities of the ``p``-periodic orbit through the laboratory-frame section
    state ``(y, x', e, ph)`` (an answer of :func:`.steady.steady_state`, ``V > 0``).

    Writes ``dmu[j] = dmu/dtheta_j`` and ``dz[j] = d(y, x', e)/dtheta_j`` of the orbit's
    section state in the kernels' frame (module doc; ``nan`` where not available) and
    returns the flags (:data:`SF_OK` ...).  Only the parameters ``want[j]`` are
    differentiated (the others stay ``nan``); ``order``: 4 (``+-h``, ``+-2h``) or 2
    (``+-h``, half the cost, an error up to ~1e-4 relative where the map bends).  A
    rigid contact does not depend on ``beta`` (0); ``sr``: the static coefficient over the
    kinetic one (not differentiated; the jump of an elastic contact is in the exact
    Jacobian, :func:`.tangent.saltation`); ``eta_c`` below
    :data:`.phases.ETA_ELASTIC` is solved as elastic and has no derivative here
    (``nan``, :data:`SF_KINK`).
    """
    dmu[:] = math.nan
    dz[:, :] = math.nan
    theta = np.array([alpha, beta, a, V, zeta, eta, a_x, phase_x])
    M = make_model(alpha, beta, a, V, zeta, eta, a_x, phase_x, on_substrate, sr)
    offset = frame_offset(a_x, phase_x, on_substrate)
    y, xd = to_kernel_frame(offset, y, xd)
    nd = _free_dimension(ph, M)
    J = np.zeros((3, 3))
    G = np.zeros(3)
    acc = np.zeros(N_ACC)
    y1, xd1, e1, ph1, ev, degenerate, _, smooth = period_map_tangent(
        y, xd, e, ph, p, M, max_events, J, G, acc)
    if degenerate < 0:
        return SF_FAILED
    if ph1 != ph or degenerate > 0 or not smooth:
        return SF_NOT_SMOOTH
    if not spectral_radius(J, nd) < NEUTRAL:
        return SF_NEUTRAL
    F, N = acc[A_F], acc[A_N]
    pure = pure_forward_slip(acc)
    mu = 1.0 if pure else F / N
    zf = np.array([y, xd, e])
    lhs = np.eye(nd) - J[:nd, :nd]
    accq = np.zeros(N_ACC)
    img = np.zeros((4, 3))
    start = np.zeros((4, 3))
    fq = np.zeros(4)
    flags = SF_OK
    rigid = math.isinf(beta)
    for j in range(N_THETA):
        if not want[j]:
            continue
        if j == T_BETA and rigid:
            dmu[j] = 0.0
            dz[j, :] = 0.0
            continue
        h = _step(theta, j, rel)
        if j == T_ETA and not (eta - (order // 2) * h >= ETA_ELASTIC) and not rigid:
            flags |= SF_KINK  # the +-h maps straddle the elastic model (or eta_c = 0)
            continue
        if j == T_ETA and rigid:
            dmu[j] = 0.0  # a rigid contact has no contact dashpot
            dz[j, :] = 0.0
            continue
        # the fourth-order stencil (+-h, +-2h): the map at fixed z* can bend on a scale of
        # 1e-4 of a parameter (a near-tangential event), where +-h alone is off by 1e-4
        kink = False
        for q in range(4):
            if order == 2 and (q == 0 or q == 3):
                continue
            tq = theta.copy()
            tq[j] += STENCIL[q] * h
            okq, sq, zq, phq, evq = _map_at(tq, on_substrate, sr, zf, ph, nd, p, max_events,
                                            accq)
            if not okq or phq != ph or evq != ev:
                kink = True
                break
            img[q, :] = zq
            start[q, :] = sq
            fq[q] = accq[A_F]
        if kink:
            flags |= SF_KINK
            continue
        rhs = np.zeros(nd)
        for i in range(nd):
            rhs[i] = _difference(img[:, i], h, order)
        x, ok = _solve_small(lhs, rhs, nd)
        if not ok:
            flags |= SF_NEUTRAL
            continue
        for i in range(3):  # the coordinates a constraint sets follow the parameters
            dz[j, i] = x[i] if i < nd else _difference(start[:, i], h, order)
        if pure:
            dmu[j] = 0.0  # f = n throughout, in every nearby orbit with its events
            continue
        dF = _difference(fq, h, order)
        for i in range(nd):
            dF += G[i] * x[i]
        dN = _normal_rate(a, p) if j == T_A else 0.0
        dmu[j] = (dF - mu * dN) / N
    return flags


@jit
def orbit_sensitivity_many(alpha, beta, a, V, zeta, eta, a_x, phase_x, on_substrate, state,
                           period, max_events, rel, order, want, dmu, dz, flags, sr):
    """:func:`orbit_sensitivity` over arrays of points (``state`` rows ``(y, x', e, ph)``;
    rows with ``period[i] <= 0`` are skipped: flags ``SF_FAILED``, nan).
    """
    for i in range(V.shape[0]):
        if period[i] <= 0:
            dmu[i, :] = math.nan
            dz[i, :, :] = math.nan
            flags[i] = SF_FAILED
            continue
        flags[i] = orbit_sensitivity(alpha[i], beta[i], a[i], V[i], zeta[i], eta[i], a_x[i],
                                     phase_x[i], on_substrate[i], state[i, 0], state[i, 1],
                                     state[i, 2], int(state[i, 3]), period[i], max_events,
                                     rel, order, want, dmu[i], dz[i], sr[i])


__all__ = ["N_THETA", "REL_STEP", "orbit_sensitivity", "orbit_sensitivity_many"]
