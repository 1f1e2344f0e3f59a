"""Section 5 of (D4b) on balls: the Gauss images and their checks' elementwise formulas, each in
one compiled pass (``arb_program``), the balls of the numpy code they replace.

Each function mirrors a numpy formula of ``d4b.curvature`` / ``gauss_image`` /
``closed_forms`` on balls operation for operation (python-flint's libflint call and operand
order), and returns None where the compiled pass does not apply (the caller then runs the numpy
formula). The tests compare every ball bit for bit with the numpy code's, except where a pass
runs a residual's scale at ``RESIDUAL_BITS`` (``_edge_resolution``, ``_along``, ``_printed_slope``,
``_rotation``): there the balls hold the same exact values and the bounds agree to 2^-26.
"""

from __future__ import annotations

from typing import Any

import flint
import numpy as np

from app.geometry import arb_program as ap
from app.geometry.arb_program import (
    ABS,
    ADD,
    CHOOSE,
    DIV,
    EXP,
    GT,
    LT,
    MIN,
    MUL,
    NEG,
    NONNEGATIVE,
    REQUIRE_GT,
    SET,
    SQRT,
    SUB,
    SWAP,
    Program,
)
from app.geometry.ball_arithmetic import RESIDUAL_BITS

AVAILABLE = ap.AVAILABLE

Columns = list[np.ndarray[Any, Any]]


def _out(reduce: bool) -> tuple[str, ...]:
    """The single output ``out`` reduced (``arb_program.run``'s ``reduce``), or none."""
    return ("out",) if reduce else ()


def _hypot(program: Program, out: str, x: str, y: str, low: bool = False) -> None:
    """``Ball.hypot`` (``arb_loops._hypot``): √(part ≥ 0 of x·x + y·y)."""
    program.op(MUL, "hypot square", x, x, low)
    program.op(MUL, "hypot other", y, y, low)
    program.op(ADD, "hypot square", "hypot square", "hypot other", low)
    program.op(NONNEGATIVE, "hypot square", "hypot square")
    program.op(SQRT, out, "hypot square", low=low)


def _relative_difference(program: Program, out: str) -> None:
    """``checks.relative_point_difference`` (``arb_loops._relative_point_difference``): the
    differences at the working precision, the lengths and the quotient at the low one."""
    program.op(SUB, "dx", "cx", "ex")
    program.op(SUB, "dy", "cy", "ey")
    _hypot(program, "scale", "ex", "ey", low=True)
    _hypot(program, "length", "dx", "dy", low=True)
    program.op(GT, "scale", "scale", "tiny")
    program.op(CHOOSE, "floor", "scale", "tiny")
    program.op(DIV, out, "length", "floor", low=True)


_DIFFERENCE = Program(["cx", "cy", "ex", "ey"], ["tiny"], ["out"])
_relative_difference(_DIFFERENCE, "out")
_SCALED_DIFFERENCE = Program(["cx", "cy", "ex", "ey", "factor"], ["tiny"], ["out"])
_relative_difference(_SCALED_DIFFERENCE, "difference")
_SCALED_DIFFERENCE.op(MUL, "out", "difference", "factor")


def relative_difference(
    computed: Any, expected: Any, tiny: Any, low: int, factor: Any = None, reduce: bool = False
) -> Any:
    """``checks.relative_point_difference`` of two ``(n, 2)`` arrays of balls (``tiny`` and
    ``low`` as it makes them), times ``factor`` entry by entry if given (``_scaled`` on
    balls): the same balls, no array in between; ``reduce``: only the two balls a check without
    per-index residuals reads (``arb_program.run``'s ``reduce``)."""
    inputs = {"cx": computed[:, 0], "cy": computed[:, 1]}
    inputs |= {"ex": expected[:, 0], "ey": expected[:, 1]}
    program = _DIFFERENCE
    if factor is not None:
        inputs["factor"] = factor
        program = _SCALED_DIFFERENCE
    done = ap.run(program, inputs, {"tiny": tiny}, low, _out(reduce))
    return None if done is None else done[0][0]


