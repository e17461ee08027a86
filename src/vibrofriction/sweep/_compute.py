"""The work of one block: runs in the calling process, a local worker or a Dask worker.

Every point is solved by :func:`vibrofriction.solver.solve_points` from its own
parameters only, so a block's values do not depend on which other points share
its call: results are bitwise identical however the grid is split.  With
continuation each row (one velocity curve) is walked up and then down in
velocity, every point starting from the final section state of the previous
one; rows are independent of each other.
"""

from __future__ import annotations

import functools
import hashlib
import math
from collections.abc import Callable
from pathlib import Path

import numpy as np

from .. import theory
from ..params import Dimensionless, inertial_velocity
from ..solver import solve_points
from ..solver.engine import solve_chain
from ..solver.points import point_table
from ._grid import DIMENSIONLESS, Plan, physical_system
from ._variables import point_variables, row_variables

#: The parameters of the critical velocity of continuous sliding (the same for a static
#: coefficient above the kinetic one: a sliding contact has the kinetic force).
CRITICAL_ARGUMENTS = ("alpha", "beta", "amplitude", "zeta", "eta_c", "a_x", "phase_x")

__all__ = ["compute_block", "identity", "warm_up"]

#: the source files that determine the values of a sweep (relative to the package)
_VALUE_SOURCES = ("_kernels/*.py", "solver/*.py", "solver/methods/*.py", "schema/*.py",
                  "capabilities.py", "params/*.py", "theory/*.py", "sweep/_compute.py",
                  "sweep/_grid.py")  # _grid: a physical row's system (physical_system)


@functools.cache
def identity() -> tuple[str, str]:
    """What a sweep's values depend on: the package version and the solver's source.

    The fingerprint hashes the source code that computes the values, so a store is never resumed,
    nor a Dask worker used, with a solver that differs from the one that started (even under the
    same version).

    Returns
    -------
    tuple of (str, str)
        ``(package version, fingerprint)``; the fingerprint is 16 hexadecimal digits.

    Examples
    --------
    >>> import vibrofriction
    >>> from vibrofriction.sweep import identity
    >>> version, fingerprint = identity()
    >>> version == vibrofriction.__version__, len(fingerprint)
    (True, 16)
    """
    from .. import __version__

    root = Path(__file__).resolve().parents[1]
    digest = hashlib.sha256()
    for pattern in _VALUE_SOURCES:
        for path in sorted(root.glob(pattern)):
            digest.update(path.relative_to(root).as_posix().encode())
            digest.update(path.read_bytes())
    return __version__, digest.hexdigest()[:16]


def warm_up() -> None:
    """Load the compiled kernels (from numba's on-disk cache, or compile and cache them).

    Each worker process of a sweep runs it first, so that no block pays for it: the
    ``flat`` part of :func:`vibrofriction.warmup.warm_up`.

    Examples
    --------
    >>> from vibrofriction.sweep import warm_up
    >>> warm_up()
    """
    from ..warmup import warm_up as compile_parts

    compile_parts(["flat"], workers=1, progress=False)


def _rows(plan: Plan, block: int) -> dict[str, np.ndarray]:
    """The non-velocity parameters of a block, broadcast over its row shape."""
    sl = plan.row_slices(block)
    k = 0
    arrays = {}
    swept = [a for a in plan.params if a.swept]
    shape = tuple(s.stop - s.start for s in sl)
    for a in plan.params:
        if a.swept:
            idx: list[slice | None] = [None] * len(shape)
            idx[k] = slice(None)
            arrays[a.name] = np.broadcast_to(a.values[sl[k]][tuple(idx)], shape)
            k += 1
        else:
            arrays[a.name] = np.broadcast_to(a.values, shape)
    assert k == len(swept)
    return arrays


def _velocity_values(plan: Plan, block: int) -> np.ndarray:
    v = plan.velocity
    if not v.swept:
        return np.asarray(v.values).reshape(1)
    return v.values[plan.block_slices(block)[-1]]


def _dimensionless_rows(plan: Plan, block: int, vel: np.ndarray):
    """The parameters and velocities of the rows of a block.

    The dimensionless parameters per row (by name, in the schema's order), the row
    variables and ``V`` per (row, velocity).
    """
    p = _rows(plan, block)
    point = {n: p[n] for n in DIMENSIONLESS}
    shape = p["alpha"].shape
    # V at vbar = 1, eq. (12) damped: also where vbar does not exist (inf, 0)
    plain = {n: x for n, x in point.items() if n in CRITICAL_ARGUMENTS}
    critical = np.array(theory.critical_inertial_velocity(**plain, inplane_on=plan.inplane_on),
                        dtype=float).reshape(shape)
    # a transverse oscillation: no continuous sliding at full friction (docs/inplane.md)
    critical = np.where(np.asarray(point["a_y"]).reshape(shape) > 0.0, np.inf, critical)
    critical = _coulomb_only(critical, np.asarray(point["rs_a"]).reshape(shape) > 0.0)
    V = np.empty((*shape, vel.size))
    for i in np.ndindex(shape):
        system = Dimensionless(**{n: float(x[i]) for n, x in point.items()},  # type: ignore[arg-type]
                               inplane_on=plan.inplane_on, rs_law=plan.rs_law)
        V[i] = inertial_velocity(system, **{plan.velocity.name: vel})
        if system.curved:
            critical[i] = _curved_critical(system.critical_inertial_velocity)
    return point, {"critical_velocity": critical}, V


