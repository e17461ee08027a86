"""A check of the MDR row without springs under a prescribed motion (issue 35's first lead).

Not a solver: it checks the representation a continuum MDR solver would carry, on a
prescribed body displacement ``u(tau)`` and indentation ``delta(tau) = 1 + a cos tau`` (no
body dynamics, no steady state).

Each point ``xi`` of the MDR row (gap ``g = xi^n``) is a play operator: its elongation
``e`` shifts with ``u`` while stuck, is held within ``|e| <= c (delta - g)`` (``c = w/k``:
the normal force ``w (delta - g)`` per unit ``xi`` over the tangential stiffness), enters
contact with ``e = 0`` and forgets on leaving.  Over a time step whose band edges
``u +- c (delta - g)`` move monotonically the new profile is ``clamp(e + du, -r, r)``,
exactly.  The row without springs keeps the profile as a list of pieces over ``xi``:

* ``AFF (A, B)``: ``e = A + B g(xi)`` (slipping, on the band's edge; or stuck since a slip
  ended); a clamp writes ``(+-c delta, -+c)``, a shift adds ``du`` to ``A``, and where it
  meets the band is a closed form in ``g``;
* ``HIST (cycle)``: ``e = u - u(tau_on(xi))``, stuck since touch-down in that loading
  branch (``tau_on`` the touch-down time); where it meets the band is a root on the stored
  history (found here by sampling and bisection), its force an integral over the history
  (here Gauss-Legendre in ``tau``, where ``xi = delta^(1/n)`` is smooth).

The row's force ``k int e dxi`` is then exact per piece.  The spring row (``M`` springs at
the cells' midpoints) stepped by the same rule on the same time steps must converge to it
as ``M`` grows, so this isolates the discretisation in ``xi``; the largest number of pieces
says what a continuum solver would carry.

``--dynamics`` also couples the row to the body (:func:`coupled`: ``y'' + gamma y' + alpha y
= -F``, ``u = y + V tau``, velocity Verlet with the damping by the trapezoidal rule, from
steady sliding, 80 periods, the mean over the last) at a few points and compares
``mu_ratio`` with the MDR solver's answer and stated error (a few minutes: plain Python).

    PYTHONPATH=src python benchmarks/mdr_continuum_check.py [--dynamics] [--write]

``--write`` appends the run to benchmarks/results/mdr_continuum.md.
"""

from __future__ import annotations

import argparse
import bisect
import math
from pathlib import Path

import numpy as np

from sections import append_run

RESULTS = Path(__file__).parent / "results" / "mdr_continuum.md"
#: (n, a, V, A): the profile's exponent, the normal amplitude and the prescribed
#: displacement u = V tau + A sin(tau + 0.4) + A/4 sin(2 tau)
CASES = [(2.0, 0.7, 0.3, 0.8), (1.0, 0.7, 0.3, 0.8), (4.0, 0.5, 0.1, 0.3),
         (2.0, 0.95, 0.05, 0.5), (1.5, 0.3, 0.02, 0.05), (2.0, 1.5, 0.3, 0.5),
         (1.0, 1.3, 0.2, 0.4)]
SPRINGS = (100, 400, 1600, 6400)
CYCLES, STEPS = 4, 2000  # drive cycles, time steps a cycle
SLIVER = 1e-12  # a sub-piece narrower than this (two cuts at one point) is dropped
GL_X, GL_W = np.polynomial.legendre.leggauss(24)


class Motion:
    """The prescribed motion and the row's constants of one case."""

    def __init__(self, n: float, a: float, V: float, A: float) -> None:
        self.n, self.a, self.V, self.A = n, a, V, A
        self.c = (n + 1.0) / n  # w / k with k = 1

    def u(self, t: float) -> float:
        return self.V * t + self.A * math.sin(t + 0.4) + 0.25 * self.A * math.sin(2.0 * t)

    def delta(self, t: float) -> float:
        return 1.0 + self.a * math.cos(t)

    def tau_on(self, xi: float, cycle: int) -> float:
        """The touch-down time of ``xi`` in loading branch ``cycle`` (``delta`` rising:
        ``tau`` in ``((2 cycle - 1) pi, 2 cycle pi)``)."""
        x = min(1.0, max(-1.0, (xi ** self.n - 1.0) / self.a))
        return 2.0 * math.pi * cycle - math.acos(x)

    def radius(self, t: float) -> float:
        return max(self.delta(t), 0.0) ** (1.0 / self.n)


