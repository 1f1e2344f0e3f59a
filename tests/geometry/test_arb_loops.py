"""The compiled reductions over balls give what python-flint's own reductions give."""

from __future__ import annotations

import random

import flint
import numpy as np
import pytest

from app.geometry import arb_loops, balls, checks
from app.geometry.ball_arithmetic import Ball

pytestmark = pytest.mark.skipif(not arb_loops.AVAILABLE, reason="no bundled libflint")


def _balls(count: int, seed: int) -> np.ndarray:
    rng = random.Random(seed)
    out = np.empty(count, dtype=object)
    out[:] = [
        flint.arb(rng.uniform(-5, 5)) / 3
        + flint.arb(0, rng.random() * 10.0 ** rng.randint(-60, -1))
        for _ in range(count)
    ]
    return out


@pytest.mark.parametrize("bits", [64, 200, 1700])
def test_the_largest_bounds_are_pythons(bits: int) -> None:
    with balls.working_precision(bits):
        values = _balls(3000, bits)
        values[17] = flint.arb(0)  # an exact zero among them
        k = arb_loops.argmax_abs(values, True)
        assert values[k].abs_upper() == max(v.abs_upper() for v in values)
        k = arb_loops.argmax_abs(values, False)
        assert values[k].abs_lower() == max(v.abs_lower() for v in values)
        ar = Ball(bits // 4)
        assert ar.largest_upper(values) == max(v.abs_upper() for v in values)
        assert ar.largest_lower(values) == max(v.abs_lower() for v in values)


def test_empty_and_unbounded_arrays_fall_back() -> None:
    assert arb_loops.argmax_abs(np.empty(0, dtype=object), True) == -1
    values = _balls(10, 1)
    values[3] = flint.arb("nan")
    assert arb_loops.argmax_abs(values, True) == -2
    values[3] = flint.arb("inf")
    assert arb_loops.argmax_abs(values, True) == -2
    ar = Ball(20)
    assert not ar.largest_upper(values).is_finite()  # Python's max decides


def test_other_entries_are_not_read() -> None:
    values = _balls(5, 2)
    assert arb_loops.all_balls(values)
    values[1] = 3
    assert not arb_loops.all_balls(values)  # the compiled loops leave such arrays alone


def test_the_largest_radii_are_the_points() -> None:
    with balls.working_precision(200):
        x, y = _balls(2000, 3), _balls(2000, 4)
        x[5], y[5] = flint.arb(0, 1e-30), flint.arb(0, 1e-31)  # reaches 0
        x[6], y[6] = flint.arb(2), flint.arb(3)  # exact
        largest, relative, reaches_zero, unbounded = arb_loops.largest_radii(x, y)
        radii = [a.rad().max(b.rad()) for a, b in zip(x, y, strict=True)]
        assert radii[largest] == max(radii)
        quotients = [
            (r / a.abs_lower().max(b.abs_lower())).upper()
            for r, a, b in zip(radii, x, y, strict=True)
            if not r.is_zero() and a.abs_lower().max(b.abs_lower()) > 0
        ]
        size = x[relative].abs_lower().max(y[relative].abs_lower())
        assert (radii[relative] / size).upper() == max(quotients)
        assert reaches_zero and not unbounded


def test_relative_point_differences_are_the_same_balls() -> None:
    rng = random.Random(5)
    ar = Ball(50)

    def points(count: int) -> np.ndarray:
        out = np.empty((count, 2), dtype=object)
        for k in range(count):
            out[k, 0] = flint.arb(rng.uniform(-3, 3)) / 7 + flint.arb(0, 1e-50)
            out[k, 1] = flint.arb(rng.uniform(-3, 3)) / 3
        return out

    with balls.working_precision(ar.bits):
        computed, expected = points(300), points(300)
        expected[3] = [flint.arb(0), flint.arb(0)]  # the floor tiny
        computed[4] = expected[4]  # a difference of the same balls
        both = np.concatenate([computed, expected])
        for c, e in ((computed, expected), (both[::2], both[1::2])):  # strided too
            fast = checks.relative_point_difference(ar, c, e)
            saved = arb_loops.AVAILABLE
            arb_loops.AVAILABLE = False
            try:
                slow = checks.relative_point_difference(ar, c, e)
            finally:
                arb_loops.AVAILABLE = saved
            assert all(
                a.mid() == b.mid() and a.rad() == b.rad() for a, b in zip(fast, slow, strict=True)
            )
            assert len({id(v) for v in fast}) == len(fast)  # fresh balls, one each


def test_hypot_gives_the_same_balls() -> None:
    ar = Ball(30)
    with balls.working_precision(ar.bits):
        x, y = _balls(500, 7), _balls(500, 8)
        x[2], y[2] = flint.arb(0, 1e-20), flint.arb(0, 1e-21)  # the sum reaches below 0
        fast = ar.hypot(x, y)
        slow = [(a * a + b * b).nonnegative_part().sqrt() for a, b in zip(x, y, strict=True)]
        assert all(
            a.mid() == b.mid() and a.rad() == b.rad() for a, b in zip(fast, slow, strict=True)
        )


@pytest.mark.skipif(not arb_loops.AVAILABLE, reason="python-flint's layout is not the known one")
def test_bind_types_another_libflint_function_for_other_modules() -> None:
    """``bind`` hands out one more libflint function from the same handle: here arb_neg on
    scratch balls gives −x, and a missing name gives None instead of an error."""
    import ctypes

    negate = arb_loops.bind("arb_neg", None, [ctypes.c_void_p, ctypes.c_void_p])
    assert negate is not None
    assert arb_loops.bind("arb_no_such_function", None, []) is None
    ball = flint.arb("0.75")
    result = -flint.arb(0)  # a fresh ball nothing else references
    negate(id(result) + arb_loops.OFFSET, id(ball) + arb_loops.OFFSET)
    assert result == -ball


_LOADED = """
import json
import numba
from app.geometry import arb_loops, arb_program
from app.geometry.d4b import arb_checks

loops = {
    f"{module.__name__}.{name}": value
    for module in (arb_loops, arb_program, arb_checks)
    for name, value in vars(module).items()
    if isinstance(value, numba.core.registry.CPUDispatcher)
}
print(json.dumps({
    name: [sum(d.stats.cache_hits.values()), sum(d.stats.cache_misses.values())]
    for name, d in loops.items()
}))
"""


@pytest.mark.skipif(not arb_loops.AVAILABLE, reason="no bundled libflint")
def test_every_ball_loop_loads_from_numbas_cache() -> None:
    """The ball loops call libflint by symbol name, so numba caches them: a second process
    loads every loop its import runs from the cache (the first fills it if it was stale) and
    compiles none."""
    import json
    import subprocess
    import sys

    for _ in range(2):
        done = subprocess.run(
            [sys.executable, "-c", _LOADED], capture_output=True, text=True, check=True
        )
    counts = json.loads(done.stdout)
    loaded = {name for name, (hits, _) in counts.items() if hits}
    assert {"app.geometry.arb_program._run", "app.geometry.d4b.arb_checks._two_step"} <= loaded
    assert "app.geometry.arb_loops._relative_point_difference" in loaded
    assert len(loaded) >= 15  # the outer loops (helpers compile into them)
    assert {name: misses for name, (_, misses) in counts.items() if misses} == {}


def test_extern_declines_what_it_cannot_type() -> None:
    """``extern`` gives None for a missing function and for a type it has no match for (the
    callers then keep their Python code), a numba external function otherwise."""
    import ctypes

    import numba

    assert arb_loops.extern("arb_no_such_function", None, []) is None
    assert arb_loops.extern("arb_neg", None, [ctypes.c_void_p, ctypes.c_float]) is None
    negate = arb_loops.extern("arb_neg", None, [ctypes.c_void_p, ctypes.c_void_p])
    assert isinstance(negate, numba.types.ExternalFunction)

    @numba.njit
    def negated(out: int, x: int) -> None:
        negate(out, x)

    ball = flint.arb("0.75")
    result = -flint.arb(0)  # a fresh ball nothing else references
    negated(id(result) + arb_loops.OFFSET, id(ball) + arb_loops.OFFSET)
    assert result == -ball


def test_a_cache_that_cannot_be_written_leaves_the_loop_in_memory(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A read-only cache that lacks a loop: saving it fails, and the loop still runs."""
    from numba.core import caching

    def refuse(*_: object) -> None:
        raise PermissionError("read-only")

    monkeypatch.setattr(caching.Cache, "_save_overload", refuse)

    def doubled(x: int) -> int:
        return 2 * x

    compiled = arb_loops.loop(doubled)
    assert compiled(21) == 42


def test_kept_arrays_are_read_only_and_their_views_addresses_are_read_ones() -> None:
    points = np.empty((7, 2), dtype=object)
    points[:] = [[flint.arb(k) / 3, flint.arb(-k)] for k in range(7)]
    kept = arb_loops.keep(points)
    assert kept is points and not kept.flags.writeable
    with pytest.raises(ValueError, match="read-only"):
        kept[0, 0] = flint.arb(1)
    views = (kept, kept[:5], kept[2:6], kept[:, 0], kept[:, 1], kept[1:, 1], kept[::2], kept.T)
    for view in views:
        assert arb_loops.known_balls(view)
        found = arb_loops.addresses(view)
        assert found.flags.c_contiguous
        assert found.tolist() == arb_loops._read_addresses(view).tolist()
    assert not arb_loops.known_balls(kept[::-1])  # read as before
    assert not arb_loops.known_balls(kept.copy())
    key = id(kept)
    del kept, points, views, view
    assert key not in arb_loops._KNOWN  # forgotten with its array


def test_only_owning_arrays_of_balls_are_kept() -> None:
    mixed = np.array([flint.arb(1), 2.0], dtype=object)
    assert arb_loops.keep(mixed).flags.writeable and not arb_loops.known_balls(mixed)
    balls_ = np.array([flint.arb(1), flint.arb(2), flint.arb(3)], dtype=object)
    view = balls_[1:]
    assert arb_loops.keep(view).flags.writeable  # not the owner: left as it is
    fresh = arb_loops.fresh(3)
    assert not fresh.flags.writeable and all(b == 0 for b in fresh)
