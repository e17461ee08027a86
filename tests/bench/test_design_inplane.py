"""The in-plane and drive design (vibrofriction.bench.designing, docs/bench.md): checked
against what the design's own code did not compute: theory's cancellation phase (closed
form), a brute-force grid solved in the test (its own SI conversion, ``solve_points``
directly), the independent reference integrator (``vibrofriction_reference.inplane``),
the stuck contact's static band; the limits, the refusals, and the claim in the drive's
refusal (a normal oscillation alone cannot drive)."""

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction.bench.designing import evaluation
from vibrofriction.figures import plot_design
from vibrofriction.solver import solve_points
from vibrofriction_reference.inplane import inplane_mean

# A pin that is (alpha, beta, a) = (0.5, 2, 0.5), zeta = 0.05, eta_c = 0.1 at 1 kHz
M, W, U, KZ, MU0 = 0.01, 2 * math.pi * 1000.0, 1e-6, 2e7, 0.3
PIN = vf.Physical(mass=M, k_x=0.5 * M * W**2, k_xc=1.5 * M * W**2, k_zc=KZ, u_z0=U,
                  du_z=0.5 * U, omega=W, mu0=MU0).with_damping(zeta=0.05, eta_c=0.1)
DUX1 = MU0 * KZ * U / (M * W**2)  # du_x of a_x = 1 at W, by hand
VU = MU0 * KZ * U / (M * W)       # the inertial velocity unit at W, by hand


def _by_hand(v0, omega, du_z, du_x, phase_x):
    """The solver's mu/mu0 with the SI -> dimensionless conversion written here."""
    omega = np.asarray(omega, float)
    s = M * omega**2
    zeta = PIN.c_x / (2 * math.sqrt(PIN.k_x * M))
    eta_c = omega * PIN.c_xc / PIN.k_xc
    out = solve_points(PIN.k_x / s, (PIN.k_x + PIN.k_xc) / s, np.asarray(du_z) / U,
                       v0 * M * omega / (MU0 * KZ * U), zeta, eta_c,
                       np.asarray(du_x) * s / (MU0 * KZ * U), phase_x)
    return out["mu_ratio"], out["trusted"]


@pytest.mark.parametrize("V", [0.05, 0.2])
@pytest.mark.parametrize("damped", [False, True])
@pytest.mark.slow
def test_the_friction_optimum_phase_is_opposite_the_cancellation_phase(V, damped):
    """Amplitudes fixed (a_x = 0.5), the phase free: friction is lowest at theory's
    *adding* phase, ``inplane_cancellation().phase_x + pi`` (the largest V_c), and highest
    near the cancellation phase itself (full friction restored sooner)."""
    pin = PIN if damped else PIN.with_(c_x=0.0, c_xc=0.0)
    zeta, eta = (0.05, 0.1) if damped else (0.0, 0.0)
    res = vf.design(pin, v0=V * VU, omega=(W, W), du_z=(0.5 * U, 0.5 * U),
                    du_x=(0.5 * DUX1, 0.5 * DUX1), n_phase=12)
    cancel = theory.inplane_cancellation(0.5, 2.0, 0.5, zeta, eta).phase_x
    offset = math.remainder(res.system.phase_x - cancel - math.pi, 2 * math.pi)
    assert abs(offset) < 2e-3
    assert res.system.du_x == pytest.approx(0.5 * DUX1, rel=1e-12)
    pm = res.phase_map  # du_x is a point range: the phase map is a line
    assert pm.cof.shape == (1, 73)
    assert float(pm.cof.min()) >= res.cof - 1e-12
    phases = res.map.phase_x.values
    cof = res.map.cof.values[0, 0, 0, :]
    worst = phases[np.argmax(cof)]
    assert abs(math.remainder(worst - cancel, 2 * math.pi)) <= 2 * math.pi / 12 + 1e-9
    assert res.trusted and res.cof < min(cof) + 1e-12


