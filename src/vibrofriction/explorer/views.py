"""The Bokeh figures of the explorer and how a computed result is drawn into them."""

from __future__ import annotations

import math

import numpy as np
from bokeh.models import ColumnDataSource, HoverTool, Label, LinearColorMapper, Range1d
from bokeh.plotting import figure

from ..figures.style import PHASE_COLORS
from ..schema import PARTIAL, ContactState
from .compute import CASE_COLORS, CONTACT_STATES, not_computed, solver_text

__all__ = ["CurveView", "HistoryView", "MapView", "SpaceTimeView"]

_TOOLS = "pan,wheel_zoom,box_zoom,reset,save"
#: the toolbars stand right of their plots: above, they would cover the titles
TOOLBAR = "right"
_FORM_COLORS = ("#d95f02", "#7570b3", "#e7298a")
_DATA_COLORS = ("#1b9e77", "#e6ab02", "#a6761d", "#666666", "#66a61e", "#e41a1c")


def _empty(**columns) -> ColumnDataSource:
    return ColumnDataSource({k: [] for k in columns} if columns else {"x": [], "y": []})


def _set_range(axis_range: Range1d, start: float, end: float) -> None:
    """Set a figure's range, and where its toolbar's reset returns.

    A ``Range1d``: the browser shows what is set here (a ``DataRange1d`` set from Python kept
    the range of an earlier view in the page).
    """
    axis_range.update(start=start, end=end, reset_start=start, reset_end=end)


def _legend_follows_data(figures, keep: tuple = ()) -> None:
    """Show a legend entry only while its renderers have something to draw.

    Or while they draw from a source in ``keep``: an entry shown and hidden at every move
    of a slider makes the browser lay the whole page out again each time.
    """
    for fig in figures:
        for item in fig.legend[0].items:
            item.visible = any(any(r.data_source is k for k in keep)
                               or len(next(iter(r.data_source.data.values()), [])) > 0
                               for r in item.renderers)


def _legend_outside(fig, location: str = "bottom_right") -> None:
    fig.legend.location = location
    fig.legend.label_text_font_size = "8pt"
    fig.legend.background_fill_alpha = 0.7
    fig.legend.click_policy = "hide"


def _legend_beside(fig) -> None:
    """The legend right of the plot, where it covers no data."""
    fig.add_layout(fig.legend[0], "right")
    fig.legend.label_text_font_size = "8pt"
    fig.legend.click_policy = "hide"
    fig.legend.spacing = 0
    fig.legend.padding = 4


def y_extent(values, reference: float) -> tuple[float, float]:
    """The range of the values a curve's plot shows.

    From 0 (or the lowest value, if below) to the highest of ``values`` (arrays: the
    curve, the static value, the closed forms, measurements and fits), and at least to
    ``reference``, the value of continuous sliding (1 for mu/mu0, mu0 for a bench's COF).
    """
    finite = np.concatenate([np.ravel(np.asarray(v, dtype=float)) for v in values] or [[]])
    finite = finite[np.isfinite(finite)]
    lo = min(0.0, float(finite.min())) if finite.size else 0.0
    hi = max(reference, float(finite.max())) if finite.size else reference
    return lo, hi if hi > lo else lo + 1.0


