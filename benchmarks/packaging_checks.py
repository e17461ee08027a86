"""The Scientific Python Development Guide's checks on this repository, as a table.

Runs ``repo-review . --format json`` (``pip install "sp-repo-review[cli]"``) in the
repository and prints the counts and one row per check: passed, failed, skipped (with
the reason: a check that does not apply, or one that needs a failed or skipped one)
or ignored (``[tool.repo-review.ignore]`` in pyproject.toml, with its reason).
docs/packaging.md quotes the output.

    python benchmarks/packaging_checks.py [path]
"""

from __future__ import annotations

import collections
import json
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def checks(path: Path) -> dict[str, dict]:
    exe = shutil.which("repo-review") or str(Path(sys.executable).parent / "repo-review")
    out = subprocess.run([exe, str(path), "--format", "json"], capture_output=True,
                         text=True, check=True)
    return json.loads(out.stdout)["checks"]


def outcome(code: str, check: dict, ignored: dict[str, str]) -> str:
    if code in ignored:
        return "ignored"
    if check["result"] is None:
        return "skipped"
    return "passed" if check["result"] else "FAILED"


def main(path: Path = ROOT) -> None:
    rows = checks(path)
    config = tomllib.loads((path / "pyproject.toml").read_text())
    ignored = config.get("tool", {}).get("repo-review", {}).get("ignore", {})
    result = {code: outcome(code, c, ignored) for code, c in rows.items()}
    counts = collections.Counter(result.values())
    print(", ".join(f"{n} {k}" for k, n in sorted(counts.items())))
    print()
    print("| check | description | result | reason |")
    print("|---|---|---|---|")
    for code, c in rows.items():
        reason = c["skip_reason"].replace("|", "/").replace("\n", " ")
        what = c["description"].replace("|", "/")
        print(f"| {code} | {what} | {result[code]} | {reason} |")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT)
