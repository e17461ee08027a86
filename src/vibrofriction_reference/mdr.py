"""A spring-row reference for a real contact geometry by the MDR (issue 21).

Its own code: it imports nothing from ``vibrofriction`` (import-linter contract), and
shares nothing with the single-spring peers of this package but the initial-state codes.

**The model** (docs/contact_geometry.md). A body of mass ``m`` on the system spring ``k_x``
and the dashpot ``c_x``, pulled at ``v0``; the contact is the MDR row of the profile
``z = c r^n``: springs on ``g(x) = kappa_n c |x|^n``, the one at ``x`` of normal force
``E* (d(t) - g(x)) dx`` while positive and of tangential stiffness ``G* dx``, each with its
own Coulomb law (stick while ``|f_i| <= mu0 N_i``, else slide with ``f_i = mu0 N_i
sign``), unloaded (elongation reset to 0) out of contact and starting unloaded when it
touches down. The indentation is imposed, ``d = d0 (1 + a cos omega t)``.

**Scaled** as in docs/model.md with the issue's scaling: ``F_N0 = F(d0)``,
``k_xc0 = 2 G* a0`` (the fully stuck contact at ``d0``), ``alpha = k_x/(m omega^2)``,
``beta = (k_x + k_xc0)/(m omega^2)``, ``V = v0 m omega/(mu0 F_N0)``, force unit
``mu0 F_N0``, ``gamma = c_x/(m omega) = 2 zeta sqrt(alpha)``. With ``xi = x/a0``,
``g/d0 = xi^n`` and ``F_N0 = 2 E* d0 a0 n/(n + 1)``, the springs on ``xi in (0, xi_max]``,
``xi_max = (1 + a)^{1/n}`` (each of width ``dxi`` standing for both sides ``+-x``) have::

    n_i(tau) = dxi (n + 1)/n max(0, 1 + a cos tau - xi_i^n),   k_i = (beta - alpha) dxi,
    x'' = alpha (V tau - x) + gamma (V - x') - sum f_i,        |f_i| <= n_i,

so the scaled model depends on the profile through ``n`` only. The flat punch
(``n = inf``) is ``xi in (0, 1]``, ``n_i = dxi (1 + a cos tau)``: every spring carries the
same share, and the row is the single spring of docs/model.md exactly.

**In-plane oscillation along the sliding** (issue 20, docs/inplane.md), written in the
laboratory frame: ``X(tau) = a_x cos(tau + phase_x)`` moves either the pulled end of the
pin's spring and dashpot (``inplane_on="holder"``: the pin pulls with ``alpha (V tau + X
- x) + gamma (V + X' - x')``) or the substrate (``"substrate"``): every spring's contact
point is carried by the substrate while it sticks, so its elongation ``x - x_c,i`` changes
by the body's displacement minus the substrate's over a step, and it slides where the
body moves relative to the substrate.

**Scheme**: velocity Verlet for the body (the pin dashpot trapezoidal: implicit in the
second half-kick), a return mapping per spring per step (elastic predictor from the
body's displacement over the step, projection onto ``|f_i| <= n_i``); a spring touching
down inside a step starts unloaded at the touch-down instant, placed by linear
interpolation of its gap ``1 + a cos tau - xi_i^n``. Springs at the midpoints
``xi_i = (i - 1/2) dxi``. Means by the trapezoid rule over whole drive periods.
:func:`mdr_reference` runs two resolutions and states their difference as the error bar.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from .model import INITIAL_SLIDING, check_count, check_windows, initial_code

__all__ = ["MDRMean", "MDRReference", "mdr_mean", "mdr_reference"]


@njit(cache=True)
def _row(alpha, beta, a, V, gamma, n_exp, M, N, n_total, avg_start, initial, record_from,
         a_x, phase_x, holder):
    """One run.

    Returns the trapezoid sums of sum_i f_i and sum_i n_i over the averaging window, their
    per-period sums and, from step ``record_from`` on, every spring's f_i and n_i (arrays (steps,
    M)). ``a_x``, ``phase_x``: the in-plane oscillation ``X``, of the holder if ``holder`` else of
    the substrate (module docstring).
    """
    k = beta - alpha
    flat = math.isinf(n_exp)
    xi_max = 1.0 if flat else (1.0 + a) ** (1.0 / n_exp)
    dxi = xi_max / M
    wn = dxi if flat else dxi * (n_exp + 1.0) / n_exp
    ks = k * dxi
    g = np.zeros(M)
    if not flat:
        for i in range(M):
            g[i] = ((i + 0.5) * dxi) ** n_exp
    dt = 2.0 * math.pi / N
    e = np.zeros(M)
    if initial == 0:  # steady sliding at d0: every loaded spring at its limit
        y = -1.0 / alpha
        v = 0.0
        for i in range(M):
            e[i] = wn * max(0.0, 1.0 - g[i]) / ks
    else:
        y = 0.0
        v = -V
    F = 0.0
    Ntot = 0.0
    for i in range(M):
        F += ks * e[i]
        Ntot += wn * max(0.0, 1.0 + a - g[i])
    nrec = max(0, n_total - record_from + 1) if record_from >= 0 else 0
    rec_f = np.zeros((nrec, M))
    rec_n = np.zeros((nrec, M))
    n_avg = (n_total - avg_start) // N
    pf = np.zeros(n_avg)
    pn = np.zeros(n_avg)
    sf = 0.0
    sn = 0.0
    if avg_start == 0:
        sf += 0.5 * F
        sn += 0.5 * Ntot
    c_old = 1.0
    # X and X' at the step's start (the holder's, or the substrate's position)
    Xh0, Xhd0, Xs0 = 0.0, 0.0, 0.0
    if a_x > 0.0:
        if holder:
            Xh0, Xhd0 = a_x * math.cos(phase_x), -a_x * math.sin(phase_x)
        else:
            Xs0 = a_x * math.cos(phase_x)
    for m in range(n_total):
        c_old = 1.0 + a * math.cos((m % N) * dt)
        c_new = 1.0 + a * math.cos(((m + 1) % N) * dt)
        Xh1, Xhd1, Xs1 = 0.0, 0.0, 0.0
        if a_x > 0.0:
            ph = ((m + 1) % N) * dt + phase_x
            if holder:
                Xh1, Xhd1 = a_x * math.cos(ph), -a_x * math.sin(ph)
            else:
                Xs1 = a_x * math.cos(ph)
        F_prev = F
        N_prev = Ntot
        # the pin: alpha (V tau + X_h - x) + gamma (V + X_h' - x'), y = x - V tau, v = y'
        vh = v + 0.5 * dt * (alpha * (Xh0 - y) + gamma * (Xhd0 - v) - F)
        y += dt * vh
        # the body's displacement over the step relative to the substrate
        dx = dt * (vh + V) - (Xs1 - Xs0)
        F = 0.0
        Ntot = 0.0
        rec = record_from >= 0 and m + 1 >= record_from
        for i in range(M):
            s_new = c_new - g[i]
            if s_new <= 0.0:
                e[i] = 0.0
                continue
            s_old = c_old - g[i]
            if s_old <= 0.0:  # touch-down inside the step: unloaded from that instant
                phi = s_old / (s_old - s_new)
                etr = (1.0 - phi) * dx
            else:
                etr = e[i] + dx
            lim = wn * s_new
            ftr = ks * etr
            if ftr > lim:
                ftr = lim
            elif ftr < -lim:
                ftr = -lim
            e[i] = ftr / ks
            F += ftr
            Ntot += lim
            if rec:
                rec_f[m + 1 - record_from, i] = ftr
                rec_n[m + 1 - record_from, i] = lim
        v = (vh + 0.5 * dt * (alpha * (Xh1 - y) + gamma * Xhd1 - F)) / (1.0 + 0.5 * dt * gamma)
        Xh0, Xhd0, Xs0 = Xh1, Xhd1, Xs1
        step = m + 1
        if step > avg_start:
            w = 0.5 if step == n_total else 1.0
            sf += w * F
            sn += w * Ntot
            j = (m - avg_start) // N
            pf[j] += 0.5 * (F_prev + F)
            pn[j] += 0.5 * (N_prev + Ntot)
        elif step == avg_start:
            sf += 0.5 * F
            sn += 0.5 * Ntot
    return sf, sn, pf, pn, rec_f, rec_n


def _check(alpha, beta, amplitude, V, profile_exponent, zeta):
    out = []
    for name, value, lo, inf_ok in (("alpha", alpha, 0.0, False), ("beta", beta, alpha, False),
                                     ("amplitude", amplitude, None, False),
                                     ("V", V, None, False),
                                     ("profile_exponent", profile_exponent, 0.0, True),
                                     ("zeta", zeta, None, False)):
        value = float(value)
        if math.isnan(value) or (math.isinf(value) and not inf_ok):
            raise ValueError(f"{name} must be a finite number, got {value}")
        if lo is not None and not value > lo:
            raise ValueError(f"{name} must be > {lo} (in ({lo}, inf{']' if inf_ok else ')'}), "
                             f"got {value}")
        if name in ("amplitude", "zeta") and value < 0.0:
            raise ValueError(f"{name} must be in [0, inf), got {value}")
        out.append(value)
    return out


def _check_inplane(a_x, phase_x, inplane_on):
    a_x, phase_x = float(a_x), float(phase_x)
    if not (math.isfinite(a_x) and a_x >= 0.0):
        raise ValueError(f"a_x must be in [0, inf) (finite and >= 0), got {a_x}")
    if not math.isfinite(phase_x):
        raise ValueError(f"phase_x must be a finite number, got {phase_x}")
    if inplane_on not in ("substrate", "holder"):
        raise ValueError(f"inplane_on must be 'substrate' or 'holder', got {inplane_on!r}")
    return a_x, phase_x, inplane_on == "holder"


def _steps(alpha, beta, steps_per_period):
    steps_per_period = float(steps_per_period)
    if not (steps_per_period > 0.0 and math.isfinite(steps_per_period)):
        raise ValueError(f"steps_per_period must be in (0, inf), got {steps_per_period}")
    w = max(1.0, math.sqrt(alpha), math.sqrt(beta))
    return max(4, int(math.ceil(steps_per_period * w - 1e-9)))


@dataclass(frozen=True)
class MDRMean:
    """One run of :func:`mdr_mean`.

    ``mu_ratio = <F_x>/(mu0 <F_N>)``, ``mean_normal_ratio = <F_N>/F_N0`` (of the discrete row), the
    per-period means of ``sum f_i`` and ``sum n_i`` over the averaging window, the resolution, and
    (if asked) every spring's ``f_i``, ``n_i`` over the last period (arrays (steps + 1, springs)).
    """

    mu_ratio: float
    mean_normal_ratio: float
    period_f: np.ndarray
    period_n: np.ndarray
    springs: int
    steps_per_drive_period: int
    spring_f: np.ndarray | None = None
    spring_n: np.ndarray | None = None

    def mu_ratio_over(self, start: int = 0, stop: int | None = None) -> float:
        """``<f>/<n>`` over the window's periods ``start..stop - 1``."""
        return float(np.sum(self.period_f[start:stop]) / np.sum(self.period_n[start:stop]))


