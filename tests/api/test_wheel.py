"""The wheel installs in a fresh virtual environment and works from a read-only install.

The wheel is built as ``make dist`` builds it, from a copy of this tree's tracked files:
the kernels precompiled into ``_kernels/_shipped`` (:func:`vibrofriction.warmup.build_shipped`;
where ``make warmup`` made them for this tree and no source changed since, a copy of
them), then ``python -m build`` (its build backend comes from PyPI). It is installed with
``--no-deps --no-index`` into a new venv that sees this environment's packages through a
``.pth`` line (nothing else is downloaded), and the installed package is made read-only.
There, the console script, ``reproduce --only`` and an example run; the first calls of
every solver compile nothing (the shipped kernels load), and without the shipped cache
numba caches a kernel compiled there in the user-wide cache (``$HOME/.cache/numba``)
instead of the package folder (one small kernel: every kernel is cached by the same class
from the same folder): a second run loads it from there and compiles nothing.

As root, ``chmod a-w`` stops no write: the commands then run without the capabilities
that bypass file permissions (``setpriv``), so that they meet the read-only folder as a
user would.
"""

from __future__ import annotations

import dataclasses
import json
import math
import os
import shutil
import stat
import subprocess
import sys
import sysconfig
import tarfile
import zipfile
from collections.abc import Iterator
from pathlib import Path

import pytest

from vibrofriction._kernels.jit import SHIPPED as SHIPPED_HERE
from vibrofriction.warmup import shipped_is_fresh

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("vibrofriction", "vibrofriction_reference")


def _run(args, **kwargs):
    return subprocess.run(args, capture_output=True, text=True, **kwargs)


def _tracked_copy(dest: Path) -> Path:
    """The files git tracks (or, outside a checkout, the tree without caches) in ``dest``."""
    listed = _run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                  cwd=ROOT, timeout=60)
    if listed.returncode == 0:
        for name in listed.stdout.split("\0"):
            if name and (ROOT / name).is_file():
                (dest / name).parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(ROOT / name, dest / name)
    else:
        shutil.copytree(ROOT, dest, dirs_exist_ok=True, ignore=shutil.ignore_patterns(
            ".venv", ".git", "__pycache__", "_shipped", "_build", "*.egg-info", "dist"))
    return dest


@pytest.fixture(scope="module")
def dist(tmp_path_factory) -> Path:
    """``make dist``: the kernels precompiled, the sdist, and the wheel."""
    tree = _tracked_copy(tmp_path_factory.mktemp("tree"))
    if shipped_is_fresh():  # made by build_shipped for this tree (make warmup): copied
        shutil.copytree(SHIPPED_HERE, tree / SHIPPED_HERE.relative_to(ROOT))
        assert len(list((tree / SHIPPED_HERE.relative_to(ROOT)).glob("*.nb[ic]"))) > 100
    else:
        env = {k: v for k, v in os.environ.items() if not k.startswith("NUMBA_")}
        shipped = _run([sys.executable, "-c", "from vibrofriction.warmup import build_shipped; "
                        "print(build_shipped())"], timeout=900,
                       env={**env, "PYTHONPATH": str(tree / "src")})
        assert shipped.returncode == 0 and int(shipped.stdout) > 100, shipped.stderr[-2000:]
    out = tmp_path_factory.mktemp("dist")
    for kind in ("--sdist", "--wheel"):  # the wheel from the tree: the sdist is source only
        built = _run([sys.executable, "-m", "build", kind, "--outdir", str(out), str(tree)],
                     timeout=600)
        assert built.returncode == 0, built.stdout[-2000:] + built.stderr[-2000:]
    return out


@pytest.fixture(scope="module")
def wheel(dist) -> Path:
    (path,) = dist.glob("vibrofriction-*.whl")
    return path


