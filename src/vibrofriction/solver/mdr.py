"""A first MDR steady-state solver (issue 21, item 1): docs/contact_geometry.md.

The event-driven kernel :mod:`vibrofriction._kernels.mdr` integrates a row of ``N`` springs
exactly (closed forms between events, events refined to round-off); this module iterates its
period map on the section ``tau = 2 pi k`` until the section state repeats, and extrapolates
in ``N`` (rows of ``N`` and ``2N`` springs, Richardson with order 2, the order measured in
docs/contact_geometry.md). The public ``Dimensionless(..., profile_exponent=...)`` API is a
later step; :func:`mdr_friction` is the entry point for now.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Iterator
from typing import Any

import numpy as np

from .._kernels.average import window_means
from .._kernels.codes import FLIGHT, O_ERR, O_MU, SLIP_POS, STICK
from .._kernels.mdr import row_geometry, steady_row
from .._kernels.phases import frame_offset, inplane_forcing
from ..capabilities import CAPABILITIES
from ..schema import FLOAT_COLUMNS, POSITIVE
from ..validation import checked_count, checked_number
from .mdr_continuum import (
    continuous_sliding,
    continuum_covers,
    continuum_friction,
    slides_continuously,
)

__all__ = ["mdr_friction", "mdr_row", "rows_alone"]

ORDER = 2.0  # the observed order of the row's convergence in N (irregular: see docs)
SUBSTEPS = 64  # the scan's sub-steps a period: a cost, not a resolution (no root is missed)
# a row's default budget and tolerance: the MDR solver's declared defaults of
# SolverSettings.max_periods and tol_state
MAX_PERIODS = int(CAPABILITIES["mdr"].settings["max_periods"])
STATE_TOL = float(CAPABILITIES["mdr"].settings["tol_state"])
ANDERSON = 6  # period maps mixed
ACCELERATED_PERIODS = 200  # then plain iteration
MAX_SPRINGS = 5120  # the finest row: a stated error of 1e-7 where asked (rows to 2560, 5120)
# beyond this row only a periodic one is refined: a row that averages runs up to max_periods,
# and one of thousands of springs would take minutes
AVERAGED_SPRINGS = 640
SKIP_PERIODS = 400  # a row of mdr_friction that may be passed over gives up after this
# the row without springs answers a point it covers where tol is below this: at every tol
# (it is exact in xi, where the rows' convergence in N can stall and their error fall
# short; far cheaper than the rows at tight tolerances and about as dear at loose ones, where
# it states errors of about 1e-7: benchmarks/bench_mdr_tol.py, results/mdr_tol.md); 0
# within rows_alone() (the MDR histories and the tests' references are the rows')
CONTINUUM_TOL = math.inf


@contextlib.contextmanager
def rows_alone() -> Iterator[None]:
    """Within it, :func:`mdr_friction` answers with the rows of springs, in this process.

    The row without springs is off (``CONTINUUM_TOL = 0``); a proven continuous sliding is
    still answered at once. For the rows' tests, references and benchmarks.
    """
    global CONTINUUM_TOL
    saved, CONTINUUM_TOL = CONTINUUM_TOL, 0.0
    try:
        yield
    finally:
        CONTINUUM_TOL = saved


def _check(alpha: float, beta: float, amplitude: float, V: float, n_exp: float,
           zeta: float, a_x: float = 0.0, phase_x: float = 0.0,
           inplane_on: str = "substrate") -> None:
    for name, value in (("alpha", alpha), ("beta", beta), ("amplitude", amplitude), ("V", V),
                        ("zeta", zeta), ("a_x", a_x), ("phase_x", phase_x)):
        if not math.isfinite(value):
            raise ValueError(f"{name} must be a finite number, got {value}")
    if not alpha > 0.0:
        raise ValueError(f"alpha must be > 0, got {alpha}")
    if not beta > alpha:
        raise ValueError(f"beta must be > alpha (finite), got {beta}")
    if amplitude < 0.0 or zeta < 0.0 or a_x < 0.0:
        raise ValueError("amplitude, zeta and a_x must be >= 0")
    if inplane_on not in ("substrate", "holder"):
        raise ValueError(f"inplane_on must be 'substrate' or 'holder', got {inplane_on!r}")
    if V == 0.0 and a_x > 0.0:
        raise ValueError("V = 0 with an in-plane oscillation (a_x > 0) is not covered: "
                         "springs that stick through whole cycles keep the elongation of "
                         "the start, so the steady state depends on it (held); the row's "
                         "period map is iterated only where every spring slips (V > 0)")
    if V < 0.0:
        raise ValueError(f"V must be >= 0 (the mirror V -> -V is not wired yet), got {V}")
    if not (n_exp > 0.0):
        raise ValueError(f"profile_exponent must be in (0, inf], got {n_exp}")


def _start(alpha: float, a: float, n_exp: float, M: int,
           warm: tuple | None, offset: tuple[float, float] = (0.0, 0.0),
           ) -> tuple[float, float, np.ndarray, np.ndarray]:
    """Section state to start a row of ``M`` springs from.

    Steady sliding (``y = -sum n_i(0)/alpha``, every loaded spring slipping forwards; in the
    laboratory frame, so relative to an oscillating substrate ``y - X(0)``, ``y' - X'(0)``:
    ``offset``), or ``warm = (y, y', st, e)``, a converged row of ``M/2`` springs (the same
    frame): each spring inherits its parent cell's state (the elongation ``e = f/k`` does not
    depend on the cell width), a stuck one clipped to its own friction limit at the section.
    """
    if warm is None:
        g, w, _, _, _, _ = row_geometry(a, n_exp, M)
        st = np.full(M, SLIP_POS, dtype=np.int64)
        st[w * (1.0 - g) <= 0.0] = FLIGHT
        y = -float(np.sum(w * np.maximum(0.0, 1.0 - g))) / alpha
        if offset[0] != 0.0 or offset[1] != 0.0:
            return y - offset[0], -offset[1], st, np.zeros(M)
        return y, 0.0, st, np.zeros(M)
    y, yd, st0, e0 = warm
    parent = np.arange(M) * st0.size // M
    st = st0[parent].copy()
    e = e0[parent].copy()
    return float(y), float(yd), st, e



def mdr_row(alpha: float, beta: float, amplitude: float, V: float, profile_exponent: float,
            n_springs: int, zeta: float = 0.0, state_tol: float = STATE_TOL,
            substeps: int = SUBSTEPS, max_periods: int = MAX_PERIODS,
            warm: tuple | None = None, accelerate: bool = True, a_x: float = 0.0,
            phase_x: float = 0.0, inplane_on: str = "substrate",
            static_ratio: float = 1.0) -> dict:
    """Steady state of one row of ``n_springs`` springs (no extrapolation in ``N``).

    ``static_ratio = mu_static/mu0 >= 1``: each spring stuck while ``|f_i| <=
    static_ratio n_i``; at that limit it slips and its force drops to the kinetic ``n_i``
    (:mod:`vibrofriction._kernels.mdr`).

    ``a_x``, ``phase_x``, ``inplane_on``: the longitudinal in-plane oscillation
    ``X = a_x cos(tau + phase_x)`` of the substrate or of the holder (docs/inplane.md;
    :mod:`vibrofriction._kernels.mdr`); on the substrate the section state
    (``final_state``, ``warm``) is relative to it.

    Starts sliding (``y = -sum n_i(0)/alpha``, every spring slipping forwards), or from a
    coarser row's final section state ``warm`` (:func:`_start`), and iterates the period
    map until the section state repeats within ``state_tol``: status ``"periodic"``
    (error: round-off, 1e-12). With ``accelerate``, once the springs' stick/slip states at
    the section repeat, the continuous part of the state (``y``, ``y'``, the stuck
    springs' elongations) is updated by Anderson mixing of the last ``ANDERSON`` period
    maps (the transient of a lightly damped body is long under plain iteration); a
    change of the discrete states restarts the history. Otherwise the mean over the last
    half of the periods run, its error the range of the means over the last three
    doubling windows (:func:`averaged_row`): ``"averaged"`` (or ``"not converged"`` if the
    kernel made no progress, or ran fewer than 8 periods). ``period_integrals``: the
    integrals of the friction and the normal force over each period run.
    """
    M = checked_count("n_springs", n_springs)
    a, n_exp = float(amplitude), float(profile_exponent)
    gamma = 2.0 * zeta * math.sqrt(alpha)
    on_substrate = inplane_on == "substrate"
    hc, hs = inplane_forcing(alpha, gamma, float(a_x), float(phase_x), on_substrate)
    y, yd, st, e = _start(alpha, a, n_exp, M, warm,
                          frame_offset(float(a_x), float(phase_x), on_substrate))
    periods, conv, pf_a, nint, frac, viol, events, y, yd = steady_row(
        alpha, beta, a, V, gamma, n_exp, M, substeps, state_tol, max_periods, accelerate,
        ANDERSON, ACCELERATED_PERIODS, y, yd, st, e, hc, hs, float(static_ratio))
    if events < 0:  # the last period did not finish
        pf_a = pf_a[:-1]
    pn_a = np.full(pf_a.size, nint)
    if events < 0:
        status, mu, err = "not converged", float(pf_a[-1] / pn_a[-1]) if periods > 1 \
            else math.nan, math.inf
    elif conv:
        status, mu, err = "periodic", float(pf_a[-1] / pn_a[-1]), 1e-12
    elif pf_a.size < 8:  # too few periods for three doubling windows (max_periods < 8)
        status, mu, err = "not converged", float(pf_a[-1] / pn_a[-1]), math.inf
    else:
        status = "averaged"
        mu, err = averaged_row(pf_a, pn_a)
    return dict(mu_ratio=mu, error=err, status=status, periods=int(periods),
                mean_normal_ratio=float(nint / (2.0 * math.pi)),
                stick_area_fraction=float(frac[0]), slip_area_fraction=float(frac[1]),
                open_area_fraction=float(frac[2]), max_excess=float(viol),
                events_per_period=int(events), n_springs=M, final_status=st.copy(),
                final_stuck=int(np.sum(st == STICK)), final_state=(y, yd, st.copy(), e.copy()),
                period_integrals=(pf_a, pn_a))


def averaged_row(pf: np.ndarray, pn: np.ndarray) -> tuple[float, float]:
    """A row's running average ``(mu, error)``.

    From its per-period integrals of the friction force ``pf`` and of the normal force
    ``pn`` (``P >= 8`` periods).

    ``mu`` is the mean over the last half, ``(P/2, P]``; ``error`` the range of the means
    over ``(P/8, P/4]``, ``(P/4, P/2]`` and ``(P/2, P]``: the event solver's rule
    (:func:`vibrofriction._kernels.average.window_means`; the periods up to ``P/8`` are
    the transient). The difference of two windows alone understates the error of noise-like
    fluctuations about a third of the time (docs/solver.md, "Averaged answers").
    """
    P = pf.size
    ks = np.array([P // 8, P // 4, P // 2, P])
    num = np.concatenate(([0.0], np.cumsum(pf)))[ks]
    den = np.concatenate(([0.0], np.cumsum(pn)))[ks]
    out = np.full(len(FLOAT_COLUMNS), math.nan)
    window_means(num, den, ks.astype(float), 4, out)
    return float(out[O_MU]), float(out[O_ERR])


def mdr_friction(alpha: float, beta: float, amplitude: float, V: float,
                 profile_exponent: float, zeta: float = 0.0, n_springs: int | None = None,
                 tol: float = 1e-5, a_x: float = 0.0, phase_x: float = 0.0,
                 inplane_on: str = "substrate", state_tol: float | None = None,
                 max_periods: int = MAX_PERIODS, static_ratio: float = 1.0) -> dict:
    """``mu_ratio = <F_x>/(mu0 <F_N>)`` of the scaled MDR model (docs/contact_geometry.md).

    Rows of ``N`` and ``2N`` springs (``N = n_springs``, or doubled from 20 up to 5120 until the
    error is ``<= tol``, beyond 640 only while the finer row is periodic; each row starts from
    the previous row's final section state); the result is the Richardson extrapolation with
    order 2, ``mu_2N + (mu_2N - mu_N)/3``, and its ``error`` is ``|mu_2N - mu_N|`` (three times
    the Richardson estimate: the convergence is irregular) plus the previous pair's difference
    ``|mu_N - mu_N/2|`` (at least three rows, 20, 40 and 80 springs, so there is one),
    plus both orbits' errors. A row
    that finds no periodic orbit within ``SKIP_PERIODS`` after a periodic one is passed
    over (``skipped_rows``) and the pair becomes ``(N, 4N)`` (extrapolated with ratio 4,
    error still the full difference). The
    flat punch (``profile_exponent = inf``) is one spring, exactly. Also returned:
    ``mean_normal_ratio = <F_N>/F_N0`` (exact for the row of ``2N``), the time-averaged
    fractions of the disc of the largest contact radius in stick, slip and out of contact
    (of the finer row), ``status`` (``"periodic"``, ``"averaged"``, ``"not converged"``:
    the worse of the two rows) and ``order``.

    ``a_x``, ``phase_x``, ``inplane_on``: a longitudinal in-plane oscillation of the
    substrate or the holder (:func:`mdr_row`; ``V > 0`` only: ``V = 0`` with ``a_x > 0``
    is refused, as its steady state depends on the start).  ``state_tol`` and
    ``max_periods`` are each row's (:func:`mdr_row`; ``state_tol`` None: ``STATE_TOL``; a
    row that may be passed over stops after at most ``SKIP_PERIODS``), and the row without
    springs' (``state_tol`` None: chosen for ``tol``, :func:`continuum_friction`);
    ``static_ratio >= 1`` too (each spring's static limit over its kinetic one; above 1
    the rows are not accelerated: they follow the motion). ``tol`` must be a finite number
    ``> 0`` and ``n_springs`` a whole number ``>= 1`` (``3.0`` too): anything else is
    refused with a ValueError naming it.
    """
    tol = checked_number("tol", tol, POSITIVE)
    n_given = None if n_springs is None else checked_count("n_springs", n_springs)
    alpha, beta, amplitude, V, n_exp, zeta, a_x, phase_x = (float(x) for x in (
        alpha, beta, amplitude, V, profile_exponent, zeta, a_x, phase_x))
    _check(alpha, beta, amplitude, V, n_exp, zeta, a_x, phase_x, inplane_on)
    static_ratio = float(static_ratio)
    if not static_ratio >= 1.0 or math.isinf(static_ratio):
        raise ValueError(f"static_ratio must be a finite number >= 1, got {static_ratio}")
    # a static limit above the kinetic one: sliding and stick-slip coexist, and Anderson's
    # step can land in the basin of an orbit the motion does not take (seen: the sliding
    # orbit, 1.0, where the row's own motion sticks at 1.06), so the rows follow the motion
    ip: dict[str, Any] = dict(a_x=a_x, phase_x=phase_x, inplane_on=inplane_on,
                              state_tol=STATE_TOL if state_tol is None else float(state_tol),
                              static_ratio=static_ratio, accelerate=static_ratio == 1.0)
    rank = {"periodic": 0, "averaged": 1, "not converged": 2}
    if n_given is None and not math.isinf(n_exp) \
            and continuum_covers(amplitude, V, static_ratio):
        on_substrate = inplane_on == "substrate"
        hc, hs = inplane_forcing(alpha, 2.0 * zeta * math.sqrt(alpha), a_x, phase_x,
                                 on_substrate)
        c: dict[str, Any] | None = None
        if hc == 0.0 and hs == 0.0 and slides_continuously(alpha, beta, amplitude, V,
                                                             n_exp, zeta):
            c = continuous_sliding(amplitude, n_exp)  # proven: at every tolerance
        elif tol < CONTINUUM_TOL:
            c = continuum_friction(alpha, beta, amplitude, V, n_exp, zeta, hc, hs,
                                   frame_offset(a_x, phase_x, on_substrate), tol,
                                   max_periods=min(max_periods, SKIP_PERIODS),
                                   state_tol=state_tol)
        if c is not None and c["status"] in ("periodic", "continuous sliding") \
                and c["error"] <= tol:
            # (each point's force is clamped to its limit exactly: no excess to report)
            c.update(order=math.inf, rows=(), n_springs=0, skipped_rows=(), max_excess=0.0)
            return c
    if math.isinf(n_exp):
        r = mdr_row(alpha, beta, amplitude, V, n_exp, 1, zeta, max_periods=max_periods, **ip)
        r.update(order=math.inf, rows=(1,))
        return r
    N = 20 if n_given is None else n_given
    coarse = mdr_row(alpha, beta, amplitude, V, n_exp, N, zeta, max_periods=max_periods, **ip)
    skipped: list[dict[str, Any]] = []
    d_prev = math.nan  # the previous pair's difference
    while True:
        # a row that finds no periodic orbit (another attractor of the finite row, e.g. a
        # period-5 orbit of 80 springs while 40 and 160 have period 1) is passed over once
        # a periodic row exists: the pair is then (N, 4N), extrapolated with its ratio
        M = 2 * (skipped[-1]["n_springs"] if skipped else N)
        periodic_coarse = coarse["status"] == "periodic"
        fine = mdr_row(alpha, beta, amplitude, V, n_exp, M, zeta,
                       warm=coarse["final_state"],
                       max_periods=min(SKIP_PERIODS, max_periods) if periodic_coarse
                       and n_springs is None and 2 * M <= MAX_SPRINGS else max_periods, **ip)
        if periodic_coarse and fine["status"] != "periodic" and n_springs is None \
                and 2 * M <= MAX_SPRINGS:
            skipped.append(fine)
            continue
        ratio = M / N
        d = fine["mu_ratio"] - coarse["mu_ratio"]
        # the convergence in N is irregular (the contact edge moves across the springs):
        # one difference can be small by chance, so where a previous pair exists its
        # difference counts too (measured: rows 40, 80 of (0.05, 0.1, 0.5, 2, zeta 0.5,
        # n = 2) differ by 3.7e-6 where the extrapolation is 6e-6 off)
        err = abs(d) + (0.0 if math.isnan(d_prev) else abs(d_prev)) \
            + coarse["error"] + fine["error"]
        # and a result needs that second difference: the first pair (20, 40) alone can
        # agree by chance (measured: 0.73019032 +- 1.3e-6 at (1, 3, 0.6, 0.4, zeta 0.02,
        # n = 2, holder a_x 0.5, phase_x 0.5) where the converged rows give 0.73019536)
        if n_springs is not None or (err <= tol and not math.isnan(d_prev)) \
                or M >= MAX_SPRINGS or (M >= AVERAGED_SPRINGS and fine["status"] != "periodic"):
            break
        d_prev = d
        N = M
        coarse = fine
        skipped = []
    out = dict(fine)
    out.update(mu_ratio=fine["mu_ratio"] + d / (ratio ** ORDER - 1.0), error=err,
               status=max(coarse["status"], fine["status"], key=lambda s: rank[s]),
               order=ORDER, rows=(N, M), unextrapolated=fine["mu_ratio"],
               skipped_rows=tuple(r["n_springs"] for r in skipped))
    if out["status"] == "averaged" and err > tol:
        out["status"] = "not converged"
    return out
