"""The time history of a curved tip (simulate with a finite profile_exponent: the MDR row
recorded at the sample times, docs/contact_geometry.md "The history")."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import vibrofriction as vf
from vibrofriction import theory
from vibrofriction.schema import ContactState
from vibrofriction.solver import solve_points
from vibrofriction.solver.mdr import mdr_friction, mdr_row, rows_alone
from vibrofriction.solver.mdr_history import mdr_history
from vibrofriction.solver.results import SectionState
from vibrofriction_reference.mdr import mdr_mean

OPEN, STICK, SLIP_POS, SLIP_NEG = (ContactState.FLIGHT, ContactState.STICK,
                                   ContactState.SLIP_POS, ContactState.SLIP_NEG)
# (alpha, beta, a, V, n, zeta): sphere, jumping sphere, cone, soft n = 3
POINTS = [(0.5, 2.0, 0.5, 0.3, 2.0, 0.0), (0.5, 2.0, 1.5, 0.3, 2.0, 0.1),
          (1.0, 3.0, 0.7, 0.5, 1.0, 0.1), (0.05, 0.1, 0.5, 2.0, 3.0, 0.5)]
#: with a longitudinal in-plane oscillation: ((alpha, beta, a, V, n, zeta), a_x, phase_x, on)
INPLANE = [((0.5, 2.0, 0.5, 0.3, 2.0, 0.1), 0.5, 1.0, "substrate"),
           ((0.5, 2.0, 0.5, -0.3, 2.0, 0.1), 0.5, 1.0, "holder"),
           ((1.0, 3.0, 1.3, 0.5, 1.0, 0.0), 0.8, 2.5, "substrate")]


def _dim(alpha, beta, a, n, zeta, **inplane):
    return vf.Dimensionless(alpha, beta, a, zeta=zeta, profile_exponent=n, **inplane)


def _balance(h):
    """Work input minus dissipation minus the change of the stored energy, at each sample."""
    E = h.stored_energy()
    return h.work_input - h.dissipated_pin - h.dissipated_friction - (E - E[0])


@pytest.mark.parametrize("alpha, beta, a, V, n, zeta", POINTS)
def test_steady_history_has_the_solvers_friction_and_normal_force(alpha, beta, a, V, n, zeta):
    """Over one period of the periodic orbit: the exact impulses' ratio is the row's own
    ``mu_ratio`` (the same springs) to round-off and the extrapolated solver's within its
    error; the samples' mean within the error too; the mean normal force is
    ``profile_mean_normal_force`` within the row's discretisation (1e-6; measured 5.7e-8
    to 5.8e-7 at these rows of 160 to 640 springs)."""
    point = solve_points(alpha, beta, a, V, zeta, profile_exponent=n)  # (no springs)
    with rows_alone():
        r = mdr_friction(alpha, beta, a, V, n, zeta=zeta)
    M = r["rows"][1]
    d = _dim(alpha, beta, a, n, zeta)
    h = vf.simulate(d, v_inertial=V, periods=1, samples_per_period=400, initial="steady",
                    springs=M)
    assert h.is_curved and h.spring_state.shape == (401, M) and h.xi.shape == (M,)
    mu = h.impulse[-1, 0] / h.normal_impulse[-1]
    assert mu == pytest.approx(mdr_row(alpha, beta, a, V, n, M, zeta)["mu_ratio"], abs=1e-11)
    assert abs(mu - r["mu_ratio"]) <= r["error"]
    mu0, err = float(point["mu_ratio"]), float(point["error"]) + r["error"]
    assert abs(mu - mu0) <= err
    assert abs(h.f[:-1].mean() / h.n[:-1].mean() - mu0) <= err
    law = theory.profile_mean_normal_force(a, n)
    assert abs(h.normal_impulse[-1] / (2 * math.pi) - law) <= 1e-6  # 5.7e-8 ... 5.8e-7
    assert abs(h.n[:-1].mean() - law) <= 1e-6
    # the exact impulse is the integral of the samples (trapezoid, 400 a period)
    assert h.impulse[-1, 0] == pytest.approx(np.trapezoid(h.f, h.tau), rel=1e-4)


@pytest.mark.parametrize("p, a_x, phase_x, on", INPLANE)
def test_with_an_inplane_oscillation(p, a_x, phase_x, on):
    """Substrate and holder, forwards and backwards: the orbit's period = solve_points
    within its error and the rows' (the history's row is one of them), the energy balances
    (the laboratory's work input, the substrate's work on the contact included) and every
    spring within its friction limit."""
    alpha, beta, a, V, n, zeta = p
    d = _dim(alpha, beta, a, n, zeta, a_x=a_x, phase_x=phase_x, inplane_on=on)
    point = solve_points(alpha, beta, a, V, zeta, a_x=a_x, phase_x=phase_x, inplane_on=on,
                         profile_exponent=n)
    with rows_alone():
        r = mdr_friction(alpha, beta, a, abs(V), n, zeta=zeta, a_x=a_x,
                         phase_x=phase_x + (math.pi if V < 0 else 0.0), inplane_on=on)
    s = vf.simulate(d, v_inertial=V, periods=1, samples_per_period=200, initial="steady",
                    springs=r["rows"][1])
    mu = s.impulse[-1, 0] / s.normal_impulse[-1]
    assert abs(mu - float(point["mu_ratio"])) <= float(point["error"]) + r["error"]
    assert s.dissipated_pin[-1] + s.dissipated_friction[-1] == pytest.approx(
        s.work_input[-1], rel=1e-9)
    h = vf.simulate(d, v_inertial=V, periods=4, samples_per_period=100, springs=60)
    assert np.max(np.abs(_balance(h))) <= 1e-11 * h.work_input[-1]
    nn = h.spring_normal()
    assert np.all(np.abs(h.spring_f) <= nn + 1e-12 * np.max(nn))
    X = a_x * np.cos(h.tau + phase_x)  # the laboratory frame: x - X periodic on the orbit
    lab = s.x - (X[:s.tau.size] if on == "substrate" else 0.0) - V * s.tau
    assert lab[-1] == pytest.approx(lab[0], abs=1e-9)


@pytest.mark.parametrize("alpha, beta, a, V, n, zeta", POINTS)
def test_energy_balance(alpha, beta, a, V, n, zeta):
    """``work_input - dissipated = stored - stored(0)`` at every sample from the sliding
    start (round-off: the work exactly, the dissipation by Gauss-Legendre); on the periodic
    orbit the drive's work in a period is ``V int f`` and all of it is dissipated."""
    d = _dim(alpha, beta, a, n, zeta)
    h = vf.simulate(d, v_inertial=V, periods=3, samples_per_period=100, springs=80)
    assert np.max(np.abs(_balance(h))) <= 1e-11 * h.work_input[-1]
    assert np.all(np.diff(h.dissipated_friction) >= 0.0)
    s = vf.simulate(d, v_inertial=V, periods=1, samples_per_period=50, springs=80,
                    initial="steady")
    assert s.work_input[-1] == pytest.approx(V * s.impulse[-1, 0], rel=1e-9)
    assert s.dissipated_pin[-1] + s.dissipated_friction[-1] == pytest.approx(
        s.work_input[-1], rel=1e-9)
    assert (s.dissipated_pin[-1] > 0.0) == (zeta > 0.0)