def _coulomb_only(critical: np.ndarray, rate_state: np.ndarray | bool) -> np.ndarray:
    """The critical velocity, nan where the friction is rate-and-state (eq. 12 is Coulomb's).

    A static coefficient above the kinetic one keeps it: a sliding contact carries the
    kinetic force, so continuous sliding sets in where it does with Coulomb friction.
    """
    return np.where(rate_state, np.nan, critical)


def _curved_critical(critical: Callable[[], float]) -> float:
    """A curved profile's critical velocity, nan where it is not derived.

    A curved profile's critical velocity (``theory.profile_critical_velocity``), nan
    where it is not derived (``eta_c``, ``a_x`` or ``a_y`` > 0: the system refuses by
    name, docs/contact_geometry.md).
    """
    try:
        return critical()
    except ValueError:
        return math.nan


def _physical_rows(plan: Plan, block: int, vel: np.ndarray):
    p = _rows(plan, block)
    shape = p["mass"].shape
    point = {n: np.empty(shape) for n in DIMENSIONLESS}
    V = np.empty((*shape, vel.size))
    vstar = np.empty(shape)
    for i in np.ndindex(shape):
        system = physical_system({name: float(arr[i]) for name, arr in p.items()}
                                 | {"inplane_on": plan.inplane_on}, plan.friction)
        dim = system.to_dimensionless()
        for n, x in point.items():
            x[i] = getattr(dim, n)
        V[i] = inertial_velocity(system, **{plan.velocity.name: vel})
        vstar[i] = _curved_critical(system.critical_velocity) if system.curved \
            else system.critical_velocity()
    vstar = _coulomb_only(vstar, plan.friction is not None)
    return point, {"critical_velocity": vstar, **point}, V


def _continuation(point, V, plan: Plan) -> dict[str, np.ndarray]:
    """Solve each row up (then down) in velocity; shape ``(*rows, directions, n_velocity)``.

    The block is validated once (:func:`~vibrofriction.solver.points.point_table`) and
    its rows' solves run as one chain (:func:`~vibrofriction.solver.engine.solve_chain`):
    each from the final state of the one before, each row's first from ``plan.initial``.
    """
    rshape, nv = V.shape[:-1], V.shape[-1]
    nd = len(plan.directions)
    order = np.concatenate([np.arange(nv), np.arange(nv - 1, -1, -1)][:nd])
    table = point_table({**{n: np.broadcast_to(x[..., None], V.shape).ravel()
                            for n, x in point.items()}, "v_inertial": V.ravel(),
                         "inplane_on": plan.inplane_on, "rs_law": plan.rs_law})
    rows = int(np.prod(rshape))
    restart = np.zeros((rows, nd * nv), dtype=bool)
    restart[:, 0] = True  # each row from plan.initial
    cols = solve_chain(table.take((np.arange(rows)[:, None] * nv + order).ravel()),
                       plan.initial, plan.settings, restart.ravel())
    out: dict[str, np.ndarray] = {}
    for k, v in cols.items():
        w = v.reshape(*rshape, nd * nv)
        out[k] = np.stack([w[..., :nv], w[..., nv:][..., ::-1]][:nd], axis=-2)
    return out


def compute_block(plan: Plan, block: int) -> tuple[int, dict[str, np.ndarray]]:
    """Solve every point of block number ``block``.

    The unit of work of :func:`sweep`, run in this process, a local worker or a Dask
    worker.

    Parameters
    ----------
    plan : Plan
        The grid (:func:`make_plan`).
    block : int
        The block's number, ``0 <= block < plan.n_blocks``.

    Returns
    -------
    tuple of (int, dict of str to numpy.ndarray)
        ``(block, variables)``: point variables have the block's shape, row variables
        the shape of its rows.

    Examples
    --------
    >>> from vibrofriction.sweep import compute_block, make_plan
    >>> plan = make_plan(alpha=0.1, beta=2.0, amplitude=0.5, vbar=[0.25, 0.5])
    >>> block, variables = compute_block(plan, 0)
    >>> variables["mu_ratio"]
    array([0.57195311, 0.58754462])
    """
    vel = _velocity_values(plan, block)
    if plan.kind == "physical":
        point, rows, V = _physical_rows(plan, block, vel)
    else:
        point, rows, V = _dimensionless_rows(plan, block, vel)
    if plan.continuation:
        cols = _continuation(point, V, plan)
        shape = V.shape[:-1] + (len(plan.directions), V.shape[-1])
        V = np.broadcast_to(V[..., None, :], shape)
    else:
        cols = solve_points(**{n: x[..., None] for n, x in point.items()}, v_inertial=V,
                            inplane_on=plan.inplane_on, rs_law=plan.rs_law,
                            initial=plan.initial, settings=plan.settings)
        shape = V.shape
    cols["v_inertial"] = V
    block_shape = tuple(s.stop - s.start for s in plan.block_slices(block))
    out: dict[str, np.ndarray] = {}
    for var in point_variables(plan.velocity.name):
        out[var.name] = np.asarray(cols[var.source or var.name]).reshape(shape).astype(
            var.dtype).reshape(block_shape)
    for var in row_variables(plan.kind):
        out[var.name] = np.asarray(rows[var.name]).astype(var.dtype)
    return block, out
