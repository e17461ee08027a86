"""A sphere: friction of a curved tip, and its stick/slip map
=============================================================

A spherical tip instead of a flat punch. Its contact radius breathes with the normal
oscillation, so at any moment an inner disc of the contact can stick while an outer
ring slips (partial slip), and the friction differs from the flat punch's.

The method of dimensionality reduction (MDR) turns the three-dimensional contact into a
row of independent springs, one per ring of the contact; the solver integrates the row
exactly and refines it until the result is converged (docs/contact_geometry.md).
The system: alpha = 0.5, beta = 2, a = 0.5, at the inertial velocity V = 0.3.

Run:  python examples/sphere_stick_slip.py [output directory]
"""

# %%
# A curved tip is one keyword
# ---------------------------
# ``profile_exponent`` is the exponent :math:`n` of the tip's profile
# :math:`z \propto r^n`: 2 is a sphere (paraboloid), 1 a cone, infinity (the default) the
# flat punch of the paper. Everything else stays as for the flat punch.

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.figure import Figure

import vibrofriction as vf

OUT = Path(sys.argv[1] if len(sys.argv) > 1 else "example_output")
OUT.mkdir(parents=True, exist_ok=True)

SPHERE = vf.Dimensionless(0.5, 2.0, 0.5, profile_exponent=2.0)
FLAT = vf.Dimensionless(0.5, 2.0, 0.5)
V_MAP = 0.3

# %%
# Friction against speed: sphere and flat punch
# ---------------------------------------------
# Both curves start below :math:`\mu_0` and reach it at a critical velocity of continuous
# sliding (:meth:`vibrofriction.Dimensionless.critical_inertial_velocity`, for a curved tip
# too). The sphere's friction is lower at low speed (its lightly loaded rim slips while
# the centre sticks: the map below), but for this system its critical velocity is
# higher. Each point of the sphere states its error, which includes the refinement of
# the row of springs.

V = np.linspace(0.05, 1.2, 24)  # V_MAP = 0.3 is one of them
sphere = vf.friction_coefficient(SPHERE, v_inertial=V)
flat = vf.friction_coefficient(FLAT, v_inertial=V)
print(f"sphere: {int(sphere.trusted.sum())} of {V.size} points trusted, "
      f"largest error {sphere.error.max():.1e}")
print(f"critical velocity: sphere {SPHERE.critical_inertial_velocity():.4f}, "
      f"flat punch {FLAT.critical_inertial_velocity():.4f}")
at = int(np.argmin(abs(V - V_MAP)))
print(f"at V = {V[at]:g}: sphere mu/mu0 = {sphere.mu_ratio[at]:.6f} +- {sphere.error[at]:.1e}, "
      f"flat punch {flat.mu_ratio[at]:.6f}")

# %%
# The steady cycle, ring by ring
# ------------------------------
# :func:`vibrofriction.simulate` with a curved tip integrates the row of springs and
# records, at each sample, every ring's state: stick, slip forwards, slip backwards or
# out of contact. ``initial="steady"`` starts on the periodic orbit, so the history shows
# the steady cycle, not the transient. Over one period the mean tangential force over
# the mean normal force is the friction coefficient: it agrees with the steady solver's
# value to within the latter's error (and the row's own resolution).

h = vf.simulate(SPHERE, v_inertial=V_MAP, periods=1, samples_per_period=400,
                initial="steady", springs=160)
mu_history = np.trapezoid(h.f, h.tau) / np.trapezoid(h.n, h.tau)
print(f"one period of the history: mu/mu0 = {mu_history:.6f}; "
      f"the steady solver: {sphere.mu_ratio[at]:.6f} +- {sphere.error[at]:.1e}")
shares = {name: float(np.mean(h.phase == name))
          for name in ("stick", "partial", "slip+", "slip-", "flight")}
print("share of the period the whole contact is in each state:",
      ", ".join(f"{k} {v:.2f}" for k, v in shares.items()))

# %%
# The stick/slip map
# ------------------
# Each ring's state over the period (right): the contact radius follows the normal
# oscillation, the stick radius (the outermost stuck ring) shows where the inner disc
# holds while the rim slips, forwards (orange) or, as the contact shrinks, backwards (red).
# Dashed on the left: the two critical velocities.

fig = Figure(figsize=(8.0, 3.4), layout="constrained")
left, right = fig.subplots(1, 2)
left.plot(V, flat.mu_ratio, "o-", ms=3, lw=1, color="0.5", label="flat punch")
ok = sphere.trusted
left.plot(V[ok], sphere.mu_ratio[ok], "o-", ms=3, lw=1, color="C0", label="sphere (MDR)")
left.plot(V[~ok], sphere.mu_ratio[~ok], "o", mfc="none", color="C0")  # untrusted
left.axvline(V_MAP, color="C1", ls=":", lw=0.8)  # the map's speed
for system, color in ((FLAT, "0.5"), (SPHERE, "C0")):
    left.axvline(system.critical_inertial_velocity(), color=color, ls="--", lw=0.8)
left.set(xlabel=r"inertial velocity $V$", ylabel=r"$\mu/\mu_0$", ylim=(0, 1.05),
         title=r"$\alpha$ = 0.5, $\beta$ = 2, $a$ = 0.5")
left.legend(fontsize=8, loc="lower right", frameon=False)

colors = ListedColormap(["#2b6cb0", "#f6ad55", "#c53030", "#f7fafc"])  # stick, +, -, flight
period = h.tau / (2 * np.pi)
right.pcolormesh(period, h.xi, h.spring_state.T, cmap=colors, vmin=-0.5, vmax=3.5,
                 shading="nearest", rasterized=True)
right.plot(period, h.contact_radius, "k-", lw=1, label="contact radius")
right.plot(period, h.stick_radius, "w--", lw=1, label="stick radius")
right.set(xlabel="time (drive periods)", ylabel=r"ring radius $r/a_0$",
          title=f"sphere at V = {V_MAP:g}: blue stick, orange slip+, red slip-")
right.title.set_fontsize(9)
right.legend(fontsize=7, loc="upper right", facecolor="0.85")
fig.savefig(OUT / "sphere_stick_slip.png", dpi=150)
print("wrote sphere_stick_slip.png")
