"""(D1): the recursion against an independent reference, its quadratic, every check's verdict."""

from __future__ import annotations

import functools
import math
from dataclasses import replace

import numpy as np
import pytest

from app.geometry.d1 import closed_forms, construction as hanging_chain, discretization as d1
from app.geometry.errors import DomainError, NotRepresentableError
from app.geometry.precision import Float64, MultiPrecision
from tests.reference import d1 as reference
from tests.reference.compare import worst_relative

# (c, delta, y0, y1): a positive start, a negative descending one, a tilted one crossing the axis,
# and the default (offset C = 0)
CASES = [
    ("0.2", "0.5", "1.0", "1.1"),
    ("0.3", "0.4", "-2.0", "-2.5"),
    ("0.05", "0.3", "-0.7", "0.4"),
    ("0.1", "0.2", "1.0", "1.0"),
]
RANGE = (-12, 15)


@functools.cache
def expected_for(case: tuple) -> dict:
    """The reference polygon of one case (computed once per test session)."""
    return reference.construct(*case, *RANGE)


def verdicts(checks: list) -> dict[str, bool | None]:
    return {c.id: c.holds for c in checks}


@pytest.mark.parametrize("case", CASES)
def test_float64_agrees_with_the_independent_reference(float64: Float64, case: tuple) -> None:
    expected = expected_for(case)
    curve = d1.compute(float64, *map(float, case), *RANGE)
    assert worst_relative(curve.polygon.vertices, expected, range(RANGE[0], RANGE[1] + 1)) < 1e-12


@pytest.mark.parametrize("case", CASES)
def test_40_digits_agree_with_the_independent_reference(mp40: MultiPrecision, case: tuple) -> None:
    expected = expected_for(case)
    curve = d1.compute(mp40, *map(float, case), *RANGE)
    assert worst_relative(curve.polygon.vertices, expected, range(RANGE[0], RANGE[1] + 1)) < 1e-35


def test_the_admissible_root_solves_the_equation_and_the_other_is_the_arch(
    float64: Float64,
) -> None:
    c, m = 0.3, -0.8
    k = hanging_chain.StepConstants.of(float64, c)
    forward = hanging_chain.forward_slope(float64, k, m)
    r = math.hypot(1, m)
    assert forward - m == pytest.approx(c * (r + math.hypot(1, forward)), rel=1e-14)
    # the other root of (1 − c²)μ² − 2κμ + κ² − c² = 0 solves the equation with −c
    kappa = m + c * r
    other = (kappa - c * math.sqrt(kappa**2 + 1 - c * c)) / (1 - c * c)
    assert other - m == pytest.approx(c * r - c * math.hypot(1, other), rel=1e-13)
    assert other - m < c * (r + math.hypot(1, other))
    # backwards undoes forwards
    assert hanging_chain.backward_slope(float64, k, forward) == pytest.approx(m, rel=1e-14)


def test_steep_negative_slopes_keep_full_precision(float64: Float64, mp40: MultiPrecision) -> None:
    # κ = m + c√(1 + m²) cancels for m ≪ 0 and c near 1: the rewritten forms avoid it
    for m in (-1e6, -3.0, -1e-8):
        got = hanging_chain.forward_slope(float64, hanging_chain.StepConstants.of(float64, 0.99), m)
        exact = hanging_chain.forward_slope(
            mp40, hanging_chain.StepConstants.of(mp40, mp40.scalar(0.99)), mp40.scalar(m)
        )
        assert got == pytest.approx(float(exact), rel=1e-14)


def test_closed_form_parameters_by_hand(float64: Float64) -> None:
    # defaults: u_0 = 0, E = 2 artanh 0.1, a = 0.2·√0.99/0.2 = √0.99, C = 1 − a cosh(E/2) = 0
    k = closed_forms.parameters(float64, 0.1, 0.2, 1.0, 1.0)
    assert k.step == pytest.approx(2 * math.atanh(0.1), rel=1e-15)
    assert k.amplitude == pytest.approx(math.sqrt(0.99), rel=1e-15)
    assert abs(k.offset) < 1e-15
    shifted = closed_forms.parameters(float64, 0.1, 0.2, 3.0, 3.0)
    assert shifted.offset == pytest.approx(2.0, rel=1e-14)