def _clamp(m: Motion, p: list, d1: float, u1: float) -> list[list]:
    """The sub-pieces of piece ``p`` after the clamp to ``|e| <= c (d1 - g)``."""
    x0, x1 = p[0], p[1]

    def e(x: float) -> float:
        return p[3] + p[4] * x ** m.n if p[2] == "AFF" else u1 - m.u(m.tau_on(x, p[3]))

    def over(x: float) -> float:  # > 0: above the band
        return e(x) - m.c * (d1 - x ** m.n)

    def under(x: float) -> float:  # < 0: below it
        return e(x) + m.c * (d1 - x ** m.n)

    cuts = {x0, x1}
    for f in (over, under):
        if p[2] == "AFF":  # affine in g: its root in closed form
            f0, slope = f(0.0), f(1.0) - f(0.0)
            if slope != 0.0 and -f0 / slope > 0.0:
                x = (-f0 / slope) ** (1.0 / m.n)
                if x0 < x < x1:
                    cuts.add(x)
        else:  # on the history: sampled, then bisected
            xs = np.linspace(x0, x1, 65)
            vs = [f(x) for x in xs]
            for i in range(64):
                if vs[i] * vs[i + 1] < 0.0:
                    lo, hi, flo = xs[i], xs[i + 1], vs[i]
                    for _ in range(60):
                        mid = 0.5 * (lo + hi)
                        if (f(mid) < 0.0) == (flo < 0.0):
                            lo = mid
                        else:
                            hi = mid
                    cuts.add(0.5 * (lo + hi))
    cuts_sorted = sorted(cuts)
    out = []
    for xa, xb in zip(cuts_sorted[:-1], cuts_sorted[1:], strict=True):
        if xb - xa <= SLIVER:
            continue
        xm = 0.5 * (xa + xb)
        if over(xm) > 0.0:
            out.append([xa, xb, "AFF", m.c * d1, -m.c])
        elif under(xm) < 0.0:
            out.append([xa, xb, "AFF", -m.c * d1, m.c])
        else:
            out.append([xa, xb, *p[2:]])
    return out


def _merge(pieces: list[list]) -> list[list]:
    """Neighbours of the same formula as one piece (and no gap a dropped sliver left)."""
    out: list[list] = []
    for p in pieces:
        if out:
            p[0] = out[-1][1]
        if out and out[-1][2:] == p[2:]:
            out[-1][1] = p[1]
        else:
            out.append(p)
    return out


def _force(m: Motion, pieces: list[list], u1: float) -> float:
    """``k int e dxi`` (k = 1), exact per piece but for the history's quadrature."""
    F = 0.0
    for x0, x1, kind, *q in pieces:
        if kind == "AFF":
            A, B = q
            F += A * (x1 - x0) + B * (x1 ** (m.n + 1) - x0 ** (m.n + 1)) / (m.n + 1)
        elif m.a > 1.0:  # in xi: tau_on(xi) is smooth, delta never turns inside
            xm, hw = 0.5 * (x0 + x1), 0.5 * (x1 - x0)
            F += hw * sum(w * (u1 - m.u(m.tau_on(xm + hw * s, q[0])))
                          for s, w in zip(GL_X, GL_W, strict=True))
        else:  # in tau: xi = delta^(1/n) is smooth (delta >= 1 - a > 0) where it turns
            ta, tb = m.tau_on(x0, q[0]), m.tau_on(x1, q[0])
            tm, hw = 0.5 * (ta + tb), 0.5 * (tb - ta)
            ts = tm + hw * GL_X
            dxi = [m.delta(t) ** (1.0 / m.n - 1.0) / m.n * -m.a * math.sin(t) for t in ts]
            F += u1 * (x1 - x0) - hw * sum(w * m.u(t) * d for t, w, d in
                                          zip(ts, GL_W, dxi, strict=True))
    return F


def _advance(m: Motion, pieces: list[list], t0: float, t1: float, u0: float,
             u1: float) -> list[list]:
    """The profile after a step from ``t0`` to ``t1`` that moves ``u`` from ``u0`` to
    ``u1``: the stuck points shift, the contact's edge moves, then the clamp."""
    moved = [[p[0], p[1], "AFF", p[3] + u1 - u0, p[4]] if p[2] == "AFF" else list(p)
             for p in pieces]
    r0, r1 = m.radius(t0), m.radius(t1)
    if r1 < r0:  # unloading: the points beyond r1 leave
        moved = [[p[0], min(p[1], r1), *p[2:]] for p in moved if p[0] < r1]
    elif r1 > r0:  # loading: the points that touched down in the step
        moved.append([r0, r1, "HIST", math.ceil(t1 / (2.0 * math.pi))])
    return _merge([q for p in moved for q in _clamp(m, p, m.delta(t1), u1)])


