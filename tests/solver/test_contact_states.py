"""One vocabulary of contact states (vibrofriction.schema.ContactState) for every solver,
and histories whose fields are all filled by the solver that returns them."""

import ast
import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction import schema
from vibrofriction._kernels import codes
from vibrofriction._kernels import mdr as kernel_mdr
from vibrofriction._kernels import plane as kernel_plane
from vibrofriction.explorer.compute import CONTACT_STATES
from vibrofriction.figures.style import PHASE_COLORS
from vibrofriction.schema import CONTACT_STATE_NAMES, PARTIAL, ContactState
from vibrofriction.solver import PHASE_NAMES, solve_points
from vibrofriction.solver.mdr import mdr_row

SOLVER = Path(vf.__file__).parent / "solver"


def test_the_states_keep_the_stored_codes_and_names():
    # atlases and CSVs store these codes: they must not move
    assert [(s.name, int(s)) for s in ContactState] == [
        ("STICK", 0), ("SLIP_POS", 1), ("SLIP_NEG", 2), ("FLIGHT", 3)]
    assert CONTACT_STATE_NAMES == ("stick", "slip+", "slip-", "flight") == PHASE_NAMES
    assert [s.long_name for s in ContactState] == ["stick", "forward slip", "reverse slip",
                                                   "flight"]
    assert schema.NO_STATE == codes.NO_PHASE == vf.solver.NO_PHASE == -1
    assert PARTIAL not in CONTACT_STATE_NAMES
    for s in ContactState:
        assert ContactState.from_label(s.label) is s
    with pytest.raises(ValueError, match="unknown contact state 'open'"):
        ContactState.from_label("open")


def test_every_kernel_uses_the_schemas_codes():
    for name in ("STICK", "SLIP_POS", "SLIP_NEG", "FLIGHT"):
        code = int(ContactState[name])
        assert getattr(codes, name) == code
        assert getattr(kernel_mdr, name) == code  # the MDR row's springs
    for name in ("STICK", "FLIGHT"):
        assert getattr(kernel_plane, name) == int(ContactState[name])
    # the 2-D kernel's one slip mode is written with the code of forward slip
    assert kernel_plane.SLIP == ContactState.SLIP_POS
    assert not hasattr(kernel_mdr, "OFF")


def test_views_name_and_colour_the_same_states():
    assert set(PHASE_COLORS) == set(CONTACT_STATE_NAMES)
    assert CONTACT_STATES == tuple(s.long_name for s in ContactState)
    # the result field's long name speaks the states' words
    assert "reverse slip" in schema.FIELD["reverse_slip_fraction"].long_name


def _curved(**kw):
    d = vf.Dimensionless(0.5, 2.0, 1.5, zeta=0.1, profile_exponent=2.0)
    return vf.simulate(d, v_inertial=0.3, periods=1, samples_per_period=200, springs=24,
                       **kw)


def test_a_curved_tips_spring_states_are_the_schemas_codes():
    """What each spring does at each sample is what its code's name says: out of contact
    no normal and no tangential force, slip+ f = n > 0, slip- f = -n < 0, stick |f| <= n;
    the summary phase is from the one set (plus partial)."""
    h = _curved(initial="steady")
    assert isinstance(h, vf.CurvedHistory)
    s, f, n = h.spring_state, h.spring_f, h.spring_normal()
    scale = 1e-12 * float(np.max(n))
    assert set(np.unique(s)) == {int(c) for c in ContactState}  # a jumping sphere: all 4
    flight = s == ContactState.FLIGHT
    assert np.all(f[flight] == 0.0) and np.all(n[flight] <= scale)
    assert np.all(n[~flight] >= 0.0)
    pos, neg = s == ContactState.SLIP_POS, s == ContactState.SLIP_NEG
    np.testing.assert_allclose(f[pos], n[pos], atol=scale)
    np.testing.assert_allclose(f[neg], -n[neg], atol=scale)
    stick = s == ContactState.STICK
    assert np.all(np.abs(f[stick]) <= n[stick] + scale)
    assert set(np.unique(h.phase)) <= {*CONTACT_STATE_NAMES, PARTIAL}
    assert "flight" in h.phase and PARTIAL in h.phase
    none_touch = np.all(flight, axis=1)
    np.testing.assert_array_equal(h.phase == "flight", none_touch)
    for state in (ContactState.STICK, ContactState.SLIP_POS, ContactState.SLIP_NEG):
        every = ~none_touch & np.all((s == state) | flight, axis=1)
        np.testing.assert_array_equal(h.phase == state.label, every)


