"""(D2a) hexagonal as served: Theorems 2 and 3 at r* and elsewhere, constants, errata,
perturbations, the two-constant fit of (7)."""

from __future__ import annotations

import warnings
from dataclasses import replace

import numpy as np
import pytest

from app.geometry import conditions
from app.geometry.d2a import hex as d2a_hex
from app.geometry.d4b import discretization as d4b
from app.geometry.errors import DomainError, NotRepresentableError
from app.geometry.precision import Arithmetic, Float64, MultiPrecision

ALL = {s.id for s in d2a_hex.STATEMENTS}
FAIL_ALWAYS = {"equation-2", "d1", "d3"}

PARAMETERS = [(1.0, 2.5, 0.5), (1.3, 2.1, 0.3), (0.4, 0.9, 0.8), (1.0, 2.0, 0.5), (2.0, 30.0, 0.1)]


def verdicts(checks: list) -> dict[str, bool | None]:
    return {c.id: c.holds for c in checks}


@pytest.mark.parametrize(("a", "b", "lam"), PARAMETERS)
def test_at_the_default_r_theorems_2_and_3_hold(
    float64: Float64, a: float, b: float, lam: float
) -> None:
    curve = d2a_hex.compute(float64, a, b, lam, None, -10, 10)
    results = verdicts(curve.checks)
    assert set(results) == ALL
    assert {k for k, v in results.items() if v is not True} == FAIL_ALWAYS


def test_at_40_digits_residuals_are_near_1e_50(mp40: MultiPrecision) -> None:
    curve = d2a_hex.compute(mp40, 1.3, 2.1, 0.3, None, -9, 12)
    for check in curve.checks:
        if check.id in FAIL_ALWAYS:
            assert check.holds is False and check.residual is not None and check.residual > 1e-6
        else:
            assert check.holds is True, check.id
            assert check.residual is not None and check.residual < 1e-45, check.id


@pytest.mark.parametrize("r", [0.0, -11.7, 3.0])
def test_any_other_r_makes_theorem_2_fail_truthfully(float64: Float64, r: float) -> None:
    curve = d2a_hex.compute(float64, 1.0, 2.5, 0.5, r, -10, 10)  # r* = −106/9
    results = verdicts(curve.checks)
    assert {k for k, v in results.items() if v is not True} == FAIL_ALWAYS | {"theorem-2"}
    theorem = next(c for c in curve.checks if c.id == "theorem-2")
    assert theorem.note is not None and "holds only for r = r*" in theorem.note


@pytest.mark.parametrize("ar", [Float64(), MultiPrecision(30)], ids=["float64", "mp30"])
def test_constants_match_11_and_the_start_height(ar: Arithmetic) -> None:
    curve = d2a_hex.compute(ar, 1.0, 2.0, 0.5, None, -8, 8)
    got = {k: float(v) for k, v in curve.constants.items()}
    assert got["c1"] == pytest.approx(1 / 63.75, rel=1e-12)
    assert got["c1_eq11"] == pytest.approx(1 / 63.75, rel=1e-12)
    assert abs(got["c2"]) < 1e-13 and got["c2_eq11"] == 0
    assert got["r_theorem_2"] == -20.5 and curve.parameters["r"] == -20.5
    # x-steps from (6): 3(1 + u)/(2(u − 1)) with u = f_1/f_0 = 1.5, and (1 + v)/(v − 1), v = 4/3
    assert got["x_step_even"] == pytest.approx(7.5, rel=1e-14)
    assert got["x_step_odd"] == pytest.approx(7.0, rel=1e-14)
    p = curve.polygon.vertices
    assert float(p[9, 0] - p[8, 0]) == pytest.approx(7.5, rel=1e-13)


def test_errata_carry_printed_residuals(float64: Float64) -> None:
    curve = d2a_hex.compute(float64, 1.0, 2.5, 0.5, None, -10, 10)
    errata = {c.id: c.erratum for c in curve.checks if c.erratum is not None}
    assert {k: e.id for k, e in errata.items()} == {
        "theorem-2": "E45",
        "theorem-3-even": "E43",
        "theorem-2-start-height": "E44",
    }
    for check_id, erratum in errata.items():
        assert erratum.printed_residual is not None and erratum.printed_residual > 1e-3, check_id
    # E45: Section 4.1 attributes (2) to the hexagonal polygon; its residual is that of (2)
    theorem_2 = next(c for c in curve.checks if c.id == "theorem-2")
    one_constant = next(c for c in curve.checks if c.id == "equation-2")
    assert theorem_2.holds is True and one_constant.holds is False
    assert errata["theorem-2"].printed_residual == one_constant.residual


def test_checks_fail_on_a_perturbed_polygon(float64: Float64) -> None:
    data = d2a_hex.polygons(float64, 1.0, 2.5, 0.5, None, -10, 10)
    results = verdicts(d2a_hex.evaluate(float64, data)[1])
    assert {k for k, v in results.items() if v is not True} == FAIL_ALWAYS
    for index, parity in ((12, "theorem-3-even"), (13, "theorem-3-odd")):
        p = data.p.copy()
        p[index] = p[index] * (1 + 1e-7)
        results = verdicts(d2a_hex.evaluate(float64, replace(data, p=p))[1])
        assert {k for k, v in results.items() if v is False} == FAIL_ALWAYS | {
            "theorem-2",
            "theorem-2-start-height",
            "equation-10",
            parity,
        }


