"""The set-up in the experimenter's terms (vf.from_bench, contact models) and the
measurement table (read_measurements): docs/bench.md."""

import math

import numpy as np
import pandas as pd
import pytest

import vibrofriction as vf
from vibrofriction.contact import FlatPunch, Material, Sphere, rigid

STEEL = Material(210e9, 0.3)


def test_hertz_and_mindlin_by_hand():
    s = Sphere(3e-3, STEEL, STEEL)
    e_star = 210e9 / (2 * (1 - 0.3**2))
    a = (3 * 20.0 * 3e-3 / (4 * e_star)) ** (1 / 3)
    assert s.contact_radius(20.0) == pytest.approx(a, rel=1e-14)
    k_z, k_x = s.stiffness(20.0)
    assert k_z == pytest.approx(2 * e_star * a, rel=1e-14)
    assert k_x / k_z == pytest.approx(2 * (1 - 0.3) / (2 - 0.3), rel=1e-14)  # Mindlin ratio
    # the tangent stiffness is dF/d(delta) of Hertz's F = 4/3 E* sqrt(R) delta^1.5
    delta = a * a / 3e-3
    def force(d):
        return 4 / 3 * e_star * math.sqrt(3e-3) * d**1.5
    h = 1e-6 * delta
    assert (force(delta + h) - force(delta - h)) / (2 * h) == pytest.approx(k_z, rel=1e-8)


def test_flat_punch_on_a_rigid_counterface():
    p = FlatPunch(1e-3, Material(70e9, 1 / 3), rigid())
    k_z, k_x = p.stiffness(10.0)
    G = 70e9 / (2 * (1 + 1 / 3))
    assert k_z == pytest.approx(2 * 70e9 / (1 - 1 / 9) * 1e-3, rel=1e-14)
    assert k_x == pytest.approx(8 * G * 1e-3 / (2 - 1 / 3), rel=1e-14)
    assert k_z / k_x == pytest.approx(1.25, rel=1e-14)  # the ratio the paper uses
    with pytest.raises(ValueError, match="rigid"):
        FlatPunch(1e-3, rigid(), rigid()).stiffness(1.0)


def test_from_bench_reproduces_what_the_experimenter_knows():
    p = vf.from_bench(natural_frequency_hz=800.0, mass=0.01, quality_factor=50.0,
                               normal_load=20.0, contact=Sphere(3e-3, STEEL, STEEL),
                               drive_frequency_hz=800.0, dF_N=10.0, mu0=0.3, eta_c=0.1)
    assert p.natural_frequency() == pytest.approx(2 * math.pi * 800.0, rel=1e-14)
    assert p.F_N0 == pytest.approx(20.0, rel=1e-14) and p.dF_N == pytest.approx(10.0)
    assert p.quality_factor == pytest.approx(50.0) and p.eta_c == pytest.approx(0.1)
    d = p.to_dimensionless()
    assert d.alpha == pytest.approx(1.0, rel=1e-14) and d.amplitude == pytest.approx(0.5)
    q = vf.from_bench(natural_frequency_hz=800.0, k_x=p.k_x, damping_ratio=0.01,
                               normal_load=20.0, k_zc=p.k_zc, k_xc=p.k_xc,
                               drive_frequency_hz=600.0, du_z=p.du_z, mu0=0.3)
    assert q.mass == pytest.approx(0.01, rel=1e-14) and q.zeta == pytest.approx(0.01)
    assert q.to_dimensionless().alpha == pytest.approx((800 / 600) ** 2, rel=1e-14)