def _pair(printed_x: bool) -> Program:
    """A constructed image (bx, by) against its corrected closed form and its printed one, in
    one program: (18) against (sech, tanh) and (sech, −tanh) (``printed_x`` false), (19)
    against (−tanh, sech) and (tanh, sech) (true; the corrected one's residuals times
    ``factor``, as ``closed`` scales them). ``relative_difference``'s operations for each, where
    the two share the difference of the common coordinate and the scale: the hypot of (sech,
    ±tanh), whose squares are the same balls (a negation of a ball at the working precision is
    exact, and a product of two negated balls is the product of the balls)."""
    inputs = ["bx", "by", "tanh", "sech"] + (["factor"] if printed_x else [])
    program = Program(inputs, ["tiny"], ["closed", "printed"])
    op = program.op
    op(NEG, "minus tanh", "tanh")  # the numpy code's negated column (python-flint's −x)
    if printed_x:  # (19): corrected (−tanh, sech), printed (tanh, sech)
        op(SUB, "dx", "bx", "minus tanh")
        op(SUB, "dy", "by", "sech")
        _hypot(program, "scale", "minus tanh", "sech", low=True)
    else:  # (18): corrected (sech, tanh), printed (sech, −tanh)
        op(SUB, "dx", "bx", "sech")
        op(SUB, "dy", "by", "tanh")
        _hypot(program, "scale", "sech", "tanh", low=True)
    _hypot(program, "length", "dx", "dy", low=True)
    op(GT, "scale", "scale", "tiny")
    op(CHOOSE, "floor", "scale", "tiny")
    if printed_x:
        op(DIV, "difference", "length", "floor", low=True)
        op(MUL, "closed", "difference", "factor")
        op(SUB, "dx", "bx", "tanh")
    else:
        op(DIV, "closed", "length", "floor", low=True)
        op(SUB, "dy", "by", "minus tanh")
    _hypot(program, "length", "dx", "dy", low=True)
    op(DIV, "printed", "length", "floor", low=True)
    return program


_PAIR_18, _PAIR_19 = _pair(False), _pair(True)


def closed_and_printed(
    key: str, built: Any, tanh: Any, sech: Any, tiny: Any, low: int, factor: Any, detail: bool
) -> Columns | None:
    """(18) (``key`` "18") or (19) (n or ñ, ``built``) against its corrected and printed closed
    forms from the columns tanh t, sech t: ``relative_difference``'s balls of both (the
    corrected (19)'s times ``factor``), the printed one reduced (its erratum's largest alone),
    the corrected one too unless ``detail``."""
    inputs = {"bx": built[:, 0], "by": built[:, 1], "tanh": tanh, "sech": sech}
    if key == "19":
        inputs["factor"] = factor
    reduce = ("printed",) if detail else ("closed", "printed")
    program = _PAIR_19 if key == "19" else _PAIR_18
    done = ap.run(program, inputs, {"tiny": tiny}, low, reduce)
    return None if done is None else done[0]


def _relative_to(program: Program, out: str, x: str, y: str, factor: str | None) -> None:
    """``_relative_difference`` of (bx, by) against (x, y) into ``out``, times ``factor``."""
    program.op(SUB, "dx", "bx", x)
    program.op(SUB, "dy", "by", y)
    _hypot(program, "scale", x, y, low=True)
    _hypot(program, "length", "dx", "dy", low=True)
    program.op(GT, "scale", "scale", "tiny")
    program.op(CHOOSE, "floor", "scale", "tiny")
    if factor is None:
        program.op(DIV, out, "length", "floor", low=True)
    else:
        program.op(DIV, "difference", "length", "floor", low=True)
        program.op(MUL, out, "difference", factor)


