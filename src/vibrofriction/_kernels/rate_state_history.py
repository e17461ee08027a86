r"""Time histories of the rate-and-state solver: its Rosenbrock integrator run to each sample.

The motion of :mod:`.rate_state` (state ``z = (y, x', m, ln theta, F, D, G)``, the kernels'
frame) integrated by the same RODAS4 steps with the same error control
(:func:`.rate_state._segment`), each step ending at the next sample time where it would pass
it: every sample is an integrated state (to the integrator's tolerance), not an
interpolation.  The quadratures ``F = int f``, ``D = int f w'`` and ``G = int gamma y'^2`` run
from the start (not reset at the sections).  Lift-off and touch-down are the integrator's
(:func:`.rate_state._cuts`): the contact ends where ``n = CUT_DELTA`` before lift-off, the
local coefficient is 0 in flight, and the contact re-forms on the slow manifold of ``m``
(:func:`.rate_state._touchdown`); a rigid contact's ``x'`` is slaved to ``m`` in contact
(:func:`.rate_state._evaluate_rigid`) and recorded as the slip rate; with contact damping
``z[Z_M]`` holds the elongation in flight (:func:`.rate_state._liftoff`).  This module adds to
:mod:`.rate_state` and changes none of it.
"""

import math

import numpy as np

from .codes import T_A_X, T_INPLANE_ON, T_PHASE_X
from .jit import jit
from .phases import frame_offset
from .rate_state import (
    CONTACT,
    FLIGHT,
    NZ,
    RIGID,
    Z_D,
    Z_F,
    Z_G,
    Z_L,
    Z_M,
    Z_V,
    _contact_mode,
    _cuts,
    _liftoff,
    _scales,
    _segment,
    _slip_rate,
    _touchdown,
    _workspace,
    point_parameters,
    rs_steady_state,
    sliding_start,
)

__all__ = ["N_R", "R_MODE", "R_TAU", "R_W", "R_Z", "rs_cuts", "rs_history", "rs_start"]

# the columns of a recorded row: tau, the state z (NZ columns from R_Z), w', the mode
R_TAU = 0
R_Z = 1
R_W = R_Z + NZ
R_MODE = R_W + 1
N_R = R_MODE + 1
#: a sample closer than this to a segment's end is that end's (no step that short)
NEAR = 1e-12


@jit
def rs_cuts(p):
    """``(end of contact, start of the next)`` within a period of the point row ``p``."""
    return _cuts(point_parameters(p))


@jit
def rs_start(p, steady, rtol, max_periods, tol_mean, out_f, out_i):
    """The state ``z`` at ``tau = 0`` (kernels' frame) of the point row ``p``, quadratures 0.

    Steady sliding at ``V`` before the oscillation (:func:`.rate_state.sliding_start`: the
    spring's force ``f = mu_ss(V)`` continuous at ``tau = 0``).  With ``steady``
    the last section state of :func:`.rate_state.rs_steady_state` from the solver's own
    start (its output rows into ``out_f``, ``out_i``).
    """
    P = point_parameters(p)
    offset = frame_offset(p[T_A_X], p[T_PHASE_X], p[T_INPLANE_ON] == 0.0)
    z = sliding_start(P, offset)
    if steady:
        rs_steady_state(P, z, rtol, max_periods, tol_mean, offset, out_f, out_i)
    z[Z_F] = 0.0
    z[Z_D] = 0.0
    z[Z_G] = 0.0
    return z


@jit
def _record(P, t, z, mode, out, r):
    """Row ``r`` of ``out``: ``tau``, ``z``, the slip rate (nan in flight), the mode
    (``CONTACT`` or ``FLIGHT``; a rigid contact's velocity ``x' = w'`` into ``z`` first).
    """
    out[r, R_TAU] = t
    if mode != FLIGHT:
        w = _slip_rate(P, z[Z_M], z[Z_L])[0]
        if mode == RIGID:
            z[Z_V] = w
        out[r, R_W] = w
    else:
        out[r, R_W] = math.nan
    for j in range(NZ):
        out[r, R_Z + j] = z[j]
    out[r, R_MODE] = FLIGHT if mode == FLIGHT else CONTACT


@jit
def rs_history(p, z, seg_t, seg_mode, grid, rtol, out):
    """Integrate ``z`` (kernels' frame) through the segments, recording rows into ``out``.

    Segment ``i`` runs from ``seg_t[i]`` to ``seg_t[i + 1]`` in ``seg_mode[i]``
    (``CONTACT`` or ``FLIGHT``); where the mode changes, the contact unloads (``m = 0``) or
    re-forms (:func:`.rate_state._touchdown`).  A row at each segment's two ends (a
    change of mode gives two rows at one time: before and after) and at each time of the
    sorted ``grid`` inside a segment (times within ``NEAR`` of the last row's: none).
    Returns the rows written, ``-1`` where a step failed (the integrator's limits).
    """
    P = point_parameters(p)
    scale = _scales(P)
    work = _workspace()
    count = np.zeros(3, np.int64)
    hbox = np.array([1e-3])
    log = np.empty(1)
    lp = np.zeros(2, np.int64)
    r = 0
    g = 0
    contact = _contact_mode(P)
    T = work[6][0]  # no tangent: the resets' rows of it are not used
    for i in range(seg_mode.size):
        t0, t1 = seg_t[i], seg_t[i + 1]
        mode = FLIGHT if seg_mode[i] == FLIGHT else contact
        if i > 0 and seg_mode[i] != seg_mode[i - 1]:
            if mode == FLIGHT:  # lift-off: the spring unloads (or e kept, damped)
                _liftoff(P, t0, z, T, contact, False)
            else:
                _touchdown(P, t0, z, T, mode, False)
        _record(P, t0, z, mode, out, r)
        r += 1
        while g < grid.size and grid[g] <= t0 + NEAR:
            g += 1
        t = t0
        while g < grid.size and grid[g] < t1 - NEAR:
            if grid[g] <= t + NEAR:  # the same time twice (to round-off): once
                g += 1
                continue
            if not _segment(P, z, t, grid[g], mode, rtol, hbox, scale, work, count, log, lp):
                return -1
            t = grid[g]
            _record(P, t, z, mode, out, r)
            r += 1
            g += 1
        if not _segment(P, z, t, t1, mode, rtol, hbox, scale, work, count, log, lp):
            return -1
        _record(P, t1, z, mode, out, r)
        r += 1
    return r
