"""(D4b): the residuals of the Section 3–4 checks on balls in compiled loops.

On balls (precision=mp) each check of ``checks`` is a chain of numpy operations on object
arrays of python-flint ``arb``: every operation a Python call and a fresh ball per entry, ≈ 0.2–1
µs each, 100 and more a vertex for the fits of Theorem 4. Here the same chains run in numba
loops that call libflint's functions on the balls' ``arb_struct`` (``arb_loops``): the
intermediates live in scratch balls reused along the loop, and only the residuals a check
reports (and the fits' constants) are written into fresh Python balls. Every function below
makes the same libflint calls, with the same operands in the same order and at the same
precision (``flint.ctx.prec``), as the Python code it stands for, so the balls are the same,
bit for bit (tests/geometry/d4b/test_arb_checks.py compares them); the checks, their decimal
bounds per index and their verdicts do not move.

``AVAILABLE`` false (another python-flint build, a function missing) leaves the callers on their
numpy code; the callers also check that every entry is a ball before an address is read.
The loops call libflint by symbol name (``arb_loops.extern``) and are cached on disk by numba
(``arb_loops.loop``): a process loads them at import (≈ 0.1 s) instead of compiling them (≈ 4 s
of CPU); ``python -m app.geometry.warm`` fills the cache.
"""

from __future__ import annotations

import ctypes
import weakref
from typing import Any

import flint
import numpy as np

from app.geometry import arb_loops
from app.geometry.ball_arithmetic import all_balls

_POINTER, _WORD = ctypes.c_void_p, ctypes.c_long
_BINARY = (None, [_POINTER, _POINTER, _POINTER, _WORD])
_UNARY = (None, [_POINTER, _POINTER, _WORD])
_COPY = (None, [_POINTER, _POINTER])
_TEST = (ctypes.c_int, [_POINTER, _POINTER])

_add = arb_loops.extern("arb_add", *_BINARY)
_sub = arb_loops.extern("arb_sub", *_BINARY)
_mul = arb_loops.extern("arb_mul", *_BINARY)
_div = arb_loops.extern("arb_div", *_BINARY)
_pow = arb_loops.extern("arb_pow", *_BINARY)
_max = arb_loops.extern("arb_max", *_BINARY)
_atan2 = arb_loops.extern("arb_atan2", *_BINARY)
_arb_abs = arb_loops.extern("arb_abs", *_COPY)
_set_round = arb_loops.extern("arb_set_round", *_UNARY)
_set = arb_loops.extern("arb_set", *_COPY)
_gt = arb_loops.extern("arb_gt", *_TEST)
_exp = arb_loops.extern("arb_exp", *_UNARY)

#: Whether the compiled residuals can be used (else the callers' numpy code runs).
AVAILABLE = arb_loops.AVAILABLE and all(
    f is not None
    for f in (
        _add,
        _sub,
        _mul,
        _div,
        _pow,
        _max,
        _atan2,
        _arb_abs,
        _set_round,
        _set,
        _gt,
        _exp,
    )
)

_B = arb_loops.ARB_BYTES
_hypot: Any = arb_loops._hypot if AVAILABLE else None


#: ``count`` fresh balls for a loop to write into (``arb_loops.fresh``: read-only afterwards,
#: their addresses remembered).
fresh = arb_loops.fresh


def balls(*arrays: Any) -> bool:
    """Whether the compiled loops apply: available, and every entry of every array a ball
    (known for the arrays of ``arb_loops.keep`` and their views)."""
    return AVAILABLE and all(
        isinstance(a, np.ndarray) and a.dtype == object and all_balls(a) for a in arrays
    )


def _address(ball: Any) -> int:
    return id(ball) + arb_loops.OFFSET


