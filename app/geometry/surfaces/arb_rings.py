"""Section 5's ring checks on balls in one compiled pass: Theorem 7's or 8's residuals and (17)'s.

On balls (precision=mp) ``ring_curvature.ring_curvatures`` writes each face of a ring in its
meridian coordinates (``_ring_curvatures_in_the_meridian_plane``), ``from_areas`` adds the
parallel residual, and ``constant_curvature_residuals`` / ``minimal_residuals`` and
``revolution_formulas.face_residuals`` turn the areas into residuals: about a hundred operations
a face, each a Python call on numpy's object loop that allocates a ball for its result. Here the
same formulas are one straight-line program (``arb_program``), the intermediates in scratch balls
reused face after face. Each residual's numerator (a difference that cancels) is made by the
numpy code's libflint calls at the working precision; its scale (a sum of magnitudes) and the
quotient run at ``RESIDUAL_BITS`` (``_ring_program`` says why the bounds stay rigorous), so the
residual balls hold the same exact values as the numpy code's and their bounds agree to about
2^-64 relative, or 2^-29 where a residual is rounding noise and its ball mostly radius (the
tests compare both ways). A quantity needed twice (p_{i+1}^y², q Δy, p_i^y n_i^y, and a
vertex's |x|, |y|, |u|, |v|, |y| cs, |v| cs, y², v², y v, which both faces of the vertex read) is
computed once.

Where the numpy code would leave the planar form (a face whose area is not certainly positive)
the program stops and the caller keeps the numpy code, which names the face; ``AVAILABLE``
false (``arb_program``) keeps the numpy code too.
"""

from __future__ import annotations

from typing import Any

import flint
import numpy as np

from app.geometry import arb_program
from app.geometry.arb_program import (
    ABS,
    ADD,
    CHOOSE,
    DIV,
    GT,
    KEEP_FLAG,
    MAX,
    MUL,
    NE,
    REQUIRE_GT,
    SQRT,
    SUB,
    SWAP,
    Program,
)
from app.geometry.ball_arithmetic import RESIDUAL_BITS

#: Whether the compiled ring pass can run (else the numpy code does).
AVAILABLE = arb_program.AVAILABLE

_INPUTS = ["x0", "y0", "u0", "v0", "x1", "y1", "u1", "v1"]
_CONSTANTS = ["q", "r", "cs", "sin sqrt r", "K", "|K|", "tiny", "zero", "two", "four"]
_CONSTANTS += ["half", "quarter"]