class Install:
    """A venv with the wheel installed read-only, and how to run commands in it."""

    def __init__(self, root: Path, wheel: Path) -> None:
        self.root = root
        self.venv = root / "venv"
        self.home = root / "home"
        self.home.mkdir()
        made = _run([sys.executable, "-m", "venv", "--without-pip", str(self.venv)],
                    timeout=300)
        assert made.returncode == 0, made.stderr
        self.python = self.venv / "bin" / "python"
        purelib = _run([str(self.python), "-c",
                        "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                       timeout=60).stdout.strip()
        self.site = Path(purelib)
        inst = _run([sys.executable, "-m", "pip", "--python", str(self.python), "install",
                     "--no-deps", "--no-index", "--quiet", str(wheel)], timeout=600,
                    env=self.env())
        assert inst.returncode == 0, inst.stderr
        # then this environment's packages, after the venv's own (a plain path line: no
        # .pth file of this environment, e.g. an editable install of this project, runs)
        (self.site / "zz_test_environment.pth").write_text(
            sysconfig.get_paths()["purelib"] + "\n")
        for name in PACKAGES:
            _read_only(self.site / name)
        self.prefix: list[str] = []
        if os.geteuid() == 0:
            if shutil.which("setpriv") is None:
                pytest.skip("running as root without setpriv: a read-only folder stays "
                            "writable, so the read-only install cannot be tested")
            self.prefix = ["setpriv", "--bounding-set", "-dac_override,-dac_read_search",
                           "--"]

    def env(self, **extra: str) -> dict[str, str]:
        env = {k: v for k, v in os.environ.items()
               if not k.startswith(("NUMBA_", "VIBROFRICTION_", "PYTHON", "XDG_"))}
        env.update(HOME=str(self.home), MPLBACKEND="Agg", **extra)
        return env

    def run(self, *args: str, cwd: Path | None = None, **env: str):
        return _run([*self.prefix, *args], cwd=cwd or self.home, env=self.env(**env),
                    timeout=900)

    def files(self) -> dict[str, float]:
        """Every file of the installed packages with its modification time."""
        return {p.relative_to(self.site).as_posix(): p.stat().st_mtime
                for name in PACKAGES for p in (self.site / name).rglob("*")}


def _read_only(folder: Path) -> None:
    for p in [folder, *folder.rglob("*")]:
        p.chmod(stat.S_IMODE(p.stat().st_mode) & ~(stat.S_IWUSR | stat.S_IWGRP | stat.S_IWOTH))


@pytest.fixture(scope="module")
def install(tmp_path_factory, wheel) -> Iterator[Install]:
    root = tmp_path_factory.mktemp("installed")
    got = Install(root, wheel)
    yield got
    for p in [*got.site.rglob("*")]:  # let pytest remove its temporary folder
        if p.is_dir():
            p.chmod(p.stat().st_mode | stat.S_IWUSR)


SHIPPED = "vibrofriction/_kernels/_shipped/"


def test_the_wheel_carries_the_typing_marker_the_license_and_the_shipped_kernels(wheel):
    names = zipfile.ZipFile(wheel).namelist()
    assert "vibrofriction/py.typed" in names and "vibrofriction_reference/py.typed" in names
    assert any(n.endswith(".dist-info/licenses/LICENSE") for n in names)
    cached = [n for n in names if n.endswith((".nbi", ".nbc", ".pyc"))]
    assert cached and all(n.startswith(SHIPPED) and not n.endswith(".pyc") for n in cached)
    assert any(n.startswith(SHIPPED + "mdr.") for n in cached)  # the curved tip's too
    assert not [n for n in names if n.startswith(("tests/", "docs/", "examples/"))]


def test_the_sdist_carries_what_the_tests_and_the_docs_need(dist):
    (path,) = dist.glob("vibrofriction-*.tar.gz")
    with tarfile.open(path) as tar:
        names = {n.split("/", 1)[1] for n in tar.getnames() if "/" in n}
    tracked = _run(["git", "ls-files", "tests", "docs", "examples", "benchmarks", "src"],
                   cwd=ROOT, timeout=60)
    if tracked.returncode != 0:
        pytest.skip("not a git checkout: no list of the tracked files to compare with")
    wanted = set(tracked.stdout.split()) | {"LICENSE", "CITATION.cff", "README.md",
                                            "pyproject.toml", "Makefile"}
    assert not sorted(wanted - names)
    assert not [n for n in names if n.endswith((".nbi", ".nbc", ".pyc"))]


def test_the_console_script_runs_from_the_read_only_install(install):
    where = install.run(str(install.python), "-c",
                        "import vibrofriction; print(vibrofriction.__file__)")
    assert where.returncode == 0, where.stderr
    assert Path(where.stdout.strip()).is_relative_to(install.site)
    version = install.run(str(install.venv / "bin" / "vibrofriction"), "--version")
    assert version.returncode == 0 and version.stdout.startswith("vibrofriction "), version


_FIRST_CALLS = """
import dataclasses
import json
from numba.core import event
import vibrofriction as vf

compiled = []
class Count(event.Listener):
    def on_start(self, ev):
        pass
    def on_end(self, ev):
        compiled.append(ev.data["dispatcher"].py_func.__qualname__)
event.register("numba:compile", Count())
system = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)
values = [vf.friction_coefficient(system, v_inertial=0.3).mu_ratio]
for other in (dict(profile_exponent=2.0), dict(a_y=0.5), dict(zeta=0.05, a_x=0.3)):
    values.append(vf.friction_coefficient(dataclasses.replace(system, **other),
                                          v_inertial=0.3).mu_ratio)
vf.simulate(system, v_inertial=0.3, periods=1)
print(json.dumps({"compiled": compiled, "values": values}))
"""


def test_the_first_calls_of_every_solver_load_the_shipped_kernels_and_compile_nothing(install):
    from vibrofriction._kernels.jit import _runs_shipped

    if not _runs_shipped():
        pytest.skip("this machine cannot run the shipped kernels' code (x86-64-v3)")
    before = install.files()
    got = install.run(str(install.python), "-c", _FIRST_CALLS)
    assert got.returncode == 0, got.stderr[-3000:]
    first = json.loads(got.stdout.splitlines()[-1])
    assert first["compiled"] == [], first["compiled"][:10]
    # the same numbers as this environment's own compiled kernels
    import vibrofriction as vf

    system = vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5)
    here = [vf.friction_coefficient(dataclasses.replace(system, **o), v_inertial=0.3).mu_ratio
            for o in ({}, dict(profile_exponent=2.0), dict(a_y=0.5), dict(zeta=0.05, a_x=0.3))]
    assert first["values"] == pytest.approx(here, rel=1e-12, abs=1e-14)
    assert install.files() == before  # nothing written into the installed package


#: One small kernel, compiled from the read-only install: the theory's lift-off angle (3
#: functions, a second of compiling; the solver's ``mu`` took a minute and more). Every kernel is
#: cached by the same class (``_kernels.jit._Cache``) from the same folder, so where this one
#: lands, they all do. Printed: the mean normal force at a = 2 (a jumping body), whose exact
#: value is ``(theta + a sin theta)/pi`` with ``theta = 2 pi/3``
_ONE_KERNEL = """
import json
import vibrofriction.theory as theory
print(json.dumps(float(theory.mean_normal_force(2.0))))
"""


def test_numba_caches_in_the_user_cache_from_the_read_only_install(install):
    before = install.files()
    logs, values = [], []
    for _ in range(2):  # without the shipped kernels: compiled for this machine, cached
        out = install.run(str(install.python), "-c", _ONE_KERNEL, NUMBA_DEBUG_CACHE="1",
                          VIBROFRICTION_SHIPPED_CACHE="0")
        assert out.returncode == 0, out.stderr[-3000:]
        lines = out.stdout.splitlines()
        logs.append([line for line in lines if line.startswith("[cache]")])
        values.append([json.loads(line) for line in lines if not line.startswith("[cache]")])
    theta = 2.0 * math.pi / 3.0
    assert values[0] == values[1] == [pytest.approx((theta + 2.0 * math.sin(theta)) / math.pi,
                                                    rel=1e-14)]
    user_cache = str(install.home / ".cache" / "numba")
    first, second = logs
    saved = [line for line in first if "data saved to" in line]
    assert saved and all(user_cache in line for line in saved), first[:5]
    assert not [line for line in second if "saved to" in line], second[:5]
    assert [line for line in second if "data loaded from" in line and user_cache in line]
    assert install.files() == before  # nothing written into the installed package


def test_reproduce_one_figure_and_run_an_example_from_the_read_only_install(install):
    out = install.home / "reproduction"
    got = install.run(str(install.venv / "bin" / "vibrofriction"), "reproduce", "--quick",
                      "--only", "fig04", "--workers", "1", "--no-progress", "--out", str(out))
    assert got.returncode == 0, got.stderr[-3000:]
    assert got.stdout.startswith("1 figures"), got.stdout
    assert (out / "fig04_limits.png").stat().st_size > 20_000
    assert (out / "report.md").is_file()
    example = install.home / "example"
    example.mkdir()
    shutil.copy(ROOT / "examples" / "pin_si_units.py", example)
    ran = install.run(str(install.python), "pin_si_units.py", str(example), cwd=example)
    assert ran.returncode == 0, ran.stderr[-3000:]
    assert (example / "pin_si_units.png").stat().st_size > 20_000
