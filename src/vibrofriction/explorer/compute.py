"""What the views show, computed by the library.

Plain, picklable functions of a :class:`~vibrofriction.explorer.state.State`, run in worker
processes (:mod:`.pool`).
"""

from __future__ import annotations

import functools
import math
import time
from typing import Any, cast

import numpy as np

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction.capabilities import CAPABILITIES
from vibrofriction.params import dimensionless as _dimensionless
from vibrofriction.params import inertial_velocity
from vibrofriction.schema import RESULT_FIELDS, ContactState, parameter_names

from .state import AXES, LAWS, State, law_solver

__all__ = ["CONTACT_STATES", "case_map", "curve", "history", "measurement_curves",
           "not_computed", "parse_measurements", "profile_text", "run_fit"]

CASE_COLORS = {"I": "#a6cee3", "II": "#b2df8a", "III": "#fb9a99", "IV": "#fdbf6f",
               "general": "#f0f0f0"}


def profile_text(exponent: float) -> str:
    """The tip's name as the page shows it: ``flat punch``, ``sphere (n = 2)``, ..."""
    if exponent == math.inf:
        return "flat punch"
    name = {2.0: "sphere", 1.0: "cone"}.get(exponent, "power law")
    return f"{name} (n = {exponent:g})"


def _to_axis(state: State, system, V: np.ndarray) -> np.ndarray:
    """Inertial velocities ``V`` on the state's axis (the library's conversions)."""
    if state.axis == "V":
        return np.asarray(V, dtype=float)
    if state.axis == "vbar":
        return np.asarray(_dimensionless(system).inertial_to_vbar(V), dtype=float)
    return np.asarray(system.inertial_to_v0(V), dtype=float)


#: The result fields a curve holds, one value per point (the schema's, by name; ``status``
#: as its name): every field but the section state and the system.
RESULT_COLUMNS = tuple(f.name for f in RESULT_FIELDS if f.name not in ("final_state", "system"))
#: Every per-point array of a curve: the axis ``x``, the plotted ``y`` and the results.
POINT_COLUMNS = ("x", "y", *RESULT_COLUMNS)


def _inertial(state: State, system, x: np.ndarray) -> np.ndarray:
    """The curve's velocities ``x`` as inertial velocities (the library's conversion)."""
    return np.asarray(inertial_velocity(system, **{state.velocity_keyword(): x}), dtype=float)


def not_computed(curve: dict) -> np.ndarray:
    """The points of a curve without a value (e.g. ``V = 0`` of the 2-D solver)."""
    return ~np.asarray(curve["trusted"], dtype=bool) & ~np.isfinite(
        np.asarray(curve["y"], dtype=float))


def merge(parts: list[dict]) -> dict:
    """One curve from the interleaved shares of :func:`curve` (in share order)."""
    n = len(parts)
    out = dict(parts[0])
    size = sum(len(p["x"]) for p in parts)
    for name in POINT_COLUMNS:
        col = np.empty(size, dtype=np.asarray(parts[0][name]).dtype)
        for i, p in enumerate(parts):
            col[i::n] = p[name]
        out[name] = col
    out["seconds"] = max(p["seconds"] for p in parts)
    return out


