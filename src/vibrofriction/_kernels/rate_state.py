r"""Rate-and-state friction on the 1-D flat punch: a Rosenbrock integrator and the steady state.

Scaled variables as everywhere (docs/model.md): ``tau = omega t``, forces in ``mu_star F_N0``,
``n = 1 + A cos tau``, ``y = x - V tau``, ``k = beta - alpha`` (``inf``: a rigid contact,
below), ``gamma = 2 zeta sqrt(alpha)``, ``h`` the longitudinal in-plane
forcing (:func:`.phases.inplane_forcing`).  The body obeys ``y'' + gamma y' + alpha y = -f +
h`` with ``f = k e``; the massless contact point slips at the rate the law gives by
inversion (docs/friction_laws.md)::

    w' = 2 v_ref sinh(m/a) exp(-Q),  Q = (1 + b ln(theta v_ref/d_c))/a,  m = f/n.

The contact's variable is the local coefficient ``m = k e/n`` rather than ``e`` (it stays
finite as ``n -> 0``): ``m' = (k (x' - w') - m n')/n``.  The state is integrated as ``L = ln
theta`` (theta spans decades): aging ``L' = e^-L - |w'|/d_c``, slip ``L' = -g (ln g + L)``
with ``g = |w'|/d_c``, plus the Linker-Dieterich term ``-(alpha_ld/b) n'/n``.  In flight
(``A > 1``) ``f = 0``, aging ``L' = e^-L``, slip ``L' = 0``, and the contact re-forms
unloaded (``e = n m/k = 0``) on the slow manifold of ``m`` (:func:`_touchdown_mu`).

A rigid contact (``k = inf``, the mode ``RIGID`` of its contact segments): the contact point
moves with the body, ``w' = x'``, and ``f = n mu(x', theta)``.  The variable stays the local
coefficient ``m = f/n``, the body's velocity slaved to it, ``x' = w'(m, L)``; the body's
equation differentiated, ``x'' = w_m m' + w_L L'``, gives ``m' = (x'' - w_L L')/w_m``
(:func:`_evaluate_rigid`).  Why ``m`` and not ``x'``: near rest ``f`` depends on ``x'``
through ``e^(1/a)``, so ``x'`` as the variable would carry the force with an error ``~a``
at the tolerance, whereas ``m`` carries it directly (``x'`` follows it, exponentially
compressed); and ``m`` does not see ``1/n`` (``f`` would: ``f' = ... + f n'/n``).  The
stiffness ``1/w_m ~ e^(1/a)`` of the relaxation to the holding force where the body
sticks is the L-stable integrator's to take.  The component ``x'`` of ``z`` is left
untouched in contact and set to ``w'(m, L)`` where a contact segment ends
(:func:`_rigid_end`: the section state's ``x'`` is slaved, the monodromy's column of it
zero); in flight the body moves freely; at touch-down ``m = mu(x', theta)`` (the body's
velocity continuous, as the reference's rigid contact); the start is steady sliding with
``x' = V`` continuous at ``tau = 0`` (``m = mu_ss(V)``, the force jumping to ``n(0) mu_ss``,
the reference's).  Where the body comes to (almost) rest the force drops to the holding
force within ``~ x'/|x''|`` at the tiny ``x'`` it sticks at: for a small ``a`` below
``H_MIN``, and the integration fails there (said, never a wrong number).

Contact damping (``eta_c > 0``, the mode ``DAMPED``): the dashpot ``c = eta_c k`` in
parallel with the spring, ``f = k e + c (x' - w') = n m``; ``m`` stays the variable (``w'``
explicit in it) and ``m' = (k (x' - w') - n' m + c (x'' - w_L L'))/(n + c w_m)``
(:func:`_evaluate_damped`).  In flight ``z[Z_M]`` holds the elongation, ``k e + c e' = 0``;
at touch-down and at the start ``m`` is the root of ``n m + c w'(m, L) = k e + c x'``
(:func:`_damped_mu`; the start keeps ``e = mu_ss/k`` and ``x' = V``).

The state vector is ``z = (y, x', m, L, F, D, G)``: ``F = int f``, ``D = int f w'`` (the
friction's dissipation) and ``G = int gamma y'^2`` (the pin dashpot's) are quadratures
reset at each section, integrated by the same steps.  Integrator: RODAS4 (Hairer & Wanner,
*Solving ODEs II*, IV.7; 6 stages, order 4 with an embedded order 3, L-stable, stiffly
accurate), the analytic Jacobian and time derivative, step control on
``max |err_i|/(rtol (s_i + |z_i|))`` with ``s_i = 1`` but for ``L``, whose error counts by
its effect on the friction, ``b dL`` (:func:`_scales`; the section distance weighs it the
same way).  Lift-off and touch-down are at the closed-form
phases ``cos tau = -1/A``; the contact segments end (and start) where ``n = CUT_DELTA``,
where ``|f| = n |m|`` is below round-off of the averages.  While the load grows a finite
contact's step is at most ``LOADING_GROWTH n/n'`` (:func:`_loading_step`): from a
touch-down the steps grow geometrically, and the error control sees the error of ``m`` there.

The steady state (:func:`rs_steady_state`): ``SETTLE`` periods from the start (at the loose
tolerance ``LOOSE_RTOL``: they only approach the orbit), then Newton's method on the period
map (inexact: a map's tolerance ``FORCING`` times the squared residual of the iterate before,
at most ``LOOSE_RTOL``; convergence is only declared on a map at ``rtol``) with its exact
Jacobian: the variational equations ``T' = J T``
ride along the state in the same Rosenbrock steps (:func:`_tangent_stage`: the augmented
system is block-triangular, so its stages are linear solves with the state's factors), the
cuts' saltation matrices are the Jacobians of their resets (the cuts are at fixed phases),
and the tangent's error is part of the step control at ``TANGENT_RTOL`` times the state's
tolerance.  The monodromy matrix and the gradient of the period's mean so come from one
integration per Newton step, and the multiplier (the spectral radius of the monodromy at
the converged orbit) is exact to the integration's tolerance.  An attracting orbit found
(the multiplier below 1) is refined by one map at ``rtol/REFINE`` and one chord step
(:func:`_refine`; close to an orbit that attracts well, that map also confirms Newton's
convergence in place of a second map at ``rtol``): the
answer is the refined mean, its error twice the change of the mean between the two
tolerances plus the next Newton step's change of the mean (the integration error
propagated and the Newton residual).  Otherwise (a response not locked to the drive:
self-excited stick-slip of a weakening contact, a quasi-periodic or subharmonic response, an
orbit that grows however slowly) the motion is averaged over doubling windows, as the event
solver does, and ``AVERAGED`` is said, never ``PERIODIC``, with the range of the last
three windows' means (at least ``10 rtol``; :func:`.average.window_means`) plus the
integration's error as the error: twice the change of the last period's mean at
``rtol/REFINE`` from the same start (:func:`_averaged_error`, as the periodic answer's).
Where the motion sits on a repelling orbit (an unstable steady sliding without oscillation,
which is an exact equilibrium from the sliding start) it is kicked off it by ``KICK`` of its
velocity.
"""

import math

import numpy as np

from .average import window_means
from .codes import (
    I_EVENTS,
    I_METHOD,
    I_PERIOD,
    I_PERIODS,
    I_PHASE,
    I_STATUS,
    O_DRIFT,
    O_E,
    O_ERR,
    O_F,
    O_FLIGHT,
    O_LAT,
    O_MU,
    O_MULT,
    O_SETTLE,
    O_WORK,
    O_XD,
    O_Y,
    SLIP_NEG,
    SLIP_POS,
    ST_AVERAGED,
    ST_FAILED,
    ST_NOT_CONVERGED,
    ST_PERIODIC,
    T_A_X,
    T_ALPHA,
    T_AMPLITUDE,
    T_BETA,
    T_ETA_C,
    T_INPLANE_ON,
    T_PHASE_X,
    T_V,
    T_ZETA,
    point_index,
)
from .integrate import to_lab_frame
from .jit import jit, jit_bare
from .newton import _solve_small, dense_spectral_radius
from .phases import frame_offset, inplane_forcing

__all__ = ["rs_period", "rs_steady_state", "rs_steady_state_many", "steady_mu"]

T_RS_A = point_index("rs_a")
T_RS_B = point_index("rs_b")
T_RS_DC = point_index("rs_d_c")
T_RS_VREF = point_index("rs_v_ref")
T_RS_ALD = point_index("rs_alpha_ld")
T_RS_LAW = point_index("rs_law")  # the index of "aging" is 0, of "slip" 1

TWO_PI = 2.0 * math.pi
# fields of the parameter vector
P_ALPHA, P_K, P_A, P_V, P_GAMMA, P_HC, P_HS, P_RA, P_RB, P_DC, P_VREF = range(11)
P_ALD, P_SLIPLAW, P_LNR, P_OFF, P_ON, P_NBAR, P_ETA = range(11, 18)
N_PAR = 18
# the state: y, x', m = f/n, ln theta and the quadratures int f, int f w', int gamma y'^2
Z_Y, Z_V, Z_M, Z_L, Z_F, Z_D, Z_G = range(7)
NZ = 7
NM = 4  # the components that feed back (the quadratures do not)
# RIGID: a rigid contact's segments (k = inf); DAMPED: a contact with its dashpot (eta_c > 0)
CONTACT, FLIGHT, RIGID, DAMPED = 0, 1, 2, 3
RECORD = 1  # lp[1] of a segment that records its steps (:func:`_segment`)
NT = 5  # rows of the tangent: the section state and the quadrature F (Z_F == NM)
# the coefficients of the second derivatives (:func:`_curvature`)
CV_KN, CV_W, CV_WM, CV_WL, CV_BA, CV_IA2, CV_LW, CV_LWW, CV_LWL, CV_LLL = range(10)
# and those of a rigid contact (:func:`_curvature_rigid`)
CV_RIGID, CV_IW, CV_R, CV_TH, CV_IA, CV_LR, CV_LL, CV_GAM, CV_ALPHA, CV_N = range(10, 20)
# and a damped contact's (:func:`_curvature_damped`; CV_IW is 1/(n + c w_m), CV_R m')
CV_DAMPED, CV_K, CV_C, CV_ND = range(20, 24)
N_CV = 24
TANGENT_RTOL = 100.0  # the variational equations' tolerance is this many rtol (their
# error is part of the step control: the multiplier to ~1e-6 where the state is to rtol)
CUT_DELTA = 1e-9  # contact segments end where n = CUT_DELTA before lift-off (see doc)
EXP_MAX = 700.0  # exponents are clipped here: an overflowing stage is rejected
H_MAX = 0.25 * math.pi  # the longest step
H_MIN = 1e-14  # a step below this (relative to 2 pi) has failed
MAX_STEPS = 200_000  # steps per period before the integration is said to have failed
SAFETY = 0.9
LOADING_GROWTH = 2.0  # a finite contact's step while the load grows: at most this many
# n/n' (:func:`_loading_step`; the load at most triples in a step)
REFINE = 20.0  # the refinement's tolerance is rtol/REFINE
ERROR_SAFETY = 2.0
NEWTON_ITERATIONS = 16
NEWTON_PROGRESS = 0.1  # after 6 iterations the residual must have fallen this much
NEUTRAL = 1.0 - 1e-6  # a multiplier modulus above this does not attract
LOOSE_RTOL = 1e-4  # the tolerance of the settling periods and of Newton's first maps
N_RES = 7  # the length of :func:`_newton`'s ``res``
SHORTCUT = 3e-5  # a residual below which a map at rtol is not repeated (:func:`_newton`)
NEAR_NEUTRAL = 1e-3  # ... unless the multiplier is within this of 1
FORCING = 0.001  # an inexact Newton map's tolerance: FORCING times the squared residual
SETTLE = 4  # plain periods from the start before Newton's method (far from the orbit its
# steps are poor: the period map is far from linear)
FIRST_CHECK = 16  # the first checkpoint of the running average, doubling
KICK = 1e-3  # relative velocity kick off a repelling orbit the motion sits on
ROUNDOFF_MU = 1e-13
L_WEIGHT_FLOOR = 0.01  # the least weight of ln theta's error, in units of a (:func:`_scales`)

