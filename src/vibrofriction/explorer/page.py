"""The explorer's page: inputs, views, measurements and sharing, wired with Panel.

Every computation runs in a worker process (:mod:`.pool`) from an async callback, the
newest input wins (moves that arrive during a computation are merged into one), and a
bad input leaves the last good view in place with the library's message beside it.
"""

from __future__ import annotations

import asyncio
import io
import math
from functools import partial
from typing import Any
from urllib.parse import urlencode

import numpy as np
import panel as pn
from bokeh.events import Tap

from vibrofriction.bench import FITTABLE
from vibrofriction.capabilities import CAPABILITIES, friction_laws
from vibrofriction.schema import CHOICES

from . import compute, exports, pool
from .messages import (
    GENERAL,
    LAW,
    curved_refusal,
    field_of,
    law_refusal,
    law_taken,
    read_inputs,
)
from .state import (
    AXES,
    BENCH,
    DIMENSIONLESS,
    LAW_DISABLED,
    LAW_INPUTS,
    LAW_POINTS,
    LAWS,
    MDR_POINTS,
    MDR_REFUSED,
    PROFILE,
    PROFILES,
    VELOCITY,
    State,
    format_value,
    law_solver,
    parse_number,
    profile_of,
)
from .texts import (
    curved_side_text,
    flat_side_text,
    mount_note,
    point_text,
    readout_text,
    status_text,
    vbar_refusal,
    with_more,
)
from .views import LOCAL_QUANTITIES, CurveView, HistoryView, MapView, SpaceTimeView
from .widgets import ERROR_STYLE, NOTE_STYLE, Input

__all__ = ["Explorer", "app", "curved_side_text", "point_text", "readout_text", "status_text"]

#: the profile selector's labels
_PROFILE_LABELS = {"flat punch": "flat", "sphere": "sphere", "cone": "cone",
                   "power law": "power"}
#: the power law's exponent when it is chosen from a named tip
_POWER_DEFAULT = 3.0
STATUS_AFTER = 0.5  # s: a curve still under way then says what it computes
#: the busy mark while a curve is computed: a ring turning (CSS only)
BUSY_MARK = '<div class="vf-spin" title="computing"></div>'
BUSY_CSS = """
.vf-spin { box-sizing: border-box; width: 16px; height: 16px; border-radius: 50%;
           border: 2px solid #d0d0d0; border-top-color: #1f77b4;
           animation: vf-spin 0.8s linear infinite; }
@keyframes vf-spin { to { transform: rotate(360deg); } }
"""
#: the inputs disabled with a curved tip: the refused ones and what only they act on (the
#: longitudinal oscillation a_x, phase_x and its mount stay: the MDR solver takes them)
_MDR_DISABLED = (*MDR_REFUSED, "phase_y")
#: the friction-law selector's labels (the laws' names in the solvers' declarations)
_LAW_LABELS = {label: law for law, label in LAWS.items()}


