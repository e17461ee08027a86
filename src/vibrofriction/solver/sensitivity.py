r"""Parameter sensitivities of the steady state: ``d mu_ratio / d theta`` (issue 19).

For a periodic orbit the implicit function theorem on the period map gives
``dz*/dtheta = (I - J)^{-1} P_theta`` and ``dmu/dtheta = (G . dz*/dtheta + F_theta -
mu N_theta) / N`` (docs/solver.md, "Parameter sensitivities";
:mod:`vibrofriction._kernels.sensitivity`): the state part ``J``, ``G`` is exact, the
explicit parameter part by central differences of the exact period map at fixed ``z*``.
A proven continuous sliding has ``mu_ratio = +-1`` identically (derivative 0).  Other
statuses (averaged, not converged, failed, held, static), neutral orbits and points whose
difference crosses an event grazing have no sensitivity here (``nan``): the caller falls
back to differences of the full solver (:func:`solve_points`) there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._kernels.sensitivity import REL_STEP, orbit_sensitivity_many
from ..params import Dimensionless, System, dimensionless, inertial_velocity
from ..schema import Status
from .engine import Initial, _mirror_rows, solve_points
from .methods.event import event_arguments
from .results import FrictionResult, result_from_columns
from .settings import DEFAULT_SETTINGS, SolverSettings

__all__ = ["SENSITIVE", "Sensitivities", "friction_gradient", "sensitivities",
           "solve_gradients"]

#: The parameters differentiated, in the order of :func:`solve_points`' arguments.
SENSITIVE = ("alpha", "beta", "amplitude", "v_inertial", "zeta", "eta_c", "a_x", "phase_x")
_V, _AX, _PX = SENSITIVE.index("v_inertial"), SENSITIVE.index("a_x"), SENSITIVE.index("phase_x")


@dataclass(frozen=True)
class Sensitivities:
    """Derivatives of the steady state at a batch of points.

    ``mu[name]``: ``d mu_ratio / d name`` (the shape of the points); ``state[name]``:
    ``d (y, x_dot, e) / d name`` of the orbit's section state in the laboratory frame
    (shape ``+ (3,)``; ``nan`` for a sliding point); ``flags``: the kernel's flags
    (:mod:`vibrofriction._kernels.sensitivity`; 0 where every derivative is formed).
    ``nan`` marks what this route cannot give (see the module doc).
    """

    mu: dict[str, NDArray[np.float64]]
    state: dict[str, NDArray[np.float64]]
    flags: NDArray[np.int64]

    @property
    def available(self) -> NDArray[np.bool_]:
        """Points whose every ``mu`` derivative is finite."""
        return np.all([np.isfinite(v) for v in self.mu.values()], axis=0)


def solve_gradients(
    alpha: ArrayLike,
    beta: ArrayLike,
    amplitude: ArrayLike,
    v_inertial: ArrayLike,
    zeta: ArrayLike = 0.0,
    eta_c: ArrayLike = 0.0,
    a_x: ArrayLike = 0.0,
    phase_x: ArrayLike = 0.0,
    *,
    inplane_on: str = "substrate",
    initial: Initial = "sliding",
    settings: SolverSettings | None = None,
    rel_step: float = REL_STEP,
    order: int = 4,
    parameters: tuple[str, ...] = SENSITIVE,
) -> tuple[dict[str, NDArray], Sensitivities]:
    """:func:`solve_points` and the sensitivities of its answers to the parameters.

    No transverse oscillation; the eight parameters :data:`SENSITIVE`.  ``V < 0`` is
    differentiated through the mirror of :func:`solve_points` (``mu(V, phase_x) =
    -mu(-V, phase_x + pi)``).

    Parameters
    ----------
    alpha, beta, amplitude, v_inertial, zeta, eta_c, a_x, phase_x : array_like
        The points, broadcast together, as for :func:`solve_points`.
    inplane_on : str, keyword-only
        ``"substrate"`` (default) or ``"holder"``.
    initial : str or SectionState, keyword-only
        The initial state, as for :func:`solve_points`.
    settings : SolverSettings or None, keyword-only
        Accuracy and effort bounds; None the defaults.
    rel_step : float, keyword-only
        The central differences' step of the explicit parameter part, relative to each
        parameter's scale.
    order : int, keyword-only
        4 (``+-h``, ``+-2h``, the default) or 2 (half the cost; off by up to ~1e-4
        relative where the map at fixed ``z*`` bends).
    parameters : tuple of str, keyword-only
        Those differentiated (the others are ``nan``); names of :data:`SENSITIVE`.

    Returns
    -------
    columns : dict of str to ndarray
        The named output columns of :func:`solve_points`.
    sensitivities : Sensitivities
        Their derivatives in the parameters.

    Raises
    ------
    ValueError
        An ``order`` other than 2 or 4, a name not in :data:`SENSITIVE`, or what
        :func:`solve_points` refuses.
    """
    settings = settings or DEFAULT_SETTINGS
    cols = solve_points(alpha, beta, amplitude, v_inertial, zeta, eta_c, a_x, phase_x,
                        inplane_on=inplane_on, initial=initial, settings=settings)
    return cols, sensitivities(cols, alpha, beta, amplitude, v_inertial, zeta, eta_c, a_x,
                               phase_x, inplane_on=inplane_on, settings=settings,
                               rel_step=rel_step, order=order, parameters=parameters)


def sensitivities(
    cols: dict[str, NDArray],
    alpha: ArrayLike,
    beta: ArrayLike,
    amplitude: ArrayLike,
    v_inertial: ArrayLike,
    zeta: ArrayLike = 0.0,
    eta_c: ArrayLike = 0.0,
    a_x: ArrayLike = 0.0,
    phase_x: ArrayLike = 0.0,
    *,
    inplane_on: str = "substrate",
    settings: SolverSettings | None = None,
    rel_step: float = REL_STEP,
    order: int = 4,
    parameters: tuple[str, ...] = SENSITIVE,
) -> Sensitivities:
    """The sensitivities of the answers ``cols`` of :func:`solve_points` at these points.

    The same arguments as :func:`solve_gradients`.
    """
    settings = settings or DEFAULT_SETTINGS
    if order not in (2, 4):
        raise ValueError(f"order must be 2 or 4, got {order!r}")
    unknown = set(parameters) - set(SENSITIVE)
    if unknown:
        raise ValueError(f"parameters must be among {SENSITIVE}, got {sorted(unknown)}")
    want = np.array([k in parameters for k in SENSITIVE])
    shape = cols["mu_ratio"].shape
    al, be, am, V, ze, et, ax, px = (np.ascontiguousarray(np.broadcast_to(
        np.asarray(x, dtype=float), shape).ravel())
        for x in (alpha, beta, amplitude, v_inertial, zeta, eta_c, a_x, phase_x))
    n = V.size
    status = cols["status"].ravel()
    periodic = (status == Status.PERIODIC.code) & (V != 0.0)
    backward = V < 0.0
    # the orbit's state, mirrored back where V < 0 (the kernels solved -V, phase_x + pi)
    state = np.column_stack([cols[k].ravel() for k in ("y", "x_dot", "e")]
                            + [cols["phase"].ravel().astype(float)])
    _mirror_rows(state, backward)
    Vk = np.abs(V)
    pxk = np.where(backward, px + math.pi, px)
    on_substrate = inplane_on == "substrate"
    dmu = np.full((n, len(SENSITIVE)), np.nan)
    dz = np.full((n, len(SENSITIVE), 3), np.nan)
    flags = np.zeros(n, dtype=np.int64)
    period = np.where(periodic, cols["period"].ravel(), 0).astype(np.int64)
    if np.any(periodic):
        orbit_sensitivity_many(al, be, am, Vk, ze, et, ax, pxk, np.full(n, on_substrate),
                               np.ascontiguousarray(state), period, event_arguments(settings)[4],
                               float(rel_step), order, want, dmu, dz, flags)
        if on_substrate:  # the laboratory frame: y + X, x' + X' with X = a_x cos(tau + px)
            dz[:, _AX, 0] += np.cos(pxk)
            dz[:, _AX, 1] -= np.sin(pxk)
            dz[:, _PX, 0] -= ax * np.sin(pxk)
            dz[:, _PX, 1] -= ax * np.cos(pxk)
    flags[~periodic] = -1
    sliding = status == Status.SLIDING.code
    dmu[np.ix_(sliding, want)] = 0.0  # mu_ratio = +-1 identically
    # the mirror: mu = -mu'(-V, phase_x + pi), state = -state'
    chain = np.where(backward, -1.0, 1.0)[:, None] * np.ones(len(SENSITIVE))
    chain[backward, _V] = 1.0
    dmu *= chain
    dz *= chain[:, :, None]
    mu = {k: dmu[:, j].reshape(shape) for j, k in enumerate(SENSITIVE)}
    st = {k: dz[:, j].reshape(shape + (3,)) for j, k in enumerate(SENSITIVE)}
    return Sensitivities(mu, st, flags.reshape(shape))


def friction_gradient(
    system: System,
    vbar: float | None = None,
    *,
    v_inertial: float | None = None,
    v0: float | None = None,
    initial: Initial = "sliding",
    settings: SolverSettings | None = None,
) -> tuple[FrictionResult, dict[str, float]]:
    """The friction coefficient at one point and its gradient in the parameters.

    :func:`~vibrofriction.solver.friction_coefficient` and ``d mu_ratio / d name`` for the
    parameters :data:`SENSITIVE` of its :class:`Dimensionless` system (``nan`` where this route has
    none: see the module doc).

    Parameters
    ----------
    system : Dimensionless or Physical
        The system: no transverse oscillation, a flat punch.
    vbar, v_inertial, v0 : float
        The sliding velocity, exactly one of them, as for :func:`friction_coefficient`.
    initial : str or SectionState, keyword-only
        The initial state, as for :func:`friction_coefficient`.
    settings : SolverSettings or None, keyword-only
        Accuracy and effort bounds; None the defaults.

    Returns
    -------
    result : FrictionResult
        The result at the point.
    gradient : dict of str to float
        ``d mu_ratio / d name`` for each name of :data:`SENSITIVE`.

    Raises
    ------
    ValueError
        A transverse oscillation (``a_y > 0``), a curved tip, a static coefficient above
        the kinetic one (``static_ratio > 1``), rate-and-state friction (``rs_a > 0``), or
        the velocities as for :func:`friction_coefficient`.
    """
    dim: Dimensionless = dimensionless(system)
    if dim.a_y != 0.0:
        raise ValueError(f"friction_gradient covers the 1-D solver only: a_y must be 0, "
                         f"got {dim.a_y!r}")
    if dim.profile_exponent != math.inf:
        raise ValueError(f"friction_gradient covers the flat punch only: profile_exponent "
                         f"must be inf, got {dim.profile_exponent!r}")
    for name, coulomb in (("static_ratio", 1.0), ("rs_a", 0.0)):
        # the parameter differences of the period map (module doc) take Coulomb's law
        if getattr(dim, name) != coulomb:
            raise ValueError(f"friction_gradient covers Coulomb friction only: {name} must be "
                             f"{coulomb:g}, got {getattr(dim, name)!r}")
    V = float(inertial_velocity(system, vbar, v_inertial=v_inertial, v0=v0))
    cols, sens = solve_gradients(dim.alpha, dim.beta, dim.amplitude, V, dim.zeta, dim.eta_c,
                                 dim.a_x, dim.phase_x, inplane_on=dim.inplane_on,
                                 initial=initial, settings=settings)
    result = result_from_columns({k: v[()].item() for k, v in cols.items()}, dim, V)
    return result, {k: float(v) for k, v in sens.mu.items()}