_IMAGE_20 = Program(
    ["bx", "by", "ax", "ay", "cx", "cy", "tanh t", "sech t", "tanh u", "sech u", "factor"],
    ["h", "d", "amplitude", "two", "tiny"],
    ["inversion", "closed", "printed"],
)
_IMAGE_20.op(ADD, "tx", "ax", "cx")  # the inversion: ``_INVERSION``
_IMAGE_20.op(ADD, "ty", "ay", "cy")
_IMAGE_20.op(MUL, "s", "tx", "tx")
_IMAGE_20.op(MUL, "w", "ty", "ty")
_IMAGE_20.op(ADD, "s", "s", "w")
_IMAGE_20.op(MUL, "a", "tx", "two")
_IMAGE_20.op(DIV, "ix", "a", "s")
_IMAGE_20.op(MUL, "b", "ty", "two")
_IMAGE_20.op(DIV, "iy", "b", "s")
_relative_to(_IMAGE_20, "inversion", "ix", "iy", "factor")
_IMAGE_20.op(NEG, "gx", "tanh u")  # (20) corrected: (−tanh u, h sech u/√(h² − d²))
_IMAGE_20.op(MUL, "gy", "amplitude", "sech u")
_relative_to(_IMAGE_20, "closed", "gx", "gy", "factor")
_IMAGE_20.op(MUL, "a", "d", "tanh t")  # (20) printed: ``_PRINTED_20``
_IMAGE_20.op(ADD, "denominator", "h", "a")
_IMAGE_20.op(MUL, "b", "h", "tanh t")
_IMAGE_20.op(SUB, "b", "b", "d")
_IMAGE_20.op(DIV, "px", "b", "denominator")
_IMAGE_20.op(MUL, "c", "h", "sech t")
_IMAGE_20.op(DIV, "py", "c", "denominator")
_relative_to(_IMAGE_20, "printed", "px", "py", None)


def image_20(
    gauss: Any,
    before: Any,
    after: Any,
    table: tuple[Any, Any, Any, Any],
    constants: dict[str, Any],
    factor: Any,
    detail: bool,
) -> Columns | None:
    """m (``gauss``, n rows) against the pole of ñ_{i−1} (``before``) and ñ_i (``after``) by
    inversion, (20) corrected and (20) printed, from the table's columns tanh t, sech t, tanh u,
    sech u (``table``; ``constants`` h, d, the amplitude h/√(h² − d²), 2 and ``tiny``; ``low``
    among them): the balls of ``pole_by_inversion``, ``_relative`` and the printed forms'
    (the inversion's and the corrected ones' times ``factor``), in one program, no
    intermediate array; the printed ones reduced, the others too unless ``detail``."""
    tanh_t, sech_t, tanh_u, sech_u = table
    inputs = {"bx": gauss[:, 0], "by": gauss[:, 1], "ax": before[:, 0], "ay": before[:, 1]}
    inputs |= {"cx": after[:, 0], "cy": after[:, 1], "tanh t": tanh_t, "sech t": sech_t}
    inputs |= {"tanh u": tanh_u, "sech u": sech_u, "factor": factor}
    fixed = {name: constants[name] for name in ("h", "d", "amplitude", "two", "tiny")}
    reduce = ("printed",) if detail else ("inversion", "closed", "printed")
    done = ap.run(_IMAGE_20, inputs, fixed, constants["low"], reduce)
    return None if done is None else done[0]


def _tanh_sech(program: Program, e: str, tanh: str, sech: str) -> None:
    """``_BallHyperbolic._tanh_sech``: 1 − 2/(E² + 1), 2/(E + 1/E)."""
    program.op(MUL, "q", e, e)
    program.op(ADD, "q", "q", "one")
    program.op(DIV, "q", "two", "q")
    program.op(SUB, tanh, "one", "q")
    program.op(DIV, "r", "one", e)
    program.op(ADD, "r", e, "r")
    program.op(DIV, sech, "two", "r")


_HYPERBOLIC = Program(
    [],
    ["before", "shift", "L", "ratio", "one", "two"],
    ["tanh t", "sech t", "tanh u", "sech u"],
    counters=("count",),
)
# the index i = lo + row as a ball: the count (exact integers, as ``Ball.indices``' balls)
_HYPERBOLIC.op(ADD, "count", "count", "one")  # row + 1 (the scratch ball starts at 0)
_HYPERBOLIC.op(ADD, "i", "count", "before")
_HYPERBOLIC.op(ADD, "t", "i", "shift")
_HYPERBOLIC.op(MUL, "t", "t", "L")
_HYPERBOLIC.op(EXP, "e", "t")
_tanh_sech(_HYPERBOLIC, "e", "tanh t", "sech t")
_HYPERBOLIC.op(MUL, "e", "e", "ratio")
_tanh_sech(_HYPERBOLIC, "e", "tanh u", "sech u")


