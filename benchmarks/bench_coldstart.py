"""A new user's cold start: the first call after installing the wheel, and ``make demo``.

1. **The first call.** The wheel is built as ``make dist`` builds it (the kernels
   precompiled into ``_kernels/_shipped``, then ``python -m build --wheel``) from a copy of
   this tree and installed into a fresh venv (``--no-deps``; the venv sees this
   environment's packages through a ``.pth`` line). A fresh ``HOME`` each run (an empty
   user-wide numba cache), then the first call, timed from the process start::

       import vibrofriction as vf
       vf.friction_coefficient(vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5), vbar=0.3)

   side by side, interleaved: the shipped kernels, and without them
   (``VIBROFRICTION_SHIPPED_CACHE=0``: every kernel compiles, as before they were shipped).
2. **make demo** (``--demo``): ``git clone`` of this repository's ``HEAD`` into a temporary
   folder and ``make demo`` there, timed (venv, install, compile, every figure).

Writes ``benchmarks/results/coldstart.md``::

    python benchmarks/bench_coldstart.py [--repeat 3] [--demo]
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import statistics
import subprocess
import sys
import sysconfig
import tempfile
import time
from datetime import UTC, datetime
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FIRST_CALL = ("import vibrofriction as vf; vf.friction_coefficient("
              "vf.Dimensionless(alpha=0.5, beta=2.0, amplitude=0.5), vbar=0.3)")


def _run(args: list[str], **kwargs) -> subprocess.CompletedProcess:
    done = subprocess.run(args, capture_output=True, text=True, **kwargs)
    if done.returncode:
        raise RuntimeError(f"{' '.join(args)[:200]} failed:\n{done.stderr[-3000:]}")
    return done


def build_wheel(tmp: Path) -> Path:
    """``make dist``'s wheel, from a copy of the tracked (and new, not ignored) files."""
    tree = tmp / "tree"
    names = _run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                 cwd=ROOT).stdout.split("\0")
    for name in filter(None, names):
        if (ROOT / name).is_file():
            (tree / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(ROOT / name, tree / name)
    env = {k: v for k, v in os.environ.items() if not k.startswith("NUMBA_")}
    _run([sys.executable, "-c", "from vibrofriction.warmup import build_shipped; "
          "build_shipped()"], env={**env, "PYTHONPATH": str(tree / "src")})
    _run([sys.executable, "-m", "build", "--wheel", "--outdir", str(tmp / "dist"), str(tree)])
    (wheel,) = (tmp / "dist").glob("*.whl")
    return wheel


def fresh_venv(tmp: Path, wheel: Path) -> Path:
    """A new venv with the wheel, seeing this environment's packages after its own."""
    venv = tmp / "venv"
    _run([sys.executable, "-m", "venv", "--without-pip", str(venv)])
    python = venv / "bin" / "python"
    clean = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
    _run([sys.executable, "-m", "pip", "--python", str(python), "install", "--no-deps",
          "--quiet", str(wheel)], env=clean)  # (a PYTHONPATH holding the package: no-op)
    site = _run([str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"]
                ).stdout.strip()
    (Path(site) / "zz_environment.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    return python


def first_call(python: Path, home: Path, **extra: str) -> float:
    """Wall seconds of a fresh process running :data:`FIRST_CALL`: a fresh ``home`` (the
    user-wide numba cache) and no numba cache beside the installed package (where numba
    writes when it can)."""
    for path in python.parent.parent.glob("lib/python*/site-packages/vibrofriction/**/*.nb[ic]"):
        if "_shipped" not in path.parts:
            path.unlink()
    shutil.rmtree(home, ignore_errors=True)
    home.mkdir()
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("NUMBA_", "VIBROFRICTION_", "PYTHON", "XDG_"))}
    env.update(HOME=str(home), **extra)
    t0 = time.perf_counter()
    _run([str(python), "-c", FIRST_CALL], env=env, cwd=home)
    return time.perf_counter() - t0


def make_demo(tmp: Path) -> float:
    clone = tmp / "clone"
    _run(["git", "clone", "--quiet", str(ROOT), str(clone)])
    t0 = time.perf_counter()
    _run(["make", "demo"], cwd=clone)
    return time.perf_counter() - t0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--demo", action="store_true", help="also time make demo in a clone")
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as name:
        tmp = Path(name)
        t0 = time.perf_counter()
        wheel = build_wheel(tmp)
        built = time.perf_counter() - t0
        python = fresh_venv(tmp, wheel)
        shipped, compiled = [], []
        for _ in range(args.repeat):
            shipped.append(first_call(python, tmp / "home"))
            compiled.append(first_call(python, tmp / "home", VIBROFRICTION_SHIPPED_CACHE="0"))
            print(f"shipped {shipped[-1]:.1f} s, compiled {compiled[-1]:.1f} s", flush=True)
        demo = make_demo(tmp) if args.demo else None
    ms, mc = statistics.median(shipped), statistics.median(compiled)
    rows.append(f"| the first call, kernels shipped in the wheel | {ms:.1f} | "
                f"{', '.join(f'{t:.1f}' for t in shipped)} |")
    rows.append(f"| the first call, every kernel compiled (`VIBROFRICTION_SHIPPED_CACHE=0`) | "
                f"{mc:.1f} | {', '.join(f'{t:.1f}' for t in compiled)} |")
    lines = [
        "# Cold start",
        "",
        f"Command: `python benchmarks/bench_coldstart.py --repeat {args.repeat}"
        f"{' --demo' if args.demo else ''}`  ",
        f"{datetime.now(UTC):%Y-%m-%d %H:%M} UTC; {platform.machine()}, "
        f"{os.cpu_count()} cores, Python {platform.python_version()}. The two first calls "
        "ran interleaved, each in a fresh process with an empty user cache; wall time "
        "from the process start (the import included).",
        "",
        "| what | median (s) | runs (s) |",
        "|---|---|---|",
        *rows,
        "",
        f"Ratio: {mc / ms:.1f}x. Building the wheel (the kernels compiled for the shipped "
        f"cache, on every core, and `python -m build --wheel`) took {built:.0f} s.",
    ]
    if demo is not None:
        lines += ["", f"`make demo` in a fresh clone (venv, install, compile, every figure): "
                  f"{demo:.0f} s ({int(demo // 60)} min {round(demo % 60)} s)."]
    out = ROOT / "benchmarks" / "results" / "coldstart.md"
    out.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
