"""The fit's problem (:mod:`.procedure`).

The free parameters in ``ln`` and the constraints that tie others to them, the residuals (with the
penalty of a row the model cannot evaluate), and the model's COF at measured points
(:func:`predict_cof`, :func:`synthetic_measurements`).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike, NDArray

from ...contact import Cone, FlatPunch, Material, PowerLaw, Sphere
from ...params import Physical, RateAndState
from ...solver import SolverSettings, solve_points
from ...solver.sensitivity import SENSITIVE, sensitivities

__all__ = ["CONTACT_FITTABLE", "FITTABLE", "LAW_FITTABLE", "predict_cof",
           "synthetic_measurements"]

#: The step in ``ln`` of the central differences of the map ``ln -> points`` (cheap, no
#: solver) in :meth:`Problem.jacobian`, and of the solver's own where it has no sensitivity.
MAP_STEP = 1e-6
SOLVER_STEP = 1e-5
#: The step in ``ln`` of the solver's central differences at a curved (MDR) row: its
#: value moves in steps up to its error bar (``tol_trusted``, 1e-5 of ``mu_ratio``) where
#: the rows of springs it extrapolates from change, so the step is large enough that
#: ``d mu`` over it (~2e-3 for a slope of 0.2) is a hundred times such a step.
MDR_STEP = 1e-2
#: The step in ``ln`` of the solver's central differences under rate-and-state friction
#: (no sensitivities): its stated error is ~1e-7 of ``mu_ratio`` (``rtol = 1e-7``), so
#: the change over the step (~1e-4 for a slope of 0.1) is a thousand times that error.
RATE_STATE_STEP = 1e-3
#: The fields of :class:`Physical` that can be fitted.
FITTABLE = ("mu0", "mass", "k_x", "k_xc", "k_zc", "u_z0", "c_x", "c_xc")
#: The parameters of a local friction law that can be fitted: the static coefficient
#: ``mu_static`` (a guess with ``mu_static > mu0``; searched as ``ln(mu_static/mu0) >= 0``,
#: so that it never falls below the kinetic ``mu0``) and the rate-and-state ``a``, ``b``
#: and ``d_c`` (m) of a guess with ``friction=RateAndState(...)`` (SI, as it holds them).
LAW_FITTABLE = ("mu_static", "a", "b", "d_c")
#: The rate-and-state parameters among them.
RATE_STATE_FITTABLE = ("a", "b", "d_c")
#: The largest ``|mu_ratio|`` a rate-and-state row is taken to reach in :meth:`Problem.penalty`
#: (the law has no bound: ``mu_ss`` grows like ``(a - b) ln v``; a fit whose model reaches
#: twice ``mu_star`` is far from any data set of a tribometer).
RATE_STATE_BOUND = 2.0
#: The parameters of a contact geometry (``fit(..., contact=...)``) that can be fitted:
#: the radius of a :class:`~vibrofriction.contact.Sphere` or
#: :class:`~vibrofriction.contact.FlatPunch`, and the effective modulus ``E*`` of the pair
#: (both bodies' moduli scaled together, Poisson's ratios kept: ``G*`` follows).
CONTACT_FITTABLE = ("radius", "E_star")
#: The fields of :class:`Physical` that a contact geometry sets at the load.
CONTACT_FIELDS = ("k_zc", "k_xc", "u_z0")
#: The global stage compares the model with every other row of a table this long or
#: longer: an evaluation costs half, so it runs twice the generations for the same
#: time, and more generations find the narrow valleys more often.
COARSE_ROWS = 20


def predict_cof(system: Physical, v0: NDArray, du_z: NDArray, omega: NDArray,
                settings: SolverSettings | None = None, *, du_x: NDArray | float = 0.0,
                phase_x: NDArray | float = 0.0, du_y: NDArray | float = 0.0,
                phase_y: NDArray | float = 0.0) -> NDArray[np.float64]:
    """``mu0 * mu_ratio`` of ``system`` at each measured point (eq. 25).

    ``mu0 * mu_ratio`` of ``system`` at each ``(v0, du_z, omega, du_x, phase_x, du_y,
    phase_y)`` (eq. 25; the in-plane oscillation on ``system.inplane_on``, ``du_y > 0``
    by the 2-D solver with the pin's ``k_y``, ``c_y``; a curved ``system`` by the MDR
    solver, docs/contact_geometry.md; ``system``'s own ``du_z``,
    ``omega``, ``du_x``, ``phase_x``, ``du_y``, ``phase_y`` are not used), ``nan`` where
    the solver's value is not trusted (:meth:`SolverSettings.trusted`): the count of
    untrusted points is ``np.isnan(...).sum()``.
    """
    groups = _groups(system, v0, du_z, omega, du_x, phase_x, du_y, phase_y)
    return _cof(system.mu0, _solve_points((*groups, system.inplane_on, law_name(system),
                                           settings)))


def _groups(system: Physical, *point) -> tuple[NDArray[np.float64], ...]:
    """:meth:`Physical.point_arguments` of ``point`` as arrays of one shape, and the law's.

    An axisymmetric pin's ``alpha_y``, ``zeta_y`` (None) are ``alpha``, ``zeta`` (the rows of
    several systems are concatenated, :meth:`Problem.costs`).  Then ``profile_exponent`` and
    the friction law's :data:`LAW_GROUPS` at each row's drive frequency
    (:meth:`Physical.law_arguments`): the 13th to 19th positional arguments of
    :func:`~vibrofriction.solver.solve_points` (its ``rs_law``: :func:`law_name`).
    """
    groups = list(system.point_arguments(*point))
    for i, twin in ((10, 0), (11, 4)):  # alpha_y -> alpha, zeta_y -> zeta
        if groups[i] is None:
            groups[i] = groups[twin]
    groups.append(system.profile_exponent)  # the 13th argument of solve_points
    law = system.law_arguments(np.asarray(point[2], dtype=float))  # at each row's omega
    groups += [law[n] for n in LAW_GROUPS]
    return tuple(np.broadcast_arrays(*(np.asarray(g, dtype=float) for g in groups)))


#: The friction law's positional arguments of :func:`~vibrofriction.solver.solve_points`
#: after ``profile_exponent`` (the groups 14 to 19 of :func:`_groups`).
LAW_GROUPS = ("static_ratio", "rs_a", "rs_b", "rs_d_c", "rs_v_ref", "rs_alpha_ld")
#: Where they start among the groups of :func:`_groups` (after the 12 of
#: :meth:`Physical.point_arguments` and ``profile_exponent``).
LAW_START = 13


def law_name(system: Physical) -> str:
    """The rate-and-state evolution law of ``system`` (without one ``"aging"``, the default)."""
    return "aging" if system.friction is None else system.friction.law


def _rate(up: ArrayLike, down: ArrayLike) -> NDArray[np.float64]:
    """The central difference of one group of the map from parameters to points.

    The central difference ``(up - down)/(2 MAP_STEP)`` of one group of the map from
    parameters to points; 0 where the group does not move (also where it is ``inf``: a
    flat punch's ``profile_exponent``, a rigid contact's ``beta``).
    """
    a, b = np.asarray(up, dtype=float), np.asarray(down, dtype=float)
    moved = a != b
    return np.subtract(a, b, out=np.zeros(np.broadcast(a, b).shape), where=moved) \
        / (2.0 * MAP_STEP)


def _cof(mu0: float, solved: tuple[NDArray, NDArray]) -> NDArray[np.float64]:
    """``mu0 * mu_ratio``, nan where the solver does not trust its value."""
    mu_ratio, trusted = solved
    return mu0 * np.where(trusted, mu_ratio, np.nan)


def synthetic_measurements(system: Physical, du_z, v0, sigma: float,
                           rng: np.random.Generator, *,
                           settings: SolverSettings | None = None) -> pd.DataFrame:
    """A measurement table made by the model, for a fit whose truth is known.

    At each amplitude of ``du_z`` (m) and each velocity of ``v0`` (m/s), at the system's
    ``omega``, :func:`predict_cof` plus Gaussian noise of standard deviation ``sigma`` (drawn
    per amplitude, in order).  SI columns ``v0, cof, du_z, omega, sigma``, the format of
    :func:`~vibrofriction.bench.read_measurements`.  A truth the solver does not trust at some
    point is refused (ValueError naming the points).
    """
    v0 = np.asarray(v0, dtype=float)
    n = v0.size
    rows = []
    for du in np.atleast_1d(np.asarray(du_z, dtype=float)):
        cof = predict_cof(system, v0, np.full(n, du), np.full(n, system.omega), settings,
                          du_x=system.du_x, phase_x=system.phase_x, du_y=system.du_y,
                          phase_y=system.phase_y)
        if np.any(np.isnan(cof)):
            bad = v0[np.isnan(cof)]
            shown = ", ".join(f"{v:.4g}" for v in bad[:5]) + (", ..." if bad.size > 5 else "")
            raise ValueError(f"the solver has no trusted value of the truth at {bad.size} of "
                             f"{n} points at du_z = {du:g} m (v0 = {shown} m/s): no "
                             "synthetic measurement is made from an untrusted value")
        rows.append(pd.DataFrame({"v0": v0, "cof": cof + rng.normal(0.0, sigma, n),
                                  "du_z": du, "omega": system.omega, "sigma": sigma,
                                  "du_x": system.du_x, "phase_x": system.phase_x,
                                  "du_y": system.du_y, "phase_y": system.phase_y}))
    return pd.concat(rows, ignore_index=True)


Contact = FlatPunch | Sphere | Cone | PowerLaw


def contact_value(contact: Contact, name: str) -> float:
    """The value of the contact parameter ``name`` (:data:`CONTACT_FITTABLE`) of ``contact``.

    Its ``radius`` (m) or its pair's ``E*`` (Pa).
    """
    if name == "E_star":
        return float(contact.e_star)
    if name == "radius" and isinstance(contact, Sphere | FlatPunch):
        return float(contact.radius)
    raise ValueError(f"{name} is not a parameter of a {type(contact).__name__} that the fit "
                     f"takes: {_contact_names(contact)}")


def _contact_names(contact: Contact) -> str:
    names = ["radius", "E_star"] if isinstance(contact, Sphere | FlatPunch) else ["E_star"]
    return f"a {type(contact).__name__}'s fittable parameters are {names}"


def contact_fields(contact: Contact, load: float, curved: bool,
                   radius: float | None = None, E_star: float | None = None
                   ) -> dict[str, float]:
    """``k_zc``, ``k_xc``, ``u_z0`` of ``contact`` at the normal ``load`` (N).

    ``k_zc``, ``k_xc``, ``u_z0`` of ``contact`` at the normal ``load`` (N), with its
    ``radius`` and its pair's ``E*`` replaced where given (both moduli scaled together,
    Poisson's ratios kept): as :func:`~vibrofriction.bench.from_bench` builds them, the MDR contact
    (``curved``: the mean indentation ``d0`` with ``F(d0) = load``, ``k_zc = 2 E* a0``,
    ``k_xc = 2 G*_mdr a0``) or the linearised one (the tangent stiffnesses at the load,
    ``u_z0 = load/k_zc``).
    """
    changes: dict[str, Any] = {}
    if radius is not None:
        changes["radius"] = radius
    if E_star is not None:
        scale = E_star / contact.e_star
        changes.update(pin=Material(contact.pin.E * scale, contact.pin.nu),
                       counterface=Material(contact.counterface.E * scale,
                                            contact.counterface.nu))
    c = dataclasses.replace(contact, **changes) if changes else contact
    if curved:
        d0 = float(c.indentation(load))
        return {"k_zc": float(c.normal_stiffness(d0)), "k_xc": float(c.tangential_stiffness(d0)),
                "u_z0": d0}
    k_zc, k_xc = c.stiffness(load)
    return {"k_zc": float(k_zc), "k_xc": float(k_xc), "u_z0": load / float(k_zc)}


def contact_exponents(contact: Contact, name: str, load: float, curved: bool
                      ) -> dict[str, float]:
    """``d ln field / d ln name`` of each of :data:`CONTACT_FIELDS`.

    ``d ln field / d ln name`` of each of :data:`CONTACT_FIELDS` (constants for the
    power-law tips: a sphere's ``k_zc`` goes as ``R^(1/3) E*^(2/3)``, its ``u_z0`` as the
    inverse), from two evaluations of :func:`contact_fields`.
    """
    x = contact_value(contact, name)
    a = contact_fields(contact, load, curved, **{name: x})
    b = contact_fields(contact, load, curved, **{name: 2.0 * x})
    return {k: math.log(b[k] / a[k]) / math.log(2.0) for k in CONTACT_FIELDS}


def check_law(guess: Physical, free: tuple[str, ...]) -> None:
    """ValueError, naming the parameter, for a law's parameter the guess does not carry.

    ``mu_static`` needs a guess with ``mu_static > mu0`` (its search, ``ln(mu_static/mu0)``
    from 0 up, must start inside); ``a``, ``b``, ``d_c`` a guess with ``friction=``
    :class:`~vibrofriction.RateAndState`.
    """
    if "mu_static" in free:
        if guess.mu_static is None:
            raise ValueError("free names mu_static, the static coefficient of friction, but the "
                             "guess has none (Coulomb friction): give the guess mu_static = a "
                             "value above mu0 to fit it")
        if not guess.static_ratio > 1.0:
            raise ValueError(f"free names mu_static, but the guess's mu_static = "
                             f"{guess.mu_static!r} is mu0: it is searched as ln(mu_static/mu0) "
                             "> 0 (never below the kinetic mu0) and must start above mu0: give "
                             "a guess with mu_static > mu0")
    rs = [n for n in free if n in RATE_STATE_FITTABLE]
    if rs and guess.friction is None:
        raise ValueError(f"free names {rs}, parameters of rate-and-state friction, but the guess "
                         "has none: give the guess friction=vf.RateAndState(a=..., b=..., "
                         "d_c=..., v_ref=...) to fit them")


def check_contact(guess: Physical, contact: Contact | None, free: tuple[str, ...]) -> None:
    """ValueError, naming the parameters, for a fit of a contact geometry it cannot make.

    A contact parameter without ``contact``, the contact's fields next to its parameters,
    ``radius`` and ``E_star`` together (not identifiable: docs/bench.md), a curved guess's
    contact fields without its geometry, or a guess not built from ``contact``.
    """
    geo = [n for n in free if n in CONTACT_FITTABLE]
    fields = [n for n in free if n in CONTACT_FIELDS]
    if contact is None:
        if geo:
            raise ValueError(f"free names {geo}, parameters of a contact geometry: pass "
                             "contact=Sphere(...) (the geometry the guess was built from)")
        if guess.curved and fields:
            raise ValueError(f"free names {fields}, but the guess is a curved MDR contact "
                             f"(profile_exponent = {guess.profile_exponent!r}) whose k_zc, "
                             "k_xc and u_z0 follow from its geometry at the load: pass "
                             "contact=Sphere(...) and fit radius or E_star")
        return
    if not isinstance(contact, Sphere | FlatPunch | Cone | PowerLaw):
        raise TypeError(f"contact must be a FlatPunch, Sphere, Cone or PowerLaw, got "
                        f"{type(contact).__name__}")
    for n in geo:
        contact_value(contact, n)  # refuses radius of a cone or a power law
    if fields:
        raise ValueError(f"free names {fields}, but with contact= the contact's k_zc, k_xc and "
                         f"u_z0 follow from its geometry at the load: fit "
                         f"{' or '.join(CONTACT_FITTABLE)} instead")
    if len(geo) > 1:
        raise ValueError("free names both radius and E_star, which the data cannot tell "
                         "apart: the contact enters the model only through k_zc = 2 E* a0 at "
                         "the load (k_xc/k_zc and k_zc u_z0 are fixed by Poisson's ratios and "
                         "the load), and a sphere's k_zc goes as (E*^2 R)^(1/3): fit one of "
                         "them with the other known (docs/bench.md)")
    if guess.curved and float(contact.exponent) != guess.profile_exponent:
        raise ValueError(f"the guess's profile_exponent {guess.profile_exponent!r} is not the "
                         f"contact's exponent {float(contact.exponent)!r}")
    built = contact_fields(contact, guess.F_N0, guess.curved)
    off = {k: v for k, v in built.items()
           if not math.isclose(v, getattr(guess, k), rel_tol=1e-6)}
    if off:
        shown = ", ".join(f"{k} {getattr(guess, k):.6g} (contact: {v:.6g})"
                          for k, v in off.items())
        raise ValueError(f"the guess was not built from this contact at its load "
                         f"{guess.F_N0:.6g} N: {shown}; build it with vf.from_bench("
                         f"contact=..., contact_model={'mdr' if guess.curved else 'linearised'!r})")


@dataclass
class Problem:
    """The free parameters in ``ln`` and how they map onto a :class:`Physical`."""

    guess: Physical
    free: tuple[str, ...]
    natural_frequency: bool
    normal_load: bool
    quality_factor: bool
    data: pd.DataFrame
    settings: SolverSettings | None = None
    #: the largest ``mu0`` of the search (the bound of an honest misfit, :meth:`penalty`)
    mu0_max: float | None = None
    #: the local fits' Jacobian: ``"exact"`` (:meth:`jacobian`) or ``"differences"``
    #: (lmfit's forward differences of the residuals)
    jacobian_kind: str = "exact"
    #: the contact geometry the guess was built from (its parameters may be free)
    contact: Any = None
    #: the largest ``|mu_ratio|`` of the search (:meth:`penalty`): 1 for Coulomb friction, the
    #: largest ``mu_static/mu0`` with a static coefficient, :data:`RATE_STATE_BOUND`
    ratio_max: float = 1.0
    #: the last solve of :meth:`evaluate` (``ln`` as bytes, the columns): lmfit asks for the
    #: Jacobian where it has just evaluated the residuals
    _last: tuple | None = field(default=None, init=False, repr=False, compare=False)

    def values(self, ln: NDArray[np.float64]) -> dict[str, Any]:
        """The fields of the system at ``ln`` of the free parameters, constraints applied.

        ``mu_static`` free is ``mu0 exp(ln)`` (its ``ln`` is that of ``mu_static/mu0``); a held
        ``mu_static`` keeps the guess's value (outside the domain where ``mu0`` passes it); free
        ``a``, ``b``, ``d_c`` replace those of the guess's law (``friction`` is ``_OUTSIDE`` where
        they leave its range: outside the domain, :func:`_in_domain`).
        """
        values = {f.name: getattr(self.guess, f.name) for f in dataclasses.fields(self.guess)}
        geo, law = {}, {}
        for n, x in zip(self.free, ln, strict=True):
            if n in CONTACT_FITTABLE:
                geo[n] = math.exp(x)
            elif n in LAW_FITTABLE:
                law[n] = math.exp(x)
            else:
                values[n] = math.exp(x)
        if "mu_static" in law:
            values["mu_static"] = values["mu0"] * law.pop("mu_static")
        if law:
            assert self.guess.friction is not None  # a, b, d_c need the law (check_law)
            try:
                values["friction"] = RateAndState(**{**dataclasses.asdict(self.guess.friction),
                                                     **law})
            except (ValueError, OverflowError):
                values["friction"] = _OUTSIDE
        g = self.guess
        if geo:
            try:
                values.update(contact_fields(self.contact, g.F_N0, g.curved, **geo))
            except (ValueError, OverflowError, ZeroDivisionError):
                values["k_zc"] = math.nan  # outside the domain
        if self.natural_frequency:
            wn2 = g.k_x / g.mass
            if "mass" in self.free:
                values["k_x"] = values["mass"] * wn2
            elif "k_x" in self.free:
                values["mass"] = values["k_x"] / wn2
        if self.normal_load:
            if "k_zc" in self.free:
                values["u_z0"] = g.F_N0 / values["k_zc"]
            elif "u_z0" in self.free:
                values["k_zc"] = g.F_N0 / values["u_z0"]
        if self.quality_factor:
            values["c_x"] = 2.0 * g.zeta * math.sqrt(values["k_x"] * values["mass"])
        return values

    def system(self, ln: NDArray[np.float64]) -> Physical:
        return Physical(**self.values(ln))

    def start(self, name: str) -> float:
        """The guess's value of the free parameter ``name`` (``exp`` of its ``ln`` coordinate).

        A field of the guess, a parameter of the contact, ``mu_static/mu0`` for ``mu_static`` or a
        parameter of the guess's rate-and-state law.
        """
        if name in CONTACT_FITTABLE:
            return contact_value(self.contact, name)
        if name == "mu_static":
            return self.guess.static_ratio
        if name in RATE_STATE_FITTABLE:
            return float(getattr(self.guess.friction, name))
        return float(getattr(self.guess, name))

    def named(self, ln: NDArray[np.float64]) -> dict[str, float]:
        """The fields of the system at ``ln`` and the free contact and law parameters' values.

        ``mu_static`` as the field (``mu0`` times the ratio), ``a``, ``b``, ``d_c`` of its law.
        """
        values = self.values(ln)
        values.update({n: math.exp(x) for n, x in zip(self.free, ln, strict=True)
                       if n in CONTACT_FITTABLE})
        law = values["friction"]
        values.update({n: float(getattr(law, n)) for n in self.free
                       if n in RATE_STATE_FITTABLE and isinstance(law, RateAndState)})
        return values

    @property
    def rate_state(self) -> bool:
        """Rate-and-state friction: the rate-and-state solver, differenced (no sensitivities)."""
        return self.guess.friction is not None

    @property
    def differenced(self) -> bool:
        """No sensitivities (a curved contact or rate-and-state friction): solver differences."""
        return self.curved or self.rate_state

    @property
    def step(self) -> float:
        """The step in ``ln`` of the solver's central differences (:meth:`_row_differences`)."""
        return MDR_STEP if self.curved else RATE_STATE_STEP if self.rate_state else SOLVER_STEP

    @property
    def curved(self) -> bool:
        """A curved MDR contact: solved by the MDR solver, differenced (no sensitivities)."""
        return self.guess.curved

    def penalty(self) -> NDArray[np.float64]:
        """The residual of a row the model cannot evaluate.

        Twice the largest honest one, ``(mu0_max ratio_max + |cof|) / sigma`` (``|mu_ratio| <=
        1`` with Coulomb friction, eq. 25; ``<= mu_static/mu0`` with a static coefficient, the
        largest of the search: :attr:`ratio_max`; :data:`RATE_STATE_BOUND` with rate-and-state
        friction), so that a failed row always costs more than any misfit of it.
        """
        mu0_max = self.guess.mu0 if self.mu0_max is None else self.mu0_max
        return 2.0 * (mu0_max * self.ratio_max + np.abs(self.data["cof"].to_numpy())) \
            / self._scale()

    def _scale(self) -> NDArray[np.float64] | float:
        return self.data["sigma"].to_numpy() if self.weighted else 1.0

    def evaluate(self, ln: NDArray[np.float64]) -> tuple[NDArray[np.float64], int, int]:
        """The residuals, and the counts of rows penalised (:meth:`penalty`).

        Penalised because the parameters leave the model's domain (every row) or because the
        solver's value is not trusted.
        """
        points = self.points(ln)
        if points is None:  # e.g. exp overflow, or k_x + k_xc == k_x in floats
            return self.penalty(), len(self.data), 0
        solved = self._solve(ln, points)
        return self._residuals(points[0], (solved["mu_ratio"], solved["trusted"]))

    def _solve(self, ln: NDArray[np.float64], points: tuple) -> dict[str, NDArray]:
        """:func:`solve_points` at ``points`` (of ``ln``), kept for :meth:`jacobian`."""
        key = np.asarray(ln, dtype=float).tobytes()
        if self._last is not None and self._last[0] == key:
            return self._last[1]
        solved = solve_points(*points[1:], inplane_on=self.guess.inplane_on,
                              rs_law=law_name(self.guess), settings=self.settings)
        self._last = (key, solved)
        return solved

    def points(self, ln: NDArray[np.float64]) -> tuple | None:
        """The solver's arguments of every row at ``ln`` (eq. 20).

        ``(mu0, alpha, beta, a, V, zeta, eta_c, a_x, phase_x, a_y, phase_y, alpha_y,
        zeta_y, profile_exponent, static_ratio, rs_a, rs_b, rs_d_c, rs_v_ref, rs_alpha_ld)`` of
        every row at ``ln`` (eq. 20, :func:`_groups`), or None where the parameters leave the
        model's domain.
        """
        values = self.values(ln)
        if not _in_domain(values):
            return None
        system, d = Physical(**values), self.data
        return (system.mu0, *_groups(system, *(d[c].to_numpy() for c in (
            "v0", "du_z", "omega", "du_x", "phase_x", "du_y", "phase_y"))))

    def _residuals(self, mu0: float, solved: tuple[NDArray, NDArray]
                   ) -> tuple[NDArray[np.float64], int, int]:
        r = (_cof(mu0, solved) - self.data["cof"].to_numpy()) / self._scale()
        bad = np.isnan(r)
        return np.where(bad, self.penalty(), r), 0, int(bad.sum())

    def residual(self, ln: NDArray[np.float64]) -> NDArray[np.float64]:
        return self.evaluate(ln)[0]

    def jacobian(self, ln: NDArray[np.float64], vary: NDArray[np.bool_] | None = None
                 ) -> NDArray[np.float64]:
        """``d residual / d ln`` of the free parameters ``vary`` (all by default): rows by columns.

        ``cof = mu0 mu_ratio`` is chained through the sensitivities of the steady state
        (:func:`~vibrofriction.solver.sensitivity.sensitivities`) and the derivatives of the
        cheap map ``ln -> (mu0, alpha, ..., phase_x)`` (:meth:`points`, central differences
        of that map alone).  Rows without a sensitivity (not periodic nor sliding, a neutral
        orbit, a difference across a grazing, a transverse row: the 2-D solver has none) are
        differenced through the solver, those rows only; penalised rows (untrusted, outside
        the domain) are constant: 0.
        """
        vary = np.ones(len(self.free), dtype=bool) if vary is None else np.asarray(vary)
        cols_j = np.flatnonzero(vary)
        out = np.zeros((len(self.data), cols_j.size))
        points = self.points(ln)
        if points is None:
            return out
        if self.differenced:  # no sensitivities (MDR, rate-and-state): differences, every row
            rows = np.flatnonzero(self._solve(ln, points)["trusted"])
            if rows.size:
                for c, j in enumerate(cols_j):
                    out[rows, c] = self._row_differences(ln, int(j), rows)
            return out
        mu0 = points[0]
        # d (mu0, alpha, ..., phase_x) / d ln_j of every row
        rates: list[list[NDArray[np.float64]] | None] = []
        for j in cols_j:
            up, down = ln.copy(), ln.copy()
            up[j] += MAP_STEP
            down[j] -= MAP_STEP
            pu, pd_ = self.points(up), self.points(down)
            if pu is None or pd_ is None:  # at the domain's edge: the solver's differences
                rates.append(None)
                continue
            rates.append([_rate(a, b) for a, b in zip(pu, pd_, strict=True)])
        moving = tuple(k for i, k in enumerate(SENSITIVE)
                       if any(r is not None and np.any(r[i + 1] != 0.0) for r in rates))
        solved = self._solve(ln, points)
        n_sens = len(SENSITIVE)  # points: mu0, SENSITIVE, a_y, phase_y, alpha_y, zeta_y
        # a transverse row is a 2-D point: the sensitivities are the 1-D solver's only
        transverse = np.asarray(points[1 + n_sens], dtype=float) > 0.0
        if np.all(transverse):  # every row differenced below
            sens_mu = {k: np.full(len(self.data), np.nan) for k in SENSITIVE}
        else:
            sens_mu = sensitivities(solved, *points[1:1 + n_sens],
                                    inplane_on=self.guess.inplane_on, settings=self.settings,
                                    order=2, parameters=moving,
                                    static_ratio=points[1 + LAW_START]).mu
        trusted, mu = solved["trusted"], solved["mu_ratio"]
        scale = self._scale()
        missing = np.zeros(len(self.data), dtype=bool)
        # a column that moves the static coefficient (mu_static, or mu0 under a held mu_static):
        # the sensitivities do not differentiate static_ratio, so the solver's differences
        law_columns = []
        for c, rate in enumerate(rates):
            if rate is None:
                missing[:] = True
                continue
            if np.any(rate[1 + LAW_START] != 0.0):
                law_columns.append(c)
                continue
            dmu = np.zeros(len(self.data))
            for name, dtheta in zip(SENSITIVE, rate[1:1 + n_sens], strict=True):
                moves = dtheta != 0.0
                dmu = dmu + np.where(moves, sens_mu[name] * np.where(moves, dtheta, 0.0), 0.0)
            out[:, c] = (rate[0] * mu + mu0 * dmu) / scale
            missing |= ~np.isfinite(out[:, c])
        missing |= transverse
        missing &= trusted
        out[~trusted] = 0.0
        if np.any(missing):
            rows = np.flatnonzero(missing)
            for c, j in enumerate(cols_j):
                out[rows, c] = self._row_differences(ln, int(j), rows)
        rows = np.flatnonzero(trusted & ~missing)
        for c in law_columns:
            if rows.size:
                out[rows, c] = self._row_differences(ln, int(cols_j[c]), rows)
        return out

    def _row_differences(self, ln: NDArray[np.float64], j: int, rows: NDArray[np.intp]
                         ) -> NDArray[np.float64]:
        """Central differences of the residuals of ``rows`` in ``ln[j]`` through the solver.

        Central differences of the residuals of ``rows`` in ``ln[j]`` through the solver
        (:attr:`step`: :data:`SOLVER_STEP`; :data:`MDR_STEP` for a curved contact,
        :data:`RATE_STATE_STEP` under rate-and-state friction); 0 where a side is penalised.
        """
        sides = []
        step = self.step
        for sign in (1.0, -1.0):
            x = ln.copy()
            x[j] += sign * step
            p = self.points(x)
            if p is None:
                return np.zeros(rows.size)
            mu, trusted = _solve_points(tuple(g[rows] for g in p[1:])
                                        + (self.guess.inplane_on, law_name(self.guess),
                                           self.settings))
            cof = p[0] * np.where(trusted, mu, np.nan)
            sides.append(cof)
        scale = self._scale()
        d = (sides[0] - sides[1]) / (2.0 * step) / (
            scale[rows] if isinstance(scale, np.ndarray) else scale)
        return np.where(np.isfinite(d), d, 0.0)

    def cost(self, ln: NDArray[np.float64]) -> float:
        r = self.residual(ln)
        return float(r @ r)

    def costs(self, population: NDArray[np.float64], map_, chunks: int) -> NDArray[np.float64]:
        """:meth:`cost` of every column of ``population``.

        :meth:`cost` of every column of ``population`` (``ln``, shape ``(free, S)``:
        the global search's screen), the rows of all
        members solved together in ``chunks`` interleaved tasks of ``map_`` (each point
        depends only on its own parameters, so the costs are those of :meth:`cost`).
        """
        members = [self.points(x) for x in np.asarray(population, dtype=float).T]
        inside = [p for p in members if p is not None]
        out = np.empty(len(members))
        if inside:
            columns = [np.concatenate([p[j] for p in inside])
                       for j in range(1, len(inside[0]))]
            size = columns[0].size
            parts = [np.arange(i, size, chunks) for i in range(min(chunks, size))]
            mu_ratio, trusted = np.empty(size), np.zeros(size, dtype=bool)
            tasks = [tuple(c[idx] for c in columns)
                     + (self.guess.inplane_on, law_name(self.guess), self.settings)
                     for idx in parts]
            for idx, (m, t) in zip(parts, map_(_solve_points, tasks), strict=True):
                mu_ratio[idx], trusted[idx] = m, t
        rows, start = len(self.data), 0
        for i, p in enumerate(members):
            if p is None:
                r = self.penalty()
            else:
                part = slice(start, start + rows)
                r = self._residuals(p[0], (mu_ratio[part], trusted[part]))[0]
                start += rows
            out[i] = r @ r
        return out


    def coarse(self) -> Problem:
        """The same problem on every other row of a large table.

        A table of at least :data:`COARSE_ROWS` rows (the global stage's cheaper chi-square).
        """
        if len(self.data) < COARSE_ROWS:
            return self
        return dataclasses.replace(self, data=self.data.iloc[::2].reset_index(drop=True))

    @property
    def weighted(self) -> bool:
        """Residuals divided by the measured ``sigma`` (given on every row)."""
        return bool(np.all(np.isfinite(self.data["sigma"].to_numpy())))


