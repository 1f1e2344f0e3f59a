"""(D4b)'s construction on balls in one compiled loop (``arb_loops.sticks``) makes the Python
loop's balls, bit for bit, and still reads the clock along a long range."""

from __future__ import annotations

from typing import Any

import flint
import pytest

from app.geometry import arb_loops, balls
from app.geometry.ball_arithmetic import Ball
from app.geometry.d4b import construction
from app.geometry.errors import TimeLimitError
from app.geometry.exact import ExactReal
from app.geometry.precision import MultiPrecision

pytestmark = pytest.mark.skipif(not arb_loops.AVAILABLE, reason="no bundled libflint")

NAMES = ("axis_points", "tractrix", "centres", "directions")


def _key(ball: Any) -> tuple[Any, ...]:
    """A ball exactly: its midpoint and radius as (mantissa, exponent)."""
    return tuple(
        part.man_exp() if part.is_finite() else str(part) for part in (ball.mid(), ball.rad())
    )


def _keys(polygon: construction.KinematicTractrix) -> dict[str, list[Any]]:
    return {name: [_key(b) for b in getattr(polygon, name).reshape(-1)] for name in NAMES}


def _both(
    monkeypatch: pytest.MonkeyPatch,
    digits: int,
    h: str,
    d: str,
    beta0: float | None,
    i_min: int,
    i_max: int,
    extra: int = 6,
) -> tuple[dict[str, list[Any]], dict[str, list[Any]]]:
    """Every ball of the compiled loop's construction and of the Python loop's."""
    ar = Ball(digits, extra, recursions_only=True)
    calls: list[int] = []
    sticks = arb_loops.sticks
    monkeypatch.setattr(
        arb_loops,
        "sticks",
        lambda *a: calls.append(1) or sticks(*a),  # type: ignore[func-returns-value]
    )
    with balls.working_precision(ar.bits), ar.recursion():
        arguments = (ExactReal(h), ExactReal(d), beta0, i_min, i_max)
        compiled = _keys(construction.construct(ar, *arguments))
        assert calls == [1]
        with monkeypatch.context() as patch:
            patch.setattr(arb_loops, "AVAILABLE", False)
            python = _keys(construction.construct(ar, *arguments))
    return compiled, python


@pytest.mark.parametrize("digits", [15, 50, 500])
@pytest.mark.parametrize(
    ("i_min", "i_max"),
    [(-40, 39), (1, 60), (5, 9), (-60, -3), (-7, 0), (0, 0), (0, 25)],
)
def test_the_compiled_loop_makes_the_python_loops_balls(
    monkeypatch: pytest.MonkeyPatch, digits: int, i_min: int, i_max: int
) -> None:
    compiled, python = _both(monkeypatch, digits, "1", "0.1", None, i_min, i_max)
    assert compiled == python
    assert len(compiled["centres"]) == 2 * (i_max - i_min + 1)


@pytest.mark.parametrize("digits", [15, 50, 500])
@pytest.mark.parametrize(("h", "d", "beta0"), [("2", "0.7", 1.0), ("1", "0.05", 2.5)])
def test_a_given_start_and_other_sticks(
    monkeypatch: pytest.MonkeyPatch, digits: int, h: str, d: str, beta0: float
) -> None:
    compiled, python = _both(monkeypatch, digits, h, d, beta0, -30, 30)
    assert compiled == python
    # the balls are those of the recursion, not of an exact start: they carry radii
    assert any(key[1][0] != 0 for key in compiled["directions"])


def test_the_clock_is_read_where_the_python_loop_reads_it(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """With 4 sticks a chunk: read before sticks 4, 8 forwards and 0, −4, −8 backwards; the
    chunks make the same balls as one pass."""
    readings: list[int] = []
    monkeypatch.setattr(arb_loops, "CLOCK_STEPS", 4)
    with balls.working_precision(200):
        h, d = flint.arb(1), flint.arb(1) / 10
        chunked = arb_loops.sticks(
            h, d, flint.arb(0), flint.arb(1), -9, 10, lambda: readings.append(1)
        )
        assert len(readings) == 5
        monkeypatch.setattr(arb_loops, "CLOCK_STEPS", 4096)
        whole = arb_loops.sticks(h, d, flint.arb(0), flint.arb(1), -9, 10, lambda: None)
    for a, b in zip(chunked, whole, strict=True):
        assert [_key(x) for x in a] == [_key(x) for x in b]
    # stick 0's direction is the start; p_0 is computed (the backward loop starts there)
    assert _key(whole[0][9]) == _key(flint.arb(0)) and _key(whole[1][9]) == _key(flint.arb(1))
    assert not whole[2][9].is_zero()


def test_a_long_range_stops_at_the_time_limit(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(arb_loops, "CLOCK_STEPS", 16)
    ar = Ball(15, 6, recursions_only=True)
    ar.start_clock(-1.0, "i_max")  # already over
    with balls.working_precision(ar.bits), ar.recursion(), pytest.raises(TimeLimitError):
        construction.construct(ar, ExactReal("1"), ExactReal("0.1"), None, -100, 100)


def test_mpmath_numbers_keep_the_python_loop(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(arb_loops, "sticks", None)  # not called
    ar = MultiPrecision(30)
    polygon = construction.construct(ar, 1.0, 0.1, None, -5, 5)
    assert all(type(x).__name__ == "mpf" for x in polygon.centres[:, 1])
    assert all(y > 0 for y in polygon.centres[:, 1])
