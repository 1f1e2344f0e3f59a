"""Compiled passes over numpy object arrays of python-flint ``arb`` balls.

A reduction on balls in Python (the largest upper bound of 1000 residuals, the largest radius
of 7000 certificate points) costs one or more Python calls per entry, each allocating a ball for
an intermediate (``abs_upper``, ``rad``, ``abs_lower``, a quotient, ``upper``) only to compare it
and drop it. Here the same libflint functions run in a numba loop straight on the balls' own
``arb_struct`` (python-flint stores it inside each ``arb`` object, at the end of its fixed-size
layout), with scratch balls allocated and freed by flint around the loop, and a reduction
returns the *index* of the winning entry: the caller computes the value from that one entry
with python-flint, so the numbers reported are those of the Python reduction it replaces (the
keys compared here are the same libflint functions at the same precision). Two elementwise
passes (``hypot``, ``relative_point_difference``) make the same libflint calls as the numpy
code they replace, at the same precisions, into fresh balls that nothing else references yet
(made by numpy's negation loop): the same balls, without a Python call per operation.

libflint is the one python-flint's wheel bundles and its ``arb`` module links, reached through
that module's handle with ctypes (the bundled file's name carries a build hash); the layout is
checked once against known balls before anything is read through it. Where either is not as
expected (another python-flint build), ``AVAILABLE`` is false and the callers keep their numpy
code. The input balls are only read, and stay referenced by the caller's arrays during a call.

The loops call libflint by symbol name (``extern``: each name registered with the JIT's linker
at its address in this process), so no process's addresses are in the machine code and numba
caches the loops on disk (``NUMBA_CACHE_DIR``, filled by ``python -m app.geometry.warm``): a
process loads them at import instead of compiling them. (A ctypes function called from a loop is
compiled in as a constant address, which numba refuses to cache.)
"""

from __future__ import annotations

import contextlib
import ctypes
import weakref
from collections.abc import Callable
from functools import partial
from typing import Any, TypeVar, cast

import flint
import flint.types.arb as flint_arb_module
import numba
import numpy as np
from numba.core import caching, externals

from app.geometry import compiled
from app.geometry.precision import CLOCK_STEPS

F = TypeVar("F", bound=Callable[..., Any])

#: Bytes of one ``arb_struct`` (midpoint ``arf_struct`` 32, radius ``mag_struct`` 16).
ARB_BYTES = 48
#: Offset of the radius (``arb_radref``) within an ``arb_struct``.
RADIUS_OFFSET = 32


_P, _W = ctypes.c_void_p, ctypes.c_long
#: The libflint functions the loops call, and their types.
_SIGNATURES: dict[str, tuple[Any, list[Any]]] = {
    "arb_get_abs_ubound_arf": (None, [_P, _P, _W]),
    "arb_get_abs_lbound_arf": (None, [_P, _P, _W]),
    "arb_get_ubound_arf": (None, [_P, _P, _W]),
    "arb_div": (None, [_P, _P, _P, _W]),
    "arf_cmp": (ctypes.c_int, [_P, _P]),
    "arf_set": (None, [_P, _P]),
    "arf_set_mag": (None, [_P, _P]),
    "arf_is_finite": (ctypes.c_int, [_P]),
    "arf_is_zero": (ctypes.c_int, [_P]),
    "mag_cmp": (ctypes.c_int, [_P, _P]),
    "mag_is_zero": (ctypes.c_int, [_P]),
    "mag_is_finite": (ctypes.c_int, [_P]),
    "arf_get_d": (ctypes.c_double, [_P, ctypes.c_int]),
    "arb_sub": (None, [_P, _P, _P, _W]),
    "arb_add": (None, [_P, _P, _P, _W]),
    "arb_mul": (None, [_P, _P, _P, _W]),
    "arb_set": (None, [_P, _P]),
    "arb_set_si": (None, [_P, _W]),
    "arb_sqrt": (None, [_P, _P, _W]),
    "arb_nonnegative_part": (None, [_P, _P]),
    "arb_gt": (ctypes.c_int, [_P, _P]),
    "_arb_vec_init": (_P, [_W]),
    "_arb_vec_clear": (None, [_P, _W]),
}


