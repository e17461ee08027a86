"""Share and reuse.

The curve as CSV, as a figure (PNG, SVG), and as a Python snippet that recomputes it with the
library.
"""

from __future__ import annotations

import io
import math

import numpy as np

from .compute import law_text, not_computed, solver_text
from .state import State

__all__ = ["curve_csv", "curve_file", "figure_bytes", "snippet"]


def curve_csv(state: State, curve: dict) -> str:
    """The curve as CSV: velocity, value, status, error, trusted (one row a point)."""
    axis = state.axis
    lines = [f"# vibrofriction explorer: {_system_text(state)}",
             f"# case {curve['case']}; static value {curve['static']:.10g}; "
             f"critical velocity ({axis}) {curve['critical']:.10g}",
             *([f"# {curve['rest_note']}"] if curve.get("rest_note") else []),
             f"{axis},{'cof' if curve['mu0'] else 'mu_ratio'},status,error,trusted"]
    for x, y, s, e, t in zip(curve["x"], curve["y"], curve["status"], curve["error"],
                             curve["trusted"], strict=True):
        lines.append(f"{float(x)!r},{float(y)!r},{s},{float(e)!r},{bool(t)}")
    return "\n".join(lines) + "\n"


def _system_text(state: State) -> str:
    if state.mode == "dimensionless":
        return (f"alpha = {state.alpha!r}, beta = {state.beta!r}, a = {state.amplitude!r}, "
                f"zeta = {state.zeta!r}, eta_c = {state.eta_c!r}"
                + (f", a_x = {state.a_x!r}, phase_x = {state.phase_x!r} on the "
                   f"{state.inplane_on}" if state.a_x else "")
                + (f", profile_exponent = {state.profile_exponent!r}" if state.curved
                   else "") + f"; friction: {law_text(state)}")
    return (", ".join(f"{k} = {v!r}" for k, v in state.bench_arguments().items())
            + f"; friction: {law_text(state)}")


def _law_code(state: State) -> str:
    """The friction law as keyword arguments of the code (empty for Coulomb)."""
    law = state.law_arguments()
    rs = law.pop("friction", None)
    if rs is not None:  # a bench's rate-and-state law, in SI
        law["friction"] = (f"vf.RateAndState(a={rs.a!r}, b={rs.b!r}, d_c={rs.d_c!r}, "
                           f"v_ref={rs.v_ref!r}, alpha_ld={rs.alpha_ld!r}, law={rs.law!r})")
        return ", ".join(f"{k}={v}" for k, v in law.items())
    return ", ".join(f"{k}={v!r}" for k, v in law.items())


def snippet(state: State) -> str:
    """Python code that recomputes the current curve with the library."""
    if state.mode == "dimensionless":
        make = (f"system = vf.Dimensionless(alpha={state.alpha!r}, beta={_num(state.beta)}, "
                f"amplitude={state.amplitude!r}, zeta={state.zeta!r}, eta_c={state.eta_c!r}"
                + (f", a_x={state.a_x!r}, phase_x={state.phase_x!r}, "
                   f"inplane_on={state.inplane_on!r}" if state.a_x else "")
                + (f", profile_exponent={state.profile_exponent!r}" if state.curved else "")
                + (f",\n    {law}" if (law := _law_code(state)) else "") + ")")
    else:
        args = ",\n    ".join(f"{k}={_num(v)}" for k, v in state.bench_arguments().items())
        make = f"system = vf.from_bench(\n    {args})"
        if law := _law_code(state):
            make += f".with_(\n    {law})"
    space = "geomspace" if state.log_x else "linspace"
    scale = " * system.mu0" if state.mode == "bench" else ""
    return "\n".join([
        "import math",
        "",
        "import numpy as np",
        "",
        "import vibrofriction as vf",
        "",
        make,
        f"{state.axis} = np.{space}({state.v_min!r}, {state.v_max!r}, "
        f"{state.curve_points})",
        *([f"{state.axis} = {state.axis}[{state.axis} != 0]  # {_rest_why(state)}"]
          if state.rest_refused else []),
        f"r = vf.friction_coefficient(system, {state.velocity_keyword()}={state.axis})",
        f"y = r.mu_ratio{scale}  # {'COF' if scale else 'mu/mu0'}; r.trusted flags each point",
    ]) + "\n"


