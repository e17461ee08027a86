"""Designing the oscillation (vibrofriction.designing): the optimum is the global one
within the actuator's limits, the limits hold, the sensitivity is reported."""

import math

import numpy as np
import pytest

import vibrofriction as vf
from vibrofriction.fitting import predict_cof

PIN = vf.Physical.from_bench(natural_frequency_hz=800.0, mass=0.01, quality_factor=50.0,
                             normal_load=20.0, k_zc=2e7, k_xc=1.5e7, drive_frequency_hz=1000.0,
                             du_z=0.5e-6, mu0=0.3)
OMEGA = (2 * math.pi * 200, 2 * math.pi * 5000)
DU_Z = (0.1e-6, 0.9e-6)


def test_the_optimum_is_global_within_the_limits_and_respects_them():
    res = vf.design(PIN, v0=0.01, omega=OMEGA, du_z=DU_Z, max_velocity_amplitude=0.01)
    s = res.system
    assert OMEGA[0] <= s.omega <= OMEGA[1] and DU_Z[0] <= s.du_z <= DU_Z[1]
    assert s.omega * s.du_z <= 0.01 * (1 + 1e-9)
    assert res.cof == pytest.approx(float(predict_cof(PIN, [0.01], [s.du_z], [s.omega])[0]))
    # an independent, finer brute-force grid finds nothing lower
    w = np.geomspace(*OMEGA, 97)
    d = np.geomspace(*DU_Z, 41)
    W, D = np.meshgrid(w, d, indexing="ij")
    ok = W * D <= 0.01
    cof = predict_cof(PIN, np.full(ok.sum(), 0.01), D[ok], W[ok])
    assert res.cof <= np.nanmin(cof) + 1e-9
    m = res.map
    assert m.cof.dims == ("omega", "du_z") and m.attrs["optimum_cof"] == res.cof
    assert not np.any(m.feasible.values & (m.omega.values[:, None] * m.du_z.values > 0.0100001))
    assert res.cof < PIN.mu0
    table = res.sensitivity.set_index("change")["cof"]
    assert table["optimum"] == pytest.approx(res.cof)
    assert {"frequency -5 %", "frequency +1 %", "mass +10 %", "k_xc -10 %", "mu0 +10 %"} \
        <= set(table.index)
    assert "optimum" in res.report()
    assert res.plot().axes


@pytest.mark.parametrize("kwargs, message", [
    (dict(omega=(10.0,)), "omega must be a pair"),
    (dict(du_z=(1e-6, 1e-7)), "du_z: low"),
    (dict(max_velocity_amplitude=1e-9), "no oscillation in range"),
    (dict(v0=-1.0), "v0"),
])
def test_design_errors(kwargs, message):
    args = dict(v0=0.01, omega=OMEGA, du_z=DU_Z)
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        vf.design(PIN, **args)
