"""Thresholds of the mp path at any digits (issue 15): a float 10^−digits is 0 from 324 digits
on (its square from about 162, √(10^−(digits+guard)) from 314), so every tolerance, guard and
threshold that compared with such a float compared with 0 there. They are numbers of the
arithmetic or exact rationals now (``app.geometry.tolerances``); float64 keeps its floats."""

from __future__ import annotations

from contextlib import nullcontext
from decimal import Decimal, localcontext
from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.geometry import balls, conditions, tolerances
from app.geometry.ball_arithmetic import Ball
from app.geometry.curve import Curve
from app.geometry.errors import NotRepresentableError
from app.geometry.precision import Arithmetic, Float64, MultiPrecision
from app.geometry.smooth.distance import distance_to_catenary
from app.registry import DISCRETIZATIONS


def _served(identifier: str, digits: int, **query: Any) -> Curve:
    entry = DISCRETIZATIONS[identifier]
    parsed = entry.query.model_validate({"precision": "mp", "digits": digits, **query})
    arguments = parsed.core_arguments()
    return balls.serve(
        identifier, MultiPrecision(digits), lambda ar: entry.compute(ar, **arguments), arguments
    )


def _checks(curve: Curve) -> dict[str, Any]:
    return {check.id: check for check in curve.checks}


def _decimal(value: Decimal, places: int = 520) -> str:
    return format(value.quantize(Decimal(1).scaleb(-places)), "f")


@pytest.mark.parametrize("digits", [30, 400, 1000])
def test_the_unit_is_never_zero(digits: int) -> None:
    for ar in (MultiPrecision(digits), Ball(digits)):
        assert tolerances.unit(ar) > 0 and tolerances.working_unit(ar) > 0
        assert tolerances.unit(ar) ** 2 > 0
    float64 = Float64()
    assert tolerances.unit(float64) == float64.eps == tolerances.working_unit(float64)
    assert tolerances.log2_working_unit(float64) == -52
    assert tolerances.log2_working_unit(MultiPrecision(digits)) == pytest.approx(
        -(digits + 10) * 3.321928094887362, rel=1e-12
    )


# --- (D2a): r = r* at 500 digits ---------------------------------------------------------------
# f0 = 1, f1 = 1.3: r* = −130/9 is not dyadic, so its ball has a radius; a float unit of 0 said
# "holds only for r = r*" on the polygon that starts at r*.

ONLY_AT_R_STAR_QUAD = ("theorem-1", "equation-5", "theorem-1-heights", "theorem-1-area-sum")


def test_d2a_quad_at_r_star_at_500_digits() -> None:
    with localcontext() as decimals:
        decimals.prec = 600
        r_star = Decimal(-130) / Decimal(9)
        exact_r_star = _decimal(r_star)  # r* to 520 digits: within 4 units of 10^-500
        above, below = (_decimal(r_star + s * Decimal("1e-480")) for s in (1, -1))
    for r in (None, exact_r_star):
        query = {"f0": "1", "f1": "1.3"} | ({} if r is None else {"r": r})
        checks = _checks(_served("d2a-quad", 500, **query))
        for identifier in ONLY_AT_R_STAR_QUAD:
            assert checks[identifier].holds is True, identifier
            assert checks[identifier].note is None, identifier
        assert Decimal(checks["theorem-1"].tolerance) < Decimal("1e-495")
    for r in (above, below):
        checks = _checks(_served("d2a-quad", 500, f0="1", f1="1.3", r=r))
        theorem = checks["theorem-1"]
        assert theorem.holds is False  # certified: a lower bound above the tolerance
        assert theorem.residual > Decimal("1e-485")
        note = theorem.note or ""
        assert "holds only for r = r*" in note and "(r − r* = " in note
        assert ("-1.00e-480" in note) == (r is below) and ("1.00e-480" in note)


