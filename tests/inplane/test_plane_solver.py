"""The 2-D (transverse) in-plane solver (issue 20, item 2), against physics it does not
contain.

* differential: against the independent reference ``vibrofriction_reference.inplane_mean``
  (solve_ivp DOP853, no shared code) at the points of ``tests/data/plane_reference.json``
  (transverse only, normal + transverse, all three components, substrate and holder,
  Jenkins and Kelvin-Voigt contacts, jumping, damped and lightly damped, several phases,
  ``V < 0``, a pin that is not axisymmetric: ``alpha_y != alpha``, ``zeta_y != zeta``),
  cached by ``tests/data/make_plane_reference.py``: ``mu_ratio`` and ``lateral_ratio``
  within their combined error bars;
* the pin across the sliding: ``alpha_y = alpha``, ``zeta_y = zeta`` given explicitly (or
  ``k_y = k_x``, ``c_y = c_x``) is bit for bit the default; without a transverse
  oscillation they have no effect (the 1-D solver, and the 2-D kernel to its error);
* ``a_y -> 0`` is the exact 1-D solver (and the 2-D kernel at ``a_y = 0`` is too);
* the kinematic transverse law of a rigid body, ``theory.kinematic_mu_transverse``,
  approached as the system stiffens;
* the transverse mirror ``y -> -y``: ``mu(phase_y) = mu(phase_y + pi)``,
  ``lateral(phase_y + pi) = -lateral(phase_y)``;
* ``|f| <= n`` along the orbit's steps; the refusals.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction._kernels import plane
from vibrofriction.schema import FLOAT_COLUMNS, INT_COLUMNS, Status, column_index
from vibrofriction.solver import solve_points

DATA = json.loads((Path(__file__).parents[1] / "data" / "plane_reference.json").read_text())
POINTS = DATA["points"]
#: Agreement is required within SAFETY times the combined error bar.
SAFETY = 3.0
ARGS = ("alpha", "beta", "amplitude", "v_inertial", "zeta", "eta_c", "a_x", "phase_x",
        "a_y", "phase_y", "alpha_y", "zeta_y")


def _solve(p: dict) -> dict:
    cols = solve_points(*(p.get(k) for k in ARGS), inplane_on=p["inplane_on"])
    return {k: v[()].item() for k, v in cols.items()}


@pytest.mark.parametrize("p", POINTS, ids=[p["label"] for p in POINTS])
def test_agrees_with_the_reference(p: dict) -> None:
    r = _solve(p)
    assert r["trusted"], (r["status"], r["error"])
    assert r["status"] == Status.PERIODIC.code
    dmu = abs(r["mu_ratio"] - p["mu_ref"])
    dlat = abs(r["lateral_ratio"] - p["lat_ref"])
    print(f"{p['label']:40s} |dmu| {dmu:.1e} (bars {r['error']:.1e} + {p['err_ref']:.1e}) "
          f"|dlat| {dlat:.1e} (bars {r['error']:.1e} + {p['lat_err_ref']:.1e})")
    assert dmu <= SAFETY * (r["error"] + p["err_ref"]) + 1e-12
    assert dlat <= SAFETY * (r["error"] + p["lat_err_ref"]) + 1e-12
    # the time fractions to the reference's event resolution
    for k in ("stick_fraction", "flight_fraction"):
        assert abs(r[k] - p[k]) < 1e-5, k
    slip = r["slip_fraction"] + r["reverse_slip_fraction"]  # the reference's is all slip
    assert abs(slip - p["slip_fraction"]) < 1e-5


def test_reference_cache_covers_every_regime() -> None:
    assert len(POINTS) >= 12
    assert any(p["amplitude"] == 0.0 for p in POINTS)  # transverse only
    assert any(p["amplitude"] > 1.0 and p["eta_c"] > 0.0 for p in POINTS)  # jumping, K-V
    assert any(p["amplitude"] > 1.0 and p["eta_c"] == 0.0 for p in POINTS)  # jumping, Jenkins
    assert {p["inplane_on"] for p in POINTS} == {"substrate", "holder"}
    assert any(p["a_x"] > 0.0 for p in POINTS) and any(p["v_inertial"] < 0 for p in POINTS)
    assert len({round(p["phase_y"], 6) for p in POINTS}) >= 6
    aniso = [p for p in POINTS if p.get("alpha_y") is not None]
    assert len(aniso) >= 4  # the pin across the sliding its own: k_y != k_x, c_y != c_x
    for p in aniso:
        assert p["alpha_y"] != p["alpha"]
        assert 2 * p["zeta_y"] * math.sqrt(p["alpha_y"]) != 2 * p["zeta"] * math.sqrt(p["alpha"])
    assert {p["inplane_on"] for p in aniso} == {"substrate", "holder"}


# --------------------------------------------------------------------------- the pin across
AXISYMMETRIC = [  # alpha, beta, a, V, zeta, eta_c, a_x, phase_x, a_y, phase_y, inplane_on
    (0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.0, 0.0, 0.5, 1.0, "substrate"),
    (0.5, 2.0, 0.5, 0.4, 0.05, 0.0, 0.5, math.pi / 2, 0.5, 3.0, "holder"),
]


@pytest.mark.parametrize("q", AXISYMMETRIC, ids=["substrate", "holder"])
def test_an_explicit_axisymmetric_pin_is_the_default(q) -> None:
    """``alpha_y = alpha``, ``zeta_y = zeta`` (and ``k_y = k_x``, ``c_y = c_x``) change
    nothing, to the last bit; ``alpha_y`` differing by 10 % does change ``mu`` (by far more
    than the errors)."""
    *args, on = q
    default = solve_points(*args, inplane_on=on)
    explicit = solve_points(*args, args[0], args[4], inplane_on=on)
    for k in ("mu_ratio", "lateral_ratio", "error", "stick_fraction", "y", "work"):
        assert float(explicit[k]) == float(default[k]), k
    other = solve_points(*args, 1.1 * args[0], args[4], inplane_on=on)
    assert bool(other["trusted"])
    assert abs(float(other["mu_ratio"]) - float(default["mu_ratio"])) > 100 * (
        float(other["error"]) + float(default["error"]))
    pin = vf.Physical(mass=0.01, k_x=2.5e5, k_xc=1.5e7, k_zc=2e7, u_z0=1e-6, du_z=5e-7,
                      omega=2 * math.pi * 1000, mu0=0.3, c_x=2.0, du_y=2e-6, phase_y=0.5)
    same = pin.with_(k_y=pin.k_x, c_y=pin.c_x)
    assert same.to_dimensionless().pin_y == pin.to_dimensionless().pin_y
    assert pin.to_dimensionless().alpha_y is None and same.to_dimensionless().alpha_y is not None
    r0, r1 = (vf.friction_coefficient(p, v0=0.05) for p in (pin, same))
    assert r0.mu_ratio == r1.mu_ratio and r0.lateral_ratio == r1.lateral_ratio


@pytest.mark.parametrize("q", [
    (0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.0, 0.0, "substrate"),
    (0.5, 4.0, 1.5, 0.3, 0.1, 0.2, 0.3, 2.0, "holder"),
], ids=["substrate", "jumping holder"])
def test_the_pin_across_has_no_effect_without_a_transverse_oscillation(q) -> None:
    """``a_y = 0``: the engine's 1-D result is bit for bit the same for any ``alpha_y``,
    ``zeta_y``, and the 2-D kernel itself with a very different pin across agrees with it
    within the errors, the body never moving across (``lateral_ratio = 0``)."""
    al, be, a, V, ze, et, ax, px, on = q
    exact = solve_points(al, be, a, V, ze, et, ax, px, inplane_on=on)
    aniso = solve_points(al, be, a, V, ze, et, ax, px, 0.0, 0.0, 3.0 * al, 0.5, inplane_on=on)
    for k in FLOAT_COLUMNS:
        np.testing.assert_array_equal(aniso[k], exact[k])
    of = np.empty(len(FLOAT_COLUMNS))
    oi = np.empty(len(INT_COLUMNS), np.int64)
    plane.plane_steady_state(al, be, a, V, ze, et, ax, px, 0.0, 0.0, 3.0 * al, 0.5,
                             on == "substrate", 0, 0.0, 0.0, 0.0, 1e-10, 20000, 10000, of, oi)
    assert oi[column_index("status")] == Status.PERIODIC.code
    assert of[column_index("lateral_ratio")] == 0.0
    e1, e2 = float(exact["error"]), of[column_index("error")]
    assert abs(of[column_index("mu_ratio")] - float(exact["mu_ratio"])) <= SAFETY * (e1 + e2) \
        + 1e-12


# --------------------------------------------------------------------------- a_y -> 0
ONE_D = [  # alpha, beta, a, V, zeta, eta_c, a_x, phase_x, inplane_on
    (0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.0, 0.0, "substrate"),
    (0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.5, 1.0, "holder"),
    (0.5, 4.0, 1.5, 0.3, 0.1, 0.0, 0.3, 2.0, "substrate"),
    (0.5, 4.0, 1.5, 0.3, 0.1, 0.2, 0.3, 2.0, "holder"),
    (3.0, 10.0, 0.3, 0.2, 0.1, 0.05, 0.0, 0.0, "substrate"),
]


@pytest.mark.parametrize("q", ONE_D, ids=[str(i) for i in range(len(ONE_D))])
def test_vanishing_transverse_amplitude_is_the_1d_solver(q) -> None:
    al, be, a, V, ze, et, ax, px, on = q
    exact = solve_points(al, be, a, V, ze, et, ax, px, inplane_on=on)
    assert bool(exact["trusted"])
    mu1, e1 = float(exact["mu_ratio"]), float(exact["error"])
    # the 2-D kernel itself at a_y = 0 (the engine routes a_y = 0 to the 1-D solver)
    of = np.empty(len(FLOAT_COLUMNS))
    oi = np.empty(len(INT_COLUMNS), np.int64)
    plane.plane_steady_state(al, be, a, V, ze, et, ax, px, 0.0, 0.0, al, ze, on == "substrate",
                             0, 0.0, 0.0, 0.0, 1e-10, 20000, 10000, of, oi)
    mu2, e2 = of[column_index("mu_ratio")], of[column_index("error")]
    assert oi[column_index("status")] == Status.PERIODIC.code
    assert abs(mu2 - mu1) <= SAFETY * (e1 + e2) + 1e-12, (mu2, mu1, e1, e2)
    assert of[column_index("lateral_ratio")] == 0.0
    for k in ("stick_fraction", "slip_fraction", "reverse_slip_fraction", "flight_fraction"):
        assert abs(of[column_index(k)] - float(exact[k])) < 1e-7, k
    # a small transverse amplitude: mu moves by O(a_y^2), the lateral ratio by O(a_y)
    small = solve_points(al, be, a, V, ze, et, ax, px, 1e-4, 0.7, inplane_on=on)
    assert bool(small["trusted"])
    assert abs(float(small["mu_ratio"]) - mu1) < 1e-6
    assert 0.0 < abs(float(small["lateral_ratio"])) < 1e-2


# --------------------------------------------------------------------------- kinematic limit
@pytest.mark.slow
def test_kinematic_transverse_law_is_approached_as_the_system_stiffens() -> None:
    """``a = 0``, substrate: a body held by a stiff, well-damped pin (elastic contact ``k =
    alpha``) moves at ``V`` and the mean friction tends to ``(2/pi) K(m)/sqrt(1 + eps^2)``
    (docs/inplane.md, section 1)."""
    a_y = 5.0
    for V in (1.25, 2.5, 3.75):
        law = float(theory.kinematic_mu_transverse(V, a_y))
        dist = []
        for S in (100.0, 400.0, 1600.0):
            r = vf.friction_coefficient(vf.Dimensionless(S, 2.0 * S, 0.0, 0.7, 0.0,
                                                         a_y=a_y, phase_y=0.3), v_inertial=V)
            assert r.trusted, (S, V, r.status, r.error)
            assert abs(r.lateral_ratio) < 1e-6  # no mean transverse force without a normal one
            dist.append(abs(r.mu_ratio - law))
        print(f"V/a_y = {V / a_y}: |mu - law| = {dist}")
        assert dist[1] <= 0.5 * dist[0] and dist[2] <= 0.5 * dist[1]
        assert dist[2] < 5e-5


# --------------------------------------------------------------------------- symmetry
@pytest.mark.parametrize("q", [
    (0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.5, 1.0, 0.5, 0.4, "substrate"),
    (0.5, 2.0, 0.5, 0.3, 0.05, 0.0, 0.0, 0.0, 0.7, 2.0, "holder"),
    (0.5, 4.0, 1.5, 0.3, 0.1, 0.2, 0.3, 2.0, 0.5, 5.0, "substrate"),
    (0.3, 3.0, 0.7, -0.2, 0.02, 0.0, 0.4, 0.3, 0.3, 1.0, "holder"),
], ids=["substrate", "holder", "jumping", "backward"])
def test_transverse_mirror(q) -> None:
    """``y -> -y`` maps the model at ``phase_y`` onto that at ``phase_y + pi``."""
    *args, py, on = q
    r0 = solve_points(*args, py, inplane_on=on)
    r1 = solve_points(*args, py + math.pi, inplane_on=on)
    assert bool(r0["trusted"]) and bool(r1["trusted"])
    tol = SAFETY * (float(r0["error"]) + float(r1["error"])) + 1e-12
    assert abs(float(r0["mu_ratio"]) - float(r1["mu_ratio"])) <= tol
    assert abs(float(r0["lateral_ratio"]) + float(r1["lateral_ratio"])) <= tol
    assert abs(float(r0["lateral_ratio"])) > 1e-3  # not trivially zero


def test_x_mirror_of_a_backward_velocity() -> None:
    """``x -> -x``: ``mu(-V; phase_x) = -mu(V; phase_x + pi)``, the lateral ratio kept;
    the engine solves ``V < 0`` by it, so the check here is the 2-D kernel's own
    integration of ``V < 0`` against the engine's mirrored answer."""
    al, be, a, V, ze, et, ax, px, ay, py = 0.5, 2.0, 0.5, 0.3, 0.05, 0.1, 0.5, 1.0, 0.5, 1.0
    fwd = solve_points(al, be, a, -V, ze, et, ax, px, ay, py)
    of = np.empty(len(FLOAT_COLUMNS))
    oi = np.empty(len(INT_COLUMNS), np.int64)
    plane.plane_steady_state(al, be, a, -V, ze, et, ax, px, ay, py, al, ze, True, 0, 0.0,
                             0.0, 0.0, 1e-10, 20000, 10000, of, oi)
    tol = SAFETY * (float(fwd["error"]) + of[column_index("error")])
    assert abs(of[column_index("mu_ratio")] - float(fwd["mu_ratio"])) <= tol
    assert abs(of[column_index("lateral_ratio")] - float(fwd["lateral_ratio"])) <= tol
    assert float(fwd["mu_ratio"]) < 0.0


