"""The warm-up (``vibrofriction warmup``) and the compile notice of a cold start.

The shipped cache (kernels precompiled into the wheel) is tested where a wheel is built:
tests/api/test_wheel.py.
"""

import os
import platform
import subprocess
import sys
from pathlib import Path

import numba
import pytest

import vibrofriction as vf
from vibrofriction._kernels import jit, notice, steady
from vibrofriction.cli import run
from vibrofriction.warmup import PARTS, shipped_is_fresh, warm_up


def _fresh_function():
    """A new function each call: numba compiles it at its first call (no cache)."""
    def add_one(x):
        return x + 1.0

    return numba.njit(cache=False)(add_one)


def test_a_slow_compilation_shows_a_notice_on_stderr_and_a_load_none(monkeypatch, capsys):
    monkeypatch.setenv("VIBROFRICTION_COMPILE_NOTICE", "1")
    monkeypatch.setattr(notice, "AFTER", 0.0)  # every compilation counts as slow
    f = _fresh_function()
    assert f(1.0) == 2.0
    err = capsys.readouterr().err
    assert err.startswith(notice.TEXT) and ": 1 functions, 0 s" in err, err
    assert f(2.0) == 3.0  # compiled already: nothing to say
    assert capsys.readouterr().err == ""


@pytest.mark.parametrize("how", ["environment", "quiet"])
def test_the_notice_is_off_by_the_environment_or_inside_a_warm_up(how, monkeypatch, capsys):
    monkeypatch.setenv("VIBROFRICTION_COMPILE_NOTICE", "0" if how == "environment" else "1")
    monkeypatch.setattr(notice, "AFTER", 0.0)
    f = _fresh_function()
    if how == "quiet":
        with notice.quiet():
            f(1.0)
    else:
        f(1.0)
    assert capsys.readouterr().err == ""


def test_a_second_warm_up_compiles_nothing_and_starts_no_pool():
    warm_up(["flat", "plane"], workers=1, progress=False)
    again = warm_up(["plane", "flat"], workers=2, progress=False)
    assert again.parts == ("flat", "plane") and again.compiled == 0
    assert again.workers == 1  # in the disk cache: loaded here, no pool started
    assert jit.cached(steady.steady_state_many)
    assert not jit.cached(len)  # not a kernel


@pytest.mark.parametrize("parts", [["flats"], []])
def test_unknown_or_no_parts_are_refused_by_name(parts):
    with pytest.raises(ValueError, match="parts must be among flat, plane, curved"):
        warm_up(parts, workers=1, progress=False)


def test_the_command_says_what_it_did(capsys):
    assert run(["warmup", "--part", "flat", "--workers", "1", "--no-progress"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("flat: ") and out.rstrip().endswith(" s"), out


def test_the_command_refuses_an_unknown_part_in_one_line():
    got = subprocess.run([sys.executable, "-m", "vibrofriction", "warmup", "--part", "curve"],
                         capture_output=True, text=True, timeout=120)
    assert got.returncode == 2
    assert got.stderr.strip().count("\n") == 0 and "--part" in got.stderr, got.stderr
    assert ", ".join(PARTS) in got.stderr


def test_the_shipped_cache_is_asked_only_where_its_code_runs(monkeypatch):
    """x86-64-v3 code (AVX2, FMA, ...) on a machine without one of them would crash."""
    jit._runs_shipped.cache_clear()
    monkeypatch.setattr("llvmlite.binding.get_host_cpu_features",
                        lambda: {f: True for f in jit._V3} | {"fma": False})
    try:
        assert not jit._runs_shipped()
        jit._runs_shipped.cache_clear()
        monkeypatch.setattr("llvmlite.binding.get_host_cpu_features",
                            lambda: dict.fromkeys(jit._V3, True))
        assert jit._runs_shipped() == (jit._SHIPPED and platform.machine()
                                       in ("x86_64", "AMD64"))
    finally:
        jit._runs_shipped.cache_clear()


def test_the_kernels_run_as_plain_python_without_the_compiler():
    """``NUMBA_DISABLE_JIT=1`` (coverage, debugging): no dispatcher, so no cache to set."""
    code = ("import vibrofriction as vf; r = vf.friction_coefficient(vf.Dimensionless("
            "alpha=0.5, beta=2.0, amplitude=0.5), vbar=0.3); print(round(r.mu_ratio, 6))")
    got = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300, env={**os.environ, "NUMBA_DISABLE_JIT": "1"})
    assert got.returncode == 0, got.stderr[-2000:]
    assert got.stdout.strip() == "0.597601"  # the README's value, 0.5976005546


def test_the_shipped_cache_is_fresh_only_whole_and_newer_than_every_source(tmp_path):
    """``make warmup`` rebuilds the shipped cache unless it is whole (the stamp
    build_shipped writes last) and newer than the sources the kernels are made from."""
    assert not shipped_is_fresh(tmp_path)  # no stamp: not whole
    stamp = tmp_path / ".complete"
    stamp.write_text("540 files\n")
    assert shipped_is_fresh(tmp_path)  # made now, after every source
    os.utime(stamp, (0.0, 0.0))  # made before the sources were (a source changed since)
    assert not shipped_is_fresh(tmp_path)


def test_the_kernels_import_nothing_of_the_package_but_the_schema():
    """The freshness rule's premise: a change outside ``_kernels`` and ``schema`` cannot
    change compiled code."""
    root = Path(vf.__file__).parent / "_kernels"
    for path in root.glob("*.py"):
        for line in path.read_text().splitlines():
            if line.startswith(("from vibrofriction", "from ..", "import vibrofriction")):
                assert line.startswith("from vibrofriction.schema"), (path.name, line)
