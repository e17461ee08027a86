"""The explorer's input widget.

A slider and a text box for one parameter, kept in step, with its message line; and the styles of
the page's messages and notes.
"""

from __future__ import annotations

import math

import panel as pn

from .state import (
    Field,
    format_value,
)

ERROR_STYLE = {"color": "#b00020", "font-size": "12px", "margin": "0 10px"}
NOTE_STYLE = {"color": "#444444", "font-size": "12px", "margin": "0 10px"}


class Input:
    """A numeric input.

    A slider (logarithmic where the range spans decades), a box for the exact value, and the
    inline message.
    """

    def __init__(self, field: Field, value: float, on_change) -> None:
        self.field = field
        lo, hi = (math.log10(field.low), math.log10(field.high)) if field.log else \
            (field.low, field.high)
        self.slider = pn.widgets.FloatSlider(label=field.label, start=lo, end=hi,
                                             step=(hi - lo) / 200, value=self._position(value),
                                             show_value=False, width=190,
                                             css_classes=[f"vf-slider-{field.name}"])
        self.text = pn.widgets.TextInput(value=format_value(value), width=110,
                                         css_classes=[f"vf-text-{field.name}"],
                                         margin=(22, 5, 5, 5))
        self.message = pn.pane.HTML("", styles=ERROR_STYLE, visible=False, width=310,
                                    css_classes=[f"vf-message-{field.name}"])
        self._quiet = False
        self._on_change = on_change
        self.slider.param.watch(self._slid, "value")
        self.text.param.watch(self._typed, "value")
        self.layout = pn.Column(pn.Row(self.slider, self.text, margin=0), self.message,
                                margin=0)

    def _position(self, value: float) -> float:
        f = self.field
        if not math.isfinite(value):
            return math.log10(f.high) if f.log else f.high
        v = min(max(value, f.low), f.high)
        return math.log10(max(v, 1e-300)) if f.log else v

    def _slid(self, event) -> None:
        if self._quiet:
            return
        value = 10.0 ** event.new if self.field.log else event.new
        self.text.value = format_value(float(f"{value:.4g}"))

    def _typed(self, event) -> None:
        self._on_change()

    def set(self, value: float) -> None:
        """Show ``value`` (from the URL, the map or a bench file)."""
        self.text.value = format_value(value)

    def sync_slider(self, value: float) -> None:
        """Move the slider to ``value`` without calling back."""
        self._quiet = True
        try:
            self.slider.value = self._position(value)
        finally:
            self._quiet = False

    def show_message(self, text: str, note: bool = False) -> None:
        """Show ``text`` below the input (``note``: what the page did); hidden when empty."""
        self.message.object = text
        self.message.styles = NOTE_STYLE if note else ERROR_STYLE
        self.message.visible = bool(text)

    def enable(self, on: bool) -> None:
        """Enable or disable the slider and the box."""
        self.slider.disabled = not on
        self.text.disabled = not on