# RODAS4 (Hairer & Wanner, Solving ODEs II, Sect. IV.7; rodas.f, ROCOE with METH = 1)
GAM = 0.25
A21 = 1.544
A31, A32 = 0.9466785280815826, 0.2557011698983284
A41, A42, A43 = 3.314825187068521, 2.896124015972201, 0.9986419139977817
A51, A52, A53, A54 = 1.221224509226641, 6.019134481288629, 12.53708332932087, -0.6878860361058950
C21 = -5.6688
C31, C32 = -2.430093356833875, -0.2063599157091915
C41, C42, C43 = -0.1073529058151375, -9.594562251023355, -20.47028614809616
C51, C52, C53, C54 = 7.496443313967647, -10.24680431464352, -33.99990352819905, 11.70890893206160
C61, C62, C63 = 8.083246795921522, -7.981132988064893, -31.52159432874371
C64, C65 = 16.31930543123136, -6.058818238834054
CC2, CC3, CC4 = 0.386, 0.21, 0.63
D1, D2, D3, D4 = 0.25, -0.1043, 0.1035, -0.0362
# the tableau as the tangent's stages use it (:func:`_tangent_stage`): stage i's point
# T + sum_l RA[i, l] KT[l], its right-hand side f + h RD[i] f_t + sum_l RCC[i, l] KT[l]/h
# (the last stage's point is the embedded solution, the solution that plus KT[5])
RA = np.array([[0.0, 0.0, 0.0, 0.0, 0.0], [A21, 0.0, 0.0, 0.0, 0.0],
               [A31, A32, 0.0, 0.0, 0.0], [A41, A42, A43, 0.0, 0.0],
               [A51, A52, A53, A54, 0.0], [A51, A52, A53, A54, 1.0]])
RD = np.array([D1, D2, D3, D4, 0.0, 0.0])
RCC = np.array([[0.0, 0.0, 0.0, 0.0, 0.0], [C21, 0.0, 0.0, 0.0, 0.0],
                [C31, C32, 0.0, 0.0, 0.0], [C41, C42, C43, 0.0, 0.0],
                [C51, C52, C53, C54, 0.0], [C61, C62, C63, C64, C65]])


@jit
def _exp(x):
    return math.exp(min(x, EXP_MAX))


@jit
def make_parameters(alpha, beta, A, V, zeta, a_x, phase_x, on_substrate, ra, rb, dc, vref,
                    ald, slip_law, eta_c=0.0):
    """The parameter vector of one point (fields ``P_*``; a rigid contact ignores
    ``eta_c``).
    """
    P = np.empty(N_PAR)
    P[P_ETA] = 0.0 if math.isinf(beta) else eta_c
    gamma = 2.0 * zeta * math.sqrt(alpha)
    hc, hs = inplane_forcing(alpha, gamma, a_x, phase_x, on_substrate)
    P[P_ALPHA], P[P_K], P[P_A], P[P_V], P[P_GAMMA] = alpha, beta - alpha, A, V, gamma
    P[P_HC], P[P_HS], P[P_RA], P[P_RB], P[P_DC], P[P_VREF] = hc, hs, ra, rb, dc, vref
    P[P_ALD], P[P_SLIPLAW], P[P_LNR] = ald, slip_law, math.log(vref / dc)
    if A >= 1.0:
        th = math.acos(-1.0 / A)
        P[P_OFF], P[P_ON] = th, TWO_PI - th
        P[P_NBAR] = (th + A * math.sin(th)) / math.pi
    else:
        P[P_OFF], P[P_ON] = TWO_PI, TWO_PI
        P[P_NBAR] = 1.0
    return P


@jit
def steady_mu(V, a, b, dc, vref):
    """``mu_ss(V) = a asinh(V/(2 v_ref) e^Q)``, ``Q = (1 + b ln(v_ref/V))/a``, without overflow."""
    lnz = math.log(V / (2.0 * vref)) + (1.0 + b * math.log(vref / V)) / a
    if lnz > 30.0:
        return a * (lnz + math.log(2.0))
    return a * math.asinh(math.exp(lnz))


@jit
def _slip_rate(P, m, L):
    """``(w', dw'/dm, dw'/dL)`` at the local coefficient ``m = f/n`` and ``L = ln theta``."""
    a = P[P_RA]
    q = (1.0 + P[P_RB] * (L + P[P_LNR])) / a
    u = m / a
    au = abs(u)
    ep = _exp(au - q)
    em = _exp(-au - q)
    w = P[P_VREF] * (ep - em)
    if u < 0.0:
        w = -w
    return w, P[P_VREF] * (ep + em) / a, -w * P[P_RB] / a


@jit
def local_mu(P, w, L):
    """The local coefficient ``a asinh(w'/(2 v_ref) e^Q)`` at the slip rate ``w'``, without
    overflow.
    """
    if w == 0.0:
        return 0.0
    a = P[P_RA]
    lnz = math.log(abs(w) / (2.0 * P[P_VREF])) + (1.0 + P[P_RB] * (L + P[P_LNR])) / a
    mu = a * (lnz + math.log(2.0)) if lnz > 30.0 else a * math.asinh(math.exp(lnz))
    return mu if w > 0.0 else -mu


@jit
def _touchdown_mu(P, tau, v, L):
    """The local coefficient on the slow manifold at the re-formed contact's tiny load.

    ``m' = 0`` to leading order: the root of ``g(m) = k (x' - w'(m)) - m n'``, which
    decreases in ``m`` and lies between 0 and the smaller in modulus of ``k x'/n'`` (the
    spring stretched at the body's velocity while the contact creeps) and the coefficient
    at the slip rate ``x'`` (the contact slipping with the body).  Newton's method kept in
    that bracket (bisection where a step leaves it).
    """
    k = P[P_K]
    nd = -P[P_A] * math.sin(tau)
    if v == 0.0:
        return 0.0
    far = local_mu(P, v, L)
    if nd > 0.0 and abs(k * v / nd) < abs(far):
        far = k * v / nd
    return _root_m(P, L, k * v, -nd, -k, far)


@jit
def _contact_mode(P):
    """The mode of the contact segments: ``RIGID`` for a rigid contact (``k = inf``),
    ``DAMPED`` with the contact's dashpot (``eta_c > 0``), else ``CONTACT``.
    """
    if math.isinf(P[P_K]):
        return RIGID
    return DAMPED if P[P_ETA] > 0.0 else CONTACT


@jit
def _inverse_slope(P, m, L):
    """``1/w_m = a e^(Q - |m|/a) / (v_ref (1 + e^(-2|m|/a)))`` without overflow: the
    stiffness of a rigid contact (``e^(1/a)`` at rest).
    """
    a = P[P_RA]
    q = (1.0 + P[P_RB] * (L + P[P_LNR])) / a
    au = abs(m) / a
    return a * _exp(q - au) / (P[P_VREF] * (1.0 + math.exp(-2.0 * au)))


@jit
def _state_rate(P, w, L, n, nd):
    """``(L', dL'/dw', dL'/dL)`` in contact at the slip rate ``w'`` (the partial derivatives;
    the Linker-Dieterich term ``-(alpha_ld/b) n'/n`` in ``L'``, independent of the state).
    """
    dc = P[P_DC]
    g = abs(w) / dc
    if P[P_SLIPLAW] != 0.0:
        lg = math.log(g) if g > 1e-300 else -690.0
        rate = -g * (lg + L)
        dLdw = -(lg + L + 1.0) / dc  # times sign(w)
        dLdL = -g
    else:
        rate = _exp(-L) - g
        dLdw = -1.0 / dc
        dLdL = -_exp(-L)
    if w < 0.0:
        dLdw = -dLdw
    if P[P_ALD] > 0.0:
        rate -= P[P_ALD] / P[P_RB] * nd / n
    return rate, dLdw, dLdL


@jit
def _rigid_terms(P, tau, z):
    """What a rigid contact's right-hand side, Jacobian and curvature share at ``(tau, z)``:
    ``(n, n', w', w_m, w_L, 1/w_m, L', dL'/dw', dL'/dL, R, h)`` with ``R = x'' - w_L L'``
    (so that ``m' = R/w_m``) and ``h`` the in-plane forcing.
    """
    A = P[P_A]
    ct, st = math.cos(tau), math.sin(tau)
    n = 1.0 + A * ct
    nd = -A * st
    h = P[P_HC] * ct + P[P_HS] * st
    y, m, L = z[Z_Y], z[Z_M], z[Z_L]
    w, wm, wL = _slip_rate(P, m, L)
    iw = _inverse_slope(P, m, L)
    lr, lw, ll = _state_rate(P, w, L, n, nd)
    R = -P[P_GAMMA] * (w - P[P_V]) - P[P_ALPHA] * y - n * m + h - wL * lr
    return n, nd, w, wm, wL, iw, lr, lw, ll, R, h


@jit
def _evaluate_rigid(P, tau, z, dz, J, ft, jac):
    """:func:`_evaluate` of a rigid contact (``w = x``, ``f = n mu(x', theta)``).

    The state is the local coefficient ``m = f/n`` with the body's velocity slaved to it,
    ``x' = w'(m, L)``; the body's equation ``x'' = -gamma (x' - V) - alpha y - n m + h``
    differentiated, ``x'' = w_m m' + w_L L'``, gives ``m' = R/w_m``, ``R = x'' - w_L L'``
    (a stiff relaxation of the friction towards the force that holds the body where it
    sticks, ``1/w_m ~ e^(1/a)`` at rest).  The component ``x'`` of ``z`` is not used (its
    rate 0): :func:`_rigid_end` sets it to ``w'`` where a segment ends.
    """
    n, nd, w, wm, wL, iw, lr, lw, ll, R, _ = _rigid_terms(P, tau, z)
    gamma, V, a = P[P_GAMMA], P[P_V], P[P_RA]
    m = z[Z_M]
    f = n * m
    md = iw * R
    if not _contact_rates(dz, w - V, 0.0, md, lr, f, w, gamma, J, ft, jac):
        return
    ba = P[P_RB] / a
    lm = lw * wm  # the total derivatives of L' by m and L
    lL = lw * wL + ll
    # DR[p] = -alpha p_y + Rm p_m + RL p_L;  m' = R/w_m, d(1/w_m) = (1/w_m) c[p] with
    # c[p] = -(tanh(m/a)/a) p_m + (b/a) p_L
    Rm = -n + (ba * lr - gamma) * wm + ba * w * lm
    RL = (ba * lr - gamma) * wL + ba * w * lL
    th = math.tanh(m / a)
    J[Z_Y, Z_M] = wm
    J[Z_Y, Z_L] = wL
    J[Z_M, Z_Y] = -P[P_ALPHA] * iw
    J[Z_M, Z_M] = iw * Rm - md * th / a
    J[Z_M, Z_L] = iw * RL + md * ba
    J[Z_L, Z_M] = lm
    J[Z_L, Z_L] = lL
    J[Z_F, Z_M] = n
    J[Z_D, Z_M] = n * w + f * wm
    J[Z_D, Z_L] = f * wL
    J[Z_G, Z_M] = 2.0 * gamma * (w - V) * wm
    J[Z_G, Z_L] = 2.0 * gamma * (w - V) * wL
    lt = _coupling_rate(P, tau)
    ct, st = math.cos(tau), math.sin(tau)
    ft[Z_M] = iw * (-nd * m + P[P_HS] * ct - P[P_HC] * st + ba * w * lt)
    ft[Z_L] = lt
    ft[Z_F] = nd * m
    ft[Z_D] = nd * m * w