def continuum(m: Motion) -> tuple[np.ndarray, int]:
    """The force at every step's end, and the most pieces held."""
    dt = 2.0 * math.pi / STEPS
    pieces = [[0.0, m.radius(0.0), "AFF", 0.0, 0.0]]
    t, u0, forces, most = 0.0, m.u(0.0), [], 1
    for k in range(CYCLES * STEPS):
        t1 = (k + 1) * dt
        u1 = m.u(t1)
        pieces = _advance(m, pieces, t, t1, u0, u1)
        most = max(most, len(pieces))
        forces.append(_force(m, pieces, u1))
        t, u0 = t1, u1
    return np.array(forces), most


def spring_row(m: Motion, M: int) -> np.ndarray:
    """The same rule on ``M`` springs at the cells' midpoints: the force at every step."""
    dt = 2.0 * math.pi / STEPS
    dx = (1.0 + m.a) ** (1.0 / m.n) / M
    xi = (np.arange(M) + 0.5) * dx
    g = xi ** m.n
    e = np.zeros(M)
    inside = g < m.delta(0.0)
    u0, forces = m.u(0.0), []
    for k in range(CYCLES * STEPS):
        t1 = (k + 1) * dt
        u1, d1 = m.u(t1), m.delta(t1)
        now = g < d1
        e = np.where(inside & now, e + (u1 - u0), 0.0)
        enter = now & ~inside
        if enter.any():
            cycle = math.ceil(t1 / (2.0 * math.pi))
            e[enter] = [u1 - m.u(m.tau_on(x, cycle)) for x in xi[enter]]
        r = m.c * np.maximum(d1 - g, 0.0)
        e = np.clip(e, -r, r)
        inside, u0 = now, u1
        forces.append(e.sum() * dx)
    return np.array(forces)


class Coupled(Motion):
    """The body's own motion as ``u``: cubic Hermite between the step ends kept, linear
    inside the step being taken (the points touching down in it)."""

    def __init__(self, n: float, a: float, k: float) -> None:
        super().__init__(n, a, 0.0, 0.0)
        self.c = (n + 1.0) / n / k
        self.ts: list[float] = []
        self.us: list[float] = []
        self.ds: list[float] = []
        self.step = (math.inf, 0.0, 0.0, 0.0)  # (t0, u0, t1, u1) of the step being taken

    def keep(self, t: float, u: float, du: float) -> None:
        self.ts.append(t)
        self.us.append(u)
        self.ds.append(du)

    def u(self, t: float) -> float:
        t0, u0, t1, u1 = self.step
        if t >= t0:
            return u0 + (u1 - u0) * (t - t0) / (t1 - t0)
        i = min(max(bisect.bisect_left(self.ts, t) - 1, 0), len(self.ts) - 2)
        h = self.ts[i + 1] - self.ts[i]
        s = (t - self.ts[i]) / h
        return ((2 * s**3 - 3 * s**2 + 1) * self.us[i] + (s**3 - 2 * s**2 + s) * h * self.ds[i]
                + (3 * s**2 - 2 * s**3) * self.us[i + 1] + (s**3 - s**2) * h * self.ds[i + 1])