# --------------------------------------------------------------------------- |f| <= n
@pytest.mark.slow
def test_contact_force_stays_in_the_cone_along_the_orbit() -> None:
    """Step by step over two periods of random points' motions from the sliding start:
    ``|f| <= n`` at every accepted step end (stick: the switch function >= 0)."""
    rng = np.random.default_rng(20)
    worst = -math.inf
    for _ in range(12):
        al = float(rng.uniform(0.2, 3.0))
        be = al + float(rng.uniform(0.5, 10.0))
        a = float(rng.choice([0.0, rng.uniform(0.1, 0.9), rng.uniform(1.1, 2.0)]))
        et = float(rng.choice([0.0, rng.uniform(0.01, 0.5)]))
        V, a_x, phase_x, a_y, phase_y = (float(rng.uniform(lo, hi)) for lo, hi in
                                         ((0.05, 1.0), (0, 1), (0, 6), (0.1, 1.5), (0, 6)))
        on_substrate = rng.integers(0, 2) == 0
        al_y = float(rng.uniform(0.2, 3.0))  # a pin that is not axisymmetric
        P = plane.parameters(al, be, a, V, 0.05, et, a_x, phase_x, a_y, phase_y, al_y,
                             float(rng.uniform(0.0, 0.3)), on_substrate)
        worst = max(worst, plane.cone_excess(P, 4, 1e-10))
    print(f"largest |f| - n: {worst:.2e}")
    assert worst <= 1e-12


