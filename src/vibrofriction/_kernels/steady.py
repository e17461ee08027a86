r"""The steady state and the macroscopic coefficient of friction (paper eq. 25): the driver.

``mu_macro / mu0 = <f> / <n>`` over the steady state, with both integrals taken
from the closed forms, so a periodic orbit gives the ratio exactly.

The run advances one drive period at a time (:func:`.period.advance_period`).  At
each Poincare section ``tau = 2 pi k`` the state ``z_k = (y, x', e, phase)`` is
compared with ``z_{k-p}`` for ``p = 1..MAX_PERIOD`` (:func:`.average.detect_period`);
Newton's method on the period map is tried on a schedule (:mod:`.newton`);
continuous sliding is proven where its certificate applies (:mod:`.sliding`);
otherwise the running average is checked at doubling checkpoints
(:func:`.average.check_average`).  Every result states an estimate of
``|mu_ratio - exact|`` (docs/solver.md, "What error means"):

* periodic, found by Newton's method with the exact Jacobian: twice the first-order
  change of the window mean to the exact orbit, ``sum |G_j dz_j| / int n``
  (:func:`.average.newton_result`); a neutral orbit adds the distance of the
  motion's mean over 512 more periods;
* periodic, found by plain iteration: the p-period means of two successive windows
  differ by ``d_mu``; the window means converge to the orbit's mean like
  ``lambda^k`` (``lambda`` the leading Floquet multiplier), so the error of the last
  window is about ``d_mu / (1 - |lambda|)``; twice that is stated (other modes add to
  it), floored at round-off;
* averaged: the disagreement of the last two averaging windows;
* not converged, failed: no value (``nan``) and ``inf``; the last windows' means
  are reported as a range, never as the answer;
* continuous sliding: 0 (proven: eqs. 10-12 generalised to a contact that opens
  and to damping, docs/damping.md; from any start by an energy argument where the
  sliding orbit's contact point never stops, :func:`.sliding.orbit_slides`, and
  without oscillation, ``a = 0``, :func:`.sliding.unmodulated_sliding`).

Output rows follow ``solver.FLOAT_COLUMNS`` / ``solver.INT_COLUMNS`` (:mod:`.codes`).
"""

import math

import numpy as np

from .average import (
    _distance,
    check_average,
    detect_period,
    last_window,
    near_orbit,
    newton_result,
    periodic_result,
    section_scale,
)
from .codes import (
    I_DEGENERATE,
    I_EVENTS,
    I_PERIOD,
    I_PERIODS,
    I_PHASE,
    I_STATUS,
    LINK_GIVEN,
    LINK_PREVIOUS,
    NO_PHASE,
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
    O_WMAX,
    O_WMIN,
    O_WORK,
    O_XD,
    O_Y,
    SLIP_NEG,
    SLIP_POS,
    ST_AVERAGED,
    ST_FAILED,
    ST_NOT_CONVERGED,
    ST_PERIODIC,
    ST_SLIDING,
    STICK,
    T_A_X,
    T_ALPHA,
    T_AMPLITUDE,
    T_BETA,
    T_ETA_C,
    T_INPLANE_ON,
    T_PHASE_X,
    T_STATIC_RATIO,
    T_V,
    T_ZETA,
)
from .integrate import TWO_PI, contact_force, initial_state, to_kernel_frame, to_lab_frame
from .jit import jit
from .newton import NEUTRAL, _free_dimension, try_newton
from .period import (
    A_F,
    A_FLIGHT,
    A_N,
    A_SLIP,
    A_SLIP_NEG,
    A_STICK,
    C_DEGENERATE,
    C_EVENTS,
    MAX_PERIOD,
    N_ACC,
    advance_counted,
    advance_period,
    pure_forward_slip,
    spring,
)
from .phases import (
    ETA_ELASTIC,
    ETA_SLOPE,
    M_A,
    M_ALPHA,
    M_OFF,
    M_ON,
    M_V,
    forced,
    frame_offset,
    make_model,
)
from .sliding import orbit_slides, sliding_certificate, sliding_orbit, unmodulated_sliding

# re-exported: the kernels' entry points and what the tests drive directly
__all__ = ["N_ACC", "advance_period", "sliding_certificate", "sliding_orbit", "steady_state",
           "steady_state_many"]

