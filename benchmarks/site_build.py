"""How long the documentation site takes to build from scratch (``make docs``'s command).

Each run removes what a build leaves (docs/_build, the generated docs/api, docs/gallery,
docs/_generated) and builds with warnings as errors, the gallery's examples executed; the
numba cache of the kernels is kept (the first build on a fresh clone compiles it too:
run with ``--cold`` to clear it first). Writes benchmarks/results/site_build.md.

Run:  python benchmarks/site_build.py [--runs 3] [--cold]
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
GENERATED = ("_build", "api", "gallery", "_generated")
BUILD = [sys.executable, "-m", "sphinx", "-b", "html", "-W", "--keep-going", "-q",
         "-d", str(DOCS / "_build" / "doctrees"), str(DOCS), str(DOCS / "_build" / "html")]


def clean(cold: bool) -> None:
    for name in GENERATED:
        shutil.rmtree(DOCS / name, ignore_errors=True)
    if cold:
        for pattern in ("*.nbi", "*.nbc"):
            for f in (ROOT / "src").rglob(pattern):
                f.unlink()


def build() -> float:
    start = time.perf_counter()
    subprocess.run(BUILD, check=True, cwd=ROOT)
    return time.perf_counter() - start


def gallery_times() -> dict[str, float]:
    """Each example's run time as sphinx-gallery recorded it on its page."""
    import re

    out = {}
    for rst in sorted((DOCS / "gallery").glob("*.rst")):
        m = re.search(r"\*\*Total running time of the script:\*\* \(\s*(\d+) minutes\s+"
                      r"([\d.]+) seconds\)", rst.read_text())
        if m:
            out[rst.stem] = 60 * int(m.group(1)) + float(m.group(2))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--cold", action="store_true", help="clear the numba cache first")
    args = ap.parse_args()
    env_src = os.environ.get("PYTHONPATH", "")
    times, examples = [], []
    for _ in range(args.runs):
        clean(args.cold)
        times.append(build())
        examples.append(gallery_times())
        print(f"build {times[-1]:.1f} s", flush=True)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True, cwd=ROOT).stdout.strip()
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True, cwd=ROOT).stdout.strip()
    lines = [
        "# Site build time",
        "",
        f"`python benchmarks/site_build.py --runs {args.runs}{' --cold' if args.cold else ''}`"
        f", {datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC, commit {commit}"
        f"{' (with uncommitted changes)' if dirty else ''}, "
        f"{platform.machine()} with {os.cpu_count()} cores, Python "
        f"{platform.python_version()}{', PYTHONPATH=' + env_src if env_src else ''}; "
        f"numba cache {'cleared before each build' if args.cold else 'kept'}. The machine "
        "may be shared: the median is quoted.",
        "",
        "| run | build from scratch (s) |",
        "| --- | --- |",
        *[f"| {i + 1} | {t:.1f} |" for i, t in enumerate(times)],
        f"| **median** | **{statistics.median(times):.1f}** |",
        "",
        "Each example's run time within the build (s; sphinx-gallery's record, median over "
        "the runs):",
        "",
        "| example | run time (s) |",
        "| --- | --- |",
    ]
    for name in examples[0]:
        lines.append(f"| {name} | {statistics.median(e[name] for e in examples):.1f} |")
    out = ROOT / "benchmarks" / "results" / "site_build.md"
    out.write_text("\n".join(lines) + "\n")
    print(out.read_text())


if __name__ == "__main__":
    main()