# --------------------------------------------------------------------------- API
def test_one_dimensional_results_have_zero_lateral_ratio() -> None:
    r = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5, a_x=0.5), v_inertial=0.3)
    assert r.lateral_ratio == 0.0
    rs = vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 0.5), v_inertial=[0.0, 0.3])
    assert np.all(rs.lateral_ratio == 0.0)


def test_physical_transverse_amplitude() -> None:
    p = vf.Physical(mass=0.01, k_x=2.5e5, k_xc=1.5e7, k_zc=2e7, u_z0=1e-6, du_z=5e-7,
                    omega=2 * math.pi * 1000, mu0=0.3, du_y=2e-6, phase_y=0.5)
    d = p.to_dimensionless()
    assert d.a_y == pytest.approx(2e-6 * 0.01 * (2 * math.pi * 1000) ** 2 / (0.3 * p.F_N0))
    assert d.phase_y == 0.5 and d.a_x == 0.0
    r = vf.friction_coefficient(p, v0=0.05)
    assert r.trusted and 0.0 < r.mu_ratio < 1.0
    assert d.critical_inertial_velocity() == math.inf


def test_refusals() -> None:
    """What the 2-D solver does not cover is refused (``V = 0`` is computed:
    tests/inplane/test_plane_vzero.py)."""
    with pytest.raises(ValueError, match="finite beta"):
        vf.friction_coefficient(vf.Dimensionless(0.5, math.inf, 0.5, a_y=0.5),
                                v_inertial=0.3)
    with pytest.raises(ValueError, match="grazing"):
        vf.friction_coefficient(vf.Dimensionless(0.5, 2.0, 1.0, a_y=0.5), v_inertial=0.3)
    with pytest.raises(ValueError, match="a_y"):
        vf.Dimensionless(0.5, 2.0, 0.5, a_y=-1.0)


@pytest.mark.slow
def test_cli_takes_the_pin_across() -> None:
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-m", "vibrofriction.cli", "mu", "--alpha", "0.5",
                          "--beta", "2", "--amplitude", "0.5", "--a-y", "0.5", "--alpha-y",
                          "1.5", "--zeta-y", "0.2", "--v-inertial", "0.3", "--json"],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    row = json.loads(out.stdout)
    d = vf.Dimensionless(0.5, 2.0, 0.5, a_y=0.5, alpha_y=1.5, zeta_y=0.2)
    assert row["mu_ratio"] == vf.friction_coefficient(d, v_inertial=0.3).mu_ratio
    assert row["system"]["alpha_y"] == 1.5 and row["system"]["zeta_y"] == 0.2
