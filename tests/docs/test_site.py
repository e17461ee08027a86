"""The documentation site (issue 22): built by ``make docs`` (``make test`` builds it first),
opened in the distribution's headless Chromium through Playwright, as the explorer's tests
do. The landing page, an API page and a gallery page render with their images, the
equations are typeset by the MathJax the site serves itself (no request leaves the
machine), the search finds ``friction_coefficient``, and no internal link of any built
page is broken. Screenshots: docs/img/site_*.png.

Marked ``browser`` and ``slow``. Where the site is not built the fixture builds it (the
``make docs`` command); without Sphinx or chromium the browser tests skip, unless
``VIBROFRICTION_BROWSER_TESTS=required`` (``make test``): then they fail.
"""

from __future__ import annotations

import doctest
import functools
import http.server
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import threading
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest

from doctest_numbers import NumberChecker

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
HTML = DOCS / "_build" / "html"
IMG = DOCS / "img"
REQUIRED = os.environ.get("VIBROFRICTION_BROWSER_TESTS") == "required"
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
# the command of `make docs`
BUILD = [sys.executable, "-m", "sphinx", "-b", "html", "-W", "--keep-going", "-q",
         "-d", str(DOCS / "_build" / "doctrees"), str(DOCS), str(HTML)]
TIMEOUT_MS = 60_000


def _missing(what: str) -> None:
    if REQUIRED:
        pytest.fail(f"{what} (required by make test)")
    pytest.skip(what)


@pytest.fixture(scope="module")
def site() -> Path:
    """The built site: ``make docs``'s output, built here if it is not there."""
    if not (HTML / "index.html").exists():
        if importlib.util.find_spec("sphinx") is None:
            _missing("the site is not built and Sphinx is not installed: make docs")
        out = subprocess.run(BUILD, capture_output=True, text=True, cwd=ROOT, timeout=1800)
        assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    return HTML


@pytest.fixture(scope="module")
def server(site):
    """The site over HTTP on a free local port (as a user's ``python -m http.server``)."""
    handler = functools.partial(_QuietHandler, directory=str(site))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}/"
    httpd.shutdown()
    httpd.server_close()


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args) -> None:  # no request log in the test output
        pass


@pytest.fixture(scope="module")
def browser():
    if REQUIRED:
        import playwright.sync_api as playwright_api
    else:
        playwright_api = pytest.importorskip("playwright.sync_api")
    if CHROMIUM is None:
        _missing("no chromium on PATH (apt-get install chromium)")
    with playwright_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, headless=True)
        yield b
        b.close()


@pytest.fixture
def page(browser, server):
    """A page whose every request to another host is refused and recorded: the site
    must render offline."""
    context = browser.new_context(viewport={"width": 1400, "height": 1000})
    page = context.new_page()
    page.set_default_timeout(TIMEOUT_MS)
    page.outside = []

    def route(r):
        if r.request.url.startswith(server):
            r.continue_()
        else:
            page.outside.append(r.request.url)
            r.abort()

    page.route("**/*", route)
    yield page
    assert page.outside == [], f"requests that left the machine: {page.outside}"
    context.close()


def _images_loaded(page) -> list[tuple[str, int]]:
    """(src, naturalWidth) of every image in the page's main content, once loaded."""
    page.wait_for_function("Array.from(document.images).every(i => i.complete)")
    return page.eval_on_selector_all(
        "main img", "imgs => imgs.map(i => [i.getAttribute('src'), i.naturalWidth])")


def _math_typeset(page, at_least: int) -> int:
    """Wait for MathJax to typeset at least ``at_least`` expressions; none in error."""
    page.wait_for_function(f"document.querySelectorAll('mjx-container').length >= {at_least}")
    assert page.locator("mjx-merror").count() == 0, "MathJax reports a TeX error"
    return page.locator("mjx-container").count()


def _shot(page, name: str) -> None:
    IMG.mkdir(exist_ok=True)
    page.screenshot(path=str(IMG / name), full_page=False)



@pytest.mark.browser
@pytest.mark.slow
def test_landing_page_renders_its_figure_and_its_math(page, server):
    page.goto(server + "index.html")
    assert "vibrofriction" in page.title()
    images = _images_loaded(page)
    assert any("pin_si_units" in src and width > 0 for src, width in images), images
    assert all(width > 0 for _, width in images), images
    _math_typeset(page, 5)  # inline math of the first paragraphs
    for target in ("getting_started.html", "parameters.html", "user_guide.html",
                   "gallery/index.html", "api/index.html"):
        assert page.locator(f"main a[href='{target}']").count() >= 1, target
    _shot(page, "site_landing.png")


