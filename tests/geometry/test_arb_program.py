"""Straight-line ball programs: the numpy operators' balls, the type check, the guards."""

from __future__ import annotations

import random

import flint
import numpy as np
import pytest
from mpmath.libmp import from_man_exp, to_str

from app.geometry import arb_loops, arb_program as ap, ball_arithmetic, balls

pytestmark = pytest.mark.skipif(not ap.AVAILABLE, reason="no bundled libflint")


def _column(values: list[object]) -> np.ndarray:
    out = np.empty(len(values), dtype=object)
    out[:] = values
    return out


def test_the_type_check_reads_every_kind_of_entry() -> None:
    ball = flint.arb(1) / 3
    assert ap.all_balls(arb_loops.addresses(_column([ball, ball + 1])))
    for other in (None, 1, 1.5, "x", flint.fmpz(2), np.float64(2.0), [ball]):
        assert not ap.all_balls(arb_loops.addresses(_column([ball, other])))


def test_the_balls_type_check_agrees_with_the_entry_by_entry_one() -> None:
    """``ball_arithmetic.all_balls`` (the compiled type check the reductions and the certificate
    use) answers as ``arb_loops.all_balls`` on 1-d, 2-d, strided and empty arrays."""
    ball = flint.arb(1) / 3
    plain = _column([ball, ball + 1, ball * 2, ball - 5])
    cases = [plain, plain.reshape(2, 2), plain.reshape(2, 2)[:, 1], plain[:0], plain[::2]]
    for other in (None, 1.5, flint.fmpz(2)):
        mixed = plain.copy()
        mixed[3] = other
        cases += [mixed, mixed.reshape(2, 2), mixed.reshape(2, 2)[:, 1], mixed.reshape(2, 2)[:, 0]]
    for values in cases:
        assert ball_arithmetic.all_balls(values) == arb_loops.all_balls(values)


def test_a_program_is_the_operators() -> None:
    with balls.working_precision(100):
        x = _column([flint.arb(k) / 7 - 3 for k in range(50)])
        y = _column([flint.arb(k) / 3 + flint.arb(0, 1e-20) for k in range(50)])
        program = ap.Program(["x", "y"], ["tiny"], ["out", "flag"])
        program.op(ap.MUL, "p", "x", "y")
        program.op(ap.NEG, "n", "p")
        program.op(ap.ABS, "a", "n")
        program.op(ap.SQRT, "r", "a")
        program.op(ap.GT, "r", "r", "tiny")
        program.op(ap.CHOOSE, "flag", "r", "tiny")
        program.op(ap.DIV, "out", "x", "flag", low=True)
        done = ap.run(program, {"x": x, "y": y}, {"tiny": flint.arb(1) / 1000}, low=30)
        assert done is not None and done[1] == -1
        out, flag = done[0]
        for k in range(50):
            root = abs(-(x[k] * y[k])).sqrt()
            chosen = root if root > flint.arb(1) / 1000 else flint.arb(1) / 1000
            with balls.working_precision(30):
                want = x[k] / chosen
            for got, expected in ((flag[k], chosen), (out[k], want)):
                assert got.mid().man_exp() == expected.mid().man_exp()
                assert got.rad().man_exp() == expected.rad().man_exp()


def test_guards() -> None:
    program = ap.Program(["x"], [], ["y"])
    with pytest.raises(NameError):
        program.op(ap.ADD, "y", "x", "z")  # z is never written
    with pytest.raises(NameError):
        program.op(ap.SET, "x", "y")  # inputs are read-only
    with pytest.raises(TypeError):
        program.op(ap.SQRT, "y", "x", "x")
    program.op(ap.REQUIRE_GT, "y", "x", "x")
    x = _column([flint.arb(1), flint.arb(2)])
    assert ap.run(program, {"x": x}, {}) is not None
    assert ap.run(program, {"x": x}, {})[1] == 0  # x > x never holds: stopped at row 0
    assert ap.run(program, {"x": _column([flint.arb(1), 2])}, {}) is None
    assert ap.run(program, {"x": _column([])}, {}) is None


def _mpmath_text(value: flint.arb, digits: int) -> str:
    mantissa, exponent = value.mid().man_exp()
    return to_str(from_man_exp(int(mantissa), int(exponent)), digits)


def test_the_decimals_are_mpmaths() -> None:
    """A response's decimals (``Ball.to_strings``, flint integers) are mpmath's ``to_str`` of
    the midpoints: magnitudes from 10^-1100 to 10^1100 (the far ones through mpmath itself),
    both signs, exact decimal ties (to the even digit, and up past it), runs of nines that
    carry into a new digit, dyadic values with few bits, and 1 to 120 digits."""
    rng = random.Random(15)
    values = [flint.arb(0), flint.arb(1), flint.arb(-1), flint.arb(0.5), flint.arb(2) ** -1]
    for k in range(1, 40):
        values += [flint.arb(k) / 8, flint.arb(2 * k + 1) / 2**k, flint.arb(10) ** k / 2]
        values += [flint.arb(10) ** -k * 5, 1 - flint.arb(2) ** (-3 * k)]
    with balls.working_precision(400):
        for _ in range(600):
            mantissa = rng.getrandbits(rng.choice((1, 3, 20, 53, 170, 400))) | 1
            exponent = rng.choice((rng.randint(-60, 60), rng.randint(-3700, 3700)))
            value = flint.arb(flint.fmpz(mantissa)) * flint.arb(2) ** exponent
            values.append(value if rng.random() < 0.5 else -value)
        for digits in (1, 2, 3, 5, 15, 17, 50, 51, 120):
            ar = ball_arithmetic.Ball(digits)
            column = _column(values)
            expected = [_mpmath_text(v, digits) for v in values]
            assert ar.to_strings(column) == expected


def test_a_reduced_output_keeps_the_bounds_a_check_reads() -> None:
    """``reduce``: per reduced output the balls of the largest |v| upper and lower bounds, so
    the check's residual (largest upper) and the erratum's (largest lower) are the column's;
    an unbounded ball gives every row's balls again (the checks count the unbounded ones)."""
    ar = ball_arithmetic.Ball(30)
    rng = random.Random(7)
    with balls.working_precision(ar.bits):
        values = [flint.arb(rng.uniform(-5, 5), rng.uniform(0, 2)) for _ in range(200)]
        x = _column(values)
        program = ap.Program(["x"], ["one"], ["square", "shifted"])
        program.op(ap.MUL, "square", "x", "x")
        program.op(ap.SUB, "shifted", "x", "one")
        one = flint.arb(1)
        full = ap.run(program, {"x": x}, {"one": one})
        reduced = ap.run(program, {"x": x}, {"one": one}, reduce=["shifted"])
        assert full is not None and reduced is not None
        assert len(reduced[0][1]) == 2
        for want, got in ((full[0][0], reduced[0][0]), (full[0][1], reduced[0][1])):
            for bound in (ar.largest_upper, ar.largest_lower):
                assert bound(got).mid().man_exp() == bound(want).mid().man_exp()
        x[17] = flint.arb(0, float("inf"))
        unbounded = ap.run(program, {"x": x}, {"one": one}, reduce=["shifted", "square"])
        assert unbounded is not None and [len(out) for out in unbounded[0]] == [200, 200]
