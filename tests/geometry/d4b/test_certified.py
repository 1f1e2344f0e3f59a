"""The ball prototype of (D4b): certified against the independent 60-digit reference."""

from __future__ import annotations

import mpmath
import pytest

from app.geometry.d4b import certified
from app.geometry.precision import Ball, ExactReal
from tests.reference import d4b as reference

D = "0.12345678901234567890123"


def test_balls_contain_the_reference_and_every_statement_is_proved() -> None:
    result = certified.certify(40, 1.0, ExactReal(D), None, -20, 20)
    centres, _, _ = reference.construct("1", D, None, -20, 20, dps=60)
    ctx = mpmath.MPContext()
    ctx.dps = 60
    for k, i in enumerate(result.indices):
        for j in (0, 1):
            ball = result.p[k, j]
            exact = ball.__class__(mpmath.nstr(centres[int(i)][j], 60), "1e-50")  # 60 digits
            assert ball.overlaps(exact)
            midpoint = ctx.mpf(result.coordinates(result.p[k : k + 1])[0][j])
            assert abs(midpoint - centres[int(i)][j]) < 1e-35 * max(1, abs(centres[int(i)][j]))
    assert result.radius < 1e-35
    verdicts = {v.id: v for v in result.verdicts}
    for statement in set(verdicts) - {"E3"}:
        assert verdicts[statement].holds is True, statement
        assert verdicts[statement].residual <= verdicts[statement].tolerance
    assert verdicts["E3"].certified_false is True
    assert verdicts["E3"].holds is False
    assert verdicts["E3"].residual > verdicts["E3"].tolerance


@pytest.mark.parametrize("beta0", [3.16e-9, 1.2, 3.1415925])
def test_certified_near_the_axis(beta0: float) -> None:
    verdicts = {v.id: v for v in certified.certify(30, 1.0, 0.05, beta0, -30, 30).verdicts}
    assert all(v.holds is True for v in verdicts.values() if v.id != "E3")
    assert len(verdicts) == 10


def test_a_wrong_value_is_not_proved_and_a_zero_is_undecided() -> None:
    ar = Ball(30)
    wrong = ar.array(["1e-20"])
    assert certified._statement("x", wrong, ar.scalar("1e-28")).holds is False
    undecided = ar.array([ar.scalar(1) / 3 - ar.scalar(1) / 3])
    printed = certified._printed("E", undecided, ar.scalar("1e-28"))
    assert printed.holds is None and printed.certified_false is False


def test_long_ranges_raise_the_precision() -> None:
    short = certified.certify(30, 1.0, 0.1, None, -5, 5)
    long = certified.certify(30, 1.0, 0.1, None, -400, 400)
    assert long.extra_digits > short.extra_digits
    assert all(v.holds is True for v in long.verdicts if v.id != "E3")