@jit
def _damped_terms(P, tau, z):
    """What a damped contact's right-hand side, Jacobian and curvature share at ``(tau,
    z)``: ``(n, n', w', w_m, w_L, L', dL'/dw', dL'/dL, x'', m', 1/(n + c w_m), k, c)``.
    """
    A = P[P_A]
    ct, st = math.cos(tau), math.sin(tau)
    n = 1.0 + A * ct
    nd = -A * st
    y, v, m, L = z[Z_Y], z[Z_V], z[Z_M], z[Z_L]
    k = P[P_K]
    cd = P[P_ETA] * k
    w, wm, wL = _slip_rate(P, m, L)
    lr, lw, ll = _state_rate(P, w, L, n, nd)
    xdd = -P[P_GAMMA] * (v - P[P_V]) - P[P_ALPHA] * y - n * m + P[P_HC] * ct + P[P_HS] * st
    iD = 1.0 / (n + cd * wm)
    md = (k * (v - w) - nd * m + cd * (xdd - wL * lr)) * iD
    return n, nd, w, wm, wL, lr, lw, ll, xdd, md, iD, k, cd


@jit
def _damped_slopes(P, n, nd, w, wm, wL, lr, lw, ll, k, cd):
    """The derivatives of the numerator ``N = k (x' - w') - n' m + c (x'' - w_L L')`` of a
    damped contact's ``m' = N/(n + c w_m)`` by ``(y, x', m, L)``, and of its denominator
    by ``(m, L)``.
    """
    ba = P[P_RB] / P[P_RA]
    lm = lw * wm
    lL = lw * wL + ll
    Ny = -cd * P[P_ALPHA]
    Nv = k - cd * P[P_GAMMA]
    Nm = -k * wm - nd + cd * (-n + ba * (wm * lr + w * lm))
    NL = -k * wL + cd * ba * (wL * lr + w * lL)
    Dm = cd * w / (P[P_RA] * P[P_RA])
    DL = -cd * ba * wm
    return Ny, Nv, Nm, NL, Dm, DL


@jit
def _evaluate_damped(P, tau, z, dz, J, ft, jac):
    """:func:`_evaluate` of a contact with its dashpot ``c = eta_c k`` in parallel with the
    spring: ``f = k e + c (x' - w') = n m``.

    The variable stays ``m = f/n`` (``w' = w'(m, L)`` explicit); differentiating
    ``n m = k e + c (x' - w')``: ``m' = (k (x' - w') - n' m + c (x'' - w_L L'))/(n + c w_m)``,
    no ``1/n`` (``e = (n m - c (x' - w'))/k`` is not needed as a variable).
    """
    n, nd, w, wm, wL, lr, lw, ll, xdd, md, iD, k, cd = _damped_terms(P, tau, z)
    gamma, V = P[P_GAMMA], P[P_V]
    v, m = z[Z_V], z[Z_M]
    f = n * m
    if not _contact_rates(dz, v - V, xdd, md, lr, f, w, gamma, J, ft, jac):
        return
    Ny, Nv, Nm, NL, Dm, DL = _damped_slopes(P, n, nd, w, wm, wL, lr, lw, ll, k, cd)
    J[Z_Y, Z_V] = 1.0
    J[Z_V, Z_Y] = -P[P_ALPHA]
    J[Z_V, Z_V] = -gamma
    J[Z_V, Z_M] = -n
    J[Z_M, Z_Y] = Ny * iD
    J[Z_M, Z_V] = Nv * iD
    J[Z_M, Z_M] = (Nm - md * Dm) * iD
    J[Z_M, Z_L] = (NL - md * DL) * iD
    J[Z_L, Z_M] = lw * wm
    J[Z_L, Z_L] = lw * wL + ll
    J[Z_F, Z_M] = n
    J[Z_D, Z_M] = n * w + f * wm
    J[Z_D, Z_L] = f * wL
    J[Z_G, Z_V] = 2.0 * gamma * (v - V)
    Nt, ht, _ = _damped_time(P, tau, z, md, nd, w, cd)
    ft[Z_V] = -nd * m + ht
    ft[Z_M] = (Nt - md * nd) * iD
    ft[Z_L] = _coupling_rate(P, tau)
    ft[Z_F] = nd * m
    ft[Z_D] = nd * m * w


@jit
def _damped_time(P, tau, z, md, nd, w, cd):
    """``(N_t, h', l_t)``: the time derivatives of a damped contact's numerator at fixed
    ``z``, of the in-plane forcing and of the coupling's term of ``L'``.
    """
    A = P[P_A]
    ct, st = math.cos(tau), math.sin(tau)
    ndd = -A * ct
    ht = P[P_HS] * ct - P[P_HC] * st
    lt = _coupling_rate(P, tau)
    m = z[Z_M]
    Nt = -ndd * m + cd * (-nd * m + ht + P[P_RB] / P[P_RA] * w * lt)
    return Nt, ht, lt


@jit
def _contact_rates(dz, yd, vd, md, lr, f, w, gamma, J, ft, jac):
    """The rates in contact into ``dz`` (``y' = yd``, ``x'' = vd``, ``m'``, ``L'`` and the
    quadratures); with ``jac`` ``J`` and ``ft`` zeroed for the caller to fill.  Returns
    ``jac``.
    """
    dz[Z_Y] = yd
    dz[Z_V] = vd
    dz[Z_M] = md
    dz[Z_L] = lr
    _quadrature_rates(dz, f, w, gamma * yd * yd)
    if jac:
        J[:, :] = 0.0
        ft[:] = 0.0
    return jac


@jit
def _quadrature_rates(dz, f, w, dissipation):
    """The quadratures' rates: ``f``, ``f w'`` and the pin dashpot's ``gamma y'^2``."""
    dz[Z_F] = f
    dz[Z_D] = f * w
    dz[Z_G] = dissipation


@jit
def _coupling_rate(P, tau):
    """The time derivative of the Linker-Dieterich term ``-(alpha_ld/b) n'/n`` of ``L'``."""
    if P[P_ALD] <= 0.0:
        return 0.0
    A = P[P_A]
    ct, st = math.cos(tau), math.sin(tau)
    n = 1.0 + A * ct
    nd = -A * st
    return -P[P_ALD] / P[P_RB] * (-A * ct / n - nd * nd / (n * n))


@jit
def _evaluate(P, tau, z, mode, dz, J, ft, jac):
    """The right-hand side into ``dz``; with ``jac`` the Jacobian ``J`` (rows of all
    components, columns of the first ``NM``) and the time derivative ``ft``.

    The contact's variable is the local coefficient ``m = f/n = k e/n`` (finite as
    ``n -> 0``, where ``e`` is not): ``m' = (k (x' - w') - m n')/n``.  The state's law
    is written out here rather than called (:func:`_state_rate`, the other modes'): the
    call made this, the finite contact's every stage, twice as long (29 against 55 ns,
    measured); tests/solver/test_rate_state.py checks that the two agree.
    """
    alpha, gamma, V = P[P_ALPHA], P[P_GAMMA], P[P_V]
    A = P[P_A]
    ct, st = math.cos(tau), math.sin(tau)
    n = 1.0 + A * ct
    nd = -A * st
    h = P[P_HC] * ct + P[P_HS] * st
    y, v, m, L = z[Z_Y], z[Z_V], z[Z_M], z[Z_L]
    dc = P[P_DC]
    k = P[P_K]
    slip_law = P[P_SLIPLAW] != 0.0
    if mode == RIGID:
        _evaluate_rigid(P, tau, z, dz, J, ft, jac)
        return
    if mode == DAMPED:
        _evaluate_damped(P, tau, z, dz, J, ft, jac)
        return
    eta = P[P_ETA]
    f = 0.0
    w = 0.0
    dwdm = dwdL = dLdw = dLdL = 0.0
    if mode == FLIGHT:  # with the dashpot z[Z_M] holds e: k e + c e' = 0
        dz[Z_M] = -m / eta if eta > 0.0 else 0.0
        dz[Z_L] = 0.0 if slip_law else _exp(-L)
    else:
        f = n * m
        w, dwdm, dwdL = _slip_rate(P, m, L)
        dz[Z_M] = (k * (v - w) - m * nd) / n
        g = abs(w) / dc
        if slip_law:
            lg = math.log(g) if g > 1e-300 else -690.0
            dz[Z_L] = -g * (lg + L)
            dLdw = -(lg + L + 1.0) / dc  # times sign(w)
            dLdL = -g
        else:
            dz[Z_L] = _exp(-L) - g
            dLdw = -1.0 / dc
            dLdL = -_exp(-L)
        if w < 0.0:
            dLdw = -dLdw
        if P[P_ALD] > 0.0:
            dz[Z_L] -= P[P_ALD] / P[P_RB] * nd / n
    dz[Z_Y] = v - V
    dz[Z_V] = -gamma * (v - V) - alpha * y - f + h
    dz[Z_F] = f
    dz[Z_D] = f * w
    dz[Z_G] = gamma * (v - V) * (v - V)
    if not jac:
        return
    J[:, :] = 0.0
    ft[:] = 0.0
    J[Z_Y, Z_V] = 1.0
    J[Z_V, Z_Y] = -alpha
    J[Z_V, Z_V] = -gamma
    J[Z_G, Z_V] = 2.0 * gamma * (v - V)
    ft[Z_V] = P[P_HS] * ct - P[P_HC] * st
    if mode == FLIGHT:
        J[Z_L, Z_L] = 0.0 if slip_law else -_exp(-L)
        if eta > 0.0:
            J[Z_M, Z_M] = -1.0 / eta
        return
    ndd = -A * ct
    J[Z_V, Z_M] = -n
    J[Z_M, Z_V] = k / n
    J[Z_M, Z_M] = -(k * dwdm + nd) / n
    J[Z_M, Z_L] = -k * dwdL / n
    J[Z_L, Z_M] = dLdw * dwdm
    J[Z_L, Z_L] = dLdL + dLdw * dwdL
    J[Z_F, Z_M] = n
    J[Z_D, Z_M] = n * w + f * dwdm
    J[Z_D, Z_L] = f * dwdL
    ft[Z_V] -= nd * m
    ft[Z_M] = -(dz[Z_M] * nd + m * ndd) / n
    ft[Z_F] = nd * m
    ft[Z_D] = nd * m * w
    if P[P_ALD] > 0.0:
        ft[Z_L] -= P[P_ALD] / P[P_RB] * (ndd / n - nd * nd / (n * n))


