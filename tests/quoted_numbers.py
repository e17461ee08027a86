"""Every deterministic number the docs quote, declared once: the page, the quoted text,
the script section that computes it and the row (tests/docs/test_quoted_numbers.py
recomputes the sections and checks the pages and the committed results files;
tests/solver/test_sensitivity.py checks the numbers its own comparison computes).

A :class:`Quote` names a page, a regular expression that matches the page's text (its
whitespace collapsed to single spaces) exactly once, with one group per quoted number,
the source (``"docs_numbers.settling"``: the function ``settling`` of
``benchmarks/docs_numbers.py``; or a test module) and the quantity of the source's row;
``field`` picks the numbers out of the row's value (one group per number of ``text``).
A quoted number agrees when the computed one rounds to it at the digits it shows
(``1.9`` for 1.87; ``1.6 \\cdot 10^{-6}`` and ``1.6e-6`` alike; ``51,806``); a word
(a status) must be equal.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from doctest_numbers import _tolerance

ROOT = Path(__file__).resolve().parents[1]
_NUM = r"([-+]?[\d.,]+(?:e[-+]?\d+| \\cdot 10\^\{[-+]?\d+\})?)"  # one quoted number


@dataclass(frozen=True)
class Quote:
    """One or more numbers of a page, computed by one row of a source."""

    page: str  # relative to the repository, e.g. "docs/solver.md"
    text: str  # regex on the page's text, one group per quoted number
    source: str  # "script.section", or "tests/<layer>/test_x.py" for a test's own numbers
    key: str  # the row's quantity
    field: str = "(.*)"  # regex on the row's value, one group per group of ``text``


def n(s: str) -> str:
    """``text`` with ``#`` standing for one quoted number (a group), the rest literal."""
    return _NUM.join(re.escape(part) for part in s.split("#"))


_DN, _MI = "docs_numbers.", "mdr_inplane_numbers."
_SENS = "tests/solver/test_sensitivity.py"
_SHAPE = "mdr_shape_numbers"
_EQUAL_F = "## flat punch a = {}: A_F = "  # + "...; curved tips at equal A_F", the first
_FLAT1 = "(0.5, 2, 0.5, 0.3, zeta 0, a_x 0.5, 1, substrate)"
_FLAT2 = "(1.3, 4, 1.4, 0.8, zeta 0.05, a_x 1.2, 2.5, holder)"
_FIRST = r"^([^ ,]+)"  # the first word of a row's value
_STIFF = "stiff contact (mass 0.01): mu_ratio, error, rows, skipped"
_STIFF_ROWS = "stiff contact, the rows alone: mu_ratio, error, rows, skipped"
_SLOPE = "slope at (0.01, 1e6), a = {}, vbar 1e-3 (sqrt(4 pi/9) = 1.1816)"


def _each(page: str, text: str, source: str, *rows: tuple[str, str]) -> list[Quote]:
    """One quote per number of ``text``, in order: ``rows`` are their ``(key, field)``,
    each field with one group."""
    k = len(rows)
    return [Quote(page, text, source, key, "()" * i + field + "()" * (k - 1 - i))
            for i, (key, field) in enumerate(rows)]


_IP, _DRIVE, _VZERO = "docs/inplane.md", "inplane_drive_numbers", "plane_vzero_numbers"
_IPN = "inplane_numbers."
_EXAMPLE = "(0.5, 2, 0.5), {}, zeta {}, eta_c {}"
_V0 = "## V = 0, zeta = 0.05, eta_c = 0.1\n| {} | "  # a row of the drive's table at V = 0
_CELL = r" \| (\S+) {} \([^)]*\)"  # one cell of that table: the mean force, its status


def _kinematic(on: str, alpha: str, amp: str, along: str) -> Quote:
    return Quote(_IP, n(f"| {on}, $\\alpha = {alpha}$ | {amp} | #{along} | # |"),
                 _IPN + "kinematic", f"{on}, alpha {float(alpha)}, amplitude {float(amp)}",
                 r"^longitudinal (\S+), transverse (\S+) \(")


def _at_v0(a_x: str, status: str) -> Quote:
    """A row of the table at V = 0 of docs/inplane.md: the band and five preloads."""
    band = "# / #" if status == "held" else "none"
    cell = " held" if status == "held" else ""
    return Quote(_IP, n(f"| {a_x} | {band} |" + f" #{cell} |" * 5), _DRIVE, _V0.format(a_x),
                 (r"^(\S+) / (\S+)" if status == "held" else r"^\+nan / \+nan")
                 + _CELL.format(status) * 5)


