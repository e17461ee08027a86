"""Parameter atlases: labelled sweeps over grids, a resumable store, all cores, Dask.

>>> import numpy as np
>>> from vibrofriction.sweep import sweep
>>> atlas = sweep(alpha=[0.01, 0.1], beta=2.0, amplitude=0.5,
...               vbar=np.linspace(0, 1.2, 13), workers=1, progress=False)
>>> atlas.mu_ratio.dims
('alpha', 'vbar')

The module itself is callable (``vibrofriction.sweep(...)`` is :func:`sweep`).
See ``docs/sweeps.md`` for the store layout, resume semantics and Dask clusters;
:func:`vibrofriction.figures.plot_atlas` draws an atlas.
"""

from __future__ import annotations

import os
import sys
import types
from typing import Any

import numpy as np
import xarray as xr
from numpy.typing import ArrayLike

from ..parallel import available_cores
from ..solver import SolverSettings
from ._compute import compute_block, identity, warm_up
from ._grid import Plan, auto_chunk_size, check_methods, make_plan, parse_axis
from ._run import check_executor, run_blocks
from ._store import MemorySink, open_atlas, open_sink
from ._variables import STATUS_PENDING

__all__ = ["STATUS_PENDING", "Plan", "auto_chunk_size", "available_cores", "compute_block",
           "fingerprint", "identity", "make_plan", "open_atlas", "parse_axis", "sweep",
           "warm_up"]


def fingerprint() -> str:
    """The hash of the source code that computes a sweep's values.

    A store records it, so that it is never resumed with another solver (see
    :func:`identity`).

    Returns
    -------
    str
        16 hexadecimal digits.

    Examples
    --------
    >>> from vibrofriction.sweep import fingerprint
    >>> len(fingerprint())
    16
    """
    return identity()[1]


