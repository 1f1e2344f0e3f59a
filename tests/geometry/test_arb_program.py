"""Straight-line ball programs: the numpy operators' balls, the type check, the guards."""

from __future__ import annotations

import flint
import numpy as np
import pytest

from app.geometry import arb_loops, arb_program as ap, balls

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
