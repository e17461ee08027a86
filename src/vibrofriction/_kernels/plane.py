"""The 2-D (transverse) in-plane solver: a tangential plane with isotropic friction.

Model (docs/inplane.md, "The 2-D solver"; scaled units): body ``u = (u_x, u_y)``, drift
removed ``y = u - (V tau, 0)``, velocity ``v``, contact spring elongation ``e = u - u_c``,
``n = max(0, 1 + a cos tau)``, in-plane oscillation ``X = a_x cos(tau + phase_x)``,
``Y = a_y cos(tau + phase_y)`` on the substrate (substrate velocity ``v_s = (X', Y')``)
or on the holder (the spring and dashpot pull on ``(V tau + X, Y)``, ``v_s = 0``)::

    v_x' = alpha   (D_x - y_x) + gamma   (h_x' - v_x) - f_x,
    v_y' = alpha_y (D_y - y_y) + gamma_y (h_y' - v_y) - f_y,   f = k e + c e',  |f| <= n,

the pin's stiffness and damping across the sliding its own (``alpha_y``, ``gamma_y = 2
zeta_y sqrt(alpha_y)``; an axisymmetric pin has ``alpha_y = alpha``, ``zeta_y = zeta``),
the contact isotropic.  Stick: ``e' = v - v_s``,
``f = k e + c (v - v_s)``.  Slip, Kelvin-Voigt (``c > 0``): ``f = n F/|F|`` with ``F =
k e + c (v - v_s)``, ``e' = (f - k e)/c``.  Slip, Jenkins (``c = 0``): ``|e| = n/k``,
``d = e/|e|``, ``f = n d``, ``e' = w - lam d`` with ``w = v - v_s`` and the slip speed
``lam = d.w - n'/k`` (slip ends where it falls to 0).  Flight: ``f = 0``, ``e' = -k e/c``
(``e = 0`` for Jenkins).  A static coefficient above the kinetic one (``static_ratio = s >
1``, ``P[P_SR]``): stick holds while ``|f| <= s n`` (the static circle), slip exerts ``n``
(the kinetic one), so the force drops at each stick -> slip (a Jenkins contact's ``e``
jumps to the kinetic cone) and the phase at a section is carried with the state
(:func:`entry_hint`, ``W[W_MODE]``).

Method: every phase (stick, slip, flight) is integrated by the Dormand-Prince 5(4)
embedded Runge-Kutta pair (local extrapolation, error control on ``y, v, e`` and the
force integrals), the stick/slip switches located by the Illinois method on the step
length (each trial a fresh RK step from the step's start, so a switch is found to
round-off of the 5th-order solution), the axis cut at every drive period and, for
``a > 1``, at lift-off and touch-down (Jenkins contact: the contact arcs shortened by
``DELTA`` at both ends, where the slip direction's equation is singular).  The steady
state is a fixed point of the period map on the section ``tau = 2 pi k`` (6 states),
found by plain iteration and then Newton's method with the period map's exact Jacobian
(the tangent carried along the integration, :func:`period_map_tangent`);
the means are integrated over one period of the orbit.  Where Newton fails or the
orbit is unstable the long-time average over a window answers (status averaged).
"""

import math

import numpy as np

from .codes import (
    EV_SLIP_TO_STICK,
    EV_STICK_TO_SLIP,
    FLIGHT,
    I_DEGENERATE,
    I_EVENTS,
    I_PERIOD,
    I_PERIODS,
    I_PHASE,
    I_STATUS,
    LINK_GIVEN,
    LINK_PREVIOUS,
    O_E,
    O_ERR,
    O_F,
    O_FLIGHT,
    O_LAT,
    O_MU,
    O_MULT,
    O_SETTLE,
    O_SLIP,
    O_SLIP_NEG,
    O_STICK,
    O_WORK,
    O_XD,
    O_Y,
    SLIP_NEG,
    SLIP_POS,
    ST_AVERAGED,
    ST_FAILED,
    ST_NOT_CONVERGED,
    ST_PERIODIC,
    STICK,
    T_A_X,
    T_A_Y,
    T_ALPHA,
    T_ALPHA_Y,
    T_AMPLITUDE,
    T_BETA,
    T_ETA_C,
    T_INPLANE_ON,
    T_PHASE_X,
    T_PHASE_Y,
    T_STATIC_RATIO,
    T_V,
    T_ZETA,
    T_ZETA_Y,
)
from .dopri import (
    _A21,
    _A31,
    _A32,
    _A41,
    _A42,
    _A43,
    _A51,
    _A52,
    _A53,
    _A54,
    _A61,
    _A62,
    _A63,
    _A64,
    _A65,
    _B1,
    _B3,
    _B4,
    _B5,
    _B6,
    _C2,
    _C3,
    _C4,
    _C5,
    _E1,
    _E3,
    _E4,
    _E5,
    _E6,
    _E7,
)
from .jit import jit, jit_bare, jit_inline
from .newton import dense_spectral_radius
from .steady import closing_in, history, lagrange_weight

TWO_PI = 2.0 * math.pi
# one slip mode in 2-D (its direction is part of the state): it carries the code of forward
# slip, and the history and the results split it into slip+ and slip- by the sign of f_x
SLIP = SLIP_POS
DELTA = 1e-7
"""Jenkins contact with ``a > 1``: each contact arc is shortened by this at both ends."""
MARGIN = 1e-12
"""After a switch the new phase starts this (relative) distance inside its domain."""
N_Z = 8  # y_x, y_y, v_x, v_y, e_x, e_y, int f_x, int f_y
N_S = 6  # the section state: y_x, y_y, v_x, v_y, e_x, e_y
# parameter vector
P_ALPHA, P_GAMMA, P_K, P_C, P_A, P_V, P_AX, P_PX, P_AY, P_PY, P_HOLDER = range(11)
P_ALPHA_Y, P_GAMMA_Y = 11, 12  # the pin across the sliding
P_SR = 13  # static_ratio: a stuck contact holds while |f| <= P[P_SR] n
# cos and sin of the in-plane phases: the drive at t from cos t and sin t (one pair a stage)
P_CPX, P_SPX, P_CPY, P_SPY = 14, 15, 16, 17
# the exact flow of the linear phases (stick, flight) over a step of P[P_H]
# (:func:`linear_flows`): the augmented state w = (z, cos t, sin t, 1) (N_L) moves as
# w' = A w, so w(t + H) = Phi w(t); each flow's Phi, and for stick the rows F of the
# contact force f = F w and their rates F A
P_H = 18
N_L = N_Z + 3
P_PHI_STICK = 19
P_F_STICK = P_PHI_STICK + N_L * N_L
P_FA_STICK = P_F_STICK + 2 * N_L
P_PHI_FLIGHT = P_FA_STICK + 2 * N_L
N_P = P_PHI_FLIGHT + N_L * N_L
W_MODE = 14
"""The row of the work array ``W`` that carries the phase across a section where the state
does not fix it (``static_ratio > 1``): ``W[W_MODE, 0]`` the phase the period map starts
from, ``W[W_MODE, 1]`` the phase it ended in (:func:`entry_hint`)."""
W_KEEP = 15
"""``W[W_KEEP:W_KEEP + 9]``: an event's last trial step past the switch (its end, its rate
and its stages), kept for the step the event takes (:func:`_rk_segment`)."""
W_EXACT = 24
"""``W[W_EXACT:W_EXACT + 2]``: the state and its successor of :func:`_exact_steps`."""
N_W = 26
# counters: events, steps, rejected steps, failures; then the step budget of a period
# (0: MAX_STEPS_PER_PERIOD; Newton's trial states get a smaller one)
C_EVENTS, C_STEPS, C_REJECT, C_FAIL, C_LIMIT = range(5)
N_C = 5
MAX_STEPS_PER_PERIOD = 1_000_000
"""Runge-Kutta steps beyond which a drive period fails (about a second: a bound on the
work, never reached by a motion of the benchmarks, which take 50 to 10^4 steps)."""
TRIAL_STEPS = 20
"""Newton's trial states may take this many times the steps of the period from the
current iterate (a state far off the orbit can be very costly: a bound on the work)."""
NEWTON_STEP_CAP = 4.0
"""Newton's step is scaled down to at most this times ``1 + |s|`` (a near-singular
``J - I`` gives absurd steps)."""
DIFF_STEP = 1e-7
"""The relative step of Newton's difference Jacobian at the solve's own tolerance."""
ROUGH_RTOL = 1e-8
"""Newton first converges at this tolerance where the solve's is tighter (its Jacobians,
six period maps each, cost about 40 % of those at ``1e-10``), then at the solve's tolerance
by chord steps on the Jacobian of the rough orbit (:func:`_orbit_search`)."""
ROUGH_SKIPPED, ROUGH_FOUND, ROUGH_FAILED = 0, 1, 2  # :func:`_rough_orbit`'s outcomes
POLISH = 0.01
"""Where the section residual counts in the error (:data:`POLISH_SHARE`), the chord steps at
``rtol`` go on to this times Newton's ``tol`` (where each cuts the residual tenfold): a chord
step converges linearly, Newton's step from the rough orbit's distance would have overshot
``tol`` by as much."""
POLISH_SHARE = 0.01
"""... that is, where the residual's term of the stated error is above this share of the
tolerance's term (:func:`_orbit_error`); below it another map at ``rtol`` would change the
stated error by less than this share, and the means by less than the error."""
ROUGH_STEP = 1e3
"""... whose difference step is this times ``ROUGH_RTOL`` (at the default ``rtol = 1e-10``,
:data:`DIFF_STEP` is the same multiple: the map's noise over the step alike)."""



@jit_inline
def _length(x, y):
    """``|(x, y)|``: ``sqrt(x^2 + y^2)``, not ``math.hypot`` (its guard against overflow costs
    about 8 ns a call, a sixth of a right-hand side; the components here are of order 1).
    """
    return math.sqrt(x * x + y * y)


@jit
def _normal(a, ct, st):
    """``n = max(0, 1 + a cos t)`` and ``n'`` from ``ct = cos t``, ``st = sin t``."""
    n = 1.0 + a * ct
    if n < 0.0:
        return 0.0, 0.0
    return n, -a * st


@jit
def normal_force(a, t):
    """``n = max(0, 1 + a cos t)`` and ``n'``."""
    return _normal(a, math.cos(t), math.sin(t))


@jit
def _drive(P, ct, st):
    """:func:`drive` from ``ct = cos t``, ``st = sin t`` (the phases' by the addition
    theorem: the stages of a step cost one cosine and one sine).
    """
    ax, ay = P[P_AX], P[P_AY]
    cx, sx = ct * P[P_CPX] - st * P[P_SPX], st * P[P_CPX] + ct * P[P_SPX]
    cy, sy = ct * P[P_CPY] - st * P[P_SPY], st * P[P_CPY] + ct * P[P_SPY]
    if P[P_HOLDER] > 0.0:
        return ax * cx, ay * cy, P[P_V] - ax * sx, -ay * sy, 0.0, 0.0
    return 0.0, 0.0, P[P_V], 0.0, -ax * sx, -ay * sy


@jit
def drive(P, t):
    """``(D_x, D_y, h_x', h_y', v_sx, v_sy)``: the holder's offset from ``(V tau, 0)``, its
    velocity, and the substrate velocity at ``t``.
    """
    return _drive(P, math.cos(t), math.sin(t))


@jit
def contact(mode, P, t, z):
    """``(f_x, f_y, e'_x, e'_y, lam)`` of the state ``z`` in ``mode``."""
    ct, st = math.cos(t), math.sin(t)
    _, _, _, _, vsx, vsy = _drive(P, ct, st)
    return _contact(mode, P, ct, st, z, vsx, vsy)


@jit
def _contact(mode, P, ct, st, z, vsx, vsy):
    """:func:`contact` from ``cos t``, ``sin t`` and the substrate's velocity."""
    k, c = P[P_K], P[P_C]
    wx, wy = z[2] - vsx, z[3] - vsy
    if mode == FLIGHT:
        if c > 0.0:
            return 0.0, 0.0, -k * z[4] / c, -k * z[5] / c, 0.0
        return 0.0, 0.0, 0.0, 0.0, 0.0
    if mode == STICK:
        return k * z[4] + c * wx, k * z[5] + c * wy, wx, wy, 0.0
    n, dn = _normal(P[P_A], ct, st)
    if c > 0.0:
        Fx, Fy = k * z[4] + c * wx, k * z[5] + c * wy
        F = _length(Fx, Fy)
        fx, fy = n * Fx / F, n * Fy / F
        return fx, fy, (fx - k * z[4]) / c, (fy - k * z[5]) / c, (F - n) / c
    r = _length(z[4], z[5])
    dx, dy = z[4] / r, z[5] / r
    lam = dx * wx + dy * wy - dn / k
    return n * dx, n * dy, wx - lam * dx, wy - lam * dy, lam


@jit
def max_step(P):
    """The longest Runge-Kutta step: an eighth of the fastest natural period (the body
    on its spring, on both springs, or the contact's relaxation ``k/c``).
    """
    al = max(P[P_ALPHA], P[P_ALPHA_Y])
    w = max(1.0, math.sqrt(al), math.sqrt(al + P[P_K]))
    if P[P_C] > 0.0:
        w = max(w, P[P_K] / P[P_C])
    return TWO_PI / (8.0 * w)


@jit_inline
def rhs(mode, P, t, z, dz):
    """The right-hand side of the phase ``mode`` into ``dz``."""
    _rhs_at(mode, P, math.cos(t), math.sin(t), z, dz)


@jit_inline
def _rhs_at(mode, P, ct, st, z, dz):
    """:func:`rhs` at ``cos t = ct``, ``sin t = st``."""
    al, g, aly, gy = P[P_ALPHA], P[P_GAMMA], P[P_ALPHA_Y], P[P_GAMMA_Y]
    Dx, Dy, hdx, hdy, vsx, vsy = _drive(P, ct, st)
    fx, fy, ex, ey, _ = _contact(mode, P, ct, st, z, vsx, vsy)
    dz[0] = z[2] - P[P_V]
    dz[1] = z[3]
    dz[2] = al * (Dx - z[0]) + g * (hdx - z[2]) - fx
    dz[3] = aly * (Dy - z[1]) + gy * (hdy - z[3]) - fy
    dz[4] = ex
    dz[5] = ey
    dz[6] = fx
    dz[7] = fy


@jit_inline
def switch_function(mode, P, t, z):
    """Positive inside the phase, falling through 0 where it ends (flight: 1)."""
    return _switch_at(mode, P, math.cos(t), math.sin(t), z)