def hyperbolic(lo: int, hi: int, shift: Any, log_ratio: Any, ratio: Any) -> Columns | None:
    """``_BallHyperbolic``'s tanh t, sech t, tanh u, sech u (t = (i + τ)L, e^u = e^t·ratio) for
    i = lo .. hi, the indices' balls counted in the program (exact integers: no ball made per
    index)."""
    if hi < lo or max(abs(lo), abs(hi)) >= 2**53:
        return None
    constants = {"before": flint.arb(lo - 1), "shift": shift, "L": log_ratio, "ratio": ratio}
    constants |= {"one": flint.arb(1), "two": flint.arb(2)}
    done = ap.run(_HYPERBOLIC, {}, constants, rows=hi - lo + 1)
    return None if done is None else done[0]


_PRINTED_20 = Program(["tanh", "sech"], ["h", "d"], ["x", "y"])
_PRINTED_20.op(MUL, "a", "d", "tanh")
_PRINTED_20.op(ADD, "denominator", "h", "a")
_PRINTED_20.op(MUL, "b", "h", "tanh")
_PRINTED_20.op(SUB, "b", "b", "d")
_PRINTED_20.op(DIV, "x", "b", "denominator")
_PRINTED_20.op(MUL, "c", "h", "sech")
_PRINTED_20.op(DIV, "y", "c", "denominator")


def printed_20(h: Any, d: Any, tanh: Any, sech: Any) -> Columns | None:
    """``_BallHyperbolic.printed("20")``: ((h tanh − d), h sech)/(h + d tanh)."""
    done = ap.run(_PRINTED_20, {"tanh": tanh, "sech": sech}, {"h": h, "d": d})
    return None if done is None else done[0]


_CONTACT = Program(["x0", "y0", "x1", "y1"], ["sign", "minus sign", "zero"], ["x", "y"])
_CONTACT.op(SUB, "ex", "x1", "x0")
_CONTACT.op(SUB, "ey", "y1", "y0")
_hypot(_CONTACT, "length", "ex", "ey")
_CONTACT.op(REQUIRE_GT, "length", "length", "zero")
_CONTACT.op(MUL, "a", "ey", "minus sign")
_CONTACT.op(DIV, "x", "a", "length")
_CONTACT.op(MUL, "b", "ex", "sign")
_CONTACT.op(DIV, "y", "b", "length")


def contact_points(polygon: Any, sign: int) -> tuple[Columns, int] | None:
    """``gauss_image.contact_points`` on balls: the unit normals (−s e^y, s e^x)/|e| of the
    edges (s = ``sign``, the orientation), and −1 or the first edge of length not certainly
    positive (the caller refuses the polygon as the numpy code does)."""
    inputs = {"x0": polygon[:-1, 0], "y0": polygon[:-1, 1]}
    inputs |= {"x1": polygon[1:, 0], "y1": polygon[1:, 1]}
    constants = {"sign": flint.arb(sign), "minus sign": flint.arb(-sign), "zero": flint.arb(0)}
    done = ap.run(_CONTACT, inputs, constants)
    return None if done is None else (done[0], done[1])


_POLES = Program(["ax", "ay", "bx", "by"], ["one"], ["x", "y"])
_POLES.op(ADD, "tx", "ax", "bx")
_POLES.op(ADD, "ty", "ay", "by")
_POLES.op(MUL, "u", "ax", "bx")
_POLES.op(MUL, "w", "ay", "by")
_POLES.op(ADD, "u", "u", "w")
_POLES.op(ADD, "denominator", "u", "one")
_POLES.op(DIV, "x", "tx", "denominator")
_POLES.op(DIV, "y", "ty", "denominator")