def mdr_mean(alpha: float, beta: float, amplitude: float, V: float,
             profile_exponent: float = math.inf, springs: int = 200,
             steps_per_period: float = 400, transient_periods: int = 200,
             average_periods: int = 50, initial: int | str = INITIAL_SLIDING,
             zeta: float = 0.0, record_last_period: bool = False, *, a_x: float = 0.0,
             phase_x: float = 0.0, inplane_on: str = "substrate") -> MDRMean:
    """One fixed-resolution run of the MDR spring row (module docstring), scaled.

    ``profile_exponent`` ``n`` of ``z = c r^n`` (``math.inf``: flat punch), ``springs``
    on ``(0, (1 + a)^{1/n}]``, ``steps_per_period`` per period of the fastest of the drive,
    ``sqrt(alpha)`` and ``sqrt(beta)`` (rounded up to whole steps per drive period),
    ``zeta`` the pin's damping ratio. Initial ``"sliding"`` (``x = -1/alpha``,
    ``x' = V``, every loaded spring at its friction limit at ``d0``; laboratory frame) or
    ``"rest"``. ``a_x``, ``phase_x``, ``inplane_on``: the longitudinal in-plane
    oscillation ``a_x cos(tau + phase_x)`` of the substrate or the holder (module
    docstring), switched on at ``tau = 0``. ValueError naming a parameter outside its
    range (``beta`` finite and ``> alpha``).
    """
    alpha, beta, amplitude, V, n_exp, zeta = _check(alpha, beta, amplitude, V,
                                                    profile_exponent, zeta)
    a_x, phase_x, holder = _check_inplane(a_x, phase_x, inplane_on)
    M = check_count("springs", springs, 1)
    transient_periods, average_periods = check_windows(transient_periods, average_periods)
    N = _steps(alpha, beta, steps_per_period)
    n_total = N * (transient_periods + average_periods)
    avg_start = N * transient_periods
    record_from = n_total - N if record_last_period else -1
    gamma = 2.0 * zeta * math.sqrt(alpha)
    sf, sn, pf, pn, rf, rn = _row(alpha, beta, amplitude, V, gamma, n_exp, M, N, n_total,
                                  avg_start, initial_code(initial), record_from, a_x,
                                  phase_x, holder)
    steps = n_total - avg_start
    return MDRMean(sf / sn, sn / steps, pf / N, pn / N, M, N,
                   rf if record_last_period else None, rn if record_last_period else None)


