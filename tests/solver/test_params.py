"""Parameters (vibrofriction.params): validation, conversions, eq. (12), cases I-IV."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from vibrofriction.params import Case, Dimensionless, Physical, classify


def physical(**changes: float) -> Physical:
    """A pin of Fig. 8: 800 Hz natural frequency, driven off resonance."""
    base = dict(mass=0.01, k_x=0.01 * (2 * math.pi * 800) ** 2, k_xc=2.0e5, k_zc=2.5e5,
                u_z0=4.0e-6, du_z=2.0e-6, omega=2 * math.pi * 1000, mu0=0.3)
    base.update(changes)
    return Physical(**base)


# --------------------------------------------------------------------------- Dimensionless
def test_dimensionless_converts_and_freezes() -> None:
    d = Dimensionless(1, 3, 0)
    assert (d.alpha, d.beta, d.amplitude) == (1.0, 3.0, 0.0)
    assert all(isinstance(v, float) for v in (d.alpha, d.beta, d.amplitude))
    with pytest.raises(dataclasses.FrozenInstanceError):
        d.alpha = 2.0  # type: ignore[misc]


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (dict(alpha=0.0), r"alpha must be finite and > 0, got 0.0"),
        (dict(alpha=-1.0), r"alpha must be finite and > 0, got -1.0"),
        (dict(alpha=math.inf, beta=math.inf), r"alpha must be finite and > 0, got inf"),
        (dict(alpha=math.nan), r"alpha must be finite and > 0, got nan"),
        (dict(beta=0.3), r"beta must be > alpha \(= 0.5\) or math.inf, got 0.3"),
        (dict(beta=0.5), r"beta must be > alpha \(= 0.5\) or math.inf, got 0.5"),
        (dict(beta=math.nan), r"beta must be > alpha \(= 0.5\) or math.inf, got nan"),
        (dict(amplitude=-0.1), r"amplitude must be finite and >= 0, got -0.1"),
        (dict(amplitude=math.inf), r"amplitude must be finite and >= 0, got inf"),
        (dict(amplitude=math.nan), r"amplitude must be finite and >= 0, got nan"),
    ],
)
def test_dimensionless_validation(kwargs: dict, message: str) -> None:
    args = dict(alpha=0.5, beta=2.0, amplitude=0.5) | kwargs
    with pytest.raises(ValueError, match=message):
        Dimensionless(**args)


@pytest.mark.parametrize(
    ("kwargs", "name", "kind"),
    [
        (dict(phase_x="1.0"), "phase_x", "str"),  # a numeric string: numpy reads 1.0
        (dict(amplitude=True), "amplitude", "bool"),  # numpy reads 1.0
        (dict(a_x=np.bool_(False)), "a_x", "bool"),
        (dict(alpha=[0.5, "0.7"]), "alpha", "str"),
        (dict(alpha=np.array(["0.5"])), "alpha", "str_"),
        (dict(beta=np.array([2.0, True], dtype=object)), "beta", "bool"),
        (dict(zeta=b"0.1"), "zeta", "bytes"),
    ],
)
def test_strings_and_booleans_are_refused_in_one_sentence(kwargs: dict, name: str,
                                                          kind: str) -> None:
    """``float("1.0")`` and ``float(True)`` are numbers to numpy: the validator refuses them,
    naming the parameter, what it must be and its range."""
    args = dict(alpha=0.5, beta=2.0, amplitude=0.5) | kwargs
    with pytest.raises(ValueError) as info:
        Dimensionless(**args)
    text = str(info.value)
    assert text.startswith(f"{name} must be a real number or an array of them (")
    assert f"not a {kind}: got" in text and text.count(". ") == 0 and "\n" not in text


@pytest.mark.parametrize(("name", "value"), [("phase_x", "1.0"), ("du_z", True),
                                             ("mass", "0.01")])
def test_a_physical_set_up_refuses_strings_and_booleans(name: str, value) -> None:
    with pytest.raises(ValueError, match=f"^{name} must be a real number or an array of them"):
        physical(**{name: value})


@pytest.mark.parametrize("value", [1, 1.0, np.float32(0.5), np.int64(2), np.array([0.5, 1.5]),
                                   [0.5, 1], np.array(0.5, dtype=object)])
def test_real_numbers_of_any_numeric_type_are_accepted(value) -> None:
    d = Dimensionless(0.5, 2.0, 0.5, phase_x=value) if np.ndim(value) == 0 else None
    assert d is None or d.phase_x == float(value)
    from vibrofriction.validation import validated

    np.testing.assert_array_equal(validated({"phase_x": value})["phase_x"],
                                  np.asarray(value, dtype=float))


@pytest.mark.parametrize("velocity", ["vbar", "v_inertial"])
@pytest.mark.parametrize("value", ["0.3", True])
def test_a_velocity_given_as_a_string_or_a_bool_is_refused(velocity: str, value) -> None:
    import vibrofriction as vf

    with pytest.raises(ValueError, match=f"^{velocity} must be a real number"):
        vf.friction_coefficient(Dimensionless(0.5, 2.0, 0.5), **{velocity: value})


def test_dimensionless_flags() -> None:
    assert Dimensionless(0.5, math.inf, 0.5).is_rigid
    assert not Dimensionless(0.5, 1e300, 0.5).is_rigid
    assert Dimensionless(0.5, 2.0, 1.5).jumping
    assert not Dimensionless(0.5, 2.0, 1.0).jumping
    assert Dimensionless(0.01, 0.02, 0.5).case is Case.STIFF
    assert Dimensionless(1.0, math.inf, 0.5).case is Case.RESONANT_SYSTEM


def test_critical_inertial_velocity_formula() -> None:
    alpha, beta, a = 0.3, 2.5, 0.8
    c = a * abs(beta - 1) / ((beta - alpha) * abs(alpha - 1))
    d = Dimensionless(alpha, beta, a)
    assert d.critical_inertial_velocity() == pytest.approx(c, rel=1e-15)
    assert Dimensionless(0.3, math.inf, a).critical_inertial_velocity() == pytest.approx(a / 0.7)
    assert d.vbar_to_inertial(1.0) == pytest.approx(c)
    np.testing.assert_allclose(d.vbar_to_inertial(np.array([0.0, 2.0])), [0.0, 2 * c])


def test_critical_inertial_velocity_resonances() -> None:
    assert Dimensionless(1.0, 3.0, 0.5).critical_inertial_velocity() == math.inf
    assert Dimensionless(0.5, 1.0, 0.5).critical_inertial_velocity() == 0.0
    assert Dimensionless(0.5, 3.0, 0.0).critical_inertial_velocity() == 0.0


@pytest.mark.parametrize(
    ("params", "why"),
    [
        ((1.0, 3.0, 0.5), r"alpha == 1 \(case IV\): v0\* is infinite"),
        ((0.5, 1.0, 0.5), r"beta == 1 \(case III\): v0\* is zero"),
        ((0.5, 3.0, 0.0), r"amplitude == 0: v0\* is zero"),
    ],
)
def test_vbar_undefined(params: tuple[float, float, float], why: str) -> None:
    d = Dimensionless(*params)
    for convert in (d.vbar_to_inertial, d.inertial_to_vbar):
        with pytest.raises(ValueError, match=why + ".*use the inertial velocity v_inertial"):
            convert(1.0)


@pytest.mark.parametrize("bad", [-1.0, math.nan, math.inf])
def test_velocity_validation(bad: float) -> None:
    d = Dimensionless(0.5, 2.0, 0.5)
    with pytest.raises(ValueError, match=rf"vbar must be finite and >= 0, got {bad!r}"):
        d.vbar_to_inertial(bad)
    with pytest.raises(ValueError, match=r"v_inertial must be finite and >= 0, got"):
        d.inertial_to_vbar(np.array([1.0, bad]))
    p = physical()
    if math.isfinite(bad):  # v0 is signed: sliding the other way
        assert p.v0_to_inertial(bad) == -p.v0_to_inertial(-bad) < 0.0
    else:
        with pytest.raises(ValueError, match=r"v0 must be finite, got"):
            p.v0_to_inertial(bad)
    with pytest.raises(ValueError, match=r"v0 must be finite and >= 0, got"):
        p.v0_to_vbar(bad)


# --------------------------------------------------------------------------- Physical
@pytest.mark.parametrize("name", ["mass", "k_x", "k_zc", "u_z0", "omega", "mu0"])
@pytest.mark.parametrize("bad", [0.0, -1.0, math.inf, math.nan])
def test_physical_positive_fields(name: str, bad: float) -> None:
    with pytest.raises(ValueError, match=rf"{name} must be finite and > 0, got {bad!r}"):
        physical(**{name: bad})


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan])
def test_physical_k_xc(bad: float) -> None:
    with pytest.raises(ValueError, match=rf"k_xc must be > 0 \(math.inf allowed\), got {bad!r}"):
        physical(k_xc=bad)


@pytest.mark.parametrize("bad", [-1e-9, math.inf, math.nan])
def test_physical_du_z(bad: float) -> None:
    with pytest.raises(ValueError, match=rf"du_z must be finite and >= 0, got {bad!r}"):
        physical(du_z=bad)


def test_physical_derived_quantities() -> None:
    p = physical()
    mw2 = p.mass * p.omega**2
    assert p.F_N0 == pytest.approx(1.0)
    assert p.dF_N == pytest.approx(0.5)
    assert p.natural_frequency() == pytest.approx(2 * math.pi * 800)
    d = p.to_dimensionless()
    assert d.alpha == pytest.approx(0.64)
    assert d.beta == pytest.approx((p.k_x + p.k_xc) / mw2)
    assert d.amplitude == 0.5
    q = p.with_(du_z=6e-6)
    assert q.du_z == 6e-6 and q.to_dimensionless().jumping and p.du_z == 2e-6
    with pytest.raises(ValueError, match="du_z must be"):
        p.with_(du_z=-1.0)


def test_physical_critical_velocity_eq12() -> None:
    p = physical()
    mw2 = p.mass * p.omega**2
    v_star = (p.mu0 * p.omega * p.du_z * p.k_zc / p.k_xc
              * abs(p.k_xc + p.k_x - mw2) / abs(p.k_x - mw2))
    assert p.critical_velocity() == pytest.approx(v_star, rel=1e-14)
    # vbar = 1 <-> v0 = v0*, through both routes
    assert p.v0_to_vbar(v_star) == pytest.approx(1.0, rel=1e-12)
    assert p.vbar_to_v0(1.0) == pytest.approx(v_star, rel=1e-12)
    unit = p.mu0 * p.F_N0 / (p.mass * p.omega)
    assert p.to_dimensionless().critical_inertial_velocity() * unit == pytest.approx(
        v_star, rel=1e-12)
    assert p.v0_to_inertial(v_star) == pytest.approx(v_star * p.mass * p.omega / (p.mu0 * p.F_N0))


def test_physical_rigid_contact() -> None:
    p = physical(k_xc=math.inf)
    mw2 = p.mass * p.omega**2
    limit = p.mu0 * p.omega * p.du_z * p.k_zc / abs(p.k_x - mw2)
    assert p.critical_velocity() == pytest.approx(limit, rel=1e-14)
    assert physical(k_xc=1e15).critical_velocity() == pytest.approx(limit, rel=1e-9)
    d = p.to_dimensionless()
    assert d.is_rigid and d.beta == math.inf
    assert p.vbar_to_v0(2.0) == pytest.approx(2 * limit, rel=1e-12)


def test_physical_resonances() -> None:
    omega = 2 * math.pi * 800.0
    p4 = physical(omega=omega, k_x=0.01 * omega**2)  # k_x = m omega^2 exactly: case IV
    assert p4.critical_velocity() == math.inf
    assert p4.to_dimensionless().case is Case.RESONANT_SYSTEM
    with pytest.raises(ValueError, match=r"case IV.*v_inertial"):
        p4.v0_to_vbar(0.1)
    with pytest.raises(ValueError, match=r"case IV.*v_inertial"):
        p4.vbar_to_v0(1.0)
    assert p4.inertial_to_v0(p4.v0_to_inertial(0.1)) == pytest.approx(0.1, rel=1e-15)
    mw2 = 0.01 * omega**2
    p3 = physical(omega=omega, k_x=0.25 * mw2, k_xc=0.75 * mw2)  # case III
    assert p3.critical_velocity() == 0.0
    assert p3.to_dimensionless().case is Case.RESONANT_CONTACT
    with pytest.raises(ValueError, match=r"case III.*v_inertial"):
        p3.v0_to_vbar(0.1)


# --------------------------------------------------------------------------- classification
@pytest.mark.parametrize(
    ("alpha", "beta", "case"),
    [
        (0.01, 0.02, Case.STIFF),  # Fig. 4a
        (0.01, 400.01, Case.SOFT),  # Fig. 4b
        (0.01, 1.0, Case.RESONANT_CONTACT),  # Fig. 5
        (0.5, 1.04, Case.RESONANT_CONTACT),
        (1.0, math.inf, Case.RESONANT_SYSTEM),  # Fig. 6
        (1.0, 1.01, Case.RESONANT_SYSTEM),
        (0.97, 1.03, Case.RESONANT_SYSTEM),  # IV takes precedence over III
        (10.0, 10.5, Case.STIFF),
        (0.01, math.inf, Case.SOFT),
        (0.3, 3.0, Case.GENERAL),
        (0.01, 5.0, Case.GENERAL),
        (0.01, 0.5, Case.GENERAL),
    ],
)
def test_classify(alpha: float, beta: float, case: Case) -> None:
    assert classify(alpha, beta) is case


def test_classify_thresholds_and_validation() -> None:
    assert classify(0.9, 2.0) is Case.GENERAL
    assert classify(0.9, 2.0, rtol=0.1) is Case.RESONANT_SYSTEM
    assert classify(0.05, 8.0, ratio=0.2) is Case.SOFT
    with pytest.raises(ValueError, match=r"ratio must be in \(0, 1\), got 1.5"):
        classify(0.5, 2.0, ratio=1.5)
    with pytest.raises(ValueError, match=r"rtol must be finite and >= 0, got -0.1"):
        classify(0.5, 2.0, rtol=-0.1)
    with pytest.raises(ValueError, match=r"beta must be > alpha \(= 0.5\)"):
        classify(0.5, 0.2)


def test_case_members() -> None:
    assert [c.value for c in Case] == ["I", "II", "III", "IV", "general"]
    for c in Case:
        label = "General" if c is Case.GENERAL else f"Case {c.value},"
        assert c.description.startswith(label), c.description
    assert "(13)" in Case.SOFT.description and "(14)" in Case.STIFF.description
    assert "(12)" in Case.GENERAL.description


# --------------------------------------------------------------------------- property tests
log_floats = st.floats(-4.0, 4.0).map(lambda e: 10.0**e)


@settings(max_examples=100, deadline=None)
@given(alpha=log_floats, gap=log_floats, a=st.floats(1e-3, 3.0),
       vbar=st.floats(0.0, 1e3))
def test_dimensionless_round_trip(alpha: float, gap: float, a: float, vbar: float) -> None:
    d = Dimensionless(alpha, alpha + gap, a)
    assume(d.alpha != 1.0 and d.beta != 1.0)
    assume(d.beta > d.alpha)
    V = d.vbar_to_inertial(vbar)
    assert d.inertial_to_vbar(V) == pytest.approx(vbar, rel=1e-12, abs=1e-300)


@settings(max_examples=100, deadline=None)
@given(
    mass=log_floats, k_x=log_floats, k_xc=st.one_of(log_floats, st.just(math.inf)),
    k_zc=log_floats, u_z0=log_floats, a=st.floats(1e-3, 3.0), omega=log_floats,
    mu0=st.floats(0.01, 2.0), vbar=st.floats(0.0, 100.0),
)
# a contact 5e7 times softer than the pin: beta - alpha holds k_xc to 1e-8 only (found by
# hypothesis in CI on 2026-12-01, off by 1.0e-8 where the bound below allows 5.5e-8)
@example(mass=5.333287788801987, k_x=8678.2554100998, k_xc=0.00017112652420471605,
         k_zc=1.0, u_z0=1.0, a=1.0, omega=5.333287788801987, mu0=1.0, vbar=0.0)
def test_physical_round_trips_and_eq12(mass: float, k_x: float, k_xc: float, k_zc: float,
                                       u_z0: float, a: float, omega: float, mu0: float,
                                       vbar: float) -> None:
    p = Physical(mass=mass, k_x=k_x, k_xc=k_xc, k_zc=k_zc, u_z0=u_z0, du_z=a * u_z0,
                 omega=omega, mu0=mu0)
    mw2 = mass * omega**2
    assume(abs(k_x / mw2 - 1.0) > 1e-6 and abs((k_x + k_xc) / mw2 - 1.0) > 1e-6)
    assume(k_x + k_xc > k_x)  # k_xc not lost in rounding
    d = p.to_dimensionless()
    v_star = p.critical_velocity()
    # eq. (12) as printed, written out here independently of theory.critical_velocity
    # (rigid contact, k_xc = inf: the limit mu0 omega du_z k_zc / |k_x - m omega^2|)
    ratio = 1.0 if math.isinf(k_xc) else abs(k_x + k_xc - mw2) / k_xc
    eq12 = mu0 * omega * a * u_z0 * k_zc * ratio / abs(k_x - mw2)
    assert v_star == pytest.approx(eq12, rel=1e-9)
    # eq. (12) through the dimensionless groups: v0* = c * mu0 F_N0 / (m omega); the
    # groups hold k_xc as beta - alpha, rounded from (k_x + k_xc)/(m omega^2): its relative
    # error, and so c's, is up to a few eps (k_x + k_xc)/k_xc (the conversion's conditioning)
    unit = mu0 * p.F_N0 / (mass * omega)
    cond = 1.0 if math.isinf(k_xc) else (k_x + k_xc) / k_xc
    assert d.critical_inertial_velocity() * unit == pytest.approx(
        v_star, rel=1e-8 + 4.0 * np.finfo(float).eps * cond)
    v0 = p.vbar_to_v0(vbar)
    assert p.v0_to_vbar(v0) == pytest.approx(vbar, rel=1e-10, abs=1e-300)
    assert v0 == pytest.approx(vbar * v_star, rel=1e-8, abs=1e-300)
    V = p.v0_to_inertial(v0)
    assert p.inertial_to_v0(V) == pytest.approx(v0, rel=1e-12, abs=1e-300)
    assert d.inertial_to_vbar(V) == pytest.approx(vbar, rel=1e-10, abs=1e-300)


def test_the_vbar_unit_is_computed_once_and_changes_nothing_else():
    """``Dimensionless`` keeps ``V_c`` after the first conversion (its fields are frozen):
    equality, hashing and pickling are unchanged, the value is eq. (12)'s, and where
    ``vbar`` does not exist every call says so (a refusal is not cached)."""
    import pickle

    s = Dimensionless(0.5, 2.0, 0.5)
    fresh = Dimensionless(0.5, 2.0, 0.5)
    assert s.vbar_to_inertial(0.3) == pytest.approx(0.3 * 0.5 * 1.0 / (1.5 * 0.5))
    assert s == fresh and hash(s) == hash(fresh)
    assert pickle.loads(pickle.dumps(s)) == s
    resonant = Dimensionless(1.0, 2.0, 0.5)
    for _ in range(2):
        with pytest.raises(ValueError, match="case IV"):
            resonant.vbar_to_inertial(0.3)
