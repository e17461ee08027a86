"""The user guide speaks to users: no project bookkeeping in it.

No issue numbers ("issue 20", "(#20)") and no commit hashes in the pages of ``docs/``
(the changelog is the place for history), and no absolute local path (a build
machine's ``/work/...``, ``/home/...``, ``/tmp/...``) anywhere in ``docs/``, the
README or the examples. Where a number needs its provenance, the page names the script
and the ``benchmarks/results/`` file it came from.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
# generated at build time (gitignored): not the sources
GENERATED = {"_build", "api", "gallery", "_generated"}
TEXT = {".md", ".rst", ".py", ".css", ".html", ".txt", ".js", ".toml", ".cfg"}

ISSUE = re.compile(r"\b(?:issues?|pull request|PR)\s*#?\d+\b|(?<![\w&/])#\d+\b", re.I)
# 7 to 40 hex digits with at least one digit and one letter a-f: a (short) commit hash
HASH = re.compile(r"(?<![\w.\-+/#])(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}(?![\w\-])")
# a development branch named where a number was measured ("2026-11-26, branch `kern20`"):
# in the prose its name is an emptied code span
BRANCH = re.compile(r"\bbranch\s+``")
# an absolute local path: /work/..., /home/..., /tmp/..., /Users/..., C:\...
ABSOLUTE = re.compile(r"(?<![\w.:/~-])/(?:work|home|tmp|Users|root|mnt|var/folders)/"
                      r"|\b[A-Z]:\\[\w ]")
FENCE = re.compile(r"^\s*(```|~~~)")
INLINE_CODE = re.compile(r"`(?:[^`\n]|\n(?!\s*\n))*`")  # not across a blank line


def _files(*paths: Path) -> list[Path]:
    out = []
    for path in paths:
        if path.is_file():
            out.append(path)
            continue
        for f in sorted(path.rglob("*")):
            if f.is_file() and f.suffix in TEXT and not GENERATED & set(
                    f.relative_to(path).parts[:1]):
                out.append(f)
    return out


def _prose(text: str) -> list[tuple[int, str]]:
    """The lines of a Markdown page outside code (fenced blocks and inline spans, which
    may run over a line break): hex data such as a fingerprint in backticks, or a
    command's argument, is not a commit."""
    kept, fenced = [], False
    for line in text.splitlines():
        if FENCE.match(line):
            fenced = not fenced
            kept.append("")
        else:
            kept.append("" if fenced else line)
    prose = INLINE_CODE.sub(lambda m: "``" + "\n" * m.group(0).count("\n"), "\n".join(kept))
    return list(enumerate(prose.splitlines(), 1))


def find_bookkeeping(text: str) -> list[tuple[int, str]]:
    """(line, match) of each issue number, commit hash or branch in a page's prose."""
    return [(number, m.group(0)) for number, line in _prose(text)
            for pattern in (ISSUE, HASH, BRANCH) for m in pattern.finditer(line)]


def find_absolute_paths(text: str) -> list[tuple[int, str]]:
    return [(number, m.group(0)) for number, line in enumerate(text.splitlines(), 1)
            for m in ABSOLUTE.finditer(line)]


PAGES = [p for p in sorted(DOCS.glob("*.md")) if p.name != "changelog.md"] + [ROOT / "README.md"]


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_no_issue_numbers_or_commits_in_the_guide(page):
    found = find_bookkeeping(page.read_text(encoding="utf-8"))
    assert not found, f"{page.name}: bookkeeping belongs in docs/changelog.md: {found}"


@pytest.mark.parametrize("path", _files(DOCS, ROOT / "README.md", ROOT / "examples"),
                         ids=lambda p: str(p.relative_to(ROOT)))
def test_no_absolute_local_paths(path):
    found = find_absolute_paths(path.read_text(encoding="utf-8"))
    assert not found, f"{path.relative_to(ROOT)}: absolute local paths {found}"


@pytest.mark.parametrize("text", [
    "Issue 20 adds an oscillation", "## Issue 21's figures", "as before (#20).",
    "see issues #7 and", "at commit 7dbaf74, 2026-11-25", "(b903c48, 2026-11-26)",
    "a full hash 3564b13b0c1f2d8e9a7b6c5d4e3f2a1b0c9d8e7f here",
    "numbers of 2026-11-26, branch `kern20`):",
])
def test_the_guard_sees_bookkeeping(text):
    assert find_bookkeeping(text)


@pytest.mark.parametrize("text", [
    "mu = 0.5976005546, error 1.7e-12", "the fingerprint `0632596c9436e78d`",
    "```\nab833f1 in a code block\n```", "# A heading", "colour #3b82f6 is 1e-5",
    "a ratio of 1234567 points", "decade", "defaced",  # no digit: words, not hashes
    "[link](changelog.md#unreleased)", "eq. (12) and 1.5e10",
])
def test_the_guard_passes_ordinary_text(text):
    assert not find_bookkeeping(text)


@pytest.mark.parametrize("text", ["--against /work/main/src", "a /home/user/x.png",
                                  "saved in /tmp/abc/fig.png", r"C:\Users\me"])
def test_the_guard_sees_absolute_paths(text):
    assert find_absolute_paths(text)


@pytest.mark.parametrize("text", ["https://example.org/home/page", "docs/_build/html",
                                  "python -m http.server -d docs/_build/html", "~/work/x"])
def test_the_guard_passes_relative_paths_and_urls(text):
    assert not find_absolute_paths(text)


def test_readme_claims_what_the_solvers_do():
    """The README's summary of the solver claims only what holds, and where: the MDR
    scan's sub-steps are the solver's constant, the claim that no pair of close roots is
    missed is made of the flat punch's root finder (and, with its one exception, of the
    MDR scan, which bounds its functions between samples), Newton's orbit is not verified
    by a further integration, and the parameter sensitivities are not called exact (their
    explicit parameter part is a central difference)."""
    from vibrofriction.solver import mdr

    text = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    assert "verified by integration" not in text
    assert "exact parameter sensitivities" not in text
    close = text.index("cannot miss a pair of close roots")
    assert "flat punch" in text[close - 120:close]
    assert f"at least {mdr.SUBSTEPS} a period" in text
    assert "no further period is integrated" in text
