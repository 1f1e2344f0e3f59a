"""(D4a): the stick construction against an independent reference, the cusp, every check."""

from __future__ import annotations

import functools
import math
from dataclasses import replace

import mpmath
import numpy as np
import pytest

from app.geometry.d4a import (
    closed_forms as sauer_closed_forms,
    construction as sauer_tractrix,
    discretization as d4a,
)
from app.geometry.errors import DomainError, NotRepresentableError
from app.geometry.precision import Float64, MultiPrecision
from tests.reference import d4a as reference
from tests.reference.compare import worst_relative

# (h, s, beta0): vertical start, tilted back (cusp at 0), tilted forward (cusp ahead), tilted
# back and low (cusp behind), nearly flat forward (cusp far ahead, outside the range)
CASES = [
    ("1", "0.1", None),
    ("1", "0.3", "2.0"),
    ("1", "0.3", "0.7"),
    ("2", "0.5", "2.8"),
    ("1.5", "0.2", "0.1"),
]
CUSPS = [0, 0, 1, -3, 16]
RANGE = (-12, 15)
INDICES = range(RANGE[0], RANGE[1] + 1)


@functools.cache
def expected_for(case: tuple) -> tuple:
    return reference.construct(*case, *RANGE)


def run(ar, case: tuple, *range_: int, method: str = "construction"):
    h, s, beta0 = case
    return d4a.compute(
        ar,
        float(h),
        float(s),
        None if beta0 is None else float(beta0),
        *range_,
        method,  # type: ignore[arg-type]
    )


def verdicts(checks: list) -> dict[str, bool | None]:
    return {c.id: c.holds for c in checks}


def polylines(curve) -> list:
    c = curve.companions
    return [
        curve.polygon.vertices,
        c["tractrix"].vertices,
        c["axis_points"].vertices,
        c["darboux"].vertices,
    ]


@pytest.mark.parametrize(("case", "cusp"), list(zip(CASES, CUSPS, strict=True)))
def test_float64_agrees_with_the_independent_reference(
    float64: Float64, case: tuple, cusp: int
) -> None:
    *expected, expected_cusp = expected_for(case)
    assert expected_cusp == (cusp if RANGE[0] - 1 <= cusp <= RANGE[1] + 3 else None)
    for name, ours, theirs in zip(
        "pdxe", polylines(run(float64, case, *RANGE)), expected, strict=True
    ):
        assert worst_relative(ours, theirs, INDICES) < 1e-12, name


@pytest.mark.parametrize("case", CASES)
def test_40_digits_agree_with_the_independent_reference(mp40: MultiPrecision, case: tuple) -> None:
    *expected, _ = expected_for(case)
    for name, ours, theirs in zip(
        "pdxe", polylines(run(mp40, case, *RANGE)), expected, strict=True
    ):
        assert worst_relative(ours, theirs, INDICES) < 1e-35, name


@pytest.mark.parametrize(("case", "cusp"), list(zip(CASES, CUSPS, strict=True)))
def test_cusp_index_of_the_explicit_form(float64: Float64, case: tuple, cusp: int) -> None:
    h, s, beta0 = case
    found = sauer_closed_forms.cusp(
        float64, float(h), float(s), None if beta0 is None else float(beta0)
    )
    assert found.index == cusp
    sticks = sauer_tractrix.construct_sticks(
        float64, float(h), float(s), None if beta0 is None else float(beta0), -5, 20
    )
    assert list(np.flatnonzero(sticks.side == 0) - 5) == ([cusp] if -5 <= cusp <= 20 else [])