@jit
def _lu(M, piv):
    """LU factorisation of the ``NM x NM`` matrix ``M`` in place, partial pivoting."""
    for c in range(NM):
        p = c
        for i in range(c + 1, NM):
            if abs(M[i, c]) > abs(M[p, c]):
                p = i
        piv[c] = p
        if M[p, c] == 0.0:
            return False
        if p != c:
            for j in range(NM):
                M[c, j], M[p, j] = M[p, j], M[c, j]
        for i in range(c + 1, NM):
            M[i, c] /= M[c, c]
            for j in range(c + 1, NM):
                M[i, j] -= M[i, c] * M[c, j]
    return True


@jit
def _lu_solve(M, piv, r):
    """Solve ``M x = r`` in place with the factors of :func:`_lu`."""
    for c in range(NM):
        p = piv[c]
        if p != c:
            r[c], r[p] = r[p], r[c]
    for i in range(NM):
        for j in range(i):
            r[i] -= M[i, j] * r[j]
    for i in range(NM - 1, -1, -1):
        for j in range(i + 1, NM):
            r[i] -= M[i, j] * r[j]
        r[i] /= M[i, i]


@jit
def _stage(P, tau, zs, mode, dz, J, M, piv, rhs, hg, K, i):
    """Solve stage ``i``: ``K[i] = (I/(h gam) - J)^-1 rhs`` (the quadratures by the
    block-triangular structure: ``k_q = h gam (rhs_q + J_q k_main)``).
    """
    for j in range(NM):
        K[i, j] = rhs[j]
    _lu_solve(M, piv, K[i, :NM])
    for q in range(NM, NZ):
        s = rhs[q]
        for j in range(NM):
            s += J[q, j] * K[i, j]
        K[i, q] = hg * s


@jit
def _curvature(P, tau, z, mode, tw):
    """What the tangent's stages need at the step's start ``(tau, z)``: the coefficients
    ``tw[6]`` of the second derivatives of the right-hand side (:func:`_hessian`) and
    ``tw[5] = J_t T``, the time derivative of the Jacobian at fixed ``z`` applied to the
    tangent ``T = tw[0]`` (the augmented system's ``f_t``).

    Only ``m'`` and ``L'`` are nonlinear.  With ``w'(m, L) = 2 v_ref sinh(m/a) e^-Q``:
    ``w_mm = w'/a^2``, ``w_mL = -(b/a) w_m``, ``w_LL = (b/a)^2 w'``; ``m'`` has
    ``-(k/n) d2w``; ``L' = l(w', L)`` has ``l_ww dw dw + l_w d2w + l_wL (dw dL + dL dw)
    + l_LL dL dL`` (aging: ``l_w = -sgn/d_c``, ``l_LL = e^-L``; slip: ``l_w = -sgn (ln g
    + L + 1)/d_c``, ``l_ww = -1/(d_c |w'|)``, ``l_wL = -sgn/d_c``).  ``J`` depends on
    ``tau`` through ``n`` in the rows of ``x'``, ``m`` and ``F``.  A rigid contact:
    :func:`_curvature_rigid`.
    """
    T, JtT, cv = tw[0], tw[5], tw[6]
    cv[:] = 0.0
    JtT[:, :] = 0.0
    slip_law = P[P_SLIPLAW] != 0.0
    L = z[Z_L]
    if mode == FLIGHT:
        cv[CV_LLL] = 0.0 if slip_law else _exp(-L)
        return
    _law_curvature(P, z, cv)
    if mode == RIGID:
        _curvature_rigid(P, tau, z, T, JtT, cv)
        return
    if mode == DAMPED:
        _curvature_damped(P, tau, z, T, JtT, cv)
        return
    A, k = P[P_A], P[P_K]
    ct, st = math.cos(tau), math.sin(tau)
    n = 1.0 + A * ct
    nd = -A * st
    ndd = -A * ct
    wm, wL = cv[CV_WM], cv[CV_WL]
    cv[CV_KN] = -k / n
    n2 = n * n
    jmv = -k * nd / n2
    jmm = -ndd / n + (k * wm + nd) * nd / n2
    jml = k * wL * nd / n2
    for c in range(NM):
        JtT[Z_V, c] = -nd * T[Z_M, c]
        JtT[Z_M, c] = jmv * T[Z_V, c] + jmm * T[Z_M, c] + jml * T[Z_L, c]
        JtT[Z_F, c] = nd * T[Z_M, c]


@jit
def _law_curvature(P, z, cv):
    """The law's coefficients of the curvature in contact (finite or rigid): ``w'`` and its
    first derivatives, ``b/a``, ``1/a^2`` and the derivatives of ``L' = l(w', L)``.
    """
    a, dc, L = P[P_RA], P[P_DC], z[Z_L]
    w, wm, wL = _slip_rate(P, z[Z_M], L)
    sg = -1.0 if w < 0.0 else 1.0
    cv[CV_W], cv[CV_WM], cv[CV_WL] = w, wm, wL
    cv[CV_BA], cv[CV_IA2] = P[P_RB] / a, 1.0 / (a * a)
    if P[P_SLIPLAW] != 0.0:
        g = abs(w) / dc
        lg = math.log(g) if g > 1e-300 else -690.0
        cv[CV_LW] = -sg * (lg + L + 1.0) / dc
        cv[CV_LWW] = -1.0 / (dc * max(abs(w), 1e-30))
        cv[CV_LWL] = -sg / dc
    else:
        cv[CV_LW] = -sg / dc
        cv[CV_LLL] = _exp(-L)


@jit
def _curvature_rigid(P, tau, z, T, JtT, cv):
    """:func:`_curvature` of a rigid contact (:func:`_evaluate_rigid`): the coefficients of
    :func:`_hessian_rigid` and ``J_t T``.  ``J`` depends on ``tau`` only in the rows of ``m``
    (through ``n``, ``h`` and the coupling's term of ``L'``) and of ``F``:
    ``d/dtau (dm'/dz) p = (1/w_m) (R_t c[p] + dR_t[p])`` with ``R_t = -n' m + h' + (b/a) w'
    l_t``, ``dR_t[p] = -n' p_m + (b/a) l_t dw[p]`` (``l_t`` the coupling term's rate).
    """
    n, nd, w, wm, wL, iw, lr, _, ll, R, _ = _rigid_terms(P, tau, z)
    a = P[P_RA]
    m = z[Z_M]
    ba = cv[CV_BA]
    th = math.tanh(m / a)
    cv[CV_RIGID] = 1.0
    cv[CV_IW], cv[CV_R], cv[CV_TH], cv[CV_IA] = iw, R, th, 1.0 / a
    cv[CV_LR], cv[CV_LL] = lr, ll
    cv[CV_GAM], cv[CV_ALPHA], cv[CV_N] = P[P_GAMMA], P[P_ALPHA], n
    lt = _coupling_rate(P, tau)
    ct, st = math.cos(tau), math.sin(tau)
    Rt = -nd * m + P[P_HS] * ct - P[P_HC] * st + ba * w * lt
    for c in range(NM):
        pm, pL = T[Z_M, c], T[Z_L, c]
        cp = -th / a * pm + ba * pL
        JtT[Z_M, c] = iw * (Rt * cp - nd * pm + ba * lt * (wm * pm + wL * pL))
        JtT[Z_F, c] = nd * pm


@jit
def _curvature_damped(P, tau, z, T, JtT, cv):
    """:func:`_curvature` of a damped contact (:func:`_evaluate_damped`): the coefficients
    of :func:`_hessian_damped` and ``J_t T``.  With ``m' = N/D``, ``D = n + c w_m``: ``d/dtau
    (dm'/dz) p = (dN_t[p] - m'_t dD[p] - n' dm'[p])/D``, ``m'_t = (N_t - m' n')/D``,
    ``dN_t[p] = -n'' p_m + c (-n' p_m + (b/a) l_t dw[p])``; the rows of ``x'`` and ``F``
    through ``n``.
    """
    n, nd, w, wm, wL, lr, lw, ll, _, md, iD, k, cd = _damped_terms(P, tau, z)
    cv[CV_DAMPED] = 1.0
    cv[CV_IW], cv[CV_R], cv[CV_LR], cv[CV_LL] = iD, md, lr, ll
    cv[CV_GAM], cv[CV_ALPHA], cv[CV_N] = P[P_GAMMA], P[P_ALPHA], n
    cv[CV_K], cv[CV_C], cv[CV_ND] = k, cd, nd
    Ny, Nv, Nm, NL, Dm, DL = _damped_slopes(P, n, nd, w, wm, wL, lr, lw, ll, k, cd)
    Nt, _, lt = _damped_time(P, tau, z, md, nd, w, cd)
    mdt = (Nt - md * nd) * iD
    ndd = -P[P_A] * math.cos(tau)
    ba = cv[CV_BA]
    for c in range(NM):
        py, pv, pm, pL = T[Z_Y, c], T[Z_V, c], T[Z_M, c], T[Z_L, c]
        dD = Dm * pm + DL * pL
        dmd = (Ny * py + Nv * pv + Nm * pm + NL * pL - md * dD) * iD
        dNt = -ndd * pm + cd * (-nd * pm + ba * lt * (wm * pm + wL * pL))
        JtT[Z_V, c] = -nd * pm
        JtT[Z_M, c] = (dNt - mdt * dD - nd * dmd) * iD
        JtT[Z_F, c] = nd * pm


@jit
def _hessian_damped(cv, p, q, c):
    """:func:`_hessian` of a damped contact: ``L' = l(w', L)`` and ``m' = N/D``
    (:func:`_evaluate_damped`), ``d2m' = (d2N - dm'[p] dD[q] - dm'[q] dD[p] - m' d2D)/D``
    with ``d2N = -k d2w + c (b/a) (d2w L' + dw[p] dL'[q] + dw[q] dL'[p] + w' d2L')`` (``N``
    is linear in ``y`` and ``x'``) and ``d2D = c (w_m/a^2 p_m q_m - (b/a) w'/a^2 (p_m q_L +
    p_L q_m) + (b/a)^2 w_m p_L q_L)``.
    """
    py, pv, pm, pL = p[Z_Y], p[Z_V], p[Z_M], p[Z_L]
    qy, qv, qm, qL = q[Z_Y, c], q[Z_V, c], q[Z_M, c], q[Z_L, c]
    d2w, d2l = _law_hessian(cv, pm, pL, qm, qL)
    w, wm, wL, ba, ia2 = cv[CV_W], cv[CV_WM], cv[CV_WL], cv[CV_BA], cv[CV_IA2]
    lw, ll, lr = cv[CV_LW], cv[CV_LL], cv[CV_LR]
    k, cd, n, nd, md, iD = cv[CV_K], cv[CV_C], cv[CV_N], cv[CV_ND], cv[CV_R], cv[CV_IW]
    alpha, gamma = cv[CV_ALPHA], cv[CV_GAM]
    dwp = wm * pm + wL * pL
    dwq = wm * qm + wL * qL
    dlp = lw * dwp + ll * pL
    dlq = lw * dwq + ll * qL
    dNp = k * (pv - dwp) - nd * pm + cd * (-alpha * py - gamma * pv - n * pm
                                           + ba * (dwp * lr + w * dlp))
    dNq = k * (qv - dwq) - nd * qm + cd * (-alpha * qy - gamma * qv - n * qm
                                           + ba * (dwq * lr + w * dlq))
    dDp = cd * (w * ia2 * pm - ba * wm * pL)
    dDq = cd * (w * ia2 * qm - ba * wm * qL)
    dmp = (dNp - md * dDp) * iD
    dmq = (dNq - md * dDq) * iD
    d2N = -k * d2w + cd * ba * (d2w * lr + dwp * dlq + dwq * dlp + w * d2l)
    d2D = cd * (wm * ia2 * pm * qm - ba * w * ia2 * (pm * qL + pL * qm) + ba * ba * wm * pL * qL)
    return 0.0, (d2N - dmp * dDq - dmq * dDp - md * d2D) * iD, d2l


