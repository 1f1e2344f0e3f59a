"""An independent high-precision (D4a): plain mpmath, no code shared with app.geometry.

Different algorithm on purpose: sticks are pairs of points (x, d); every move intersects a
circle with the x-axis (the new leader at distance h from the new end, or the carrying stick's
axis end at distance h − s from the carried point), and p_i and e_i come from the tractrix
points alone: p_i solves the two perpendicular-bisector equations of the carried edges with
``lu_solve``, e_i reflects x_i in the carried edge's midpoint. No angles, no explicit form.
Same definition: the cusp stick is the one whose end is higher than h − s; the pursuit runs away
from it on both sides (see app/geometry/d4a/construction.py for the geometry).
"""

from __future__ import annotations

import mpmath


def construct(h: str, s: str, beta0: str | None, i_min: int, i_max: int, dps: int = 60):
    """Dicts i -> (x, y) of mpf for p_i, d_i, x_i, e_i on i_min .. i_max, and the cusp index."""
    ctx = mpmath.MPContext()
    ctx.dps = dps
    h_, s_ = ctx.mpf(h), ctx.mpf(s)
    beta = ctx.pi / 2 if beta0 is None else ctx.mpf(beta0)
    lo, hi = min(0, i_min - 1), max(0, i_max + 3)
    leader = {0: ctx.mpf(0)}
    end = {0: (h_ * ctx.cos(beta), h_ * ctx.sin(beta)) if beta0 is not None else (ctx.mpf(0), h_)}
    kind = {}

    def is_cusp(i):
        return end[i][1] > h_ - s_

    def classify(i, default):
        kind[i] = "cusp" if is_cusp(i) else default

    def moved(i):
        """The point of stick i at distance s from its end, towards its leader."""
        (dx, dy), x = end[i], leader[i]
        return dx + s_ * (x - dx) / h_, dy - s_ * dy / h_

    def extended(x, carried):
        """The end of the stick from axis point x through ``carried`` (h − s away from x)."""
        scale = h_ / (h_ - s_)
        return x + scale * (carried[0] - x), scale * carried[1]

    def leader_for(point, radius, right):
        half = ctx.sqrt(radius**2 - point[1] ** 2)
        return point[0] + half if right else point[0] - half

    lean_back = end[0][0] < leader[0]
    classify(0, "pursuit" if lean_back else "mirrored")
    for i in range(1, hi + 1):
        if kind[i - 1] in ("cusp", "pursuit"):  # d_i on stick i − 1, leader ahead
            end[i] = moved(i - 1)
            leader[i] = leader_for(end[i], h_, right=True)
            kind[i] = "pursuit"
        else:  # stick i carries d_{i−1}; it leans forward: its leader is left of d_{i−1}
            carried = end[i - 1]
            leader[i] = leader_for(carried, h_ - s_, right=False)
            end[i] = extended(leader[i], carried)
            classify(i, "mirrored")
    for i in range(-1, lo - 1, -1):
        if kind[i + 1] in ("cusp", "mirrored"):  # d_i on stick i + 1, leader behind
            end[i] = moved(i + 1)
            leader[i] = leader_for(end[i], h_, right=False)
            kind[i] = "mirrored"
        else:  # stick i carries d_{i+1}; it leans back: its leader is right of d_{i+1}
            carried = end[i + 1]
            leader[i] = leader_for(carried, h_ - s_, right=True)
            end[i] = extended(leader[i], carried)
            classify(i, "pursuit")

    def edge(i):
        return (end[i - 1], end[i]) if kind[i] == "mirrored" else (end[i], end[i + 1])

    def bisector(i):
        a, b = edge(i)
        n = (b[0] - a[0], b[1] - a[1])
        m = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        return n, n[0] * m[0] + n[1] * m[1]

    p, e = {}, {}
    for i in range(i_min, i_max + 1):
        (n1, c1), (n2, c2) = bisector(i), bisector(i + 1)
        solution = ctx.lu_solve(ctx.matrix([[n1[0], n1[1]], [n2[0], n2[1]]]), ctx.matrix([c1, c2]))
        p[i] = (solution[0], solution[1])
        a, b = edge(i)
        e[i] = (a[0] + b[0] - leader[i], a[1] + b[1])
    keep = range(i_min, i_max + 1)
    cusp = next((i for i in kind if kind[i] == "cusp"), None)
    return (
        p,
        {i: end[i] for i in keep},
        {i: (leader[i], ctx.mpf(0)) for i in keep},
        e,
        cusp,
    )