_CG, _HIST, _CONV = "docs/contact_geometry.md", "mdr_history_numbers", "mdr_convergence"
_CLOSED = "## closed forms (vibrofriction.theory)\n| {} | "  # a row of mdr_convergence's first
_COLUMNS = r"^(\S+) \| (\S+) \| (\S+) \| (\S+) \|$"  # a row's four columns after its key
_DEFAULT = "\nmdr_reference default ((100, 200), (200, 400)): "  # after a point's heading
_POINT = {"sphere": "## sphere, soft, a=0.5", "jumping": "## sphere, resonant, jumping a=1.5",
          "cone": "## cone, stiff-ish, a=0.8"}


def _closed_forms(a: str) -> Quote:
    """A row of the closed forms' table of docs/contact_geometry.md (15 numbers)."""
    three = "#, #, #"
    return Quote(_CG, n(f"| {a} | {three} | {three} | {three}; {three}; {three} |"), _CONV,
                 _CLOSED.format(a), r"^([^,]+), ([^,]+), ([^ ]+) \| ([^,]+), ([^,]+), ([^ ]+) "
                 r"\| ([^,]+), ([^,]+), ([^;]+); ([^,]+), ([^,]+), ([^;]+); ([^,]+), ([^,]+), "
                 r"([^ ]+) \|$")


_BENCH, _DESIGN = "docs/bench.md", "design_numbers"


def _cols(*index: int) -> str:
    """A field picking the columns ``index`` (0: the first after the row's key), in that
    order, out of a table row's value."""
    return "".join(rf"(?=^(?:[^|]*\| ){{{i}}}([^|]*?) \|)" for i in index)


#: the reference's difference from the design and its bar, of the in-plane design table
_REF = (r"(?=^(?:[^|]*\| ){9}(\S+) \(\S+\) \|)", r"(?=^(?:[^|]*\| ){9}\S+ \((\S+)\) \|)")
#: the blocking forces mu(0+), mu(0-) of a row of the in-plane design table (its column 7)
_BLOCK = r"(?=^(?:[^|]*\| ){7}(\S+) / (\S+) \|)"


def _design(key: str, text: str, *index: int) -> Quote:
    """Numbers of one row of design_numbers' tables, ``index`` its columns in the text's
    order."""
    return Quote(_BENCH, n(text), _DESIGN, key, _cols(*index))


def _long_budget(beta: str, vbar: str) -> Quote:
    return Quote("docs/solver.md", n(f"| {beta} | {vbar} | # | # | # | # |"),
                 _DN + "long_budget", f"beta {beta}, vbar {vbar}",
                 r"mu/mu0 ([^,]+), periods ([\d,]+), multiplier ([\d.]+), settling ([\d,]+),")


def _case_iv_rise(a: str) -> Quote:
    return Quote("docs/damping.md", n(f"| {a} | # | # | # |"), _DN + "case_iv_rise", f"a = {a}",
                 r"zeta 0.005: (\S+), zeta 0.02: (\S+), zeta 0.05: (\S+)$")


