"""The inputs of the local friction laws: RateAndState, mu_static, their conversion and refusals.

The conversion is checked against the units written out by hand here (docs/friction_laws.md):
``d_c`` over ``mu0 F_N0/(m omega^2)``, ``v_ref`` over ``mu0 F_N0/(m omega)``, ``a``, ``b``,
``alpha_ld`` over ``mu0``.
"""

from __future__ import annotations

import math

import pytest

import vibrofriction as vf
from vibrofriction.solver import friction_gradient

PIN = dict(mass=0.01, k_x=2.5e5, k_xc=2e5, k_zc=2.5e5, u_z0=4e-6, du_z=2e-6, omega=6283.0,
           mu0=0.3)


def test_rate_and_state_in_si_converts_to_the_model_units() -> None:
    law = vf.RateAndState(a=0.012, b=0.018, d_c=2e-6, v_ref=1e-3, alpha_ld=0.006, law="slip")
    dim = vf.Physical(**PIN, friction=law).to_dimensionless()
    F_N0 = PIN["k_zc"] * PIN["u_z0"]  # a flat punch without jumping: k_zc u_z0
    length = PIN["mu0"] * F_N0 / (PIN["mass"] * PIN["omega"] ** 2)
    assert dim.rs_a == pytest.approx(0.012 / 0.3, rel=1e-15)
    assert dim.rs_b == pytest.approx(0.018 / 0.3, rel=1e-15)
    assert dim.rs_alpha_ld == pytest.approx(0.006 / 0.3, rel=1e-15)
    assert dim.rs_d_c == pytest.approx(2e-6 / length, rel=1e-14)
    assert dim.rs_v_ref == pytest.approx(1e-3 / (length * PIN["omega"]), rel=1e-14)
    assert dim.rs_law == "slip" and dim.static_ratio == 1.0
    # the dimensionless law is the same law seen in other units: the steady coefficient at the
    # same sliding velocity agrees (mu_ss in mu_star units times mu0)
    v0 = 3e-4
    V = v0 / (length * PIN["omega"])
    mu_model = float(vf.theory.steady_mu_ratio(V, dim.rs_a, dim.rs_b, dim.rs_d_c, dim.rs_v_ref))
    assert mu_model * 0.3 == pytest.approx(law.steady_mu(v0, mu_star=0.3), rel=1e-13)
    assert dim.friction == vf.RateAndState(a=dim.rs_a, b=dim.rs_b, d_c=dim.rs_d_c,
                                           v_ref=dim.rs_v_ref, alpha_ld=dim.rs_alpha_ld,
                                           law="slip")
    plain = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)
    assert plain.friction is None
    assert plain.with_friction(dim.friction).friction == dim.friction
    assert plain.with_friction(dim.friction).with_friction(None) == plain


def test_mu_static_is_the_static_ratio() -> None:
    assert vf.Physical(**PIN).to_dimensionless().static_ratio == 1.0
    pin = vf.Physical(**PIN, mu_static=0.39)
    assert pin.to_dimensionless().static_ratio == pytest.approx(1.3, rel=1e-15)
    assert pin.with_(mu0=0.39).static_ratio == 1.0  # mu_static stays 0.39


@pytest.mark.parametrize(("kwargs", "message"), [
    (dict(a=0.0, b=0.01, d_c=1e-6, v_ref=1e-3), "a must be finite and > 0, got 0.0"),
    (dict(a=0.01, b=-0.01, d_c=1e-6, v_ref=1e-3), "b must be finite and >= 0"),
    (dict(a=0.01, b=0.01, d_c=0.0, v_ref=1e-3), "d_c must be finite and > 0"),
    (dict(a=0.01, b=0.01, d_c=1e-6, v_ref=math.inf), "v_ref must be finite and > 0"),
    (dict(a=0.01, b=0.01, d_c=1e-6, v_ref=1e-3, law="ageing"),
     "law must be one of 'aging', 'slip', got 'ageing'"),
    (dict(a=0.01, b=0.0, d_c=1e-6, v_ref=1e-3, alpha_ld=0.2), "alpha_ld = 0.2 > 0 needs b > 0"),
])
def test_a_bad_law_is_refused_by_name(kwargs, message) -> None:
    with pytest.raises(ValueError, match=message):
        vf.RateAndState(**kwargs)


@pytest.mark.parametrize(("kwargs", "message"), [
    (dict(static_ratio=0.9), "static_ratio must be finite and >= 1"),
    (dict(rs_b=0.1), "rs_b > 0 needs rs_a > 0"),
    (dict(rs_a=0.1, rs_alpha_ld=0.1), "rs_alpha_ld > 0 needs rs_b > 0"),
    (dict(rs_a=0.1, rs_b=0.2, rs_alpha_ld=0.1, amplitude=1.0), "rs_alpha_ld > 0 needs "
     "amplitude < 1"),
    (dict(rs_a=0.1, static_ratio=1.2), "static_ratio > 1 is a law of Coulomb friction"),
    (dict(rs_a=0.1, rs_d_c=0.0), "rs_d_c must be finite and > 0"),
])
def test_dimensionless_law_pairs_are_refused_by_name(kwargs, message) -> None:
    base = dict(alpha=0.5, beta=2.0, amplitude=0.5)
    with pytest.raises(ValueError, match=message):
        vf.Dimensionless(**{**base, **kwargs})


def test_physical_refusals() -> None:
    with pytest.raises(ValueError, match=r"mu_static must be >= mu0 \(= 0.3"):
        vf.Physical(**PIN, mu_static=0.2)
    with pytest.raises(TypeError, match="friction must be a vibrofriction.RateAndState"):
        vf.Physical(**PIN, friction="aging")  # type: ignore[arg-type]
    law = vf.RateAndState(a=0.01, b=0.01, d_c=1e-6, v_ref=1e-3)
    with pytest.raises(ValueError, match="mu_static is a law of Coulomb friction"):
        vf.Physical(**PIN, mu_static=0.4, friction=law)


def test_parts_without_the_laws_refuse_them_by_name() -> None:
    """Nothing drops a law silently: the gradients refuse it (the fit and the design carry both
    laws: tests/bench/test_fit_friction_laws.py, test_design_friction_laws.py)."""
    with pytest.raises(ValueError, match="friction_gradient does not cover rate-and-state"):
        friction_gradient(vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5, rs_a=0.03),
                          v_inertial=0.3)