def _library() -> Any:
    """libflint as python-flint's ``arb`` extension module links it, or None.

    The module's own handle: the dynamic linker looks a symbol up in the module and then in the
    libraries it was loaded with, so libflint's functions are found whatever the bundled file
    is called (``python_flint.libs/libflint-<hash>.so`` in the wheel), with nothing searched.
    """
    try:
        return ctypes.CDLL(flint_arb_module.__file__)
    except (OSError, TypeError):
        return None


def _bind(library: Any) -> dict[str, Any] | None:
    """The libflint functions the loops call, typed; None if one is missing."""
    bound = {}
    for name, (result, arguments) in _SIGNATURES.items():
        function = getattr(library, name, None)
        if function is None:
            return None
        function.restype, function.argtypes = result, arguments
        bound[name] = function
    return bound


def _offset(functions: dict[str, Any]) -> int | None:
    """Where an ``arb`` object holds its ``arb_struct``: at the end of its fixed-size layout,
    confirmed on known balls (midpoint and radius read back through libflint)."""
    offset = flint.arb.__basicsize__ - ARB_BYTES
    if offset < ctypes.sizeof(ctypes.c_void_p) * 2:
        return None
    for value, radius in ((0.75, 0.125), (-3.5, 0.5), (1e-300, 0.0)):
        ball = flint.arb(value, radius)
        address = id(ball) + offset
        if functions["arf_get_d"](address, 4) != value:  # ARF_RND_NEAR: exact here
            return None
        if bool(functions["mag_is_zero"](address + RADIUS_OFFSET)) != (radius == 0):
            return None
    return offset


_FUNCTIONS: dict[str, Any] | None = None
OFFSET = 0
_library_handle = _library()
if _library_handle is not None:
    _FUNCTIONS = _bind(_library_handle)
if _FUNCTIONS is not None:
    found = _offset(_FUNCTIONS)
    if found is None:
        _FUNCTIONS = None
    else:
        OFFSET = found

#: Whether the compiled reductions can be used (else the callers' Python reductions run).
AVAILABLE = _FUNCTIONS is not None


def bind(name: str, result: Any, arguments: list[Any]) -> Any:
    """One more libflint function from the same handle, typed for numba's nopython loops in
    another module (bind it to a module global there); None when the compiled passes are not
    available or the function is missing (the caller then keeps its Python code)."""
    if _library_handle is None or _FUNCTIONS is None:
        return None
    function = getattr(_library_handle, name, None)
    if function is None:
        return None
    function.restype, function.argtypes = result, arguments
    return function


#: numba's types for the ctypes types of the functions' signatures (addresses as integers).
_NUMBA_TYPES: dict[Any, Any] = {
    None: numba.types.void,
    ctypes.c_void_p: numba.types.int64,
    ctypes.c_long: numba.types.int64,
    ctypes.c_ulong: numba.types.uint64,
    ctypes.c_int: numba.types.int32,
    ctypes.c_uint: numba.types.uint32,
    ctypes.c_double: numba.types.float64,
}


def extern(name: str, result: Any, arguments: list[Any]) -> Any:
    """One libflint function for the compiled loops, called by symbol name: ``arb_loops.<name>``
    is registered with the JIT's linker at the function's address in this process (numba's own
    helper for its C functions) and resolved when a loop is compiled or loaded from the cache.
    A numba ``ExternalFunction`` typed as the ctypes signature (pointers and ``long`` as 64-bit
    integers, ``int`` as 32-bit: the same registers in the C calling convention); None where
    ``bind`` gives None or a type has no match here (add it to ``_NUMBA_TYPES``: the callers
    otherwise keep their Python code)."""
    function = bind(name, result, arguments)
    if function is None or not {result, *arguments} <= _NUMBA_TYPES.keys():
        return None
    if ctypes.sizeof(ctypes.c_void_p) != 8 or ctypes.sizeof(ctypes.c_long) != 8:
        return None
    symbol = f"arb_loops.{name}"
    address = ctypes.cast(function, ctypes.c_void_p).value
    externals._add_missing_symbol(symbol, address)  # type: ignore[no-untyped-call]
    signature = _NUMBA_TYPES[result](*(_NUMBA_TYPES[a] for a in arguments))
    return numba.types.ExternalFunction(symbol, signature)