FIRST_NEWTON = 1  # first attempt to solve the periodicity condition, in periods
MAX_CHECKPOINTS = 64  # doubling checkpoints of the running average
RUNNING = -2  # not a status: the run goes on
NEUTRAL_WINDOW = 512  # the motion near a neutral orbit is measured over periods (N, 2N]
SLIDING_SETTLE = 16  # periods in which a proven sliding looks for its last stick
# static above kinetic: an orbit found by Newton answers only once the motion's own section
# state comes within this distance of it (relative to the state's size, as tol_state):
# sliding and stick-slip coexist there, and Newton's iterate may converge to an attractor
# that the motion does not approach (seed 1130's campaign, benchmarks/results)
FOLLOW_DISTANCE = 1e-5
# ... or, for an orbit that sticks, once within LINEAR_DISTANCE each step of the motion over
# the orbit's period has been the one the orbit's linearisation predicts (the Jacobian of
# its map applied to the motion's offset from it) to LINEAR_MISS of the step, in
# LINEAR_PERIODS such steps running: the motion is then in the orbit's linear neighbourhood,
# on its way in (an orbit that attracts slowly would otherwise take thousands of periods
# to come within FOLLOW_DISTANCE; a motion bound elsewhere missed by 8 % and more, where a
# looser test failed).  The sliding orbit answers only by the certificate from the
# motion's own state (_run)
LINEAR_DISTANCE, LINEAR_MISS, LINEAR_PERIODS = 1e-2, 0.02, 3


@jit
def _start(init_kind, y0, xd0, e0, ph0, M, offset):
    """The section state ``(y, x', e, phase, e')`` at ``tau = 0`` in the kernels' frame (see
    :func:`steady_state`; an explicit state is given in the laboratory frame).
    """
    z = np.empty(5)  # y, x', e, phase, e' (exact rate where known, else nan)
    if init_kind == 2:
        y0, xd0 = to_kernel_frame(offset, y0, xd0)
        z[0], z[1], z[2], z[3], z[4] = y0, xd0, e0, ph0, math.nan
    else:
        z[0], z[1], z[2], z[3], z[4] = initial_state(init_kind, M, offset)
    return z


@jit
def _newton_from(z, dprev, k, M, tol_state, max_events, count, win, out_f, jac):
    """:func:`.newton.try_newton` from a copy of ``z``, its events counted and its drive
    periods added to ``out_f[O_WORK]``: ``(zn, p, lam, shift, mu_first, mu)``, ``zn`` the
    iterate, ``p = -1`` where the event budget is spent; ``jac`` the Jacobian of its map.
    """
    zn = z.copy()
    pn, ev, work, lam, shift, mu_first, mu = try_newton(zn, dprev, k, M, tol_state,
                                                        max_events - count[C_EVENTS], win,
                                                        jac)
    count[C_EVENTS] += ev
    out_f[O_WORK] += work
    if count[C_EVENTS] > max_events:
        pn = -1
    return zn, pn, lam, shift, mu_first, mu


@jit
def _newton_jump(z, dprev, k, M, tol_state, max_events, count, win, out_f, jac):
    """Newton on the period map (:func:`.newton.try_newton`) at period ``k``.

    On success the result of the orbit is written (:func:`.average.newton_result`),
    ``win`` holds its window and its period is returned; an attracting orbit's state
    replaces ``z``, a neutral one leaves ``z`` to the motion (:func:`_run` measures how
    far the motion's mean stays from it).  Returns 0 where no orbit was found, -1 where
    the event budget is spent.  The drive periods integrated are added to
    ``out_f[O_WORK]``; ``jac`` receives the Jacobian of the orbit's map.
    """
    zn, pn, lam, shift, mu_first, mu = _newton_from(z, dprev, k, M, tol_state, max_events,
                                                    count, win, out_f, jac)
    if pn > 0:
        # the first map from z is the motion's own next pn periods
        newton_result(mu, k + pn, lam, shift, mu_first, out_f)
        if lam < NEUTRAL:
            z[:] = zn
    return pn


@jit
def _newton_candidate(z, dprev, k, M, tol_state, max_events, count, cand_z, cand_win,
                      cand_out, cand_jac, out_f):
    """Newton on the period map at period ``k`` (:func:`.newton.try_newton`) without moving
    the motion: an attracting orbit found is kept as the candidate (its section state
    ``cand_z``, window ``cand_win``, result ``cand_out`` and the Jacobian of its map
    ``cand_jac``) that :func:`_run` returns once the motion itself comes to it
    (:func:`closing_in`).  Returns its period
    (0: none kept, -1: the event budget is spent); ``out_f`` keeps only the work added.
    """
    win = np.zeros(N_ACC)
    zn, pn, lam, shift, mu_first, mu = _newton_from(z, dprev, k, M, tol_state, max_events,
                                                    count, win, out_f, cand_jac)
    if pn < 0:
        return -1
    if pn == 0 or not lam < NEUTRAL:
        return 0
    cand_out[:] = out_f
    newton_result(mu, k + pn, lam, shift, mu_first, cand_out)
    cand_z[:] = zn
    cand_win[:] = win
    return pn


