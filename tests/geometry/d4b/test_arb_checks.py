"""The compiled residuals of (D4b)'s checks on balls are the numpy code's balls, bit for bit."""

from __future__ import annotations

import random
from typing import Any

import flint
import numpy as np
import pytest

from app.geometry import balls, conditions, darboux, nikolaides
from app.geometry.ball_arithmetic import Ball
from app.geometry.checks import point_distance, relative_difference, relative_to
from app.geometry.d4b import (
    arb_checks,
    certified,
    checks as d4b_checks,
    closed_forms,
    discretization,
)

pytestmark = pytest.mark.skipif(not arb_checks.AVAILABLE, reason="no bundled libflint")


def _exact(value: Any) -> Any:
    """An exact arb as (mantissa, exponent), or its text where it is not finite."""
    return value.man_exp() if value.is_finite() else str(value)


def _key(ball: Any) -> tuple[Any, ...]:
    return (_exact(ball.mid()), _exact(ball.rad()))


def _same(computed: np.ndarray, expected: np.ndarray) -> None:
    assert len(computed) == len(expected)
    assert [_key(b) for b in computed] == [_key(b) for b in expected]


def _polygons(digits: int, h: float, d: float, i_min: int, i_max: int) -> tuple[Ball, Any]:
    arguments = {"h": h, "d": d, "beta0": None, "i_min": i_min, "i_max": i_max}
    ar = Ball(digits, certified.extra_digits(arguments), recursions_only=True)
    return ar, discretization.polygons(ar, h, d, None, i_min, i_max)


def _perturbed(points: np.ndarray, seed: int, zero: bool = True) -> np.ndarray:
    """The points with a random radius on each coordinate (and an exact 0 among them), so the
    radii's arithmetic is exercised too."""
    rng = random.Random(seed)
    out = points.copy()
    flat = out.reshape(-1)
    for k in range(flat.size):
        flat[k] = flat[k] + flint.arb(0, rng.random() * 10.0 ** rng.randint(-40, -5))
    if zero:
        flat[3] = flint.arb(0)
    return out


CASES = [(30, 1.0, 0.1, -20, 19), (60, 1.0, 0.7, -8, 30), (25, 2.0, 0.05, 0, 40)]


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("perturb", [False, True])
def test_recursions_are_the_numpy_balls(case: tuple[Any, ...], perturb: bool) -> None:
    ar, data = _polygons(*case)
    with balls.working_precision(ar.bits):
        p = _perturbed(data.p, case[0]) if perturb else data.p
        y, d = p[:, 1], ar.scalar(case[2])
        tiny = ar.scalar(np.finfo(np.float64).tiny)
        expected = relative_difference(ar, y[2:], closed_forms.recursion_13(d, y[:-2], y[1:-1]))
        _same(arb_checks.recursion_13(d, y, tiny), expected)
        corrected, printed = arb_checks.two_step(d, y, tiny)
        a, b = y[:-3], y[1:-2]
        _same(corrected, relative_difference(ar, y[3:], closed_forms.two_step(d, a, b)))
        _same(printed, relative_difference(ar, y[3:], closed_forms.two_step_printed(d, a, b)))


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("perturb", [False, True])
def test_nikolaides_is_the_numpy_balls(case: tuple[Any, ...], perturb: bool) -> None:
    ar, data = _polygons(*case)
    with balls.working_precision(ar.bits):
        p, tractrix, axis = data.p, data.tractrix, data.axis
        if perturb:
            p, tractrix = _perturbed(p, 1), _perturbed(tractrix, 2, zero=False)
        n = data.vertices - 1
        at_p = nikolaides.right_angle_residuals(tractrix[:n], axis[:n], p[:n])
        at_next = nikolaides.right_angle_residuals(tractrix[:n], axis[:n], p[1 : n + 1])
        _same(arb_checks.nikolaides(tractrix, axis, p, n), ar.maximum(at_p, at_next))


