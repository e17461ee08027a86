"""A row of springs that finds no periodic orbit answers ``averaged``: the mean over the last
half of its periods, its error the range of the means over its last three doubling windows
(:func:`vibrofriction.solver.mdr.averaged_row`; docs/contact_geometry.md, "Averaged rows").

* on given per-period integrals: a motion on an orbit of three periods (no window holds a
  whole number of them) states an error that covers the orbit's mean, one that drifts states
  at least the drift between its windows, an orbit whose period divides the windows is
  exact;
* on a row whose motion is not locked to the drive (a jumping cone, static limit above the
  kinetic one): the answer after 4000 periods lies within its stated error of the mean of a
  run four times as long (within that run's own spread), where the earlier rule (the mean
  over the last 100 periods, the difference of its halves as the error) misses it by four
  times its error.
"""

from __future__ import annotations

import numpy as np

from vibrofriction.solver.mdr import averaged_row, mdr_row


def _uniform(mu: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per-period integrals of a unit normal force with period means ``mu``."""
    return mu * 2.0 * np.pi, np.full(mu.size, 2.0 * np.pi)


def test_an_orbit_of_three_periods_is_covered() -> None:
    orbit = np.array([0.3, 0.9, 0.45])
    mu, err = averaged_row(*_uniform(np.tile(orbit, 1334)[:4000]))
    assert abs(mu - orbit.mean()) <= err
    assert 1e-5 < err < 1e-2  # a partial orbit at each window's end, over its length


def test_an_orbit_dividing_the_windows_is_exact() -> None:
    orbit = np.array([0.3, 0.9, 0.45, 0.7])
    mu, err = averaged_row(*_uniform(np.tile(orbit, 1000)))
    assert abs(mu - orbit.mean()) <= 1e-13
    assert err <= 1e-12


def test_a_drift_is_stated() -> None:
    k = np.arange(4000)
    mu, err = averaged_row(*_uniform(0.5 + 1e-7 * k))
    # the windows (P/8, P/4], (P/4, P/2], (P/2, P]: periods 500-999 and 2000-3999
    assert abs(err - 1e-7 * (2999.5 - 749.5)) <= 1e-12
    assert abs(mu - (0.5 + 1e-7 * 2999.5)) <= 1e-12


def test_a_row_not_locked_to_the_drive() -> None:
    kw = dict(alpha=0.9208695091648791, beta=3.740873051424434, amplitude=1.5682144473185495,
              V=0.665339699525243, profile_exponent=1.0, zeta=0.01,
              static_ratio=1.829484997188377, n_springs=40, accelerate=False)
    r = mdr_row(max_periods=4000, **kw)
    assert r["status"] == "averaged"
    long = mdr_row(max_periods=16000, **kw)
    assert long["status"] == "averaged"
    pf, pn = long["period_integrals"]
    assert np.array_equal(pf[:4000], r["period_integrals"][0])  # the same motion
    truth, spread = averaged_row(pf, pn)
    assert abs(r["mu_ratio"] - truth) <= r["error"] + spread
    # the earlier rule on the same periods
    old = np.sum(pf[3900:4000]) / np.sum(pn[3900:4000])
    old_err = abs(np.sum(pf[3900:3950]) / np.sum(pn[3900:3950])
                  - np.sum(pf[3950:4000]) / np.sum(pn[3950:4000]))
    assert abs(old - truth) > 3.0 * (old_err + spread)