class _JointStamp:
    """A cache locator for the files of ``loop``'s functions: their cache entries are stamped
    with this file's contents as well as their own (numba's stamp: its source file only), since
    they may call its loops (``_hypot``): a change here recompiles them too."""

    @classmethod
    def from_function(cls, py_func: Any, py_file: str) -> Any:
        if py_file not in _LOOP_FILES:
            return None
        return super().from_function(py_func, py_file)  # type: ignore[misc]

    def get_source_stamp(self) -> Any:
        this_file = _ThisFile().get_source_stamp()  # type: ignore[no-untyped-call]
        return super().get_source_stamp(), this_file  # type: ignore[misc]


class _ThisFile(caching._SourceFileBackedLocatorMixin):
    """numba's stamp of this file (a digest of its contents)."""

    _py_file = __file__


class _CacheDirectory(_JointStamp, compiled.ReadableCacheLocator):
    """``NUMBA_CACHE_DIR`` (also read-only, as ``compiled``'s kernels)."""


class _BesideSource(_JointStamp, caching.InTreeCacheLocator):
    """``__pycache__`` beside the source where ``NUMBA_CACHE_DIR`` is not set."""


caching.CacheImpl._locator_classes = [
    _CacheDirectory,
    _BesideSource,
    *caching.CacheImpl._locator_classes,
]
#: The source files of ``loop``'s functions.
_LOOP_FILES: set[str] = set()


class _Cache(caching.FunctionCache):
    """numba's cache of a function, where a failed save (a read-only cache without this loop:
    another CPU, a changed file) leaves the loop compiled in memory instead of raising."""

    def save_overload(self, sig: Any, data: Any) -> None:
        with contextlib.suppress(OSError):
            super().save_overload(sig, data)  # type: ignore[no-untyped-call]


def loop(function: F) -> F:
    """``numba.njit`` cached on disk (for loops that call libflint through ``extern`` only, and
    other loops of ``loop``), compiled at the first call where the cache lacks it; in memory
    only where numba finds no cache directory."""
    _LOOP_FILES.add(function.__code__.co_filename)
    dispatcher: Any = numba.njit(cache=False)(function)
    with contextlib.suppress(RuntimeError):  # numba: no cache directory for this file
        dispatcher._cache = _Cache(function)  # type: ignore[no-untyped-call]
    return cast(F, dispatcher)


#: id of a read-only array of balls made here (``fresh``, ``keep``) -> (a weak reference to
#: it, its entries' ``arb_struct`` addresses in C order). Entries go when their array does.
_KNOWN: dict[int, tuple[weakref.ref[Any], np.ndarray[Any, np.dtype[np.int64]]]] = {}


def fresh(count: int) -> np.ndarray[Any, Any]:
    """``count`` fresh balls (numpy's negation loop over zeros: one allocation each), which
    nothing else references yet, for a loop to write into; read-only (``keep``)."""
    return keep(np.negative(np.full(count, _ZERO, dtype=object)), checked=True)


def keep(values: np.ndarray[Any, Any], checked: bool = False) -> np.ndarray[Any, Any]:
    """Make a C-contiguous object array of balls that owns its entries read-only and remember
    its addresses: ``addresses`` and ``known_balls`` of it, or of a view of it, then take no
    pass over its entries (a read-only array's entries cannot be replaced, nor can its views
    be written). Returns ``values``; an array that does not qualify is left as it is."""
    if (
        values.dtype == object
        and values.base is None
        and values.flags.c_contiguous
        and values.size
        and (checked or _checked_balls(values))
    ):
        found = _read_addresses(values)
        values.flags.writeable = False
        key = id(values)
        _KNOWN[key] = (weakref.ref(values, partial(_forget, key)), found)
    return values


def _forget(key: int, _: object) -> None:
    """Drop an array's entry of ``_KNOWN`` (its weak reference's callback, as it goes)."""
    _KNOWN.pop(key, None)


def _checked_balls(values: np.ndarray[Any, Any]) -> bool:
    """Whether every entry is a ball: ``arb_program``'s compiled type check where it exists."""
    from app.geometry import arb_program  # it builds on this module

    if arb_program.AVAILABLE:
        return arb_program.all_balls(_read_addresses(values))
    return all_balls(values)