@jit
def _to_candidate(z, cand_z, M):
    """The motion's section state ``z``'s distance from the candidate orbit's ``cand_z``
    relative to its size (that of :func:`.average.detect_period`); inf in another phase.
    """
    if z[3] != cand_z[3]:
        return math.inf
    alpha, kk = M[M_ALPHA], spring(M)
    return _distance(alpha, kk, z, cand_z) / section_scale(alpha, kk, z)


@jit
def _linear_miss(z, zprev, cand_z, jac, M):
    """How far the motion's step over the orbit's period (``zprev`` to ``z``) misses the one the
    linearisation of the candidate orbit's map predicts (``jac`` applied to the offset from
    ``cand_z``), relative to the step; inf where a state is in another phase.
    """
    ph = int(cand_z[3])
    if int(z[3]) != ph or int(zprev[3]) != ph:
        return math.inf
    nd = _free_dimension(ph, M)
    kk = spring(M)
    miss, size = 0.0, 0.0
    for i in range(nd):
        pred = 0.0
        for j in range(nd):
            pred += jac[i, j] * (zprev[j] - cand_z[j])
        w = M[M_ALPHA] if i == 0 else (1.0 if i == 1 else kk)  # the section's weights
        miss += w * abs(z[i] - cand_z[i] - pred)
        size += w * abs(z[i] - zprev[i])
    return miss / size if size > 0.0 else math.inf


@jit
def closing_in(d, miss, run):
    """One period of a motion followed to an orbit: its relative distance ``d`` to it, the
    ``miss`` of its step from the one the orbit's linearisation predicts, relative to the
    step (inf where not known), and ``run`` the periods running within :data:`LINEAR_DISTANCE` with
    the miss within :data:`LINEAR_MISS`.  Returns ``(run, reached)``: reached within
    :data:`FOLLOW_DISTANCE`, or after :data:`LINEAR_PERIODS` such periods running.
    """
    run = run + 1 if d <= LINEAR_DISTANCE and miss <= LINEAR_MISS else 0
    return run, d <= FOLLOW_DISTANCE or run >= LINEAR_PERIODS


@jit
def _neutral_result(acc, start, orbit_out, orbit_win, win, out_f):
    """The answer of a neutral orbit found by Newton (its result ``orbit_out``, window
    ``orbit_win``): the motion from the start need not approach it, so its error includes
    the distance of the motion's mean over the last ``NEUTRAL_WINDOW`` periods
    (accumulators ``acc - start``) from the orbit's, and its settling time is unknown.
    """
    work = out_f[O_WORK]
    out_f[:] = orbit_out
    out_f[O_WORK] = work
    win[:] = orbit_win
    mean = (acc[A_F] - start[A_F]) / (acc[A_N] - start[A_N])
    out_f[O_ERR] = max(out_f[O_ERR], abs(mean - out_f[O_MU]))
    out_f[O_SETTLE] = math.nan


@jit
def _checkpoint(chk_c, chk_k, nchk, acc, k, final, near, tol_mean, win, out_f):
    """Record a checkpoint of the running average and test it (``near``: the motion is near
    a periodic orbit, :func:`.average.near_orbit`); returns ``(nchk, status)``, ``RUNNING``
    while no answer (the last checkpoint, ``final``, always answers).
    """
    if nchk < MAX_CHECKPOINTS:
        chk_c[nchk, :] = acc
        chk_k[nchk] = k
        nchk += 1
    if check_average(chk_k, chk_c, nchk, near, tol_mean, win, out_f):
        out_f[O_SETTLE] = k
        return nchk, ST_AVERAGED
    if final:
        # no answer: the window means (range in O_WMIN, O_WMAX) are not one
        if nchk < 2:
            win[:] = acc
            out_f[O_WMIN] = out_f[O_WMAX] = acc[A_F] / acc[A_N]
        out_f[O_MU] = math.nan
        out_f[O_ERR] = math.inf
        return nchk, ST_NOT_CONVERGED
    return nchk, RUNNING


