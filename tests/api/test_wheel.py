"""The wheel installs in a fresh virtual environment and works from a read-only install.

The wheel is built from this tree (``python -m build``: its build backend comes from PyPI),
installed with ``--no-deps --no-index`` into a new venv that sees this environment's
packages through a ``.pth`` line (nothing else is downloaded), and the installed package
is made read-only. There, the console script, ``reproduce --only`` and an example run, and
numba caches the kernels in the user-wide cache (``$HOME/.cache/numba``) instead of the
package folder: a second run loads them from there and compiles nothing.

As root, ``chmod a-w`` stops no write: the commands then run without the capabilities
that bypass file permissions (``setpriv``), so that they meet the read-only folder as a
user would.
"""

from __future__ import annotations

import json
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

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("vibrofriction", "vibrofriction_reference")


def _run(args, **kwargs):
    return subprocess.run(args, capture_output=True, text=True, **kwargs)


@pytest.fixture(scope="module")
def dist(tmp_path_factory) -> Path:
    """``python -m build``: the sdist, and the wheel built from the sdist."""
    out = tmp_path_factory.mktemp("dist")
    built = _run([sys.executable, "-m", "build", "--outdir", str(out), str(ROOT)],
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


def test_the_wheel_carries_the_typing_marker_and_the_license_and_no_caches(wheel):
    names = zipfile.ZipFile(wheel).namelist()
    assert "vibrofriction/py.typed" in names and "vibrofriction_reference/py.typed" in names
    assert any(n.endswith(".dist-info/licenses/LICENSE") for n in names)
    assert not [n for n in names if n.endswith((".nbi", ".nbc", ".pyc"))]
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


def test_numba_caches_in_the_user_cache_from_the_read_only_install(install):
    before = install.files()
    mu = [str(install.venv / "bin" / "vibrofriction"), "mu", "--alpha", "1", "--beta", "inf",
          "--amplitude", "0.5", "--v-inertial", "3", "--json"]
    logs, values = [], []
    for _ in range(2):
        out = install.run(*mu, NUMBA_DEBUG_CACHE="1")
        assert out.returncode == 0, out.stderr[-3000:]
        lines = out.stdout.splitlines()
        logs.append([line for line in lines if line.startswith("[cache]")])
        values.append([json.loads(line) for line in lines if line.startswith("{")])
    # case IV's energy-balance plateau at a = 0.5 (theory.resonant_plateau_exact: 0.7427)
    assert values[0] == values[1] and values[0][0]["mu_ratio"] == pytest.approx(0.7427,
                                                                                 abs=1e-3)
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
