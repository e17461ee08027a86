"""The MDR row without springs (the continuum limit): docs/contact_geometry.md.

:mod:`vibrofriction._kernels.mdr_continuum` integrates one period of the body driven by the
continuous row, the profile kept as a few pieces, exact in ``xi``; this module finds the
periodic orbit.  Its section is ``tau = pi`` (mod ``2 pi``), the smallest indentation: every
point that touched down in the last loading has left there (``a < 1``), so the profile is a
few affine pieces over the core ``xi <= (1 - a)^(1/n)`` and the section state is the vector
``(y, y', the pieces' ends, their levels relative to u)``.  Anderson's mixing of the last
``DEPTH`` period maps of that vector (restarted when the pieces' kinds change; a mixed
step after which the map moves the state ten times farther is undone) finds the orbit in
about ten to twenty-five periods where the plain iteration takes hundreds
(``tests/mdr/test_mdr_continuum.py``'s points).  From that orbit the search goes on with
maps at a tenth of the tolerance (a hundredth where the coarse orbit grazes, and for a
jumping indenter: ``FINE_GRAZE``) to their own orbit, which gives ``mu_ratio``; the
difference of the two orbits' ``mu``, plus the section state's
tolerance, is the stated error.  (One fine period from the coarse orbit is not enough:
the orbit of a map moves with the map's error, by more where it attracts slowly, and the
error so estimated held half the true one at such points.)  The first periods, where the
pieces still change, have their mean force balance restored (the kernel's ``_balance``);
maps over which the body creeps with the substrate (a soft pin's spring loading) are not
mixed but extrapolated by doubling steps (the kernel's ``DRIFT``).
A jumping indenter (``a > 1``) is in its flight at the section: the state is ``(y, y')``,
and the stated error also holds how far the search may have stopped from the orbit
(:func:`_search_error`).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from .. import theory
from .._kernels import mdr_continuum as mc

__all__ = ["continuous_sliding", "continuum_covers", "continuum_friction", "mdr_continuum",
           "slides_continuously"]

RTOL = 1e-8  # the period maps' tolerance (Dormand-Prince, relative), by default
# the maps' tolerances continuum_friction chooses from: looser maps go wrong just below the
# critical velocity, passing over brief sticks or settling on an orbit with less stick (at
# 1e-5, even with the kernel's guards; benchmarks/mdr_loose_maps.py)
LOOSEST, TIGHTEST = 1e-7, 1e-10
STATE_LOOSEST, STATE_TIGHTEST = 1e-7, 1e-9  # ... and the search's (the maps' noise below)
FACTOR = 0.3  # ... each this times tol_trusted (benchmarks/mdr_continuum_calibration.py)
RETRY = 0.01  # both tightened by this while the stated error exceeds tol_trusted
FINE = 0.1  # the fine orbit's maps' tolerance: this times the coarse one, ...
FINE_GRAZE = 0.01  # ... and where the coarse orbit grazes (not 0.1: just below V_c maps
# ten times finer can keep the coarse orbit with less stick, and the two orbits'
# difference then understates the error; benchmarks/mdr_near_critical.py): an edge's
# velocity turning back within GRAZE_DEPTH times V + c a of 0, or changing sign twice
# within GRAZE_TIME (a brief stick or slip); and always for a jumping indenter (its brief
# stick near V_c ends at the flight, where the stretches stop: unmeasured, and ten times
# finer fell short at 7 of 235 points, mdr_near_critical.py --jumping).  Measured
# (benchmarks/mdr_graze.py): the points whose FINE 0.1 fell short at 0.9995 and 0.9999
# V_c had a stretch of at most 0.064; the regimes of benchmarks/bench_ratios.py none
# below 0.31 and a depth of 0.008 and above
GRAZE_DEPTH = 3e-3
GRAZE_TIME = 0.2
DEPTH = 5  # period maps mixed
STATE_TOL = 1e-9  # the section state's change that ends the search
GROWTH = 10.0  # a mixed step whose residual grows by this restarts the mixing
HISTORY = 20000  # rows of the history of u
DIFF_RTOL = 1e-6  # _search_error's difference maps' tolerance at the tightest, and their
DIFF_STEP = 1e-5  # step (relative) times sqrt(its tolerance / 1e-7): far above their noise


def continuum_covers(amplitude: float, V: float, static_ratio: float) -> bool:
    """Whether the continuum covers a point.

    ``0 < a < 1`` or a jumping indenter (``a > 1``), ``V > 0``, Coulomb friction.
    """
    return (0.0 < amplitude < 1.0 or amplitude > 1.0) and V > 0.0 and static_ratio == 1.0


@functools.lru_cache(maxsize=64)
def _jacobi(n: float) -> np.ndarray:
    """Gauss-Jacobi's nodes and weights on ``[0, 1]`` for the weight ``s^(1/n)``.

    ``int_0^1 s^(1/n) f(s) ds`` (the kernel's quadrature from a touch-down), ``mc.GJ_N``
    each.
    """
    from scipy.special import roots_jacobi  # (not at import: the cold start)

    x, w = roots_jacobi(mc.GJ_N, 0.0, 1.0 / n)  # weight (1 + x)^(1/n) on [-1, 1]
    out = np.concatenate((0.5 * (1.0 + x), w / 2.0 ** (1.0 + 1.0 / n)))
    out.flags.writeable = False
    return out


def _parameters(alpha: float, beta: float, a: float, V: float, n: float, zeta: float,
                hc: float, hs: float) -> np.ndarray:
    """The kernel's parameter vector (``mc.P_*``)."""
    k = beta - alpha
    return np.concatenate(([alpha, 2.0 * zeta * math.sqrt(alpha), k, (n + 1.0) / n / k, n, a,
                            V, hc, hs], _jacobi(n)))


def _flight_map(prm: np.ndarray, t: float, y: float, v: float, rtol: float) -> np.ndarray:
    """One period map of a jumping indenter from ``(y, y')`` at ``t`` in the flight.

    Nothing else is left there. Returns ``(y, y', int F)`` at ``t + 2 pi``, at the given
    tolerance and always from the same first step (so its differences are smooth).
    """
    PC = np.zeros((mc.MAX_PIECES + 1, mc.N_PC))
    HS = np.empty((HISTORY, mc.N_HS))  # (rows written before they are read)
    HS[0, mc.HT], HS[0, mc.HU], HS[0, mc.HD] = t, y + prm[mc.P_V] * t, v + prm[mc.P_V]
    z = np.zeros(mc.N_Z)
    z[0], z[1] = y, v
    npc, _, _ = mc.period(prm, t, z, PC, 0, HS, 1, rtol, 0.01 * rtol, 0.5, 0.1,
                          np.zeros((8, mc.N_Z)), np.zeros_like(PC), np.zeros(4, np.int64),
                          np.full(6, np.nan), 2)
    if npc != 0:
        return np.full(3, np.nan)
    return np.array([z[0], z[1], z[3]])


def _search_error(prm: np.ndarray, t: float, x: np.ndarray, g: np.ndarray,
                  rtol: float) -> float:
    """How far the search's ``int F`` can be from the orbit's, a jumping indenter's.

    The search stops where the section state changes by less than ``state_tol`` over a
    period; on a slowly attracting orbit it is farther from the orbit than that. The last
    map took ``x`` (at ``t``) to ``g``; Newton's step from ``x`` to
    the orbit, ``dx = -(J - I)^-1 (g - x)`` (``J`` by differences of three more maps, from
    ``x`` and from ``x`` moved along each axis, at ``rtol`` but at least :data:`DIFF_RTOL`,
    plenty for a first-order correction: all at one tolerance, as the difference of two
    maps' errors divided by the step would bias ``J``, by more than ``1 - |lambda|`` near a
    slowly attracting orbit), moves ``int F`` by ``G . dx`` to first order (``G``
    likewise); so the last map's ``int F`` is about ``|G . dx|`` from the orbit's, and twice
    that is returned (the step is first-order).  ``inf`` where ``J - I`` is singular or a
    map fails.  The differences' step is :data:`DIFF_STEP` times ``sqrt(tolerance/1e-7)``,
    far above the maps' noise.
    """
    J = np.empty((2, 2))
    G = np.empty(2)
    rtol = max(rtol, DIFF_RTOL)
    rel = DIFF_STEP * math.sqrt(rtol / 1e-7)
    base = _flight_map(prm, t, x[0], x[1], rtol)  # (the differences' maps at one tolerance)
    for j in range(2):
        step = rel * (1.0 + abs(x[j]))
        xs = x.copy()
        xs[j] += step
        m = _flight_map(prm, t, xs[0], xs[1], rtol)
        J[:, j] = (m[:2] - base[:2]) / step
        G[j] = (m[2] - base[2]) / step
    try:
        dx = -np.linalg.solve(J - np.eye(2), g - x)
    except np.linalg.LinAlgError:
        return math.inf
    err = 2.0 * abs(float(G @ dx))
    return err if math.isfinite(err) else math.inf


def mdr_continuum(alpha: float, beta: float, amplitude: float, V: float,
                  profile_exponent: float, zeta: float = 0.0, hc: float = 0.0,
                  hs: float = 0.0, offset: tuple[float, float] = (0.0, 0.0),
                  max_periods: int = 200, rtol: float = RTOL,
                  state_tol: float = STATE_TOL) -> dict:
    """The periodic orbit of the continuum MDR row (:func:`continuum_covers`).

    ``hc``, ``hs``: the in-plane force ``hc cos tau + hs sin tau`` on the body, ``offset``
    the start's frame offset (:func:`vibrofriction._kernels.phases.frame_offset`), as for
    :func:`vibrofriction.solver.mdr.mdr_row`.  ``state_tol``: the section state's change
    (``y`` absolute, the rest relative) that ends each stage of the search, by the map and
    by the mixing's step (it adds to the stated error).  Returns
    ``mu_ratio``, ``error``, ``status``
    (``"periodic"``, or ``"failed"`` with the reason in ``reason``), ``periods``, the
    time-averaged area fractions in stick, slip and out of contact and
    ``mean_normal_ratio`` (``<F_N>/F_N0``, the theory's).
    """
    a, n = float(amplitude), float(profile_exponent)
    prm = _parameters(alpha, beta, a, V, n, zeta, hc, hs)
    PC = np.zeros((mc.MAX_PIECES + 1, mc.N_PC))
    HS = np.empty((HISTORY, mc.N_HS))  # (rows written before they are read)
    cnt = np.zeros(4, dtype=np.int64)
    y0 = -(1.0 + a) ** (1.0 + 1.0 / n) / alpha - offset[0]
    z = np.zeros(mc.N_Z)
    z[0], z[1] = y0, -offset[1]
    npc, nh = mc.start(prm, z[0], z[1], PC, HS)
    res = np.zeros(9)
    nbar = float(theory.profile_mean_normal_force(a, n))  # the sliding <F>: <y> = -nbar/alpha
    code, periods, events = mc.steady(prm, z, PC, npc, HS, nh, rtol, FINE, FINE_GRAZE,
                                      GRAZE_DEPTH, GRAZE_TIME, DEPTH, state_tol, GROWTH,
                                      -nbar / alpha, max_periods, cnt, res)
    if code != 0:
        reason = ("no periodic orbit within max_periods" if code == mc.SECTION_NO_ORBIT
                  else f"kernel code {code}")
        return dict(mu_ratio=math.nan, error=math.inf, status="failed", periods=periods,
                    stick_area_fraction=math.nan, slip_area_fraction=math.nan,
                    open_area_fraction=math.nan, events_per_period=0, reason=reason,
                    mean_normal_ratio=nbar)
    nint = 2.0 * math.pi * nbar
    mu = res[2] / nint
    # the fine orbit's difference from the coarse one (the maps' error), and the section
    # state's tolerance (the orbit's)
    err = abs(res[2] - res[0]) / nint + state_tol
    if a > 1.0:  # and how far the search stopped from a slowly attracting orbit
        t_last = math.pi + 2.0 * math.pi * (periods - 1)  # (the last map's start)
        err += _search_error(prm, t_last, res[5:7].copy(), z[:2].copy(), rtol) / nint
    area = 2.0 * math.pi * (1.0 + a) ** (2.0 / n)
    stick, slip = res[3] / area, res[4] / area
    return dict(mu_ratio=float(mu), error=float(err), status="periodic", periods=periods,
                stick_area_fraction=float(stick), slip_area_fraction=float(slip),
                open_area_fraction=float(1.0 - stick - slip),
                events_per_period=int(events), reason="", mean_normal_ratio=nbar)


SLIDING_SAMPLES = 256  # the grid of the sliding orbit's check
_TAU = 2.0 * math.pi * np.arange(SLIDING_SAMPLES) / SLIDING_SAMPLES
_COS, _SIN = np.cos(_TAU), np.sin(_TAU)
_HARMONICS = np.arange(SLIDING_SAMPLES // 2 + 1, dtype=float)


def slides_continuously(alpha: float, beta: float, amplitude: float, V: float,
                        profile_exponent: float, zeta: float) -> bool:
    """Whether continuous forward sliding is proven at ``V`` (``0 < a < 1``, no drive).

    The check of ``theory.profile_critical_velocity`` (docs/contact_geometry.md,
    "Continuous sliding") on a coarse grid: the sliding orbit's slip velocity
    ``V - f(tau)``, ``f = -y_p' - (p a/(beta - alpha)) sin tau``, from the Fourier series
    of the normal force (an FFT of :data:`SLIDING_SAMPLES` points), must stay positive.
    Proven where ``V`` exceeds the grid's largest ``f`` by more than the grid can miss
    (``h^2/8`` times a bound of ``|f''|`` from the series, plus its last coefficient's
    size); anything closer is left to the solver (``False``), as is a jumping indenter
    (``a >= 1``).
    """
    a, n = amplitude, profile_exponent
    if not a < 1.0:
        return False
    r = round(math.sqrt(alpha))
    if alpha == 0.0 or (zeta == 0.0 and r <= SLIDING_SAMPLES // 2 and r * r == alpha):
        return False  # undamped resonance of a harmonic of the force
    p = 1.0 + 1.0 / n
    N = SLIDING_SAMPLES
    M = np.fft.rfft((1.0 + a * _COS) ** p)  # N m = sum_k M_k e^{ik tau} + c.c.
    k = _HARMONICS
    Yd = -1j * k * M / (alpha - k * k + 2j * zeta * math.sqrt(alpha) * k)  # N y_p'
    yd = np.fft.irfft(Yd, N)
    f = -yd - p * a / (beta - alpha) * _SIN
    bound = 2.0 * float(np.abs(Yd) @ (k * k)) / N + p * a / (beta - alpha)
    miss = (2.0 * math.pi / N) ** 2 / 8.0 * bound + 100.0 * float(np.abs(Yd[-1])) / N
    return bool(V > float(np.max(f)) + miss + 1e-12 * (1.0 + abs(V)))


def continuous_sliding(amplitude: float, profile_exponent: float) -> dict:
    """The answer where every point slips forwards at its limit all the time.

    Where :func:`slides_continuously` holds, ``F = F_N``, so ``mu_ratio = 1`` exactly; the
    contact slips wherever it touches (its time-averaged area on the grid of the check).
    """
    tau = 2.0 * math.pi * np.arange(SLIDING_SAMPLES) / SLIDING_SAMPLES
    slip = float(np.mean(((1.0 + amplitude * np.cos(tau)) / (1.0 + amplitude))
                         ** (2.0 / profile_exponent)))
    return dict(mu_ratio=1.0, error=0.0, status="continuous sliding", periods=0,
                stick_area_fraction=0.0, slip_area_fraction=slip,
                open_area_fraction=1.0 - slip, events_per_period=0, reason="",
                mean_normal_ratio=float(theory.profile_mean_normal_force(amplitude,
                                                                         profile_exponent)))


def first_tolerances(tol: float, state_tol: float | None = None) -> tuple[float, float]:
    """The first run's tolerances in :func:`continuum_friction`: ``(rtol, state_tol)``.

    At ``tol``, with ``state_tol`` given or not (None).
    """
    rtol = min(LOOSEST, max(TIGHTEST, FACTOR * tol))
    if state_tol is not None:
        return rtol, max(STATE_TIGHTEST, float(state_tol))
    return rtol, min(STATE_LOOSEST, max(STATE_TIGHTEST, FACTOR * tol))


def continuum_friction(alpha: float, beta: float, amplitude: float, V: float,
                       profile_exponent: float, zeta: float, hc: float, hs: float,
                       offset: tuple[float, float], tol: float,
                       max_periods: int = 200, state_tol: float | None = None) -> dict:
    """:func:`mdr_continuum` with its maps' and its search's tolerances chosen for ``tol``.

    The maps' ``FACTOR`` times ``tol`` within ``[TIGHTEST, LOOSEST]``; the search's
    ``state_tol``, where not given, likewise within ``[STATE_TIGHTEST, STATE_LOOSEST]`` (a
    given one at least ``STATE_TIGHTEST``). Both tightened a hundredfold while the stated
    error exceeds ``tol``, down to their tightest (a given ``state_tol`` stays): a tenfold
    step can land where the maps' error has not fallen yet and the two orbits' difference
    understates it (measured with maps looser than ``LOOSEST``: from ``3e-6`` to ``3e-7``
    they stated ``1.3e-6`` at a slowly attracting jumping point ``2.1e-6`` off).
    """
    chosen = state_tol is not None
    rtol, stol = first_tolerances(tol, state_tol)
    while True:
        r = mdr_continuum(alpha, beta, amplitude, V, profile_exponent, zeta, hc, hs, offset,
                          max_periods=max_periods, rtol=rtol, state_tol=stol)
        if r["status"] != "periodic" or r["error"] <= tol \
                or (rtol <= TIGHTEST and (chosen or stol <= STATE_TIGHTEST)) \
                or (chosen and stol >= tol):  # (tighter maps cannot help that)
            return r
        rtol = max(TIGHTEST, RETRY * rtol)
        if not chosen:
            stol = max(STATE_TIGHTEST, RETRY * stol)
