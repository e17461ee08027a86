"""Sphinx configuration of the vibrofriction site (``make docs``; docs/site.md says why).

Built offline with warnings as errors: MathJax is served from the site itself
(sphinx-mathjax-offline), the gallery runs ``examples/`` at build time, and the API
pages are generated from each public module's ``__all__`` (:mod:`api_pages`).
"""

from __future__ import annotations

import importlib
import pkgutil
import re
import sys
from pathlib import Path

from sphinx.pycode import ModuleAnalyzer

DOCS = Path(__file__).resolve().parent
sys.path.insert(0, str(DOCS))  # api_pages, gallery_hooks
sys.path.insert(0, str(DOCS.parent / "src"))  # the checkout's package before any install

import api_pages  # noqa: E402

import vibrofriction  # noqa: E402

project = "vibrofriction"
author = "the vibrofriction authors"
copyright = "2026, the vibrofriction authors"
release = vibrofriction.__version__
version = release

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.napoleon",
    "sphinx.ext.viewcode",  # [source] links: the highlighted module source on the site
    "sphinx.ext.intersphinx",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # MathJax 3 copied into _static: no network when viewed
    "sphinx_gallery.gen_gallery",
    "sphinx_copybutton",
]

# --- sources ---------------------------------------------------------------------------
templates_path = ["_templates"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "_generated", "img/README.md", "gallery/*.ipynb", "gallery/*.py",
                    "gallery/*.zip", "gallery/*.md5", "gallery/*.json"]
api_pages.write(DOCS / "api")  # api/<module>.rst from each __all__ (gitignored)
api_pages.write_parameter_table(DOCS / "_generated")  # parameters.md includes it
api_pages.write_capability_table(DOCS / "_generated")  # solver.md includes it

# MyST: the existing Markdown pages are the user guide; $...$ and $$...$$ are maths,
# numbered with the paper's numbers by \tag{n}
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3
myst_dmath_double_inline = True

# MathJax 3 from the site (sphinx-mathjax-offline sets mathjax_path); \tag numbers on
mathjax3_config = {"tex": {"tags": "none"}}

# --- API --------------------------------------------------------------------------------
autosummary_generate = True
autosummary_imported_members = True
autodoc_default_options = {"members": True, "show-inheritance": True,
                           "member-order": "bysource"}
# one clean signature per object: the types are in each docstring's numpydoc sections, so
# the signature shows none; "none" is also what hides the @overload variants (autodoc
# prints one signature per overload otherwise: friction_coefficient had four) and keeps
# ArrayLike from being expanded into numpy's _NestedSequence[_SupportsArray[...]]
autodoc_typehints = "none"
autodoc_typehints_format = "short"
autodoc_type_aliases = {"ArrayLike": "ArrayLike"}
autodoc_class_signature = "mixed"
autodoc_preserve_defaults = True
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_ivar = True
napoleon_use_rtype = False
# the types of Parameters and Returns become links (numpy.ndarray to numpy's page, ...)
napoleon_preprocess_types = True
napoleon_type_aliases = {"array_like": ":term:`numpy:array_like`",
                         "callable": ":func:`python:callable`",
                         "mapping": ":term:`python:mapping`",
                         "sequence": ":term:`python:sequence`",
                         "iterable": ":term:`python:iterable`"}

# --- links into numpy, scipy, xarray, pandas, matplotlib and Python ----------------------
# offline: each inventory is a small file in the repository (docs/_inventories/, written by
# docs/make_inventories.py) listing only the objects these docs name, with their real
# addresses on each project's site; nothing is downloaded at build time
INVENTORIES = DOCS / "_inventories"
intersphinx_mapping = {
    name: (url, str(INVENTORIES / f"{name}.inv"))
    for name, url in {
        "python": "https://docs.python.org/3/",
        "numpy": "https://numpy.org/doc/stable/",
        "scipy": "https://docs.scipy.org/doc/scipy/",
        "xarray": "https://docs.xarray.dev/en/stable/",
        "pandas": "https://pandas.pydata.org/docs/",
        "matplotlib": "https://matplotlib.org/stable/",
        "panel": "https://panel.holoviz.org/",
    }.items()
}
intersphinx_timeout = 1

# the copy button copies the code of a doctest without its >>> and ... prompts or output
copybutton_prompt_text = r">>> |\.\.\. |\$ "
copybutton_prompt_is_regexp = True
copybutton_only_copy_prompt_lines = True