def _rest_why(state: State) -> str:
    """Why ``V = 0`` is no point of the curve (:attr:`State.rest_refused`), as a comment."""
    if state.curved:
        return "the MDR solver refuses V = 0 with a_x > 0"
    return ("the 1-D solver has no static limit of a static coefficient" if
            state.friction == "static" else "rate-and-state friction creeps: no V = 0")


def _num(x: float) -> str:
    return "math.inf" if math.isinf(x) else repr(x)


def figure_bytes(curve: dict, fmt: str = "png") -> bytes:
    """The curve as a matplotlib figure (``png`` or ``svg``).

    Trusted points solid, untrusted hollow grey, the static value, the critical velocity, the closed
    forms.
    """
    from matplotlib.figure import Figure

    if fmt not in ("png", "svg"):
        raise ValueError(f"fmt must be 'png' or 'svg', got {fmt!r}")
    fig = Figure(figsize=(6.4, 4.2), layout="constrained")
    ax = fig.subplots()
    x, y, ok = curve["x"], curve["y"], curve["trusted"]
    solver = solver_text(curve)
    line_x, line_y = x, np.where(ok, y, np.nan)
    k = int(np.searchsorted(x, 0.0))
    if curve.get("rest_note") and 0 < k < len(x):  # V = 0 left out: the line breaks
        line_x, line_y = np.insert(x, k, 0.0), np.insert(line_y, k, np.nan)
    ax.plot(line_x, line_y, "-", color="C0", lw=1.5, label=solver)
    bad = ~ok & np.isfinite(y)
    if np.any(bad):
        ax.plot(x[bad], y[bad], "o", mfc="none", color="0.5", ms=4,
                label="not trusted (solver)")
    gap = not_computed(curve)
    if np.any(gap):  # no value: marked on the bottom edge
        ax.plot(x[gap], np.full(int(gap.sum()), 0.02), "v", mfc="none", color="0.5", ms=5,
                transform=ax.get_xaxis_transform(), clip_on=False,
                label="not trusted, no value")
    for k, form in enumerate(curve["closed_forms"]):
        ax.plot(form["x"], form["y"], "--", color=f"C{k + 1}", lw=1.2, label=form["label"])
    if math.isfinite(curve["static"]):
        ax.plot([x[0]], [curve["static"]], "s", color="k", ms=5, label="static value, eq. (2)")
    if math.isfinite(curve["critical"]):
        ax.axvline(curve["critical"], color="C3", lw=0.8, ls=":",
                   label=curve.get("critical_label", "critical velocity, eq. (12)"))
    ax.set_xlabel(curve["x_label"])
    ax.set_ylabel(curve["y_label"])
    ax.set_title(f"alpha = {curve['alpha']:.4g}, beta = {curve['beta']:.4g}, "
                 f"a = {curve['amplitude']:.4g}: case {curve['case']}", fontsize=9)
    ax.legend(fontsize=7)
    buf = io.BytesIO()
    fig.savefig(buf, format=fmt, dpi=150)
    return buf.getvalue()


def curve_file(state: State | None, curve: dict | None, fmt: str) -> io.BytesIO:
    """The curve shown (with the inputs ``state`` it was computed for) as a file.

    ``fmt`` is ``"csv"`` or a figure format (``"png"``, ``"svg"``). Never an empty file:
    before the first curve there is nothing to export (``RuntimeError``; the page keeps
    its buttons disabled until then).
    """
    if curve is None:
        raise RuntimeError("no curve has been computed yet: nothing to export")
    if fmt == "csv":
        assert state is not None  # set with the curve
        return io.BytesIO(curve_csv(state, curve).encode())
    return io.BytesIO(figure_bytes(curve, fmt))
