"""Doctest's comparison with numbers to the digits they show: the README, the tour
(tests/docs/test_readme.py) and the site's getting-started page (tests/docs/test_site.py)."""

from __future__ import annotations

import doctest
import re

# a number not inside a name (u_z0, k_x) or a longer number
NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?(?![\w.])")



def _tolerance(shown: str) -> float:
    """Half a unit of the last digit ``shown`` (``0.848``: 5e-4; ``9.0e-07``: 5e-9)."""
    mantissa, _, exponent = shown.lower().lstrip("+-").partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals) * (1 + 1e-9)


class NumberChecker(doctest.OutputChecker):
    """Doctest's comparison, except that each number of the expected output matches a
    computed one that rounds to it (as pytest's NUMBER option)."""

    def check_output(self, want: str, got: str, optionflags: int) -> bool:
        if super().check_output(want, got, optionflags):
            return True
        shown, computed = NUMBER.findall(want), NUMBER.findall(got)
        if not shown or len(shown) != len(computed):
            return False
        if any(abs(float(c) - float(s)) > _tolerance(s)
               for s, c in zip(shown, computed, strict=True)):
            return False
        it = iter(shown)
        return super().check_output(want, NUMBER.sub(lambda m: next(it), got), optionflags)
