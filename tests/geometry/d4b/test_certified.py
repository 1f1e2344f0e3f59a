"""(D4b) precision=mp on rigorous balls (issue 15), against the independent 60-digit reference."""

from __future__ import annotations

import math
import threading
from decimal import Decimal
from typing import Any

import flint
import mpmath
import numpy as np
import pytest

from app.geometry import balls
from app.geometry.ball_arithmetic import Ball
from app.geometry.checks import check_residuals, printed_residual
from app.geometry.curve import NOTHING, Curve
from app.geometry.d4b import certified, discretization as d4b
from app.geometry.d4b.discretization import STATEMENTS
from app.geometry.precision import ExactReal, Float64, MultiPrecision
from tests.reference import d4b as reference

D = "0.12345678901234567890123"


def _served(digits: int, **arguments: Any) -> Curve:
    arguments = {"h": 1.0, "d": 0.1, "beta0": None, "i_min": -10, "i_max": 10, **arguments}
    return balls.serve(
        "d4b", MultiPrecision(digits), lambda ar: d4b.compute(ar, **arguments), arguments
    )


def test_balls_contain_the_reference_and_every_statement_is_proved() -> None:
    curve = _served(40, d=ExactReal(D), i_min=-20, i_max=20)
    ar = curve.arithmetic
    assert isinstance(ar, Ball)
    centres, _, _ = reference.construct("1", D, None, -20, 20, dps=60)
    ctx = mpmath.MPContext()
    ctx.dps = 60
    shown = [ar.to_strings(curve.polygon.vertices[:, j]) for j in (0, 1)]
    for k, i in enumerate(curve.polygon.indices):
        for j in (0, 1):
            exact = centres[int(i)][j]
            ball = curve.polygon.vertices[k, j]
            assert ball.overlaps(flint.arb(mpmath.nstr(exact, 60), "1e-50"))
            assert abs(ctx.mpf(shown[j][k]) - exact) < 1e-35 * max(1, abs(exact))
    certificate = balls.certificate(ar)
    assert certificate is not None and certificate.resolved and float(certificate.radius) < 1e-35
    assert float(certificate.relative_radius) < 1e-41
    assert len(curve.checks) == len(STATEMENTS) == 21
    for check in curve.checks:
        assert check.holds is True, check.id
        assert check.residual is not None and check.residual <= check.tolerance
        if check.erratum is not None and check.erratum.printed_residual is not None:
            assert check.erratum.printed_residual > check.tolerance  # certified false


@pytest.mark.parametrize("beta0", [3.16e-9, 1.2, 3.1415925])
def test_every_statement_is_proved_near_the_axis(beta0: float) -> None:
    curve = _served(30, d=0.05, beta0=beta0, i_min=-30, i_max=30)
    assert all(check.holds is True for check in curve.checks)


def test_the_served_answer_agrees_with_mpmath() -> None:
    on_balls = _served(30, i_min=-40, i_max=40)
    on_mpmath = d4b.compute(MultiPrecision(30), 1.0, 0.1, None, -40, 40)
    a = on_balls.arithmetic.to_strings(on_balls.polygon.vertices.reshape(-1))
    b = on_mpmath.arithmetic.to_strings(on_mpmath.polygon.vertices.reshape(-1))  # type: ignore[attr-defined]
    ctx = mpmath.MPContext()
    ctx.dps = 40
    for x, y in zip(a, b, strict=True):
        assert abs(ctx.mpf(x) - ctx.mpf(y)) <= 1e-28 * max(1, abs(ctx.mpf(y)))
    verdicts = {c.id: c.holds for c in on_mpmath.checks}
    assert {c.id: c.holds for c in on_balls.checks} == verdicts


def test_long_ranges_raise_the_precision() -> None:
    short = balls.certificate(_served(30, i_min=-5, i_max=5).arithmetic)
    long = balls.certificate(_served(30, i_min=-300, i_max=300).arithmetic)
    assert short is not None and long is not None
    assert long.working_digits > short.working_digits + 40  # 300 sticks lose about 48 digits
    assert long.resolved and short.resolved