@pytest.fixture(scope="module")
def drive():
    """A drive design over frequency, both amplitudes and the phase, the combined
    velocity limit binding on part of the range; a coarse map (the refinement works)."""
    return vf.design(PIN, v0=0.02 * VU, omega=(0.8 * W, 1.25 * W), du_z=(0.25 * U, 0.75 * U),
                     du_x=(0.0, 1.2 * DUX1), max_velocity_amplitude=W * DUX1, goal="drive",
                     n_omega=5, n_du_z=3, n_du_x=4, n_phase=8)


@pytest.mark.slow
def test_the_drive_respects_the_limits_and_beats_a_brute_force_grid(drive):
    s = drive.system
    assert 0.8 * W <= s.omega <= 1.25 * W and 0.25 * U <= s.du_z <= 0.75 * U
    assert 0.0 <= s.du_x <= 1.2 * DUX1
    assert s.omega * math.hypot(s.du_z, s.du_x) <= W * DUX1 * (1 + 1e-9)
    # the grid: 7 frequencies x 3 x 7 amplitudes x 36 phases, 5292 points
    w, dz, dx, ph = np.meshgrid(np.linspace(0.8 * W, 1.25 * W, 7), np.linspace(0.25, 0.75, 3) * U,
                                np.linspace(0.0, 1.2, 7) * DUX1,
                                np.linspace(0, 2 * math.pi, 36, endpoint=False), indexing="ij")
    mu, ok = _by_hand(drive.v0, w, dz, dx, ph)
    feasible = w * np.hypot(dz, dx) <= W * DUX1
    assert (~feasible).any()  # the limit binds on part of the grid
    best = np.max(np.where(ok & feasible, -mu, -np.inf))
    assert best > 0.0  # the grid drives ...
    assert drive.drive_ratio >= best - 1e-9  # ... and the design does at least as well
    # its value by the solver with the test's conversion, and by the reference integrator
    mu_here, ok_here = _by_hand(drive.v0, s.omega, s.du_z, s.du_x, s.phase_x)
    assert bool(ok_here) and float(mu_here) == pytest.approx(drive.mu_ratio, abs=1e-12)
    d = s.to_dimensionless()
    ref = inplane_mean(d.alpha, d.beta, d.amplitude, 0.02 * VU / s.velocity_unit(),
                       zeta=d.zeta, eta_c=d.eta_c, a_x=d.a_x, phase_x=d.phase_x)
    assert abs(ref.mu_ratio - drive.mu_ratio) <= 3 * (ref.mu_error + drive.error) + 1e-9


@pytest.mark.slow
def test_the_drive_reports_its_idle_velocity_and_blocking_force(drive):
    s = drive.system
    assert drive.goal == "drive" and drive.mu_ratio < 0.0 and drive.blocking_trusted
    v_idle = drive.idle_velocity
    assert v_idle > drive.v0
    mu, ok = _by_hand(np.array([0.99, 1.0, 1.01]) * v_idle, s.omega, s.du_z, s.du_x, s.phase_x)
    assert ok.all() and mu[0] < 0.0 < mu[2] and abs(mu[1]) < 1e-6
    # the blocking force: mu at V = +-1e-5, by the test's own call
    d = s.to_dimensionless()
    b = solve_points(d.alpha, d.beta, d.amplitude, np.array([1e-5, -1e-5]), d.zeta, d.eta_c,
                     d.a_x, d.phase_x)["mu_ratio"]
    np.testing.assert_allclose(drive.blocking, b, atol=1e-12)
    assert "idle velocity" in drive.report() and "blocking force" in drive.report()


def test_the_drive_blocking_force_against_the_static_band():
    """At a fixed oscillation whose contact can stick through a cycle, the blocking
    force is the edge of theory's static band (docs/inplane.md, section 3)."""
    res = vf.design(PIN, v0=0.001 * VU, omega=(W, W), du_z=(0.5 * U, 0.5 * U),
                    du_x=(0.5 * DUX1, 0.5 * DUX1), phase_x=math.pi / 2, goal="drive")
    band = theory.inplane_static_mu_ratio(0.5, 2.0, 0.5, 0.5, math.pi / 2, 0.05, 0.1)
    assert abs(res.blocking[0] - band.upper) < 1e-3 and abs(res.blocking[1] - band.lower) < 1e-3
    # this oscillation only brakes: no idle velocity, and the report says so
    assert res.mu_ratio > 0.0 and math.isnan(res.idle_velocity) and "none" in res.idle_message