@jit_inline
def _switch_at(mode, P, ct, st, z):
    """:func:`switch_function` at ``cos t = ct``, ``sin t = st``."""
    if mode == FLIGHT:
        return 1.0
    _, _, _, _, vsx, vsy = _drive(P, ct, st)
    if mode == STICK:
        n, _ = _normal(P[P_A], ct, st)
        fx, fy, _, _, _ = _contact(STICK, P, ct, st, z, vsx, vsy)
        return P[P_SR] * n - _length(fx, fy)
    return _contact(SLIP, P, ct, st, z, vsx, vsy)[4]


@jit_bare
def rk_step(mode, P, t, z, k1, h, znew, k7, K):
    """One Dormand-Prince step of length ``h`` from ``(t, z)`` (``k1 = f(t, z)``):
    ``znew``, ``k7 = f(t + h, znew)``; the error estimate's components into ``K[6]``
    (``K`` is (7, N_Z) scratch).  Returns ``(cos, sin)`` of ``t + h`` (the last two stages'
    time, and the step's end's: the switch function and the projection there take them).
    """
    tmp = K[6]
    for i in range(N_Z):
        tmp[i] = z[i] + h * _A21 * k1[i]
    rhs(mode, P, t + _C2 * h, tmp, K[1])
    for i in range(N_Z):
        tmp[i] = z[i] + h * (_A31 * k1[i] + _A32 * K[1, i])
    rhs(mode, P, t + _C3 * h, tmp, K[2])
    for i in range(N_Z):
        tmp[i] = z[i] + h * (_A41 * k1[i] + _A42 * K[1, i] + _A43 * K[2, i])
    rhs(mode, P, t + _C4 * h, tmp, K[3])
    for i in range(N_Z):
        tmp[i] = z[i] + h * (_A51 * k1[i] + _A52 * K[1, i] + _A53 * K[2, i]
                             + _A54 * K[3, i])
    rhs(mode, P, t + _C5 * h, tmp, K[4])
    for i in range(N_Z):
        tmp[i] = z[i] + h * (_A61 * k1[i] + _A62 * K[1, i] + _A63 * K[2, i]
                             + _A64 * K[3, i] + _A65 * K[4, i])
    ce, se = math.cos(t + h), math.sin(t + h)
    _rhs_at(mode, P, ce, se, tmp, K[5])
    for i in range(N_Z):
        znew[i] = z[i] + h * (_B1 * k1[i] + _B3 * K[2, i] + _B4 * K[3, i]
                              + _B5 * K[4, i] + _B6 * K[5, i])
    _rhs_at(mode, P, ce, se, znew, k7)
    for i in range(N_Z):
        tmp[i] = h * (_E1 * k1[i] + _E3 * K[2, i] + _E4 * K[3, i] + _E5 * K[4, i]
                      + _E6 * K[5, i] + _E7 * k7[i])
    return ce, se


@jit_inline
def error_norm(z, znew, err, rtol, atol):
    s = 0.0
    for i in range(N_Z):
        sc = atol + rtol * max(abs(z[i]), abs(znew[i]))
        s += (err[i] / sc) ** 2
    return math.sqrt(s / N_Z)


@jit_inline
def rhs_jacobian(mode, P, t, z, D):
    """The Jacobian of :func:`rhs`'s first six components by the section state ``z[:6]``
    into ``D`` (6 x 6), in closed form: the body's springs and dashpots, and the contact's
    force and elongation rate of the phase ``mode`` (stick: ``f = k e + c w``; slip of a
    Kelvin-Voigt contact: ``f = n F/|F|``, ``F = k e + c w``, ``e' = (f - k e)/c``; of a
    Jenkins one: ``f = n d``, ``d = e/|e|``, ``e' = w - lam d``, ``lam = d.w - n'/k``;
    flight: ``f = 0``), ``w`` the contact point's velocity over the substrate's.
    """
    D[:] = 0.0
    D[0, 2] = 1.0
    D[1, 3] = 1.0
    D[2, 0], D[2, 2] = -P[P_ALPHA], -P[P_GAMMA]
    D[3, 1], D[3, 3] = -P[P_ALPHA_Y], -P[P_GAMMA_Y]
    k, c = P[P_K], P[P_C]
    if mode == FLIGHT:
        if c > 0.0:
            D[4, 4] = D[5, 5] = -k / c
        return
    if mode == STICK:
        D[2, 4] -= k
        D[3, 5] -= k
        D[2, 2] -= c
        D[3, 3] -= c
        D[4, 2] = D[5, 3] = 1.0
        return
    ct, st = math.cos(t), math.sin(t)
    _, _, _, _, vsx, vsy = _drive(P, ct, st)
    n, dn = _normal(P[P_A], ct, st)
    w0, w1 = z[2] - vsx, z[3] - vsy
    if c > 0.0:
        Fx, Fy = k * z[4] + c * w0, k * z[5] + c * w1
        F = _length(Fx, Fy)
        ux, uy = Fx / F, Fy / F
        q = n / F  # df/dF = q (I - u u^T)
        a00, a01, a11 = q * (1.0 - ux * ux), -q * ux * uy, q * (1.0 - uy * uy)
        for i in range(2):
            for j in range(2):
                aij = a00 if i + j == 0 else (a11 if i + j == 2 else a01)
                D[2 + i, 4 + j] -= k * aij
                D[2 + i, 2 + j] -= c * aij
                D[4 + i, 4 + j] = k * aij / c - (k / c if i == j else 0.0)
                D[4 + i, 2 + j] = aij
        return
    r = _length(z[4], z[5])
    dx, dy = z[4] / r, z[5] / r
    b00, b01, b11 = (1.0 - dx * dx) / r, -dx * dy / r, (1.0 - dy * dy) / r  # dd/de
    lam = dx * w0 + dy * w1 - dn / k
    bw0, bw1 = b00 * w0 + b01 * w1, b01 * w0 + b11 * w1  # dlam/de
    d0, d1 = dx, dy
    for i in range(2):
        di = d0 if i == 0 else d1
        for j in range(2):
            dj = d0 if j == 0 else d1
            bij = b00 if i + j == 0 else (b11 if i + j == 2 else b01)
            D[2 + i, 4 + j] -= n * bij
            D[4 + i, 2 + j] = (1.0 if i == j else 0.0) - di * dj
            D[4 + i, 4 + j] = -(di * (bw0 if j == 0 else bw1) + lam * bij)


# Dormand-Prince stages: nodes and coefficients by row (the first six stages; b the weights)
_DP_C = np.array([0.0, _C2, _C3, _C4, _C5, 1.0])
_DP_A = np.array([[0.0, 0.0, 0.0, 0.0, 0.0],
                  [_A21, 0.0, 0.0, 0.0, 0.0],
                  [_A31, _A32, 0.0, 0.0, 0.0],
                  [_A41, _A42, _A43, 0.0, 0.0],
                  [_A51, _A52, _A53, _A54, 0.0],
                  [_A61, _A62, _A63, _A64, _A65]])
_DP_B = np.array([_B1, 0.0, _B3, _B4, _B5, _B6])
N_T = 10
"""The tangent's work array ``T`` (``N_T`` x 6 x 6): ``T[0]`` the tangent ``Y`` carried
along (``dz/ds``, the section state's six components), ``T[1]`` scratch, ``T[2]`` the
Jacobian of the right-hand side, ``T[3]`` scratch (an exact step's product), ``T[4:10]``
the six stages; ``T`` of length 0: no tangent (the plain integration)."""


@jit_bare
def tangent_step(mode, P, t, z, k1, K, h, znew, T):
    """Carry the tangent ``T[0]`` over the Dormand-Prince step of length ``h`` from ``(t,
    z)`` that :func:`rk_step` just took (its stages ``k1``, ``K[1:6]``) to ``znew``: the
    same stages applied to ``Y' = Df Y`` (the exact derivative of the step), then, for a
    Jenkins slip, the derivative of :func:`project` (``I - d d^T`` on ``e``).  Stick and
    flight are linear with constant coefficients: their ``Df`` is taken once a step.
    """
    Y, st, D = T[0], T[1, 0], T[2]
    linear = mode != SLIP
    if linear:
        rhs_jacobian(mode, P, t, z, D)
    for i in range(6):
        if not linear:
            for m in range(2, N_S):  # the stage's state (Df reads y', e)
                acc = _DP_A[i, 0] * k1[m]
                for j in range(1, i):
                    acc += _DP_A[i, j] * K[j, m]
                st[m] = z[m] + h * acc
            rhs_jacobian(mode, P, t + _DP_C[i] * h, st, D)
        KY = T[4 + i]
        for q in range(N_S):  # a column at a time, its stage argument in scalars
            a0, a1, a2, a3, a4, a5 = Y[0, q], Y[1, q], Y[2, q], Y[3, q], Y[4, q], Y[5, q]
            for j in range(i):
                c = h * _DP_A[i, j]
                Kj = T[4 + j]
                a0 += c * Kj[0, q]
                a1 += c * Kj[1, q]
                a2 += c * Kj[2, q]
                a3 += c * Kj[3, q]
                a4 += c * Kj[4, q]
                a5 += c * Kj[5, q]
            KY[0, q] = a2  # y' = v
            KY[1, q] = a3
            for r in range(2, N_S):
                KY[r, q] = (((((0.0 + D[r, 0] * a0) + D[r, 1] * a1) + D[r, 2] * a2)
                              + D[r, 3] * a3) + D[r, 4] * a4) + D[r, 5] * a5
    for r in range(N_S):
        for q in range(N_S):
            acc = Y[r, q]
            for i in range(6):
                acc += h * _DP_B[i] * T[4 + i, r, q]
            Y[r, q] = acc
    if mode == SLIP and P[P_C] == 0.0:
        _cone_tangent(znew, Y, 1.0)


@jit
def _cone_tangent(z, Y, scale):
    """``Y``'s rows of ``e`` times ``scale (I - d d^T)``, ``d = e/|e|``: the derivative of a
    map that puts ``e`` at a given length, its direction kept.
    """
    r = _length(z[4], z[5])
    dx, dy = z[4] / r, z[5] / r
    for q in range(N_S):
        y4, y5 = Y[4, q], Y[5, q]
        dot = dx * y4 + dy * y5
        Y[4, q] = scale * (y4 - dx * dot)
        Y[5, q] = scale * (y5 - dy * dot)


@jit_inline
def project(mode, P, t, z):
    """Jenkins slip: put ``e`` back on the cone ``|e| = n/k`` (its direction kept)."""
    _project_at(mode, P, math.cos(t), z)


@jit_inline
def _project_at(mode, P, ct, z):
    """:func:`project` at ``cos t = ct``."""
    if mode == SLIP and P[P_C] == 0.0:
        n, _ = _normal(P[P_A], ct, 0.0)
        r = _length(z[4], z[5])
        if r > 0.0:
            z[4] *= n / (P[P_K] * r)
            z[5] *= n / (P[P_K] * r)


@jit
def _linear_rows(mode, P, t, z, out):
    """The right-hand side (:func:`rhs`) into ``out[:N_Z]`` and the contact force into
    ``out[N_Z:N_Z + 2]``: for stick and flight both linear in ``(z, cos t, sin t, 1)``.
    """
    rhs(mode, P, t, z, out)
    fx, fy, _, _, _ = contact(mode, P, t, z)
    out[N_Z], out[N_Z + 1] = fx, fy


@jit
def _linear_system(mode, P, A, F):
    """The constant matrix ``A`` (N_L x N_L) of ``w' = A w``, ``w = (z, cos t, sin t, 1)``,
    of the linear phase ``mode`` (stick or flight), and the rows ``F`` (2 x N_L) of its
    contact force ``f = F w``, read off :func:`rhs` and :func:`contact` themselves: a
    column of ``z`` from a unit state (the response to ``z = 0`` taken off), those of the
    drive from ``z = 0`` at ``t = 0, pi/2, pi`` (``cos t``, ``sin t``, 1 there).
    """
    zero, unit = np.zeros(N_Z), np.zeros(N_Z)
    r0, r1, rq, rp = np.empty(N_Z + 2), np.empty(N_Z + 2), np.empty(N_Z + 2), np.empty(N_Z + 2)
    _linear_rows(mode, P, 0.0, zero, r0)
    _linear_rows(mode, P, 0.5 * math.pi, zero, rq)
    _linear_rows(mode, P, math.pi, zero, rp)
    A[:] = 0.0
    for j in range(N_Z):
        unit[:] = 0.0
        unit[j] = 1.0
        _linear_rows(mode, P, 0.0, unit, r1)
        for i in range(N_Z + 2):
            v = r1[i] - r0[i]
            if i < N_Z:
                A[i, j] = v
            else:
                F[i - N_Z, j] = v
    for i in range(N_Z + 2):
        cos_, one = 0.5 * (r0[i] - rp[i]), 0.5 * (r0[i] + rp[i])
        sin_ = rq[i] - one
        if i < N_Z:
            A[i, N_Z], A[i, N_Z + 1], A[i, N_Z + 2] = cos_, sin_, one
        else:
            F[i - N_Z, N_Z], F[i - N_Z, N_Z + 1], F[i - N_Z, N_Z + 2] = cos_, sin_, one
    A[N_Z, N_Z + 1] = -1.0  # (cos t)' = -sin t
    A[N_Z + 1, N_Z] = 1.0  # (sin t)' = cos t


EXPM_TERMS = 30
"""Taylor terms of :func:`_expm` at most (its argument scaled to a norm of 1/2: the terms
fall below round-off after about 18)."""


@jit
def _expm(A, h):
    """``exp(A h)`` by scaling and squaring: Taylor's series of ``A h / 2^q``, whose norm
    is at most 1/2, summed to round-off, then squared ``q`` times.  ``A`` is sparse (each
    axis couples to a few others), so each term multiplies the last by its nonzeros only.
    """
    n = A.shape[0]
    norm = 0.0
    for i in range(n):
        row = 0.0
        for j in range(n):
            row += abs(A[i, j])
        norm = max(norm, row * abs(h))
    q = max(0, int(math.ceil(math.log2(norm / 0.5)))) if norm > 0.5 else 0
    c = h / 2.0 ** q
    rows, cols, vals = np.empty(n * n, np.int64), np.empty(n * n, np.int64), np.empty(n * n)
    nnz = 0
    for i in range(n):
        for j in range(n):
            if A[i, j] != 0.0:
                rows[nnz], cols[nnz], vals[nnz] = i, j, A[i, j] * c
                nnz += 1
    E = np.eye(n)
    term = np.eye(n)
    nxt = np.empty((n, n))
    for m in range(1, EXPM_TERMS + 1):
        nxt[:] = 0.0
        for p in range(nnz):  # term @ X, X's nonzeros only
            kk, j, v = rows[p], cols[p], vals[p] / m
            for i in range(n):
                nxt[i, j] += term[i, kk] * v
        big, small = 0.0, 0.0
        for i in range(n):
            for j in range(n):
                term[i, j] = nxt[i, j]
                E[i, j] += nxt[i, j]
                small = max(small, abs(nxt[i, j]))
                big = max(big, abs(E[i, j]))
        if small <= 1e-17 * big:
            break
    for _ in range(q):
        E = E @ E
    return E


