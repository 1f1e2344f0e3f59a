"""Section 5's ring checks on balls in one compiled pass: Theorem 7's or 8's residuals and (17)'s.

On balls (precision=mp) ``ring_curvature.ring_curvatures`` writes each face of a ring in its
meridian coordinates (``_ring_curvatures_in_the_meridian_plane``), ``from_areas`` adds the
parallel residual, and ``constant_curvature_residuals`` / ``minimal_residuals`` and
``revolution_formulas.face_residuals`` turn the areas into residuals: about ninety operations a
face, each a Python call on numpy's object loop that allocates a ball for its result. Here the
same libflint functions run in the same order at the same precision (the working precision,
``flint.ctx.prec``) inside a numba loop on the balls' own ``arb_struct``
(``app.geometry.arb_loops``), the intermediates in scratch balls reused face after face, so the
residual balls are the very ones the numpy code makes (the tests compare them bit for bit). A
quantity the numpy code computes twice (p_{i+1}^y², q Δy) is computed once: the same call on
the same balls gives the same ball.

Where the numpy code would leave the planar form (a face whose area is not certainly positive)
the loop stops and the caller keeps the numpy code, which names the face. Compiled at import
(about a second once per process, as ``arb_loops``); ``AVAILABLE`` false keeps the numpy code.
"""

from __future__ import annotations

import ctypes
from typing import Any

import flint
import numba
import numpy as np

from app.geometry import arb_loops, arb_program

_P, _W = ctypes.c_void_p, ctypes.c_long
_SIGNATURES: dict[str, tuple[Any, list[Any]]] = {
    "arb_add": (None, [_P, _P, _P, _W]),
    "arb_sub": (None, [_P, _P, _P, _W]),
    "arb_mul": (None, [_P, _P, _P, _W]),
    "arb_div": (None, [_P, _P, _P, _W]),
    "arb_sqrt": (None, [_P, _P, _W]),
    "arb_abs": (None, [_P, _P]),
    "arb_set_round": (None, [_P, _P, _W]),
    "arb_max": (None, [_P, _P, _P, _W]),
    "arb_set": (None, [_P, _P]),
    "arb_zero": (None, [_P]),
    "arb_gt": (ctypes.c_int, [_P, _P]),
    "arb_ne": (ctypes.c_int, [_P, _P]),
}
_BOUND = {name: arb_loops.bind(name, *signature) for name, signature in _SIGNATURES.items()}

#: Whether the compiled ring pass can run (else the numpy code does).
AVAILABLE = arb_loops.AVAILABLE and all(f is not None for f in _BOUND.values())

#: Scratch balls of one face.
_SCRATCH = 48

#: The constants' slots in ``constants`` (addresses of balls made by the caller).
Q, R, CS, SIN, SQRT_R, K, ABS_K, TINY, ZERO, TWO, FOUR = range(11)