@pytest.mark.slow
def test_directions_and_the_each_rule():
    """The velocity rule "each" limits omega du_z and omega du_x separately; the table
    of directions holds the best normal-only and longitudinal-only choices, each inside
    its own limits, and the combined optimum is no worse than those it contains."""
    vmax = 0.5 * W * DUX1
    res = vf.design(PIN, v0=0.1 * VU, omega=(0.8 * W, 1.25 * W), du_z=(0.0, 0.75 * U),
                    du_x=(0.0, 1.2 * DUX1), max_velocity_amplitude=vmax, velocity_rule="each",
                    n_omega=4, n_du_z=3, n_du_x=3, n_phase=6)
    s = res.system
    assert s.omega * max(s.du_z, s.du_x) <= vmax * (1 + 1e-9)
    table = res.directions.set_index("direction")
    assert list(table.index) == ["combined", "normal only", "longitudinal only"]
    assert table.loc["normal only", "du_x"] == 0.0 and table.loc["longitudinal only", "du_z"] == 0
    assert abs(res.cof) <= abs(table["cof"]).min() + 1e-12
    for _, row in table.iterrows():
        mu, ok = _by_hand(res.v0, row["omega"], row["du_z"], row["du_x"], row["phase_x"])
        assert bool(ok) and MU0 * float(mu) == pytest.approx(row["cof"], abs=1e-12)
        assert row["omega"] * max(row["du_z"], row["du_x"]) <= vmax * (1 + 1e-9)
    assert "which direction" in res.report()


def test_a_normal_oscillation_alone_cannot_drive():
    """The claim in the refusal of goal='drive' without du_x: with the normal oscillation
    only, mu has the sign of v0 (energy: the holder supplies all the contact dissipates).
    Random points over every regime, stick-slip with reverse slip among them."""
    rng = np.random.default_rng(7)
    n = 300
    al = 10 ** rng.uniform(-2, 1.5, n)
    be = al * (1 + 10 ** rng.uniform(-2, 2, n))
    out = solve_points(al, be, rng.uniform(0, 3, n), 10 ** rng.uniform(-4, 0.5, n),
                       rng.choice([0.0, 0.05, 0.3], n), rng.choice([0.0, 0.1, 1.0], n))
    ok = out["trusted"]
    assert ok.sum() > 250 and np.nanmax(out["reverse_slip_fraction"][ok]) > 0.01
    assert (out["mu_ratio"][ok] > 0.0).all()
    with pytest.raises(ValueError, match=r"goal='drive' needs an in-plane oscillation: give "
                                         r"du_x.*cannot drive"):
        vf.design(PIN, v0=0.01, omega=(W, 2 * W), du_z=(0.0, U), goal="drive")
    with pytest.raises(ValueError, match=r"goal='drive' needs"):
        vf.design(PIN, v0=0.01, omega=(W, 2 * W), du_z=(0.0, U), du_x=(0.0, 0.0), goal="drive")


@pytest.mark.parametrize("kwargs, message", [
    (dict(du_x=(1e-6,)), r"du_x must be a pair"),
    (dict(du_x=(-1e-7, 1e-6)), r"du_x must be finite and >= 0"),
    (dict(du_x=(2e-6, 1e-6)), r"du_x: low"),
    (dict(du_x=(0.0, 1e-6), phase_x=math.nan), r"phase_x must be finite"),
    (dict(du_x=(0.0, 1e-6), goal="brake"), r"goal must be one of \['drive', 'friction'\]"),
    (dict(du_x=(0.0, 1e-6), velocity_rule="sum"), r"velocity_rule must be one of"),
    (dict(du_x=(0.0, 1e-6), inplane_on="disk"), r"inplane_on"),
    (dict(du_x=(0.0, 1e-6), n_phase=0), r"n_phase must be an integer >= 1"),
    (dict(du_x=(1e-6, 2e-6), du_z=(0.0, 1e-6), max_velocity_amplitude=1e-4),
     r"no oscillation in range respects max_velocity_amplitude"),
    (dict(phase_x=1.0), r"phase_x and inplane_on need an in-plane oscillation"),
    (dict(du_x=(0.0, 1e-6), v0=0.0), r"v0 must be finite and > 0"),
])
def test_inplane_design_errors(kwargs, message):
    args = dict(v0=0.01, omega=(W, 2 * W), du_z=(0.0, U))
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        vf.design(PIN, **args)