@jit
def linear_flows(P):
    """Fill ``P``'s exact flows of the linear phases over the step ``P[P_H]`` (half the
    longest Runge-Kutta step): stick's ``Phi``, ``F`` and ``F A``, flight's ``Phi``
    (:func:`_exact_steps`).
    """
    H = 0.5 * max_step(P)
    P[P_H] = H
    A, F = np.zeros((N_L, N_L)), np.zeros((2, N_L))
    _linear_system(STICK, P, A, F)
    P[P_PHI_STICK:P_F_STICK] = _expm(A, H).ravel()
    P[P_F_STICK:P_FA_STICK] = F.ravel()
    P[P_FA_STICK:P_PHI_FLIGHT] = (F @ A).ravel()
    _linear_system(FLIGHT, P, A, F)
    P[P_PHI_FLIGHT:N_P] = _expm(A, H).ravel()


@jit
def _cubic_dips(g0, d0, g1, d1):
    """Does the cubic of Hermite with values ``g0, g1 > 0`` and slopes ``d0, d1`` (over a
    unit interval) fall to 0 or below inside it?
    """
    # p(s) = g0 + d0 s + b s^2 + c s^3
    b = 3.0 * (g1 - g0) - 2.0 * d0 - d1
    c = 2.0 * (g0 - g1) + d0 + d1
    # p'(s) = d0 + 2 b s + 3 c s^2 = 0 at the extrema (nan: none)
    qa, qb, qc = 3.0 * c, 2.0 * b, d0
    x1 = x2 = math.nan
    if qa == 0.0:
        if qb != 0.0:
            x1 = -qc / qb
    else:
        disc = qb * qb - 4.0 * qa * qc
        if disc >= 0.0:
            sq = math.sqrt(disc)
            x1, x2 = (-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa)
    for x in (x1, x2):
        if 0.0 < x < 1.0 and g0 + x * (d0 + x * (b + x * c)) <= 0.0:
            return True
    return False


@jit
def _stick_margin(P, w, c, s):
    """The stick's switch function ``s_r n - |f|`` at the augmented state ``(w, c, s, 1)``
    (``w`` the state, ``c = cos t``, ``s = sin t``) and its rate (``f = F w``, ``f' = F A w``).
    """
    F, FA = P[P_F_STICK:P_FA_STICK], P[P_FA_STICK:P_PHI_FLIGHT]
    fx, fy, dfx, dfy = 0.0, 0.0, 0.0, 0.0
    for j in range(N_L):
        wj = w[j] if j < N_Z else (c if j == N_Z else (s if j == N_Z + 1 else 1.0))
        fx += F[j] * wj
        fy += F[N_L + j] * wj
        dfx += FA[j] * wj
        dfy += FA[N_L + j] * wj
    n, dn = _normal(P[P_A], c, s)
    f = _length(fx, fy)
    rate = P[P_SR] * dn - ((fx * dfx + fy * dfy) / f if f > 0.0 else _length(dfx, dfy))
    return P[P_SR] * n - f, rate


@jit_bare
def _exact_steps(mode, P, t, t1, z, acc, cnt, T, W):
    """Advance the linear phase ``mode`` (stick or flight) from ``t`` by its exact flow
    (:func:`linear_flows`) in whole steps ``H`` while they end before ``t1`` and, in
    stick, its switch function stays positive at the step's end and on the cubic of
    Hermite through both ends (a step that may hold the switch is left to the
    Runge-Kutta steps, which locate it).  Returns the time reached.
    """
    H = P[P_H]
    if mode == STICK:
        Phi = P[P_PHI_STICK:P_F_STICK].reshape((N_L, N_L))
    else:
        Phi = P[P_PHI_FLIGHT:N_P].reshape((N_L, N_L))
    if t + H > t1:
        return t
    # the augmented state (z, cos t, sin t, 1): z in a row of W, the rest in scalars
    w, wn = W[W_EXACT], W[W_EXACT + 1]
    for i in range(N_Z):
        w[i] = z[i]
    c, s = math.cos(t), math.sin(t)
    tangent = T.shape[0] > 0
    if tangent:
        Y, arg = T[0], T[3]
    ph = mode if mode != FLIGHT else 2
    g0, d0 = _stick_margin(P, w, c, s) if mode == STICK else (0.0, 0.0)
    while t + H <= t1:
        for i in range(N_Z):
            v = 0.0
            for j in range(N_Z):
                v += Phi[i, j] * w[j]
            v += Phi[i, N_Z] * c
            v += Phi[i, N_Z + 1] * s
            v += Phi[i, N_Z + 2] * 1.0
            wn[i] = v
        tn = t + H
        c, s = math.cos(tn), math.sin(tn)  # not propagated
        if mode == STICK:
            g1, d1 = _stick_margin(P, wn, c, s)
            if g1 <= 0.0 or _cubic_dips(g0, H * d0, g1, H * d1):
                break
            g0, d0 = g1, d1
        if tangent:
            for r in range(N_S):
                for q in range(N_S):
                    v = 0.0
                    for m in range(N_S):
                        v += Phi[r, m] * Y[m, q]
                    arg[r, q] = v
            for r in range(N_S):
                for q in range(N_S):
                    Y[r, q] = arg[r, q]
        _account(mode, P, t, H, wn, acc, ph, 0.0, 0.0)
        for i in range(N_Z):
            z[i] = wn[i]
        w, wn = wn, w
        cnt[C_STEPS] += 1
        t = tn
    return t


@jit_bare
def segment(mode, P, t, t1, z, h, rtol, atol, hmax, W, acc, cnt, T):
    """Integrate ``mode`` from ``t`` towards ``t1`` until its switch function falls
    through 0 (located to round-off) or ``t1``.  ``z`` is updated in place.  Returns
    ``(t_end, event, h)``.  ``acc`` accumulates the time in stick, slip, flight and in
    slip with ``f_x < 0`` (from step ends, linearly interpolated at a sign change).
    ``T``: the tangent carried along (:data:`N_T`; length 0: none).

    Stick and flight go by their exact flows (:func:`_exact_steps`) where a whole step of
    it is safe; the rest (a step that may hold the switch, the piece before ``t1``) by the
    Runge-Kutta steps of :func:`_rk_segment`.
    """
    # the phase a constant at each call: the compiled steps specialise to it (a third
    # faster than steps that test a variable phase).  That rests on LLVM inlining the steps
    # here; benchmarks/plane_floor.py's period costs show it (an edit of the steps that
    # cost a third more per period had lost it)
    if mode == SLIP:
        return _rk_segment(SLIP, P, t, t1, z, h, rtol, atol, hmax, W, acc, cnt, T)
    if mode == STICK:
        return _linear_segment(STICK, P, t, t1, z, h, rtol, atol, hmax, W, acc, cnt, T)
    return _linear_segment(FLIGHT, P, t, t1, z, h, rtol, atol, hmax, W, acc, cnt, T)


@jit_bare
def _linear_segment(mode, P, t, t1, z, h, rtol, atol, hmax, W, acc, cnt, T):
    """:func:`segment` of stick or flight: exact steps, the rest by Runge-Kutta steps."""
    if switch_function(mode, P, t, z) < 0.0:
        return t, True, h
    while True:
        t = _exact_steps(mode, P, t, t1, z, acc, cnt, T, W)
        tb = min(t + P[P_H], t1)
        t, event, h = _rk_segment(mode, P, t, tb, z, h, rtol, atol, hmax, W, acc, cnt, T)
        if event or t >= t1 or cnt[C_FAIL] > 0:
            return t, event, h


@jit_inline
def _copy_rows(z, k, K, z2, k2, K2, stages):
    """``z``, ``k`` (and with ``stages`` the Runge-Kutta stages ``K``) into ``z2``, ``k2``,
    ``K2``, element by element (no slice assignment: :func:`_rk_segment` runs without
    reference counting).
    """
    for i in range(N_Z):
        z2[i] = z[i]
        k2[i] = k[i]
    if stages:
        for j in range(7):
            for i in range(N_Z):
                K2[j, i] = K[j, i]


@jit_bare
def _rk_segment(mode, P, t, t1, z, h, rtol, atol, hmax, W, acc, cnt, T):
    """:func:`segment` by Dormand-Prince steps alone."""
    k1, k7, znew, zb, kb, K = W[0], W[1], W[2], W[3], W[4], W[5:12]
    g0 = switch_function(mode, P, t, z)
    if g0 < 0.0:
        return t, True, h
    rhs(mode, P, t, z, k1)
    ph = mode if mode != FLIGHT else 2
    while t < t1:
        hh = min(h, hmax)
        last = False
        if t + hh >= t1:
            hh = t1 - t
            last = True
        ce, se = rk_step(mode, P, t, z, k1, hh, znew, k7, K)
        en = error_norm(z, znew, K[6], rtol, atol)
        cnt[C_STEPS] += 1
        if not (en <= 1.0):
            cnt[C_REJECT] += 1
            if not math.isfinite(en) or hh < 1e-14 * (1.0 + abs(t)):
                cnt[C_FAIL] += 1
                return t, False, h
            h = hh * max(0.2, 0.9 * en ** -0.2)
            continue
        tn = t1 if last else t + hh
        if tn != t + hh:  # (the step's end rounds apart from t1)
            ce, se = math.cos(tn), math.sin(tn)
        _project_at(mode, P, ce, znew)
        g1 = _switch_at(mode, P, ce, se, znew)
        if g1 < 0.0:  # a switch inside the step: Illinois on the step length
            sl, gl, sr, gr = 0.0, g0, hh, g1
            side = 0
            width = 4e-16 * (abs(t) + hh)
            # the last trial past the switch is the step the event takes: kept, not redone
            tangent = T.shape[0] > 0
            right = False
            zr, kr, Kr = W[W_KEEP], W[W_KEEP + 1], W[W_KEEP + 2:W_KEEP + 9]
            for _ in range(80):
                if sr - sl <= width:
                    break
                if gl == 0.0:
                    # the left end is the root itself (its value rounds to 0): the next
                    # trial just past it, not a bisection towards it from the right
                    s = min(sl + width, 0.5 * (sl + sr))
                else:
                    s = (sl * gr - sr * gl) / (gr - gl)
                    if not (sl < s < sr):
                        s = 0.5 * (sl + sr)
                cs, ss = rk_step(mode, P, t, z, k1, s, zb, kb, K)
                _project_at(mode, P, cs, zb)
                gs = _switch_at(mode, P, cs, ss, zb)
                if gs < 0.0:
                    sr, gr = s, gs
                    right = True
                    _copy_rows(zb, kb, K, zr, kr, Kr, tangent)
                    if side == -1:
                        gl *= 0.5
                    side = -1
                else:
                    sl, gl = s, gs
                    if side == 1:
                        gr *= 0.5
                    side = 1
            if right:
                _copy_rows(zr, kr, Kr, zb, kb, K, tangent)
            else:
                cs, _ = rk_step(mode, P, t, z, k1, sr, zb, kb, K)
                _project_at(mode, P, cs, zb)
            if tangent:
                tangent_step(mode, P, t, z, k1, K, sr, zb, T)
            _account(mode, P, t, sr, zb, acc, ph, k1[6], kb[6])
            for i in range(N_Z):
                z[i] = zb[i]
            cnt[C_EVENTS] += 1
            return t + sr, True, h
        if T.shape[0] > 0:
            tangent_step(mode, P, t, z, k1, K, hh, znew, T)
        _account(mode, P, t, tn - t, znew, acc, ph, k1[6], k7[6])
        for i in range(N_Z):
            z[i] = znew[i]
            k1[i] = k7[i]
        t = tn
        g0 = g1
        if not last:
            h = hh * min(5.0, max(0.2, 0.9 * en ** -0.2))
    return t, False, h


@jit_inline
def _account(mode, P, t, dt, z1, acc, ph, f0, f1):
    """Add a step of ``dt`` from ``t`` to the state ``z1`` to the phases' times ``acc``; in slip
    the time with ``f_x < 0`` from ``f_x`` at its ends, ``f0`` and ``f1`` (the step's first
    and last stages' rates of ``int f_x``: the direction a Jenkins contact's return to its
    cone keeps).
    """
    acc[ph] += dt
    if acc.shape[0] > 4 and mode != FLIGHT:  # a check asked for: the largest |f| - bound
        fx, fy, _, _, _ = contact(mode, P, t + dt, z1)
        n, _ = normal_force(P[P_A], t + dt)
        bound = P[P_SR] * n if mode == STICK else n  # static circle in stick, kinetic in slip
        acc[4] = max(acc[4], math.hypot(fx, fy) - bound)
    if mode == SLIP:
        if f0 < 0.0 and f1 < 0.0:
            acc[3] += dt
        elif f0 < 0.0 <= f1:
            acc[3] += dt * f0 / (f0 - f1)
        elif f1 < 0.0 <= f0:
            acc[3] += dt * f1 / (f1 - f0)


@jit
def entry(P, t, z):
    """The phase of a contact state with no history (a section start, a touch-down of a
    viscous contact); a Jenkins slip state is put on the cone.
    """
    k, c = P[P_K], P[P_C]
    n, _ = normal_force(P[P_A], t)
    if c > 0.0:
        fx, fy, _, _, _ = contact(STICK, P, t, z)
        return STICK if math.hypot(fx, fy) <= n else SLIP
    r = math.hypot(z[4], z[5])
    if k * r < n * (1.0 - 1e-9) or r == 0.0:
        return STICK
    return _onto_cone(P, t, z, n, k, r)


@jit
def _onto_cone(P, t, z, n, k, r):
    """A Jenkins contact's elongation ``e`` (of length ``r``) put on the kinetic cone ``|e| =
    n/k``, its direction kept: slip where the slip speed there is positive, else stick a
    relative :data:`MARGIN` inside.
    """
    z[4] *= n / (k * r)
    z[5] *= n / (k * r)
    if contact(SLIP, P, t, z)[4] > 0.0:
        return SLIP
    z[4] *= 1.0 - MARGIN
    z[5] *= 1.0 - MARGIN
    return STICK