@pytest.mark.browser
@pytest.mark.slow
def test_api_page_renders_the_docstring(page, server):
    page.goto(server + "api/generated/vibrofriction.friction_coefficient.html")
    sig = page.locator("dl.py.function dt.sig").first
    assert "friction_coefficient" in sig.inner_text() and "vbar" in sig.inner_text()
    body = page.locator("dl.py.function dd").first.inner_text()
    assert "Macroscopic coefficient of friction" in body and "settings" in body
    assert all(width > 0 for _, width in _images_loaded(page))
    # the top-level page lists every public name of vibrofriction.__all__
    page.goto(server + "api/vibrofriction.html")
    import vibrofriction as vf

    listed = page.locator("table.autosummary").inner_text()
    for name in set(vf.__all__) - {"__version__", "sweep"}:
        assert re.search(rf"\b{name}\b", listed), name
    page.goto(server + "api/generated/vibrofriction.Dimensionless.html")
    _shot(page, "site_api.png")


@pytest.mark.browser
@pytest.mark.slow
def test_gallery_page_shows_code_figure_and_run_time(page, server):
    page.goto(server + "gallery/index.html")
    thumbs = _images_loaded(page)
    assert len(thumbs) >= 6 and all(width > 0 for _, width in thumbs), thumbs
    page.goto(server + "gallery/pin_si_units.html")
    figures = [(s, w) for s, w in _images_loaded(page) if "sphx_glr_pin_si_units" in s]
    assert figures and all(w > 0 for _, w in figures), figures
    text = page.locator("main").inner_text()
    assert "vf.friction_coefficient(PIN, v0=v0)" in text  # the code
    assert "v0* =" in text  # what it printed when the site was built
    assert re.search(r"Total running time of the script: \(\d+ minutes \d+\.\d+ seconds\)",
                     text), "no run time"
    for suffix in (".py", ".ipynb"):
        href = page.locator(f"a.download[href$='pin_si_units{suffix}']").first
        assert href.count() == 1, suffix
    _shot(page, "site_gallery.png")


@pytest.mark.browser
@pytest.mark.slow
def test_equations_render_with_the_papers_numbers(page, server):
    page.goto(server + "theory.html")
    _math_typeset(page, 10)
    shown = page.locator("main").inner_text()
    for tag in ("(2)", "(12)", "(26)", "(27, corrected)", "(32)"):
        assert tag in shown, tag
    page.goto(server + "model.html")
    _math_typeset(page, 8)
    assert "(20)" in page.locator("main").inner_text()


# the user guide's pages whose formulas are MathJax, the fewest formulas each typesets
# (about 90 % of the count when they were converted) and an equation tag it shows
GUIDE_MATH = (("damping.html", 170, "(12, damped)"),
              ("inplane.html", 470, "(12, in-plane)"),
              ("contact_geometry.html", 470, "(12, profile)"),
              ("theory.html", 200, "(27, corrected)"),
              ("solver.html", 310, None),
              ("modulation.html", 90, None))


@pytest.mark.browser
@pytest.mark.slow
def test_user_guide_formulas_are_typeset(page, server):
    """Issue 22: the formulas of the guide are mathematics, not code: every page typesets
    its formulas without a TeX error, no ``$`` is left as text and no display equation is
    wider than the column."""
    for name, at_least, tag in GUIDE_MATH:
        page.goto(server + name)
        _math_typeset(page, at_least)
        text = page.locator("main").inner_text()
        assert "$" not in text, (name, text[text.index("$") - 60:text.index("$") + 60])
        if tag:
            assert tag in text, (name, tag)
        wide = page.evaluate("""Array.from(document.querySelectorAll('mjx-container[display]'))
            .filter(e => e.firstElementChild.getBoundingClientRect().width
                         > e.getBoundingClientRect().width + 1).length""")
        assert wide == 0, (name, wide)


@pytest.mark.browser
@pytest.mark.slow
def test_search_box_finds_friction_coefficient(page, server):
    page.goto(server + "index.html")
    page.locator("button.search-button__button, button.search-button").first.click()
    box = page.locator("input[name='q']:visible").first
    box.fill("friction_coefficient")
    box.press("Enter")
    page.wait_for_url(re.compile(r"search\.html\?q=friction_coefficient"))
    results = page.locator("#search-results ul.search li")
    results.first.wait_for()
    texts = results.all_inner_texts()
    assert any("friction_coefficient" in t for t in texts), texts[:5]