def _known(values: np.ndarray[Any, Any]) -> np.ndarray[Any, np.dtype[np.int64]] | None:
    """The addresses of an array of ``keep``, or of a view of one (the same byte offsets and
    strides over its addresses, 8 bytes an entry in both), in C order; None otherwise."""
    if values.flags.writeable:
        return None
    entry = _KNOWN.get(id(values))
    if entry is not None and entry[0]() is values:
        return entry[1]
    base = values.base
    entry = _KNOWN.get(id(base)) if type(base) is np.ndarray else None
    if entry is None or entry[0]() is not base or min(values.strides, default=0) < 0:
        return None
    assert base is not None
    start = (values.__array_interface__["data"][0] - base.__array_interface__["data"][0]) // 8
    if values.flags.c_contiguous:  # rows of the base: a range of its addresses
        return entry[1][start : start + values.size]
    if values.ndim == 1:  # a column or a strided range (copied: the loops take C order)
        step = values.strides[0] // 8
        return np.ascontiguousarray(entry[1][start : start + (values.size - 1) * step + 1 : step])
    view = np.lib.stride_tricks.as_strided(
        entry[1][start:], shape=values.shape, strides=values.strides, writeable=False
    )
    return np.ascontiguousarray(view).reshape(-1)


def known_balls(values: np.ndarray[Any, Any]) -> bool:
    """Whether ``values`` is an array of ``keep`` or a view of one (every entry a ball)."""
    return _known(values) is not None


def addresses(values: np.ndarray[Any, Any]) -> np.ndarray[Any, np.dtype[np.int64]]:
    """The ``arb_struct`` address of every entry of an object array of ``arb`` (all of them
    ``arb``: the caller checks), in C order. The array must stay alive while the addresses are
    used. Those of an array of ``keep`` (or a view of one) are its remembered ones."""
    found = _known(values)
    return found if found is not None else _read_addresses(values)


def _read_addresses(values: np.ndarray[Any, Any]) -> np.ndarray[Any, np.dtype[np.int64]]:
    """``addresses`` read from the array.

    An object array stores its entries' object addresses (CPython's ``id``): they are read from
    its buffer (a C-ordered copy for a strided view, such as a column) in one copy, about 5 ns
    an entry where ``map(id, …)`` took about 80."""
    if not _POINTER_BUFFER:
        flat = values.reshape(-1)
        return np.fromiter(map(id, flat), dtype=np.int64, count=flat.size) + OFFSET
    contiguous = np.ascontiguousarray(values)
    if not contiguous.size:
        return np.zeros(0, dtype=np.int64)
    pointers = (ctypes.c_int64 * contiguous.size).from_address(contiguous.ctypes.data)
    return np.ctypeslib.as_array(pointers) + OFFSET  # a new array: no view of the buffer kept


#: Whether an object array's buffer holds 64-bit object addresses (CPython on 64-bit hosts).
_POINTER_BUFFER = ctypes.sizeof(ctypes.c_void_p) == 8 == np.dtype(object).itemsize


def all_balls(values: np.ndarray[Any, Any]) -> bool:
    """Whether every entry is an ``arb`` (the compiled reductions read nothing else)."""
    return set(map(type, values.reshape(-1))) <= {flint.arb}


#: The functions of ``_SIGNATURES`` as the loops call them (``extern``).
_EXTERN = {name: extern(name, *_SIGNATURES[name]) for name in _SIGNATURES} if AVAILABLE else {}
if any(f is None for f in _EXTERN.values()):
    AVAILABLE = False