@settings(max_examples=12, deadline=None)
@given(alpha=st.floats(0.05, 3.0), k=st.floats(0.1, 5.0), a=st.floats(0.0, 2.5),
       V=st.floats(0.0, 2.0), n=st.sampled_from([0.7, 1.0, 2.0, 4.0]),
       zeta=st.sampled_from([0.0, 0.1]), a_x=st.sampled_from([0.0, 0.0, 0.6]),
       phase_x=st.floats(0.0, 6.0), on=st.sampled_from(["substrate", "holder"]))
def test_every_spring_stays_within_its_friction_cone(alpha, k, a, V, n, zeta, a_x, phase_x,
                                                     on):
    """``|f_i| <= n_i`` for every spring at every sample; open springs carry nothing, the
    stuck ones are in contact, inside the contact radius; the energy balances (with or
    without a longitudinal in-plane oscillation, ``V > 0`` with it)."""
    inplane = dict(a_x=a_x, phase_x=phase_x, inplane_on=on) if a_x > 0 else {}
    h = vf.simulate(_dim(alpha, alpha + k, a, n, zeta, **inplane),
                    v_inertial=max(V, 0.05) if a_x > 0 else V, periods=2,
                    samples_per_period=100, springs=40)
    nn = h.spring_normal()
    scale = 1e-12 * float(np.max(nn))
    assert np.all(np.abs(h.spring_f) <= nn + scale)
    assert np.all(h.spring_f[h.spring_state == OPEN] == 0.0)
    assert np.all(nn[h.spring_state != OPEN] >= 0.0)
    slip = (h.spring_state == SLIP_POS) | (h.spring_state == SLIP_NEG)
    np.testing.assert_allclose(np.abs(h.spring_f[slip]), nn[slip], rtol=1e-12, atol=scale)
    assert np.all(h.stick_radius < h.contact_radius + 1e-12)
    assert np.all(h.xi[None, :] * (h.spring_state == STICK) <= h.stick_radius[:, None])
    fractions = h.stick_area_fraction + h.slip_area_fraction + h.open_area_fraction
    np.testing.assert_allclose(fractions, 1.0, atol=1e-12)
    assert np.all(h.open_area_fraction >= -1e-12)
    assert np.max(np.abs(_balance(h))) <= 1e-10 * max(1.0, h.work_input[-1])
    np.testing.assert_allclose(h.f, h.spring_f.sum(axis=1), atol=1e-12)
    np.testing.assert_allclose(h.n, nn.sum(axis=1), atol=1e-12)


