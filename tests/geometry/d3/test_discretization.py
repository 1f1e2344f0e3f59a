"""(D3): the recursion against an independent reference, its two roots, every check's verdict."""

from __future__ import annotations

import functools
import math
from dataclasses import replace

import numpy as np
import pytest

from app.geometry.d3 import construction as area_length, discretization as d3
from app.geometry.errors import DomainError, NotRepresentableError
from app.geometry.precision import Float64, MultiPrecision
from tests.reference import d3 as reference
from tests.reference.compare import worst_relative

# (c, delta, y0, branch): up and down starts, a wide step, and a start at the lowest point
CASES = [
    ("1", "0.2", "1", "up"),
    ("1", "0.3", "1.2", "down"),
    ("2", "1", "5", "down"),
    ("0.7", "0.5", "3", "up"),
]
RANGE = (-12, 15)


@functools.cache
def expected_for(case: tuple) -> dict:
    """The reference polygon of one case (computed once per test session)."""
    return reference.construct(*case, *RANGE)


def verdicts(checks: list) -> dict[str, bool | None]:
    return {c.id: c.holds for c in checks}


def run(ar, case: tuple, *range_: int, method: str = "construction"):
    c, delta, y0, branch = case
    return d3.compute(ar, float(c), float(delta), float(y0), branch, *range_, method)  # type: ignore[arg-type]


@pytest.mark.parametrize("case", CASES)
def test_float64_agrees_with_the_independent_reference(float64: Float64, case: tuple) -> None:
    expected = expected_for(case)
    curve = run(float64, case, *RANGE)
    assert worst_relative(curve.polygon.vertices, expected, range(RANGE[0], RANGE[1] + 1)) < 1e-12


@pytest.mark.parametrize("case", CASES)
def test_40_digits_agree_with_the_independent_reference(mp40: MultiPrecision, case: tuple) -> None:
    expected = expected_for(case)
    curve = run(mp40, case, *RANGE)
    assert worst_relative(curve.polygon.vertices, expected, range(RANGE[0], RANGE[1] + 1)) < 1e-35


def test_both_roots_are_admissible_and_mirror_images(float64: Float64) -> None:
    c, delta, y = 1.0, 0.3, 1.2
    q = area_length.quadratic(float64, c, delta)
    big, small = area_length.step_roots(float64, q, y)
    for w in (big, small):
        assert delta * (y + w) / 2 == pytest.approx(c * math.hypot(delta, w - y), rel=1e-14)
    # mirror images in the vertical through p_0: p_1 is one root, p_{−1} the other
    p = run(float64, ("1", "0.3", "1.2", "up"), -1, 1).polygon.vertices
    assert (p[2, 1], p[0, 1]) == pytest.approx((big, small), rel=1e-15)


def test_the_fold_back_root_is_the_previous_vertex(float64: Float64) -> None:
    p = run(float64, ("1", "0.3", "1.2", "up"), 0, 5).polygon.vertices
    q = area_length.quadratic(float64, 1.0, 0.3)
    for i in range(1, 5):
        roots = area_length.step_roots(float64, q, p[i, 1])
        assert min(abs(r - p[i - 1, 1]) for r in roots) < 1e-13
        assert min(abs(r - p[i + 1, 1]) for r in roots) < 1e-13


def test_roots_are_the_catenary_moved_by_2d_either_way(float64: Float64) -> None:
    c, delta = 2.0, 1.0
    a = math.sqrt(c * c - delta * delta / 4)
    D = math.atanh(delta / (2 * c))
    v = 0.7
    big, small = area_length.step_roots(
        float64, area_length.quadratic(float64, c, delta), a * math.cosh(v)
    )
    assert big == pytest.approx(a * math.cosh(v + 2 * D), rel=1e-14)
    assert small == pytest.approx(a * math.cosh(v - 2 * D), rel=1e-14)


def test_start_at_the_lowest_point_is_symmetric(float64: Float64) -> None:
    a = area_length.lowest_height(1.0, 0.4)
    for branch in ("up", "down"):
        y = d3.compute(float64, 1.0, 0.4, a, branch, -6, 6).polygon.vertices[:, 1]
        np.testing.assert_allclose(y, y[::-1], rtol=1e-13)
        assert y.min() == y[6]


def test_verdicts_and_constants_d3_implies_d1_and_equation_2(float64: Float64) -> None:
    c, delta = 2.0, 1.0
    curve = d3.compute(float64, c, delta, 5.0, "down", -10, 10)
    assert all(verdicts(curve.checks).values())
    got = {k: float(v) for k, v in curve.constants.items()}
    assert got == pytest.approx(
        {"d3": c, "d1": delta / (2 * c), "eq2": delta / (2 * c * c), "equilibrium": 1 / (2 * c)},
        rel=1e-12,
    )
    assert [ch.id for ch in curve.checks] == [s.id for s in d3.STATEMENTS]


