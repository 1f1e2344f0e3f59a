"""Straight-line ball formulas run row by row in one compiled loop, the same libflint calls.

A formula on numpy object arrays of python-flint ``arb`` balls (``(a + b) / (1 + a·b)`` over
1000 rows) makes one Python call and one new ball per operation and row. A ``Program`` writes
the same formula as a list of libflint operations on named registers; ``run`` executes it for
every row inside one numba loop (``app.geometry.arb_loops``' machinery: the balls' own
``arb_struct``, scratch balls reused row after row), and writes the named outputs into fresh
balls. Each operation is the libflint function python-flint calls for the operator, with the
operands in python-flint's order (its ``abs`` and negation round to the precision, as here),
at the working precision (``flint.ctx.prec``) or at a lower
one given to ``run``: the balls are those of the numpy code (the callers' tests compare them bit
for bit). A quantity the numpy code computes twice is computed once (the same call on the same
balls gives the same ball).

Compiled once into numba's cache and loaded from it at import, as ``arb_loops``' loops (libflint
called by symbol name); ``AVAILABLE`` false keeps the callers' numpy code.
"""

from __future__ import annotations

import ctypes
from collections.abc import Collection
from typing import Any

import flint
import numpy as np

from app.geometry import arb_loops

_P, _W = ctypes.c_void_p, ctypes.c_long
_SIGNATURES: dict[str, tuple[Any, list[Any]]] = {
    "arb_add": (None, [_P, _P, _P, _W]),
    "arb_sub": (None, [_P, _P, _P, _W]),
    "arb_mul": (None, [_P, _P, _P, _W]),
    "arb_div": (None, [_P, _P, _P, _W]),
    "arb_sqrt": (None, [_P, _P, _W]),
    "arb_exp": (None, [_P, _P, _W]),
    "arb_abs": (None, [_P, _P]),
    "arb_set_round": (None, [_P, _P, _W]),
    "arb_neg_round": (None, [_P, _P, _W]),
    "arb_max": (None, [_P, _P, _P, _W]),
    "arb_min": (None, [_P, _P, _P, _W]),
    "arb_set": (None, [_P, _P]),
    "arb_nonnegative_part": (None, [_P, _P]),
    "arb_gt": (ctypes.c_int, [_P, _P]),
    "arb_lt": (ctypes.c_int, [_P, _P]),
    "arb_ne": (ctypes.c_int, [_P, _P]),
    "arb_get_abs_ubound_arf": (None, [_P, _P, _W]),
    "arb_get_abs_lbound_arf": (None, [_P, _P, _W]),
    "arf_cmp": (ctypes.c_int, [_P, _P]),
    "arf_set": (None, [_P, _P]),
    "arf_is_finite": (ctypes.c_int, [_P]),
}
_BOUND = {name: arb_loops.extern(name, *signature) for name, signature in _SIGNATURES.items()}
#: GMP's comparison of limb vectors (libflint's dependency, through the same handle): one word
#: of each entry's object header, its type, against ``flint.arb``'s address (``_all_balls``).
_COMPARE_WORDS = arb_loops.extern("__gmpn_cmp", ctypes.c_int, [_P, _P, _W])
#: Where a CPython object keeps its type's address (after its reference count).
_TYPE_OFFSET = ctypes.sizeof(ctypes.c_ssize_t)

#: Whether programs run compiled (else the callers keep their numpy code).
AVAILABLE = (
    arb_loops.AVAILABLE
    and all(f is not None for f in _BOUND.values())
    and _COMPARE_WORDS is not None
    and _TYPE_OFFSET == 8
)

# operation codes: (code, destination, a, b) on registers
ADD, SUB, MUL, DIV, SQRT, EXP, ABS, NEG, MAX, MIN, SET, NONNEGATIVE = range(12)
GT, LT, CHOOSE, REQUIRE_GT, NE, KEEP_FLAG, SWAP = range(12, 19)
"""``GT``/``LT``/``NE`` set the flag to a > b / a < b / a ≠ b (certainly); ``CHOOSE`` sets d to
a if the flag is set, else to b (an exact copy); ``KEEP_FLAG`` keeps the flag as the row's
entry of ``run``'s flags; ``REQUIRE_GT`` stops the run at the first row where a > b is not
certain (``run`` returns that row); ``SWAP`` exchanges two scratch registers' balls (no
libflint call: a value of this row kept for the next, see ``Program.op``'s ``first``)."""

#: Flags of an operation (``Program.compiled``'s last column): at the low precision; on the
#: first row only.
LOW, FIRST = 1, 2

_ARITY = {ADD: 2, SUB: 2, MUL: 2, DIV: 2, MAX: 2, MIN: 2, GT: 2, LT: 2, NE: 2, CHOOSE: 2}
_ARITY |= {KEEP_FLAG: 1, SWAP: 1}
_ARITY |= {REQUIRE_GT: 2, SQRT: 1, EXP: 1, ABS: 1, NEG: 1, SET: 1, NONNEGATIVE: 1}