def test_d2a_hex_at_r_star_at_400_and_500_digits() -> None:
    for digits in (400, 500):
        checks = _checks(_served("d2a-hex", digits))
        assert checks["theorem-2"].holds is True
        assert checks["theorem-2"].note is None  # it said "holds only for r = r*" here
    # the default r* = −106/9: off by 1e-450 the theorem fails, certified, with the difference
    with localcontext() as decimals:
        decimals.prec = 600
        r = _decimal(Decimal(-106) / Decimal(9) + Decimal("1e-450"))
    theorem = _checks(_served("d2a-hex", 500, r=r))["theorem-2"]
    assert theorem.holds is False
    assert theorem.note is not None and "(r − r* = 1.00e-450)" in theorem.note


def test_a_d2a_gap_below_the_working_precision_is_refused_at_500_digits() -> None:
    # √(10^-510) = 1e-255 (a float: 0, so nothing was refused); the gap is exact, from the
    # decimals written (as floats 1 + 1e-300 is 1, a gap of 0)
    mp = MultiPrecision(500)
    entry = DISCRETIZATIONS["d2a-quad"]
    tight = entry.query.model_validate(
        {"precision": "mp", "digits": 500, "f0": "1", "f1": "1." + "0" * 299 + "1"}
    )
    with pytest.raises(NotRepresentableError) as refused:
        entry.compute(mp, **tight.core_arguments())
    assert refused.value.parameter == "f1"
    assert "(f1 − f0)/f1 >= 1e-255 in mp with 500 digits" in str(refused.value.constraint)
    # a gap of 1e-200 is resolved: every check of the quad polygon decided
    wide = _served("d2a-quad", 500, f0="1", f1="1." + "0" * 199 + "1", i_min=-2, i_max=2)
    assert all("undecided" not in (check.note or "") for check in wide.checks)
    hex_entry = DISCRETIZATIONS["d2a-hex"]
    hex_query = hex_entry.query.model_validate(
        {"precision": "mp", "digits": 500, "a": "1", "b": "1." + "0" * 299 + "1"}
    )
    with pytest.raises(NotRepresentableError) as refused:
        hex_entry.compute(mp, **hex_query.core_arguments())
    assert refused.value.parameter == "b" and "1e-255" in str(refused.value.constraint)


def test_d4b_and_d4a_resolution_guards_beyond_the_float_range() -> None:
    # 100·√(10^-330) = 1e-163 (a float: 0 from 314 digits on); parameters are at least 1e-100
    # and at most 1e100 in magnitude, so d/h = 1e-170 is the kind of ratio that reaches it
    d4b = DISCRETIZATIONS["d4b"]
    query = d4b.query.model_validate({"precision": "mp", "digits": 320, "d": "1e-100", "h": "1e70"})
    with pytest.raises(NotRepresentableError) as refused:
        d4b.compute(MultiPrecision(320), **query.core_arguments())
    assert "d/h >= 1e-163 in mp with 320 digits" in str(refused.value.constraint)
    d4a = DISCRETIZATIONS["d4a"]
    query = d4a.query.model_validate({"precision": "mp", "digits": 300, "s": "1e-100", "h": "1e60"})
    with pytest.raises(NotRepresentableError) as refused:
        d4a.compute(MultiPrecision(300), **query.core_arguments())
    assert "s/h >= 1e-150 with digits=300" in str(refused.value.constraint)
    assert tolerances.power_of_ten_text(-500) == "1e-500"  # the bound shown from 648 digits on
    assert tolerances.root_working_unit_text(Ball(1000), 100) == "1e-503"


def test_the_d4a_bound_reads_the_same_at_few_digits() -> None:
    d4a = DISCRETIZATIONS["d4a"]
    for digits, shown in ((1, "s/h >= 1 with digits=1"), (3, "s/h >= 0.1 with digits=3")):
        query = d4a.query.model_validate({"precision": "mp", "digits": digits, "s": "0.01"})
        with pytest.raises(NotRepresentableError) as refused:
            d4a.compute(MultiPrecision(digits), **query.core_arguments())
        assert shown in str(refused.value.constraint)