if AVAILABLE:
    _add = _BOUND["arb_add"]
    _sub = _BOUND["arb_sub"]
    _mul = _BOUND["arb_mul"]
    _div = _BOUND["arb_div"]
    _sqrt = _BOUND["arb_sqrt"]
    _arb_abs = _BOUND["arb_abs"]
    _set_round = _BOUND["arb_set_round"]
    _max = _BOUND["arb_max"]
    _set = _BOUND["arb_set"]
    _zero = _BOUND["arb_zero"]
    _gt = _BOUND["arb_gt"]
    _ne = _BOUND["arb_ne"]
    _B = arb_loops.ARB_BYTES

    @numba.njit(cache=False)
    def _abs(out: int, x: int, prec: int) -> None:
        """python-flint's ``abs``: |x| rounded to the precision."""
        _arb_abs(out, x)
        _set_round(out, out, prec)

    @numba.njit(cache=False)
    def _ring(
        x: Any,
        y: Any,
        u: Any,
        v: Any,
        constants: Any,
        constant_k: bool,
        theorem: Any,
        equation_17: Any,
        defined: Any,
        prec: int,
        scratch: int,
    ) -> int:
        """Per face k (vertices k, k + 1 of the meridian (x, y) and its Gauss image (u, v)):
        the theorem's residual (7 with ``constant_k``: K = constants[K], else 8: H = 0) into
        ``theorem[k]``, (17)'s larger residual (0 where 0/0) into ``equation_17[k]`` and
        whether (17) is defined there. −1 on success, else the first face whose area is not
        certainly positive (the caller's numpy code takes over)."""
        q, r, cs, sin = constants[Q], constants[R], constants[CS], constants[SIN]
        sqrt_r, curvature, abs_k = constants[SQRT_R], constants[K], constants[ABS_K]
        tiny, zero, two, four = constants[TINY], constants[ZERO], constants[TWO], constants[FOUR]
        s = np.empty(_SCRATCH, dtype=np.int64)
        for j in range(_SCRATCH):
            s[j] = scratch + j * _B
        s_f, s_n, dx, dy, du, dv = s[0], s[1], s[2], s[3], s[4], s[5]
        qdy, rdx, t1, t2, length, inner = s[6], s[7], s[8], s[9], s[10], s[11]
        area, gauss_area, mixed, t3 = s[12], s[13], s[14], s[15]
        ax, ay, bx, by, au, av, bu, bv = s[16], s[17], s[18], s[19], s[20], s[21], s[22], s[23]
        f1, f2, n1, n2 = s[24], s[25], s[26], s[27]
        mag_f, mag_n, mag_fn, turned = s[28], s[29], s[30], s[31]
        parallel, residual = s[32], s[33]
        p1sq, p0sq, dp, sp, n1sq, n0sq = s[34], s[35], s[36], s[37], s[38], s[39]
        p0n0, p1n1, k_scale, h_scale, k_res, h_res = s[40], s[41], s[42], s[43], s[44], s[45]
        for k in range(theorem.shape[0]):
            a, b = k, k + 1
            # ring_curvature._ring_curvatures_in_the_meridian_plane
            _add(s_f, y[a], y[b], prec)
            if not _gt(s_f, zero):
                return k
            _add(s_n, v[a], v[b], prec)
            _sub(dx, x[b], x[a], prec)
            _sub(dy, y[b], y[a], prec)
            _sub(du, u[b], u[a], prec)
            _sub(dv, v[b], v[a], prec)
            _mul(qdy, q, dy, prec)
            _mul(t1, qdy, dy, prec)
            _mul(rdx, r, dx, prec)
            _mul(t2, rdx, dx, prec)
            _add(t1, t1, t2, prec)
            _sqrt(length, t1, prec)
            if not _gt(length, zero):
                return k
            _mul(t1, qdy, dv, prec)
            _mul(t2, rdx, du, prec)
            _add(inner, t1, t2, prec)
            _mul(t1, s_f, length, prec)
            _div(area, t1, two, prec)
            _mul(t1, s_n, inner, prec)
            _mul(t2, two, length, prec)
            _div(gauss_area, t1, t2, prec)
            _mul(t1, s_f, inner, prec)
            _mul(t2, s_n, length, prec)
            _mul(t2, t2, length, prec)
            _add(t1, t1, t2, prec)
            _mul(t2, four, length, prec)
            _div(mixed, t1, t2, prec)
            _abs(ax, x[a], prec)
            _abs(ay, y[a], prec)
            _abs(bx, x[b], prec)
            _abs(by, y[b], prec)
            _abs(au, u[a], prec)
            _abs(av, v[a], prec)
            _abs(bu, u[b], prec)
            _abs(bv, v[b], prec)
            _add(t1, ax, ay, prec)  # f1 = ax + ay + bx + by cs
            _add(t1, t1, bx, prec)
            _mul(t2, by, cs, prec)
            _add(f1, t1, t2, prec)
            _mul(t2, ay, cs, prec)  # f2 = ax + ay cs + bx + by
            _add(t1, ax, t2, prec)
            _add(t1, t1, bx, prec)
            _add(f2, t1, by, prec)
            _add(t1, au, av, prec)  # n1
            _add(t1, t1, bu, prec)
            _mul(t2, bv, cs, prec)
            _add(n1, t1, t2, prec)
            _mul(t2, av, cs, prec)  # n2
            _add(t1, au, t2, prec)
            _add(t1, t1, bu, prec)
            _add(n2, t1, bv, prec)
            _mul(t1, f1, f2, prec)
            _div(mag_f, t1, two, prec)
            _mul(t1, n1, n2, prec)
            _div(mag_n, t1, two, prec)
            _mul(t1, f1, n2, prec)
            _mul(t2, n1, f2, prec)
            _add(t1, t1, t2, prec)
            _div(mag_fn, t1, four, prec)
            _mul(t1, dy, du, prec)  # turn = |Δy Δu − Δx Δv| sin √r
            _mul(t2, dx, dv, prec)
            _sub(t1, t1, t2, prec)
            _abs(t1, t1, prec)
            _mul(t1, t1, sin, prec)
            _mul(t3, t1, sqrt_r, prec)
            _mul(t1, s_f, s_n, prec)  # turned = |S_f S_n| turn / 4
            _abs(t1, t1, prec)
            _mul(t1, t1, t3, prec)
            _div(turned, t1, four, prec)
            # curvature.from_areas: the parallel residual
            _mul(t1, mag_f, mag_n, prec)
            _div(parallel, turned, t1 if _gt(t1, tiny) else tiny, prec)
            # the theorem: constant_curvature_residuals or minimal_residuals, then the larger
            # of it and the parallel residual
            if constant_k:
                _mul(t1, abs_k, mag_f, prec)
                _add(t2, mag_n, t1, prec)
                _mul(t1, curvature, area, prec)
                _sub(t1, gauss_area, t1, prec)
                _abs(t1, t1, prec)
                _div(residual, t1, t2, prec)
            else:
                _abs(t1, mixed, prec)
                _div(residual, t1, mag_fn, prec)
            _max(theorem[k], residual, parallel, prec)
            # revolution_formulas.face_residuals (balls: the radii unscaled)
            p0, p1, n0, n1_ = y[a], y[b], v[a], v[b]
            _mul(p1sq, p1, p1, prec)
            _mul(p0sq, p0, p0, prec)
            _sub(dp, p1sq, p0sq, prec)
            _add(sp, p1sq, p0sq, prec)
            _mul(n1sq, n1_, n1_, prec)
            _mul(n0sq, n0, n0, prec)
            _mul(t1, mag_n, sp, prec)  # k_scale
            _add(t2, n1sq, n0sq, prec)
            _mul(t2, mag_f, t2, prec)
            _add(k_scale, t1, t2, prec)
            _mul(p0n0, p0, n0, prec)
            _mul(p1n1, p1, n1_, prec)
            _mul(t1, mag_fn, sp, prec)  # h_scale
            _abs(t2, p0n0, prec)
            _abs(t3, p1n1, prec)
            _add(t2, t2, t3, prec)
            _mul(t2, mag_f, t2, prec)
            _add(h_scale, t1, t2, prec)
            _mul(t1, gauss_area, dp, prec)  # k_res
            _sub(t2, n1sq, n0sq, prec)
            _mul(t2, area, t2, prec)
            _sub(t1, t1, t2, prec)
            _abs(t1, t1, prec)
            _div(k_res, t1, k_scale if _gt(k_scale, tiny) else tiny, prec)
            _mul(t1, mixed, dp, prec)  # h_res
            _sub(t2, p0n0, p1n1, prec)
            _mul(t2, area, t2, prec)
            _add(t1, t1, t2, prec)
            _abs(t1, t1, prec)
            _div(h_res, t1, h_scale if _gt(h_scale, tiny) else tiny, prec)
            is_defined = _ne(dp, zero) != 0
            defined[k] = is_defined
            if is_defined:
                _max(equation_17[k], k_res, h_res, prec)
            else:
                _zero(equation_17[k])
        return -1


