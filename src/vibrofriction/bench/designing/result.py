"""The design's result: :class:`DesignResult`, its statuses and its report."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd
import xarray as xr

from ...params import Physical

#: ``DesignResult.status``: what the optimum rests on.
DESIGN_STATUSES = {
    "trusted": "every point of the map within the limits is trusted",
    "untrusted_in_map": "the map has untrusted points within the limits, none next to the "
                        "optimum",
    "untrusted_near_optimum": "untrusted points lie next to the optimum: a lower value may "
                              "hide among them",
}


@dataclass
class DesignResult:
    """The chosen oscillation and what it is worth.

    ``system``: the pin at the chosen ``omega`` and ``du_z``; ``cof`` and ``mu_ratio``
    there (always a trusted value) and the solver's ``error`` estimate of ``mu_ratio``;
    ``map``: the labelled Dataset over ``(omega, du_z)`` (``cof``, nan where not
    trusted, ``mu_ratio``, ``error``, ``trusted``, ``feasible``) with the optimum and the
    counts in its attributes; ``sensitivity``: the COF when the frequency is off by +-1,
    +-5 % and when each pin parameter is off by +-10 % (a DataFrame with ``change``,
    ``cof``, nan where untrusted, and ``trusted``).

    ``n_untrusted``: untrusted map points within the limits; ``n_untrusted_near``: those
    next to the optimum (its map cell's neighbours); ``n_rejected``: untrusted
    evaluations the refinement rejected (all starts); ``status``: a key of
    :data:`DESIGN_STATUSES`, ``message`` says it with the counts.
    """

    system: Physical
    v0: float
    cof: float
    mu_ratio: float
    error: float
    map: xr.Dataset
    sensitivity: pd.DataFrame
    status: str
    message: str
    n_untrusted: int
    n_untrusted_near: int
    n_rejected: int
    goal: str = "friction"
    velocity_rule: str = "combined"
    directions: pd.DataFrame | None = None
    phase_map: xr.Dataset | None = None
    blocking: tuple[float, float] | None = None
    blocking_trusted: bool | None = None
    idle_velocity: float | None = None
    idle_message: str = ""

    @property
    def trusted(self) -> bool:
        """Whether every point of the map within the limits is trusted (status ``trusted``)."""
        return self.status == "trusted"

    @property
    def inplane(self) -> bool:
        """Whether the design was allowed an in-plane oscillation (``du_x`` given)."""
        return "du_x" in self.map.dims

    @property
    def drive_ratio(self) -> float:
        """The drive force at ``v0`` in units of ``mu0 <F_N>``.

        ``-mu_ratio``, positive where the oscillation pushes the slider forward against a
        load.
        """
        return -self.mu_ratio

    def report(self) -> str:
        """The design in words: the optimum, its COF and status, and its sensitivities."""
        s = self.system
        if not self.inplane:
            lines = [f"optimum at v0 = {self.v0:g} m/s: f = {s.omega / (2 * math.pi):.6g} Hz, "
                     f"du_z = {s.du_z:.4g} m (velocity amplitude {s.omega * s.du_z:.4g} "
                     f"m/s): COF {self.cof:.5g} (mu/mu0 = {self.mu_ratio:.5g}, solver error "
                     f"{self.error:.1e})"]
        else:
            what = ("largest drive force" if self.goal == "drive" else
                    "smallest friction force |COF|")
            across = (f", du_y = {s.du_y:.4g} m, phase_y = {s.phase_y:.4f} rad (across the "
                      f"sliding)" if s.du_y > 0.0 else "")
            lines = [f"{what} at v0 = {self.v0:g} m/s ({s.inplane_on}): f = "
                     f"{s.omega / (2 * math.pi):.6g} Hz, du_z = {s.du_z:.4g} m, du_x = "
                     f"{s.du_x:.4g} m, phase_x = {s.phase_x:.4f} rad{across} (combined "
                     f"velocity amplitude "
                     f"{s.omega * math.hypot(s.du_z, s.du_x, s.du_y):.4g} m/s): COF "
                     f"{self.cof:.5g} (mu/mu0 = {self.mu_ratio:.5g}, solver error "
                     f"{self.error:.1e})"]
            if self.goal == "drive":
                lines.append(f"drive force at v0: {self.drive_ratio:.5g} mu0 <F_N>")
                if self.blocking is not None:
                    flag = "" if self.blocking_trusted else " (UNTRUSTED)"
                    lines.append(f"blocking force: mu/mu0 = {self.blocking[0]:+.5g} at V -> 0+, "
                                 f"{self.blocking[1]:+.5g} at V -> 0-{flag}")
                lines.append(f"idle velocity: {self.idle_message}")
        if s.friction is not None:
            lines.append(f"local friction: rate-and-state, {s.friction!r}, mu_star = mu0 = "
                         f"{s.mu0:g}")
        elif s.static_ratio != 1.0:
            lines.append(f"local friction: static above kinetic, mu_static = {s.mu_static:g}, "
                         f"mu0 = {s.mu0:g}")
        lines += [f"status: {self.status}: {self.message}"]
        if self.directions is not None:
            lines.append("which direction (best within the same limits):")
            for _, row in self.directions.iterrows():
                inplane = (f"du_y = {row['du_y']:.3g} m, phase_y = {row['phase_y']:.3f}"
                           if row.get("du_y", 0.0) > 0.0 else
                           f"du_x = {row['du_x']:.3g} m, phase_x = {row['phase_x']:.3f}")
                value = ("not allowed by the ranges" if not np.isfinite(row["cof"]) else
                         f"COF {row['cof']:.5g} at f = {row['omega'] / (2 * math.pi):.5g} Hz, "
                         f"du_z = {row['du_z']:.3g} m, {inplane}")
                lines.append(f"  {row['direction']:>18s}: {value}")
        lines.append("sensitivity (COF):")
        for _, row in self.sensitivity.iterrows():
            value = f"{row['cof']:.5g}" if row["trusted"] else "untrusted (no value)"
            lines.append(f"  {row['change']:>28s}: {value}")
        return "\n".join(lines)