if AVAILABLE:
    _add = _BOUND["arb_add"]
    _sub = _BOUND["arb_sub"]
    _mul = _BOUND["arb_mul"]
    _div = _BOUND["arb_div"]
    _sqrt = _BOUND["arb_sqrt"]
    _exp = _BOUND["arb_exp"]
    _abs = _BOUND["arb_abs"]
    _set_round = _BOUND["arb_set_round"]
    _neg_round = _BOUND["arb_neg_round"]
    _max = _BOUND["arb_max"]
    _min = _BOUND["arb_min"]
    _set = _BOUND["arb_set"]
    _nonnegative = _BOUND["arb_nonnegative_part"]
    _gt = _BOUND["arb_gt"]
    _lt = _BOUND["arb_lt"]
    _ne = _BOUND["arb_ne"]
    _abs_ubound = _BOUND["arb_get_abs_ubound_arf"]
    _abs_lbound = _BOUND["arb_get_abs_lbound_arf"]
    _arf_cmp = _BOUND["arf_cmp"]
    _arf_set = _BOUND["arf_set"]
    _arf_is_finite = _BOUND["arf_is_finite"]

    @arb_loops.loop
    def _compiled_all_balls(addresses: Any, offset: int, key: int) -> bool:
        """Whether the objects at these ``arb_struct`` addresses are all ``arb``: each
        object's type word compared with the one at ``key`` (every entry of an object array
        is an object, so its header can be read whatever it is)."""
        for k in range(addresses.shape[0]):
            if _COMPARE_WORDS(addresses[k] - offset, key, 1) != 0:
                return False
        return True

    @arb_loops.loop
    def _run(
        code: Any,
        inputs: Any,
        outputs: Any,
        fixed: Any,
        prec: int,
        low: int,
        flags: Any,
        reduced: Any,
        kept: Any,
        keys: Any,
    ) -> int:
        """Every row of ``inputs``/``outputs`` (addresses, one column a register) through
        ``code`` (rows: operation, destination, a, b, 1 for the low precision); registers are
        the inputs, the outputs, then ``fixed`` (constants' and scratch balls' addresses).

        The outputs numbered in ``reduced`` are one scratch ball for every row (``outputs``
        repeats its address), reduced after each row as ``arb_loops._argmax_abs`` reduces a
        column: the ball of the largest |v| upper bound (flint's ``abs_upper`` at ``prec``, the
        first of equal ones) copied into ``kept[2r]``, of the largest lower bound into
        ``kept[2r + 1]`` (``keys``: a key and the two best bounds per reduced output, as
        ``arf``). −1, the row where a ``REQUIRE_GT`` failed, or −2 where a reduced output's
        upper bound is not finite (then ``kept`` is incomplete)."""
        n_in, n_out = inputs.shape[1], outputs.shape[1]
        registers = np.empty(n_in + n_out + fixed.shape[0], dtype=np.int64)
        for j in range(fixed.shape[0]):
            registers[n_in + n_out + j] = fixed[j]
        flag = False
        key = keys[0]
        for row in range(inputs.shape[0]):
            for j in range(n_in):
                registers[j] = inputs[row, j]
            for j in range(n_out):
                registers[n_in + j] = outputs[row, j]
            for step in range(code.shape[0]):
                op, flags_of = code[step, 0], code[step, 4]
                if row and flags_of & FIRST:
                    continue
                if op == SWAP:
                    kept_register = registers[code[step, 1]]
                    registers[code[step, 1]] = registers[code[step, 2]]
                    registers[code[step, 2]] = kept_register
                    continue
                d = registers[code[step, 1]]
                a, b = registers[code[step, 2]], registers[code[step, 3]]
                p = low if flags_of & LOW else prec
                if op == ADD:
                    _add(d, a, b, p)
                elif op == SUB:
                    _sub(d, a, b, p)
                elif op == MUL:
                    _mul(d, a, b, p)
                elif op == DIV:
                    _div(d, a, b, p)
                elif op == SQRT:
                    _sqrt(d, a, p)
                elif op == EXP:
                    _exp(d, a, p)
                elif op == ABS:  # python-flint's abs: rounded to the precision
                    _abs(d, a)
                    _set_round(d, d, p)
                elif op == NEG:  # and its negation
                    _neg_round(d, a, p)
                elif op == MAX:
                    _max(d, a, b, p)
                elif op == MIN:
                    _min(d, a, b, p)
                elif op == SET:
                    _set(d, a)
                elif op == NONNEGATIVE:
                    _nonnegative(d, a)
                elif op == GT:
                    flag = _gt(a, b) != 0
                elif op == LT:
                    flag = _lt(a, b) != 0
                elif op == NE:
                    flag = _ne(a, b) != 0
                elif op == KEEP_FLAG:
                    flags[row] = flag
                elif op == CHOOSE:
                    _set(d, a if flag else b)
                elif op == REQUIRE_GT and not _gt(a, b):
                    return row
            for r in range(reduced.shape[0]):
                ball = registers[n_in + reduced[r]]
                _abs_ubound(key, ball, prec)
                if not _arf_is_finite(key):
                    return -2
                if row == 0 or _arf_cmp(key, keys[2 * r + 1]) > 0:
                    _arf_set(keys[2 * r + 1], key)
                    _set(kept[2 * r], ball)
                _abs_lbound(key, ball, prec)
                if row == 0 or _arf_cmp(key, keys[2 * r + 2]) > 0:
                    _arf_set(keys[2 * r + 2], key)
                    _set(kept[2 * r + 1], ball)
        return -1


