"""Section 2: the smooth catenary and tractrix, (S1)–(S4).

Each statement of the paper is defined here once; see ``app.geometry.catalog``.
"""

from __future__ import annotations

from app.geometry.catalog.conditions import (
    S4_CUSP,
    S4_LEADER,
)
from app.geometry.checks import Statement

S4_PURSUIT = Statement(
    "tractrix-s4",
    "Section 2, (S4): the tractrix as a pursuit curve",
    "|d(x) − (x, 0)| = h and the tangent d'(x) points along the stick towards (x, 0). Residual: "
    "largest of | |d − (x, 0)| − h | and |d' × ((x, 0) − d)|, relative to the magnitude of the "
    "numbers involved.",
    conditions=(S4_LEADER,),
)

S4_EVOLUTE = Statement(
    "evolute-s4",
    "Section 2, (S4): the evolute of the tractrix is the hyperbolic cosine",
    "The centre of curvature q(x) = d + (|d'|²/(d' × d'')) J d', computed from the tractrix's "
    "derivatives, equals (x, h cosh(x/h)). Residual: largest |q(x) − (x, h cosh(x/h))| relative "
    "to the magnitude of the two points; the cusp x = 0 (where d' = 0) is skipped.",
    conditions=(S4_CUSP,),
)

S4_NIKOLAIDES = Statement(
    "nikolaides-s4",
    "Section 2, (S4): construction of Nikolaides",
    "The triangle (x, 0), q(x), d(x) has a right angle at d(x). Residual: largest |cos| of that "
    "angle, with the vectors measured against the magnitude of their end points; the cusp is "
    "skipped.",
    conditions=(S4_CUSP,),
)
