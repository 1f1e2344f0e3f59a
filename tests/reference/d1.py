"""An independent high-precision (D1): plain mpmath, no code shared with app.geometry.

Different algorithm on purpose: each step solves the unsquared difference equation
Δ²y_i = c(l_i + l_{i+1}) for the unknown height by Newton's method. As a function of the next
edge's rise t, f(t) = t − t_prev − c(l_prev + √(δ² + t²)) is increasing and concave (f' ≥ 1 − c),
so Newton started left of the root climbs to it monotonically; backwards the same holds for the
mirrored unknown. No quadratic, no closed form.
"""

from __future__ import annotations

import mpmath


def construct(c: str, delta: str, y0: str, y1: str, i_min: int, i_max: int, dps: int = 60):
    """Dict i -> (x, y) of mpf for i in i_min .. i_max."""
    ctx = mpmath.MPContext()
    ctx.dps = dps
    c_, d_ = ctx.mpf(c), ctx.mpf(delta)
    tol = ctx.mpf(10) ** (-dps + 5)

    def solve(known_rise):
        """The rise t of the edge after one with rise ``known_rise``."""
        known_length = ctx.sqrt(d_**2 + known_rise**2)

        def f(t):
            return t - known_rise - c_ * (known_length + ctx.sqrt(d_**2 + t**2))

        def df(t):
            return 1 - c_ * t / ctx.sqrt(d_**2 + t**2)

        t = known_rise - 10 * (abs(known_rise) + d_)  # left of the root: f(t) < 0
        assert f(t) < 0
        for _ in range(500):
            step = f(t) / df(t)
            t -= step
            if abs(step) <= tol * (1 + abs(t)):
                return t
        raise AssertionError("Newton did not converge")

    y = {0: ctx.mpf(y0), 1: ctx.mpf(y1)}
    for i in range(2, i_max + 1):
        y[i] = y[i - 1] + solve(y[i - 1] - y[i - 2])
    for i in range(-1, i_min - 1, -1):
        # mirrored: the rise of edge i, read backwards, follows the reversed rise of edge i + 1
        y[i] = y[i + 1] + solve(y[i + 1] - y[i + 2])
    return {i: (i * d_, y[i]) for i in range(i_min, i_max + 1)}