class Explorer:
    """One page (one browser tab or one notebook cell)."""

    def __init__(self, state: State | None = None) -> None:
        query_problems: dict[str, str] = {}
        if state is None:
            args = dict(pn.state.session_args) if pn.state.curdoc is not None and \
                pn.state.curdoc.session_context else {}
            state, query_problems = State.from_query(args)
        self.state = state
        self.curve: dict[str, Any] | None = None
        self.curve_state: State | None = None  # the inputs of the curve shown
        self.data: Any = None  # the measurements loaded (a pandas DataFrame)
        self._doc = pn.state.curdoc if (pn.state.curdoc is not None and
                                        pn.state.curdoc.session_context) else None
        self._location = pn.state.location if self._doc is not None else None
        self._want: State | None = None
        self._busy = False
        self._history_want: float | None = None
        self._history_busy = False
        self._picked_x: float | None = None
        self._point_text = ""  # the picked point's results, from the curve
        self._point_y = math.nan
        self._adjusting = False  # the page itself is setting inputs (no new reading)
        # what the page did to the inputs at the last change (reset, switched) and why the
        # disabled ones are: by input name or "axis"; made anew at every change
        self._notes: dict[str, str] = {}
        self._build()
        self._changed()
        for name, text in query_problems.items():  # kept: the defaults stand in for them
            self._message(name, f"URL parameter {name}: {text}")

    # ------------------------------------------------------------------ layout
    def _build(self) -> None:
        self._build_controls()
        self._build_views()
        self._build_input_boxes()
        self.layout = pn.Row(self._sidebar(), self._main(), sizing_mode="stretch_width")
        self._show_mode()

    def _build_controls(self) -> None:
        """The inputs, the switches and the text panes of the sidebar."""
        s = self.state
        self.inputs = {f.name: Input(f, getattr(s, f.name), self._changed)
                       for f in (*DIMENSIONLESS, PROFILE, *BENCH, *VELOCITY, *LAW_INPUTS)}
        self.law = pn.widgets.RadioButtonGroup(options=_LAW_LABELS, value=s.friction,
                                               width=330, css_classes=["vf-law"])
        self.rs_law = pn.widgets.RadioButtonGroup(
            options={f"{v} law": v for v in CHOICES["rs_law"].values}, value=s.rs_law, width=200,
            css_classes=["vf-rs-law"])
        self.law_note = pn.pane.HTML("", styles=NOTE_STYLE, visible=False, width=310,
                                     css_classes=["vf-law-note"])
        self.profile = pn.widgets.RadioButtonGroup(
            options=_PROFILE_LABELS, value=profile_of(s.profile_exponent), width=330,
            label="profile", css_classes=["vf-profile"])
        self.profile.param.watch(self._profile_chosen, "value")
        self.profile_note = pn.pane.HTML("", styles=NOTE_STYLE, visible=False, width=310,
                                         css_classes=["vf-profile-note"])
        self.mode = pn.widgets.RadioButtonGroup(
            options={"dimensionless (alpha, beta, a)": "dimensionless", "bench (SI)": "bench"},
            value=s.mode, color="primary", width=320)
        self.axis = pn.widgets.RadioButtonGroup(options={k: k for k in AXES}, value=s.axis,
                                                width=200, label="velocity axis")
        self.axis_message = pn.pane.HTML("", styles=ERROR_STYLE, visible=False, width=310,
                                         css_classes=["vf-axis-message"])
        self.log_x = pn.widgets.Checkbox(label="logarithmic velocity axis", value=s.log_x)
        self.inplane_on = pn.widgets.RadioButtonGroup(
            options={f"in-plane on the {v}": v for v in CHOICES["inplane_on"].values},
            value=s.inplane_on, width=320, label="inplane_on",
            css_classes=["vf-inplane-on"])
        self.inplane_note = pn.pane.HTML("", styles=NOTE_STYLE, visible=False, width=310,
                                         css_classes=["vf-inplane-note"])
        self.general = pn.pane.HTML("", styles=ERROR_STYLE, visible=False, width=310)
        for w in (self.mode, self.axis, self.log_x, self.inplane_on, self.law, self.rs_law):
            w.param.watch(lambda e: self._changed(), "value")
        # the busy mark: a fixed-size pane whose text changes (a widget whose classes change,
        # like a LoadingSpinner, makes the browser lay the whole page out again, twice a
        # curve: most of a redraw; benchmarks/results/explorer.md)
        self.busy = pn.pane.HTML("", width=20, height=20, margin=(12, 5),
                                 stylesheets=[BUSY_CSS], css_classes=["vf-busy"])
        self.status = pn.pane.Markdown("", width=330, css_classes=["vf-status"])
        self.readout = pn.pane.Markdown("", width=330, css_classes=["vf-readout"])
        self.history_text = pn.pane.Markdown("click a point of the curve for its history",
                                             css_classes=["vf-history"])
        # what the figure below the forces shows of a rate-and-state history
        self.history_quantity = pn.widgets.RadioButtonGroup(
            options={v: k for k, v in LOCAL_QUANTITIES.items()}, value="coefficient",
            width=330, visible=False, css_classes=["vf-history-quantity"])
        self.history_quantity.param.watch(
            lambda e: self.history_view.choose(e.new), "value")
        self.case_text = pn.pane.HTML("", width=330, css_classes=["vf-case"])

    def _build_views(self) -> None:
        """The curve, history, space-time and map views, their taps wired."""
        self.curve_view = CurveView()
        self.history_view = HistoryView()
        self.spacetime_view = SpaceTimeView()
        self.map_view = MapView(compute.case_map())
        for fig in self.curve_view.figures.values():
            fig.on_event(Tap, self._tapped_curve)
        self.map_view.figure.on_event(Tap, self._tapped_map)
        self.curve_pane = pn.pane.Bokeh(self.curve_view.figures["linear"],
                                        sizing_mode="stretch_width", min_height=400)

    def _build_input_boxes(self) -> None:
        """The dimensionless and the bench inputs, each in its box (one shown per mode)."""
        self.dim_box = pn.Column(*(self.inputs[f.name].layout for f in DIMENSIONLESS),
                                 self.inplane_on, self.inplane_note,
                                 pn.pane.Markdown("**the tip** (profile z = c r^n)"),
                                 self.profile, self.inputs[PROFILE.name].layout,
                                 self.profile_note, margin=0)
        self.bench_box = pn.Column(*(self.inputs[f.name].layout for f in BENCH), margin=0)
        self.bench_file = pn.widgets.FileInput(accept=".json", width=300)
        self.bench_file.param.watch(self._bench_file, "value")
        self.bench_box.append(pn.Column(pn.pane.Markdown("bench file (JSON, docs/bench.md):"),
                                        self.bench_file, margin=0))
        self.law_box = pn.Column(pn.pane.Markdown("**local friction law**"), self.law,
                                 *(self.inputs[f.name].layout for f in LAW_INPUTS),
                                 self.rs_law, self.law_note, margin=0)
        self.bench_box.append(pn.pane.HTML(with_more(
            "The bench inputs are the linearised contact: a curved tip is chosen on the "
            "dimensionless inputs.",
            "The linearised contact: its stiffnesses at the load. A curved tip in SI units: "
            "vf.from_bench(contact=Sphere(...), contact_model=\"mdr\") in Python "
            "(docs/contact_geometry.md)."), width=330, styles=NOTE_STYLE))

    def _sidebar(self):
        """The sidebar: the mode, the inputs, the velocity axis and the curve's status."""
        return pn.Column(
            pn.pane.Markdown("## vibrofriction explorer\nFriction under normal oscillations "
                             "(Mao, Popov, Starcevic, Popov 2017), by the exact solver."),
            self.mode, self.general, self.dim_box, self.bench_box, self.law_box,
            pn.pane.Markdown("**velocity**"), self.axis, self.axis_message,
            *(self.inputs[f.name].layout for f in VELOCITY), self.log_x,
            pn.Row(pn.pane.Markdown("**the curve**"), self.busy, margin=0), self.status,
            self.readout,
            self.case_text, width=350)

    def _main(self):
        """The main column.

        The curve, the history and the map, the measurements and the sharing tabs.
        """
        return pn.Column(self.curve_pane,
                         pn.Row(pn.Column(self.history_view.figure,
                                          self.history_quantity,
                                          self.history_view.coefficient_figure,
                                          self.history_view.theta_figure,
                                          self.history_view.path_figure,
                                          self.spacetime_view.figure, self.history_text,
                                          sizing_mode="stretch_width"),
                                self.map_view.figure, sizing_mode="stretch_width"),
                         pn.Tabs(("Measurements & fit", self._measurements_panel()),
                                 ("Export & share", self._share_panel()), dynamic=False),
                         sizing_mode="stretch_width")

    def _measurements_panel(self):
        self.csv_input = pn.widgets.FileInput(accept=".csv", label="measurements",
                                              css_classes=["vf-csv"])
        self.csv_input.param.watch(self._csv_dropped, "value")
        self.csv_message = pn.pane.HTML("", styles=ERROR_STYLE, visible=False)
        self.csv_info = pn.pane.Markdown("no measurements loaded", css_classes=["vf-csv-info"])
        self.free = pn.widgets.MultiChoice(label="free parameters of the fit",
                                           value=["mu0", "mass", "k_xc"],
                                           options=list(FITTABLE),
                                           width=400)
        self.fit_button = pn.widgets.Button(label="fit", color="primary", disabled=True,
                                            width=100)
        self.fit_button.on_click(self._fit_clicked)
        self.fit_busy = pn.indicators.Progress(active=False, visible=False, width=200)
        self.fit_report = pn.pane.Markdown("", sizing_mode="stretch_width")
        return pn.Column(
            pn.pane.Markdown("Drop a measurement table (CSV, the format of docs/bench.md: "
                             "`v0`, `cof`, `du_z`, `omega`, optional `sigma`) on the box, or "
                             "click it: the points are overlaid (bench inputs)."),
            self.csv_input, self.csv_message, self.csv_info, pn.Row(self.free, self.fit_button,
                                                     self.fit_busy), self.fit_report)

    def _share_panel(self):
        self.snippet = pn.pane.Markdown("", sizing_mode="stretch_width")
        # disabled until a curve is shown: there is nothing to export before
        self.downloads = [pn.widgets.FileDownload(callback=partial(self._export, fmt),
                                                  filename=f"vibrofriction_curve.{fmt}",
                                                  label=f"download {fmt.upper()}",
                                                  color="default", width=160,
                                                  disabled=True)
                          for fmt in ("png", "svg", "csv")]
        self.link = pn.pane.Markdown("")
        return pn.Column(pn.Row(*self.downloads), self.link,
                         pn.pane.Markdown("Python that recomputes this curve:"), self.snippet)

    def _show_mode(self) -> None:
        bench = self.mode.value == "bench"
        self.dim_box.visible = not bench
        self.bench_box.visible = bench
        shown = {f.name for f in self._law_fields()}
        for f in LAW_INPUTS:
            self.inputs[f.name].layout.visible = f.name in shown
        self.rs_law.visible = self.law.value == "rate_state"

    def _law_fields(self):
        """The inputs of the chosen law in the chosen mode."""
        return self.state.with_(mode=self.mode.value, friction=self.law.value).law_fields()

    # ------------------------------------------------------------------ inputs
    def _names(self) -> list[str]:
        fields = BENCH if self.mode.value == "bench" else (*DIMENSIONLESS, PROFILE)
        return [f.name for f in (*fields, *self._law_fields(), *VELOCITY)]

    def _profile_chosen(self, event) -> None:
        """The selector sets the exponent (the power law's box is the only one typed)."""
        box = self.inputs[PROFILE.name].text
        if event.new == "power":
            try:
                current = parse_number(PROFILE.name, box.value or "")
            except ValueError:
                current = math.inf
            value = current if profile_of(current) == "power" else _POWER_DEFAULT
        else:
            value = PROFILES[event.new]
        if box.value != format_value(value):
            box.value = format_value(value)  # its watcher reads the inputs
        else:
            self._changed()

    def _guard(self) -> None:
        """Before the inputs are read: what a curved tip or an in-plane drive excludes.

        With a curved tip, reset what the MDR solver refuses (``eta_c``, ``a_y``) to 0, saying
        so next to each with the library's message, and disable them (and ``phase_y``) with
        the reason beside them; a flat punch enables them again.  The longitudinal
        oscillation (``a_x``, ``phase_x``, the mount) and the axis ``vbar`` stay.  Where the
        library refuses ``vbar`` (an in-plane amplitude ``a_x`` or ``a_y`` > 0), switch the
        axis to ``V``, saying why next to the axis and the amplitude.
        """
        try:
            n = parse_number(PROFILE.name, self.inputs[PROFILE.name].text.value or "")
        except ValueError:
            return  # read_inputs says so
        dimensionless = self.mode.value == "dimensionless"
        curved = dimensionless and n != math.inf
        self.inputs[PROFILE.name].enable(self.profile.value == "power")
        probe = self.state.with_(profile_exponent=n, mode="dimensionless",
                                 friction=self.law.value, rs_law=self.rs_law.value)
        self._adjusting = True
        try:
            if curved and (why := law_taken(probe)):  # the law is reset, as eta_c is
                self._notes[LAW] = with_more(f"{LAWS[probe.friction]} reset to Coulomb: the "
                                             "MDR solver does not take it yet", why)
                self.law.value = "coulomb"
                probe = probe.with_(friction="coulomb")
                self._show_mode()
            law_off = self._law_disabled(probe.friction)
            for name in {*_MDR_DISABLED, *(n for law in LAWS for n in self._law_disabled(law))}:
                self.inputs[name].enable(not (curved and name in _MDR_DISABLED)
                                         and name not in law_off)
            if curved:
                self._reset(MDR_REFUSED, partial(curved_refusal, probe),
                            "the MDR solver does not take it yet")
            else:
                self._reset([n for n in law_off if n not in ("phase_x", "phase_y")],
                            lambda name, value: law_refusal(
                                probe, "eta_c" if name == "bench_eta_c" else name, value),
                            f"not taken with {LAWS[probe.friction]} friction yet")
            if dimensionless and self.axis.value == "vbar":
                self._leave_vbar(probe)
        finally:
            self._adjusting = False
        self.profile_note.visible = curved
        if curved:
            self.profile_note.object = with_more(
                f"{compute.profile_text(n)} by the MDR solver (at most {MDR_POINTS} points); "
                "not taken yet, so disabled: eta_c, a_y, beta = inf",
                f"A curved tip is computed by the MDR solver (docs/contact_geometry.md): at "
                f"most {MDR_POINTS} points a curve (~30 ms a point). It takes the "
                "longitudinal in-plane oscillation (a_x, phase_x, the mount) at V != 0 (with "
                "a_x > 0 the curve leaves V = 0 out) and the axis vbar (V over the tip's "
                "critical velocity of continuous sliding). It does not take yet: contact "
                "damping eta_c, the transverse oscillation a_y, a rigid contact beta = inf.")

    def _typed(self, name: str) -> float | None:
        """The value typed in the box of ``name``, or None where it does not read."""
        try:
            return parse_number(name, self.inputs[name].text.value or "")
        except ValueError:
            return None

    def _law_disabled(self, law: str) -> tuple[str, ...]:
        """The inputs ``law`` disables in the chosen mode (:data:`LAW_DISABLED`)."""
        if self.mode.value == "dimensionless":
            return LAW_DISABLED[law]
        return tuple(f"bench_{n}" for n in LAW_DISABLED[law] if f"bench_{n}" in self.inputs)

    def _reset(self, names, refusal, reason: str) -> None:
        """Reset ``names`` to 0, ``reason`` beside each.

        With the library's ``refusal(name, value)`` behind "more" (a curved tip's MDR solver,
        a friction law's solver).
        """
        for name in names:
            box = self.inputs[name].text
            value = self._typed(name)
            why = refusal(name, 1.0 if value in (None, 0.0) else value)
            if value == 0.0:  # the library's refusal without its "got ..." of a probe value
                self._notes[name] = with_more(f"disabled: {reason}", why.split(": got ")[0])
                continue
            applied = value is not None and value == getattr(self.state, name)
            self._notes[name] = with_more(
                f"{name} reset from {box.value} to 0: {reason}"
                if applied else f"{name} = {box.value} (never applied) cleared to 0: {reason}",
                why)
            box.value = "0"

    def _leave_vbar(self, probe: State) -> None:
        """Switch the axis ``vbar`` to ``V`` where the library refuses ``vbar``; say why.

        The refusals that remain: an in-plane amplitude (``a_x`` or ``a_y`` > 0, any tip)
        and contact damping (``eta_c > 0``) with a curved tip; the library's message goes
        behind "more".
        """
        typed = {n: v for n in ("a_x", "a_y", "eta_c") if (v := self._typed(n)) and v > 0.0}
        why = vbar_refusal(probe.with_(**{"a_x": 0.0, "a_y": 0.0, "eta_c": 0.0, **typed}))
        if not why:
            return
        self.axis.value = "V"
        amplitudes = [n for n in ("a_x", "a_y") if n in typed]
        cause = ("with an in-plane oscillation" if amplitudes else
                 "for a curved tip with contact damping (eta_c > 0)")
        self._notes["axis"] = with_more(f"axis set from vbar to V: vbar is not defined {cause}",
                                        why)
        for name in amplitudes:
            self._notes[name] = with_more(
                "the velocity axis is now V: vbar is not defined with an in-plane "
                "oscillation", why)

    def _changed(self) -> None:
        """Read every input; on success ask for the curve, else place the message."""
        if self._adjusting:
            return
        self._notes = {}  # what the last change did is no longer news
        self._show_mode()
        self._guard()
        base = self.state.with_(mode=self.mode.value, axis=self.axis.value,
                                log_x=bool(self.log_x.value),
                                inplane_on=self.inplane_on.value, friction=self.law.value,
                                rs_law=self.rs_law.value)
        texts: dict[str, Any] = {n: self.inputs[n].text.value for n in self._names()}
        state, problems = read_inputs(texts, base)
        notes = self._notes
        for name, inp in self.inputs.items():
            inp.show_message(problems.get(name, notes.get(name, "")), note=name not in problems)
        self.general.object = problems.get(GENERAL, "")
        self.general.visible = GENERAL in problems
        law_text = problems.get(LAW, notes.get(LAW, "")) or self._law_standing()
        self.law_note.object = law_text
        self.law_note.styles = ERROR_STYLE if LAW in problems else NOTE_STYLE
        self.law_note.visible = bool(law_text)
        axis_text = problems.get("axis", notes.get("axis", ""))
        self.axis_message.object = axis_text
        self.axis_message.styles = ERROR_STYLE if "axis" in problems else NOTE_STYLE
        self.axis_message.visible = bool(axis_text)
        if state is None:
            return
        mount = mount_note(state)
        self.inplane_note.object = mount
        self.inplane_note.visible = bool(mount)
        for n in self._names():
            self.inputs[n].sync_slider(getattr(state, n))
        self.state = state
        self._want = state
        if not self._busy:
            pn.state.execute(self._refresh)

    def _law_standing(self) -> str:
        """What holds under the chosen law: its solver, ``V = 0`` left out, what it disables."""
        law = self.law.value
        if self.mode.value == "dimensionless" and self.profile.value != "flat":
            taken = ", ".join(friction_laws(CAPABILITIES["mdr"]))
            return with_more(f"a curved tip (the MDR solver) takes: {taken}",
                             "The other laws are taken by the flat punch's solvers "
                             "(docs/friction_laws.md).")
        if law == "coulomb":
            return ""
        solver = CAPABILITIES[law_solver(law)]
        off = self._law_disabled(law)
        short = (f"{solver.title}; V = 0 left out of the curve"
                 + (f"; at most {LAW_POINTS} points" if law == "rate_state" else "")
                 + (f"; disabled: {', '.join(n.removeprefix('bench_') for n in off)}"
                    if off else ""))
        return with_more(short, f"{solver.title} ({solver.takes}) takes {LAWS[law]} friction; "
                                f"velocities: {solver.velocities}.")

    def _message(self, name: str, text: str) -> None:
        if name in self.inputs:
            self.inputs[name].show_message(text)
        else:
            self.general.object = text
            self.general.visible = bool(text)

    def _on_doc(self, func) -> None:
        """Run ``func`` with the document lock held (server) or at once (notebook)."""
        if self._doc is not None:
            self._doc.add_next_tick_callback(func)
        else:
            func()

    # ------------------------------------------------------------------ the curve
    async def _refresh(self) -> None:
        if self._busy:
            return
        self._busy = True
        self._on_doc(partial(setattr, self.busy, "object", BUSY_MARK))
        try:
            while self._want is not None:
                state, self._want = self._want, None
                # what is computed is said only where it takes a while: a line that comes
                # and goes at every move of a slider changes the page's height, and the
                # browser lays the whole page out again each time
                said = asyncio.get_running_loop().call_later(
                    STATUS_AFTER, self._on_doc,
                    partial(setattr, self.status, "object", status_text(state)))
                try:
                    curve = await pool.run_shared(compute.curve, compute.merge, state)
                except Exception as exc:  # the last good view stays; say why, no traceback
                    self._on_doc(partial(self._failed, state, exc))
                    continue
                finally:
                    said.cancel()
                self._on_doc(partial(self._show_curve, state, curve))
        finally:
            self._busy = False
            self._on_doc(partial(setattr, self.busy, "object", ""))
            self._on_doc(partial(setattr, self.status, "object", ""))

    def _failed(self, state: State, exc: Exception) -> None:
        text = str(exc) if isinstance(exc, ValueError) else \
            f"could not compute: {type(exc).__name__}: {exc}"
        self._message(field_of(text, state.mode), text)

    def _show_curve(self, state: State, curve: dict) -> None:
        if self._want is not None and self._want != state:
            return  # a newer state is on its way
        self.curve, self.curve_state = curve, state
        for button in self.downloads:
            button.disabled = False
        fig = self.curve_view.figures["log" if state.log_x else "linear"]
        if self.curve_pane.object is not fig:  # setting it again would re-render the figure
            self.curve_pane.object = fig
        self.curve_view.show(curve, state.log_x)
        self.map_view.show(curve["alpha"], curve["beta"])
        self.readout.object = readout_text(curve)
        self.case_text.object = (flat_side_text if curve["profile"] == "flat punch" else
                                 curved_side_text)(curve, state)
        self.snippet.object = f"```python\n{exports.snippet(state)}```"
        query = urlencode(state.to_query())
        self.link.object = f"Share this view: the page's address holds it (`?{query}`)."
        if self._location is not None:
            self._location.search = f"?{query}" if query else ""
        self._overlay_measurements()
        pn.state.execute(partial(self._history_at_rest, state))

    async def _history_at_rest(self, state: State, rest: float = 0.4) -> None:
        """The history follows the curve once the inputs rest.

        Not at every step of a slider: it would hold up the next curve.
        """
        await asyncio.sleep(rest)
        if self.state is not state or self._want is not None or self._busy:
            return
        assert self.curve is not None  # scheduled when a curve was shown
        x = np.asarray(self.curve["x"], float)
        i = len(x) // 4 if self._picked_x is None or not x[0] <= self._picked_x <= x[-1] \
            else int(np.argmin(np.abs(x - self._picked_x)))
        self._on_doc(partial(self._pick, i))

    # ------------------------------------------------------------------ history
    def _tapped_curve(self, event) -> None:
        c = self.curve
        if c is None or event.x is None:
            return
        x = np.asarray(c["x"], float)
        i = int(np.argmin(np.abs(np.log(np.maximum(x, 1e-300) / max(event.x, 1e-300)))
                          if self.state.log_x else np.abs(x - event.x)))
        self._picked_x = float(x[i])
        self._pick(i)

    def _pick(self, i: int) -> None:
        """Show the history of the curve's point ``i``."""
        c = self.curve
        assert c is not None  # a point of the curve shown
        x = np.asarray(c["x"], float)
        if not np.isfinite(c["y"][i]):
            return
        self.curve_view.pick(float(x[i]), float(c["y"][i]))
        self._point_text = point_text(c, i)
        self._point_y = float(c["y"][i])
        self._history_want = float(x[i])
        if not self._history_busy:
            pn.state.execute(self._refresh_history)

    async def _refresh_history(self) -> None:
        self._history_busy = True
        try:
            while self._history_want is not None:
                x, self._history_want = self._history_want, None
                state = self.state
                try:
                    h = await pool.run(compute.history, state, x)
                except Exception as exc:
                    self._on_doc(partial(self._failed, state, exc))
                    continue
                self._on_doc(partial(self._show_history, state, h))
        finally:
            self._history_busy = False

    def _show_history(self, state: State, h: dict) -> None:
        where = f"{state.axis} = {h['x']:.4g}"
        self.history_quantity.visible = h.get("theta") is not None  # rate-and-state's
        if h.get("curved"):
            self._show_mdr_history(where, h)
            return
        if h["t"] is None:  # the law's solver gives no history: say so
            self.history_view.hide()
            self.spacetime_view.hide()
            self.history_text.object = (
                f"point at {where}: mu/mu0 = {h['mu_ratio']:.6g} ({h['status']}"
                f"{'' if h['trusted'] else ', not trusted'}); {h['message']}; "
                f"{self._point_text}")
            return
        self.history_view.figure.visible = True
        self.spacetime_view.hide()
        self.history_view.show(h, where)
        kinds = sorted({e[1] for e in h["events"]})
        self.history_text.object = (
            f"history at {where}: mu/mu0 = {h['mu_ratio']:.6g} ({h['status']}"
            f"{'' if h['trusted'] else ', not trusted'}); "
            f"{'steady state' if h['steady'] else 'from steady sliding (no trusted steady state)'}"
            f", {len(h['events'])} events ({', '.join(kinds) or 'none'}); "
            f"{self._point_text}")

    def _show_mdr_history(self, where: str, h: dict) -> None:
        """A curved tip: the space-time view of its contact, its forces and its results.

        A curved tip: the space-time view of its contact (or why there is none), the
        forces where the MDR history gives them, and the point's results.
        """
        forces = h.get("t") is not None
        self.history_view.figure.visible = forces
        self.history_view.path_figure.visible = False
        self.history_view.coefficient_figure.visible = False
        self.history_view.theta_figure.visible = False
        if forces:  # the curve's mu/mu0 at the point (the solver's, not the row's estimate)
            self.history_view.show({**h, "mu_ratio": self._point_y}, where)
        self.spacetime_view.show(h, where)
        self.history_text.object = (
            f"point at {where} ({self.curve['profile'] if self.curve else 'curved tip'}, "
            f"MDR): {self._point_text}"
            + (f"; space-time view: {h['message']}" if h.get("message") else ""))

    # ------------------------------------------------------------------ map
    def _tapped_map(self, event) -> None:
        if event.x is None or event.y is None:
            return
        if self.mode.value != "dimensionless":
            self.general.object = ("the map moves the dimensionless inputs: choose "
                                   "'dimensionless' to move there")
            self.general.visible = True
            return
        alpha, beta = float(f"{event.x:.3g}"), float(f"{event.y:.3g}")
        self.inputs["alpha"].text.value = format_value(alpha)
        self.inputs["beta"].text.value = format_value(beta)

    # ------------------------------------------------------------------ bench file
    def _bench_file(self, event) -> None:
        if not event.new:
            return
        import json

        try:
            spec = json.loads(event.new)
            if not isinstance(spec, dict):
                raise ValueError("a bench file holds a JSON object (docs/bench.md)")
            known = {f.name for f in BENCH} | {"du_z", "eta_c"}
            for k in spec:
                if k not in known:
                    raise ValueError(f"bench key {k!r}: the explorer takes "
                                     f"{sorted(known)} (a contact model: use the library)")
        except ValueError as exc:
            self.general.object = f"bench file: {exc}"
            self.general.visible = True
            return
        if "du_z" in spec:
            spec["du_z_um"] = float(spec.pop("du_z")) * 1e6
        if "eta_c" in spec:
            spec["bench_eta_c"] = spec.pop("eta_c")
        for k, v in spec.items():
            self.inputs[k].text.value = format_value(float(v))

    # ------------------------------------------------------------------ measurements
    def _csv_dropped(self, event) -> None:
        if event.new is None:
            return
        try:
            data = compute.parse_measurements(event.new, self.csv_input.filename or "the file")
        except ValueError as exc:
            self.csv_message.object = str(exc)
            self.csv_message.visible = True
            return
        self.csv_message.visible = False
        self.data = data
        self.fit_button.disabled = False
        if self.mode.value != "bench":
            self.csv_message.object = ("measurements are in SI units: choose the bench inputs "
                                       "to overlay them")
            self.csv_message.visible = True
        self._overlay_measurements()

    def _overlay_measurements(self) -> None:
        if self.data is None:
            return
        if self.state.mode != "bench":
            self.curve_view.show_measurements([])
            return
        try:
            groups = compute.measurement_curves(self.state, self.data)
        except ValueError as exc:
            self.csv_message.object = str(exc)
            self.csv_message.visible = True
            return
        self.curve_view.show_measurements(groups)
        self.csv_info.object = (f"overlaid {sum(len(g['x']) for g in groups)} measured points "
                                f"in {len(groups)} group(s): "
                                + "; ".join(g["label"] for g in groups))
        self.csv_message.object = ""
        self.csv_message.visible = False

    def _fit_clicked(self, event) -> None:
        if self.data is None or self.fit_busy.visible:
            return
        pn.state.execute(partial(self._fit, self.state, self.data, tuple(self.free.value)))

    async def _fit(self, state: State, data, free: tuple[str, ...]) -> None:
        self._on_doc(partial(self._fit_running, True))
        try:
            out = await pool.run(compute.run_fit, state, data, free, kind="fit")
        except Exception as exc:
            text = str(exc) if isinstance(exc, ValueError) else f"{type(exc).__name__}: {exc}"
            self._on_doc(partial(self._fit_done, None, f"fit failed: {text}"))
            return
        self._on_doc(partial(self._fit_done, out, None))

    def _fit_running(self, running: bool) -> None:
        self.fit_busy.visible = running
        self.fit_busy.active = running
        self.fit_button.disabled = running
        if running:
            self.fit_report.object = "fitting (tens of seconds; other tabs are not held up)..."

    def _fit_done(self, out: dict | None, error: str | None) -> None:
        self._fit_running(False)
        if out is None:
            self.fit_report.object = error
            return
        self.curve_view.show_fit(out["curves"])
        self.fit_report.object = f"```\n{out['report']}\n```"

    # ------------------------------------------------------------------ export
    def _export(self, fmt: str) -> io.BytesIO:
        """The curve shown as a file (:func:`.exports.curve_file`)."""
        return exports.curve_file(self.curve_state, self.curve, fmt)

def app(state: State | None = None) -> pn.viewable.Viewable:
    """The explorer as a Panel object.

    Serve it, or show it in a notebook (``pn.extension()`` first).
    """
    return Explorer(state).layout
