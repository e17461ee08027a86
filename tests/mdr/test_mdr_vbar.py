"""``vbar`` of a curved tip: ``V = vbar V_c``, ``V_c`` the tip's critical velocity of
continuous sliding (``theory.profile_critical_velocity``, docs/contact_geometry.md), by the
package's one conversion (``params.vbar_to_inertial``); checked against the MDR solver,
which knows nothing of ``V_c``: its friction reaches ``mu0`` (continuous sliding, no
spring sticks) just above ``vbar = 1`` and not just below."""

import math

import pytest

import vibrofriction as vf
from vibrofriction.contact import Material, Sphere
from vibrofriction.params import inertial_to_vbar, vbar_to_inertial

TIPS = [  # sphere, damped cone, jumping damped sphere, n = 3, a stiff damped sphere
    dict(alpha=0.5, beta=2.0, amplitude=0.5, profile_exponent=2.0),
    dict(alpha=1.5, beta=4.0, amplitude=0.7, profile_exponent=1.0, zeta=0.05),
    dict(alpha=0.3, beta=3.0, amplitude=1.5, profile_exponent=2.0, zeta=0.1),
    dict(alpha=2.0, beta=6.0, amplitude=0.8, profile_exponent=3.0),
    dict(alpha=0.05, beta=0.1, amplitude=0.5, profile_exponent=2.0, zeta=0.5)]


@pytest.mark.parametrize("tip", TIPS, ids=lambda t: f"n={t['profile_exponent']:g}")
def test_the_solver_slides_continuously_just_above_vbar_1_and_not_below(tip):
    system = vf.Dimensionless(**tip)
    Vc = system.critical_inertial_velocity()
    assert 0.0 < Vc < math.inf
    below, above = (vf.friction_coefficient(system, vbar=v) for v in (0.98, 1.02))
    assert below.v_inertial == 0.98 * Vc and above.v_inertial == 1.02 * Vc
    assert below.trusted and above.trusted
    # above: mu0, and no spring ever sticks
    assert above.mu_ratio == pytest.approx(1.0, abs=above.error + 1e-12)
    assert above.stick_area_fraction == 0.0
    # below: springs stick now and then, and the friction is below mu0 by far more than
    # the solver's error
    assert 1.0 - below.mu_ratio > 20 * below.error and below.stick_area_fraction > 0.0


def test_the_one_conversion_for_a_curved_tip():
    tip = TIPS[0]
    system = vf.Dimensionless(**tip)
    Vc = float(vf.theory.profile_critical_velocity(0.5, 2.0, 0.5, 2.0))
    assert system.vbar_to_inertial(0.3) == pytest.approx(0.3 * Vc, rel=1e-15)
    assert system.inertial_to_vbar(0.3 * Vc) == pytest.approx(0.3, rel=1e-15)
    assert vbar_to_inertial(0.5, 2.0, 0.5, 0.3, profile_exponent=2.0) == \
        pytest.approx(0.3 * Vc, rel=1e-15)
    assert inertial_to_vbar(0.5, 2.0, 0.5, Vc, profile_exponent=2.0) == pytest.approx(1.0)
    # the flat punch's own (eq. 12), not the tip's, where profile_exponent is not given
    assert vbar_to_inertial(0.5, 2.0, 0.5, 1.0) == pytest.approx(2.0 / 3.0)
    r = vf.friction_coefficient(system, vbar=0.3)
    assert r.vbar == pytest.approx(0.3) and r.v_inertial == 0.3 * Vc
    assert r.mu_ratio == vf.friction_coefficient(system, v_inertial=0.3 * Vc).mu_ratio
    # a bench with a sphere: v0 <-> vbar through the same unit
    steel = Material(210e9, 0.3)
    pin = vf.from_bench(natural_frequency_hz=800.0, mass=0.01, normal_load=20.0,
                        drive_frequency_hz=1000.0, mu0=0.3, du_z=2e-8,
                        contact=Sphere(1e-3, steel, steel), contact_model="mdr")
    d = pin.to_dimensionless()
    assert d.curved
    assert pin.v0_to_vbar(pin.vbar_to_v0(0.7)) == pytest.approx(0.7)
    assert pin.vbar_to_v0(1.0) == pytest.approx(pin.inertial_to_v0(
        d.critical_inertial_velocity()))


def test_vbar_of_a_curved_tip_is_refused_where_its_critical_velocity_is_not_derived():
    with pytest.raises(ValueError, match="contact damping"):
        vf.Dimensionless(**TIPS[0], eta_c=0.1).vbar_to_inertial(0.5)
    with pytest.raises(ValueError, match="in-plane"):
        vf.friction_coefficient(vf.Dimensionless(**TIPS[0], a_x=0.3), vbar=0.5)
    # undamped at alpha = 1: the first harmonic of the normal force resonates
    with pytest.raises(ValueError, match="infinite"):
        vf.Dimensionless(1.0, 2.0, 0.5, profile_exponent=2.0).vbar_to_inertial(0.5)


def test_a_sweep_of_a_curved_tip_on_vbar():
    from vibrofriction.sweep import compute_block, make_plan

    plan = make_plan(alpha=0.5, beta=2.0, amplitude=0.5, profile_exponent=2.0,
                     vbar=[0.98, 1.02])
    _, variables = compute_block(plan, 0)
    Vc = vf.Dimensionless(**TIPS[0]).critical_inertial_velocity()
    assert variables["critical_velocity"] == pytest.approx(Vc, rel=1e-15)
    mu = variables["mu_ratio"].ravel()
    assert mu[0] < 0.9999 and mu[1] == pytest.approx(1.0, abs=1e-10)
    assert mu[0] == vf.friction_coefficient(vf.Dimensionless(**TIPS[0]), vbar=0.98).mu_ratio


def test_the_stiff_laws_vbar_is_the_limit_of_the_tips():
    """docs/contact_geometry.md, "Stiff law of a curved profile": the stiff law's
    ``(beta - alpha) V n/((n + 1) a)`` is ``V/V_c`` as ``alpha, beta -> 0``."""
    ratios = [float(vf.theory.profile_critical_velocity(al, 2 * al, 0.5, 2.0)) * al / 1.5 / 0.5
              for al in (0.05, 0.005)]
    assert ratios == [pytest.approx(0.948, abs=5e-4), pytest.approx(0.995, abs=5e-4)]
