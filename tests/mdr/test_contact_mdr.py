"""Real contact geometry by the MDR (docs/contact_geometry.md): power-law profiles, cone,
sphere and flat punch against Hertz, Sneddon's cone, Sneddon's general axisymmetric
solution and a direct quadrature of the MDR row."""

import math

import numpy as np
import pytest
from scipy import integrate, special

from vibrofriction.contact import (
    Cone,
    FlatPunch,
    Material,
    PowerLaw,
    Sphere,
    effective_modulus,
    effective_shear_modulus,
    mdr_kappa,
    mdr_shear_modulus,
    rigid,
)

STEEL = Material(210e9, 0.3)
GLASS = Material(70e9, 0.22)


def test_kappa_by_hand_and_from_gamma():
    assert mdr_kappa(2.0) == pytest.approx(2.0, rel=1e-14)        # sphere
    assert mdr_kappa(1.0) == pytest.approx(math.pi / 2, rel=1e-14)  # cone
    for n in (0.3, 0.5, 1.7, 3.0, 8.0, 40.0):
        by_gamma = math.sqrt(math.pi) * special.gamma(n / 2 + 1) / special.gamma(n / 2 + 0.5)
        assert mdr_kappa(n) == pytest.approx(by_gamma, rel=1e-12)
    # large n: kappa_n ~ sqrt(pi n / 2)
    assert mdr_kappa(1e6) / math.sqrt(math.pi * 1e6 / 2) == pytest.approx(1.0, abs=1e-6)
    assert mdr_kappa(math.inf) == math.inf
    with pytest.raises(ValueError, match="exponent must be"):
        mdr_kappa(0.0)


def test_sphere_is_hertz():
    s = Sphere(3e-3, STEEL, GLASS)
    e_star = effective_modulus(STEEL, GLASS)
    for d in (1e-8, 3e-7, 2e-6):
        assert s.normal_force(d) == pytest.approx(4 / 3 * e_star * math.sqrt(3e-3) * d**1.5,
                                                  rel=1e-13)
        assert s.radius_at(d) == pytest.approx(math.sqrt(3e-3 * d), rel=1e-13)
    # the load form of Hertz (the bench's contact radius) agrees with the MDR one
    for load in (0.5, 20.0):
        assert s.radius_at(s.indentation(load)) == pytest.approx(s.contact_radius(load),
                                                                 rel=1e-13)
        k_z, k_x = s.stiffness(load)
        d = s.indentation(load)
        assert s.normal_stiffness(d) == pytest.approx(k_z, rel=1e-13)
        assert s.tangential_stiffness(d) == pytest.approx(k_x, rel=1e-13)
    same = PowerLaw(1 / (2 * 3e-3), 2.0, STEEL, GLASS)
    assert same.normal_force(1e-6) == pytest.approx(s.normal_force(1e-6), rel=1e-13)
    assert same.stiffness(5.0) == pytest.approx(s.stiffness(5.0), rel=1e-13)


def test_cone_is_sneddon():
    theta = 1.3  # half-angle from the axis, radians
    c = Cone.from_half_angle(theta, STEEL, rigid())
    e_star = effective_modulus(STEEL, rigid())
    assert c.slope == pytest.approx(1 / math.tan(theta), rel=1e-14)
    assert c.half_angle == pytest.approx(theta, rel=1e-14)
    for d in (1e-7, 4e-6):
        # Sneddon (1948): F = (2/pi) E* tan(theta) d^2, d = (pi/2) a cot(theta)
        assert c.normal_force(d) == pytest.approx(2 / math.pi * e_star * math.tan(theta) * d**2,
                                                  rel=1e-13)
        a = c.radius_at(d)
        assert d == pytest.approx(math.pi / 2 * a / math.tan(theta), rel=1e-13)
    with pytest.raises(ValueError, match=r"half_angle must be in \(0, pi/2\)"):
        Cone.from_half_angle(math.pi / 2, STEEL, STEEL)
    with pytest.raises(ValueError, match="slope must be finite and > 0"):
        Cone(0.0, STEEL, STEEL)


def _sneddon(n: float, c: float, a: float, e_star: float) -> tuple[float, float]:
    """Sneddon (1965), axisymmetric punch of profile f(rho), rho = r/a:
    d = int_0^1 f'(rho)/sqrt(1 - rho^2), F = 2 E* a int_0^1 rho^2 f'(rho)/sqrt(1 - rho^2)."""
    k = c * a**n * n  # f'(rho) = k rho^(n - 1): the weights carry the power laws

    def moment(p):
        return k * integrate.quad(lambda r: (1.0 + r) ** -0.5, 0.0, 1.0, weight="alg",
                                  wvar=(p, -0.5),
                                  epsabs=0, epsrel=1e-13)[0]
    return moment(n - 1.0), 2 * e_star * a * moment(n + 1.0)