class CurveView:
    """``mu/mu0`` (or the COF) against velocity.

    Trusted points, untrusted points, the static value, the critical velocity, the closed forms,
    measurements and the fit.
    """

    def __init__(self, x_log: bool = False) -> None:
        self.trusted = _empty(x=1, y=1, n=1, stick=1, slip=1, open=1)
        self.untrusted = _empty(x=1, y=1, status=1)
        self.missing = _empty(x=1, y=1, status=1)  # no value: marked on the bottom edge
        self.static = _empty(x=1, y=1)
        self.critical = _empty(x0=1, x1=1, y0=1, y1=1)  # the flat punch's (eq. 12)
        self.critical_curved = _empty(x0=1, x1=1, y0=1, y1=1)  # continuous sliding
        self.forms = _empty(xs=1, ys=1, form=1, color=1)
        self.measured = _empty(x=1, y=1, group=1, color=1)
        self.fitted = _empty(xs=1, ys=1, color=1)
        self.picked = _empty(x=1, y=1)
        self._reference = 1.0  # the value of continuous sliding: mu/mu0 = 1 or a bench's mu0
        self.figures = {kind: self._figure(kind) for kind in ("linear", "log")}

    def _figure(self, kind: str):
        fig = figure(height=400, sizing_mode="stretch_width", tools=_TOOLS + ",tap",
                     x_axis_type=kind, title="mu/mu0 against velocity (exact solver)",
                     toolbar_location=TOOLBAR, y_range=Range1d(0.0, 1.0))
        fig.line("x", "y", source=self.trusted, line_width=2, color="#1f77b4",
                 legend_label="computed (trusted)")
        pts = fig.scatter("x", "y", source=self.trusted, size=4, color="#1f77b4",
                          legend_label="computed (trusted)")
        fig.scatter("x", "y", source=self.untrusted, size=7, fill_color=None,
                    line_color="#888888", line_width=1.5,
                    legend_label="not trusted (solver error > tol)")
        fig.scatter("x", "y", source=self.missing, size=9, marker="inverted_triangle",
                    fill_color=None, line_color="#888888", line_width=1.5,
                    legend_label="not trusted, no value (on the axis)")
        fig.multi_line("xs", "ys", source=self.forms, color="color", line_dash="dashed",
                       line_width=2, legend_field="form")
        fig.scatter("x", "y", source=self.static, marker="square", size=10, color="black",
                    legend_label="static value mu(v0 -> 0)")
        fig.segment("x0", "y0", "x1", "y1", source=self.critical, color="#d62728",
                    line_dash="dotted", line_width=2,
                    legend_label="critical velocity, eq. (12)")
        fig.segment("x0", "y0", "x1", "y1", source=self.critical_curved, color="#d62728",
                    line_dash="dotted", line_width=2,
                    legend_label="critical velocity: continuous sliding")
        fig.scatter("x", "y", source=self.measured, size=8, marker="triangle",
                    color="color", legend_field="group")
        fig.multi_line("xs", "ys", source=self.fitted, color="color", line_width=2,
                       line_dash="dotdash", legend_label="fit")
        fig.scatter("x", "y", source=self.picked, size=14, fill_color=None,
                    line_color="#ff7f0e", line_width=3, legend_label="point of the history")
        fig.add_tools(HoverTool(renderers=[pts], tooltips=[
            ("v", "@x{0.0000g}"), ("mu", "@y{0.000000}"), ("<F_N>/F_N0", "@n{0.0000}"),
            ("stick, slip, open", "@stick{0.000}, @slip{0.000}, @open{0.000}")]))
        _legend_beside(fig)
        return fig

    def show(self, curve: dict, log_x: bool) -> None:
        """Draw a computed curve (``compute.curve``)."""
        x, y, ok = curve["x"], curve["y"], curve["trusted"]
        trusted = {"x": x, "y": np.where(ok, y, np.nan), "n": curve["mean_normal_ratio"],
                   "stick": curve["stick_area_fraction"],
                   "slip": curve["slip_area_fraction"],
                   "open": curve["open_area_fraction"]}
        k = int(np.searchsorted(x, 0.0))
        if curve.get("rest_note") and 0 < k < len(x):  # V = 0 left out: the line breaks
            trusted = {name: np.insert(np.asarray(v, dtype=float), k,
                                       0.0 if name == "x" else np.nan)
                       for name, v in trusted.items()}
        self.trusted.data = trusted
        bad = ~ok & np.isfinite(y)
        self.untrusted.data = {"x": x[bad], "y": y[bad], "status": curve["status"][bad]}
        shown = math.isfinite(curve["static"])
        self.static.data = {"x": [x[0]] if shown else [], "y": [curve["static"]] if shown else []}
        self._reference = 1.0 if curve["mu0"] is None else curve["mu0"]
        gap = not_computed(curve)
        self.missing.data = {"x": x[gap], "y": np.zeros(int(gap.sum())),  # see _rescale
                             "status": curve["status"][gap]}
        crit = curve["critical"]
        in_range = math.isfinite(crit) and x[0] <= crit <= x[-1]
        line = {"x0": [crit], "x1": [crit], "y0": [0.0], "y1": [1.0]}  # see _rescale
        none: dict[str, list[float]] = {k: [] for k in line}
        curved = curve["profile"] != "flat punch"
        self.critical.data = line if in_range and not curved else none
        self.critical_curved.data = line if in_range and curved else none
        forms = curve["closed_forms"]
        self.forms.data = {"xs": [f["x"] for f in forms], "ys": [f["y"] for f in forms],
                           "form": [f["label"] for f in forms],
                           "color": list(_FORM_COLORS[:len(forms)])}
        for fig in self.figures.values():
            fig.yaxis.axis_label = curve["y_label"]
            fig.xaxis.axis_label = curve["x_label"]
            solver = solver_text(curve)
            fig.title.text = (f"{curve['y_label']} against velocity ({solver}): case "
                              f"{curve['case']}")
        self.picked.data = {"x": [], "y": []}
        self._rescale()

    def _rescale(self) -> None:
        """Fit the y axis to what is drawn; the points without a value on its bottom edge."""
        values = [self.trusted.data["y"], self.untrusted.data["y"], self.static.data["y"],
                  *self.forms.data["ys"], self.measured.data["y"], *self.fitted.data["ys"]]
        lo, hi = y_extent(values, self._reference)
        bottom, top = lo - 0.05 * (hi - lo), hi + 0.06 * (hi - lo)  # the static value may be 0
        self.missing.data = {**self.missing.data,
                             "y": np.full(len(self.missing.data["x"]), lo - 0.03 * (hi - lo))}
        for src in (self.critical, self.critical_curved):  # the vertical line: edge to edge
            if len(src.data["x0"]):
                src.data = {**src.data, "y0": [bottom], "y1": [top]}
        for fig in self.figures.values():
            _set_range(fig.y_range, bottom, top)
        # (the point of the history keeps its entry: it is cleared here and drawn again
        # once the inputs rest)
        _legend_follows_data(self.figures.values(), keep=(self.picked,))

    def show_measurements(self, groups: list[dict]) -> None:
        """Draw the measured points, one colour per group."""
        xs, ys, labels, colors = [], [], [], []
        for k, g in enumerate(groups):
            xs += list(g["x"])
            ys += list(g["cof"])
            labels += [f"measured: {g['label']}"] * len(g["x"])
            colors += [_DATA_COLORS[k % len(_DATA_COLORS)]] * len(g["x"])
        self.measured.data = {"x": xs, "y": ys, "group": labels, "color": colors}
        self._rescale()

    def show_fit(self, curves: list[dict]) -> None:
        """Draw the fitted curves, one per group."""
        self.fitted.data = {"xs": [c["x"] for c in curves], "ys": [c["cof"] for c in curves],
                            "color": [_DATA_COLORS[k % len(_DATA_COLORS)]
                                      for k in range(len(curves))]}
        self._rescale()

    def pick(self, x: float, y: float) -> None:
        """Mark the picked point ``(x, y)``."""
        self.picked.data = {"x": [x], "y": [y]}
        _legend_follows_data(self.figures.values())


