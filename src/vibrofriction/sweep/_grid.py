"""The grid of a sweep: parsing, validation before any work, chunking into blocks.

A grid is the outer product of one axis per *swept* parameter (a 1-D array or
list); parameters given as scalars are held fixed.  The velocity axis (``vbar``,
``v_inertial`` or, for a :class:`~vibrofriction.params.Physical` system, ``v0``)
always comes last, so that a block holds whole velocity curves whenever it can
(and always does with continuation).  With continuation a ``direction``
dimension (``up``, ``down``; ``up`` alone for the upward sweep) sits just before the
velocity.

A :class:`Plan` is everything that defines the result (grid, solver settings,
initial state, continuation) plus the block shape; :meth:`Plan.signature` is
what a store must match to be resumed.
"""

from __future__ import annotations

import dataclasses
import itertools
import json
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..capabilities import CAPABILITIES, Refusal
from ..params import Dimensionless, Physical, RateAndState
from ..schema import CHOICES, PARAMETER, PARAMETERS, choice_names, parameter_names
from ..solver import SolverSettings
from ..validation import checked_choice, validated
from ._axes import Axis, make_axis, parse_axis
from ._variables import signature as variables_signature

__all__ = [
    "DIMENSIONLESS",
    "PHYSICAL",
    "Axis",
    "Plan",
    "check_methods",
    "make_plan",
    "physical_system",
    "parse_axis",
]

# the optional parameters (the pin across the sliding, k_y, alpha_y, ...) are not swept
DIMENSIONLESS = parameter_names("dimensionless", optional=False)
PHYSICAL = parameter_names("physical", optional=False)
#: The static coefficient of a physical sweep: an SI axis when given (None: ``mu0``).
MU_STATIC = "mu_static"
#: The local friction law's parameters of the dimensionless model (docs/friction_laws.md),
#: and the one they are checked with at the grid's corners (``rs_alpha_ld`` needs
#: ``amplitude < 1``).
FRICTION_LAW = ("static_ratio", "rs_a", "rs_b", "rs_d_c", "rs_v_ref", "rs_alpha_ld")
_LAW_CORNERS = ("amplitude", *FRICTION_LAW)
#: The SI parameters of a physical sweep's rate-and-state law (the system's ``friction``):
#: axes ``friction_a`` ... (held at the law's values unless swept) where it has one.
_SI_LAW = ("a", "b", "d_c", "v_ref", "alpha_ld")
FRICTION_SI = tuple(f"friction_{n}" for n in _SI_LAW)
#: The parameters some solver refuses at every value but its default (a ``whole``
#: :class:`~vibrofriction.capabilities.Limit`): checked before any work.
_LIMITED = tuple(dict.fromkeys(lim.parameter for c in CAPABILITIES.values()
                               for lim in c.limits if lim.whole))
DIRECTIONS = ("up", "down")
#: The continuations a sweep can walk, by name: the directions of each velocity curve.
CONTINUATIONS = {"": (), "up": ("up",), "both": DIRECTIONS}
DEFAULT_CHUNK_SIZE = 1000
#: The block size when none is given: about 1/AUTO_BLOCKS of the grid, between
#: DEFAULT_CHUNK_SIZE and AUTO_MAX_CHUNK points.  Writing a block costs the sweep process
#: about 60 ms whatever its size (zarr's asynchronous writes of some 30 arrays), time
#: taken from the two workers: 1000-point blocks made a 10^6-point atlas 69 s where
#: 10,000-point ones make it 54 s (benchmarks/results/sweep.md); a hundred blocks still
#: balance the cores and show progress.
AUTO_BLOCKS = 100
AUTO_MAX_CHUNK = 10_000


# --------------------------------------------------------------------------- plan
def _hex(values: NDArray[np.float64]) -> str | list[str]:
    if values.ndim == 0:
        return float(values).hex()
    return [float(x).hex() for x in values]


