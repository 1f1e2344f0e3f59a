"""(D4b) on rigorous balls: how many extra digits the construction's balls need.

precision=mp of (D4b) runs ``discretization.compute`` on ``ball_arithmetic.Ball`` (``app.geometry.
balls.serve``): the construction of Section 3, the closed forms (14), (16), every check of
Sections 3–5 (the fits (D1), (D3), (2), the Gauss images and curvatures included) on balls.

The recursion carries the balls' dependency problem: the radius of sin β_i grows about like
e^{2|i|L}·ulp while sin β_i decays like e^{−|i|L} (L = ln((h+d)/(h−d))), a pessimism of the
balls, not an error of the construction. ``extra_digits`` is that loss in decimal digits, over
the range the construction covers (stick 0 to i_min − 1 and i_max + 2), carried from the start;
``balls.serve`` raises the precision further if a returned radius is still too large.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any


def extra_digits_needed(h: float, d: float, i_min: int, i_max: int) -> int:
    """The digits the balls lose over the recursion: about 2·max|i|·L/ln 10 (see above)."""
    L = math.log1p(2 * d / (h - d))
    return math.ceil(2 * max(abs(i_min - 1), abs(i_max + 2), 1) * L / math.log(10)) + 5


def extra_digits(arguments: Mapping[str, Any]) -> int:
    """``extra_digits_needed`` for a request's arguments (``h``, ``d``, ``i_min``, ``i_max``);
    the closed forms need none (their radii do not grow along the range)."""
    if arguments.get("method", "construction") != "construction":
        return 5
    h, d = float(arguments.get("h", 1.0)), float(arguments.get("d", 0.1))
    if not 0 < d < h:
        return 0  # refused by the construction's validation
    return extra_digits_needed(h, d, int(arguments["i_min"]), int(arguments["i_max"]))