@jit
def _hessian(cv, p, q, out):
    """Add the second derivatives of ``(y', m', L')`` along the direction ``p`` (a vector)
    and each column of ``q`` (:func:`_curvature`) to the rows ``Z_Y``, ``Z_M``, ``Z_L`` of
    ``out`` (``y'`` is linear but for a rigid contact, :func:`_hessian_rigid`; a damped
    contact's :func:`_hessian_damped`).
    """
    rigid, damped = cv[CV_RIGID] != 0.0, cv[CV_DAMPED] != 0.0
    kn = cv[CV_KN]
    pm, pL = p[Z_M], p[Z_L]
    for c in range(NM):
        if rigid:
            hy, hm, hl = _hessian_rigid(cv, p, q, c)
            out[Z_Y, c] += hy
        elif damped:
            _, hm, hl = _hessian_damped(cv, p, q, c)
        else:
            d2w, hl = _law_hessian(cv, pm, pL, q[Z_M, c], q[Z_L, c])
            hm = kn * d2w
        out[Z_M, c] += hm
        out[Z_L, c] += hl


@jit
def _law_hessian(cv, pm, pL, qm, qL):
    """``(d2w, d2l)``: the second derivatives of ``w'(m, L)`` and of ``L' = l(w', L)``
    along ``(pm, pL)`` and ``(qm, qL)``.
    """
    w, wm, ba = cv[CV_W], cv[CV_WM], cv[CV_BA]
    d2w = cv[CV_IA2] * w * pm * qm - ba * wm * (pm * qL + pL * qm) + ba * ba * w * pL * qL
    dwp = wm * pm + cv[CV_WL] * pL
    dwq = wm * qm + cv[CV_WL] * qL
    hl = (cv[CV_LWW] * dwp * dwq + cv[CV_LW] * d2w + cv[CV_LWL] * (dwp * qL + pL * dwq)
          + cv[CV_LLL] * pL * qL)
    return d2w, hl


@jit
def _hessian_rigid(cv, p, q, c):
    """:func:`_hessian` of a rigid contact: ``y' = w' - V``, ``L' = l(w', L)`` and
    ``m' = R/w_m`` (:func:`_evaluate_rigid`), whose second derivative is ``(1/w_m) (d2R +
    dR[p] c[q] + dR[q] c[p] + R (c[p] c[q] - (1 - tanh^2(m/a))/a^2 p_m q_m))`` with
    ``d(1/w_m) = (1/w_m) c``, ``c[p] = -(tanh(m/a)/a) p_m + (b/a) p_L``, ``R = -gamma (w' -
    V) - alpha y - n m + h + (b/a) w' L'``.
    """
    py, pm, pL = p[Z_Y], p[Z_M], p[Z_L]
    qy, qm, qL = q[Z_Y, c], q[Z_M, c], q[Z_L, c]
    d2w, d2l = _law_hessian(cv, pm, pL, qm, qL)
    w, wm, wL, ba = cv[CV_W], cv[CV_WM], cv[CV_WL], cv[CV_BA]
    lw, ll = cv[CV_LW], cv[CV_LL]
    gamma, alpha, n, th, ia = cv[CV_GAM], cv[CV_ALPHA], cv[CV_N], cv[CV_TH], cv[CV_IA]
    R, lr = cv[CV_R], cv[CV_LR]
    dwp = wm * pm + wL * pL
    dwq = wm * qm + wL * qL
    dlp = lw * dwp + ll * pL
    dlq = lw * dwq + ll * qL
    g = ba * lr - gamma
    drp = -alpha * py - n * pm + g * dwp + ba * w * dlp
    drq = -alpha * qy - n * qm + g * dwq + ba * w * dlq
    d2r = g * d2w + ba * (dwp * dlq + dwq * dlp) + ba * w * d2l
    cp = -th * ia * pm + ba * pL
    cq = -th * ia * qm + ba * qL
    hm = cv[CV_IW] * (d2r + drp * cq + drq * cp
                      + R * (cp * cq - (1.0 - th * th) * ia * ia * pm * qm))
    return d2w, hm, d2l


@jit
def _tangent_stage(i, J, Js, M, piv, K, hh, hg, tw):
    """Stage ``i`` of the variational equations ``T' = J T`` (rows ``Z_Y .. Z_F``): the
    RODAS4 stage of the augmented system ``(z, T)``, whose Jacobian is block-triangular,
    ``[[J, 0], [H(., T), J]]``: ``KT_c = (I/(h gam) - J)^-1 (rhs_c + H(K_i, T_c))`` with
    the same factors as the state's stage, the quadrature ``F`` by the triangular structure.
    ``Js`` is the Jacobian at the stage's point (``J`` itself at stage 0).  The columns are
    the innermost loops (four contiguous numbers: one vector operation each).
    """
    T, KT, Ts, rT, JtT, cv = tw[0], tw[2], tw[3], tw[4], tw[5], tw[6]
    ih = 1.0 / hh
    hd = hh * RD[i]
    for r in range(NT):
        for c in range(NM):
            Ts[r, c] = T[r, c]
        for l in range(i):
            a = RA[i, l]
            for c in range(NM):
                Ts[r, c] += a * KT[l, r, c]
    for r in range(NT):
        for c in range(NM):
            rT[r, c] = hd * JtT[r, c]
        for j in range(NM):
            a = Js[r, j]
            if a != 0.0:
                for c in range(NM):
                    rT[r, c] += a * Ts[j, c]
        for l in range(i):
            b = ih * RCC[i, l]
            for c in range(NM):
                rT[r, c] += b * KT[l, r, c]
    _hessian(cv, K[i], T, rT)
    # (I/(h gam) - J) KT = rT for the four columns at once, with the state's factors
    for c in range(NM):
        p = piv[c]
        if p != c:
            for q in range(NM):
                rT[c, q], rT[p, q] = rT[p, q], rT[c, q]
    for r in range(NM):
        for j in range(r):
            a = M[r, j]
            for q in range(NM):
                rT[r, q] -= a * rT[j, q]
    for r in range(NM - 1, -1, -1):
        for j in range(r + 1, NM):
            a = M[r, j]
            for q in range(NM):
                rT[r, q] -= a * rT[j, q]
        a = 1.0 / M[r, r]
        for q in range(NM):
            rT[r, q] *= a
    for c in range(NM):
        s = rT[Z_F, c]
        for j in range(NM):
            KT[i, j, c] = rT[j, c]
            s += J[Z_F, j] * rT[j, c]
        KT[i, Z_F, c] = hg * s


@jit
def _step(P, tau, z, hh, mode, rtol, scale, ws, K, J, M, piv, znew, tangent, tw):
    """One RODAS4 step of length ``hh`` from ``(tau, z)`` into ``znew``; returns the error
    norm (``inf`` where a stage is not finite or the matrix singular).  With ``tangent``
    the variational equations ride along (``tw[0]`` into ``tw[1]``, :func:`_tangent_stage`)
    and their error is part of the norm.
    """
    dz, ft, zs, rhs = ws[0], ws[1], ws[2], ws[3]
    Js, fts = tw[7], tw[8]
    _evaluate(P, tau, z, mode, dz, J, ft, True)
    hg = hh * GAM
    for i in range(NM):
        for j in range(NM):
            M[i, j] = -J[i, j]
        M[i, i] += 1.0 / hg
    if not _lu(M, piv):
        return math.inf
    if tangent:
        _curvature(P, tau, z, mode, tw)
    ih = 1.0 / hh
    # stage 1
    for j in range(NZ):
        rhs[j] = dz[j] + hh * D1 * ft[j]
    _stage(P, tau, zs, mode, dz, J, M, piv, rhs, hg, K, 0)
    if tangent:
        _tangent_stage(0, J, J, M, piv, K, hh, hg, tw)
    # stage 2
    for j in range(NZ):
        zs[j] = z[j] + A21 * K[0, j]
    _evaluate(P, tau + CC2 * hh, zs, mode, dz, Js, fts, tangent)
    for j in range(NZ):
        rhs[j] = dz[j] + hh * D2 * ft[j] + ih * C21 * K[0, j]
    _stage(P, tau, zs, mode, dz, J, M, piv, rhs, hg, K, 1)
    if tangent:
        _tangent_stage(1, J, Js, M, piv, K, hh, hg, tw)
    # stage 3
    for j in range(NZ):
        zs[j] = z[j] + A31 * K[0, j] + A32 * K[1, j]
    _evaluate(P, tau + CC3 * hh, zs, mode, dz, Js, fts, tangent)
    for j in range(NZ):
        rhs[j] = dz[j] + hh * D3 * ft[j] + ih * (C31 * K[0, j] + C32 * K[1, j])
    _stage(P, tau, zs, mode, dz, J, M, piv, rhs, hg, K, 2)
    if tangent:
        _tangent_stage(2, J, Js, M, piv, K, hh, hg, tw)
    # stage 4
    for j in range(NZ):
        zs[j] = z[j] + A41 * K[0, j] + A42 * K[1, j] + A43 * K[2, j]
    _evaluate(P, tau + CC4 * hh, zs, mode, dz, Js, fts, tangent)
    for j in range(NZ):
        rhs[j] = dz[j] + hh * D4 * ft[j] + ih * (C41 * K[0, j] + C42 * K[1, j] + C43 * K[2, j])
    _stage(P, tau, zs, mode, dz, J, M, piv, rhs, hg, K, 3)
    if tangent:
        _tangent_stage(3, J, Js, M, piv, K, hh, hg, tw)
    # stage 5
    for j in range(NZ):
        zs[j] = z[j] + A51 * K[0, j] + A52 * K[1, j] + A53 * K[2, j] + A54 * K[3, j]
    _evaluate(P, tau + hh, zs, mode, dz, Js, fts, tangent)
    for j in range(NZ):
        rhs[j] = dz[j] + ih * (C51 * K[0, j] + C52 * K[1, j] + C53 * K[2, j] + C54 * K[3, j])
    _stage(P, tau, zs, mode, dz, J, M, piv, rhs, hg, K, 4)
    if tangent:
        _tangent_stage(4, J, Js, M, piv, K, hh, hg, tw)
    # stage 6 (the embedded solution is zs + K[4], the solution zs + K[4] + K[5])
    for j in range(NZ):
        zs[j] += K[4, j]
    _evaluate(P, tau + hh, zs, mode, dz, Js, fts, tangent)
    for j in range(NZ):
        rhs[j] = dz[j] + ih * (C61 * K[0, j] + C62 * K[1, j] + C63 * K[2, j]
                               + C64 * K[3, j] + C65 * K[4, j])
    _stage(P, tau, zs, mode, dz, J, M, piv, rhs, hg, K, 5)
    if tangent:
        _tangent_stage(5, J, Js, M, piv, K, hh, hg, tw)
    err = 0.0
    for j in range(NZ):
        znew[j] = zs[j] + K[5, j]
        if not math.isfinite(znew[j]):
            return math.inf
        sc = rtol * (scale[j] + max(abs(z[j]), abs(znew[j])))
        err = max(err, abs(K[5, j]) / sc)
    if tangent:
        T, Tnew, KT, Ts = tw[0], tw[1], tw[2], tw[3]
        for r in range(NT):
            for c in range(NM):
                Tnew[r, c] = Ts[r, c] + KT[5, r, c]
                if not math.isfinite(Tnew[r, c]):
                    return math.inf
                # in the components' weighted units (:func:`_scales`): T[r, c] w_r/w_c
                wrc = scale[c] / scale[r]
                sc = rtol * (1.0 + wrc * max(abs(T[r, c]), abs(Tnew[r, c])))
                err = max(err, wrc * abs(KT[5, r, c]) / (TANGENT_RTOL * sc))
    return err