def curve(state: State, part: tuple[int, int] = (0, 1)) -> dict:
    """The friction curve of the state, with what the page draws over it.

    ``mu/mu0`` (or the COF on a bench) over the state's velocities by the exact solver
    (a curved tip: the MDR solver), with the static value (eq. 2), the critical velocity
    (eq. 12; a curved tip: ``theory.profile_critical_velocity``, or the library's reason
    for none in ``critical_note``), the case and the closed forms that apply; ``rest_note``
    says why ``V = 0`` is left out (:attr:`State.rest_refused`), else ``""``.
    ``part = (i, n)``: only the ``i``-th of ``n`` interleaved shares of the points
    (:func:`merge` joins them; the closed forms come with share 0).
    """
    t0 = time.perf_counter()
    system = state.system()
    dim = _dimensionless(system)
    i, n = part
    x = state.velocities()[i::n]
    # the 2-D solver does not compute V = 0 (docs/inplane.md section 6): a gap there
    solved = x != 0.0 if dim.a_y > 0.0 else np.ones(x.size, dtype=bool)
    res = cast(vf.FrictionResults,  # the velocities are an array
               vf.friction_coefficient(system, **{state.velocity_keyword(): x[solved]}))
    scale = system.mu0 if isinstance(system, vf.Physical) else 1.0
    curved = dim.curved
    critical_note = ""
    try:  # a curved tip: theory.profile_critical_velocity, derived without a_x
        V_c = dim.critical_inertial_velocity()
    except ValueError as exc:
        V_c, critical_note = math.nan, str(exc)
    critical = {"vbar": 1.0, "V": V_c}.get(state.axis, math.nan)  # v0: below
    if state.axis == "v0":
        assert isinstance(system, vf.Physical)  # the v0 axis is the bench's
        critical = system.critical_velocity()
    if not (V_c > 0.0 and math.isfinite(V_c)):
        critical = math.nan
    if state.friction == "rate_state":  # eq. (12) is Coulomb's: no critical velocity
        critical = math.nan
    static = math.nan  # eq. (2) is the limit v0 -> 0+ of the normal oscillation alone
    if dim.a_x == 0.0 and dim.a_y == 0.0 and x[0] >= 0.0 and state.friction == "coulomb":
        static = float(theory.profile_static_mu_ratio(dim.amplitude, dim.profile_exponent)
                       if curved else theory.static_mu_ratio(dim.amplitude)) * scale
    case = vf.classify(dim.alpha, dim.beta)
    rest_note = ""
    if state.rest_refused and np.any(state.grid() == 0.0):
        try:  # the library's refusal of the point left out
            vf.friction_coefficient(system, v_inertial=0.0)
        except ValueError as exc:
            rest_note = f"V = 0 left out of the curve: {exc}"
    results = {k: _spread(np.asarray(getattr(res, k)), solved) for k in RESULT_COLUMNS}
    results["status"] = _spread(np.asarray([s.value for s in res.status], dtype=object),
                                solved, "not computed (V = 0, transverse oscillation)")
    return {
        "x": x, "y": np.asarray(results["mu_ratio"], dtype=float) * scale, **results,
        "static": static,
        "mean_normal": float(theory.profile_mean_normal_force(dim.amplitude,
                                                              dim.profile_exponent)),
        "profile": profile_text(dim.profile_exponent),
        "band": _band(dim, scale) if state.friction == "coulomb" else None,
        "critical": float(critical), "jumping": dim.jumping,
        "law": state.friction, "law_text": law_text(state),
        "case": case.value,
        "case_text": _curved_case_text(case) if curved else case.description,
        "critical_label": ("critical velocity of continuous sliding (curved tip)" if curved
                           else "critical velocity, eq. (12)"),
        "critical_note": critical_note, "rest_note": rest_note,
        **{n: getattr(dim, n) for n in parameter_names("dimensionless", optional=False)},
        "closed_forms": [] if i else closed_forms(state, system, state.velocities(), case,
                                                  scale),
        "x_label": ("vbar = v0/v0* (v0*: the curved tip's critical velocity)"
                    if curved and state.axis == "vbar" else AXES[state.axis][1]),
        "y_label": "COF = mu" if scale != 1.0 else "mu/mu0",
        "mu0": scale if scale != 1.0 else None,
        "seconds": time.perf_counter() - t0,
    }


#: the bench's law inputs as the library names them (vf.RateAndState's fields) and their units
_SHORT = {"friction_a": "a", "friction_b": "b", "friction_d_c_um": "d_c",
          "friction_v_ref_mm_s": "v_ref", "friction_alpha_ld": "alpha_ld"}
_UNITS = {"friction_d_c_um": " um", "friction_v_ref_mm_s": " mm/s"}


def solver_text(curve: dict) -> str:
    """The solver of a curve as its plot's title and legend name it."""
    if curve.get("profile", "flat punch") != "flat punch":
        return f"{curve['profile']}, MDR solver"
    return "rate-and-state solver" if curve.get("law") == "rate_state" else "exact solver"