@dataclass(frozen=True, eq=False)
class Plan:
    """A validated grid, what defines its results, and how it is cut into blocks.

    Made by :func:`make_plan` (never by hand); :func:`compute_block` solves one of its
    blocks.

    Parameters
    ----------
    kind : str
        ``"dimensionless"`` or ``"physical"``.
    params : tuple of Axis
        The non-velocity parameters, in the schema's order.
    velocity : Axis
        The velocity axis.
    settings : vibrofriction.SolverSettings
        The solver's settings.
    initial : str
        ``"sliding"`` or ``"rest"``.
    continuation : str
        How each velocity curve is walked (:data:`CONTINUATIONS`): ``""`` not at all
        (independent starts), ``"up"`` up, ``"both"`` up and then down.
    chunks : tuple of int
        The block shape over :attr:`dims`.
    version : str
        The package version.
    fingerprint : str, optional
        The hash of the solver's source (:func:`identity`).
    inplane_on : str, optional
        Where the in-plane oscillation is imposed.
    rs_law : str, optional
        The state's evolution law of rate-and-state friction, one for the grid.
    friction : RateAndState, optional
        A physical sweep's rate-and-state law in SI units (None: Coulomb friction): its
        ``law``; its parameters are the axes ``friction_a`` ... of :attr:`params`.

    Examples
    --------
    >>> from vibrofriction.sweep import make_plan
    >>> plan = make_plan(alpha=[0.01, 0.1], beta=2.0, amplitude=0.5,
    ...                  vbar=[0.0, 0.5, 1.0])
    >>> plan.dims, plan.shape, plan.n_blocks
    (('alpha', 'vbar'), (2, 3), 1)
    """

    kind: str  # "dimensionless" or "physical"
    params: tuple[Axis, ...]  # non-velocity parameters, canonical order
    velocity: Axis
    settings: SolverSettings
    initial: str
    continuation: str
    chunks: tuple[int, ...]  # block shape over `dims`
    version: str
    fingerprint: str = ""  # hash of the solver's source (see _compute.identity)
    inplane_on: str = "substrate"  # where the in-plane oscillation is imposed (schema.CHOICES)
    rs_law: str = "aging"  # the state's law of rate-and-state friction (schema.CHOICES)
    friction: RateAndState | None = None  # a physical sweep's rate-and-state law (SI)

    # ---- shape
    @property
    def directions(self) -> tuple[str, ...]:
        """The directions each velocity curve is walked in (none: independent starts)."""
        return CONTINUATIONS[self.continuation]

    @property
    def row_dims(self) -> tuple[str, ...]:
        return tuple(a.name for a in self.params if a.swept)

    @property
    def dims(self) -> tuple[str, ...]:
        extra = (("direction",) if self.continuation else ()) + (
            (self.velocity.name,) if self.velocity.swept else ())
        return self.row_dims + extra

    @property
    def row_shape(self) -> tuple[int, ...]:
        return tuple(len(a) for a in self.params if a.swept)

    @property
    def shape(self) -> tuple[int, ...]:
        extra = ((len(self.directions),) if self.continuation else ()) + (
            (len(self.velocity),) if self.velocity.swept else ())
        return self.row_shape + extra

    @property
    def size(self) -> int:
        return math.prod(self.shape)

    @property
    def fixed(self) -> dict[str, float]:
        out = {a.name: float(a.values) for a in self.params if not a.swept}
        if not self.velocity.swept:
            out[self.velocity.name] = float(self.velocity.values)
        return out

    def axis(self, name: str) -> Axis:
        for a in (*self.params, self.velocity):
            if a.name == name:
                return a
        raise KeyError(name)

    # ---- blocks
    @property
    def block_grid(self) -> tuple[int, ...]:
        return tuple(-(-n // c) for n, c in zip(self.shape, self.chunks, strict=True))

    @property
    def n_blocks(self) -> int:
        return math.prod(self.block_grid)

    def block_slices(self, block: int) -> tuple[slice, ...]:
        """Index of block number ``block`` (C order over :attr:`block_grid`) in the grid."""
        if not 0 <= block < self.n_blocks:
            raise IndexError(f"block {block} out of range (0..{self.n_blocks - 1})")
        idx = np.unravel_index(block, self.block_grid) if self.block_grid else ()
        return tuple(slice(int(i) * c, min((int(i) + 1) * c, n))
                     for i, c, n in zip(idx, self.chunks, self.shape, strict=True))

    def block_size(self, block: int) -> int:
        return math.prod(s.stop - s.start for s in self.block_slices(block))

    def row_slices(self, block: int) -> tuple[slice, ...]:
        """The part of :meth:`block_slices` over the non-velocity (row) dimensions."""
        return self.block_slices(block)[: len(self.row_dims)]

    # ---- identity
    def signature(self) -> dict[str, Any]:
        """Everything that defines the values of the result (not the block shape)."""
        return {
            "kind": self.kind,
            "params": {a.name: _hex(a.values) for a in self.params},
            "velocity": {self.velocity.name: _hex(self.velocity.values)},
            "settings": dataclasses.asdict(self.settings),
            "initial": self.initial,
            "inplane_on": self.inplane_on,
            "rs_law": self.rs_law,
            "friction": None if self.friction is None else "rate-and-state",
            "continuation": self.continuation,
            "version": self.version,
            "fingerprint": self.fingerprint,
            "variables": variables_signature(self.kind, self.velocity.name),
        }

    def token(self) -> str:
        """A short hash of :meth:`signature` (Dask task keys)."""
        import hashlib

        text = json.dumps(self.signature(), sort_keys=True)
        return hashlib.sha256(text.encode()).hexdigest()[:16]

    def with_chunks(self, chunks: tuple[int, ...]) -> Plan:
        if len(chunks) != len(self.shape) or any(c < 1 for c in chunks):
            raise ValueError(f"bad block shape {chunks} for a grid of shape {self.shape}")
        return dataclasses.replace(self, chunks=tuple(int(c) for c in chunks))


def _chunks(shape: tuple[int, ...], n_tail: int, chunk_size: int,
            whole_tail: bool) -> tuple[int, ...]:
    """Block shape of about ``chunk_size`` points, filled from the last dimension.

    The last ``n_tail`` dimensions (direction, velocity) are kept whole if
    ``whole_tail`` (continuation) even when that exceeds ``chunk_size``.
    """
    chunks = [1] * len(shape)
    budget = chunk_size
    for d in range(len(shape) - 1, -1, -1):
        tail = d >= len(shape) - n_tail
        if (tail and whole_tail) or shape[d] <= budget:
            c = shape[d]
        else:  # as many blocks as needed, of (nearly) equal size: no small remainder block
            c = -(-shape[d] // -(-shape[d] // budget))
        chunks[d] = c
        budget = max(1, budget // c)
    return tuple(chunks)


def make_plan(
    *,
    system: Any = None,
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
    physical: dict[str, ArrayLike] | None = None,
    settings: SolverSettings | None = None,
    initial: str = "sliding",
    continuation: bool | str = False,
    chunk_size: int | None = None,
    version: str = "",
    fingerprint: str = "",
) -> Plan:
    """Validate a grid and cut it into blocks; every check happens here, before any work.

    (What the solvers chosen in the grid never take is checked by :func:`check_methods`,
    which :func:`sweep` calls on the plan: a plan itself is only the grid.)

    The grid's parameters and options are those of :func:`sweep` (``system``,
    ``alpha`` ... ``profile_exponent``, the friction law's ``static_ratio``, ``rs_a`` ...
    ``rs_alpha_ld``, ``inplane_on``, ``rs_law``, the velocity axis, ``settings``,
    ``initial``, ``continuation``, ``chunk_size``); besides them:

    Parameters
    ----------
    physical : dict of str to array_like, optional
        The SI fields of a :class:`~vibrofriction.params.Physical` ``system`` to sweep
        (the keywords of :func:`sweep`).
    version, fingerprint : str, optional
        Recorded in the plan: what a store made from it is resumed with (:func:`identity`).

    Returns
    -------
    Plan
        The grid, cut into blocks of about ``chunk_size`` points.

    Raises
    ------
    ValueError
        For a bad grid or option, naming it.

    Examples
    --------
    >>> import numpy as np
    >>> from vibrofriction.sweep import make_plan
    >>> plan = make_plan(alpha=[0.01, 0.1], beta=2.0, amplitude=0.5,
    ...                  vbar=np.linspace(0, 1.2, 13))
    >>> plan.kind, plan.dims, plan.size
    ('dimensionless', ('alpha', 'vbar'), 26)
    >>> plan.fixed["beta"], plan.fixed["amplitude"]
    (2.0, 0.5)
    """
    settings = _checked_options(settings, initial, chunk_size)
    _check_axisymmetric(system)
    on = getattr(system, "inplane_on", CHOICES["inplane_on"].default) if inplane_on is None \
        else checked_choice("inplane_on", inplane_on)
    law = dict(static_ratio=static_ratio, rs_a=rs_a, rs_b=rs_b, rs_d_c=rs_d_c,
               rs_v_ref=rs_v_ref, rs_alpha_ld=rs_alpha_ld)
    friction = None
    if isinstance(system, Physical):
        kind = "physical"
        friction = _physical_law(system, rs_law)
        state_law = CHOICES["rs_law"].default if friction is None else friction.law
        physical = dict(physical or {})
        if phase_x is not None:
            physical["phase_x"] = phase_x
        if phase_y is not None:
            physical["phase_y"] = phase_y
        if profile_exponent is not None:
            physical["profile_exponent"] = profile_exponent
        params, velocity = _physical_axes(
            system.with_(inplane_on=on, friction=friction), physical, v0, dict(
                alpha=alpha, beta=beta, amplitude=amplitude, zeta=zeta, eta_c=eta_c, a_x=a_x,
                a_y=a_y, vbar=vbar, v_inertial=v_inertial, **law))
    else:
        kind = "dimensionless"
        state_law = getattr(system, "rs_law", CHOICES["rs_law"].default) if rs_law is None \
            else checked_choice("rs_law", rs_law)
        values = dict(alpha=alpha, beta=beta, amplitude=amplitude, zeta=zeta, eta_c=eta_c,
                      a_x=a_x, phase_x=phase_x, a_y=a_y, phase_y=phase_y,
                      profile_exponent=profile_exponent, **law)
        params, velocity = _dimensionless_axes(system, values, vbar, v_inertial,
                                               dict(physical or {}), v0)
    continuation = continuation_name(continuation)
    if continuation:
        _check_continuation(velocity)
        curved = [a for a in params if a.name == "profile_exponent"
                  and np.any(np.isfinite(a.values))]
        if curved:
            raise ValueError("continuation is not available for a curved profile "
                             "(profile_exponent finite in the grid): the MDR solver starts "
                             "from steady sliding only")
        if friction is not None or any(a.name == "rs_a" and np.any(a.values > 0.0)
                                       for a in params):
            raise ValueError("continuation is not available for rate-and-state friction "
                             "(rs_a > 0 in the grid): the section state it passes on does "
                             "not carry the friction's state theta")
    plan = Plan(kind=kind, params=params, velocity=velocity, settings=settings,
                initial=initial, continuation=continuation, chunks=(),
                version=version, fingerprint=fingerprint, inplane_on=on, rs_law=state_law,
                friction=friction)
    n_tail = int(bool(continuation)) + int(velocity.swept)
    if chunk_size is None:
        chunk_size = auto_chunk_size(int(np.prod(plan.shape)))
    return plan.with_chunks(_chunks(plan.shape, n_tail, int(chunk_size), bool(continuation)))


def _physical_law(system: Physical, rs_law: str | None) -> RateAndState | None:
    """The rate-and-state law of a physical sweep: the system's, with ``rs_law`` if given.

    ValueError for ``rs_law`` without a law to take it (``friction=None``): never ignored.
    """
    friction = system.friction
    if rs_law is None:
        return friction
    if friction is None:
        raise ValueError(f"rs_law = {rs_law!r} needs rate-and-state friction: a Physical "
                         "system takes it as friction=RateAndState(..., law=...), and this "
                         "one has none (Coulomb friction)")
    return dataclasses.replace(friction, law=checked_choice("rs_law", rs_law))


def _check_axisymmetric(system: Any) -> None:
    """Refuse a system whose pin is not axisymmetric.

    ValueError for a system whose pin is not axisymmetric (``k_y``, ``c_y``,
    ``alpha_y``, ``zeta_y`` given): the sweep does not carry them yet (refused, never
    ignored).  ``mu_static`` (the static coefficient, twin of ``mu0``) is an SI axis.
    """
    names = [p.name for p in PARAMETERS if p.twin and p.name != MU_STATIC
             and getattr(system, p.name, None) is not None]
    if names:
        raise ValueError(f"the sweep does not take a pin that is not axisymmetric yet "
                         f"({', '.join(names)} given): sweep with friction_coefficient over "
                         "an array of velocities, or leave them None")


def auto_chunk_size(points: int) -> int:
    """The block size of a grid of ``points`` points when none is given.

    About a hundredth of the grid (:data:`AUTO_BLOCKS`), from 1000 to 10,000 points.

    Parameters
    ----------
    points : int
        The grid's size.

    Returns
    -------
    int
        The number of points per block.

    Examples
    --------
    >>> from vibrofriction.sweep import auto_chunk_size
    >>> auto_chunk_size(1000), auto_chunk_size(10**6), auto_chunk_size(10**8)
    (1000, 10000, 10000)
    """
    return min(AUTO_MAX_CHUNK, max(DEFAULT_CHUNK_SIZE, points // AUTO_BLOCKS))


def _checked_options(settings: Any, initial: str, chunk_size: Any) -> SolverSettings:
    """The solver settings (default ones for None); ValueError for a bad option."""
    settings = settings if settings is not None else SolverSettings()
    if not isinstance(settings, SolverSettings):
        raise TypeError(f"settings must be a SolverSettings, got {type(settings).__name__}")
    if initial not in ("sliding", "rest"):
        raise ValueError(f"initial must be 'sliding' or 'rest' for a sweep, got {initial!r}")
    if chunk_size is not None and (isinstance(chunk_size, bool) or not isinstance(
            chunk_size, int | np.integer) or chunk_size < 1):
        raise ValueError(f"chunk_size must be an integer >= 1 or None, got {chunk_size!r}")
    return settings


def _physical_axes(system: Physical, physical: dict[str, ArrayLike], v0: ArrayLike | None,
                   dimensionless: dict[str, ArrayLike | None]) -> tuple[tuple[Axis, ...], Axis]:
    """The SI axes (canonical order) and ``v0`` of a sweep around ``system``.

    ``mu_static`` is an axis where it is given (a keyword or the system's), else ``mu0``
    holds for it; a rate-and-state law (``friction``) gives the axes ``friction_a``,
    ``friction_b``, ``friction_d_c``, ``friction_v_ref``, ``friction_alpha_ld`` (its SI
    parameters, held at the law's values unless given).
    """
    law = [n for n in FRICTION_LAW if dimensionless.get(n) is not None]
    if law:
        raise ValueError(f"{', '.join(law)}: a Physical system's friction law is its "
                         "mu_static and its friction=RateAndState(...) in SI units: sweep "
                         "mu_static=[...] or friction_a=[...], friction_b, friction_d_c, "
                         "friction_v_ref, friction_alpha_ld")
    if any(v is not None for v in dimensionless.values()):
        raise ValueError("a Physical system is swept over its SI parameters and v0; "
                         "alpha, beta, amplitude, zeta, eta_c, a_x, vbar, v_inertial are not "
                         "allowed, nor a_y (sweep c_x, c_xc, du_x, du_y instead of zeta, "
                         "eta_c, a_x, a_y)")
    bare = sorted(n for n in physical if n in _SI_LAW)
    if bare:
        raise ValueError(f"{', '.join(bare)}: a physical sweep takes the parameters of its "
                         f"rate-and-state law as {', '.join('friction_' + n for n in bare)}")
    law = sorted(n for n in physical if n in FRICTION_SI)
    if law and system.friction is None:
        raise ValueError(f"{', '.join(law)} need{'s' if len(law) == 1 else ''} "
                         "rate-and-state friction: a Physical system "
                         "takes it as friction=RateAndState(a=..., b=..., d_c=..., v_ref=...), "
                         "and this one has none (Coulomb friction)")
    names = PHYSICAL + ((MU_STATIC,) if MU_STATIC in physical or system.mu_static is not None
                        else ()) + (FRICTION_SI if system.friction is not None else ())
    unknown = sorted(set(physical) - set(names) - {MU_STATIC})
    if unknown:
        raise ValueError(f"unknown physical parameter(s) {unknown}; "
                         f"choose from {[*PHYSICAL, MU_STATIC, *FRICTION_SI]}")
    if v0 is None:
        raise ValueError("give the sliding velocity v0 (m/s) for a Physical system")
    base = _physical_fields(system)
    params = tuple(make_axis(n, physical.get(n, base[n])) for n in names)
    fixed = {n: base[n] for n in choice_names("physical")} | {"friction": system.friction}
    velocity = make_axis("v0", v0)
    validated({"v0": velocity.values})
    for a in params:  # each value of each axis, with the others at their base values
        for x in np.atleast_1d(a.values):
            try:
                physical_system(base | {a.name: float(x)}, system.friction)
            except ValueError as exc:  # RateAndState names its own fields: a, b, ...
                named = a.name in FRICTION_SI
                raise ValueError(f"{a.name} = {float(x):g}: {exc}" if named else str(exc)) \
                    from None
    _check_physical_corners(params, velocity, fixed)
    return params, velocity


def _physical_fields(system: Physical) -> dict[str, Any]:
    """The fields of ``system``, its rate-and-state law as ``friction_a`` ... (if any)."""
    fields = dataclasses.asdict(system)
    law = fields.pop("friction")
    return fields | ({} if law is None else {f"friction_{n}": law[n] for n in _SI_LAW})


def physical_system(values: dict[str, Any], friction: RateAndState | None) -> Physical:
    """The system of a physical grid's point: its SI fields and its law's ``friction_*``.

    ``friction`` is the grid's law (its ``law``, and its parameters where ``values`` has
    no ``friction_*``).
    """
    own = {n.removeprefix("friction_"): values[n] for n in FRICTION_SI if n in values}
    if own:
        if friction is None:
            raise ValueError(f"{', '.join(own)} need a rate-and-state law (friction=None)")
        friction = dataclasses.replace(friction, **own)
    return Physical(**{n: v for n, v in values.items() if n not in FRICTION_SI and
                       n != "friction"}, friction=friction)


def _dimensionless_axes(system: Any, values: dict[str, ArrayLike | None],
                        vbar: ArrayLike | None, v_inertial: ArrayLike | None,
                        physical: dict[str, ArrayLike],
                        v0: ArrayLike | None) -> tuple[tuple[Axis, ...], Axis]:
    """The parameter axes and the velocity axis of a sweep.

    The axes of :data:`DIMENSIONLESS` (``values`` by name; None: the system's, else the
    schema's default) and the velocity axis (``vbar`` or ``v_inertial``).
    """
    if physical:
        raise ValueError(f"physical parameter(s) {sorted(physical)} need a Physical "
                         "system (sweep(Physical(...), v0=..., ...))")
    if v0 is not None:
        raise ValueError("v0 (m/s) needs a Physical system; use vbar or v_inertial")
    if system is not None and not isinstance(system, Dimensionless):
        raise TypeError(f"system must be a Dimensionless or Physical, "
                        f"got {type(system).__name__}")
    def base(name: str) -> float | None:
        return PARAMETER[name].default if system is None else getattr(system, name)

    values = {n: base(n) if values.get(n) is None else values[n] for n in DIMENSIONLESS}
    missing = [n for n, v in values.items() if v is None]
    if missing:
        raise ValueError(f"missing parameter(s) {missing}: give a value or an array each")
    given = [n for n, v in (("vbar", vbar), ("v_inertial", v_inertial)) if v is not None]
    if len(given) != 1:
        raise ValueError(f"give exactly one velocity axis, vbar or v_inertial "
                         f"(got {given or 'none'})")
    axes = tuple(make_axis(n, v) for n, v in values.items() if v is not None)  # none missing
    speed = vbar if vbar is not None else v_inertial
    assert speed is not None  # exactly one is given
    velocity = make_axis(given[0], speed)
    for a in (*axes, velocity):  # each axis alone: the ranges, not the relations
        validated({a.name: a.values})
    _check_above(axes)
    _check_law_corners(axes)
    by_name = {a.name: a for a in axes}
    if velocity.name == "vbar":
        if np.any(by_name["a_x"].values > 0.0) or np.any(by_name["a_y"].values > 0.0):
            raise ValueError("vbar (v0/v0* of eq. 16) is not defined with an in-plane "
                             "oscillation (a_x or a_y > 0 in the grid): sweep v_inertial (signed) "
                             "instead")
        if np.any(by_name["rs_a"].values > 0.0):
            raise ValueError("vbar (v0/v0* of eq. 16) is not defined for rate-and-state "
                             "friction (rs_a > 0 in the grid: eq. 12 is Coulomb's): sweep "
                             "v_inertial (signed) instead")
        _check_vbar_exists(*(by_name[n] for n in ("alpha", "beta", "amplitude", "zeta",
                                                  "eta_c")))
    return axes, velocity


def _check_above(axes: tuple[Axis, ...]) -> None:
    """Check that each ordered pair of parameters is ordered at every point.

    A parameter that must exceed another (``beta > alpha``, the schema's
    ``Range.above``) does so at every point of the outer product.
    """
    by_name = {a.name: a for a in axes}
    for a in axes:
        other = PARAMETER[a.name].range.above
        if not other:
            continue
        lo, hi = float(np.min(a.values)), float(np.max(by_name[other].values))
        if not lo > hi:
            p, q = PARAMETER[a.name], PARAMETER[other]
            raise ValueError(
                f"{a.name} must be > {other} at every grid point: {a.name} = {lo!r} <= "
                f"{other} = {hi!r} ({a.name} = {p.definition} exceeds {other} = "
                f"{q.definition})")


def _check_law_corners(axes: tuple[Axis, ...]) -> None:
    """Refuse friction-law values that cannot go together anywhere in the grid.

    The validator (:func:`~vibrofriction.validation.validated`) on every corner of the
    outer product of the friction law's axes and ``amplitude`` (their ends): each pair it
    refuses (``rs_b > 0`` with ``rs_a = 0``, ``rs_alpha_ld > 0`` with ``rs_b = 0`` or
    ``amplitude >= 1``, ``static_ratio > 1`` with ``rs_a > 0``, ...) is refused at some
    point of the grid exactly when it is at a corner, every condition being one-sided in
    each parameter.
    """
    ends = {a.name: np.unique([np.min(a.values), np.max(a.values)]) for a in axes
            if a.name in _LAW_CORNERS}
    corners = np.meshgrid(*ends.values(), indexing="ij")
    try:
        validated({n: c.ravel() for n, c in zip(ends, corners, strict=True)})
    except ValueError as exc:
        raise ValueError(f"the grid's friction law: {exc}") from None


def _check_methods(values: dict[str, NDArray[np.float64]]) -> None:
    """Refuse, before any work, what a solver chosen somewhere in the grid never takes.

    ``values``: the values each parameter takes in the grid (its axis, or a physical
    grid's groups at its corners).  The solvers are those of the grid's
    ``profile_exponent`` and ``a_y`` (:func:`~vibrofriction.solver.methods.choose`), and
    each refuses every value but the default of a parameter it declares ``whole``
    (:class:`~vibrofriction.capabilities.Limit`: a friction law it does not cover, contact
    damping for the MDR solver): the outer product holds each such value with each solver.
    The other limits depend on the point: refused when solved.
    """
    from ..solver.methods import METHODS, choose

    n, y = np.meshgrid(np.unique(values["profile_exponent"]), np.unique(values["a_y"]))
    for i in np.unique(choose(n, y)):
        c = list(METHODS.values())[int(i)].capabilities
        for limit in c.limits:
            if not limit.whole or limit.parameter not in values:
                continue
            x = np.asarray(values[limit.parameter], dtype=float)
            bad = np.asarray(limit.refuses({limit.parameter: x}), dtype=bool)
            if bad.any():
                raise Refusal(f"{c.title} ({c.takes}) does not take {limit.what}: got "
                              f"{limit.parameter} = {float(x[bad.argmax()]):g} in the grid",
                              limit.parameter)


def _check_vbar_exists(al: Axis, be: Axis, am: Axis, ze: Axis, et: Axis) -> None:
    """``vbar`` is undefined where ``v0*`` is infinite or zero (eqs. 12, 16).

    Without damping on ``alpha == 1`` or ``beta == 1``, and wherever ``amplitude == 0``.
    """
    undamped = not np.any(ze.values > 0)
    for axis, value, why in ((al, 1.0, "alpha == 1 (case IV: v0* is infinite)"),
                             (be, 1.0, "beta == 1 (case III: v0* is zero)"),
                             (am, 0.0, "amplitude == 0 (v0* is zero)")):
        relevant = axis is am or (undamped and (axis is al or not np.any(et.values > 0)))
        if relevant and np.any(axis.values == value):
            raise ValueError(f"vbar does not exist where {why}, and {axis.name} = "
                             f"{value:g} is in the grid: sweep v_inertial instead")
    if np.any(ze.values == 0.0) and np.any(al.values == 1.0):
        raise ValueError("vbar does not exist where alpha == 1 and zeta == 0 (case IV: "
                         "v0* is infinite), and both are in the grid: sweep v_inertial "
                         "instead")


def continuation_name(continuation: bool | str) -> str:
    """The key of :data:`CONTINUATIONS` that ``continuation`` names (True: ``"both"``)."""
    if isinstance(continuation, bool | np.bool_):
        return "both" if continuation else ""
    if continuation in CONTINUATIONS and continuation:
        return continuation
    raise ValueError(f"continuation must be False, True, 'up' or 'both', got {continuation!r}")


def _check_continuation(velocity: Axis) -> None:
    if not velocity.swept or len(velocity) < 2:
        raise ValueError(f"continuation needs a swept velocity axis ({velocity.name}) "
                         "with at least two values")
    if not np.all(np.diff(velocity.values) > 0):
        raise ValueError(f"continuation needs {velocity.name} strictly increasing")


def _check_physical_corners(params: tuple[Axis, ...], velocity: Axis,
                            fixed: dict[str, Any]) -> None:
    """The dimensionless groups are monotonic in each SI parameter: check the corners.

    Catches combinations that are valid one by one but not together (overflow of
    ``m omega^2``, ``k_xc`` below the rounding of ``k_x`` so that ``beta == alpha``,
    ``mu_static`` below ``mu0``, a rate-and-state law's ``alpha_ld > 0`` with ``du_z >=
    u_z0``).
    """
    vmin, vmax = float(np.min(velocity.values)), float(np.max(velocity.values))
    for where, p in _physical_corners(params, fixed):
        try:
            p.to_dimensionless()
            V = max(abs(float(p.v0_to_inertial(v))) for v in (vmin, vmax))
        except ValueError as exc:
            raise ValueError(f"the physical grid has an invalid corner {where}: {exc}") from None
        if not math.isfinite(V):
            raise ValueError(f"v0 = {vmin!r}..{vmax!r} overflows the inertial velocity at "
                             f"{where}")


def _physical_corners(params: tuple[Axis, ...], fixed: dict[str, Any]):
    """``(values, Physical)`` at each corner of a physical grid (each axis's distinct ends).

    ValueError naming the corner where the system itself is refused.
    """
    names = [a.name for a in params]
    ends = [sorted({float(np.min(a.values)), float(np.max(a.values))}) for a in params]
    for corner in itertools.product(*ends):
        where = dict(zip(names, corner, strict=True))
        try:
            yield where, physical_system(where | fixed, fixed.get("friction"))
        except ValueError as exc:
            raise ValueError(f"the physical grid has an invalid corner {where}: {exc}") from None


def check_methods(plan: Plan) -> None:
    """Refuse, before any work, what a solver chosen somewhere in ``plan`` never takes.

    :func:`sweep` calls it on its plan (a plan itself is only the grid: a friction law no
    solver covers yet still makes one).  A physical grid is judged by the groups at its
    corners (those that matter are one-sided in each SI parameter).

    Raises
    ------
    vibrofriction.capabilities.Refusal
        A ValueError naming the parameter, its value and the solver.
    """
    if plan.kind == "dimensionless":
        _check_methods({a.name: np.atleast_1d(a.values) for a in plan.params})
        return
    fixed = {"inplane_on": plan.inplane_on, "friction": plan.friction}
    dims = [p.to_dimensionless() for _, p in _physical_corners(plan.params, fixed)]
    _check_methods({n: np.array([float(getattr(d, n)) for d in dims])
                    for n in ("profile_exponent", "a_y", *_LIMITED)})