# --- gallery: examples/ run at build time --------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": "../examples",
    "gallery_dirs": "gallery",
    # every example runs (tests/docs/test_examples.py runs them as scripts too)
    "filename_pattern": r"/.*\.py$",
    "ignore_pattern": r"__init__\.py",
    # examples write PNGs with matplotlib.figure.Figure into the directory of argv[1]:
    # hand them a directory under _build and collect what they wrote
    "reset_argv": "gallery_hooks.reset_argv",
    "image_scrapers": ("gallery_hooks.png_scraper",),
    "within_subsection_order": "gallery_hooks.ReadmeOrder",
    "download_all_examples": False,
    "remove_config_comments": True,
    "min_reported_time": 0,
    # its tables load scripts from the network: left out (each page states its run time)
    "write_computation_times": False,
    "show_memory": False,
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "plot_gallery": "True",
}

# --- HTML ------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = f"vibrofriction {release}"
html_static_path = ["_static"]
html_css_files = ["custom.css"]  # long API titles wrap
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "header_links_before_dropdown": 7,
    "navbar_end": ["theme-switcher", "navbar-icon-links"],
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
html_show_sourcelink = False
# pages without sub-pages: no empty "Section Navigation" column
html_sidebars = {page: [] for page in ("index", "getting_started", "parameters", "changelog",
                                        "citing", "site")}
html_last_updated_fmt = None


# --- hooks -------------------------------------------------------------------------------
def _public_bases(app, name, obj, options, bases) -> None:
    """Show a class's public ancestors in "Bases:", not the private helpers it extends."""
    public: list[type] = []

    def add(base: type) -> None:
        if base.__name__.startswith("_"):
            for ancestor in getattr(base, "__bases__", ()):
                add(ancestor)
        elif base not in public:
            public.append(base)

    for base in list(bases):
        add(base)
    bases[:] = public


_TITLE = re.compile(r"(<h1>)(.*?)(<a class=\"headerlink\")", re.S)


def _breakable_titles(app, pagename, templatename, context, doctree) -> None:
    """Let an API page's title (a long dotted name) wrap after its dots."""
    if pagename.startswith("api/") and "body" in context:
        context["body"] = _TITLE.sub(
            lambda m: m.group(1) + m.group(2).replace(".", ".<wbr>") + m.group(3),
            context["body"], count=1)


_BACKLINK = re.compile(r'(href="[^"#]*?generated/)([^"/#]+)\.html#([^"]+)"')


def _backlink(match: re.Match) -> str:
    """The ``[docs]`` link of a highlighted source, pointed at the object's own anchor.

    viewcode writes ``#<module>.<name>`` with one module per source file, the first one
    an object of that file was documented under; an object re-exported elsewhere (the
    schema's ``Status`` at the top level, its ``Field`` in ``vibrofriction.schema``) then
    gets another module's anchor. An API page is named after the object it documents,
    so the anchor is that name followed by the member's path, if any.
    """
    prefix, page, anchor = match.groups()
    top = page.rsplit(".", 1)[-1]
    at = re.search(rf"\.{re.escape(top)}(?=\.|$)", anchor)
    if anchor == page or anchor.startswith(page + ".") or at is None:
        return match.group(0)
    return f'{prefix}{page}.html#{page}{anchor[at.end():]}"'


def _viewcode_links(app, pagename, templatename, context, doctree) -> None:
    """Fix the highlighted sources' links (viewcode: anchors, and an index entry for
    ``builtins`` that it writes for a type alias such as ``parallel.Task``)."""
    if pagename.startswith("_modules/") and "body" in context:
        body = _BACKLINK.sub(_backlink, context["body"])
        context["body"] = re.sub(r'<li><a href="builtins\.html">builtins</a></li>\s*', "", body)


def _reexported_data_docs(app, what, name, obj, options, lines) -> None:
    """The ``#:`` comment of a constant re-exported by a package (``vibrofriction.schema``
    re-exports those of its modules), not the docstring of its type (dict, tuple)."""
    if what != "data" or not name.startswith("vibrofriction."):
        return
    package, _, attr = name.rpartition(".")
    module = importlib.import_module(package)
    for sub in getattr(module, "__path__", None) and pkgutil.iter_modules(module.__path__) or ():
        docs = ModuleAnalyzer.for_module(f"{package}.{sub.name}").find_attr_docs()
        if ("", attr) in docs:
            lines[:] = list(docs[("", attr)])
            return


def setup(app) -> None:
    app.connect("autodoc-process-docstring", _reexported_data_docs)
    app.connect("autodoc-process-bases", _public_bases)
    app.connect("html-page-context", _breakable_titles)
    app.connect("html-page-context", _viewcode_links)