@pytest.mark.parametrize("changes, message", [
    (dict(mass=None), "exactly one of mass"),
    (dict(k_x=1e5), "exactly one of mass"),
    (dict(contact=None), "k_zc and k_xc"),
    (dict(k_zc=1e6), "either contact"),
    (dict(dF_N=None), "exactly one of du_z"),
    (dict(du_z=1e-6), "exactly one of du_z"),
    (dict(natural_frequency_hz=-1.0), "natural_frequency_hz"),
    (dict(normal_load=0.0), "normal_load"),
    (dict(quality_factor=50.0, damping_ratio=0.01), "at most one"),
    (dict(eta_c=-0.1), "eta_c"),
])
def test_from_bench_errors_name_the_input(changes, message):
    kwargs = dict(natural_frequency_hz=800.0, mass=0.01, normal_load=20.0,
                  contact=Sphere(3e-3, STEEL, STEEL), drive_frequency_hz=800.0, dF_N=10.0,
                  mu0=0.3)
    kwargs.update(changes)
    kwargs = {k: v for k, v in kwargs.items() if v is not None}
    with pytest.raises(ValueError, match=message):
        vf.from_bench(**kwargs)


def test_material_errors():
    with pytest.raises(ValueError, match="nu"):
        Material(1e9, 0.5)
    with pytest.raises(ValueError, match="E"):
        Material(-1.0, 0.3)


# --------------------------------------------------------------------------- measurements
def test_read_measurements_converts_units(tmp_path):
    path = tmp_path / "m.csv"
    path.write_text("# pin-on-disk, 800 Hz\n"
                    "v0 [mm/s],cof,du_z [um],omega [Hz],sigma\n"
                    "1.0,0.21,1.3,800,0.005\n"
                    "10.0,0.27,5.4,800,0.004\n")
    d = vf.read_measurements(path)
    np.testing.assert_allclose(d["v0"], [1e-3, 1e-2])
    np.testing.assert_allclose(d["du_z"], [1.3e-6, 5.4e-6])
    np.testing.assert_allclose(d["omega"], 2 * math.pi * 800.0)
    np.testing.assert_allclose(d["sigma"], [0.005, 0.004])
    same = vf.read_measurements(pd.DataFrame({"v0": [1e-3], "cof": [0.2], "du_z": [1e-6],
                                              "omega": [5000.0]}))
    assert list(same.columns) == ["v0", "cof", "du_z", "omega", "sigma", "du_x", "phase_x",
                                  "du_y", "phase_y"]
    assert math.isnan(same["sigma"][0]) and same["du_x"][0] == same["phase_x"][0] == 0.0
    assert same["du_y"][0] == same["phase_y"][0] == 0.0
    inplane = vf.read_measurements(pd.DataFrame({
        "v0 [mm/s]": [-2.0], "cof": [-0.1], "du_z": [1e-6], "omega": [5000.0],
        "du_x [um]": [3.0], "phase_x [deg]": [90.0]}))
    assert inplane.iloc[0].to_dict() == pytest.approx({
        "v0": -2e-3, "cof": -0.1, "du_z": 1e-6, "omega": 5000.0, "sigma": math.nan,
        "du_x": 3e-6, "phase_x": math.pi / 2, "du_y": 0.0, "phase_y": 0.0}, nan_ok=True)