def law_text(state: State) -> str:
    """The friction law as the page names it, with its parameters (``Coulomb`` alone)."""
    if state.friction == "coulomb":
        return "Coulomb"
    values = ", ".join(f"{_SHORT.get(f.name, f.name)} = {getattr(state, f.name):g}"
                       f"{_UNITS.get(f.name, '')}" for f in state.law_fields())
    law = f", {state.rs_law} law" if state.friction == "rate_state" else ""
    return f"{LAWS[state.friction]} ({values}{law})"


def _curved_case_text(case: vf.Case) -> str:
    """The case of ``(alpha, beta)`` for a curved tip.

    ``classify``'s description without its flat-punch ``v0*`` (eqs. 12 to 14; a curved tip's is
    ``theory.profile_critical_velocity``) and what follows it.
    """
    head = case.description.split("v0*")[0].rstrip(" :;,")
    return (f"{head}; the critical velocity of a curved tip is that of continuous sliding "
            "(theory.profile_critical_velocity, docs/contact_geometry.md)")


def _spread(values: np.ndarray, solved: np.ndarray, fill: object = None) -> np.ndarray:
    """``values`` at the ``solved`` points, a gap elsewhere (nan, False, -1 or ``fill``)."""
    if solved.all():
        return values
    if fill is None:
        fill = {"f": np.nan, "b": False}.get(values.dtype.kind, -1)
    out = np.full(solved.size, fill, dtype=values.dtype)
    out[solved] = values
    return out


def _band(dim: vf.Dimensionless, scale: float) -> tuple[float, float, str] | None:
    """The closed-form stuck band of an in-plane oscillation.

    The blocking forces ``mu(V -> 0+)``, ``mu(V -> 0-)`` of the closed-form stuck band (nan: slips
    every cycle) and the regime's name.
    """
    if dim.a_x == 0.0 or dim.a_y > 0.0 or dim.curved:  # the flat punch's 1-D stuck band
        return None
    args = (dim.alpha, dim.beta, dim.amplitude, dim.a_x, dim.phase_x, dim.zeta, dim.eta_c,
            dim.inplane_on)
    upper, lower = theory.inplane_static_mu_ratio(*args)
    code = int(theory.inplane_regime(*args))
    name = theory.INPLANE_REGIMES[code] if code >= 0 else "slips every cycle near V = 0"
    return float(upper) * scale, float(lower) * scale, name


def closed_forms(state: State, system, x: np.ndarray, case: vf.Case,
                 scale: float) -> list[dict]:
    """The closed forms that apply to this system, at the curve's velocities.

    The paper's closed forms (docs/theory.md) that apply to this system, each with its
    label and its points at the curve's velocities ``x``; none outside their regime. They
    are Coulomb's: under another friction law, only rate-and-state friction's steady
    sliding without oscillation (``theory.steady_mu_ratio``, odd in ``V``).
    """
    dim = _dimensionless(system)
    V = _inertial(state, system, x)
    a = dim.amplitude
    out: list[dict] = []
    if state.friction != "coulomb":
        if state.friction == "rate_state":
            mu = theory.steady_mu_ratio(V, dim.rs_a, dim.rs_b, dim.rs_d_c, dim.rs_v_ref)
            out.append({"label": "steady sliding without oscillation, mu_ss(v0)",
                        "x": x, "y": np.asarray(mu, dtype=float) * scale})
        return out
    if dim.curved:
        return _curved_closed_forms(dim, x, V, case, scale)
    if dim.a_x > 0.0 or dim.a_y > 0.0:  # the laws below are the normal oscillation's only
        return out
    V_c = dim.critical_inertial_velocity()
    vbar = V / V_c if 0.0 < V_c < math.inf else None

    def add(label: str, y, where=None) -> None:
        y = np.asarray(y, dtype=float) * scale
        keep = np.ones(x.size, bool) if where is None else where
        out.append({"label": label, "x": x[keep], "y": np.broadcast_to(y, x.shape)[keep]})

    if a <= 1.0 and not dim.damped and vbar is not None:
        if case is vf.Case.STIFF:
            add("exact stiff law (alpha, beta -> 0)", theory.mu_ratio_stiff_exact(vbar, a))
            add("eq. (26), stiff law of Part I", theory.mu_ratio_stiff(vbar, a))
        elif case is vf.Case.SOFT:
            add("eq. (27) corrected, soft law", theory.mu_ratio_soft_corrected(vbar, a))
    if case is vf.Case.RESONANT_SYSTEM:
        if dim.zeta == 0.0:
            add("eq. (32): case IV plateau, exact tau* (V -> inf)",
                theory.resonant_plateau_exact(a))
        elif math.isfinite(V_c):
            where = (V >= 0.3 * V_c)
            add("case IV damped rise (energy balance, docs/damping.md)",
                theory.resonant_damped_mu_ratio(V, a, dim.zeta), where)
    if case is vf.Case.RESONANT_CONTACT and a <= 1.0 and not dim.damped:
        add("case III: mu = mu0 for v0 > 0", 1.0, V > 0.0)
    return out


