"""Differential tests: the exact solver against the independent fixed-step reference.

For seeded random points of every regime (``tests/reference_points.py``) the solver's
``mu_ratio`` must lie within its own stated ``error`` plus the reference's error bar
``err_ref`` of the reference value (eq. 25), for every result whose status claims a
value (periodic, continuous sliding, averaged). The reference
(:mod:`vibrofriction_reference`, peer B) shares no code with the solver; its error bar
covers its discretisation error and its transient/averaging error (see
``reference_points``).

Two jumping points above ``V*`` are included by name: the solver once claimed a proven
continuous sliding (``mu = 1``) there, while the truth is below 1.
"""

from __future__ import annotations

import pytest

import vibrofriction as vf
from reference_points import REGIMES, random_points, reference_mu, v_star

SEED = 2017
POINTS_PER_REGIME = 6
CLAIMS_A_VALUE = ("periodic", "continuous sliding", "averaged")

# (alpha, beta, a, vbar) as stated (3 decimals); V = vbar V* (eq. 12)
KNOWN_JUMPING = {
    "alpha10.5-a1.30": (10.467, 49.110, 1.302, 1.460),
    "alpha15.7-a2.76": (15.730, 56.390, 2.761, 1.314),
}


def inertial_point(alpha: float, beta: float, a: float, vbar: float):
    return alpha, beta, a, vbar * v_star(alpha, beta, a)


def disagreement(point: tuple[float, float, float, float]) -> str | None:
    """``None`` if the solver agrees with the reference at ``point`` (or claims no value),
    else a line saying by how much it does not."""
    alpha, beta, a, V = point
    r = vf.friction_coefficient(vf.Dimensionless(alpha, beta, a), v_inertial=V)
    if r.status.value not in CLAIMS_A_VALUE:
        return None
    mu_ref, err_ref = reference_mu(alpha, beta, a, V)
    allowed = max(r.error, 1e-9) + err_ref
    if abs(r.mu_ratio - mu_ref) <= allowed:
        return None
    return (f"alpha={alpha!r}, beta={beta!r}, a={a!r}, V={V!r}: solver {r.status.value} "
            f"mu={r.mu_ratio:.9f} (error {r.error:.2e}), reference mu={mu_ref:.9f} "
            f"(err {err_ref:.2e}); |difference| {abs(r.mu_ratio - mu_ref):.2e} > "
            f"allowed {allowed:.2e}")


@pytest.mark.parametrize("regime", REGIMES)
def test_solver_agrees_with_reference(regime):
    failures = [line for p in random_points(SEED, POINTS_PER_REGIME, regime)
                if (line := disagreement(p)) is not None]
    assert not failures, "\n".join(failures)


@pytest.mark.parametrize("point", list(KNOWN_JUMPING.values()), ids=list(KNOWN_JUMPING))
def test_solver_agrees_with_reference_at_known_jumping_points(point):
    line = disagreement(inertial_point(*point))
    assert line is None, line