#: Phase colours of the contact point's path (darker than the shading of the history).
_PATH_COLORS = {"stick": "#2171b5", "slip+": "#e6550d", "slip-": "#a50f15",
                "flight": "#737373"}


#: The history's phases: a curved tip's row adds "partial" (stick and slip at once).
_HISTORY_COLORS = {**PHASE_COLORS, PARTIAL: "#dadaeb"}


def _below(fig, title: str, y_label: str, y_range: tuple[float, float], css: str, **kw):
    """A hidden figure under the history's ``fig``, on its time axis."""
    out = figure(height=220, sizing_mode="stretch_width", tools=_TOOLS, title=title,
                 toolbar_location=TOOLBAR, x_axis_label="t/T (drive periods)",
                 y_axis_label=y_label, x_range=fig.x_range, y_range=Range1d(*y_range),
                 css_classes=[css], **kw)
    out.visible = False
    return out


def _legend_small(fig):
    """``fig`` with its legend small, bottom right, see-through; returned."""
    fig.legend.location = "bottom_right"
    fig.legend.label_text_font_size = "8pt"
    fig.legend.background_fill_alpha = 0.7
    return fig


#: What the second figure of a rate-and-state history shows (:meth:`HistoryView.choose`).
LOCAL_QUANTITIES = {"coefficient": "local coefficient f/n", "theta": "state theta"}