@jit
def _workspace():
    """Scratch arrays of the integrator: ``(ws, K, J, M, piv, znew, tw)``, ``tw`` those of
    the variational equations (:func:`_tangent_workspace`), which a segment without them
    passes along unused (allocated once, not per segment).
    """
    return (np.empty((4, NZ)), np.empty((6, NZ)), np.empty((NZ, NM)), np.empty((NM, NM)),
            np.empty(NM, np.int64), np.empty(NZ), _tangent_workspace())


@jit
def _tangent_workspace():
    """Scratch arrays of the variational equations: ``(T, T_new, KT, T_stage, rhs, J_t T,
    curvature, J_stage, f_t stage)``; ``T`` (rows ``Z_Y .. Z_F``, columns the section
    state) is the tangent carried along.
    """
    return (np.zeros((NT, NM)), np.empty((NT, NM)), np.empty((6, NT, NM)),
            np.empty((NT, NM)), np.empty((NT, NM)), np.zeros((NT, NM)), np.zeros(N_CV),
            np.empty((NZ, NM)), np.empty(NZ))


@jit
def _scales(P):
    """The absolute part of the error weights: 1 in the units of each component but
    ``L = ln theta``, whose error counts by its effect on the friction.

    The law sees ``L`` only as ``b L`` beside ``m`` (``w' ~ exp((m - b L)/a)``): an error
    ``dL`` acts as an error ``b dL`` of the local coefficient, so ``L``'s absolute
    tolerance is ``rtol/b`` (``b`` floored at ``L_WEIGHT_FLOOR a``: without ``b`` the state
    does not act back, and is still integrated to ``rtol/(L_WEIGHT_FLOOR a)``).
    """
    scale = np.ones(NZ)
    scale[Z_L] = 1.0 / _l_weight(P)
    return scale


@jit
def _l_weight(P):
    """The weight of ``L = ln theta`` beside ``m``: ``b``, at least ``L_WEIGHT_FLOOR a``."""
    return max(P[P_RB], L_WEIGHT_FLOOR * P[P_RA])


@jit
def _segment(P, z, t0, t1, mode, rtol, hbox, scale, work, count, log, lp):
    """Integrate ``z`` from ``t0`` to ``t1`` in ``mode``; ``hbox[0]`` carries the step size.

    ``count[0]`` counts the accepted steps, ``count[1]`` the rejected ones.  ``lp[1]``: 0
    adaptive, ``RECORD`` with the accepted steps appended to ``log`` (at ``lp[0]``;
    beyond its end nothing is recorded and ``lp[0]`` is set past it; the segment's last
    step is recorded negative).  Returns False where the step size fell below ``H_MIN`` or
    ``MAX_STEPS`` were taken.
    """
    return _advance(P, z, t0, t1, mode, rtol, hbox, scale, work, count, log, lp, False,
                    work[6])


@jit_bare
def _advance(P, z, t0, t1, mode, rtol, hbox, scale, work, count, log, lp, tangent, tw):
    """:func:`_segment`, with ``tangent`` the variational equations along (``tw[0]``).

    A finite contact's step while the load grows is at most :func:`_loading_step`.
    """
    ws, K, J, M, piv, znew = work[0], work[1], work[2], work[3], work[4], work[5]
    T, Tnew = tw[0], tw[1]
    t = t0
    steps = 0
    loading = mode == CONTACT or mode == DAMPED
    while t < t1:
        hh = min(hbox[0], H_MAX)
        if loading:
            hh = min(hh, _loading_step(P, t))
        last = t + hh >= t1 * (1.0 - 1e-15) or t + hh >= t1
        if last:
            hh = t1 - t
        if hh < H_MIN:
            return False
        err = _step(P, t, z, hh, mode, rtol, scale, ws, K, J, M, piv, znew, tangent, tw)
        if err <= 1.0:
            t = t1 if last else t + hh
            for i in range(z.shape[0]):  # (element by element: no reference counting here)
                z[i] = znew[i]
            if tangent:
                for i in range(T.shape[0]):
                    for j in range(T.shape[1]):
                        T[i, j] = Tnew[i, j]
            count[0] += 1
            steps += 1
            if steps > MAX_STEPS:
                return False
            if lp[1] == RECORD:
                if lp[0] < log.shape[0]:
                    log[lp[0]] = -hh if last else hh
                lp[0] += 1
            fac = min(6.0, max(0.2, SAFETY * (max(err, 1e-10)) ** -0.25))
            if not (last and fac > 1.0):  # a clipped last step says little about the next
                hbox[0] = hh * fac
        else:
            count[1] += 1
            fac = 0.2 if not math.isfinite(err) else max(0.2, SAFETY * err ** -0.25)
            hbox[0] = hh * fac
    return True


@jit
def _loading_step(P, t):
    """The longest step from ``t`` of a finite contact (with or without its dashpot) while the
    load grows: ``LOADING_GROWTH n/n'`` (no limit where ``n' <= 0``).

    ``m' = (k (x' - w') - m n')/n`` has the rate ``n'/n`` in ``m`` beside the law's ``k
    w_m/n``: it is ``1/(tau - tau_on)`` after a touch-down, a singular point of the equation
    at which only the solution on the slow manifold is finite, not a stiffness of a fast
    transient.  A Rosenbrock step freezes its Jacobian at the step's start: a step from the
    touch-down (``n = CUT_DELTA``) to where ``n`` is many times larger takes that rate at its
    start as the step's, puts ``m`` on the manifold ``k (x' - w') = m n'`` at the step's end
    (whereas the motion's ``m`` there lags it by about as much as it moved: stuck, ``m'`` is
    half the manifold's), and both of its solutions agree on that, so the error estimate
    does not see it (measured: a step from ``n = 1e-9`` to ``0.026`` accepted at ``rtol =
    1e-7`` left an error of 0.015 in ``m``).  With ``n`` growing at most ``1 +
    LOADING_GROWTH`` times a step the Jacobian holds over the step and the error estimate
    sees the error; the steps grow geometrically from the touch-down (measured on that
    point: 354 steps and 52 rejected a period, against 357 and 55 of an unlimited step that
    left the error).  A rigid contact's ``m' = R/w_m`` has no ``1/n``.
    """
    A = P[P_A]
    nd = -A * math.sin(t)
    if nd <= 0.0:
        return math.inf
    return LOADING_GROWTH * (1.0 + A * math.cos(t)) / nd


@jit
def _cuts(P):
    """``(end of contact, start of the next contact)`` within the period: the phases
    where ``n`` is ``CUT_DELTA`` before lift-off and after touch-down (``A >= 1``).
    """
    A = P[P_A]
    if A < 1.0:
        return TWO_PI, TWO_PI
    off, on = P[P_OFF], P[P_ON]
    sl = A * math.sin(off)  # |n'| at lift-off (0 at grazing, A = 1)
    if sl > 1e-6:
        d = CUT_DELTA / sl
    else:
        d = math.sqrt(2.0 * CUT_DELTA)  # n ~ (tau - pi)^2/2 at grazing
    return off - d, on + d


@jit
def rs_period(P, z, rtol, hbox, work, count):
    """The period map: ``z`` at ``tau = 0`` to ``tau = 2 pi`` in place, its quadratures
    ``F``, ``D``, ``G`` over the period (reset first).  ``count[2]`` counts lift-offs and
    touch-downs.  Returns False where the integration failed.
    """
    return _period(P, z, rtol, hbox, work, count, np.empty(1), np.zeros(2, np.int64))


@jit
def _period(P, z, rtol, hbox, work, count, log, lp):
    """:func:`rs_period`, its steps recorded where ``lp[1]`` says so (:func:`_segment`;
    ``lp[0]`` is reset to the start of ``log``).
    """
    return _period_tangent(P, z, rtol, hbox, work, count, log, lp, False, work[6])


@jit
def _period_tangent(P, z, rtol, hbox, work, count, log, lp, tangent, tw):
    """:func:`_period`; with ``tangent`` the variational equations from ``tw[0]`` along.

    The cuts are at fixed phases (``n = CUT_DELTA``), not at states, so the saltation
    matrix of each is the Jacobian of its reset: at lift-off ``m = 0`` (the row of ``m``
    zeroed); at touch-down ``m = m_td(x', L)``, the root of ``g = k (x' - w'(m, L)) - m n'``
    (:func:`_touchdown_mu`), whose derivatives are ``dm/dx' = k/(k w_m + n')`` and
    ``dm/dL = -k w_L/(k w_m + n')``.
    """
    scale = _scales(P)
    lp[0] = 0
    z[Z_F] = z[Z_D] = z[Z_G] = 0.0
    T = tw[0]
    c_off, c_on = _cuts(P)
    mode = _contact_mode(P)
    if c_off >= TWO_PI:
        ok = _advance(P, z, 0.0, TWO_PI, mode, rtol, hbox, scale, work, count, log, lp,
                      tangent, tw)
        _rigid_end(P, z, T, mode, tangent)
        return ok
    if not _advance(P, z, 0.0, c_off, mode, rtol, hbox, scale, work, count, log, lp,
                    tangent, tw):
        return False
    _liftoff(P, c_off, z, T, mode, tangent)
    count[2] += 2
    if not _advance(P, z, c_off, c_on, FLIGHT, rtol, hbox, scale, work, count, log, lp,
                    tangent, tw):
        return False
    _touchdown(P, c_on, z, T, mode, tangent)
    ok = _advance(P, z, c_on, TWO_PI, mode, rtol, hbox, scale, work, count, log, lp,
                  tangent, tw)
    _rigid_end(P, z, T, mode, tangent)
    return ok