QUOTES: list[Quote] = [
    # docs/contact_geometry.md, "Using it"
    Quote("docs/contact_geometry.md", n("`r.mu_ratio = #` (error #, status ") + r"(\w+);",
          _DN + "contact_geometry_using_it", "sphere (mdr): mu_ratio, error, status",
          r"^(\S+), (\S+), (\w+)$"),
    Quote("docs/contact_geometry.md", n("`mean_normal_ratio` #;"),
          _DN + "contact_geometry_using_it", "sphere (mdr): mean_normal_ratio"),
    Quote("docs/contact_geometry.md", n("stick, slip, open #, #, # of the disc"),
          _DN + "contact_geometry_using_it", "sphere (mdr): stick, slip, open area",
          r"^(\S+), (\S+), (\S+)$"),
    Quote("docs/contact_geometry.md", n("`r_lin.mu_ratio = #` for the linearised one at the "
                                        "same $V = #$"),
          _DN + "contact_geometry_using_it", "linearised: mu_ratio, error", r"^(\S+),.*()$"),
    Quote("docs/contact_geometry.md", n("at the same $V = #$"), _DN + "contact_geometry_using_it",
          "V (both)"),
    Quote("docs/contact_geometry.md", n("the rows of springs now find it periodic, $# \\pm #$ "
                                        "(rows #, #;"),
          _DN + "contact_geometry_using_it", _STIFF_ROWS, r"^(\S+), (\S+), \((\d+), (\d+)\)"),
    Quote("docs/contact_geometry.md", n("row without springs gives $# \\pm #$, both"),
          _DN + "contact_geometry_using_it", _STIFF, r"^(\S+), (\S+), \(\)"),
    # docs/contact_geometry.md, "In-plane oscillation along the sliding"
    Quote("docs/contact_geometry.md", n("`solve_points` with `a_x` within # at seven points"),
          _MI + "flat_punch", "largest |diff|"),
    *_each("docs/contact_geometry.md", n("# and # apart against the row's bars # and #"),
           _MI + "reference_flat_punch", (_FLAT1, r"diff (\S+)$"), (_FLAT2, r"diff (\S+)$"),
           (_FLAT1, r"^row \S+ \+- ([^,]+),"), (_FLAT2, r"^row \S+ \+- ([^,]+),")),
    Quote("docs/contact_geometry.md", n("**# of # within the combined bars**"),
          _MI + "against_reference", "within the combined bars", r"^(\d+) of (\d+)$"),
    *_each("docs/contact_geometry.md", n("`|diff|/(error + bar)` at most # (# to # apart; the "
                                         "solver's errors # to #:"),
           _MI + "against_reference", ("largest ratio", "(.*)"),
           ("|diff|, smallest to largest", r"^(\S+) to"),
           ("|diff|, smallest to largest", r"to (\S+)$"),
           ("the solver's errors, smallest to largest", r"^(\S+) to"),
           ("the solver's errors, smallest to largest", r"to (\S+)$")),
    Quote("docs/contact_geometry.md", n("bar (# from its rows (100, 200) to (200, 400)) was short "
                                        "(it moves # more to (400, 800))"),
          _MI + "against_reference", "their steps", r"^([^,]+), ([^,]+),"),
    Quote("docs/contact_geometry.md", n("(bars median #, largest #;"), _MI + "calibration",
          "reference bars: median, largest", r"^(\S+), (\S+)$"),
    Quote("docs/contact_geometry.md", n("`|diff|/error` median #, largest # (their errors # to "
                                        "#)"),
          _MI + "calibration", "|diff|/error: median, largest", r"^(\S+), (\S+)$()()"),
    Quote("docs/contact_geometry.md", n("`|diff|/error` median #, largest # (their errors # to "
                                        "#)"),
          _MI + "calibration", "the rows' errors, smallest to largest", r"()()^(\S+) to (\S+)$"),
    Quote("docs/contact_geometry.md", n("answers all 24, `|diff|/(error + bar)` median #, "
                                        "largest # (its errors # to #, the"),
          _MI + "calibration", "the solver: |diff|/(error + bar): median, largest",
          r"^(\S+), (\S+)$()()"),
    Quote("docs/contact_geometry.md", n("answers all 24, `|diff|/(error + bar)` median #, "
                                        "largest # (its errors # to #, the"),
          _MI + "calibration", "the solver's errors, smallest to largest", r"()()^(\S+) to (\S+)$"),
    *_each("docs/contact_geometry.md", n("agree by chance (#, #; 80 springs: #), and a bar of "
                                         "their one difference, #, is # short of the "
                                         "reference's $# \\pm #$"),
           _MI + "short_bar", ("the solver's row of 20", "(.*)"),
           ("the solver's row of 40", "(.*)"), ("the solver's row of 80", "(.*)"),
           ("bar of the difference of the rows 20, 40", "(.*)"),
           ("row 40 from the reference", "(.*)"), ("reference", r"^(\S+) \+-"),
           ("reference", r"\+- (\S+) ")),
    Quote("docs/contact_geometry.md", n("the point gives $# \\pm #$, # off"), _MI + "short_bar",
          "mdr_friction (two differences)", r"^(\S+) \+- (\S+) ()"),
    Quote("docs/contact_geometry.md", n("the point gives $# \\pm #$, # off"), _MI + "short_bar",
          "mdr_friction from the reference", r"()()(.*)"),
    # docs/contact_geometry.md, "How much the shape matters"
    Quote("docs/contact_geometry.md", n("is a sphere at $a = #$ and a cone at `#`; the jumping"),
          _SHAPE, _EQUAL_F.format("0.5") + "\na: flat punch", r"sphere (\S+) .* cone (\S+) "),
    Quote("docs/contact_geometry.md", n("the jumping flat punch $a = 1.5$ ($A_F = #$)"), _SHAPE,
          _EQUAL_F.format("0.5") + "\n## flat punch a = 1.5: A_F = ", r"^([^;]+);"),
    Quote("docs/contact_geometry.md", n("is a sphere at $a = #$ and a cone at `#`: **at equal"),
          _SHAPE, _EQUAL_F.format("1.5") + "\na: flat punch", r"sphere (\S+) .* cone (\S+) "),
    Quote("docs/contact_geometry.md", n("(flat #, sphere #, cone #: the smallest force"), _SHAPE,
          _EQUAL_F.format("0.5") + "\na: flat punch",
          r"static (\S+)\), sphere .* static (\S+)\), .* static (\S+)\)$"),
    *(Quote("docs/contact_geometry.md", n(text), _SHAPE, f"{_EQUAL_F.format(a)}\n{line}",
            r"^(\S+) \| (\S+) \| (\S+) \|")
      for a, text, line in (
          ("0.5", "stiff $x = 5$: flat #, sphere #, cone #;", "| stiff (0.01, 0.02) | 5 | "),
          ("0.5", "soft $x = 0.05$: #, #, #;", "| soft (0.01, 40) | 0.05 | "),
          ("0.5", "resonant $x = 1$: #, #, #;", "| resonant (1, 3) | 1 | "),
          ("1.5", "stiff $x = 45$: flat #, sphere #, cone #;", "| stiff (0.01, 0.02) | 45 | "),
          ("1.5", "soft $x = 0.15$: #, #, #;", "| soft (0.01, 40) | 0.15 | "),
          ("1.5", "resonant $x = 0.2$: #, #, # (", "| resonant (1, 3) | 0.2 | "),
          ("1.5", "(and still #, #, # at $x = 3$", "| resonant (1, 3) | 3 | "))),
    Quote("docs/contact_geometry.md", n("e.g. stiff $x = 15$: #, #, #; with jumping"), _SHAPE,
          "## flat punch a = 0.5: A_F = 0.5000; curved tips at equal indentation amplitude a\n"
          "| stiff (0.01, 0.02) | 15 | ", r"^(\S+) \| (\S+) \| (\S+) \|"),
    # docs/contact_geometry.md, "Continuous sliding"
    *(Quote("docs/contact_geometry.md", n(f"| $a = {a}$ | #{eq} | # | # | # |"),
            "mdr_critical_numbers", f"| (0.5, 2) (0.5, 2) | {a} | ",
            r"^(\S+) \(\S+\) \| (\S+) \(\S+\) \| (\S+) \(\S+\) \| (\S+) \(")
      for a, eq in (("0.2", ""), ("0.5", ""), ("1.5", " (eq. 12: 2.0)"))),
    # docs/solver.md
    Quote("docs/solver.md", n("re-solves the orbit each time), worst relative disagreement #;"),
          _SENS, "worst relative disagreement of d mu / d theta"),
    Quote("docs/solver.md", n("the differences of the solver's final section state, worst #"),
          _SENS, "worst disagreement of d z* / d theta"),
    *_each("docs/solver.md", n("`multiplier = #`, $\\mu = #$, error #, and needs about # periods"),
           _DN + "settling", ("multiplier", "(.*)"), ("mu/mu0", "(.*)"), ("error", "(.*)"),
           ("settling_periods", "(.*)")),
    Quote("docs/solver.md", n("(`tests/solver/test_solver_physics.py`; # at $\\beta = 2"),
          _DN + "near_alpha_one", "max |mu(1 +- 1e-9) - mu(1)| at V = 0.5, 1, 3"),
    Quote("docs/solver.md", n("(# at $\\alpha = 1000, \\beta = 10^4$"), _DN + "stiff_contacts",
          "alpha 1000, beta 10000: |mu - mu(rigid)| <="),
    *_each("docs/solver.md", n("work # periods at $\\bar v = 0.02$, #-# at the others, # at "
                               "$\\bar v = 0.016$"),
           _DN + "near_beta_one_default", ("beta 1.01, vbar 0.02", r"work ([\d,]+),"),
           ("work at the others: least-most", r"^(\d+)-"),
           ("work at the others: least-most", r"-(\d+)$"),
           ("beta 1.01, vbar 0.016", r"work ([\d,]+),")),
    Quote("docs/solver.md", n("estimates from the multiplier (# to # periods"),
          _DN + "near_beta_one_default", "settling: least, most", r"^(\S+) to (\S+)$"),
    *(_long_budget(beta, vbar) for beta, vbar in (("1.01", "0.016"), ("1.01", "0.02"),
                                                  ("1.01", "0.04"), ("1.01", "0.064"),
                                                  ("1.02", "0.05"), ("1.005", "0.02"))),
    Quote("docs/solver.md", n("effect of a loss factor just above the floor is at most $#"),
          _DN + "loss_factor_floor", "max |mu(eta_c) - mu(0)| / eta_c, eta_c = 1.5e-6, 1e-5"),
    # docs/damping.md
    *_each("docs/damping.md", n("gives $V_c = #$; the solver has $\\mu = #$ at $0.9 V_c$ and "
                                "$\\mu = #$ at $1.02 V_c$"),
           _DN + "case_iii_damped", ("V_c", "(.*)"), ("mu/mu0 at 0.9 V_c", "(.*)"),
           ("mu/mu0 at 1.02 V_c", r"^(\S+) \(sliding\)$")),
    *(_case_iv_rise(a) for a in ("0.2", "0.5", "1.0", "1.5")),
    *_each("docs/damping.md", n("linearly in $\\alpha$: #, #, # for"), _DN + "stiff_exact_law",
           *((f"solver vs exact law, (alpha, beta) = ({alpha}, {beta})",
              r"^(\S+) \(trusted: True\)")
             for alpha, beta in (("0.01", "0.02"), ("0.001", "0.002"), ("0.0001", "0.0002")))),
    Quote("docs/damping.md", n("differs from the exact law by at most $# a$**, near $\\bar v "
                               "= #$"),
          _DN + "stiff_exact_law", "max |eq. 26 - exact| / a, a = 1.0", r"^(\S+) at vbar (\S+)$"),
    Quote("docs/damping.md", n("measured effect on $\\mu$ of a loss factor just above that floor "
                               "is at most $#"),
          _DN + "loss_factor_floor", "max |mu(eta_c) - mu(0)| / eta_c, eta_c = 1.5e-6, 1e-5"),
    # docs/figures.md
    *_each("docs/figures.md", n("`mu/mu0` = #, #, #, #, #, #, # for `zeta` = 0, 1e-5, 1e-4"),
           _DN + "fig13_zeta_series",
           *((f"zeta {zeta}", r"^(\S+) \(periodic, trusted True\)$")
             for zeta in ("0", "1e-05", "0.0001", "0.0003", "0.001", "0.003", "0.01"))),
    Quote("docs/figures.md", n("the point `vbar = 0.02` converges to `mu/mu0 = #`"),
          _DN + "long_budget", "beta 1.01, vbar 0.02", r"mu/mu0 ([^,]+),"),
    Quote("docs/figures.md", n("and settles after about # periods (`long_budget`"),
          _DN + "long_budget", "beta 1.01, vbar 0.02", r"settling ([\d,]+),"),
    # docs/theory.md
    Quote("docs/theory.md", n("|\\alpha - 1|) = #$ at (0.01, 400.01)"),
          _DN + "critical_velocity_limits", "v0*/v0*_soft at (0.01, 400.01)"),
    Quote("docs/theory.md", n("|\\alpha - 1| = #$ at (0.01, 0.02)"),
          _DN + "critical_velocity_limits", "v0*/v0*_stiff at (0.01, 0.02)"),
    Quote("docs/theory.md", n("deeper in the soft limit, (0.01, 1e4): #;"), _DN + "soft_limit",
          "max |numerics - eq. 27 corrected| at (0.01, 1e4)"),
    Quote("docs/theory.md", n("and # at $\\beta = 10^4$"), _DN + "soft_limit",
          "least-squares exponent at (0.01, 1e4)"),
    *(Quote("docs/theory.md", n("(# measured at $\\beta = 10^6$, vbar = 1e-3, a = 0.5 and 1)"),
            _DN + "soft_limit", _SLOPE.format(a)) for a in ("0.5", "1.0")),
    *_each("docs/theory.md", n("at a = 1.5 $\\mu/\\mu_0$ is # at V = 0.05 and # at V = 0.1 for "
                               "(0.2, 1), reaching 1 only at V = # (# for alpha = 0.01;"),
           _DN + "case_iii_jumping", ("(alpha, beta) = (0.2, 1)", r"mu/mu0 (\S+) at V = 0.05"),
           ("(alpha, beta) = (0.2, 1)", r"(\S+) at V = 0.1;"),
           ("(alpha, beta) = (0.2, 1)", r"= 1 from V = (\S+)$"),
           ("(alpha, beta) = (0.01, 1)", r"= 1 from V = (\S+)$")),
    Quote("docs/theory.md", n("where the numerics give # and # (deviation"),
          _DN + "case_iv_plateau", "plateau (exact tau*) a = 1.5, 2, 5, 1e6", r"^(\S+), (\S+),"),
    Quote("docs/theory.md", n("(Section 6): # (a = 1.5), # (2), # (5), and tends to # for"),
          _DN + "case_iv_plateau", "plateau (exact tau*) a = 1.5, 2, 5, 1e6",
          r"^(\S+), (\S+), (\S+), (\S+)$"),
    Quote("docs/theory.md", n("the approximation tends to $1 - \\pi/4 = #$"),
          _DN + "case_iv_plateau", "small-tau* approximation, a = 1e6"),
    Quote("docs/theory.md", n("within 1e-3 of the plateau for V >= # (a = 0.2), # (0.5), # (0.8), "
                              "# (1), # (1.5), # (2)"),
          _DN + "case_iv_plateau", "within 1e-3 of the plateau from",
          r"a = 0.2: V >= (\S+), a = 0.5: V >= (\S+), a = 0.8: V >= (\S+), a = 1.0: V >= (\S+), "
          r"a = 1.5: V >= (\S+), a = 2.0: V >= (\S+)$"),
    # docs/inplane.md, section 1: the kinematic laws against the dynamics
    *(_kinematic(on, alpha, amp, along) for on, alpha, amp, along in (
        ("substrate", "0.01", "10", ""), ("substrate", "0.1", "3", ""),
        ("substrate", "0.1", "10", ""), ("substrate", "10", "1", ""),
        ("substrate", "10", "3", ""), ("substrate", "100", "1", ""),
        ("holder", "0.1", "3", " (law not applicable)"), ("holder", "100", "1", ""))),
    # docs/inplane.md, sections 2 and 3: the example system's closed forms
    Quote(_IP, n("undamped $V_c = #$ (both modes: $H = -1$ at $\\alpha = 0.5$), against `#` "
                 "without the in-plane oscillation; cancellation at $\\varphi_x = #$ with "
                 "$a_x = #$."),
          _IPN + "combined_critical", _EXAMPLE.format("substrate", "0.0", "0.0"),
          r"(?=.*pi/2\) (\S+);)(?=.*a_x=0\) (\S+);)(?=.*phase (\S+), a_x (\S+);)"),
    *_each(_IP, n("With $\\zeta = 0.05, \\eta_c = 0.1$: `#` (substrate), `#` (holder)."),
           _IPN + "combined_critical",
           *((_EXAMPLE.format(on, "0.05", "0.1"), r"V_c\(0.5, pi/2\) (\S+);")
             for on in ("substrate", "holder"))),
    Quote(_IP, n("(# rad at `(0.5, 2, 0.5)`"), _IPN + "combined_critical",
          _EXAMPLE.format("substrate", "0.05", "0.1"), r"cancels at phase (\S+),"),
    *(Quote(_IP, n(text), _IPN + "combined_critical", _EXAMPLE.format("substrate", *damping),
            r"static mu\(0\+\) (\S+), mu\(0-\) (\S+)$")
      for text, damping in (("(`#, #` for the example system", ("0.0", "0.0")),
                            ("(`#, #` with $\\zeta = 0.05$", ("0.05", "0.1")))),
    # docs/inplane.md, section 5: v0 = 0, the example system
    *(_at_v0(a_x, status) for a_x, status in (("0.5", "held"), ("1", "held"),
                                              ("1.25", "periodic"), ("2", "periodic"))),
    *_each(_IP, n("between the creeping limits $\\mu(0^-) = #$ and $\\mu(0^+) = #$"), _DRIVE,
           *(("## zeta = 0.05, eta_c = 0.1\n* blocking force (the limits V -> 0+ and 0-): ",
              field) for field in (r" and (\S+) at", r"^(\S+) and"))),
    # docs/figures.md, Fig. 16: the drive's blocking forces and the band
    *(Quote("docs/figures.md", n("`a_x = 0.5`: # / # undamped (band +-0.375) and # / # damped "
                                 "(band # / #)"), _DRIVE,
            f"## zeta = {zeta}\n* blocking force (the limits V -> 0+ and 0-): ", field)
      for zeta, field in (("0.0", r"^(\S+) and (\S+) at()()()()"),
                          ("0.05", r"()()^(\S+) and (\S+) at .* contact (\S+) / (\S+)$"))),
    # docs/inplane.md, section 5 in 2-D, and the slow points near v0 = 0
    *(Quote(_IP, n(text), _VZERO, f"| {point} | rest | ", r"^\w+ \| \S+ \| (\S+) \|")
      for text, point in (("held `#` and slipping", "held, transverse only"),
                          ("and slipping `#`)", "slips, transverse only"))),
    Quote(_IP, n("$|\\mu - \\mu_\\text{ref}|$ at most `#`, $|\\text{lat} - "
                 "\\text{lat}_\\text{ref}|$ at most `#` (stated errors `#` to `#`)"), _VZERO,
          "Where it slips: ",
          r"at most (\S+), \|lat - ref\| at most (\S+), stated errors (\S+) to (\S+);"),
    Quote(_IP, n("inside the region and within `#` of the reference's"), _VZERO,
          "Where it slips: ", r"both within (\S+)\.$"),
    Quote(_IP, n("preloaded start, `#` off"), _VZERO, "| held, holder, anisotropic | preload | ",
          r"^\w+ \| \S+ \| \S+ \| \S+ \| (\S+) \|"),
    *(Quote(_IP, n(before) + r"(\w+)" + n(", #, "), _VZERO, f"| {point} | ",
            r"^\S+ \| (\w+) \| \S+ \| \S+ \| (\S+) \|")
      # the "now" column (the "after" one is the record of 2026-11-28)
      for before, point in (("error 1.8e-3, 37.6 s | periodic, 7.2e-8, 0.15 s | ",
                             "transverse bench, v0 = -1.4e-4 m/s"),
                            ("error 3.4e-4, 288 s | periodic, 7.5e-8, 0.10 s | ",
                             "transverse bench, phase_y = pi/2"),
                            ("error 2.7e-4, 39.2 s | periodic, 3.8e-8, 0.16 s | ",
                             "fuzz_plane slowest (undamped)"))),
    # docs/contact_geometry.md, the closed forms and the spring-row reference
    *(_closed_forms(a) for a in ("0.2", "0.5", "0.8", "1.0", "1.5", "3.0")),
    Quote(_CG, n("(sphere # against flat # at $a = 0.5, \\bar v = 0.3$)"), _CONV,
          _CLOSED.format("0.5"), r"^(?=(?:[^;]*; ){1}[^,]*, (\S+),)(?=[^|]*\|[^|]*\| [^,]*, "
          r"(\S+),)"),
    *(Quote(_CG, n(text), _CONV, f"{_POINT[point]}\n| 800 | ", _COLUMNS)
      for text, point in (("(sphere, soft: #, #, #, # at 100 ... 800 steps", "sphere"),
                          ("cone: #, #, #, #), and about second order", "cone"))),
    *_each(_CG, n("(sphere, 800 steps: #, #, #, #, # at 50 ... 800 springs"), _CONV,
           *((f"{_POINT['sphere']}\n| {m} | ", r"\| (\S+) \|$") for m in (50, 100, 200, 400, 800))),
    *_each(_CG, n("three points measured (# vs #; # vs # jumping; # vs # cone)"), _CONV,
           *((_POINT[p] + _DEFAULT, field) for p in ("sphere", "jumping", "cone")
             for field in (r"\+- (\S+); true", r"true error (\S+);"))),
    *_each(_CG, n("(sphere # +- # vs #; jumping # vs #)"), _CONV,
           (_POINT["sphere"] + _DEFAULT, r"F_N0 = (\S+) \+-"),
           (_POINT["sphere"] + _DEFAULT, r"F_N0 = \S+ \+- (\S+),"),
           (_POINT["sphere"] + _DEFAULT, r"closed form (\S+)$"),
           (_POINT["jumping"] + _DEFAULT, r"F_N0 = (\S+) \+-"),
           (_POINT["jumping"] + _DEFAULT, r"closed form (\S+)$")),
    *(Quote(_CG, n(text), _CONV, f"## static limit\n| n=2 | {a} | ",
            r"\| (\S+) \| (\S+) \| (\S+) \|$")
      for text, a in (("(sphere $a = 0.5$: #, #, # at $V", "0.5"),
                      ("jumping: #, #, # towards 0)", "1.5"))),
    # docs/contact_geometry.md, "The history"
    Quote(_CG, n("dissipation within # of it, round-off (at every point, the jumping cone"),
          _HIST, "## Energy balance\n"
          "| (1.0, 3.0, 1.3, 0.5, 1.0, 0.0, 'a_x 0.8, phase_x 2.5, substrate') | ",
          r"\| < (\S+) \|$"),
    Quote(_CG, n("$\\zeta = 0.1$: # = # + #;"), _HIST,
          "## Energy balance\n| (0.5, 2.0, 1.5, 0.3, 2.0, 0.1) | ",
          r"^\S+ \| \S+ \| (\S+) \| (\S+) \| (\S+) \|"),
    *(Quote(_CG, n(text), _HIST, f"## One period of the periodic orbit\n| {point} | ",
            r"^\d+ \| (\S+) \| \S+ \| (\S+) \+- (\S+) \|")
      for text, point in (("its error (# against # +- # for the sphere",
                           "(0.5, 2.0, 0.5, 0.3, 2.0, 0.0)"),
                          ("; # against # +- # jumping)", "(0.5, 2.0, 1.5, 0.3, 2.0, 0.1)"))),
    Quote(_CG, n("every spring's force agrees to #, #, # of the largest"), _HIST,
          "## Every spring's force against the spring-row reference\n"
          "| (0.5, 2.0, 0.5, 0.3, 2.0, 0.0) | ", r"^(\S+) \| (\S+) \| (\S+) \|$"),
    # docs/bench.md, "Design the oscillation"
    *(Quote(_BENCH, n("the best frequency is #, #, # and # Hz at `v0 = 0.001, 0.01, 0.1, 0.5 "
                      "m/s`, always at the largest amplitude, 0.9 um, with COF #, #, #, #;"),
            _DESIGN, f"## The optimum against the operating velocity (default map 161 x 41, "
            f"8 starts)\n| {v0} | ", "()" * i + _cols(0) + "()" * (3 - i) + "()" * i + _cols(3)
            + "()" * (3 - i))
      for i, v0 in enumerate(("0.001", "0.01", "0.1", "0.5"))),
    Quote(_BENCH, n("COF (#, # against #), which is"), _DESIGN, "## The optimum against\n| 0.01 | ",
          r"(?=^(?:[^|]*\| ){6}(\S+) / (\S+) \|)" + _cols(3)),  # COF at f -1 % / +1 %
    _design("| 21 x 5 | 1 | ", "a single start stops at # Hz, # above the", 0, 2),
    _design("| friction | 0.01 | 0.01 | ", "(# Hz, # um normal, # um longitudinal, `phase_x` # "
            "rad) gives COF #, against # with the normal oscillation alone and # with the "
            "longitudinal one alone", 0, 1, 2, 3, 4, 5, 6),
    _design("| friction | 0.1 | 0.01 | ", "at 0.1 m/s # against # and #;", 4, 5, 6),
    _design("| friction | 0.001 | 0.01 | ", "(force-free sliding, COF # against # and #)",
            4, 5, 6),
    _design("| each | ", "allowing a little more, gives # at 0.01 m/s", 4),
    Quote(_BENCH, n("(COF #; # Hz, # um at `phase_x` #), blocking force `mu(0+) = #`, "
                    "`mu(0-) = #` (an actuator: both limits push), idle velocity # m/s"),
          _DESIGN, "| drive | 0.001 | 0.01 | ", _cols(4, 0, 2, 3) + _BLOCK + _cols(8)),
    Quote(_BENCH, n("range (# Hz, # um, # um, `phase_x` #): COF #, blocking # both ways, "
                    "idle velocity # m/s"), _DESIGN, "| drive | 0.001 | 0.03 | ",
          _cols(0, 1, 2, 3, 4) + _BLOCK.replace(r" / (\S+)", r" / \S+") + _cols(8)),
    Quote(_BENCH, n("blocking # both ways"), _DESIGN, "| drive | 0.001 | 0.03 | ",
          _BLOCK.replace(r"(\S+) / ", r"\S+ / ")),
    _design("| drive | 0.003 | 0.03 | ", "at `v0 = 0.003` m/s COF #, idle # m/s", 4, 8),
    *_each(_BENCH, n("points where that bar is large: # (bar #) and # (bar #, the"), _DESIGN,
           *((key, field) for key in ("| friction | 0.001 | 0.01 | ", "| drive | 0.001 | 0.03 | ")
             for field in _REF)),
]