def test_default_polygon_is_d4b_shifted_by_d(float64: Float64) -> None:
    # p_i^y = √(h² − d²) cosh((i − ½)L), L = 2 artanh(d/h), h = 1, d = 0.1, at x = 2di
    curve = d1.compute(float64)
    i = np.arange(-10, 11)
    L = 2 * math.atanh(0.1)
    expected = np.column_stack([0.2 * i, math.sqrt(0.99) * np.cosh((i - 0.5) * L)])
    np.testing.assert_allclose(curve.polygon.vertices, expected, rtol=1e-13)


def test_verdicts_with_an_offset(float64: Float64) -> None:
    curve = d1.compute(float64, 0.2, 0.5, 1.0, 1.1, -10, 10)
    assert verdicts(curve.checks) == {
        "d1": True,
        "d3": False,
        "equation-2": False,
        "hanging-sticks": True,
        "d1-closed-form": True,
    }
    assert float(curve.constants["d1"]) == pytest.approx(0.2, rel=1e-12)
    assert float(curve.constants["equilibrium"]) == pytest.approx(0.2 / 0.5, rel=1e-12)
    check = next(c for c in curve.checks if c.id == "d3")
    assert check.residual is not None and check.residual > 1e-3
    assert "C = -0.2247548" in (check.note or "")


@pytest.mark.parametrize("ar", [Float64(), MultiPrecision(30)], ids=["float64", "mp30"])
def test_zero_offset_satisfies_d3_and_equation_2_with_the_predicted_constants(ar) -> None:
    # C = 0 when y0 = a cosh(u_0 − E/2); with y1 = y0 (u_0 = 0): y0 = delta/(2c)
    c, delta = 0.25, 0.3
    y0 = delta / (2 * c)
    curve = d1.compute(ar, c, delta, y0, y0, -8, 8)
    assert all(verdicts(curve.checks).values())
    got = {k: float(v) for k, v in curve.constants.items()}
    assert got == pytest.approx(
        {"d1": c, "d3": delta / (2 * c), "eq2": 2 * c * c / delta, "equilibrium": c / delta},
        rel=1e-12,
    )


def test_every_check_holds_at_40_digits_far_below_tolerance(mp40: MultiPrecision) -> None:
    curve = d1.compute(mp40, 0.1, 0.2, 1.0, 1.0, -10, 10)
    for check in curve.checks:
        assert check.holds is True, check.id
        assert check.residual is not None and check.residual < 1e-38, check.id


def _perturbed(data: d1.D1Polygons, index: int, factor: float) -> d1.D1Polygons:
    p = data.p.copy()
    p[index, 1] = p[index, 1] * factor
    return replace(data, p=p)


def test_each_check_fails_on_a_perturbed_polygon(float64: Float64) -> None:
    args = (0.1, 0.2, 1.0, 1.0)
    data = d1.polygons(float64, *args, -10, 10)
    assert all(verdicts(d1.evaluate(float64, data)[1]).values())
    results = verdicts(d1.evaluate(float64, _perturbed(data, 12, 1 + 1e-7))[1])
    assert results == dict.fromkeys(results, False)


def test_closed_form_method_skips_the_comparison(float64: Float64) -> None:
    curve = d1.compute(float64, 0.2, 0.5, 1.0, 1.1, -50, 50, "closed-form")
    check = next(c for c in curve.checks if c.id == "d1-closed-form")
    assert check.holds is None and "closed-form" in (check.note or "")
    built = d1.compute(float64, 0.2, 0.5, 1.0, 1.1, -50, 50)
    np.testing.assert_allclose(curve.polygon.vertices, built.polygon.vertices, rtol=1e-12)


def test_any_range_works_including_one_vertex_and_ranges_away_from_zero(float64: Float64) -> None:
    whole = d1.compute(float64, 0.2, 0.5, 1.0, 1.1, -30, 30).polygon.vertices
    for lo, hi in ((-30, -20), (20, 30), (5, 5), (-3, -3)):
        part = d1.compute(float64, 0.2, 0.5, 1.0, 1.1, lo, hi).polygon.vertices
        np.testing.assert_array_equal(part, whole[lo + 30 : hi + 31])
    single = d1.compute(float64, 0.2, 0.5, 1.0, 1.1, 5, 5)
    assert verdicts(single.checks)["d1"] is None