if AVAILABLE:

    @arb_loops.loop
    def _abs(out: int, x: int, prec: int) -> None:
        """|x| as python-flint's ``abs`` makes it: rounded to the working precision."""
        _arb_abs(out, x)
        _set_round(out, out, prec)

    @arb_loops.loop
    def _relative(out: int, computed: int, expected: int, tiny: int, scale: int, prec: int) -> None:
        """``checks.relative_difference`` of one entry: |c − e| / (|e| if |e| > tiny else
        tiny)."""
        _abs(scale, expected, prec)
        _sub(out, computed, expected, prec)
        _abs(out, out, prec)
        _div(out, out, scale if _gt(scale, tiny) else tiny, prec)

    @arb_loops.loop
    def _recursion_13(
        y: Any, d: int, two_d: int, one: int, tiny: int, out: Any, prec: int, s: int
    ) -> None:
        """``relative_difference(y[2:], closed_forms.recursion_13(d, y[:-2], y[1:-1]))``."""
        ba, t, da, db, num, den = s, s + _B, s + 2 * _B, s + 3 * _B, s + 4 * _B, s + 5 * _B
        scale = s + 6 * _B
        for k in range(out.shape[0]):
            a, b = y[k], y[k + 1]
            # (b * (b / a) + 2 * d * (d / a) + d * (d / b)) / (1 - (d / a) * (d / b))
            _div(ba, b, a, prec)
            _mul(num, b, ba, prec)
            if k == 0:  # else d / a is the previous entry's d / b
                _div(da, d, a, prec)
            _mul(t, two_d, da, prec)
            _add(num, num, t, prec)
            _div(db, d, b, prec)
            _mul(t, d, db, prec)
            _add(num, num, t, prec)
            _mul(t, da, db, prec)
            _sub(den, one, t, prec)
            _div(num, num, den, prec)
            _relative(out[k], y[k + 2], num, tiny, scale, prec)
            da, db = db, da

    @arb_loops.loop
    def _two_step(
        y: Any,
        d: int,
        d2: int,
        d4: int,
        small: Any,
        tiny: int,
        corrected: Any,
        printed: Any,
        prec: int,
        s: int,
    ) -> None:
        """``relative_difference(y[3:], closed_forms.two_step(d, a, b))`` into ``corrected`` and
        the same of ``two_step_printed`` into ``printed`` (a = y[:-3], b = y[1:-2]); ``small``
        holds the exact balls 1 … 5."""
        one, two, three, four, five = small[0], small[1], small[2], small[3], small[4]
        e, f, r, q = s, s + _B, s + 2 * _B, s + 3 * _B
        t, u, num, acc = s + 4 * _B, s + 5 * _B, s + 6 * _B, s + 7 * _B
        scale = s + 8 * _B
        # a², a³ and b², b³ (a of entry k + 1 is b of entry k: its powers and d/a are kept)
        a2, a3, b2, b3 = s + 9 * _B, s + 10 * _B, s + 11 * _B, s + 12 * _B
        for k in range(corrected.shape[0]):
            a, b, target = y[k], y[k + 1], y[k + 3]
            # e = d / a; f = d / b
            if k == 0:
                _div(e, d, a, prec)
            _div(f, d, b, prec)
            # b * (b / a) * (b / a)
            _div(r, b, a, prec)
            _mul(num, b, r, prec)
            _mul(num, num, r, prec)
            # (d * f) * (a / b + 2 + 3 * (b / a) + 4 * (b / a) * (b / a))
            _div(q, a, b, prec)
            _add(acc, q, two, prec)
            _mul(t, three, r, prec)
            _add(acc, acc, t, prec)
            _mul(t, four, r, prec)
            _mul(t, t, r, prec)
            _add(acc, acc, t, prec)
            _mul(t, d, f, prec)
            _mul(t, t, acc, prec)
            _add(num, num, t, prec)
            # + (d * e) * (e * f) * (2 * (a / b) + 3)
            _mul(t, d, e, prec)
            _mul(u, e, f, prec)
            _mul(t, t, u, prec)
            _mul(acc, two, q, prec)
            _add(acc, acc, three, prec)
            _mul(t, t, acc, prec)
            _add(num, num, t, prec)
            # / ((1 - e * f) * (1 - e * f))
            _sub(u, one, u, prec)
            _mul(u, u, u, prec)
            _div(num, num, u, prec)
            _relative(corrected[k], target, num, tiny, scale, prec)
            # b**5 + d**2 * (a**3 + 2 * a**2 * b + 3 * a * b**2 + 4 * b**3)
            #   + d**4 * (2 * b**3 + 2 * a + 3 * b), over (d**2 - a * b) ** 2
            _pow(num, b, five, prec)
            if k == 0:
                _pow(a3, a, three, prec)
                _pow(a2, a, two, prec)
            _mul(t, two, a2, prec)
            _mul(t, t, b, prec)
            _add(acc, a3, t, prec)
            _mul(t, three, a, prec)
            _pow(b2, b, two, prec)
            _mul(t, t, b2, prec)
            _add(acc, acc, t, prec)
            _pow(b3, b, three, prec)
            _mul(t, four, b3, prec)
            _add(acc, acc, t, prec)
            _mul(acc, d2, acc, prec)
            _add(num, num, acc, prec)
            _mul(acc, two, b3, prec)
            _mul(t, two, a, prec)
            _add(acc, acc, t, prec)
            _mul(t, three, b, prec)
            _add(acc, acc, t, prec)
            _mul(acc, d4, acc, prec)
            _add(num, num, acc, prec)
            _mul(t, a, b, prec)
            _sub(t, d2, t, prec)
            _pow(t, t, two, prec)
            _div(num, num, t, prec)
            _relative(printed[k], target, num, tiny, scale, prec)
            e, f = f, e  # the next entry's d / a, and a scratch ball
            a2, b2 = b2, a2
            a3, b3 = b3, a3

    @arb_loops.loop
    def _magnitude_into(out: int, a: Any, i: int, v: Any, j: int, prec: int, t: int) -> None:
        """``polygon.magnitude(a, v)`` of one pair: ((|a^x| + |a^y|) + |v^x|) + |v^y|."""
        _abs(out, a[2 * i], prec)
        _abs(t, a[2 * i + 1], prec)
        _add(out, out, t, prec)
        _abs(t, v[2 * j], prec)
        _add(out, out, t, prec)
        _abs(t, v[2 * j + 1], prec)
        _add(out, out, t, prec)

    @arb_loops.loop
    def _right_angle(
        out: int, vertex: Any, i: int, ux: int, uy: int, ma: int, b: Any, m: int, prec: int, s: int
    ) -> None:
        """``nikolaides.right_angle_residuals`` of one entry: vertex_i, a_j, b_m, where ux, uy
        hold a_j − vertex_i and ``ma`` the magnitude of (a_j, vertex_i), which both entries at
        vertex_i share (``_nikolaides``)."""
        wx, wy, dot, t, mb = s, s + _B, s + 2 * _B, s + 3 * _B, s + 4 * _B
        _sub(wx, b[2 * m], vertex[2 * i], prec)
        _sub(wy, b[2 * m + 1], vertex[2 * i + 1], prec)
        _mul(dot, ux, wx, prec)
        _mul(t, uy, wy, prec)
        _add(dot, dot, t, prec)
        _abs(dot, dot, prec)
        _magnitude_into(mb, b, m, vertex, i, prec, t)
        _mul(mb, ma, mb, prec)
        _div(out, dot, mb, prec)

    @arb_loops.loop
    def _nikolaides(tractrix: Any, axis: Any, p: Any, out: Any, prec: int, s: int) -> None:
        """max(right angle at p_i, at p_{i+1}) (``arb_max``), as ``checks._nikolaides``."""
        at_p, at_next, ux, uy, ma = s, s + _B, s + 2 * _B, s + 3 * _B, s + 4 * _B
        t, scratch = s + 5 * _B, s + 6 * _B
        for k in range(out.shape[0]):
            _sub(ux, axis[2 * k], tractrix[2 * k], prec)
            _sub(uy, axis[2 * k + 1], tractrix[2 * k + 1], prec)
            _magnitude_into(ma, axis, k, tractrix, k, prec, t)
            _right_angle(at_p, tractrix, k, ux, uy, ma, p, k, prec, scratch)
            _right_angle(at_next, tractrix, k, ux, uy, ma, p, k + 1, prec, scratch)
            _max(out[k], at_p, at_next, prec)

    # --- the columns of (D1), (D3) and eq. (2), and their fits ---

    #: Column numbers in a ``Columns`` block (each ``stride`` balls long).
    LENGTHS, SIZES, AREAS, AREA_SIZES, SECOND, SECOND_SIZES = 0, 1, 2, 3, 4, 5

    @arb_loops.loop
    def _columns(p: Any, count: int, block: int, two: int, prec: int, s: int) -> None:
        """The columns of ``polygon`` for the ``count`` vertices at ``p`` into ``block``
        (column j, entry k at ball j·count + k), as ``edge_lengths`` (``arb_loops``' hypot),
        ``edge_magnitude``, ``signed_areas``, ``area_magnitude``, ``second_difference`` and
        ``second_difference_magnitude`` compute them."""
        ex, ey, square, t = s, s + _B, s + 2 * _B, s + 3 * _B
        # |x_k| and |y_k| (python-flint's abs) once a vertex: at 5 + 2k and 6 + 2k
        sizes = s + 5 * _B
        for k in range(count):
            _abs(sizes + 2 * k * _B, p[2 * k], prec)
            _abs(sizes + (2 * k + 1) * _B, p[2 * k + 1], prec)
        for k in range(count - 1):
            x0, y0, x1, y1 = p[2 * k], p[2 * k + 1], p[2 * k + 2], p[2 * k + 3]
            ax0, ay0 = sizes + 2 * k * _B, sizes + (2 * k + 1) * _B
            ax1, ay1 = sizes + (2 * k + 2) * _B, sizes + (2 * k + 3) * _B
            length = block + (LENGTHS * count + k) * _B
            size = block + (SIZES * count + k) * _B
            area = block + (AREAS * count + k) * _B
            area_size = block + (AREA_SIZES * count + k) * _B
            _sub(ex, x1, x0, prec)
            _sub(ey, y1, y0, prec)
            _hypot(length, ex, ey, prec, square)
            # ((|x0| + |y0|) + |x1|) + |y1|
            _add(size, ax0, ay0, prec)
            _add(size, size, ax1, prec)
            _add(size, size, ay1, prec)
            # (y0 + y1) / 2 * (x1 − x0)
            _add(area, y0, y1, prec)
            _div(area, area, two, prec)
            _mul(area, area, ex, prec)
            # (|y0| + |y1|) / 2 * (|x0| + |x1|)
            _add(area_size, ay0, ay1, prec)
            _div(area_size, area_size, two, prec)
            _add(t, ax0, ax1, prec)
            _mul(area_size, area_size, t, prec)
        for k in range(count - 2):
            y0, y1, y2 = p[2 * k + 1], p[2 * k + 3], p[2 * k + 5]
            ay0 = sizes + (2 * k + 1) * _B
            ay1, ay2 = ay0 + 2 * _B, ay0 + 4 * _B
            second = block + (SECOND * count + k) * _B
            second_size = block + (SECOND_SIZES * count + k) * _B
            # y2 − 2·y1 + y0
            _mul(t, two, y1, prec)
            _sub(second, y2, t, prec)
            _add(second, second, y0, prec)
            # |y2| + 2·|y1| + |y0|
            _mul(t, two, ay1, prec)
            _add(second_size, ay2, t, prec)
            _add(second_size, second_size, ay0, prec)

    @arb_loops.loop
    def _entry(block: int, count: int, column: int, k: int) -> int:
        return block + (column * count + k) * _B

    @arb_loops.loop
    def _sides(
        block: int, count: int, kind: int, k: int, rhs: int, rhs_size: int, prec: int
    ) -> tuple[int, int, int, int]:
        """(lhs, |lhs|~, rhs, |rhs|~) of equation k of ``kind`` (0: (D1), 1: (D3), 2: eq. (2));
        the paired right sides (r_k + r_{k+1}) are formed into ``rhs`` and ``rhs_size``."""
        if kind == 1:
            return (
                _entry(block, count, AREAS, k),
                _entry(block, count, AREA_SIZES, k),
                _entry(block, count, LENGTHS, k),
                _entry(block, count, SIZES, k),
            )
        r, r_size = (LENGTHS, SIZES) if kind == 0 else (AREAS, AREA_SIZES)
        _add(rhs, _entry(block, count, r, k), _entry(block, count, r, k + 1), prec)
        _add(rhs_size, _entry(block, count, r_size, k), _entry(block, count, r_size, k + 1), prec)
        return (
            _entry(block, count, SECOND, k),
            _entry(block, count, SECOND_SIZES, k),
            rhs,
            rhs_size,
        )

    @arb_loops.loop
    def _fit_sums(
        block: int, count: int, kind: int, m: int, tiny: int, vv: int, uv: int, prec: int, s: int
    ) -> None:
        """``conditions.fit``'s two sums (mp: no scaling) over equations 0 … m − 1: Σ v·v into
        ``vv`` and Σ u·v into ``uv`` (numpy's order: from the first term on)."""
        rhs, rhs_size, u, v, t, w = s, s + _B, s + 2 * _B, s + 3 * _B, s + 4 * _B, s + 5 * _B
        for k in range(m):
            lhs, lhs_size, r, _ = _sides(block, count, kind, k, rhs, rhs_size, prec)
            weight = lhs_size if _gt(lhs_size, tiny) else tiny
            _div(u, lhs, weight, prec)
            _div(v, r, weight, prec)
            _set(w, v)  # v·v of two balls (numpy's product of two arrays: no squaring)
            _mul(t, v, w, prec)
            if k == 0:
                _set(vv, t)
            else:
                _add(vv, vv, t, prec)
            _mul(t, u, v, prec)
            if k == 0:
                _set(uv, t)
            else:
                _add(uv, uv, t, prec)

    @arb_loops.loop
    def _misfit(
        block: int,
        count: int,
        kind: int,
        c: int,
        size_c: int,
        tiny: int,
        out: Any,
        prec: int,
        s: int,
    ) -> None:
        """``conditions.misfit`` with the constant c (``size_c`` = |c|) into ``out``."""
        rhs, rhs_size, t, scale = s, s + _B, s + 2 * _B, s + 3 * _B
        for k in range(out.shape[0]):
            lhs, lhs_size, r, r_size = _sides(block, count, kind, k, rhs, rhs_size, prec)
            _mul(t, size_c, r_size, prec)
            _add(scale, lhs_size, t, prec)
            _mul(t, c, r, prec)
            _sub(t, lhs, t, prec)
            _abs(t, t, prec)
            _div(out[k], t, scale if _gt(scale, tiny) else tiny, prec)

    @arb_loops.loop
    def _ratio_spread(
        block: int, count: int, m: int, size: int, tiny: int, out: Any, prec: int, s: int
    ) -> None:
        """``checks._ratio_erratum``'s spread: ratio_j = Δ²y_{j+1} / (l_j + l_{j+1}) for
        j < m, their mean (sum from the first on, over ``size`` = m), and
        ``relative_difference(ratio, mean)``; the ratios are kept in ``out`` meanwhile."""
        t, total, scale = s, s + _B, s + 2 * _B
        for j in range(m):
            _add(
                t,
                _entry(block, count, LENGTHS, j),
                _entry(block, count, LENGTHS, j + 1),
                prec,
            )
            _div(out[j], _entry(block, count, SECOND, j + 1), t, prec)
            if j == 0:
                _set(total, out[j])
            else:
                _add(total, total, out[j], prec)
        _div(total, total, size, prec)
        for j in range(m):
            _relative(out[j], out[j], total, tiny, scale, prec)

    # --- the rotation angle, Darboux's transform ---

    @arb_loops.loop
    def _signed_angle(
        out: int, ax: int, ay: int, bx: int, by: int, prec: int, cross: int, t: int
    ) -> None:
        """``checks._signed_angle`` of one pair: atan2(a^x b^y − a^y b^x, a^x b^x + a^y b^y)."""
        _mul(cross, ax, by, prec)
        _mul(t, ay, bx, prec)
        _sub(cross, cross, t, prec)
        _mul(out, ax, bx, prec)
        _mul(t, ay, by, prec)
        _add(out, out, t, prec)
        _atan2(out, cross, out, prec)

    @arb_loops.loop
    def _rotation_angle(
        p: Any, axis: Any, d: int, two: int, out: Any, printed: Any, prec: int, s: int
    ) -> None:
        """``checks._rotation_angle`` on balls for i = 1 … n − 1 (k = i − 1): |angle at p_i
        between x_{i−1} and x_i − 2 atan2(d, p_i^y)| into ``out``, the printed indexing's
        (x_i and x_{i+1}) into ``printed``."""
        ax, ay, bx, by, cx, cy = s, s + _B, s + 2 * _B, s + 3 * _B, s + 4 * _B, s + 5 * _B
        formula, angle, cross, t = s + 6 * _B, s + 7 * _B, s + 8 * _B, s + 9 * _B
        for k in range(out.shape[0]):
            i = k + 1
            px, py = p[2 * i], p[2 * i + 1]
            _sub(ax, axis[2 * k], px, prec)  # x_{i−1} − p_i
            _sub(ay, axis[2 * k + 1], py, prec)
            _sub(bx, axis[2 * i], px, prec)  # x_i − p_i
            _sub(by, axis[2 * i + 1], py, prec)
            _signed_angle(angle, ax, ay, bx, by, prec, cross, t)
            _atan2(t, d, py, prec)
            _mul(formula, two, t, prec)
            _sub(angle, angle, formula, prec)
            _abs(out[k], angle, prec)
            _sub(cx, axis[2 * i + 2], px, prec)  # x_{i+1} − p_i
            _sub(cy, axis[2 * i + 3], py, prec)
            _signed_angle(angle, bx, by, cx, cy, prec, cross, t)
            _sub(angle, angle, formula, prec)
            _abs(printed[k], angle, prec)

    @arb_loops.loop
    def _distance(out: int, a: Any, i: int, b: Any, j: int, prec: int, dx: int, dy: int) -> None:
        """``checks.point_distance`` of one pair: hypot(a^x − b^x, a^y − b^y) (``arb_loops``'
        hypot, its square in ``dx``)."""
        _sub(dx, a[2 * i], b[2 * j], prec)
        _sub(dy, a[2 * i + 1], b[2 * j + 1], prec)
        _hypot(out, dx, dy, prec, dx)

    @arb_loops.loop
    def _add_size(total: int, a: Any, i: int, prec: int, t: int) -> None:
        """total + |a_i^x| + |a_i^y| (``polygon.magnitude``'s step)."""
        _abs(t, a[2 * i], prec)
        _add(total, total, t, prec)
        _abs(t, a[2 * i + 1], prec)
        _add(total, total, t, prec)

    @arb_loops.loop
    def _darboux(
        x: Any, e: Any, expected: int, edges: Any, distances: Any, prec: int, s: int
    ) -> None:
        """``darboux.edge_length_residuals`` into ``edges`` and ``distance_residuals`` (to
        ``expected``) into ``distances``, on balls."""
        ex, ee, dx, dy, size, t = s, s + _B, s + 2 * _B, s + 3 * _B, s + 4 * _B, s + 5 * _B
        # for the edges: |x_k^x|, |x_k^y|, |e_k^x|, |e_k^y| once a vertex, at 6 + 4k …
        sizes = s + 6 * _B
        for k in range(edges.shape[0] + 1 if edges.shape[0] else 0):
            _abs(sizes + 4 * k * _B, x[2 * k], prec)
            _abs(sizes + (4 * k + 1) * _B, x[2 * k + 1], prec)
            _abs(sizes + (4 * k + 2) * _B, e[2 * k], prec)
            _abs(sizes + (4 * k + 3) * _B, e[2 * k + 1], prec)
        for k in range(edges.shape[0]):
            _distance(ex, x, k + 1, x, k, prec, dx, dy)
            _distance(ee, e, k + 1, e, k, prec, dx, dy)
            here, after = sizes + 4 * k * _B, sizes + 4 * (k + 1) * _B
            # |x_{k+1}| + |x_k| + |e_{k+1}| + |e_k|, each |·^x| + |·^y|, from the left
            _add(size, after, after + _B, prec)
            _add(size, size, here, prec)
            _add(size, size, here + _B, prec)
            _add(size, size, after + 2 * _B, prec)
            _add(size, size, after + 3 * _B, prec)
            _add(size, size, here + 2 * _B, prec)
            _add(size, size, here + 3 * _B, prec)
            _sub(ee, ee, ex, prec)
            _abs(ee, ee, prec)
            _div(edges[k], ee, size, prec)
        for k in range(distances.shape[0]):
            _distance(ex, x, k, e, k, prec, dx, dy)
            _sub(ex, ex, expected, prec)
            _abs(ex, ex, prec)
            _abs(size, x[2 * k], prec)
            _abs(t, x[2 * k + 1], prec)
            _add(size, size, t, prec)
            _add_size(size, e, k, prec, t)
            _div(distances[k], ex, size, prec)

    @arb_loops.loop
    def _relative_distances(
        a: Any, b: Any, scales: Any, tiny: int, out: Any, prec: int, s: int
    ) -> None:
        """``checks.relative_to(point_distance(a, b), scales)`` entry by entry."""
        dx, dy, t = s, s + _B, s + 2 * _B
        for k in range(out.shape[0]):
            _distance(t, a, k, b, k, prec, dx, dy)
            _abs(t, t, prec)
            scale = scales[k]
            _div(out[k], t, scale if _gt(scale, tiny) else tiny, prec)

    @arb_loops.loop
    def _hypothesis(
        y: Any, d2: int, zero: int, violation: Any, ratios: Any, prec: int, s: int
    ) -> None:
        """``checks._hypothesis`` on balls: max(d² − y_{k} y_{k+1}, 0) / d² into ``violation``
        and y_k y_{k+1} / d² into ``ratios``."""
        product, t = s, s + _B
        for k in range(violation.shape[0]):
            _mul(product, y[k], y[k + 1], prec)
            _sub(t, d2, product, prec)
            _max(t, t, zero, prec)
            _div(violation[k], t, d2, prec)
            _div(ratios[k], product, d2, prec)

    @arb_loops.loop
    def _closed_kinematics(
        i: Any, constants: Any, p_x: Any, p_y: Any, d_x: Any, d_y: Any, prec: int, s: int
    ) -> None:
        """Theorems 5 and 6 from one exponential per index (``closed_forms.kinematic_balls``):
        E = e^t, t = i·L + τL; e^u = E·e^{−L/2} (u = t − L/2); p_i = (i·2d − d,
        a·(e^u + 1/e^u)·½), d_i = (i·2d − h·tanh t, h·sech t) with tanh t = 1 − 2/(E² + 1)
        and sech t = 2/(E + 1/E) (``constants``: L, τL, e^{−L/2}, 2d, d, h, a = √(h² − d²), 1,
        2, ½)."""
        length, offset, ratio, step, d, h, amplitude, one, two, half = (
            constants[0],
            constants[1],
            constants[2],
            constants[3],
            constants[4],
            constants[5],
            constants[6],
            constants[7],
            constants[8],
            constants[9],
        )
        t, e, w, x = s, s + _B, s + 2 * _B, s + 3 * _B
        for k in range(p_x.shape[0]):
            _mul(t, i[k], length, prec)
            _add(t, t, offset, prec)
            _exp(e, t, prec)
            _mul(x, i[k], step, prec)
            # p_i = (x − d, a·(e^u + 1/e^u)·½)
            _sub(p_x[k], x, d, prec)
            _mul(t, e, ratio, prec)
            _div(w, one, t, prec)
            _add(t, t, w, prec)
            _mul(t, t, half, prec)
            _mul(p_y[k], amplitude, t, prec)
            # d_i = (x − h·tanh t, h·sech t)
            _mul(t, e, e, prec)
            _add(t, t, one, prec)
            _div(t, two, t, prec)
            _sub(t, one, t, prec)
            _mul(t, h, t, prec)
            _sub(d_x[k], x, t, prec)
            _div(w, one, e, prec)
            _add(t, e, w, prec)
            _div(t, two, t, prec)
            _mul(d_y[k], h, t, prec)