@dataclass(frozen=True)
class MDRReference:
    """The result of :func:`mdr_reference`.

    The finest run's ``mu_ratio`` and ``mean_normal_ratio`` with error bars (the differences from
    the coarser run), and both runs.
    """

    mu_ratio: float
    mu_error: float
    mean_normal_ratio: float
    normal_error: float
    runs: tuple[MDRMean, MDRMean]


def mdr_reference(alpha: float, beta: float, amplitude: float, V: float,
                  profile_exponent: float = math.inf,
                  resolutions: tuple[tuple[int, float], tuple[int, float]] = ((100, 200),
                                                                               (200, 400)),
                  transient_periods: int = 200, average_periods: int = 50,
                  initial: int | str = INITIAL_SLIDING, zeta: float = 0.0, *,
                  a_x: float = 0.0, phase_x: float = 0.0,
                  inplane_on: str = "substrate") -> MDRReference:
    """The row at two resolutions ``(springs, steps_per_period)``.

    The second is reported, and the error bar is ``|fine - coarse|`` (for a second-order scheme
    refined by 2, three times the fine run's own error, measured in docs/contact_geometry.md).
    ``a_x``, ``phase_x``, ``inplane_on`` as in :func:`mdr_mean`.
    """
    runs = tuple(mdr_mean(alpha, beta, amplitude, V, profile_exponent, springs, steps,
                          transient_periods, average_periods, initial, zeta, a_x=a_x,
                          phase_x=phase_x, inplane_on=inplane_on)
                 for springs, steps in resolutions)
    if len(runs) != 2:
        raise ValueError(f"resolutions must be two (springs, steps_per_period) pairs, "
                         f"got {resolutions!r}")
    coarse, fine = runs
    return MDRReference(fine.mu_ratio, abs(fine.mu_ratio - coarse.mu_ratio),
                        fine.mean_normal_ratio,
                        abs(fine.mean_normal_ratio - coarse.mean_normal_ratio), (coarse, fine))
