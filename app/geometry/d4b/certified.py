"""(D4b) on rigorous balls: how many extra digits the construction's balls need.

precision=mp of (D4b) runs ``discretization.compute`` on ``ball_arithmetic.Ball`` (``app.geometry.
balls.serve``): the construction of Section 3, the closed forms (14), (16), every check of
Sections 3–5 (the fits (D1), (D3), (2), the Gauss images and curvatures included) on balls.

The recursion carries the balls' dependency problem: each stick's direction comes from the one
before, and the radius of p_i^y relative to p_i^y grows by a factor of about
(h + 3d)/(h − d) = 2e^L − 1 per stick (L = ln((h+d)/(h−d)): about e^{2L} for small d/h, about
e^L as d → h), a pessimism of the balls, not an error of the construction. Measured on balls of
2000 extra digits (d/h from 0.001 to 0.99, ranges up to 40001 sticks, tilted first sticks), the
digits p lost were within 0–6 of ``extra_digits_needed``; the tractrix and the stick directions
lose about half as many. ``extra_digits_needed`` is that loss over the range the construction
covers (stick 0 to i_min − 1 and i_max + 2), carried inside the construction only
(``Arithmetic.recursion``); ``balls.serve`` raises the precision further if a returned radius is
still too large. (The estimate before, 2·max|i|·L/ln 10 + 5, is the same for small d/h and up to
1.9× larger as d → h.)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any


def extra_digits_needed(h: float, d: float, i_min: int, i_max: int) -> int:
    """The digits the balls of p lose over the recursion: max|i|·log10((h + 3d)/(h − d)), plus
    2 (the guard digits leave 9 more before a point is unresolved)."""
    steps = max(abs(i_min - 1), abs(i_max + 2), 1)
    return math.ceil(steps * math.log10((h + 3 * d) / (h - d))) + 2


def extra_digits(arguments: Mapping[str, Any]) -> int:
    """``extra_digits_needed`` for a request's arguments (``h``, ``d``, ``i_min``, ``i_max``);
    the closed forms need none (their radii do not grow along the range)."""
    if arguments.get("method", "construction") != "construction":
        return 5
    h, d = float(arguments.get("h", 1.0)), float(arguments.get("d", 0.1))
    if not 0 < d < h:
        return 0  # refused by the construction's validation
    return extra_digits_needed(h, d, int(arguments["i_min"]), int(arguments["i_max"]))