@jit
def entry_hint(P, t, z, hint):
    """The phase of a contact state whose phase before was ``hint`` (``z`` adjusted in
    place).  ``static_ratio = 1`` or a slipping ``hint``: :func:`entry` (slip where the
    state is on or beyond the kinetic circle with a positive slip speed).  Above 1 a
    stuck state holds up to the static circle ``static_ratio n`` (a force between the two
    circles is held in stick and slides in slip: the state alone does not fix the phase,
    which is therefore carried across the section): stick unless it lies at or beyond
    the static circle with its margin falling; then it slips, the force dropping to ``n``
    (a Jenkins contact's elongation jumps to the kinetic cone ``n/k``), and sticks again
    at once where its slip speed there is not positive.
    """
    sr = P[P_SR]
    if sr == 1.0 or hint == SLIP:
        return entry(P, t, z)
    k, c = P[P_K], P[P_C]
    n, dn = normal_force(P[P_A], t)
    if c > 0.0:
        fx, fy, _, _, _ = contact(STICK, P, t, z)
        return STICK if math.hypot(fx, fy) <= sr * n else SLIP
    r = math.hypot(z[4], z[5])
    if r == 0.0 or k * r < sr * n * (1.0 - 1e-9):
        return STICK
    _, _, _, _, vsx, vsy = drive(P, t)
    rate = (z[4] * (z[2] - vsx) + z[5] * (z[3] - vsy)) / r  # d|e|/dt in stick
    if k * rate <= sr * dn:  # the margin sr n - k |e| does not fall: still stuck
        z[4] *= sr * n / (k * r) * (1.0 - MARGIN)
        z[5] *= sr * n / (k * r) * (1.0 - MARGIN)
        return STICK
    return _onto_cone(P, t, z, n, k, r)  # from the static circle: the jump


@jit
def switch(mode, P, t, z):
    """The phase after the switch of ``mode`` at ``t`` (``z`` adjusted in place).

    Stick to slip of a Jenkins contact puts ``e`` on the kinetic cone ``|e| = n/k``: with
    ``static_ratio > 1`` a jump from the static circle, after which the slip speed may be
    negative at once (the contact sticks again, at ``n/k``: a slip of no duration).
    """
    k, c = P[P_K], P[P_C]
    if c > 0.0:
        return SLIP if mode == STICK else STICK
    n, _ = normal_force(P[P_A], t)
    r = math.hypot(z[4], z[5])
    if mode == STICK:
        if r > 0.0:
            z[4] *= n / (k * r)
            z[5] *= n / (k * r)
        if P[P_SR] != 1.0 and contact(SLIP, P, t, z)[4] <= 0.0:
            z[4] *= 1.0 - MARGIN
            z[5] *= 1.0 - MARGIN
            return STICK
        return SLIP
    s = n / (k * r) * (1.0 - MARGIN)
    z[4] *= s
    z[5] *= s
    return STICK


@jit
def touchdown(P, t, z):
    """Contact begins at ``t`` after a flight."""
    k = P[P_K]
    if P[P_C] > 0.0:
        return entry_hint(P, t, z, STICK)  # a re-formed contact starts stuck
    n, dn = normal_force(P[P_A], t)
    _, _, _, _, vsx, vsy = drive(P, t)
    wx, wy = z[2] - vsx, z[3] - vsy
    w = math.hypot(wx, wy)
    z[4] = 0.0
    z[5] = 0.0
    if P[P_SR] * dn >= k * w or w == 0.0:  # stuck while the static circle grows faster
        return STICK
    z[4] = n / k * wx / w
    z[5] = n / k * wy / w
    return SLIP


@jit
def one_period(P, t0, z, mode, rtol, atol, hmax, W, acc, cnt, max_events, T):
    """Integrate one drive period from ``t0 = 2 pi j`` (``z`` in place, the integrals
    ``z[6:8]`` accumulated); ``mode`` the phase at ``t0``.  Returns ``(mode, ok)``.
    ``T``: the tangent carried along (:func:`segment`; through each switch by
    :func:`_switch_tangent`, through lift-off and touch-down by their maps' derivatives).
    """
    a = P[P_A]
    jenkins = P[P_C] == 0.0
    ends = np.empty(3)
    contact_ = np.empty(3, np.bool_)
    m = 1
    if a > 1.0:
        th = math.acos(-1.0 / a)
        d = DELTA if jenkins else 0.0
        ends[0], ends[1], ends[2] = t0 + th - d, t0 + TWO_PI - th + d, t0 + TWO_PI
        contact_[0], contact_[1], contact_[2] = True, False, True
        m = 3
    else:
        ends[0] = t0 + TWO_PI
        contact_[0] = True
    t = t0
    h = hmax
    ev = 0
    limit = cnt[C_STEPS] + (cnt[C_LIMIT] if cnt[C_LIMIT] > 0 else MAX_STEPS_PER_PERIOD)
    for j in range(m):
        t1 = ends[j]
        if not contact_[j]:
            if jenkins:
                z[4] = 0.0
                z[5] = 0.0
                if T.shape[0] > 0:  # at a fixed time: the reset's derivative
                    T[0, 4, :] = 0.0
                    T[0, 5, :] = 0.0
            mode = FLIGHT
        elif mode == FLIGHT:
            mode = touchdown(P, t, z)
            if T.shape[0] > 0 and jenkins:
                _touchdown_tangent(P, t, z, mode, T[0])
        while t < t1:
            t, event, h = segment(mode, P, t, t1, z, h, rtol, atol, hmax, W, acc, cnt, T)
            if cnt[C_FAIL] > 0:
                return mode, False
            if cnt[C_STEPS] > limit:
                cnt[C_FAIL] += 1
                return mode, False
            if event:
                if T.shape[0] > 0:
                    mode = _switch_tangent(mode, P, t, z, T)
                else:
                    mode = switch(mode, P, t, z)
                ev += 1
                if ev > max_events:
                    cnt[C_FAIL] += 1
                    return mode, False
    return mode, True


@jit
def _touchdown_tangent(P, t, z, mode, Y):
    """The derivative of a Jenkins contact's touch-down (:func:`touchdown`, at a fixed
    time) on the tangent ``Y``: ``e = 0`` where it sticks, ``e = (n/k) w/|w|`` where it
    slips (``w`` the contact point's velocity over the substrate's).
    """
    for q in range(N_S):
        Y[4, q] = Y[5, q] = 0.0
    if mode != SLIP:
        return
    n, _ = normal_force(P[P_A], t)
    _, _, _, _, vsx, vsy = drive(P, t)
    w0, w1 = z[2] - vsx, z[3] - vsy
    w = math.hypot(w0, w1)
    u0, u1 = w0 / w, w1 / w
    sc = n / (P[P_K] * w)
    for q in range(N_S):
        dot = u0 * Y[2, q] + u1 * Y[3, q]
        Y[4, q] = sc * (Y[2, q] - u0 * dot)
        Y[5, q] = sc * (Y[3, q] - u1 * dot)


SALTATION_STEP = 1e-7
"""The relative step of the central differences of a switch function and a switch's map
(:func:`_switch_tangent`): their second-order error and the round-off over the step are
both about ``1e-14`` of their scale."""


@jit
def _switch_tangent(mode, P, t, z, T):
    """:func:`switch` of ``mode`` at its event ``(t, z)``, the tangent ``T[0]`` carried
    through it: ``Y+ = DR Y- + (DR f- + dR/dt - f+) dt*/ds``, ``dt*/ds = -(dg Y-)/(dg/dt +
    dg f-)`` (``g`` the switch function, ``R`` the switch's map of the state, ``f-`` and
    ``f+`` the fields of the phases before and after it), ``dg``, ``DR`` and the time
    derivatives by central differences.  A graze (the switch function's rate 0), or a
    difference that changes the phase after the switch, leaves ``nan`` in the tangent (the
    caller differences the map instead).  Returns the phase after the switch.
    """
    Y = T[0]
    zp, zm = np.empty(N_Z), np.empty(N_Z)
    fa, fb = np.empty(N_Z), np.empty(N_Z)
    rhs(mode, P, t, z, fa)
    dg = np.empty(N_S)
    for j in range(N_S):
        d = SALTATION_STEP * (1.0 + abs(z[j]))
        zp[:] = z
        zm[:] = z
        zp[j] += d
        zm[j] -= d
        dg[j] = (switch_function(mode, P, t, zp) - switch_function(mode, P, t, zm)) / (2 * d)
    dt = SALTATION_STEP * (1.0 + abs(t))
    gt = (switch_function(mode, P, t + dt, z) - switch_function(mode, P, t - dt, z)) / (2 * dt)
    rate = gt
    for j in range(N_S):
        rate += dg[j] * fa[j]
    # the map of the state: the elongation of a Jenkins contact rescaled (else none)
    DR = np.eye(N_S)
    rt = np.zeros(N_S)
    zb = z.copy()
    new = switch(mode, P, t, z)
    bad = rate == 0.0 or not math.isfinite(rate)
    if P[P_C] == 0.0:
        for j in range(N_S + 1):
            d = SALTATION_STEP * (1.0 + abs(zb[j] if j < N_S else t))
            zp[:] = zb
            zm[:] = zb
            tp = tm = t
            if j < N_S:
                zp[j] += d
                zm[j] -= d
            else:
                tp, tm = t + d, t - d
            mp = switch(mode, P, tp, zp)
            mm = switch(mode, P, tm, zm)
            bad = bad or mp != new or mm != new
            for i in range(N_S):
                v = (zp[i] - zm[i]) / (2 * d)
                if j < N_S:
                    DR[i, j] = v
                else:
                    rt[i] = v
    rhs(new, P, t, z, fb)
    jump = np.empty(N_S)  # DR f- + dR/dt - f+
    for i in range(N_S):
        acc = rt[i] - fb[i]
        for j in range(N_S):
            acc += DR[i, j] * fa[j]
        jump[i] = acc
    for q in range(N_S):
        dts = 0.0
        for j in range(N_S):
            dts -= dg[j] * Y[j, q]
        dts /= rate
        col = np.empty(N_S)
        for i in range(N_S):
            acc = jump[i] * dts
            for j in range(N_S):
                acc += DR[i, j] * Y[j, q]
            col[i] = acc
        for i in range(N_S):
            Y[i, q] = math.nan if bad else col[i]
    return new


@jit
def period_map(P, s, sout, rtol, atol, hmax, W, acc, cnt, max_events):
    """The period map of the section state ``s`` (6) into ``sout``; returns
    ``(ok, int f_x, int f_y)`` over the period.  The phase at the section follows from
    the state (:func:`entry`).
    """
    z = W[12]
    for i in range(N_S):
        z[i] = s[i]
    z[6] = 0.0
    z[7] = 0.0
    mode = entry_hint(P, 0.0, z, int(W[W_MODE, 0]))
    mode, ok = one_period(P, 0.0, z, mode, rtol, atol, hmax, W, acc, cnt, max_events,
                          np.empty((0, N_S, N_S)))
    for i in range(N_S):
        sout[i] = z[i]
    if ok and mode != FLIGHT:  # put the end state through the same entry rule
        mode = entry_hint(P, TWO_PI, sout, mode)
    W[W_MODE, 1] = mode
    return ok, z[6], z[7]


@jit
def _entry_jacobian(P, t, z, hint, E):
    """The derivative of the section's entry rule (:func:`entry_hint` at ``t`` from the phase
    ``hint``) at the state ``z`` into ``E`` (6 x 6): where the rule keeps the state (every
    Kelvin-Voigt contact, a Jenkins one inside its cone) the identity; where it puts a
    Jenkins contact's elongation at a length ``rho`` of its own (on a cone, its direction
    kept) ``rho/|e| (I - d d^T)`` on ``e``, the side of the rule the state is on.
    """
    E[:] = np.eye(N_S)
    if P[P_C] > 0.0:
        return
    zb = np.empty(N_S)
    for i in range(N_S):
        zb[i] = z[i]
    entry_hint(P, t, zb, hint)
    if zb[4] == z[4] and zb[5] == z[5]:
        return
    _cone_tangent(z, E, math.hypot(zb[4], zb[5]) / math.hypot(z[4], z[5]))


@jit
def period_map_tangent(P, s, sout, rtol, atol, hmax, W, acc, cnt, max_events, J):
    """:func:`period_map` and its Jacobian ``J`` (6 x 6) from one integration: the tangent
    carried along (:func:`tangent_step`, :func:`_switch_tangent`), the section's entry rule
    at both ends through its derivative (:func:`_entry_jacobian`).  Returns ``(ok, exact)``:
    ``exact`` False where the tangent does not hold (a graze, or a switch whose phase a
    difference changes: :func:`_switch_tangent`; the caller differences the map instead).
    """
    T = np.zeros((N_T, N_S, N_S))
    z = W[12]
    for i in range(N_S):
        z[i] = s[i]
    z[6] = 0.0
    z[7] = 0.0
    hint = int(W[W_MODE, 0])
    _entry_jacobian(P, 0.0, z, hint, T[0])
    mode = entry_hint(P, 0.0, z, hint)
    mode, ok = one_period(P, 0.0, z, mode, rtol, atol, hmax, W, acc, cnt, max_events, T)
    for i in range(N_S):
        sout[i] = z[i]
    E = np.eye(N_S)
    if ok and mode != FLIGHT:  # the end state through the same entry rule
        _entry_jacobian(P, TWO_PI, sout, mode, E)
        mode = entry_hint(P, TWO_PI, sout, mode)
    W[W_MODE, 1] = mode
    J[:] = E @ T[0]
    return ok, np.all(np.isfinite(J))


@jit
def _scale(s):
    return 1.0 + max(abs(s[0]), abs(s[1]), abs(s[2]), abs(s[3]))


@jit
def _dist(a, b, k):
    """Scaled distance of section states (``e`` weighted by ``k``: a force)."""
    d = 0.0
    for i in range(4):
        d = max(d, abs(a[i] - b[i]))
    for i in range(4, 6):
        d = max(d, k * abs(a[i] - b[i]))
    return d


@jit
def orbit_mean(P, s, rtol, atol, hmax, W, cnt, max_events, out):
    """Means over one period from the section state ``s``: ``out = (mu, lateral,
    stick, slip, flight, reverse slip, ok)`` and the end state in ``W[13]``.
    """
    acc = np.zeros(4)
    ok, ifx, ify = period_map(P, s, W[13], rtol, atol, hmax, W, acc, cnt, max_events)
    _means(P, ok, ifx, ify, acc, out)


@jit
def _means(P, ok, ifx, ify, acc, out):
    """The means of one period map (its force integrals ``ifx, ify`` and phase times
    ``acc``) into ``out`` as :func:`orbit_mean` gives them.
    """
    nbar = mean_normal(P[P_A])
    out[0] = ifx / (TWO_PI * nbar)
    out[1] = ify / (TWO_PI * nbar)
    for i in range(4):
        out[2 + i] = acc[i] / TWO_PI
    out[6] = 1.0 if ok else 0.0


@jit
def mean_normal(a):
    """``<n>`` over a period (the contact opens for ``a > 1``)."""
    if a <= 1.0:
        return 1.0
    th = math.acos(-1.0 / a)
    return (th + a * math.sin(th)) / math.pi


