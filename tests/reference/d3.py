"""An independent high-precision (D3): plain mpmath, no code shared with app.geometry.

Different algorithm on purpose: each step finds both heights w with
δ(y + w)/2 = c√(δ² + (w − y)²) by bracketing on the unsquared condition (bisection, then
mpmath's Anderson–Björck solver). F(w) = δ(y + w)/2 − c√(δ² + (w − y)²) is concave, has its
maximum where (w − y)/√(δ² + (w − y)²) = δ/(2c) and tends to −∞ on both sides (δ < 2c), so each
root is bracketed between the maximum and a far point. No quadratic formula, no closed form.
"""

from __future__ import annotations

import mpmath


def construct(c: str, delta: str, y0: str, branch: str, i_min: int, i_max: int, dps: int = 60):
    """Dict i -> (x, y) of mpf for i in i_min .. i_max."""
    ctx = mpmath.MPContext()
    ctx.dps = dps
    c_, d_ = ctx.mpf(c), ctx.mpf(delta)

    def roots(y):
        def F(w):
            return d_ * (y + w) / 2 - c_ * ctx.sqrt(d_**2 + (w - y) ** 2)

        rho = d_ / (2 * c_)
        top = y + d_ * rho / ctx.sqrt(1 - rho**2)  # where F is largest
        assert F(top) >= 0, "no real step"
        far = 10 * (abs(y) + d_ + c_)

        def bisect(inside, outside):
            # bisection to a narrow bracket, then the bracketing Anderson–Björck solver
            for _ in range(40):
                mid = (inside + outside) / 2
                if F(mid) >= 0:
                    inside = mid
                else:
                    outside = mid
            return ctx.findroot(F, (inside, outside), solver="anderson")

        lower = top - far
        while F(lower) >= 0:
            lower -= far
        upper = top + far
        while F(upper) >= 0:
            upper += far
        return bisect(top, upper), bisect(top, lower)

    y = {0: ctx.mpf(y0)}
    big, small = roots(y[0])
    y[1], y[-1] = (big, small) if branch == "up" else (small, big)
    for i in range(2, i_max + 1):
        a, b = roots(y[i - 1])
        y[i] = a if abs(a - y[i - 2]) > abs(b - y[i - 2]) else b
    for i in range(-2, i_min - 1, -1):
        a, b = roots(y[i + 1])
        y[i] = a if abs(a - y[i + 2]) > abs(b - y[i + 2]) else b
    return {i: (i * d_, y[i]) for i in range(i_min, i_max + 1)}