@jit
def _touchdown(P, tau, z, T, mode, tangent):
    """The contact re-forms at ``tau``: ``m`` in place, with ``tangent`` its row of ``T``
    (the reset's Jacobian).

    Finite contact: unloaded (``e = n m/k = 0`` to round-off), on the slow manifold of ``m``
    (its layer lasts ``~ a n/(k x') ~ 1e-12``), :func:`_touchdown_mu`.  Rigid: the contact
    point moves with the body at once, ``m = mu(x', theta)`` (the reference's), whose
    derivatives are ``dm/dx' = 1/w_m`` and ``dm/dL = -w_L/w_m``.
    """
    if mode == RIGID:
        z[Z_M] = local_mu(P, z[Z_V], z[Z_L])
        if tangent:
            _, _, wL = _slip_rate(P, z[Z_M], z[Z_L])
            iw = _inverse_slope(P, z[Z_M], z[Z_L])
            for c in range(NM):
                T[Z_M, c] = iw * (T[Z_V, c] - wL * T[Z_L, c])
        return
    if mode == DAMPED:  # z[Z_M] held e through the flight
        k = P[P_K]
        cd = P[P_ETA] * k
        n = 1.0 + P[P_A] * math.cos(tau)
        e = z[Z_M]
        z[Z_M] = _damped_mu(P, n, z[Z_V], e, z[Z_L])
        if tangent:
            _, wm, wL = _slip_rate(P, z[Z_M], z[Z_L])
            iD = 1.0 / (n + cd * wm)
            for c in range(NM):
                T[Z_M, c] = (k * T[Z_M, c] + cd * T[Z_V, c] - cd * wL * T[Z_L, c]) * iD
        return
    z[Z_M] = _touchdown_mu(P, tau, z[Z_V], z[Z_L])
    if tangent:
        k = P[P_K]
        _, wm, wL = _slip_rate(P, z[Z_M], z[Z_L])
        den = k * wm - P[P_A] * math.sin(tau)
        for c in range(NM):
            T[Z_M, c] = k * (T[Z_V, c] - wL * T[Z_L, c]) / den


@jit
def _liftoff(P, tau, z, T, mode, tangent):
    """The contact ends at ``tau`` (where ``n = CUT_DELTA``): the spring unloads (``m = 0``;
    a rigid contact's ``x' = w'`` first, :func:`_rigid_end`), or, with the dashpot, ``z[Z_M]``
    holds the elongation ``e = (n m - c (x' - w'))/k`` through the flight (``f = k e + c e'
    = 0``); with ``tangent`` the row of ``T`` (the reset's Jacobian).
    """
    _rigid_end(P, z, T, mode, tangent)
    if mode != DAMPED:
        z[Z_M] = 0.0
        T[Z_M, :] = 0.0
        return
    k = P[P_K]
    cd = P[P_ETA] * k
    n = 1.0 + P[P_A] * math.cos(tau)
    w, wm, wL = _slip_rate(P, z[Z_M], z[Z_L])
    z[Z_M] = (n * z[Z_M] - cd * (z[Z_V] - w)) / k
    if tangent:
        for c in range(NM):
            T[Z_M, c] = ((n + cd * wm) * T[Z_M, c] - cd * T[Z_V, c] + cd * wL * T[Z_L, c]) / k


@jit
def _damped_mu(P, n, v, e, L):
    """The local coefficient ``m`` of a damped contact with the elongation ``e`` and the
    body's velocity ``x' = v`` under the load ``n``: the root of ``g(m) = n m + c w'(m, L) -
    (k e + c x')``, increasing in ``m``, between 0 and the smaller in modulus of ``(k e + c
    x')/n`` and ``mu((k e + c x')/c)`` (:func:`_root_m`).
    """
    k = P[P_K]
    cd = P[P_ETA] * k
    F0 = k * e + cd * v
    if F0 == 0.0:
        return 0.0
    far = local_mu(P, F0 / cd, L)
    if n > 0.0 and abs(F0 / n) < abs(far):
        far = F0 / n
    return _root_m(P, L, -F0, n, cd, far)


@jit
def _root_m(P, L, s0, s1, s2, far):
    """The root ``m`` of the monotone ``g(m) = s0 + s1 m + s2 w'(m, L)`` between 0 and
    ``far`` (``g`` changes sign there): Newton's method kept in the bracket (bisection
    where a step leaves it).
    """
    lo, hi = (0.0, far) if far > 0.0 else (far, 0.0)
    up = s0 < 0.0  # g(0) = s0: g increases through the root where g(0) < 0 and far > 0
    if far < 0.0:
        up = not up
    m = 0.5 * (lo + hi)
    for _ in range(200):
        w, dwdm, _ = _slip_rate(P, m, L)
        g = s0 + s1 * m + s2 * w
        if g == 0.0:
            return m
        if (g < 0.0) == up:
            lo = m
        else:
            hi = m
        dg = s1 + s2 * dwdm
        mn = m - g / dg if dg != 0.0 else 0.5 * (lo + hi)
        if not (lo <= mn <= hi):  # (a converged step lands on the end just moved)
            mn = 0.5 * (lo + hi)
        if abs(mn - m) <= 1e-15 * (1.0 + abs(m)) or hi - lo <= 1e-15 * (1.0 + abs(m)):
            return mn
        m = mn
    return m


@jit
def _rigid_end(P, z, T, mode, tangent):
    """At the end of a rigid contact's segment the body's velocity ``x' = w'(m, L)`` into
    ``z`` (the segment leaves it untouched), with ``tangent`` its row of ``T``.  Nothing for
    a finite contact.
    """
    if mode != RIGID:
        return
    w, wm, wL = _slip_rate(P, z[Z_M], z[Z_L])
    z[Z_V] = w
    if tangent:
        for c in range(NM):
            T[Z_V, c] = wm * T[Z_M, c] + wL * T[Z_L, c]


@jit
def _elongation(P, z, f, w):
    """The contact spring's elongation ``e = (f - c (x' - w'))/k`` in contact (0 rigid)."""
    return (f - P[P_ETA] * P[P_K] * (z[Z_V] - w)) / P[P_K] if P[P_ETA] > 0.0 else f / P[P_K]


@jit
def contact_state(P, z):
    """``(f, w')`` at ``tau = 0`` (in contact: ``n = 1 + A``)."""
    w, _, _ = _slip_rate(P, z[Z_M], z[Z_L])
    return (1.0 + P[P_A]) * z[Z_M], w


@jit
def sliding_start(P, offset):
    """Steady sliding at ``V`` before the oscillation: ``theta = d_c/V``, ``f = mu_ss(V)``,
    ``e = f/k``, ``x' = V``, ``y = -f/alpha`` (laboratory frame, then the kernels').

    The oscillation starts at ``tau = 0``, where ``n = 1 + A``: the spring's force ``f`` is
    continuous there, so the local coefficient starts at ``m = f/n = mu_ss/(1 + A)``.
    """
    V = P[P_V]
    f = steady_mu(V, P[P_RA], P[P_RB], P[P_DC], P[P_VREF])
    z = np.zeros(NZ)
    z[Z_Y] = -f / P[P_ALPHA] - offset[0]
    z[Z_V] = V - offset[1]
    mode = _contact_mode(P)
    if mode == RIGID:  # the body's velocity continuous: m = mu(x', theta)
        z[Z_M] = local_mu(P, z[Z_V], math.log(P[P_DC] / V))
    elif mode == DAMPED:  # the elongation e = f/k and x' continuous: the force jumps
        z[Z_M] = _damped_mu(P, 1.0 + P[P_A], z[Z_V], f / P[P_K], math.log(P[P_DC] / V))
    else:
        z[Z_M] = f / (1.0 + P[P_A])  # the spring's force continuous: n(0) = 1 + A
    z[Z_L] = math.log(P[P_DC] / V)
    return z


@jit
def _kick(P, z):
    """The velocity kicked by ``KICK`` off a repelling orbit (a rigid contact's through
    ``m``, its velocity being slaved to it).
    """
    z[Z_V] += KICK * (abs(z[Z_V]) + P[P_V])
    if _contact_mode(P) == RIGID:
        z[Z_M] = local_mu(P, z[Z_V], z[Z_L])


@jit
def _weights(P, z):
    """Weights of the section distance (forces and velocities, as the event solver's) and
    its relative scale.
    """
    wv = np.empty(NM)
    wv[Z_Y] = P[P_ALPHA]
    wv[Z_V] = 1.0
    wv[Z_M] = 1.0 + P[P_A]  # the force at tau = 0
    wv[Z_L] = _l_weight(P)  # by its effect on the friction, as in the step control
    s = 1.0 + P[P_ALPHA] * abs(z[Z_Y]) + abs(z[Z_V]) + wv[Z_M] * abs(z[Z_M])
    return wv, s


@jit
def _distance(wv, z1, z2):
    d = 0.0
    for j in range(NM):
        d += wv[j] * abs(z1[j] - z2[j])
    return d


@jit
def _map_mean(P, z, rtol, hbox, work, count, tw, log, lp):
    """``(ok, mu)``: the period map from ``z`` in place (:func:`_period`) and the period's
    mean ``F/N``.
    """
    ok = _period_tangent(P, z, rtol, hbox, work, count, log, lp, False, tw)
    return ok, z[Z_F] / (TWO_PI * P[P_NBAR])


@jit
def _tangent_map(P, z, rtol, hbox, work, count, tw, log, lp, D, gmu):
    """:func:`_map_mean` with the variational equations along: ``D`` receives the period
    map's Jacobian (the monodromy matrix on the section) and ``gmu`` the gradient of the
    period's mean, both from the same integration.
    """
    T = tw[0]
    T[:, :] = 0.0
    for c in range(NM):
        T[c, c] = 1.0
    ok = _period_tangent(P, z, rtol, hbox, work, count, log, lp, True, tw)
    nbar = TWO_PI * P[P_NBAR]
    for c in range(NM):
        for r in range(NM):
            D[r, c] = T[r, c]
        gmu[c] = T[Z_F, c] / nbar
    return ok, z[Z_F] / nbar


@jit
def _newton_step(D, z0, z1, dz):
    """The Newton step ``dz = -(D - I)^-1 (z1 - z0)``; False where singular."""
    Mx = np.empty((NM, NM))
    rhs = np.empty(NM)
    for r in range(NM):
        for c in range(NM):
            Mx[r, c] = D[r, c]
        Mx[r, r] -= 1.0
        rhs[r] = -(z1[r] - z0[r])
    x, ok = _solve_small(Mx, rhs, NM)
    dz[:] = x
    return ok