def test_untrusted_values_are_never_the_optimum_and_are_counted(monkeypatch):
    """Solver results near the best phase made untrusted and stale (lower): never chosen."""
    real = solve_points

    def stale(alpha, beta, a, V, zeta, eta_c, a_x=0.0, phase_x=0.0, *transverse, **kwargs):
        out = real(alpha, beta, a, V, zeta, eta_c, a_x, phase_x, *transverse, **kwargs)
        ph = np.broadcast_to(np.asarray(phase_x, float), np.shape(out["mu_ratio"]))
        bad = (np.abs(np.remainder(ph - 3.4, 2 * math.pi)) < 0.6) & \
            (np.broadcast_to(np.asarray(a_x, float), ph.shape) > 0)
        out["mu_ratio"] = np.where(bad, out["mu_ratio"] - 0.5, out["mu_ratio"])
        out["trusted"] = out["trusted"] & ~bad
        return out

    monkeypatch.setattr(evaluation, "solve_points", stale)
    res = vf.design(PIN, v0=0.2 * VU, omega=(W, W), du_z=(0.5 * U, 0.5 * U),
                    du_x=(0.5 * DUX1, 0.5 * DUX1), n_phase=12)
    assert not np.remainder(res.system.phase_x - 3.4, 2 * math.pi) < 0.6
    mu, ok = _by_hand(res.v0, W, 0.5 * U, 0.5 * DUX1, res.system.phase_x)
    assert bool(ok) and MU0 * float(mu) == pytest.approx(res.cof, abs=1e-12)
    assert res.n_untrusted == int((~res.map.trusted.values).sum()) > 0
    assert res.status == "untrusted_near_optimum" and not res.trusted


def test_the_design_map_figure(drive):
    fig = plot_design(drive)
    assert len(fig.axes) >= 2
    assert drive.phase_map is not None and drive.phase_map.cof.dims == ("du_x", "phase_x")


def _by_hand_y(v0, omega, du_z, du_y, phase_y, pin=PIN):
    """The 2-D solver's mu/mu0 with the SI -> dimensionless conversion written here (the
    pin's own k_y, c_y across the sliding)."""
    omega = np.asarray(omega, float)
    s = M * omega**2
    k_y = pin.k_x if pin.k_y is None else pin.k_y
    c_y = pin.c_x if pin.c_y is None else pin.c_y
    out = solve_points(pin.k_x / s, (pin.k_x + pin.k_xc) / s, np.asarray(du_z) / U,
                       v0 * M * omega / (MU0 * KZ * U), pin.c_x / (2 * math.sqrt(pin.k_x * M)),
                       omega * pin.c_xc / pin.k_xc, 0.0, 0.0,
                       np.asarray(du_y) * s / (MU0 * KZ * U), phase_y, k_y / s,
                       c_y / (2 * math.sqrt(k_y * M)))
    return out["mu_ratio"], out["trusted"]


@pytest.mark.parametrize("k_y", [None, 0.3 * M * W**2])
@pytest.mark.slow
def test_the_transverse_design_against_a_brute_force_grid(k_y):
    """Transverse only (``du_z = 0``, no ``du_x``), one frequency: the design's COF is the
    smallest of a brute-force grid of 2-D solves over ``du_y`` made here, and, friction
    falling as the transverse velocity amplitude grows (the kinematic law, a monotone
    function of ``omega du_y/v0``), it sits at the top of the range; the transverse row
    of ``directions`` is what the by-hand conversion gives; an anisotropic pin
    (``k_y``) is used, not the axisymmetric one."""
    pin = PIN.with_(k_y=k_y)
    v0 = 0.3 * VU
    res = vf.design(pin, v0=v0, omega=(W, W), du_z=(0.0, 0.0), du_y=(0.0, 1.5 * DUX1),
                    n_du_y=4)
    grid = np.linspace(0.0, 1.5 * DUX1, 13)
    mu, ok = _by_hand_y(v0, W, 0.0, grid, 0.0, pin)
    assert ok.all()
    assert np.all(np.diff(mu) < 0.0)  # monotone: the best is the largest amplitude
    assert res.system.du_y == pytest.approx(1.5 * DUX1, rel=1e-9)
    assert res.cof == pytest.approx(MU0 * float(mu[-1]), abs=1e-9)
    assert res.cof <= MU0 * mu.min() + 1e-9
    table = res.directions.set_index("direction")
    assert list(table.index) == ["combined", "transverse only"]
    row = table.loc["transverse only"]
    m, t = _by_hand_y(v0, row["omega"], row["du_z"], row["du_y"], row["phase_y"], pin)
    assert bool(t) and MU0 * float(m) == pytest.approx(row["cof"], abs=1e-12)
    assert table.loc["combined", "cof"] == pytest.approx(MU0 * float(mu[-1]), abs=1e-9)
    assert "across the sliding" in res.report()