class Program:
    """A straight-line formula on named registers: ``inputs`` (one ball per row each),
    ``constants`` (one ball for every row), ``outputs`` (written, fresh balls per row); any
    other name is a scratch ball. ``op`` appends one operation (``low``: at ``run``'s low
    precision). ``counters``: scratch balls that may be read before they are written: each
    holds 0 at the start of a run and keeps its value from row to row (as every scratch
    ball)."""

    def __init__(
        self,
        inputs: list[str],
        constants: list[str],
        outputs: list[str],
        counters: tuple[str, ...] = (),
    ) -> None:
        self.inputs, self.constants, self.outputs = inputs, constants, outputs
        self.scratch: list[str] = list(counters)
        self.steps: list[tuple[int, str, str, str, int]] = []
        self._table: np.ndarray[Any, np.dtype[np.int64]] | None = None

    def op(
        self,
        code: int,
        d: str,
        a: str,
        b: str | None = None,
        low: bool = False,
        first: bool = False,
    ) -> None:
        """``d`` = ``code``(a, b); ``first``: on the first row only (a value the rows then
        carry, each row computing the next row's and ``SWAP``-ping it in at its end)."""
        if (b is None) != (_ARITY[code] == 1):
            raise TypeError("wrong number of operands")
        if code == SWAP and not {d, a} <= {*self.scratch}:
            raise NameError("only scratch registers are swapped")
        known = {*self.inputs, *self.constants, *self.outputs, *self.scratch}
        for name in (a, b):
            if name is not None and name not in known:
                raise NameError(f"register {name!r} read before it is written")
        if d in self.inputs or d in self.constants:
            raise NameError(f"register {d!r} is read-only")
        if d not in known:
            self.scratch.append(d)
        self.steps.append((code, d, a, a if b is None else b, LOW * low + FIRST * first))
        self._table = None

    def compiled(self) -> np.ndarray[Any, np.dtype[np.int64]]:
        """The operation table ``_run`` reads (register numbers), made once."""
        if self._table is None:
            names = [*self.inputs, *self.outputs, *self.constants, *self.scratch]
            number = {name: k for k, name in enumerate(names)}
            steps = self.steps
            table = [(c, number[d], number[a], number[b], f) for c, d, a, b, f in steps]
            self._table = np.array(table, dtype=np.int64).reshape(-1, 5)
        return self._table


