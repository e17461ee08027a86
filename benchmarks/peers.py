"""The two peer integrators the event-driven solver is benchmarked against.

Thin wrappers over :mod:`vibrofriction_reference` with the period counts used
for benchmarking (see ``benchmarks/README.md`` for why these counts):

* ``peer_a`` -- :func:`vibrofriction_reference.solve_ivp_mu`: scipy ``solve_ivp``
  (DOP853, rtol 1e-10, atol 1e-12) phase by phase with terminal events;
  200 transient + 20 averaging drive periods.
* ``peer_b`` -- :func:`vibrofriction_reference.return_mapping_mu`: numba
  fixed-step velocity Verlet + Jenkins return mapping (Moreau time-stepping for
  a rigid contact); 200 transient + 50 averaging drive periods.

Both start from the default "sliding" initial state of docs/model.md and return
``mu_macro / mu0``.
"""

from __future__ import annotations

from vibrofriction_reference import return_mapping_mu, solve_ivp_mu

__all__ = [
    "PEER_A_AVERAGE_PERIODS",
    "PEER_A_TRANSIENT_PERIODS",
    "PEER_B_AVERAGE_PERIODS",
    "PEER_B_TRANSIENT_PERIODS",
    "peer_a",
    "peer_b",
    "warm_up",
]

PEER_A_TRANSIENT_PERIODS = 200
PEER_A_AVERAGE_PERIODS = 20
PEER_B_TRANSIENT_PERIODS = 200
PEER_B_AVERAGE_PERIODS = 50


def peer_a(
    alpha: float,
    beta: float,
    a: float,
    V: float,
    transient_periods: int = PEER_A_TRANSIENT_PERIODS,
    average_periods: int = PEER_A_AVERAGE_PERIODS,
    rtol: float = 1e-10,
    atol: float = 1e-12,
) -> float:
    """Peer A: ``solve_ivp`` with events, ``mu_macro / mu0``."""
    return solve_ivp_mu(alpha, beta, a, V, transient_periods, average_periods, rtol, atol)


def peer_b(
    alpha: float,
    beta: float,
    a: float,
    V: float,
    steps_per_period: float = 400,
    transient_periods: int = PEER_B_TRANSIENT_PERIODS,
    average_periods: int = PEER_B_AVERAGE_PERIODS,
    zeta: float = 0.0,
    eta_c: float = 0.0,
) -> float:
    """Peer B: numba fixed-step return mapping, ``mu_macro / mu0``.

    ``steps_per_period`` counts steps per period of the fastest oscillation
    (drive, ``sqrt(alpha)`` or ``sqrt(beta)``); ``zeta``, ``eta_c``: the dashpots
    (docs/damping.md; the damped scheme when either is nonzero).
    """
    return return_mapping_mu(
        alpha, beta, a, V, steps_per_period, transient_periods, average_periods,
        zeta=zeta, eta_c=eta_c,
    )


def warm_up() -> None:
    """Compile (or load from the numba cache) peer B's kernels before timing."""
    return_mapping_mu(0.5, 2.0, 0.5, 0.3, 50, 1, 1)
    return_mapping_mu(0.5, float("inf"), 0.5, 0.3, 50, 1, 1)
