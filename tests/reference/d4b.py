"""An independent high-precision (D4b): plain mpmath, no code shared with app.geometry.

Different algorithm on purpose: the rotation centre is found by solving the 2×2 linear system of
the two lines with ``mpmath.lu_solve``, the rotation angle with ``atan2`` and the rotation with
``cos``/``sin`` of that angle, and d_i by rotating the point d_{i−1} (not the direction).
"""

from __future__ import annotations

import mpmath


def construct(h: str, d: str, beta0: str | None, i_min: int, i_max: int, dps: int = 60):
    """Dicts i -> (x, y) of mpf for p_i, d_i (tractrix) and x_i (axis), i in i_min..i_max."""
    ctx = mpmath.MPContext()
    ctx.dps = dps
    h_, d_ = ctx.mpf(h), ctx.mpf(d)
    beta = ctx.pi / 2 if beta0 is None else ctx.mpf(beta0)
    axis = {i: (2 * d_ * i, ctx.mpf(0)) for i in range(min(0, i_min - 1), max(0, i_max) + 1)}
    tip = {0: (h_ * ctx.cos(beta), h_ * ctx.sin(beta))}
    centre = {}

    def centre_for(i_from: int, i_to: int):
        # on x = (x_from + x_to)/2 and on the line through tip[i_from] orthogonal to that stick
        (ax, _), (bx, _) = axis[i_from], axis[i_to]
        tx, ty = tip[i_from]
        ux, uy = tx - axis[i_from][0], ty
        a = ctx.matrix([[1, 0], [ux, uy]])
        b = ctx.matrix([(ax + bx) / 2, ux * tx + uy * ty])
        sol = ctx.lu_solve(a, b)
        return sol[0], sol[1]

    def rotate(point, about, angle):
        x, y = point[0] - about[0], point[1] - about[1]
        c, s = ctx.cos(angle), ctx.sin(angle)
        return about[0] + c * x - s * y, about[1] + s * x + c * y

    def step(i_from: int, i_to: int) -> None:
        p = centre_for(i_from, i_to)
        a = (axis[i_from][0] - p[0], -p[1])
        b = (axis[i_to][0] - p[0], -p[1])
        angle = ctx.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1])
        tip[i_to] = rotate(tip[i_from], p, angle)
        centre[max(i_from, i_to)] = p

    for i in range(1, max(0, i_max) + 1):
        step(i - 1, i)
    for i in range(0, min(0, i_min - 1), -1):
        step(i, i - 1)
    keep = range(i_min, i_max + 1)
    return (
        {i: centre[i] for i in keep},
        {i: tip[i] for i in keep},
        {i: axis[i] for i in keep},
    )