@jit
def newton(P, s, ph, have_map, rtol, atol, hmax, W, cnt, max_events, tol, floor, max_iter, J,
           info, chord, hrel, polish, means, near_tol, map_steps=0):
    """Newton's method on ``Phi(s) - s`` (the Jacobian ``J`` of :func:`_jacobian`, of
    ``Phi``), ``s`` in place.  ``info = (iterations, residual, periods integrated)``;
    returns True where the residual fell below ``tol``, or stopped falling (the
    integration's noise) below ``floor``.  The step is capped (:data:`NEWTON_STEP_CAP`)
    and each trial period has a step budget (:data:`TRIAL_STEPS` times the iterate's);
    a trial that fails (budget, chatter) is a failed trial, not a failed point.

    A Jacobian taken near the orbit (the residual within ``near_tol``) is kept for the
    next iterates (chord steps: a tangent map costs about 2.5 plain ones) while each step
    cuts the residual by :data:`CHORD_RATE` at least; otherwise, and where a kept one
    gives no descent, it is taken afresh at the iterate.  Until one is near, each full
    step's map carries the tangent (:func:`period_map_tangent`), so that the iterate it
    accepts has its Jacobian from the same integration.  With ``chord`` the ``J`` given (the
    orbit's, e.g. at another tolerance) is used from the first step, else the first map
    carries the tangent.  ``hrel``: the relative step of ``J`` where it is differenced;
    ``info[3]`` gets the residual at the iterate where ``J`` was last taken (inf: none
    taken); where the last iterate's tangent is at hand, ``J`` is that.
    ``polish > 0``: once below ``tol`` with a kept Jacobian, chord steps go on while each
    cuts the residual by :data:`CHORD_RATE`, down to ``polish * tol`` (a map each; the
    section residual enters the stated error).  ``means`` gets the means of the period
    map from the last iterate (:func:`orbit_mean`'s, computed on the way), ``ph`` that
    map's end, ``Phi(s)``; ``have_map``: they hold those of ``s`` already (that map is not
    integrated again; Coulomb friction only, where the state fixes the phase); with
    ``have_map`` and not ``chord``, ``J`` is that map's tangent (taken at ``s``, perhaps
    at another tolerance: the transient's last period, :func:`_attempt`) and
    ``map_steps`` its steps (the trials' budget).
    """
    acc = np.zeros(4)
    pp = np.empty(N_S)
    sp = np.empty(N_S)
    Jt = np.empty((N_S, N_S))
    k = P[P_K]
    periods = 0
    fail0 = cnt[C_FAIL]
    steps0 = cnt[C_STEPS]
    if not chord:
        info[3] = math.inf
    have_tan = False
    if not have_map:
        ok, ifx, ify, have_tan = _trial_map(P, s, ph, rtol, atol, hmax, W, acc, cnt,
                                            max_events, not chord, Jt)
        _means(P, ok, ifx, ify, acc, means)
        periods += 1
        if not ok:
            info[2] += periods
            return False
    elif not chord:  # the given map's tangent, J
        Jt[:] = J
        have_tan = True
    # static_ratio > 1: the phase at the section is part of the state (W[W_MODE, 0],
    # kept through the search); an orbit must end in the phase it started from
    same_phase = P[P_SR] == 1.0 or W[W_MODE, 1] == W[W_MODE, 0]
    # a given orbit's trials have the whole step budget (``s`` is an orbit already)
    cnt[C_LIMIT] = 0 if have_map and chord \
        else TRIAL_STEPS * max(100, cnt[C_STEPS] - steps0 + map_steps)
    res = _dist(ph, s, k)
    it = 0
    fresh = not chord  # J is to be differenced at this iterate
    near = chord  # J was differenced near the orbit (or given)
    polishing = False
    while it < max_iter:
        if res <= tol and not polishing:
            if fresh or res <= polish * tol or polish == 0.0:
                _take_tangent(have_tan, Jt, J, res, info)
                info[0], info[1] = it, res
                info[2] += periods
                return same_phase
            polishing = True
        if polishing and res <= polish * tol:
            break
        it += 1
        if fresh:
            near = res <= near_tol
            if not _take_tangent(have_tan, Jt, J, res, info):
                info[3] = res
                periods = _jacobian(P, s, np.empty(N_S), rtol, atol, hmax, W, acc, cnt,
                                    max_events, J, sp, pp, periods, hrel, np.zeros(7))
                if periods < 0:
                    info[2] += -periods
                    cnt[C_FAIL] = fail0
                    cnt[C_LIMIT] = 0
                    return False
            have_tan = False
        A = J - np.eye(N_S)
        r = ph - s
        try:
            ds = np.linalg.solve(A, -r)
        except Exception:  # noqa: BLE001 - a singular matrix
            info[2] += periods
            cnt[C_LIMIT] = 0
            return False
        size = 0.0
        for i in range(N_S):
            size = max(size, abs(ds[i]) * (k if i >= 4 else 1.0))
        cap = NEWTON_STEP_CAP * (1.0 + _dist(s, np.zeros(N_S), k))
        lam = 1.0 if size <= cap else cap / size
        improved = False
        before = res
        for trial in range(6):
            for i in range(N_S):
                sp[i] = s[i] + lam * ds[i]
            acc[:] = 0.0
            # the full step carries the tangent until a Jacobian is near (a halved one,
            # where the full step failed, need not: the iteration is off its quadratic
            # course, and a map with the tangent costs about 2.5 plain ones)
            ok, ifx, ify, tan = _trial_map(P, sp, pp, rtol, atol, hmax, W, acc, cnt,
                                           max_events, not near and trial == 0, Jt)
            periods += 1
            if not ok:
                cnt[C_FAIL] = fail0
            else:
                rn = _dist(pp, sp, k)
                if rn < res:
                    _means(P, ok, ifx, ify, acc, means)
                    for i in range(N_S):
                        s[i] = sp[i]
                        ph[i] = pp[i]
                    res = rn
                    have_tan = tan
                    same_phase = P[P_SR] == 1.0 or W[W_MODE, 1] == W[W_MODE, 0]
                    improved = True
                    break
            if not fresh:
                break  # a kept Jacobian that gives no descent: a fresh one, not a line search
            lam *= 0.5
        if not improved:
            if fresh or polishing:
                break
            fresh = True
            continue
        if polishing and res > CHORD_RATE * before:
            break
        # kept only if differenced near the orbit (its multiplier decides the status)
        fresh = not near or res > CHORD_RATE * before
    _take_tangent(have_tan, Jt, J, res, info)
    info[0], info[1] = it, res
    info[2] += periods
    cnt[C_LIMIT] = 0
    return (res <= tol or res <= floor) and same_phase


@jit
def _trial_map(P, s, sout, rtol, atol, hmax, W, acc, cnt, max_events, tangent, Jt):
    """A period map of :func:`newton`: plain, or with ``tangent`` carrying its Jacobian into
    ``Jt``.  Returns ``(ok, int f_x, int f_y, exact)``, ``exact`` where ``Jt`` holds.
    """
    if not tangent:
        ok, ifx, ify = period_map(P, s, sout, rtol, atol, hmax, W, acc, cnt, max_events)
        return ok, ifx, ify, False
    ok, exact = period_map_tangent(P, s, sout, rtol, atol, hmax, W, acc, cnt, max_events, Jt)
    return ok, W[12, 6], W[12, 7], ok and exact


@jit
def _take_tangent(have_tan, Jt, J, res, info):
    """Where the iterate's tangent is at hand, ``J`` is it (taken at the residual ``res``)."""
    if have_tan:
        J[:] = Jt
        info[3] = res
    return have_tan


CHORD_RATE = 0.1
"""A chord step of :func:`newton` (the Jacobian kept) must cut the residual by this."""
CHORD_NEAR = 1e6
"""... and the Jacobian must have been differenced within this many ``tol`` of the orbit:
a Jacobian from farther off gave multipliers off by up to 0.03 (150 random points)."""


@jit
def _near(scale):
    """The residual within which a Jacobian is near the orbit of the solve at ``rtol``
    (:data:`CHORD_NEAR` times its tolerance, ``1e-12 scale``).
    """
    return CHORD_NEAR * 1e-12 * scale


@jit
def _jacobian(P, s, ph, rtol, atol, hmax, W, acc, cnt, max_events, J, sp, pp, periods, hrel,
              means):
    """Newton's Jacobian of the period map at ``s`` into ``J``: the tangent's, from one
    period map (:func:`period_map_tangent`), where it holds; else by forward differences
    (:func:`_difference_jacobian`, six more, about that map's ``Phi(s)``).  That map's end
    goes into ``ph``, its means into ``means``.  Returns ``periods`` plus the maps
    integrated, negated where a map failed.
    """
    acc[:] = 0.0
    ok, exact = period_map_tangent(P, s, ph, rtol, atol, hmax, W, acc, cnt, max_events, J)
    periods += 1
    if not ok:
        return -periods
    _means(P, ok, W[12, 6], W[12, 7], acc, means)
    if exact:
        return periods
    return _difference_jacobian(P, s, ph, rtol, atol, hmax, W, acc, cnt, max_events, J, sp,
                                pp, periods, hrel)


@jit
def _difference_jacobian(P, s, ph, rtol, atol, hmax, W, acc, cnt, max_events, J, sp, pp,
                         periods, hrel):
    """The forward-difference Jacobian of the period map at ``s`` (``ph = Phi(s)``) into
    ``J``, the relative step ``hrel``: six period maps.  Returns ``periods`` plus those
    maps, negated where a map failed.
    """
    for j in range(N_S):
        hj = hrel * (1.0 + abs(s[j])) if j < 4 else hrel * (1.0 / P[P_K] + abs(s[j]))
        for i in range(N_S):
            sp[i] = s[i]
        sp[j] += hj
        ok, _, _ = period_map(P, sp, pp, rtol, atol, hmax, W, acc, cnt, max_events)
        periods += 1
        if not ok:
            return -periods
        for i in range(N_S):
            J[i, j] = (pp[i] - ph[i]) / hj
    return periods


TRANSIENT_PERIODS, TRANSIENT_EXIT = 20, 1e-4
"""The transient before Newton's method: at most this many periods, until the map moves the
state by less than this (:func:`_transient`)."""
TRANSIENT_EARLY, EARLY_ITERATIONS = 8, 6
"""... where it has not settled after this many, Newton's rough orbit is tried from there
with at most this many steps (:func:`_start_transient`)."""
TRANSIENT_RTOL = 1e-6
"""The tolerance of the transient before Newton's method (:func:`_transient`)."""
ITER_RESERVE = 2000
"""Plain iteration (``V = 0``): the periods kept back from ``max_periods`` for the check
at ``100 rtol`` (which is also bounded by it)."""
ITER_SPAN = 16
"""Plain iteration: the multiplier is estimated over spans of this many periods."""
FALLBACK_ITER = 4000
"""``V != 0``: where Newton fails, plain iteration for at most this many periods before
the averaging."""


@jit
def iterate(P, s, rtol, hmax, W, cnt, max_events, tol, floor, max_it, info):
    """Plain iteration of the period map from ``s`` (in place) until the step ``d =
    |Phi(s) - s|`` falls below ``tol``, or stops falling below ``floor`` (the
    integration's noise), at most ``max_it`` periods.  ``info = (iterations, last step
    d, periods integrated, multiplier)``, the multiplier estimated from the envelope of
    the steps (their largest over the last :data:`ITER_SPAN` periods against the
    :data:`ITER_SPAN` before, which copes with the oscillating steps of complex
    multipliers; 0 where the iteration converged at once); returns True where it
    converged, False at once where at that contraction the floor lies beyond twice the
    periods left.
    """
    acc = np.zeros(4)
    s2 = np.empty(N_S)
    ring = np.full(2 * ITER_SPAN, math.inf)
    k = P[P_K]
    rho = 0.0
    d_prev = math.inf
    it = 0
    info[0] = info[1] = info[3] = 0.0
    while it < max_it:
        ok, _, _ = period_map(P, s, s2, rtol, rtol, hmax, W, acc, cnt, max_events)
        it += 1
        if not ok:
            info[2] += it
            return False
        d = _dist(s2, s, k)
        for i in range(N_S):
            s[i] = s2[i]
        W[W_MODE, 0] = W[W_MODE, 1]  # the phase goes on with the state
        ring[it % (2 * ITER_SPAN)] = d
        if it >= 2 * ITER_SPAN and d > floor:
            recent, before = 0.0, 0.0
            for j in range(ITER_SPAN):
                recent = max(recent, ring[(it - j) % (2 * ITER_SPAN)])
                before = max(before, ring[(it - ITER_SPAN - j) % (2 * ITER_SPAN)])
            if before > 0.0:
                rho = min(0.999, (recent / before) ** (1.0 / ITER_SPAN))
        info[0], info[1], info[3] = it, d, rho
        # converged: below tol, or below the noise floor and either no longer falling or
        # the stated error's term 10 d/(1 - rho) (plane_steady_section) below 1e3 tol
        if d <= tol or (d <= floor and (d >= d_prev or 10.0 * d <= 1e3 * tol * (1.0 - rho))):
            info[2] += it
            return True
        # hopeless: at the estimated contraction the floor lies beyond twice the budget
        if it >= 8 * ITER_SPAN and d > floor and rho > 0.0 \
                and math.log(floor / d) / math.log(rho) > 2.0 * (max_it - it):
            info[2] += it
            return False
        d_prev = d
    info[2] += it
    return False


@jit
def start_state(P, init_kind, y0, xd0, e0, s):
    """The section state at ``tau = 0``: 0 steady sliding (``x' = V``, spring stretched
    by ``sign V``, ``e = sign V/k``), 1 rest, 2 explicit ``(y, x', e)`` (transverse 0).
    """
    for i in range(N_S):
        s[i] = 0.0
    if init_kind == 0 and P[P_V] != 0.0:
        sg = 1.0 if P[P_V] > 0.0 else -1.0
        s[0], s[2], s[4] = -sg / P[P_ALPHA], P[P_V], sg / P[P_K]
    elif init_kind == 2:
        s[0], s[2], s[4] = y0, xd0, e0


@jit
def parameters(alpha, beta, a, V, zeta, eta, a_x, phase_x, a_y, phase_y, alpha_y, zeta_y,
               on_substrate, static_ratio=1.0):
    """The parameter vector ``P`` of a point (``alpha_y``, ``zeta_y``: the pin across the
    sliding, resolved: ``alpha``, ``zeta`` for an axisymmetric one; ``static_ratio`` the
    static circle's radius over the kinetic one's).
    """
    P = np.empty(N_P)
    P[P_ALPHA] = alpha
    P[P_GAMMA] = 2.0 * zeta * math.sqrt(alpha)
    P[P_ALPHA_Y] = alpha_y
    P[P_GAMMA_Y] = 2.0 * zeta_y * math.sqrt(alpha_y)
    P[P_K] = beta - alpha
    P[P_C] = eta * (beta - alpha)
    P[P_A], P[P_V] = a, V
    P[P_AX], P[P_PX], P[P_AY], P[P_PY] = a_x, phase_x, a_y, phase_y
    P[P_HOLDER] = 0.0 if on_substrate else 1.0
    P[P_SR] = static_ratio
    P[P_CPX], P[P_SPX] = math.cos(phase_x), math.sin(phase_x)
    P[P_CPY], P[P_SPY] = math.cos(phase_y), math.sin(phase_y)
    linear_flows(P)
    return P