def _number(s: str) -> tuple[float, float] | None:
    """The value of a quoted or computed number and half a unit of its last digit, or
    None for a word."""
    plain = re.sub(r" \\cdot 10\^\{([-+]?\d+)\}", r"e\1", s.replace(",", "").strip())
    if not re.fullmatch(r"[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?", plain):
        return None
    return float(plain), _tolerance(plain)


@cache
def page_text(page: str) -> str:
    """The page's text, whitespace collapsed to single spaces."""
    return " ".join((ROOT / page).read_text().split())


def disagreements(quote: Quote, rows: dict[str, str]) -> list[str]:
    """What is wrong with ``quote`` given its source's rows ``{quantity: value}``: each
    problem named by page, quantity, quoted and computed value (empty: it agrees)."""
    where = f"{quote.page} ({quote.source}, {quote.key!r})"
    found = list(re.finditer(quote.text, page_text(quote.page)))
    if len(found) != 1:
        return [f"{where}: the quoted text {quote.text!r} is found {len(found)} times "
                "(it must be found once)"]
    if quote.key not in rows:
        return [f"{where}: the source has no row {quote.key!r} (it has {sorted(rows)})"]
    computed = re.search(quote.field, rows[quote.key])
    if computed is None or len(computed.groups()) != len(found[0].groups()):
        return [f"{where}: the row's value {rows[quote.key]!r} does not match the field "
                f"{quote.field!r} with one group per quoted number"]
    out = []
    for shown, value in zip(found[0].groups(), computed.groups(), strict=True):
        if value == "":  # a group of another quote of the same text
            continue
        q, c = _number(shown), _number(value)
        ok = (shown == value if q is None or c is None
              else abs(c[0] - q[0]) <= q[1])
        if not ok:
            out.append(f"{where}: the page quotes {shown}, the source computes {value}")
    return out


def check(source: str, rows: dict[str, str]) -> None:
    """Assert that every quote of ``source`` agrees with ``rows`` (for a test that computes
    quoted numbers itself)."""
    quotes = [q for q in QUOTES if q.source == source and q.key in rows]
    assert quotes, f"no quote has the source {source} and a key of {sorted(rows)}"
    problems = [p for q in quotes for p in disagreements(q, rows)]
    assert not problems, "\n".join(problems)