def _curved_closed_forms(dim: vf.Dimensionless, x: np.ndarray, V: np.ndarray,
                         case: vf.Case, scale: float) -> list[dict]:
    """The closed forms of a curved tip (docs/contact_geometry.md).

    Its stiff law in case II, undamped (``theory.mu_ratio_stiff_profile``, the quadrature of the
    flat law over the MDR springs, at ``vbar = (beta - alpha) V n/((n + 1) a)``); none with ``a_x >
    0``.
    """
    a, n = dim.amplitude, dim.profile_exponent
    if case is not vf.Case.STIFF or dim.damped or a == 0.0 or dim.a_x > 0.0:
        return []
    keep = V >= 0.0
    vbar = (dim.beta - dim.alpha) * V[keep] * n / ((n + 1.0) * a)
    y = np.asarray(theory.mu_ratio_stiff_profile(vbar, a, n), dtype=float) * scale
    return [{"label": "stiff law of the curved tip (alpha, beta -> 0)", "x": x[keep],
             "y": y}]


#: The state of an MDR spring by its code in ``CurvedHistory.spring_state``
#: (:class:`~vibrofriction.schema.ContactState`), as the space-time view names them.
CONTACT_STATES = tuple(s.long_name for s in ContactState)


def history(state: State, x: float, periods: float = 3.0) -> dict:
    """The time history at the curve's velocity ``x`` (Fig. 2).

    Forces, phases, events; the steady state where the solver trusts it, else the motion from steady
    sliding. With an in-plane oscillation (``a_x > 0`` or ``a_y > 0``) also the contact point's
    position on the substrate (``History.contact_point``): ``xc`` and, in 2-D, ``yc`` and the
    transverse force ``f_y`` (None otherwise). With rate-and-state friction also the state
    ``theta`` (unit ``1/omega``), its steady-sliding value ``d_c/|V|`` and the local coefficient
    of steady sliding ``mu_ss(V)/mu_star`` (``sliding_mu_ratio``); None otherwise. A curved tip:
    :func:`mdr_history`.
    """
    if state.curved:
        return mdr_history(state, x)
    system = state.system()
    kw: dict[str, Any] = {state.velocity_keyword(): float(x)}
    solver = CAPABILITIES[law_solver(state.friction)]
    if not solver.histories:  # vf.simulate does not cover it (its declaration)
        r = cast(vf.FrictionResult, vf.friction_coefficient(system, **kw))
        return {"t": None, "x": float(x), "mu_ratio": float(r.mu_ratio),
                "status": r.status.value, "trusted": bool(r.trusted),
                "message": f"{solver.title} gives no time history yet (vf.simulate does not "
                           "cover it)"}
    try:
        h = vf.simulate(system, **kw, periods=periods, initial="steady")
        steady = True
    except ValueError:
        h = vf.simulate(system, **kw, periods=periods)
        steady = False
    t = h.tau / (2.0 * math.pi)
    change = np.flatnonzero(h.phase[1:] != h.phase[:-1]) + 1
    starts = np.concatenate([[0], change])
    ends = np.concatenate([change, [t.size - 1]])
    r = cast(vf.FrictionResult, vf.friction_coefficient(system, **kw))  # one velocity
    inplane = h.system.a_x > 0.0 or h.system.a_y > 0.0
    xc, yc = h.contact_point() if inplane else (None, None)
    f_y = h.f_y if isinstance(h, vf.PlaneHistory) else None  # 2-D only, as yc
    with np.errstate(divide="ignore", invalid="ignore"):  # no coefficient in flight
        coefficient = np.where(h.n > 0.0, h.f / h.n, np.nan)
    rs = h if isinstance(h, vf.RateStateHistory) else None
    if rs is not None:  # the integrator's own local coefficient (nan in flight)
        coefficient = rs.local_mu
    return {
        "theta": None if rs is None else rs.theta,
        "theta_sliding": None if rs is None else rs.system.rs_d_c / abs(rs.v_inertial),
        "sliding_mu_ratio": float(r.sliding_mu_ratio),
        "t": t, "f": h.f, "n": h.n, "x_dot": h.x_dot, "f_y": f_y,
        "coefficient": coefficient,
        "static_ratio": h.system.static_ratio,
        "phase": h.phase, "xc": xc, "yc": None if f_y is None else yc,
        "spans": [(float(t[i]), float(t[j]), str(h.phase[i])) for i, j in
                  zip(starts, ends, strict=True) if t[j] > t[i]],
        "events": [(e.tau / (2.0 * math.pi), e.kind) for e in h.events],
        "steady": steady, "x": float(x), "mu_ratio": float(r.mu_ratio),
        "status": r.status.value, "trusted": bool(r.trusted), "message": r.message,
    }