def poles(contact: Any) -> Columns | None:
    """``d4b.curvature._poles``: (a + b)/(1 + a·b) of consecutive contact points."""
    inputs = {"ax": contact[:-1, 0], "ay": contact[:-1, 1]}
    inputs |= {"bx": contact[1:, 0], "by": contact[1:, 1]}
    done = ap.run(_POLES, inputs, {"one": flint.arb(1)})
    return None if done is None else done[0]


def _edge_resolution(program: Program, carried: bool) -> None:
    """``d4b.curvature._Edges`` and ``_edge_resolution`` of the edge x0 → x1: its coordinates
    ex, ey, its size |x0| + |y0| + |x1| + |y1| (coordinates summed) and resolution |e|/size;
    ``carried``: the absolute values kept in registers of their own, a vertex's made on the
    first row only (the caller carries |x1|, |y1| to the next row's |x0|, |y0|).

    The size and the resolution only scale residuals (a resolution ≤ 1 multiplies one, a size
    divides one): they run at ``run``'s low precision (``RESIDUAL_BITS``), as the lengths and
    quotients of ``_relative_difference`` do. arb encloses the exact value at any precision,
    so each is a ball holding the exact size or resolution, and a residual scaled by it holds
    the exact residual: its upper bound stays rigorous, within about 2^-64 relative of the
    same formula at the working precision (up to about 2^-29 where the residual is rounding
    noise and its ball mostly radius). ex and ey, which numerators read, stay at the working
    precision."""
    x0, y0, x1, y1 = ("|x0|", "|y0|", "|x1|", "|y1|") if carried else ("a", "b", "a", "a")
    program.op(SUB, "ex", "x1", "x0")
    program.op(SUB, "ey", "y1", "y0")
    program.op(ABS, x0, "x0", low=True, first=carried)
    program.op(ABS, y0, "y0", low=True, first=carried)
    program.op(ADD, "size", x0, y0, low=True)
    program.op(ABS, x1, "x1", low=True)
    program.op(ADD, "size", "size", x1, low=True)
    program.op(ABS, y1, "y1", low=True)
    program.op(ADD, "size", "size", y1, low=True)
    _hypot(program, "length", "ex", "ey", low=True)
    program.op(DIV, "resolution", "length", "size", low=True)


_EDGES = Program(["x0", "y0", "x1", "y1"], [], ["ex", "ey", "size", "resolution"])
_edge_resolution(_EDGES, carried=False)


def _low() -> int:
    """The precision of the operations that only scale a residual (``RESIDUAL_BITS``)."""
    return min(flint.ctx.prec, RESIDUAL_BITS)


def edges(points: Any) -> Columns | None:
    """``d4b.curvature._Edges`` and ``_edge_resolution`` on balls: the edges' coordinates, their
    sizes |p_i| + |p_{i+1}| (coordinates summed) and |e_i| over that (these two at
    ``RESIDUAL_BITS``: ``_edge_resolution``)."""
    inputs = {"x0": points[:-1, 0], "y0": points[:-1, 1]}
    inputs |= {"x1": points[1:, 0], "y1": points[1:, 1]}
    done = ap.run(_EDGES, inputs, {}, _low())
    return None if done is None else done[0]


def _along(program: Program, vx: str, vy: str, out: str = "out") -> None:
    """``d4b.curvature._along``: |v × e|/size, or 1 where v · e < 0 (into ``out``); the cross
    product (a difference that cancels) and the sign test at the working precision, its
    absolute value and the quotient by the size at the low one (``_edge_resolution``)."""
    program.op(MUL, "a", vx, "ey")
    program.op(MUL, "b", vy, "ex")
    program.op(SUB, "a", "a", "b")
    program.op(ABS, "|a|", "a", low=True)
    program.op(DIV, "along", "|a|", "size", low=True)
    program.op(MUL, "a", vx, "ex")
    program.op(MUL, "b", vy, "ey")
    program.op(ADD, "a", "a", "b")
    program.op(LT, "a", "a", "zero")
    program.op(CHOOSE, out, "one", "along")