@jit
def plane_steady_state(alpha, beta, a, V, zeta, eta, a_x, phase_x, a_y, phase_y, alpha_y,
                       zeta_y, on_substrate, init_kind, y0, xd0, e0, rtol, max_periods,
                       max_events, out_f, out_i, static_ratio=1.0):
    """Steady state of the 2-D model at one point into the output rows (columns of
    ``solver.FLOAT_COLUMNS``, ``INT_COLUMNS``); ``out_f[O_LAT]`` the lateral ratio.

    ``rtol`` the Runge-Kutta tolerance (``atol = rtol``); the error estimate adds the
    difference from a second solve at ``100 rtol`` to the section residual's effect.
    ``max_periods`` bounds the whole search (an orbit found later is not converged);
    ``max_events`` the switches per period (chatter: status failed).  ``static_ratio``:
    a stuck contact holds while ``|f| <= static_ratio n`` (the static circle), a
    slipping one exerts ``n`` (the kinetic circle).
    """
    plane_steady_section(alpha, beta, a, V, zeta, eta, a_x, phase_x, a_y, phase_y, alpha_y,
                         zeta_y, on_substrate, init_kind, y0, xd0, e0, rtol, max_periods,
                         max_events, out_f, out_i, np.empty(N_S), static_ratio)


@jit
def _transient(P, s, rtol, hmax, W, cnt, max_events, max_periods):
    """A transient by plain iteration of the period map on ``s`` (in place): until the
    map moves the state by < 1e-4, at most ``max_periods``. Returns ``(periods,
    settled)``, ``settled`` where it stopped on that test.

    Where Newton's method follows (``V != 0``) the transient only brings the state near
    the orbit, at the tolerance :data:`TRANSIENT_RTOL` (or ``rtol`` if looser); at
    ``V = 0`` the motion's own end is the answer (:func:`_orbit_search`), at ``rtol``.
    """
    s2 = np.empty(N_S)
    acc = np.zeros(4)
    k = P[P_K]
    periods = 0
    rt = max(rtol, TRANSIENT_RTOL) if P[P_V] != 0.0 else rtol
    # a transient by plain iteration: until the map moves the state by < 1e-4
    for _ in range(max_periods):
        ok, _, _ = period_map(P, s, s2, rt, rt, hmax, W, acc, cnt, max_events)
        periods += 1
        if not ok:
            break
        d = _dist(s2, s, k)
        for i in range(N_S):
            s[i] = s2[i]
        W[W_MODE, 0] = W[W_MODE, 1]  # the phase goes on with the state
        if d < TRANSIENT_EXIT:
            return periods, True
    return periods, False


@jit
def _start_transient(P, s, rtol, hmax, W, cnt, max_events, max_periods, J, info, R):
    """The transient before the orbit's search (:func:`_transient`), with an early attempt:
    after :data:`TRANSIENT_EARLY` periods that have not settled (the last carries the
    tangent, :func:`_attempt`), the rough orbit (:func:`_rough_orbit`, at most
    :data:`EARLY_ITERATIONS` Newton steps, the first on that tangent); where it is
    found ``s`` is that orbit, ``J`` its Jacobian and ``R`` its record, else ``s``, the
    phase and the failure count are as the transient left them and it goes on, to
    :data:`TRANSIENT_PERIODS` in all.  Not with a static circle above the kinetic one,
    where sliding and stick-slip coexist: there the motion's own transient picks the
    attractor, as in a continuation.
    Returns ``(periods, found)``.
    """
    first = min(TRANSIENT_EARLY, max_periods)
    attempt = first == TRANSIENT_EARLY and P[P_V] != 0.0 and rtol < ROUGH_RTOL \
        and P[P_SR] == 1.0
    # where the attempt follows, the transient's last period carries the tangent
    plain = first - 1 if attempt else first
    periods, settled = _transient(P, s, rtol, hmax, W, cnt, max_events, plain)
    if settled or periods < plain or cnt[C_FAIL] > 0:
        return periods, False
    if attempt:
        periods, found, stop = _attempt(P, s, rtol, hmax, W, cnt, max_events, J, info, R,
                                        periods)
        if stop:
            return periods, found
    more, _ = _transient(P, s, rtol, hmax, W, cnt, max_events,
                         min(TRANSIENT_PERIODS, max_periods) - first)
    return periods + more, False


@jit
def _attempt(P, s, rtol, hmax, W, cnt, max_events, J, info, R, periods):
    """:func:`_start_transient`'s early attempt: the transient's last period (with the
    tangent, at its tolerance), then the rough orbit from there, Newton's first step on
    that tangent.  Returns ``(periods, found, stop)``, ``stop`` where the transient stops
    (found, settled or failed); unless found, ``s`` and the phase are that period's end's.
    """
    rt = max(rtol, TRANSIENT_RTOL)
    ph = np.empty(N_S)
    means = np.zeros(7)
    acc = np.zeros(4)
    steps0 = cnt[C_STEPS]
    ok, ifx, ify, tan = _trial_map(P, s, ph, rt, rt, hmax, W, acc, cnt, max_events, True, J)
    periods += 1
    if not ok:
        return periods, False, True
    end_phase = W[W_MODE, 1]
    d = _dist(ph, s, P[P_K])
    if d >= TRANSIENT_EXIT:  # not settled: the attempt
        _means(P, ok, ifx, ify, acc, means)
        scale = 1.0 + _dist(ph, np.zeros(N_S), P[P_K])
        # the map is Newton's first where its residual lies above the rough orbit's
        # tolerance (so that orbit is one at that tolerance)
        mapped = tan and d > 100.0 * ROUGH_RTOL * scale
        found = _rough_orbit(P, s, rtol, hmax, W, cnt, max_events, scale, J, info, R, False,
                             EARLY_ITERATIONS, mapped, ph, means,
                             int(cnt[C_STEPS] - steps0)) == ROUGH_FOUND
        periods += int(info[2])
        info[:] = 0.0
        cnt[C_LIMIT] = 0  # the transient's periods have the whole step budget
        if found:
            return periods, True, True
    # settled, or not found: the transient goes on from that period's end
    s[:] = ph
    W[W_MODE, 0] = end_phase
    return periods, False, d < TRANSIENT_EXIT or cnt[C_FAIL] > 0


@jit
def _rough_orbit(P, s, rtol, hmax, W, cnt, max_events, scale, J, info, R, given, max_iter,
                 mapped, ph0, means0, map_steps):
    """Newton's method at :data:`ROUGH_RTOL` from ``s``, where ``rtol`` is tighter.

    ``given``: ``J`` holds a neighbour's Jacobian (a continuation), for chord steps from
    the start; the rough orbit's own is taken at it all the same (its multiplier).

    Returns ``ROUGH_FOUND``: ``s`` is the rough orbit, ``J`` its Jacobian (the solve at
    ``rtol`` starts with chord steps on it); ``ROUGH_FAILED``: Newton found no orbit (nor
    will it at ``rtol``: the plain iteration follows), or ``ROUGH_SKIPPED`` (``rtol`` not
    tighter, or a period map failed at the rough orbit): Newton at ``rtol`` as it would
    without this stage.  Unless found, ``s``, the phase hint and the failure count are as
    they were.  ``info[2]`` counts the periods (each a period at ``ROUGH_RTOL``).
    ``R`` (:data:`N_R`) gets the rough orbit's record (its last map, and the Jacobian
    there): ``R[R_OK] = 1``, else 0.  ``mapped``: ``s``'s period map is given (its end
    ``ph0``, means ``means0``, ``map_steps`` steps, and its tangent in ``J``), perhaps at
    another tolerance, for Newton's first step (:func:`newton`).
    """
    info[:] = 0.0
    R[R_OK] = 0.0
    if rtol >= ROUGH_RTOL:
        return ROUGH_SKIPPED
    sr = s.copy()
    ph = np.empty(N_S)
    means = np.zeros(7)
    if mapped:
        ph[:] = ph0
        means[:] = means0
    hint = W[W_MODE, 0]
    fail0 = cnt[C_FAIL]
    floor = 100.0 * ROUGH_RTOL * scale
    hrel = ROUGH_STEP * ROUGH_RTOL
    if given:
        info[3] = math.inf  # no J differenced at this point yet
    near = _near(scale)  # the solve at rtol's rule (:func:`_orbit_search`)
    if newton(P, sr, ph, mapped, ROUGH_RTOL, ROUGH_RTOL, hmax, W, cnt, max_events, floor,
              floor, max_iter, J, info, given and not mapped, hrel, 0.0, means, near,
              map_steps):
        if info[3] <= near:
            _record_rough(sr, ph, means, J, R)
        else:
            # no J taken at the rough orbit (the neighbour's only), or one taken farther
            # off than the solve at rtol would keep: afresh here
            periods = _jacobian(P, sr, ph, ROUGH_RTOL, ROUGH_RTOL, hmax, W, np.zeros(4), cnt,
                                max_events, J, np.empty(N_S), np.empty(N_S), 0, hrel, means)
            info[2] += abs(periods)
            if periods < 0:
                W[W_MODE, 0] = hint
                cnt[C_FAIL] = fail0
                return ROUGH_SKIPPED
            _record_rough(sr, ph, means, J, R)
        for i in range(N_S):
            s[i] = sr[i]
        return ROUGH_FOUND
    W[W_MODE, 0] = hint
    cnt[C_FAIL] = fail0
    return ROUGH_FAILED


R_S, R_PH, R_MEANS, R_OK, R_J = 0, N_S, 2 * N_S, 2 * N_S + 7, 2 * N_S + 8
N_R = R_J + N_S * N_S
"""The rough orbit's record (:func:`_rough_orbit`): its state, its map's end ``Phi(s)``
and means (at :data:`ROUGH_RTOL`), 1 where the record holds, the Jacobian there (by
rows).  The error's solve at ``100 rtol`` starts from it where that is ``ROUGH_RTOL``
(:func:`_orbit_error`): the orbit's map there is integrated already."""


@jit
def _record_rough(s, ph, means, J, R):
    R[R_S:R_S + N_S] = s
    R[R_PH:R_PH + N_S] = ph
    R[R_MEANS:R_MEANS + 7] = means
    R[R_J:] = J.ravel()
    R[R_OK] = 1.0


@jit
def _orbit_search(P, s, s0, rtol, hmax, W, cnt, max_events, scale, budget, periods, J, info,
                  means, R, ph, given=False, rough_found=False, newton_ok=True):
    """The periodic orbit from the transient's end ``s0``: Newton where ``V != 0`` (a
    stable orbit), else or where it fails, plain iteration (bounded). Returns ``(status,
    mult, use_newton, periods)``, ``s`` the orbit's section state (and where Newton found
    it, ``means`` its means, ``J`` its Jacobian, ``ph`` its map's end ``Phi(s)``).
    ``given``: ``J`` holds a neighbour's Jacobian (:func:`_rough_orbit`); ``R`` the rough
    orbit's record (given where ``rough_found``); ``newton_ok`` False: plain iteration only.
    Newton's chord steps from the rough orbit stop at its ``tol``: where the residual
    matters to the stated error they go on in :func:`_orbit_error` (:data:`POLISH`).
    """
    status = ST_FAILED
    mult = math.nan
    # V = 0: no Newton.  Where the contact can stick through whole cycles the stuck
    # orbits form a continuum (any preload in the stuck region), along which the period
    # map is singular; plain iteration follows the motion from the given start and keeps
    # the symmetries of that start exactly (docs/inplane.md, "v0 = 0")
    use_newton = P[P_V] != 0.0 and newton_ok
    if use_newton:
        if rough_found:  # ``s`` is the rough orbit already, ``J`` its Jacobian
            rough = ROUGH_FOUND
        else:
            rough = _rough_orbit(P, s, rtol, hmax, W, cnt, max_events, scale, J, info, R,
                                 given, 12, False, s, means, 0)
        periods += int(info[2])
        info[:] = 0.0
        conv = False
        if rough != ROUGH_FAILED:
            chord = rough == ROUGH_FOUND
            conv = newton(P, s, ph, False, rtol, rtol, hmax, W, cnt, max_events,
                          1e-12 * scale, 100.0 * rtol * scale, 12, J, info, chord, DIFF_STEP,
                          0.0, means, _near(scale))
            periods += int(info[2])
        if conv:
            mult = dense_spectral_radius(J)
            if mult < 1.0 + 1e-6:
                status = ST_PERIODIC
        if status != ST_PERIODIC and cnt[C_FAIL] == 0:
            # Newton failed (a near-singular J - I: slow creep near V = 0, a stick
            # through most of the cycle) or found an unstable orbit: plain iteration
            # of the motion from the transient's end, bounded, before the averaging
            use_newton = False
            for i in range(N_S):
                s[i] = s0[i]
            budget = min(budget - periods, FALLBACK_ITER)
    if not use_newton and cnt[C_FAIL] == 0:
        info[:] = 0.0
        conv = iterate(P, s, rtol, hmax, W, cnt, max_events, 1e-12 * scale,
                       100.0 * rtol * scale, budget, info)
        periods += int(info[2])
        if conv:
            mult = info[3]
            status = ST_PERIODIC
    return status, mult, use_newton, periods


@jit
def _follow(P, sm, s, phase, J, sticks, rtol, hmax, W, cnt, max_events, max_it):
    """The motion from ``sm`` (in place; its phase hint in ``W[W_MODE, 0]``) by plain periods
    at :data:`ROUGH_RTOL` (or ``rtol`` if looser), until it comes to the orbit ``s`` (the
    Jacobian of its map ``J``) in the orbit's phase ``phase`` as the 1-D solver's motion
    comes to Newton's orbit (:func:`.steady.closing_in`), at most ``max_it`` periods; an
    orbit that never sticks (``sticks`` False) only within the follow distance (no
    certificate here proves that the motion near it never sticks).  Where sliding
    and stick-slip coexist (a static circle above the kinetic one), Newton's iterate may
    converge to an orbit the motion does not approach.  Returns ``(reached, periods)``.
    """
    s2 = np.empty(N_S)
    acc = np.zeros(4)
    k = P[P_K]
    rt = max(rtol, ROUGH_RTOL)
    scale = 1.0 + _dist(s, np.zeros(N_S), k)
    zero = np.zeros(N_S)
    run = 0
    for it in range(max_it):
        same = W[W_MODE, 0] == phase  # the step's start in the orbit's phase
        ok, _, _ = period_map(P, sm, s2, rt, rt, hmax, W, acc, cnt, max_events)
        if not ok:
            return False, it + 1
        W[W_MODE, 0] = W[W_MODE, 1]  # the phase goes on with the state
        same = same and W[W_MODE, 0] == phase
        d = _dist(s2, s, k) / scale if W[W_MODE, 0] == phase else math.inf
        # the step's miss from the one the orbit's linearisation predicts, relative to it
        step = _dist(s2, sm, k)
        miss = _dist(s2 - s - J @ (sm - s), zero, k) / step \
            if sticks and same and step > 0.0 else math.inf
        for i in range(N_S):
            sm[i] = s2[i]
        run, arrived = closing_in(d, miss, run)
        if arrived:
            return True, it + 1
    return False, max_it