def _solve_points(task) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """``mu_ratio`` and ``trusted`` at the points of ``task``: a pool task.

    ``mu_ratio`` and ``trusted`` at the points of ``task`` (the twelve group arrays of
    :meth:`Physical.point_arguments`, ``profile_exponent`` and the law's :data:`LAW_GROUPS`,
    ``inplane_on``, ``rs_law`` and the settings): a pool task of :meth:`Problem.costs`.
    """
    *groups, inplane_on, rs_law, settings = task
    out = solve_points(*groups, inplane_on=inplane_on, rs_law=rs_law, settings=settings)
    return out["mu_ratio"], out["trusted"]


#: :meth:`Problem.values`' ``friction`` where the free law parameters leave its range.
_OUTSIDE = "outside the law's range"


def _in_domain(values: dict[str, Any]) -> bool:
    """Whether ``values`` make a valid :class:`Physical`.

    Whether ``values`` make a valid :class:`Physical` whose every point has
    ``beta > alpha`` (checked here, so that no error of the model is swallowed).
    """
    positive = ("mass", "k_x", "k_zc", "u_z0", "omega", "mu0")
    if not all(math.isfinite(values[n]) and values[n] > 0.0 for n in positive):
        return False
    if not values["k_xc"] > 0.0:  # math.inf: a rigid contact
        return False
    if values["friction"] is _OUTSIDE or (values["mu_static"] is not None and not (
            values["mu_static"] >= values["mu0"] and math.isfinite(values["mu_static"]))):
        return False
    if not all(math.isfinite(values[n]) and values[n] >= 0.0 for n in ("c_x", "c_xc", "du_z")):
        return False
    return values["k_x"] + values["k_xc"] > values["k_x"]


