"""Named integer constants shared by the kernels and the Python layer.

The output column indices, the status codes and the contact-state codes are derived from
:mod:`vibrofriction.schema` (standard library only), the one place they are defined.
"""

from vibrofriction.schema import (
    CONTACT_STATE_NAMES,
    NO_STATE,
    ContactState,
    Status,
    column_index,
    point_index,
)

# states of the contact (vibrofriction.schema.ContactState): of the single contact point
# (1-D and 2-D kernels) and of each spring of the MDR row (kernels/mdr.py)
STICK = int(ContactState.STICK)
SLIP_POS = int(ContactState.SLIP_POS)  # contact point slides in +x (s = +1)
SLIP_NEG = int(ContactState.SLIP_NEG)  # contact point slides in -x (s = -1)
FLIGHT = int(ContactState.FLIGHT)  # out of contact (jumping; a spring of the row lifted off)

NO_PHASE = NO_STATE  # none: no phase to avoid on entry, or no section state (static points)

PHASE_NAMES = CONTACT_STATE_NAMES

# event kinds (transitions and cuts)
EV_STICK_TO_SLIP = 0
EV_SLIP_TO_STICK = 1
EV_REVERSAL = 2  # slip s -> slip -s (rigid contact only)
EV_LIFTOFF = 3
EV_TOUCHDOWN = 4
EV_SECTION = 5  # Poincare section tau = 2 pi k (not a physical event)
EV_NONE = -1  # no event (the start of a history)

EVENT_NAMES = ("stick->slip", "slip->stick", "reversal", "lift-off", "touchdown", "section")

# steady-state status (vibrofriction.schema.Status)
ST_PERIODIC = Status.PERIODIC.code
ST_AVERAGED = Status.AVERAGED.code
ST_NOT_CONVERGED = Status.NOT_CONVERGED.code
ST_FAILED = Status.FAILED.code  # the event budget was exhausted or the integration got stuck
ST_SLIDING = Status.SLIDING.code  # continuous forward sliding proven (mu/mu0 = 1 exactly)
ST_STATIC = Status.STATIC.code  # zero velocity: the static limit, not computed by the kernels

# output rows of the steady state (vibrofriction.schema.FLOAT_COLUMNS, INT_COLUMNS)
O_MU = column_index("mu_ratio")
O_ERR = column_index("error")
O_STICK = column_index("stick_fraction")
O_SLIP = column_index("slip_fraction")
O_SLIP_NEG = column_index("reverse_slip_fraction")
O_FLIGHT = column_index("flight_fraction")
O_Y = column_index("y")
O_XD = column_index("x_dot")
O_F = column_index("f")
O_MULT = column_index("multiplier")
O_SETTLE = column_index("settling_periods")
O_WMIN = column_index("window_min")
O_WMAX = column_index("window_max")
O_DRIFT = column_index("drift_rate")
O_E = column_index("e")
O_WORK = column_index("work")
O_LAT = column_index("lateral_ratio")
I_STATUS = column_index("status")
I_PERIOD = column_index("period")
I_PERIODS = column_index("periods")
I_EVENTS = column_index("events")
I_PHASE = column_index("phase")
I_DEGENERATE = column_index("degenerate")

# columns of a history row (integrate.run_periods)
SEG_TAU, SEG_Y, SEG_XD, SEG_F, SEG_PHASE, SEG_EVENT, SEG_INT_F, SEG_INT_N = range(8)
SEG_THETA, SEG_E, SEG_E_DOT = 8, 9, 10
N_SEG_COLUMNS = 11
# columns of a sampled history (integrate.sample)
SMP_Y, SMP_XD, SMP_F, SMP_N, SMP_PHASE, SMP_E = range(6)
N_SMP_COLUMNS = 6

# columns of a table of points (vibrofriction.schema.POINT_COLUMNS): the batch kernels read
# a packed row of a point's parameters by these
T_ALPHA = point_index("alpha")
T_BETA = point_index("beta")
T_AMPLITUDE = point_index("amplitude")
T_ZETA = point_index("zeta")
T_ETA_C = point_index("eta_c")
T_A_X = point_index("a_x")
T_PHASE_X = point_index("phase_x")
T_A_Y = point_index("a_y")
T_PHASE_Y = point_index("phase_y")
T_ALPHA_Y = point_index("alpha_y")
T_ZETA_Y = point_index("zeta_y")
T_PROFILE_EXPONENT = point_index("profile_exponent")
T_V = point_index("v_inertial")
T_STATIC_RATIO = point_index("static_ratio")
T_INPLANE_ON = point_index("inplane_on")  # the index of "substrate" is 0
I_METHOD = column_index("method")

#: How a point of a chain kernel (``steady_state_many``, ``plane_steady_chain``) starts: from
#: its own start (``init_kind``, ``init[i]``), from the final section state of the point
#: before it where that has one (a continuation; else its own start), or from the explicit
#: state ``init[i]``.
LINK_OWN, LINK_PREVIOUS, LINK_GIVEN = 0, 1, 2
