r"""One drive period, the period map and the distance on the Poincare section.

The state on the section ``tau = 2 pi k`` is ``z = (y, x', e, phase, e')``
(:mod:`.integrate`); one period is integrated event by event
(:func:`advance_period`), accumulating the integrals of ``f`` and ``n`` (paper
eq. 25) and the time in each phase.
"""

import math

import numpy as np

from .codes import EV_SECTION, FLIGHT, SLIP_NEG, STICK
from .integrate import TWO_PI, segment
from .jit import jit
from .phases import M_K

MAX_PERIOD = 12  # longest periodic orbit looked for, in drive periods
MAX_DEGENERATE = 1000  # transitions decided within round-off before giving up (chatter)
MAX_ZERO_SEGMENTS = 100  # successive zero-length segments before giving up (stuck)

# accumulators: integrals of f and n, times in stick, slip, reverse slip, flight
A_F, A_N, A_STICK, A_SLIP, A_SLIP_NEG, A_FLIGHT = 0, 1, 2, 3, 4, 5
N_ACC = 6
# counters: events, degenerate transitions, successive zero-length segments
C_EVENTS, C_DEGENERATE, C_ZERO = 0, 1, 2


@jit
def accumulate(acc, count, ph, t, ev, ok, i_f, i_n):
    """Add a segment of length ``t`` in phase ``ph`` (integrals ``i_f``, ``i_n``, ended by
    event ``ev``, ``ok`` False if its transition was degenerate) to ``acc`` and ``count``.
    """
    acc[A_F] += i_f
    acc[A_N] += i_n
    if ph == STICK:
        acc[A_STICK] += t
    elif ph == FLIGHT:
        acc[A_FLIGHT] += t
    else:
        acc[A_SLIP] += t
        if ph == SLIP_NEG:
            acc[A_SLIP_NEG] += t
    if ev != EV_SECTION:
        count[C_EVENTS] += 1
    if not ok:
        count[C_DEGENERATE] += 1
    count[C_ZERO] = count[C_ZERO] + 1 if t == 0.0 else 0


@jit
def stop_integration(count, max_events):
    """The integration must stop: event budget, zero-length segments (stuck) or chatter."""
    return (count[C_EVENTS] > max_events or count[C_ZERO] > MAX_ZERO_SEGMENTS
            or count[C_DEGENERATE] > MAX_DEGENERATE)


@jit
def advance_period(z, acc, count, M, max_events):
    """Integrate one drive period from the section state ``z = (y, x', e, phase, e')``
    (``e'``: the exact rate where known, else nan; :func:`.phases.elongation`).

    ``z`` is updated in place, ``acc`` accumulates the integrals and phase times,
    ``count`` the events, degenerate transitions and zero-length segments.
    Returns False when the integration must stop (event budget, chatter, stuck).
    """
    theta = 0.0
    y, xd, e, ph, ed = z[0], z[1], z[2], int(z[3]), z[4]
    while theta < TWO_PI:
        t, theta, y, xd, e, ed, f, ph1, ev, i_f, i_n, ok = segment(theta, y, xd, e, ed, ph, M)
        accumulate(acc, count, ph, t, ev, ok, i_f, i_n)
        ph = ph1
        if stop_integration(count, max_events):
            return False
    z[0], z[1], z[2], z[3], z[4] = y, xd, e, ph, ed
    return True


@jit
def pure_forward_slip(win):
    """A window without stick or reverse slip: ``f = n`` throughout (``0 = 0`` in flight)."""
    return win[A_STICK] == 0.0 and win[A_SLIP_NEG] == 0.0


@jit
def window_mu(win):
    return 1.0 if pure_forward_slip(win) else win[A_F] / win[A_N]


@jit
def elapsed(acc):
    """The time integrated into the accumulators ``acc``, in drive periods."""
    return (acc[A_STICK] + acc[A_SLIP] + acc[A_FLIGHT]) / TWO_PI


@jit
def advance_counted(z, acc, count, M, max_events):
    """:func:`advance_period` and its work: returns ``(ok, work)``, ``work`` 1 drive period,
    or the fraction of one integrated before the integration stopped.
    """
    t0 = elapsed(acc)
    if advance_period(z, acc, count, M, max_events):
        return True, 1.0
    return False, elapsed(acc) - t0


@jit
def period_map(y, xd, e, ph, p, M, max_events):
    """Integrate ``p`` drive periods from the section; returns the state, the event count,
    the number of degenerate transitions (-1: the integration did not finish) and the
    drive periods integrated (``p``, less where it did not finish).

    Transitions decided within round-off (degenerate, e.g. among the hundreds of
    micro-slips per period of a stiff contact) do not make the map unusable for Newton's
    iterations and Jacobians; the orbit is accepted only from a map without them.
    """
    z = np.array([y, xd, e, float(ph), math.nan])
    acc = np.zeros(N_ACC)
    count = np.zeros(3, np.int64)
    work = 0.0
    for _ in range(p):
        ok, w = advance_counted(z, acc, count, M, max_events)
        work += w
        if not ok:
            return z[0], z[1], z[2], int(z[3]), count[C_EVENTS], -1, work
    return z[0], z[1], z[2], int(z[3]), count[C_EVENTS], count[C_DEGENERATE], work


@jit
def spring(M):
    """The contact stiffness as a weight of ``e`` in distances (0 for a rigid contact)."""
    return 0.0 if math.isinf(M[M_K]) else M[M_K]