@jit
def _orbit_error(P, s, s_start, rtol, hmax, W, cnt, max_events, scale, use_newton, J, info,
                 mult, res, periods, periods_to_orbit, means, out_f, R, ph):
    """The periodic orbit's means into ``means`` (where Newton found it, they are already
    there: its last map's), their error (the same orbit at ``100 rtol``, and the section
    residual ``res``) and the settling into ``out_f``. Returns the periods run.

    Where the rough orbit's record ``R`` holds and ``100 rtol`` is :data:`ROUGH_RTOL`, the
    solve at ``100 rtol`` is Newton's from the rough orbit, whose map is at hand, with its
    Jacobian (Coulomb friction: the state fixes the phase); else, or where that ends above
    the residual's tolerance, from the orbit at ``rtol`` with its Jacobian.

    Where Newton found the orbit (``ph`` its map's end) and the residual's share of the
    error is above :data:`POLISH_SHARE` of the tolerance's, its chord steps go on
    (:data:`POLISH`) before the error is stated.
    """
    k = P[P_K]
    if not use_newton:  # else Newton's last map gave them
        orbit_mean(P, s, rtol, rtol, hmax, W, cnt, max_events, means)
        periods += 1
    # the tolerance's effect: the same orbit at 100 rtol
    sl = s.copy()
    hint = W[W_MODE, 0]
    info[:] = 0.0
    loose = np.zeros(7)
    if use_newton:
        Jl = J.copy()
        phl = np.empty(N_S)
        given = R[R_OK] == 1.0 and 100.0 * rtol == ROUGH_RTOL and P[P_SR] == 1.0
        if given:
            sl[:] = R[R_S:R_S + N_S]
            phl[:] = R[R_PH:R_PH + N_S]
            loose[:] = R[R_MEANS:R_MEANS + 7]
            Jl[:] = R[R_J:].reshape((N_S, N_S))
        conv = _loose_orbit(P, sl, phl, given, rtol, hmax, W, cnt, max_events, scale, Jl,
                            info, loose)
        if given and not (conv and info[1] <= 1e-12 * scale):
            # not to the residual's tolerance (the map's noise: its orbit is as uncertain,
            # and the one nearest the orbit at rtol tells the tolerance's effect): from there
            periods += int(info[2])
            info[:] = 0.0
            sl[:] = s
            conv = _loose_orbit(P, sl, phl, False, rtol, hmax, W, cnt, max_events, scale,
                                J.copy(), info, loose)
    else:
        conv = iterate(P, sl, 100.0 * rtol, hmax, W, cnt, max_events,
                       1e-12 * scale, 1e4 * rtol * scale, ITER_RESERVE, info)
    if conv:
        if not use_newton:  # Newton's last map gave them
            orbit_mean(P, sl, 100.0 * rtol, 100.0 * rtol, hmax, W, cnt, max_events,
                       loose)
            periods += 1
        err = max(abs(loose[0] - means[0]), abs(loose[1] - means[1]))
    else:
        err = math.inf
    W[W_MODE, 0] = hint  # the orbit's phase at its section
    periods += int(info[2])
    # the section residual: a state error res moves a mean by about res/(1 - mult)
    gain = 10.0 / max(1e-3, 1.0 - min(mult, 0.999))
    if use_newton and conv and gain * res > POLISH_SHARE * err:
        # the residual counts in the error: chord steps on J go on (its means follow)
        info[:] = 0.0
        newton(P, s, ph, True, rtol, rtol, hmax, W, cnt, max_events, 1e-12 * scale,
               100.0 * rtol * scale, 12, J, info, True, DIFF_STEP, POLISH, means,
               _near(scale))
        W[W_MODE, 0] = hint
        periods += int(info[2])
        res = min(res, info[1])
        err = max(abs(loose[0] - means[0]), abs(loose[1] - means[1]))
    err += gain * res
    out_f[O_ERR] = err
    # settling: the linearised contraction from the start to within the error
    # (plain iteration: the periods it took)
    d0 = _dist(s_start, s, k)
    if not use_newton:
        out_f[O_SETTLE] = periods_to_orbit
    elif d0 <= err or mult <= 0.0:
        out_f[O_SETTLE] = 0.0
    elif mult < 1.0 - 1e-6:
        out_f[O_SETTLE] = math.log(d0 / max(err, 1e-300)) / -math.log(mult)
    return periods


@jit
def _loose_orbit(P, s, ph, have_map, rtol, hmax, W, cnt, max_events, scale, J, info, means):
    """:func:`_orbit_error`'s solve at ``100 rtol``: chord steps on ``J`` from ``s`` (its map
    ``ph`` and ``means`` given where ``have_map``) to ``1e-12 scale``.
    """
    return newton(P, s, ph, have_map, 100.0 * rtol, 100.0 * rtol, hmax, W, cnt, max_events,
                  1e-12 * scale, 1e4 * rtol * scale, 6, J, info, True, DIFF_STEP, 0.0, means,
                  _near(scale))


@jit
def _averaged(P, s, s0, use_newton, rtol, hmax, W, cnt, max_events, status, means, out_f):
    """The long-time average from the transient's end ``s0`` into ``means`` (not Newton's
    last iterate; at V = 0 the plain iteration's last state, the motion's own), its error
    the window's spread plus the difference from a run at 100 rtol, or ``inf`` where the
    window lies on an orbit not shown to attract (:func:`_attracts`; with a static circle
    above the kinetic one, any orbit). Returns the status.
    """
    if use_newton:
        for i in range(N_S):
            s[i] = s0[i]
    sl = s.copy()
    hint = W[W_MODE, 0]
    spread, p = average(P, s, rtol, hmax, W, cnt, max_events, means)
    hint_end = W[W_MODE, 0]
    W[W_MODE, 0] = hint
    loose = np.zeros(7)
    average(P, sl, 100.0 * rtol, hmax, W, cnt, max_events, loose)
    W[W_MODE, 0] = hint_end
    if cnt[C_FAIL] == 0:
        status = ST_AVERAGED
        out_f[O_ERR] = spread + max(abs(loose[0] - means[0]),
                                    abs(loose[1] - means[1]))
        if p > 0 and (P[P_SR] != 1.0
                      or not _attracts(P, s, p, rtol, hmax, W, cnt, max_events)):
            # the window lies on an orbit of p periods: its mean is the orbit's, which is
            # the long-time one only where the orbit attracts and is the motion's own.
            # With a static circle above the kinetic one attractors coexist, and which one
            # the motion takes can turn on the tolerance of its transient: the motion of
            # vibrofriction.simulate from the same start was found elsewhere at 6 of 15
            # such windows (docs/inplane.md, "Averaged answers")
            out_f[O_ERR] = math.inf
    return status


@jit
def _attracts(P, s, p, rtol, hmax, W, cnt, max_events):
    """Whether the orbit of ``p`` periods through the section state ``s`` (its phase in
    ``W[W_MODE, 0]``) attracts: the spectral radius of the product of its ``p`` one-period
    Jacobians (:func:`period_map_tangent`) below ``1 - 1e-6``; False where a tangent does
    not hold (a graze, or a switch a difference changes).  ``s`` and the phase are kept.
    """
    hint = W[W_MODE, 0]
    s1 = s.copy()
    s2 = np.empty(N_S)
    J = np.eye(N_S)
    Jk = np.empty((N_S, N_S))
    acc = np.zeros(4)
    exact = True
    for _ in range(p):
        ok, exact = period_map_tangent(P, s1, s2, rtol, rtol, hmax, W, acc, cnt,
                                       max_events, Jk)
        if not (ok and exact):
            exact = False
            break
        J = Jk @ J
        W[W_MODE, 0] = W[W_MODE, 1]
        s1[:] = s2
    W[W_MODE, 0] = hint
    if not exact:
        return False
    return dense_spectral_radius(J) < 1.0 - 1e-6


@jit
def _write_rows(P, s, W, cnt, status, mult, periods, means, out_f, out_i, s_out):
    """The output rows (columns of ``solver.FLOAT_COLUMNS``, ``INT_COLUMNS``) and the
    final section state ``s`` into ``s_out``.
    """
    if status == ST_PERIODIC or status == ST_AVERAGED:
        out_f[O_MU] = means[0]
        out_f[O_LAT] = means[1]
        out_f[O_STICK] = means[2]
        out_f[O_SLIP] = means[3] - means[5]  # forward: f_x >= 0, as the 1-D solver's
        out_f[O_FLIGHT] = means[4]
        out_f[O_SLIP_NEG] = means[5]
        # the final section state (x components, laboratory frame)
        z = W[13]
        for i in range(N_S):
            z[i] = s[i]
        mode = entry_hint(P, 0.0, z, int(W[W_MODE, 0]))
        fx = contact(mode, P, 0.0, z)[0]
        out_f[O_Y] = z[0]
        out_f[O_XD] = z[2]
        out_f[O_F] = fx
        out_f[O_E] = z[4]
        out_i[I_PHASE] = STICK if mode == STICK else (SLIP_POS if fx >= 0.0 else SLIP_NEG)
    else:
        out_f[O_ERR] = math.inf
    for i in range(N_S):
        s_out[i] = s[i]
    if s_out.shape[0] > N_S:  # the phase at the section (static_ratio > 1: part of the state)
        s_out[N_S] = W[W_MODE, 0]
    out_f[O_MULT] = mult
    out_f[O_WORK] = periods
    out_i[I_STATUS] = status
    out_i[I_PERIODS] = periods
    out_i[I_EVENTS] = cnt[C_EVENTS]
    out_i[I_DEGENERATE] = 0


@jit
def plane_steady_section(alpha, beta, a, V, zeta, eta, a_x, phase_x, a_y, phase_y, alpha_y,
                         zeta_y, on_substrate, init_kind, y0, xd0, e0, rtol, max_periods,
                         max_events, out_f, out_i, s_out, static_ratio=1.0):
    """:func:`plane_steady_state`, and the full section state ``(y_x, y_y, v_x, v_y, e_x,
    e_y)`` it ends on into ``s_out`` (the periodic orbit's, or the averaging window's
    end; the output rows keep only the x components); a seventh element of ``s_out``, if
    given, gets the phase at that section (the hint of :func:`entry_hint`).
    """
    P = parameters(alpha, beta, a, V, zeta, eta, a_x, phase_x, a_y, phase_y, alpha_y, zeta_y,
                   on_substrate, static_ratio)
    s = np.empty(N_S)
    start_state(P, init_kind, y0, xd0, e0, s)
    # the phase before the start: steady sliding slips (where the state allows it), a
    # contact with no history (rest, an explicit state) is stuck
    _steady(P, s, SLIP if init_kind == 0 else STICK, False, np.zeros((N_S, N_S)), False, rtol,
            max_periods, max_events, out_f, out_i, s_out)


@jit
def _steady(P, s, hint, warm, J, given, rtol, max_periods, max_events, out_f, out_i, s_out):
    """The steady state of the point ``P`` from the section state ``s`` at ``tau = 0`` and
    the phase ``hint`` before it (:func:`plane_steady_section`).  ``warm``: ``s`` is a
    neighbour's periodic orbit (a continuation, :func:`plane_steady_chain`), and Newton's
    method starts from it at once, without the transient (where it finds no orbit, the plain
    iteration follows the motion from ``s``, as from a transient's end); ``given``: ``J``
    holds that neighbour's Jacobian, for Newton's first steps.  Returns True where Newton
    found the orbit, ``J`` then its Jacobian.
    """
    out_f[:] = math.nan
    out_f[O_WORK] = 0.0
    out_i[:] = 0
    out_i[I_PHASE] = -1
    hmax = max_step(P)
    W = np.zeros((N_W, N_Z))
    W[W_MODE, 0] = hint
    cnt = np.zeros(N_C, np.int64)
    info = np.zeros(4)
    s_start = s.copy()
    k = P[P_K]
    warm = warm and P[P_V] != 0.0
    found = False
    periods = 0
    R = np.zeros(N_R)  # the rough orbit's record
    ph = np.empty(N_S)  # Newton's last map's end, Phi(s)
    if not warm:
        periods, found = _start_transient(P, s, rtol, hmax, W, cnt, max_events, max_periods,
                                          J, info, R)
    status = ST_FAILED
    mult = math.nan
    use_newton = False
    means = np.zeros(7)
    s0 = s.copy()
    budget = max_periods - periods - N_AVG - N_WINDOW - ITER_RESERVE
    if cnt[C_FAIL] == 0:
        scale = 1.0 + _dist(s, np.zeros(N_S), k)
        hint0 = W[W_MODE, 0]
        status, mult, use_newton, periods = _orbit_search(
            P, s, s0, rtol, hmax, W, cnt, max_events, scale, budget, periods, J, info, means,
            R, ph, warm and given, found)
        if status == ST_PERIODIC and use_newton and P[P_SR] != 1.0:
            # sliding and stick-slip coexist: the motion from the transient's end must come
            # to Newton's orbit; where it does not, its own orbit by plain iteration
            phase = W[W_MODE, 0]
            sm = s0.copy()
            W[W_MODE, 0] = hint0
            reached, more = _follow(P, sm, s, phase, J, means[2] > 0.0, rtol, hmax, W, cnt,
                                    max_events, max(0, min(FALLBACK_ITER, budget - periods)))
            periods += more
            if reached:
                W[W_MODE, 0] = phase
            elif cnt[C_FAIL] == 0:
                s[:] = sm
                s0[:] = sm
                info[:] = 0.0
                status, mult, use_newton, periods = _orbit_search(
                    P, s, s0, rtol, hmax, W, cnt, max_events, scale, budget - periods, periods,
                    J, info, means, R, ph, False, False, False)
        periods_to_orbit = periods
        if status == ST_PERIODIC and periods > max_periods:
            status = ST_NOT_CONVERGED  # the orbit took more periods than allowed
        res = info[1]
        if status == ST_PERIODIC:
            out_i[I_PERIOD] = 1
            periods = _orbit_error(P, s, s_start, rtol, hmax, W, cnt, max_events, scale,
                                   use_newton, J, info, mult, res, periods,
                                   periods_to_orbit, means, out_f, R, ph)
        elif cnt[C_FAIL] == 0 and periods + N_AVG + N_WINDOW < max_periods:
            status = _averaged(P, s, s0, use_newton, rtol, hmax, W, cnt, max_events, status,
                               means, out_f)
            periods += N_AVG + N_WINDOW
        elif cnt[C_FAIL] == 0:
            status = ST_NOT_CONVERGED
    _write_rows(P, s, W, cnt, status, mult, periods, means, out_f, out_i, s_out)
    return status == ST_PERIODIC and use_newton