def coupled(alpha: float, beta: float, a: float, V: float, zeta: float, n: float,
            steps: int, periods: int = 80) -> float:
    """``mu_ratio`` of the row without springs driving the body (the scaled model of
    ``_kernels/mdr.py``), from steady sliding, over the last of ``periods`` periods of
    ``steps`` steps each (the force at the step ends over the normal force there)."""
    k, gamma = beta - alpha, 2.0 * zeta * math.sqrt(alpha)
    m = Coupled(n, a, k)
    h = 2.0 * math.pi / steps
    pieces = [[0.0, m.radius(0.0), "AFF", m.c * m.delta(0.0), -m.c]]  # all slipping on
    F = k * _force(m, pieces, 0.0)
    y, v = -F / alpha, 0.0  # the spring balances the sliding force
    m.keep(0.0, y, V)
    acc = -(alpha * y + F)
    sum_f = sum_n = 0.0
    for j in range(periods * steps):
        t0, t1 = j * h, (j + 1) * h
        vh = v + 0.5 * h * acc
        y1 = y + h * vh
        u0, u1 = y + V * t0, y1 + V * t1
        m.step = (t0, u0, t1, u1)
        pieces = _advance(m, pieces, t0, t1, u0, u1)
        F = k * _force(m, pieces, u1)
        v = (vh - 0.5 * h * (alpha * y1 + F)) / (1.0 + 0.5 * h * gamma)
        acc = -(alpha * y1 + gamma * v + F)
        y = y1
        m.keep(t1, u1, v + V)
        if j >= (periods - 1) * steps:
            sum_f += F
            sum_n += max(m.delta(t1), 0.0) ** (1.0 + 1.0 / n)
    return sum_f / sum_n


#: (alpha, beta, a, V, zeta, n) coupled to the body (--dynamics)
DYNAMICS = [(0.5, 2.0, 0.5, 0.3, 0.0, 2.0), (0.5, 2.0, 0.5, 0.3, 0.1, 2.0),
            (1.0, 3.0, 0.7, 0.5, 0.1, 1.0), (0.5, 4.0, 1.5, 0.3, 0.1, 2.0)]
# (the undamped jumping point (0.5, 4, 1.5, 0.3, 0, 2) settles over hundreds of periods: mu
# 0.197, 0.212, 0.2078, 0.20801 after 40, 80, 160, 240 at 500 steps, the solver's 0.20798)


def dynamics() -> list[str]:
    from vibrofriction.solver import solve_points

    lines = ["| alpha, beta, a, V, zeta, n | MDR solver mu +- error | continuum mu, 1000 "
             "steps | 2000 steps | extrapolated (order 2) | difference / solver's error |",
             "|---|---|---|---|---|---|"]
    for case in DYNAMICS:
        keys = ("alpha", "beta", "amplitude", "v_inertial", "zeta", "profile_exponent")
        out = solve_points(**{key: np.array([v]) for key, v in zip(keys, case, strict=True)})
        mu, err = float(out["mu_ratio"][0]), float(out["error"][0])
        m1, m2 = coupled(*case, 1000), coupled(*case, 2000)
        ext = m2 + (m2 - m1) / 3.0
        line = (f"| {', '.join(f'{v:g}' for v in case)} | {mu:.8f} +- {err:.1e} | "
                f"{m1:.8f} | {m2:.8f} | {ext:.8f} | {abs(ext - mu) / err:.2f} |")
        print(line, flush=True)
        lines.append(line)
    return lines


def run() -> list[str]:
    head = " | ".join(f"M = {M}" for M in SPRINGS)
    lines = [f"| n, a, V, A | pieces at most | largest force | {head} |",
             "|---" * (3 + len(SPRINGS)) + "|"]
    for case in CASES:
        m = Motion(*case)
        Fc, most = continuum(m)
        cells = []
        for M in SPRINGS:
            cells.append(f"{np.max(np.abs(spring_row(m, M) - Fc)):.2e}")
        line = (f"| {', '.join(f'{v:g}' for v in case)} | {most} | "
                f"{np.max(np.abs(Fc)):.3f} | {' | '.join(cells)} |")
        print(line, flush=True)
        lines.append(line)
    lines += ["", "Each M column: the largest difference over the run between the spring "
              "row's force and the row without springs (k = 1, the same time steps)."]
    return lines


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--write", action="store_true", help=f"append to {RESULTS}")
    ap.add_argument("--dynamics", action="store_true", help="also coupled to the body")
    args = ap.parse_args()
    lines = run()
    if args.dynamics:
        lines += ["", *dynamics(), "", "The row coupled to the body: velocity Verlet (the "
                  "damping by the trapezoidal rule) from steady sliding, 80 periods, mu over "
                  "the last; extrapolated from the two step sizes as second order."]
    if args.write:
        flag = " --dynamics" if args.dynamics else ""
        append_run(RESULTS, "The MDR row without springs against the spring row",
                   f"PYTHONPATH=src python benchmarks/mdr_continuum_check.py{flag} --write",
                   f"{CYCLES} drive cycles of {STEPS} time steps each, a prescribed motion"
                   + ("; below it the row driving the body" if args.dynamics else "")
                   + "; deterministic.", lines)

if __name__ == "__main__":
    main()