def _printed_slope(program: Program, x: str, y: str) -> None:
    """The printed (18)'s first form (√(1/(1 + k²)), √(k²/(1 + k²))) from k = e^y/e^x into
    (x, y), at the low precision: it is read only by its erratum's printed residual, a lower
    bound, and where the form is wrong (k < 0) that residual is of order 1, so a form good to
    about 2^-64 moves the bound by as much (where the form is right the bound is 0 either
    way)."""
    program.op(DIV, "k", "ey", "ex", low=True)
    program.op(MUL, "kk", "k", "k", low=True)
    program.op(ADD, "denominator", "kk", "one", low=True)
    program.op(DIV, "c", "one", "denominator", low=True)
    program.op(SQRT, x, "c", low=True)
    program.op(DIV, "c", "kk", "denominator", low=True)
    program.op(SQRT, y, "c", low=True)


def _rotation(program: Program, vx: str, vy: str, scale: str, out: str) -> None:
    """The rotation check's residual: |ñ − (−n^y, n^x)| (``checks.point_distance``) times
    ``scale``, the differences at the working precision, their length and the product at the
    low one (as ``_relative_difference``'s lengths)."""
    program.op(NEG, "r", vy)
    program.op(SUB, "dx", "cx", "r")
    program.op(SUB, "dy", "cy", vx)
    _hypot(program, "distance", "dx", "dy", low=True)
    program.op(MUL, out, "distance", scale, low=True)


_ALONG = Program(["vx", "vy", "ex", "ey", "size"], ["zero", "one"], ["out"])
_along(_ALONG, "vx", "vy")

_SLOPE = Program(["ex", "ey", "size"], ["zero", "one"], ["out"])
_printed_slope(_SLOPE, "vx", "vy")
_along(_SLOPE, "vx", "vy")


def along(vectors: Any, edge_x: Any, edge_y: Any, size: Any, reduce: bool = False) -> Any:
    """``d4b.curvature._along`` of unit vectors on edges (coordinates and sizes given);
    ``reduce`` as in ``relative_difference``."""
    inputs = {"vx": vectors[:, 0], "vy": vectors[:, 1], "ex": edge_x, "ey": edge_y, "size": size}
    constants = {"zero": flint.arb(0), "one": flint.arb(1)}
    done = ap.run(_ALONG, inputs, constants, _low(), _out(reduce))
    return None if done is None else done[0][0]


def along_printed_slope(edge_x: Any, edge_y: Any, size: Any, reduce: bool = False) -> Any:
    """``_along`` of the printed (18)'s first form from the edges' slopes k = e^y/e^x
    (``closed_forms.normal_from_slope_printed``: (√(1/(1 + k²)), √(k²/(1 + k²))));
    ``reduce`` as in ``relative_difference``."""
    inputs = {"ex": edge_x, "ey": edge_y, "size": size}
    constants = {"zero": flint.arb(0), "one": flint.arb(1)}
    done = ap.run(_SLOPE, inputs, constants, _low(), _out(reduce))
    return None if done is None else done[0][0]


_ROTATION = Program(["cx", "cy", "nx", "ny", "scale"], [], ["out"])
_rotation(_ROTATION, "nx", "ny", "scale", "out")


def rotation(contact: Any, normals: Any, scale: Any, reduce: bool = False) -> Any:
    """The rotation check's residuals: |ñ − (−n^y, n^x)| times the resolution
    (``checks.point_distance``, then ``_scaled``); ``reduce`` as in ``relative_difference``."""
    inputs = {"cx": contact[:, 0], "cy": contact[:, 1], "nx": normals[:, 0]}
    inputs |= {"ny": normals[:, 1], "scale": scale}
    done = ap.run(_ROTATION, inputs, {}, _low(), _out(reduce))
    return None if done is None else done[0][0]


