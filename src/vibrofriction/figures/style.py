r"""One matplotlib style for every figure: column widths, the paper's symbols.

Figures are built with the object-oriented API (``matplotlib.figure.Figure``, no
pyplot), so importing this package leaves the backend of a notebook or script as
it was and works headless.

Sizes follow a two-column journal page: :data:`COLUMN` (one column, 3.4 in) and
:data:`PAGE` (both columns, 7.0 in); fonts are 8 pt so that the figures are
readable when printed at those widths.  Labels use the paper's notation
(``$\bar v$``, ``$\mu_{macro}/\mu_0$``, ``$\alpha$``, ``$\beta$``).
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import matplotlib
import numpy as np
from matplotlib.figure import Figure

__all__ = [
    "COLUMN",
    "PAGE",
    "MU",
    "VBAR",
    "V_INERTIAL",
    "ALPHA",
    "BETA",
    "AMPLITUDE",
    "NUMERIC",
    "THEORY",
    "RESONANT",
    "PHASE_COLORS",
    "RC",
    "figure",
    "save",
    "amplitude_colors",
    "sequence_colors",
    "panel_label",
    "styled",
    "use",
]

#: Width of one column and of the full page, inches.
COLUMN: float = 3.4
PAGE: float = 7.0

#: Axis labels in the paper's symbols.
MU = r"$\mu_{\mathrm{macro}}/\mu_0$"
VBAR = r"$\bar v = v_0/v_0^*$"
V_INERTIAL = r"$v_0\,m\omega/(\mu_0 F_{N,0})$"
ALPHA = r"$\alpha = k_x/(m\omega^2)$"
BETA = r"$\beta = (k_x + k_{x,c})/(m\omega^2)$"
AMPLITUDE = r"$\Delta u_z/u_{z,0}$"

#: Colours: numerics in black (as in the paper's Fig. 4), closed forms in red,
#: resonant panels and lines in orange.
NUMERIC = "black"
THEORY = "#d62728"
RESONANT = "#e08a00"
#: The phases of the motion (stick, slip forward and backward, flight), one colour each
#: for every view that shades them (Fig. 2 leaves forward slip, the ordinary sliding,
#: unshaded; the explorer shades all four).
PHASE_COLORS = {"stick": "#9ecae1", "slip+": "#fdd0a2", "slip-": "#fcbba1",
                "flight": "#d9d9d9"}

RC: dict[Any, Any] = {  # matplotlib types the keys as literals
    "font.size": 8,
    "axes.labelsize": 8,
    "axes.titlesize": 8,
    "xtick.labelsize": 7,
    "ytick.labelsize": 7,
    "legend.fontsize": 7,
    "legend.frameon": False,
    "lines.linewidth": 1.0,
    "lines.markersize": 3,
    "axes.linewidth": 0.6,
    "xtick.major.width": 0.6,
    "ytick.major.width": 0.6,
    "xtick.direction": "in",
    "ytick.direction": "in",
    "xtick.top": False,
    "ytick.right": False,
    "axes.spines.top": True,
    "axes.spines.right": True,
    "axes.grid": False,
    "savefig.dpi": 300,
    "pdf.fonttype": 42,
    "mathtext.fontset": "dejavusans",
    "figure.dpi": 100,
}


@contextmanager
def use() -> Iterator[None]:
    """Apply :data:`RC` for the duration of a ``with`` block."""
    with matplotlib.rc_context(RC):
        yield


def styled(func: Callable[..., Any]) -> Callable[..., Any]:
    """Decorator: run ``func`` (which builds a figure) inside :func:`use`.

    Matplotlib reads most style parameters when an artist is created, so the whole
    drawing function, not only the saving, must run under the style.
    """

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        with use():
            return func(*args, **kwargs)

    return wrapper


def figure(width: float = COLUMN, height: float | None = None, **kwargs) -> Figure:
    """A new figure of the given width (inches), height defaulting to ``0.75 width``.

    Uses the object-oriented API (no pyplot state), so figures can be built in
    worker processes and garbage-collected without ``plt.close``.
    """
    with matplotlib.rc_context(RC):
        kwargs.setdefault("layout", "constrained")
        return Figure(figsize=(width, height if height is not None else 0.75 * width),
                      **kwargs)


def save(fig: Figure, directory: Path, name: str) -> list[Path]:
    """Write ``name.png`` (300 dpi) and ``name.pdf`` into ``directory``; return the paths.

    The layout (constrained) is computed once, for the PNG, and then frozen, so that
    the PDF shows the same geometry and does not pay for the layout again.
    """
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    paths = []
    with matplotlib.rc_context(RC):
        for ext in ("png", "pdf"):
            path = directory / f"{name}.{ext}"
            # no creation date in the PDF: a reproduction is byte-for-byte repeatable
            fig.savefig(path, metadata={"CreationDate": None} if ext == "pdf" else None)
            paths.append(path)
            fig.set_layout_engine("none")
    return paths


def sequence_colors(n: int, cmap: str = "viridis", lo: float = 0.0,
                    hi: float = 0.85) -> list[tuple[float, float, float, float]]:
    """``n`` colours evenly spaced along a perceptually uniform colormap."""
    cm = matplotlib.colormaps[cmap]
    if n == 1:
        return [cm(lo)]
    return [cm(lo + (hi - lo) * i / (n - 1)) for i in range(n)]


def amplitude_colors(amplitudes) -> list[tuple[float, float, float, float]]:
    """Colours for a series of amplitudes (dark = large), consistent across figures."""
    cm = matplotlib.colormaps["plasma"]
    return [cm(0.8 * (1.0 - min(float(a), 2.0) / 2.0)) for a in amplitudes]


def panel_label(ax, text: str, *, x: float = 0.02, y: float = 0.97, **kwargs) -> None:
    """A bold panel label such as ``(a)`` in the upper-left corner of ``ax``."""
    ax.text(x, y, text, transform=ax.transAxes, ha="left", va="top", fontweight="bold",
            **kwargs)


def mark_untrusted(ax: Any, x: Any, curve: Any, color: Any, scale: float = 1.0,
                   ms: float = 2.0, where: Any = None,
                   clip: tuple[float, float] = (0.0, 1.0)) -> None:
    """Draw a curve's untrusted points as what they are, never as results.

    A converged status whose error is too large: an open circle at its value.  A
    motion that did not settle (no value): a thin vertical bar over the range of its
    last averaging windows' means.  ``scale`` multiplies ``mu/mu0`` (e.g. ``mu0``);
    ``where`` (a mask over the curve) restricts the points, with ``x`` given for those;
    an open circle's value is clipped to ``clip`` (a law of friction other than Coulomb's
    can exceed ``mu0``).
    """
    sel = np.ones(curve.mu_ratio.shape, bool) if where is None else np.asarray(where)
    x = np.asarray(x)
    mu, lo, hi = (np.asarray(v)[sel] for v in (curve.mu_ratio, curve.window_min,
                                                  curve.window_max))
    bad = ~np.asarray(curve.trusted)[sel]
    valued = bad & np.isfinite(mu)
    if np.any(valued):
        ax.plot(x[valued], scale * np.clip(mu[valued], *clip), "o", ms=ms, mfc="none",
                mec=color, mew=0.5)
    ranged = bad & ~np.isfinite(mu) & np.isfinite(lo)
    if np.any(ranged):  # a bar with end ticks (visible even where the range is tiny)
        ax.vlines(x[ranged], scale * lo[ranged], scale * hi[ranged], colors=color, lw=0.6)
        for end in (lo, hi):
            ax.plot(x[ranged], scale * end[ranged], "_", ms=ms + 1, color=color, mew=0.6)