def test_equation_7_fit_recovers_11_and_rejects_a_single_constant_polygon(
    mp40: MultiPrecision,
) -> None:
    data = d2a_hex.polygons(mp40, 1.3, 2.1, 0.3, None, -6, 6)
    fit = conditions.equation_7(mp40, data.p, data.i_min)
    assert fit.constants is not None
    c1, c2 = fit.constants
    assert abs(float(c1) - 0.05388854868340477) < 1e-15
    assert abs(float(c2) + 0.14030769230769231) < 1e-15
    assert float(max(fit.residuals)) < 1e-45
    # the (D4b) polygon satisfies (2), i.e. (7) with c_1 = c_2 = d/h²
    kinematic = d4b.polygons(mp40, 1.0, 0.3, None, -6, 6)
    fit = conditions.equation_7(mp40, kinematic.p, -6)
    assert fit.constants is not None
    assert [float(c) for c in fit.constants] == pytest.approx([0.3, 0.3], rel=1e-14)
    assert conditions.equation_7(mp40, kinematic.p[:3], -6).constants is None  # one equation
    bent = data.p.copy()
    bent[5, 1] = bent[5, 1] * (1 + mp40.scalar("1e-10"))
    assert float(max(conditions.equation_7(mp40, bent, -6).residuals)) > 1e-12


def test_short_ranges(float64: Float64) -> None:
    results = verdicts(d2a_hex.compute(float64, 1.0, 2.5, 0.5, None, 2, 2).checks)
    assert results["theorem-3-even"] is True and results["theorem-3-odd"] is None
    assert results["theorem-2"] is None and results["equation-10"] is None


def test_range_and_float64_limits_are_domain_errors(float64: Float64) -> None:
    with pytest.raises(DomainError, match="i_max must satisfy i_min <= i_max"):
        d2a_hex.compute(float64, 1.0, 2.5, 0.5, None, 3, 2)
    with pytest.raises(NotRepresentableError, match=r"b must satisfy \(b − a\)/b >= 0.0001"):
        d2a_hex.compute(float64, 1.0, 1.00001, 0.5, None, 0, 3)
    with pytest.raises(NotRepresentableError, match="lambda must satisfy"):
        d2a_hex.compute(float64, 1.0, 2.0, 1e-6, None, 0, 3)
    with pytest.raises(NotRepresentableError, match="lambda must satisfy"):
        d2a_hex.compute(float64, 1.0, 2.0, 1 - 1e-6, None, 0, 3)
    with pytest.raises(NotRepresentableError, match="i_max must satisfy every f_i"):
        d2a_hex.compute(float64, 1.0, 10.0, 0.5, None, 0, 120)


def test_mp_handles_lambda_near_the_edge() -> None:
    curve = d2a_hex.compute(MultiPrecision(30), 1.0, 2.0, 1e-8, None, -6, 6)
    assert all(c.holds is True for c in curve.checks if c.id not in FAIL_ALWAYS)
    assert np.all(np.diff(curve.polygon.indices) == 1)


def test_relation_checks_hold_on_a_polygon_that_satisfies_them(float64: Float64) -> None:
    # (D4b) satisfies (D1), (D3) and (2): the same checks, fed its polygon, hold
    data = d2a_hex.polygons(float64, 1.0, 2.5, 0.5, None, -10, 10)
    kinematic = d4b.polygons(float64, 1.0, 0.3, None, -10, 9).p
    results = verdicts(d2a_hex.evaluate(float64, replace(data, p=kinematic))[1])
    assert {k for k in FAIL_ALWAYS if results[k] is not True} == set()


def test_equation_7_fit_does_not_overflow_when_areas_dwarf_second_differences(
    float64: Float64,
) -> None:
    # x stretched by 1e150 and y squeezed by 1e-150 keep every area and divide Δ²y by 1e150, so
    # (7) holds with both constants divided by 1e150; the weighted areas are ~1e150 and their
    # products in the normal equations overflowed (the fit then said "not determined")
    data = d2a_hex.polygons(float64, 1.3, 2.1, 0.3, None, -6, 6)
    reference = conditions.equation_7(float64, data.p, data.i_min)
    assert reference.constants is not None
    scaled = data.p * np.array([1e150, 1e-150])
    with np.errstate(all="raise"):
        fit = conditions.equation_7(float64, scaled, data.i_min)
    assert fit.constants is not None
    for c, c_reference in zip(fit.constants, reference.constants, strict=True):
        assert c == pytest.approx(c_reference * 1e-150, rel=1e-12)
    assert np.max(fit.residuals) < 1e-13


def test_an_overflowing_printed_form_is_reported_as_not_a_number(float64: Float64) -> None:
    # (8) as printed has literal powers of a and b: at a ≈ 7e15 they overflow while the
    # construction and the corrected form stay finite
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        curve = d2a_hex.compute(
            float64, 7438379186113947.0, 23 * 7438379186113947.0, 0.5, None, 0, 30
        )
    even = next(c for c in curve.checks if c.id == "theorem-3-even")
    assert even.holds is True
    assert even.erratum is not None and even.erratum.printed_residual is None