def mdr_history(state: State, x: float, periods: float = 1.0,
                samples_per_period: int = 200) -> dict:
    """A curved tip's history at the inertial velocity ``x``.

    A curved tip's history at the inertial velocity ``x`` (``vf.simulate`` of the MDR
    row, ``initial="steady"``: one period of its periodic orbit; where the row has none,
    the last of three periods from steady sliding, said so): the forces and phases of
    :func:`history` and, for the space-time view (``spacetime``), ``t`` (drive periods),
    the springs' positions ``xi = x/a0`` along the profile, each spring's state per sample
    (``state``, shape ``(T, M)``, codes of :data:`CONTACT_STATES`), the stick and contact
    radii and the area fractions against time.  ``spacetime`` is None, with the reason in
    ``message``, where the library gives no history.
    """
    system = state.system()
    message = ""
    try:
        try:
            h = vf.simulate(system, v_inertial=float(x), periods=periods, initial="steady",
                            samples_per_period=samples_per_period)
            steady = True
        except ValueError as exc:
            if "did not converge" not in str(exc):
                raise
            h = vf.simulate(system, v_inertial=float(x), periods=3.0 * periods,
                            samples_per_period=samples_per_period)
            steady = False
            message = "no periodic orbit of the row: the third period from steady sliding"
    except ValueError as exc:  # a library without the MDR history
        return {"curved": True, "x": float(x), "spacetime": None, "t": None,
                "message": f"needs the MDR history ({exc})"}
    last = h.tau >= h.tau[-1] - 2.0 * math.pi * periods - 1e-9  # the period shown
    t = h.tau[last] / (2.0 * math.pi)
    phase = h.phase[last]
    change = np.flatnonzero(phase[1:] != phase[:-1]) + 1
    starts = np.concatenate([[0], change])
    ends = np.concatenate([change, [t.size - 1]])
    assert isinstance(h, vf.CurvedHistory)  # a curved tip's history
    return {
        "curved": True, "x": float(x), "steady": steady, "message": message,
        "t": t, "f": h.f[last], "n": h.n[last], "x_dot": h.x_dot[last], "f_y": None,
        "phase": phase, "xc": None, "yc": None, "events": [],
        "spans": [(float(t[i]), float(t[j]), str(phase[i])) for i, j in
                  zip(starts, ends, strict=True) if t[j] > t[i]],
        "spacetime": {"t": t, "xi": h.xi, "state": h.spring_state[last],
                      "stick_radius": h.stick_radius[last],
                      "contact_radius": h.contact_radius[last],
                      "stick": h.stick_area_fraction[last],
                      "slip": h.slip_area_fraction[last],
                      "open": h.open_area_fraction[last], "springs": int(h.xi.size)},
    }