@jit
def plane_steady_chain(points, init_kind, init, link, rtol, max_periods, max_events, out_f,
                       out_i):
    """:func:`plane_steady_state_many` as a continuation: ``link[i]`` says where point ``i``
    starts (``codes.LINK_OWN``: its own start, ``init_kind`` and ``init[i]``;
    ``LINK_GIVEN``: the state ``init[i]``; ``LINK_PREVIOUS``: the final section state of
    point ``i - 1``, all six components and its phase, where that point found a periodic
    orbit, with Coulomb friction Newton's method from it at once (:func:`_steady`); else
    its own start).  Where up to three points before it are such orbits on one velocity
    curve with it (:func:`.steady.history`), Newton starts from the orbit extrapolated along
    ``V`` through them (:func:`_extrapolated`), as the 1-D chain does.
    """
    S = np.zeros((points.shape[0], N_S + 1))  # each point's final section state and phase
    orbit = False  # point i - 1 ended on a periodic orbit, in S[i - 1]
    J = np.zeros((N_S, N_S))
    newton_j = False  # ... found by Newton: J is its Jacobian
    for i in range(points.shape[0]):
        p = points[i]
        P = parameters(p[T_ALPHA], p[T_BETA], p[T_AMPLITUDE], p[T_V], p[T_ZETA], p[T_ETA_C],
                       p[T_A_X], p[T_PHASE_X], p[T_A_Y], p[T_PHASE_Y], p[T_ALPHA_Y],
                       p[T_ZETA_Y], p[T_INPLANE_ON] == 0.0, p[T_STATIC_RATIO])
        s = np.empty(N_S)
        s_out = np.zeros(N_S + 1)
        if link[i] == LINK_PREVIOUS and orbit:
            for j in range(N_S):
                s[j] = S[i - 1, j]
            # Coulomb friction: Newton from the neighbour's orbit at once (a static circle
            # above the kinetic one runs the transient from it: sliding and stick-slip
            # coexist there, as in the 1-D chain)
            warm = p[T_STATIC_RATIO] == 1.0
            m = history(points, out_i, link, i, out_i[i - 1, I_PHASE]) if warm else 0
            if m > 1:
                _extrapolated(points, S, i, m, s)
            newton_j = _steady(P, s, int(S[i - 1, N_S]), warm, J, newton_j and warm, rtol,
                               max_periods, max_events, out_f[i], out_i[i], s_out)
        else:
            kind = 2 if link[i] == LINK_GIVEN else init_kind
            start_state(P, kind, init[i, 0], init[i, 1], init[i, 2], s)
            newton_j = _steady(P, s, SLIP if kind == 0 else STICK, False, J, False, rtol,
                               max_periods, max_events, out_f[i], out_i[i], s_out)
        orbit = out_i[i, I_STATUS] == ST_PERIODIC
        S[i, :] = s_out


@jit
def _extrapolated(points, S, i, m, s):
    """The orbit's section state at point ``i`` extrapolated along ``V`` through the final
    states ``S`` of the ``m`` points before it (Lagrange's polynomial of degree ``m - 1``;
    a predictor that Newton corrects) into ``s``.
    """
    s[:] = 0.0
    for a in range(i - m, i):
        w = lagrange_weight(points, i, m, a)
        for j in range(N_S):
            s[j] += w * S[a, j]


@jit
def cone_excess(P, periods, rtol):
    """The largest ``|f| - n`` at the step ends and switches of ``periods`` drive periods
    from the sliding start of the parameter vector ``P`` (a check of the phase rules).
    """
    hmax = max_step(P)
    W = np.zeros((N_W, N_Z))
    cnt = np.zeros(N_C, np.int64)
    acc = np.zeros(5)
    acc[4] = -math.inf
    s = np.empty(N_S)
    start_state(P, 0, 0.0, 0.0, 0.0, s)
    z = W[13]
    for i in range(N_S):
        z[i] = s[i]
    mode = entry_hint(P, 0.0, z, SLIP)  # the sliding start
    for j in range(periods):
        mode, ok = one_period(P, TWO_PI * j, z, mode, rtol, rtol, hmax, W, acc, cnt, 10000,
                              np.empty((0, N_S, N_S)))
        if not ok:
            return math.inf
    return acc[4]


N_AVG = 200
"""The averaging fallback: this many periods of transient, then a window of
:data:`N_WINDOW`."""
N_WINDOW = 360
"""... periods, whose thirds hold whole orbits of 1-6, 8, 10 and 12 periods (the 2-D solver
finds orbits of one period; a motion on one of several periods is averaged, and its
thirds' means then agree to round-off)."""


@jit
def average(P, s, rtol, hmax, W, cnt, max_events, means):
    """The long-time average from the section state ``s``: ``N_AVG`` periods of
    transient, then means over ``N_WINDOW`` periods into ``means`` (as :func:`orbit_mean`),
    ``s`` the end state.  Returns the window's spread, the larger of the ranges of its
    thirds' means (:func:`_thirds_range`) in ``mu`` and in the lateral ratio, and the
    period of the orbit the window lies on (:func:`_orbit_periods`; 0: none).
    """
    z = W[13]
    for i in range(N_S):
        z[i] = s[i]
    z[6] = 0.0
    z[7] = 0.0
    mode = entry_hint(P, 0.0, z, int(W[W_MODE, 0]))
    pfx = np.zeros(N_WINDOW)
    pfy = np.zeros(N_WINDOW)
    acc = np.zeros(4)
    no_tangent = np.empty((0, N_S, N_S))
    for j in range(N_AVG + N_WINDOW):
        z[6] = 0.0
        z[7] = 0.0
        if j == N_AVG:
            acc[:] = 0.0
        mode, ok = one_period(P, 0.0, z, mode, rtol, rtol, hmax, W, acc, cnt, max_events,
                              no_tangent)
        if not ok:
            return math.inf, 0
        if j >= N_AVG:
            pfx[j - N_AVG] = z[6]
            pfy[j - N_AVG] = z[7]
    nbar = TWO_PI * mean_normal(P[P_A])
    means[0] = pfx.sum() / (N_WINDOW * nbar)
    means[1] = pfy.sum() / (N_WINDOW * nbar)
    for i in range(4):
        means[2 + i] = acc[i] / (TWO_PI * N_WINDOW)
    for i in range(N_S):
        s[i] = z[i]
    W[W_MODE, 0] = mode
    return max(_thirds_range(pfx, nbar), _thirds_range(pfy, nbar)), _orbit_periods(pfx, pfy)


ORBIT_REPEAT = 1e-6
"""A window whose per-period integrals of the force repeat after ``p`` periods to this
(relative to their size) lies on an orbit of ``p`` periods (:func:`_orbit_periods`)."""


@jit
def _orbit_periods(pfx, pfy):
    """The smallest ``p`` <= 12 after which the window's per-period integrals of ``(f_x,
    f_y)`` repeat to :data:`ORBIT_REPEAT`, else 0 (a motion not on an orbit).
    """
    n = pfx.shape[0]
    size = 1e-300
    for j in range(n):
        size = max(size, abs(pfx[j]) + abs(pfy[j]))
    for p in range(1, 13):
        repeats = True
        for j in range(n - p):
            if abs(pfx[j + p] - pfx[j]) + abs(pfy[j + p] - pfy[j]) > ORBIT_REPEAT * size:
                repeats = False
                break
        if repeats:
            return p
    return 0


@jit
def _thirds_range(per, nbar):
    """The range of the means over the three thirds of a window (``per``: each period's
    integral, ``nbar`` that of ``n``): the error of the window's mean (the difference of
    its halves is exceeded about three times as often where the motion is not locked to
    the drive; docs/inplane.md).
    """
    n = per.shape[0]
    t = n // 3
    m0 = per[:t].sum() / (t * nbar)
    m1 = per[t:2 * t].sum() / (t * nbar)
    m2 = per[2 * t:].sum() / ((n - 2 * t) * nbar)
    return max(m0, m1, m2) - min(m0, m1, m2)


@jit
def plane_steady_state_many(points, init_kind, init, rtol, max_periods, max_events, out_f,
                            out_i):
    """:func:`plane_steady_state` over a table of points (``points`` rows by the schema's
    indices, ``codes.T_*``; ``init`` rows ``(y, x', e)``).
    """
    for i in range(points.shape[0]):
        p = points[i]
        plane_steady_state(p[T_ALPHA], p[T_BETA], p[T_AMPLITUDE], p[T_V], p[T_ZETA],
                           p[T_ETA_C], p[T_A_X], p[T_PHASE_X], p[T_A_Y], p[T_PHASE_Y],
                           p[T_ALPHA_Y], p[T_ZETA_Y], p[T_INPLANE_ON] == 0.0, init_kind,
                           init[i, 0], init[i, 1], init[i, 2], rtol, max_periods,
                           max_events, out_f[i], out_i[i], p[T_STATIC_RATIO])


# columns of a 2-D history row (plane_history)
H_TAU, H_Y, H_V, H_E, H_INT, H_F, H_N, H_PHASE, H_SLIP, H_EVENT = 0, 1, 3, 5, 7, 9, 11, 12, 13, 15
N_H = 16
"""A row: tau, (y_x, y_y), (v_x, v_y), (e_x, e_y), the integrals of (f_x, f_y) since
``tau = 0``, (f_x, f_y), n, phase (stick 0, slip 1, flight 3), the contact point's
velocity relative to the substrate (x, y), and the event code (``codes.EVENT_NAMES``,
-1 for a sample of the grid)."""


@jit
def _record(P, t, z, mode, event, out, row):
    """The row ``row`` of ``out`` (:data:`N_H` columns) for the state ``z`` in ``mode``."""
    if row >= out.shape[0]:
        return row + 1
    r = out[row]
    r[H_TAU] = t
    for i in range(N_Z):
        r[H_Y + i] = z[i]
    fx, fy, ex, ey, _ = contact(mode, P, t, z)
    _, _, _, _, vsx, vsy = drive(P, t)
    n, _ = normal_force(P[P_A], t)
    r[H_F], r[H_F + 1], r[H_N] = fx, fy, n
    r[H_PHASE] = mode
    r[H_SLIP] = z[2] - vsx - ex  # the contact point's velocity minus the substrate's
    r[H_SLIP + 1] = z[3] - vsy - ey
    r[H_EVENT] = event
    return row + 1


@jit
def plane_history(P, s, periods, grid, rtol, max_events, out, hint=STICK):
    """Integrate ``periods`` drive periods from the section state ``s`` (6) at ``tau =
    0``, recording a row (:data:`N_H` columns) at every time of the sorted ``grid`` and
    two at every event (the state before the switch, in the old phase, and after it, in
    the new one): stick/slip switches, lift-off and touch-down.  The phase is carried
    across the sections (as :func:`average` does).  Returns the number of rows (more
    than ``out`` holds: call again with a larger one), or -1 where the integration
    failed (chatter: more than ``max_events`` switches in a period, or a step that
    could not be taken).  ``hint``: the phase before the start (:func:`entry_hint`; a
    slip of no duration, ``static_ratio > 1``, gives both events, four rows).
    """
    a = P[P_A]
    jenkins = P[P_C] == 0.0
    hmax = max_step(P)
    W = np.zeros((N_W, N_Z))
    cnt = np.zeros(N_C, np.int64)
    acc = np.zeros(4)
    z = np.zeros(N_Z)
    for i in range(N_S):
        z[i] = s[i]
    mode = entry_hint(P, 0.0, z, hint)
    ends = np.empty(3)
    contact_ = np.empty(3, np.bool_)
    th = math.acos(-1.0 / a) if a > 1.0 else 0.0
    d = DELTA if jenkins else 0.0
    ng = grid.shape[0]
    no_tangent = np.empty((0, N_S, N_S))
    gi = 0
    row = 0
    t = 0.0
    h = hmax
    while gi < ng and grid[gi] <= t:
        row = _record(P, t, z, mode, -1, out, row)
        gi += 1
    for j in range(periods):
        t0 = TWO_PI * j
        t_end = TWO_PI * (j + 1)  # as the grid's sections (t0 + TWO_PI can differ by an ulp)
        if a > 1.0:
            ends[0], ends[1], ends[2] = t0 + th - d, t0 + TWO_PI - th + d, t_end
            contact_[0], contact_[1], contact_[2] = True, False, True
            m = 3
        else:
            ends[0] = t_end
            contact_[0] = True
            m = 1
        ev = 0
        for p in range(m):
            t1 = ends[p]
            if not contact_[p]:
                if mode != FLIGHT:
                    row = _record(P, t, z, mode, 3, out, row)  # lift-off
                    if jenkins:
                        z[4] = 0.0
                        z[5] = 0.0
                    mode = FLIGHT
                    row = _record(P, t, z, mode, 3, out, row)
            elif mode == FLIGHT:
                row = _record(P, t, z, mode, 4, out, row)  # touch-down
                mode = touchdown(P, t, z)
                row = _record(P, t, z, mode, 4, out, row)
            while t < t1:
                target = t1
                if gi < ng and grid[gi] < t1:
                    target = grid[gi]
                t, event, h = segment(mode, P, t, target, z, h, rtol, rtol, hmax, W, acc,
                                      cnt, no_tangent)
                if cnt[C_FAIL] > 0:
                    return -1
                if event:
                    code = EV_STICK_TO_SLIP if mode == STICK else EV_SLIP_TO_STICK
                    row = _record(P, t, z, mode, code, out, row)
                    new = switch(mode, P, t, z)
                    if new == mode:  # stick, a jump to the kinetic cone and stick again
                        row = _record(P, t, z, SLIP, code, out, row)
                        row = _record(P, t, z, SLIP, EV_SLIP_TO_STICK, out, row)
                        code = EV_SLIP_TO_STICK
                    mode = new
                    row = _record(P, t, z, mode, code, out, row)
                    ev += 1
                    if ev > max_events:
                        return -1
                while gi < ng and grid[gi] <= t:
                    row = _record(P, t, z, mode, -1, out, row)
                    gi += 1
    return row
