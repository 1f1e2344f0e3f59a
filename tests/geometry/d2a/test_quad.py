"""(D2a) quad as served: verdicts at r* and elsewhere, constants, errata, perturbations."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from app.geometry.d2a import quad as d2a_quad
from app.geometry.errors import DomainError, NotRepresentableError
from app.geometry.precision import Arithmetic, Float64, MultiPrecision

ALL = {s.id for s in d2a_quad.STATEMENTS}
FAIL_ALWAYS = {"d1", "d3"}
ONLY_AT_R_STAR = {"theorem-1", "equation-5", "theorem-1-heights", "theorem-1-area-sum"}


def verdicts(checks: list) -> dict[str, bool | None]:
    return {c.id: c.holds for c in checks}


@pytest.mark.parametrize(("f0", "f1"), [(1.0, 1.5), (0.3, 0.5), (2.0, 9.0)])
def test_at_the_default_r_every_proof_formula_holds_and_d1_d3_fail(
    float64: Float64, f0: float, f1: float
) -> None:
    curve = d2a_quad.compute(float64, f0, f1, None, -10, 10)
    results = verdicts(curve.checks)
    assert set(results) == ALL
    assert {k for k, v in results.items() if v is not True} == FAIL_ALWAYS
    assert curve.parameters["r"] == pytest.approx(-f1 * (1 + f0**2) / (2 * (f1 - f0) ** 2))


def test_at_40_digits_residuals_are_near_1e_50(mp40: MultiPrecision) -> None:
    curve = d2a_quad.compute(mp40, 0.7, 1.1, None, -12, 9)
    for check in curve.checks:
        if check.id in FAIL_ALWAYS:
            assert check.holds is False and check.residual is not None and check.residual > 1e-6
        else:
            assert check.holds is True, check.id
            assert check.residual is not None and check.residual < 1e-45, check.id


@pytest.mark.parametrize("r", [0.0, 1.0, -5.9, 100.0])
def test_any_other_r_makes_theorem_1_fail_truthfully(float64: Float64, r: float) -> None:
    curve = d2a_quad.compute(float64, 1.0, 1.5, r, -10, 10)  # r* = −6
    results = verdicts(curve.checks)
    assert {k for k, v in results.items() if v is not True} == FAIL_ALWAYS | ONLY_AT_R_STAR
    theorem = next(c for c in curve.checks if c.id == "theorem-1")
    assert theorem.note is not None and "r* = -6" in theorem.note
    # (2) with the right c misses by much more than rounding
    assert theorem.residual is not None and theorem.residual > 1e-4


def test_theorem_1_fails_even_on_three_vertices_off_r_star(float64: Float64) -> None:
    # one equation can always be fitted; the proof's c cannot
    results = verdicts(d2a_quad.compute(float64, 1.0, 1.5, 0.0, 0, 2).checks)
    assert results["theorem-1"] is False
    assert verdicts(d2a_quad.compute(float64, 1.0, 1.5, None, 0, 2).checks)["theorem-1"] is True


@pytest.mark.parametrize("ar", [Float64(), MultiPrecision(30)], ids=["float64", "mp30"])
def test_constants(ar: Arithmetic) -> None:
    curve = d2a_quad.compute(ar, 1.0, 2.0, None, -6, 6)
    got = {k: float(v) for k, v in curve.constants.items()}
    c = 4 * (1 / 3) ** 3
    assert got == pytest.approx(
        {"eq2": c, "c_theorem_1": c, "r_theorem_1": -2.0, "x_step": 1.5}, rel=1e-12
    )


def test_errata_carry_printed_residuals(float64: Float64) -> None:
    curve = d2a_quad.compute(float64, 1.0, 1.5, None, -10, 10)
    errata = {c.id: c.erratum for c in curve.checks if c.erratum is not None}
    assert {k: e.id for k, e in errata.items()} == {
        "theorem-1-x-step": "E40",
        "theorem-1-second-difference": "E41",
        "theorem-1": "E42",
    }
    for check_id, erratum in errata.items():
        assert erratum.printed_residual is not None and erratum.printed_residual > 1e-2, check_id


def _perturbed(data: d2a_quad.QuadPolygons, field: str, index: int, factor: float):  # type: ignore[no-untyped-def]
    values = getattr(data, field).copy()
    values[index] = values[index] * factor
    return replace(data, **{field: values})


PERTURBED_P = {
    "theorem-1",
    "theorem-1-start-height",
    "theorem-1-dual-edge",
    "theorem-1-x-step",
    "theorem-1-second-difference",
    "equation-5",
    "theorem-1-heights",
    "theorem-1-area-sum",
}


@pytest.mark.parametrize(
    ("field", "failing"),
    [
        ("p", PERTURBED_P),
        ("gauss_edges", {"theorem-1-gauss-edge", "theorem-1-gauss-edge-norm"}),
    ],
)
def test_checks_fail_on_perturbed_data(float64: Float64, field: str, failing: set[str]) -> None:
    data = d2a_quad.polygons(float64, 1.0, 1.5, None, -10, 10)
    results = verdicts(d2a_quad.evaluate(float64, data)[1])
    assert {k for k, v in results.items() if v is not True} == FAIL_ALWAYS
    bad = _perturbed(data, field, 12, 1 + 1e-7)
    results = verdicts(d2a_quad.evaluate(float64, bad)[1])
    assert {k for k, v in results.items() if v is False} == failing | FAIL_ALWAYS


def test_short_ranges_make_long_checks_not_applicable(float64: Float64) -> None:
    results = verdicts(d2a_quad.compute(float64, 1.0, 1.5, None, 4, 4).checks)
    assert results["theorem-1"] is None and results["theorem-1-dual-edge"] is None
    results = verdicts(d2a_quad.compute(float64, 1.0, 1.5, None, 4, 5).checks)
    assert results["theorem-1-dual-edge"] is True and results["equation-5"] is True
    assert results["theorem-1-heights"] is None


def test_range_and_float64_limits_are_domain_errors(float64: Float64) -> None:
    with pytest.raises(DomainError, match="i_max must satisfy i_min <= i_max"):
        d2a_quad.compute(float64, 1.0, 1.5, None, 3, 2)
    with pytest.raises(NotRepresentableError, match=r"f1 must satisfy \(f1 − f0\)/f1 >= 0.0001"):
        d2a_quad.compute(float64, 1.0, 1.00001, None, 0, 3)
    with pytest.raises(NotRepresentableError, match="i_max must satisfy every f_i and 1/f_i"):
        d2a_quad.compute(float64, 1.0, 2.0, None, 0, 200)
    with pytest.raises(NotRepresentableError, match="i_min must satisfy every f_i and 1/f_i"):
        d2a_quad.compute(float64, 1.0, 2.0, None, -200, 0)


def test_mp_has_no_float64_range_limit() -> None:
    curve = d2a_quad.compute(MultiPrecision(20), 1.0, 2.0, None, 300, 303)
    assert all(c.holds is True for c in curve.checks if c.id not in FAIL_ALWAYS)
    y = curve.polygon.vertices[0, 1]
    assert y < -(10**90)  # p_i^y = −(f_i + 1/f_i) with f_i = 2^i
    assert float(y / 2**300) == pytest.approx(-1.0, rel=1e-15)
    assert np.all(curve.polygon.indices == np.arange(300, 304))


def test_d1_d3_checks_hold_on_a_polygon_that_satisfies_them(float64: Float64) -> None:
    from app.geometry.d4b import discretization as d4b

    data = d2a_quad.polygons(float64, 1.0, 1.5, None, -10, 10)
    kinematic = d4b.polygons(float64, 1.0, 0.3, None, -10, 9).p
    results = verdicts(d2a_quad.evaluate(float64, replace(data, p=kinematic))[1])
    assert results["d1"] is True and results["d3"] is True and results["theorem-1"] is False