def search_bounds(problem: Problem, span: float) -> list[tuple[float, float]]:
    """The search range of each free parameter in ``ln``: a factor ``span`` about the guess.

    ``mu_static``'s coordinate ``ln(mu_static/mu0)`` is cut at 0 (``mu_static >= mu0``).
    """
    out = []
    for n in problem.free:
        x = math.log(problem.start(n)) if problem.start(n) > 0 else None
        if x is None:
            raise ValueError(f"{n} of the guess must be > 0 to be fitted, got "
                             f"{problem.start(n)!r}")
        lo = x - math.log(span)
        out.append((max(lo, 0.0) if n == "mu_static" else lo, x + math.log(span)))
    return out


#: The pairs a constraint ties together (the first follows the second when that is free,
#: and the other way round), and the single field it sets.
_CONSTRAINED = {"natural_frequency": ("mass", "k_x", "k_x = mass (2 pi f_n)^2"),
                "normal_load": ("k_zc", "u_z0", "k_zc u_z0 = F_N0")}


def free_and_tied(free: tuple[str, ...], natural_frequency: bool, normal_load: bool,
                   quality_factor: bool, points: int
                   ) -> tuple[tuple[str, ...], dict[str, tuple[str, float]]]:
    """``free`` validated, and the fields that follow a free one by a constraint.

    ``free`` validated (a field a constraint holds is refused, naming the keyword that
    releases it), and the fields that follow a free one by a constraint (``name:
    (source, +-1)``, ``ln name = +-ln source + const``).
    """
    unknown = [n for n in free if n not in FITTABLE + CONTACT_FITTABLE + LAW_FITTABLE]
    if unknown or not free:
        raise ValueError(f"free must name fields of Physical among {list(FITTABLE)}, "
                         f"parameters of the contact among {list(CONTACT_FITTABLE)} or of "
                         f"the friction law among {list(LAW_FITTABLE)}, got {list(free)}")
    if len(set(free)) != len(free):
        raise ValueError(f"free names a parameter twice: {list(free)}")
    on = {"natural_frequency": natural_frequency, "normal_load": normal_load}
    tied: dict[str, tuple[str, float]] = {}
    for key, (a, b, law) in _CONSTRAINED.items():
        if not on[key]:
            continue
        if a in free and b in free:
            raise ValueError(f"free names both {a} and {b}, but the constraint {key} "
                             f"({law}, of the guess) holds {b} to {a}: pass {key}=False to "
                             f"fit both, or leave one out of free")
        sign = 1.0 if key == "natural_frequency" else -1.0
        if a in free:
            tied[b] = (a, sign)
        elif b in free:
            tied[a] = (b, sign)
    if quality_factor and "c_x" in free:
        raise ValueError("free names c_x, but the constraint quality_factor (c_x = 2 zeta "
                         "sqrt(k_x mass), zeta of the guess) holds it: pass "
                         "quality_factor=False to fit c_x")
    if len(free) > points:
        raise ValueError(f"{len(free)} free parameters but only {points} data points")
    return free, tied