@functools.lru_cache(maxsize=4)
def case_map(n: int = 90, alpha: tuple[float, float] = (1e-3, 1e2),
             beta: tuple[float, float] = (1e-3, 1e4)) -> dict:
    """The cases I-IV of ``vf.classify`` over a log grid of ``(alpha, beta)``.

    ``""`` where ``beta <= alpha`` (no system).
    """
    al = np.geomspace(*alpha, n)
    be = np.geomspace(*beta, n)
    cases = np.full((n, n), "", dtype=object)
    for j, b in enumerate(be):
        for i, a in enumerate(al):
            if b > a:
                cases[j, i] = vf.classify(a, b).value
    return {"alpha": al, "beta": be, "cases": cases, "alpha_range": alpha,
            "beta_range": beta}


def parse_measurements(content: bytes, name: str = "measurements.csv"):
    """A dropped CSV as the library's measurement table.

    A dropped CSV as the library's measurement table (``vf.read_measurements``; its
    messages name the file and the line).
    """
    import tempfile
    from pathlib import Path

    name = Path(name).name or "measurements.csv"
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / name
        path.write_bytes(content)
        try:
            return vf.read_measurements(path)
        except UnicodeDecodeError as exc:
            raise ValueError(f"{name!r} is not a text (CSV) file: {exc}") from None
        except ValueError as exc:
            raise ValueError(str(exc).replace(str(path), name)) from None
        except Exception as exc:  # a parser error of pandas: not a table
            raise ValueError(f"{name!r} is not a CSV table: {exc}") from None


def measurement_curves(state: State, data) -> list[dict]:
    """The measured points with the model's COF at the same points.

    The measured points per (amplitude, frequency) on the state's axis, with the model's
    COF at the same points (the bench's system at that amplitude and frequency).
    """
    system = state.system()
    if not isinstance(system, vf.Physical):
        raise ValueError("measurements are in SI units: choose the bench inputs to overlay "
                         "them")
    out = []
    for (du_z, omega), g in data.groupby(["du_z", "omega"], sort=True):
        point = system.with_(du_z=float(du_z), omega=float(omega))
        V = np.asarray(point.v0_to_inertial(g["v0"].to_numpy()))
        x = _to_axis(state, point, V) if state.axis != "vbar" else \
            np.asarray(point.v0_to_vbar(g["v0"].to_numpy()))
        out.append({"label": f"du_z = {du_z * 1e6:.3g} um, f = {omega / (2 * math.pi):.4g} Hz",
                    "x": np.asarray(x, float), "cof": g["cof"].to_numpy(),
                    "sigma": g["sigma"].to_numpy(), "du_z": float(du_z),
                    "omega": float(omega)})
    return out


def run_fit(state: State, data, free: tuple[str, ...]) -> dict:
    """``vf.fit`` of the bench to the measurements.

    Its report and the fitted COF per measured (amplitude, frequency) on the state's axis.
    """
    guess = state.system()
    if not isinstance(guess, vf.Physical):
        raise ValueError("the fit needs the bench inputs (a Physical guess)")
    res = vf.fit(data, guess, free=list(free), progress=False)
    curves = []
    for (du_z, omega), g in data.groupby(["du_z", "omega"], sort=True):
        v0 = np.geomspace(max(g["v0"].min(), 1e-9), max(g["v0"].max(), 2e-9), 80)
        cof = res.predict(v0, np.full(v0.size, du_z), np.full(v0.size, omega))
        point = res.system.with_(du_z=float(du_z), omega=float(omega))
        x = _to_axis(state, point, np.asarray(point.v0_to_inertial(v0)))
        curves.append({"x": x, "cof": cof})
    return {"report": res.report(), "curves": curves,
            "system": {k: getattr(res.system, k) for k in (
                "mass", "k_x", "k_xc", "k_zc", "u_z0", "du_z", "omega", "mu0", "c_x",
                "c_xc")}}