def test_every_check_holds_at_40_digits_far_below_tolerance(mp40: MultiPrecision) -> None:
    curve = d3.compute(mp40, 1.0, 0.3, 1.2, "down", -10, 10)
    for check in curve.checks:
        assert check.holds is True, check.id
        assert check.residual is not None and check.residual < 1e-38, check.id


def test_each_check_fails_on_a_perturbed_polygon(float64: Float64) -> None:
    data = d3.polygons(float64, 1.0, 0.3, 1.2, "down", -10, 10)
    assert all(verdicts(d3.evaluate(float64, data)[1]).values())
    p = data.p.copy()
    p[12, 1] *= 1 + 1e-7
    results = verdicts(d3.evaluate(float64, replace(data, p=p))[1])
    assert results == dict.fromkeys(results, False)


def test_a_zig_zag_satisfies_d3_but_not_d1(float64: Float64) -> None:
    # taking the fold-back root every time: p_2 = p_0, p_3 = p_1, ... still has A_i = c l_i
    data = d3.polygons(float64, 1.0, 0.3, 1.2, "up", 0, 6)
    p = data.p.copy()
    p[2::2, 1], p[3::2, 1] = p[0, 1], p[1, 1]
    results = verdicts(d3.evaluate(float64, replace(data, p=p))[1])
    assert results["d3"] is True
    assert results["d1"] is False and results["d3-closed-form"] is False


def test_closed_form_method(float64: Float64) -> None:
    case = ("1", "0.3", "1.2", "down")
    closed = run(float64, case, -40, 40, method="closed-form")
    assert verdicts(closed.checks)["d3-closed-form"] is None
    np.testing.assert_allclose(
        closed.polygon.vertices, run(float64, case, -40, 40).polygon.vertices, rtol=1e-12
    )


@pytest.mark.parametrize(
    ("args", "match"),
    [
        ((0.0, 0.2, 1.0, "up"), "c must satisfy c > 0"),
        ((-1.0, 0.2, 1.0, "up"), "c must satisfy c > 0"),
        ((1.0, 0.0, 1.0, "up"), "delta must satisfy 0 < delta < 2c"),
        ((1.0, 2.0, 1.0, "up"), "delta must satisfy 0 < delta < 2c, got 2.0: c = 1.0; for"),
        ((1.0, 3.0, 1.0, "up"), "zig-zags"),
        ((1.0, 0.2, 0.9, "up"), r"y0 must satisfy y0 >= √\(c² − delta²/4\), got 0.9"),
        ((1.0, 0.2, -5.0, "up"), "y0 must satisfy y0 >= "),
        ((1.0, 0.2, math.nan, "up"), "y0 must satisfy y0 is a finite number"),
        ((1.0, 0.2, 1.0, "sideways"), "branch must satisfy branch is 'up' or 'down'"),
    ],
)
def test_domain_errors_name_the_parameter(float64: Float64, args: tuple, match: str) -> None:
    with pytest.raises(DomainError, match=match):
        d3.compute(float64, *args)


def test_below_the_lowest_height_the_roots_are_complex(float64: Float64) -> None:
    # the best area/length of an edge from height y over the width δ is √(y² + δ²/4) < c
    c, delta, y = 1.0, 0.2, 0.9
    w = np.linspace(-100, 100, 200001)
    ratio = delta * (y + w) / 2 / np.hypot(delta, w - y)
    assert ratio.max() == pytest.approx(math.sqrt(y * y + delta * delta / 4), rel=1e-6)
    assert ratio.max() < c


def test_range_order_and_float64_limits(float64: Float64) -> None:
    with pytest.raises(DomainError, match="i_max must satisfy i_min <= i_max"):
        d3.compute(float64, 1.0, 0.2, 1.0, "up", 1, 0)
    with pytest.raises(NotRepresentableError, match=r"\|i_min\| <= \d+ in float64"):
        d3.compute(float64, 1.0, 1.9, 1.0, "up", -200, 0)
    curve = d3.compute(MultiPrecision(20), 1.0, 1.9, 1.0, "up", 199, 200, "closed-form")
    assert float(curve.polygon.vertices[1, 1]) > 1e150


def test_closed_form_tolerance_allows_the_conditioning_next_to_the_lowest_point(
    float64: Float64,
) -> None:
    c, delta = 487.42349999455126, 974.0284171398698
    a = area_length.lowest_height(c, delta)
    curve = d3.compute(float64, c, delta, a * (1 + 4e-12), "up", 0, 5)
    check = next(ch for ch in curve.checks if ch.id == "d3-closed-form")
    assert check.holds is True and "lowest point" in (check.note or "")
    assert check.tolerance > 1e3 * float64.tolerance(16)
    data = d3.polygons(float64, c, delta, a * (1 + 4e-12), "up", 0, 5)
    p = data.p.copy()
    p[3, 1] *= 1 + 1e-7
    bad = next(ch for ch in d3.evaluate(float64, replace(data, p=p))[1] if ch.id == check.id)
    assert bad.holds is False
    generic = next(
        ch for ch in d3.compute(float64, 2.0, 1.0, 5.0, "up", 0, 5).checks if ch.id == check.id
    )
    assert generic.note is None