class HistoryView:
    """A point's time history.

    Forces, the phases shaded, the events marked; the local coefficient ``f/n`` below
    (``coefficient_figure``), or with rate-and-state friction the state ``theta`` instead
    (``theta_figure``, log scale) where :meth:`choose` says so; with an in-plane oscillation
    a further figure (``path_figure``, hidden otherwise) shows the contact point on the
    substrate: ``x_c`` against time (1-D) or its path ``(x_c, y_c)`` in the plane (2-D),
    coloured by phase.
    """

    def __init__(self) -> None:
        self.lines = _empty(t=1, f=1, n=1)
        self.lateral = _empty(t=1, f_y=1)
        self.path = _empty(x=1, y=1)
        self.path_points = _empty(x=1, y=1, t=1, color=1, phase=1, size=1)
        self.spans = _empty(left=1, right=1, bottom=1, top=1, color=1, phase=1)
        self.events = _empty(t=1, y=1, kind=1)
        fig = figure(height=330, sizing_mode="stretch_width", tools=_TOOLS,
                     title="time history: click a point of the curve",
                     x_axis_label="t/T (drive periods)",
                     y_axis_label="force / (mu0 F_N0)", toolbar_location=TOOLBAR,
                     x_range=Range1d(0.0, 3.0), y_range=Range1d(-1.0, 2.0))
        fig.quad("left", "right", "bottom", "top", source=self.spans, color="color",
                 alpha=0.6, legend_field="phase")
        fig.line("t", "n", source=self.lines, color="black", line_width=1.5,
                 legend_label="n = F_N/F_N0 (friction limit)")
        fig.line("t", "f", source=self.lines, color="#1f77b4", line_width=2,
                 legend_label="f = F_x/(mu0 F_N0)")
        fig.line("t", "f_y", source=self.lateral, color="#2ca02c", line_width=2,
                 legend_label="f_y = F_y/(mu0 F_N0)")
        ev = fig.scatter("t", "y", source=self.events, marker="diamond", size=8,
                         color="#d62728", legend_label="events")
        fig.add_tools(HoverTool(renderers=[ev], tooltips=[("event", "@kind"),
                                                          ("t/T", "@t{0.0000}")]))
        _legend_outside(fig, "top_center")
        fig.legend.orientation = "horizontal"
        self.figure = fig
        self.coefficient = _empty(t=1, mu=1)
        self.levels = _empty(t=1, y=1, level=1)
        local = _below(fig, "local coefficient f/n", "f/n (over mu0)", (-1.5, 1.5),
                       "vf-coefficient")
        local.line("t", "mu", source=self.coefficient, color="#1f77b4", line_width=2,
                   legend_label="f/n (none in flight)")
        local.multi_line("t", "y", source=self.levels, color="#d62728", line_dash="dashed",
                         legend_field="level")
        self.coefficient_figure = _legend_small(local)
        self.theta = _empty(t=1, theta=1)
        self.theta_level = _empty(t=1, y=1)
        state = _below(fig, "state theta", "theta (1/omega)", (1e-3, 1.0), "vf-theta",
                       y_axis_type="log")
        state.line("t", "theta", source=self.theta, color="#6a3d9a", line_width=2,
                   legend_label="theta (ages in flight)")
        state.line("t", "y", source=self.theta_level, color="#d62728", line_dash="dashed",
                   legend_label="steady sliding d_c/V")
        self.theta_figure = _legend_small(state)
        self.quantity = "coefficient"
        self._last: tuple[dict, str] | None = None
        path = figure(height=300, sizing_mode="stretch_width", tools=_TOOLS,
                      title="contact point on the substrate", toolbar_location=TOOLBAR,
                      x_axis_label="t/T (drive periods)", y_axis_label="x_c")
        path.line("x", "y", source=self.path, color="#bbbbbb", line_width=1)
        dots = path.scatter("x", "y", source=self.path_points, color="color", size="size",
                            legend_field="phase")
        path.add_tools(HoverTool(renderers=[dots], tooltips=[
            ("t/T", "@t{0.000}"), ("phase", "@phase"), ("(x, y)", "(@x{0.0000}, @y{0.0000})")]))
        path.add_layout(path.legend[0], "right")
        path.legend.label_text_font_size = "8pt"
        path.visible = False
        self.path_figure = path

    def hide(self) -> None:
        """Hide the history's figures (a point without a history)."""
        for fig in (self.figure, self.coefficient_figure, self.theta_figure, self.path_figure):
            fig.visible = False

    def choose(self, quantity: str) -> None:
        """Show ``quantity`` (a key of :data:`LOCAL_QUANTITIES`) below the forces.

        ``"theta"`` applies to a rate-and-state history (the others have no state: their
        coefficient stays); the history shown is redrawn.
        """
        if quantity not in LOCAL_QUANTITIES:
            raise ValueError(f"quantity must be one of {', '.join(LOCAL_QUANTITIES)}, "
                             f"got {quantity!r}")
        self.quantity = quantity
        if self._last is not None:
            self._show_local(*self._last)

    def _show_local(self, h: dict, where: str) -> None:
        """The local coefficient or, chosen and given, the state theta."""
        theta = h.get("theta")
        if theta is not None and self.quantity == "theta":
            self._show_coefficient({"coefficient": None}, where)
            self._show_theta(h, where)
        else:
            self._show_theta({"theta": None}, where)
            self._show_coefficient(h, where)

    def _show_theta(self, h: dict, where: str) -> None:
        """The state ``theta`` against time (log scale), with its steady-sliding value."""
        theta = h.get("theta")
        fig = self.theta_figure
        if theta is None:
            self.theta.data = {"t": [], "theta": []}
            self.theta_level.data = {"t": [], "y": []}
            fig.visible = False
            return
        t0, t1 = float(h["t"][0]), float(h["t"][-1])
        level = float(h["theta_sliding"])
        self.theta.data = {"t": h["t"], "theta": theta}
        self.theta_level.data = {"t": [t0, t1], "y": [level, level]}
        lo = min(float(np.min(theta)), level)
        hi = max(float(np.max(theta)), level)
        _set_range(fig.y_range, lo / 1.5, hi * 1.5)
        fig.title.text = f"state theta at {where} (unit 1/omega)"
        fig.visible = True

    def _show_coefficient(self, h: dict, where: str) -> None:
        """The local coefficient ``f/n`` against time, with the law's limits.

        Kinetic ``+-1`` and, for a static coefficient above the kinetic one, ``+-static_ratio``;
        with rate-and-state friction the coefficient of steady sliding at the velocity,
        ``+-mu_ss(V)/mu_star``; hidden where the history has no coefficient (a curved tip's).
        """
        mu = h.get("coefficient")
        fig = self.coefficient_figure
        if mu is None:
            self.coefficient.data = {"t": [], "mu": []}
            self.levels.data = {"t": [], "y": [], "level": []}
            fig.visible = False
            return
        t0, t1 = float(h["t"][0]), float(h["t"][-1])
        s_r = float(h.get("static_ratio", 1.0))
        levels = [("kinetic +-1", 1.0)] + ([(f"static +-{s_r:g}", s_r)] if s_r > 1.0 else [])
        if h.get("theta") is not None:  # rate-and-state: steady sliding's at this velocity
            mu_ss = abs(float(h["sliding_mu_ratio"]))
            levels = [(f"steady sliding +-{mu_ss:.4g}", mu_ss)]
        self.coefficient.data = {"t": h["t"], "mu": mu}
        self.levels.data = {"t": [[t0, t1]] * 2 * len(levels),
                            "y": [[sign * v] * 2 for _, v in levels for sign in (1, -1)],
                            "level": [name for name, _ in levels for _ in (1, -1)]}
        finite = np.asarray(mu, dtype=float)
        finite = finite[np.isfinite(finite)]
        top = max(s_r, float(np.max(np.abs(finite))) if finite.size else 1.0) * 1.1
        _set_range(fig.y_range, -top, top)
        fig.title.text = f"local coefficient f/n at {where} (over mu0)"
        fig.visible = True

    def show(self, h: dict, where: str) -> None:
        """Draw the history ``h`` at the velocity ``where``."""
        t, f, n = h["t"], h["f"], h["n"]
        self.lines.data = {"t": t, "f": f, "n": n}
        self._last = (h, where)
        self._show_local(h, where)
        f_y = h.get("f_y")
        self.lateral.data = {"t": t if f_y is not None else [],
                             "f_y": f_y if f_y is not None else []}
        self._show_path(h)
        lo = min(0.0, float(np.min(f)), float(np.min(n)))
        hi = max(float(np.max(f)), float(np.max(n)))
        if f_y is not None:
            lo, hi = min(lo, float(np.min(f_y))), max(hi, float(np.max(f_y)))
        # one row holds four entries in the width of the figure: the phases, n, f, f_y, events
        entries = len({s[2] for s in h["spans"]}) + 2 + (f_y is not None) + bool(h["events"])
        two_rows = entries > 4
        pad = (0.6 if two_rows else 0.35) * (hi - lo or 1.0)  # room for the legend on top
        self.spans.data = {
            "left": [s[0] for s in h["spans"]], "right": [s[1] for s in h["spans"]],
            "bottom": [lo - 0.05 * pad] * len(h["spans"]),
            "top": [hi + pad] * len(h["spans"]),
            "color": [_HISTORY_COLORS.get(s[2], "#ffffff") for s in h["spans"]],
            "phase": [s[2] for s in h["spans"]]}
        ev_t = np.array([e[0] for e in h["events"]], dtype=float)
        self.events.data = {"t": ev_t, "y": np.interp(ev_t, t, f) if ev_t.size else ev_t,
                            "kind": [e[1] for e in h["events"]]}
        _set_range(self.figure.y_range, lo - 0.05 * pad, hi + pad)
        _set_range(self.figure.x_range, float(t[0]), float(t[-1]))
        self.figure.title.text = (f"time history at {where}: mu/mu0 = {h['mu_ratio']:.5g}"
                                  f"{'' if h['steady'] else ' (transient)'}")
        _legend_follows_data([self.figure])  # no f_y entry in 1-D
        self.figure.legend.nrows = 2 if two_rows else "auto"

    def _show_path(self, h: dict) -> None:
        """The contact point on the substrate.

        The contact point on the substrate, or nothing (and hidden) without an
        in-plane oscillation.
        """
        xc, yc = h.get("xc"), h.get("yc")
        fig = self.path_figure
        if xc is None:
            self.path.data = {"x": [], "y": []}
            self.path_points.data = {"x": [], "y": [], "t": [], "color": [], "phase": [],
                                     "size": []}
            fig.visible = False
            return
        t = h["t"]
        x, y = (xc, yc) if yc is not None else (t, xc)
        phase = [str(p) for p in h["phase"]]
        self.path.data = {"x": x, "y": y}
        self.path_points.data = {"x": x, "y": y, "t": t, "phase": phase,
                                 "color": [_PATH_COLORS.get(p, "#000000") for p in phase],
                                 # stick stands still: larger dots, so that it shows
                                 "size": [8 if p == "stick" else 3 for p in phase]}
        if yc is not None:
            fig.title.text = "contact point's path on the substrate (still in stick)"
            fig.xaxis.axis_label, fig.yaxis.axis_label = "x_c", "y_c"
        else:
            fig.title.text = "contact point on the substrate: x_c (flat in stick)"
            fig.xaxis.axis_label, fig.yaxis.axis_label = "t/T (drive periods)", "x_c"
        fig.visible = True