def test_vertical_start_is_mirror_symmetric_with_the_bottom_pair_by_hand(float64: Float64) -> None:
    h, s = 1.0, 0.1
    curve = d4a.compute(float64, h, s, None, -10, 9)
    p, d = curve.polygon.vertices, curve.companions["tractrix"].vertices
    w = math.sqrt(s * (2 * h - s))
    np.testing.assert_allclose(p[9:11], [[-w / 2, h - s / 2], [w / 2, h - s / 2]], rtol=1e-15)
    np.testing.assert_allclose(p[::-1] * [-1, 1], p, rtol=1e-13, atol=1e-15)  # p_{−1−i}
    # d_{−i} mirrors d_i, and the tractrix folds back at the cusp: d_{−1} = d_1 = (0, h − s)
    np.testing.assert_allclose(d[1:10][::-1] * [-1, 1], d[11:20], rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose([d[9], d[11]], [[0, h - s], [0, h - s]], atol=1e-16)
    assert d[10].tolist() == [0.0, 1.0]


def test_heights_decay_geometrically_away_from_the_cusp(float64: Float64) -> None:
    d = d4a.compute(float64, 2.0, 0.5, 2.8, -10, 10).companions["tractrix"].vertices
    cusp = -3
    k = 1 - 0.5 / 2.0
    ratio = d[1:, 1] / d[:-1, 1]
    i = np.arange(-10, 10)
    np.testing.assert_allclose(ratio[i >= cusp], k, rtol=1e-13)
    np.testing.assert_allclose(ratio[i < cusp - 1], 1 / k, rtol=1e-13)


def test_verdicts(float64: Float64) -> None:
    curve = d4a.compute(float64, 1.0, 0.3, 2.0, -10, 10)
    results = verdicts(curve.checks)
    assert [s.id for s in d4a.STATEMENTS] == list(results)
    failing = {"d1", "d3", "equation-2", "hanging-sticks"}
    assert {k for k, v in results.items() if v is not True} == failing
    assert all(results[k] is False for k in failing)
    for check in curve.checks:
        if check.id in failing:
            assert check.residual is not None and check.residual > 1e-3, check.id
            assert "best constant" in (check.note or "")
    assert set(curve.constants) == {"d1", "d3", "eq2", "equilibrium"}


def test_every_check_of_the_construction_holds_at_40_digits(mp40: MultiPrecision) -> None:
    curve = d4a.compute(mp40, 2.0, 0.5, 2.8, -10, 10)
    for check in curve.checks:
        if check.id in {"d1", "d3", "equation-2", "hanging-sticks"}:
            assert check.holds is False, check.id
        else:
            assert check.holds is True, check.id
            assert check.residual is not None and check.residual < 1e-38, check.id


def test_errata_printed_forms_fail_past_the_cusp_and_hold_after_it(float64: Float64) -> None:
    both_sides = d4a.compute(float64, 1.0, 0.1, None, -10, 10)
    pursuit_only = d4a.compute(float64, 1.0, 0.1, None, 1, 10)
    for curve, large in ((both_sides, True), (pursuit_only, False)):
        errata = {c.id: c.erratum for c in curve.checks if c.erratum is not None}
        assert set(errata) == {"d4a-sticks", "darboux-d4a", "darboux-d4a-distance"}
        for check_id, erratum in errata.items():
            assert erratum.printed_residual is not None
            assert (erratum.printed_residual > 1e-3) is large, check_id
            assert (erratum.printed_residual < 1e-14) is not large, check_id
        assert {e.id for e in errata.values()} == {"E20", "E21"}


PERTURBED = {
    "p": {
        "rotation-centre-d4a",
        "nikolaides-d4a",
        "d4a-closed-form",
        "d1",
        "d3",
        "equation-2",
        "hanging-sticks",
    },
    "tractrix": {"d4a-sticks", "d4a-arc-length", "rotation-centre-d4a", "d4a-closed-form"},
    "axis": {
        "d4a-sticks",
        "darboux-d4a",
        "darboux-d4a-distance",
        "rotation-centre-d4a",
        "nikolaides-d4a",
    },
    "darboux": {"darboux-d4a", "darboux-d4a-distance"},
}


@pytest.mark.parametrize("field", list(PERTURBED))
def test_checks_fail_on_a_perturbed_polygon(float64: Float64, field: str) -> None:
    data = d4a.polygons(float64, 1.0, 0.3, 2.0, -10, 10)
    truth = verdicts(d4a.evaluate(float64, data)[1])
    points = getattr(data, field).copy()
    points[12] = points[12] * (1 + 1e-7) + 1e-7
    results = verdicts(d4a.evaluate(float64, data.replaced(**{field: points}))[1])
    flipped = {k for k in results if truth[k] is True and results[k] is False}
    # the property checks fail on D4a anyway: the next test perturbs a polygon satisfying them
    assert flipped == PERTURBED[field] - {"d1", "d3", "equation-2", "hanging-sticks"}


def test_property_checks_fail_on_a_perturbed_polygon_that_satisfies_them(float64: Float64) -> None:
    # feed a (D1) = (D3) polygon (D4b's p, shifted) through D4a's evaluation: the property checks
    # hold, and a perturbation makes each of them fail
    data = d4a.polygons(float64, 1.0, 0.3, 2.0, -10, 10)
    i = np.arange(-10, 12)
    L = 2 * math.atanh(0.1)
    chain = np.column_stack([0.2 * i, math.sqrt(0.99) * np.cosh((i - 0.5) * L)])
    good = verdicts(d4a.evaluate(float64, replace(data, p=chain))[1])
    names = ("d1", "d3", "equation-2", "hanging-sticks")
    assert all(good[k] is True for k in names)
    chain[12, 1] *= 1 + 1e-7
    bad = verdicts(d4a.evaluate(float64, replace(data, p=chain))[1])
    assert all(bad[k] is False for k in names)


def test_closed_form_method_agrees_and_skips_the_comparison(float64: Float64) -> None:
    case = ("2", "0.5", "2.8")
    closed = run(float64, case, -60, 60, method="closed-form")
    built = run(float64, case, -60, 60)
    assert verdicts(closed.checks)["d4a-closed-form"] is None
    for ours, theirs in zip(polylines(closed), polylines(built), strict=True):
        np.testing.assert_allclose(ours, theirs, rtol=1e-11, atol=1e-12)


@pytest.mark.parametrize(
    ("args", "match"),
    [
        ((0.0, 0.1, None), "h must satisfy h > 0"),
        ((-1.0, 0.1, None), "h must satisfy h > 0"),
        ((1.0, 0.0, None), "s must satisfy 0 < s < h"),
        ((1.0, 1.0, None), "s must satisfy 0 < s < h, got 1.0: the stick length is h = 1.0"),
        ((1.0, 0.1, 0.0), "beta0 must satisfy 0 < beta0 < π"),
        ((1.0, 0.1, math.pi), "beta0 must satisfy 0 < beta0 < π"),
    ],
)
def test_domain_errors_name_the_parameter(float64: Float64, args: tuple, match: str) -> None:
    with pytest.raises(DomainError, match=match):
        d4a.compute(float64, *args)


def test_range_order_and_float64_limits(float64: Float64) -> None:
    with pytest.raises(DomainError, match="i_max must satisfy i_min <= i_max"):
        d4a.compute(float64, 1.0, 0.1, None, 0, -1)
    with pytest.raises(NotRepresentableError, match=r"s must satisfy s/h >= 0.001 in float64"):
        d4a.compute(float64, 1.0, 1e-4, None, -2, 2)
    with pytest.raises(NotRepresentableError, match=r"\|i_max\| <= \d+ in float64"):
        d4a.compute(float64, 1.0, 0.5, None, 0, 600)
    curve = d4a.compute(MultiPrecision(20), 1.0, 0.5, None, 598, 600, "closed-form")
    assert float(curve.polygon.vertices[0, 1]) > 1e150
    assert d4a.compute(MultiPrecision(20), 1.0, 1e-4, None, -2, 2).checks[0].holds is True


def test_a_step_close_to_the_stick_length_keeps_its_digits(float64: Float64) -> None:
    # k = (h − s)/h ≈ 3.4e-5; computing it as 1 − s/h would lose five digits
    curve = d4a.compute(float64, 0.00027376008574665897, 0.0002737507782835455, 3.0133, -5, 1)
    results = verdicts(curve.checks)
    assert all(results[k] for k in results if k not in {"d1", "d3", "equation-2", "hanging-sticks"})


def test_mp_refuses_steps_below_its_resolution() -> None:
    with pytest.raises(NotRepresentableError, match=r"s must satisfy s/h >= 1e-10 with digits=20"):
        d4a.compute(MultiPrecision(20), 1.0, 1e-11, None, -2, 2)


@pytest.mark.parametrize(("digits", "beta0"), [(30, 0.01), (60, 1e-50), (60, 3.1)])
def test_the_cusp_of_the_smallest_step_is_found_at_once(digits: int, beta0: float) -> None:
    # s/h at the resolution limit puts the cusp ~10^(digits/2) sticks away; the floor of
    # log(sin β0)/log(k) was taken through a float64, and the search walked the error stick by stick
    ar = MultiPrecision(digits)
    h, s = ar.scalar(1), ar.scalar(10.0 ** -(digits // 2))
    found = sauer_closed_forms.cusp(ar, h, s, beta0)
    k, sin_c = (h - s) / h, found.sin
    assert sin_c > h - s >= h * sin_c * k  # the stick past the cusp would reach the axis
    sin0 = ar.sin(ar.scalar(beta0))
    assert abs(sin_c - sin0 / k ** abs(found.index)) <= 10 ** (4 - digits) * sin_c
    with mpmath.workdps(digits + 20):  # independent: the count at full precision
        expected = int(mpmath.log(sin0) / mpmath.log(k))
    assert abs(abs(found.index) - expected) <= 1
    assert (found.index < 0) == (beta0 > math.pi / 2)
    curve = d4a.compute(ar, 1.0, float(s), beta0, -2, 2)
    results = verdicts(curve.checks)
    assert results["d4a-sticks"] is True and results["d4a-closed-form"] is True
