"""Sphinx configuration of the vibrofriction site (``make docs``; docs/site.md says why).

Built offline with warnings as errors: MathJax is served from the site itself
(sphinx-mathjax-offline), the gallery runs ``examples/`` at build time, and the API
pages are generated from each public module's ``__all__`` (:mod:`api_pages`).
"""

from __future__ import annotations

import sys
from pathlib import Path

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
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # MathJax 3 copied into _static: no network when viewed
    "sphinx_gallery.gen_gallery",
]

# --- sources ---------------------------------------------------------------------------
templates_path = ["_templates"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "_generated", "img/README.md", "gallery/*.ipynb", "gallery/*.py",
                    "gallery/*.zip", "gallery/*.md5", "gallery/*.json"]
api_pages.write(DOCS / "api")  # api/<module>.rst from each __all__ (gitignored)
api_pages.write_parameter_table(DOCS / "_generated")  # parameters.md includes it

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
autodoc_typehints = "description"
autodoc_typehints_format = "short"
autodoc_class_signature = "mixed"
autodoc_preserve_defaults = True
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_ivar = True
napoleon_use_rtype = False

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
html_static_path: list[str] = []
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
