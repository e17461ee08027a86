"""Write the API reference's module pages from each public module's ``__all__``.

Called by conf.py at every build into ``docs/api/`` (gitignored), so a name added to an
``__all__`` appears in the reference without editing a page. A name exported by the
top level (``vibrofriction.X``) is documented once, there; a subpackage's table lists
it and links to that page.
"""

from __future__ import annotations

import importlib
import re
from pathlib import Path

TOP = "vibrofriction"
# the public subpackages and modules, top of the layers first (README "Layout")
MODULES = [
    ("vibrofriction.params", "Systems: dimensionless and physical, the cases I-IV"),
    ("vibrofriction.solver", "The exact event-driven solver and its results"),
    ("vibrofriction.theory", "Every closed form of the paper and beyond"),
    ("vibrofriction.contact", "Contact profiles: flat punch, sphere, cone, power law (MDR)"),
    ("vibrofriction.bench", "The bench: measurements, fit, design"),
    ("vibrofriction.sweep", "Parameter atlases on local cores or Dask, stored in zarr"),
    ("vibrofriction.figures", "Every figure of the reproduction, and the plotting helpers"),
    ("vibrofriction.report", "The reproduction report"),
    ("vibrofriction.explorer", "The browser explorer (Panel)"),
    ("vibrofriction.schema", "The one vocabulary: parameters, result fields, statuses, contact "
     "states"),
    ("vibrofriction.validation", "The one validator of model parameters"),
    ("vibrofriction.parallel", "The one pool of worker processes"),
    ("vibrofriction.warmup", "Compiling the solver's kernels ahead: the warm-up"),
]
SKIP_TOP = {"__version__", "sweep"}  # a string, and the module documented below


def public_names(module: str) -> list[str]:
    """The module's ``__all__``, in its order."""
    return list(importlib.import_module(module).__all__)


def _underline(title: str, char: str = "=") -> str:
    return f"{title}\n{char * len(title)}\n"


def _table(names: list[str], toctree: bool) -> str:
    if not names:
        return ""
    head = ".. autosummary::\n   :nosignatures:\n"
    if toctree:
        head += "   :toctree: generated\n"
    return head + "\n" + "".join(f"   {n}\n" for n in names) + "\n"


def top_page() -> str:
    names = [n for n in public_names(TOP) if n not in SKIP_TOP]
    return (_underline(f"``{TOP}``")
            + f"\n.. automodule:: {TOP}\n   :no-members:\n\n.. currentmodule:: {TOP}\n\n"
            + "The names a user imports: ``import vibrofriction as vf``. ``vf.sweep`` is "
              "the module :mod:`vibrofriction.sweep` (callable: ``vf.sweep(...)``); "
              "``vf.__version__`` the installed version.\n\n"
            + _table(names, toctree=True))


def _defines(module: str, name: str) -> bool:
    """Whether ``name`` is assigned, defined or declared in ``module``'s own source."""
    mod = importlib.import_module(module)
    path = Path(mod.__file__)
    files = sorted(path.parent.glob("*.py")) if path.name == "__init__.py" else [path]
    pattern = re.compile(rf"^(?:{re.escape(name)}\s*[:=]|(?:def|class) {re.escape(name)}\b)",
                         re.M)
    return any(pattern.search(f.read_text()) for f in files)


def home(name: str, module: str) -> str:
    """The one module whose page documents ``module.name``: the top level if it exports
    the same object, else the public module that defines it."""
    obj = getattr(importlib.import_module(module), name)
    if name in public_names(TOP) and getattr(importlib.import_module(TOP), name) is obj:
        return TOP
    for other, _ in MODULES:
        if (other != module and name in public_names(other)
                and getattr(importlib.import_module(other), name) is obj
                and _defines(other, name) and not _defines(module, name)):
            return other
    return module


def module_page(module: str, summary: str) -> str:
    names = public_names(module)
    own = [n for n in names if home(n, module) == module]
    shared = [n for n in names if home(n, module) != module]
    text = (_underline(f"``{module}``")
            + f"\n{summary}.\n\n.. automodule:: {module}\n   :no-members:\n\n"
            + f".. currentmodule:: {module}\n\n" + _table(own, toctree=True))
    if shared:
        refs = ", ".join(f":obj:`{home(n, module)}.{n}`" for n in shared)
        text += f"Also exported here, documented where they are defined: {refs}.\n"
    return text


def index_page() -> str:
    rows = "".join(f"   {m}\n" for m, _ in MODULES)
    return (_underline("API reference")
            + "\nGenerated from the docstrings of every public name: the top level, then "
              "each public subpackage's ``__all__`` (private modules, such as the numba "
              "kernels ``vibrofriction._kernels``, are not part of the API).\n\n"
            + ".. toctree::\n   :maxdepth: 1\n\n   vibrofriction\n" + rows)


def write(out: Path) -> None:
    """Write ``out/index.rst`` and one page per module (only files whose text changed)."""
    out.mkdir(parents=True, exist_ok=True)
    pages = {"index": index_page(), TOP: top_page()}
    pages.update({m: module_page(m, s) for m, s in MODULES})
    for name, text in pages.items():
        path = out / f"{name}.rst"
        if not path.exists() or path.read_text() != text:
            path.write_text(text)


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def parameter_table() -> str:
    """Every model parameter of the schema as a Markdown table."""
    from vibrofriction.schema import PARAMETERS

    rows = ["| name | model | unit | what it is | equation | range | default |",
            "| --- | --- | --- | --- | --- | --- | --- |"]
    for p in PARAMETERS:
        default = ("required" if p.default is None and not p.twin
                   else f"`{p.twin}`" if p.twin else f"`{p.default!r}`")
        rows.append(f"| `{p.name}` | {', '.join(p.models)} | `{p.unit}` | "
                    f"{_cell(p.long_name)} | {_cell(p.equation)} | "
                    f"{_cell(p.range.text())} | {default} |")
    return "\n".join(rows) + "\n"


def write_parameter_table(out: Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    path, text = out / "parameter_table.md", parameter_table()
    if not path.exists() or path.read_text() != text:
        path.write_text(text)


def write_capability_table(out: Path) -> None:
    """``_generated/methods.md``: what each solver covers, from the methods' declarations
    (docs/solver.md includes it)."""
    from vibrofriction.solver.methods import capability_table

    out.mkdir(parents=True, exist_ok=True)
    path, text = out / "methods.md", capability_table()
    if not path.exists() or path.read_text() != text:
        path.write_text(text)
