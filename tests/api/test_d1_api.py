"""GET/POST /discretizations/d1: bodies, precisions, theorems, and every 422."""

from __future__ import annotations

from decimal import Decimal

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.geometry.d1 import discretization as d1
from app.geometry.precision import Float64
from app.schemas.curve import CurveResponse
from tests.api.test_errors import problem


def test_default_curve_matches_the_core_and_the_schema(client: TestClient) -> None:
    response = client.get("/discretizations/d1")
    assert response.status_code == 200
    body = response.json()
    CurveResponse.model_validate(body)
    assert body["parameters"] == {
        "c": 0.1,
        "delta": 0.2,
        "y0": 1.0,
        "y1": 1.0,
        "i_min": -10,
        "i_max": 10,
        "method": "construction",
    }
    core = d1.compute(Float64())
    np.testing.assert_array_equal(np.array(body["vertices"]), core.polygon.vertices)
    assert body["vertices"][10] == [0.0, 1.0] and body["vertices"][11] == [0.2, 1.0]
    assert body["companions"] == {}
    assert [c["id"] for c in body["checks"]] == [s.id for s in d1.STATEMENTS]
    assert all(c["holds"] for c in body["checks"])  # the default start has offset 0


def test_an_offset_start_reports_failing_checks_as_answers(client: TestClient) -> None:
    body = client.get("/discretizations/d1", params={"y0": 2.0, "y1": 2.0}).json()
    checks = {c["id"]: c for c in body["checks"]}
    assert checks["d1"]["holds"] is True
    assert checks["d3"]["holds"] is False and checks["equation-2"]["holds"] is False
    assert checks["d3"]["residual"] > 1e-3 and "C = 1" in checks["d3"]["note"]
    assert body["constants"]["d1"] == pytest.approx(0.1, rel=1e-12)


def test_post_equals_get_and_mp_gives_decimal_strings(client: TestClient) -> None:
    params = {"c": 0.3, "delta": 0.4, "y0": -2.0, "y1": -2.5, "i_min": -3, "i_max": 4}
    assert client.post("/discretizations/d1", json=params).json() == (
        client.get("/discretizations/d1", params=params).json()
    )
    body = client.get(
        "/discretizations/d1", params={**params, "precision": "mp", "digits": 40}
    ).json()
    x, y = body["vertices"][4]  # p_1 = (0.4, −2.5)
    assert Decimal(x) == Decimal("0.4") and Decimal(y) == Decimal("-2.5")
    assert isinstance(body["constants"]["d1"], str)
    assert Decimal(body["constants"]["d1"]) == pytest.approx(Decimal("0.3"), rel=Decimal("1e-35"))


def test_theorems_default_to_d1_for_its_own_statements(client: TestClient) -> None:
    body = client.get("/theorems/d1-closed-form", params={"c": 0.5, "i_max": 20}).json()
    assert body["discretization"] == "d1" and body["check"]["holds"] is True
    body = client.get("/theorems/d3", params={"discretization": "d1", "y0": 3.0}).json()
    assert body["discretization"] == "d1" and body["check"]["holds"] is False


@pytest.mark.parametrize(
    ("query", "parameter", "constraint"),
    [
        ("c=1", "c", "c < 1"),
        ("c=0", "c", "c > 0"),
        ("c=-0.5", "c", "c > 0"),
        ("c=nan", "c", "c is a finite number"),
        ("delta=0", "delta", "delta > 0"),
        ("y0=inf", "y0", "y0 is a finite number"),
        ("y1=1e200", "y1", "y1 <= 1e+100"),
        ("i_min=2&i_max=1", "i_max", "i_min <= i_max"),
        ("c=0.5&i_max=400", "i_max", "in float64"),
        ("delta=1e-60&y1=1e95", "y1", "|y1 − y0|/delta <= 1e+150 in float64"),
        ("delta=1e-300", "delta", "delta is 0 or at least 1e-100 in magnitude"),
        ("method=guess", "method", "method is one of"),
        ("h=1", "h", "not a parameter of this endpoint"),
    ],
)
def test_bad_query_is_a_422_naming_the_parameter(
    client: TestClient, query: str, parameter: str, constraint: str
) -> None:
    body = problem(client.get(f"/discretizations/d1?{query}"), 422)
    named = {e["parameter"]: e["constraint"] for e in body["errors"]}
    assert parameter in named, body
    assert constraint in named[parameter], body