def sweep(
    system: Any = None,
    *,
    alpha: ArrayLike | None = None,
    beta: ArrayLike | None = None,
    amplitude: ArrayLike | None = None,
    zeta: ArrayLike | None = None,
    eta_c: ArrayLike | None = None,
    a_x: ArrayLike | None = None,
    phase_x: ArrayLike | None = None,
    a_y: ArrayLike | None = None,
    phase_y: ArrayLike | None = None,
    profile_exponent: ArrayLike | None = None,
    static_ratio: ArrayLike | None = None,
    rs_a: ArrayLike | None = None,
    rs_b: ArrayLike | None = None,
    rs_d_c: ArrayLike | None = None,
    rs_v_ref: ArrayLike | None = None,
    rs_alpha_ld: ArrayLike | None = None,
    inplane_on: str | None = None,
    rs_law: str | None = None,
    vbar: ArrayLike | None = None,
    v_inertial: ArrayLike | None = None,
    v0: ArrayLike | None = None,
    store: str | os.PathLike | None = None,
    client: Any = None,
    workers: int | None = None,
    chunk_size: int | None = None,
    settings: SolverSettings | None = None,
    initial: str = "sliding",
    continuation: bool | str = False,
    progress: bool = True,
    overwrite: bool = False,
    **physical: ArrayLike,
) -> xr.Dataset:
    """Steady-state friction ``mu_macro/mu0`` (eq. 25) over a grid of parameters.

    Every parameter given as a 1-D array or list is swept (one dimension of the
    result, in the order ``alpha, beta, amplitude`` then the velocity); a scalar is
    held fixed (a scalar coordinate).  The grid is the outer product of the axes.

    Parameters
    ----------
    system : Dimensionless or Physical, optional
        The base values. A :class:`~vibrofriction.params.Dimensionless` (``alpha``,
        ``beta``, ``amplitude`` keywords override it) or a
        :class:`~vibrofriction.params.Physical` system, swept over any of its SI fields
        passed as keywords (``mass=..., k_x=..., k_xc=..., k_zc=..., u_z0=...,
        du_z=..., omega=..., mu0=..., c_x=..., c_xc=..., du_x=..., phase_x=...,
        mu_static=...``, and of its rate-and-state law ``friction_a=...,
        friction_b=..., friction_d_c=..., friction_v_ref=..., friction_alpha_ld=...``)
        and the velocity ``v0`` (m/s).
    alpha, beta, amplitude : array_like, optional
        Eq. (20) and ``a = du_z/u_z0``; ``beta = inf`` is a rigid contact.
        ``beta > alpha`` must hold at every grid point.
    zeta, eta_c : array_like, optional
        The pin's damping ratio and the contact's loss factor (docs/damping.md); default
        the system's, or 0. Physical systems sweep ``c_x``, ``c_xc`` (N s/m).
    a_x, phase_x : array_like, optional
        The longitudinal in-plane oscillation ``a_x cos(tau + phase_x)``
        (docs/inplane.md); default the system's, or 0. Physical systems sweep ``du_x``
        (m) and ``phase_x`` (rad).
    a_y, phase_y : array_like, optional
        The transverse in-plane oscillation ``a_y cos(tau + phase_y)`` (the 2-D solver,
        docs/inplane.md section 6); default the system's, or 0. Physical systems sweep
        ``du_y`` (m) and ``phase_y`` (rad).
    profile_exponent : array_like, optional
        The exponent ``n`` of the tip ``z = c r^n`` (docs/contact_geometry.md; the same
        in SI and scaled form); default the system's, or ``inf`` (the flat punch).
        Points with a finite ``n`` are solved by the MDR solver, point by point (a
        tenth of a second to seconds each), from steady sliding (no continuation), on
        the ``v_inertial`` or ``v0`` axis (``vbar`` is not defined for them yet), and
        not with ``eta_c``, ``a_y`` > 0 (refused before any work), ``a_x > 0`` at
        ``V = 0`` or ``beta = inf`` (a ValueError when solved); their
        ``critical_velocity`` is ``theory.profile_critical_velocity`` (nan with
        ``eta_c``, ``a_x`` or ``a_y`` > 0: not derived). In a physical sweep the other SI
        fields are held, so ``F_N0 = k_zc u_z0 n/(n + 1)`` changes with
        ``n`` (:class:`~vibrofriction.params.Physical`): not the same tip seen flat.
    static_ratio : array_like, optional
        ``mu_static/mu0 >= 1``, the static coefficient of friction over the kinetic one
        (docs/friction_laws.md); default the system's, or 1 (Coulomb friction). Physical
        systems sweep ``mu_static`` (None: ``mu0``).
    rs_a, rs_b, rs_d_c, rs_v_ref, rs_alpha_ld : array_like, optional
        Rate-and-state friction in the model's units (docs/friction_laws.md); default the
        system's, or ``rs_a = 0`` (Coulomb friction). The pairs the model refuses
        (``rs_b > 0`` or ``rs_alpha_ld > 0`` with ``rs_a = 0``, ``rs_alpha_ld > 0`` with
        ``rs_b = 0`` or ``amplitude >= 1``, ``static_ratio > 1`` with ``rs_a > 0``) are
        refused anywhere in the grid, before any work; so are a law no solver of the
        grid takes, ``vbar`` and continuation with ``rs_a > 0``. A rate-and-state
        row's ``critical_velocity`` is nan (eq. 12 is Coulomb's); a static coefficient
        keeps the Coulomb one (a sliding contact carries the kinetic force). Physical
        systems sweep the SI parameters of their ``friction=RateAndState(...)`` as
        ``friction_a`` ... ``friction_alpha_ld`` (held at the law's values unless given;
        its ``law`` is the grid's ``rs_law``), and the scaled ``rs_*`` of each row
        (:meth:`~vibrofriction.Physical.friction_fields`) are coordinates of the atlas.
    inplane_on : {"substrate", "holder"}, optional
        Where the in-plane oscillation is imposed (one for the whole grid); default the
        system's, or ``"substrate"``.
    rs_law : {"aging", "slip"}, optional
        The state's evolution law of rate-and-state friction (one for the whole grid);
        default the system's (its ``friction.law`` for a Physical system, which needs
        one), or ``"aging"``.
    vbar, v_inertial : array_like, optional
        The velocity axis, exactly one of: ``v0/v0*`` (eq. 16; does not exist where
        ``alpha == 1``, ``beta == 1`` or ``amplitude == 0``, nor with an in-plane
        oscillation) or the inertial velocity ``v0 m omega/(mu0 F_N0)`` (Fig. 6;
        signed: negative slides the other way).
    v0 : array_like, optional
        The velocity in m/s (Physical systems; signed).
    store : str or os.PathLike, optional
        The path of a zarr store. Each finished block is written as soon as it is
        done; calling again with the same arguments resumes, recomputing only
        unfinished blocks. A store made for another grid, other settings, another
        initial state, package version or solver source is an error. None (default):
        the results stay in memory.
    client : dask.distributed.Client, optional
        Run the blocks on its cluster.
    workers : int, optional
        Local processes (default: all cores available); 1 runs in this process.
        Workers die with the process that started them, even when it is killed
        (:mod:`vibrofriction.parallel`).
    chunk_size : int, optional
        About how many points make a block of work (and a zarr chunk); None (default):
        about 1 % of the grid, from 1000 to 10,000 points (:func:`auto_chunk_size`). An
        existing store keeps its own block shape.
    settings : vibrofriction.SolverSettings, optional
        The solver's settings (:class:`~vibrofriction.SolverSettings`), recorded in the
        attributes.
    initial : {"sliding", "rest"}, optional
        The start of every point (docs/model.md), or with continuation of the first
        point of each upward sweep.
    continuation : bool or {"up", "both"}, optional
        Walk each velocity curve up and then down (True or ``"both"``), or only up
        (``"up"``), every point starting from the final state of the previous one
        (hysteresis, coexisting steady states: the branch a slow sweep of the speed
        follows); adds a ``direction`` dimension (``up``, ``down``, or ``up`` alone).
        The velocity axis must be swept and increasing. Each point starts near its
        orbit, so a continuation costs less a solve than independent starts
        (docs/sweeps.md).
    progress : bool, optional
        Show a progress bar (points done, rate, time left) on stderr.
    overwrite : bool, optional
        Replace an existing store instead of resuming it.
    **physical : array_like
        The SI fields of a :class:`~vibrofriction.params.Physical` ``system`` to sweep.

    Returns
    -------
    xarray.Dataset
        ``mu_ratio``, ``status`` (codes with ``flag_values``/``flag_meanings``),
        ``error``, ``trusted`` (converged status and ``error <= tol_trusted``, the
        package's one notion, :meth:`~vibrofriction.solver.SolverSettings.trusted`),
        ``period``, ``periods``, ``events``, the stick/slip/reverse-slip/flight
        fractions, the orbit's ``multiplier``, ``settling_periods``, ``window_min``,
        ``window_max``, ``v_inertial``, the final section
        state, and ``critical_velocity`` (eq. 12) over the non-velocity parameters;
        units, long names and symbols in the attributes, package version and solver
        settings (``solver_tol_trusted``, ...) in the Dataset's attributes.  With a
        store the Dataset is opened lazily from it.

    Results are bitwise identical however the work is split (one process, local
    cores, a Dask cluster, any ``chunk_size``): each point depends on its own
    parameters only.

    Raises
    ------
    ValueError
        Before any work, for a bad grid.

    Examples
    --------
    Below the critical velocity (``vbar = 1``, eq. 16) the oscillation lowers the
    friction; at it the friction is back to ``mu0``:

    >>> import vibrofriction as vf
    >>> atlas = vf.sweep(alpha=0.1, beta=2.0, amplitude=0.5, vbar=[0.25, 0.5, 1.0],
    ...                  workers=1, progress=False)
    >>> atlas.mu_ratio.values
    array([0.57195311, 0.58754462, 1.        ])
    >>> bool(atlas.trusted.all())
    True
    """
    version, fingerprint = identity()
    plan = make_plan(system=system, alpha=alpha, beta=beta, amplitude=amplitude, zeta=zeta,
                     eta_c=eta_c, a_x=a_x, phase_x=phase_x, a_y=a_y, phase_y=phase_y,
                     profile_exponent=profile_exponent, static_ratio=static_ratio, rs_a=rs_a,
                     rs_b=rs_b, rs_d_c=rs_d_c, rs_v_ref=rs_v_ref, rs_alpha_ld=rs_alpha_ld,
                     inplane_on=inplane_on, rs_law=rs_law, vbar=vbar,
                     v_inertial=v_inertial, v0=v0, physical=physical, settings=settings,
                     initial=initial, continuation=continuation, chunk_size=chunk_size,
                     version=version, fingerprint=fingerprint)
    check_methods(plan)
    check_executor(client, workers)
    if store is None:
        sink: Any = MemorySink(plan)
    else:
        sink, _bad = open_sink(store, plan, overwrite=overwrite)
        plan = sink.plan
    try:
        todo = [int(b) for b in np.flatnonzero(~sink.done)]
        done_points = sum(plan.block_size(int(b)) for b in np.flatnonzero(sink.done))
        run_blocks(plan, todo, sink.write, client=client, workers=workers,
                   progress=progress, initial_points=done_points)
    finally:
        sink.close()
    return sink.dataset()


class _CallableModule(types.ModuleType):
    """``vibrofriction.sweep(...)`` calls :func:`sweep`; the module stays a module."""

    def __call__(self, *args: Any, **kwargs: Any) -> xr.Dataset:
        return sweep(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
