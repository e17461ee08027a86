"""An averaged answer's error against the motion's own long-time mean (docs/solver.md, "What
error means"; the calibration over fresh points: benchmarks/averaged_error.py).

The long-time mean is the mean of the same motion over far more periods than the solver
ran, by the period map alone (no checkpoint, window or Newton logic): the claim under test
is the averaging rule's, that the last window's mean is within ``error`` of it.
"""

from __future__ import annotations

import numpy as np

import vibrofriction as vf
from vibrofriction._kernels.period import A_F, A_N, N_ACC, advance_counted
from vibrofriction._kernels.phases import frame_offset, make_model
from vibrofriction._kernels.steady import _start

# (alpha, beta, a, V, zeta, s_r, start), from benchmarks/averaged_error.py's streams
LINGERS = (0.709700576504594, 5.6347692058134085, 0.25461069713800655, 0.18949416749342968,
           0.08303086635877359, 1.846684571545051, "sliding")
WANDERS = (0.34621801733604424, np.inf, 0.19690361643669924, 0.45996171753964676, 0.0,
           1.107709929244969, "rest")
UNLOCKED = (0.4560065759104873, 8.012817768791477, 0.18427141797487911, 0.317843576088484,
            0.14889755570294777, 2.004655174831411, "sliding")


def _solve(p: tuple) -> vf.FrictionResult:
    alpha, beta, a, V, zeta, sr, start = p
    return vf.friction_coefficient(vf.Dimensionless(alpha, beta, a, zeta=zeta,
                                                    static_ratio=sr),
                                   v_inertial=V, initial=start)


def _window_means(p: tuple, edges: list[int]) -> list[float]:
    """The motion's means of ``f/n`` between successive ``edges`` (periods from the start)."""
    alpha, beta, a, V, zeta, sr, start = p
    M = make_model(alpha, beta, a, V, zeta, 0.0, 0.0, 0.0, True, sr)
    z = _start({"sliding": 0, "rest": 1}[start], 0.0, 0.0, 0.0, 0.0, M,
               frame_offset(0.0, 0.0, True))
    acc, count = np.zeros(N_ACC), np.zeros(3, np.int64)
    sums = [(0.0, 0.0)]
    for k in range(1, edges[-1] + 1):
        ok, _ = advance_counted(z, acc, count, M, 10**9)
        assert ok
        if k in edges:
            sums.append((acc[A_F], acc[A_N]))
    sums = sums[1:] if edges[0] else sums
    return [(f1 - f0) / (n1 - n0) for (f0, n0), (f1, n1) in zip(sums, sums[1:], strict=False)]


def test_no_average_while_the_motion_lingers_near_an_orbit() -> None:
    """A static point whose motion lingers near an unstable orbit: its window means over
    (64, 128], (128, 256] and (256, 512] agree within 1e-7 (so a rule without the nearby
    orbit answered 1.0085430 +- 1.5e-8), and the motion leaves: its mean over
    (8192, 16384] is 1e-3 higher.  The answer is not trusted, or within its error of that.
    """
    early = _window_means(LINGERS, [64, 128, 256, 512])
    late = _window_means(LINGERS, [8192, 16384])[0]
    assert max(early) - min(early) < 1e-7
    assert late - early[-1] > 5e-4
    r = _solve(LINGERS)
    assert not r.trusted or abs(r.mu_ratio - late) <= r.error


def test_a_wandering_average_is_not_trusted_on_two_windows() -> None:
    """Undamped, near the neutral sliding orbit (stuck 1.3 % of the time): the means over
    (4096, 8192] and (8192, 16384] agree to 5e-8, the window before differs by 1.4e-6,
    and the motion's mean over (131072, 262144] is 1.6e-7 from the last; the answer is not
    trusted at the default tol_mean, or within its error of the long mean."""
    w = _window_means(WANDERS, [2048, 4096, 8192, 16384])
    assert abs(w[2] - w[1]) < 1e-7 < abs(w[1] - w[0])
    late = _window_means(WANDERS, [131072, 262144])[0]
    assert abs(late - w[2]) > 1e-7
    r = _solve(WANDERS)
    assert not r.trusted


def test_an_unlocked_average_states_its_windows_range() -> None:
    """A damped static point not locked to the drive: averaged, its error the range of
    the last three windows' means (``window_min``, ``window_max``), the answer the last's,
    and the motion's mean over periods (8192, 16384] within that error."""
    r = _solve(UNLOCKED)
    assert r.status is vf.Status.AVERAGED and r.trusted
    k = r.periods
    w = _window_means(UNLOCKED, [k // 8, k // 4, k // 2, k])
    assert r.mu_ratio == w[-1]
    assert r.window_min == min(w) and r.window_max == max(w)
    assert r.error == max(w) - min(w)
    late = _window_means(UNLOCKED, [8192, 16384])[0]
    assert abs(r.mu_ratio - late) <= r.error