_INVERSION = Program(["ax", "ay", "bx", "by"], ["two"], ["x", "y"])
_INVERSION.op(ADD, "tx", "ax", "bx")
_INVERSION.op(ADD, "ty", "ay", "by")
_INVERSION.op(MUL, "s", "tx", "tx")
_INVERSION.op(MUL, "w", "ty", "ty")
_INVERSION.op(ADD, "s", "s", "w")
_INVERSION.op(MUL, "a", "tx", "two")
_INVERSION.op(DIV, "x", "a", "s")
_INVERSION.op(MUL, "b", "ty", "two")
_INVERSION.op(DIV, "y", "b", "s")


def pole_by_inversion(before: Any, after: Any) -> Columns | None:
    """``closed_forms.pole_by_inversion`` on balls: 2t/|t|², t = before + after."""
    inputs = {"ax": before[:, 0], "ay": before[:, 1], "bx": after[:, 0], "by": after[:, 1]}
    done = ap.run(_INVERSION, inputs, {"two": flint.arb(2)})
    return None if done is None else done[0]


_MINIMUM = Program(["a", "b"], [], ["out"])
_MINIMUM.op(MIN, "out", "a", "b")


def minimum(a: Any, b: Any) -> Any:
    """arb's min entry by entry (``d4b.curvature._ball_minimum``)."""
    done = ap.run(_MINIMUM, {"a": a, "b": b}, {})
    return None if done is None else done[0][0]


_SCALED = Program(["a", "b"], [], ["out"])
_SCALED.op(MUL, "out", "a", "b")


def product(a: Any, b: Any) -> Any:
    """a·b entry by entry (``d4b.curvature._scaled`` on balls)."""
    done = ap.run(_SCALED, {"a": a, "b": b}, {})
    return None if done is None else done[0][0]


_EDGE_CHECKS = Program(
    ["x0", "y0", "x1", "y1", "vx", "vy", "cx", "cy"],
    ["before", "zero", "one"],
    ["resolution", "pole resolution", "along n", "slope", "rotation"],
)
_edge_resolution(_EDGE_CHECKS, carried=True)  # ``_EDGES``, a vertex's |x|, |y| made once (``SWAP``)
_EDGE_CHECKS.op(SET, "previous", "before", first=True)  # the smaller of consecutive resolutions
_EDGE_CHECKS.op(MIN, "pole resolution", "previous", "resolution")
_EDGE_CHECKS.op(SET, "previous", "resolution")
_along(_EDGE_CHECKS, "vx", "vy", "along n")  # ``_ALONG``
_printed_slope(_EDGE_CHECKS, "sx", "sy")  # ``_SLOPE``
_along(_EDGE_CHECKS, "sx", "sy", "slope")
_rotation(_EDGE_CHECKS, "vx", "vy", "resolution", "rotation")  # ``_ROTATION``
_EDGE_CHECKS.op(SWAP, "|x0|", "|x1|")
_EDGE_CHECKS.op(SWAP, "|y0|", "|y1|")


def edge_checks(points: Any, normals: Any, contact: Any, before: Any, detail: bool) -> Any:
    """The checks on the edges p_i p_{i+1} of ``points`` in one program: their resolutions, the
    smaller of consecutive ones (``before`` the resolution of the edge before the first),
    ``_along`` of ``normals`` (n) and of the printed (18)'s slope form, and the rotation's
    scaled distances of ``contact`` (ñ_{i+1}) from the turned n: the balls of ``edges``,
    ``minimum``, ``along``, ``along_printed_slope`` and ``rotation`` (the resolutions per
    row; the slope's reduced, the others' too unless ``detail``)."""
    inputs = {"x0": points[:-1, 0], "y0": points[:-1, 1], "x1": points[1:, 0]}
    inputs |= {"y1": points[1:, 1], "vx": normals[:, 0], "vy": normals[:, 1]}
    inputs |= {"cx": contact[:, 0], "cy": contact[:, 1]}
    constants = {"before": before, "zero": flint.arb(0), "one": flint.arb(1)}
    reduce = ("slope",) if detail else ("along n", "slope", "rotation")
    done = ap.run(_EDGE_CHECKS, inputs, constants, _low(), reduce)
    return None if done is None else done[0]