class MapView:
    """The ``(alpha, beta)`` plane coloured by the case of ``vf.classify``; click to move."""

    def __init__(self, case_map: dict) -> None:
        al, cases = case_map["alpha"], case_map["cases"]
        n = len(al)
        img = np.zeros((n, n), dtype=np.uint32)
        view = img.view(dtype=np.uint8).reshape((n, n, 4))
        for j in range(n):
            for i in range(n):
                view[j, i] = _rgba(CASE_COLORS.get(cases[j, i], "#ffffff"))
        (a0, a1), (b0, b1) = case_map["alpha_range"], case_map["beta_range"]
        fig = figure(height=330, width=500, x_axis_type="log", y_axis_type="log",
                     x_range=Range1d(a0, a1), y_range=Range1d(b0, b1),
                     tools="tap,pan,wheel_zoom,reset,save", toolbar_location=TOOLBAR,
                     title="cases I-IV, click to move",
                     x_axis_label="alpha", y_axis_label="beta")
        fig.image_rgba(image=[img], x=a0, y=b0, dw=a1 - a0, dh=b1 - b0)
        # the resonance bands are thinner than a pixel of the grid: draw them as lines
        fig.segment(x0=[1.0], x1=[1.0], y0=[1.0], y1=[b1], color=CASE_COLORS["IV"],
                    line_width=4)
        fig.segment(x0=[a0], x1=[1.0], y0=[1.0], y1=[1.0], color=CASE_COLORS["III"],
                    line_width=4)
        for label, case in (("I soft", "I"), ("II stiff", "II"), ("III beta ~ 1", "III"),
                            ("IV alpha ~ 1", "IV"), ("general", "general")):
            fig.scatter([a0 / 10], [b0 / 10], marker="square", size=10, color=CASE_COLORS[case],
                        line_color="#555555", legend_label=label)
        fig.scatter([a0 / 10], [b0 / 10], marker="square", size=10, color="#ffffff",
                    line_color="#555555",
                    legend_label="beta <= alpha: no system")
        self.current = _empty(x=1, y=1, marker=1)
        fig.scatter("x", "y", source=self.current, size=16, marker="marker",
                    fill_color="#d62728", line_color="black", legend_label="current system")
        fig.add_layout(fig.legend[0], "right")
        fig.legend.label_text_font_size = "8pt"
        fig.legend.background_fill_alpha = 0.8
        fig.legend.spacing = 0
        fig.legend.padding = 4
        self.figure = fig
        self.beta_top = b1

    def show(self, alpha: float, beta: float) -> None:
        """Mark the system ``(alpha, beta)`` on the case map."""
        infinite = math.isinf(beta)
        self.current.data = {"x": [alpha], "y": [self.beta_top * 0.8 if infinite else beta],
                             "marker": ["triangle" if infinite else "circle"]}