@pytest.mark.slow
def test_the_design_chooses_the_transverse_direction_where_it_is_best():
    """Normal, longitudinal and transverse allowed within one velocity limit (the rule
    "each"): every row of ``directions`` is the by-hand conversion's value, each within its
    limits, and the chosen oscillation is the best row (here a longitudinal one, which
    can bring the friction force to zero).  Without ``du_x`` the transverse component
    wins: normal + transverse below normal only at this point (``V = 0.1``)."""
    vmax = 0.5 * W * DUX1
    kw = dict(v0=0.1 * VU, omega=(0.8 * W, 1.25 * W), du_z=(0.0, 0.75 * U),
              du_y=(0.0, 1.2 * DUX1), max_velocity_amplitude=vmax, velocity_rule="each",
              n_omega=4, n_du_z=3, n_du_x=3, n_phase=6, n_du_y=3, n_phase_y=3)
    both = vf.design(PIN, du_x=(0.0, 1.2 * DUX1), **kw)
    across = vf.design(PIN, **kw)
    for res, names in ((both, ["combined", "normal only", "longitudinal only",
                               "normal + transverse", "transverse only"]),
                       (across, ["combined", "normal only", "normal + transverse",
                                 "transverse only"])):
        table = res.directions.set_index("direction")
        print(table[["cof", "du_z", "du_x", "du_y"]])
        assert list(table.index) == names
        for name, row in table.iterrows():
            if row["du_y"] > 0.0:
                assert row["du_x"] == 0.0
                mu, ok = _by_hand_y(res.v0, row["omega"], row["du_z"], row["du_y"],
                                    row["phase_y"])
            else:
                mu, ok = _by_hand(res.v0, row["omega"], row["du_z"], row["du_x"],
                                  row["phase_x"])
            assert bool(ok) and MU0 * float(mu) == pytest.approx(row["cof"], abs=1e-12), name
            assert row["omega"] * max(row["du_z"], row["du_x"], row["du_y"]) <= vmax * (
                1 + 1e-9)
        assert abs(res.cof) == pytest.approx(abs(table["cof"]).min(), abs=1e-12)
    assert both.system.du_x > 0.0 and both.system.du_y == 0.0
    table = across.directions.set_index("direction")
    assert across.system.du_y > 0.0 and across.system.du_z > 0.0  # transverse is best here
    assert table.loc["normal + transverse", "cof"] < table.loc["normal only", "cof"] - 0.01


def test_transverse_design_refusals():
    with pytest.raises(ValueError, match="transverse oscillation .* give du_y"):
        vf.design(PIN.with_(du_y=1e-7), v0=0.01, omega=(W, W), du_z=(0.0, U))
    with pytest.raises(ValueError, match="goal='drive' does not take a transverse"):
        vf.design(PIN, v0=0.01, omega=(W, W), du_z=(0.0, U), du_x=(0, 1e-6),
                  du_y=(0.0, 1e-6), goal="drive")
    with pytest.raises(ValueError, match="finite k_xc"):
        vf.design(PIN.with_(k_xc=math.inf, c_xc=0.0), v0=0.01, omega=(W, W),
                  du_z=(0.0, U), du_y=(0.0, 1e-6))