def _ring_program(constant_k: bool) -> Program:
    """The face of vertices 0, 1 of the meridian (x, y) and its Gauss image (u, v): the
    theorem's residual (7 with ``constant_k``: K given, else 8: H = 0) and (17)'s larger
    residual (0 where 0/0, the flag kept: whether (17) is defined).

    Every quantity that only scales a residual runs at ``run``'s low precision (``LOW``
    below): the magnitudes |a(f)|, |a(n)|, |a(f, n)| and their factors, (17)'s scales, the
    parallel residual's turn after its cross product, and each quotient. Each residual is a
    quotient a / s of a numerator a (a difference that cancels: computed at the working
    precision, as before) by a scale s; arb encloses the exact value at any precision, so s
    at 64 bits is a ball holding the exact s, and arb's division of a by that ball holds
    a / s for every s in it, its upper bound dividing by s's lower bound: the residual's
    upper bound stays rigorous. It moves from the numpy code's by about 2^-64 relative, or up
    to about 2^-29 (either way) where the residual is rounding noise and its ball mostly
    radius, which arb keeps in 30-bit ``mag``s rounded up at every step (a different order of
    steps, a different rounding). The scales also take fewer steps than the numpy code's
    formulas: |a(f)| = (|x0| + |x1| + |y0| + |y1| cs)(|x0| + |x1| + |y0| cs + |y1|)/2 with
    |x0| + |x1| summed once and |y| cs carried to the next face, halves and quarters as
    products, sin √r one constant. The tiny floors and (17)'s "defined" flag compare the
    same quantities as before; only a scale within about 2^-64 of ``tiny`` could choose
    otherwise, and either choice is a floor of an honest scale."""
    program = Program(_INPUTS, _CONSTANTS, ["theorem", "equation 17"])

    def op(code: int, d: str, a: str, b: str | None = None, first: bool = False) -> None:
        program.op(code, d, a, b, first=first)

    def scale(code: int, d: str, a: str, b: str | None = None, first: bool = False) -> None:
        program.op(code, d, a, b, low=True, first=first)

    # ring_curvature._ring_curvatures_in_the_meridian_plane
    op(ADD, "s_f", "y0", "y1")
    op(REQUIRE_GT, "s_f", "s_f", "zero")
    op(ADD, "s_n", "v0", "v1")
    op(SUB, "dx", "x1", "x0")
    op(SUB, "dy", "y1", "y0")
    op(SUB, "du", "u1", "u0")
    op(SUB, "dv", "v1", "v0")
    op(MUL, "q dy", "q", "dy")
    op(MUL, "t1", "q dy", "dy")
    op(MUL, "r dx", "r", "dx")
    op(MUL, "t2", "r dx", "dx")
    op(ADD, "t1", "t1", "t2")
    op(SQRT, "length", "t1")
    op(REQUIRE_GT, "length", "length", "zero")
    op(MUL, "t1", "q dy", "dv")
    op(MUL, "t2", "r dx", "du")
    op(ADD, "inner", "t1", "t2")
    op(MUL, "t1", "s_f", "length")
    op(DIV, "area", "t1", "two")
    op(MUL, "t1", "s_n", "inner")
    op(MUL, "t2", "two", "length")
    op(DIV, "gauss area", "t1", "t2")
    op(MUL, "t1", "s_f", "inner")
    op(MUL, "t2", "s_n", "length")
    op(MUL, "t2", "t2", "length")
    op(ADD, "t1", "t1", "t2")
    op(MUL, "t2", "four", "length")
    op(DIV, "mixed", "t1", "t2")
    # a vertex's |x|, |y|, |u|, |v|, |y| cs, |v| cs: made for vertex 1 of each face and kept
    # for the next face's vertex 0 (``SWAP`` at the end), vertex 0's made on the first face
    # only; the scales in registers of their own ("l…", one precision each)
    for name in ("x", "y", "u", "v"):
        scale(ABS, f"|{name}0|", f"{name}0", first=True)
        scale(ABS, f"|{name}1|", f"{name}1")
    for f1, f2, (a, b, c, d) in (
        ("f1", "f2", ("|x0|", "|y0|", "|x1|", "|y1|")),
        ("n1", "n2", ("|u0|", "|v0|", "|u1|", "|v1|")),
    ):
        scale(MUL, f"{b} cs", b, "cs", first=True)
        scale(MUL, f"{d} cs", d, "cs")
        scale(ADD, "l1", a, c)
        scale(ADD, "l2", "l1", b)  # a + b + c + d cs
        scale(ADD, f1, "l2", f"{d} cs")
        scale(ADD, "l2", "l1", d)  # a + b cs + c + d
        scale(ADD, f2, "l2", f"{b} cs")
    scale(MUL, "l1", "f1", "f2")
    scale(MUL, "mag f", "l1", "half")
    scale(MUL, "l1", "n1", "n2")
    scale(MUL, "mag n", "l1", "half")
    scale(MUL, "l1", "f1", "n2")
    scale(MUL, "l2", "n1", "f2")
    scale(ADD, "l1", "l1", "l2")
    scale(MUL, "mag fn", "l1", "quarter")
    op(MUL, "t1", "dy", "du")  # turn = |Δy Δu − Δx Δv| sin √r
    op(MUL, "t2", "dx", "dv")
    op(SUB, "t1", "t1", "t2")
    scale(ABS, "l1", "t1")
    scale(MUL, "turn", "l1", "sin sqrt r")
    scale(MUL, "l1", "s_f", "s_n")  # turned = |S_f S_n| turn / 4
    scale(ABS, "l1", "l1")
    scale(MUL, "l1", "l1", "turn")
    scale(MUL, "turned", "l1", "quarter")
    # curvature.from_areas: the parallel residual
    scale(MUL, "l1", "mag f", "mag n")
    op(GT, "l1", "l1", "tiny")
    op(CHOOSE, "l1", "l1", "tiny")
    scale(DIV, "parallel", "turned", "l1")
    # the theorem: constant_curvature_residuals or minimal_residuals, then the larger of it
    # and the parallel residual
    if constant_k:
        scale(MUL, "l1", "|K|", "mag f")
        scale(ADD, "l2", "mag n", "l1")
        op(MUL, "t1", "K", "area")
        op(SUB, "t1", "gauss area", "t1")
        scale(ABS, "l1", "t1")
        scale(DIV, "residual", "l1", "l2")
    else:
        scale(ABS, "l1", "mixed")
        scale(DIV, "residual", "l1", "mag fn")
    scale(MAX, "theorem", "residual", "parallel")
    # revolution_formulas.face_residuals (balls: the radii unscaled)
    op(MUL, "p1²", "y1", "y1")
    op(MUL, "p0²", "y0", "y0", first=True)
    op(SUB, "dp", "p1²", "p0²")
    scale(ADD, "sp", "p1²", "p0²")
    op(MUL, "n1²", "v1", "v1")
    op(MUL, "n0²", "v0", "v0", first=True)
    scale(MUL, "l1", "mag n", "sp")  # k_scale
    scale(ADD, "l2", "n1²", "n0²")
    scale(MUL, "l2", "mag f", "l2")
    scale(ADD, "k scale", "l1", "l2")
    op(MUL, "p0 n0", "y0", "v0", first=True)
    op(MUL, "p1 n1", "y1", "v1")
    scale(MUL, "l1", "mag fn", "sp")  # h_scale
    scale(ABS, "l2", "p0 n0")
    scale(ABS, "l3", "p1 n1")
    scale(ADD, "l2", "l2", "l3")
    scale(MUL, "l2", "mag f", "l2")
    scale(ADD, "h scale", "l1", "l2")
    op(MUL, "t1", "gauss area", "dp")  # k_res
    op(SUB, "t2", "n1²", "n0²")
    op(MUL, "t2", "area", "t2")
    op(SUB, "t1", "t1", "t2")
    scale(ABS, "l1", "t1")
    op(GT, "k scale", "k scale", "tiny")
    op(CHOOSE, "l3", "k scale", "tiny")
    scale(DIV, "k res", "l1", "l3")
    op(MUL, "t1", "mixed", "dp")  # h_res
    op(SUB, "t2", "p0 n0", "p1 n1")
    op(MUL, "t2", "area", "t2")
    op(ADD, "t1", "t1", "t2")
    scale(ABS, "l1", "t1")
    op(GT, "h scale", "h scale", "tiny")
    op(CHOOSE, "l3", "h scale", "tiny")
    scale(DIV, "h res", "l1", "l3")
    scale(MAX, "both", "k res", "h res")
    op(NE, "dp", "dp", "zero")  # (17) defined: the larger residual, else 0
    op(KEEP_FLAG, "dp", "dp")
    op(CHOOSE, "equation 17", "both", "zero")
    for kept, made in (("p0²", "p1²"), ("n0²", "n1²"), ("p0 n0", "p1 n1")):
        op(SWAP, kept, made)
    for name in ("x", "y", "u", "v"):
        op(SWAP, f"|{name}0|", f"|{name}1|")
    for name in ("y", "v"):
        op(SWAP, f"|{name}0| cs", f"|{name}1| cs")
    return program