def ring_checks(
    meridian: np.ndarray[Any, Any],
    gauss: np.ndarray[Any, Any],
    cos: Any,
    sin: Any,
    curvature: Any,
) -> tuple[np.ndarray[Any, Any], np.ndarray[Any, Any], int] | None:
    """On balls: Theorem 7's residuals (``curvature`` the ball K) or 8's (None: H = 0) and
    (17)'s larger residual per face (0 where (17) is 0/0, that many), the balls the numpy code
    makes (``ring_curvature.ring_curvatures`` and the residual functions; the caller runs inside
    the working precision); None where that code must run (not available, fewer than two
    vertices, an entry not a ball, a face without certain area)."""
    faces = len(meridian) - 1
    if not AVAILABLE or faces < 1 or len(gauss) != faces + 1:
        return None
    if meridian.dtype != object or gauss.dtype != object:
        return None
    columns = [meridian[:, 0], meridian[:, 1], gauss[:, 0], gauss[:, 1]]
    addresses = [arb_loops.addresses(column) for column in columns]
    if arb_program.AVAILABLE:  # the compiled type check
        if not all(arb_program.all_balls(found) for found in addresses):
            return None
    elif not (arb_loops.all_balls(meridian) and arb_loops.all_balls(gauss)):
        return None
    if type(cos) is not flint.arb or type(sin) is not flint.arb:
        return None
    if curvature is not None and type(curvature) is not flint.arb:
        return None
    # the scalars exactly as the numpy code makes them
    k = 1 - cos
    q, r = sin * sin, sin * sin + k * k
    sqrt_r = r.sqrt()
    cs = cos + sin
    constant = curvature if curvature is not None else flint.arb(0)
    tiny = flint.arb(repr(float(np.finfo(np.float64).tiny)))  # as ``Ball.scalar`` makes it
    scalars = [q, r, cs, sin, sqrt_r, constant, abs(constant), tiny]
    scalars += [flint.arb(0), flint.arb(2), flint.arb(4)]
    constants = np.fromiter(map(id, scalars), dtype=np.int64, count=len(scalars))
    constants += arb_loops.OFFSET
    column = meridian[1:, 0]
    theorem, equation_17 = np.negative(column), np.negative(column)  # fresh balls, written over
    defined = np.zeros(faces, dtype=np.bool_)
    with arb_loops.Scratch(_SCRATCH) as scratch:
        x, y, u, v = addresses
        stopped = _ring(
            x,
            y,
            u,
            v,
            constants,
            curvature is not None,
            arb_loops.addresses(theorem),
            arb_loops.addresses(equation_17),
            defined,
            flint.ctx.prec,
            scratch,
        )
    del scalars  # the constants' balls lived until here
    if stopped >= 0:
        return None
    return theorem, equation_17, int(np.count_nonzero(~defined))


def _warm() -> None:
    """Compile the loop now, at import, so that no request pays for it."""
    points = np.empty((3, 2), dtype=object)
    points[:, 0] = [flint.arb(0), flint.arb(1), flint.arb(2)]
    points[:, 1] = [flint.arb(1), flint.arb(2), flint.arb(2)]
    gauss = np.empty((3, 2), dtype=object)
    gauss[:, 0] = [flint.arb(0), flint.arb(1) / 2, flint.arb(1) / 2]
    gauss[:, 1] = [flint.arb(1), flint.arb(1) / 2, flint.arb(1) / 2]
    theta = flint.arb.pi() / 16
    ring_checks(points, gauss, theta.cos(), theta.sin(), flint.arb(-1))
    ring_checks(points, gauss, theta.cos(), theta.sin(), None)


if AVAILABLE:
    _warm()