class Columns:
    """The columns of (D1), (D3) and eq. (2) of a polygon of balls (``_columns``) in a block of
    flint's balls, freed with this object; the fits and misfits of those conditions on the
    polygon's first ``vertices`` vertices, and the ratio of the proof of Theorem 4 (i)."""

    def __init__(self, p: np.ndarray[Any, Any], tiny: Any) -> None:
        self.count = len(p)
        self.tiny = tiny
        self._two = flint.arb(2)
        self._scratch = arb_loops.Scratch(6 * self.count)
        self.block = self._scratch.__enter__()
        weakref.finalize(self, self._scratch.__exit__, None, None, None)
        if self.count >= 2:
            with arb_loops.Scratch(5 + 2 * self.count) as scratch:
                _columns(
                    arb_loops.addresses(p),
                    self.count,
                    self.block,
                    _address(self._two),
                    flint.ctx.prec,
                    scratch,
                )

    def equations(self, kind: int, vertices: int) -> int:
        """How many equations ``kind`` has on the first ``vertices`` vertices."""
        return max(vertices - (1 if kind == D3 else 2), 0)

    def fit(self, kind: int, vertices: int) -> tuple[Any, np.ndarray[Any, Any]]:
        """``conditions.fit`` of ``kind`` (``D1``, ``D3``, ``EQUATION_2``) on the first
        ``vertices`` vertices: (constant or None, residuals), the same balls."""
        m = self.equations(kind, vertices)
        if not m:
            return None, self.misfit(kind, vertices, flint.arb(0))
        sums = fresh(2)
        with arb_loops.Scratch(6) as scratch:
            _fit_sums(
                self.block,
                self.count,
                kind,
                m,
                _address(self.tiny),
                _address(sums[0]),
                _address(sums[1]),
                flint.ctx.prec,
                scratch,
            )
        vv, uv = sums
        constant = uv / vv if vv > 0 else None
        c = constant if constant is not None else flint.arb(0)
        return constant, self.misfit(kind, vertices, c)

    def misfit(self, kind: int, vertices: int, c: Any) -> np.ndarray[Any, Any]:
        """``conditions.misfit`` of ``kind`` with the constant c (a ball)."""
        m = self.equations(kind, vertices)
        out = fresh(m)
        if m:
            size_c = abs(c)
            with arb_loops.Scratch(4) as scratch:
                _misfit(
                    self.block,
                    self.count,
                    kind,
                    _address(c),
                    _address(size_c),
                    _address(self.tiny),
                    arb_loops.addresses(out),
                    flint.ctx.prec,
                    scratch,
                )
        return out

    def ratio_spread(self) -> np.ndarray[Any, Any] | None:
        """The spread of the proof's ratio over the whole polygon (``checks._ratio_erratum``);
        None for fewer than two ratios."""
        m = self.count - 3
        if m < 2:
            return None
        out = fresh(m)
        size = flint.arb(m)
        with arb_loops.Scratch(3) as scratch:
            _ratio_spread(
                self.block,
                self.count,
                m,
                _address(size),
                _address(self.tiny),
                arb_loops.addresses(out),
                flint.ctx.prec,
                scratch,
            )
        return out