@pytest.mark.parametrize("alpha, beta, a, V, n, zeta", POINTS[:3])
def test_the_independent_reference_converges_to_the_history(alpha, beta, a, V, n, zeta):
    """Every spring's force over the periodic orbit against the spring-row reference's
    (its own code; 300 periods from its own start, 40 springs): the distance falls second
    order in the reference's step (measured 1.1e-4, 6.7e-6, 4.0e-7 of the largest n_i at
    200, 800, 3200 steps a period for the sphere)."""
    dist = []
    for steps in (200, 800):
        ref = mdr_mean(alpha, beta, a, V, n, springs=40, steps_per_period=steps,
                       transient_periods=300, average_periods=1, zeta=zeta,
                       record_last_period=True)
        N = ref.steps_per_drive_period
        h = vf.simulate(_dim(alpha, beta, a, n, zeta), v_inertial=V, periods=1,
                        samples_per_period=N, springs=40, initial="steady")
        nn = h.spring_normal()
        np.testing.assert_allclose(nn, ref.spring_n, atol=1e-13)
        dist.append(np.max(np.abs(h.spring_f - ref.spring_f)) / np.max(nn))
    assert dist[1] < 1e-5 and dist[1] < dist[0] / 8


@pytest.mark.parametrize("alpha, beta, a, V, zeta, inplane", [
    (0.5, 2.0, 0.5, 0.3, 0.0, {}), (0.5, 2.0, 1.5, 0.3, 0.1, {}),
    (1.0, 3.0, 0.7, 0.5, 0.1, {}), (0.5, 2.0, 0.5, -0.3, 0.0, {}),
    (0.5, 2.0, 0.5, 0.3, 0.0, dict(a_x=0.5, phase_x=1.0)),
    (1.3, 4.0, 1.4, 0.8, 0.05, dict(a_x=1.2, phase_x=0.3, inplane_on="holder")),
    (0.5, 2.0, 1.2, -0.3, 0.1, dict(a_x=0.5, phase_x=4.0)),
    (0.5, 2.0, 0.5, -0.3, 0.1, dict(a_x=0.5, phase_x=1.0, inplane_on="holder"))])
@pytest.mark.parametrize("springs", [1, 4])
def test_flat_punch_row_is_the_single_spring_history(alpha, beta, a, V, zeta, inplane,
                                                     springs):
    """A flat punch as a row (each spring the same share) = the 1-D simulate at the same
    samples, from the same start and from the steady state, to round-off; with a
    longitudinal in-plane oscillation too (a start whose slip agrees with the velocity
    relative to the substrate: an inconsistent one is resolved differently)."""
    d = vf.Dimensionless(alpha, beta, a, zeta=zeta, **inplane)
    s = math.copysign(1.0, V)
    start = SectionState(-s / alpha, V, s * (1 + a), "slip+" if V > 0 else "slip-")
    for flat_start, row_start in ((start, "sliding"), ("steady", "steady")):
        one = vf.simulate(d, v_inertial=V, periods=3, samples_per_period=100,
                          initial=flat_start)
        row = mdr_history(d, V, 3, 100, row_start, springs)
        j = np.searchsorted(one.tau, row.tau)  # the grid's samples (the later of a pair)
        assert np.all(np.abs(one.tau[j] - row.tau) <= 1e-13)
        for name in ("x", "x_dot", "f", "n", "e", "work_input", "dissipated_pin",
                     "dissipated_friction"):
            np.testing.assert_allclose(getattr(row, name), getattr(one, name)[j],
                                       atol=1e-12, err_msg=name)
        assert np.array_equal(row.phase, one.phase[j])
        np.testing.assert_allclose(row.stored_energy(), one.stored_energy()[j], atol=1e-12)