def _rgba(color: str) -> tuple[int, int, int, int]:
    c = color.lstrip("#")
    return int(c[0:2], 16), int(c[2:4], 16), int(c[4:6], 16), 255


#: Colours of the MDR springs' states by code (:data:`.compute.CONTACT_STATES`).
CONTACT_COLORS = tuple({ContactState.STICK: "#4292c6", ContactState.SLIP_POS: "#fd8d3c",
                        ContactState.SLIP_NEG: "#a50f15", ContactState.FLIGHT: "#eeeeee"}[s]
                       for s in ContactState)


class SpaceTimeView:
    """A curved tip's contact over one period.

    The position ``xi = x/a0`` along the profile against ``t/T``, each spring coloured by its state
    (stick, slip, flight), with the stick and contact radii where the history gives them;
    hidden for the flat punch. Without an MDR time history it says so (``show`` with ``spacetime``
    None).
    """

    def __init__(self) -> None:
        self.image = _empty(image=1, x=1, y=1, dw=1, dh=1)
        self.radii = _empty(t=1, stick=1, contact=1)
        mapper = LinearColorMapper(palette=list(CONTACT_COLORS), low=-0.5,
                                   high=len(CONTACT_COLORS) - 0.5)
        fig = figure(height=330, sizing_mode="stretch_width", tools=_TOOLS,
                     title="contact in space and time (curved tip)", toolbar_location=TOOLBAR,
                     x_axis_label="t/T (drive periods)",
                     y_axis_label="xi = x/a0 (position along the profile)",
                     x_range=Range1d(0.0, 1.0), y_range=Range1d(0.0, 1.0),
                     css_classes=["vf-spacetime"])
        fig.image("image", "x", "y", "dw", "dh", source=self.image,
                  color_mapper=mapper)  # type: ignore[call-arg]  # bokeh: a glyph property
        for name, color in zip(CONTACT_STATES, CONTACT_COLORS, strict=True):
            fig.scatter([-10.0], [-10.0], marker="square", size=10, color=color,
                        line_color="#555555", legend_label=name)
        fig.line("t", "stick", source=self.radii, color="#08519c", line_width=2,
                 legend_label="stick radius")
        fig.line("t", "contact", source=self.radii, color="black", line_width=1.5,
                 line_dash="dashed", legend_label="contact radius")
        self.note = Label(x=0.5, y=0.5, x_units="data", y_units="data", text="",
                          text_align="center", text_baseline="middle",
                          text_font_size="11pt", text_color="#b00020")
        fig.add_layout(self.note)
        fig.add_layout(fig.legend[0], "right")
        fig.legend.label_text_font_size = "8pt"
        fig.visible = False
        self.figure = fig

    def hide(self) -> None:
        """Hide the view."""
        self.figure.visible = False

    def show(self, h: dict, where: str) -> None:
        """Draw ``compute.mdr_history``'s contact (or its placeholder message)."""
        fig = self.figure
        fig.visible = True
        st = h.get("spacetime")
        if st is None:
            self.image.data = {"image": [], "x": [], "y": [], "dw": [], "dh": []}
            self.radii.data = {"t": [], "stick": [], "contact": []}
            self.note.text = "needs the MDR history"
            fig.title.text = f"contact at {where}: {h['message']}"
            return
        t, xi, codes = (np.asarray(st[k], dtype=float) for k in ("t", "xi", "state"))
        t0, t1 = float(t[0]), float(t[-1])
        top = float(xi[-1] + xi[0])  # the cells' outer edge: the largest contact radius
        # rows of the image are xi (upwards), columns are time
        self.image.data = {"image": [np.ascontiguousarray(codes.T)], "x": [t0], "y": [0.0],
                           "dw": [t1 - t0], "dh": [top]}
        self.radii.data = {"t": t, "stick": st.get("stick_radius", np.full(t.size, np.nan)),
                           "contact": st.get("contact_radius", np.full(t.size, np.nan))}
        self.note.text = ""
        _set_range(fig.x_range, t0, t1)
        _set_range(fig.y_range, 0.0, top)
        fig.title.text = f"contact at {where}: {st['springs']} springs, one period"
