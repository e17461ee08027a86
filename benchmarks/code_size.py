"""Rooms of a size a reader can hold: the long files, long functions and long signatures.

For a source tree (default ``src/vibrofriction``) this counts

* files over 600 lines,
* function bodies over 60 and over 100 lines: from the first statement after the
  docstring to the function's ``end_lineno`` (``ast``), methods and nested functions
  included, each counted on its own (a nested function's lines also count in its host's),
* functions with 15 or more parameters (positional, keyword-only, ``*args``, ``**kwargs``),
* functions whose first parameters are ``(alpha, beta, ...)`` (the model's two
  dimensionless numbers passed loose rather than as one object),

and prints a table of the offenders and the counts.  ``--exclude PATH`` (repeatable, a path
relative to the tree, a file or a folder) counts those files apart, in a second block.

Run:  python benchmarks/code_size.py [TREE] [--exclude _kernels/plane.py ...]
"""

from __future__ import annotations

import argparse
import ast
from dataclasses import dataclass
from pathlib import Path

FILE_LINES = 600
BODY_LONG = 60
BODY_VERY_LONG = 100
MANY_PARAMETERS = 15


@dataclass(frozen=True)
class Function:
    """One function (or method) of the tree: where it is and how big."""

    path: str
    name: str
    line: int
    body: int
    parameters: int
    alpha_beta: bool


def _body_lines(node: ast.FunctionDef | ast.AsyncFunctionDef) -> int:
    """Lines from the first statement after the docstring to the end of the function."""
    body = node.body
    first = body[0]
    if (
        len(body) > 1
        and isinstance(first, ast.Expr)
        and isinstance(first.value, ast.Constant)
        and isinstance(first.value.value, str)
    ):
        first = body[1]
    end = node.end_lineno if node.end_lineno is not None else first.lineno
    return end - first.lineno + 1


def _parameters(node: ast.FunctionDef | ast.AsyncFunctionDef) -> list[str]:
    args = node.args
    names = [a.arg for a in args.posonlyargs + args.args]
    if args.vararg is not None:
        names.append(args.vararg.arg)
    names += [a.arg for a in args.kwonlyargs]
    if args.kwarg is not None:
        names.append(args.kwarg.arg)
    return names


def functions(path: Path, shown: str) -> list[Function]:
    """Every function and method of one file."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            names = _parameters(node)
            if names[:1] in (["self"], ["cls"]):
                names = names[1:]
            found.append(
                Function(
                    path=shown,
                    name=node.name,
                    line=node.lineno,
                    body=_body_lines(node),
                    parameters=len(names),
                    alpha_beta=names[:2] == ["alpha", "beta"],
                )
            )
    return found


def _excluded(relative: Path, excludes: list[Path]) -> bool:
    return any(relative == e or e in relative.parents for e in excludes)


def report(title: str, files: list[tuple[str, Path]]) -> list[str]:
    """The offenders' tables and the counts for one set of files, as Markdown lines."""
    long_files = []
    found: list[Function] = []
    for shown, path in files:
        lines = len(path.read_text(encoding="utf-8").splitlines())
        if lines > FILE_LINES:
            long_files.append((lines, shown))
        found += functions(path, shown)
    long_files.sort(reverse=True)
    long_bodies = sorted((f for f in found if f.body > BODY_LONG), key=lambda f: -f.body)
    many = sorted(
        (f for f in found if f.parameters >= MANY_PARAMETERS), key=lambda f: -f.parameters
    )
    alpha_beta = [f for f in found if f.alpha_beta]
    out = [f"### {title}", "", f"{len(files)} files, {len(found)} functions", ""]
    out += ["| file | lines |", "| --- | ---: |"]
    out += [f"| {shown} | {lines} |" for lines, shown in long_files]
    out += ["", "| function | body lines | parameters |", "| --- | ---: | ---: |"]
    out += [f"| {f.path}:{f.line} {f.name} | {f.body} | {f.parameters} |" for f in long_bodies]
    out += ["", f"functions with {MANY_PARAMETERS} or more parameters:", ""]
    out += [f"* {f.path}:{f.line} {f.name} ({f.parameters})" for f in many] or ["* none"]
    out += ["", "functions whose first parameters are (alpha, beta, ...):", ""]
    out += [f"* {f.path}:{f.line} {f.name}" for f in alpha_beta] or ["* none"]
    out += [
        "",
        "| count | value |",
        "| --- | ---: |",
        f"| files over {FILE_LINES} lines | {len(long_files)} |",
        f"| function bodies over {BODY_LONG} lines | {len(long_bodies)} |",
        f"| function bodies over {BODY_VERY_LONG} lines "
        f"| {sum(f.body > BODY_VERY_LONG for f in found)} |",
        f"| functions with {MANY_PARAMETERS} or more parameters | {len(many)} |",
        f"| functions starting (alpha, beta, ...) | {len(alpha_beta)} |",
        "",
    ]
    return out


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tree", nargs="?", default="src/vibrofriction", type=Path)
    parser.add_argument(
        "--exclude", action="append", default=[], type=Path,
        help="a file or folder relative to the tree, counted apart (repeatable)",
    )
    args = parser.parse_args(argv)
    tree: Path = args.tree
    kept, apart = [], []
    for path in sorted(tree.rglob("*.py")):
        relative = path.relative_to(tree)
        (apart if _excluded(relative, args.exclude) else kept).append((str(relative), path))
    lines = report(f"{tree}" + (" without the excluded files" if apart else ""), kept)
    if apart:
        lines += report("the excluded files: " + ", ".join(map(str, args.exclude)), apart)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