if AVAILABLE:
    _abs_ubound = _EXTERN["arb_get_abs_ubound_arf"]
    _abs_lbound = _EXTERN["arb_get_abs_lbound_arf"]
    _ubound = _EXTERN["arb_get_ubound_arf"]
    _div = _EXTERN["arb_div"]
    _arf_cmp = _EXTERN["arf_cmp"]
    _arf_set = _EXTERN["arf_set"]
    _arf_set_mag = _EXTERN["arf_set_mag"]
    _arf_is_finite = _EXTERN["arf_is_finite"]
    _arf_is_zero = _EXTERN["arf_is_zero"]
    _mag_cmp = _EXTERN["mag_cmp"]
    _mag_is_zero = _EXTERN["mag_is_zero"]
    _mag_is_finite = _EXTERN["mag_is_finite"]

    @loop
    def _argmax_abs(points: Any, upward: bool, prec: int, scratch: int) -> int:
        """Index of the largest |v| upper (``upward``) or lower bound; −1 for no entries, −2
        if a bound is not finite (the caller's Python reduction decides those)."""
        key, best = scratch, scratch + ARB_BYTES
        found = -1
        for k in range(points.shape[0]):
            if upward:
                _abs_ubound(key, points[k], prec)
            else:
                _abs_lbound(key, points[k], prec)
            if not _arf_is_finite(key):
                return -2
            if found < 0 or _arf_cmp(key, best) > 0:
                _arf_set(best, key)
                found = k
        return found

    @loop
    def _largest_radii(xs: Any, ys: Any, prec: int, scratch: int) -> Any:
        """For points (x, y): the index of the largest radius max(rad x, rad y) (−1: every
        point exact), the index of the largest upper bound of that radius over the point's
        size max(|x|, |y|) (its lower bound, ``abs_lower``) among the inexact points of
        positive size (−1: none), whether an inexact point has size 0, and whether a radius
        or a bound is not finite (then the caller's Python reduction decides)."""
        radius, size, other = scratch, scratch + ARB_BYTES, scratch + 2 * ARB_BYTES
        quotient, key, best = (
            scratch + 3 * ARB_BYTES,
            scratch + 4 * ARB_BYTES,
            scratch + 5 * ARB_BYTES,
        )
        largest = -1
        largest_relative = -1
        reaches_zero = False
        for k in range(xs.shape[0]):
            rx, ry = xs[k] + RADIUS_OFFSET, ys[k] + RADIUS_OFFSET
            if not _mag_is_finite(rx) or not _mag_is_finite(ry):
                return -2, -2, False, True
            r = rx if _mag_cmp(rx, ry) >= 0 else ry
            if _mag_is_zero(r):
                continue
            if largest < 0:
                largest = k
            else:
                previous = xs[largest] + RADIUS_OFFSET
                if _mag_cmp(ys[largest] + RADIUS_OFFSET, previous) > 0:
                    previous = ys[largest] + RADIUS_OFFSET
                if _mag_cmp(r, previous) > 0:
                    largest = k
            _abs_lbound(size, xs[k], prec)
            _abs_lbound(other, ys[k], prec)
            if _arf_cmp(other, size) > 0:
                _arf_set(size, other)
            if not _arf_is_finite(size):
                return -2, -2, False, True
            if _arf_is_zero(size):
                reaches_zero = True
                continue
            _arf_set_mag(radius, r)  # radius and size: exact balls (zero radius)
            _div(quotient, radius, size, prec)
            _ubound(key, quotient, prec)
            if not _arf_is_finite(key):
                return -2, -2, False, True
            if largest_relative < 0 or _arf_cmp(key, best) > 0:
                _arf_set(best, key)
                largest_relative = k
        return largest, largest_relative, reaches_zero, False

    _sub = _EXTERN["arb_sub"]
    _add = _EXTERN["arb_add"]
    _mul = _EXTERN["arb_mul"]
    _sqrt = _EXTERN["arb_sqrt"]
    _nonnegative = _EXTERN["arb_nonnegative_part"]
    _gt = _EXTERN["arb_gt"]

    @loop
    def _hypot(out: int, x: int, y: int, prec: int, square: int) -> None:
        """out = sqrt(nonnegative part of x·x + y·y), as ``Ball.hypot`` (``square``: scratch)."""
        _mul(square, x, x, prec)
        _mul(out, y, y, prec)
        _add(square, square, out, prec)
        _nonnegative(square, square)
        _sqrt(out, square, prec)

    @loop
    def _hypots(xs: Any, ys: Any, out: Any, prec: int, square: int) -> None:
        """``_hypot`` entry by entry into the balls at ``out``."""
        for k in range(out.shape[0]):
            _hypot(out[k], xs[k], ys[k], prec, square)

    @loop
    def _relative_point_difference(
        computed: Any, expected: Any, tiny: int, out: Any, work: int, low: int, scratch: int
    ) -> None:
        """``checks.relative_point_difference`` row by row into the balls at ``out``: the
        differences at ``work`` bits, the lengths and the quotient at ``low``."""
        dx, dy, square = scratch, scratch + ARB_BYTES, scratch + 2 * ARB_BYTES
        scale, length = scratch + 3 * ARB_BYTES, scratch + 4 * ARB_BYTES
        for k in range(out.shape[0]):
            cx, cy, ex, ey = (
                computed[2 * k],
                computed[2 * k + 1],
                expected[2 * k],
                expected[2 * k + 1],
            )
            _sub(dx, cx, ex, work)
            _sub(dy, cy, ey, work)
            _hypot(scale, ex, ey, low, square)
            _hypot(length, dx, dy, low, square)
            _div(out[k], length, scale if _gt(scale, tiny) else tiny, low)

    _set = _EXTERN["arb_set"]

    @loop
    def _rotation(centre: int, d: int, one: int, two: int, prec: int, s: int) -> None:
        """cos α and sin α of ``construction.rotation_about(centre, d)`` into the scratch balls
        ``s + 5·ARB_BYTES`` and ``s + 7·ARB_BYTES``: r = d/p_y, q = 1 + r·r, cos α = (1 − r·r)/q,
        sin α = 2r/q, the calls python-flint's operators make (``r * r`` multiplies r by a
        copy of itself: the operator's second operand is never the first one's struct)."""
        r, copy, square, q = s, s + ARB_BYTES, s + 2 * ARB_BYTES, s + 3 * ARB_BYTES
        numerator, ca = s + 4 * ARB_BYTES, s + 5 * ARB_BYTES
        twice, sa = s + 6 * ARB_BYTES, s + 7 * ARB_BYTES
        _div(r, d, centre, prec)
        _set(copy, r)
        _mul(square, r, copy, prec)
        _add(q, one, square, prec)
        _mul(twice, two, r, prec)
        _sub(numerator, one, square, prec)
        _div(ca, numerator, q, prec)
        _div(sa, twice, q, prec)

    @loop
    def _sticks(
        cos_u: Any,
        sin_u: Any,
        centre_y: Any,
        h: int,
        d: int,
        one: int,
        two: int,
        lo: int,
        start: int,
        stop: int,
        prec: int,
        s: int,
    ) -> None:
        """The mp loop of ``construction.construct`` for j = start .. stop − 1 (forwards, stop >
        start: stick j−1 to stick j about p_j) or j = start down to stop + 1 (backwards: stick j
        to stick j−1), on the balls at ``cos_u``, ``sin_u``, ``centre_y`` (entry j − lo), with
        its calls on its operands in its order (``_rotation``); scratch ``s``: 12 balls."""
        ca, sa = s + 5 * ARB_BYTES, s + 7 * ARB_BYTES
        product, first, second = s + 8 * ARB_BYTES, s + 9 * ARB_BYTES, s + 10 * ARB_BYTES
        forward = stop > start
        step = 1 if forward else -1
        for j in range(start, stop, step):
            if forward:
                c, sn = cos_u[j - 1 - lo], sin_u[j - 1 - lo]
                _mul(product, d, c, prec)  # p_y = (h − d·c)/s
                _sub(product, h, product, prec)
            else:
                c, sn = cos_u[j - lo], sin_u[j - lo]
                _mul(product, d, c, prec)  # p_y = (h + d·c)/s
                _add(product, h, product, prec)
            p_y = centre_y[j - lo]
            _div(p_y, product, sn, prec)
            _rotation(p_y, d, one, two, prec, s)
            if forward:  # (ca·c − sa·s, sa·c + ca·s)
                _mul(first, ca, c, prec)
                _mul(second, sa, sn, prec)
                _sub(cos_u[j - lo], first, second, prec)
                _mul(first, sa, c, prec)
                _mul(second, ca, sn, prec)
                _add(sin_u[j - lo], first, second, prec)
            else:  # (ca·c + sa·s, ca·s − sa·c)
                _mul(first, ca, c, prec)
                _mul(second, sa, sn, prec)
                _add(cos_u[j - 1 - lo], first, second, prec)
                _mul(first, ca, sn, prec)
                _mul(second, sa, c, prec)
                _sub(sin_u[j - 1 - lo], first, second, prec)

    _set_si = _EXTERN["arb_set_si"]

    @loop
    def _points(
        cos_u: Any,
        sin_u: Any,
        i_min: int,
        constants: Any,
        axis_x: Any,
        tractrix_x: Any,
        tractrix_y: Any,
        centre_x: Any,
        prec: int,
        s: int,
    ) -> None:
        """``construction._assemble``'s new balls for sticks i = i_min …: x_i^x = (2d)·i,
        d_i = (x_i^x + h·cos, 0 + h·sin), p_i^x = (2·i − 1)·d, with the calls numpy's object
        loops make through python-flint's operators (``constants``: h, d, 2d, 2, 1, 0)."""
        h, d, two_d, two, one, zero = (
            constants[0],
            constants[1],
            constants[2],
            constants[3],
            constants[4],
            constants[5],
        )
        index, t = s, s + ARB_BYTES
        for k in range(axis_x.shape[0]):
            _set_si(index, i_min + k)  # flint.arb(i): exact
            _mul(axis_x[k], two_d, index, prec)
            _mul(t, h, cos_u[k], prec)
            _add(tractrix_x[k], axis_x[k], t, prec)
            _mul(t, h, sin_u[k], prec)
            _add(tractrix_y[k], zero, t, prec)
            _mul(t, two, index, prec)
            _sub(t, t, one, prec)
            _mul(centre_x[k], t, d, prec)

    _vec_init = bind("_arb_vec_init", *_SIGNATURES["_arb_vec_init"])
    _vec_clear = bind("_arb_vec_clear", *_SIGNATURES["_arb_vec_clear"])