def test_a_short_estimate_is_raised_until_resolved(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(balls.EXTRA_DIGITS, "d4b", lambda arguments: 0)
    certificate = balls.certificate(_served(30, i_min=-200, i_max=200).arithmetic)
    assert certificate is not None and certificate.resolved
    assert certificate.working_digits >= 30 + certified.extra_digits_needed(1, 0.1, -200, 200) / 2


def test_bounds_decide_only_what_they_prove() -> None:
    ar = Ball(30)
    statement = STATEMENTS[0]
    indices = np.arange(1, dtype=np.int64)
    with balls.working_precision(ar.bits):
        tolerance = 1e-28
        above = ar.array([flint.arb("1e-20")])
        assert check_residuals(statement, ar, indices, above, tolerance, False).holds is False
        below = ar.array([flint.arb("1e-40")])
        assert check_residuals(statement, ar, indices, below, tolerance, False).holds is True
        straddling = ar.array([flint.arb("1e-28", "1e-29")])
        undecided = check_residuals(statement, ar, indices, straddling, tolerance, False)
        assert undecided.holds is None and undecided.note is not None
        assert "undecided" in undecided.note
        assert undecided.residual is not None and undecided.residual >= 1.1e-28
        zero = ar.array([ar.scalar(1) / 3 - ar.scalar(1) / 3])  # a ball around 0
        assert printed_residual(ar, zero) == 0.0
        assert ar.to_floats(zero)[0] > 0  # an upper bound, not the midpoint 0
        a, b = ar.array([flint.arb(1, 1e-10)]), ar.array([flint.arb(1 + 1e-11, 1e-10)])
        largest = ar.maximum(a, b)[0]
        assert largest.upper() >= a[0].upper() and largest.upper() >= b[0].upper()


def test_the_working_precision_is_restored_and_not_shared() -> None:
    before = flint.ctx.prec
    results: dict[int, list[str]] = {}

    def run(digits: int) -> None:
        curve = _served(digits, i_min=-60, i_max=60)
        results[digits] = curve.arithmetic.to_strings(curve.polygon.vertices[:, 1])

    threads = [threading.Thread(target=run, args=(n,)) for n in (20, 80, 20, 80)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert flint.ctx.prec == before
    for digits in (20, 80):
        alone = _served(digits, i_min=-60, i_max=60)
        assert results[digits] == alone.arithmetic.to_strings(alone.polygon.vertices[:, 1])


def test_float64_and_ids_not_on_balls_are_untouched() -> None:
    calls: list[object] = []

    def compute(ar: Any) -> Any:
        calls.append(ar)
        return "curve"

    assert balls.serve("d4b", Float64(), compute, {}) == "curve"
    assert isinstance(calls[-1], Float64)
    assert balls.serve("not-on-balls", MultiPrecision(30), compute, {}) == "curve"
    assert isinstance(calls[-1], MultiPrecision)


def test_the_extra_digits_are_carried_in_the_construction_only() -> None:
    seen: list[tuple[int, int]] = []
    construct = d4b.construct

    def recording(ar: Any, *arguments: Any) -> Any:
        seen.append((flint.ctx.prec, ar.bits))
        return construct(ar, *arguments)

    arguments: dict[str, Any] = {"h": 1.0, "d": 0.1, "beta0": None, "i_min": -100, "i_max": 100}
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(d4b, "construct", recording)
        curve = balls.serve(
            "d4b", MultiPrecision(40), lambda ar: d4b.compute(ar, **arguments), arguments
        )
    ar = curve.arithmetic
    assert isinstance(ar, Ball) and ar.recursions_only
    assert ar.bits == math.ceil(50 * math.log2(10)) < ar.recursion_bits
    assert seen == [(ar.recursion_bits, ar.bits)]  # once, with the extra digits
    certificate = balls.certificate(ar)
    assert certificate is not None and certificate.resolved
    assert certificate.working_digits == 50 + certified.extra_digits(arguments)  # no raise
    assert all(check.holds is True for check in curve.checks)


def test_a_check_undecided_without_the_extra_digits_is_computed_again_with_them() -> None:
    seen: list[bool] = []
    arguments: dict[str, Any] = {"h": 1.0, "d": 0.1, "beta0": None, "i_min": -5, "i_max": 5}

    def compute(ar: Any) -> Curve:
        seen.append(ar.recursions_only)
        if ar.recursions_only:
            ar.undecided += 1  # as check_residuals counts a check it cannot decide
        return d4b.compute(ar, **arguments)

    curve = balls.serve("d4b", MultiPrecision(30), compute, arguments)
    assert seen == [True, False]
    ar = curve.arithmetic
    assert isinstance(ar, Ball) and ar.bits == ar.recursion_bits


def test_a_tolerance_below_the_float_range_still_decides() -> None:
    # 400 digits: 64·10^-400 is 0.0 as a float; the tolerance and the residual are compared as
    # decimals (a float tolerance left every check with a nonzero bound undecided)
    ar = Ball(400, 0, recursions_only=True)
    tolerance = ar.tolerance(1)
    with balls.working_precision(ar.bits):
        exact = ar.array([ar.scalar(1) / 3 - ar.scalar(1) / 3])
        tiny = ar.array([flint.arb("1e-420")])
        large = ar.array([flint.arb("1e-395")])
        wide = ar.array([flint.arb("1e-398", "1e-397")])  # holds 0 and 1.1e-397
        checks = [
            check_residuals(STATEMENTS[1], ar, np.arange(1), r, tolerance, False)
            for r in (exact, tiny, large, wide)
        ]
    assert [c.holds for c in checks] == [True, True, False, None]
    assert checks[0].tolerance == Decimal("6.4e-399") and checks[0].residual < Decimal("1e-400")
    assert Decimal("1e-420") <= checks[1].residual <= Decimal("1.000000001e-420")
    assert checks[2].residual >= Decimal("1e-395") and ar.undecided == 1
    assert "undecided" in (checks[3].note or "")


@pytest.mark.parametrize(
    ("h", "d", "i_min", "i_max", "beta0"),
    [(1.0, 0.9, -20, 20, None), (1.0, 0.01, -1500, 1500, None), (2.0, 0.3, -100, 300, 0.3)],
)
def test_the_extra_digits_estimate_is_not_short(
    h: float, d: float, i_min: int, i_max: int, beta0: float | None
) -> None:
    arguments: dict[str, Any] = {"h": h, "d": d, "beta0": beta0, "i_min": i_min, "i_max": i_max}
    curve = balls.serve(
        "d4b",
        MultiPrecision(20),
        lambda ar: d4b.compute(ar, **arguments, selection=NOTHING),
        arguments,
    )
    certificate = balls.certificate(curve.arithmetic)
    assert certificate is not None and certificate.resolved
    # resolved at the first attempt: the estimate was enough
    assert certificate.working_digits == 30 + certified.extra_digits(arguments)


def test_the_extra_digits_estimate() -> None:
    # per stick about log10((h + 3d)/(h − d)): 0.1597 digits for d = h/10
    needed = certified.extra_digits_needed(1, 0.1, -500, 499)
    assert needed == math.ceil(502 * math.log10(1.3 / 0.9)) + 2 == 83
    assert certified.extra_digits_needed(1, 0.1, -5, 5) == 4
    closed = {"h": 1.0, "d": 0.1, "i_min": 0, "i_max": 9, "method": "closed-form"}
    assert certified.extra_digits(closed) == 5