@jit
def _run(z, M, max_periods, min_periods, tol_state, tol_mean, max_events, count, win, out_f,
         certify=False, ys=0.0, yds=0.0, es=0.0, neutral_ok=True, warm=False, follow=False):
    """Advance period by period from ``z`` until an orbit or an average answers.

    Called where the sliding orbit's contact point stops, or there is no sliding orbit
    (:func:`.sliding.orbit_slides`): the certificate of continuous sliding cannot hold
    from any state then (its bound only adds the free motion's amplitude to the
    orbit's own test), so it is not tried.  With a static coefficient above the kinetic
    one the sliding orbit ``(ys, yds, es)`` may slide and yet not attract every start
    (:func:`_static_run`): ``certify`` then tries its certificate at every section in
    forward slip, and a proof answers ``SLIDING``.  ``neutral_ok`` False: a neutral orbit
    found by Newton is no answer (there the motion near a neutral sliding orbit can go on
    sticking now and then, its mean not the orbit's); the motion is followed on.  ``warm``:
    ``z`` is (near) an orbit of one period, a neighbour's in a continuation, and Newton is
    tried from it at once (its first map is the motion's first period), not after a period.
    ``follow``: where attractors coexist (a static coefficient above the kinetic one), an
    orbit found by Newton is only a candidate, and answers once the motion's own section
    state comes within :data:`FOLLOW_DISTANCE` of it (:func:`_newton_candidate`); Newton's
    iterate can converge to an orbit that the motion from ``z`` does not approach.

    Newton's method is not tried at ``V = 0`` (a held body's orbits form a continuum).
    Returns ``(status, period, periods)``; ``z`` ends as the last section state,
    ``win`` holds the accumulators of the answering window, ``out_f[O_WORK]`` counts the
    drive periods integrated.
    """
    nring = MAX_PERIOD + 1
    ring_z = np.zeros((nring, 5))
    ring_c = np.zeros((nring, N_ACC))
    dprev = np.full(nring, np.inf)
    chk_c = np.zeros((MAX_CHECKPOINTS, N_ACC))
    chk_k = np.zeros(MAX_CHECKPOINTS)
    acc = np.zeros(N_ACC)
    neutral_win = np.zeros(N_ACC)  # the window of a neutral orbit found by Newton
    neutral_from = np.zeros(N_ACC)  # the accumulators where the motion's window starts
    neutral_out = np.zeros(out_f.shape[0])
    neutral_period, neutral_end = 0, 0
    cand_z = np.zeros(5)  # follow: the candidate orbit found by Newton, and its result
    cand_win = np.zeros(N_ACC)
    cand_out = np.zeros(out_f.shape[0])
    cand_jac = np.zeros((3, 3))
    cand_p = 0
    cand_d = math.inf  # the motion's distance to it at the last attempt
    cand_run = 0  # periods running on the orbit's linearisation (closing_in)
    cand_next = 0  # ... the next one, an orbit's period on
    ring_z[0, :] = z
    # V = 0: no Newton.  A held body has a continuum of stuck orbits (any preload in the
    # band); Newton's period map is singular along it and walks to the band's edge, an
    # orbit that attracts only from outside the band (docs/inplane.md, "v0 = 0")
    nchk, next_chk = 0, min_periods
    next_newton = FIRST_NEWTON if M[M_V] != 0.0 else -1
    k = 0
    if warm and next_newton > 0:
        # the start is a neighbour's orbit of one period: Newton's first map is the motion's
        # own first period, so it is tried at once; an orbit that is not found (or neutral)
        # leaves the schedule as it was
        pn = _newton_jump(z, dprev, 0, M, tol_state, max_events, count, win, out_f, cand_jac)
        if pn > 0 and out_f[O_MULT] < NEUTRAL:
            return ST_PERIODIC, pn, 0
        if pn < 0:
            return ST_FAILED, 0, 0
        out_f[O_MU] = out_f[O_ERR] = out_f[O_MULT] = out_f[O_SETTLE] = math.nan
    while True:
        ok, w = advance_counted(z, acc, count, M, max_events)
        out_f[O_WORK] += w
        if not ok:
            return ST_FAILED, 0, k
        k += 1
        if certify and int(z[3]) == SLIP_POS and sliding_certificate(
                z[0], z[1], z[2], SLIP_POS, M, True, ys, yds, es):
            out_f[O_MU], out_f[O_ERR], out_f[O_SETTLE] = 1.0, 0.0, k
            _sliding_window(M, win)
            return ST_SLIDING, 0, k
        ring_z[k % nring, :] = z
        ring_c[k % nring, :] = acc
        p, d, rho = detect_period(ring_z, dprev, k, M, tol_state)
        if p > 0:
            last_window(acc, ring_c, k, p, win)
            ev, w = periodic_result(z, win, p, k, rho, M, max_events, out_f)
            count[C_EVENTS] += ev
            out_f[O_WORK] += w
            return ST_PERIODIC, p, k
        reached = _to_candidate(z, cand_z, M) if cand_p > 0 else math.inf
        arrived = reached <= FOLLOW_DISTANCE
        if cand_p > 0 and k >= cand_p and (cand_run == 0 or k == cand_next):
            # the step over the orbit's period from the same point of it (an orbit of p
            # periods: every p-th period, once the motion is at the candidate's point)
            miss = _linear_miss(z, ring_z[(k - cand_p) % nring], cand_z, cand_jac, M)
            cand_run, arrived = closing_in(reached, miss, cand_run)
            cand_next = k + cand_p
        if arrived and not (certify and pure_forward_slip(cand_win)):
            # the motion has come to the candidate orbit: its answer (the sliding orbit's
            # only by the certificate from the motion's state, above); the settling time
            # from here at the orbit's contraction, the relative distance to the error
            work = out_f[O_WORK]
            out_f[:] = cand_out
            out_f[O_WORK] = work
            err, lam = out_f[O_ERR], out_f[O_MULT]
            out_f[O_SETTLE] = k + (math.log(err / reached) / math.log(lam)
                                   if reached > err and 0.0 < lam < 1.0 else 0.0)
            win[:] = cand_win
            z[:] = cand_z
            return ST_PERIODIC, cand_p, k
        if follow and k == next_newton and k < max_periods:
            next_newton = k + max(1, k // 2)
            # Newton again only where there is no candidate, or the motion has moved away
            # from it since the last attempt (it may be heading elsewhere)
            if cand_p == 0 or reached > cand_d:
                pn = _newton_candidate(z, dprev, k, M, tol_state, max_events, count, cand_z,
                                       cand_win, cand_out, cand_jac, out_f)
                if pn < 0:
                    return ST_FAILED, 0, k
                if pn > 0:
                    cand_p = pn
                    reached = _to_candidate(z, cand_z, M)
                    cand_run = 0
            cand_d = reached
        elif neutral_end > 0:
            # near a neutral orbit found by Newton the motion runs on: the running
            # average may still answer; otherwise the orbit does, with the motion's mean
            # over the last window
            if k == neutral_end - NEUTRAL_WINDOW:
                neutral_from[:] = acc
            if k == neutral_end:
                _neutral_result(acc, neutral_from, neutral_out, neutral_win, win, out_f)
                return ST_PERIODIC, neutral_period, k
        elif k == next_newton and k < max_periods:
            next_newton = k + max(1, k // 2)
            pn = _newton_jump(z, dprev, k, M, tol_state, max_events, count, win, out_f,
                              cand_jac)
            if pn > 0 and out_f[O_MULT] < NEUTRAL:
                return ST_PERIODIC, pn, k
            if pn > 0 and not neutral_ok:
                out_f[O_MU] = out_f[O_ERR] = out_f[O_MULT] = out_f[O_SETTLE] = math.nan
            elif pn > 0:
                neutral_out[:] = out_f
                neutral_win[:] = win
                neutral_period = pn
                neutral_end = max(2 * NEUTRAL_WINDOW, k + NEUTRAL_WINDOW)
                out_f[O_MU] = out_f[O_ERR] = out_f[O_MULT] = out_f[O_SETTLE] = math.nan
            if pn < 0:
                return ST_FAILED, 0, k
        if k == next_chk or k >= max_periods:
            next_chk *= 2
            nchk, status = _checkpoint(chk_c, chk_k, nchk, acc, k, k >= max_periods,
                                       near_orbit(dprev, z, M), tol_mean, win, out_f)
            if status != RUNNING:
                return status, 0, k


@jit
def _sliding_window(M, win):
    """The accumulators of one period of the sliding orbit: forward slip in contact,
    flight out of it (the fractions of a proven continuous sliding).
    """
    win[:] = 0.0
    flight = M[M_ON] - M[M_OFF] if M[M_A] > 1.0 else 0.0
    win[A_SLIP] = TWO_PI - flight
    win[A_FLIGHT] = flight


@jit
def _orbit_proof(z, M, ys, yds, es, max_events, count, win, out_f):
    """The sliding orbit's contact point never stops (:func:`.sliding.orbit_slides`):
    ``mu/mu0 = 1`` is proven from any start.  The motion is integrated only to say when
    its contact point stops for the last time: the first period (up to
    ``SLIDING_SETTLE`` periods) from which the certificate proves that it never stops
    again is the settling time and ``periods``; where none is found within them the
    settling time is unknown (nan) and the transient may still stick now and then
    (the final state is then the orbit's).  Returns ``(status, period, periods)``.
    """
    out_f[O_MU], out_f[O_ERR] = 1.0, 0.0
    _sliding_window(M, win)
    acc = np.zeros(N_ACC)
    for k in range(SLIDING_SETTLE + 1):
        if sliding_certificate(z[0], z[1], z[2], int(z[3]), M, True, ys, yds, es):
            out_f[O_SETTLE] = k
            return ST_SLIDING, 0, k
        if k == SLIDING_SETTLE:
            break
        ok, w = advance_counted(z, acc, count, M, max_events)
        out_f[O_WORK] += w
        if not ok:
            break
    out_f[O_SETTLE] = math.nan
    z[0], z[1], z[2], z[3], z[4] = ys, M[M_V] + yds, es, SLIP_POS, math.nan
    return ST_SLIDING, 0, 0


@jit
def _unmodulated(z, M, win, out_f):
    """``a = 0``: ``mu/mu0 = 1`` is proven from any start (:func:`.sliding.unmodulated_sliding`);
    the final state is steady sliding, reached at once from it (settling 0), else at
    an unknown time (nan).  Returns ``(status, period, periods)``.
    """
    energy, z[0], z[1], z[2] = unmodulated_sliding(z[0], z[1], z[2], M)
    z[3], z[4] = SLIP_POS, 0.0
    out_f[O_MU], out_f[O_ERR] = 1.0, 0.0
    out_f[O_SETTLE] = 0.0 if energy == 0.0 else math.nan
    win[:] = 0.0
    win[A_SLIP] = 1.0
    return ST_SLIDING, 0, 0


@jit
def _static_run(z, M, max_periods, min_periods, tol_state, tol_mean, max_events, count, win,
                out_f):
    """The steady state where the static coefficient is above the kinetic one (``s_r > 1``).

    Continuous sliding carries the kinetic force, so the sliding orbit and the condition
    that its contact point never stops are Coulomb's (docs/friction_laws.md); but the energy
    argument of :func:`.sliding.orbit_slides` ("from any start") fails: a stuck contact
    holds up to ``s_r n > n``, so a stick-slip motion can coexist with sliding. The proof is
    therefore only from the motion's own state (the certificate, tried at the start and at
    every section), otherwise the motion is followed as where no sliding orbit slides,
    except that an orbit found by Newton answers only once the motion itself comes to it
    (``follow`` of :func:`_run`: Newton's iterate may converge to the attractor the motion
    does not take, the sliding orbit where the motion goes on to stick-slip), and a neutral
    orbit is no answer: undamped, the motion near the neutral sliding orbit can stick every
    few periods for ever, its mean above the orbit's. Without
    oscillation (``a = 0``) the same: the proof of :func:`.sliding.unmodulated_sliding`
    fails alike.
    """
    orbit_ok, ys, yds, es = sliding_orbit(M)
    certify = orbit_slides(M, orbit_ok, ys, yds, es)
    if certify and int(z[3]) == SLIP_POS and sliding_certificate(
            z[0], z[1], z[2], SLIP_POS, M, True, ys, yds, es):
        out_f[O_MU], out_f[O_ERR], out_f[O_SETTLE] = 1.0, 0.0, 0.0
        _sliding_window(M, win)
        return ST_SLIDING, 0, 0
    status, period, k = _run(z, M, max_periods, min_periods, tol_state, tol_mean, max_events,
                             count, win, out_f, certify, ys, yds, es, False, follow=True)
    if status == ST_PERIODIC and certify and pure_forward_slip(win) and sliding_certificate(
            z[0], z[1], z[2], int(z[3]), M, True, ys, yds, es):
        # the orbit found is the sliding one, and the motion from its state slides for ever
        out_f[O_MU], out_f[O_ERR] = 1.0, 0.0
        _sliding_window(M, win)
        return ST_SLIDING, 0, k
    return status, period, k


@jit
def _fractions(win, status, out_f):
    total = win[A_STICK] + win[A_SLIP] + win[A_FLIGHT]
    if total <= 0.0 or status == ST_FAILED:
        total = math.nan
    out_f[O_STICK] = win[A_STICK] / total
    out_f[O_SLIP] = win[A_SLIP] / total
    out_f[O_SLIP_NEG] = win[A_SLIP_NEG] / total
    out_f[O_FLIGHT] = win[A_FLIGHT] / total


@jit
def _finish(status, period, k, z, count, win, M, beta, eta, offset, out_f, out_i):
    """The error's last terms, the fractions, the final state and the integer columns."""
    if status == ST_FAILED or status == ST_NOT_CONVERGED:
        out_f[O_MU] = math.nan  # no value: a window mean of an earlier checkpoint is none
        out_f[O_ERR] = math.inf
    elif not math.isfinite(out_f[O_ERR]):
        out_f[O_ERR] = math.inf  # no estimate: nothing is known about the value
    elif 0.0 < eta < ETA_ELASTIC and not math.isinf(beta):
        out_f[O_ERR] += ETA_SLOPE * eta  # solved as an elastic contact (phases.ETA_ELASTIC)
    _fractions(win, status, out_f)
    out_f[O_Y], out_f[O_XD] = to_lab_frame(offset, z[0], z[1])
    out_f[O_E] = z[2]
    out_f[O_F] = contact_force(M, int(z[3]), 0.0, z[0], z[1], z[2])
    out_i[I_STATUS] = status
    out_i[I_PERIOD] = period
    out_i[I_PERIODS] = k
    out_i[I_EVENTS] = count[C_EVENTS]
    out_i[I_PHASE] = int(z[3])
    out_i[I_DEGENERATE] = count[C_DEGENERATE]


@jit
def steady_state(alpha, beta, a, V, zeta, eta, a_x, phase_x, on_substrate, sr, init_kind, y0,
                 xd0, e0, ph0, max_periods, min_periods, tol_state, tol_mean, max_events,
                 out_f, out_i, warm=False):
    """Long-time average from a given start, written into the rows ``out_f``, ``out_i``.

    ``a_x``, ``phase_x``, ``on_substrate``: the longitudinal in-plane oscillation
    (:func:`.phases.inplane_forcing`; ``a_x = 0``: none); ``sr``: the static coefficient
    over the kinetic one (1: Coulomb friction; above 1: :func:`_static_run`). ``init_kind``:
    0 steady sliding, 1 rest, 2 explicit state ``(y0, x0', e0, ph0)`` at ``tau = 0``
    (laboratory frame, as the final state written). The columns are ``solver.FLOAT_COLUMNS``
    and ``solver.INT_COLUMNS``; the fractions are of time in the averaging window and the
    state is the final one on the section. A failed or not converged run has no value
    (``nan``) and no error estimate (``inf``).  ``warm``: the explicit start is a
    neighbour's orbit of one period (a continuation; :func:`_run`).
    """
    M = make_model(alpha, beta, a, V, zeta, eta, a_x, phase_x, on_substrate, sr)
    offset = frame_offset(a_x, phase_x, on_substrate)
    z = _start(init_kind, y0, xd0, e0, ph0, M, offset)
    static = sr > 1.0
    unmodulated = a == 0.0 and not forced(M) and not static
    count = np.zeros(3, np.int64)
    win = np.zeros(N_ACC)
    out_f[:] = math.nan
    out_f[O_WORK] = 0.0
    out_f[O_LAT] = 0.0  # no transverse oscillation here (the 2-D solver: plane.py)
    if unmodulated:
        status, period, k = _unmodulated(z, M, win, out_f)
    elif static:
        status, period, k = _static_run(z, M, max_periods, min_periods, tol_state, tol_mean,
                                        max_events, count, win, out_f)
    else:
        orbit_ok, ys, yds, es = sliding_orbit(M)
        if orbit_slides(M, orbit_ok, ys, yds, es):
            status, period, k = _orbit_proof(z, M, ys, yds, es, max_events, count, win, out_f)
        else:
            status, period, k = _run(z, M, max_periods, min_periods, tol_state, tol_mean,
                                     max_events, count, win, out_f, warm=warm)
    # eta_c below ETA_ELASTIC was solved as elastic; the a = 0 proof holds for any eta_c
    _finish(status, period, k, z, count, win, M, beta, 0.0 if unmodulated else eta, offset,
            out_f, out_i)


@jit
def _chained(out_f, out_i):
    """The start a row's final state gives the next point of a chain: ``(kind, y, x', e,
    phase)``, kind 2 (that state), -1 (none: not finite, or a phase without a section state,
    so the chain's own start) or -2 (a state whose ``e`` is not known: the caller derives it).
    """
    ph = out_i[I_PHASE]
    y, xd, f, e = out_f[O_Y], out_f[O_XD], out_f[O_F], out_f[O_E]
    if not (ph == STICK or ph == SLIP_POS or ph == SLIP_NEG) or not (
            math.isfinite(y) and math.isfinite(xd) and math.isfinite(f)):
        return -1, 0.0, 0.0, 0.0, 0
    if not math.isfinite(e):
        return -2, 0.0, 0.0, 0.0, 0
    return 2, y, xd, e, ph


@jit
def _one_period(row_i):
    """The row's result is an orbit of one period (its final state on it)."""
    return row_i[I_STATUS] == ST_PERIODIC and row_i[I_PERIOD] == 1


PREDICTOR_POINTS = 3
"""The most orbits before a point of a continuation its start is extrapolated from."""


@jit
def history(points, out_i, link, i, ph):
    """How many points before ``i`` (up to :data:`PREDICTOR_POINTS`) are orbits of one period
    with the section phase ``ph``, linked one to the next, on one velocity curve with
    ``i`` (the other parameters equal, ``V`` distinct).
    """
    m = 0
    while m < PREDICTOR_POINTS and i - m - 1 >= 0:
        j = i - m - 1
        if not (_one_period(out_i[j]) and out_i[j, I_PHASE] == ph):
            break
        for q in range(points.shape[1]):
            if q != T_V and points[j, q] != points[i, q]:
                return m
        for q in range(j + 1, i):
            if points[q, T_V] == points[j, T_V]:
                return m
        m += 1
        if link[j] != LINK_PREVIOUS:
            break
    return m


@jit
def lagrange_weight(points, i, m, a):
    """Lagrange's weight of point ``a`` at point ``i``'s ``V``, through the ``m`` points before
    ``i`` (the extrapolation of a continuation's start along ``V``).
    """
    v = points[i, T_V]
    w = 1.0
    for b in range(i - m, i):
        if b != a:
            w *= (v - points[b, T_V]) / (points[a, T_V] - points[b, T_V])
    return w


@jit
def _predicted(points, out_f, i, m):
    """The orbit's state at point ``i`` extrapolated along ``V`` through the orbits of the
    ``m`` points before it (the polynomial of degree ``m - 1``; a predictor that Newton
    corrects).
    """
    y = xd = e = 0.0
    for a in range(i - m, i):
        w = lagrange_weight(points, i, m, a)
        y += w * out_f[a, O_Y]
        xd += w * out_f[a, O_XD]
        e += w * out_f[a, O_E]
    return y, xd, e


@jit
def steady_state_many(points, init_kind, init, link, max_periods, min_periods, tol_state,
                      tol_mean, max_events, out_f, out_i):
    """:func:`steady_state` over a table of points (one compiled loop, no Python calls).

    ``points`` has shape ``(n, len(POINT_COLUMNS))`` (columns by the schema's indices,
    ``codes.T_*``); ``init`` has shape ``(n, 4)`` (used when ``init_kind == 2``); row
    ``i`` of ``out_f`` and ``out_i`` receives point ``i``; ``link[i]`` says where point
    ``i`` starts (:data:`LINK_OWN`, ...; all ``LINK_OWN``: independent points).

    A point linked to an orbit of one period (Coulomb friction) starts Newton's method from
    it at once; where the two points before it are both such orbits on one velocity curve,
    from the orbit extrapolated along ``V`` (:func:`_predicted`): the continuation's
    predictor, which Newton corrects.  A point at ``V = 0`` without an in-plane
    oscillation (the static limit, whose rows the caller fills) is skipped: its phase is
    ``NO_PHASE``, so a successor linked to it starts from its own start.  Returns the
    number of points solved: ``n``, or fewer where a final state lacks its elongation (the
    caller derives it and goes on).
    """
    for i in range(points.shape[0]):
        p = points[i]
        if p[T_V] == 0.0 and p[T_A_X] == 0.0:
            out_i[i, I_PHASE] = NO_PHASE
            continue
        kind, y0, xd0, e0, ph0 = init_kind, init[i, 0], init[i, 1], init[i, 2], int(init[i, 3])
        warm = False
        if link[i] == LINK_GIVEN:
            kind = 2
        elif link[i] == LINK_PREVIOUS and i > 0:
            k, y, xd, e, ph = _chained(out_f[i - 1], out_i[i - 1])
            if k == -2:
                return i
            if k == 2:
                kind, y0, xd0, e0, ph0 = k, y, xd, e, ph
                # Coulomb friction: Newton from a neighbour's orbit at once (a static
                # coefficient above the kinetic one starts from the state as it is: sliding
                # and stick-slip coexist there, and its proof of sliding is the motion's own)
                warm = p[T_STATIC_RATIO] == 1.0 and _one_period(out_i[i - 1])
                m = history(points, out_i, link, i, ph) if warm else 0
                if m > 1:
                    y0, xd0, e0 = _predicted(points, out_f, i, m)
        steady_state(p[T_ALPHA], p[T_BETA], p[T_AMPLITUDE], p[T_V], p[T_ZETA], p[T_ETA_C],
                     p[T_A_X], p[T_PHASE_X], p[T_INPLANE_ON] == 0.0, p[T_STATIC_RATIO],
                     kind, y0, xd0, e0, ph0, max_periods, min_periods,
                     tol_state, tol_mean, max_events, out_f[i], out_i[i], warm)
    return points.shape[0]