class _Links(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.links: list[tuple[str, str]] = []
        self.ids: set[str] = set()
        self.external_loads: list[str] = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "a" and "name" in a:
            self.ids.add(a["name"])
        for key in ("href", "src"):
            if a.get(key):
                self.links.append((tag, a[key]))
        loads = (tag in ("script", "img", "iframe") and a.get("src")) or (
            tag == "link" and "stylesheet" in (a.get("rel") or "") and a.get("href"))
        if loads and re.match(r"(https?:)?//", loads):
            self.external_loads.append(loads)


@functools.cache
def _parse(path: Path) -> _Links:
    parser = _Links()
    parser.feed(path.read_text(errors="replace"))
    return parser


@pytest.mark.browser
@pytest.mark.slow
def test_no_internal_link_is_broken_and_nothing_loads_from_the_network(site):
    # every built page (_static holds the theme's template fragments, not pages)
    pages = sorted(p for p in site.rglob("*.html") if "_static" not in p.relative_to(site).parts)
    assert len(pages) > 50, len(pages)
    broken, external = [], []
    for path in pages:
        links = _parse(path)
        external += [(path.relative_to(site), u) for u in links.external_loads]
        for tag, url in links.links:
            parts = urlsplit(url)
            if parts.scheme or url.startswith(("//", "mailto:", "javascript:")):
                continue
            target = path if not parts.path else (path.parent / unquote(parts.path))
            target = target.resolve()
            if target.is_dir():
                target = target / "index.html"
            if not target.exists():
                broken.append((str(path.relative_to(site)), url))
            elif parts.fragment and target.suffix == ".html" and tag == "a" \
                    and unquote(parts.fragment) not in _parse(target).ids:
                broken.append((str(path.relative_to(site)), url))
    assert broken == [], f"{len(broken)} broken internal links: {broken[:20]}"
    assert external == [], f"resources loaded from the network: {external[:10]}"


@pytest.mark.browser
@pytest.mark.slow
def test_api_reference_covers_every_public_name(site):
    """Each public module's page names every entry of its ``__all__``, and each name has
    one page (where it is defined, or the top level)."""
    import importlib

    sys.path.insert(0, str(DOCS))
    try:
        api_pages = importlib.import_module("api_pages")
    finally:
        sys.path.remove(str(DOCS))
    for module, _ in api_pages.MODULES:
        text = (site / "api" / f"{module}.html").read_text()
        for name in importlib.import_module(module).__all__:
            home = api_pages.home(name, module)
            assert (site / "api" / "generated" / f"{home}.{name}.html").exists(), (module, name)
            assert f"{home}.{name}.html" in text, (module, name)


@pytest.mark.browser
@pytest.mark.slow
@pytest.mark.parametrize("name", ["friction_coefficient", "simulate", "Dimensionless"])
def test_api_page_shows_one_clean_signature_with_its_source(site, name):
    """One signature (not one per ``@overload``), no ``ArrayLike`` spelled out as numpy's
    private ``_NestedSequence[...]``, a ``[source]`` link and a copy button."""
    html = (site / "api" / "generated" / f"vibrofriction.{name}.html").read_text()
    signatures = re.findall(rf'<dt class="sig sig-object py"[^>]*id="vibrofriction\.{name}"',
                            html)
    assert len(signatures) == 1, (name, len(signatures))
    assert "_NestedSequence" not in html and "_SupportsArray" not in html, name
    assert 'class="viewcode-link"' in html, name
    assert "copybutton" in html, name


@pytest.mark.browser
@pytest.mark.slow
def test_docstring_types_link_to_the_projects_they_come_from(site):
    """The offline inventories (docs/_inventories) make xarray's and Python's names links
    to those projects' own pages."""
    html = (site / "api" / "generated" / "vibrofriction.sweep.open_atlas.html").read_text()
    assert 'href="https://docs.xarray.dev/en/stable/generated/xarray.Dataset.html' in html
    assert 'href="https://docs.python.org/3/library/os.html#os.PathLike"' in html
    html = (site / "api" / "generated" / "vibrofriction.validation.checked.html").read_text()
    assert 'href="https://numpy.org/doc/stable/reference/generated/numpy.ndarray.html' in html


def test_getting_started_runs_and_prints_what_it_shows():
    """The ``>>>`` block of docs/getting_started.md, a number to the digits it shows."""
    text = (DOCS / "getting_started.md").read_text()
    parser = doctest.DocTestParser()
    test = parser.get_doctest(text, {}, "getting_started.md", str(DOCS), 0)
    assert len(test.examples) >= 8
    runner = doctest.DocTestRunner(checker=NumberChecker(), verbose=False,
                                   optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    assert runner.failures == 0, "docs/getting_started.md: see the doctest report above"


@pytest.mark.browser
@pytest.mark.slow
@pytest.mark.parametrize("width", [1400, 900])
def test_tables_fit_their_column(page, server, width):
    """The theory page's summary table (the widest) wraps its cells, code included, to
    the article's width instead of running over the page (docs/_static/custom.css)."""
    page.set_viewport_size({"width": width, "height": 1000})
    page.goto(server + "theory.html")
    _math_typeset(page, 20)
    sizes = page.eval_on_selector_all(
        ".bd-article table",
        "ts => ts.map(t => [t.scrollWidth, t.clientWidth, "
        "t.closest('.bd-article').getBoundingClientRect().right"
        " - t.getBoundingClientRect().right])")
    assert sizes and all(scroll <= client + 1 and margin >= -1 for scroll, client, margin
                         in sizes), sizes


@pytest.mark.browser
@pytest.mark.slow
@pytest.mark.parametrize("name", ["frictional_drive", "sphere_stick_slip"])
def test_new_gallery_pages_teach_in_steps(page, server, name):
    """A gallery page alternates text and code: sections with prose between the code
    blocks, and the figure the script drew."""
    page.goto(server + f"gallery/{name}.html")
    figures = [(s, w) for s, w in _images_loaded(page) if f"sphx_glr_{name}" in s]
    assert figures and all(w > 0 for _, w in figures), figures
    assert page.locator("main section section").count() >= 3  # the cells' headings
    assert page.locator("main div.highlight-Python").count() >= 4
    assert page.locator("main section section > p").count() >= 4
