"""sphinx-gallery hooks: the examples' output directory, and a scraper of their PNGs.

The examples are scripts a user runs as ``python examples/x.py [output directory]``;
they draw with :class:`matplotlib.figure.Figure` (no pyplot state) and save PNGs there.
At build time each gets ``docs/_build/gallery_output/<name>/`` as that argument, and
after each code block the scraper copies the PNGs that appeared into the gallery.
(Named by string in conf.py, so Sphinx can pickle its configuration.)
"""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

from sphinx_gallery.scrapers import figure_rst

OUTPUT = Path(__file__).resolve().parent / "_build" / "gallery_output"
_seen: dict[str, set[str]] = {}


def output_dir(src_file: str) -> Path:
    """Where the example ``src_file`` writes its figures during the build."""
    return OUTPUT / Path(src_file).stem


def reset_argv(gallery_conf: dict[str, Any], script_vars: dict[str, Any]) -> list[str]:
    """``sys.argv[1:]`` of an example: a fresh output directory."""
    out = output_dir(script_vars["src_file"])
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    _seen[str(out)] = set()
    return [str(out)]


def png_scraper(block: Any, block_vars: dict[str, Any], gallery_conf: dict[str, Any],
                **kwargs: Any) -> str:
    """Copy the PNGs the block wrote (in the order written) into the gallery's images."""
    out = output_dir(block_vars["src_file"])
    seen = _seen.setdefault(str(out), set())
    new = sorted((p for p in out.glob("*.png") if p.name not in seen),
                 key=lambda p: (p.stat().st_mtime_ns, p.name))
    paths = []
    for png, target in zip(new, block_vars["image_path_iterator"], strict=False):
        shutil.copyfile(png, target)
        seen.add(png.name)
        paths.append(target)
    return figure_rst(paths, gallery_conf["src_dir"]) if paths else ""


# the README's order: from a first curve to the bench
ORDER = ["pin_si_units", "resonant_case_iv", "paper_experiment", "frictional_drive",
         "sphere_stick_slip", "design_oscillation", "fit_pin_on_disk", "atlas_on_dask"]


class ReadmeOrder:
    """sphinx-gallery's ``within_subsection_order``: the examples in :data:`ORDER`, then
    any other by name."""

    def __init__(self, src_dir: str) -> None:
        self.src_dir = src_dir

    def __call__(self, filename: str) -> tuple[int, str]:
        stem = Path(filename).stem
        return (ORDER.index(stem) if stem in ORDER else len(ORDER), stem)