def test_short_polygons_give_no_residuals() -> None:
    y = np.empty(2, dtype=object)
    y[:] = [flint.arb(1), flint.arb(2)]
    tiny = flint.arb(1) / 100
    assert len(arb_checks.recursion_13(flint.arb(1) / 10, y, tiny)) == 0
    corrected, printed = arb_checks.two_step(flint.arb(1) / 10, y, tiny)
    assert len(corrected) == len(printed) == 0


def test_other_entries_are_refused() -> None:
    values = np.empty(3, dtype=object)
    values[:] = [flint.arb(1), 2.0, flint.arb(3)]
    assert not arb_checks.balls(values)
    assert not arb_checks.balls(np.zeros(3))


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("perturb", [False, True])
def test_fits_are_the_numpy_balls(case: tuple[Any, ...], perturb: bool) -> None:
    ar, data = _polygons(*case)
    with balls.working_precision(ar.bits):
        p = _perturbed(data.p, 5) if perturb else data.p
        n = len(p) - 1
        tiny = ar.scalar(np.finfo(np.float64).tiny)
        columns = arb_checks.Columns(p, tiny)
        expected = {
            arb_checks.D1: conditions.d1(ar, p[:n]),
            arb_checks.D3: conditions.d3(ar, p[:n]),
            arb_checks.EQUATION_2: conditions.equation_2(ar, p[:n]),
        }
        for kind, fit in expected.items():
            constant, residuals = columns.fit(kind, n)
            _same(residuals, fit.residuals)
            assert fit.constant is not None and constant is not None
            _same(np.array([constant]), np.array([fit.constant]))
        c1, c3 = expected[arb_checks.D1].constant, expected[arb_checks.D3].constant
        assert c1 is not None and c3 is not None
        c = c1 / c3
        misfit = columns.misfit(arb_checks.EQUATION_2, n, c)
        _same(misfit, conditions.equation_2_misfit(ar, p[:n], c))
        y = p[:, 1]
        lengths = ar.hypot(p[1:, 0] - p[:-1, 0], y[1:] - y[:-1])
        ratio = (y[3:] - 2 * y[2:-1] + y[1:-2]) / (lengths[:-2] + lengths[1:-1])
        mean = np.full_like(ratio, np.sum(ratio) / len(ratio))
        spread = columns.ratio_spread()
        assert spread is not None
        _same(spread, relative_difference(ar, ratio, mean))


def test_fits_of_too_few_vertices() -> None:
    p = np.empty((3, 2), dtype=object)
    p[:, 0] = [flint.arb(k) for k in range(3)]
    p[:, 1] = [flint.arb(1), flint.arb(2), flint.arb(4)]
    columns = arb_checks.Columns(p, flint.arb(1) / 100)
    assert columns.ratio_spread() is None
    constant, residuals = columns.fit(arb_checks.D1, 2)
    assert constant is None and len(residuals) == 0
    constant, residuals = columns.fit(arb_checks.D3, 2)
    assert constant is not None and len(residuals) == 1


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("perturb", [False, True])
def test_rotation_angle_and_darboux_are_the_numpy_balls(
    case: tuple[Any, ...], perturb: bool
) -> None:
    ar, data = _polygons(*case)
    with balls.working_precision(ar.bits):
        p, axis, e = data.p, data.axis, data.darboux
        if perturb:
            p, axis, e = _perturbed(p, 7), _perturbed(axis, 8, zero=False), _perturbed(e, 9)
        n, d = data.vertices - 1, ar.scalar(case[2])
        a, b = axis[: n - 1] - p[1:n], axis[1:n] - p[1:n]
        formula = 2 * ar.atan2(d, p[1:n, 1])
        angle = d4b_checks._signed_angle(ar, a, b)
        printed = d4b_checks._signed_angle(ar, b, axis[2 : n + 1] - p[1:n])
        corrected, printed_residuals = arb_checks.rotation_angle(d, p, axis, n)
        _same(corrected, abs(angle - formula))
        _same(printed_residuals, abs(printed - formula))
        expected = 2 * ar.scalar(case[1])
        _same(
            arb_checks.darboux_edges(axis[:n], e[:n]),
            darboux.edge_length_residuals(ar, axis[:n], e[:n]),
        )
        _same(
            arb_checks.darboux_distances(axis[:n], e[:n], expected),
            darboux.distance_residuals(ar, axis[:n], e[:n], expected),
        )


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("perturb", [False, True])
def test_hypothesis_and_theorem_6_are_the_numpy_balls(case: tuple[Any, ...], perturb: bool) -> None:
    ar, data = _polygons(*case)
    with balls.working_precision(ar.bits):
        p, tractrix, closed = data.p, data.tractrix, data.closed_tractrix
        if perturb:
            p, tractrix = _perturbed(p, 11), _perturbed(tractrix, 12)
        n, d = data.vertices - 1, ar.scalar(case[2])
        y = p[:n, 1]
        products = y[:-1] * y[1:]
        violation, ratios = arb_checks.hypothesis(d, y)
        _same(violation, ar.maximum(d * d - products, ar.scalar(0)) / (d * d))
        _same(ratios, products / (d * d))
        scale = abs(data.axis[:n, 0]) + ar.scalar(case[1])
        tiny = ar.scalar(np.finfo(np.float64).tiny)
        expected = relative_to(ar, point_distance(ar, tractrix[:n], closed[:n]), scale)
        _same(arb_checks.relative_distances(tractrix[:n], closed[:n], scale, tiny), expected)