# --- the fit of eq. (7): its determinant guard at 400 digits -----------------------------------


def _line(ar: Arithmetic, step: Any) -> Any:
    x = ar.array([ar.scalar(i) * step for i in range(12)])
    return np.stack([x, ar.array([1] * 12)], axis=1)


@pytest.mark.parametrize("kind", ["mpmath", "balls"])
def test_equation_7_guard_at_400_digits(kind: str) -> None:
    ar: Arithmetic = MultiPrecision(400) if kind == "mpmath" else Ball(400)
    exact_step = ar.scalar(1) / 8
    with balls.working_precision(ar.bits) if isinstance(ar, Ball) else nullcontext():
        # equal areas: the columns of c1 and c2 are equal, det = 0, the constants undetermined
        assert conditions.equation_7(ar, _line(ar, exact_step), 0).constants is None
    # the hexagonal polygon determines them: the fitted c1, c2 of (7) are eq. (11)'s, and
    # Theorem 2 is proved
    curve = _served("d2a-hex", 400)
    assert _checks(curve)["theorem-2"].holds is True
    constants = curve.constants
    for fitted, closed in (("c1", "c1_eq11"), ("c2", "c2_eq11")):
        difference = abs(constants[fitted] - constants[closed])
        assert difference < Ball(400).scalar("1e-380") * abs(constants[closed]), fitted


def test_the_nearest_point_on_the_catenary_at_400_digits() -> None:
    # the iteration's stopping tolerance was 4·10^-410 as a float (0): log2(0) raised, and
    # /convergence/theorem-14 answered 500 at 400 digits
    ar = MultiPrecision(400)
    q = np.stack([ar.array([0.5, 1.0]), ar.array([1.3, 1.7])], axis=1)
    distances = distance_to_catenary(ar, ar.scalar(1), q)
    reference = distance_to_catenary(MultiPrecision(60), MultiPrecision(60).scalar(1), q)
    for near, far in zip(distances, reference, strict=True):
        assert abs(float(near) - float(far)) < 1e-15 and 0.09 < float(near) < 0.16


def test_theorem_14_study_at_400_digits(client: TestClient) -> None:
    params: dict[str, str | int | float] = {
        "precision": "mp",
        "digits": 400,
        "levels": 2,
        "samples": 5,
        "x_max": 1.0,
    }
    response = client.get("/convergence/theorem-14", params=params)
    assert response.status_code == 200
    assert response.json()["checks"][0]["holds"] is True


@pytest.mark.parametrize("path", ["/surfaces/catenoid", "/smooth/tractrix"])
def test_mpmath_checks_beyond_the_float_range_are_undecided(client: TestClient, path: str) -> None:
    # surfaces and smooth references compute mp with mpmath and report float residuals: at 400
    # digits residual and tolerance were 0.0 and every check "held"
    deep = client.get(path, params={"precision": "mp", "digits": 400}).json()["checks"]
    assert deep and all(check["holds"] is None for check in deep)
    assert all("beyond 300 digits" in check["note"] for check in deep)
    shallow = client.get(path, params={"precision": "mp", "digits": 300}).json()["checks"]
    assert [check["id"] for check in shallow] == [check["id"] for check in deep]
    assert all(check["holds"] is True and check["tolerance"] > 0 for check in shallow)


def test_exact_reads_parameters_as_mp_does() -> None:
    from fractions import Fraction

    from app.geometry.exact import ExactReal

    assert tolerances.exact(ExactReal("1." + "0" * 299 + "1")) > 1  # the decimal as written
    assert tolerances.exact(0.1) == Fraction(1, 10)  # a float's shortest decimal
    assert tolerances.exact(np.float64(1.5)) == Fraction(3, 2)
    assert tolerances.exact(np.int64(3)) == 3
