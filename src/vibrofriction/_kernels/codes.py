"""Named integer constants shared by the kernels and the Python layer."""

# phases of the contact
STICK = 0
SLIP_POS = 1  # contact point slides in +x (s = +1)
SLIP_NEG = 2  # contact point slides in -x (s = -1)
FLIGHT = 3  # no contact (jumping, amplitude > 1)

NO_PHASE = -1  # none: no phase to avoid on entry, or no section state (static points)

PHASE_NAMES = ("stick", "slip+", "slip-", "flight")

# event kinds (transitions and cuts)
EV_STICK_TO_SLIP = 0
EV_SLIP_TO_STICK = 1
EV_REVERSAL = 2  # slip s -> slip -s (rigid contact only)
EV_LIFTOFF = 3
EV_TOUCHDOWN = 4
EV_SECTION = 5  # Poincare section tau = 2 pi k (not a physical event)
EV_NONE = -1  # no event (the start of a history)

EVENT_NAMES = ("stick->slip", "slip->stick", "reversal", "lift-off", "touchdown", "section")

# steady-state status
ST_PERIODIC = 0
ST_AVERAGED = 1
ST_NOT_CONVERGED = 2
ST_FAILED = 3  # the event budget was exhausted or the integration got stuck
ST_SLIDING = 4  # continuous forward sliding proven (mu/mu0 = 1 exactly)
ST_STATIC = -1  # zero velocity: the static limit of eq. (2), not computed by the kernels

# output columns of the steady-state rows: they follow solver.FLOAT_COLUMNS and
# solver.INT_COLUMNS, in that order (plain named ints, the one place the kernels read)
O_MU, O_ERR, O_STICK, O_SLIP, O_SLIP_NEG, O_FLIGHT, O_Y, O_XD, O_F = 0, 1, 2, 3, 4, 5, 6, 7, 8
O_MULT, O_SETTLE, O_WMIN, O_WMAX, O_DRIFT, O_E = 9, 10, 11, 12, 13, 14
I_STATUS, I_PERIOD, I_PERIODS, I_EVENTS, I_PHASE, I_DEGENERATE = 0, 1, 2, 3, 4, 5