@jit
def _newton(P, z, rtol, hbox, work, count, tw, log, lp, D, gmu, res):
    """Newton's method on the period map from ``z``; on success ``z`` is the orbit's state.

    Every iterate's map carries the variational equations (:func:`_tangent_map`), so
    ``D`` and ``gmu`` are the exact Jacobian of the period map and the mean's gradient at
    the last iterate (to the integration's tolerance), not a secant's.  ``res`` receives
    ``(mu, shift, multiplier, maps, refined, mu_refined, error)``: the orbit's mean, the
    change of the mean the next Newton step would make (``|gmu . dz|``), the spectral
    radius of ``D``, the period maps integrated, and whether the orbit is already refined
    (:func:`_refine`; then its mean and error).  Returns True where the residual fell to
    the integration's level (``10 rtol`` relative, weighted as the section distance), or
    where the refinement confirmed it.

    The first map at ``rtol`` close to an attracting orbit (its residual below
    ``SHORTCUT`` relative, its multiplier below ``1 - NEAR_NEUTRAL``) is not repeated to
    confirm the convergence: its Newton step is taken and the refinement's map, from the
    new iterate, is that confirmation (Newton's quadratic convergence leaves a residual of
    about the square of the step; the refinement checks it).  Near a neutral multiplier the
    convergence is confirmed at ``rtol`` first, so that the multiplier is the orbit's.
    """
    if res.shape[0] < N_RES:
        raise ValueError("_newton: res needs N_RES entries")
    z0 = z.copy()
    z1 = z.copy()
    dz = np.empty(NM)
    maps = 0
    tol = 10.0 * rtol
    res[3] = 0.0
    res[4] = 0.0
    d_first = math.inf
    rt = max(rtol, LOOSE_RTOL)
    for it in range(NEWTON_ITERATIONS):
        z1[:] = z0
        ok, mu = _tangent_map(P, z1, rt, hbox, work, count, tw, log, lp, D, gmu)
        maps += 1
        if not ok:
            break
        wv, s = _weights(P, z0)
        d = _distance(wv, z0, z1)
        if it == 0:
            d_first = d
        if not math.isfinite(d) or (it > 0 and d > 100.0 * s) or \
                (it >= 6 and d > NEWTON_PROGRESS * d_first):
            break  # diverged, or not converging: left to the motion
        if not _newton_step(D, z0, z1, dz):
            break  # singular: no orbit found here
        shift = 0.0
        for r in range(NM):
            shift += gmu[r] * dz[r]
        if rt == rtol and d <= tol * s:
            res[0], res[1] = mu, abs(shift)
            res[2] = dense_spectral_radius(D)
            res[3] = maps
            z[:] = z0
            return True
        if rt == rtol and d <= SHORTCUT * s:
            radius = dense_spectral_radius(D)
            if radius < 1.0 - NEAR_NEUTRAL:
                for r in range(NM):
                    z0[r] += dz[r]
                maps += 1
                if _refine(P, z0, mu + shift, rtol, hbox, work, count, tw, log, lp, D, gmu,
                           res):
                    res[2] = radius
                    res[3] = maps
                    res[4] = 1.0
                    z[:] = z0
                    return True
                continue  # not converged yet: on from the refined map's start, at rtol
        # a step longer than half the state's scale is cut
        step = 0.0
        for r in range(NM):
            step += wv[r] * abs(dz[r])
        cut = min(1.0, 0.5 * s / step) if step > 0.0 else 1.0
        for r in range(NM):
            z0[r] += cut * dz[r]
        # inexact Newton: the next map's tolerance well below the residual it should show
        # (about the square of this one), the last ones' at rtol
        rt = max(rtol, min(LOOSE_RTOL, FORCING * (d / s) ** 2))
    res[3] = maps
    return False


@jit
def _refine(P, z, mu_coarse, rtol, hbox, work, count, tw, log, lp, D, gmu, res):
    """The orbit through (close to) ``z`` at ``rtol/REFINE``: one map and one chord step.

    ``mu_coarse`` is the mean at ``rtol`` carried to ``z`` (the map's mean plus the
    gradient times the step to ``z``).  Where the refined map's residual is within
    ``1e3 rtol`` (the integration's difference between the tolerances, which the chord
    step removes), ``res[5]`` receives the refined mean (the chord step's change
    included) and ``res[6]`` its error: twice the change of the mean between the two
    tolerances plus the chord step's change of the mean (the integration error propagated
    and the Newton residual), and ``z`` the state after the chord step.  Returns whether
    it was within.
    """
    zf = z.copy()
    ok, muf = _map_mean(P, zf, rtol / REFINE, hbox, work, count, tw, log, lp)
    if not ok:
        return False
    wv, s = _weights(P, z)
    dzf = np.empty(NM)
    if not (_newton_step(D, z, zf, dzf) and _distance(wv, z, zf) <= 1e3 * rtol * s):
        return False
    shift = 0.0
    for r in range(NM):
        shift += gmu[r] * dzf[r]
    mu = muf + shift
    res[5] = mu
    res[6] = max(ERROR_SAFETY * (abs(mu - mu_coarse) + abs(shift)),
                 ROUNDOFF_MU * (1.0 + abs(mu)))
    for r in range(NM):
        z[r] += dzf[r]
    return True


@jit
def _averaged_error(P, z, hbox, mu, rtol, work, count, tw, log, lp):
    """The integration's error of an averaged answer: ``ERROR_SAFETY`` times the change of
    the mean ``mu`` of the period from ``z`` (integrated at ``rtol`` from the step size
    ``hbox``) at ``rtol/REFINE`` (``inf`` where that integration fails).  ``z`` and
    ``hbox`` are used up.

    The periodic answer's error measures the same change of its orbit's mean
    (:func:`_refine`); the windows' disagreement does not contain it (every period of the
    windows carries the same integration error).
    """
    ok, muf = _map_mean(P, z, rtol / REFINE, hbox, work, count, tw, log, lp)
    if not ok:
        return math.inf
    return ERROR_SAFETY * abs(mu - muf)


@jit
def rs_steady_state(P, z, rtol, max_periods, tol_mean, offset, out_f, out_i):
    """The steady state from the section state ``z`` (kernels' frame); see the module doc.

    Writes the output rows (``solver.FLOAT_COLUMNS``, ``INT_COLUMNS``); ``z`` ends as the
    last section state.
    """
    out_f[:] = math.nan
    out_i[:] = 0
    work = _workspace()
    count = np.zeros(3, np.int64)
    hbox = np.array([1e-3])
    res = np.zeros(N_RES)
    tw = work[6]
    log = np.empty(1)  # no step log
    lp = np.zeros(2, np.int64)
    D = np.empty((NM, NM))
    gmu = np.empty(NM)
    periods = 0.0  # maps integrated, Newton's included
    nbar = TWO_PI * P[P_NBAR]
    status = ST_NOT_CONVERGED
    k = 0
    chk_k = FIRST_CHECK
    acc = 0.0
    accs = np.zeros(64)
    kchk = np.zeros(64)
    nchk = 0
    next_newton = SETTLE
    z_last = z.copy()
    h_last = np.array([hbox[0]])
    period = 0
    settle = math.nan
    failed = False
    while True:
        if k == next_newton:
            zn = z.copy()
            hn = np.array([hbox[0]])  # a failed map's step size is not the motion's
            found = _newton(P, zn, rtol, hn, work, count, tw, log, lp, D, gmu, res)
            periods += res[3]
            next_newton = 4 * k
            if found and res[2] < NEUTRAL:
                # the same orbit at rtol/REFINE (:func:`_refine`; Newton's method may have
                # done it already): the change of the mean is the integration's error (a
                # bound of the coarse value's, reported for the refined one)
                refined = res[4] == 1.0
                if not refined:
                    periods += 1.0
                    refined = _refine(P, zn, res[0], rtol, hn, work, count, tw, log, lp, D,
                                      gmu, res)
                    if refined:  # the last Newton step's change too (the coarse residual)
                        res[6] += ERROR_SAFETY * res[1]
                if refined:
                    z[:NM] = zn[:NM]
                    out_f[O_MU] = res[5]
                    out_f[O_ERR] = res[6]
                    out_f[O_MULT] = res[2]
                    status = ST_PERIODIC
                    period = 1
                    settle = float(k)
                    break
            elif found:
                # a repelling (or neutral) orbit: where the motion sits on it (an unstable
                # steady sliding without oscillation) a kick lets it leave; the averages
                # are taken once a kick of KICK has grown to the state's size
                wv, s = _weights(P, z)
                if _distance(wv, z, zn) <= 1e3 * rtol * s:
                    _kick(P, z)
                    grow = math.log(1.0 / KICK) / math.log(max(res[2], 1.0 + 1e-9))
                    while chk_k < k + 2.0 * grow and chk_k <= max_periods:
                        chk_k *= 2
                    nchk = 0
        if k >= max_periods:
            break
        # the settling periods only approach the orbit (Newton's method corrects): loose
        rt = max(rtol, LOOSE_RTOL) if k < SETTLE else rtol
        z_last[:] = z  # the period's start and step size (:func:`_averaged_error`)
        h_last[0] = hbox[0]
        ok, mu = _map_mean(P, z, rt, hbox, work, count, tw, log, lp)
        periods += 1.0
        if not ok:
            failed = True
            break
        k += 1
        acc += z[Z_F]
        if k == chk_k or k >= max_periods:
            accs[nchk] = acc
            kchk[nchk] = k
            nchk += 1
            chk_k *= 2
            if nchk >= 2:
                # the range of the last three windows' means (:func:`.average.window_means`)
                three = window_means(accs, nbar * kchk, kchk, nchk, out_f)
                converged = three and out_f[O_ERR] <= tol_mean
                out_f[O_ERR] = max(out_f[O_ERR], 10.0 * rtol)
                if converged:
                    status = ST_AVERAGED
                    settle = float(k)
                    periods += 1.0
                    out_f[O_ERR] += _averaged_error(P, z_last, h_last, mu, rtol, work, count,
                                                    tw, log, lp)
                    break
            if k >= max_periods:
                break
    if failed:
        status = ST_FAILED
    if status == ST_FAILED or status == ST_NOT_CONVERGED:
        out_f[O_MU] = math.nan
        out_f[O_ERR] = math.inf
    out_f[O_SETTLE] = settle
    out_f[O_WORK] = periods
    out_f[O_LAT] = 0.0
    out_f[O_DRIFT] = math.nan
    A = P[P_A]
    out_f[O_FLIGHT] = (P[P_ON] - P[P_OFF]) / TWO_PI if A > 1.0 else 0.0
    f, w = contact_state(P, z)
    out_f[O_Y], out_f[O_XD] = to_lab_frame(offset, z[Z_Y], z[Z_V])
    out_f[O_F] = f
    out_f[O_E] = _elongation(P, z, f, w)
    out_i[I_STATUS] = status
    out_i[I_PERIOD] = period
    out_i[I_PERIODS] = int(periods)
    out_i[I_EVENTS] = count[2]
    out_i[I_PHASE] = SLIP_NEG if w < 0.0 else SLIP_POS


@jit
def point_parameters(p):
    """The parameter vector of a row of the table of points."""
    return make_parameters(p[T_ALPHA], p[T_BETA], p[T_AMPLITUDE], p[T_V], p[T_ZETA],
                           p[T_A_X], p[T_PHASE_X], p[T_INPLANE_ON] == 0.0, p[T_RS_A],
                           p[T_RS_B], p[T_RS_DC], p[T_RS_VREF], p[T_RS_ALD], p[T_RS_LAW],
                           p[T_ETA_C])


@jit
def rs_steady_state_many(points, rtol, max_periods, tol_mean, out_f, out_i):
    """:func:`rs_steady_state` from steady sliding over a table of points (``V > 0``;
    one compiled loop); row ``i`` of ``out_f`` and ``out_i`` receives point ``i``.
    """
    for i in range(points.shape[0]):
        p = points[i]
        P = point_parameters(p)
        offset = frame_offset(p[T_A_X], p[T_PHASE_X], p[T_INPLANE_ON] == 0.0)
        z = sliding_start(P, offset)
        rs_steady_state(P, z, rtol, max_periods, tol_mean, offset, out_f[i], out_i[i])
        out_i[i, I_METHOD] = 0  # the caller writes the method's index