def test_p0_and_p1_are_the_given_starts_exactly(float64: Float64) -> None:
    p = d1.compute(float64, 0.3, 0.4, -2.0, -2.5, -2, 2).polygon.vertices
    assert p[2].tolist() == [0.0, -2.0]
    assert p[3].tolist() == [0.4, -2.5]


@pytest.mark.parametrize(
    ("args", "match"),
    [
        ((1.0, 0.2, 1.0, 1.0), r"c must satisfy 0 < c < 1, got 1.0: for c >= 1 no polygon"),
        ((1.5, 0.2, 1.0, 1.0), "c must satisfy 0 < c < 1"),
        ((0.0, 0.2, 1.0, 1.0), "c must satisfy 0 < c < 1"),
        ((-0.1, 0.2, 1.0, 1.0), "c must satisfy 0 < c < 1"),
        ((math.nan, 0.2, 1.0, 1.0), "c must satisfy 0 < c < 1"),
        ((0.1, 0.0, 1.0, 1.0), "delta must satisfy delta > 0"),
        ((0.1, -1.0, 1.0, 1.0), "delta must satisfy delta > 0"),
        ((0.1, 0.2, math.inf, 1.0), "y0 must satisfy y0 is a finite number"),
        ((0.1, 0.2, 1.0, math.nan), "y1 must satisfy y1 is a finite number"),
    ],
)
def test_domain_errors_name_the_parameter(float64: Float64, args: tuple, match: str) -> None:
    with pytest.raises(DomainError, match=match):
        d1.compute(float64, *args)


def test_for_c_at_least_1_no_slope_satisfies_the_step(float64: Float64) -> None:
    # the reason for c < 1: |m' − m| <= |m| + |m'| < c(√(1+m²) + √(1+m'²)) for every m, m'
    m = np.linspace(-50, 50, 2001)
    for c in (1.0, 1.2):
        lhs = m[:, None] - m[None, :]
        rhs = c * (np.hypot(1, m)[:, None] + np.hypot(1, m)[None, :])
        assert np.all(np.abs(lhs) < rhs)


def test_range_order_and_float64_limits(float64: Float64) -> None:
    with pytest.raises(DomainError, match="i_max must satisfy i_min <= i_max"):
        d1.compute(float64, 0.1, 0.2, 1.0, 1.0, 3, 2)
    with pytest.raises(NotRepresentableError, match=r"\|i_max\| <= \d+ in float64"):
        d1.compute(float64, 0.5, 1.0, 1.0, 1.0, 0, 400)
    with pytest.raises(NotRepresentableError, match=r"c must satisfy delta/\(2c\) <= 1e\+150"):
        d1.compute(float64, 1e-300, 1.0, 1.0, 1.0, 0, 2)
    with pytest.raises(NotRepresentableError, match=r"y1 must satisfy \|y1 − y0\|/delta"):
        d1.compute(float64, 0.1, 1e-300, 0.0, 1e100, 0, 2)
    # the same range in mp is fine
    curve = d1.compute(MultiPrecision(20), 0.5, 1.0, 1.0, 1.0, 399, 400, "closed-form")
    assert float(curve.polygon.vertices[1, 1]) > 1e150


def test_closed_form_keeps_its_digits_for_a_nearly_straight_chain(float64: Float64) -> None:
    # a = δ√(1 − c²)/(2c) ≈ 7.5e5 ≫ |y|: C + a cosh(…) would cancel; the product form does not
    built = d1.compute(float64, 1e-6, 1.5, 0.0, 2.0, 0, 400)
    closed = d1.compute(float64, 1e-6, 1.5, 0.0, 2.0, 0, 400, "closed-form")
    assert verdicts(built.checks)["d1-closed-form"] is True
    assert verdicts(closed.checks)["d1"] is True  # the served closed form satisfies (D1)
    # p_0 at the origin is compared absolutely
    origin = d1.compute(float64, 0.1, 2.0, 0.0, 1e-300, 0, 3)
    assert verdicts(origin.checks)["d1-closed-form"] is True