#: The kinds of ``Columns.fit``, as ``conditions``' float64 ``Columns``.
D1, D3, EQUATION_2 = 0, 1, 2


def _small() -> tuple[list[Any], np.ndarray[Any, np.dtype[np.int64]]]:
    """The exact balls 1 … 5 (kept alive by the caller) and their addresses."""
    values = [flint.arb(k) for k in range(1, 6)]
    return values, np.array([_address(v) for v in values], dtype=np.int64)


def recursion_13(d: Any, y: np.ndarray[Any, Any], tiny: Any) -> np.ndarray[Any, Any]:
    """The residuals of (13) on the heights ``y`` (balls), as ``checks._recursion`` computes
    them on balls; ``(n,) -> (n − 2,)``."""
    m = max(len(y) - 2, 0)
    out = fresh(m)
    if m:
        one, two_d = flint.arb(1), 2 * d
        with arb_loops.Scratch(7) as scratch:
            _recursion_13(
                arb_loops.addresses(y),
                _address(d),
                _address(two_d),
                _address(one),
                _address(tiny),
                arb_loops.addresses(out),
                flint.ctx.prec,
                scratch,
            )
    return out


def two_step(
    d: Any, y: np.ndarray[Any, Any], tiny: Any
) -> tuple[np.ndarray[Any, Any], np.ndarray[Any, Any]]:
    """The residuals of (13) twice (corrected form) and of the proof's printed form, as
    ``checks._two_step`` computes them on balls; ``(n,) -> (n − 3,)`` each."""
    m = max(len(y) - 3, 0)
    corrected, printed = fresh(m), fresh(m)
    if m:
        small, addresses = _small()
        d2, d4 = d**2, d**4
        with arb_loops.Scratch(13) as scratch:
            _two_step(
                arb_loops.addresses(y),
                _address(d),
                _address(d2),
                _address(d4),
                addresses,
                _address(tiny),
                arb_loops.addresses(corrected),
                arb_loops.addresses(printed),
                flint.ctx.prec,
                scratch,
            )
        del small
    return corrected, printed