def run(
    program: Program,
    inputs: dict[str, np.ndarray[Any, Any]],
    constants: dict[str, Any],
    low: int | None = None,
    reduce: Collection[str] = (),
    rows: int = 0,
) -> tuple[list[np.ndarray[Any, Any]], int, np.ndarray[Any, np.dtype[np.bool_]]] | None:
    """``program`` on equal-length 1-d object arrays of balls (by input name) and constant
    balls: the outputs (in ``program.outputs`` order) as fresh balls, and −1 or the row where
    a ``REQUIRE_GT`` failed (the outputs are then incomplete), and the rows' kept flags
    (``KEEP_FLAG``, else false); None where the compiled loop
    does not apply (not available, an entry not a ball, no rows: the caller's numpy code runs).
    ``low``: the precision of the operations marked low (default the working precision).

    The outputs named in ``reduce`` are not kept per row: each is returned as the two balls a
    check without per-index residuals reduces it to (``reduced``), no ball made per row. Where
    one of them has an unbounded ball, every output is made per row instead (the checks' notes
    count the residuals that are not finite). ``rows``: how many rows a program without
    inputs runs (one reading a counter of its own)."""
    if not AVAILABLE:
        return None
    columns = [inputs[name] for name in program.inputs]
    rows = len(columns[0]) if columns else rows
    if not rows or any(c.ndim != 1 or len(c) != rows or c.dtype != object for c in columns):
        return None
    address_in = np.empty((rows, len(columns)), dtype=np.int64)
    for j, column in enumerate(columns):
        address_in[:, j] = arb_loops.addresses(column)
    if not all_balls(address_in):
        return None
    fixed_balls = [constants[name] for name in program.constants]
    if any(type(ball) is not flint.arb for ball in fixed_balls):
        return None
    reduced = [program.outputs.index(name) for name in reduce]
    outputs: list[Any] = [None] * len(program.outputs)
    if columns:
        negated = columns[0]
    else:
        negated = np.empty(rows, dtype=object)
        negated[:] = [flint.arb()] * rows
    address_out = np.empty((rows, len(program.outputs)), dtype=np.int64)
    for j in range(len(program.outputs)):
        if j not in reduced:
            outputs[j] = np.negative(negated)  # fresh balls, written over
            address_out[:, j] = arb_loops.addresses(outputs[j])
    kept = [flint.arb() for _ in range(2 * len(reduced))]
    prec = flint.ctx.prec
    flags = np.zeros(rows, dtype=np.bool_)
    table = program.compiled()
    count = len(program.scratch) + 1 + 3 * len(reduced)  # scratch, then the reductions' own
    with arb_loops.Scratch(count) as scratch:
        fixed = np.empty(len(fixed_balls) + len(program.scratch), dtype=np.int64)
        fixed[: len(fixed_balls)] = [id(ball) for ball in fixed_balls]
        fixed[: len(fixed_balls)] += arb_loops.OFFSET
        fixed[len(fixed_balls) :] = scratch + arb_loops.ARB_BYTES * np.arange(
            len(program.scratch), dtype=np.int64
        )
        ours = scratch + arb_loops.ARB_BYTES * (
            len(program.scratch) + np.arange(1 + 3 * len(reduced), dtype=np.int64)
        )
        for r, j in enumerate(reduced):  # a reduced output: one scratch ball for every row
            address_out[:, j] = ours[1 + len(reduced) * 2 + r]
        stopped = _run(
            table,
            address_in,
            address_out,
            fixed,
            prec,
            prec if low is None else low,
            flags,
            np.array(reduced, dtype=np.int64),
            np.array([id(ball) for ball in kept], dtype=np.int64) + arb_loops.OFFSET,
            ours[: 1 + 2 * len(reduced)],
        )
    del fixed_balls  # the constants lived until here
    if stopped == -2:  # an unbounded reduced residual: every row's ball, for the checks' notes
        return run(program, inputs, constants, low, rows=rows)
    for r, j in enumerate(reduced):
        outputs[j] = reduced_pair(kept[2 * r], kept[2 * r + 1])
    return outputs, int(stopped), flags


def reduced_pair(upper: Any, lower: Any) -> np.ndarray[Any, Any]:
    """What a check without per-index residuals reads of a column of residual balls: the ball
    whose |v| upper bound is the largest and the one whose lower bound is (``run``'s
    ``reduce``); its largest upper and lower bounds (``Ball.largest_upper``/``largest_lower``)
    are the column's."""
    pair = np.empty(2, dtype=object)
    pair[0], pair[1] = upper, lower
    return pair


def all_balls(addresses: np.ndarray[Any, np.dtype[np.int64]]) -> bool:
    """Whether every object of an object array is an ``arb``, from its ``arb_loops.addresses``
    (about 3 ns an entry, where ``arb_loops.all_balls`` takes about 40): checked before any
    ball is read through them."""
    if not AVAILABLE or _COMPARE_WORDS is None or _TYPE_OFFSET != 8:
        raise RuntimeError("no compiled type check")
    key = np.array([id(flint.arb)], dtype=np.int64)
    found = _compiled_all_balls(
        addresses.reshape(-1), arb_loops.OFFSET - _TYPE_OFFSET, key.ctypes.data
    )
    return bool(found)


def _warm() -> None:
    """Compile the loop now, at import, so that no request pays for it."""
    program = Program(["x"], ["one"], ["y"])
    program.op(ADD, "s", "x", "one")
    program.op(REQUIRE_GT, "s", "s", "one")
    program.op(GT, "s", "s", "one")
    program.op(CHOOSE, "y", "s", "one")
    column = np.empty(2, dtype=object)
    column[:] = [flint.arb(1), flint.arb(2)]
    run(program, {"x": column}, {"one": flint.arb(1)})
    run(program, {"x": column}, {"one": flint.arb(1)}, reduce=["y"])
    mixed = np.empty(2, dtype=object)
    mixed[:] = [flint.arb(1), 1.5]
    if all_balls(arb_loops.addresses(column)) is not True or all_balls(arb_loops.addresses(mixed)):
        raise RuntimeError("the compiled type check does not read object headers as expected")


if AVAILABLE:
    try:
        _warm()
    except RuntimeError:  # object headers not as expected: the numpy code runs
        AVAILABLE = False