def test_mirror_image():
    d = _dim(0.5, 2.0, 1.2, 2.0, 0.1)
    fwd = vf.simulate(d, v_inertial=0.4, periods=2, samples_per_period=60, springs=30)
    back = vf.simulate(d, v_inertial=-0.4, periods=2, samples_per_period=60, springs=30)
    for name in ("x", "x_dot", "f", "spring_f"):
        np.testing.assert_allclose(getattr(back, name), -getattr(fwd, name), atol=1e-13)
    mirrored = {OPEN: OPEN, STICK: STICK, SLIP_POS: SLIP_NEG, SLIP_NEG: SLIP_POS}
    swap = np.vectorize(lambda c: int(mirrored[ContactState(c)]))(fwd.spring_state)
    assert np.any(fwd.spring_state == SLIP_POS) and np.any(fwd.spring_state == STICK)
    assert np.array_equal(back.spring_state, swap)
    np.testing.assert_allclose(back.dissipated_friction, fwd.dissipated_friction, atol=1e-13)


def test_a_jumping_sphere_opens_its_outer_ring_first():
    """Sphere at a = 1.5: the outer ring is out of contact while the centre touches, and
    the whole contact opens for part of the cycle; the centre is open for less of it than
    the edge (arccos(-1/a)/pi of the cycle for the centre); stick, slip and open coexist."""
    h = vf.simulate(_dim(1.0, 4.0, 1.5, 2.0, 0.0), v_inertial=1.0, periods=1,
                    samples_per_period=400, initial="steady", springs=100)
    s = h.spring_state[:-1]
    centre, edge = s[:, 0], s[:, -1]
    assert np.any((centre != OPEN) & (edge == OPEN))
    flight = h.phase[:-1] == "flight"
    assert np.any(flight) and np.array_equal(flight, np.all(s == OPEN, axis=1))
    assert np.mean(centre == OPEN) < np.mean(edge == OPEN)
    assert np.mean(centre == OPEN) == pytest.approx(1 - math.acos(-1 / 1.5) / math.pi,
                                                     abs=2 / 400)
    assert np.any(s == STICK) and np.any(s == SLIP_POS) and np.any(s == OPEN)
    touching = h.contact_radius > 0
    assert np.all(h.stick_radius[~touching] == 0.0)


def test_stick_radius_and_area_fractions_against_the_steady_state():
    """The time means of the area fractions are the steady state's (the uniform samples
    of a piecewise constant state: within a few samples' width); the stick radius is
    inside the contact radius and positive while the centre sticks."""
    p = (0.5, 2.0, 0.5, 0.3, 2.0, 0.0)
    d = _dim(*p[:3], p[4], p[5])
    h = vf.simulate(d, v_inertial=p[3], periods=1, samples_per_period=800, initial="steady",
                    springs=80)
    row = mdr_row(*p[:5], 80, p[5])
    assert h.stick_area_fraction[:-1].mean() == pytest.approx(row["stick_area_fraction"],
                                                              abs=2e-3)
    assert h.slip_area_fraction[:-1].mean() == pytest.approx(row["slip_area_fraction"], abs=2e-3)
    assert h.open_area_fraction[:-1].mean() == pytest.approx(
        row["open_area_fraction"], abs=2e-3)
    stuck_centre = h.spring_state[:, 0] == STICK
    assert np.all(h.stick_radius[stuck_centre] >= h.xi[0])
    assert np.all(h.stick_radius < h.contact_radius)
    np.testing.assert_allclose(h.contact_radius, np.sqrt(1 + 0.5 * np.cos(h.tau)))


@pytest.mark.parametrize("kwargs, V, message", [
    (dict(a_y=0.1), 0.3, "a_y"), (dict(a_x=0.1), 0.0, "a_x"), (dict(eta_c=0.1), 0.3, "eta_c"),
    (dict(beta=math.inf), 0.3, "beta")])
def test_refusals_name_the_parameter(kwargs, V, message):
    d = vf.Dimensionless(**(dict(alpha=0.5, beta=2.0, amplitude=0.5, profile_exponent=2.0)
                            | kwargs))
    with pytest.raises(ValueError, match=message):
        vf.simulate(d, v_inertial=V, periods=1)


@pytest.mark.parametrize("kwargs, message", [
    (dict(initial="rest"), "initial"), (dict(springs=0), "springs"),
    (dict(springs=2.5), "springs")])
def test_bad_arguments(kwargs, message):
    d = vf.Dimensionless(0.5, 2.0, 0.5, profile_exponent=2.0)
    with pytest.raises(ValueError, match=message):
        vf.simulate(d, v_inertial=0.3, periods=1, **kwargs)