def nikolaides(
    tractrix: np.ndarray[Any, Any], axis: np.ndarray[Any, Any], p: np.ndarray[Any, Any], n: int
) -> np.ndarray[Any, Any]:
    """``checks._nikolaides`` on balls: the larger of the right-angle residuals at p_i and at
    p_{i+1}, i < n; ``(n,)``."""
    out = fresh(n)
    if n:
        with arb_loops.Scratch(11) as scratch:
            _nikolaides(
                arb_loops.addresses(tractrix[:n]),
                arb_loops.addresses(axis[:n]),
                arb_loops.addresses(p[: n + 1]),
                arb_loops.addresses(out),
                flint.ctx.prec,
                scratch,
            )
    return out


def rotation_angle(
    d: Any, p: np.ndarray[Any, Any], axis: np.ndarray[Any, Any], n: int
) -> tuple[np.ndarray[Any, Any], np.ndarray[Any, Any]]:
    """``checks._rotation_angle`` on balls: (residuals, printed indexing's residuals), i = 1 …
    n − 1; ``p`` and ``axis`` hold at least n + 1 points."""
    m = max(n - 1, 0)
    out, printed = fresh(m), fresh(m)
    if m:
        two = flint.arb(2)
        with arb_loops.Scratch(10) as scratch:
            _rotation_angle(
                arb_loops.addresses(p[: n + 1]),
                arb_loops.addresses(axis[: n + 1]),
                _address(d),
                _address(two),
                arb_loops.addresses(out),
                arb_loops.addresses(printed),
                flint.ctx.prec,
                scratch,
            )
    return out, printed


