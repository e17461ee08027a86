"""The allowed in-plane oscillations (:class:`Space`), their map and its optimisation.

The map is over ``(omega, du_z, du_x, phase_x)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...params import Physical
from .evaluation import ZERO_AMPLITUDE_FLOOR, log_step, map_axes_2d, solve_design

# --------------------------------------------------------------------------------------
# In-plane design: normal + longitudinal oscillation, friction or drive (docs/bench.md)

#: ``velocity_rule``: what ``max_velocity_amplitude`` limits.
VELOCITY_RULES = {
    "combined": "omega sqrt(du_z^2 + du_x^2) (the peak speed of the contact's vibration at "
                "the worst phase, sqrt(2) times its rms speed at any phase)",
    "each": "omega du_z and omega du_x separately (two actuators, each with its limit)",
}


#: ``goal``: what the design optimises at ``v0``.
GOALS = {
    "friction": "the smallest friction force magnitude |COF| = mu0 |mu(v0)|",
    "drive": "the largest drive force -mu(v0) (forward, against a load, at v0 > 0)",
}


#: The blocking force is ``mu`` at ``V = +-BLOCKING_V`` (inertial units).
BLOCKING_V = 1e-5


AXES = ("omega", "du_z", "du_x", "phase_x")


#: A transverse design's map (the 2-D solver, ~7 ms a point): at most this many
#: frequencies and normal amplitudes (then ``n_du_y x n_phase_y``).
PLANE_MAP = (9, 4)


#: ... and at most this many refinements from its lowest points.
PLANE_STARTS = 2


@dataclass
class Space:
    """The allowed oscillations.

    Ranges (SI), the phase (``None``: free), the limit; ``component`` the in-plane direction
    that ``du_x`` and ``phase`` stand for: ``"x"`` (longitudinal) or ``"y"`` (transverse:
    ``du_y``, ``phase_y``).
    """

    omega: tuple[float, float]
    du_z: tuple[float, float]
    du_x: tuple[float, float]
    phase: float | None
    vmax: float
    rule: str
    component: str = "x"

    def solve(self, pin, v0, w, dz, d, ph, on, settings) -> dict[str, np.ndarray]:
        """:func:`solve_design` with the in-plane amplitude ``d`` and phase ``ph``.

        Along ``component``.
        """
        if self.component == "y":
            return solve_design(pin, v0, w, dz, settings, 0.0, 0.0, on, d, ph)
        return solve_design(pin, v0, w, dz, settings, d, ph, on)

    def feasible(self, w, dz, dx) -> np.ndarray:
        """Whether the velocity amplitude is within ``vmax`` by the rule, elementwise."""
        w, dz, dx = (np.asarray(x, float) for x in (w, dz, dx))
        speed = w * (np.hypot(dz, dx) if self.rule == "combined" else np.maximum(dz, dx))
        return speed <= self.vmax * (1 + 1e-12)

    def inside(self, w, dz, dx) -> bool:
        """Whether one point is within the ranges and feasible."""
        return (self.omega[0] <= w <= self.omega[1] and self.du_z[0] <= dz <= self.du_z[1]
                and self.du_x[0] <= dx <= self.du_x[1] and bool(self.feasible(w, dz, dx)))

    def restricted(self, **ranges) -> Space:
        """A copy with some ranges replaced."""
        return Space(**{**self.__dict__, **ranges})


def _amplitudes(lo: float, hi: float, n: int) -> np.ndarray:
    if lo == hi:
        return np.array([lo])
    if lo == 0.0:
        return np.concatenate([[0.0], np.geomspace(ZERO_AMPLITUDE_FLOOR * hi, hi,
                                                   max(n - 1, 1))])
    return np.unique(np.geomspace(lo, hi, n))


def _map_axes(pin: Physical, space: Space, n_omega: int, n_du_z: int, n_du_x: int,
              n_phase: int) -> list[np.ndarray]:
    ws = (np.array([space.omega[0]]) if space.omega[0] == space.omega[1] else
          map_axes_2d(pin, space.omega, (1.0, 1.0), n_omega, 1)[0])
    dxs = _amplitudes(*space.du_x, n_du_x)
    if space.phase is not None:
        phs = np.array([space.phase])
    elif dxs.max() == 0.0:
        phs = np.zeros(1)  # no in-plane oscillation: the phase means nothing
    else:
        phs = np.linspace(0.0, 2 * math.pi, n_phase, endpoint=False)
    return [ws, _amplitudes(*space.du_z, n_du_z), dxs, phs]


def objective_of(goal: str, cof: np.ndarray) -> np.ndarray:
    """The value minimised: ``|COF|`` (friction) or ``COF`` (drive: ``-COF`` maximised)."""
    return np.abs(cof) if goal == "friction" else cof


def _solve_map(pin, v0, axes, on, settings, space: Space):
    """The solver on the 4-D grid.

    Points without in-plane amplitude are solved at the first phase only and copied (the phase
    means nothing there).
    """
    grids = np.meshgrid(*axes, indexing="ij")
    need = (grids[2] > 0.0) | (np.arange(axes[3].size) == 0)[None, None, None, :]
    sol = {k: np.full(grids[0].shape, np.nan) for k in ("cof", "mu_ratio", "error")}
    sol["trusted"] = np.zeros(grids[0].shape, bool)
    w, dz, dx, ph = (g[need] for g in grids)
    part = space.solve(pin, v0, w, dz, dx, ph, on, settings)
    for k, v in part.items():
        sol[k][need] = v
        sol[k][:, :, axes[2] == 0.0, :] = sol[k][:, :, axes[2] == 0.0, :1]
    return grids, sol


def _refine_inplane(pin, v0, on, goal, settings, space: Space, starts, steps):
    """Nelder-Mead from each start in the free coordinates.

    Nelder-Mead from each start in the free coordinates (``ln omega``, ``ln du_z``,
    ``ln du_x`` where the start's value is > 0 and its range not a point; ``phase_x``
    when free), inside the limits, on trusted values only.  Returns the best
    ``(point, objective)`` (starts included), the rejected evaluations in all and in
    the winning run.
    """
    from scipy.optimize import minimize

    best = min(starts, key=lambda s: s[1])
    rejected = {"all": 0, "run": 0}
    best_rejected = 0
    for point, _ in starts:
        free = [i for i, (v, rng) in enumerate(zip(point[:3], (space.omega, space.du_z,
                                                                  space.du_x), strict=True))
                if v > 0.0 and rng[0] < rng[1]]
        if space.phase is None and point[2] > 0.0:
            free.append(3)
        if not free:
            continue

        def full(x, point=point, free=free):
            p = list(point)
            for i, xi in zip(free, x, strict=True):
                p[i] = xi % (2 * math.pi) if i == 3 else math.exp(xi)
            return p

        def objective(x, full=full):
            w, dz, dx, ph = full(x)
            if not space.inside(w, dz, dx):
                return math.inf
            c = float(space.solve(pin, v0, w, dz, dx, ph, on, settings)["cof"])
            if math.isnan(c):
                rejected["run"] += 1
                return math.inf
            return float(objective_of(goal, np.array(c)))

        x0 = np.array([point[i] if i == 3 else math.log(point[i]) for i in free])
        simplex = [x0]
        for k, i in enumerate(free):  # step towards the inside: down in amplitude
            e = np.zeros(len(free))
            e[k] = steps[i] if i in (0, 3) else -steps[i]
            simplex.append(x0 + e)
        rejected["run"] = 0
        with np.errstate(invalid="ignore"):
            res = minimize(objective, x0, method="Nelder-Mead",
                           options={"xatol": 1e-7, "fatol": 1e-10,
                                    "maxfev": 60 + 60 * len(free),
                                    "initial_simplex": np.array(simplex)})
        rejected["all"] += rejected["run"]
        if res.fun < best[1]:
            best = (tuple(full(res.x)), float(res.fun))
            best_rejected = rejected["run"]
    return best, rejected["all"], best_rejected


def optimise(pin, v0, on, goal, space: Space, sizes, starts, settings):
    """Map and refinement over ``space``.

    ``(point, objective, grids, axes, sol, feasible, n_rejected, rejected_run)``; ValueError
    without a trusted feasible point.
    """
    axes = _map_axes(pin, space, *sizes)
    grids, sol = _solve_map(pin, v0, axes, on, settings, space)
    feasible = space.feasible(*grids[:3])
    value = np.where(feasible & sol["trusted"], objective_of(goal, sol["cof"]), np.inf)
    order = [k for k in np.argsort(value, axis=None)[:starts] if np.isfinite(value.flat[k])]
    if not order:
        raise ValueError(f"no trusted point of the map respects the limits "
                         f"({int((feasible & ~sol['trusted']).sum())} untrusted within them)")
    steps = [log_step(axes[0]), log_step(axes[1]), log_step(axes[2]),
             2 * math.pi / axes[3].size if axes[3].size > 1 else 0.2]
    (point, obj), n_rej, rej_run = _refine_inplane(
        pin, v0, on, goal, settings, space,
        [(tuple(float(g.flat[k]) for g in grids), float(value.flat[k])) for k in order],
        steps)
    return point, obj, grids, axes, sol, feasible, n_rej, rej_run


def untrusted_near_nd(untrusted: np.ndarray, axes, point) -> int:
    """Untrusted map points among the neighbours of the map point nearest ``point``.

    Amplitudes and frequency by ratio, the phase by its periodic distance.
    """
    index = []
    for k, (ax, v) in enumerate(zip(axes, point, strict=True)):
        if k == 3:
            d = np.abs(np.angle(np.exp(1j * (ax - v))))
        elif v == 0.0 or not np.any(ax > 0):
            d = np.abs(ax - v)
        else:
            with np.errstate(divide="ignore"):
                d = np.abs(np.log(np.where(ax > 0.0, ax, 1e-300) / v))
        i = int(np.argmin(d))
        index.append(slice(max(i - 1, 0), i + 2))
    return int(untrusted[tuple(index)].sum())


def direction_row(name, pin, v0, on, goal, space, sizes, starts, settings):
    """The best choice within ``space``.

    A row of ``directions`` (``du_x``, ``phase_x``, ``du_y``, ``phase_y``: the one along
    ``space.component`` set, the other 0).
    """
    try:
        point, _, *_ = optimise(pin, v0, on, goal, space, sizes, starts, settings)
    except ValueError:
        return {"direction": name, "omega": math.nan, "du_z": math.nan, "du_x": math.nan,
                "phase_x": math.nan, "du_y": math.nan, "phase_y": math.nan,
                "cof": math.nan, "allowed": False}
    cof = float(space.solve(pin, v0, *point, on, settings)["cof"])
    d, ph = point[2], point[3] if point[2] > 0.0 else 0.0
    inplane = ({"du_x": 0.0, "phase_x": 0.0, "du_y": d, "phase_y": ph}
               if space.component == "y" else
               {"du_x": d, "phase_x": point[3], "du_y": 0.0, "phase_y": 0.0})
    return {"direction": name, "omega": point[0], "du_z": point[1], **inplane, "cof": cof,
            "allowed": space.inside(*point[:3])}
