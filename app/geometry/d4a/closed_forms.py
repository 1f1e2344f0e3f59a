"""Explicit form of Sauer's discrete tractrix (D4a) (a theorem; not in the paper).

Let k = 1 − s/h and let c be the cusp stick (``sauer_tractrix``). A stick carried away from the
cusp has its end at height (h − s) sin β of the previous one, so with σ_i = sin β_i and
γ_i = cos β_i

    σ_i = σ_c k^{|i − c|},   γ_i = −√(1 − σ_i²) for i > c,  +√(1 − σ_i²) for i < c,

and the axis points advance by

    x_{i+1} − x_i = h(k γ_i − γ_{i+1})  (i ≥ c),     h(γ_i − k γ_{i+1})  (i < c),

both positive (they equal h(1 − k²)/(|γ_{i+1}| − kγ_i) and h(1 − k²)/(γ_i + k|γ_{i+1}|), the
forms used where the first would cancel). So d_i = x_i + h(γ_i, σ_i) is explicit in i up to the
partial sums x_i, which have no closed form (they add up √(1 − σ_c² k^{2j})). The heights
d_i^y = hσ_c k^{|i−c|} decay geometrically, like those of the smooth tractrix, h e^{−t/h} at arc
length t. The rotation centre p_i lies over the midpoint
of x_i x_{i+1} on the normal of stick i at distance H = h − s/2 from x_i, hence

    p_i = ((x_i + x_{i+1})/2,  (H − (x_{i+1} − x_i) γ_i / 2) / σ_i),

and e_i = x_i + (2h − s)(γ_i, σ_i). On the pursuit side (i ≥ c, γ_i ≤ 0, σ_{i+1} = kσ_i) this is
p_i^y = h(1 + kσ_i² + √((1 − σ_i²)(1 − k²σ_i²)))/(2σ_i), for the vertical start p_0^y = h − s/2.

The cusp: stick 0 is the cusp when hσ_0 > h − s; otherwise the cusp is j = ⌊log σ_0 / log k⌋
sticks away (behind stick 0 when it leans back, ahead when it leans forward, with the same lean)
and σ_c = σ_0 / k^j. At the exact boundaries σ_0 = k^j (σ_c = 1) the two computations of the cusp
agree only up to rounding.

Nothing here calls the construction: comparing the two tests this form.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from app.geometry.errors import NotRepresentableError
from app.geometry.precision import Arithmetic, Array, Scalar

#: rounding moves the floor of log(sin β0)/log(k) by a step or two at most
CUSP_SEARCH_STEPS = 8


@dataclass(frozen=True)
class Cusp:
    """The cusp stick: its index and its direction (cos β_c, sin β_c)."""

    index: int
    cos: Scalar
    sin: Scalar


@dataclass(frozen=True)
class ExplicitTractrix:
    """Explicit (D4a) on the indices i_lo .. i_hi (``(n, 2)``); p on i_lo .. i_hi − 1."""

    axis_points: Array
    tractrix: Array
    darboux: Array
    hyperbolic_cosine: Array
    cusp: Cusp


def cusp(ar: Arithmetic, h: Scalar, s: Scalar, beta0: float | None) -> Cusp:
    """The cusp stick of the (D4a) polygon whose stick 0 has angle beta0."""
    if beta0 is None:
        return Cusp(0, ar.scalar(0), ar.scalar(1))
    angle = ar.scalar(beta0)
    cos0, sin0 = ar.cos(angle), ar.sin(angle)
    what = "which stick is the cusp stick"
    if ar.exceeds(h * sin0, h - s, "beta0", what):
        return Cusp(0, cos0, sin0)
    k = (h - s) / h
    if not k < 1:
        raise NotRepresentableError(
            "s", "1 − s/h < 1 at this precision", float(s), "use more digits"
        )
    # the floor in the arithmetic's own precision: a float64 round trip would be off by
    # j·1e-16 sticks, and the search below would walk them one by one
    j = max(1, ar.truncate(ar.log(sin0) / ar.log(k)))
    for _ in range(CUSP_SEARCH_STEPS):  # at most a step or two of rounding either way
        if not ar.exceeds(h * sin0 / k**j, h - s, "beta0", what):
            j += 1
        elif j > 1 and ar.exceeds(h * sin0 / k ** (j - 1), h - s, "beta0", what):
            j -= 1
        else:
            break
    else:
        raise NotRepresentableError(
            "s", "s/h large enough for the cusp stick to be found", float(s), "use more digits"
        )
    sin_c = sin0 / k**j
    cos_c = ar.sqrt((1 - sin_c) * (1 + sin_c))
    leans_back = ar.exceeds(ar.scalar(0), cos0, "beta0", "which way stick 0 leans")
    return Cusp(-j, -cos_c, sin_c) if leans_back else Cusp(j, cos_c, sin_c)


def _advance(h: Scalar, k: Scalar, outer: Array, inner: Array) -> Array:
    """h(outer + k·inner) for outer > 0, rewritten as h(1 − k²)/(outer − k·inner) if inner < 0."""
    direct = h * (outer + k * inner)
    negative = inner < 0
    safe = np.where(negative, outer - k * inner, 1)
    return np.where(negative, h * (1 - k) * (1 + k) / safe, direct)


def tractrix(
    ar: Arithmetic, h: Scalar, s: Scalar, beta0: float | None, i_lo: int, i_hi: int
) -> ExplicitTractrix:
    """Explicit (D4a) on i_lo .. i_hi (i_lo <= 0 <= i_hi): x_i, d_i, e_i and p_i (to i_hi − 1).

    Every step is elementwise in i (``Arithmetic.points``, ``values``: float64 runs them in
    cache-sized blocks) except the partial sums x_i, one cumulative sum.
    """
    c = cusp(ar, h, s, beta0)
    k = (h - s) / h
    log_k = ar.log(k)
    n = i_hi - i_lo + 1

    def direction(i: Array) -> tuple[Array, Array]:
        """u_i = (γ_i, σ_i) from σ_i = σ_c k^{|i − c|}."""
        sin_b = c.sin * ar.exp(abs(i - c.index) * log_k)
        cos_abs = ar.sqrt((1 - sin_b) * (1 + sin_b))
        return np.where(i > c.index, -cos_abs, cos_abs), sin_b

    u = ar.points(direction, ar.indices(i_lo, i_hi))
    if c.index in range(i_lo, i_hi + 1):
        u[c.index - i_lo] = c.cos, c.sin
    cos_b, sin_b = u[:, 0], u[:, 1]

    def advance(i: Array, before: Array, after: Array) -> Array:
        """x_{i+1} − x_i from γ_i and γ_{i+1}, in the form without cancellation."""
        pursuit = i >= c.index
        outer = np.where(pursuit, abs(after), before)
        inner = np.where(pursuit, before, -after)
        return _advance(h, k, outer, inner)

    step = ar.values(advance, ar.indices(i_lo, i_hi - 1), cos_b[:-1], cos_b[1:])
    x = ar.empty(n)
    x[0] = ar.scalar(0)
    np.cumsum(step, out=x[1:])
    x -= x[-i_lo]
    H = h - s / 2

    def centre(x: Array, step: Array, cos: Array, sin: Array, cos1: Array, sin1: Array) -> Any:
        """p_i on the normal of stick i, or of stick i+1, whichever avoids cancellation."""
        half = step / 2
        from_i = (H - half * cos) / sin
        from_next = (H + half * cos1) / sin1
        return x + half, np.where(-cos >= cos1, from_i, from_next)

    p = ar.points(centre, x[:-1], step, cos_b[:-1], sin_b[:-1], cos_b[1:], sin_b[1:])
    darboux_length = 2 * h - s
    return ExplicitTractrix(
        axis_points=ar.points(lambda x: (x, ar.zeros(len(x))), x),
        tractrix=ar.points(lambda x, c, s: (x + h * c, h * s), x, cos_b, sin_b),
        darboux=ar.points(
            lambda x, c, s: (x + darboux_length * c, darboux_length * s), x, cos_b, sin_b
        ),
        hyperbolic_cosine=p,
        cusp=c,
    )