def darboux_edges(x: np.ndarray[Any, Any], e: np.ndarray[Any, Any]) -> np.ndarray[Any, Any]:
    """``darboux.edge_length_residuals`` of the ``(n, 2)`` points x, e on balls; ``(n − 1,)``."""
    return _darboux_pass(x, e, None, max(len(x) - 1, 0), 0)[0]


def darboux_distances(
    x: np.ndarray[Any, Any], e: np.ndarray[Any, Any], expected: Any
) -> np.ndarray[Any, Any]:
    """``darboux.distance_residuals`` of the ``(n, 2)`` points x, e to ``expected`` on balls;
    ``(n,)``."""
    return _darboux_pass(x, e, expected, 0, len(x))[1]


def _darboux_pass(
    x: np.ndarray[Any, Any], e: np.ndarray[Any, Any], expected: Any, edges: int, distances: int
) -> tuple[np.ndarray[Any, Any], np.ndarray[Any, Any]]:
    out_edges, out_distances = fresh(edges), fresh(distances)
    if edges or distances:
        with arb_loops.Scratch(6 + (4 * (edges + 1) if edges else 0)) as scratch:
            _darboux(
                arb_loops.addresses(x),
                arb_loops.addresses(e),
                _address(expected if expected is not None else x[0, 0]),
                arb_loops.addresses(out_edges),
                arb_loops.addresses(out_distances),
                flint.ctx.prec,
                scratch,
            )
    return out_edges, out_distances