class Scratch:
    """``count`` zeroed ``arb_struct`` allocated by flint, freed on leaving (also on errors);
    for the loops of other modules too."""

    def __init__(self, count: int) -> None:
        self.count = count
        self.address = 0

    def __enter__(self) -> int:
        self.address = int(_vec_init(self.count))
        return self.address

    def __exit__(self, *exception: object) -> None:
        _vec_clear(self.address, self.count)
        self.address = 0


def argmax_abs(
    values: np.ndarray[Any, Any],
    upward: bool,
    read: np.ndarray[Any, np.dtype[np.int64]] | None = None,
) -> int:
    """Index of the entry whose |v| upper (``upward``) or lower bound is the largest (flint's
    ``abs_upper``/``abs_lower`` at the working precision, compared exactly; the first of equal
    ones); −1 for an empty array, −2 when some bound is not finite. ``read``: the entries'
    ``addresses`` if the caller has them already (else they are read here)."""
    if not values.size:
        return -1
    found = addresses(values) if read is None else read
    with Scratch(2) as scratch:
        return int(_argmax_abs(found, upward, flint.ctx.prec, scratch))


def largest_radii(x: np.ndarray[Any, Any], y: np.ndarray[Any, Any]) -> tuple[int, int, bool, bool]:
    """For the points (x, y) (``_largest_radii``): (index of the largest radius, index of the
    largest relative radius, whether an inexact point's ball reaches 0 in both coordinates,
    whether something is not finite)."""
    with Scratch(6) as scratch:
        largest, relative, reaches_zero, unbounded = _largest_radii(
            addresses(x), addresses(y), flint.ctx.prec, scratch
        )
    return int(largest), int(relative), bool(reaches_zero), bool(unbounded)


