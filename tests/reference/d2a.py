"""An independent high-precision (D2a): plain mpmath, no code shared with app.geometry.

Different algorithm on purpose: the stereographic images are the complex numbers
w = (f + i)/(f − i) (the Cayley map, which is Φ restricted to the y-axis), computed with
``mpc`` at a working precision raised by the digits that the differences of nearby images cancel;
each dual edge is the complex inversion k/conj(Δw) of (1) (equal to k Δφ/‖Δφ‖²); the vertices
are added one by one in a loop from p_0 = (0, r); the hexagonal sequence is built by applying the
similarity b/a repeatedly.
"""

from __future__ import annotations

import mpmath


def _context(dps: int, f_values: list) -> mpmath.MPContext:
    ctx = mpmath.MPContext()
    spread = max(abs(mpmath.log10(abs(v))) for v in f_values if v != 0)
    ctx.dps = dps + 2 * int(spread) + 10
    return ctx


def _dual(ctx, f: dict, weight, r, i_min: int, i_max: int):
    """Dicts i -> (x, y) of mpf: p_i from the f_i (dict covering min(0,i_min)..max(0,i_max))."""
    w = {i: ctx.mpc(v, 1) / ctx.mpc(v, -1) for i, v in f.items()}
    p = {0: (ctx.mpf(0), ctx.mpf(r))}

    def edge(i):  # p_{i+1} − p_i
        delta = w[i + 1] - w[i]
        e = weight(i) / ctx.conj(delta)
        return e.real, e.imag

    for i in range(0, max(0, i_max)):
        ex, ey = edge(i)
        p[i + 1] = (p[i][0] + ex, p[i][1] + ey)
    for i in range(-1, min(0, i_min) - 1, -1):
        ex, ey = edge(i)
        p[i] = (p[i + 1][0] - ex, p[i + 1][1] - ey)
    phi = {i: (w[i].real, w[i].imag) for i in f}
    keep = range(i_min, i_max + 1)
    return {i: p[i] for i in keep}, {i: phi[i] for i in keep}, {i: f[i] for i in keep}


def quad(f0: str, f1: str, r: str | None, i_min: int, i_max: int, dps: int = 60):
    """(p, φ, f) of (D2a) quad; r = None means r* = −f1(1 + f0²)/(2(f1 − f0)²)."""
    lo, hi = min(0, i_min), max(0, i_max)
    probe = [mpmath.mpf(f0) * (mpmath.mpf(f1) / mpmath.mpf(f0)) ** i for i in (lo, hi)]
    ctx = _context(dps, probe)
    a, b = ctx.mpf(f0), ctx.mpf(f1)
    f = {0: a}
    for i in range(1, hi + 1):  # (3): f_i = f_{i−1} f1/f0
        f[i] = f[i - 1] * b / a
    for i in range(-1, lo - 1, -1):
        f[i] = f[i + 1] * a / b
    start = -b * (1 + a * a) / (2 * (b - a) ** 2) if r is None else ctx.mpf(r)
    return _dual(ctx, f, lambda i: 1, start, i_min, i_max)


def hexagonal(a: str, b: str, lam: str, r: str | None, i_min: int, i_max: int, dps: int = 60):
    """(p, φ, f) of (D2a) hexagonal; r = None means r* of the proof of Theorem 2 (corrected)."""
    lo, hi = min(0, i_min) - 2, max(0, i_max) + 2
    s = mpmath.mpf(b) / mpmath.mpf(a)
    probe = [mpmath.mpf(a) * s ** (i / 2) for i in (lo, hi)]
    ctx = _context(dps, probe)
    A, B, L = ctx.mpf(a), ctx.mpf(b), ctx.mpf(lam)
    f = {0: A}
    for i in range(2, hi + 1, 2):
        f[i] = f[i - 2] * B / A
    for i in range(-2, lo - 1, -2):
        f[i] = f[i + 2] * A / B
    lo_even = lo if lo % 2 == 0 else lo + 1
    for i in range(lo_even + 1, hi, 2):
        f[i] = L * f[i + 1] + (1 - L) * f[i - 1]
    if r is None:
        m = L - 1
        num = 3 * A**3 * m**2 - 5 * A**2 * B * m * L + 2 * A * B**2 * L**2 - B * (L - 3)
        start = num / (2 * L * m * (A - B) ** 2)
    else:
        start = ctx.mpf(r)
    needed = {i: f[i] for i in range(min(0, i_min), max(0, i_max) + 1)}
    return _dual(ctx, needed, lambda i: 3 if i % 2 == 0 else 2, start, i_min, i_max)