@pytest.mark.parametrize("digits", [15, 50, 500])
@pytest.mark.parametrize("beta0", [None, 0.3, 2.9])
@pytest.mark.parametrize(("h", "d", "i_min", "i_max"), [(1.0, 0.1, -60, 59), (2.0, 1.7, -5, 30)])
def test_theorems_5_and_6_from_one_exponential_hold_the_closed_forms(
    digits: int, beta0: float | None, h: float, d: float, i_min: int, i_max: int
) -> None:
    """Eqs. (14) and (16) from one exponential per index (``kinematic_balls``) overlap the
    balls of the two closed forms, with radii of the same order (at most 4 times theirs, plus
    64 units of the precision of the values' size)."""
    ar = Ball(digits, 3, recursions_only=True)
    with balls.working_precision(ar.bits):
        hh, dd = ar.scalar(h), ar.scalar(d)
        shift = closed_forms.tilt_shift(ar, hh, dd, beta0)
        i = ar.indices(i_min, i_max)
        pair = closed_forms.kinematic_balls(ar, hh, dd, i, shift)
        assert pair is not None
        expected = (
            closed_forms.hyperbolic_cosine(ar, hh, dd, i, shift),
            closed_forms.tractrix(ar, hh, dd, i, shift),
        )
        ulp = flint.arb(2) ** (-ar.bits)
        for got, want in zip(pair, expected, strict=True):
            assert got.shape == want.shape == (i_max - i_min + 1, 2)
            assert arb_checks.balls(got)
            for a, b in zip(got.reshape(-1), want.reshape(-1), strict=True):
                assert a.overlaps(b)
                size = abs(b).upper() + flint.arb(h)
                assert a.rad() <= 4 * b.rad() + 64 * ulp * size


def test_theorems_5_and_6_from_one_exponential_on_balls_only() -> None:
    """Off balls (an index that is not a ball, or float64), the two functions run apart."""
    ar = Ball(30)
    with balls.working_precision(ar.bits):
        h, d = ar.scalar(1.0), ar.scalar(0.25)
        i = np.array([flint.arb(1), 2, flint.arb(3)], dtype=object)
        assert closed_forms.kinematic_balls(ar, h, d, i, ar.scalar(0)) is None
        assert closed_forms.kinematic_balls(ar, h, 0.25, ar.indices(0, 2), ar.scalar(0)) is None
        assert closed_forms.kinematic_balls(ar, h, d, ar.indices(0, 2), ar.scalar(0)) is not None