@pytest.mark.parametrize("n", [0.6, 1.0, 1.5, 2.0, 3.0, 7.5])
def test_power_law_against_sneddon_and_the_mdr_row(n):
    p = PowerLaw(2.0e3, n, STEEL, GLASS)
    e_star = effective_modulus(STEEL, GLASS)
    d = 1e-6
    a = p.radius_at(d)
    assert p.profile_1d(a) == pytest.approx(d, rel=1e-13)
    # the 3-D solution (independent of kappa_n) at the same contact radius
    d3, F3 = _sneddon(n, 2.0e3, a, e_star)
    assert d3 == pytest.approx(d, rel=1e-9) and p.normal_force(d) == pytest.approx(F3, rel=1e-9)
    # the MDR row summed numerically
    row = 2 * e_star * integrate.quad(lambda x: d - p.profile_1d(x), 0.0, a, epsrel=1e-13)[0]
    assert p.normal_force(d) == pytest.approx(row, rel=1e-8)
    # the normal stiffness is dF/dd, the inverse is the inverse
    h = 1e-5 * d
    dfdd = (p.normal_force(d + h) - p.normal_force(d - h)) / (2 * h)
    assert p.normal_stiffness(d) == pytest.approx(dfdd, rel=1e-8)
    assert p.indentation(p.normal_force(d)) == pytest.approx(d, rel=1e-12)
    assert p.normal_force(-1e-7) == 0.0 and p.radius_at(-1e-7) == 0.0


def test_flat_punch_limit_and_moduli():
    f = FlatPunch(1e-3, STEEL, GLASS)
    e_star = effective_modulus(STEEL, GLASS)
    assert f.normal_force(2e-6) == pytest.approx(2 * e_star * 1e-3 * 2e-6, rel=1e-14)
    assert f.indentation(f.normal_force(2e-6)) == pytest.approx(2e-6, rel=1e-14)
    assert f.radius_at(2e-6) == 1e-3 and f.radius_at(0.0) == 0.0
    assert f.profile_1d(0.5e-3) == 0.0 and f.profile_1d(1.1e-3) == math.inf
    # the G* (2 - nu over 4 G) times 2a is the bench's 8 G* a
    k_z, k_x = f.stiffness(1.0)
    assert f.tangential_stiffness(1e-6) == pytest.approx(k_x, rel=1e-14)
    assert f.normal_stiffness(1e-6) == pytest.approx(k_z, rel=1e-14)
    inv = sum((2 - m.nu) / (4 * m.G) for m in (STEEL, GLASS))
    assert mdr_shear_modulus(STEEL, GLASS) == pytest.approx(1 / inv, rel=1e-14)
    assert mdr_shear_modulus(STEEL, GLASS) == pytest.approx(
        4 * effective_shear_modulus(STEEL, GLASS), rel=1e-14)
    # a steep power law tends to the flat punch of the same contact radius
    A, h = 0.5, 1e-6
    wide = FlatPunch(A, STEEL, GLASS)
    for n, tol in ((50.0, 0.03), (500.0, 0.003)):
        p = PowerLaw(h / A**n, n, STEEL, GLASS)  # z = h (r/A)^n
        d = p.profile_1d(A)  # contact radius A
        assert p.normal_force(d) / wide.normal_force(d) == pytest.approx(1.0, abs=tol)


@pytest.mark.parametrize("make, message", [
    (lambda: PowerLaw(-1.0, 2.0, STEEL, STEEL), "c must be finite and > 0"),
    (lambda: PowerLaw(1.0, 0.0, STEEL, STEEL), "n must be finite and > 0"),
    (lambda: PowerLaw(1.0, math.inf, STEEL, STEEL), "n must be finite and > 0"),
    (lambda: PowerLaw(1.0, 2.0, STEEL, STEEL).indentation(-1.0), "normal_load must be"),
    (lambda: PowerLaw(1.0, 2.0, STEEL, STEEL).radius_at(np.nan), "indentation must be"),
])
def test_errors_name_the_parameter_and_range(make, message):
    with pytest.raises(ValueError, match=message):
        make()