def relative_point_difference(
    computed: np.ndarray[Any, Any], expected: np.ndarray[Any, Any], tiny: Any, low: int
) -> np.ndarray[Any, Any]:
    """``checks.relative_point_difference`` of two ``(n, 2)`` arrays of balls in one compiled
    pass: the same libflint operations at the same precisions (the differences at the working
    precision, the rest at ``low`` bits), so the same balls. The results are written into fresh
    balls made by negating a column (numpy's loop: one allocation each, no conversion), which
    nothing else references yet."""
    out = np.negative(expected[:, 0])
    with Scratch(5) as scratch:
        _relative_point_difference(
            addresses(computed),
            addresses(expected),
            id(tiny) + OFFSET,
            addresses(out),
            flint.ctx.prec,
            low,
            scratch,
        )
    return out


def hypot(x: np.ndarray[Any, Any], y: np.ndarray[Any, Any]) -> np.ndarray[Any, Any]:
    """``Ball.hypot`` of two equal-length 1-d arrays of balls in one compiled pass (the same
    operations: the same balls), into fresh balls as ``relative_point_difference``."""
    out = np.negative(x)
    with Scratch(1) as scratch:
        _hypots(addresses(x), addresses(y), addresses(out), flint.ctx.prec, scratch)
    return out


def sticks(
    h: Any, d: Any, c0: Any, s0: Any, lo: int, hi: int, clock: Callable[[], None]
) -> tuple[np.ndarray[Any, Any], np.ndarray[Any, Any], np.ndarray[Any, Any]]:
    """The mp recursion of ``construction.construct`` on balls: (cos β_j, sin β_j, p_j^y) for j
    = lo .. hi as object arrays of fresh balls, stick 0 = (c0, s0) (balls), h and d balls, at
    the working precision. The same libflint calls as that Python loop (``_sticks``), so the
    same balls; run in chunks of ``CLOCK_STEPS`` sticks with ``clock()`` between them, where the
    Python loop reads the clock. Entry 0 of p^y stays 0 when lo = 0, as there."""
    n = hi - lo + 1
    cos_u, sin_u, centre_y = (np.negative(np.full(n, _ZERO, dtype=object)) for _ in range(3))
    cos_u[-lo], sin_u[-lo] = c0, s0
    cos_u, sin_u, centre_y = (keep(a, checked=True) for a in (cos_u, sin_u, centre_y))
    cos_a, sin_a, centre_a = addresses(cos_u), addresses(sin_u), addresses(centre_y)
    one, two = flint.arb(1), flint.arb(2)
    prec = flint.ctx.prec
    constants = (id(h) + OFFSET, id(d) + OFFSET, id(one) + OFFSET, id(two) + OFFSET, lo)
    with Scratch(12) as scratch:
        for step, start, end in ((1, 1, hi + 1), (-1, 0, lo)):  # forwards, then backwards
            while (end - start) * step > 0:
                if not start % CLOCK_STEPS:  # where the Python loop reads it
                    clock()
                # to the next multiple of CLOCK_STEPS in the direction of the loop, or its end
                stop = step * (abs(start) // CLOCK_STEPS + 1) * CLOCK_STEPS
                stop = min(stop, end) if step > 0 else max(stop, end)
                _sticks(cos_a, sin_a, centre_a, *constants, start, stop, prec, scratch)
                start = stop
    return cos_u, sin_u, centre_y


def stick_points(
    h: Any,
    d: Any,
    i_min: int,
    cos_u: np.ndarray[Any, Any],
    sin_u: np.ndarray[Any, Any],
    centre_y: np.ndarray[Any, Any],
) -> dict[str, np.ndarray[Any, Any]]:
    """``construction._assemble``'s four ``(n, 2)`` arrays of sticks i_min … from the balls of
    ``sticks`` (directions and centre heights: the same objects), the new ones made in one
    compiled pass (``_points``: the same balls as its numpy operations); each read-only with
    its addresses kept (``keep``)."""
    n = len(cos_u)
    axis_x, tractrix_x, tractrix_y, centre_x = (fresh(n) for _ in range(4))
    zero = flint.arb(0)
    constants = [h, d, 2 * d, flint.arb(2), flint.arb(1), zero]
    with Scratch(2) as scratch:
        _points(
            addresses(cos_u),
            addresses(sin_u),
            i_min,
            np.array([id(c) + OFFSET for c in constants], dtype=np.int64),
            addresses(axis_x),
            addresses(tractrix_x),
            addresses(tractrix_y),
            addresses(centre_x),
            flint.ctx.prec,
            scratch,
        )
    del constants
    zeros = np.full(n, zero, dtype=object)
    pairs = {
        "axis_points": (axis_x, zeros),
        "tractrix": (tractrix_x, tractrix_y),
        "centres": (centre_x, centre_y),
        "directions": (cos_u, sin_u),
    }
    out = {}
    for name, (x, y) in pairs.items():
        both = np.empty((n, 2), dtype=object)
        both[:, 0], both[:, 1] = x, y
        out[name] = keep(both, checked=True)
    return out


_ZERO = flint.arb(0)


def _warm() -> None:
    """Compile every loop now, at import (about a second), so that no request pays for it."""
    x = np.empty(2, dtype=object)
    x[:] = [flint.arb(1) / 3, flint.arb(-2)]
    points = np.empty((2, 2), dtype=object)
    points[:, 0], points[:, 1] = x, x[::-1]
    argmax_abs(x, True)
    largest_radii(x, x[::-1])
    hypot(x, x[::-1])
    relative_point_difference(points, points[::-1], flint.arb(1), 64)
    cos_u, sin_u, centre_y = sticks(
        flint.arb(1), flint.arb(1) / 10, flint.arb(0), flint.arb(1), -2, 2, lambda: None
    )
    stick_points(flint.arb(1), flint.arb(1) / 10, -2, cos_u, sin_u, centre_y)


if AVAILABLE:
    _warm()