def relative_distances(
    a: np.ndarray[Any, Any], b: np.ndarray[Any, Any], scales: np.ndarray[Any, Any], tiny: Any
) -> np.ndarray[Any, Any]:
    """``checks.relative_to(ar, point_distance(ar, a, b), scales)`` on balls: |a_k − b_k| over
    the scale floored at ``tiny``; ``(n, 2), (n, 2), (n,) -> (n,)``."""
    out = fresh(len(a))
    if len(a):
        with arb_loops.Scratch(3) as scratch:
            _relative_distances(
                arb_loops.addresses(a),
                arb_loops.addresses(b),
                arb_loops.addresses(scales),
                _address(tiny),
                arb_loops.addresses(out),
                flint.ctx.prec,
                scratch,
            )
    return out


def hypothesis(
    d: Any, y: np.ndarray[Any, Any]
) -> tuple[np.ndarray[Any, Any], np.ndarray[Any, Any]]:
    """The hypothesis of Theorem 4 on balls as ``checks._hypothesis`` computes it: (max(d² −
    y_k y_{k+1}, 0) / d², y_k y_{k+1} / d²); ``(m,) -> (m − 1,)`` each."""
    m = max(len(y) - 1, 0)
    violation, ratios = fresh(m), fresh(m)
    if m:
        d2, zero = d * d, flint.arb(0)
        with arb_loops.Scratch(2) as scratch:
            _hypothesis(
                arb_loops.addresses(y),
                _address(d2),
                _address(zero),
                arb_loops.addresses(violation),
                arb_loops.addresses(ratios),
                flint.ctx.prec,
                scratch,
            )
    return violation, ratios