def test_the_1d_and_2d_histories_speak_the_same_states():
    """The names of 1-D and 2-D histories and their events are the schema's, and mean it:
    flight has no force, forward slip f = n, reverse slip f = -n, stick |f| <= n."""
    jumping = vf.Dimensionless(0.5, 2.0, 1.5)
    plane = vf.Dimensionless(0.5, 2.0, 0.5, a_y=0.6)
    for h in (vf.simulate(jumping, v_inertial=0.3, periods=2),
              vf.simulate(plane, v_inertial=0.2, periods=2)):
        assert set(np.unique(h.phase)) <= set(CONTACT_STATE_NAMES)
        names = {e.before for e in h.events} | {e.after for e in h.events}
        assert names <= set(CONTACT_STATE_NAMES) and len(h.events) > 0
        fl = h.phase == "flight"
        assert np.all(np.abs(h.f[fl]) <= 1e-12) and np.all(h.n[fl] <= 1e-12)
        st = h.phase == "stick"
        assert np.any(st) and np.all(np.abs(h.f[st]) <= h.n[st] + 1e-9)
    one_d = vf.simulate(jumping, v_inertial=0.3, periods=2)
    assert "flight" in one_d.phase
    fwd = one_d.phase == "slip+"
    np.testing.assert_allclose(one_d.f[fwd], one_d.n[fwd], atol=1e-9)


def test_the_results_phase_code_names_its_final_state():
    V = (0.05, 0.2, 0.5)
    r = solve_points(0.3, 3.0, 0.8, np.array(V))
    for code, v in zip(r["phase"], V, strict=True):
        one = vf.friction_coefficient(vf.Dimensionless(0.3, 3.0, 0.8), v_inertial=v)
        assert isinstance(one, vf.FrictionResult) and one.final_state is not None
        assert ContactState(int(code)).label == one.final_state.phase


def _fields(cls):
    return {f.name: f for f in dataclasses.fields(cls)}


def test_no_history_field_is_none_for_its_solver():
    base = _fields(vf.History)
    plane, curved = _fields(vf.PlaneHistory), _fields(vf.CurvedHistory)
    rate_state = _fields(vf.RateStateHistory)
    assert set(base) < set(plane) and set(base) < set(curved) and set(base) < set(rate_state)
    assert not (set(plane) - set(base)) & (set(curved) - set(base)) - {"impulse"}
    # the only optional field: a curved tip has no section state
    for fields in (base, plane, curved, rate_state):
        assert [n for n, f in fields.items() if f.default is None] == ["final_state"]
    histories = {
        vf.History: vf.simulate(vf.Dimensionless(0.5, 2.0, 0.5), v_inertial=0.3, periods=0.5),
        vf.PlaneHistory: vf.simulate(vf.Dimensionless(0.5, 2.0, 0.5, a_y=0.3),
                                     v_inertial=0.3, periods=0.5),
        vf.CurvedHistory: _curved(),
        vf.RateStateHistory: vf.simulate(vf.Dimensionless(0.5, 2.0, 0.5, rs_a=0.01),
                                         v_inertial=0.3, periods=0.5),
    }
    for cls, h in histories.items():
        assert type(h) is cls
        for name in _fields(cls):
            if name != "final_state" or cls is not vf.CurvedHistory:
                assert getattr(h, name) is not None, (cls.__name__, name)
    assert histories[vf.CurvedHistory].final_state is None
    # less than a period: the last section is the start
    p = histories[vf.PlaneHistory]
    assert p.final_state is not None and p.plane_state.shape == (6,)
    assert p.plane_state[0] == pytest.approx(p.x[0]) and p.tau[0] == 0.0
    assert p.final_state.x_dot == pytest.approx(p.x_dot[0])
    assert histories[vf.History].final_state.x_dot == pytest.approx(
        histories[vf.History].x_dot[0])


def _imports(path: Path) -> set[str]:
    tree = ast.parse(path.read_text())
    return {("." * n.level) + (n.module or "") for n in ast.walk(tree)
            if isinstance(n, ast.ImportFrom)}


def test_the_history_modules_import_no_circle():
    assert ".history" not in _imports(SOLVER / "mdr_history.py")
    assert not {".history", ".mdr_history"} & _imports(SOLVER / "history_types.py")
    assert ".mdr_history" in _imports(SOLVER / "history.py")


def test_the_mdr_solver_speaks_the_results_names():
    r = mdr_row(0.5, 2.0, 1.5, 0.3, 2.0, 20, 0.1)
    assert "out_of_contact_fraction" not in r
    assert r["open_area_fraction"] > 0.0 and math.isclose(
        r["stick_area_fraction"] + r["slip_area_fraction"] + r["open_area_fraction"], 1.0,
        abs_tol=1e-12)