@pytest.mark.parametrize("text, message", [
    ("v0,cof,du_z\n1,0.2,1e-6\n", r"lacks the column\(s\) \['omega'\]"),
    ("v0 [km/h],cof,du_z,omega\n1,0.2,1e-6,5000\n", r"column 'v0': unit 'km/h'"),
    ("v0,cof,du_z,omega\n1,0.2,1e-6,5000\n2,nan,1e-6,5000\n", r"column 'cof', line 3"),
    ("v0,cof,du_z,omega\n-1,0.2,1e-6,5000\n", r"column 'v0', line 2"),
    ("v0,cof,du_z,omega\n1,0.2,1e-6,0\n", r"column 'omega', line 2: .* > 0"),
    ("v0,cof,du_z,omega,sigma\n1,0.2,1e-6,5,abc\n", r"column 'sigma', line 2: 'abc'"),
    # the line as an editor numbers it: comments (the documented format starts with one),
    # blank lines and inline comments count
    ("# pin-on-disk\n# 20 N\nv0,cof,du_z,omega\n1,0.2,1e-6,5000\n2,nan,1e-6,5000\n",
     r"column 'cof', line 5: nan is not"),
    ("# c\n\nv0,cof,du_z,omega # SI\n\n1,0.2,1e-6,5000 # ok\n# mid\n2,0.2,1e-6,-5\n",
     r"column 'omega', line 7: -5 is not"),
    ("# c\r\nv0,cof,du_z,omega\r\n1,0.2,1e-6,5000\r\n2,0.2,-1,5000\r\n",
     r"column 'du_z', line 4"),
    # names match regardless of case: a Sigma column is read (and checked)
    ("v0,cof,du_z,omega,Sigma\n1,0.2,1e-6,5000,-1\n", r"column 'sigma', line 2"),
    ("v0,cof,COF,du_z,omega\n1,0.2,0.2,1e-6,5000\n", r"'cof' appears twice .*'COF'"),
    # a name close to a known one is a misspelling, not an ignored column
    ("v0,cof,du_z,omega,sigm\n1,0.2,1e-6,5000,0.01\n", r"column 'sigm' .* close to 'sigma'"),
    ("v0,cof,du-z [um],omega\n1,0.2,1,5000\n", r"column 'du-z \[um\]' .* close to 'du_z'"),
])
def test_read_measurements_errors_name_column_and_row(tmp_path, text, message):
    path = tmp_path / "bad.csv"
    path.write_bytes(text.encode())
    with pytest.raises(ValueError, match=message):
        vf.read_measurements(path)


def test_read_measurements_matches_names_regardless_of_case(tmp_path):
    path = tmp_path / "m.csv"
    path.write_text("# other columns are ignored\n"
                    "time,V0 [MM/S],Cof,DU_Z [um],Omega [Hz],Sigma,load\n"
                    "0,1.0,0.21,1.3,800,0.005,20\n")
    d = vf.read_measurements(path)
    assert d.iloc[0].to_dict() == pytest.approx({"v0": 1e-3, "cof": 0.21, "du_z": 1.3e-6,
                                                 "omega": 2 * math.pi * 800, "sigma": 0.005,
                                                 "du_x": 0.0, "phase_x": 0.0, "du_y": 0.0,
                                                 "phase_y": 0.0})
    frame = pd.DataFrame({"v0": [1e-3], "cof": [0.2], "du_z": [1e-6], "omega": [5e3],
                          "Sigma": [0.01]})
    assert vf.read_measurements(frame)["sigma"][0] == 0.01


@pytest.mark.parametrize(("contact", "key"), [
    ({"type": "sphere", "radius": 0.003, "radus": 0.003}, "radus"),
    ({"type": "cone", "slope": 0.5, "radius": 0.003}, "radius"),  # a sphere's key
    ({"type": "flat_punch", "radius": 1e-3, "mu0": 0.3}, "mu0"),  # a top-level key
])
def test_an_unknown_key_in_a_bench_files_contact_is_named(tmp_path, contact, key):
    """It was ignored: a misspelt key left the contact as the file's other keys made it."""
    import json

    materials = {"pin": {"E": 210e9, "nu": 0.3}, "counterface": {"E": 210e9, "nu": 0.3}}
    spec = {"natural_frequency_hz": 800, "mass": 0.01, "normal_load": 20, "mu0": 0.3,
            "drive_frequency_hz": 1000, "du_z": 1e-7, "contact": {**contact, **materials}}
    path = tmp_path / "bench.json"
    path.write_text(json.dumps(spec))
    sizes = {"sphere": "'radius'", "cone": "'slope'", "flat_punch": "'radius'"}[contact["type"]]
    with pytest.raises(ValueError) as info:
        vf.from_bench_file(path)
    assert str(info.value) == (
        f"bench file {str(path)!r}: unknown key {key!r} in \"contact\" of type "
        f"{contact['type']!r}; its keys are 'type', {sizes}, 'pin', 'counterface'")
    del spec["contact"][key]  # without it the file is read
    path.write_text(json.dumps(spec))
    assert isinstance(vf.from_bench_file(path), vf.Physical)