def closed_kinematics(
    i: np.ndarray[Any, Any], constants: list[Any]
) -> tuple[np.ndarray[Any, Any], np.ndarray[Any, Any]]:
    """(p_i, d_i) of Theorems 5 and 6 at the indices ``i`` (balls) in one compiled pass
    (``_closed_kinematics``, whose docstring lists ``constants``), each ``(n, 2)``: fresh balls,
    read-only with their addresses kept (``arb_loops.keep``)."""
    n = len(i)
    columns = [fresh(n) for _ in range(4)]
    if n:
        with arb_loops.Scratch(4) as scratch:
            _closed_kinematics(
                arb_loops.addresses(i),
                np.array([_address(c) for c in constants], dtype=np.int64),
                arb_loops.addresses(columns[0]),
                arb_loops.addresses(columns[1]),
                arb_loops.addresses(columns[2]),
                arb_loops.addresses(columns[3]),
                flint.ctx.prec,
                scratch,
            )
    pairs = []
    for x, y in (columns[:2], columns[2:]):
        points = np.empty((n, 2), dtype=object)
        points[:, 0], points[:, 1] = x, y
        pairs.append(arb_loops.keep(points, checked=True))
    return pairs[0], pairs[1]


def _warm() -> None:
    """Compile every loop now, at import, so that no request pays for it."""
    points = np.empty((6, 2), dtype=object)
    points[:, 0] = [flint.arb(k) / 3 for k in range(6)]
    points[:, 1] = [flint.arb(k + 2) / 7 for k in range(6)]
    tiny, d = flint.arb(1) / 1000, flint.arb(1) / 10
    y = np.ascontiguousarray(points[:, 1])
    recursion_13(d, y, tiny)
    two_step(d, y, tiny)
    nikolaides(points, points[::-1].copy(), points, 5)
    columns = Columns(points, tiny)
    for kind in (D1, D3, EQUATION_2):
        columns.fit(kind, 5)
    columns.ratio_spread()
    rotation_angle(d, points, points[::-1].copy(), 5)
    darboux_edges(points, points[::-1].copy())
    relative_distances(points, points[::-1].copy(), y, tiny)
    hypothesis(d, y)
    darboux_distances(points, points[::-1].copy(), d)
    closed_kinematics(y, [d, tiny, d, d, d, d, d, tiny, d, tiny])


if AVAILABLE:
    _warm()