_THEOREM_7, _THEOREM_8 = _ring_program(True), _ring_program(False)


def ring_checks(
    meridian: np.ndarray[Any, Any],
    gauss: np.ndarray[Any, Any],
    cos: Any,
    sin: Any,
    curvature: Any,
    reduce: bool = False,
) -> tuple[np.ndarray[Any, Any], np.ndarray[Any, Any], int] | None:
    """On balls: Theorem 7's residuals (``curvature`` the ball K) or 8's (None: H = 0) and
    (17)'s larger residual per face (0 where (17) is 0/0, that many): the numpy code's
    formulas (``ring_curvature.ring_curvatures`` and the residual functions; the caller runs
    inside the working precision), their scales at ``RESIDUAL_BITS`` (``_ring_program``: each
    residual's upper bound rigorous, within about 2^-64 relative of the numpy code's where the
    residual is not rounding noise); None where that code must run (not available, fewer than
    two vertices, an entry not a ball, a face without certain area).
    ``reduce``: the theorem's residuals as the two balls a check without per-index residuals
    reads (``arb_program.run``'s ``reduce``)."""
    faces = len(meridian) - 1
    if not AVAILABLE or faces < 1 or len(gauss) != faces + 1:
        return None
    if meridian.dtype != object or gauss.dtype != object or meridian.ndim != 2:
        return None
    if type(cos) is not flint.arb or type(sin) is not flint.arb:
        return None
    if curvature is not None and type(curvature) is not flint.arb:
        return None
    # the scalars exactly as the numpy code makes them
    k = 1 - cos
    q, r = sin * sin, sin * sin + k * k
    constant = curvature if curvature is not None else flint.arb(0)
    constants = {"q": q, "r": r, "cs": cos + sin, "sin sqrt r": sin * r.sqrt()}
    constants |= {"K": constant, "|K|": abs(constant)}
    constants["tiny"] = flint.arb(repr(float(np.finfo(np.float64).tiny)))  # ``Ball.scalar``
    constants |= {"zero": flint.arb(0), "two": flint.arb(2), "four": flint.arb(4)}
    constants |= {"half": flint.arb(0.5), "quarter": flint.arb(0.25)}
    inputs = {}
    for end, rows in (("0", slice(None, -1)), ("1", slice(1, None))):
        for name, points, column in (("x", meridian, 0), ("y", meridian, 1)):
            inputs[name + end] = points[rows, column]
        for name, points, column in (("u", gauss, 0), ("v", gauss, 1)):
            inputs[name + end] = points[rows, column]
    program = _THEOREM_7 if curvature is not None else _THEOREM_8
    low = min(flint.ctx.prec, RESIDUAL_BITS)
    done = arb_program.run(program, inputs, constants, low, ("theorem",) if reduce else ())
    if done is None or done[1] >= 0:
        return None
    (theorem, equation_17), _, defined = done
    return theorem, equation_17, int(np.count_nonzero(~defined))


_MAXIMUM = Program(["a", "b"], [], ["out"])
_MAXIMUM.op(MAX, "out", "a", "b")


def maximum(a: Any, b: Any, reduce: bool) -> Any:
    """arb's max entry by entry (``Ball.maximum``: the same balls) in one compiled pass; with
    ``reduce`` only the two balls a check without per-index residuals reads
    (``arb_program.run``'s ``reduce``); None where the pass does not apply."""
    if a.dtype != object or b.dtype != object or a.ndim != 1 or b.ndim != 1:
        return None
    done = arb_program.run(_MAXIMUM, {"a": a, "b": b}, {}, reduce=("out",) if reduce else ())
    return None if done is None else done[0][0]
