"""Write the small intersphinx inventories of ``docs/_inventories/`` (run by hand).

The site is built offline, so intersphinx cannot download ``objects.inv`` from numpy,
scipy, xarray, pandas, matplotlib, Panel or Python. Instead this script writes, for each, an
inventory in Sphinx's version-2 format listing only the objects these docs name, each
with its real address on the project's site (relative to the base address of
``intersphinx_mapping`` in ``conf.py``). When a docstring names a new outside object
(the nitpicky build ``sphinx -n`` lists it as "reference target not found"), add it
below and run ``python docs/make_inventories.py``; the files are committed.
"""

from __future__ import annotations

import zlib
from pathlib import Path

OUT = Path(__file__).resolve().parent / "_inventories"

# project: (title, version, [(name, domain:role, path on the site), ...]);
# each "$" of a path stands for the name
OBJECTS: dict[str, tuple[str, str, list[tuple[str, str, str]]]] = {
    "python": ("Python", "3", [
        ("bool", "py:class", "library/functions.html#bool"),
        ("callable", "py:function", "library/functions.html#callable"),
        ("mapping", "std:term", "glossary.html#term-mapping"),
        ("sequence", "std:term", "glossary.html#term-sequence"),
        ("iterable", "std:term", "glossary.html#term-iterable"),
        ("int", "py:class", "library/functions.html#int"),
        ("float", "py:class", "library/functions.html#float"),
        ("complex", "py:class", "library/functions.html#complex"),
        ("str", "py:class", "library/stdtypes.html#str"),
        ("bytes", "py:class", "library/stdtypes.html#bytes"),
        ("list", "py:class", "library/stdtypes.html#list"),
        ("tuple", "py:class", "library/stdtypes.html#tuple"),
        ("dict", "py:class", "library/stdtypes.html#dict"),
        ("set", "py:class", "library/stdtypes.html#set"),
        ("frozenset", "py:class", "library/stdtypes.html#frozenset"),
        ("object", "py:class", "library/functions.html#object"),
        ("type", "py:class", "library/functions.html#type"),
        ("slice", "py:class", "library/functions.html#slice"),
        ("range", "py:class", "library/stdtypes.html#range"),
        ("None", "py:data", "library/constants.html#None"),
        ("True", "py:data", "library/constants.html#True"),
        ("False", "py:data", "library/constants.html#False"),
        ("ValueError", "py:exception", "library/exceptions.html#ValueError"),
        ("TypeError", "py:exception", "library/exceptions.html#TypeError"),
        ("KeyError", "py:exception", "library/exceptions.html#KeyError"),
        ("RuntimeError", "py:exception", "library/exceptions.html#RuntimeError"),
        ("FileNotFoundError", "py:exception", "library/exceptions.html#FileNotFoundError"),
        ("FileExistsError", "py:exception", "library/exceptions.html#FileExistsError"),
        ("pathlib.Path", "py:class", "library/pathlib.html#pathlib.Path"),
        ("os.PathLike", "py:class", "library/os.html#os.PathLike"),
        ("collections.abc.Callable", "py:class", "library/collections.abc.html#$"),
        ("collections.abc.Iterable", "py:class", "library/collections.abc.html#$"),
        ("collections.abc.Iterator", "py:class", "library/collections.abc.html#$"),
        ("collections.abc.Sequence", "py:class", "library/collections.abc.html#$"),
        ("collections.abc.Mapping", "py:class", "library/collections.abc.html#$"),
        ("typing.Any", "py:data", "library/typing.html#$"),
        ("typing.NamedTuple", "py:class", "library/typing.html#$"),
        ("enum.IntEnum", "py:class", "library/enum.html#$"),
        ("enum.Enum", "py:class", "library/enum.html#$"),
        ("concurrent.futures.Executor", "py:class", "library/concurrent.futures.html#$"),
        ("concurrent.futures.ProcessPoolExecutor", "py:class",
         "library/concurrent.futures.html#$"),
        ("multiprocessing", "py:module", "library/multiprocessing.html#module-$"),
        ("doctest", "py:module", "library/doctest.html#module-$"),
        ("hashlib", "py:module", "library/hashlib.html#module-$"),
        ("json", "py:module", "library/json.html#module-$"),
        ("os.cpu_count", "py:function", "library/os.html#$"),
        ("os.sched_getaffinity", "py:function", "library/os.html#$"),
    ]),
    "numpy": ("NumPy", "2", [
        ("numpy", "py:module", "reference/index.html#module-$"),
        ("array_like", "std:term", "glossary.html#term-array_like"),
        ("numpy.ndarray", "py:class", "reference/generated/$.html#$"),
        ("numpy.float64", "py:class", "reference/arrays.scalars.html#$"),
        ("numpy.int64", "py:class", "reference/arrays.scalars.html#$"),
        ("numpy.bool", "py:class", "reference/arrays.scalars.html#$"),
        ("numpy.dtype", "py:class", "reference/generated/$.html#$"),
        ("numpy.typing.ArrayLike", "py:data", "reference/typing.html#$"),
        ("numpy.typing.NDArray", "py:data", "reference/typing.html#$"),
        ("numpy.random.Generator", "py:class", "reference/random/generator.html#$"),
        ("numpy.random.default_rng", "py:function", "reference/random/generator.html#$"),
        ("numpy.asarray", "py:function", "reference/generated/$.html#$"),
        ("numpy.linspace", "py:function", "reference/generated/$.html#$"),
        ("numpy.geomspace", "py:function", "reference/generated/$.html#$"),
        ("numpy.logspace", "py:function", "reference/generated/$.html#$"),
        ("numpy.vectorize", "py:class", "reference/generated/$.html#$"),
        ("numpy.nan", "py:data", "reference/constants.html#$"),
        ("numpy.inf", "py:data", "reference/constants.html#$"),
    ]),
    "scipy": ("SciPy", "1", [
        ("scipy.optimize", "py:module", "reference/optimize.html#module-$"),
        ("scipy.optimize.brentq", "py:function", "reference/generated/$.html#$"),
        ("scipy.optimize.least_squares", "py:function", "reference/generated/$.html#$"),
        ("scipy.optimize.differential_evolution", "py:function",
         "reference/generated/$.html#$"),
        ("scipy.optimize.minimize_scalar", "py:function", "reference/generated/$.html#$"),
        ("scipy.optimize.root_scalar", "py:function", "reference/generated/$.html#$"),
        ("scipy.integrate.solve_ivp", "py:function", "reference/generated/$.html#$"),
        ("scipy.special.gamma", "py:function", "reference/generated/$.html#$"),
        ("scipy.special.beta", "py:function", "reference/generated/$.html#$"),
    ]),
    "xarray": ("xarray", "2025", [
        ("xarray.Dataset", "py:class", "generated/$.html#$"),
        ("xarray.DataArray", "py:class", "generated/$.html#$"),
        ("xarray.open_zarr", "py:function", "generated/$.html#$"),
        ("xarray.open_dataset", "py:function", "generated/$.html#$"),
        ("xarray.Dataset.to_zarr", "py:method", "generated/$.html#$"),
    ]),
    "pandas": ("pandas", "2", [
        ("pandas.DataFrame", "py:class", "reference/api/$.html#$"),
        ("pandas.Series", "py:class", "reference/api/$.html#$"),
        ("pandas.read_csv", "py:function", "reference/api/$.html#$"),
        ("pandas.DataFrame.to_csv", "py:method", "reference/api/$.html#$"),
    ]),
    "matplotlib": ("Matplotlib", "3", [
        ("matplotlib.figure.Figure", "py:class", "api/_as_gen/$.html#$"),
        ("matplotlib.figure.Figure.savefig", "py:method",
         "api/_as_gen/matplotlib.figure.Figure.html#$"),
        ("matplotlib.axes.Axes", "py:class", "api/_as_gen/$.html#$"),
        ("matplotlib.lines.Line2D", "py:class", "api/_as_gen/$.html#$"),
        ("matplotlib.rcParams", "py:data", "api/matplotlib_configuration_api.html#$"),
    ]),
    "panel": ("Panel", "1", [
        ("panel.layout.Row", "py:class", "reference/layouts/Row.html"),
    ]),
}


def inventory(title: str, version: str, objects: list[tuple[str, str, str]]) -> bytes:
    """One ``objects.inv`` file: the 4-line header, then the zlib-compressed entries.

    Parameters
    ----------
    title : str
        The project's name, as its own inventory gives it.
    version : str
        The version written in the header (intersphinx shows it in tooltips only).
    objects : list of tuple of str
        ``(name, "domain:role", path)`` for each object; each ``$`` of a path stands
        for the name.

    Returns
    -------
    bytes
        The file's content.
    """
    head = (f"# Sphinx inventory version 2\n# Project: {title}\n# Version: {version}\n"
            "# The remainder of this file is compressed using zlib.\n")
    lines = "".join(f"{name} {role} 1 {path.replace('$', name)} -\n"
                    for name, role, path in sorted(objects))
    return head.encode() + zlib.compress(lines.encode(), 9)


def main() -> None:
    """Write ``docs/_inventories/<project>.inv`` for every project of :data:`OBJECTS`."""
    OUT.mkdir(exist_ok=True)
    for name, (title, version, objects) in OBJECTS.items():
        (OUT / f"{name}.inv").write_bytes(inventory(title, version, objects))


if __name__ == "__main__":
    main()
