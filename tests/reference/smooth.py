"""An independent high-precision evolute of the tractrix: plain mpmath, no code from app.

Different algorithm on purpose: the derivatives of x ↦ (x − h tanh(x/h), h sech(x/h)) are taken
numerically with ``mpmath.diff`` (not by hand), and the centre of curvature is the point on the
normal at distance 1/κ, κ = (x'y'' − y'x'')/(x'² + y'²)^{3/2}.
"""

from __future__ import annotations

import mpmath


def tractrix_evolute(h: str, xs: list[str], dps: int = 60):
    """Lists of (x, y) mpf: the tractrix points and their centres of curvature."""
    ctx = mpmath.MPContext()
    ctx.dps = dps
    h_ = ctx.mpf(h)

    def fx(t):
        return t - h_ * ctx.tanh(t / h_)

    def fy(t):
        return h_ / ctx.cosh(t / h_)

    points, centres = [], []
    for x in map(ctx.mpf, xs):
        dx, ddx = ctx.diff(fx, x, 1), ctx.diff(fx, x, 2)
        dy, ddy = ctx.diff(fy, x, 1), ctx.diff(fy, x, 2)
        speed = ctx.sqrt(dx**2 + dy**2)
        curvature = (dx * ddy - dy * ddx) / speed**3
        normal = (-dy / speed, dx / speed)
        points.append((fx(x), fy(x)))
        centres.append((fx(x) + normal[0] / curvature, fy(x) + normal[1] / curvature))
    return points, centres
